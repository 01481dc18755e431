!> The precision a scene needs, chosen per scene with a certificate.
!>
!> `simulate_auto` runs a real128 scene first in real64 with the rounding
!> certificate of simulate_certified (every decision of the run beats a
!> running bound on the rounding error): if it holds, real64 has taken the
!> decisions exact arithmetic takes, and its results lie within the bounds of
!> the exact ones. Otherwise the scene runs in real128 with the engine's full
!> rules, once (the certificate is applied there too only if asked for).
module sphere_row_auto
    use sphere_row_kinds, only: dp, qp
    use sphere_row_status, only: event_collision, status_invalid, answer_exact
    use sphere_row_engine_qp, only: scene_t, run_t, bounds_t, event_log_t, simulate_wp, &
        simulate_certified_wp
    use sphere_row_engine_dp, only: scene_dp_t => scene_t, run_dp_t => run_t, &
        bounds_dp_t => bounds_t, event_log_dp_t => event_log_t, &
        certified_dp => simulate_certified_wp, simulate_dp => simulate_wp, &
        order_premise_dp => order_premise_wp
    implicit none
    private
    public :: auto_t, simulate_auto, simulate_in_dp, order_premise_in_dp, velocity_bound

    !> Which precision answered a scene and how far its results may be from
    !> exact arithmetic's.
    type :: auto_t
        !> "dp" or "qp".
        character(len=2) :: answered = "qp"
        !> True if the answering run's certificate holds.
        logical :: certified = .false.
        !> Largest bound on a final velocity [v0 units of the scene] (0 if not
        !> certified), and why the real64 run was not enough (blank if it was).
        real(qp) :: v_bound = 0.0_qp
        !> The same bound for each sphere (size p where certified).
        real(qp), allocatable :: v_bounds(:)
        character(len=:), allocatable :: why_not_dp
    end type auto_t

contains

    !> Run `scene` in the precision it needs; `run` holds the answer in
    !> real128 whichever kind computed it, and `pairs`, if present, its
    !> collision sequence (the left sphere of each pair, in order). real64 is
    !> not tried on a row that real128 runs with its calendar (p >=
    !> scene%calendar_from, tol >= real128's epsilon): the certificate scans
    !> every gap at every collision, where that calendar takes O(log p) (an
    !> elastic row of 20,000 spheres of graded masses, certified in real64:
    !> 1.87 s, against 0.06 s in real128). The real64 run stops at the first
    !> decision its certificate cannot take,
    !> and the scene then runs once in real128, whose answer carries the
    !> engine's own label (auto%certified false), as with precision qp. Only
    !> with `certify_qp` is that run certified as well, by a second run of the
    !> certificate, which scans every gap at every collision (O(p), where the
    !> engine's calendar of a long row takes O(log p)).
    subroutine simulate_auto(scene, run, auto, pairs, certify_qp)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(inout) :: run
        type(auto_t), intent(out) :: auto
        integer, allocatable, intent(inout), optional :: pairs(:)
        logical, intent(in), optional :: certify_qp
        type(scene_dp_t) :: low
        type(run_dp_t) :: run_low
        type(bounds_dp_t) :: bounds_low
        type(bounds_t) :: bounds
        type(run_t) :: check
        type(event_log_dp_t) :: log_low
        type(event_log_t) :: log
        logical :: long, done
        ! (a row real128 runs with its calendar: p >= calendar_from, tol at least
        ! real128's epsilon, as run_start decides)
        long = scene%p >= scene%calendar_from .and. scene%tol >= epsilon(1.0_qp)
        auto%why_not_dp = "a long row (p >= calendar_from): the certificate scans every gap " &
            //"at every collision"
        if (.not. long) then
            auto%why_not_dp = "the scene's values are beyond real64"
            if (fits_dp(scene)) then
                call try_real64(done)
                if (done) return
            end if
        end if
        if (present(pairs)) then
            call simulate_wp(scene, run, log)
            pairs = pack(log%first(1:log%n), log%kind(1:log%n) == event_collision)
        else
            call simulate_wp(scene, run)
        end if
        auto%answered = "qp"
        if (.not. present(certify_qp)) return
        if (.not. certify_qp) return
        call simulate_certified_wp(scene, check, bounds)
        auto%certified = bounds%certified .and. check%n == run%n .and. check%status == run%status
        if (auto%certified) then
            auto%v_bounds = bounds%v
            auto%v_bound = maxval(auto%v_bounds)
        end if
    contains
        !> The scene in real64 under the certificate; done if it holds (and
        !> every result is finite), then `run` and `auto` hold its answer.
        subroutine try_real64(done)
            logical, intent(out) :: done
            call to_dp(scene, low)
            if (present(pairs)) then
                call certified_dp(low, run_low, bounds_low, log_low)
            else
                call certified_dp(low, run_low, bounds_low)
            end if
            auto%why_not_dp = bounds_low%why
            done = bounds_low%certified
            if (.not. done) return
            done = finite(run_low, bounds_low)
            if (.not. done) then
                auto%why_not_dp = "a result or its bound beyond real64's range"
                return
            end if
            call from_dp(run_low, run)
            auto%answered = "dp"
            auto%certified = .true.
            auto%v_bounds = real(bounds_low%v, qp)
            auto%v_bound = maxval(auto%v_bounds)
            if (present(pairs)) pairs = pack(log_low%first(1:log_low%n), &
                log_low%kind(1:log_low%n) == event_collision)
        end subroutine try_real64
    end subroutine simulate_auto

    !> The bound on sphere i's final velocity, as sphere-row writes it: the
    !> sphere's own (run%v_bounds, its rounding included) where the run gives
    !> one, else run%v_bound; where simulate_auto's certificate holds and the
    !> answer is exact (rounding only), the smaller of that and the
    !> certificate's bound of the same rounding. `auto` as simulate_auto left
    !> it (a default auto_t for a run made otherwise).
    pure real(qp) function velocity_bound(run, auto, i) result(bound)
        type(run_t), intent(in) :: run
        type(auto_t), intent(in) :: auto
        integer, intent(in) :: i
        bound = run%v_bound
        if (allocated(run%v_bounds)) bound = run%v_bounds(i)
        if (auto%certified .and. run%answer == answer_exact .and. allocated(auto%v_bounds)) then
            bound = min(bound, auto%v_bounds(i))
        end if
    end function velocity_bound

    !> Every result and bound of a real64 run is finite.
    pure logical function finite(run, bounds)
        type(run_dp_t), intent(in) :: run
        type(bounds_dp_t), intent(in) :: bounds
        real(dp), parameter :: top = huge(1.0_dp)
        finite = all(abs(run%v) <= top) .and. all(abs(run%x) <= top) .and. &
            all(abs(run%y) <= top) .and. abs(run%t_end) <= top .and. &
            all(bounds%v <= top) .and. all(bounds%x <= top)
    end function finite

    !> Run `scene` in real64 with the engine's full rules (no certificate);
    !> `run` holds the answer in real128. A scene that real64 cannot carry
    !> (fits_dp) is not run: its status is status_invalid, and the message
    !> says why (a front door checks each key first, to name the one at fault).
    subroutine simulate_in_dp(scene, run)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(inout) :: run
        type(scene_dp_t) :: low
        type(run_dp_t) :: run_low
        if (.not. fits_dp(scene)) then
            run%status = status_invalid
            run%message = "scene: its values or scales are beyond the normal range of " &
                //"real(8); allowed a scene within it for a run in real(8)"
            return
        end if
        call to_dp(scene, low)
        call simulate_dp(low, run_low)
        if (run_low%status == status_invalid) then
            ! a run the engine refused has no results to convert
            run%status = run_low%status
            run%message = run_low%message
            return
        end if
        call from_dp(run_low, run)
    end subroutine simulate_in_dp

    !> order_premise for a run made in real(8) (simulate_in_dp, or
    !> simulate_auto's answer in real(8)): the check in real(8), the order
    !> that run followed (of `run`, its collisions and its first limit).
    subroutine order_premise_in_dp(scene, run, work_most, proven, why)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        real(qp), intent(in) :: work_most
        logical, intent(out) :: proven
        !> (order_check's messages fit in 80 characters)
        character(len=80), intent(out) :: why
        type(scene_dp_t) :: low
        type(run_dp_t) :: run_low
        call to_dp(scene, low)
        run_low%n = run%n
        run_low%limits%n = run%limits%n
        run_low%limits%at = run%limits%at
        run_low%order_n = run%order_n
        if (allocated(run%order_gaps)) run_low%order_gaps = run%order_gaps(:run%order_n)
        call order_premise_dp(low, run_low, real(min(work_most, real(huge(1.0_dp), qp)), dp), &
            proven, why)
    end subroutine order_premise_in_dp

    !> Every value of the scene, and the sums the engine forms of them (mass
    !> pairs, the row's length, its time scale), is a finite real64, and every
    !> nonzero one is in real64's normal range, where rounding to it is a
    !> relative error of at most u (a tolerance below that range becomes 0,
    !> which decides the same for every rate real64 can hold).
    pure logical function fits_dp(scene)
        type(scene_t), intent(in) :: scene
        real(qp), parameter :: top = real(huge(1.0_dp), qp), low = real(tiny(1.0_dp), qp)
        real(qp) :: length
        length = scene%p*scene%d + sum(scene%a)
        fits_dp = 2*maxval(scene%m) <= top .and. length <= top .and. &
            scene%v0 <= top .and. scene%v0 >= low .and. all(scene%m >= low) .and. &
            length/scene%v0 <= top .and. normal(scene%d) .and. normal(scene%e) .and. &
            all(scene%a == 0.0_qp .or. scene%a >= low)
    contains
        pure logical function normal(x)
            real(qp), intent(in) :: x
            normal = x == 0.0_qp .or. x >= low
        end function normal
    end function fits_dp

    !> The scene rounded to real64, each value kept in its range: a tol just
    !> below 1 (allowed) that rounds to 1 (not allowed) becomes the real64
    !> next below 1, as the front door takes a text just below an open bound.
    pure subroutine to_dp(scene, low)
        type(scene_t), intent(in) :: scene
        type(scene_dp_t), intent(out) :: low
        low%p = scene%p
        low%e = real(scene%e, dp)
        low%d = real(scene%d, dp)
        low%v0 = real(scene%v0, dp)
        low%m = real(scene%m, dp)
        low%a = real(scene%a, dp)
        low%tol = min(real(scene%tol, dp), nearest(1.0_dp, -1.0_dp))
        low%max_collisions = scene%max_collisions
        low%closed_form_limits = scene%closed_form_limits
        low%calendar_from = scene%calendar_from
        low%vtol = real(scene%vtol, dp)
        if (allocated(scene%v)) low%v = real(scene%v, dp)
        low%x1 = real(scene%x1, dp)
        low%wall_left = real(scene%wall_left, dp)
        low%wall_right = real(scene%wall_right, dp)
        low%e_wall = real(scene%e_wall, dp)
        low%ring = real(scene%ring, dp)
        low%t_max = real(scene%t_max, dp)
        low%keep_order = scene%keep_order
    end subroutine to_dp

    !> A real64 run's results in a real128 run.
    pure subroutine from_dp(low, run)
        type(run_dp_t), intent(in) :: low
        type(run_t), intent(inout) :: run
        run%status = low%status
        run%message = low%message
        run%n = low%n
        run%t_end = real(low%t_end, qp)
        run%clock%t = real(low%clock%t, qp)
        run%limits%n = low%limits%n
        run%limits%closed_form = low%limits%closed_form
        run%limits%exact = low%limits%exact
        run%limits%certified = low%limits%certified
        run%limits%tolerance = low%limits%tolerance
        run%limits%bounded = low%limits%bounded
        run%limits%first = low%limits%first
        run%limits%last = low%limits%last
        run%limits%t = real(low%limits%t, qp)
        run%limits%norm = real(low%limits%norm, qp)
        run%limits%at = low%limits%at
        run%order_n = low%order_n
        if (allocated(low%order_gaps)) run%order_gaps = low%order_gaps(:low%order_n)
        run%answer = low%answer
        run%rests_on = low%rests_on
        run%clock%passed = low%clock%passed
        run%clock%window_energy = real(low%clock%window_energy, qp)
        run%clock%horizon_doubt = low%clock%horizon_doubt
        run%v_bound = real(low%v_bound, qp)
        if (allocated(low%v_bounds)) run%v_bounds = real(low%v_bounds, qp)
        if (allocated(low%v_rounding)) run%v_rounding = real(low%v_rounding, qp)
        if (allocated(low%active)) run%active = low%active
        run%y = real(low%y, qp)
        run%dy = real(low%dy, qp)
        run%x1 = real(low%x1, qp)
        run%dx1 = real(low%dx1, qp)
        run%x = real(low%x, qp)
        run%v = real(low%v, qp)
    end subroutine from_dp

end module sphere_row_auto
