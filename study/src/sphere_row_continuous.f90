!> Method 3 of the comparison: the equations of motion (4) integrated by GSL's
!> `gsl_odeiv2` (real64), each gap watched as a state event.
!>
!> The state vector holds the definition's relative variables: the p-1 gaps
!> y_i and x_1, then the p-1 rates dy_i and dx_1 (2p values). Between impacts
!> every second derivative is zero. An adaptive Runge-Kutta integrator takes
!> steps; when a gap changes sign from positive to non-positive within a step,
!> the crossing is located by bisection on the step size, re-integrating one
!> step from the start of the step each time, until the bracket is shorter than
!> the event tolerance. The collision update (6) is applied at the left end of
!> the bracket (where every gap is still positive) and the integrator is
!> restarted. One number, `tol`, sets the integrator's local error, the event
!> tolerance in time and the end criterion, all relative to the scene's scales.
module sphere_row_continuous
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
    use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_funptr, &
        c_null_ptr, c_null_funptr, c_funloc, c_loc, c_f_pointer, c_associated
    use sphere_row, only: dp, qp, scene_dp_t, scene_check, budget
    use sphere_row_outcome, only: outcome_t, outcome_start, outcome_add
    use sphere_row_status, only: status_normal, status_max_collisions, status_budget, &
        status_solver_failed, status_invalid
    use sphere_row_impact, only: impact
    use sphere_row_gsl_ode, only: gsl_odeiv2_system, gsl_success, gsl_odeiv2_step_rk8pd, &
        gsl_odeiv2_step_rkf45, gsl_odeiv2_step_alloc, gsl_odeiv2_step_apply, &
        gsl_odeiv2_step_reset, gsl_odeiv2_step_free, gsl_odeiv2_control_scaled_new, &
        gsl_odeiv2_control_free, gsl_odeiv2_evolve_alloc, gsl_odeiv2_evolve_apply, &
        gsl_odeiv2_evolve_reset, gsl_odeiv2_evolve_free, gsl_set_error_handler_off, &
        gsl_set_error_handler
    implicit none
    private
    public :: simulate_ode, stepper_rk8pd, stepper_rkf45, stepper_name

    !> GSL's rk8pd: explicit embedded Runge-Kutta Prince-Dormand (8, 9).
    integer, parameter :: stepper_rk8pd = 1
    !> GSL's rkf45: explicit embedded Runge-Kutta-Fehlberg (4, 5).
    integer, parameter :: stepper_rkf45 = 2

    !> First trial step, as a fraction of the time scale L/v0 (L = max(d, a_i)):
    !> small enough for the first impact, and the control grows it quickly.
    real(dp), parameter :: first_step_fraction = 1.0e-2_dp
    !> The event tolerance never goes below this many roundoffs of the time scale,
    !> where bisection could no longer halve the bracket.
    real(dp), parameter :: event_floor_ulps = 4.0_dp
    !> Default horizon, in units of L/v0: the run ends with status_budget there.
    real(dp), parameter :: default_horizon = 1.0e9_dp

contains

    !> Name of a stepper constant.
    pure function stepper_name(stepper) result(name)
        integer, intent(in) :: stepper
        character(len=:), allocatable :: name
        select case (stepper)
        case (stepper_rk8pd)
            name = "rk8pd"
        case (stepper_rkf45)
            name = "rkf45"
        case default
            name = "unknown"
        end select
    end function stepper_name

    !> Run a scene to its end by ODE integration with events.
    !>
    !> `tol` (0 < tol < 1) is the relative accuracy asked for: the integrator's
    !> local error per component is below tol times the component's scale (L
    !> for positions, v0 for rates) plus tol times its size; each impact is
    !> located to within tol*L/v0 in time; and the run ends when every rate is
    !> at least -tol*v0 (the definition's criterion with tol as the
    !> insignificant rate). `stepper` is stepper_rk8pd (default) or
    !> stepper_rkf45. The run ends with status_max_collisions after
    !> `max_events` impacts (default budget(scene)), with status_budget at
    !> time `t_max` (default 1e9 L/v0), and with status_solver_failed if GSL
    !> reports an error. scene%tol is not used. `record` asks for every
    !> collision in `out`.
    subroutine simulate_ode(scene, tol, out, record, stepper, max_events, t_max)
        type(scene_dp_t), intent(in) :: scene
        real(dp), intent(in) :: tol
        type(outcome_t), intent(inout) :: out
        logical, intent(in), optional :: record
        integer, intent(in), optional :: stepper, max_events
        real(dp), intent(in), optional :: t_max

        integer(c_int), target :: half
        type(gsl_odeiv2_system) :: sys
        type(c_ptr) :: step_type, step, control, evolve
        type(c_funptr) :: previous_handler
        real(c_double), allocatable :: u(:), u0(:), u_lo(:), u_mid(:), u_err(:), scale(:)
        real(c_double) :: t, t0, h, t_lo, t_hi, t_mid, horizon
        real(dp) :: length, time_scale, tv, t_tol
        integer :: p, n, events_max, k, code

        call outcome_start(out, scene%p, record)
        call scene_check(scene, out%status, out%message)
        if (out%status /= status_normal) return
        if (.not. (tol > 0.0_dp .and. tol < 1.0_dp)) then
            out%status = status_invalid
            write (out%message, "(a, es10.3, a)") "tol = ", tol, ": allowed 0 < tol < 1"
            return
        end if
        call set_up()

        t = 0.0_c_double
        h = first_step_fraction*time_scale
        do while (out%status == status_normal)
            call touching_impacts()
            if (out%status /= status_normal) exit
            if (all(u(p + 1:n - 1) >= -tv)) exit
            if (t >= horizon) then
                out%status = status_budget
                write (out%message, "(a, es10.3)") "time budget reached at t = ", t
                exit
            end if
            t0 = t
            u0 = u
            code = gsl_odeiv2_evolve_apply(evolve, control, step, sys, t, horizon, h, u)
            out%steps = out%steps + 1
            if (code /= gsl_success) then
                call solver_failed("gsl_odeiv2_evolve_apply", code)
                exit
            end if
            if (.not. crossed(u)) then
                out%min_gap = min(out%min_gap, real(minval(u(1:p - 1)), qp))
                cycle
            end if
            call locate()
            if (out%status /= status_normal) exit
            call collide(first_crossing())
            code = gsl_odeiv2_evolve_reset(evolve)
            code = gsl_odeiv2_step_reset(step)
        end do

        call finish()

    contains

        !> Scales, the tolerances derived from them, the initial state (sphere 1
        !> moving at v0 toward the resting row) and GSL's solver objects.
        subroutine set_up()
            p = scene%p
            n = 2*p
            events_max = budget(scene)
            if (present(max_events)) events_max = max_events
            length = max(scene%d, maxval(scene%a))
            if (length <= 0.0_dp) length = 1.0_dp
            time_scale = length/scene%v0
            horizon = default_horizon*time_scale
            if (present(t_max)) horizon = t_max
            tv = tol*scene%v0
            t_tol = max(tol, event_floor_ulps*epsilon(1.0_dp))*time_scale

            step_type = gsl_odeiv2_step_rk8pd
            if (present(stepper)) then
                if (stepper == stepper_rkf45) step_type = gsl_odeiv2_step_rkf45
            end if
            half = int(p, c_int)
            sys%function = c_funloc(free_motion)
            sys%jacobian = c_null_funptr
            sys%dimension = int(n, c_size_t)
            sys%params = c_loc(half)
            allocate (u(n), u0(n), u_lo(n), u_mid(n), u_err(n), scale(n))
            scale(1:p) = length
            scale(p + 1:n) = scene%v0
            u(1:p - 1) = scene%a
            u(p) = 0.0_dp
            u(p + 1:n) = 0.0_dp
            u(p + 1) = -scene%v0
            u(n) = scene%v0

            previous_handler = gsl_set_error_handler_off()
            step = gsl_odeiv2_step_alloc(step_type, sys%dimension)
            control = gsl_odeiv2_control_scaled_new(real(tol, c_double), real(tol, c_double), &
                1.0_c_double, 0.0_c_double, scale, sys%dimension)
            evolve = gsl_odeiv2_evolve_alloc(sys%dimension)
            if (.not. (c_associated(step) .and. c_associated(control) .and. &
                c_associated(evolve))) then
                out%status = status_solver_failed
                out%message = "GSL could not allocate the ODE solver"
            end if
        end subroutine set_up

        !> Free GSL's solver objects, restore its error handler, and hand the
        !> final gaps and velocities to `out`.
        subroutine finish()
            if (c_associated(evolve)) call gsl_odeiv2_evolve_free(evolve)
            if (c_associated(control)) call gsl_odeiv2_control_free(control)
            if (c_associated(step)) call gsl_odeiv2_step_free(step)
            previous_handler = gsl_set_error_handler(previous_handler)
            out%y = real(u(1:p - 1), qp)
            out%v(1) = real(u(n), qp)
            do k = 1, p - 1
                out%v(k + 1) = out%v(k) + real(u(p + k), qp)
            end do
        end subroutine finish

        !> A gap that was positive at the start of the step is not any more.
        logical function crossed(state)
            real(c_double), intent(in) :: state(:)
            crossed = any(state(1:p - 1) <= 0.0_c_double .and. u0(1:p - 1) > 0.0_c_double)
        end function crossed

        !> Bisection on the step size: shrink [t_lo, t_hi] around the first
        !> crossing in the step just taken, re-integrating one step from (t0, u0)
        !> to each midpoint. Leaves the state at t_lo in (t, u).
        subroutine locate()
            t_lo = t0
            t_hi = t
            u_lo = u0
            do while (t_hi - t_lo > t_tol)
                t_mid = t_lo + 0.5_c_double*(t_hi - t_lo)
                if (t_mid <= t_lo .or. t_mid >= t_hi) exit
                u_mid = u0
                code = gsl_odeiv2_step_apply(step, t0, t_mid - t0, u_mid, u_err, c_null_ptr, &
                    c_null_ptr, sys)
                out%steps = out%steps + 1
                if (code /= gsl_success) then
                    call solver_failed("gsl_odeiv2_step_apply", code)
                    return
                end if
                if (crossed(u_mid)) then
                    t_hi = t_mid
                else
                    t_lo = t_mid
                    u_lo = u_mid
                end if
            end do
            t = t_lo
            u = u_lo
            out%min_gap = min(out%min_gap, real(minval(u(1:p - 1)), qp))
        end subroutine locate

        !> The pair that closes first from the located state: the smallest
        !> gap / approach rate among the closing gaps.
        integer function first_crossing() result(kk)
            integer :: i
            real(dp) :: ti, best
            kk = 0
            best = huge(1.0_dp)
            do i = 1, p - 1
                if (u(p + i) < 0.0_dp) then
                    ti = max(u(i), 0.0_dp)/(-u(p + i))
                    if (ti < best) then
                        best = ti
                        kk = i
                    end if
                end if
            end do
        end function first_crossing

        !> Collisions due at once: gaps already closed that still approach
        !> faster than tol*v0 (a touching row, or two impacts within the event
        !> tolerance). Fastest approach first, then the leftmost pair.
        subroutine touching_impacts()
            integer :: i, kk
            do
                kk = 0
                do i = 1, p - 1
                    if (u(i) <= 0.0_dp .and. u(p + i) < -tv) then
                        if (kk == 0) then
                            kk = i
                        else if (u(p + i) < u(p + kk)) then
                            kk = i
                        end if
                    end if
                end do
                if (kk == 0) return
                call collide(kk)
                if (out%status /= status_normal) return
            end do
        end subroutine touching_impacts

        !> Impact of pair (kk, kk+1) at the current time, with the budget check.
        subroutine collide(kk)
            integer, intent(in) :: kk
            if (kk == 0) return
            if (out%n >= events_max) then
                out%status = status_max_collisions
                write (out%message, "(a, i0, a)") "event budget of ", events_max, " reached"
                return
            end if
            call impact(scene%e, scene%m, kk, u(p + 1:n - 1), u(n))
            call outcome_add(out, real(t, qp), kk)
        end subroutine collide

        subroutine solver_failed(where, status)
            character(len=*), intent(in) :: where
            integer, intent(in) :: status
            out%status = status_solver_failed
            write (out%message, "(a, i0)") where//" returned GSL error ", status
        end subroutine solver_failed

    end subroutine simulate_ode

    !> Right-hand side of (4) for GSL: the derivative of each gap and of x_1 is
    !> its rate, and no rate changes between impacts. `params` points to p.
    function free_motion(t, u, dudt, params) bind(C) result(status)
        real(c_double), value :: t
        real(c_double), intent(in) :: u(*)
        real(c_double), intent(out) :: dudt(*)
        type(c_ptr), value :: params
        integer(c_int) :: status
        integer(c_int), pointer :: p
        call c_f_pointer(params, p)
        dudt(1:p) = u(p + 1:2*p)
        dudt(p + 1:2*p) = 0.0_c_double
        status = gsl_success
        ! A time that is not a number can only come from a broken step: fail it.
        if (ieee_is_nan(t)) status = -1_c_int
    end function free_motion

end module sphere_row_continuous
