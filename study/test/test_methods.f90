!> Tests of the methods compared with the engine: each runs its fastest
!> scenes against the reference (the engine in real128, tol = sqrt(tiny)), with
!> tolerances that follow from the method's own error.
module test_methods
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: sp, dp, qp, scene_t, scene_dp_t, scene_init, str, &
        status_normal, status_collapsed, status_max_collisions, status_invalid, itoa
    use sphere_row_outcome, only: outcome_t, comparison_t, compare_outcomes, classify, &
        category_right, category_wrong_count, category_wrong_state, category_no_end, &
        category_negative_gap, outcome_start, outcome_add
    use sphere_row_methods, only: method_t, new_method, reference_method, method_prepare, &
        method_run, method_label, method_v_tol, method_engine, method_absolute, method_ode, &
        method_stepping, stepper_rk8pd, stepper_rkf45
    use sphere_row_absolute_dp, only: simulate_absolute
    use sphere_row_kind_engines, only: built_kinds, kind_built, kind_engine_t, new_kind_engine
    use sphere_row_continuous, only: simulate_ode
    use sphere_row_stepping, only: simulate_stepping
    use sphere_row_status, only: status_negative_gap, status_solver_failed, status_budget
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_methods

    !> Unit roundoff of real64, the kind of methods 2 to 4 here.
    real(qp), parameter :: eps_dp = real(epsilon(1.0_dp), qp)
    !> The critical restitution 3 - 2 sqrt(2) of the definition's scene.
    real(qp), parameter :: e_crit = 3.0_qp - 2.0_qp*sqrt(2.0_qp)

contains

    !> The methods' tests.
    function collect_methods() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("reference_counts", test_reference_counts), &
            new_unittest("compare_and_classify", test_classify), &
            new_unittest("engine_kinds_via_dispatch", test_engine_kinds), &
            new_unittest("kinds_built", test_kinds_built), &
            new_unittest("absolute_dp_e03", test_absolute_dp), &
            new_unittest("absolute_qp_e02", test_absolute_qp), &
            new_unittest("absolute_budget", test_absolute_budget), &
            new_unittest("absolute_negative_gap", test_absolute_negative_gap), &
            new_unittest("ode_rk8pd_e02", test_ode_rk8pd), &
            new_unittest("ode_rkf45_e05", test_ode_rkf45), &
            new_unittest("ode_end_criterion", test_ode_end), &
            new_unittest("stepping_elastic", test_stepping_elastic), &
            new_unittest("stepping_e02", test_stepping_e02), &
            new_unittest("stepping_budget", test_stepping_budget), &
            new_unittest("invalid_settings", test_invalid_settings) &
            ]
    end function collect_methods

    !> The reference of the definition's scene at e.
    subroutine reference(e, ref)
        real(qp), intent(in) :: e
        type(outcome_t), intent(out) :: ref
        call run_method(reference_method(), e, ref)
    end subroutine reference

    !> Prepare `method` for the definition's scene at e and run it recorded.
    subroutine run_method(method_in, e, out)
        type(method_t), intent(in) :: method_in
        real(qp), intent(in) :: e
        type(outcome_t), intent(out) :: out
        type(method_t) :: method
        type(scene_t) :: scene
        integer :: stat
        character(len=200) :: msg
        method = method_in
        call scene_init(scene, stat, msg, e=e)
        call method_prepare(method, scene, stat, msg)
        call method_run(method, out, record=.true.)
    end subroutine run_method

    !> The reference `ref` of the definition's scene at e, `method`'s run of it
    !> and their comparison.
    subroutine against_reference(method, e, ref, run, cmp)
        type(method_t), intent(in) :: method
        real(qp), intent(in) :: e
        type(outcome_t), intent(out) :: ref, run
        type(comparison_t), intent(out) :: cmp
        call reference(e, ref)
        call run_method(method, e, run)
        cmp = compare_outcomes(ref, run)
    end subroutine against_reference

    !> The definition's scene in real64 at e, with the gaps, tol and collision
    !> budget given.
    subroutine definition_dp(scene, e, gaps, tol, max_collisions)
        type(scene_dp_t), intent(out) :: scene
        real(dp), intent(in) :: e
        real(dp), intent(in), optional :: gaps(:), tol
        integer, intent(in), optional :: max_collisions
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, e=e, gaps=gaps, tol=tol, max_collisions=max_collisions)
    end subroutine definition_dp

    !> The reference reproduces the known counts, including 236 at e_c + 1e-4,
    !> where the engine with its default tolerance (the kind's epsilon) reaches
    !> tol first and follows the group on its own scale to the same 236 (it
    !> took a collapse limit there before it did: the reason the reference
    !> has a tiny tol).
    subroutine test_reference_counts(error)
        type(error_t), allocatable, intent(out) :: error
        type(outcome_t) :: ref, run
        call reference(0.2_qp, ref)
        call check(error, ref%n == 13 .and. ref%status == status_normal, "e = 0.2: not 13")
        call reference(1.0_qp, ref)
        call check(error, ref%n == 3, "e = 1: not 3")
        call reference(0.172_qp, ref)
        call check(error, ref%n == 115 .and. ref%status == status_normal, "e = 0.172: not 115")
        call reference(e_crit + 1.0e-4_qp, ref)
        call check(error, ref%n == 236 .and. ref%status == status_normal, &
            "e_c + 1e-4: reference gives "//itoa(ref%n)//", expected 236")
        call run_method(new_method(method_engine, qp), e_crit + 1.0e-4_qp, run)
        call check(error, run%status == status_normal .and. run%n == 236, &
            "e_c + 1e-4: the engine with default tol gives "//itoa(run%n)//", expected 236")
        call reference(0.1_qp, ref)
        call check(error, ref%status == status_collapsed .and. &
            all(abs(ref%v - 0.25_qp) <= 64*epsilon(1.0_qp)), "e = 0.1: not quasi-plastic")
    end subroutine test_reference_counts

    !> compare_outcomes and classify on hand-made outcomes.
    subroutine test_classify(error)
        type(error_t), allocatable, intent(out) :: error
        type(outcome_t) :: ref, run
        type(comparison_t) :: cmp
        call made_up(ref, [1, 2, 1], [1.0_qp, 2.0_qp, 3.0_qp])
        call made_up(run, [1, 2, 1], [1.0_qp, 2.5_qp, 3.0_qp])
        cmp = compare_outcomes(ref, run)
        call check(error, cmp%same_sequence .and. cmp%n_matched == 3 .and. &
            abs(cmp%t_error - 0.5_qp) <= 0.0_qp, "same sequence, time error 0.5")
        call check(error, classify(ref, run, 1.0e-12_qp) == category_right, "right")
        run%v(4) = run%v(4) + 1.0e-9_qp
        call check(error, classify(ref, run, 1.0e-12_qp) == category_wrong_state, "wrong state")
        call made_up(run, [1, 3, 1], [1.0_qp, 2.0_qp, 3.0_qp])
        cmp = compare_outcomes(ref, run)
        call check(error, .not. cmp%same_sequence .and. cmp%n_matched == 1, "other sequence")
        call check(error, classify(ref, run, 1.0_qp) == category_wrong_count, "wrong sequence")
        call made_up(run, [1, 2], [1.0_qp, 2.0_qp])
        call check(error, classify(ref, run, 1.0_qp) == category_wrong_count, "wrong count")
        run%status = status_budget
        call check(error, classify(ref, run, 1.0_qp) == category_no_end, "no end")
        run%status = status_negative_gap
        call check(error, classify(ref, run, 1.0_qp) == category_negative_gap, "negative gap")
        ref%status = status_collapsed
        run%status = status_normal
        call check(error, classify(ref, run, 1.0_qp) == category_right, &
            "collapsed reference: any count with the right state is right")
    contains
        subroutine made_up(out, pairs, times)
            type(outcome_t), intent(out) :: out
            integer, intent(in) :: pairs(:)
            real(qp), intent(in) :: times(:)
            integer :: j
            call outcome_start(out, 4, .true.)
            do j = 1, size(pairs)
                call outcome_add(out, times(j), pairs(j))
            end do
            out%status = status_normal
            out%v = [0.0_qp, 0.0_qp, 0.0_qp, 1.0_qp]
        end subroutine made_up
    end subroutine test_classify

    !> Every kind of the engine through method_run: same sequence as the
    !> reference at e = 0.5 and velocities within the kind's classification
    !> tolerance, so a broken dispatch or kind conversion shows.
    subroutine test_engine_kinds(error)
        type(error_t), allocatable, intent(out) :: error
        type(outcome_t) :: ref, run
        type(comparison_t) :: cmp
        type(method_t) :: method
        integer :: i
        call reference(0.5_qp, ref)
        do i = 1, size(built_kinds)
            method = new_method(method_engine, built_kinds(i)%precision)
            call run_method(method, 0.5_qp, run)
            cmp = compare_outcomes(ref, run)
            call check(error, cmp%same_sequence, method_label(method)//": other sequence")
            call check(error, classify(ref, run, method_v_tol(method, 1.0_qp)) == category_right, &
                method_label(method)//": not right, v error "//str(cmp%v_error))
        end do
    end subroutine test_engine_kinds

    !> The kinds every compiler has are built; every kind built exists in this
    !> compiler (its kind value is positive), and a kind that is not built gets
    !> no engine.
    subroutine test_kinds_built(error)
        type(error_t), allocatable, intent(out) :: error
        class(kind_engine_t), allocatable :: engine
        integer :: i
        call check(error, kind_built(sp) .and. kind_built(dp) .and. kind_built(qp), &
            "sp, dp or qp not built")
        do i = 1, size(built_kinds)
            call check(error, built_kinds(i)%precision > 0, &
                trim(built_kinds(i)%name)//": built with a negative kind value")
        end do
        call new_kind_engine(-1, engine)
        call check(error, .not. allocated(engine), "an engine of kind -1 was made")
    end subroutine test_kinds_built

    !> Absolute variables in real64 at e = 0.3 (9 collisions): the positions
    !> are of size up to ~10 L, so each gap carries ~10 eps L of rounding and each
    !> time ~10 eps L/v0; over n collisions the errors stay below 64 n eps in
    !> units of v0 and L/v0 (about 1e-13).
    subroutine test_absolute_dp(error)
        type(error_t), allocatable, intent(out) :: error
        type(comparison_t) :: cmp
        call check_absolute(error, dp, 0.3_qp, eps_dp, cmp)
        call check(error, cmp%v_error > 0.0_qp, "absolute dp agrees exactly: is it the reference?")
    end subroutine test_absolute_dp

    !> Absolute variables in real128 at e = 0.2: same sequence, errors of the
    !> order of real128 roundoff (1e-30 with the same allowance as above).
    subroutine test_absolute_qp(error)
        type(error_t), allocatable, intent(out) :: error
        type(comparison_t) :: cmp
        call check_absolute(error, qp, 0.2_qp, epsilon(1.0_qp), cmp, n=13)
    end subroutine test_absolute_qp

    !> Absolute variables in `kind` (of unit roundoff eps) at e against the
    !> reference: a normal end, the same sequence (`n` collisions where
    !> given), velocity and time errors within 64 n eps (times relative to the
    !> last); `cmp` is the comparison.
    subroutine check_absolute(error, kind, e, eps, cmp, n)
        type(error_t), allocatable, intent(out) :: error
        integer, intent(in) :: kind
        real(qp), intent(in) :: e, eps
        type(comparison_t), intent(out) :: cmp
        integer, intent(in), optional :: n
        type(outcome_t) :: ref, run
        character(len=:), allocatable :: what
        real(qp) :: tol
        what = "absolute "//trim(merge("dp", "qp", kind == dp))
        call against_reference(new_method(method_absolute, kind), e, ref, run, cmp)
        tol = 64*ref%n*eps
        call check(error, run%status == status_normal .and. cmp%same_sequence, &
            what//", e = "//str(e)//": other sequence or status")
        if (present(n)) call check(error, run%n == n, &
            what//", e = "//str(e)//": "//itoa(run%n)//" collisions, not "//itoa(n))
        call check(error, cmp%v_error <= tol, what//": v error "//str(cmp%v_error))
        call check(error, cmp%t_error <= tol*maxval(ref%t(:ref%n)), &
            what//": t error "//str(cmp%t_error))
    end subroutine check_absolute

    !> The collision budget of the absolute method is honoured and reported.
    subroutine test_absolute_budget(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_dp_t) :: scene
        type(outcome_t) :: run
        call definition_dp(scene, 0.2_dp, max_collisions=5)
        call simulate_absolute(scene, run)
        call check(error, run%status == status_max_collisions .and. run%n == 5, &
            "absolute dp: budget of 5 collisions not honoured")
        call check(error, run%min_gap <= 0.0_qp, "min_gap must be <= 0")
    end subroutine test_absolute_budget

    !> A pair the absolute method takes as not approaching (its rate is below
    !> tol*v0) keeps closing while another pair travels towards its impact: the
    !> overlap is seen and reported. Hand-built: e = 0.5, gaps 1, 0, 5, tol = 0.1;
    !> after the impacts 1-2 (t = 1) and at once 2-3, spheres 1 and 2 touch and
    !> close at 1/16 v0, while 3 needs 5/(9/16) L/v0 to reach 4: the overlap is
    !> 5/9 L when 3-4 collide.
    subroutine test_absolute_negative_gap(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_dp_t) :: scene
        type(outcome_t) :: run
        call definition_dp(scene, 0.5_dp, gaps=[1.0_dp, 0.0_dp, 5.0_dp], tol=0.1_dp)
        call simulate_absolute(scene, run, record=.true.)
        call check(error, run%status == status_negative_gap .and. run%n == 3, &
            "absolute dp: overlap not reported, status "//itoa(run%status)//", n = "//itoa(run%n))
        call check(error, abs(run%min_gap + 5.0_qp/9) <= 64*eps_dp, &
            "absolute dp: overlap "//str(run%min_gap)//", expected -5/9")
    end subroutine test_absolute_negative_gap

    !> GSL rk8pd at tol = 1e-10, e = 0.2: the sequence of 13 is right; each
    !> impact is located to 1e-10 L/v0 and the errors add up over the run, so
    !> times agree to 1e-7; the rates are exact between impacts, so velocities
    !> agree to roundoff (and certainly to 1e-7).
    subroutine test_ode_rk8pd(error)
        type(error_t), allocatable, intent(out) :: error
        type(outcome_t) :: run
        type(comparison_t) :: cmp
        call check_ode(error, "rk8pd", stepper_rk8pd, 1.0e-10_qp, 0.2_qp, 1.0e-7_qp, run, cmp)
        call check(error, cmp%v_error <= 1.0e-7_qp, "ode rk8pd: v error "//str(cmp%v_error))
        call check(error, cmp%t_error > 0.0_qp .and. run%steps > 0, &
            "ode rk8pd: exact times or no steps: is GSL called at all?")
    end subroutine test_ode_rk8pd

    !> GSL rkf45 at tol = 1e-8, e = 0.5: right sequence, times to 1e-5.
    subroutine test_ode_rkf45(error)
        type(error_t), allocatable, intent(out) :: error
        type(outcome_t) :: run
        type(comparison_t) :: cmp
        call check_ode(error, "rkf45", stepper_rkf45, 1.0e-8_qp, 0.5_qp, 1.0e-5_qp, run, cmp)
    end subroutine test_ode_rkf45

    !> The ODE method with GSL's `stepper` (named `name`) at tolerance `tol`
    !> on the definition's scene at e: a normal end, the reference's sequence,
    !> times within t_tol; `run` and `cmp` are its run and the comparison.
    subroutine check_ode(error, name, stepper, tol, e, t_tol, run, cmp)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in) :: name
        integer, intent(in) :: stepper
        real(qp), intent(in) :: tol, e, t_tol
        type(outcome_t), intent(out) :: run
        type(comparison_t), intent(out) :: cmp
        type(outcome_t) :: ref
        call against_reference(new_method(method_ode, tol=tol, stepper=stepper), e, ref, run, cmp)
        call check(error, run%status == status_normal .and. cmp%same_sequence, &
            "ode "//name//" "//str(tol)//", e = "//str(e)//": count "//itoa(run%n) &
            //" or sequence wrong")
        call check(error, cmp%t_error <= t_tol, "ode "//name//": t error "//str(cmp%t_error))
    end subroutine check_ode

    !> The ODE method's end criterion is its tolerance: at e = 0.2 the last
    !> impact approaches at 9.1e-4 v0, so tol = 1e-3 stops one impact early
    !> (12) and tol = 1e-4 does not (13).
    subroutine test_ode_end(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_dp_t) :: scene
        type(outcome_t) :: run
        call definition_dp(scene, 0.2_dp)
        call simulate_ode(scene, 1.0e-3_dp, run)
        call check(error, run%status == status_normal .and. run%n == 12, &
            "ode tol 1e-3, e = 0.2: expected 12 impacts, got "//itoa(run%n))
        call simulate_ode(scene, 1.0e-4_dp, run)
        call check(error, run%status == status_normal .and. run%n == 13, &
            "ode tol 1e-4, e = 0.2: expected 13 impacts, got "//itoa(run%n))
        call simulate_ode(scene, 1.0e-6_dp, run, max_events=4)
        call check(error, run%status == status_max_collisions .and. run%n == 4, &
            "ode: event budget of 4 not honoured")
    end subroutine test_ode_end

    !> Stepping, h = 1e-3, e = 1: three impacts at t = 1, 2, 3, each found at
    !> the end of its step (within h, late never early), motion handed on exactly.
    subroutine test_stepping_elastic(error)
        type(error_t), allocatable, intent(out) :: error
        type(outcome_t) :: ref, run
        type(comparison_t) :: cmp
        real(qp), parameter :: h = 1.0e-3_qp
        call against_reference(new_method(method_stepping, h=h), 1.0_qp, ref, run, cmp)
        call check(error, run%n == 3 .and. cmp%same_sequence, "stepping e = 1: not 3 impacts")
        call check(error, cmp%t_error <= h*(1 + 1.0e-9_qp) .and. &
            all(run%t(:3) >= ref%t(:3) - 16*eps_dp*3), &
            "stepping e = 1: times not within one step after the reference")
        call check(error, cmp%v_error <= 4*eps_dp, "stepping e = 1: velocities not exact")
        call check(error, run%min_gap < 0.0_qp .and. run%min_gap >= -h*(1 + 1.0e-9_qp), &
            "stepping e = 1: overlap not within one step of approach: "//str(run%min_gap))
    end subroutine test_stepping_elastic

    !> Stepping, e = 0.2, h = 1e-3 and 1e-4: the impacts are at least 0.1 L/v0
    !> apart, so the sequence is right and the velocities exact (rates change
    !> only at impacts). An overlap of up to h times a fast approach shifts a
    !> later impact of a slow pair by much more than h, so the time error is not
    !> bounded by h; but it is first order: ten times smaller h, three to thirty
    !> times smaller error.
    subroutine test_stepping_e02(error)
        type(error_t), allocatable, intent(out) :: error
        type(outcome_t) :: ref, run
        type(comparison_t) :: cmp
        real(qp) :: error_coarse
        real(qp), parameter :: h = 1.0e-3_qp
        call against_reference(new_method(method_stepping, h=h), 0.2_qp, ref, run, cmp)
        call check(error, cmp%same_sequence .and. run%status == status_normal, &
            "stepping e = 0.2: count "//itoa(run%n)//" or sequence wrong")
        call check(error, cmp%v_error <= 16*eps_dp, "stepping e = 0.2: v error "//str(cmp%v_error))
        error_coarse = cmp%t_error
        call run_method(new_method(method_stepping, h=h/10), 0.2_qp, run)
        cmp = compare_outcomes(ref, run)
        call check(error, cmp%same_sequence .and. cmp%t_error <= error_coarse/3 .and. &
            cmp%t_error >= error_coarse/30, "stepping e = 0.2: not first order, t errors " &
            //str(error_coarse)//" and "//str(cmp%t_error))
    end subroutine test_stepping_e02

    !> The step budget ends a run with status_budget.
    subroutine test_stepping_budget(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_dp_t) :: scene
        type(outcome_t) :: run
        call definition_dp(scene, 0.2_dp)
        call simulate_stepping(scene, 1.0e-3_dp, run, max_steps=100_int64)
        call check(error, run%status == status_budget .and. run%steps == 100 .and. run%n == 0, &
            "stepping: budget of 100 steps not honoured")
    end subroutine test_stepping_budget

    !> Settings a method cannot take are refused with a status, not a stop.
    subroutine test_invalid_settings(error)
        type(error_t), allocatable, intent(out) :: error
        type(method_t) :: method
        type(scene_t) :: scene
        type(scene_dp_t) :: scene_dp
        type(outcome_t) :: run
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg)
        method = new_method(method_absolute, sp)
        call method_prepare(method, scene, stat, msg)
        call check(error, stat == status_invalid, "absolute in sp accepted")
        call method_run(method, run)
        call check(error, run%status == status_invalid, "unprepared method ran")
        method = new_method(method_stepping, h=0.0_qp)
        call method_prepare(method, scene, stat, msg)
        call check(error, stat == status_invalid, "stepping with h = 0 accepted")
        call scene_init(scene_dp, stat, msg)
        call simulate_ode(scene_dp, 2.0_dp, run)
        call check(error, run%status == status_invalid, "ode with tol = 2 accepted")
        call check(error, run%status /= status_solver_failed, "ode tol = 2 reached GSL")
    end subroutine test_invalid_settings

end module test_methods
