!> Command-line input shared by the CLI and the study programs.
!>
!> Every program takes `key=value` arguments; the scene keys below are common
!> to all of them, and a single argument without `=` names a namelist file with
!> a `&scene` group of the same keys. Parsing is strict: a value must be a
!> finite number written as one, and every refusal comes back as a status and a
!> one-line message naming the key, the value and what is allowed.
module sphere_row_args
    use sphere_row_kinds, only: qp
    use sphere_row_status, only: status_normal, status_invalid
    use sphere_row, only: scene_t, scene_init
    implicit none
    private
    public :: get_args, split_key_value, parse_real, parse_int, parse_reals, parse_flag
    public :: scene_from_args, scene_help, unused_arg, wants_help, take_key, real_key, int_key

    !> Longest `masses` or `gaps` list a namelist file may hold.
    integer, parameter :: max_list = 100000

contains

    !> All command-line arguments, each trimmed.
    subroutine get_args(args)
        character(len=:), allocatable, intent(out) :: args(:)
        integer :: i, n, length, longest
        n = command_argument_count()
        longest = 1
        do i = 1, n
            call get_command_argument(i, length=length)
            longest = max(longest, length)
        end do
        allocate (character(len=longest) :: args(n))
        do i = 1, n
            call get_command_argument(i, args(i))
        end do
    end subroutine get_args

    !> True if any argument asks for the usage text.
    pure logical function wants_help(args)
        character(len=*), intent(in) :: args(:)
        integer :: i
        wants_help = .false.
        do i = 1, size(args)
            if (args(i) == "--help" .or. args(i) == "-h" .or. args(i) == "help") wants_help = .true.
        end do
    end function wants_help

    !> Split `key=value`; `stat` is status_invalid if there is no `=` or no key.
    pure subroutine split_key_value(arg, key, value, stat, msg)
        character(len=*), intent(in) :: arg
        character(len=:), allocatable, intent(out) :: key, value
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        integer :: i
        i = index(arg, "=")
        stat = status_invalid
        if (i <= 1) then
            key = ""
            value = ""
            msg = "argument '"//trim(arg)//"': allowed key=value (see --help)"
            return
        end if
        key = trim(adjustl(arg(:i - 1)))
        value = trim(adjustl(arg(i + 1:)))
        stat = status_normal
        msg = ""
    end subroutine split_key_value

    !> Read a finite real from `text`, strictly: digits, one sign per part, a
    !> decimal point and an exponent letter only.
    pure subroutine parse_real(key, text, x, stat, msg)
        character(len=*), intent(in) :: key, text
        real(qp), intent(out) :: x
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        integer :: ios
        x = 0.0_qp
        stat = status_invalid
        if (has_word(text, "nan") .or. has_word(text, "inf")) then
            msg = key//" = "//text//": allowed a finite number"
            return
        end if
        if (len_trim(text) == 0 .or. verify(trim(text), "0123456789+-.eEdD") /= 0 &
            .or. scan(text, "0123456789") == 0) then
            msg = key//" = '"//text//"': not a number"
            return
        end if
        read (text, *, iostat=ios) x
        if (ios /= 0) then
            msg = key//" = '"//text//"': not a number"
            return
        end if
        if (.not. (abs(x) <= huge(x))) then
            msg = key//" = "//text//": allowed a finite number"
            return
        end if
        stat = status_normal
        msg = ""
    end subroutine parse_real

    !> Read an integer from `text`: an optional sign and digits only.
    pure subroutine parse_int(key, text, n, stat, msg)
        character(len=*), intent(in) :: key, text
        integer, intent(out) :: n
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        integer :: ios, start
        n = 0
        stat = status_invalid
        start = 1
        if (len_trim(text) > 0) then
            if (text(1:1) == "+" .or. text(1:1) == "-") start = 2
        end if
        if (len_trim(text) < start .or. verify(trim(text(start:)), "0123456789") /= 0 &
            .or. len_trim(text) > 10) then
            msg = key//" = '"//text//"': allowed an integer"
            return
        end if
        read (text, *, iostat=ios) n
        if (ios /= 0) then
            msg = key//" = '"//text//"': allowed an integer"
            return
        end if
        stat = status_normal
        msg = ""
    end subroutine parse_int

    !> Read a comma-separated list of finite reals.
    pure subroutine parse_reals(key, text, xs, stat, msg)
        character(len=*), intent(in) :: key, text
        real(qp), allocatable, intent(out) :: xs(:)
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        integer :: i, j, n, start
        n = 1
        do i = 1, len_trim(text)
            if (text(i:i) == ",") n = n + 1
        end do
        allocate (xs(n))
        start = 1
        do j = 1, n
            i = index(text(start:), ",")
            if (i == 0) then
                i = len_trim(text) + 1
            else
                i = start + i - 1
            end if
            call parse_real(key, trim(adjustl(text(start:i - 1))), xs(j), stat, msg)
            if (stat /= status_normal) then
                msg = key//" = "//text//": entry "//itoa(j)//" is not a finite number"
                return
            end if
            start = i + 1
        end do
    end subroutine parse_reals

    !> Read `yes` or `no`.
    pure subroutine parse_flag(key, text, flag, stat, msg)
        character(len=*), intent(in) :: key, text
        logical, intent(out) :: flag
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        stat = status_normal
        msg = ""
        select case (text)
        case ("yes")
            flag = .true.
        case ("no")
            flag = .false.
        case default
            flag = .false.
            stat = status_invalid
            msg = key//" = '"//text//"': allowed yes or no"
        end select
    end subroutine parse_flag

    !> Build a scene from the scene keys among `args` (and from a namelist file
    !> if one argument has no `=`); `used(i)` tells which arguments were taken.
    !> Arguments that are not scene keys are left for the caller, who must refuse
    !> any it does not know (see unused_arg). `e` overrides the default e of
    !> the definition's scene when given.
    subroutine scene_from_args(args, scene, used, stat, msg, e_default)
        character(len=*), intent(in) :: args(:)
        type(scene_t), intent(out) :: scene
        logical, intent(out) :: used(:)
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        real(qp), intent(in), optional :: e_default
        type(scene_t) :: defaults
        integer :: i, p, max_collisions, n_masses, n_gaps
        real(qp) :: e, d, a, v0, tol
        real(qp), allocatable :: masses(:), gaps(:), list(:)
        character(len=:), allocatable :: key, value
        logical :: have_masses, have_gaps

        p = defaults%p
        e = defaults%e
        if (present(e_default)) e = e_default
        d = defaults%d
        a = 1.0_qp
        v0 = defaults%v0
        tol = defaults%tol
        max_collisions = defaults%max_collisions
        have_masses = .false.
        have_gaps = .false.
        used = .false.
        stat = status_normal
        msg = ""

        do i = 1, size(args)
            if (index(args(i), "=") == 0 .and. args(i)(1:1) /= "-") then
                call read_namelist(trim(args(i)))
                if (stat /= status_normal) return
                used(i) = .true.
            end if
        end do

        do i = 1, size(args)
            if (used(i) .or. index(args(i), "=") == 0) cycle
            call split_key_value(args(i), key, value, stat, msg)
            if (stat /= status_normal) return
            used(i) = .true.
            select case (key)
            case ("p")
                call parse_int(key, value, p, stat, msg)
            case ("e")
                call parse_real(key, value, e, stat, msg)
            case ("d")
                call parse_real(key, value, d, stat, msg)
            case ("a")
                call parse_real(key, value, a, stat, msg)
            case ("v0")
                call parse_real(key, value, v0, stat, msg)
            case ("tol")
                call parse_real(key, value, tol, stat, msg)
            case ("max_collisions")
                call parse_int(key, value, max_collisions, stat, msg)
            case ("masses")
                call parse_reals(key, value, list, stat, msg)
                if (stat == status_normal) call move_alloc(list, masses)
                have_masses = .true.
            case ("gaps")
                call parse_reals(key, value, list, stat, msg)
                if (stat == status_normal) call move_alloc(list, gaps)
                have_gaps = .true.
            case default
                used(i) = .false.
            end select
            if (stat /= status_normal) return
        end do

        if (.not. have_gaps .and. .not. (a >= 0.0_qp)) then
            stat = status_invalid
            msg = "a = "//trim(adjustl(rstr(a)))//": allowed a >= 0"
            return
        end if
        if (have_masses .and. have_gaps) then
            call scene_init(scene, stat, msg, p=p, e=e, d=d, v0=v0, tol=tol, &
                max_collisions=max_collisions, masses=masses, gaps=gaps)
        else if (have_masses) then
            call scene_init(scene, stat, msg, p=p, e=e, d=d, a=a, v0=v0, tol=tol, &
                max_collisions=max_collisions, masses=masses)
        else if (have_gaps) then
            call scene_init(scene, stat, msg, p=p, e=e, d=d, v0=v0, tol=tol, &
                max_collisions=max_collisions, gaps=gaps)
        else
            call scene_init(scene, stat, msg, p=p, e=e, d=d, a=a, v0=v0, tol=tol, &
                max_collisions=max_collisions)
        end if

    contains

        !> Read the &scene group of a namelist file into the local values.
        subroutine read_namelist(path)
            character(len=*), intent(in) :: path
            real(qp), allocatable :: m_in(:), a_in(:)
            character(len=200) :: iomsg
            integer :: unit, ios
            namelist /scene/ p, e, d, a, v0, tol, max_collisions, masses, gaps
            real(qp), parameter :: unset = -huge(1.0_qp)
            allocate (m_in(max_list), a_in(max_list), source=unset)
            call move_alloc(m_in, masses)
            call move_alloc(a_in, gaps)
            open (newunit=unit, file=path, status="old", action="read", iostat=ios, iomsg=iomsg)
            if (ios /= 0) then
                stat = status_invalid
                msg = "namelist file '"//path//"': cannot be read ("//trim(iomsg)//")"
                return
            end if
            read (unit, nml=scene, iostat=ios, iomsg=iomsg)
            close (unit)
            if (ios /= 0) then
                stat = status_invalid
                msg = "namelist file '"//path//"': "//trim(iomsg) &
                    //" (allowed: a &scene group of the scene keys)"
                return
            end if
            n_masses = last_set(masses)
            n_gaps = last_set(gaps)
            have_masses = n_masses > 0
            have_gaps = n_gaps > 0
            masses = masses(:n_masses)
            gaps = gaps(:n_gaps)
            if (.not. (abs(e) <= huge(e) .and. abs(d) <= huge(d) .and. abs(a) <= huge(a) &
                .and. abs(v0) <= huge(v0) .and. abs(tol) <= huge(tol))) then
                stat = status_invalid
                msg = "namelist file '"//path//"': e, d, a, v0, tol: allowed finite numbers"
            end if
        end subroutine read_namelist

        pure integer function last_set(xs)
            real(qp), intent(in) :: xs(:)
            integer :: j
            last_set = 0
            do j = size(xs), 1, -1
                if (xs(j) /= -huge(1.0_qp)) then
                    last_set = j
                    return
                end if
            end do
        end function last_set

    end subroutine scene_from_args

    !> The value of the last `key=value` argument among those not yet used;
    !> `found` tells whether there was one, and it is marked used.
    pure subroutine take_key(args, used, key, value, found)
        character(len=*), intent(in) :: args(:)
        logical, intent(inout) :: used(:)
        character(len=*), intent(in) :: key
        character(len=:), allocatable, intent(out) :: value
        logical, intent(out) :: found
        integer :: i, j
        found = .false.
        value = ""
        do i = 1, size(args)
            if (used(i)) cycle
            j = index(args(i), "=")
            if (j <= 1) cycle
            if (trim(adjustl(args(i)(:j - 1))) /= key) cycle
            value = trim(adjustl(args(i)(j + 1:)))
            used(i) = .true.
            found = .true.
        end do
    end subroutine take_key

    !> The optional `key=value` among args read into x, which keeps its value
    !> when the key is absent; a value outside [lo, hi] is refused with a
    !> message naming `allowed` (default: lo <= key <= hi).
    subroutine real_key(args, used, key, x, lo, hi, stat, msg, allowed)
        character(len=*), intent(in) :: args(:), key
        logical, intent(inout) :: used(:)
        real(qp), intent(inout) :: x
        real(qp), intent(in) :: lo, hi
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        character(len=*), intent(in), optional :: allowed
        character(len=:), allocatable :: text
        logical :: found
        real(qp) :: value
        stat = status_normal
        msg = ""
        call take_key(args, used, key, text, found)
        if (.not. found) return
        call parse_real(key, text, value, stat, msg)
        if (stat /= status_normal) return
        if (.not. (value >= lo .and. value <= hi)) then
            stat = status_invalid
            if (present(allowed)) then
                msg = key//" = "//text//": allowed "//allowed
            else
                msg = key//" = "//text//": allowed "//trim(rstr(lo))//" <= "//key//" <= " &
                    //trim(rstr(hi))
            end if
            return
        end if
        x = value
    end subroutine real_key

    !> The optional integer `key=value` among args read into n, as real_key.
    subroutine int_key(args, used, key, n, lo, hi, stat, msg)
        character(len=*), intent(in) :: args(:), key
        logical, intent(inout) :: used(:)
        integer, intent(inout) :: n
        integer, intent(in) :: lo, hi
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        character(len=:), allocatable :: text
        character(len=24) :: bounds
        logical :: found
        integer :: value
        stat = status_normal
        msg = ""
        call take_key(args, used, key, text, found)
        if (.not. found) return
        call parse_int(key, text, value, stat, msg)
        if (stat /= status_normal) return
        if (value < lo .or. value > hi) then
            stat = status_invalid
            write (bounds, "(i0, ' <= ', a)") lo, key
            msg = key//" = "//text//": allowed "//trim(bounds)
            if (hi < huge(hi)) then
                write (bounds, "(' <= ', i0)") hi
                msg = trim(msg)//trim(bounds)
            end if
            return
        end if
        n = value
    end subroutine int_key

    !> Message for the first argument that no key of the program took.
    pure subroutine unused_arg(args, used, allowed, stat, msg)
        character(len=*), intent(in) :: args(:)
        logical, intent(in) :: used(:)
        character(len=*), intent(in) :: allowed
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        integer :: i, j
        stat = status_normal
        msg = ""
        do i = 1, size(args)
            if (used(i)) cycle
            stat = status_invalid
            j = index(args(i), "=")
            if (j > 1) then
                msg = "unknown key '"//args(i)(:j - 1)//"': allowed keys are "//allowed
            else
                msg = "argument '"//trim(args(i))//"': allowed key=value with keys "//allowed
            end if
            return
        end do
    end subroutine unused_arg

    !> Usage lines for the scene keys common to every program.
    pure function scene_help() result(text)
        character(len=:), allocatable :: text
        character(len=*), parameter :: nl = new_line("a")
        text = &
            "  p=4                 number of spheres, integer >= 2"//nl// &
            "  e=0.2               restitution coefficient, 0 <= e <= 1"//nl// &
            "  d=1                 sphere diameter, >= 0"//nl// &
            "  a=1                 every initial gap, >= 0"//nl// &
            "  gaps=a1,a2,...      initial gaps, p-1 values >= 0 (overrides a)"//nl// &
            "  v0=1                speed of sphere 1 at t=0, > 0"//nl// &
            "  masses=m1,m2,...    masses, p values > 0 (default all 1)"//nl// &
            "  tol=1.93e-34        rates below tol*v0 and gaps below tol*max(d,a) are"//nl// &
            "                      insignificant (end of run, collapse); 0 <= tol < 1"//nl// &
            "  max_collisions=1000000  safety net, integer >= 1"//nl// &
            "  FILE                a namelist file with a &scene group of these keys"
    end function scene_help

    pure logical function has_word(text, word)
        character(len=*), intent(in) :: text, word
        integer :: i
        character(len=len(text)) :: lower
        lower = text
        do i = 1, len(text)
            if (lower(i:i) >= "A" .and. lower(i:i) <= "Z") &
                lower(i:i) = achar(iachar(lower(i:i)) + 32)
        end do
        has_word = index(lower, word) > 0
    end function has_word

    pure function itoa(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=16) :: buf
        write (buf, "(i0)") i
        s = trim(buf)
    end function itoa

    pure function rstr(x) result(s)
        real(qp), intent(in) :: x
        character(len=48) :: s
        write (s, "(g0)") real(x, kind(1.0d0))
    end function rstr

end module sphere_row_args
