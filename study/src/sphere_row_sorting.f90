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
    !> Parts of the radix sort's first pass: at least min_part_size keys each
    !> (fewer are not worth a thread's start), at most max_parts of them (more
    !> than threads, so that a thread held up by other work holds up little).
    integer, parameter :: min_part_size = 65536, max_parts = 16

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

    !> Sort doubles into ascending order in O(n): a radix sort on 64-bit keys
    !> that order as the doubles do (see order_key). NaNs are not ordered; -0
    !> sorts before +0. A digit that is the same in every key (the exponent's
    !> top bits of values in [0, 1], say) is left out.
    !>
    !> The keys are first distributed by their most significant digit that
    !> differs among them, stably, into its buckets; each bucket is then
    !> sorted on its own, least significant digit first (it is small enough
    !> to stay in cache). With OpenMP the keys are cut into parts, each
    !> counted and distributed by one thread (a bucket takes the parts in
    !> order), and the buckets are shared among the threads: every step is
    !> that of one thread, so the result is the same for any number of them,
    !> and the threads meet only three times.
    subroutine radix_sort(x)
        real(dp), intent(inout) :: x(:)
        integer(int64), allocatable :: key(:), tmp(:), counts(:, :, :), place(:, :)
        integer(int64) :: starts(0:radix_buckets)
        integer :: n, parts, part, i, top, d
        n = size(x)
        if (n < 2) return
        parts = max(1, min(max_parts, n/min_part_size))
        allocate (key(n), tmp(n), counts(0:radix_buckets - 1, radix_passes, parts))
        allocate (place(0:radix_buckets - 1, parts))
        !$omp parallel do schedule(dynamic, 1) default(shared) private(part, i) if (parts > 1)
        do part = 1, parts
            counts(:, :, part) = 0
            do i = part_first(n, parts, part), part_first(n, parts, part + 1) - 1
                key(i) = order_key(x(i))
                call count_digits(key(i), counts(:, :, part))
            end do
        end do
        !$omp end parallel do
        ! the most significant digit that differs among the keys (none: all equal)
        top = radix_passes
        do while (maxval(sum(counts(:, top, :), dim=2)) == n)
            top = top - 1
            if (top == 0) return
        end do
        call bucket_places(counts(:, top, :), place, starts)
        !$omp parallel do schedule(dynamic, 1) default(shared) private(part, i, d) if (parts > 1)
        do part = 1, parts
            do i = part_first(n, parts, part), part_first(n, parts, part + 1) - 1
                d = digit(key(i), top)
                tmp(place(d, part)) = key(i)
                place(d, part) = place(d, part) + 1
            end do
        end do
        !$omp end parallel do
        !$omp parallel do schedule(dynamic, 1) default(shared) private(d) if (parts > 1)
        do d = 0, radix_buckets - 1
            associate (lo => starts(d), hi => starts(d + 1) - 1)
                if (hi >= lo) call lsd_sort(tmp(lo:hi), key(lo:hi), top - 1, x(lo:hi))
            end associate
        end do
        !$omp end parallel do
    end subroutine radix_sort

    !> Sort keys on their digits 1 ... passes (the higher ones being the same
    !> in every key), least significant first, each pass stable; `work` is
    !> as long as `keys`; x gets the doubles of the sorted keys.
    subroutine lsd_sort(keys, work, passes, x)
        integer(int64), intent(inout) :: keys(:), work(:)
        integer, intent(in) :: passes
        real(dp), intent(out) :: x(:)
        integer(int64) :: counts(0:radix_buckets - 1, radix_passes), starts(0:radix_buckets)
        integer(int64) :: place(0:radix_buckets - 1, 1)
        integer :: i, pass, d
        logical :: in_keys
        counts = 0
        do i = 1, size(keys)
            call count_digits(keys(i), counts)
        end do
        in_keys = .true.
        do pass = 1, passes
            if (maxval(counts(:, pass)) == size(keys)) cycle
            call bucket_places(counts(:, pass:pass), place, starts)
            if (in_keys) then
                call scatter(keys, work)
            else
                call scatter(work, keys)
            end if
            in_keys = .not. in_keys
        end do
        if (in_keys) then
            x = from_key(keys)
        else
            x = from_key(work)
        end if

    contains

        !> One stable pass: each key to the next place of its digit's bucket.
        subroutine scatter(from, to)
            integer(int64), intent(in) :: from(:)
            integer(int64), intent(out) :: to(:)
            integer :: j, dj
            do j = 1, size(from)
                dj = digit(from(j), pass)
                to(place(dj, 1)) = from(j)
                place(dj, 1) = place(dj, 1) + 1
            end do
        end subroutine scatter

    end subroutine lsd_sort

    !> Where each part's keys of each digit go: counts(d, part) keys of digit
    !> d in part `part`; the buckets in the order of their digits, each
    !> holding its parts in order. `starts(d)` is where bucket d begins
    !> (starts(radix_buckets) is one past the end).
    pure subroutine bucket_places(counts, place, starts)
        integer(int64), intent(in) :: counts(0:, :)
        integer(int64), intent(out) :: place(0:, :), starts(0:)
        integer(int64) :: next
        integer :: d, part
        next = 1
        do d = 0, radix_buckets - 1
            starts(d) = next
            do part = 1, size(counts, 2)
                place(d, part) = next
                next = next + counts(d, part)
            end do
        end do
        starts(radix_buckets) = next
    end subroutine bucket_places

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

end module sphere_row_sorting
