!> Collapse in general rows: a seeded survey of random rows of spheres (see
!> sphere_row_survey for their distribution), each run to its end with the
!> closed-form collapse limits, and the first of them once more with the
!> fallback rule alone; how many end with an answer, how many collisions
!> that takes, and whether every invariant holds; and each row left
!> unanswered, with the command line that runs it again and, where it was in
!> a cascade at one instant, that cascade stepped further (step_further): how
!> many more collisions it takes to end.
program c12_collapse
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, simulate, str, itoa, status_max_collisions
    use sphere_row_survey, only: survey_t, survey_open, survey_close, survey_scene, &
        check_invariants, scene_command, further_t, step_further, further_word, &
        further_none, further_going
    use sphere_row_tables, only: open_table, close_table, write_answer, answer_header, tab, &
        row_t, write_rows
    use sphere_row_study_cli, only: cli_t, start_program, read_keys, stop_unless_normal, &
        stop_unless_written
    implicit none
    character(len=*), parameter :: nl = new_line("a")
    !> Rules compared: closed-form limits with the fallback, the fallback alone.
    integer, parameter :: closed = 1, fallback = 2
    !> Multiple of the kind's epsilon by which the invariants may miss, and
    !> the multiple more for each collision a run takes (its rounding).
    real(qp), parameter :: slack = 1.0e4_qp, per_collision = 4.0_qp
    type(cli_t) :: cli
    type(survey_t) :: survey
    character(len=:), allocatable :: out
    integer :: n, n_before, cap, seed, p_max
    !> Collisions by which an unanswered row's cascade at one instant is
    !> stepped further.
    integer(int64) :: further_most
    !> What one run leaves for the tables.
    type :: outcome_t
        logical :: answered = .false., broken = .false.
        integer(int64) :: n = 0
        real :: seconds = 0
        type(further_t) :: further
    end type outcome_t
    ! per rule: scenes, answered, invariant failures, collisions and seconds
    integer :: scenes(2), answered(2), broken(2)
    integer(int64) :: collisions(2)
    !> Wall seconds of the slowest run and of all runs, per rule (each run
    !> timed on its own thread).
    real :: seconds_max(2), seconds_sum(2)
    ! per p, closed-form rule: scenes and answered
    integer, allocatable :: by_p(:, :)
    ! rows of collapse_unanswered.tsv, one per unanswered row (closed-form rule)
    type(row_t), allocatable :: unanswered(:)
    !> Of the unanswered rows (closed-form rule): those of equal masses, and
    !> those whose largest mass is 10^4 times the smallest or more.
    integer :: unanswered_equal = 0, unanswered_far = 0
    !> Of the unanswered rows: those left in a cascade at one instant, and
    !> those whose cascade, stepped further, is over within the collisions
    !> allowed (no approach faster than tol v0 left).
    integer :: unanswered_instant = 0, unanswered_over = 0

    call start_program(cli, "c12-collapse", &
        "Collapse in general rows: random rows run to their end with closed-form"//nl// &
        "collapse limits, and the first n_before of them with the fallback rule alone."//nl// &
        "Writes OUT/collapse_survey.tsv, OUT/collapse_by_p.tsv, OUT/collapse_answers.tsv"//nl// &
        "and OUT/collapse_unanswered.tsv. An unanswered row left in a cascade at one"//nl// &
        "instant has that cascade stepped up to `further` more collisions by the"//nl// &
        "engine's rule, in double precision, to tell how long that cascade runs.")
    call cli%add_int("n", "1000", "random rows run with closed-form limits", lo=1)
    call cli%add_int("n_before", "300", "of these, rows run with the fallback rule alone", lo=0)
    call cli%add_int("cap", "10000", "collisions after which a run counts as unanswered", lo=1)
    call cli%add_int("seed", "12", "seed of the MT19937 stream of the rows", lo=0)
    call cli%add_int("p_max", "20", "largest row length drawn (p from 2)", lo=2)
    call cli%add_int("further", "1048576", "collisions an unanswered row's cascade at "// &
        "one instant is stepped further (0: none)", lo=0)
    call read_keys(cli)
    out = cli%get_word("out")
    n = cli%get_int("n")
    n_before = min(cli%get_int("n_before"), n)
    cap = cli%get_int("cap")
    seed = cli%get_int("seed")
    p_max = cli%get_int("p_max")
    further_most = cli%get_int("further")

    call run_survey()
    call write_tables()

contains

    !> Draw the rows (one stream, in order), run each under the rules on the
    !> OpenMP threads, then count the outcomes in row order.
    subroutine run_survey()
        type(scene_t), allocatable :: rows(:)
        type(outcome_t), allocatable :: outcome(:, :)
        type(scene_t) :: scene
        integer :: i, job, rule
        allocate (by_p(2, 2:p_max), source=0)
        allocate (unanswered(0), rows(n), outcome(2, n))
        scenes = 0
        answered = 0
        broken = 0
        collisions = 0
        seconds_max = 0
        seconds_sum = 0
        call survey_open(survey, seed, 2, p_max, 1.0e3_qp)
        do i = 1, n
            call survey_scene(survey, rows(i))
            rows(i)%max_collisions = cap
        end do
        call survey_close(survey)
        ! jobs 1..n: the rows with closed-form limits; n+1..n+n_before: the
        ! first rows again with the fallback rule alone
        !$omp parallel do schedule(dynamic, 1) default(shared) private(job, i, rule, scene)
        do job = 1, n + n_before
            rule = merge(closed, fallback, job <= n)
            i = merge(job, job - n, job <= n)
            scene = rows(i)
            scene%closed_form_limits = rule == closed
            call one_run(scene, outcome(rule, i))
        end do
        !$omp end parallel do
        do i = 1, n
            call tally(rows(i), closed, outcome(closed, i), i)
            if (i <= n_before) call tally(rows(i), fallback, outcome(fallback, i), i)
        end do
    end subroutine run_survey

    !> Run one row and keep what the tables need of it.
    subroutine one_run(scene, outcome)
        type(scene_t), intent(in) :: scene
        type(outcome_t), intent(out) :: outcome
        type(run_t) :: run
        character(len=:), allocatable :: why
        integer(int64) :: c0, c1, rate
        call system_clock(c0, rate)
        call simulate(scene, run)
        call system_clock(c1)
        outcome%seconds = real(c1 - c0)/real(rate)
        outcome%answered = run%status /= status_max_collisions
        outcome%n = run%n
        if (.not. outcome%answered) then
            ! (the table lists the unanswered rows of the closed-form rule only)
            if (further_most > 0 .and. scene%closed_form_limits) then
                call step_further(scene, run, further_most, outcome%further)
            end if
            return
        end if
        call check_invariants(scene, run, slack, per_collision, why)
        outcome%broken = why /= ""
    end subroutine one_run

    !> Count the outcome of row `index` under one rule.
    subroutine tally(scene, rule, outcome, index)
        type(scene_t), intent(in) :: scene
        integer, intent(in) :: rule, index
        type(outcome_t), intent(in) :: outcome
        scenes(rule) = scenes(rule) + 1
        seconds_max(rule) = max(seconds_max(rule), outcome%seconds)
        seconds_sum(rule) = seconds_sum(rule) + outcome%seconds
        if (rule == closed) by_p(1, scene%p) = by_p(1, scene%p) + 1
        if (.not. outcome%answered) then
            if (rule /= closed) return
            unanswered = [unanswered, unanswered_row(scene, index, outcome%further)]
            if (outcome%further%end /= further_none) unanswered_instant = unanswered_instant + 1
            if (outcome%further%end /= further_none .and. &
                outcome%further%end /= further_going) then
                unanswered_over = unanswered_over + 1
            end if
            if (all(scene%m == scene%m(1))) unanswered_equal = unanswered_equal + 1
            if (maxval(scene%m) >= 1.0e4_qp*minval(scene%m)) unanswered_far = unanswered_far + 1
            return
        end if
        answered(rule) = answered(rule) + 1
        collisions(rule) = collisions(rule) + outcome%n
        if (rule == closed) by_p(2, scene%p) = by_p(2, scene%p) + 1
        if (outcome%broken) broken(rule) = broken(rule) + 1
    end subroutine tally

    !> The survey table, the table per row length and the answers.
    subroutine write_tables()
        character(len=*), parameter :: names(2) = ["closed_form  ", "fallback_only"]
        integer :: unit, stat, rule, p
        character(len=300) :: msg
        call open_table(out, "collapse_survey.tsv", "rule"//tab//"scenes"//tab//"answered"// &
            tab//"unanswered"//tab//"invariant_failures"//tab//"mean_collisions"//tab// &
            "run_max[s]"//tab//"run_total[s]", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do rule = closed, fallback
            write (unit, "(a)") trim(names(rule))//tab//itoa(scenes(rule))//tab// &
                itoa(answered(rule))//tab//itoa(scenes(rule) - answered(rule))//tab// &
                itoa(broken(rule))//tab//str(mean_collisions(rule))//tab// &
                str(real(seconds_max(rule), qp))//tab//str(real(seconds_sum(rule), qp))
        end do
        call close_table(unit, stat, msg)
        call stop_unless_written(stat, msg)
        call open_table(out, "collapse_by_p.tsv", "p"//tab//"scenes"//tab//"answered"//tab// &
            "answered_share", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do p = 2, p_max
            if (by_p(1, p) == 0) cycle
            write (unit, "(a)") itoa(p)//tab//itoa(by_p(1, p))//tab//itoa(by_p(2, p))//tab// &
                str(real(by_p(2, p), qp)/by_p(1, p))
        end do
        call close_table(unit, stat, msg)
        call stop_unless_written(stat, msg)
        call open_table(out, "collapse_unanswered.tsv", "row"//tab//"p"//tab//"e[1]"//tab// &
            "mass_ratio[1]"//tab//"closed_gaps"//tab//"block"//tab//"further_collisions"// &
            tab//"further_end"//tab//"further_decades[1]"//tab//"command", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call write_rows(unit, unanswered)
        call close_table(unit, stat, msg)
        call stop_unless_written(stat, msg)
        call open_table(out, "collapse_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call write_answer(unit, "collapse.answered", itoa(answered(closed)), "scenes", &
            itoa(scenes(closed)), itoa(answered(closed) - scenes(closed)), &
            "random rows (seed "//itoa(seed)//", p = 2.."//itoa(p_max)//") that end, normal "// &
            "or quasi-plastic, within "//itoa(cap)//" collisions with closed-form limits")
        call write_answer(unit, "collapse.answered_before", itoa(answered(fallback)), &
            "scenes", itoa(scenes(fallback)), itoa(answered(fallback) - scenes(fallback)), &
            "the first "//itoa(scenes(fallback))//" of them with the fallback rule alone")
        call write_answer(unit, "collapse.unanswered_equal_masses", itoa(unanswered_equal), &
            "unanswered", itoa(size(unanswered)), itoa(unanswered_equal - size(unanswered)), &
            "unanswered rows of equal masses (collapse_unanswered.tsv)")
        call write_answer(unit, "collapse.unanswered_mass_ratio_1e4", itoa(unanswered_far), &
            "unanswered", itoa(size(unanswered)), itoa(unanswered_far - size(unanswered)), &
            "unanswered rows whose largest mass is 10^4 times the smallest or more")
        call write_answer(unit, "collapse.unanswered_at_one_instant", &
            itoa(unanswered_instant), "unanswered", itoa(size(unanswered)), &
            itoa(unanswered_instant - size(unanswered)), "unanswered rows left in a "// &
            "cascade at one instant through a touching block (further_end not -)")
        call write_answer(unit, "collapse.unanswered_cascade_over_further", &
            itoa(unanswered_over), "unanswered", itoa(size(unanswered)), &
            itoa(unanswered_over - size(unanswered)), "unanswered rows whose cascade at "// &
            "one instant, stepped up to "//itoa(int(further_most))//" more collisions by "// &
            "the engine's rule alone in double precision, is over: no approach faster than "// &
            "tol v0 left (further_end merges or ends); the row may go on after it")
        call write_answer(unit, "collapse.invariant_failures", itoa(broken(closed)), &
            "expected", "0", itoa(broken(closed)), "runs that ended with momentum, energy, "// &
            "a gap or a closing pair outside "//str(slack)//" + "//str(per_collision)// &
            " n epsilon of their scales (n collisions)")
        call close_table(unit, stat, msg)
        call stop_unless_written(stat, msg)
    end subroutine write_tables

    !> The row of collapse_unanswered.tsv of row `index` of the survey: its
    !> length, restitution, largest mass over smallest, gaps that start
    !> closed, the touching block of the cascade at one instant it was left
    !> in and that cascade stepped further (collisions, how it stood after
    !> them, the decades its fastest approach fell; - if it was in none), and the
    !> sphere-row command that runs it (scene_command).
    type(row_t) function unanswered_row(scene, index, further) result(row)
        type(scene_t), intent(in) :: scene
        integer, intent(in) :: index
        type(further_t), intent(in) :: further
        call row%add(index)
        call row%add(scene%p)
        call row%add(scene%e)
        call row%add(maxval(scene%m)/minval(scene%m))
        call row%add(count(scene%a == 0))
        if (further%end == further_none) then
            call row%add("-")
            call row%add("-")
            call row%add("-")
            call row%add("-")
        else
            call row%add(itoa(further%first)//"-"//itoa(further%last))
            call row%add(further%n)
            call row%add(further_word(further%end))
            call row%add(further%decades)
        end if
        call row%add(scene_command(scene))
    end function unanswered_row

    !> Mean collisions of the answered runs of a rule (0 if none).
    real(qp) function mean_collisions(rule)
        integer, intent(in) :: rule
        mean_collisions = 0
        if (answered(rule) > 0) mean_collisions = real(collisions(rule), qp)/answered(rule)
    end function mean_collisions

end program c12_collapse
