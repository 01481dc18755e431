!> Speed of the engine per precision kind and of the study, into bench.tsv.
!>
!> Timing is measured here, never asserted in tests: wall-clock numbers of
!> one machine, written with a description of that machine. `parts` names
!> the parts measured anew; the others' rows are kept from OUT/bench.tsv as
!> they were (a part's timings stand with the machine and the day they were
!> taken on; the parts loop and whole name their machine in rows of their own).
program c12_bench
    use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options, &
        int64
    use sphere_row, only: qp, dp, scene_t, scene_init, status_normal, itoa, real_str
    use sphere_row_kind_engines, only: built_kinds, kind_info_t, kind_engine_t, new_kind_engine
    use sphere_row_tables, only: open_table, tab, split_tabs, cpu_model
    use sphere_row_monte_carlo, only: mc_counts_t, monte_carlo_v4
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, fail, &
        stop_unless_normal, close_tables
    use sphere_row_sorting, only: median
    implicit none
    character(len=*), parameter :: tasks(7) = [character(len=7) :: "a1", "a2", "b1", &
        "b2", "c1", "c2", "methods"]
    type(cli_t) :: cli
    character(len=:), allocatable :: out, bin
    !> Pairs of runs of the side-by-side timings.
    integer, parameter :: pairs = 5
    character(len=4000) :: arg0
    character(len=300) :: msg
    !> ns per collision of the engine on the elastic row of 10^6 spheres in
    !> real(16), from cost_vs_loop.tsv (0: not there).
    real(qp) :: engine_ns_p1e6
    real :: min_seconds
    integer :: stat, unit
    !> The parts of the table, in its order, and those measured anew.
    character(len=*), parameter :: part_names(9) = [character(len=12) :: "kinds", &
        "monte_carlo", "side_by_side", "callgrind", "methods", "loop", "whole", "study", "ring"]
    logical :: measure(size(part_names))
    !> The rows of the previous OUT/bench.tsv (kept for the parts not measured).
    character(len=4000), allocatable :: previous(:)

    call start_program(cli, "c12-bench", &
        "Times the engine in each precision kind (ns per collision) and collects"//nl// &
        "the wall time of each study program from OUT/timing/; writes OUT/bench.tsv.")
    call cli%add_real("min_seconds", "0.1", "seconds of repeated runs per timing", &
        lo=0.0_qp, hi=100.0_qp, lo_open=.true., hi_open=.true.)
    call cli%add_word("parts", "all", "the parts measured anew, comma-separated (kinds, " &
        //"monte_carlo, side_by_side, callgrind, methods, loop, whole, study, ring), or all; the " &
        //"others' rows kept from OUT/bench.tsv")
    call read_keys(cli)
    out = cli%get_word("out")
    call choose_parts(cli%get_word("parts"))
    ! the runs' own outputs and records, whichever parts are measured
    call execute_command_line("mkdir -p build/bench-runs")
    ! the study's programs are installed next to this one
    call get_command_argument(0, arg0)
    bin = "."
    if (index(arg0, "/", back=.true.) > 0) bin = arg0(:index(arg0, "/", back=.true.) - 1)
    min_seconds = real(cli%get_real("min_seconds"))

    call open_table(out, "bench.tsv", "quantity"//tab//"value"//tab//"unit"//tab//"note", &
        unit, stat, msg)
    call stop_unless_normal(stat, msg)
    if (measure(1)) then
        call machine_and_kinds()
    else
        call keep(1)
    end if
    if (measure(2)) then
        call time_monte_carlo()
    else
        call keep(2)
    end if
    if (measure(3)) then
        call side_by_side()
    else
        call keep(3)
    end if
    if (measure(4)) then
        call callgrind_counts()
    else
        call keep(4)
    end if
    if (measure(5)) then
        call method_costs()
    else
        call keep(5)
    end if
    call loop_costs(engine_ns_p1e6, measure(6))
    if (.not. measure(6)) call keep(6)
    if (measure(7)) then
        call whole_process(engine_ns_p1e6)
    else
        call keep(7)
    end if
    if (measure(8)) then
        call study_total()
    else
        call keep(8)
    end if
    if (measure(9)) then
        call ring_costs()
    else
        call keep(9)
    end if
    call close_tables([unit])

contains

    !> The parts named in `words` (all, or a comma-separated list of
    !> part_names) are measured; with any left out, the previous table's rows
    !> are read to keep theirs.
    subroutine choose_parts(words)
        character(len=*), intent(in) :: words
        character(len=4000) :: line
        integer :: first, last, k, u, ios, n
        measure = words == "all"
        if (words == "all") return
        first = 1
        do while (first <= len(words))
            last = index(words(first:), ",") + first - 2
            if (last < first) last = len(words)
            k = findloc(part_names, words(first:last), 1)
            if (k == 0) call fail("c12-bench: parts = "//words//": '"//words(first:last)// &
                "' is not a part; allowed all or parts among kinds, monte_carlo, " &
                //"side_by_side, callgrind, methods, loop, whole, study, ring")
            measure(k) = .true.
            first = last + 2
        end do
        open (newunit=u, file=out//"/bench.tsv", status="old", action="read", iostat=ios)
        if (ios /= 0) call fail("c12-bench: parts = "//words//": "//out//"/bench.tsv, whose " &
            //"other parts it keeps, cannot be read; allowed parts = all")
        allocate (previous(0))
        n = 0
        do
            read (u, "(a)", iostat=ios) line
            if (ios /= 0) exit
            n = n + 1
            if (n > 1) previous = [previous, line]
        end do
        close (u)
    end subroutine choose_parts

    !> The previous table's rows of part k, as they were.
    subroutine keep(k)
        integer, intent(in) :: k
        integer :: i
        do i = 1, size(previous)
            if (part_of(previous(i)) == k) write (unit, "(a)") trim(previous(i))
        end do
    end subroutine keep

    !> The part a row of the table belongs to, by its quantity's prefix.
    pure integer function part_of(row)
        character(len=*), intent(in) :: row
        part_of = 0
        if (starts(row, "machine.") .or. starts(row, "engine.")) then
            part_of = 1
        else if (starts(row, "c2.monte_carlo")) then
            part_of = 2
        else if (starts(row, "c2.") .or. starts(row, "openmp.")) then
            part_of = 3
        else if (starts(row, "callgrind.")) then
            part_of = 4
        else if (starts(row, "methods.")) then
            part_of = 5
        else if (starts(row, "loop.")) then
            part_of = 6
        else if (starts(row, "whole.")) then
            part_of = 7
        else if (starts(row, "study.")) then
            part_of = 8
        else if (starts(row, "ring.")) then
            part_of = 9
        end if
    end function part_of

    !> `text` begins with `prefix`.
    pure logical function starts(text, prefix)
        character(len=*), intent(in) :: text, prefix
        starts = .false.
        if (len(text) >= len(prefix)) starts = text(:len(prefix)) == prefix
    end function starts

    !> The machine, and the definition's scene in every kind built at three e.
    subroutine machine_and_kinds()
        real(qp), parameter :: e_values(3) = [0.2_qp, 0.5_qp, 0.18_qp]
        integer :: i, k
        write (unit, "(a)") "machine.cpu"//tab//cpu_model()//tab//"-"//tab//"/proc/cpuinfo"
        write (unit, "(a)") "machine.compiler"//tab//compiler_version()//tab//"-"//tab//"-"
        write (unit, "(a)") "machine.flags"//tab//compiler_options()//tab//"-"//tab//"-"
        do k = 1, size(e_values)
            do i = size(built_kinds), 1, -1
                call time_kind(built_kinds(i), e_values(k))
            end do
        end do
    end subroutine machine_and_kinds

    !> The study programs' wall times of one make study, summed.
    subroutine study_total()
        real(qp) :: seconds
        integer :: i
        seconds = 0
        do i = 1, size(tasks)
            call study_time("c12-"//trim(tasks(i)), seconds)
        end do
        write (unit, "(a, f0.3, a)") "study.total_seconds"//tab, seconds, tab//"s"//tab// &
            "wall time of the study programs (six tasks and the methods) of one make study, "// &
            "one after the other"
    end subroutine study_total

    !> Open a table of study results on unit u and find its columns `names`
    !> (c(j) the column of names(j)); not ok (and closed) if the table or a
    !> column is missing.
    subroutine open_columns(path, names, u, c, ok)
        character(len=*), intent(in) :: path, names(:)
        integer, intent(out) :: u, c(size(names))
        logical, intent(out) :: ok
        character(len=4000) :: line
        character(len=:), allocatable :: head(:)
        integer :: ios, j
        c = 0
        open (newunit=u, file=path, status="old", action="read", iostat=ios)
        ok = ios == 0
        if (.not. ok) return
        read (u, "(a)", iostat=ios) line
        if (ios == 0) then
            call split_tabs(trim(line), head)
            do j = 1, size(head)
                where (names == head(j)) c = j
            end do
        end if
        ok = minval(c) > 0
        if (.not. ok) close (u)
    end subroutine open_columns

    !> Nanoseconds per collision of the definition's scene at e in one kind,
    !> over at least min_seconds of repeated runs (one core).
    subroutine time_kind(info, e)
        type(kind_info_t), intent(in) :: info
        real(qp), intent(in) :: e
        !> Runs between two looks at the clock.
        integer(int64), parameter :: runs_per_look = 1000
        class(kind_engine_t), allocatable :: engine
        type(scene_t) :: scene
        integer(int64) :: c0, c1, rate, collisions, runs
        real :: elapsed
        character(len=32) :: buf
        character(len=:), allocatable :: key
        call scene_init(scene, stat, msg, e=e)
        call new_kind_engine(info%precision, engine)
        call engine%prepare(scene, -1.0_qp, stat, msg)
        collisions = 0
        runs = 0
        call system_clock(c0, rate)
        do
            collisions = collisions + engine%count_collisions()
            runs = runs + 1
            if (mod(runs, runs_per_look) /= 0) cycle
            call system_clock(c1)
            elapsed = real(c1 - c0)/real(rate)
            if (elapsed >= min_seconds) exit
        end do
        write (buf, "(f4.2)") e
        key = "engine."//trim(info%storage)
        write (unit, "(a, f0.1, a)") key//".ns_per_collision.e"//trim(buf) &
            //tab, 1.0e9*elapsed/real(collisions), tab//"ns"//tab//itoa(int(collisions/runs)) &
            //" collisions per run, "//itoa(int(runs))//" runs"
        write (unit, "(a, es10.3, a)") key//".collisions_per_second.e" &
            //trim(buf)//tab, real(collisions)/elapsed, tab//"1/s"//tab//"-"
    end subroutine time_kind

    !> Wall time of the c2 Monte Carlo loop alone: 10^6 runs of the
    !> definition's scene with e ~ N(0.5, 0.05) on the lean path, in real(16)
    !> and with precision auto (as many threads as OpenMP gives).
    subroutine time_monte_carlo()
        type(scene_t) :: scene
        type(mc_counts_t) :: counts
        real(dp), allocatable :: v4(:), e(:)
        integer(int64) :: c0, c1, rate
        call scene_init(scene, stat, msg)
        allocate (v4(1000000), e(1000000))
        call system_clock(c0, rate)
        call monte_carlo_v4(scene, 0.5_qp, 0.05_qp, 12, 1, v4, e, counts, stat, msg)
        call system_clock(c1)
        write (unit, "(a, f0.3, a)") "c2.monte_carlo_seconds_1e6"//tab, &
            real(c1 - c0)/real(rate), tab//"s"//tab//"10^6 samples in real(16), lean path, " &
            //"the threads OpenMP gives (OMP_NUM_THREADS)"
        call system_clock(c0, rate)
        call monte_carlo_v4(scene, 0.5_qp, 0.05_qp, 12, 1, v4, e, counts, stat, msg, auto=.true.)
        call system_clock(c1)
        write (unit, "(a, f0.3, a)") "c2.monte_carlo_seconds_1e6_auto"//tab, &
            real(c1 - c0)/real(rate), tab//"s"//tab//"the same samples with precision auto " &
            //"(real(8) certified, "//itoa(int(counts%escalated))//" escalated to real(16))"
    end subroutine time_monte_carlo

    !> The cost of each method of c12-methods on the same scenes, copied from
    !> its table so that bench.tsv holds every speed figure of the study.
    subroutine method_costs()
        character(len=4000) :: line
        character(len=:), allocatable :: f(:)
        integer :: u, ios, c(4)
        logical :: ok
        call open_columns(out//"/timing/methods_costs.tsv", [character(len=20) :: "e[1]", &
            "label", "ns_per_run[ns]", "ns_per_collision[ns]"], u, c, ok)
        if (.not. ok) return
        do
            read (u, "(a)", iostat=ios) line
            if (ios /= 0) exit
            call split_tabs(trim(line), f)
            if (size(f) < maxval(c)) cycle
            write (unit, "(a)") "methods."//trim(f(c(2)))//".ns_per_run"//tab// &
                trim(f(c(3)))//tab//"ns"//tab//"e = "//trim(f(c(1)))// &
                ", from timing/methods_costs.tsv"
            write (unit, "(a)") "methods."//trim(f(c(2)))//".ns_per_collision"//tab// &
                trim(f(c(4)))//tab//"ns"//tab//"e = "//trim(f(c(1)))// &
                ", from timing/methods_costs.tsv"
        end do
        close (u)
    end subroutine method_costs

    !> Wall seconds of a command run by the shell (its output discarded).
    function wall_seconds(command) result(seconds)
        character(len=*), intent(in) :: command
        real(qp) :: seconds
        integer(int64) :: c0, c1, rate
        integer :: exitstat, cmdstat
        call system_clock(c0, rate)
        call execute_command_line(command//" > /dev/null 2>&1", exitstat=exitstat, &
            cmdstat=cmdstat)
        call system_clock(c1)
        if (cmdstat /= 0 .or. exitstat /= 0) call fail("bench: the command '"//command &
            //"' failed")
        seconds = real(c1 - c0, qp)/real(rate, qp)
    end function wall_seconds

    !> Two commands timed in turn, A B A B ..., `pairs` times; the medians of
    !> A, of B and of the ratios A/B pair by pair (pairing keeps the ratio
    !> meaningful when the machine's speed drifts).
    subroutine in_turn(command_a, command_b, median_a, median_b, median_ratio)
        character(len=*), intent(in) :: command_a, command_b
        real(qp), intent(out) :: median_a, median_b, median_ratio
        real(dp) :: a(pairs), b(pairs)
        integer :: j
        do j = 1, pairs
            a(j) = real(wall_seconds(command_a), dp)
            b(j) = real(wall_seconds(command_b), dp)
        end do
        median_a = median(a)
        median_b = median(b)
        median_ratio = median(a/b)
    end subroutine in_turn

    !> `command` on one thread, on two, and as two one-thread copies at once, in
    !> rounds (4 `pairs` under 0.5 s, 2 under 1.5 s, else `pairs`): medians of the
    !> times and of the ratios 1/2 threads and 2 (1 thread)/(both copies); `fastest`:
    !> the two ratios of the rounds' fastest times.
    subroutine one_against_two(command, runs, t_one, t_two, speedup, ceiling, fastest, rounds)
        character(len=*), intent(in) :: command, runs
        real(qp), intent(out) :: t_one, t_two, speedup, ceiling, fastest(2)
        integer, intent(out) :: rounds
        real(dp) :: a(4*pairs), b(4*pairs), c(4*pairs)
        character(len=:), allocatable :: one
        integer :: j
        one = "OMP_NUM_THREADS=1 "//command
        rounds = 4*pairs
        do j = 1, 4*pairs
            a(j) = real(wall_seconds(one//" out="//runs), dp)
            b(j) = real(wall_seconds("OMP_NUM_THREADS=2 "//command//" out="//runs), dp)
            ! the first copy's status through `wait $p`, the second's through &&
            c(j) = real(wall_seconds("("//one//" out="//runs//"/a & p=$!; "//one//" out=" &
                //runs//"/b && wait $p)"), dp)
            if (j == 1 .and. a(1) >= 0.5_dp) rounds = 2*pairs
            if (j == 1 .and. a(1) >= 1.5_dp) rounds = pairs
            if (j == rounds) exit
        end do
        t_one = median(a(:rounds))
        t_two = median(b(:rounds))
        speedup = median(a(:rounds)/b(:rounds))
        ceiling = median(2*a(:rounds)/c(:rounds))
        fastest = [real(minval(a(:rounds))/minval(b(:rounds)), qp), &
            real(2*minval(a(:rounds))/minval(c(:rounds)), qp)]
    end subroutine one_against_two

    !> c12-c2 with its defaults (precision auto) and with precision=qp, each
    !> on one thread against the minimal real(16) loop of the same job
    !> (c12-minimal-loop), side by side; the runs c2 escalated; and c2 and the
    !> sweeps (b1's scan, b2's grid, the stability map) on one thread against
    !> two.
    subroutine side_by_side()
        character(len=:), allocatable :: runs, one
        real(qp) :: ta, tb, ratio, ceiling, fastest(2)
        integer :: k, rounds
        !> What runs on one thread against two: c2 and the sweeps (each the
        !> whole process; the sweep alone where a program does more).
        type :: sweep_t
            character(len=40) :: key, command
            character(len=120) :: note
        end type sweep_t
        type(sweep_t), parameter :: sweeps(*) = [ &
            sweep_t("c12-c2", "c12-c2", "its defaults, 10^6 runs"), &
            sweep_t("c12-c2.nmax_1e7", "c12-c2 nmax=10000000", "as make study runs it"), &
            sweep_t("c12-b1", "c12-b1", "the whole task: scan, bisections of its changes, " &
            //"and the search for e_crit (a chain of runs; the next steps' run ahead)"), &
            sweep_t("c12-b1.sweep", "c12-b1 critical=no", "the scan of e and the bisections " &
            //"of its changes"), &
            sweep_t("c12-b2", "c12-b2 n_grid=20001", "the grid of e, 20 times denser than " &
            //"the task's"), &
            sweep_t("c12-methods.stability_map", "c12-methods work_precision=no", "the " &
            //"stability map (the timed tables run one thing at a time by design)")]
        runs = "build/bench-runs"
        one = "OMP_NUM_THREADS=1 "
        call in_turn(one//bin//"/c12-c2 out="//runs, one//bin//"/c12-minimal-loop", ta, tb, &
            ratio)
        write (unit, "(a)") "c2.seconds_one_thread"//tab//real_str(ta, 4)//tab//"s"//tab// &
            "c12-c2 with its defaults (10^6 runs, lean path, precision auto), " &
            //"OMP_NUM_THREADS=1, median of "//itoa(pairs)
        write (unit, "(a)") "c2.minimal_loop_seconds"//tab//real_str(tb, 4)//tab//"s"//tab// &
            "c12-minimal-loop (the same 10^6 runs, minimal real(16) loop), in turn with c12-c2"
        write (unit, "(a)") "c2.ratio_to_minimal_loop"//tab//real_str(ratio, 4)//tab//"1"// &
            tab//"median of c12-c2 (precision auto) / c12-minimal-loop, pair by pair; target " &
            //"at most 0.35"
        call copy_answer(runs//"/c2_answers.tsv", "c2.escalated", "runs of c12-c2's 10^6 " &
            //"escalated from real(8) to real(16) (a decision too close to call), from its " &
            //"c2_answers.tsv")
        call in_turn(one//bin//"/c12-c2 precision=qp out="//runs, one//bin//"/c12-minimal-loop", &
            ta, tb, ratio)
        write (unit, "(a)") "c2.qp.seconds_one_thread"//tab//real_str(ta, 4)//tab//"s"//tab// &
            "c12-c2 precision=qp (every run in real(16)), OMP_NUM_THREADS=1, median of " &
            //itoa(pairs)//"; c12-minimal-loop in turn with it: "//real_str(tb, 4)//" s"
        write (unit, "(a)") "c2.qp.ratio_to_minimal_loop"//tab//real_str(ratio, 4)//tab//"1"// &
            tab//"median of c12-c2 precision=qp / c12-minimal-loop, pair by pair; target at " &
            //"most 1.2"
        do k = 1, size(sweeps)
            call one_against_two(bin//"/"//trim(sweeps(k)%command), runs, ta, tb, ratio, &
                ceiling, fastest, rounds)
            write (unit, "(a)") "openmp."//trim(sweeps(k)%key)//".speedup_two_threads"//tab// &
                real_str(ratio, 3)//tab//"1"//tab//"median of wall(1 thread)/wall(2 threads)" &
                //" round by round of `"//trim(sweeps(k)%command)//"`, "//real_str(ta, 3)// &
                " s and "//real_str(tb, 3)//" s, "//itoa(rounds)//" rounds; "//itoa(cores()) &
                //" processors online; "//trim(sweeps(k)%note)
            write (unit, "(a)") "openmp."//trim(sweeps(k)%key)//".two_copies_speedup"//tab// &
                real_str(ceiling, 3)//tab//"1"//tab//"median of 2 wall(1 thread)/wall(two " &
                //"one-thread copies started at once, sharing nothing), in the same rounds: " &
                //"what the second processor gives at that moment, the ceiling of the row above"
            write (unit, "(a)") "openmp."//trim(sweeps(k)%key)//".speedup_two_threads_fastest" &
                //tab//real_str(fastest(1), 3)//tab//"1"//tab//"fastest wall on one thread / " &
                //"fastest on two, over the same rounds: the estimate for two idle cores (other " &
                //"work on the machine only slows a run down); the two copies' ceiling so: " &
                //real_str(fastest(2), 3)
        end do
    end subroutine side_by_side

    !> The engine against the study's tight loop per collision, copied from
    !> c12-cost's cost_vs_loop.tsv (paired runs there, medians of rounds):
    !> the ratio to the loop with its clock in one real, the issue's yardstick,
    !> and to the same loop with the engine's two-real clock.
    subroutine loop_costs(engine_ns_p1e6, rows)
        real(qp), intent(out) :: engine_ns_p1e6
        !> Write the rows (else only read the engine's price at p = 10^6).
        logical, intent(in) :: rows
        character(len=4000) :: line
        character(len=:), allocatable :: f(:), key
        integer :: u, ios, c(8)
        logical :: ok
        engine_ns_p1e6 = 0
        call open_columns(out//"/cost_vs_loop.tsv", [character(len=23) :: "row", "p", "e", &
            "precision", "engine_ns_per_collision", "loop_ns_per_collision", "ratio", &
            "ratio_loop2"], u, c, ok)
        if (.not. ok) return
        if (rows) write (unit, "(a)") "loop.machine"//tab//cpu_model()//tab//"-"//tab// &
            "the processor of the rows below (cost_vs_loop.tsv made on it), /proc/cpuinfo"
        do
            read (u, "(a)", iostat=ios) line
            if (ios /= 0) exit
            call split_tabs(trim(line), f)
            if (size(f) < maxval(c)) cycle
            key = "loop."//trim(f(c(1)))//".p"//trim(f(c(2)))//"."//trim(f(c(4)))
            if (key == "loop.elastic.p1000000.qp") read (f(c(5)), *, iostat=ios) engine_ns_p1e6
            if (.not. rows) cycle
            write (unit, "(a)") key//".ratio"//tab//trim(f(c(7)))//tab//"1"//tab// &
                "ns per collision of the engine ("//trim(f(c(5)))//") over the tight loop's (" &
                //trim(f(c(6)))//"), e = "//trim(f(c(3)))//", median of paired rounds, from " &
                //"cost_vs_loop.tsv"
            write (unit, "(a)") key//".ratio_loop2"//tab//trim(f(c(8)))//tab//"1"//tab// &
                "the same over the loop with the engine's two-real clock"
        end do
        close (u)
    end subroutine loop_costs

    !> sphere-row p = 10^6, e = 1 as a whole process (its answer written to
    !> /dev/null) against the tight real(16) loop's process on the same row,
    !> in turn; and what is not the run in that process (reading the scene,
    !> setting up, the answer's 3 10^6 numbers written): its time less the
    !> engine's 999,999 collisions at their price in cost_vs_loop.tsv.
    subroutine whole_process(engine_ns_p1e6)
        real(qp), intent(in) :: engine_ns_p1e6
        real(qp) :: ta, tb, ratio
        call in_turn(bin//"/sphere-row p=1000000 e=1", bin//"/c12-tight-loop p=1000000 e=1", &
            ta, tb, ratio)
        write (unit, "(a)") "whole.machine"//tab//cpu_model()//tab//"-"//tab// &
            "the processor of the rows below, /proc/cpuinfo"
        write (unit, "(a)") "whole.p1e6_e1.seconds"//tab//real_str(ta, 3)//tab//"s"//tab// &
            "sphere-row p=1000000 e=1 (qp), the whole process, its 3 10^6 numbers to /dev/null," &
            //" median of "//itoa(pairs)
        write (unit, "(a)") "whole.p1e6_e1.loop_seconds"//tab//real_str(tb, 3)//tab//"s"//tab// &
            "c12-tight-loop p=1000000 e=1 (real(16), one-real clock, no output), in turn with it"
        write (unit, "(a)") "whole.p1e6_e1.ratio"//tab//real_str(ratio, 3)//tab//"1"//tab// &
            "median of the pairs' ratios; target at most 3.5"
        call peaks_of("sphere-row p=1000000 e=1", "c12-tight-loop p=1000000 e=1")
        if (engine_ns_p1e6 > 0) write (unit, "(a)") "whole.p1e6_e1.not_the_run_seconds"//tab &
            //real_str(ta - 999999*engine_ns_p1e6*1.0e-9_qp, 3)//tab//"s"//tab//"the process " &
            //"above less its run (999,999 collisions at the engine's "//real_str(engine_ns_p1e6, &
            3)//" ns in cost_vs_loop.tsv): reading, setting up, writing 3 10^6 numbers with " &
            //"every digit; target for the output at most 0.5"
    end subroutine whole_process

    !> The cooling ring of 10^5 rods at e = 0.99, n d = 0.1, T0 = 1 (the gas of
    !> sphere-row gas=ring, seed 1) to t0 and to 10 t0 (t0 = 801.6 for these,
    !> Haff's time: docs/scenes.md), as whole processes in turn: sphere-row in
    !> precision dp against the tight real(8) ring loop, and in qp against the
    !> real(16) loop, on the same gas to the same time (they take the same
    !> collisions, 3,540,316 to t0): medians of the times and of the ratios,
    !> which are the ratios per collision. Targets: dp at most 2, qp at most
    !> 2.2.
    subroutine ring_costs()
        character(len=*), parameter :: gas = " p=100000 e=0.99 density=0.1", &
            times(2) = [character(len=12) :: "801.6", "8016"], names(2) = &
            [character(len=3) :: "t0", "t10"]
        character(len=*), parameter :: kinds(2) = ["dp", "qp"]
        real(qp), parameter :: targets(2) = [2.0_qp, 2.2_qp]
        real(qp) :: ta, tb, ratio
        integer :: i, j
        write (unit, "(a)") "ring.machine"//tab//cpu_model()//tab//"-"//tab// &
            "the processor of the rows below, /proc/cpuinfo"
        do j = 1, size(kinds)
            do i = 1, size(times)
                call in_turn(bin//"/sphere-row gas=ring"//gas//" t_max="//trim(times(i))// &
                    " precision="//kinds(j), bin//"/c12-ring-loop"//gas//" t_max="// &
                    trim(times(i))//" kind="//kinds(j), ta, tb, ratio)
                write (unit, "(a)") "ring."//trim(names(i))//"."//kinds(j)//".seconds"//tab// &
                    real_str(ta, 3)//tab//"s"//tab//"sphere-row gas=ring"//gas//" t_max=" &
                    //trim(times(i))//" precision="//kinds(j)//", the whole process, median of " &
                    //itoa(pairs)
                write (unit, "(a)") "ring."//trim(names(i))//"."//kinds(j)//".loop_seconds"// &
                    tab//real_str(tb, 3)//tab//"s"//tab//"c12-ring-loop"//gas//" t_max=" &
                    //trim(times(i))//" kind="//kinds(j)//", in turn with it"
                write (unit, "(a)") "ring."//trim(names(i))//"."//kinds(j)//".ratio"//tab// &
                    real_str(ratio, 3)//tab//"1"//tab//"median of the pairs' ratios; target " &
                    //"at most "//real_str(targets(j), 2)
            end do
        end do
    end subroutine ring_costs

    !> The peak memory (the largest resident set) of `command` and of the
    !> loop's `loop_command`, each run once more, as GNU time reports it
    !> (/usr/bin/time -f %M); no rows where it is not installed.
    subroutine peaks_of(command, loop_command)
        character(len=*), intent(in) :: command, loop_command
        real(qp) :: engine_mib, loop_mib
        engine_mib = peak_mib(bin//"/"//command)
        loop_mib = peak_mib(bin//"/"//loop_command)
        if (engine_mib <= 0 .or. loop_mib <= 0) return
        write (unit, "(a)") "whole.p1e6_e1.peak_mib"//tab//real_str(engine_mib, 4)//tab//"MiB" &
            //tab//command//", the largest resident set (/usr/bin/time -f %M)"
        write (unit, "(a)") "whole.p1e6_e1.loop_peak_mib"//tab//real_str(loop_mib, 4)//tab// &
            "MiB"//tab//loop_command//", the same"
        write (unit, "(a)") "whole.p1e6_e1.peak_ratio"//tab//real_str(engine_mib/loop_mib, 3)// &
            tab//"1"//tab//"the two peaks' ratio; target at most 2.5"
    end subroutine peaks_of

    !> The largest resident set of a command in MiB, 0 if it cannot be told.
    function peak_mib(command) result(mib)
        character(len=*), intent(in) :: command
        real(qp) :: mib
        character(len=*), parameter :: record = "build/bench-runs/peak"
        integer :: u, ios, exitstat, cmdstat
        integer(int64) :: kib
        mib = 0
        call execute_command_line("/usr/bin/time -f %M -o "//record//" "//command// &
            " > /dev/null 2>&1", exitstat=exitstat, cmdstat=cmdstat)
        if (cmdstat /= 0 .or. exitstat /= 0) return
        open (newunit=u, file=record, status="old", action="read", iostat=ios)
        if (ios /= 0) return
        read (u, *, iostat=ios) kib
        close (u)
        if (ios == 0) mib = real(kib, qp)/1024
    end function peak_mib

    !> The value of row `key` of an answer table, copied as a row of
    !> bench.tsv with the note `note` (nothing if the table has no such row).
    subroutine copy_answer(table, key, note)
        character(len=*), intent(in) :: table, key, note
        character(len=4000) :: line
        character(len=:), allocatable :: f(:)
        integer :: u, ios
        open (newunit=u, file=table, status="old", action="read", iostat=ios)
        if (ios /= 0) return
        do
            read (u, "(a)", iostat=ios) line
            if (ios /= 0) exit
            call split_tabs(trim(line), f)
            if (size(f) < 2) cycle
            if (f(1) /= key) cycle
            write (unit, "(a)") key//tab//trim(f(2))//tab//"1"//tab//note
            exit
        end do
        close (u)
    end subroutine copy_answer

    !> The last counts of `make callgrind` (callgrind.tsv), copied.
    subroutine callgrind_counts()
        character(len=4000) :: line
        integer :: u, ios
        open (newunit=u, file=out//"/callgrind.tsv", status="old", action="read", iostat=ios)
        if (ios /= 0) return
        read (u, "(a)", iostat=ios) line
        do
            read (u, "(a)", iostat=ios) line
            if (ios /= 0) exit
            write (unit, "(a)") "callgrind."//trim(line)
        end do
        close (u)
    end subroutine callgrind_counts

    !> Processors online (getconf), 0 if unknown.
    integer function cores()
        integer :: u, ios
        cores = 0
        call execute_command_line("getconf _NPROCESSORS_ONLN > build/bench-runs/cores 2>&1")
        open (newunit=u, file="build/bench-runs/cores", status="old", action="read", iostat=ios)
        if (ios /= 0) return
        read (u, *, iostat=ios) cores
        if (ios /= 0) cores = 0
        close (u)
    end function cores

    !> Wall time of one study program as recorded by the Makefile.
    subroutine study_time(program, total)
        character(len=*), intent(in) :: program
        real(qp), intent(inout) :: total
        character(len=200) :: line
        character(len=:), allocatable :: f(:)
        real(qp) :: t
        integer :: u, ios
        open (newunit=u, file=out//"/timing/"//program//".tsv", status="old", action="read", &
            iostat=ios)
        if (ios /= 0) return
        read (u, "(a)", iostat=ios) line
        close (u)
        if (ios /= 0) return
        call split_tabs(line, f)
        if (size(f) < 2) return
        read (f(2), *, iostat=ios) t
        if (ios /= 0) return
        total = total + t
        write (unit, "(a)") "study."//program//".seconds"//tab//trim(f(2))//tab//"s"//tab// &
            "wall time of its last run by make"
    end subroutine study_time


end program c12_bench
