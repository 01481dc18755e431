!> Text form of numbers: reals with every significant digit of their kind,
!> integers of either kind with as many places as they need.
module sphere_row_format
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: qp
    implicit none
    private
    public :: real_str, itoa

    !> Text of an integer of either kind.
    interface itoa
        module procedure itoa_default, itoa_int64
    end interface itoa

contains

    !> Text of a default integer.
    pure function itoa_default(i) result(s)
        integer, intent(in) :: i
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write (buf, "(i0)") i
        s = trim(buf)
    end function itoa_default

    !> Text of a 64-bit integer (counts, fingerprints).
    pure function itoa_int64(i) result(s)
        integer(int64), intent(in) :: i
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write (buf, "(i0)") i
        s = trim(buf)
    end function itoa_int64

    !> `x` (converted exactly to real128) written with `digits` significant
    !> digits in scientific notation; the exponent gets as many places as it needs.
    !> Non-finite values are written as `nan`, `inf` or `-inf`.
    pure function real_str(x, digits) result(str)
        real(qp), intent(in) :: x
        integer, intent(in) :: digits
        character(len=:), allocatable :: str
        character(len=64) :: buf, form
        integer :: ew
        if (x /= x) then
            str = "nan"
            return
        else if (abs(x) > huge(x)) then
            str = merge("inf ", "-inf", x > 0)
            str = trim(str)
            return
        end if
        ew = 2
        if (x /= 0.0_qp) then
            if (abs(log10(abs(x))) >= 99.0_qp) ew = 4
        end if
        write (form, "('(es', i0, '.', i0, 'e', i0, ')')") digits + ew + 8, digits - 1, ew
        write (buf, form) x
        str = trim(adjustl(buf))
    end function real_str

end module sphere_row_format
