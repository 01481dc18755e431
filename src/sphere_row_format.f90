!> Text form of reals with every significant digit of their kind.
module sphere_row_format
    use sphere_row_kinds, only: qp
    implicit none
    private
    public :: real_str

contains

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
