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

    !> Sort doubles into ascending order in O(n): x, or into x the values of
    !> `source` (as many), which stays as it is. A radix sort on 64-bit keys
    !> that order as the doubles do (see order_key). NaNs are not ordered; -0
    !> sorts before +0. A digit that is the same in every key (the exponent's
    !> top bits of values in [0, 1], say) is left out.
    !>
    !> The values are first distributed by the most significant digit of
    !> their keys that differs among them, stably, into its buckets; each
    !> bucket is then sorted on its own, least significant digit first (a
    !> fraction of the values, nearer the cache). With OpenMP the values are
    !> cut into parts, each counted and distributed by one thread (a bucket
    !> takes the parts in order), and the buckets are shared among the
    !> threads: every step is that of one thread, so the result is the same
    !> for any number of them, and the threads meet only three times.
    subroutine radix_sort(x, source)
        real(dp), intent(inout) :: x(:)
        real(dp), intent(in), optional :: source(:)
        real(dp), allocatable :: tmp(:)
        integer(int64), allocatable :: counts(:, :, :), place(:, :)
        integer(int64) :: starts(0:radix_buckets)
        integer :: n, parts, top, d
        n = size(x)
        parts = max(1, min(max_parts, n/min_part_size))
        allocate (tmp(n), counts(0:radix_buckets - 1, radix_passes, parts))
        allocate (place(0:radix_buckets - 1, parts))
        if (present(source)) then
            call count_parts(source)
        else
            call count_parts(x)
        end if
        ! the most significant digit that differs among the keys (none: all
        ! equal, or fewer than two)
        top = radix_passes
        do while (maxval(sum(counts(:, top, :), dim=2)) == n)
            top = top - 1
            if (top == 0) exit
        end do
        if (top == 0) then
            if (present(source)) x = source
            return
        end if
        call bucket_places(counts(:, top, :), place, starts)
        if (present(source)) then
            call distribute(source)
        else
            call distribute(x)
        end if
        !$omp parallel do schedule(dynamic, 1) default(shared) private(d) if (parts > 1)
        do d = 0, radix_buckets - 1
            associate (lo => starts(d), hi => starts(d + 1) - 1)
                if (hi >= lo) call lsd_sort(tmp(lo:hi), x(lo:hi), top - 1)
            end associate
        end do
        !$omp end parallel do

    contains

        !> The counts of every digit of the keys in each part of `from`.
        subroutine count_parts(from)
            real(dp), intent(in) :: from(:)
            integer :: part, i
            !$omp parallel do schedule(dynamic, 1) default(shared) private(part, i) &
            !$omp if (parts > 1)
            do part = 1, parts
                counts(:, :, part) = 0
                do i = part_first(n, parts, part), part_first(n, parts, part + 1) - 1
                    call count_digits(order_key(from(i)), counts(:, :, part))
                end do
            end do
            !$omp end parallel do
        end subroutine count_parts

        !> The values of `from` into tmp, each to the next place of the bucket
        !> of its key's top digit.
        subroutine distribute(from)
            real(dp), intent(in) :: from(:)
            integer :: part, i, dj
            !$omp parallel do schedule(dynamic, 1) default(shared) private(part, i, dj) &
            !$omp if (parts > 1)
            do part = 1, parts
                do i = part_first(n, parts, part), part_first(n, parts, part + 1) - 1
                    dj = digit(order_key(from(i)), top)
                    tmp(place(dj, part)) = from(i)
                    place(dj, part) = place(dj, part) + 1
                end do
            end do
            !$omp end parallel do
        end subroutine distribute

    end subroutine radix_sort

    !> Sort x on the digits 1 ... passes of its keys (the higher ones being
    !> the same in every key) into `sorted`, least significant digit first,
    !> each pass stable; x is the work space.
    subroutine lsd_sort(x, sorted, passes)
        real(dp), intent(inout) :: x(:)
        real(dp), intent(out) :: sorted(:)
        integer, intent(in) :: passes
        integer(int64) :: counts(0:radix_buckets - 1, radix_passes), starts(0:radix_buckets)
        integer(int64) :: place(0:radix_buckets - 1, 1)
        integer :: i, pass
        logical :: in_x
        counts = 0
        do i = 1, size(x)
            call count_digits(order_key(x(i)), counts)
        end do
        in_x = .true.
        do pass = 1, passes
            if (maxval(counts(:, pass)) == size(x)) cycle
            call bucket_places(counts(:, pass:pass), place, starts)
            if (in_x) then
                call scatter(x, sorted)
            else
                call scatter(sorted, x)
            end if
            in_x = .not. in_x
        end do
        if (in_x) sorted = x

    contains

        !> One stable pass: each value to the next place of its digit's bucket.
        subroutine scatter(from, to)
            real(dp), intent(in) :: from(:)
            real(dp), intent(out) :: to(:)
            integer :: j, dj
            do j = 1, size(from)
                dj = digit(order_key(from(j)), pass)
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
