!> Scenes beyond the struck row: any initial velocities, walls, a ring, a
!> horizon. Each is checked against what holds without the engine: the
!> independent replay in 80 digits (tools/replay, absolute positions and
!> velocities, written from the definition), collision for collision; the
!> mirror image of a wall; Newton's cradle; and a ring's momentum and energy
!> ledger.
module test_scenes
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, event_log_t, scene_init, simulate, itoa, str, &
        event_collision, event_collapse, status_horizon, status_normal, momentum, &
        kinetic_energy, answer_word, answer_exact, velocities_now
    use sphere_row_gas, only: gas_state, gas_uniform
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text
    use test_support, only: scene_of, split_tabs, read_reals
    implicit none
    private
    public :: collect_scenes

    !> A scene of the replay table: its keys as sphere-row and tools/replay
    !> take them, and why it is there.
    type :: row_t
        character(len=:), allocatable :: keys, why
    end type row_t

contains

    !> The scene tests.
    function collect_scenes() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("scenes_agree_with_replay", test_replay_table), &
            new_unittest("wall_is_the_mirror_row", test_mirror), &
            new_unittest("two_strike_three", test_cradle), &
            new_unittest("ring_keeps_momentum_and_energy_ledger", test_ring_ledger), &
            new_unittest("horizon_state_is_the_run_moved_on", test_horizon), &
            new_unittest("horizon_before_a_collapse_ends", test_horizon_in_collapse), &
            new_unittest("horizon_within_rounding_of_a_collision", test_horizon_doubt), &
            new_unittest("wall_group_at_rest", test_wall_group), &
            new_unittest("gas_state_as_asked", test_gas_state) &
            ]
    end function collect_scenes

    !> A row of the table.
    pure function row(keys, why)
        character(len=*), intent(in) :: keys, why
        type(row_t) :: row
        row%keys = keys
        row%why = why
    end function row

    !> Every scene of the table, run by the engine with its event log and by
    !> tools/replay in 80 digits: the same outcome (separated, or stopped at
    !> the horizon), the same collisions in the same order (each a gap number:
    !> 0 the left wall, p the right wall or the seam), and every final
    !> velocity within the engine's bound of the replay's.
    subroutine test_replay_table(error)
        type(error_t), allocatable, intent(out) :: error
        type(row_t), allocatable :: rows(:)
        integer :: i
        rows = [ &
            row("p=5 e=1 velocities=1,1,0,0,0 gaps=0.1,1,0.1,0.1", "two strike three"), &
            row("p=3 e=0.7 e_wall=0.5 velocities=-1,-0.5,0.2 wall_left=0.3 gaps=0.5,0.4", &
                "a row against a left wall of its own restitution"), &
            row("p=4 e=0.9 masses=1,2,0.5,1 velocities=1,-1,0.5,-0.3 wall_left=0.2 " &
                //"wall_right=0.7 gaps=0.3,0.6,0.2 t_max=12", "a box of mixed masses"), &
            row("p=5 e=0.8 masses=1,3,1,0.7,2 velocities=0.3,-0.9,0.5,1.1,-0.4 ring=0.6 " &
                //"gaps=0.5,0.2,0.9,0.4 t_max=10", "a ring of mixed masses"), &
            row("p=2 e=0.6 velocities=1,-1 ring=0.5 gaps=0.25 t_max=6", &
                "the smallest ring: both gaps one pair"), &
            row("p=4 e=0.5 velocities=0,0,0,-1 wall_right=0.4 gaps=1,1,1 t_max=30", &
                "the definition's row turned round against a right wall"), &
            row("p=3 e=1 velocities=2,0,-1 wall_left=0.5 wall_right=0.5 gaps=1,1 t_max=9.3", &
                "an elastic box, its horizon clear of the collision at t = 9") &
            ]
        do i = 1, size(rows)
            call replay_one(rows(i), error)
            if (allocated(error)) return
        end do
    end subroutine test_replay_table

    !> One scene of the replay table.
    subroutine replay_one(r, error)
        type(row_t), intent(in) :: r
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: seq_file = "build/test_scenes_sequence.txt", &
            out_file = "build/test_scenes_replay.tsv"
        type(scene_t) :: scene
        type(run_t) :: run
        type(event_log_t) :: log
        character(len=:), allocatable :: text, fields(:)
        integer, allocatable :: engine_seq(:), replay_seq(:)
        real(qp), allocatable :: v(:)
        integer :: stat, i
        call scene_of(r%keys, scene, error)
        if (allocated(error)) return
        call simulate(scene, run, log)
        call execute_command_line("python3 tools/replay dps=80 format=tsv sequence="//seq_file &
            //" "//r%keys//" > "//out_file, exitstat=stat)
        call check(error, stat == 0, r%why//": tools/replay failed on "//r%keys)
        if (allocated(error)) return
        text = read_text(out_file)
        call split_tabs(text, fields)
        engine_seq = pack(log%first(1:log%n), log%kind(1:log%n) == event_collision)
        call read_ints(seq_file, replay_seq)
        call check(error, size(engine_seq) == size(replay_seq), r%why//": "//itoa(run%n) &
            //" collisions against the replay's "//itoa(size(replay_seq))//" ("//r%keys//")")
        if (allocated(error)) return
        do i = 1, size(engine_seq)
            if (engine_seq(i) /= replay_seq(i)) exit
        end do
        call check(error, i > size(engine_seq), r%why//": collision "//itoa(i)//" at gap " &
            //itoa(engine_seq(min(i, size(engine_seq))))//", the replay's at gap " &
            //itoa(replay_seq(min(i, size(replay_seq)))))
        if (allocated(error)) return
        call check(error, (trim(fields(1)) == "horizon") .eqv. (run%status == status_horizon), &
            r%why//": outcome "//trim(fields(1))//" against status "//itoa(run%status))
        if (allocated(error)) return
        call read_reals(fields(7), v)
        call check(error, size(v) == scene%p, r%why//": the replay's velocities unread")
        if (allocated(error)) return
        do i = 1, scene%p
            call check(error, abs(run%v(i) - v(i)) <= run%v_bounds(i), r%why//": v" &
                //itoa(i)//" = "//str(run%v(i))//", the replay's "//str(v(i)) &
                //", apart beyond the bound "//str(run%v_bounds(i)))
            if (allocated(error)) return
        end do
        call check(error, run%answer == answer_exact, r%why//": answer " &
            //answer_word(run%answer))
    end subroutine replay_one

    !> The mirror image of a wall: p spheres against a left wall of e_wall = e
    !> move as the symmetric row of 2p spheres with the mirrored velocities
    !> (each wall collision is the middle pair's collision, each other one a
    !> mirrored pair of collisions at one time): the same velocities, the
    !> same last time, and 2 n - n_wall collisions.
    subroutine test_mirror(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: wall, twice
        type(run_t) :: a, b
        type(event_log_t) :: log
        real(qp), parameter :: v(4) = [-1.0_qp, 0.3_qp, -0.2_qp, 0.5_qp], &
            g(3) = [0.4_qp, 0.7_qp, 0.2_qp], m(4) = [1.0_qp, 2.0_qp, 0.5_qp, 1.5_qp]
        real(qp), parameter :: g0 = 0.35_qp
        integer :: stat, n_wall, i
        character(len=200) :: msg
        call scene_init(wall, stat, msg, p=4, e=0.6_qp, masses=m, gaps=g, velocities=v, &
            wall_left=g0)
        call check(error, stat == status_normal, "mirror: "//trim(msg))
        if (allocated(error)) return
        call scene_init(twice, stat, msg, p=8, e=0.6_qp, masses=[m(4:1:-1), m], &
            gaps=[g(3:1:-1), 2*g0, g], velocities=[-v(4:1:-1), v])
        call check(error, stat == status_normal, "mirror: "//trim(msg))
        if (allocated(error)) return
        call simulate(wall, a, log)
        call simulate(twice, b)
        n_wall = count(log%kind(1:log%n) == event_collision .and. log%first(1:log%n) == 0)
        call check(error, n_wall > 0 .and. b%n == 2*a%n - n_wall, "mirror: "//itoa(a%n) &
            //" collisions, "//itoa(n_wall)//" of them at the wall, against the mirror's " &
            //itoa(b%n))
        if (allocated(error)) return
        call check(error, abs(a%t_end - b%t_end) <= 64*epsilon(1.0_qp)*b%t_end, &
            "mirror: last collision at "//str(a%t_end)//" against "//str(b%t_end))
        if (allocated(error)) return
        do i = 1, 4
            call check(error, abs(a%v(i) - b%v(4 + i)) <= a%v_bounds(i) + b%v_bounds(4 + i) &
                .and. abs(a%v(i) + b%v(5 - i)) <= a%v_bounds(i) + b%v_bounds(5 - i), &
                "mirror: v"//itoa(i)//" = "//str(a%v(i))//" against "//str(b%v(4 + i)))
            if (allocated(error)) return
        end do
    end subroutine test_mirror

    !> Newton's cradle with two balls: two equal spheres at v0 strike three at
    !> rest, elastic, small gaps: the first three end at rest, the last two
    !> leave at v0.
    subroutine test_cradle(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat, i
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=5, e=1.0_qp, gaps=[0.01_qp, 0.5_qp, 0.01_qp, &
            0.01_qp], velocities=[1.0_qp, 1.0_qp, 0.0_qp, 0.0_qp, 0.0_qp])
        call check(error, stat == status_normal, "cradle: "//trim(msg))
        if (allocated(error)) return
        call simulate(scene, run)
        call check(error, run%status == status_normal .and. run%answer == answer_exact, &
            "cradle: ended "//itoa(run%status)//", answer "//answer_word(run%answer))
        if (allocated(error)) return
        do i = 1, 5
            call check(error, abs(run%v(i) - merge(1.0_qp, 0.0_qp, i >= 4)) <= run%v_bounds(i), &
                "cradle: v"//itoa(i)//" = "//str(run%v(i)))
            if (allocated(error)) return
        end do
    end subroutine test_cradle

    !> A ring keeps its momentum within the bound, and loses at each
    !> collision (1 - e^2) mu w^2/2 (mu the pair's reduced mass, w its
    !> approach rate): the energy lost to the horizon is their sum, within
    !> what the velocities' bound allows; at e = 1 it keeps its energy.
    subroutine test_ring_ledger(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), parameter :: es(2) = [0.7_qp, 1.0_qp]
        real(qp), parameter :: m(6) = [1.0_qp, 2.0_qp, 0.5_qp, 1.0_qp, 3.0_qp, 1.5_qp], &
            v(6) = [0.4_qp, -0.2_qp, 1.1_qp, -0.7_qp, 0.3_qp, -0.5_qp]
        type(scene_t) :: scene
        type(run_t) :: run
        type(event_log_t) :: log
        real(qp) :: lost, e0, e1, p0, p1, mu, drift, norm
        integer :: stat, j, i, k
        character(len=200) :: msg
        do j = 1, size(es)
            call scene_init(scene, stat, msg, p=6, e=es(j), masses=m, gaps=[0.3_qp, 0.5_qp, &
                0.1_qp, 0.8_qp, 0.4_qp], velocities=v, ring=0.6_qp, t_max=40.0_qp)
            call check(error, stat == status_normal, "ring ledger: "//trim(msg))
            if (allocated(error)) return
            call simulate(scene, run, log)
            call check(error, run%status == status_horizon .and. run%n > 20, &
                "ring ledger: e = "//str(es(j))//": "//itoa(run%n)//" collisions, status " &
                //itoa(run%status))
            if (allocated(error)) return
            lost = 0
            do k = 1, log%n
                if (log%kind(k) /= event_collision) cycle
                i = log%first(k)
                mu = m(i)*m(mod(i, 6) + 1)/(m(i) + m(mod(i, 6) + 1))
                lost = lost + 0.5_qp*(1 - es(j)**2)*mu*log%w(k)**2
            end do
            e0 = kinetic_energy(scene, v)
            e1 = kinetic_energy(scene, run%v)
            p0 = momentum(scene, v)
            p1 = momentum(scene, run%v)
            ! (a velocity error within v_bounds moves the energy by at most
            ! sum m |v| b + sum m b^2 / 2, the momentum by sum m b)
            norm = sum(m*run%v_bounds)
            drift = sum(m*abs(run%v)*run%v_bounds) + 0.5_qp*sum(m*run%v_bounds**2) &
                + 1.0e-30_qp*e0
            call check(error, abs(p1 - p0) <= norm + 1.0e-32_qp, "ring ledger: momentum " &
                //str(p0)//" -> "//str(p1)//", beyond its bound "//str(norm))
            if (allocated(error)) return
            call check(error, abs((e0 - e1) - lost) <= drift, "ring ledger: e = "//str(es(j)) &
                //": energy lost "//str(e0 - e1)//" against the collisions' "//str(lost))
            if (allocated(error)) return
        end do
    end subroutine test_ring_ledger

    !> A run to a horizon gives the state at that time: the same collisions
    !> as the run that goes on, every gap the last event's moved on linearly
    !> to t_max (gaps_at_time), and the velocities of that last event.
    subroutine test_horizon(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run, longer
        integer :: stat
        real(qp) :: v_now(5), norm
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=5, e=0.9_qp, velocities=[1.0_qp, -0.5_qp, &
            0.2_qp, 0.9_qp, -1.0_qp], ring=0.7_qp, t_max=7.3_qp)
        call check(error, stat == status_normal, "horizon: "//trim(msg))
        if (allocated(error)) return
        call simulate(scene, run)
        scene%t_max = 7.3_qp + 1.0e-3_qp
        call simulate(scene, longer)
        call check(error, run%status == status_horizon .and. run%clock%t == 7.3_qp, &
            "horizon: stopped at "//str(run%clock%t)//", status "//itoa(run%status))
        if (allocated(error)) return
        ! (no collision between the two horizons, for this scene)
        call check(error, longer%n == run%n, "horizon: "//itoa(run%n)//" collisions to " &
            //"t_max, "//itoa(longer%n)//" to a moment later")
        if (allocated(error)) return
        call check(error, all(abs(longer%y - (run%y + run%dy*1.0e-3_qp)) <= 1.0e-30_qp), &
            "horizon: the gaps a moment later are not the state at t_max moved on")
        if (allocated(error)) return
        call velocities_now(scene, longer, v_now, norm)
        call check(error, all(abs(v_now - run%v) <= run%v_bounds + norm), &
            "horizon: the velocities differ a moment later")
    end subroutine test_horizon

    !> A horizon inside a collapse: the definition's row at e = 0.1 collapses
    !> by a certified cycle whose collisions accumulate at t_c = 6.0543...,
    !> its limit found at a collision before t_c and taken after a further
    !> time. With t_max between that collision and t_c the run does not take
    !> the limit (finitely many collisions come first, and it takes them),
    !> and the velocities are not yet the group's; with t_max just after t_c,
    !> the limit is taken and every sphere moves at v0/4.
    subroutine test_horizon_in_collapse(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: whole, before, after
        type(event_log_t) :: log
        integer :: stat, k
        real(qp) :: t_found
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=4, e=0.1_qp)
        call check(error, stat == status_normal, "horizon in a collapse: "//trim(msg))
        if (allocated(error)) return
        call simulate(scene, whole, log)
        ! (the collision after which the limit was found: the log's row before it)
        k = findloc(log%kind(1:log%n), event_collapse, 1)
        call check(error, whole%limits%certified == 1 .and. k > 1, &
            "horizon in a collapse: the row's limit is not a certified cycle's")
        if (allocated(error)) return
        t_found = log%t(k - 1)
        call check(error, t_found < whole%limits%t, "horizon in a collapse: the limit is not " &
            //"taken after a further time")
        if (allocated(error)) return
        scene%t_max = t_found + (whole%limits%t - t_found)/2
        call simulate(scene, before)
        call check(error, before%status == status_horizon .and. before%limits%n == 0 .and. &
            before%n >= whole%n .and. maxval(before%v) - minval(before%v) > 0.0_qp, &
            "horizon in a collapse: before t_c, "//itoa(before%limits%n)//" limits, " &
            //itoa(before%n)//" collisions, spread "//str(maxval(before%v) - minval(before%v)))
        if (allocated(error)) return
        scene%t_max = whole%limits%t + 1.0e-6_qp
        call simulate(scene, after)
        call check(error, after%limits%certified == 1 .and. all(abs(after%v - 0.25_qp) <= &
            after%v_bounds), "horizon in a collapse: after t_c, "//itoa(after%limits%n) &
            //" limits, v1 = "//str(after%v(1)))
    end subroutine test_horizon_in_collapse

    !> Two equal spheres and a wall, e = e_wall = 0.1, below their collapse
    !> threshold: the pair collapses against the wall; the run takes the
    !> limit of both at rest (at tolerance, its bound the group's energy in
    !> the wall's frame) instead of spending its budget.
    subroutine test_wall_group(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=2, e=0.1_qp, velocities=[-1.0_qp, -1.0_qp], &
            wall_left=0.5_qp, gaps=[0.5_qp])
        call check(error, stat == status_normal, "wall group: "//trim(msg))
        if (allocated(error)) return
        call simulate(scene, run)
        call check(error, run%limits%tolerance == 1 .and. run%n < 1000, "wall group: " &
            //itoa(run%n)//" collisions, "//itoa(run%limits%tolerance)//" limits at tolerance")
        if (allocated(error)) return
        call check(error, all(run%v == 0.0_qp) .and. run%v_bound < 1.0e-30_qp, &
            "wall group: v = "//str(run%v(1))//", "//str(run%v(2))//", bound " &
            //str(run%v_bound))
        if (allocated(error)) return
        ! a group at the wall whose gaps and rates are quiet but which moves
        ! away from it is not taken to rest: spheres 1 and 2 leave the wall
        ! together at v0 as a light third is struck plastically (its strike
        ! changes their rate by 1e-12, below tol = 1e-10)
        call scene_init(scene, stat, msg, p=3, e=0.0_qp, masses=[1.0_qp, 1.0_qp, 1.0e-3_qp], &
            velocities=[1.0_qp, 1.0_qp, 1.0_qp - 1.0e-9_qp], gaps=[0.0_qp, 0.0_qp], &
            wall_left=0.0_qp, tol=1.0e-10_qp)
        call check(error, stat == status_normal, "wall group: "//trim(msg))
        if (allocated(error)) return
        call simulate(scene, run)
        call check(error, run%n > 0 .and. all(abs(run%v - 1.0_qp) < 1.0e-6_qp), &
            "wall group: a pair leaving the wall ends at v1 = "//str(run%v(1)))
    end subroutine test_wall_group

    !> The random gas is as asked: gaps that fill the free length exactly
    !> (no overlap), zero momentum, the temperature exact, and the same state
    !> whatever slice of spheres is made (each number a function of its index).
    subroutine test_gas_state(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: p = 1000
        real(qp) :: gaps(p), v(p), m(p), t
        type(scene_t) :: scene
        logical :: ok
        m = 1
        m(::3) = 2
        call gas_state(p, 1.0_qp, m, 0.25_qp, 2.0_qp, 7_int64, gaps, v, ok)
        call check(error, ok .and. all(gaps >= 0), "gas: refused, or a gap below 0")
        if (allocated(error)) return
        call check(error, abs(sum(gaps) - p*(4.0_qp - 1.0_qp)) <= 1.0e-28_qp*p, &
            "gas: the gaps sum to "//str(sum(gaps))//", not the free length")
        if (allocated(error)) return
        t = sum(m*(v - sum(m*v)/sum(m))**2)/p
        call check(error, abs(sum(m*v)) <= 1.0e-28_qp .and. abs(t - 2.0_qp) <= 1.0e-28_qp, &
            "gas: momentum "//str(sum(m*v))//", temperature "//str(t))
        if (allocated(error)) return
        ! (gap 17's exponential variate is -log of counter 34's uniform)
        call check(error, abs(gaps(17)/gaps(18) - log(real(gas_uniform(7_int64, 34_int64), &
            qp))/log(real(gas_uniform(7_int64, 36_int64), qp))) <= 1.0e-25_qp, &
            "gas: gap 17 is not its own counter's")
        if (allocated(error)) return
        call gas_state(p, 1.0_qp, m, 1.0_qp, 2.0_qp, 7_int64, gaps, v, ok)
        call check(error, .not. ok, "gas: density d = 1 accepted")
        if (allocated(error)) return
        ! (as sphere-row reads it: the velocities drawn for the masses given)
        call scene_of("gas=ring p=10 temperature=2 masses=1,2,1,2,1,2,1,2,1,3 t_max=1", &
            scene, error)
        if (allocated(error)) return
        t = sum(scene%m*scene%v**2)/scene%p
        call check(error, abs(sum(scene%m*scene%v)) <= 1.0e-30_qp .and. &
            abs(t - 2.0_qp) <= 1.0e-30_qp, "gas with masses: momentum " &
            //str(sum(scene%m*scene%v))//", temperature "//str(t))
    end subroutine test_gas_state

    !> A horizon within rounding of a collision's time: whether that
    !> collision comes before t_max rests on the computed times, so the
    !> answer is not exact and its bound holds either way (two spheres, the
    !> impact at t = 1 exactly; t_max 10^-37 before it rounds to 1, and
    !> 10^-34 after it); and at 6.054359977935181991382103682933078, 5.5e-34
    !> after the accumulation time of p = 4, e = 0.1's collapse, where every
    !> sphere moves at v0/4, which the run does not reach.
    subroutine test_horizon_doubt(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: keys(3) = [character(len=60) :: &
            "p=2 velocities=1,0 t_max=0.9999999999999999999999999999999999999", &
            "p=2 velocities=1,0 t_max=1.0000000000000000000000000000000001", &
            "p=4 e=0.1 t_max=6.054359977935181991382103682933078"]
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: i
        logical :: within
        do i = 1, size(keys)
            call scene_of(trim(keys(i)), scene, error)
            if (allocated(error)) return
            call simulate(scene, run)
            if (i < 3) then
                ! (before the collision 1, 0; after it (1 - e)/2, (1 + e)/2)
                within = all(abs(run%v - [1.0_qp, 0.0_qp]) <= run%v_bounds) .and. &
                    all(abs(run%v - [1 - scene%e, 1 + scene%e]/2) <= run%v_bounds)
            else
                within = all(abs(run%v - 0.25_qp) <= run%v_bounds)
            end if
            call check(error, run%answer /= answer_exact .and. within, trim(keys(i))// &
                ": answer "//answer_word(run%answer)//", v_bound "//str(run%v_bound))
            if (allocated(error)) return
        end do
        ! (a horizon clear of every collision stays exact)
        call scene_of("p=2 velocities=1,0 t_max=1.00001", scene, error)
        if (allocated(error)) return
        call simulate(scene, run)
        call check(error, run%answer == answer_exact .and. run%v_bound < 1.0e-30_qp, &
            "a horizon clear of the collision: answer "//answer_word(run%answer))
    end subroutine test_horizon_doubt

    !> The integers of a file, one a line.
    subroutine read_ints(path, ks)
        character(len=*), intent(in) :: path
        integer, allocatable, intent(out) :: ks(:)
        integer :: unit, n, ios, k
        n = 0
        open (newunit=unit, file=path, status="old", action="read")
        do
            read (unit, *, iostat=ios) k
            if (ios /= 0) exit
            n = n + 1
        end do
        rewind (unit)
        allocate (ks(n))
        read (unit, *) ks
        close (unit)
    end subroutine read_ints

end module test_scenes
