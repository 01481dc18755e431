!> Sorting: insertion sort and the median of the short arrays of the study
!> (scan points, timing batches), stable and without work space; and an
!> O(n) radix sort of the long arrays of doubles of the Monte Carlo.
module sphere_row_sorting
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp
    implicit none
    private
    public :: sort, median, radix_sort

    !> Bits per pass of the radix sort (256 buckets: the counts stay in cache).
    integer, parameter :: radix_bits = 8
    integer, parameter :: radix_buckets = 2**radix_bits, radix_passes = 64/radix_bits

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

    !> Sort doubles into ascending order in O(n): a least-significant-digit
    !> radix sort, stable, on 64-bit keys that order as the doubles do. A
    !> double's bits order like its value for x >= 0 once the sign bit is set,
    !> and reversed for x < 0, where every bit is flipped; the keys are compared
    !> as unsigned numbers digit by digit (ibits), so the sign of the int64
    !> does not matter. The counts of all passes come from one read of the keys;
    !> a pass whose digit is the same in every key (the exponent's top bits of
    !> values in [0, 1], say) moves nothing and is left out. NaNs are not
    !> ordered; -0 sorts before +0.
    subroutine radix_sort(x)
        real(dp), intent(inout) :: x(:)
        integer(int64), allocatable :: key(:), tmp(:)
        integer(int64) :: counts(0:radix_buckets - 1, radix_passes), k
        integer(int64) :: place, c
        integer :: n, i, pass, d, shift
        logical :: in_key
        n = size(x)
        if (n < 2) return
        allocate (key(n), tmp(n))
        counts = 0
        do i = 1, n
            k = transfer(x(i), k)
            if (k < 0) then
                k = not(k)
            else
                k = ibset(k, 63)
            end if
            key(i) = k
            do pass = 1, radix_passes
                d = int(ibits(k, (pass - 1)*radix_bits, radix_bits))
                counts(d, pass) = counts(d, pass) + 1
            end do
        end do
        in_key = .true.
        do pass = 1, radix_passes
            if (maxval(counts(:, pass)) == n) cycle
            ! bucket starts from the counts
            place = 1
            do d = 0, radix_buckets - 1
                c = counts(d, pass)
                counts(d, pass) = place
                place = place + c
            end do
            shift = (pass - 1)*radix_bits
            if (in_key) then
                call scatter(key, tmp)
            else
                call scatter(tmp, key)
            end if
            in_key = .not. in_key
        end do
        if (.not. in_key) key = tmp
        do i = 1, n
            k = key(i)
            if (btest(k, 63)) then
                k = ibclr(k, 63)
            else
                k = not(k)
            end if
            x(i) = transfer(k, x(i))
        end do

    contains

        !> One stable pass: each key to the next place of its digit's bucket.
        subroutine scatter(from, to)
            integer(int64), intent(in) :: from(:)
            integer(int64), intent(out) :: to(:)
            integer :: j, dj
            do j = 1, n
                dj = int(ibits(from(j), shift, radix_bits))
                to(counts(dj, pass)) = from(j)
                counts(dj, pass) = counts(dj, pass) + 1
            end do
        end subroutine scatter

    end subroutine radix_sort

end module sphere_row_sorting
