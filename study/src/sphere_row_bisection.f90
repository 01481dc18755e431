!> Bisection of the study in real128: the one place that halves a bracket.
!>
!> `bisect` narrows [lo, hi] around the single change of a two-valued test
!> (`below` true at lo, false at hi): collapsed against finite runs, the sign
!> of a discriminant, a right against a wrong collision sequence.
!> `bisect_changes` finds every change of a many-valued label between two
!> points, as far as midpoints separate them. `bisect_ahead` takes the very
!> steps of `bisect`, with the tests of the next steps made beforehand on the
!> other OpenMP threads.
module sphere_row_bisection
    use, intrinsic :: iso_fortran_env, only: int64
    !$ use omp_lib, only: omp_get_max_threads, omp_in_parallel
    use sphere_row, only: qp
    implicit none
    private
    public :: side_fn, class_fn, bisect, bisect_ahead, bisect_changes

    abstract interface
        !> Which side of the change x lies on: true on the side of lo.
        function side_fn(x) result(below)
            import :: qp, int64
            real(qp), intent(in) :: x
            logical :: below
        end function side_fn

        !> A label of the outcome at e (for instance a sequence fingerprint):
        !> its changes are what bisect_changes looks for.
        function class_fn(e) result(class)
            import :: qp, int64
            real(qp), intent(in) :: e
            integer(int64) :: class
        end function class_fn
    end interface

contains

    !> Halve [lo, hi] (below(lo) true, below(hi) false) until it is at most
    !> `width` wide, `max_steps` tests were made, or the midpoint equals an
    !> end (the bracket is as narrow as real128 allows). The midpoint moves
    !> lo where below() holds there and hi where it does not.
    subroutine bisect(below, lo, hi, width, max_steps)
        procedure(side_fn) :: below
        real(qp), intent(inout) :: lo, hi
        real(qp), intent(in) :: width
        integer, intent(in) :: max_steps
        real(qp) :: mid
        integer :: step
        do step = 1, max_steps
            if (hi - lo <= width) exit
            mid = 0.5_qp*(lo + hi)
            if (mid <= lo .or. mid >= hi) exit
            if (below(mid)) then
                lo = mid
            else
                hi = mid
            end if
        end do
    end subroutine bisect

    !> `bisect` with its next tests run side by side, one per OpenMP thread:
    !> the midpoint, then the midpoints of the halves it may leave, level by
    !> level, as many as there are threads, the half on the side of the last
    !> step first (bisecting towards a change, the steps tend to run in
    !> stretches to one side; on two threads, the one half tested). The walk
    !> down that tree takes bisect's steps, so lo and hi end bit for bit where
    !> bisect leaves them, on any number of threads; the tests off its path
    !> are thrown away. Worth it where each test is long (a run of thousands
    !> of collisions); `below` must be safe to call on several threads at
    !> once. Called on a thread of a parallel region, it is bisect (no
    !> threads to spare).
    subroutine bisect_ahead(below, lo, hi, width, max_steps)
        procedure(side_fn) :: below
        real(qp), intent(inout) :: lo, hi
        real(qp), intent(in) :: width
        integer, intent(in) :: max_steps
        real(qp), allocatable :: a(:), b(:), mid(:)
        logical, allocatable :: tested(:), side(:)
        logical :: last
        integer :: nodes, k, step
        nodes = 1
        !$ if (.not. omp_in_parallel()) nodes = max(1, omp_get_max_threads())
        ! node k brackets [a(k), b(k)]; node 2k is the half of it left if
        ! below() at its midpoint equals `last`, the side of the last step
        ! taken (the half above the midpoint if that is true), node 2k+1 the
        ! other half
        allocate (a(nodes), b(nodes), mid(nodes), tested(nodes), side(nodes))
        step = 0
        last = .true.
        do
            a(1) = lo
            b(1) = hi
            do k = 1, nodes
                if (k > 1) then
                    tested(k) = tested(k/2)
                    if (.not. tested(k)) cycle
                    a(k) = merge(mid(k/2), a(k/2), (mod(k, 2) == 0) .eqv. last)
                    b(k) = merge(b(k/2), mid(k/2), (mod(k, 2) == 0) .eqv. last)
                end if
                mid(k) = 0.5_qp*(a(k) + b(k))
                tested(k) = b(k) - a(k) > width .and. mid(k) > a(k) .and. mid(k) < b(k)
            end do
            !$omp parallel do schedule(dynamic, 1) default(shared) private(k) if (nodes > 1)
            do k = 1, nodes
                if (tested(k)) side(k) = below(mid(k))
            end do
            !$omp end parallel do
            k = 1
            do while (k <= nodes)
                if (step >= max_steps .or. .not. tested(k)) return
                step = step + 1
                if (side(k)) then
                    lo = mid(k)
                else
                    hi = mid(k)
                end if
                k = 2*k + merge(0, 1, side(k) .eqv. last)
            end do
            last = side(k/2)
        end do
    end subroutine bisect_ahead

    !> Every change of class(e) between a < b (classes ca /= cb), bisected
    !> until the bracket is at most `resolution` wide; the bracket midpoints
    !> are appended to `boundaries`. Both halves are searched whenever the
    !> midpoint differs from both ends, so several changes between a and b are
    !> found as long as a midpoint falls between them.
    recursive subroutine bisect_changes(classify, a, b, ca, cb, resolution, boundaries)
        procedure(class_fn) :: classify
        real(qp), intent(in) :: a, b, resolution
        integer(int64), intent(in) :: ca, cb
        real(qp), allocatable, intent(inout) :: boundaries(:)
        real(qp) :: m
        integer(int64) :: cm
        m = 0.5_qp*(a + b)
        if (b - a <= resolution .or. m <= a .or. m >= b) then
            boundaries = [boundaries, m]
            return
        end if
        cm = classify(m)
        if (cm /= ca) call bisect_changes(classify, a, m, ca, cm, resolution, boundaries)
        if (cm /= cb) call bisect_changes(classify, m, b, cm, cb, resolution, boundaries)
    end subroutine bisect_changes

end module sphere_row_bisection
