!> The program c12-methods: the four methods of the comparison compared against
!> the reference engine (real128) on the definition's scene, written as TSV tables:
!> work-precision, stability over e, smallest distance to e_c per precision,
!> costs per collision, and the platform the times were taken on.
program c12_methods
    use, intrinsic :: iso_fortran_env, only: int64, &
        compiler_version, compiler_options
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use sphere_row, only: dp, qp, scene_t, status_normal, status_word, str, itoa
    use sphere_row_tables, only: open_table, cpu_model, tab, yes_no
    use sphere_row_outcome, only: outcome_t, comparison_t, compare_outcomes, classify, &
        category_word
    use sphere_row_methods, only: method_t, new_method, method_run, method_name, method_label, &
        method_setting, method_v_tol, kind_name, method_engine, method_absolute, method_ode, &
        method_stepping, stepper_rk8pd, stepper_rkf45, engine_methods, method_time
    use sphere_row_kind_engines, only: kind_info, kind_info_t
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, fail, &
        stop_unless_normal, close_tables, say
    use sphere_row_bisection, only: bisect
    use sphere_row_method_runs, only: scene_at, reference_run, prepare_method
    implicit none

    character(len=*), parameter :: name = "c12-methods"
    !> The critical restitution of the definition's scene, 3 - 2 sqrt(2).
    real(qp), parameter :: e_crit = 3.0_qp - 2.0_qp*sqrt(2.0_qp)
    !> Closest distance to e_c of the stability map: the reference's count is
    !> right down to about 1e-7 (see reference_method).
    real(qp), parameter :: closest = 1.0e-7_qp
    !> Decades searched for the smallest distance to e_c per precision.
    integer, parameter :: max_decade = 12
    !> Bisection steps refining that distance within a decade (in log10).
    integer, parameter :: refine_steps = 12

    type(cli_t) :: cli
    character(len=:), allocatable :: out_dir
    type(method_t), allocatable :: methods(:)
    logical, allocatable :: in_map(:)
    integer :: repeats, points, stat
    character(len=300) :: msg
    character(len=40) :: seconds_text
    integer(int64) :: max_steps
    real(qp) :: min_time
    real :: clock_start, clock_end
    !> The method under test in min_distance's bisection, each thread's own.
    type(method_t), save :: tested
    !$omp threadprivate(tested)

    call cpu_time(clock_start)
    call define_keys()
    call read_keys(cli)
    out_dir = cli%get_word("out")
    repeats = cli%get_int("repeats")
    min_time = cli%get_real("min_time")
    points = cli%get_int("points")
    max_steps = cli%get_int("max_steps")
    call execute_command_line("mkdir -p '"//out_dir//"'", exitstat=stat)
    if (stat /= 0) call fail("out = "//out_dir//": the directory cannot be created")

    call method_list()
    if (cli%get_flag("work_precision")) then
        call work_precision()
        call lap("work-precision and costs")
    end if
    call stability()
    call lap("stability map, "//itoa(points)//" values of e")
    call min_distance()
    call lap("smallest distances to e_c")
    call platform()
    call cpu_time(clock_end)
    write (seconds_text, "(f0.1)") clock_end - clock_start
    call say(name//": tables written to "//out_dir//"/ in "//trim(seconds_text)//" s of CPU time")

contains

    !> The keys of c12-methods: where the tables go and how long to time.
    subroutine define_keys()
        call start_program(cli, name, &
            "Compares four methods on the definition's scene (p = 4, d = a = v0 = 1)"//nl// &
            "against the reference engine (real128): the engine in each real kind built;"//nl// &
            "absolute variables in dp, qp; GSL ODE integration (rk8pd, rkf45) with state"//nl// &
            "events; fixed time steps. Writes into the directory `out`:"//nl// &
            "  methods_work_precision.tsv  errors per scene, method, setting"//nl// &
            "  methods_stability.tsv       outcome category over e from 1 to 0"//nl// &
            "  methods_min_distance.tsv    smallest e - e_c with the right count, per kind"//nl// &
            "and the machine's measurements into `out`/timing:"//nl// &
            "  methods_work_precision.tsv  CPU time per run of each row of the table above"//nl// &
            "  methods_costs.tsv           ns per run and per collision at e = 0.2, 0.172"//nl// &
            "  methods_platform.tsv        CPU model, compiler version and options")
        call cli%add_int("repeats", "5", "timing batches per measurement (median taken)", &
            lo=1, hi=1000)
        call cli%add_real("min_time", "0.05", "CPU seconds per measurement", lo=0.0_qp, &
            hi=60.0_qp)
        call cli%add_int("points", "300", "values of e on the stability map", lo=8, hi=100000)
        call cli%add_int("max_steps", "20000000", "step budget of time stepping", lo=1)
        call cli%add_flag("work_precision", "yes", "also the timed tables (work-precision" &
            //" and costs); no: the stability map and the distances to e_c only")
    end subroutine define_keys

    !> The methods and settings compared; in_map marks those on the stability
    !> map. Every other ODE tolerance is left out there (below e_c an ODE run
    !> locates thousands of impacts, each by some 50 re-integrations), and so is
    !> time stepping with h = 1e-5 (1e6 steps and more per scene).
    subroutine method_list()
        integer :: k
        real(qp), parameter :: ode_tols(6) = [1.0e-3_qp, 1.0e-5_qp, 1.0e-7_qp, 1.0e-9_qp, &
            1.0e-11_qp, 1.0e-13_qp]
        real(qp), parameter :: rkf45_tols(3) = [1.0e-4_qp, 1.0e-8_qp, 1.0e-12_qp]
        real(qp), parameter :: steps(5) = [1.0e-1_qp, 1.0e-2_qp, 1.0e-3_qp, 1.0e-4_qp, 1.0e-5_qp]
        !> The smallest time step on the map.
        real(qp), parameter :: finest_mapped_step = 1.0e-4_qp
        !> The one rkf45 tolerance on the map (1e-8).
        integer, parameter :: mapped_rkf45 = 2
        type(kind_info_t) :: real64
        real64 = kind_info(dp)
        methods = [engine_methods(tiny_tol=.false.), &
            new_method(method_engine, dp, tol=real64%sqrt_tiny), &
            new_method(method_absolute, dp), new_method(method_absolute, qp)]
        in_map = [(.true., k=1, size(methods))]
        do k = 1, size(ode_tols)
            methods = [methods, new_method(method_ode, tol=ode_tols(k), stepper=stepper_rk8pd)]
            in_map = [in_map, mod(k, 2) == 1]  ! 1e-3, 1e-7, 1e-11
        end do
        do k = 1, size(rkf45_tols)
            methods = [methods, new_method(method_ode, tol=rkf45_tols(k), stepper=stepper_rkf45)]
            in_map = [in_map, k == mapped_rkf45]
        end do
        do k = 1, size(steps)
            methods = [methods, new_method(method_stepping, h=steps(k), max_steps=max_steps)]
            in_map = [in_map, steps(k) >= finest_mapped_step]
        end do
    end subroutine method_list

    !> methods_work_precision.tsv: every method on each scene against the
    !> reference; its CPU times, which differ from machine to machine, go to
    !> timing/methods_work_precision.tsv (row by row the same) and
    !> timing/methods_costs.tsv, so that the table of errors is the same
    !> wherever the study runs.
    subroutine work_precision()
        !> The scenes: a finite run (e = 0.2), three above e_c by a decade each,
        !> and e = 0.172 just above e_c.
        real(qp), parameter :: scenes(*) = [0.2_qp, e_crit + 1.0e-2_qp, e_crit + 1.0e-3_qp, &
            0.172_qp, e_crit + 1.0e-4_qp]
        !> The scenes of the costs table: e = 0.2 and e = 0.172.
        logical, parameter :: in_costs(*) = [.true., .false., .false., .true., .false.]
        !> Nanoseconds in a second.
        real(qp), parameter :: ns_per_s = 1.0e9_qp
        type(outcome_t) :: ref, run
        type(comparison_t) :: cmp
        type(scene_t) :: scene
        real(qp) :: seconds, err
        integer :: s, m, unit, unit_time, unit_cost, runs, batches
        call open_table(out_dir, "methods_work_precision.tsv", "scene"//tab//"e[1]"//tab &
            //"e_minus_ec[1]"//tab//"label"//tab//"method"//tab//"kind"//tab &
            //"setting[1|L/V]"//tab//"collisions"//tab//"collisions_ref"//tab//"same_count" &
            //tab//"same_sequence"//tab//"matched"//tab//"v_error[V]"//tab//"t_error[L/V]" &
            //tab//"error[1]"//tab//"min_gap[L]"//tab//"steps"//tab//"status"//tab//"category", &
            unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call open_table(timing_dir(), "methods_work_precision.tsv", "scene"//tab//"label" &
            //tab//"cpu_per_run[s]"//tab//"batches"//tab//"runs_per_batch", unit_time, stat, msg)
        call stop_unless_normal(stat, msg)
        call open_table(timing_dir(), "methods_costs.tsv", "e[1]"//tab//"label"//tab &
            //"method"//tab//"kind"//tab//"setting[1|L/V]"//tab//"collisions_ref"//tab &
            //"collisions"//tab//"ns_per_run[ns]"//tab//"ns_per_collision[ns]"//tab &
            //"category", unit_cost, stat, msg)
        call stop_unless_normal(stat, msg)
        do s = 1, size(scenes)
            call scene_at(scenes(s), scene)
            call reference_run(scene, ref)
            do m = 1, size(methods)
                call prepare_method(methods(m), scene)
                call method_run(methods(m), run, record=.true.)
                cmp = compare_outcomes(ref, run)
                ! One number per run for the chart: velocities in units of v0,
                ! times in units of L/v0 (L = max(d, a) = 1 here).
                err = max(cmp%v_error/scene%v0, &
                    cmp%t_error*scene%v0/max(scene%d, maxval(scene%a)))
                call method_time(methods(m), min_time, repeats, seconds, batches, &
                    runs)
                write (unit, "(a)") itoa(s)//tab//str(scenes(s))//tab//str(scenes(s) - e_crit) &
                    //tab//method_label(methods(m))//tab//method_name(methods(m))//tab &
                    //kind_name(methods(m)%precision)//tab//str(method_setting(methods(m))) &
                    //tab//itoa(run%n)//tab//itoa(ref%n)//tab//yes_no(cmp%same_count)//tab &
                    //yes_no(cmp%same_sequence)//tab//itoa(cmp%n_matched)//tab &
                    //str(cmp%v_error)//tab//str(cmp%t_error)//tab//str(err)//tab &
                    //str(run%min_gap)//tab//itoa(run%steps)//tab//status_word(run%status) &
                    //tab//category_word(classify(ref, run, method_v_tol(methods(m), scene%v0)))
                write (unit_time, "(a)") itoa(s)//tab//method_label(methods(m))//tab &
                    //str(seconds)//tab//itoa(batches)//tab//itoa(runs)
                if (in_costs(s)) then
                    write (unit_cost, "(a)") str(scenes(s))//tab//method_label(methods(m))//tab &
                        //method_name(methods(m))//tab//kind_name(methods(m)%precision)//tab &
                        //str(method_setting(methods(m)))//tab//itoa(ref%n)//tab//itoa(run%n) &
                        //tab//str(ns_per_s*seconds)//tab//str(ns_per_s*seconds/max(1, run%n)) &
                        //tab//category_word(classify(ref, run, &
                        method_v_tol(methods(m), scene%v0)))
                end if
            end do
        end do
        call close_tables([unit, unit_time, unit_cost])
    end subroutine work_precision

    !> The directory of the machine's measurements: `out`/timing.
    function timing_dir() result(dir)
        character(len=:), allocatable :: dir
        dir = out_dir//"/timing"
    end function timing_dir

    !> methods_stability.tsv: the category of each method on the map over e,
    !> from 1 down through e_c to 0, log-spaced in |e - e_c| from 1e-7 on.
    !> The values of e are independent: they run in parallel (OpenMP), each
    !> thread on its own copy of the methods, and the rows are written in
    !> order afterwards, so the table does not depend on the threads.
    subroutine stability()
        !> One point in this many lies below e_c.
        integer, parameter :: below_part = 4
        type(outcome_t) :: ref, run
        type(scene_t) :: scene
        type(method_t), allocatable :: mine(:)
        real(qp), allocatable :: es(:)
        real(qp) :: lo, hi
        integer :: n_above, n_below, j, k, m, unit, row
        ! per value of e and method: category, collisions, status; and the reference's
        integer, allocatable :: category(:, :), n_run(:, :), status_run(:, :)
        integer, allocatable :: n_ref(:), status_ref(:)
        n_below = points/below_part
        n_above = points - n_below
        allocate (es(points))
        lo = log10(closest)
        hi = log10(1.0_qp - e_crit)
        do j = 1, n_above
            es(j) = e_crit + 10.0_qp**(hi + (lo - hi)*(j - 1)/(n_above - 1))
        end do
        es(1) = 1.0_qp
        hi = log10(e_crit)
        do j = 1, n_below
            es(n_above + j) = e_crit - 10.0_qp**(lo + (hi - lo)*(j - 1)/(n_below - 1))
        end do
        es(points) = 0.0_qp
        call open_table(out_dir, "methods_stability.tsv", "row"//tab//"label"//tab//"e[1]" &
            //tab//"e_minus_ec[1]"//tab//"category_code"//tab//"category"//tab//"collisions" &
            //tab//"collisions_ref"//tab//"status"//tab//"status_ref", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        allocate (category(size(methods), points), n_run(size(methods), points), &
            status_run(size(methods), points), n_ref(points), status_ref(points))
        ! from e = 0 up: the runs below e_c, the longest, are handed out first
        !$omp parallel do schedule(dynamic) default(shared) private(k, j, m, scene, ref, run, mine)
        do k = 1, points
            j = points + 1 - k
            if (.not. allocated(mine)) mine = methods
            call scene_at(es(j), scene)
            call reference_run(scene, ref)
            n_ref(j) = ref%n
            status_ref(j) = ref%status
            do m = 1, size(mine)
                if (.not. in_map(m)) cycle
                call prepare_method(mine(m), scene)
                call method_run(mine(m), run, record=.true.)
                category(m, j) = classify(ref, run, method_v_tol(mine(m), scene%v0))
                n_run(m, j) = run%n
                status_run(m, j) = run%status
            end do
        end do
        !$omp end parallel do
        do j = 1, points
            row = 0
            do m = 1, size(methods)
                if (.not. in_map(m)) cycle
                row = row + 1
                write (unit, "(a)") itoa(row)//tab//method_label(methods(m))//tab//str(es(j)) &
                    //tab//str(es(j) - e_crit)//tab//itoa(category(m, j))//tab &
                    //category_word(category(m, j))//tab//itoa(n_run(m, j))//tab &
                    //itoa(n_ref(j))//tab//status_word(status_run(m, j))//tab &
                    //status_word(status_ref(j))
            end do
        end do
        call close_tables([unit])
    end subroutine stability

    !> methods_min_distance.tsv: for each precision of the engine (and of the
    !> absolute method), the smallest e - e_c = 10^-k, k = 1, 2, ..., down to
    !> which every decade gives the reference's collision sequence; then a
    !> bisection in log10(e - e_c) within the next decade for the boundary.
    subroutine min_distance()
        type(method_t), allocatable :: chosen(:)
        type(outcome_t) :: ref, run
        type(scene_t) :: scene
        real(qp) :: wrong_log, nan
        real(qp), allocatable :: right_log(:)
        integer :: m, k, unit, ref_limit
        integer, allocatable :: k_right(:), n_right(:)
        logical, allocatable :: reliable(:)
        nan = ieee_value(nan, ieee_quiet_nan)
        chosen = [engine_methods(tiny_tol=.false.), engine_methods(tiny_tol=.true.), &
            new_method(method_absolute, dp), new_method(method_absolute, qp)]
        ! The reference itself holds to the decade where it still ends normally.
        ref_limit = 0
        do k = 1, max_decade
            call scene_at(e_crit + 10.0_qp**(-k), scene)
            call reference_run(scene, ref)
            if (ref%status /= status_normal) exit
            ref_limit = k
        end do
        call open_table(out_dir, "methods_min_distance.tsv", "label"//tab//"method"//tab &
            //"kind"//tab//"epsilon[1]"//tab//"min_distance_decade[1]"//tab &
            //"collisions_there"//tab//"min_distance_bisected[1]"//tab//"reference_limit[1]", &
            unit, stat, msg)
        call stop_unless_normal(stat, msg)
        allocate (right_log(size(chosen)), k_right(size(chosen)), n_right(size(chosen)), &
            reliable(size(chosen)))
        ! each method searched on a thread of its own (OpenMP), the rows
        ! written in order afterwards
        !$omp parallel do schedule(dynamic, 1) default(shared) private(m, k, run, wrong_log)
        do m = 1, size(chosen)
            k_right(m) = 0
            n_right(m) = 0
            do k = 1, ref_limit
                if (.not. right_at(chosen(m), -real(k, qp), run)) exit
                k_right(m) = k
                n_right(m) = run%n
            end do
            right_log(m) = -real(k_right(m), qp)
            wrong_log = right_log(m) - 1
            reliable(m) = k_right(m) < ref_limit
            if (k_right(m) > 0 .and. reliable(m)) then
                tested = chosen(m)
                call bisect(wrong_at, wrong_log, right_log(m), 0.0_qp, refine_steps)
            end if
        end do
        !$omp end parallel do
        do m = 1, size(chosen)
            write (unit, "(a)") method_label(chosen(m))//tab//method_name(chosen(m))//tab &
                //kind_name(chosen(m)%precision)//tab//str(method_setting(chosen(m)))//tab &
                //str(merge(10.0_qp**(-real(k_right(m), qp)), nan, k_right(m) > 0))//tab &
                //itoa(n_right(m))//tab &
                //str(merge(10.0_qp**right_log(m), nan, k_right(m) > 0 .and. reliable(m))) &
                //tab//str(10.0_qp**(-ref_limit))
        end do
        call close_tables([unit])
    end subroutine min_distance

    !> Whether the method `tested` misses the reference's collision sequence
    !> at e = e_c + 10^log_distance, for bisect.
    logical function wrong_at(log_distance)
        real(qp), intent(in) :: log_distance
        type(outcome_t) :: run
        wrong_at = .not. right_at(tested, log_distance, run)
    end function wrong_at

    !> Whether `method` gives the reference's collision sequence at
    !> e = e_c + 10^log_distance.
    logical function right_at(method, log_distance, run) result(right)
        type(method_t), intent(inout) :: method
        real(qp), intent(in) :: log_distance
        type(outcome_t), intent(inout) :: run
        type(outcome_t) :: ref
        type(scene_t) :: scene
        type(comparison_t) :: cmp
        call scene_at(e_crit + 10.0_qp**log_distance, scene)
        call reference_run(scene, ref)
        call prepare_method(method, scene)
        call method_run(method, run, record=.true.)
        cmp = compare_outcomes(ref, run)
        right = cmp%same_sequence .and. run%status == status_normal
    end function right_at

    !> Report the CPU time of the part just finished.
    subroutine lap(part)
        character(len=*), intent(in) :: part
        real, save :: last = -1.0e0
        real :: now
        character(len=40) :: seconds
        if (last < 0.0e0) last = clock_start
        call cpu_time(now)
        write (seconds, "(f0.2)") now - last
        call say(name//": "//part//": "//trim(seconds)//" s")
        last = now
    end subroutine lap

    !> timing/methods_platform.tsv: where and how the times were taken.
    subroutine platform()
        integer :: unit
        call open_table(timing_dir(), "methods_platform.tsv", "item"//tab//"value", unit, stat, &
            msg)
        call stop_unless_normal(stat, msg)
        write (unit, "(a)") "cpu_model"//tab//cpu_model()
        write (unit, "(a)") "compiler_version"//tab//compiler_version()
        write (unit, "(a)") "compiler_options"//tab//compiler_options()
        write (unit, "(a)") "clock"//tab//"cpu_time (process CPU time), median over batches"
        write (unit, "(a)") "batches"//tab//itoa(repeats)
        write (unit, "(a)") "min_time[s]"//tab//str(real(min_time, dp))
        write (unit, "(a)") "stepping_max_steps"//tab//itoa(max_steps)
        call close_tables([unit])
    end subroutine platform

end program c12_methods
