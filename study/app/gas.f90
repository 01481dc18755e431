!> The freely cooling granular gas in one dimension: p hard rods on a ring
!> (random, from the library's generator), run by the engine to a horizon in
!> units of Haff's time t0 at each restitution asked for, its temperature
!> sampled at log-spaced times against Haff's law T0/(1 + t/t0)^2 and, per
!> collisions per rod c, against exp(-(1 - e^2) c); where the gas leaves
!> the law, the collapses it meets (with their labels) and the late decay
!> against t^(-2/3); and the same gas by the field's way past collapse, a
!> tight real(8) loop in which a collision slower than a cutoff is elastic,
!> beside it. Writes OUT/gas_haff.tsv, OUT/gas_answers.tsv and the runs'
!> wall times in OUT/timing/gas_runs.tsv (docs/study.md).
program c12_gas
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, dp, scene_t, run_t, simulate, itoa, real_str, short_text, &
        answer_word, status_word
    use sphere_row_gas, only: gas_state
    use sphere_row_gas_study, only: gas_watch_t, ring_gas, haff_t0
    use sphere_row_ring_dp, only: ring_run
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, stop_unless_normal, &
        close_tables, say
    implicit none
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    real(qp), allocatable :: es(:)
    real(qp) :: density, temperature, horizon, from, cutoff
    integer :: p, per_decade, budget, loop_budget, unit, unit_answers, unit_time, stat, j
    integer(int64) :: seed
    character(len=300) :: msg

    call start_program(cli, "c12-gas", &
        "The freely cooling ring of p hard rods (diameter 1, mass 1) at each restitution"//nl// &
        "e: its temperature against Haff's law, per time and per collisions, where it"//nl// &
        "leaves the law, the collapses met and their labels, the late decay, and the same"//nl// &
        "gas with collisions below a cutoff speed elastic (the field's workaround).")
    call cli%add_int("p", "1000", "rods on the ring", lo=3, hi=1000000)
    call cli%add_reals("es", "0.99,0.9,0.5", "the restitutions e", lo=0.0_qp, hi=1.0_qp, &
        hi_open=.true.)
    call cli%add_real("density", "0.1", "rods per unit length (n d, d = 1)", lo=0.0_qp, &
        hi=1.0_qp, lo_open=.true., hi_open=.true.)
    call cli%add_real("temperature", "1", "T0, the temperature at t = 0", lo=0.0_qp, &
        lo_open=.true.)
    call cli%add_int("seed", "1", "the gas's random seed", lo=0)
    call cli%add_real("horizon", "20", "the horizon in units of t0", lo=0.0_qp, lo_open=.true.)
    call cli%add_real("from", "0.01", "the first sample after t = 0, in units of t0", &
        lo=0.0_qp, lo_open=.true.)
    call cli%add_int("per_decade", "5", "samples a decade of t", lo=1, hi=100)
    call cli%add_int("max_collisions", "10000000", "the engine's budget a run (0: its " &
        //"default, max(10^6, 100 p); a ring at e = 0.9 spends most of it in its collapses)", &
        lo=0)
    call cli%add_real("cutoff", "1e-3", "the workaround's cutoff speed over sqrt(T0): a " &
        //"collision slower than it is elastic", lo=0.0_qp)
    call cli%add_int("loop_max", "20000000", "the workaround loop's budget a run", lo=1)
    call read_keys(cli)
    out = cli%get_word("out")
    p = cli%get_int("p")
    es = [0.99_qp, 0.9_qp, 0.5_qp]
    if (cli%given("es")) es = cli%get_reals("es")
    density = cli%get_real("density")
    temperature = cli%get_real("temperature")
    seed = cli%get_int("seed")
    horizon = cli%get_real("horizon")
    from = cli%get_real("from")
    per_decade = cli%get_int("per_decade")
    budget = cli%get_int("max_collisions")
    cutoff = cli%get_real("cutoff")*sqrt(temperature)
    loop_budget = cli%get_int("loop_max")

    call open_table(out, "gas_haff.tsv", "e"//tab//"t_over_t0"//tab//"T_over_T0"//tab &
        //"T_bound_over_T0"//tab//"haff"//tab//"T_over_haff"//tab//"collisions_per_sphere" &
        //tab//"exp_law"//tab//"clusters"//tab//"limits_certified"//tab//"limits_tolerance" &
        //tab//"limits_bounded"//tab//"cutoff_T_over_T0"//tab//"cutoff_collisions_per_sphere", &
        unit, stat, msg)
    call stop_unless_normal(stat, msg)
    call open_table(out, "gas_answers.tsv", answer_header, unit_answers, stat, msg)
    call stop_unless_normal(stat, msg)
    call open_table(out//"/timing", "gas_runs.tsv", "e"//tab//"collisions"//tab//"engine[s]" &
        //tab//"engine_per_collision[us]"//tab//"loop_collisions"//tab//"loop[s]", &
        unit_time, stat, msg)
    call stop_unless_normal(stat, msg)
    call write_answer(unit_answers, "gas.n", itoa(p), "-", "-", "-", "rods on the ring")
    call write_answer(unit_answers, "gas.density", short_text(density), "-", "-", "-", &
        "rods per unit length (diameter 1)")
    do j = 1, size(es)
        call one_restitution(es(j))
    end do
    call close_tables([unit, unit_answers, unit_time])
contains

    !> The gas at restitution e: the engine's run with its samples, the
    !> workaround's at the same times, their rows and answers.
    subroutine one_restitution(e)
        real(qp), intent(in) :: e
        type(scene_t), target :: scene
        type(run_t) :: run
        type(gas_watch_t) :: watch
        real(qp), allocatable :: times(:), gaps(:), v(:), m(:)
        real(dp), allocatable :: loop_t(:), loop_c(:)
        real(qp) :: t0, noise, slope
        integer :: n_samples, loop_n, parts, leaves
        integer(int64) :: c0, c1, c2, rate
        real(dp) :: loop_end
        logical :: ok
        character(len=:), allocatable :: key, how
        t0 = haff_t0(e, density, 1.0_qp, temperature)
        call sample_times(t0, times)
        n_samples = size(times)
        call ring_gas(p, e, density, temperature, seed, horizon*t0, scene, stat, msg)
        call stop_unless_normal(stat, msg)
        scene%max_collisions = budget
        allocate (watch%t(n_samples), watch%temperature(n_samples), watch%bound(n_samples), &
            watch%per_sphere(n_samples), watch%clusters(n_samples), watch%limits(n_samples), &
            watch%certified(n_samples), watch%tolerance(n_samples), watch%bounded(n_samples))
        watch%t = times
        watch%wake = times(1)
        watch%scene => scene
        call system_clock(c0, rate)
        call simulate(scene, run, observer=watch)
        call system_clock(c1)
        ! the same gas, the workaround's loop in real(8)
        allocate (gaps(p), v(p), m(p), loop_t(n_samples), loop_c(n_samples))
        m = 1
        call gas_state(p, 1.0_qp, m, density, temperature, seed, gaps, v, ok)
        call ring_run(p, real(e, dp), real(cutoff, dp), real(gaps, dp), real(v, dp), &
            real(times, dp), loop_budget, loop_n, loop_end, loop_t, loop_c)
        call system_clock(c2)
        ! (T of N rods fluctuates by about sqrt(2/N) of itself: three of it)
        noise = 3*sqrt(2.0_qp/p)
        call write_samples(e, t0, noise, times, watch, loop_t, loop_c, leaves, parts)
        key = "gas."//trim(short_text(e))//"."
        how = "ring of "//itoa(p)//" rods, n d = "//short_text(density)//", T0 = " &
            //short_text(temperature)//", seed "//itoa(int(seed))
        call write_answer(unit_answers, key//"t0", short_text(t0, 6), "-", "-", "-", &
            "Haff's time sqrt(pi m/T0) (1 - n d)/((1 - e^2) n), "//how)
        call write_answer(unit_answers, key//"t_reached", short_text(watch%t(max(watch%n, &
            1))/t0, 4), "-", "-", "-", "the last sample reached, in units of t0 (horizon " &
            //short_text(horizon)//" t0)")
        call write_answer(unit_answers, key//"collisions", itoa(run%n), "-", "-", "-", &
            "collisions to the horizon, status "//status_word(run%status))
        call write_answer(unit_answers, key//"answer", answer_word(run%answer), "-", "-", "-", &
            "how good the state at the end is (the weakest of its limits')")
        call write_answer(unit_answers, key//"v_bound", real_str(run%v_bound, 2), "-", "-", &
            "-", "the bound on every velocity at the end")
        call write_answer(unit_answers, key//"noise", real_str(noise, 2), "-", "-", "-", &
            "3 sqrt(2/N): the relative scatter of T of N rods that Haff's law is read within")
        call write_answer(unit_answers, key//"haff_until", sample_t0(times, t0, leaves - 1), &
            "-", "-", "-", "the last sample (t/t0) up to which T/T0 keeps within the noise " &
            //"of Haff's " &
            //"law, from the start")
        call write_answer(unit_answers, key//"haff_ratio_end", real_str(watch%temperature( &
            max(watch%n, 1))/temperature*(1 + watch%t(max(watch%n, 1))/t0)**2, 3), "-", "-", &
            "-", "T over Haff's T at the last sample reached")
        call write_answer(unit_answers, key//"limits", itoa(run%limits%n), "-", "-", "-", &
            "collapse limits taken")
        call write_answer(unit_answers, key//"limits_certified", itoa(run%limits%certified &
            + run%limits%exact), "-", "-", "-", "of them exact or certified")
        call write_answer(unit_answers, key//"limits_tolerance", itoa(run%limits%tolerance), &
            "-", "-", "-", "of them at tolerance")
        call write_answer(unit_answers, key//"limits_bounded", itoa(run%limits%bounded), "-", &
            "-", "-", "of them bounded")
        call write_answer(unit_answers, key//"first_limit", sample_value(run%limits%t/t0, &
            run%limits%n > 0), "-", "-", "-", "the time of the first collapse limit, in t0")
        slope = late_slope(watch)
        call write_answer(unit_answers, key//"late_exponent", sample_value(slope, &
            slope < 1), "-0.667", "-2/3", sample_value(slope + 2.0_qp/3, slope < 1), &
            "d log T/d log t over the last decade of samples (Haff: -2 at t >> t0; the " &
            //"sticky gas: -2/3)")
        call write_answer(unit_answers, key//"cutoff_parts", sample_t0(times, t0, parts), "-", &
            "-", "-", "the first sample (t/t0) at which the workaround's T leaves the " &
            //"engine's by " &
            //"more than the noise (cutoff "//short_text(cutoff)//"; '-': never)")
        call write_answer(unit_answers, key//"cutoff_collisions", itoa(loop_n), "-", "-", "-", &
            "the workaround's collisions to the horizon or its budget "//itoa(loop_budget))
        write (unit_time, "(a)") short_text(e)//tab//itoa(run%n)//tab// &
            short_text(real(c1 - c0, qp)/rate, 3)//tab// &
            short_text(1.0e6_qp*real(c1 - c0, qp)/rate/max(run%n, 1), 3)//tab//itoa(loop_n) &
            //tab//short_text(real(c2 - c1, qp)/rate, 3)
        call say("c12-gas: e = "//short_text(e)//": "//itoa(run%n)//" collisions to t = " &
            //short_text(watch%t(max(watch%n, 1))/t0, 3)//" t0, answer " &
            //answer_word(run%answer)//", "//itoa(run%limits%n)//" limits")
    end subroutine one_restitution

    !> The rows of gas_haff.tsv of the samples the engine reached at
    !> restitution e, beside the workaround's (loop_t, loop_c: -1 where it did
    !> not reach them); `leaves`, the first sample at which T/T0 leaves Haff's
    !> law by more than `noise`, and `parts`, the first at which the
    !> workaround's T leaves the engine's so (0: none).
    subroutine write_samples(e, t0, noise, times, watch, loop_t, loop_c, leaves, parts)
        real(qp), intent(in) :: e, t0, noise, times(:)
        type(gas_watch_t), intent(in) :: watch
        real(dp), intent(in) :: loop_t(:), loop_c(:)
        integer, intent(out) :: leaves, parts
        real(qp) :: haff, ratio
        integer :: k
        leaves = 0
        parts = 0
        do k = 1, watch%n
            haff = 1/(1 + times(k)/t0)**2
            ratio = watch%temperature(k)/temperature/haff
            write (unit, "(a)") short_text(e)//tab//short_text(times(k)/t0, 6)//tab// &
                real_str(watch%temperature(k)/temperature, 8)//tab// &
                real_str(watch%bound(k)/temperature, 2)//tab//real_str(haff, 8)//tab// &
                real_str(ratio, 6)//tab//real_str(watch%per_sphere(k), 6)//tab// &
                real_str(exp(-(1 - e**2)*watch%per_sphere(k)), 8)//tab// &
                itoa(watch%clusters(k))//tab//itoa(watch%certified(k))//tab// &
                itoa(watch%tolerance(k))//tab//itoa(watch%bounded(k))//tab// &
                loop_text(loop_t(k)/real(temperature, dp))//tab//loop_text(loop_c(k))
            if (leaves == 0 .and. abs(ratio - 1) > noise) leaves = k
            if (parts == 0 .and. loop_t(k) > 0) then
                if (abs(loop_t(k)/watch%temperature(k) - 1) > noise) parts = k
            end if
        end do
    end subroutine write_samples

    !> t = 0 and the log-spaced sample times from `from` t0 to the horizon.
    subroutine sample_times(t0, times)
        real(qp), intent(in) :: t0
        real(qp), allocatable, intent(out) :: times(:)
        integer :: n, k
        n = ceiling(per_decade*log10(horizon/from) - 1.0e-9_qp) + 1
        allocate (times(n + 1))
        times(1) = 0
        do k = 1, n
            times(k + 1) = t0*min(horizon, from*10.0_qp**(real(k - 1, qp)/per_decade))
        end do
    end subroutine sample_times

    !> The loop's sample (-1: not reached) as text.
    function loop_text(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        text = "-"
        if (x >= 0) text = real_str(real(x, qp), 8)
    end function loop_text

    !> Sample k's time over t0 ('-' for none, k < 1).
    function sample_t0(times, t0, k) result(text)
        real(qp), intent(in) :: times(:), t0
        integer, intent(in) :: k
        character(len=:), allocatable :: text
        text = "-"
        if (k >= 1) text = short_text(times(k)/t0, 3)
    end function sample_t0

    !> A value, or '-' where there is none.
    function sample_value(x, there) result(text)
        real(qp), intent(in) :: x
        logical, intent(in) :: there
        character(len=:), allocatable :: text
        text = "-"
        if (there) text = short_text(x, 3)
    end function sample_value

    !> The least-squares slope of log T against log t over the last decade
    !> of samples reached (2 if fewer than three).
    pure real(qp) function late_slope(w) result(slope)
        type(gas_watch_t), intent(in) :: w
        real(qp) :: sx, sy, sxx, sxy, x, y
        integer :: k, n
        sx = 0
        sy = 0
        sxx = 0
        sxy = 0
        n = 0
        slope = 2
        do k = 2, w%n
            if (w%t(k) < w%t(w%n)/10) cycle
            x = log(w%t(k))
            y = log(w%temperature(k))
            sx = sx + x
            sy = sy + y
            sxx = sxx + x*x
            sxy = sxy + x*y
            n = n + 1
        end do
        if (n < 3) return
        slope = (n*sxy - sx*sy)/(n*sxx - sx*sx)
    end function late_slope

end program c12_gas
