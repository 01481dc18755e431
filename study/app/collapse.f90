!> Collapse in general rows: a seeded survey of random rows of spheres (see
!> sphere_row_survey for their distribution), each run to its end with the
!> closed-form collapse limits, and the first of them once more with the
!> fallback rule alone; how many end with an answer, how many collisions
!> that takes, and whether every invariant holds.
program c12_collapse
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, simulate, str, itoa, status_max_collisions
    use sphere_row_survey, only: survey_t, survey_open, survey_close, survey_scene, &
        check_invariants
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab
    use sphere_row_study_cli, only: cli_t, start_program, read_keys, stop_unless_normal
    implicit none
    character(len=*), parameter :: nl = new_line("a")
    !> Rules compared: closed-form limits with the fallback, the fallback alone.
    integer, parameter :: closed = 1, fallback = 2
    !> Multiple of the kind's epsilon by which the invariants may miss.
    real(qp), parameter :: slack = 1.0e4_qp
    type(cli_t) :: cli
    type(survey_t) :: survey
    character(len=:), allocatable :: out
    integer :: n, n_before, cap, seed, p_max
    ! per rule: scenes, answered, invariant failures, collisions and cpu
    integer :: scenes(2), answered(2), broken(2)
    integer(int64) :: collisions(2)
    real :: cpu_max(2), cpu_sum(2)
    ! per p, closed-form rule: scenes and answered
    integer, allocatable :: by_p(:, :)

    call start_program(cli, "c12-collapse", &
        "Collapse in general rows: random rows run to their end with closed-form"//nl// &
        "collapse limits, and the first n_before of them with the fallback rule alone."//nl// &
        "Writes OUT/collapse_survey.tsv, OUT/collapse_by_p.tsv, OUT/collapse_answers.tsv.")
    call cli%add_int("n", "1000", "random rows run with closed-form limits", lo=1)
    call cli%add_int("n_before", "300", "of these, rows run with the fallback rule alone", lo=0)
    call cli%add_int("cap", "10000", "collisions after which a run counts as unanswered", lo=1)
    call cli%add_int("seed", "12", "seed of the MT19937 stream of the rows", lo=0)
    call cli%add_int("p_max", "20", "largest row length drawn (p from 2)", lo=2)
    call read_keys(cli)
    out = cli%get_word("out")
    n = cli%get_int("n")
    n_before = min(cli%get_int("n_before"), n)
    cap = cli%get_int("cap")
    seed = cli%get_int("seed")
    p_max = cli%get_int("p_max")

    call run_survey()
    call write_tables()

contains

    !> Draw the rows and run each under the rules.
    subroutine run_survey()
        type(scene_t) :: scene
        integer :: i
        allocate (by_p(2, 2:p_max), source=0)
        scenes = 0
        answered = 0
        broken = 0
        collisions = 0
        cpu_max = 0
        cpu_sum = 0
        call survey_open(survey, seed, 2, p_max, 1.0e3_qp)
        do i = 1, n
            call survey_scene(survey, scene)
            scene%max_collisions = cap
            call one_run(scene, closed)
            if (i > n_before) cycle
            scene%closed_form_limits = .false.
            call one_run(scene, fallback)
        end do
        call survey_close(survey)
    end subroutine run_survey

    !> Run one row under one rule and count its outcome.
    subroutine one_run(scene, rule)
        type(scene_t), intent(in) :: scene
        integer, intent(in) :: rule
        type(run_t) :: run
        character(len=:), allocatable :: why
        real :: t0, t1
        call cpu_time(t0)
        call simulate(scene, run)
        call cpu_time(t1)
        scenes(rule) = scenes(rule) + 1
        cpu_max(rule) = max(cpu_max(rule), t1 - t0)
        cpu_sum(rule) = cpu_sum(rule) + (t1 - t0)
        if (rule == closed) by_p(1, scene%p) = by_p(1, scene%p) + 1
        if (run%status == status_max_collisions) return
        answered(rule) = answered(rule) + 1
        collisions(rule) = collisions(rule) + run%n
        if (rule == closed) by_p(2, scene%p) = by_p(2, scene%p) + 1
        call check_invariants(scene, run, slack, why)
        if (why /= "") broken(rule) = broken(rule) + 1
    end subroutine one_run

    !> The survey table, the table per row length and the answers.
    subroutine write_tables()
        character(len=*), parameter :: names(2) = ["closed_form  ", "fallback_only"]
        integer :: unit, stat, rule, p
        character(len=300) :: msg
        call open_table(out, "collapse_survey.tsv", "rule"//tab//"scenes"//tab//"answered"// &
            tab//"unanswered"//tab//"invariant_failures"//tab//"mean_collisions"//tab// &
            "cpu_max[s]"//tab//"cpu_total[s]", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do rule = closed, fallback
            write (unit, "(a)") trim(names(rule))//tab//itoa(scenes(rule))//tab// &
                itoa(answered(rule))//tab//itoa(scenes(rule) - answered(rule))//tab// &
                itoa(broken(rule))//tab//str(mean_collisions(rule))//tab// &
                str(real(cpu_max(rule), qp))//tab//str(real(cpu_sum(rule), qp))
        end do
        close (unit)
        call open_table(out, "collapse_by_p.tsv", "p"//tab//"scenes"//tab//"answered"//tab// &
            "answered_share", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do p = 2, p_max
            if (by_p(1, p) == 0) cycle
            write (unit, "(a)") itoa(p)//tab//itoa(by_p(1, p))//tab//itoa(by_p(2, p))//tab// &
                str(real(by_p(2, p), qp)/by_p(1, p))
        end do
        close (unit)
        call open_table(out, "collapse_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call write_answer(unit, "collapse.answered", itoa(answered(closed)), "scenes", &
            itoa(scenes(closed)), itoa(answered(closed) - scenes(closed)), &
            "random rows (seed "//itoa(seed)//", p = 2.."//itoa(p_max)//") that end, normal "// &
            "or quasi-plastic, within "//itoa(cap)//" collisions with closed-form limits")
        call write_answer(unit, "collapse.answered_before", itoa(answered(fallback)), &
            "scenes", itoa(scenes(fallback)), itoa(answered(fallback) - scenes(fallback)), &
            "the first "//itoa(scenes(fallback))//" of them with the fallback rule alone")
        call write_answer(unit, "collapse.invariant_failures", itoa(broken(closed)), &
            "expected", "0", itoa(broken(closed)), "runs that ended with momentum, energy, "// &
            "a gap or a closing pair outside "//str(slack)//" epsilon of their scales")
        close (unit)
    end subroutine write_tables

    !> Mean collisions of the answered runs of a rule (0 if none).
    real(qp) function mean_collisions(rule)
        integer, intent(in) :: rule
        mean_collisions = 0
        if (answered(rule) > 0) mean_collisions = real(collisions(rule), qp)/answered(rule)
    end function mean_collisions

end program c12_collapse
