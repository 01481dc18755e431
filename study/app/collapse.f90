!> Collapse in general rows: a seeded survey of random rows of spheres (see
!> sphere_row_survey for their distribution), each run to its end by every
!> collapse rule, and the first of them once more with the fallback rule alone
!> (the engine before its closed forms); how good each answer is (exact,
!> certified, tolerance, bounded, unresolved), the bound on its final
!> velocities, how many collisions and how much time it takes, and whether
!> every invariant holds; and each row left unresolved, with the groups still
!> active, the bound reached on them and the command that runs it again.
program c12_collapse
    use, intrinsic :: iso_fortran_env, only: int64, error_unit
    use sphere_row, only: qp, scene_t, run_t, simulate, str, itoa, real_str, answer_word, &
        answer_words, answer_exact, answer_certified, answer_tolerance, answer_bounded, &
        answer_unresolved, order_premise
    use sphere_row_survey, only: survey_t, survey_open, survey_close, survey_scene, &
        check_invariants, scene_command
    use sphere_row_sorting, only: sort
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab, &
        row_t, write_rows
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, stop_unless_normal, &
        close_tables, fail, add_run_keys, set_run_keys
    implicit none
    !> Rules compared: every collapse rule, the fallback alone.
    integer, parameter :: every = 1, fallback = 2
    character(len=*), parameter :: rule_names(2) = ["every_rule   ", "fallback_only"]
    !> Multiple of the kind's epsilon by which the invariants may miss, and
    !> the multiple more for each collision a run takes (its rounding).
    real(qp), parameter :: slack = 1.0e4_qp, per_collision = 4.0_qp
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    integer :: n, n_before, seed, p_min, p_max
    real(qp) :: span, equal_share
    !> What one run leaves for the tables.
    type :: outcome_t
        integer :: answer = 0
        logical :: broken = .false.
        character(len=16) :: why = ""
        integer(int64) :: n = 0
        real(qp) :: bound = 0
        real :: seconds = 0
        !> order_check proves exact arithmetic's order of collisions as far as
        !> the run went: to its end, or to its first limit (order_premise).
        logical :: order_checked = .false.
        !> The row's line of collapse_unanswered.tsv (unresolved), or of
        !> collapse_order_computed.tsv (exact or certified, its order not
        !> proven).
        type(row_t) :: row
    end type outcome_t
    type(outcome_t), allocatable :: outcome(:, :)
    type(scene_t), allocatable :: rows(:)

    call start_program(cli, "c12-collapse", &
        "Collapse in general rows: random rows run to their end by every collapse rule,"//nl// &
        "and the first n_before of them by the fallback rule alone. Writes"//nl// &
        "OUT/collapse_survey.tsv (rows per answer, bounds, collisions),"//nl// &
        "OUT/collapse_by_p.tsv, OUT/collapse_answers.tsv, OUT/collapse_unanswered.tsv"//nl// &
        "(every row left unresolved, its active groups and the bound reached on them),"//nl// &
        "OUT/collapse_order_computed.tsv (every exact or certified row whose order of"//nl// &
        "collisions the check does not prove, and the decision that stopped it)"//nl// &
        "and the runs' wall times in OUT/timing/collapse_survey.tsv.")
    call cli%add_int("n", "1000", "random rows run by every collapse rule", lo=1)
    call cli%add_int("n_before", "300", "of these, rows run with the fallback rule alone", lo=0)
    call cli%add_int("seed", "12", "seed of the MT19937 stream of the rows", lo=0)
    call cli%add_int("p_min", "2", "least row length drawn", lo=2)
    call cli%add_int("p_max", "20", "largest row length drawn", lo=2)
    call cli%add_real("span", "1000", "unequal masses are log-uniform over [1/span, span]", &
        lo=1.0_qp)
    call cli%add_real("equal_share", "0.5", "share of the rows of equal masses", lo=0.0_qp, &
        hi=1.0_qp)
    call add_run_keys(cli)
    call read_keys(cli)
    out = cli%get_word("out")
    n = cli%get_int("n")
    n_before = min(cli%get_int("n_before"), n)
    seed = cli%get_int("seed")
    p_min = cli%get_int("p_min")
    p_max = cli%get_int("p_max")
    if (p_max < p_min) call fail("c12-collapse: p_max = "//itoa(p_max)// &
        ": allowed p_max >= p_min = "//itoa(p_min))
    span = cli%get_real("span")
    equal_share = cli%get_real("equal_share")

    call run_survey()
    call write_tables()

contains

    !> Draw the rows (one stream, in order), run each under the rules on the
    !> OpenMP threads; the tables count them in row order.
    subroutine run_survey()
        type(survey_t) :: survey
        type(scene_t) :: scene
        integer :: i, job, rule
        allocate (rows(n), outcome(2, n))
        call survey_open(survey, seed, p_min, p_max, span, equal_share)
        do i = 1, n
            call survey_scene(survey, rows(i))
            call set_run_keys(cli, rows(i))
        end do
        call survey_close(survey)
        ! jobs 1..n: the rows with every rule; n+1..n+n_before: the first
        ! rows again with the fallback rule alone
        !$omp parallel do schedule(dynamic, 1) default(shared) private(job, i, rule, scene)
        do job = 1, n + n_before
            rule = merge(every, fallback, job <= n)
            i = merge(job, job - n, job <= n)
            scene = rows(i)
            scene%closed_form_limits = rule == every
            if (rule == fallback) scene%vtol = 0
            ! (the run keeps its order, which the order check must match)
            if (rule == every) scene%keep_order = huge(1)
            call one_run(scene, i, outcome(rule, i))
        end do
        !$omp end parallel do
        ! each row's last field, the command that runs it again, made here on
        ! one thread: scene_command's texts are of deferred length, which
        ! threads may not make at once
        do rule = every, fallback
            do i = 1, merge(n, n_before, rule == every)
                if (allocated(outcome(rule, i)%row%text)) then
                    call outcome(rule, i)%row%add(scene_command(rows(i)))
                end if
            end do
        end do
        ! a broken invariant is named, with the command that runs the row again
        do rule = every, fallback
            do i = 1, merge(n, n_before, rule == every)
                if (outcome(rule, i)%broken) write (error_unit, "(a)") "c12-collapse: row " &
                    //itoa(i)//" ("//trim(rule_names(rule))//") breaks "// &
                    trim(outcome(rule, i)%why)//": "//scene_command(rows(i))
            end do
        end do
    end subroutine run_survey

    !> Run one row and keep what the tables need of it (an unresolved row's
    !> line of collapse_unanswered.tsv, or an exact or certified row's of
    !> collapse_order_computed.tsv where the check does not prove its order,
    !> built here on the thread by row_t, all but its last field, the command).
    subroutine one_run(scene, index, result)
        type(scene_t), intent(in) :: scene
        integer, intent(in) :: index
        type(outcome_t), intent(out) :: result
        type(run_t) :: run
        character(len=:), allocatable :: why
        character(len=80) :: why_not
        integer(int64) :: c0, c1, rate
        integer :: j, at
        character(len=2000) :: groups
        call system_clock(c0, rate)
        call simulate(scene, run)
        call system_clock(c1)
        result%seconds = real(c1 - c0)/real(rate)
        result%answer = run%answer
        result%bound = run%v_bound
        result%n = run%n
        call check_invariants(scene, run, slack, per_collision, why)
        result%broken = why /= ""
        result%why = why
        if (scene%closed_form_limits .and. (run%answer == answer_exact .or. &
                run%answer == answer_certified)) then
            call order_premise(scene, run, huge(1.0_qp), result%order_checked, why_not)
            if (.not. result%order_checked) then
                call result%row%add(index)
                call result%row%add(scene%p)
                call result%row%add(scene%e)
                call result%row%add(trim(answer_words(run%answer)))
                call result%row%add(merge(run%limits%at, run%n, run%limits%n > 0))
                call result%row%add(trim(why_not))
            end if
        end if
        if (run%answer /= answer_unresolved .or. .not. scene%closed_form_limits) return
        call result%row%add(index)
        call result%row%add(scene%p)
        call result%row%add(scene%e)
        call result%row%add(maxval(scene%m)/minval(scene%m))
        call result%row%add(count(scene%a == 0))
        call result%row%add(run%v_bound, 2)
        ! the groups as "first-last first-last ..." (a fixed buffer: threads
        ! may not make character results of deferred length at once)
        groups = "-"
        at = 0
        do j = 1, min(size(run%active, 2), 80)
            write (groups(at + 1:), "(i0, '-', i0, ' ')") run%active(:, j)
            at = len_trim(groups) + 1
        end do
        call result%row%add(trim(groups))
    end subroutine one_run

    !> The survey table, the table per row length, the unresolved rows, the
    !> rows whose order is computed and the answers.
    subroutine write_tables()
        integer :: unit, unit_time, stat, rule, p, a, rows_of, k
        character(len=300) :: msg
        character(len=*), parameter :: answer_columns = "exact"//tab//"certified"//tab// &
            "tolerance"//tab//"bounded"//tab//"unresolved"
        call open_table(out, "collapse_survey.tsv", "rule"//tab//"scenes"//tab// &
            answer_columns//tab//"invariant_failures"//tab//"v_bound_max[V]"//tab// &
            "mean_collisions", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        ! the runs' wall times, which differ from machine to machine, in a table
        ! of their own under timing/, so that the survey's is the same anywhere
        call open_table(out//"/timing", "collapse_survey.tsv", "rule"//tab//"run_median[s]" &
            //tab//"run_max[s]"//tab//"run_total[s]", unit_time, stat, msg)
        call stop_unless_normal(stat, msg)
        do rule = every, fallback
            rows_of = merge(n, n_before, rule == every)
            if (rows_of == 0) cycle
            write (unit, "(a)") trim(rule_names(rule))//tab//itoa(rows_of)//tab// &
                answer_counts(rule, 1, rows_of)//tab//itoa(count(outcome(rule, :rows_of)%broken)) &
                //tab//real_str(bound_max(rule, rows_of), 3)//tab// &
                str(real(sum(outcome(rule, :rows_of)%n), qp)/rows_of)
            write (unit_time, "(a)") trim(rule_names(rule))//tab// &
                str(real(median_seconds(rule, rows_of), qp))//tab// &
                str(real(maxval(outcome(rule, :rows_of)%seconds), qp))//tab// &
                str(real(sum(outcome(rule, :rows_of)%seconds), qp))
        end do
        call close_tables([unit, unit_time])
        call open_table(out, "collapse_by_p.tsv", "p"//tab//"scenes"//tab//answer_columns, &
            unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do p = p_min, p_max
            if (count(rows%p == p) == 0) cycle
            write (unit, "(a)") itoa(p)//tab//itoa(count(rows%p == p))//tab// &
                answer_counts(every, 1, n, p)
        end do
        call close_tables([unit])
        call write_picked("collapse_unanswered.tsv", "row"//tab//"p"//tab//"e[1]"//tab// &
            "mass_ratio[1]"//tab//"closed_gaps"//tab//"v_bound[V]"//tab//"active"//tab// &
            "command", outcome(every, :)%answer == answer_unresolved)
        ! (the collisions the answer rests on: every one, or those before the
        ! first limit)
        call write_picked("collapse_order_computed.tsv", "row"//tab//"p"//tab//"e[1]"//tab// &
            "answer"//tab//"premise_collisions"//tab//"order_stopped_by"//tab//"command", &
            (outcome(every, :)%answer == answer_exact .or. outcome(every, :)%answer == &
            answer_certified) .and. .not. outcome(every, :)%order_checked)
        call open_table(out, "collapse_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do a = answer_exact, answer_unresolved
            call write_answer(unit, "collapse."//answer_word(a), &
                itoa(count(outcome(every, :)%answer == a)), "scenes", itoa(n), "-", &
                "random rows (seed "//itoa(seed)//", p = "//itoa(p_min)//".."//itoa(p_max)// &
                ") whose answer is " &
                //answer_word(a)//", run by every collapse rule within "//budget_words())
        end do
        call write_answer(unit, "collapse.answered", &
            itoa(count(outcome(every, :)%answer /= answer_unresolved)), "scenes", itoa(n), &
            itoa(count(outcome(every, :)%answer /= answer_unresolved) - n), &
            "rows with an answer: every label but unresolved")
        do a = answer_exact, answer_certified
            rows_of = count(outcome(every, :)%answer == a)
            k = count(outcome(every, :)%answer == a .and. outcome(every, :)%order_checked)
            call write_answer(unit, "collapse.order_checked_"//answer_word(a), itoa(k), &
                "scenes", itoa(rows_of), itoa(k - rows_of), "rows whose answer is " &
                //answer_word(a)//" and for which order_check proves exact arithmetic's " &
                //"order of collisions (each decision beyond the bound on its rounding, " &
                //"to first order) as far as the run went: every collision and the end, " &
                //"or, where it took a limit, the collisions before its first (sphere-row's " &
                //"order proven; the rest, the difference, rest on the run's own order: " &
                //"order computed)")
        end do
        call write_answer(unit, "collapse.v_bound_max", real_str(bound_max(every, n), 3), &
            "-", "-", "-", "the largest bound on the final velocities of a row with an " &
            //"answer (0: every answer exact or certified)")
        if (n_before > 0) call write_answer(unit, "collapse.answered_fallback_only", &
            itoa(count(outcome(fallback, :n_before)%answer /= answer_unresolved)), "scenes", &
            itoa(n_before), &
            itoa(count(outcome(fallback, :n_before)%answer /= answer_unresolved) - n_before), &
            "the first "//itoa(n_before)//" rows with the fallback rule alone")
        call write_answer(unit, "collapse.invariant_failures", &
            itoa(count(outcome(every, :)%broken)), "expected", "0", &
            itoa(count(outcome(every, :)%broken)), "runs that ended with momentum (from the " &
            //"run's own x_1 rate and rates), energy, a gap or a closing pair outside " &
            //str(slack)//" + "//str(per_collision)//" n epsilon of their scales (n collisions)")
        call close_tables([unit])
    end subroutine write_tables

    !> The table `name` of the lines of the rows of every rule that `pick`
    !> marks, in row order.
    subroutine write_picked(name, header, pick)
        character(len=*), intent(in) :: name, header
        logical, intent(in) :: pick(:)
        type(row_t), allocatable :: lines(:)
        integer :: unit, stat, j, k
        character(len=300) :: msg
        call open_table(out, name, header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        ! (picked one by one: pack of a component of a section of outcome
        ! would copy the section to an array temporary)
        allocate (lines(count(pick)))
        k = 0
        do j = 1, size(pick)
            if (.not. pick(j)) cycle
            k = k + 1
            lines(k) = outcome(every, j)%row
        end do
        call write_rows(unit, lines)
        call close_tables([unit])
    end subroutine write_picked

    !> The rows of each answer, tab-separated, among rows first..last of a
    !> rule (of length p only, if given).
    function answer_counts(rule, first, last, p) result(text)
        integer, intent(in) :: rule, first, last
        integer, intent(in), optional :: p
        character(len=:), allocatable :: text
        integer :: a, c
        logical :: take(last - first + 1)
        take = .true.
        if (present(p)) take = rows(first:last)%p == p
        text = ""
        do a = answer_exact, answer_unresolved
            c = count(take .and. outcome(rule, first:last)%answer == a)
            if (a > answer_exact) text = text//tab
            text = text//itoa(c)
        end do
    end function answer_counts

    !> The largest bound of a row with an answer (not unresolved) of a rule.
    real(qp) function bound_max(rule, rows_of)
        integer, intent(in) :: rule, rows_of
        bound_max = maxval(outcome(rule, :rows_of)%bound, &
            mask=outcome(rule, :rows_of)%answer /= answer_unresolved)
        if (.not. any(outcome(rule, :rows_of)%answer /= answer_unresolved)) bound_max = 0
    end function bound_max

    !> The median wall time of a rule's rows.
    real function median_seconds(rule, rows_of)
        integer, intent(in) :: rule, rows_of
        real(qp) :: times(rows_of)
        times = outcome(rule, :rows_of)%seconds
        call sort(times)
        median_seconds = real(times((rows_of + 1)/2))
    end function median_seconds

    !> The budget in words.
    function budget_words() result(text)
        character(len=:), allocatable :: text
        integer :: cap
        cap = cli%get_int("cap")
        if (cap == 0) then
            text = "the default budget, max(10^6, 100 p) collisions"
        else
            text = itoa(cap)//" collisions"
        end if
    end function budget_words

end program c12_collapse
