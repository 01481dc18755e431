!> Bisection of the study in real128: the one place that halves a bracket.
!>
!> `bisect` narrows [lo, hi] around the single change of a two-valued test
!> (`below` true at lo, false at hi): collapsed against finite runs, the sign
!> of a discriminant, a right against a wrong collision sequence.
!> `bisect_changes` finds every change of a many-valued label between two
!> points, as far as midpoints separate them.
module sphere_row_bisection
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp
    implicit none
    private
    public :: side_fn, class_fn, bisect, bisect_changes

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
