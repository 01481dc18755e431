!> The scene as a table (`spheres=FILE.tsv`): a header line `x<TAB>v<TAB>m`,
!> then one sphere a line, its position, velocity and mass, tab-separated,
!> positions increasing so that every gap x(i+1) - x(i) - d is at least 0.
!> A row of 10^6 spheres is a file of tens of megabytes: read line by line.
!> A refusal names the file, the line and the value at fault.
module sphere_row_spheres_file
    use sphere_row_kinds, only: qp
    use sphere_row_format, only: itoa, short_text
    use sphere_row_error, only: error_t, fatal_error
    use sphere_row_read, only: read_real, printable, has_control
    use sphere_row_system, only: path_kind, path_regular, system_error_text
    implicit none
    private
    public :: read_spheres

    character(len=*), parameter :: tab = achar(9), header = "x"//tab//"v"//tab//"m"

contains

    !> The spheres of the table at `path` for spheres of diameter d: x1 (the
    !> first position), the gaps (p - 1), velocities and masses (p each).
    subroutine read_spheres(path, d, x1, gaps, v, m, error)
        character(len=*), intent(in) :: path
        real(qp), intent(in) :: d
        real(qp), intent(out) :: x1
        real(qp), allocatable, intent(out) :: gaps(:), v(:), m(:)
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: x(:)
        character(len=:), allocatable :: line
        integer :: unit, ios, errno, n, lines, i
        character(len=256) :: iomsg
        x1 = 0.0_qp
        if (path_kind(path, errno) /= path_regular) then
            call refuse(0, "not a readable regular file ("//system_error_text(errno)//"); " &
                //"allowed a table x<TAB>v<TAB>m, one sphere a line")
            return
        end if
        open (newunit=unit, file=path, status="old", action="read", iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            call refuse(0, "cannot be opened ("//trim(iomsg)//"); allowed a readable " &
                //"table x<TAB>v<TAB>m, one sphere a line")
            return
        end if
        ! the lines, counted first: the arrays are made once
        lines = 0
        do
            call get_line(unit, line, ios)
            if (ios /= 0) exit
            lines = lines + 1
        end do
        n = lines - 1
        if (n < 2) then
            close (unit)
            call refuse(0, "holds "//itoa(max(n, 0))//" spheres after its header; allowed " &
                //"at least 2, one a line")
            return
        end if
        rewind (unit)
        allocate (x(n), v(n), m(n))
        call get_line(unit, line, ios)
        if (trim(line) /= header) then
            close (unit)
            call refuse(1, "the header is "//printable(line)//"; allowed x<TAB>v<TAB>m")
            return
        end if
        do i = 1, n
            call get_line(unit, line, ios)
            call parse(i + 1, line, x(i), v(i), m(i))
            if (allocated(error)) exit
            if (i > 1) then
                if (.not. x(i) - x(i - 1) - d >= 0.0_qp) then
                    call refuse(i + 1, "x = "//short_text(x(i))//" overlaps the sphere of " &
                        //"line "//itoa(i)//" (x = "//short_text(x(i - 1))//", d = " &
                        //short_text(d)//"); allowed x at least the line before's + d")
                    exit
                end if
            end if
        end do
        close (unit)
        if (allocated(error)) return
        x1 = x(1)
        allocate (gaps(n - 1))
        do i = 1, n - 1
            gaps(i) = x(i + 1) - x(i) - d
        end do
    contains
        !> The refusal of the file, at line `at` (0: the file as a whole).
        subroutine refuse(at, why)
            integer, intent(in) :: at
            character(len=*), intent(in) :: why
            if (at > 0) then
                call fatal_error(error, "spheres = "//printable(path)//": line "//itoa(at) &
                    //": "//why)
            else
                call fatal_error(error, "spheres = "//printable(path)//": "//why)
            end if
        end subroutine refuse

        !> One line of three tab-separated numbers: x, v and m > 0.
        subroutine parse(at, text, xi, vi, mi)
            integer, intent(in) :: at
            character(len=*), intent(in) :: text
            real(qp), intent(out) :: xi, vi, mi
            integer :: t1, t2
            type(error_t), allocatable :: bad
            xi = 0.0_qp
            vi = 0.0_qp
            mi = 0.0_qp
            t1 = index(text, tab)
            t2 = 0
            if (t1 > 0) t2 = t1 + index(text(t1 + 1:), tab)
            if (t1 == 0 .or. t2 == t1 .or. index(text(t2 + 1:), tab) > 0 .or. &
                has_control(text(t2 + 1:))) then
                call refuse(at, printable(text)//": not three tab-separated numbers; " &
                    //"allowed x<TAB>v<TAB>m")
                return
            end if
            call read_real("x", text(:t1 - 1), xi, bad)
            if (.not. allocated(bad)) call read_real("v", text(t1 + 1:t2 - 1), vi, bad)
            if (.not. allocated(bad)) call read_real("m", text(t2 + 1:), mi, bad, "a mass > 0")
            if (.not. allocated(bad) .and. .not. mi > 0.0_qp) call fatal_error(bad, "m = " &
                //printable(text(t2 + 1:))//": allowed a finite mass > 0")
            if (allocated(bad)) call refuse(at, bad%message)
        end subroutine parse
    end subroutine read_spheres

    !> The next line of `unit`, whole, without its end (a carriage return of a
    !> CRLF file too); ios /= 0 at the end of the file.
    subroutine get_line(unit, line, ios)
        integer, intent(in) :: unit
        character(len=:), allocatable, intent(out) :: line
        integer, intent(out) :: ios
        character(len=256) :: buffer
        integer :: n
        line = ""
        do
            read (unit, "(a)", advance="no", size=n, iostat=ios) buffer
            line = line//buffer(:n)
            if (ios /= 0) exit
        end do
        if (is_iostat_eor(ios)) ios = 0
        n = len(line)
        if (n > 0) then
            if (line(n:n) == achar(13)) line = line(:n - 1)
        end if
    end subroutine get_line

end module sphere_row_spheres_file
