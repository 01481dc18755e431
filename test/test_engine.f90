!> Tests of the collision engine against closed forms and conservation laws.
module test_engine
    use sphere_row, only: qp, dp, scene_t, run_t, event_log_t, scene_init, simulate, &
        kinetic_energy, momentum, status_normal, status_collapsed, status_invalid, &
        event_collision, event_collapse, str, itoa
    use sphere_row, only: scene_dp_t, run_dp_t
    use testsuite, only: error_t, unittest_t, new_unittest, check, seed_random
    use test_support, only: scene_of
    implicit none
    private
    public :: collect_engine

    !> Unit roundoff of the working precision, the scale of every tolerance here.
    real(qp), parameter :: eps = epsilon(1.0_qp)

    !> A scaling law of the row: the scene `scaled` (key=value words) runs as
    !> `original` with every time multiplied by time_factor and every velocity
    !> by speed_factor.
    type :: scaling_t
        character(len=16) :: what
        character(len=32) :: original, scaled
        real(qp) :: time_factor, speed_factor
    end type scaling_t

    !> The scaling laws tested: lengths (gaps and d doubled), speed (v0 doubled).
    type(scaling_t), parameter :: scalings(2) = [ &
        scaling_t("scaled lengths", "e=0.3 gaps=1,0.7,1.3 d=0.4", "e=0.3 gaps=2,1.4,2.6 d=0.8", &
        2.0_qp, 1.0_qp), &
        scaling_t("scaled speed", "e=0.25 masses=1,3,2,1", "e=0.25 masses=1,3,2,1 v0=2", &
        0.5_qp, 2.0_qp)]

contains

    !> A light sphere 1 bounces back at about e v0 and sends sphere 2 off at
    !> (1 + e) m_1/(m_1 + m_2) v0, which a sum from sphere 1 would lose in the
    !> rounding of the large velocity: masses 1e-40, 1, 1, 1 give v2 =
    !> 1.2e-40 (closed form, to 1e-30 relative), and p = 2 with masses 1e-20, 1
    !> gives v2 = 1.2e-20/(1 + 1e-20) to 1e-30 relative.
    subroutine test_small_behind_large(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        real(qp) :: exact
        call scene_init(scene, stat, msg, masses=[1.0e-40_qp, 1.0_qp, 1.0_qp, 1.0_qp])
        call simulate(scene, run)
        exact = 1.2_qp*1.0e-40_qp/(1 + 1.0e-40_qp)
        call check(error, abs(run%v(2) - exact) <= 1.0e-30_qp*exact, &
            "masses 1e-40,1,1,1: v2 = "//str(run%v(2))//", closed form "//str(exact))
        call scene_init(scene, stat, msg, p=2, masses=[1.0e-20_qp, 1.0_qp])
        call simulate(scene, run)
        exact = 1.2_qp*1.0e-20_qp/(1 + 1.0e-20_qp)
        call check(error, abs(run%v(2) - exact) <= 1.0e-30_qp*exact, &
            "p = 2, masses 1e-20,1: v2 = "//str(run%v(2))//", closed form "//str(exact))
    end subroutine test_small_behind_large

    !> d only shifts positions: the collisions, collapse limits and velocities
    !> of p = 20 at e = 0.5 do not depend on it (d = 1 and d = 1e34).
    subroutine test_independent_of_d(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: near, far
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=20, e=0.5_qp)
        call simulate(scene, near)
        scene%d = 1.0e34_qp
        call simulate(scene, far)
        call check(error, near%n == far%n .and. near%limits%n == far%limits%n .and. &
            all(near%v == far%v), "p = 20, e = 0.5: d = 1e34 changes the run: " &
            //str(real(near%n, qp))//" against "//str(real(far%n, qp))//" collisions")
    end subroutine test_independent_of_d

    !> At equal impact times and equal approach rates the leftmost pair
    !> collides first (the documented rule, in the scan and in the calendar).
    !> In the touching row of masses 2, 1, 1, 2 at e = 1/2, contacts 1 and 2
    !> both close at rate -9/16 v0 (exact in binary) before the fourth
    !> collision; that collision must be at contact 1.
    subroutine test_tie_leftmost(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(event_log_t) :: log
        integer :: stat, way
        character(len=200) :: msg
        call scene_init(scene, stat, msg, e=0.5_qp, masses=[2.0_qp, 1.0_qp, 1.0_qp, 2.0_qp], &
            gaps=[0.0_qp, 0.0_qp, 0.0_qp])
        do way = 1, 2
            if (way == 2) scene%calendar_from = 2
            call simulate(scene, run, log)
            call check(error, log%n >= 4, "tie: fewer than 4 events")
            if (allocated(error)) return
            call check(error, all(log%y(1:2, 3) == 0.0_qp) .and. &
                log%dy(1, 3) == log%dy(2, 3) .and. log%dy(1, 3) < 0.0_qp, &
                "tie: contacts 1 and 2 do not close at one rate before event 4")
            call check(error, log%first(4) == 1 .and. log%last(4) == 2, &
                "tie: event 4 is at pair "//str(real(log%first(4), qp))//", not the leftmost")
            if (allocated(error)) return
        end do
    end subroutine test_tie_leftmost

    !> The definition's row, elastic, with d = 2.5 and a = 0.5: sphere i rests
    !> at x = 3 (i - 1) until the one behind it arrives at t = (i - 1)/2 and
    !> moves on at v0, so at the last collision, t = 1.5, the positions are
    !> 0.5, 3.5, 6.5 and 9 (by hand), the gaps 0.5, 0.5 and 0.
    subroutine test_cradle_positions(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, e=1.0_qp, d=2.5_qp, a=0.5_qp)
        call simulate(scene, run)
        call check(error, run%n == 3 .and. abs(run%t_end - 1.5_qp) <= 4*eps, &
            "elastic d = 2.5, a = 0.5: not 3 collisions ending at t = 1.5")
        call check(error, all(abs(run%x - [0.5_qp, 3.5_qp, 6.5_qp, 9.0_qp]) <= 16*eps), &
            "elastic d = 2.5, a = 0.5: positions "//str(run%x(1))//" "//str(run%x(2))//" " &
            //str(run%x(3))//" "//str(run%x(4))//", by hand 0.5, 3.5, 6.5, 9")
        call check(error, all(abs(run%y(1:2) - 0.5_qp) <= 4*eps) .and. run%y(3) == 0.0_qp, &
            "elastic d = 2.5, a = 0.5: gaps other than 0.5, 0.5, 0")
    end subroutine test_cradle_positions

    !> The engine's tests.
    function collect_engine() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("two_mass_formulas", test_two_mass), &
            new_unittest("momentum_conserved", test_momentum), &
            new_unittest("energy_loss_per_collision", test_energy_loss), &
            new_unittest("elastic_cradle_p2_to_50", test_elastic_cradle), &
            new_unittest("elastic_cradle_positions", test_cradle_positions), &
            new_unittest("small_velocity_behind_a_large_one", test_small_behind_large), &
            new_unittest("closed_gaps_independent_of_d", test_independent_of_d), &
            new_unittest("tie_goes_to_the_leftmost_pair", test_tie_leftmost), &
            new_unittest("scaling_lengths", test_scaling_lengths), &
            new_unittest("scaling_speed", test_scaling_speed), &
            new_unittest("low_e_grid_terminates", test_low_e), &
            new_unittest("all_e_terminate", test_all_e), &
            new_unittest("plastic_limit_e0", test_plastic), &
            new_unittest("collapse_reported", test_collapse_reported), &
            new_unittest("definition_scene_e02", test_definition_scene), &
            new_unittest("real64_matches_real128", test_kinds_agree), &
            new_unittest("invalid_scene_status", test_invalid), &
            new_unittest("touching_row_elastic", test_touching) &
            ]
    end function collect_engine

    !> One collision of two spheres of random masses against formula (2).
    subroutine test_two_mass(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        real(qp) :: m(2), e, v1, v2, u(3)
        integer :: i, stat
        character(len=200) :: msg
        call seed_random(12345, 7)
        do i = 1, 200
            call random_number(u)
            m = [0.1_qp + 10*u(1), 0.1_qp + 10*u(2)]
            e = u(3)
            call scene_init(scene, stat, msg, p=2, e=e, masses=m, v0=1.5_qp)
            call simulate(scene, run)
            v1 = 1.5_qp - (1 + e)*m(2)/(m(1) + m(2))*(1.5_qp - 0)
            v2 = 0 + (1 + e)*m(1)/(m(1) + m(2))*(1.5_qp - 0)
            call check(error, run%n == 1, "two masses: expected one collision")
            call check(error, abs(run%v(1) - v1) <= 8*eps*1.5_qp, &
                "v1 = "//str(run%v(1))//" differs from (2): "//str(v1))
            call check(error, abs(run%v(2) - v2) <= 8*eps*1.5_qp, &
                "v2 = "//str(run%v(2))//" differs from (2): "//str(v2))
        end do
    end subroutine test_two_mass

    !> Total momentum m1 v0 is conserved over whole runs to 1e-30 relative,
    !> collapses included.
    subroutine test_momentum(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        real(qp) :: u(12), p0, p1
        real(qp), allocatable :: m(:)
        integer :: i, p, stat
        character(len=200) :: msg
        call seed_random(12345, 7)
        do i = 1, 300
            call random_number(u)
            p = 2 + int(7*u(1))
            m = 0.2_qp + 5*u(3:p + 2)
            call scene_init(scene, stat, msg, p=p, e=u(2), masses=m)
            call simulate(scene, run)
            p0 = m(1)*scene%v0
            p1 = momentum(scene, run%v)
            call check(error, abs(p1 - p0) <= 1.0e-30_qp*p0, "momentum drift " &
                //str((p1 - p0)/p0)//" at e = "//str(scene%e))
            call check(error, run%status == status_normal .or. run%status == status_collapsed, &
                "run did not end at e = "//str(scene%e))
        end do
    end subroutine test_momentum

    !> The kinetic energy lost in each collision is (1-e^2) mu w^2 / 2.
    subroutine test_energy_loss(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(event_log_t) :: log
        real(qp) :: e_values(4) = [0.9_qp, 0.5_qp, 0.2_qp, 0.18_qp]
        real(qp) :: v(5), ke_before, ke_after, mu, loss, energy0
        integer :: i, j, k, stat
        character(len=200) :: msg
        do i = 1, size(e_values)
            call scene_init(scene, stat, msg, p=5, e=e_values(i), &
                masses=[1.0_qp, 2.0_qp, 0.5_qp, 1.5_qp, 1.0_qp])
            call simulate(scene, run, log)
            energy0 = 0.5_qp*scene%m(1)*scene%v0**2
            call velocities(0)
            ke_before = kinetic_energy(scene, v)
            do j = 1, log%n
                call velocities(j)
                ke_after = kinetic_energy(scene, v)
                if (log%kind(j) == event_collision) then
                    k = log%first(j)
                    mu = scene%m(k)*scene%m(k + 1)/(scene%m(k) + scene%m(k + 1))
                    loss = 0.5_qp*(1 - scene%e**2)*mu*log%w(j)**2
                    call check(error, abs((ke_before - ke_after) - loss) <= 64*eps*energy0, &
                        "energy loss "//str(ke_before - ke_after)//" /= "//str(loss))
                end if
                ke_before = ke_after
            end do
        end do
    contains
        subroutine velocities(j)
            integer, intent(in) :: j
            integer :: q
            v(1) = log%dx1(j)
            do q = 1, 4
                v(q + 1) = v(q) + log%dy(q, j)
            end do
        end subroutine velocities
    end subroutine test_energy_loss

    !> e = 1, equal masses: exactly p-1 collisions, all motion in the last sphere.
    subroutine test_elastic_cradle(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: p, i
        do p = 2, 50
            call check_end(error, "p="//itoa(p)//" e=1", [(0.0_qp, i=1, p - 1), 1.0_qp], &
                4*eps, n=p - 1, status=status_normal)
        end do
    end subroutine test_elastic_cradle

    !> The scene of `keys` (key=value words) ends with the velocities `v` to
    !> `tol`, after `n` collisions and with `status` where these are given;
    !> `run` is its run.
    subroutine check_end(error, keys, v, tol, n, status, run)
        type(error_t), allocatable, intent(inout) :: error
        character(len=*), intent(in) :: keys
        real(qp), intent(in) :: v(:), tol
        integer, intent(in), optional :: n, status
        type(run_t), intent(out), optional :: run
        type(scene_t) :: scene
        type(run_t) :: ran
        if (allocated(error)) return
        call scene_of(keys, scene, error)
        if (allocated(error)) return
        call simulate(scene, ran)
        if (present(n)) call check(error, ran%n == n, &
            keys//": "//itoa(ran%n)//" collisions, not "//itoa(n))
        if (present(status)) call check(error, ran%status == status, &
            keys//": status "//itoa(ran%status)//", not "//itoa(status))
        call check(error, size(ran%v) == size(v), keys//": other number of spheres")
        if (allocated(error)) return
        call check(error, all(abs(ran%v - v) <= tol), &
            keys//": final velocities not the closed form")
        if (present(run)) run = ran
    end subroutine check_end

    !> Doubling every gap and the diameter doubles every event time.
    subroutine test_scaling_lengths(error)
        type(error_t), allocatable, intent(out) :: error
        call check_scaling(error, scalings(1))
    end subroutine test_scaling_lengths

    !> Doubling v0 halves every event time and doubles every velocity.
    subroutine test_scaling_speed(error)
        type(error_t), allocatable, intent(out) :: error
        call check_scaling(error, scalings(2))
    end subroutine test_scaling_speed

    !> A scaling law: the scene `law%scaled` has the events of `law%original`,
    !> more than 3, at time_factor times their times (to 16 eps relative) and
    !> ends with speed_factor times its velocities (to 16 eps).
    subroutine check_scaling(error, law)
        type(error_t), allocatable, intent(out) :: error
        type(scaling_t), intent(in) :: law
        type(scene_t) :: s1, s2
        type(run_t) :: r1, r2
        type(event_log_t) :: l1, l2
        character(len=:), allocatable :: what
        what = trim(law%what)
        call scene_of(trim(law%original), s1, error)
        if (allocated(error)) return
        call scene_of(trim(law%scaled), s2, error)
        if (allocated(error)) return
        call simulate(s1, r1, l1)
        call simulate(s2, r2, l2)
        call check(error, l1%n == l2%n .and. l1%n > 3, what//": other event count")
        if (allocated(error)) return
        call check(error, all(abs(l2%t(:l1%n) - law%time_factor*l1%t(:l1%n)) <= &
            16*eps*l2%t(:l1%n)), what//": event times not scaled by "//str(law%time_factor))
        call check(error, all(abs(r2%v - law%speed_factor*r1%v) <= 16*eps), &
            what//": velocities not scaled by "//str(law%speed_factor))
    end subroutine check_scaling

    !> Every e in [0, 0.2] on a fine grid ends, in bounded time, normally or
    !> quasi-plastically, with momentum conserved.
    subroutine test_low_e(error)
        type(error_t), allocatable, intent(out) :: error
        call check_e_grid(error, 0.2_qp, 2000)
    end subroutine test_low_e

    !> Every e from 0 to 1 ends, and the final rates satisfy the definition's
    !> termination criterion (no significant closing rate).
    subroutine test_all_e(error)
        type(error_t), allocatable, intent(out) :: error
        call check_e_grid(error, 1.0_qp, 1000)
    end subroutine test_all_e

    !> The definition's row at e = e_max i/steps, i = 0 ... steps: every run
    !> ends, normally or quasi-plastically (then with equal velocities), in
    !> bounded time, with momentum conserved to 1e-30, no closing rate above
    !> tol v0 and no negative gap.
    subroutine check_e_grid(error, e_max, steps)
        type(error_t), allocatable, intent(out) :: error
        real(qp), intent(in) :: e_max
        integer, intent(in) :: steps
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: i, stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg)
        do i = 0, steps
            scene%e = e_max*i/steps
            call simulate(scene, run)
            call check(error, run%status == status_normal .or. run%status == status_collapsed, &
                "e = "//str(scene%e)//": no end")
            call check(error, run%t_end <= huge(1.0_qp) .and. run%n < 100000, &
                "e = "//str(scene%e)//": unbounded")
            call check(error, abs(momentum(scene, run%v) - 1) <= 1.0e-30_qp, &
                "e = "//str(scene%e)//": momentum")
            call check(error, run%status == status_normal .or. &
                maxval(run%v) - minval(run%v) <= 64*eps, &
                "e = "//str(scene%e)//": quasi-plastic with unequal velocities")
            call check(error, all(run%dy >= -scene%tol*scene%v0), &
                "e = "//str(scene%e)//": ended with a closing gap")
            call check(error, all(run%y >= 0), "e = "//str(scene%e)//": negative gap")
        end do
    end subroutine check_e_grid

    !> e = 0: perfectly plastic, every sphere ends with v0/p.
    subroutine test_plastic(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: p, i
        do p = 2, 8
            call check_end(error, "p="//itoa(p)//" e=0", [(1.0_qp/p, i=1, p)], 64*eps)
        end do
    end subroutine test_plastic

    !> The definition's scene at e = 0.1 collapses; the result says so, and the
    !> e = 0 scene first collapses in spheres 1-3 at t = 3 (derived by hand:
    !> 1 and 2 stick at t = 1, reach sphere 3 after a gap of 1 at speed 1/2).
    subroutine test_collapse_reported(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        call scene_of("e=0.1", scene, error)
        if (allocated(error)) return
        call simulate(scene, run)
        call check(error, run%status == status_collapsed .and. run%limits%n >= 1, &
            "e = 0.1 not reported as collapsed")
        call check(error, abs(run%v(4) - 0.25_qp) <= 64*eps, "e = 0.1: v4 /= 1/4")
        scene%e = 0
        call simulate(scene, run)
        call check(error, run%limits%first == 1 .and. run%limits%last == 3 .and. &
            abs(run%limits%t - 3) <= 8*eps, "e = 0: first collapse not spheres 1-3 at t = 3")
        call check(error, abs(run%t_end - 6) <= 8*eps, "e = 0: end not at t = 6")
    end subroutine test_collapse_reported

    !> The definition's scene, e = 0.2: first collisions and velocities by hand.
    subroutine test_definition_scene(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(event_log_t) :: log
        call scene_of("e=0.2", scene, error)
        if (allocated(error)) return
        call simulate(scene, run, log)
        ! 1-2 at t = 1; sphere 2 leaves at (1+e)/2 = 0.6 and meets 3 after 1/0.6.
        call check(error, log%first(1) == 1 .and. abs(log%t(1) - 1) <= 4*eps, "first collision")
        call check(error, log%first(2) == 2 .and. abs(log%t(2) - (1 + 1/0.6_qp)) <= 8*eps, &
            "second collision")
        call check(error, abs(momentum(scene, run%v) - 1) <= 1.0e-32_qp, "momentum")
        call check(error, run%n == 13 .and. run%status == status_normal, "count or status")
    end subroutine test_definition_scene

    !> real64 and real128 agree to 1e-12 on well-conditioned scenes (e well above
    !> the collapse threshold of these masses, which lies above 0.2).
    subroutine test_kinds_agree(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: sq
        type(run_t) :: rq
        type(scene_dp_t) :: sd
        type(run_dp_t) :: rd
        real(qp) :: e_values(5) = [1.0_qp, 0.8_qp, 0.6_qp, 0.4_qp, 0.3_qp]
        real(qp), parameter :: m(4) = [1.0_qp, 1.5_qp, 0.75_qp, 2.0_qp]
        integer :: i, stat
        character(len=200) :: msg
        do i = 1, size(e_values)
            call scene_init(sq, stat, msg, e=e_values(i), masses=m)
            call scene_init(sd, stat, msg, e=real(e_values(i), dp), masses=real(m, dp))
            call simulate(sq, rq)
            call simulate(sd, rd)
            call check(error, rq%n == rd%n, "real64 count differs at e = "//str(e_values(i)))
            call check(error, all(abs(rq%v - rd%v) <= 1.0e-12_qp), &
                "real64 velocities differ at e = "//str(e_values(i)))
            call check(error, abs(rq%t_end - rd%t_end) <= 1.0e-12_qp*rq%t_end, &
                "real64 end time differs at e = "//str(e_values(i)))
        end do
    end subroutine test_kinds_agree

    !> Invalid scenes come back as a status with a message naming the input.
    subroutine test_invalid(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, e=1.5_qp)
        call check(error, stat == status_invalid .and. msg(1:4) == "e = ", "e = 1.5 accepted")
        call scene_init(scene, stat, msg, p=1)
        call check(error, stat == status_invalid .and. msg(1:4) == "p = ", "p = 1 accepted")
        call scene_init(scene, stat, msg, masses=[1.0_qp, -1.0_qp, 1.0_qp, 1.0_qp])
        call check(error, stat == status_invalid .and. msg(1:6) == "masses", "mass < 0 accepted")
        call scene_init(scene, stat, msg, gaps=[1.0_qp, 1.0_qp])
        call check(error, stat == status_invalid .and. msg(1:4) == "gaps", "2 gaps for p=4 accepted")
        call scene_init(scene, stat, msg)
        scene%v0 = 0
        call simulate(scene, run)
        call check(error, run%status == status_invalid .and. run%message(1:2) == "v0", &
            "simulate ran a scene with v0 = 0")
    end subroutine test_invalid

    !> Touching spheres (all gaps 0), e = 1: the impulse runs through the row at t = 0.
    subroutine test_touching(error)
        type(error_t), allocatable, intent(out) :: error
        type(run_t) :: run
        call check_end(error, "p=5 e=1 a=0", [0.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, 1.0_qp], 4*eps, &
            n=4, run=run)
        if (allocated(error)) return
        call check(error, run%t_end == 0, "touching row: events after t = 0")
    end subroutine test_touching

end module test_engine
