!> Tests of the critical restitution of the struck row: the rate map of the
!> collapse cycle against the closed forms of p = 3 and p = 4, the scanned
!> edge around them, e_c growing with p, and what a scan says of its edge.
module test_ecrit
    use sphere_row, only: qp, dp, str, itoa, status_normal, scene_t, run_t, scene_dp_t, &
        run_dp_t, scene_init, simulate
    use sphere_row_ecrit, only: ecrit_settings_t, ecrit_row_t, ecrit_row, rate_map_critical, &
        edge_t, edge_of, digits_of, decimal_text, outcome_certified, outcome_unproven, &
        outcome_finite, outcome_undecided, outcome_of, outcome_word
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_ecrit

    !> Agreement asked of the rate map with a closed form (30-digit kind).
    real(qp), parameter :: closed_tol = 1.0e-25_qp
    !> Cheap settings for the tests: a coarse locating scan, a short scan of
    !> the edge.
    integer, parameter :: test_grid = 10, test_scan = 24

contains

    !> The e_c tests.
    function collect_ecrit() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("rate_map_cycle_p3", test_map_p3), &
            new_unittest("rate_map_cycle_p4", test_map_p4), &
            new_unittest("rows_3_and_4", test_rows), &
            new_unittest("e_crit_increases", test_increasing), &
            new_unittest("edge_of_a_scan", test_edge_of), &
            new_unittest("outcome_told_by_the_labels", test_outcome_of) &
            ]
    end function collect_ecrit

    !> p = 3: the cycle 12 gives 7 - 4 sqrt(3).
    subroutine test_map_p3(error)
        type(error_t), allocatable, intent(out) :: error
        call check_rate_map(error, 3, [1, 2], 7.0_qp - 4.0_qp*sqrt(3.0_qp))
    end subroutine test_map_p3

    !> p = 4: the cycle 32121232 of task b1 gives 3 - 2 sqrt(2).
    subroutine test_map_p4(error)
        type(error_t), allocatable, intent(out) :: error
        call check_rate_map(error, 4, [3, 2, 1, 2, 1, 2, 3, 2], 3.0_qp - 2.0_qp*sqrt(2.0_qp))
    end subroutine test_map_p4

    !> The rate map of collapse cycle `cycle` of p equal spheres finds its e_c
    !> within closed_tol of the closed form `closed`, searched near it.
    subroutine check_rate_map(error, p, cycle, closed)
        type(error_t), allocatable, intent(inout) :: error
        integer, intent(in) :: p, cycle(:)
        real(qp), intent(in) :: closed
        real(qp), parameter :: window = 1.0e-3_qp, probe = 1.0e-8_qp
        real(qp) :: e_c, m(p)
        integer :: stat
        m = 1.0_qp
        call rate_map_critical(m, cycle, closed - window, closed + window, probe, e_c, stat)
        call check(error, stat == status_normal, "p = "//itoa(p)//": no sign change of the pair")
        if (allocated(error)) return
        call check(error, abs(e_c - closed) <= closed_tol, "p = "//itoa(p)//": e_c = "//str(e_c))
    end subroutine check_rate_map

    !> The whole row procedure for p = 3 and 4: the rate map found from the
    !> row's own run matches the closed form, and the scan of the edge (at a
    !> deep tol) is clean, with no separated point below the closed form (the
    !> rows below it collapse) and the closed form within its bracket.
    subroutine test_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(ecrit_settings_t) :: s
        type(ecrit_row_t) :: row
        type(edge_t) :: g
        real(qp) :: closed(3:4)
        integer :: p
        closed = [7.0_qp - 4.0_qp*sqrt(3.0_qp), 3.0_qp - 2.0_qp*sqrt(2.0_qp)]
        s%n_grid = test_grid
        s%n_scan = test_scan
        s%tol_scan = 1.0e-300_qp
        s%robust_p_max = 0
        do p = 3, 4
            call ecrit_row(p, s, row)
            call check(error, row%has_map, "p = "//itoa(p)//": no rate-map value")
            if (allocated(error)) return
            call check(error, abs(row%e_map - closed(p)) <= closed_tol, &
                "rate map "//str(row%e_map))
            if (allocated(error)) return
            g = edge_of(row%e_from, row%e_to, row%outcomes, row%decades)
            call check(error, .not. g%mixed .and. g%finite_min > closed(p) .and. &
                g%collapse_max <= closed(p) + g%collapse_width, "p = "//itoa(p)// &
                ": edge ["//str(g%collapse_max)//", "//str(g%finite_min)//"], mixed "// &
                merge("T", "F", g%mixed))
            if (allocated(error)) return
        end do
    end subroutine test_rows

    !> The lowest separated point of the scan grows with p over p = 3 ... 12.
    subroutine test_increasing(error)
        type(error_t), allocatable, intent(out) :: error
        type(ecrit_settings_t) :: s
        type(ecrit_row_t) :: row
        type(edge_t) :: g
        real(qp) :: last
        integer :: p
        integer, parameter :: p_last = 12
        s%n_grid = test_grid
        s%n_scan = test_scan
        s%p_fine = 0
        s%map_p_max = 0
        s%robust_p_max = 0
        last = 0.0_qp
        do p = 3, p_last
            call ecrit_row(p, s, row)
            g = edge_of(row%e_from, row%e_to, row%outcomes, row%decades)
            call check(error, g%finite_min > last .and. g%finite_min < 1.0_qp, &
                "the edge does not grow at p = "//itoa(p)//": "//str(g%finite_min))
            if (allocated(error)) return
            last = g%finite_min
        end do
    end subroutine test_increasing

    !> A point's outcome is what its run's labels prove, never its count:
    !> separated only where the run ended normally with an exact answer,
    !> certified only where collapse_proven holds. Each scene has one label
    !> that decides: a separation (p = 4, e = 0.2), a certified cycle
    !> (e = 0.1), a group merged at tolerance and nothing else that denies a
    !> proof (a heavy sphere striking light ones; its other group certified),
    !> a bounded cascade (a touching row of 20 with the closed forms off),
    !> certified limits but a collision passed over below tol (a row near
    !> p = 8's edge; at tol = 1e-60 it takes more collisions),
    !> a normal end with a pair still closing slower than tol v0 (p = 3,
    !> e = 1/2, tol = 0.3: spheres 1 and 2 close at v0/16 after two
    !> collisions), and the budget spent; in real64 the first, the second and
    !> the normal end at tolerance again.
    subroutine test_outcome_of(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(scene_dp_t) :: scene_dp
        type(run_dp_t) :: run_dp
        integer :: stat, i
        character(len=200) :: msg
        !> The real64 scenes (tol the default, real64's epsilon, where not
        !> given) and the outcome each must have.
        character(len=*), parameter :: dp_names(3) = [character(len=24) :: &
            "real64 p=4 e=0.2", "real64 p=4 e=0.1", "real64 p=3 e=0.5 tol=0.3"]
        integer, parameter :: dp_p(3) = [4, 4, 3], &
            dp_expected(3) = [outcome_finite, outcome_certified, outcome_undecided]
        real(dp), parameter :: dp_e(3) = [0.2_dp, 0.1_dp, 0.5_dp], &
            dp_tol(3) = [epsilon(1.0_dp), epsilon(1.0_dp), 0.3_dp]
        call scene_init(scene, stat, msg, p=4, e=0.2_qp)
        call expect("p=4 e=0.2", outcome_finite)
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=4, e=0.1_qp)
        call expect("p=4 e=0.1", outcome_certified)
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=4, e=0.555963_qp, &
            masses=[18.25_qp, 0.04349_qp, 0.02667_qp, 0.2489_qp], &
            gaps=[0.6196_qp, 0.0_qp, 1.546_qp])
        call expect("merged at tolerance", outcome_unproven)
        if (allocated(error)) return
        call check(error, run%limits%tolerance > 0 .and. run%limits%bounded == 0 .and. &
            .not. run%clock%passed, "merged at tolerance: the premise, a limit at "// &
            "tolerance and nothing else that denies a proof, does not hold")
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=20, e=0.5_qp, gaps=spread(0.0_qp, 1, 19))
        scene%closed_form_limits = .false.
        scene%vtol = 1.0e-6_qp
        call expect("bounded cascade", outcome_unproven)
        if (allocated(error)) return
        call check(error, run%limits%bounded > 0 .and. run%limits%tolerance == 0, &
            "bounded cascade: the premise, a bounded limit alone, does not hold")
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=8, e=0.427873_qp, masses=[67.09_qp, 1.965_qp, &
            1.002_qp, 1.569_qp, 1.526_qp, 1.79_qp, 1.805_qp, 1.102_qp], gaps=[1.046_qp, &
            1.121_qp, 1.486_qp, 0.0_qp, 0.03103_qp, 0.0_qp, 0.5512_qp])
        call expect("certified limits, a pass below tol", outcome_unproven)
        if (allocated(error)) return
        call check(error, run%limits%n > 0 .and. run%limits%certified == run%limits%n .and. &
            run%clock%passed, "certified limits, a pass below tol: the premise does not hold")
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=3, e=0.5_qp, tol=0.3_qp)
        call expect("p=3 e=0.5 tol=0.3", outcome_undecided)
        if (allocated(error)) return
        call check(error, run%status == status_normal .and. run%limits%n == 0, &
            "p=3 e=0.5 tol=0.3: the premise, a normal end without limits, does not hold")
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=4, e=0.1_qp, max_collisions=20)
        call expect("p=4 e=0.1 max_collisions=20", outcome_undecided)
        if (allocated(error)) return
        do i = 1, size(dp_names)
            call scene_init(scene_dp, stat, msg, p=dp_p(i), e=dp_e(i), tol=dp_tol(i))
            call simulate(scene_dp, run_dp)
            call check(error, outcome_of(run_dp) == dp_expected(i), trim(dp_names(i))// &
                ": outcome "//outcome_word(outcome_of(run_dp))//", expected " &
                //outcome_word(dp_expected(i)))
        end do
    contains
        !> Run `scene`; its outcome must be `expected`.
        subroutine expect(name, expected)
            character(len=*), intent(in) :: name
            integer, intent(in) :: expected
            call simulate(scene, run)
            call check(error, outcome_of(run) == expected, name//": outcome "// &
                outcome_word(outcome_of(run))//", expected "//outcome_word(expected))
        end subroutine expect
    end subroutine test_outcome_of

    !> edge_of on a made-up scan of 11 points over [0, 1] (h = 0.1): the ends,
    !> the widths that unproven and undecided points add (an unproven merge is
    !> not a collapse), the band where outcomes mix, the decimals, the counts.
    subroutine test_edge_of(error)
        type(error_t), allocatable, intent(out) :: error
        type(edge_t) :: g
        integer, parameter :: c = outcome_certified, b = outcome_unproven, &
            f = outcome_finite, u = outcome_undecided
        real(qp), parameter :: h = 0.1_qp, close_enough = 1.0e-30_qp
        g = edge_of(0.0_qp, 1.0_qp, [c, c, c, u, f, c, b, u, u, f, f], &
            [0, 0, 0, 0, -7, 0, 0, 0, 0, -3, -1])
        call check(error, abs(g%collapse_max - 0.5_qp) < close_enough .and. &
            abs(g%collapse_width - 4*h) < close_enough .and. &
            abs(g%finite_min - 0.4_qp) < close_enough .and. &
            abs(g%finite_width - 2*h) < close_enough, "ends "//str(g%collapse_max)//" + "// &
            str(g%collapse_width)//", "//str(g%finite_min)//" - "//str(g%finite_width))
        if (allocated(error)) return
        call check(error, g%mixed .and. g%band_points == 2 .and. g%band_collapses == 1 .and. &
            g%finite_decade == -7 .and. all(g%counts == [3, 4, 1, 3]) .and. &
            abs(g%certified_max - 0.5_qp) < close_enough .and. &
            g%collapse_digits == 1 .and. digits_of(2.5e-4_qp) == 4, "band, counts or digits")
        if (allocated(error)) return
        g = edge_of(0.0_qp, 1.0_qp, [c, c, u, f], [0, 0, 0, -2])
        call check(error, .not. g%mixed .and. abs(g%collapse_width - 2.0_qp/3) < close_enough &
            .and. abs(g%finite_width - 2.0_qp/3) < close_enough .and. &
            decimal_text(0.39725_qp, 3) == "0.397", "a clean edge across an undecided point: "// &
            str(g%collapse_width)//" "//decimal_text(0.39725_qp, 3))
    end subroutine test_edge_of

end module test_ecrit
