!> c12-c2: task c2 of ARGESIM Comparison 12. The restitution coefficient e is
!> normally distributed (mean 0.5, standard deviation 0.05); the distribution
!> of the final velocity v4 of the last sphere, its mean, standard deviation,
!> the 95 % confidence interval of the mean and the 95 % interval of v4 itself,
!> from a Monte Carlo of the row in real(16): with precision=auto (the
!> default) each run is made in real(64) where a rounding certificate shows
!> that it takes real(16)'s decisions, and again in real(16) where not.
!>
!> One stream of nmax samples is drawn; the main answers are the statistics of
!> its first n samples and the convergence table takes the prefixes
!> N = 10^2, 10^3, ... of the same stream, so its row N = n is the main
!> answer. The stream is made of blocks of 10^4 samples, each from its own
!> generator (see monte_carlo_v4), run in parallel with OpenMP where built
!> with it: the output is the same for any number of threads.
!>
!> For the definition's row every answer is checked against the exact
!> law of v4 = v0 ((1+e)/2)^3, valid where sphere 4 is struck once; the bound
!> of that region is found with the engine and the samples below it counted.
program c12_c2
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
    use sphere_row, only: dp, qp, scene_t, itoa
    use sphere_row_monte_carlo, only: mc_counts_t, monte_carlo_v4, normal_mass_outside_unit, &
        min_acceptance
    use sphere_row_c2_tables, only: c2_sample_t, c2_statistics, c2_write_tables
    use sphere_row_study_cli, only: cli_t, add_scene_keys, start_program, read_keys, fail, &
        stop_unless_normal
    use sphere_row_terminal, only: stderr_is_terminal
    use sphere_row_error, only: error_t
    implicit none

    character(len=*), parameter :: name = "c12-c2"
    character(len=*), parameter :: nl = new_line("a")
    !> Sample sizes: at least 100 for the normal-quantile interval (see
    !> mean_ci_half_width); at most 10^8, about 3 GB of work arrays.
    integer, parameter :: n_least = 100, n_most = 100000000
    integer, parameter :: bins_most = 100000
    !> Progress on a terminal: from this many seconds on, at most once per
    !> report_every seconds.
    real(dp), parameter :: report_after = 2.0_dp, report_every = 1.0_dp

    type(cli_t) :: cli
    character(len=:), allocatable :: out
    character(len=300) :: msg
    type(scene_t) :: scene
    type(c2_sample_t) :: c
    type(error_t), allocatable :: error
    integer :: stat
    integer(int64) :: clock0, clock_rate, clock_shown
    real(dp) :: seconds
    logical :: terminal, shown

    call define_keys()
    call read_keys(cli, scene)
    out = cli%get_word("out")
    c%n = cli%get_int("n")
    c%nmax = c%n
    if (cli%given("nmax")) c%nmax = cli%get_int("nmax")
    c%seed = cli%get_int("seed")
    c%mean = cli%get_real("mean")
    c%sd = cli%get_real("sd")
    c%bins = cli%get_int("bins")
    c%precision = cli%get_word("precision")
    c%v0 = scene%v0
    call check_settings()

    call run_stream()
    call c2_statistics(c, scene, error)
    if (allocated(error)) call fail(error)
    call c2_write_tables(c, out, error)
    if (allocated(error)) call fail(error)
    write (output_unit, "(a)") name//": "//itoa(c%nmax)//" runs in "//fixed(seconds) &
        //" s ("//fixed(1.0e6_dp*seconds/c%nmax)//" us per run); tables in "//out

contains

    !> The stream, timed: first the main sample, then its continuation up to nmax.
    subroutine run_stream()
        type(mc_counts_t) :: counts_rest
        integer(int64) :: clock1
        allocate (c%v4(c%nmax), c%e(c%nmax))
        terminal = stderr_is_terminal()
        shown = .false.
        call system_clock(clock0, clock_rate)
        clock_shown = clock0
        call monte_carlo_v4(scene, c%mean, c%sd, c%seed, 1, c%v4(:c%n), c%e(:c%n), c%counts, &
            stat, msg, progress=show_progress, auto=c%precision == "auto")
        call stop_unless_normal(stat, msg)
        c%escalated_nmax = c%counts%escalated
        if (c%nmax > c%n) then
            call monte_carlo_v4(scene, c%mean, c%sd, c%seed, c%n + 1, c%v4(c%n + 1:), &
                c%e(c%n + 1:), counts_rest, stat, msg, progress=show_progress, &
                auto=c%precision == "auto")
            call stop_unless_normal(stat, msg)
            c%escalated_nmax = c%escalated_nmax + counts_rest%escalated
        end if
        call system_clock(clock1)
        if (shown) write (error_unit, "(a)") ""
        seconds = real(clock1 - clock0, dp)/real(clock_rate, dp)
    end subroutine run_stream

    !> On a terminal, after report_after seconds: the share of the runs done,
    !> on one line of stderr rewritten in place.
    subroutine show_progress(done, total)
        integer(int64), intent(in) :: done, total
        integer(int64) :: now
        if (.not. terminal) return
        call system_clock(now)
        if (real(now - clock0, dp) < report_after*clock_rate) return
        if (real(now - clock_shown, dp) < report_every*clock_rate .and. done < total) return
        clock_shown = now
        shown = .true.
        write (error_unit, "(a, i0, a, i0, a)", advance="no") achar(13)//name//": ", &
            (100*done)/total, " % of ", total, " runs"
        flush (error_unit)
    end subroutine show_progress

    !> Refuse settings outside their ranges before any work is done.
    !> The keys of c2: the sample, the law of e, the histogram, and the scene
    !> keys but e, which is sampled.
    subroutine define_keys()
        call start_program(cli, name, &
            "Task c2 of ARGESIM Comparison 12: e ~ N(mean, sd^2), drawn by Box-Muller"//nl// &
            "from GSL's MT19937 and truncated to 0 <= e <= 1 (draws outside are drawn"//nl// &
            "again and counted); each row is run in real(16), or with precision=auto in"//nl// &
            "real(64) where a rounding certificate holds. Writes c2_answers.tsv,"//nl// &
            "c2_ecdf.tsv, c2_histogram.tsv and c2_convergence.tsv into the directory out.")
        call cli%add_int("n", "1000000", "main sample size", lo=n_least, hi=n_most)
        call cli%add_int("nmax", "", "largest N of the convergence table (rows 10^2, 10^3," &
            //" ..., n, nmax; one stream), at least n", lo=n_least, hi=n_most, shown="n")
        call cli%add_int("seed", "12", "MT19937 seed", lo=1)
        call cli%add_real("mean", "0.5", "mean of e; at least 10 % of the law in [0, 1]")
        call cli%add_real("sd", "0.05", "standard deviation of e", lo=0.0_qp, lo_open=.true.)
        call cli%add_int("bins", "100", "histogram bins", lo=1, hi=bins_most)
        call cli%add_word("precision", "auto", "auto: real(8) where a rounding certificate" &
            //" holds, else real(16); qp: real(16) for every run")
        call add_scene_keys(cli, e_set_by="the normal law of e")
    end subroutine define_keys

    !> What the keys' own ranges cannot say: nmax >= n, the precision's name,
    !> and enough of the law of e inside [0, 1] for the truncation to draw
    !> again rarely.
    subroutine check_settings()
        if (c%nmax < c%n) call fail("nmax = "//cli%get_text("nmax")//": allowed an integer " &
            //"n <= nmax <= "//itoa(n_most)//" (n = "//itoa(c%n)//")")
        if (c%precision /= "auto" .and. c%precision /= "qp") call fail("precision = " &
            //c%precision//": allowed auto or qp")
        if (.not. (1.0_dp - normal_mass_outside_unit(c%mean, c%sd) >= min_acceptance)) then
            call fail("mean = "//cli%get_text("mean")//", sd = "//cli%get_text("sd") &
                //": under 10 % of the normal law lies in 0 <= e <= 1; allowed at least 10 %")
        end if
    end subroutine check_settings

    !> Three decimals with the leading zero that f0.3 leaves out.
    pure function fixed(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: buf
        write (buf, "(f32.3)") x
        s = trim(adjustl(buf))
    end function fixed

end program c12_c2
