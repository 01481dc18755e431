!> Tests of the collapse limits taken in closed form: certified collision
!> cycles and plastic cascades at one instant. Each compares with a closed
!> form, with the fallback rule alone, or with the same run without limits.
module test_collapse
    use sphere_row, only: qp, dp, scene_t, run_t, event_log_t, scene_init, simulate, &
        kinetic_energy, momentum, status_normal, status_collapsed, status_max_collisions, str, &
        itoa, answer_exact, answer_certified, answer_tolerance, answer_bounded, collapse_proven, &
        answer_unresolved, answer_word, struck_least, event_collision, event_collapse
    use sphere_row_cascade, only: cascade_jump
    use testsuite, only: error_t, unittest_t, new_unittest, check, seed_random, cases, &
        read_text
    use test_support, only: run_and_rerun, scene_of, split_tabs, random_row
    implicit none
    private
    public :: collect_collapse

    !> Unit roundoff of the working precision, the scale of every tolerance here.
    real(qp), parameter :: eps = epsilon(1.0_qp)
    !> Critical restitution of the struck row: p = 4 (3 - 2 sqrt 2) and the
    !> three-sphere cycle (7 - 4 sqrt 3).
    real(qp), parameter :: e_crit_4 = 3 - 2*sqrt(2.0_qp), e_crit_3 = 7 - 4*sqrt(3.0_qp)

    !> A row that ends in merged blocks (check_row_merges): what it shows, its
    !> budget, whether every limit must be in closed form, whether it ends as
    !> one block, and its scene as sphere-row takes it.
    type :: merging_t
        character(len=:), allocatable :: what
        integer :: most
        logical :: closed_only, one_block
        character(len=:), allocatable :: keys
    end type merging_t

contains

    !> A run cut by its budget is unresolved, names its active groups, and
    !> the velocities it ends with lie within its bound of those the same
    !> scene ends with when run to its answer (the cone bound: whatever the
    !> order of the collisions still to come). Random rows of light and heavy
    !> spheres, cut after 200 to 2000 collisions (60 rows drawn, 1200 in the
    !> long tests; a cut run that ends in a nested run of a group followed on
    !> its own scale merges that group at tolerance instead: not unresolved).
    subroutine test_unresolved_bound(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: short, long
        real(qp) :: u(42)
        integer :: i, checked
        call seed_random(8642, 7)
        checked = 0
        do i = 1, cases(60, 1200)
            call random_row(scene, 0.3_qp, 20000, p_range=[3, 10], unequal=.true., drawn=u)
            call simulate(scene, long)
            if (long%answer > answer_tolerance .or. long%n < 40) cycle
            scene%max_collisions = 10 + int((long%n - 20)*u(42))
            call simulate(scene, short)
            if (short%answer /= answer_unresolved) cycle
            checked = checked + 1
            call check(error, size(short%active, 2) > 0, "unresolved row "//itoa(i)// &
                ": no active group named")
            call check(error, all(abs(long%v - short%v) <= (short%v_bounds + long%v_bounds) &
                *(1 + 1.0e-20_qp)), "unresolved row "//itoa(i)//": velocities moved by "// &
                str(maxval(abs(long%v - short%v)))//", beyond their bounds (largest " &
                //str(short%v_bound)//")")
            if (allocated(error)) return
        end do
        call check(error, checked >= cases(10, 150), "unresolved bounds: too few rows checked: " &
            //itoa(checked))
    end subroutine test_unresolved_bound

    !> A touching row of 20 equal spheres, struck at one end, merges (the box
    !> proves it: every sphere at v0/20). With the closed-form rules off the
    !> engine steps its cascade at one instant, and the bounded rule takes it
    !> after 4096 collisions, its cone bound then within vtol (1e-6): every
    !> velocity it gives is within that bound of the merge (e = 0.5 and 0.6).
    subroutine test_bounded_cascade(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: bounded, merged
        integer :: i
        character(len=*), parameter :: rows(2) = ["p=20 a=0 e=0.5", "p=20 a=0 e=0.6"]
        do i = 1, size(rows)
            call scene_of(rows(i), scene, error)
            if (allocated(error)) return
            call run_and_rerun(scene, merged, bounded, vtol=1.0e-6_qp, closed_form_limits=.false.)
            call check(error, merged%answer == answer_certified .and. &
                bounded%answer == answer_bounded .and. bounded%limits%bounded == 1, &
                "bounded cascade, "//rows(i)//": answers "//answer_word(merged%answer) &
                //" and "//answer_word(bounded%answer))
            call check(error, bounded%v_bound > 0 .and. bounded%v_bound <= scene%vtol, &
                "bounded cascade: bound "//str(bounded%v_bound)//" not in (0, vtol]")
            call check(error, all(abs(bounded%v - merged%v) <= bounded%v_bound*(1 + 1.0e-20_qp)), &
                "bounded cascade: velocities "//str(maxval(abs(bounded%v - merged%v)))// &
                " from the merge, beyond the bound "//str(bounded%v_bound))
            if (allocated(error)) return
        end do
        ! the rule waits for vtol: at vtol a third of the bound b it reaches at
        ! its first look (4096 collisions), it takes the cascade only later,
        ! with a bound of at most vtol
        call scene_of(rows(1), scene, error)
        if (allocated(error)) return
        scene%closed_form_limits = .false.
        scene%vtol = 0.999_qp
        call simulate(scene, merged)
        scene%vtol = merged%v_bound/3
        call simulate(scene, bounded)
        call check(error, bounded%answer == answer_bounded .and. bounded%n > merged%n .and. &
            bounded%v_bound <= scene%vtol, "bounded cascade at vtol "//str(scene%vtol) &
            //": taken after "//itoa(bounded%n)//" collisions (at vtol 0.999: " &
            //itoa(merged%n)//") with the bound "//str(bounded%v_bound))
    end subroutine test_bounded_cascade

    !> Three equal spheres, elastic, the budget spent after the first
    !> collision (v = 0, 1, 0; the cradle ends at 0, 0, 1): each velocity moves
    !> by 1 and its own cone bound is 1/2 + sqrt(1/2) (the pool of 2, 3 at
    !> 1/2, at distance sqrt(1/2) from the cone): the bound holds, and is
    !> tight to that factor, not loose by more.
    subroutine test_cone_bound_by_hand(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: short, long
        integer :: stat
        character(len=200) :: msg
        real(qp), parameter :: expected = 0.5_qp + sqrt(0.5_qp)
        call scene_init(scene, stat, msg, p=3, e=1.0_qp, max_collisions=1)
        call run_and_rerun(scene, short, long, max_collisions=0)
        call check(error, short%answer == answer_unresolved .and. long%answer == answer_exact, &
            "cone bound by hand: answers "//answer_word(short%answer)//" and " &
            //answer_word(long%answer))
        call check(error, all(abs(long%v - short%v) <= short%v_bounds), &
            "cone bound by hand: a velocity beyond its bound")
        call check(error, abs(short%v_bounds(2) - expected) <= 1.0e-30_qp .and. &
            abs(short%v_bounds(3) - expected) <= 1.0e-30_qp, "cone bound by hand: bounds " &
            //str(short%v_bounds(2))//" and "//str(short%v_bounds(3))//", expected "//str(expected))
    end subroutine test_cone_bound_by_hand

    !> A run that ends with an insignificant closing rate says tolerance, and
    !> the same scene at a finer tolerance ends within the bound it gives:
    !> sphere 2, sent off at 1.2e-40 v0 by sphere 1 of mass 1e-40, still closes
    !> on sphere 3 at rest when the run ends (its rate is below tol v0 =
    !> 1.9e-34). Each sphere within its own bound: 2..4's of about 1e-40, not
    !> the light sphere 1's 1e-20.
    subroutine test_tolerance_end(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: coarse, fine
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, masses=[1.0e-40_qp, 1.0_qp, 1.0_qp, 1.0_qp])
        call run_and_rerun(scene, coarse, fine, tol=1.0e-60_qp)
        call check(error, coarse%answer == answer_tolerance .and. fine%answer == answer_exact, &
            "tolerance end: answers "//answer_word(coarse%answer)//" and " &
            //answer_word(fine%answer))
        call check(error, coarse%v_bound > 0 .and. &
            all(abs(fine%v - coarse%v) <= coarse%v_bounds*(1 + 1.0e-20_qp)) .and. &
            maxval(coarse%v_bounds(2:)) < 1.0e-39_qp, &
            "tolerance end: velocities "//str(maxval(abs(fine%v - coarse%v)))// &
            " from the finer run, beyond their bounds, or the bounds of spheres 2..4 " &
            //"not below 1e-39")
    end subroutine test_tolerance_end

    !> A certified cycle's limit is taken at the accumulation time of its
    !> collisions: the same scene stepped by the fallback alone at a tolerance
    !> of 1e-60, which runs the geometric series of the collisions down to
    !> rates of 1e-60, ends within 1e-12 of that time (p = 3 at e = 0.05 and
    !> the definition's row at e = 0.1). A limit taken one period early or
    !> late is off by a whole period's duration (4e-8 at p = 3). (The cycle's
    !> tail is summed from the last ratio of its period times, which after
    !> three periods is good to about 1e-16.) A row of unequal masses
    !> (1, 2, 1.5, 1) collapses in an order with no period in exact
    !> arithmetic (as far as 16,000 collisions): the group is followed on
    !> its own scale, where real(16)'s own order falls into a cycle
    !> (docs/collapse.md: the premise "the same collisions" fails after
    !> 586), and the certified limit, the group's mean, is within 1e-12 of
    !> the time stepped to 1e-60 (a
    !> merge of its gaps once they were below tol v0, at rates of 1e-13, had
    !> ended it 2e-19 early and called it certified).
    subroutine test_cycle_time(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: cycle, stepped
        integer :: i
        character(len=*), parameter :: rows(3) = [character(len=32) :: "p=3 e=0.05", &
            "p=4 e=0.1", "p=4 e=0.1 masses=1,2,1.5,1"]
        do i = 1, size(rows)
            call scene_of(trim(rows(i)), scene, error)
            if (allocated(error)) return
            call run_and_rerun(scene, cycle, stepped, tol=1.0e-60_qp, closed_form_limits=.false.)
            call check(error, cycle%status == status_collapsed .and. &
                cycle%limits%closed_form >= 1 .and. cycle%answer == answer_certified .and. &
                stepped%status == status_collapsed, "cycle time, scene "//itoa(i) &
                //": not a certified closed-form limit and a stepped collapse, answer " &
                //answer_word(cycle%answer))
            call check(error, abs(cycle%t_end - stepped%t_end) <= 1.0e-12_qp, &
                "cycle time, scene "//itoa(i)//": limit at "//str(cycle%t_end) &
                //", stepped to "//str(stepped%t_end))
            if (allocated(error)) return
        end do
    end subroutine test_cycle_time

    !> The collapse tests.
    function collect_collapse() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("light_middle_sphere", test_light_middle), &
            new_unittest("labels_hold_near_the_edge", test_labels_near_edge), &
            new_unittest("try_at_tol_proves_no_collapse", test_try_at_tol), &
            new_unittest("label_of_a_pass_below_tol", test_pass_below_tol), &
            new_unittest("rounding_bound_holds", test_rounding_bound), &
            new_unittest("rounding_bound_in_double_covers_its_formula", test_rounding_in_double), &
            new_unittest("unresolved_bound_holds", test_unresolved_bound), &
            new_unittest("bounded_cascade_within_its_bound", test_bounded_cascade), &
            new_unittest("tolerance_end_within_its_bound", test_tolerance_end), &
            new_unittest("cone_bound_by_hand", test_cone_bound_by_hand), &
            new_unittest("cycle_limit_at_its_accumulation_time", test_cycle_time), &
            new_unittest("plastic_cascade_matches_fallback", test_plastic_cascade), &
            new_unittest("plastic_unequal_masses", test_plastic_unequal), &
            new_unittest("finite_counts_near_e_crit", test_near_critical), &
            new_unittest("three_sphere_threshold", test_three_spheres), &
            new_unittest("touching_three_blocks_certified_below_their_edge", test_three_blocks), &
            new_unittest("log_does_not_change_result", test_log_neutral), &
            new_unittest("random_rows_finite_unchanged", test_random_rows), &
            new_unittest("touching_cascade_matches_fallback", test_touching_cascade), &
            new_unittest("light_spheres_between_heavy", test_light_between_heavy), &
            new_unittest("long_rows_answer", test_long_rows), &
            new_unittest("struck_blocks_absorb_in_constant_work", test_struck_sweep), &
            new_unittest("struck_block_proof_by_hand", test_struck_least), &
            new_unittest("struck_block_absorbed_from_q0_on", test_struck_from_q0), &
            new_unittest("cascade_jump_equals_stepping", test_cascade_jump), &
            new_unittest("shuttle_in_touching_row", test_shuttle_row), &
            new_unittest("rows_end_in_merged_blocks", test_merging_rows), &
            new_unittest("quiet_cascade_matches_fallback", test_quiet_cascade) &
            ]
    end function collect_collapse

    !> Rows near p = 5's edge that separate in exact arithmetic, far below tol
    !> (the replay, tools/replay: after 1062 collisions at rates of 2.6e-106
    !> v0, after 441 at 1.2e-49): at the default tol their gaps and rates
    !> fall below tol first, and the group, followed on its own scale,
    !> separates with the replay's count and scale (a merge of their sub-tol
    !> gaps as a touching block had called them certified collapses, and a
    !> merge at tolerance left them unproven); at tol = 1e-300 each separates
    !> the same way.
    subroutine test_labels_near_edge(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat, i
        character(len=200) :: msg
        real(qp), parameter :: es(2) = [0.2593_qp, 0.260419_qp]
        integer, parameter :: counts(2) = [1062, 441]
        real(qp), parameter :: scales(2) = [2.6e-106_qp, 1.2e-49_qp]
        do i = 1, size(es)
            call scene_init(scene, stat, msg, p=5, e=es(i))
            call simulate(scene, run)
            call check(error, run%status == status_normal .and. run%answer == answer_exact .and. &
                run%n == counts(i) .and. abs(log10(maxval(abs(run%dy))/scales(i))) < 0.1_qp, &
                "e = "//str(es(i))//" at the default tol: "//itoa(run%n)//" collisions, answer " &
                //answer_word(run%answer)//", scale "//str(maxval(abs(run%dy)))// &
                "; the replay: "//itoa(counts(i))//" at "//str(scales(i)))
            if (allocated(error)) return
            scene%tol = 1.0e-300_qp
            call simulate(scene, run)
            call check(error, run%status == status_normal .and. run%answer == answer_exact .and. &
                run%n == counts(i) .and. abs(log10(maxval(abs(run%dy))/scales(i))) < 0.1_qp, &
                "e = "//str(es(i))//" at tol 1e-300: "//itoa(run%n)//" collisions, scale "// &
                str(maxval(abs(run%dy)))//"; the replay: "//itoa(counts(i))//" at "// &
                str(scales(i)))
            if (allocated(error)) return
        end do
    end subroutine test_labels_near_edge

    !> A touching block's try that steps the block until its rates fall below
    !> tol (the try's quiet end) proves nothing below tol: the struck block
    !> 3..6 of this row (sphere 3 of mass 712.3 between spheres near 1),
    !> given no budget to be followed on its own scale (100 collisions), is
    !> merged after 12 collisions at tolerance, no limit certified, and the
    !> collapse unproven; in exact arithmetic the row separates (the replay,
    !> tools/replay: after 604 collisions), as the run at the default budget
    !> does (the block followed on its own scale) and the run at tol =
    !> 1e-300, each with the replay's count.
    subroutine test_try_at_tol(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=6, e=0.314286_qp, &
            masses=[1.021_qp, 1.435_qp, 712.3_qp, 1.376_qp, 0.9328_qp, 1.115_qp], &
            gaps=[1.302_qp, 0.8459_qp, 1.528_qp, 0.0_qp, 0.0_qp], max_collisions=100)
        call simulate(scene, run)
        call check(error, run%answer == answer_tolerance .and. run%limits%certified == 0 &
            .and. run%limits%tolerance > 0 .and. run%status == status_collapsed, &
            "answer "//answer_word(run%answer)//" with "//itoa(run%limits%certified)// &
            " certified limits; expected a merge at tolerance and no certified limit")
        if (allocated(error)) return
        scene%max_collisions = 0
        call simulate(scene, run)
        call check(error, run%status == status_normal .and. run%answer == answer_exact .and. &
            run%n == 604, "followed: "//itoa(run%n)//" collisions, answer "// &
            answer_word(run%answer)//"; the replay separates after 604")
        if (allocated(error)) return
        scene%tol = 1.0e-300_qp
        call simulate(scene, run)
        call check(error, run%status == status_normal .and. run%answer == answer_exact .and. &
            run%n == 604, "at tol 1e-300: "//itoa(run%n)//" collisions, answer "// &
            answer_word(run%answer)//"; the replay separates after 604")
    end subroutine test_try_at_tol

    !> A collision passed over because its pair closed slower than tol v0 is
    !> one that exact arithmetic takes: a run that passed one rests on tol,
    !> whatever its limits proved. Two rows near p = 8's edge with spheres of
    !> unequal masses pass such collisions and take no limit at tolerance
    !> (their limits are certified): run again at tol = 1e-60 they take more
    !> collisions (1532 for 809, 833 for 503), so their answer cannot be one
    !> that holds without tol; it is tolerance.
    subroutine test_pass_below_tol(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: coarse, fine
        integer :: i
        character(len=*), parameter :: rows(2) = [character(len=120) :: &
            "p=8 e=0.427873 masses=67.09,1.965,1.002,1.569,1.526,1.79,1.805,1.102 " &
            //"gaps=1.046,1.121,1.486,0,0.03103,0,0.5512", &
            "p=8 e=0.431267 masses=1.034,0.6691,0.3555,0.6543,0.794,0.002794,0.6175,1.253 " &
            //"gaps=0,1.199,0.6832,0.675,1.975,0,1.594"]
        do i = 1, size(rows)
            call scene_of(trim(rows(i)), scene, error)
            if (allocated(error)) return
            call run_and_rerun(scene, coarse, fine, tol=1.0e-60_qp)
            call check(error, fine%n > coarse%n .and. coarse%answer == answer_tolerance, &
                "e = "//str(scene%e)//": "//itoa(coarse%n)//" collisions, answer "// &
                answer_word(coarse%answer)//"; at tol 1e-60 "//itoa(fine%n)// &
                " collisions: expected more, and the first answer tolerance")
            if (allocated(error)) return
        end do
    end subroutine test_pass_below_tol

    !> The rounding bound holds and earns its digits: the definition's row at
    !> e = 0.2 ends at rational velocities (its 13 collisions multiply and add
    !> decimals of e = 1/5 and halves), 0.24974780416, 0.24993030144,
    !> 0.2501074944 and 0.2502144 v0. Each computed velocity lies within its
    !> sphere's bound of them, and the bound is below 1e-31 (some 500
    !> roundings of the working precision: it adds each collision's at most).
    !> The same for the definition's collapse at e = 0.1, every velocity 1/4.
    subroutine test_rounding_bound(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        real(qp), parameter :: exact(4) = [0.24974780416_qp, 0.24993030144_qp, &
            0.2501074944_qp, 0.2502144_qp]
        call scene_init(scene, stat, msg, e=0.2_qp)
        call simulate(scene, run)
        call check(error, run%answer == answer_exact .and. all(abs(run%v - exact) <= &
            run%v_bounds) .and. all(run%v_bounds > 0) .and. run%v_bound < 1.0e-31_qp, &
            "e = 0.2: velocities "//str(maxval(abs(run%v - exact)))//" from the exact ones, "// &
            "bounds "//str(minval(run%v_bounds))//" ... "//str(run%v_bound))
        if (allocated(error)) return
        scene%e = 0.1_qp
        call simulate(scene, run)
        call check(error, run%answer == answer_certified .and. all(abs(run%v - 0.25_qp) <= &
            run%v_bounds) .and. run%v_bound < 1.0e-31_qp, "e = 0.1: velocities "// &
            str(maxval(abs(run%v - 0.25_qp)))//" from 1/4, bound "//str(run%v_bound))
    end subroutine test_rounding_bound

    !> The rounding bound is evaluated in double precision with its own
    !> rounding covered, or in real(16) where a quantity it reads is beyond
    !> double's safe range. A scene run at v0 = 1 and at v0 = 2^-900 takes the
    !> same collisions and limits with every rate, velocity and sum scaled by
    !> 2^-900 exactly (a power of two, far from real(16)'s limits), and its
    !> bound in real(16) (the second run) scaled back is the formula's value
    !> to real(16)'s precision: the bound in double (the first) must be at
    !> least that, and within 1e-8 of it (its cover is 2 (8 p + 16) 2^-53).
    !> Equal masses (summed from sphere 1), a heaviest sphere inside the row
    !> (summed from it, the momentum fixed), elastic, inelastic and
    !> collapsing rows.
    subroutine test_rounding_in_double(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: one, tiny
        real(qp), parameter :: scale = 2.0_qp**(-900)
        real(qp), parameter :: masses(7) = [1.0_qp, 2.0_qp, 3.0_qp, 0.5_qp, 3.0_qp, 1.0_qp, &
            0.25_qp]
        real(qp) :: back(300)
        integer :: stat, i, p
        character(len=200) :: msg
        do i = 1, 6
            select case (i)
            case (1)
                call scene_init(scene, stat, msg, p=300, e=1.0_qp)
            case (2)
                call scene_init(scene, stat, msg, p=60, e=0.5_qp)
            case (3)
                call scene_init(scene, stat, msg, p=4, e=0.1_qp)
            case (4)
                call scene_init(scene, stat, msg, p=7, e=0.7_qp, masses=masses)
            case (5)
                call scene_init(scene, stat, msg, p=7, e=0.2_qp, masses=masses)
            case default
                call scene_init(scene, stat, msg, p=7, e=0.9_qp, masses=masses(7:1:-1))
            end select
            p = scene%p
            call simulate(scene, one)
            scene%v0 = scale
            call simulate(scene, tiny)
            call check(error, one%n == tiny%n .and. one%limits%n == tiny%limits%n .and. &
                all(tiny%v == one%v*scale), "scene "//itoa(i)//": the run at v0 = 2^-900 is " &
                //"not the run at v0 = 1 scaled")
            if (allocated(error)) return
            back(:p) = tiny%v_rounding/scale
            call check(error, all(one%v_rounding >= back(:p)) .and. &
                all(one%v_rounding <= back(:p)*(1 + 1.0e-8_qp)) .and. all(back(:p) > 0), &
                "scene "//itoa(i)//": the bound in double lies "// &
                str(minval(one%v_rounding/back(:p) - 1))//" ... "// &
                str(maxval(one%v_rounding/back(:p) - 1))//" from its formula in real(16)")
            if (allocated(error)) return
        end do
    end subroutine test_rounding_in_double

    !> A light sphere between two heavy ones shuttles with rates shrinking by
    !> about 1 - 2m/M per cycle; the cycle limit gives the common velocity
    !> m1 v0 / sum(m) at once.
    subroutine test_light_middle(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        real(qp), parameter :: light = 1.0e-5_qp, e_values(3) = [0.0_qp, 0.5_qp, 0.9_qp]
        integer :: stat, i
        character(len=200) :: msg
        do i = 1, size(e_values)
            call scene_init(scene, stat, msg, p=3, e=e_values(i), masses=[1.0_qp, light, 1.0_qp])
            call simulate(scene, run)
            call check(error, run%status == status_collapsed .and. run%n < 1000, &
                "light middle sphere: no collapse within 1000 collisions")
            if (allocated(error)) return
            call check(error, all(abs(run%v - 1/(2 + light)) <= 1.0e-25_qp), &
                "light middle sphere: velocities not 1/(2 + m)")
            if (allocated(error)) return
        end do
    end subroutine test_light_middle

    !> At e = 0 the cascade through touching spheres is pooled in closed form;
    !> the fallback rule alone, run to the tolerance, reaches the same state.
    subroutine test_plastic_cascade(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: fast, slow
        real(qp) :: u(12)
        integer :: stat, i, p
        character(len=200) :: msg
        call seed_random(4321, 11)
        do i = 1, 40
            call random_number(u)
            p = 3 + int(6*u(1))
            call scene_init(scene, stat, msg, p=p, e=0.0_qp, masses=0.5_qp + 1.5_qp*u(2:p + 1), &
                gaps=merge(0.0_qp, u(3:p + 1), u(3:p + 1) < 0.4_qp))
            call run_and_rerun(scene, fast, slow, closed_form_limits=.false.)
            call check(error, fast%status == status_collapsed .and. &
                slow%status /= status_max_collisions, "plastic cascade: status")
            if (allocated(error)) return
            call check(error, all(abs(fast%v - slow%v) <= 1.0e4_qp*eps), &
                "plastic cascade: velocities differ from the fallback's")
            if (allocated(error)) return
            call check(error, fast%n <= slow%n, "plastic cascade: more collisions than before")
            if (allocated(error)) return
        end do
    end subroutine test_plastic_cascade

    !> e = 0, masses over six decades: momentum kept, energy not gained, no pair
    !> closing at the end, and few collisions.
    subroutine test_plastic_unequal(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        real(qp) :: u(21), v0(20)
        integer :: stat, i, p
        character(len=200) :: msg
        call seed_random(4321, 11)
        do i = 1, 200
            call random_number(u)
            p = 2 + int(19*u(1))
            call scene_init(scene, stat, msg, p=p, e=0.0_qp, masses=1.0e3_qp**(2*u(2:p + 1) - 1))
            call simulate(scene, run)
            v0 = 0.0_qp
            v0(1) = 1.0_qp
            call check(error, run%status == status_normal .or. run%status == status_collapsed, &
                "e = 0, unequal masses: run did not end")
            if (allocated(error)) return
            call check(error, abs(momentum(scene, run%v) - scene%m(1)) <= &
                1.0e3_qp*eps*maxval(scene%m), "e = 0: momentum")
            call check(error, kinetic_energy(scene, run%v) <= &
                kinetic_energy(scene, v0(:p))*(1 + 1.0e3_qp*eps), "e = 0: energy gained")
            call check(error, all(run%dy >= -scene%tol*scene%v0), "e = 0: a pair still closing")
            call check(error, run%n <= 4*p*p, "e = 0: too many collisions")
            if (allocated(error)) return
        end do
    end subroutine test_plastic_unequal

    !> Just above e_crit the run is finite; with a tolerance far below any
    !> rate it keeps its exact count whether closed-form limits are on or off
    !> (115 collisions at e = 0.172).
    subroutine test_near_critical(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: with, without
        real(qp), parameter :: above(3) = [1.0e-3_qp, 1.0e-5_qp, 1.0e-7_qp]
        integer :: stat, i
        character(len=200) :: msg
        call scene_init(scene, stat, msg, e=0.172_qp, tol=1.0e-4000_qp)
        call simulate(scene, with)
        call check(error, with%n == 115 .and. with%status == status_normal, &
            "e = 0.172: not 115 collisions")
        do i = 1, size(above)
            call scene_init(scene, stat, msg, e=e_crit_4 + above(i), tol=1.0e-4000_qp)
            call run_and_rerun(scene, with, without, closed_form_limits=.false.)
            call check(error, with%status == status_normal .and. with%n == without%n .and. &
                all(with%v == without%v), "just above e_crit: the count or state changed")
            if (allocated(error)) return
        end do
        call scene_init(scene, stat, msg, e=e_crit_4 - 1.0e-3_qp, tol=1.0e-4000_qp)
        call simulate(scene, with)
        call check(error, with%status == status_collapsed .and. with%limits%closed_form >= 1 .and. &
            all(abs(with%v - 0.25_qp) <= 64*eps), "just below e_crit: no cycle limit")
    end subroutine test_near_critical

    !> Three equal spheres: the alternating cycle collapses below 7 - 4 sqrt 3
    !> and breaks out above it.
    subroutine test_three_spheres(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=3, e=e_crit_3 - 1.0e-4_qp, tol=1.0e-4000_qp)
        call simulate(scene, run)
        call check(error, run%status == status_collapsed .and. run%limits%closed_form == 1 .and. &
            all(abs(run%v - 1/3.0_qp) <= 64*eps), "p = 3 below e_crit: no cycle limit")
        call scene_init(scene, stat, msg, p=3, e=e_crit_3 + 1.0e-4_qp, tol=1.0e-4000_qp)
        call simulate(scene, run)
        call check(error, run%status == status_normal .and. run%limits%n == 0, &
            "p = 3 above e_crit: not finite")
    end subroutine test_three_spheres

    !> Three spheres touching, struck from one end (gaps 0,0, or 1,0: sphere
    !> 1 strikes the touching pair), collapse only below the three-body edge
    !> (1 - sin t)/(1 + sin t), cos^2 t = m1 m3/((m1 + m2)(m2 + m3)) (7 - 4
    !> sqrt 3 for equal masses, 0.10102 for 2, 1, 1); above it the cascade
    !> at one instant separates, hundreds of collisions later as e comes
    !> closer (503 at e = 0.0718 at rates of 1.5e-288). So above the edge no
    !> run, at the default tol or a deep one, may say certified or collapse
    !> proven; 2 % below it the collapse is certified.
    subroutine test_three_blocks(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        real(qp) :: edge, cos2, above(5), m(3)
        integer :: stat, i, j, g, t
        character(len=200) :: msg
        real(qp), parameter :: masses(3, 3) = reshape([1.0_qp, 1.0_qp, 1.0_qp, &
            2.0_qp, 1.0_qp, 1.0_qp, 1.0_qp, 0.3_qp, 3.0_qp], [3, 3])
        real(qp), parameter :: tols(2) = [0.0_qp, 1.0e-300_qp]
        do j = 1, size(masses, 2)
            m = masses(:, j)
            cos2 = m(1)*m(3)/((m(1) + m(2))*(m(2) + m(3)))
            edge = (1 - sqrt(1 - cos2))/(1 + sqrt(1 - cos2))
            above = edge*[1 + 1.0e-8_qp, 1 + 1.0e-6_qp, 1 + 1.0e-4_qp, 1 + 1.0e-3_qp, &
                1 + 4.0e-3_qp]
            do g = 1, 2
                do t = 1, size(tols)
                    do i = 1, size(above)
                        call init(above(i))
                        call simulate(scene, run)
                        call check(error, run%answer /= answer_certified .and. &
                            .not. collapse_proven(run), "masses "//str(m(1))//" "//str(m(2)) &
                            //" "//str(m(3))//", e = "//str(above(i))//" above the edge " &
                            //str(edge)//": certified or proven")
                        if (allocated(error)) return
                    end do
                    call init(0.98_qp*edge)
                    call simulate(scene, run)
                    call check(error, run%answer == answer_certified .and. collapse_proven(run), &
                        "masses "//str(m(1))//", e = 0.98 of the edge: not certified")
                    if (allocated(error)) return
                end do
            end do
        end do
    contains
        subroutine init(e)
            real(qp), intent(in) :: e
            real(qp) :: gaps(2)
            gaps = 0.0_qp
            if (g == 2) gaps(1) = 1.0_qp
            if (tols(t) > 0) then
                call scene_init(scene, stat, msg, p=3, e=e, gaps=gaps, masses=m, tol=tols(t))
            else
                call scene_init(scene, stat, msg, p=3, e=e, gaps=gaps, masses=m)
            end if
        end subroutine init
    end subroutine test_three_blocks

    !> Keeping a log changes no result line: x_1 is brought forward at the same
    !> points with or without it.
    subroutine test_log_neutral(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: plain, logged
        type(event_log_t) :: log
        real(qp), parameter :: e_values(4) = [0.0_qp, 0.1_qp, 0.2_qp, 0.7_qp]
        integer :: stat, i
        character(len=200) :: msg
        do i = 1, size(e_values)
            call scene_init(scene, stat, msg, p=5, e=e_values(i), &
                gaps=[0.3_qp, 1.7_qp, 0.0_qp, 2.1_qp])
            call simulate(scene, plain)
            call simulate(scene, logged, log)
            call check(error, all(plain%x == logged%x) .and. all(plain%v == logged%v) .and. &
                all(plain%y == logged%y) .and. plain%t_end == logged%t_end, &
                "a log changed the result")
            if (allocated(error)) return
        end do
    end subroutine test_log_neutral

    !> Seeded random rows (p = 2..20, masses log-uniform over 1e-3..1e3 or all
    !> equal, e uniform in [0, 1], a fifth of the gaps closed): a run that is
    !> finite without closed-form limits is the same run with them, bit for
    !> bit; a run that ends keeps momentum, gains no energy, has no negative
    !> gap and no pair still closing.
    subroutine test_random_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: with, without
        real(qp) :: v0(20), scale
        integer :: i, p, finite, limited
        integer, parameter :: cap = 5000
        integer :: scenes
        scenes = cases(100, 1000)
        call seed_random(4321, 11)
        finite = 0
        limited = 0
        do i = 1, scenes
            call random_row(scene, 0.2_qp, cap)
            p = scene%p
            call run_and_rerun(scene, with, without, closed_form_limits=.false.)
            if (without%status == status_normal) then
                finite = finite + 1
                call check(error, with%status == status_normal .and. with%n == without%n .and. &
                    all(with%v == without%v) .and. all(with%y == without%y), &
                    "a finite run changed with closed-form limits")
                if (allocated(error)) return
            end if
            if (with%limits%closed_form > 0) limited = limited + 1
            if (with%status == status_max_collisions) cycle
            v0 = 0.0_qp
            v0(1) = 1.0_qp
            ! rounding of each collision adds up: the scale is the largest
            ! momentum of a sphere times the number of collisions
            scale = (with%n + 1)*maxval(scene%m)*max(1.0_qp, maxval(abs(with%v)))
            call check(error, abs(momentum(scene, with%v) - scene%m(1)) <= 64*eps*scale, &
                "random row: momentum")
            call check(error, kinetic_energy(scene, with%v) <= &
                kinetic_energy(scene, v0(:p)) + 64*eps*scale*max(1.0_qp, maxval(abs(with%v))), &
                "random row: energy gained")
            call check(error, all(with%y >= 0.0_qp), "random row: negative gap")
            call check(error, all(with%dy >= -scene%tol*scene%v0), "random row: pair closing")
            if (allocated(error)) return
        end do
        call check(error, finite > scenes/4, "random rows: too few finite runs to compare")
        ! the comparison means something only if closed-form limits were taken
        call check(error, limited > scenes/20, "random rows: too few closed-form limits taken")
    end subroutine test_random_rows

    !> At 0 < e < 1, touching rows (every gap closed; masses equal or over four
    !> decades) struck by sphere 1: where the fallback rule alone answers, a
    !> run with the certified limit of cascades through touching spheres ends
    !> with the same velocities, sooner. A limit taken where the cascade in
    !> fact ends would show here as velocities far apart.
    subroutine test_touching_cascade(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: fast, slow
        real(qp) :: u(24)
        integer :: stat, i, p, compared
        character(len=200) :: msg
        call seed_random(2718, 11)
        compared = 0
        do i = 1, 120
            call random_number(u)
            p = 3 + int(8*u(1))
            call scene_init(scene, stat, msg, p=p, e=u(2), &
                masses=merge(1.0_qp, 1.0e2_qp**(2*u(3:p + 2) - 1), u(24) < 0.5_qp), &
                gaps=spread(0.0_qp, 1, p - 1), max_collisions=100000)
            call run_and_rerun(scene, fast, slow, closed_form_limits=.false.)
            if (slow%status == status_max_collisions .or. fast%limits%closed_form == 0) cycle
            compared = compared + 1
            ! (a run that the fallback ends `normal`, its last rates within tol
            ! of 0 but converging to one velocity, may end collapsed here; one
            ! whose group is followed on its own scale below tol takes more
            ! collisions than the fallback, which merges it there)
            call check(error, all(abs(fast%v - slow%v) <= 1.0e-25_qp), &
                "touching cascade: velocities differ from the fallback's")
            if (allocated(error)) return
        end do
        call check(error, compared >= 20, "touching cascade: too few limits compared: " &
            //achar(48 + compared/10)//achar(48 + mod(compared, 10)))
    end subroutine test_touching_cascade

    !> Three light spheres between two heavy ones (masses over five decades):
    !> their gaps shrink by decades a shuttle while the rates fall by a
    !> fraction of a percent, so the gaps are below tol long before the rates
    !> are. A gap below tol is not a contact: the run steps the shuttles (in
    !> the relative variables, below the clock's resolution) until a limit is
    !> proven, within 300,000 collisions, where the fallback alone takes more
    !> than 100,000; both leave spheres 2..6 at their mean, within 1e-25.
    subroutine test_light_between_heavy(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: fast, slow
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=6, e=0.875_qp, &
            masses=[76.0_qp, 143.0_qp, 0.0019_qp, 0.0104_qp, 0.217_qp, 54.5_qp], &
            gaps=[0.0_qp, 0.62_qp, 1.79_qp, 0.33_qp, 1.3_qp])
        call run_and_rerun(scene, fast, slow, max_collisions=2000000, closed_form_limits=.false.)
        call check(error, fast%status == status_collapsed .and. fast%n < 300000 .and. &
            fast%limits%closed_form >= 1 .and. fast%answer == answer_certified, &
            "light between heavy: no certified limit within 300,000")
        if (allocated(error)) return
        call check(error, slow%status == status_collapsed .and. slow%n > 100000, &
            "light between heavy: the fallback alone no longer needs a long run")
        if (allocated(error)) return
        call check(error, all(abs(fast%v(2:) - sum(scene%m(2:)*fast%v(2:))/sum(scene%m(2:))) &
            <= 1.0e4_qp*eps), "light between heavy: spheres 2..6 not at their mean")
        if (allocated(error)) return
        call check(error, all(abs(fast%v - slow%v) <= 1.0e-25_qp), &
            "light between heavy: velocities differ from the fallback's")
    end subroutine test_light_between_heavy

    !> Long rows whose cascades through touching spheres used to run to the
    !> collision cap: each now collapses within a few 10^4 collisions, the
    !> equal-mass ones fully, to the row's mean velocity.
    subroutine test_long_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat, i, j
        character(len=200) :: msg
        integer, parameter :: rows(5) = [40, 64, 32, 20, 20]
        real(qp), parameter :: e_values(5) = [0.5_qp, 0.3_qp, 0.6_qp, 0.1_qp, 0.1_qp]
        real(qp) :: mean
        do i = 1, size(rows)
            call scene_init(scene, stat, msg, p=rows(i), e=e_values(i))
            ! the last two alternate masses 1 and 1000, starting with either
            if (i >= 4) scene%m = [(merge(1.0_qp, 1.0e3_qp, mod(j + i, 2) == 0), j=1, rows(i))]
            call simulate(scene, run)
            mean = scene%m(1)/sum(scene%m)
            call check(error, run%status == status_collapsed .and. run%n < 60000, &
                "long row "//achar(48 + i)//": no collapse within 60000 collisions")
            if (allocated(error)) return
            call check(error, abs(momentum(scene, run%v) - scene%m(1)) <= 1.0e-28_qp*sum(scene%m) &
                .and. all(run%dy >= -scene%tol*scene%v0), &
                "long row "//achar(48 + i)//": momentum, or a pair still closing")
            if (allocated(error)) return
            ! (with masses 1 and 1000 a light sphere 1 rebounds)
            if (i > 3) cycle
            call check(error, all(abs(run%v - mean) <= 1.0e-28_qp), &
                "long row "//achar(48 + i)//": not every sphere at the mean velocity")
            if (allocated(error)) return
        end do
    end subroutine test_long_rows

    !> The quasi-plastic sweep of a long struck row: a merged block of B equal
    !> spheres at v0/B absorbs the next sphere, one collision and one limit a
    !> sphere (sphere_row_struck.inc), the limit proven for every B >= 36 at
    !> e <= 0.7 by one box: 20,000 spheres at e = 0.2 and 0.5 end within 10,000
    !> collisions more than one a sphere (the front's forming; a proof of each
    !> block's merge by its own box, as before, cost O(B) a sphere), every
    !> sphere at v0/p, the momentum kept, the last absorption at t = p(p - 1)/2
    !> (the block of B reaches sphere B + 1, a gap of 1 ahead, in time B), and
    !> at e = 0.2 the collapse proven.
    subroutine test_struck_sweep(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat, i
        integer, parameter :: p = 20000
        real(qp), parameter :: e_values(2) = [0.2_qp, 0.5_qp]
        character(len=200) :: msg
        do i = 1, size(e_values)
            call scene_init(scene, stat, msg, p=p, e=e_values(i))
            call simulate(scene, run)
            call check(error, run%status == status_collapsed .and. run%n < p + 10000 .and. &
                run%limits%certified > p - 100, "e = "//str(e_values(i))//": "// &
                itoa(run%n)//" collisions, "//itoa(run%limits%certified)//" certified limits")
            if (allocated(error)) return
            call check(error, all(abs(run%v - 1.0_qp/p) <= run%v_bounds) .and. &
                abs(momentum(scene, run%v) - 1) <= 1.0e-25_qp .and. &
                abs(run%t_end - real(p, qp)*(p - 1)/2) <= 1.0e-20_qp*p*p, "e = " &
                //str(e_values(i))//": velocities, momentum or t_end "//str(run%t_end))
            if (allocated(error)) return
        end do
        call check(error, collapse_proven(run) .eqv. .false., "e = 0.5: its front merges at tol")
        call scene_init(scene, stat, msg, p=p, e=0.2_qp)
        call simulate(scene, run)
        call check(error, collapse_proven(run) .and. run%answer == answer_certified, &
            "e = 0.2: the collapse not proven")
    end subroutine test_struck_sweep

    !> The proof that a struck block merges, for every length from q0 on
    !> (struck_least), against the cascade itself: at e = 0.5 q0 = 36, and the
    !> cascade at one instant of a block of q0 ... q0 + 3 equal spheres struck
    !> at an end, run in the engine's order (the largest approach first)
    !> for 200,000 collisions, keeps every momentum excess S_j positive, as the
    !> proof says it does for ever; at e = 0 every block merges (q0 = 2); from
    !> e = 0.93 on no q0 is found, and at e = 0.95 a block of 100 spheres
    !> separates within 10,000 collisions.
    subroutine test_struck_least(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: q
        logical :: ends
        call check(error, struck_least(0.5_qp) == 36 .and. struck_least(0.0_qp) == 2 .and. &
            struck_least(0.95_qp) == huge(1), "q0 at 0.5, 0, 0.95: "// &
            itoa(struck_least(0.5_qp))//" "//itoa(struck_least(0.0_qp)))
        if (allocated(error)) return
        do q = 36, 39
            call struck_cascade(0.5_qp, q, 200000, ends)
            call check(error, .not. ends, "e = 0.5: a struck block of "//itoa(q)//" ends")
            if (allocated(error)) return
        end do
        call struck_cascade(0.95_qp, 100, 10000, ends)
        call check(error, ends, "e = 0.95: a struck block of 100 does not separate")
    contains
        !> The cascade at one instant of q equal spheres, q - 1 at velocity 1
        !> and the last at 0, in the engine's order, for at most `most`
        !> collisions: whether it ends (no pair approaching) or a momentum
        !> excess S_j reaches 0 first.
        subroutine struck_cascade(e, q, most, ends)
            real(qp), intent(in) :: e
            integer, intent(in) :: q, most
            logical, intent(out) :: ends
            real(qp) :: u(q), d
            integer :: n, c, j
            u = 1
            u(q) = 0
            ends = .true.
            do n = 1, most
                c = maxloc(u(:q - 1) - u(2:), 1)
                d = u(c) - u(c + 1)
                if (.not. d > 0) return
                u(c) = u(c) - (1 + e)/2*d
                u(c + 1) = u(c + 1) + (1 + e)/2*d
                ! (the excesses of the prefixes, about the mean)
                if (mod(n, 1000) == 0) then
                    do j = 1, q - 1
                        if (.not. sum(u(:j)) - j*sum(u)/q > 0) return
                    end do
                    u = (u - sum(u)/q)/maxval(abs(u - sum(u)/q)) + 1
                end if
            end do
            ends = .false.
        end subroutine struck_cascade
    end subroutine test_struck_least

    !> The struck block's absorption is taken from q0 = struck_least(e) on,
    !> where its proof holds, and not one sphere below. At e = 0.5 sphere 1
    !> strikes a touching row of q - 2, which merges into a block (certified)
    !> and strikes sphere q at rest: for q = q0 the strike is absorbed at
    !> once (the next event is the limit of spheres 1-q); for q = q0 - 1 its
    !> cascade is the touching block's rule's, which steps collisions (7,
    !> measured) before its limit. Both end as one block at v0/q.
    subroutine test_struck_from_q0(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(event_log_t) :: log
        character(len=200) :: msg
        integer :: q, q0, strike, stat
        q0 = struck_least(0.5_qp)
        do q = q0 - 1, q0
            call scene_init(scene, stat, msg, p=q, e=0.5_qp, &
                gaps=[spread(0.0_qp, 1, q - 2), 1.0_qp])
            call simulate(scene, run, log)
            strike = findloc(log%kind(1:log%n) == event_collision .and. &
                log%first(1:log%n) == q - 1 .and. log%last(1:log%n) == q, .true., 1)
            call check(error, strike > 0 .and. strike < log%n, "q = "//itoa(q) &
                //": no strike of sphere q followed by an event, in "//itoa(log%n))
            if (allocated(error)) return
            call check(error, (log%kind(strike + 1) == event_collapse) .eqv. (q >= q0), &
                "q = "//itoa(q)//", q0 = "//itoa(q0)//": the strike's next event is a " &
                //merge("collapse ", "collision", log%kind(strike + 1) == event_collapse))
            if (allocated(error)) return
            call check(error, run%answer == answer_certified .and. &
                maxval(abs(run%v - 1.0_qp/q)) <= 64*epsilon(1.0_qp), "q = "//itoa(q) &
                //": answer "//answer_word(run%answer)//", not one block at v0/q")
            if (allocated(error)) return
        end do
    end subroutine test_struck_from_q0

    !> A light sphere shuttling between two heavy ones while other contacts
    !> wait: the jump over the shuttle's periods (doubling its period map)
    !> lands where stepping the rule period by period does, on the same count;
    !> at the first contacts of a block, and inside one (a window of contacts
    !> that is not the whole block).
    subroutine test_cascade_jump(error)
        type(error_t), allocatable, intent(out) :: error
        real(dp), parameter :: e = 0.24_dp
        real(dp), allocatable :: kl(:), kr(:)
        integer :: pattern(2)
        call one_block([126.0_dp, 0.00105_dp, 55.0_dp, 31.5_dp], [0.5_dp, 0.3_dp, 0.2_dp])
        if (allocated(error)) return
        call one_block([300.0_dp, 126.0_dp, 0.00105_dp, 55.0_dp, 31.5_dp, 20.0_dp], &
            [0.0_dp, 0.5_dp, 0.3_dp, 0.2_dp, 0.1_dp])
    contains
        !> A block of masses m with approach rates w0 at its contacts.
        subroutine one_block(m, w0)
            real(dp), intent(in) :: m(:), w0(:)
            real(dp) :: w(size(w0)), jumped(size(w0)), stepped(size(w0))
            integer :: seq(6), times, periods, n
            n = size(w0)
            w = w0
            kl = (1 + e)*m(2:)/(m(:n) + m(2:))
            kr = (1 + e)*m(:n)/(m(:n) + m(2:))
            ! step until a pattern of two contacts has run three periods
            seq = -[1, 2, 3, 4, 5, 6]
            do while (.not. all(seq(3:) == seq(:4)))
                seq = [seq(2:), rule(w)]
                if (seq(6) == 0) exit
                call collide(w, seq(6))
            end do
            call check(error, all(seq > 0), "cascade jump: the block's cascade ended")
            if (allocated(error)) return
            pattern = seq(5:6)
            jumped = w
            call cascade_jump(kl, kr, e, pattern, jumped, times)
            ! the rule, period by period, until it breaks: the jump lands one
            ! period before that (where the pattern still holds once more)
            periods = 0
            stepped = w
            do while (follows(w))
                periods = periods + 1
                if (periods == times) stepped = w
            end do
            call check(error, times > 1000 .and. times == periods - 1, &
                "cascade jump: not the count of whole periods the rule takes")
            if (allocated(error)) return
            call check(error, maxval(abs(jumped - stepped)) <= 1.0e-10_dp*maxval(abs(stepped)), &
                "cascade jump: rates differ from the stepped ones")
        end subroutine one_block
        !> The rule's choice: the largest closing rate, the leftmost of equals
        !> (0 if none closes).
        integer function rule(u)
            real(dp), intent(in) :: u(:)
            rule = maxloc(u, 1)
            if (.not. u(rule) > 0) rule = 0
        end function rule
        subroutine collide(u, c)
            real(dp), intent(inout) :: u(:)
            integer, intent(in) :: c
            real(dp) :: uc
            uc = u(c)
            if (c > 1) u(c - 1) = u(c - 1) + kl(c)*uc
            if (c < size(u)) u(c + 1) = u(c + 1) + kr(c)*uc
            u(c) = -e*uc
        end subroutine collide
        !> Whether one more period of the pattern follows from u (then taken);
        !> from a copy, so that u is left where the pattern breaks.
        logical function follows(u)
            real(dp), intent(inout) :: u(:)
            real(dp) :: v(size(u))
            integer :: i
            v = u
            follows = .false.
            do i = 1, size(pattern)
                if (rule(v) /= pattern(i)) return
                call collide(v, pattern(i))
            end do
            u = v
            follows = .true.
        end function follows
    end subroutine test_cascade_jump

    !> A row struck into a touching block in which a light sphere shuttles
    !> between two heavy ones: with the shuttle's periods jumped, the cascade
    !> is certified to merge within a few thousand collisions (the fallback
    !> alone needs 15,200,513 at e = 0.24), and every sphere ends at the row's
    !> mean velocity m_1 v_0 / sum(m).
    subroutine test_shuttle_row(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        real(qp), parameter :: e_values(1) = [0.24_qp]
        integer :: stat, i
        character(len=200) :: msg
        do i = 1, size(e_values)
            call scene_init(scene, stat, msg, p=5, e=e_values(i), &
                masses=[126.0_qp, 0.00105_qp, 55.0_qp, 31.5_qp, 26.8_qp], &
                gaps=[0.0_qp, 1.0_qp, 0.0_qp, 0.0_qp])
            call simulate(scene, run)
            call check(error, run%status == status_collapsed .and. run%n < 10000, &
                "shuttle in a touching row: no collapse within 10000 collisions")
            if (allocated(error)) return
            call check(error, all(abs(run%v - scene%m(1)/sum(scene%m)) <= 1.0e-28_qp), &
                "shuttle in a touching row: not every sphere at the mean velocity")
            if (allocated(error)) return
        end do
    end subroutine test_shuttle_row

    !> Survey rows (and rows like them) that end in merged blocks, each
    !> within its budget, run by the scan and by the calendar
    !> (check_row_merges): each row of test/merging_rows.tsv names what it
    !> shows, and why it is here.
    subroutine test_merging_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(merging_t), allocatable :: rows(:)
        type(scene_t) :: scene
        integer :: i
        call merging_rows(rows, error)
        if (allocated(error)) return
        do i = 1, size(rows)
            call scene_of(rows(i)%keys, scene, error)
            if (allocated(error)) return
            call check_row_merges(scene, rows(i)%most, rows(i)%closed_only, rows(i)%what, &
                error, one_block=rows(i)%one_block)
            if (allocated(error)) return
        end do
    end subroutine test_merging_rows

    !> The rows of test_merging_rows, from test/merging_rows.tsv: a line each
    !> with what it shows, its budget, whether every limit must be in closed
    !> form, whether it ends as one block, its scene as sphere-row takes it and
    !> why it is there.
    subroutine merging_rows(rows, error)
        type(merging_t), allocatable, intent(out) :: rows(:)
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: text, fields(:)
        integer :: at, most, ios
        allocate (rows(0))
        text = read_text("test/merging_rows.tsv")
        ! (the header line first)
        at = index(text, new_line("a"))
        text = text(at + 1:)
        do while (len(text) > 0)
            at = index(text, new_line("a"))
            call split_tabs(text(:at - 1), fields)
            text = text(at + 1:)
            call check(error, size(fields) == 6, "merging_rows.tsv: a line of " &
                //itoa(size(fields))//" fields, not 6")
            if (allocated(error)) return
            read (fields(2), *, iostat=ios) most
            call check(error, ios == 0, "merging_rows.tsv: budget "//trim(fields(2)))
            if (allocated(error)) return
            rows = [rows, merging(trim(fields(1)), most, fields(3) == "true", &
                fields(4) == "true", trim(fields(5)))]
        end do
        call check(error, size(rows) >= 6, "merging_rows.tsv: "//itoa(size(rows))//" rows")
    end subroutine merging_rows

    !> A row of the table of rows that end in merged blocks.
    pure function merging(what, most, closed_only, one_block, keys) result(row)
        character(len=*), intent(in) :: what, keys
        integer, intent(in) :: most
        logical, intent(in) :: closed_only, one_block
        type(merging_t) :: row
        row = merging_t(what, most, closed_only, one_block, keys)
    end function merging

    !> Run `scene` by the scan and by the calendar: it must end collapsed
    !> within `most` collisions (every limit in closed form if `closed_only`),
    !> every sphere at the mean velocity m1 v0/sum(m) or, unless `one_block`
    !> (the row ends in several blocks), with momentum kept and no
    !> pair still closing.
    subroutine check_row_merges(scene, most, closed_only, what, error, one_block)
        type(scene_t), intent(in) :: scene
        integer, intent(in) :: most
        logical, intent(in) :: closed_only
        character(len=*), intent(in) :: what
        type(error_t), allocatable, intent(out) :: error
        logical, intent(in) :: one_block
        type(scene_t) :: each
        type(run_t) :: run
        integer :: way
        character(len=20) :: most_text
        write (most_text, "(i0)") most
        do way = 1, 2
            each = scene
            if (way == 2) each%calendar_from = 2
            each%max_collisions = most
            call simulate(each, run)
            call check(error, run%status == status_collapsed .and. run%n < most, &
                what//": no collapse within "//trim(most_text)//" collisions")
            if (allocated(error)) return
            call check(error, run%limits%n > 0 .and. &
                (run%limits%closed_form == run%limits%n .or. .not. closed_only), &
                what//": a limit not taken in closed form")
            if (allocated(error)) return
            if (one_block) then
                call check(error, all(abs(run%v - each%m(1)/sum(each%m)) <= 1.0e3_qp*eps), &
                    what//": not every sphere at the mean velocity")
            else
                call check(error, abs(momentum(each, run%v) - each%m(1)) <= &
                    1.0e3_qp*eps*sum(each%m) .and. all(run%dy >= -each%tol*each%v0), &
                    what//": momentum, or a pair still closing")
            end if
            if (allocated(error)) return
        end do
    end subroutine check_row_merges

    !> An equal-mass row whose spheres arrive one by one at a growing touching
    !> block: once a limit has closed the block's gaps, each arrival sets off a
    !> cascade at one instant that follows no repeating pattern and falls to
    !> insignificant rates within a few thousand collisions. The cascade in
    !> the engine's order, run in double precision, shows that the fallback
    !> rule will merge the block; the run with that rule alone steps every
    !> collision and ends with the same velocities (within a few roundings).
    subroutine test_quiet_cascade(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: fast, slow
        integer :: stat, way
        character(len=200) :: msg
        character(len=*), parameter :: ways(2) = ["scan    ", "calendar"]
        ! the gaps scanned for the next impact, then taken from a calendar
        do way = 1, size(ways)
            call scene_init(scene, stat, msg, p=13, e=0.47820431017316877841949462890625_qp, &
                gaps=[1.6572488923557102680206298828125_qp, 1.8588508977554738521575927734375_qp, &
                1.6575302076525986194610595703125_qp, 0.0535340649075806140899658203125_qp, &
                1.7805416318587958812713623046875_qp, 0.3285969612188637256622314453125_qp, &
                0.6679445472545921802520751953125_qp, 0.7546023228205740451812744140625_qp, &
                1.6365618654526770114898681640625_qp, 0.3961061802692711353302001953125_qp, &
                0.3520521004684269428253173828125_qp, 0.0_qp])
            if (way == 2) scene%calendar_from = 2
            call run_and_rerun(scene, fast, slow, &
                max_collisions=1000000, closed_form_limits=.false.)
            call check(error, fast%status == status_collapsed .and. fast%n < 5000, &
                "quiet cascade ("//trim(ways(way))//"): no collapse within 5000 collisions")
            if (allocated(error)) return
            ! a limit that is the fallback's, not a closed form
            call check(error, fast%limits%n > fast%limits%closed_form, &
                "quiet cascade ("//trim(ways(way))//"): no limit taken by the fallback's rule")
            if (allocated(error)) return
            call check(error, slow%status == status_collapsed .and. slow%n > 2*fast%n, &
                "quiet cascade ("//trim(ways(way))//"): the fallback alone needs no longer run")
            if (allocated(error)) return
            call check(error, all(abs(fast%v - slow%v) <= 1.0e3_qp*eps), &
                "quiet cascade ("//trim(ways(way))//"): velocities differ from the fallback's")
            if (allocated(error)) return
        end do
    end subroutine test_quiet_cascade

end module test_collapse
