!> The cost of a collision against the length of the row: wall time per
!> collision of the engine in real(16) for rows of p equal spheres struck at
!> one end, p = 4 ... 10^6, found by scanning every gap (O(p) per collision)
!> and from the calendar of impacts (a heap, O(log p)); elastic rows (e = 1,
!> p - 1 collisions) and inelastic ones (e = 0.5, the first 4 (p - 1)
!> collisions, before any cycle watching starts). The crossover is the
!> shortest row from which the calendar is faster.
program c12_cost
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, str, itoa, &
        status_normal, status_max_collisions
    use sphere_row_tables, only: open_table, close_table, tab
    use sphere_row_study_cli, only: cli_t, start_program, read_keys, fail, stop_unless_normal, &
        stop_unless_written
    use sphere_row_sorting, only: median
    use sphere_row_kinds, only: dp
    implicit none
    character(len=*), parameter :: nl = new_line("a")
    !> The two ways of finding the next impact, as calendar_from values.
    integer, parameter :: scan = huge(1), calendar = 2
    character(len=*), parameter :: search_names(2) = ["scan    ", "calendar"]
    !> Rows: elastic (e = 1) and inelastic (e = 0.5, cut after 4 (p - 1)).
    real(qp), parameter :: row_e(2) = [1.0_qp, 0.5_qp]
    character(len=*), parameter :: row_names(2) = ["elastic  ", "inelastic"]
    !> Longest row of the comparison of elastic rows in one run, and the
    !> shorter one it is compared with.
    integer, parameter :: p_long = 32000, p_short = 2000
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
    call close_table(unit, stat, msg)
    call stop_unless_written(stat, msg)
    call write_summary()

contains

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
        if (run%status /= status_normal .and. run%status /= status_max_collisions) then
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
        call close_table(u, stat, msg)
        call stop_unless_written(stat, msg)
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
