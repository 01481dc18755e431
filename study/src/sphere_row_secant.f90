!> A secant iteration in real128 for f(x) = 0 on an interval, that reports
!> where it cannot go on instead of returning garbage.
!>
!> The functions met here (a final velocity against e) are only piecewise
!> smooth and flat in places, so each step is checked: a zero or
!> insignificant difference of f (flat), a step that leaves the interval, and
!> iterates that stop moving (stagnation) each end the iteration with their own
!> status.
module sphere_row_secant
    use sphere_row, only: qp
    implicit none
    private
    public :: secant, secant_result_t, residual_fn, secant_word
    public :: secant_converged, secant_flat, secant_left_interval, secant_stagnated, &
        secant_max_iterations, secant_invalid

    !> |f| <= f_tol reached.
    integer, parameter :: secant_converged = 0
    !> f(x_k) and f(x_{k-1}) differ by less than slope_tol * max(|f|): no slope.
    integer, parameter :: secant_flat = 1
    !> The secant step leaves [x_min, x_max]: the local slope is too small.
    integer, parameter :: secant_left_interval = 2
    !> x_k and x_{k-1} agree to the precision without |f| <= f_tol.
    integer, parameter :: secant_stagnated = 3
    !> max_iterations steps without convergence.
    integer, parameter :: secant_max_iterations = 4
    !> Starting values outside the interval, equal, or not finite.
    integer, parameter :: secant_invalid = 5

    abstract interface
        !> The residual f(x).
        function residual_fn(x) result(f)
            import :: qp
            real(qp), intent(in) :: x
            real(qp) :: f
        end function residual_fn
    end interface

    !> Outcome of a secant iteration, with its history (row 0 and 1 are the
    !> starting values).
    type :: secant_result_t
        !> One of the secant_* codes.
        integer :: status = secant_invalid
        !> Last iterate and its residual.
        real(qp) :: x = 0.0_qp, f = 0.0_qp
        !> Number of secant steps taken.
        integer :: iterations = 0
        !> Iterates and residuals, indices 0..iterations+1.
        real(qp), allocatable :: xs(:), fs(:)
    end type secant_result_t

contains

    !> Secant iteration from x0, x1 on [x_min, x_max] until |f| <= f_tol.
    !> slope_tol: relative size of f(x_k) - f(x_{k-1}) below which f counts as
    !> flat (a few units of roundoff of the residual is the natural choice).
    subroutine secant(f, x0, x1, x_min, x_max, f_tol, slope_tol, max_iterations, result)
        procedure(residual_fn) :: f
        real(qp), intent(in) :: x0, x1, x_min, x_max, f_tol, slope_tol
        integer, intent(in) :: max_iterations
        type(secant_result_t), intent(out) :: result
        real(qp) :: xa, xb, fa, fb, xc
        integer :: k
        logical :: done

        allocate (result%xs(0:max_iterations + 1), result%fs(0:max_iterations + 1))
        result%xs = 0.0_qp
        result%fs = 0.0_qp
        result%status = secant_invalid
        if (.not. (x0 >= x_min .and. x0 <= x_max .and. x1 >= x_min .and. x1 <= x_max) &
            .or. x0 == x1) return
        xa = x0
        xb = x1
        fa = f(xa)
        fb = f(xb)
        result%xs(0) = xa
        result%fs(0) = fa
        call take(0, done)
        if (done) return
        do k = 1, max_iterations
            if (abs(fb - fa) <= slope_tol*max(abs(fa), abs(fb))) then
                result%status = secant_flat
                return
            end if
            xc = xb - fb*(xb - xa)/(fb - fa)
            if (.not. (xc >= x_min .and. xc <= x_max)) then
                result%status = secant_left_interval
                return
            end if
            xa = xb
            fa = fb
            xb = xc
            fb = f(xb)
            result%iterations = k
            call take(k, done)
            if (done) return
            if (abs(xb - xa) <= 4*epsilon(xb)*abs(xb)) then
                result%status = secant_stagnated
                return
            end if
        end do
        result%status = secant_max_iterations
    contains
        !> Record xb, fb as the iterate after step k (x1 after step 0) and the
        !> answer so far; done, with the status converged, if |fb| <= f_tol.
        subroutine take(k, done)
            integer, intent(in) :: k
            logical, intent(out) :: done
            result%xs(k + 1) = xb
            result%fs(k + 1) = fb
            result%x = xb
            result%f = fb
            done = abs(fb) <= f_tol
            if (done) result%status = secant_converged
        end subroutine take
    end subroutine secant

    !> The word printed for a secant status.
    pure function secant_word(status) result(word)
        integer, intent(in) :: status
        character(len=:), allocatable :: word
        select case (status)
        case (secant_converged)
            word = "converged"
        case (secant_flat)
            word = "flat"
        case (secant_left_interval)
            word = "left_interval"
        case (secant_stagnated)
            word = "stagnated"
        case (secant_max_iterations)
            word = "max_iterations"
        case default
            word = "invalid_start"
        end select
    end function secant_word

end module sphere_row_secant
