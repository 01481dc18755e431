!> Method 4 of the comparison: fixed time steps (real64), the simplest treatment a
!> simulation package offers.
!>
!> The state is the definition's relative variables (gaps y_i, rates dy_i, x_1
!> and its rate). Every step advances all gaps by h times their rates; a gap
!> found closed (y_i <= 0) and still approaching at the end of a step collides
!> there by (6), the leftmost pair first. The gap is not moved back, so spheres
!> overlap by up to one step of approach: the run reports the deepest overlap as
!> its most negative gap. Impacts closer together than h merge into one step,
!> which is how the method loses collisions.
module sphere_row_stepping
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp, scene_dp_t, scene_check, budget
    use sphere_row_outcome, only: outcome_t, outcome_start, outcome_add
    use sphere_row_status, only: status_normal, status_max_collisions, status_budget, &
        status_invalid
    use sphere_row_impact, only: impact
    implicit none
    private
    public :: simulate_stepping, default_max_steps

    !> Default step budget: the run ends with status_budget after this many steps.
    integer(int64), parameter :: default_max_steps = 100000000_int64

contains

    !> Run a scene with fixed steps of size `h` [L/V] (h > 0).
    !>
    !> A gap collides only while it still approaches faster than scene%tol*v0:
    !> a pair that overlaps but already separates must not be struck again, or
    !> it would be turned back into approach. The run ends normally when no rate
    !> is below -scene%tol*v0 (the definition's criterion), with status_budget
    !> after `max_steps` steps (default default_max_steps), and with
    !> status_max_collisions after budget(scene) impacts. Collision times
    !> are the ends of the steps in which they were found. `record` asks for every
    !> collision in `out`.
    pure subroutine simulate_stepping(scene, h, out, record, max_steps)
        type(scene_dp_t), intent(in) :: scene
        real(dp), intent(in) :: h
        type(outcome_t), intent(inout) :: out
        logical, intent(in), optional :: record
        integer(int64), intent(in), optional :: max_steps
        real(dp) :: y(scene%p - 1), dy(scene%p - 1)
        real(dp) :: dx1, tv, t, min_gap
        integer(int64) :: steps, steps_max
        integer :: p, i, code
        logical :: hit, closing

        call outcome_start(out, scene%p, record)
        call scene_check(scene, out%status, out%message)
        if (out%status /= status_normal) return
        if (.not. (h > 0.0_dp .and. h <= huge(1.0_dp))) then
            out%status = status_invalid
            out%message = "h: allowed a finite step h > 0"
            return
        end if
        steps_max = default_max_steps
        if (present(max_steps)) steps_max = max_steps
        p = scene%p
        tv = scene%tol*scene%v0
        y = scene%a
        dy = 0.0_dp
        dy(1) = -scene%v0
        dx1 = scene%v0
        min_gap = 0.0_dp
        steps = 0
        t = 0.0_dp

        ! Rates change only at impacts, so the end test is redone only there.
        closing = any(dy < -tv)
        do while (closing)
            if (steps >= steps_max) then
                out%status = status_budget
                write (out%message, "(a, i0, a)") "step budget of ", steps_max, " reached"
                exit
            end if
            steps = steps + 1
            y = y + dy*h
            hit = .false.
            do i = 1, p - 1
                if (y(i) <= 0.0_dp) hit = .true.
            end do
            if (.not. hit) cycle
            ! Time is formed from the step count so that it does not drift.
            t = real(steps, dp)*h
            do i = 1, p - 1
                min_gap = min(min_gap, y(i))
                if (y(i) <= 0.0_dp .and. dy(i) < -tv) then
                    if (out%n >= budget(scene)) then
                        out%status = status_max_collisions
                        exit
                    end if
                    call impact(scene%e, scene%m, i, dy, dx1)
                    call outcome_add(out, real(t, qp), i)
                end if
            end do
            if (out%status /= status_normal) exit
            closing = any(dy < -tv)
        end do

        out%steps = steps
        out%min_gap = real(min_gap, qp)
        out%y = real(y, qp)
        out%v(1) = real(dx1, qp)
        do i = 1, p - 1
            out%v(i + 1) = out%v(i) + real(dy(i), qp)
        end do
    end subroutine simulate_stepping

end module sphere_row_stepping
