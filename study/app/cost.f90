!> The cost of a collision against the length of the row: wall time per
!> collision of the engine in real(16) for rows of p equal spheres struck at
!> one end, p = 4 ... 10^6, found by scanning every gap (O(p) per collision)
!> and from the calendar of impacts (a heap, O(log p)); elastic rows (e = 1,
!> p - 1 collisions) and inelastic ones (e = 0.5, the first 4 (p - 1)
!> collisions, before any cycle watching starts, or fewer where the struck
!> row has merged into one block before: its collisions and limits, per
!> collision). The crossover is the
!> shortest row from which the calendar is faster.
!>
!> Then the price of the engine's bookkeeping: each precision of sphere-row
!> (the engine in real(16), in real(8) with real(8)'s epsilon as tol, and
!> precision auto) against the tight event loop of the
!> study (sphere_row_tight.inc: the same variables, rule and stop, a heap,
!> nothing else) in real(16), or real(8) for dp, on elastic rows p = 10^3 ...
!> 10^6, inelastic rows that end normally, a collapse-heavy row (p = 10^5,
!> e = 0.2, its first 10^6 collisions) and the collapse region late
!> (p = 100, e = 0.9, run to its answer, the loop as many collisions); runs
!> in turn, engine and loop, the median of the ratios of the rounds
!> (cost_vs_loop.tsv); and against the
!> same loop with the engine's two-real clock (loop2), which tells the price
!> of that clock's accuracy from the price of the rest.
program c12_cost
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, str, itoa, &
        status_normal, status_max_collisions, status_collapsed, auto_t, simulate_auto, real_str, &
        scene_dp_t, run_dp_t
    use sphere_row_tight_qp, only: tight_qp => tight_run
    use sphere_row_tight_dp, only: tight_dp => tight_run
    use sphere_row_tables, only: open_table, tab
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, fail, &
        stop_unless_normal, close_tables
    use sphere_row_sorting, only: median
    use sphere_row_kinds, only: dp
    implicit none
    !> The two ways of finding the next impact, as calendar_from values.
    integer, parameter :: scan = huge(1), calendar = 2
    character(len=*), parameter :: search_names(2) = ["scan    ", "calendar"]
    !> Rows: elastic (e = 1) and inelastic (e = 0.5, cut after 4 (p - 1)).
    real(qp), parameter :: row_e(2) = [1.0_qp, 0.5_qp]
    character(len=*), parameter :: row_names(2) = ["elastic  ", "inelastic"]
    !> Longest row of the comparison of elastic rows in one run, and the
    !> shorter one it is compared with.
    integer, parameter :: p_long = 32000, p_short = 2000
    !> The scenes of the comparison with the tight loop: p, e and the
    !> collision budget (0: none), their rounds, and whether the loop runs as
    !> many collisions as the engine took (else the budget's).
    type :: loop_scene_t
        character(len=13) :: name
        integer :: p
        real(qp) :: e
        integer :: budget, rounds
        logical :: as_engine = .false.
    end type loop_scene_t
    type(loop_scene_t), parameter :: loop_scenes(*) = [ &
        loop_scene_t("elastic", 1000, 1.0_qp, 0, 5), &
        loop_scene_t("elastic", 10000, 1.0_qp, 0, 5), &
        loop_scene_t("elastic", 100000, 1.0_qp, 0, 5), &
        loop_scene_t("elastic", 1000000, 1.0_qp, 0, 3), &
        loop_scene_t("inelastic", 200, 0.98_qp, 0, 5), &
        loop_scene_t("inelastic", 1000, 0.999_qp, 0, 3), &
        loop_scene_t("collapse", 100000, 0.2_qp, 1000000, 3), &
        loop_scene_t("collapse_late", 100, 0.9_qp, 40000000, 1, .true.)]
    character(len=*), parameter :: precisions(3) = ["qp  ", "dp  ", "auto"]
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    integer :: p_max, scan_max, inelastic_max, unit, stat, crossover(2)
    real(qp) :: min_seconds
    character(len=300) :: msg

    call start_program(cli, "c12-cost", &
        "Wall time per collision against the row length p (4 ... p_max, doubling), by scan"//nl// &
        "and by calendar, for elastic rows and inelastic rows (e = 0.5, first 4(p-1))."//nl// &
        "Writes OUT/cost.tsv and OUT/cost_summary.tsv (machine-dependent timings).")
    call cli%add_int("p_max", "1000000", "longest row (p = 4, 8, 16, ... and p_max)", lo=4, &
        hi=1000000)
    call cli%add_int("scan_max", "2048", "longest row timed with the scan", lo=4)
    call cli%add_int("inelastic_max", "65536", "longest inelastic row timed", lo=4)
    call cli%add_real("min_seconds", "0.02", "each point repeats runs for at least this long", &
        lo=0.0_qp)
    call cli%add_flag("loop", "yes", "the comparison with the tight loop (cost_vs_loop.tsv)")
    call read_keys(cli)
    out = cli%get_word("out")
    p_max = cli%get_int("p_max")
    scan_max = cli%get_int("scan_max")
    inelastic_max = cli%get_int("inelastic_max")
    min_seconds = cli%get_real("min_seconds")

    call open_table(out, "cost.tsv", "row"//tab//"search"//tab//"p"//tab//"collisions"//tab// &
        "runs"//tab//"seconds_per_run"//tab//"ns_per_collision", unit, stat, msg)
    call stop_unless_normal(stat, msg)
    call sweep(1, crossover(1))
    call sweep(2, crossover(2))
    call close_tables([unit])
    call write_summary()
    if (cli%get_flag("loop")) call against_loop()

contains

    !> Every scene of loop_scenes in every precision against the tight loop:
    !> one row each in cost_vs_loop.tsv.
    subroutine against_loop()
        integer :: u, i, j
        call open_table(out, "cost_vs_loop.tsv", "row"//tab//"p"//tab//"e"//tab// &
            "precision"//tab//"collisions"//tab//"loop_collisions"//tab//"rounds"//tab// &
            "engine_ns_per_collision"//tab//"loop_ns_per_collision"//tab//"ratio"//tab// &
            "loop2_ns_per_collision"//tab//"ratio_loop2", u, stat, msg)
        call stop_unless_normal(stat, msg)
        do i = 1, size(loop_scenes)
            do j = 1, size(precisions)
                call loop_row(u, loop_scenes(i), trim(precisions(j)))
            end do
        end do
        call close_tables([u])
    end subroutine against_loop

    !> One scene in one precision against its loop (real(8) for dp, else
    !> real(16)), engine and loop in turn, each repeated for min_seconds in a
    !> round; the medians of the rounds' ns per collision and of their ratios.
    subroutine loop_row(u, ls, precision)
        integer, intent(in) :: u
        type(loop_scene_t), intent(in) :: ls
        character(len=*), intent(in) :: precision
        type(scene_t) :: scene
        type(run_t) :: run
        type(scene_dp_t) :: scene_dp
        type(run_dp_t) :: run_dp
        type(auto_t) :: auto
        real(dp) :: engine_ns(ls%rounds), loop_ns(ls%rounds), loop2_ns(ls%rounds)
        integer :: status, n_engine
        real(qp) :: tol
        integer(int64) :: t0, t1, rate
        integer :: r, runs, st, n_loop, budget
        character(len=200) :: text
        call scene_init(scene, st, text, p=ls%p, e=ls%e)
        if (ls%budget > 0) scene%max_collisions = ls%budget
        budget = huge(1)
        if (ls%budget > 0) budget = ls%budget
        tol = scene%tol
        ! real(8) at its own epsilon as tol, as sphere-row precision=dp
        call scene_init(scene_dp, st, text, p=ls%p, e=real(ls%e, dp))
        scene_dp%max_collisions = scene%max_collisions
        if (precision == "dp") tol = real(scene_dp%tol, qp)
        do r = 1, ls%rounds
            runs = 0
            call system_clock(t0, rate)
            do
                select case (precision)
                case ("qp")
                    call simulate(scene, run)
                case ("dp")
                    call simulate(scene_dp, run_dp)
                case default
                    call simulate_auto(scene, run, auto)
                end select
                runs = runs + 1
                call system_clock(t1)
                if (real(t1 - t0, qp)/rate >= min_seconds) exit
            end do
            status = run%status
            n_engine = run%n
            if (precision == "dp") then
                status = run_dp%status
                n_engine = run_dp%n
            end if
            ! (the collapse-heavy row may end merged within its budget)
            if (status /= status_normal .and. status /= status_max_collisions .and. &
                status /= status_collapsed) then
                call fail(trim(ls%name)//" p = "//itoa(ls%p)//" "//precision// &
                    ": the run ended with status "//itoa(status))
            end if
            engine_ns(r) = real(1.0e9_qp*real(t1 - t0, qp)/rate/(real(runs, qp)*max(n_engine, 1)), &
                dp)
            if (ls%as_engine) budget = n_engine
            loop_ns(r) = loop_time(ls, precision == "dp", tol, budget, .false., n_loop)
            loop2_ns(r) = loop_time(ls, precision == "dp", tol, budget, .true., n_loop)
        end do
        write (u, "(a)") trim(ls%name)//tab//itoa(ls%p)//tab//real_str(ls%e, 3)//tab// &
            precision//tab//itoa(n_engine)//tab//itoa(n_loop)//tab//itoa(ls%rounds)//tab// &
            real_str(real(median(engine_ns), qp), 3)//tab//real_str(real(median(loop_ns), qp), 3) &
            //tab//real_str(real(median(engine_ns/loop_ns), qp), 3)//tab// &
            real_str(real(median(loop2_ns), qp), 3)//tab// &
            real_str(real(median(engine_ns/loop2_ns), qp), 3)
        flush (u)
    end subroutine loop_row

    !> ns per collision of the tight loop on scene ls, in real(8) (in_dp) or
    !> real(16), the clock in two reals or one, repeated for min_seconds;
    !> n_loop its collisions.
    real(dp) function loop_time(ls, in_dp, tol, budget, two_real, n_loop) result(ns)
        type(loop_scene_t), intent(in) :: ls
        logical, intent(in) :: in_dp, two_real
        real(qp), intent(in) :: tol
        integer, intent(in) :: budget
        integer, intent(out) :: n_loop
        real(qp) :: t_end, v_sum
        real(dp) :: t_end_dp, v_sum_dp
        integer(int64) :: t0, t1, rate
        integer :: runs
        runs = 0
        call system_clock(t0, rate)
        do
            if (in_dp) then
                call tight_dp(ls%p, real(ls%e, dp), 1.0_dp, real(tol, dp), budget, two_real, &
                    n_loop, t_end_dp, v_sum_dp)
            else
                call tight_qp(ls%p, ls%e, 1.0_qp, tol, budget, two_real, n_loop, t_end, v_sum)
            end if
            runs = runs + 1
            call system_clock(t1)
            if (real(t1 - t0, qp)/rate >= min_seconds) exit
        end do
        ns = real(1.0e9_qp*real(t1 - t0, qp)/rate/(real(runs, qp)*max(n_loop, 1)), dp)
    end function loop_time

    !> Time every p of one row kind, both ways; `cross` is the shortest p
    !> from which the calendar is faster than the scan at every longer p
    !> timed with both (0 if it never is).
    subroutine sweep(row, cross)
        integer, intent(in) :: row
        integer, intent(out) :: cross
        real(qp) :: ns_scan, ns_cal
        integer :: p, p_end
        cross = 0
        p = 4
        p_end = p_max
        if (row == 2) p_end = min(p_max, inelastic_max)
        do
            ns_cal = time_point(row, calendar, p)
            if (p <= scan_max) then
                ns_scan = time_point(row, scan, p)
                if (ns_cal < ns_scan) then
                    if (cross == 0) cross = p
                else
                    cross = 0
                end if
            end if
            if (p >= p_end) exit
            p = min(2*p, p_end)
        end do
    end subroutine sweep

    !> Time runs of one row, one search, p spheres: runs repeated until
    !> min_seconds have passed; one table row; returns ns per collision.
    function time_point(row, search, p) result(ns)
        integer, intent(in) :: row, search, p
        real(qp) :: ns
        type(scene_t) :: scene
        type(run_t) :: run
        integer(int64) :: t0, t1, rate
        integer :: runs, st
        real(qp) :: seconds
        character(len=200) :: text
        call scene_init(scene, st, text, p=p, e=row_e(row))
        if (row == 2) scene%max_collisions = 4*(p - 1)
        scene%calendar_from = search
        runs = 0
        call system_clock(t0, rate)
        do
            call simulate(scene, run)
            runs = runs + 1
            call system_clock(t1)
            seconds = real(t1 - t0, qp)/rate
            if (seconds >= min_seconds) exit
        end do
        ! (an inelastic row may merge into one block within its budget: its
        ! collisions and limits are the work timed)
        if (run%status /= status_normal .and. run%status /= status_max_collisions .and. &
            .not. (row == 2 .and. run%status == status_collapsed)) then
            call fail("p = "//itoa(p)//": the run ended with status "//itoa(run%status))
        end if
        ns = 1.0e9_qp*seconds/(real(runs, qp)*max(run%n, 1))
        write (unit, "(a)") trim(row_names(row))//tab//trim(search_names(merge(1, 2, &
            search == scan)))//tab//itoa(p)//tab//itoa(run%n)//tab//itoa(runs)//tab// &
            str(seconds/runs)//tab//str(ns)
    end function time_point

    !> Crossovers, and the growth of an elastic row's wall time from p_short
    !> to p_long spheres with the engine's own choice (median of 5 pairs).
    subroutine write_summary()
        integer :: u, i
        real(dp) :: ratios(5)
        do i = 1, size(ratios)
            ratios(i) = real(seconds_of(p_long)/seconds_of(p_short), dp)
        end do
        call open_table(out, "cost_summary.tsv", "quantity"//tab//"value"//tab//"note", u, &
            stat, msg)
        call stop_unless_normal(stat, msg)
        write (u, "(a)") "crossover.elastic"//tab//itoa(crossover(1))//tab// &
            "shortest p (of 4, 8, 16, ...) from which the calendar is faster, elastic rows"
        write (u, "(a)") "crossover.inelastic"//tab//itoa(crossover(2))//tab// &
            "the same, inelastic rows (e = 0.5, first 4(p-1) collisions)"
        write (u, "(a)") "elastic.time_ratio_"//itoa(p_long)//"_"//itoa(p_short)//tab// &
            str(real(median(ratios), qp))//tab//"wall time of one elastic row of "//itoa(p_long)// &
            " spheres over one of "//itoa(p_short)//", engine's choice, median of 5 pairs"
        call close_tables([u])
    end subroutine write_summary

    !> Wall time of one elastic row of p spheres with the engine's choice.
    function seconds_of(p) result(seconds)
        integer, intent(in) :: p
        real(qp) :: seconds
        type(scene_t) :: scene
        type(run_t) :: run
        integer(int64) :: t0, t1, rate
        integer :: st
        character(len=200) :: text
        call scene_init(scene, st, text, p=p, e=1.0_qp)
        call system_clock(t0, rate)
        call simulate(scene, run)
        call system_clock(t1)
        seconds = real(t1 - t0, qp)/rate
        if (run%n /= p - 1) then
            call fail("p = "//itoa(p)//": an elastic row took "//itoa(run%n)// &
                " collisions, not p - 1")
        end if
    end function seconds_of

end program c12_cost
