!> Sorting: insertion sort and the median of the short arrays of the study
!> (scan points, timing batches), stable and without work space; and an
!> O(n) radix sort of the long arrays of doubles of the Monte Carlo.
module sphere_row_sorting
    use, intrinsic :: iso_fortran_env, only: int64
    !$ use omp_lib, only: omp_get_max_threads
    use sphere_row, only: dp, qp
    implicit none
    private
    public :: sort, median, radix_sort

    !> Bits per pass of the radix sort (256 buckets: the counts stay in cache).
    integer, parameter :: radix_bits = 8
    integer, parameter :: radix_buckets = 2**radix_bits, radix_passes = 64/radix_bits
    !> Fewest keys per thread of the radix sort: shorter arrays are not worth a
    !> thread's start.
    integer, parameter :: min_part_size = 16384

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
    !> radix sort, stable, on 64-bit keys that order as the doubles do (see
    !> order_key). The counts of all passes come from one read of the keys; a
    !> pass whose digit is the same in every key (the exponent's top bits of
    !> values in [0, 1], say) moves nothing and is left out. NaNs are not
    !> ordered; -0 sorts before +0.
    !>
    !> The keys are cut into one contiguous part per OpenMP thread: each part
    !> is counted and scattered by its own thread, the parts of a digit's
    !> bucket placed in part order, so every pass is the serial pass and the
    !> result is the same for any number of threads. A part's counts of a
    !> later pass are taken again after the keys moved (on one part they are
    !> those of all keys, which do not change).
    subroutine radix_sort(x)
        real(dp), intent(inout) :: x(:)
        integer(int64), allocatable :: key(:), tmp(:)
        integer(int64), allocatable :: counts(:, :, :)
        integer :: n, parts, part, i, pass
        logical :: in_key, moved
        n = size(x)
        if (n < 2) return
        parts = 1
        !$ parts = max(1, min(omp_get_max_threads(), n/min_part_size))
        allocate (key(n), tmp(n), counts(0:radix_buckets - 1, radix_passes, parts))
        !$omp parallel do schedule(static, 1) default(shared) private(part, i) if (parts > 1)
        do part = 1, parts
            counts(:, :, part) = 0
            do i = part_first(n, parts, part), part_first(n, parts, part + 1) - 1
                key(i) = order_key(x(i))
                call count_digits(key(i), counts(:, :, part))
            end do
        end do
        !$omp end parallel do
        in_key = .true.
        moved = .false.
        do pass = 1, radix_passes
            if (maxval(sum(counts(:, pass, :), dim=2)) == n) cycle
            if (moved .and. parts > 1) then
                if (in_key) then
                    call count_pass(key, pass, parts, counts(:, pass, :))
                else
                    call count_pass(tmp, pass, parts, counts(:, pass, :))
                end if
            end if
            if (in_key) then
                call scatter_pass(key, tmp, pass, parts, counts(:, pass, :))
            else
                call scatter_pass(tmp, key, pass, parts, counts(:, pass, :))
            end if
            in_key = .not. in_key
            moved = .true.
        end do
        if (in_key) then
            call keys_to_doubles(key, parts, x)
        else
            call keys_to_doubles(tmp, parts, x)
        end if
    end subroutine radix_sort

    !> A key whose bits, compared as an unsigned number, order as the double
    !> x does: a double's bits order like its value for x >= 0 once the sign
    !> bit is set, and reversed for x < 0, where every bit is flipped. The
    !> digits are read with ibits, so the sign of the int64 does not matter.
    elemental integer(int64) function order_key(x) result(k)
        real(dp), intent(in) :: x
        k = transfer(x, k)
        if (k < 0) then
            k = not(k)
        else
            k = ibset(k, 63)
        end if
    end function order_key

    !> The double of an order key (the inverse of order_key).
    elemental real(dp) function from_key(key) result(x)
        integer(int64), intent(in) :: key
        integer(int64) :: k
        if (btest(key, 63)) then
            k = ibclr(key, 63)
        else
            k = not(key)
        end if
        x = transfer(k, x)
    end function from_key

    !> The doubles of sorted keys, on `parts` threads.
    subroutine keys_to_doubles(keys, parts, x)
        integer(int64), intent(in) :: keys(:)
        integer, intent(in) :: parts
        real(dp), intent(out) :: x(:)
        integer :: i
        !$omp parallel do schedule(static) default(shared) private(i) if (parts > 1)
        do i = 1, size(x)
            x(i) = from_key(keys(i))
        end do
        !$omp end parallel do
    end subroutine keys_to_doubles

    !> The digit of pass `pass` (the least significant first) of a key.
    elemental integer function digit(key, pass)
        integer(int64), intent(in) :: key
        integer, intent(in) :: pass
        digit = int(ibits(key, (pass - 1)*radix_bits, radix_bits))
    end function digit

    !> Count every digit of a key, in the counts of each pass.
    pure subroutine count_digits(key, counts)
        integer(int64), intent(in) :: key
        integer(int64), intent(inout) :: counts(0:, :)
        integer :: pass, d
        do pass = 1, radix_passes
            d = digit(key, pass)
            counts(d, pass) = counts(d, pass) + 1
        end do
    end subroutine count_digits

    !> First index of part `part` of n keys cut into `parts` nearly equal
    !> contiguous parts (part parts + 1 gives n + 1, one past the last).
    pure integer function part_first(n, parts, part)
        integer, intent(in) :: n, parts, part
        part_first = int((int(part - 1, int64)*n)/parts) + 1
    end function part_first

    !> The counts of the digits of pass `pass` in each part of `keys`.
    subroutine count_pass(keys, pass, parts, counts)
        integer(int64), intent(in) :: keys(:)
        integer, intent(in) :: pass, parts
        integer(int64), intent(out) :: counts(0:, :)
        integer :: n, part, i, d
        n = size(keys)
        !$omp parallel do schedule(static, 1) default(shared) private(part, i, d)
        do part = 1, parts
            counts(:, part) = 0
            do i = part_first(n, parts, part), part_first(n, parts, part + 1) - 1
                d = digit(keys(i), pass)
                counts(d, part) = counts(d, part) + 1
            end do
        end do
        !$omp end parallel do
    end subroutine count_pass

    !> One stable pass: each key of `from` to the next place of its digit's
    !> bucket in `to`; within a bucket the parts come in order, each from the
    !> place where the parts before it end. `counts` is used up.
    subroutine scatter_pass(from, to, pass, parts, counts)
        integer(int64), intent(in) :: from(:)
        integer(int64), intent(inout) :: to(:)
        integer, intent(in) :: pass, parts
        integer(int64), intent(inout) :: counts(0:, :)
        integer(int64) :: place, c
        integer :: n, part, i, d
        n = size(from)
        place = 1
        do d = 0, radix_buckets - 1
            do part = 1, parts
                c = counts(d, part)
                counts(d, part) = place
                place = place + c
            end do
        end do
        !$omp parallel do schedule(static, 1) default(shared) private(part, i, d) if (parts > 1)
        do part = 1, parts
            do i = part_first(n, parts, part), part_first(n, parts, part + 1) - 1
                d = digit(from(i), pass)
                to(counts(d, part)) = from(i)
                counts(d, part) = counts(d, part) + 1
            end do
        end do
        !$omp end parallel do
    end subroutine scatter_pass

end module sphere_row_sorting
