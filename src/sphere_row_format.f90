!> Text form of numbers: reals with every significant digit of their kind
!> (tables), reals in the fewest digits that read back (messages, `--help`,
!> prose), integers of either kind with as many places as they need.
module sphere_row_format
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: qp
    implicit none
    private
    public :: real_str, short_text, itoa, real_text, int_text, number_text_length

    !> Length of the buffers of real_text (enough for up to 52 digits) and
    !> int_text.
    integer, parameter :: number_text_length = 64

    !> Text of an integer of either kind.
    interface itoa
        module procedure itoa_default, itoa_int64
    end interface itoa

contains

    !> Text of a default integer.
    pure function itoa_default(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        s = itoa_int64(int(i, int64))
    end function itoa_default

    !> Text of a 64-bit integer (counts, fingerprints).
    pure function itoa_int64(i) result(s)
        integer(int64), intent(in) :: i
        character(len=:), allocatable :: s
        character(len=number_text_length) :: buf
        integer :: length
        call int_text(i, buf, length)
        s = buf(:length)
    end function itoa_int64

    !> itoa into `text`, its first `length` characters: a subroutine, as
    !> real_text and for the same reason, so that threads may call it at once.
    pure subroutine int_text(i, text, length)
        integer(int64), intent(in) :: i
        character(len=number_text_length), intent(out) :: text
        integer, intent(out) :: length
        character(len=24) :: buf
        integer(int64) :: rest
        integer :: at
        ! digits from the right, without formatted I/O (it is called per
        ! line of long outputs); the most negative value has no positive twin
        if (i == -huge(i) - 1) then
            text = "-9223372036854775808"
            length = 20
            return
        end if
        rest = abs(i)
        at = len(buf) + 1
        do
            at = at - 1
            buf(at:at) = achar(iachar("0") + int(mod(rest, 10_int64)))
            rest = rest/10
            if (rest == 0) exit
        end do
        if (i < 0) then
            at = at - 1
            buf(at:at) = "-"
        end if
        text = buf(at:)
        length = len(buf) - at + 1
    end subroutine int_text

    !> `x` (converted exactly to real128) written with `digits` significant
    !> digits in scientific notation; the exponent gets as many places as it needs.
    !> Non-finite values are written as `nan`, `inf` or `-inf`.
    pure function real_str(x, digits) result(str)
        real(qp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=:), allocatable :: str
        character(len=number_text_length) :: buf
        integer :: length
        call real_text(x, digits, buf, length)
        str = buf(:length)
    end function real_str

    !> real_str into `text`, its first `length` characters. No character
    !> result of deferred length: gfortran 12 keeps the length of such a
    !> result in a static variable of the caller, so two threads that call one
    !> at once may get each other's length; threads may call this subroutine
    !> at once.
    pure subroutine real_text(x, digits, text, length)
        real(qp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=number_text_length), intent(out) :: text
        integer, intent(out) :: length
        character(len=number_text_length) :: buf, form, w, d, e
        integer :: ew, nw, nd, ne
        if (x /= x) then
            buf = "nan"
        else if (abs(x) > huge(x)) then
            buf = merge("inf ", "-inf", x > 0)
        else
            ! two exponent digits unless |log10 |x|| >= 99
            ew = 2
            if (x /= 0.0_qp .and. (abs(x) >= 1.0e99_qp .or. abs(x) <= 1.0e-99_qp)) ew = 4
            call int_text(int(digits + ew + 8, int64), w, nw)
            call int_text(int(digits - 1, int64), d, nd)
            call int_text(int(ew, int64), e, ne)
            form = "(es"//w(:nw)//"."//d(:nd)//"e"//e(:ne)//")"
            write (buf, form) x
            buf = adjustl(buf)
        end if
        length = len_trim(buf)
        text = buf(:length)
    end subroutine real_text

    !> The shortest text (at most `digits` significant digits, default as many
    !> as needed) that reads back as `x`: 0.2, 1, 1000000, 1.93e-34. A bound
    !> cut to a few digits is rounded `toward` "down" or "up" if asked, so that
    !> the text is still on the allowed side.
    pure function short_text(x, digits, toward) result(text)
        real(qp), intent(in) :: x
        integer, intent(in), optional :: digits
        character(len=*), intent(in), optional :: toward
        character(len=:), allocatable :: text
        character(len=80) :: buffer, form
        character(len=3) :: mode
        real(qp) :: y
        integer :: d, most, ios
        logical :: plain
        most = 37
        if (present(digits)) most = digits
        mode = ""
        if (present(toward)) then
            if (toward == "down") mode = "rd,"
            if (toward == "up") mode = "ru,"
        end if
        plain = x == 0.0_qp .or. (abs(x) >= 1.0e-3_qp .and. abs(x) < 1.0e7_qp)
        do d = 1, most
            if (plain) then
                write (form, "('(', a, 'f0.', i0, ')')") trim(mode), d
            else
                write (form, "('(', a, 'es60.', i0, 'e5)')") trim(mode), d - 1
            end if
            write (buffer, form) x
            read (buffer, *, iostat=ios) y
            if (ios == 0 .and. y == x) exit
        end do
        text = tidy_number(trim(adjustl(buffer)))
    end function short_text

    !> Tidy a number written by short_text: no trailing zeros or '.' in the
    !> mantissa, a leading 0 before '.', a lower-case exponent without '+'
    !> and leading zeros: "1.00" -> "1", ".5" -> "0.5", "1.9E-0034" -> "1.9e-34".
    pure function tidy_number(text) result(tidy)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: tidy
        character(len=:), allocatable :: m, exponent, sign
        integer :: e
        e = scan(text, "eEdD")
        if (e == 0) then
            m = text
            exponent = ""
        else
            m = text(:e - 1)
            exponent = text(e + 1:)
        end if
        if (index(m, ".") > 0) then
            do while (len(m) > 1)
                if (m(len(m):len(m)) /= "0") exit
                m = m(:len(m) - 1)
            end do
            if (m(len(m):len(m)) == ".") m = m(:len(m) - 1)
        end if
        if (len(m) == 0) m = "0"
        if (m(1:1) == ".") m = "0"//m
        if (len(m) > 1) then
            if (m(1:2) == "-.") m = "-0"//m(2:)
        end if
        if (len(exponent) > 0) then
            sign = ""
            if (exponent(1:1) == "-") sign = "-"
            exponent = exponent(verify(exponent, "+-0"):)
            tidy = m//"e"//sign//exponent
        else
            tidy = m
        end if
    end function tidy_number

end module sphere_row_format
