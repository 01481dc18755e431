!> Strict readers of the numbers a user types: the whole text must be a
!> number of the kind asked for (no list-directed extras such as `1-5`, `4*1`,
!> `0.5_16`), within the range of real(16) or of the default integer. A
!> refusal is an `error_t` naming the key, the text as given (control
!> characters shown escaped) and what is allowed.
module sphere_row_read
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: qp
    use sphere_row_format, only: itoa, short_text
    use sphere_row_error, only: error_t, fatal_error
    implicit none
    private
    public :: read_real, read_int, read_reals, is_real_text, is_int_text
    public :: printable, has_control, lower

    !> How a number is written, as messages say it.
    character(len=*), parameter :: number_rule = &
        "a number such as 0.25, -3, 1e-5 or 2.5d3"

contains

    !> True if the whole of `text` is a real number in Fortran or C syntax: an
    !> optional sign, digits with an optional '.' (at least one digit), and an
    !> optional exponent: e, E, d or D, an optional sign and digits.
    pure logical function is_real_text(text)
        character(len=*), intent(in) :: text
        integer :: i, n, digits
        is_real_text = .false.
        n = len(text)
        i = 1
        if (n == 0) return
        if (text(1:1) == "+" .or. text(1:1) == "-") i = 2
        digits = 0
        do while (i <= n)
            if (.not. is_digit(text(i:i))) exit
            digits = digits + 1
            i = i + 1
        end do
        if (i <= n) then
            if (text(i:i) == ".") then
                i = i + 1
                do while (i <= n)
                    if (.not. is_digit(text(i:i))) exit
                    digits = digits + 1
                    i = i + 1
                end do
            end if
        end if
        if (digits == 0) return
        if (i <= n) then
            if (scan(text(i:i), "eEdD") == 0) return
            i = i + 1
            if (i <= n) then
                if (text(i:i) == "+" .or. text(i:i) == "-") i = i + 1
            end if
            if (i > n) return
            do while (i <= n)
                if (.not. is_digit(text(i:i))) return
                i = i + 1
            end do
        end if
        is_real_text = .true.
    end function is_real_text

    !> True if the whole of `text` is an optional sign and digits.
    pure logical function is_int_text(text)
        character(len=*), intent(in) :: text
        integer :: start
        is_int_text = .false.
        if (len(text) == 0) return
        start = 1
        if (text(1:1) == "+" .or. text(1:1) == "-") start = 2
        if (start > len(text)) return
        is_int_text = verify(text(start:), "0123456789") == 0
    end function is_int_text

    pure logical function is_digit(c)
        character, intent(in) :: c
        is_digit = c >= "0" .and. c <= "9"
    end function is_digit

    !> Read `text` as the real value of key `name` in real(16), strictly (see
    !> is_real_text). Refused: anything else, a value beyond the largest
    !> real(16) (it would be inf) and a non-zero value that rounds to 0.
    !> `allowed` ends the message (default: a finite number).
    pure subroutine read_real(name, text, x, error, allowed)
        character(len=*), intent(in) :: name, text
        real(qp), intent(out) :: x
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in), optional :: allowed
        character(len=:), allocatable :: what
        integer :: ios
        what = "a finite number"
        if (present(allowed)) what = allowed
        x = 0.0_qp
        if (len(text) == 0) then
            call fatal_error(error, name//" = : no value; allowed "//what)
            return
        else if (.not. is_real_text(text)) then
            call fatal_error(error, name//" = "//printable(text)//": not a number; allowed " &
                //what//", written as "//number_rule)
            return
        end if
        read (text, *, iostat=ios) x
        if (ios /= 0) then
            call fatal_error(error, name//" = "//printable(text)//": not a number; allowed " &
                //what//", written as "//number_rule)
        else if (.not. (abs(x) <= huge(x))) then
            call fatal_error(error, name//" = "//text//": beyond the largest real(16) number " &
                //short_text(huge(x), 3, "down")//"; allowed "//what)
        else if (x == 0.0_qp .and. scan(mantissa(text), "123456789") > 0) then
            call fatal_error(error, name//" = "//text//": too small for real(16), it would " &
                //"read as 0; allowed "//what)
        end if
    end subroutine read_real

    !> The part of a number before its exponent letter.
    pure function mantissa(text) result(m)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: m
        integer :: i
        i = scan(text, "eEdD")
        if (i == 0) then
            m = text
        else
            m = text(:i - 1)
        end if
    end function mantissa

    !> Read `text` as the integer value of key `name`: an optional sign and
    !> digits, within the range of the default integer.
    pure subroutine read_int(name, text, n, error, allowed)
        character(len=*), intent(in) :: name, text
        integer, intent(out) :: n
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in), optional :: allowed
        character(len=:), allocatable :: what, digits
        integer(int64) :: wide
        integer :: ios, first
        what = "an integer"
        if (present(allowed)) what = allowed
        n = 0
        if (len(text) == 0) then
            call fatal_error(error, name//" = : no value; allowed "//what)
            return
        else if (.not. is_int_text(text)) then
            call fatal_error(error, name//" = "//printable(text)//": not an integer; allowed " &
                //what//", written as an optional sign and digits")
            return
        end if
        first = verify(text, "+-0")
        if (first == 0) return
        digits = text(first:)
        if (len(digits) > 18) then
            wide = huge(wide)
        else
            read (text, *, iostat=ios) wide
            if (ios /= 0) wide = huge(wide)
        end if
        if (abs(wide) > huge(n)) then
            call fatal_error(error, name//" = "//text//": beyond the largest integer " &
                //itoa(huge(n))//"; allowed "//what)
            return
        end if
        n = int(wide)
    end subroutine read_int

    !> Read a comma-separated list of reals, each as read_real reads one;
    !> an empty entry is refused.
    pure subroutine read_reals(name, text, xs, error, allowed)
        character(len=*), intent(in) :: name, text
        real(qp), allocatable, intent(out) :: xs(:)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in), optional :: allowed
        character(len=:), allocatable :: what
        integer :: i, j, n, start
        what = "comma-separated numbers"
        if (present(allowed)) what = allowed
        n = 1
        do i = 1, len(text)
            if (text(i:i) == ",") n = n + 1
        end do
        allocate (xs(n))
        start = 1
        do j = 1, n
            i = index(text(start:), ",")
            if (i == 0) then
                i = len(text) + 1
            else
                i = start + i - 1
            end if
            call read_real(name, text(start:i - 1), xs(j), error)
            if (allocated(error)) then
                if (i == start) then
                    error%message = name//" = "//printable(text)//": value "//itoa(j) &
                        //" is empty; allowed "//what
                else
                    error%message = name//" = "//printable(text)//": value "//itoa(j) &
                        //" = "//printable(text(start:i - 1)) &
                        //after_colon(error%message, name//" = "//printable(text(start:i - 1))) &
                        //"; allowed "//what
                end if
                return
            end if
            start = i + 1
        end do
    end subroutine read_reals

    !> The reason in a message `head: reason; allowed ...`, as ": reason".
    pure function after_colon(message, head) result(reason)
        character(len=*), intent(in) :: message, head
        character(len=:), allocatable :: reason
        integer :: stop_at
        reason = message(len(head) + 1:)
        stop_at = index(reason, "; allowed")
        if (stop_at > 0) reason = reason(:stop_at - 1)
    end function after_colon

    !> `text` with every control character shown escaped (\n, \t, \r, \xHH),
    !> so that a message stays one line.
    pure function printable(text) result(shown)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: shown
        character(len=*), parameter :: hex = "0123456789abcdef"
        integer :: i, c
        shown = ""
        do i = 1, len(text)
            c = iachar(text(i:i))
            select case (c)
            case (10)
                shown = shown//"\n"
            case (9)
                shown = shown//"\t"
            case (13)
                shown = shown//"\r"
            case (0:8, 11:12, 14:31, 127)
                shown = shown//"\x"//hex(c/16 + 1:c/16 + 1)//hex(mod(c, 16) + 1:mod(c, 16) + 1)
            case default
                shown = shown//text(i:i)
            end select
        end do
    end function printable

    pure logical function has_control(text)
        character(len=*), intent(in) :: text
        integer :: i
        has_control = .false.
        do i = 1, len(text)
            if (iachar(text(i:i)) < 32 .or. iachar(text(i:i)) == 127) has_control = .true.
        end do
    end function has_control

    pure function lower(text) result(low)
        character(len=*), intent(in) :: text
        character(len=len(text)) :: low
        integer :: i
        low = text
        do i = 1, len(text)
            if (low(i:i) >= "A" .and. low(i:i) <= "Z") low(i:i) = achar(iachar(low(i:i)) + 32)
        end do
    end function lower

end module sphere_row_read
