!> The program tsv-compare checks that regenerated study tables agree with the
!> committed ones.
!>
!> Every `*.tsv` of the fresh directory is compared with the file of the same
!> name in the committed directory, field by field. Words and integers must be
!> equal. A real must agree to the precision it was printed with: printed with
!> D significant digits, the tolerance is 10^(4-D) relative to the largest
!> magnitude of its column (so real(16) columns agree to ~1e-30, real64 ones to
!> ~1e-12). Timing columns (a header with [s] or [ns], and the repeat counts
!> `batches`, `runs_per_batch` chosen from timings) and the tables of timings
!> and of the machine (bench.tsv, cost.tsv, cost_summary.tsv; the study's own
!> are in the subdirectory timing/, which is not compared) are skipped: they
!> are measurements.
program tsv_compare
    use, intrinsic :: iso_fortran_env, only: error_unit
    use sphere_row, only: qp, itoa
    use sphere_row_tables, only: split_tabs
    use sphere_row_study_cli, only: cli_t, start_program, read_keys, fail, say
    implicit none
    character(len=*), parameter :: name = "tsv-compare"
    type(cli_t) :: cli
    character(len=:), allocatable :: committed, fresh, listing
    character(len=4000) :: file
    integer :: stat, unit, ios, n_files, n_values, n_bad

    call start_program(cli, name, "Compares every *.tsv of DIR fresh with the same file in " &
        //"DIR committed.", tables=.false.)
    call cli%add_word("committed", "", "directory of the committed tables (required)")
    call cli%add_word("fresh", "", "directory of the regenerated tables (required)")
    call read_keys(cli)
    if (.not. cli%given("committed")) call fail("committed: missing: allowed committed=DIR")
    if (.not. cli%given("fresh")) call fail("fresh: missing: allowed fresh=DIR")
    committed = cli%get_word("committed")
    fresh = cli%get_word("fresh")

    listing = "build/tsv-compare.list"
    call execute_command_line("mkdir -p build && ls -1 '"//fresh//"' | grep '\.tsv$' > " &
        //listing, exitstat=stat)
    if (stat /= 0) call fail("fresh = "//fresh//": no list of its .tsv files (none there, " &
        //"or build/ cannot be written); allowed a directory of tables and a writable build/")
    open (newunit=unit, file=listing, status="old", action="read")
    n_files = 0
    n_values = 0
    n_bad = 0
    do
        read (unit, "(a)", iostat=ios) file
        if (ios /= 0) exit
        if (trim(file) == "bench.tsv" .or. trim(file) == "cost.tsv" .or. &
            trim(file) == "cost_summary.tsv") cycle
        call compare_file(trim(file))
        n_files = n_files + 1
    end do
    close (unit)
    if (n_bad > 0) then
        write (error_unit, "(a)") name//": "//itoa(n_bad)//" fields differ in "// &
            itoa(n_files)//" tables: results/ is stale, run `make study` and commit"
        stop 1, quiet=.true.
    end if
    call say(name//": "//itoa(n_files)//" tables, "//itoa(n_values)// &
        " numbers agree with "//committed)

contains

    !> Compare one table; report each differing field on stderr.
    subroutine compare_file(base)
        character(len=*), intent(in) :: base
        character(len=:), allocatable :: a_lines(:), b_lines(:)
        character(len=:), allocatable :: a_fields(:), b_fields(:), header(:)
        real(qp), allocatable :: scale(:)
        real(qp) :: x, y, tol
        integer :: i, j, digits
        logical :: xa, xb
        call read_lines(committed//"/"//base, a_lines)
        call read_lines(fresh//"/"//base, b_lines)
        if (size(a_lines) == 0) then
            call report(base//": missing or empty in "//committed)
            return
        end if
        if (size(a_lines) /= size(b_lines)) then
            call report(base//": "//itoa(size(a_lines))//" lines committed, "// &
                itoa(size(b_lines))//" regenerated")
            return
        end if
        call split_tabs(a_lines(1), header)
        ! column scales from the committed table
        allocate (scale(size(header)), source=0.0_qp)
        do i = 2, size(a_lines)
            call split_tabs(a_lines(i), a_fields)
            do j = 1, min(size(a_fields), size(scale))
                call as_real(a_fields(j), x, xa, digits)
                if (xa) scale(j) = max(scale(j), abs(x))
            end do
        end do
        do i = 1, size(a_lines)
            call split_tabs(a_lines(i), a_fields)
            call split_tabs(b_lines(i), b_fields)
            if (size(a_fields) /= size(b_fields)) then
                call report(base//":"//itoa(i)//": other number of fields")
                cycle
            end if
            do j = 1, size(a_fields)
                if (j <= size(header)) then
                    if (is_timing(header(j))) cycle
                end if
                call as_real(a_fields(j), x, xa, digits)
                call as_real(b_fields(j), y, xb, digits)
                if (xa .and. xb .and. digits > 0) then
                    n_values = n_values + 1
                    tol = 10.0_qp**(4 - digits)*max(scale(min(j, size(scale))), tiny(1.0_qp))
                    if (abs(x - y) > tol) call report(base//":"//itoa(i)//":"//itoa(j)// &
                        ": "//trim(a_fields(j))//" committed, "//trim(b_fields(j))//" now")
                else if (trim(a_fields(j)) /= trim(b_fields(j))) then
                    call report(base//":"//itoa(i)//":"//itoa(j)//": '"//trim(a_fields(j))// &
                        "' committed, '"//trim(b_fields(j))//"' now")
                end if
            end do
        end do
    end subroutine compare_file

    !> A column that holds a measurement of time, or a count chosen from one.
    pure logical function is_timing(head)
        character(len=*), intent(in) :: head
        is_timing = index(head, "[s]") > 0 .or. index(head, "[ns]") > 0 .or. &
            trim(head) == "batches" .or. trim(head) == "runs_per_batch"
    end function is_timing

    !> One differing field, on stderr (the first 20 only).
    subroutine report(text)
        character(len=*), intent(in) :: text
        n_bad = n_bad + 1
        if (n_bad <= 20) write (error_unit, "(a)") name//": "//text
    end subroutine report

    !> A field that reads as a real with a decimal point or exponent; `digits`
    !> is its number of significant digits (0 for an integer, which must match
    !> exactly as text).
    subroutine as_real(field, x, is_real, digits)
        character(len=*), intent(in) :: field
        real(qp), intent(out) :: x
        logical, intent(out) :: is_real
        integer, intent(out) :: digits
        integer :: ios, k, mantissa_end
        character(len=:), allocatable :: f
        f = trim(field)
        x = 0
        digits = 0
        is_real = .false.
        if (len(f) == 0) return
        if (verify(f, "0123456789+-.eE") /= 0 .or. scan(f, "0123456789") == 0) return
        if (scan(f, ".eE") == 0) return
        read (f, *, iostat=ios) x
        if (ios /= 0) return
        is_real = .true.
        mantissa_end = scan(f, "eE") - 1
        if (mantissa_end < 0) mantissa_end = len(f)
        do k = 1, mantissa_end
            if (f(k:k) >= "0" .and. f(k:k) <= "9") digits = digits + 1
        end do
    end subroutine as_real

    subroutine read_lines(path, lines)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: lines(:)
        character(len=100000) :: buf
        integer :: u, ios, n, longest
        n = 0
        longest = 1
        open (newunit=u, file=path, status="old", action="read", iostat=ios)
        if (ios /= 0) then
            allocate (character(len=1) :: lines(0))
            return
        end if
        do
            read (u, "(a)", iostat=ios) buf
            if (ios /= 0) exit
            n = n + 1
            longest = max(longest, len_trim(buf))
        end do
        rewind (u)
        allocate (character(len=longest) :: lines(n))
        do n = 1, size(lines)
            read (u, "(a)") buf
            lines(n) = buf(:longest)
        end do
        close (u)
    end subroutine read_lines


end program tsv_compare
