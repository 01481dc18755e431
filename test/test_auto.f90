!> Tests of the precision chosen per scene: wherever real64 is certified it
!> has real128's collision sequence, count and status, and its velocities lie
!> within the stated bound of real128's.
module test_auto
    use sphere_row, only: qp, dp, scene_t, run_t, event_log_t, scene_init, simulate, &
        scene_dp_t, run_dp_t, event_log_dp_t, bounds_dp_t, simulate_certified, auto_t, &
        simulate_auto, itoa, order_check, order_premise, order_premise_in_dp, simulate_in_dp
    use testsuite, only: error_t, unittest_t, new_unittest, check, cases
    use test_support, only: bounded_row
    implicit none
    private
    public :: collect_auto

    !> Critical restitution of the definition's row, 3 - 2 sqrt 2.
    real(qp), parameter :: e_crit = 3 - 2*sqrt(2.0_qp)
    !> Scan of n(e) for the breakpoints, and how close to each the values go.
    integer, parameter :: scan_points = 1000, offsets = 13
    !> Values of e drawn uniformly, and random rows of other masses and lengths
    !> (of the deep run; the quick run takes a tenth of each).
    integer, parameter :: uniform_values = 3000, random_rows = 3200
    !> Collision cap of every run here (a random row may collapse slowly).
    integer, parameter :: cap = 4000

contains

    !> The auto tests.
    function collect_auto() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("auto_e_0172_as_real128", test_near_critical), &
            new_unittest("auto_equals_real128", test_many_values), &
            new_unittest("auto_at_extreme_scales", test_extreme_scales), &
            new_unittest("auto_long_row_in_real128_once", test_long_row), &
            new_unittest("order_check_stops_where_exact_order_leaves", test_order_check), &
            new_unittest("order_premise_is_the_runs_own_order", test_order_premise), &
            new_unittest("in_dp_keeps_the_limits", test_in_dp_limits) &
            ]
    end function collect_auto

    !> A run made in real(8) for a real(16) caller (simulate_in_dp, as
    !> simulate_auto's answer in real(8)) carries the real(8) run's record of
    !> its limits whole: bounded_row, in real(8) too, takes a bounded limit,
    !> whose bound sums into limits%norm.
    subroutine test_in_dp_limits(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(scene_dp_t) :: low
        type(run_t) :: run
        type(run_dp_t) :: direct
        integer :: stat
        character(len=200) :: msg
        call bounded_row(scene)
        call simulate_in_dp(scene, run)
        call scene_init(low, stat, msg, p=20, e=0.5_dp, gaps=spread(0.0_dp, 1, 19))
        low%closed_form_limits = scene%closed_form_limits
        low%vtol = real(scene%vtol, dp)
        low%tol = real(scene%tol, dp)
        call simulate(low, direct)
        call check(error, direct%limits%bounded > 0 .and. direct%limits%norm > 0, &
            "the premise: a bounded limit in real(8), "//itoa(direct%limits%bounded))
        if (allocated(error)) return
        call check(error, run%limits%n == direct%limits%n .and. &
            run%limits%closed_form == direct%limits%closed_form .and. &
            run%limits%exact == direct%limits%exact .and. &
            run%limits%certified == direct%limits%certified .and. &
            run%limits%tolerance == direct%limits%tolerance .and. &
            run%limits%bounded == direct%limits%bounded .and. &
            run%limits%first == direct%limits%first .and. &
            run%limits%last == direct%limits%last .and. run%limits%at == direct%limits%at .and. &
            run%limits%t == real(direct%limits%t, qp) .and. &
            run%limits%norm == real(direct%limits%norm, qp), &
            "simulate_in_dp's limits differ from the real(8) run's")
    end subroutine test_in_dp_limits

    !> Near e_crit real64 is not enough; auto answers as real128 does.
    subroutine test_near_critical(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(auto_t) :: auto
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, e=0.172_qp)
        call simulate_auto(scene, run, auto)
        call check(error, run%n == 115 .and. auto%answered == "qp", &
            "e = 0.172: not 115 collisions in real128")
        call scene_init(scene, stat, msg, e=0.5_qp)
        call simulate_auto(scene, run, auto)
        call check(error, auto%answered == "dp" .and. auto%certified, &
            "e = 0.5: real64 not certified")
    end subroutine test_near_critical

    !> A long row (p >= calendar_from) is not tried in real64, whose
    !> certificate scans every gap at every collision: an elastic row of 60
    !> spheres of graded masses runs in real128, once (not certified), and the
    !> same row with calendar_from above 60 is certified in real64, with the
    !> same collisions.
    subroutine test_long_row(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(auto_t) :: auto
        integer :: stat, i, n_long
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=60, e=1.0_qp, &
            masses=[(1 + i/100.0_qp, i=0, 59)])
        call simulate_auto(scene, run, auto)
        n_long = run%n
        call check(error, auto%answered == "qp" .and. .not. auto%certified .and. &
            index(auto%why_not_dp, "a long row") == 1, "p = 60: "//auto%answered//", " &
            //auto%why_not_dp)
        if (allocated(error)) return
        scene%calendar_from = 61
        call simulate_auto(scene, run, auto)
        call check(error, auto%answered == "dp" .and. auto%certified .and. run%n == n_long, &
            "p = 60, calendar_from = 61: "//auto%answered//", "//itoa(run%n)//" collisions, " &
            //itoa(n_long)//" before; "//auto%why_not_dp)
    end subroutine test_long_row

    !> Scenes with e uniform, e dense near every change of n(e) and near
    !> e_crit (p = 4, equal masses), and random rows: at least 10^4 in the
    !> deep run; the quick run takes a tenth of the uniform values and random
    !> rows, every fourth distance from a change of n(e) and from e_crit.
    subroutine test_many_values(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: breaks(:)
        real(qp) :: u(20), e
        integer :: i, j, s, tried, low, p, n_uniform, n_rows, stride
        call breakpoints(breaks)
        n_uniform = cases(uniform_values/10, uniform_values)
        n_rows = cases(random_rows/10, random_rows)
        stride = cases(4, 1)
        tried = 0
        low = 0
        do i = 1, n_uniform
            e = (i - 0.5_qp)/n_uniform
            call compare_one(4, e, [(1.0_qp, j=1, 4)], error, tried, low)
            if (allocated(error)) return
        end do
        ! away from the changes of n(e) and from e_crit real64 should mostly do
        call check(error, low > n_uniform/2, "real64 certified for too few of the " &
            //"uniform values: "//itoa(low))
        do i = 1, size(breaks)
            do j = 1, offsets, stride
                do s = -1, 1, 2
                    e = breaks(i) + s*10.0_qp**(-2 - j)
                    if (e < 0 .or. e > 1) cycle
                    call compare_one(4, e, [(1.0_qp, p=1, 4)], error, tried, low)
                    if (allocated(error)) return
                end do
            end do
        end do
        do j = 1, 30, stride
            do s = -1, 1, 2
                do i = 1, 20
                    e = e_crit + s*i*10.0_qp**(-1 - j/2.0_qp)/20
                    call compare_one(4, e, [(1.0_qp, p=1, 4)], error, tried, low)
                    if (allocated(error)) return
                end do
            end do
        end do
        call random_seed(put=[(977 + 3*i, i=1, 64)])
        do i = 1, n_rows
            call random_number(u)
            p = 2 + int(7*u(1))
            call compare_one(p, u(2), 1.0e2_qp**(2*u(3:p + 2) - 1), error, tried, low)
            if (allocated(error)) return
        end do
        call check(error, tried >= cases(1500, 10000), "too few scenes: "//itoa(tried))
    end subroutine test_many_values

    !> Scales at and beyond real64's range (closed gaps, gaps below its normal
    !> range, huge or tiny masses, lengths and speeds): auto must still give
    !> real128's count and status, and real64's velocities within their own
    !> bounds where it answers.
    subroutine test_extreme_scales(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), parameter :: gap_choices(6) = [0.0_qp, 1.0e-400_qp, 1.0e-300_qp, 1.0_qp, &
            1.0e300_qp, 1.0e308_qp]
        real(qp), parameter :: scale_choices(5) = [1.0e-300_qp, 1.0e-9_qp, 1.0_qp, 1.0e9_qp, &
            1.0e307_qp]
        type(scene_t) :: scene
        type(run_t) :: ref, run
        type(auto_t) :: auto
        real(qp) :: u(30)
        integer :: i, j, p, stat
        character(len=200) :: msg
        call random_seed(put=[(4099 + 5*i, i=1, 64)])
        do i = 1, cases(100, 400)
            call random_number(u)
            p = 2 + int(5*u(1))
            call scene_init(scene, stat, msg, p=p, e=u(2), max_collisions=cap, &
                v0=scale_choices(1 + int(5*u(3))), &
                masses=[(scale_choices(1 + int(5*u(3 + j))), j=1, p)], &
                gaps=[(gap_choices(1 + int(6*u(10 + j))), j=1, p - 1)])
            if (stat /= 0) cycle
            call simulate(scene, ref)
            if (ref%status /= 0 .and. ref%status /= 1) cycle
            call simulate_auto(scene, run, auto)
            call check(error, run%n == ref%n .and. run%status == ref%status, &
                "extreme scales: count or status differs, row "//itoa(i))
            if (allocated(error)) return
            if (auto%answered /= "dp") cycle
            call check(error, all(abs(run%v - ref%v) <= auto%v_bound + &
                64*epsilon(1.0_qp)*maxval(abs(ref%v))), &
                "extreme scales: velocities beyond the bound, row "//itoa(i))
            if (allocated(error)) return
        end do
    end subroutine test_extreme_scales

    !> Every change of the collision count n(e) on a scan of e (p = 4, equal
    !> masses), each bisected to 1e-15.
    subroutine breakpoints(breaks)
        real(qp), allocatable, intent(out) :: breaks(:)
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: i, stat, n_prev, it
        real(qp) :: lo, hi, mid
        character(len=200) :: msg
        allocate (breaks(0))
        call scene_init(scene, stat, msg)
        n_prev = -1
        do i = 0, scan_points
            scene%e = real(i, qp)/scan_points
            call simulate(scene, run)
            if (i > 0 .and. run%n /= n_prev) then
                lo = real(i - 1, qp)/scan_points
                hi = scene%e
                do it = 1, 40
                    mid = 0.5_qp*(lo + hi)
                    scene%e = mid
                    call simulate(scene, run)
                    if (run%n == n_prev) then
                        lo = mid
                    else
                        hi = mid
                    end if
                end do
                breaks = [breaks, 0.5_qp*(lo + hi)]
                scene%e = real(i, qp)/scan_points
                call simulate(scene, run)
            end if
            n_prev = run%n
        end do
    end subroutine breakpoints

    !> One scene: auto against real128; where real64 answered, its certified
    !> run has real128's sequence, and its velocities are within the bound.
    subroutine compare_one(p, e, m, error, tried, low)
        integer, intent(in) :: p
        real(qp), intent(in) :: e, m(:)
        type(error_t), allocatable, intent(inout) :: error
        integer, intent(inout) :: tried, low
        type(scene_t) :: scene
        type(run_t) :: ref, run
        type(event_log_t) :: log
        type(scene_dp_t) :: scene_low
        type(run_dp_t) :: run_low
        type(bounds_dp_t) :: bounds
        type(event_log_dp_t) :: log_low
        type(auto_t) :: auto
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=p, e=e, masses=m, max_collisions=cap)
        call simulate(scene, ref, log)
        call simulate_auto(scene, run, auto)
        tried = tried + 1
        call check(error, run%n == ref%n .and. run%status == ref%status, &
            "auto: count or status differs at e = "//itoa(tried))
        if (allocated(error) .or. auto%answered /= "dp") return
        low = low + 1
        call check(error, all(abs(run%v - ref%v) <= auto%v_bound + 64*epsilon(1.0_qp)), &
            "auto: velocities beyond the bound, scene "//itoa(tried))
        if (allocated(error)) return
        call scene_init(scene_low, stat, msg, p=p, e=real(e, dp), masses=real(m, dp), &
            tol=real(scene%tol, dp), max_collisions=cap)
        call simulate_certified(scene_low, run_low, bounds, log_low)
        call check(error, log_low%n == log%n, "auto: sequence length differs")
        if (allocated(error)) return
        call check(error, all(log_low%first(1:log%n) == log%first(1:log%n)), &
            "auto: sequence differs, scene "//itoa(tried))
    end subroutine compare_one


    !> The order check (order_check) proves no more of a run's order than
    !> exact arithmetic takes: real(16) takes exact arithmetic's collisions of
    !> p = 4, e = 0.1, masses 1, 2, 1.5, 1 to the 586th and another from the
    !> 587th (tools/replay at 3,000 and 6,000 digits, docs/collapse.md), so
    !> the check stops before that, and real(8)'s before real(16)'s; the
    !> engine certifies that row after 11,734 collisions, past the check. It
    !> proves the whole of a separation far below v0 (p = 5, e = 0.2593: 1062
    !> collisions, separating at rates of 2.6e-106 v0) and the collisions of a
    !> periodic collapse to its certificate (p = 5, e = 0.258: 469); it stops
    !> where the rates reach the kind's underflow; a row of more than 200
    !> spheres is refused.
    subroutine test_order_check(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(scene_dp_t) :: scene_dp
        type(run_t) :: run
        character(len=80) :: why, why_dp
        integer :: stat, n, n_dp
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=4, e=0.1_qp, masses=[1.0_qp, 2.0_qp, 1.5_qp, 1.0_qp])
        call order_check(scene, 20000, n, why)
        call scene_init(scene_dp, stat, msg, p=4, e=0.1_dp, masses=[1.0_dp, 2.0_dp, 1.5_dp, 1.0_dp])
        call order_check(scene_dp, 20000, n_dp, why_dp)
        call check(error, n > 100 .and. n <= 586 .and. n_dp < n, "p=4 e=0.1 masses=1,2,1.5,1: " &
            //"order checked to "//itoa(n)//" in real(16) ("//trim(why)//"), "//itoa(n_dp)// &
            " in real(8); expected at most 586, where real(16) leaves exact arithmetic's order, " &
            //"and fewer in real(8)")
        if (allocated(error)) return
        call simulate(scene, run)
        call check(error, run%n > n, "p=4 e=0.1 masses=1,2,1.5,1: certified after "// &
            itoa(run%n)//" collisions, the order checked to "//itoa(n)//"; expected beyond")
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=5, e=0.2593_qp)
        call simulate(scene, run)
        call order_check(scene, run%n + 1, n, why)
        call check(error, n == run%n .and. why == "separated" .and. run%n == 1062, &
            "p=5 e=0.2593: "//itoa(run%n)//" collisions, order checked to "//itoa(n)//" ("// &
            trim(why)//"); expected the whole separation, 1062")
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=5, e=0.258_qp)
        call simulate(scene, run)
        call order_check(scene, run%limits%at, n, why)
        call check(error, run%limits%certified == 1 .and. run%limits%at > 400 .and. &
            n == run%limits%at, "p=5 e=0.258: certified limit after "//itoa(run%limits%at)// &
            " collisions, order checked to "//itoa(n)//" ("//trim(why)//"); expected to the limit")
        if (allocated(error)) return
        ! a plastic cascade of spheres 1-3 at one instant, which in exact
        ! arithmetic goes on for ever: its rates fall to the kind's underflow,
        ! where real(16) takes gap 3 (at collision 10,409); the check stops
        ! before, at the underflow
        call scene_init(scene, stat, msg, p=4, e=0.0_qp, masses=[2.0_qp, 4.0_qp, 2.0_qp, &
            2.0_qp], gaps=[2.0_qp, 1.0_qp, 3.0_qp])
        call order_check(scene, 20000, n, why)
        call check(error, n < 10409 .and. index(why, "underflow") > 0, "p=4 e=0 masses=2,4,2," &
            //"2 gaps=2,1,3: order checked to "//itoa(n)//" ("//trim(why)// &
            "); expected a stop at the underflow, before collision 10,409")
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=201, e=0.5_qp)
        call order_check(scene, 10, n, why)
        call check(error, n == 0 .and. index(why, "more than 200 spheres") > 0, &
            "p=201: order checked to "//itoa(n)//" ("//trim(why)//"); expected a refusal")
    end subroutine test_order_check

    !> order_premise proves the order the run itself took. p = 5, e = 0.258
    !> certifies its limit after 469 collisions, those from the 311th in the
    !> whole row followed on its own scale; a row of mixed masses follows so
    !> a group that does not begin at sphere 1, to its first limit on spheres
    !> 3 to 6 (the run keeps a followed group's collisions in the row's
    !> numbers). A run that kept no order is not checked, and one whose kept
    !> gap at a collision (the 5th, and the last, in the followed group) is
    !> not exact arithmetic's is stopped there. precision=auto's answer in
    !> real(8), its certified run, keeps its order too.
    subroutine test_order_premise(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scenes(2)
        type(run_t) :: run
        type(auto_t) :: auto
        character(len=80) :: why
        character(len=:), allocatable :: what
        logical :: proven
        integer :: stat, i, j, at(2)
        character(len=200) :: msg
        call scene_init(scenes(1), stat, msg, p=5, e=0.258_qp)
        call scene_init(scenes(2), stat, msg, p=6, e=0.311_qp, masses=[1.93_qp, 0.77_qp, &
            1.25_qp, 1.11_qp, 0.32_qp, 1.38_qp], gaps=[3.0_qp, 0.2_qp, 1.0_qp, 0.05_qp, 0.2_qp])
        do i = 1, size(scenes)
            what = "p="//itoa(scenes(i)%p)//" e="//merge("0.258", "0.311", i == 1)
            call simulate(scenes(i), run)
            call order_premise(scenes(i), run, huge(1.0_qp), proven, why)
            call check(error, .not. proven .and. index(why, "did not keep") > 0, &
                what//" without keep_order: "//trim(why)//"; expected not checked")
            if (allocated(error)) return
            scenes(i)%keep_order = huge(1)
            call simulate(scenes(i), run)
            call order_premise(scenes(i), run, huge(1.0_qp), proven, why)
            call check(error, proven .and. run%limits%certified > 0 .and. &
                run%order_n == run%limits%at, what//": limit after "//itoa(run%limits%at)// &
                " collisions, "//itoa(run%order_n)//" kept, proven "//merge("yes", "no ", &
                proven)//" ("//trim(why)//"); expected every one kept, and proven")
            if (allocated(error)) return
            at = [5, run%limits%at]
            do j = 1, size(at)
                run%order_gaps(at(j)) = 1 + modulo(run%order_gaps(at(j)), scenes(i)%p - 1)
                call order_premise(scenes(i), run, huge(1.0_qp), proven, why)
                call check(error, .not. proven .and. index(why, "the run's collision " &
                    //itoa(at(j))//" closed gap") > 0, what//", the run's gap at collision " &
                    //itoa(at(j))//" changed: "//trim(why)//"; expected the check to stop there")
                if (allocated(error)) return
                call simulate(scenes(i), run)
            end do
        end do
        call scene_init(scenes(1), stat, msg, p=4, e=0.2_qp)
        scenes(1)%keep_order = huge(1)
        call simulate_auto(scenes(1), run, auto)
        call order_premise_in_dp(scenes(1), run, huge(1.0_qp), proven, why)
        call check(error, auto%answered == "dp" .and. run%order_n == run%n .and. proven, &
            "p=4 e=0.2 by precision=auto: answered in "//auto%answered//", "// &
            itoa(run%order_n)//" of "//itoa(run%n)//" collisions kept, ("//trim(why)// &
            "); expected real(8), every one kept, and proven")
    end subroutine test_order_premise

end module test_auto
