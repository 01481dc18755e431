!> Strict readers of the numbers a user types: the whole text must be a
!> number of the kind asked for (no list-directed extras such as `1-5`, `4*1`,
!> `0.5_16`), within the range of real(16) or of the default integer, and a
!> real that is not 0 must be a normal real(16) (a subnormal one keeps fewer
!> digits than the text asks for). A refusal is an `error_t` naming the key,
!> the text as given (control characters and bytes beyond ASCII shown
!> escaped) and what is allowed. `compare_decimal` orders two numbers by
!> their exact decimal texts, for range checks that rounding must not decide.
module sphere_row_read
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: qp
    use sphere_row_format, only: itoa, short_text
    use sphere_row_error, only: error_t, fatal_error
    implicit none
    private
    public :: read_real, read_int, read_reals, is_real_text, is_int_text, compare_decimal
    public :: printable, has_control, lower

    !> How a number is written, as messages say it.
    character(len=*), parameter :: number_rule = &
        "a number such as 0.25, -3, 1e-5 or 2.5d3"
    !> Why a number below the normal range of real(16) is refused.
    character(len=*), parameter :: too_small = "too small for real(16): not 0 and below " &
        //"its smallest normal number 3.3621e-4932, where it would keep fewer digits or read as 0"

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
    !> real(16) (it would be inf) and a non-zero value below the smallest
    !> normal real(16), which would read as 0 or as a subnormal number of
    !> fewer significant bits (a scene made of such values runs with other
    !> ratios than the ones typed). `allowed` ends the message (default: a
    !> finite number).
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
        else if (abs(x) < tiny(x) .and. scan(mantissa(text), "123456789") > 0) then
            call fatal_error(error, name//" = "//text//": "//too_small//"; allowed "//what &
                //", and 0 or a magnitude >= "//short_text(tiny(x), 3, "up"))
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
                    if (index(error%message, too_small) > 0) error%message = error%message &
                        //", and each 0 or of magnitude >= "//short_text(tiny(1.0_qp), 3, "up")
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

    !> `text` with every control character and every byte beyond ASCII shown
    !> escaped (\n, \t, \r, \xHH), so that a message stays one line of
    !> plain text. Linear in the length of `text` (a value may be a list of a
    !> million numbers).
    pure function printable(text) result(shown)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: shown
        character(len=*), parameter :: hex = "0123456789abcdef"
        integer :: i, c, n
        n = 0
        do i = 1, len(text)
            n = n + escaped_length(iachar(text(i:i)))
        end do
        allocate (character(len=n) :: shown)
        n = 0
        do i = 1, len(text)
            c = iachar(text(i:i))
            select case (escaped_length(c))
            case (1)
                shown(n + 1:n + 1) = text(i:i)
            case (2)
                shown(n + 1:n + 2) = "\"//merge("n", merge("t", "r", c == 9), c == 10)
            case default
                shown(n + 1:n + 4) = "\x"//hex(c/16 + 1:c/16 + 1) &
                    //hex(mod(c, 16) + 1:mod(c, 16) + 1)
            end select
            n = n + escaped_length(c)
        end do
    end function printable

    !> Characters that byte `c` takes in a printable text.
    pure integer function escaped_length(c)
        integer, intent(in) :: c
        select case (c)
        case (9, 10, 13)
            escaped_length = 2
        case (32:126)
            escaped_length = 1
        case default
            escaped_length = 4
        end select
    end function escaped_length

    pure logical function has_control(text)
        character(len=*), intent(in) :: text
        integer :: i
        has_control = .false.
        do i = 1, len(text)
            if (iachar(text(i:i)) < 32 .or. iachar(text(i:i)) == 127) has_control = .true.
        end do
    end function has_control

    !> -1, 0 or 1 as the number written `a` is below, equal to or above the
    !> one written `b`, exactly, from their decimal digits (both must pass
    !> is_real_text): 1.00000000000000000000000000000000001 is above 1 though
    !> both round to the same real(16).
    pure integer function compare_decimal(a, b)
        character(len=*), intent(in) :: a, b
        character(len=:), allocatable :: da, db
        integer(int64) :: pa, pb
        integer :: sa, sb, i
        character :: ca, cb
        call decimal_parts(a, sa, da, pa)
        call decimal_parts(b, sb, db, pb)
        if (sa /= sb) then
            compare_decimal = merge(1, -1, sa > sb)
            return
        end if
        compare_decimal = 0
        if (sa == 0) return
        ! same sign: the larger power of ten, then the first differing digit
        if (pa /= pb) then
            compare_decimal = merge(1, -1, pa > pb)
        else
            do i = 1, max(len(da), len(db))
                ca = "0"
                cb = "0"
                if (i <= len(da)) ca = da(i:i)
                if (i <= len(db)) cb = db(i:i)
                if (ca == cb) cycle
                compare_decimal = merge(1, -1, ca > cb)
                exit
            end do
        end if
        compare_decimal = sa*compare_decimal
    end function compare_decimal

    !> A number's text as sign (-1, 0 or 1), significant digits d1 d2 ... (no
    !> leading or trailing zeros) and power, the value being 0.d1 d2 ... *
    !> 10^power. An exponent beyond int64 saturates (it is far beyond any
    !> real's range either way).
    pure subroutine decimal_parts(text, sign, digits, power)
        character(len=*), intent(in) :: text
        integer, intent(out) :: sign
        character(len=:), allocatable, intent(out) :: digits
        integer(int64), intent(out) :: power
        integer(int64), parameter :: most = huge(1_int64)/20
        character(len=:), allocatable :: m
        integer(int64) :: e
        integer :: i, at, dot, first, last, before
        logical :: negative
        negative = text(1:1) == "-"
        at = 1
        if (scan(text(1:1), "+-") > 0) at = 2
        i = scan(text, "eEdD")
        if (i == 0) then
            m = text(at:)
            e = 0
        else
            m = text(at:i - 1)
            e = exponent_value(text(i + 1:))
        end if
        dot = index(m, ".")
        if (dot == 0) then
            before = len(m)
        else
            before = dot - 1
            m = m(:dot - 1)//m(dot + 1:)
        end if
        first = verify(m, "0")
        sign = 0
        digits = ""
        power = 0
        if (first == 0) return
        last = verify(m, "0", back=.true.)
        sign = merge(-1, 1, negative)
        digits = m(first:last)
        power = max(-most, min(most, e)) + (before - first + 1)
    contains
        pure function exponent_value(t) result(v)
            character(len=*), intent(in) :: t
            integer(int64) :: v
            integer :: j, start
            start = 1
            if (scan(t(1:1), "+-") > 0) start = 2
            v = 0
            do j = start, len(t)
                v = min(most, 10*v + (iachar(t(j:j)) - iachar("0")))
            end do
            if (t(1:1) == "-") v = -v
        end function exponent_value
    end subroutine decimal_parts

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
