!> Sorting and the median of the short arrays of the study (scan points,
!> timing batches): insertion sort, stable and without work space.
module sphere_row_sorting
    use sphere_row, only: dp, qp
    implicit none
    private
    public :: sort, median

contains

    !> Sort `x` into ascending order.
    pure subroutine sort(x)
        real(qp), intent(inout) :: x(:)
        integer :: i, j
        real(qp) :: key
        do i = 2, size(x)
            key = x(i)
            j = i - 1
            do while (j >= 1)
                if (x(j) <= key) exit
                x(j + 1) = x(j)
                j = j - 1
            end do
            x(j + 1) = key
        end do
    end subroutine sort

    !> Median of `x` (size >= 1); real64 converts exactly to real128 and back.
    pure real(dp) function median(x)
        real(dp), intent(in) :: x(:)
        real(qp) :: s(size(x))
        integer :: n
        s = real(x, qp)
        call sort(s)
        n = size(s)
        if (mod(n, 2) == 1) then
            median = real(s(n/2 + 1), dp)
        else
            median = real(0.5_qp*(s(n/2) + s(n/2 + 1)), dp)
        end if
    end function median

end module sphere_row_sorting
