!> C12 task b1: number of collisions n(e) from e = 1 down into the
!> quasi-plastic regime, its intervals of constant n and sequence, and the
!> critical restitution below which the collisions never end.
program c12_b1
    use sphere_row, only: qp, scene_t, run_t, event_log_t, simulate, str, status_word, &
        status_normal, status_collapsed, itoa, auto_t, simulate_auto
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab, &
        row_t, write_rows
    use sphere_row_analysis, only: sequence_of, sequence_text, sequence_hash, tail_period, &
        critical_restitution
    use sphere_row_bisection, only: bisect_ahead, bisect_changes
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, &
        stop_unless_normal, close_tables, add_row_keys, precision_is_auto
    use sphere_row_sorting, only: sort
    implicit none
    !> Class of a run with a collapse: its count depends on tol, not on e alone.
    integer(8), parameter :: collapsed_class = 0_8
    !> Smallest n of a point in the power-law fit: below it the run is too far
    !> from e_crit for the asymptote n ~ (e - e_crit)^(-1/2).
    integer, parameter :: min_fit_collisions = 200
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    character(len=300) :: msg
    type(scene_t) :: scene
    type(run_t) :: run
    type(event_log_t) :: events
    integer, allocatable :: pairs(:), cycle(:)
    integer :: stat, unit, j, n_scan, n_bisect_max, n_boundaries, period, k
    integer :: n_intervals, n_fit, stat_c
    real(qp) :: resolution, tol_fine, e_lo, e_hi, e_c, e_c_sim, closed, lo, hi
    real(qp) :: sx, sy, sxx, sxy, slope, intercept, e_quasi, delta
    real(qp), allocatable :: e_scan(:), boundaries(:)
    integer, allocatable :: n_scan_runs(:), status_scan(:)
    integer(8), allocatable :: class_scan(:)
    !> The keys precision = auto (scan and bisections) and critical = yes.
    logical :: auto_runs, with_critical
    !> An interval of e whose runs have one class: its ends, the run at its
    !> middle (count, status, collision sequence) and that class.
    type :: interval_t
        real(qp) :: lo = 0, hi = 0
        integer :: n = 0, status = 0
        integer, allocatable :: pairs(:)
        integer(8) :: class = 0
    end type interval_t
    !> The intervals from e = 0 up to 1, neighbours of one class joined, and
    !> the run at e = 1 itself.
    type(interval_t), allocatable :: intervals(:)
    type(interval_t) :: at_1
    !> A thread's own scene, run and log for the bisections of step 2.
    type(scene_t), save :: thread_scene
    type(run_t), save :: thread_run
    type(event_log_t), save :: thread_events
    integer, allocatable, save :: thread_pairs(:)
    !$omp threadprivate(thread_scene, thread_run, thread_events, thread_pairs)

    e_c = -1.0_qp
    call define_keys()
    call scan()
    call find_changes()
    call find_intervals()
    if (with_critical) call critical_by_simulation()
    if (with_critical) call critical_from_cycle()
    call write_intervals()
    if (with_critical) call write_critical()
    call write_answers()

contains

    !> The keys of c12-b1, read from the command line.
    subroutine define_keys()
        call start_program(cli, "c12-b1", &
            "C12 task b1: n(e) from e = 1 down to 0, its intervals of constant n and"//nl// &
            "collision sequence, and the critical restitution of inelastic collapse."//nl// &
            "Writes OUT/b1_scan.tsv, b1_intervals.tsv, b1_critical.tsv, b1_answers.tsv."//nl// &
            "A sequence names each collision in order by its pair, k for spheres k and"//nl// &
            "k+1: 123121 is 1-2, 2-3, 3-4, 1-2, 2-3, 1-2 (dots between pairs past 9).")
        call cli%add_int("n_scan", "2001", "points of the scan of e in [0, 1]", lo=3)
        call cli%add_real("resolution", "1e-12", &
            "width to which each change of n is bisected", lo=1.0e-30_qp, hi=0.1_qp)
        call cli%add_int("n_bisect_max", "300", "changes with larger n on both sides are " &
            //"not bisected", lo=1)
        call cli%add_real("tol_fine", "1e-4000", "tolerance of the runs near e_crit", &
            lo=1.0e-4900_qp, hi=0.5_qp)
        call cli%add_flag("critical", "yes", "also the critical restitution: bisection of" &
            //" collapsed against finite runs with tol_fine, the collapse cycle's rate map, " &
            //"b1_critical.tsv")
        call add_row_keys(cli, e_set_by="the scan of e")
        call read_keys(cli, scene)
        auto_runs = precision_is_auto(cli)
        out = cli%get_word("out")
        n_scan = cli%get_int("n_scan")
        resolution = cli%get_real("resolution")
        n_bisect_max = cli%get_int("n_bisect_max")
        tol_fine = cli%get_real("tol_fine")
        with_critical = cli%get_flag("critical")
    end subroutine define_keys

    !> Step 1: a dense scan of e from 1 down to 0 with the scene's own tolerance,
    !> in parallel (OpenMP; the slow runs near e = 0 first), and b1_scan.tsv.
    subroutine scan()
        ! a thread's own scene, run and log
        type(scene_t) :: scan_scene
        type(run_t) :: scan_run
        type(event_log_t) :: scan_events
        integer, allocatable :: scan_pairs(:)
        type(row_t), allocatable :: scan_rows(:)
        integer :: i
        allocate (e_scan(n_scan), n_scan_runs(n_scan), status_scan(n_scan), class_scan(n_scan))
        allocate (scan_rows(n_scan))
        call open_table(out, "b1_scan.tsv", "e"//tab//"collisions"//tab//"status"//tab// &
            "sequence_hash", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        !$omp parallel do schedule(dynamic, 8) default(shared) &
        !$omp private(i, scan_scene, scan_run, scan_events, scan_pairs)
        do i = n_scan, 1, -1
            e_scan(i) = 1.0_qp - real(i - 1, qp)/real(n_scan - 1, qp)
            scan_scene = scene
            call classify_with(e_scan(i), scan_scene, scan_run, scan_events, scan_pairs, &
                class_scan(i))
            n_scan_runs(i) = scan_run%n
            status_scan(i) = scan_run%status
            call scan_rows(i)%add(e_scan(i))
            call scan_rows(i)%add(n_scan_runs(i))
            call scan_rows(i)%add_status(status_scan(i))
            call scan_rows(i)%add(class_scan(i))
        end do
        !$omp end parallel do
        call write_rows(unit, scan_rows)
        call close_tables([unit])
    end subroutine scan

    !> Step 2: every change of (n, sequence) between neighbours of the scan,
    !> bisected to `resolution`, in increasing order. The intervals are
    !> bisected in parallel (OpenMP), each thread on its own scene and run, the
    !> slow ones of low e first, and their changes joined in the scan's order.
    subroutine find_changes()
        !> The changes found in one interval of the scan.
        type :: found_t
            real(qp), allocatable :: e(:)
        end type found_t
        type(found_t), allocatable :: found(:)
        integer :: i
        allocate (found(n_scan - 1))
        !$omp parallel do schedule(dynamic, 1) default(shared) private(i)
        do i = n_scan - 1, 1, -1
            allocate (found(i)%e(0))
            if (class_scan(i) == class_scan(i + 1)) cycle
            if (min(n_scan_runs(i), n_scan_runs(i + 1)) > n_bisect_max) cycle
            thread_scene = scene
            call bisect_changes(class_in_thread, e_scan(i + 1), e_scan(i), class_scan(i + 1), &
                class_scan(i), resolution, found(i)%e)
        end do
        !$omp end parallel do
        allocate (boundaries(0))
        do i = 1, n_scan - 1
            boundaries = [boundaries, found(i)%e]
        end do
        n_boundaries = size(boundaries)
        call sort(boundaries)
    end subroutine find_changes

    !> The class of the run at e on the calling thread's own scene and run.
    function class_in_thread(e) result(class)
        real(qp), intent(in) :: e
        integer(8) :: class
        call classify_with(e, thread_scene, thread_run, thread_events, thread_pairs, class)
    end function class_in_thread

    !> Step 3: the critical restitution by simulation alone, with a tolerance
    !> near the bottom of real128's range: bisect finite against collapsed.
    !> The next steps' runs (up to ~2 10^4 collisions near e_crit) run ahead on other threads.
    subroutine critical_by_simulation()
        !> Half-width of the bracket around e_quasi in which the simulation alone
        !> bisects collapsed against finite runs.
        real(qp), parameter :: simulation_bracket = 0.01_qp
        !> Most bisection steps of that bracket.
        integer, parameter :: max_bisection_steps = 200
        scene%tol = tol_fine
        lo = e_quasi - simulation_bracket
        hi = e_quasi + simulation_bracket
        call bisect_ahead(collapses, lo, hi, resolution, max_bisection_steps)
        e_c_sim = hi
    end subroutine critical_by_simulation

    !> Step 4: the critical restitution from the cycle of the collapse. A run
    !> with the fine tolerance just below the simulated boundary follows the
    !> cycle for thousands of collisions; its period is found inside the run,
    !> and e_c is where the cycle's rate map gets complex eigenvalues. The
    !> run's limit is taken by the fallback alone, not as soon as the cycle is
    !> certified: it is wanted for its long tail of the cycle.
    subroutine critical_from_cycle()
        !> How far below the simulated bound the run that shows the collapse cycle
        !> starts: a collapsed run, yet close enough to e_crit to follow the cycle
        !> for thousands of collisions.
        real(qp), parameter :: cycle_run_offset = 0.001_qp
        !> Part of the cycle run's collisions searched for the period: the end of
        !> the run, where the fallback takes the limit, is left out.
        integer, parameter :: cycle_part_num = 3, cycle_part_den = 4
        !> Collisions at the end of that part that must repeat with the period.
        integer, parameter :: period_window = 48
        !> Longest period looked for.
        integer, parameter :: max_period = 24
        !> How far above the simulated bound the discriminant of the cycle's rate
        !> map is bracketed.
        real(qp), parameter :: discriminant_bracket = 0.01_qp
        e_lo = e_c_sim - cycle_run_offset
        scene%e = e_lo
        scene%closed_form_limits = .false.
        call simulate(scene, run, events)
        scene%closed_form_limits = .true.
        call sequence_of(events, pairs, before_collapse=.true.)
        pairs = pairs(:cycle_part_num*size(pairs)/cycle_part_den)
        period = tail_period(pairs, period_window, max_period)
        e_c = -1.0_qp
        stat_c = -1
        if (period > 0) then
            cycle = pairs(size(pairs) - period + 1:)
            e_hi = e_c_sim + discriminant_bracket
            call critical_restitution(scene%m, cycle, e_lo, e_hi, e_c, stat_c)
        end if
        if (stat_c /= status_normal) e_c = -1.0_qp
        closed = 3.0_qp - 2.0_qp*sqrt(2.0_qp)
    end subroutine critical_from_cycle

    !> Step 5, b1_critical.tsv: n against the distance to e_c with the fine
    !> tolerance, and the power law fitted to it. The runs are independent:
    !> they are made in parallel (OpenMP), the long ones closest to e_c first.
    subroutine write_critical()
        !> Rows of b1_critical.tsv: e - e_crit log-spaced over the decades below.
        integer, parameter :: n_delta = 25
        !> Largest and smallest e - e_crit of b1_critical.tsv, as powers of ten.
        real(qp), parameter :: delta_top_decade = -1.0_qp, delta_bottom_decade = -7.0_qp
        type(run_t) :: runs(n_delta)
        type(scene_t) :: mine
        real(qp) :: e_base
        e_base = e_c_sim
        if (e_c > 0) e_base = e_c
        !$omp parallel do schedule(dynamic, 1) default(shared) private(k, mine)
        do k = n_delta, 1, -1
            mine = scene
            mine%e = e_base + 10.0_qp**(delta_top_decade + (delta_bottom_decade &
                - delta_top_decade)*real(k - 1, qp)/real(n_delta - 1, qp))
            call simulate(mine, runs(k))
        end do
        !$omp end parallel do
        call open_table(out, "b1_critical.tsv", "delta=e-e_crit"//tab//"e"//tab// &
            "collisions"//tab//"status"//tab//"collisions*sqrt(delta)", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        sx = 0
        sy = 0
        sxx = 0
        sxy = 0
        n_fit = 0
        do k = 1, n_delta
            delta = 10.0_qp**(delta_top_decade + (delta_bottom_decade - delta_top_decade) &
                *real(k - 1, qp)/real(n_delta - 1, qp))
            associate (r => runs(k))
                write (unit, "(a)") str(delta)//tab//str(e_base + delta)//tab//itoa(r%n)//tab// &
                    status_word(r%status)//tab//str(r%n*sqrt(delta))
                ! fit log n = intercept + slope log delta where the asymptote holds
                if (r%status == status_normal .and. r%n >= min_fit_collisions) then
                    sx = sx + log(delta)
                    sy = sy + log(real(r%n, qp))
                    sxx = sxx + log(delta)**2
                    sxy = sxy + log(delta)*log(real(r%n, qp))
                    n_fit = n_fit + 1
                end if
            end associate
        end do
        call close_tables([unit])
        slope = 0
        intercept = 0
        if (n_fit >= 2) then
            slope = (n_fit*sxy - sx*sy)/(n_fit*sxx - sx**2)
            intercept = (sy - slope*sx)/n_fit
        end if
    end subroutine write_critical

    !> The answers of task b1: the critical restitution from the collapse cycle
    !> and by simulation, against 3 - 2 sqrt(2); the power law of n near it;
    !> the top of the quasi-plastic range; the scan and its intervals.
    subroutine write_answers()
        call open_table(out, "b1_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        if (with_critical) call write_critical_answers()
        call write_answer(unit, "b1.e_quasi_plastic", str(e_quasi), "-", "-", "-", &
            "largest e where the scene's default tolerance (the relative velocities fall "// &
            "below epsilon v0) reports the quasi-plastic case: the definition's "// &
            "'quasi-plastic case reached'")
        call write_answer(unit, "b1.scan_points", itoa(n_scan), "-", "-", "-", &
            "e from 1 down to 0 in equal steps")
        call write_answer(unit, "b1.resolution", str(resolution), "-", "-", "-", &
            "width to which each change of the scan's collision sequence is bisected")
        call write_answer(unit, "b1.intervals", itoa(n_intervals), "-", "-", "-", &
            "intervals of constant n and sequence found above the quasi-plastic ones (the "// &
            "point e = 1 among them), each end bisected to "//str(resolution)// &
            " (changes with n > "//itoa(n_bisect_max)//" on both sides are left to the "// &
            "critical table)")
        call write_answer(unit, "b1.n_at_e1", itoa(n_scan_runs(1)), "closed_form", &
            itoa(scene%p - 1), itoa(n_scan_runs(1) - (scene%p - 1)), &
            "e = 1: one collision per pair")
        call close_tables([unit])
    end subroutine write_answers

    !> The answers about e_crit: from the collapse cycle and by simulation
    !> against 3 - 2 sqrt(2), the power law of n near it, the fine tolerance.
    subroutine write_critical_answers()
        if (e_c > 0) then
            call write_answer(unit, "b1.e_crit", str(e_c), "closed_form_3-2sqrt2", str(closed), &
                str(e_c - closed), "e where the rate map of the collapse cycle "// &
                sequence_text(cycle)//" (period "//itoa(period)//", from the run at e = "// &
                str(e_lo)//") gets a complex eigenvalue pair: bisection of its discriminant "// &
                "in real(16); it coincides with tan^2(pi/8) = 3 - 2 sqrt(2)")
        else
            call write_answer(unit, "b1.e_crit", str(e_c_sim), "-", "-", "-", &
                "no collapse cycle found for this scene (or not 4 spheres): the "// &
                "simulation bound b1.e_crit_simulation is given")
        end if
        call write_answer(unit, "b1.e_crit_simulation", str(e_c_sim), "b1.e_crit", str(e_c), &
            str(e_c_sim - e_c), "bisection of collapsed against finite runs with tol = "// &
            str(tol_fine)//"; a finite run this close to e_crit shrinks its relative "// &
            "velocities below any fixed tolerance, so this bound lies above e_crit")
        call write_answer(unit, "b1.exponent", str(slope), "theory", str(-0.5_qp), &
            str(slope + 0.5_qp), "least-squares slope of log n against log(e - e_crit) over "// &
            itoa(n_fit)//" points with n >= "//itoa(min_fit_collisions)//"; near e_crit the "// &
            "cycle map has eigenvalues r exp(+-i theta) with theta ~ sqrt(e - e_crit), and "// &
            "the collisions end after about pi/theta cycles")
        call write_answer(unit, "b1.prefactor", str(exp(intercept)), "-", "-", "-", &
            "n ~ prefactor (e - e_crit)^exponent")
        call write_answer(unit, "b1.tol_fine", str(tol_fine), "-", "-", "-", &
            "tolerance of the runs near e_crit: the simulated bound, the cycle run and "// &
            "b1_critical.tsv")
    end subroutine write_critical_answers

    !> Step 2b: the intervals between consecutive changes, each with the run
    !> at its middle (run in parallel); neighbours of one class are joined (a
    !> change bisected towards e = 1, where only the point e = 1 itself
    !> differs, would otherwise split one interval in two); e_quasi is the
    !> top of the collapsed ones.
    subroutine find_intervals()
        type(interval_t), allocatable :: middles(:)
        ! interval j from ends(j) to ends(j + 1), from 0 to the first change ...
        real(qp), allocatable :: ends(:)
        type(scene_t) :: mine
        type(run_t) :: got
        type(event_log_t) :: log
        integer :: n_joined
        allocate (middles(0:n_boundaries), ends(0:n_boundaries + 1))
        ends = [0.0_qp, boundaries, 1.0_qp]
        !$omp parallel do schedule(dynamic, 1) default(shared) private(j, mine, got, log)
        do j = n_boundaries, 0, -1
            mine = scene
            call classify_with(0.5_qp*(ends(j) + ends(j + 1)), mine, got, log, &
                middles(j)%pairs, middles(j)%class)
            middles(j)%lo = ends(j)
            middles(j)%hi = ends(j + 1)
            middles(j)%n = got%n
            middles(j)%status = got%status
        end do
        !$omp end parallel do
        allocate (intervals(n_boundaries + 1))
        n_joined = 0
        e_quasi = -1.0_qp
        do j = 0, n_boundaries
            if (n_joined > 0) then
                if (intervals(n_joined)%class == middles(j)%class) then
                    intervals(n_joined)%hi = middles(j)%hi
                    cycle
                end if
            end if
            n_joined = n_joined + 1
            intervals(n_joined) = middles(j)
        end do
        intervals = intervals(:n_joined)
        do j = 1, n_joined
            if (intervals(j)%status == status_collapsed) e_quasi = max(e_quasi, intervals(j)%hi)
        end do
        call classify(1.0_qp, at_1%class)
        at_1%n = run%n
        at_1%status = run%status
        at_1%pairs = pairs
    end subroutine find_intervals

    !> b1_intervals.tsv: the intervals of find_intervals, each with its
    !> collision count and sequence, and what the row does there in exact
    !> arithmetic. The collapsed interval is split at e_crit (when the
    !> collapse cycle gave it): below it the row collapses, above it the row
    !> separates after ever more collisions as e -> e_crit, which the
    !> default tolerance merges (their counts are b1_critical.tsv's). Neither
    !> part has a finite count or a sequence. e = 1 itself is a point of its
    !> own (one collision per pair), apart from the interval just below it.
    subroutine write_intervals()
        logical :: split
        call open_table(out, "b1_intervals.tsv", "e_low"//tab//"e_high"//tab//"width"//tab// &
            "collisions"//tab//"status"//tab//"in_exact_arithmetic"//tab//"sequence", unit, &
            stat, msg)
        call stop_unless_normal(stat, msg)
        n_intervals = 0
        do j = 1, size(intervals)
            associate (v => intervals(j))
                if (v%status == status_collapsed) then
                    split = e_c > v%lo .and. e_c < v%hi
                    if (split) then
                        call collapsed_row(v%lo, e_c, "collapses")
                        call collapsed_row(e_c, v%hi, "separates")
                    else
                        call collapsed_row(v%lo, v%hi, merge("collapses", "-        ", &
                            e_c >= v%hi))
                    end if
                else
                    write (unit, "(a)") str(v%lo)//tab//str(v%hi)//tab//str(v%hi - v%lo)//tab &
                        //itoa(v%n)//tab//status_word(v%status)//tab//"separates"//tab &
                        //sequence_text(v%pairs)
                    n_intervals = n_intervals + 1
                end if
            end associate
        end do
        if (at_1%class /= intervals(size(intervals))%class) then
            write (unit, "(a)") str(1.0_qp)//tab//str(1.0_qp)//tab//str(0.0_qp)//tab// &
                itoa(at_1%n)//tab//status_word(at_1%status)//tab//"separates"//tab// &
                sequence_text(at_1%pairs)
            n_intervals = n_intervals + 1
        end if
        call close_tables([unit])
    end subroutine write_intervals

    !> A row of b1_intervals.tsv for the collapsed interval from a to b: no
    !> count, no sequence; `exact` says what the row does there.
    subroutine collapsed_row(a, b, exact)
        real(qp), intent(in) :: a, b
        character(len=*), intent(in) :: exact
        write (unit, "(a)") str(a)//tab//str(b)//tab//str(b - a)//tab//"-"//tab// &
            status_word(status_collapsed)//tab//trim(exact)//tab//"-"
    end subroutine collapsed_row

    !> Whether the run at e with the scene's tolerance collapses (own scene and run: thread-safe).
    logical function collapses(e)
        real(qp), intent(in) :: e
        type(scene_t) :: mine
        type(run_t) :: got
        mine = scene
        mine%e = e
        call simulate(mine, got)
        collapses = got%status == status_collapsed
    end function collapses

    !> classify as a function, for bisect_changes.
    function class_of(e) result(class)
        real(qp), intent(in) :: e
        integer(8) :: class
        call classify(e, class)
    end function class_of

    !> Run at e with the scene's tolerance; class = sequence fingerprint, or
    !> collapsed_class when the row collapsed.
    subroutine classify(e, class)
        real(qp), intent(in) :: e
        integer(8), intent(out) :: class
        call classify_with(e, scene, run, events, pairs, class)
    end subroutine classify

    !> The class of the run at e on a scene, run and log of the caller's;
    !> on_pairs is left with its collision sequence.
    subroutine classify_with(e, on_scene, on_run, on_events, on_pairs, class)
        real(qp), intent(in) :: e
        type(scene_t), intent(inout) :: on_scene
        type(run_t), intent(inout) :: on_run
        type(event_log_t), intent(inout) :: on_events
        integer, allocatable, intent(inout) :: on_pairs(:)
        integer(8), intent(out) :: class
        type(auto_t) :: auto
        on_scene%e = e
        if (auto_runs) then
            call simulate_auto(on_scene, on_run, auto, on_pairs, certify_qp=.false.)
        else
            call simulate(on_scene, on_run, on_events)
            call sequence_of(on_events, on_pairs)
        end if
        if (on_run%status == status_collapsed) then
            class = collapsed_class
        else
            class = sequence_hash(on_pairs)
        end if
    end subroutine classify_with

end program c12_b1
