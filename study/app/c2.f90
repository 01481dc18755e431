!> c12-c2: task c2 of ARGESIM Comparison 12. The restitution coefficient e is
!> normally distributed (mean 0.5, standard deviation 0.05); the distribution
!> of the final velocity v4 of the last sphere, its mean, standard deviation,
!> the 95 % confidence interval of the mean and the 95 % interval of v4 itself,
!> from a Monte Carlo of the row in real(16).
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
    use sphere_row, only: dp, qp, scene_t, run_t, simulate, str, real_str, itoa
    use sphere_row_monte_carlo, only: mc_counts_t, monte_carlo_v4, &
        normal_mass_outside_unit, normal_cdf, normal_density, sample_moments, normal_quantile, &
        mean_ci_half_width, sort_values, sorted_quantile, ks_distance, cubic_law_applies, &
        cubic_law_mean, cubic_law_sd, cubic_law_quantile, cubic_law_cdf, cubic_law_density, &
        cubic_law_v4, single_impact_bound, min_acceptance
    use sphere_row_study_cli, only: cli_t, add_scene_keys, start_program, read_keys, fail, &
        stop_unless_normal
    use sphere_row_terminal, only: stderr_is_terminal
    implicit none

    character(len=*), parameter :: name = "c12-c2"
    character(len=*), parameter :: nl = new_line("a")
    character(len=1), parameter :: tab = achar(9)
    !> Sample sizes: at least 100 for the normal-quantile interval (see
    !> mean_ci_half_width); at most 10^8, about 3 GB of work arrays.
    integer, parameter :: n_least = 100, n_most = 100000000
    integer, parameter :: bins_most = 100000
    !> Rows of the empirical distribution function table (every k-th order statistic).
    integer, parameter :: ecdf_rows = 1000
    !> Sampled e re-run to compare the engine with the closed form in real128,
    !> and stored v4 compared with the closed form rounded to a double.
    integer, parameter :: closed_form_reruns = 1000, closed_form_checks = 100000
    !> Progress on a terminal: from this many seconds on, at most once per
    !> report_every seconds.
    real(dp), parameter :: report_after = 2.0_dp, report_every = 1.0_dp
    real(qp), parameter :: confidence = 0.95_qp
    !> Asymptotic 95 % quantile of the Kolmogorov distribution: a sample of the
    !> law itself exceeds ks_95/sqrt(n) with probability 5 %.
    real(qp), parameter :: ks_95 = 1.3581_qp
    !> Bracket of the bisection for the region of one impact on sphere 4: at
    !> e = 0.2 it is struck three times, at e = 1 (elastic) once.
    real(qp), parameter :: bracket_lo = 0.2_qp, bracket_hi = 1.0_qp

    type(cli_t) :: cli
    character(len=:), allocatable :: out
    character(len=300) :: msg
    logical :: exact
    type(scene_t) :: scene
    type(mc_counts_t) :: counts, counts_rest
    integer :: stat, n, nmax, seed, bins
    real(qp) :: mean, sd
    real(dp), allocatable :: v4(:), e(:), work(:)
    integer(int64) :: clock0, clock1, clock_rate, clock_shown
    real(dp) :: seconds
    logical :: terminal, shown

    ! the answers of the main sample (statistics in double: see sample_moments)
    real(dp) :: v_mean, v_sd, e_mean, e_sd
    real(qp) :: half_width, z975
    real(dp) :: q025, q975, ks
    ! checks against the exact law (definition's row only)
    real(qp) :: bound, max_diff, redraws_expected, outside_expected
    integer :: outside, reruns, mismatches, checks

    call define_keys()
    call read_keys(cli, scene)
    out = cli%get_word("out")
    n = cli%get_int("n")
    nmax = n
    if (cli%given("nmax")) nmax = cli%get_int("nmax")
    seed = cli%get_int("seed")
    mean = cli%get_real("mean")
    sd = cli%get_real("sd")
    bins = cli%get_int("bins")
    call check_settings()

    ! the stream: first the main sample, then its continuation up to nmax
    allocate (v4(nmax), e(nmax))
    terminal = stderr_is_terminal()
    shown = .false.
    call system_clock(clock0, clock_rate)
    clock_shown = clock0
    call monte_carlo_v4(scene, mean, sd, seed, 1, v4(:n), e(:n), counts, stat, msg, &
        progress=show_progress)
    call stop_unless_normal(stat, msg)
    if (nmax > n) then
        call monte_carlo_v4(scene, mean, sd, seed, n + 1, v4(n + 1:), e(n + 1:), counts_rest, &
            stat, msg, progress=show_progress)
        call stop_unless_normal(stat, msg)
    end if
    call system_clock(clock1)
    if (shown) write (error_unit, "(a)") ""
    seconds = real(clock1 - clock0, dp)/real(clock_rate, dp)

    ! main answers from the first n samples
    allocate (work(nmax))
    call sample_moments(v4(:n), v_mean, v_sd)
    call sample_moments(e(:n), e_mean, e_sd)
    z975 = normal_quantile(0.5_qp + confidence/2)
    half_width = mean_ci_half_width(real(v_sd, qp), n, confidence)
    work(:n) = v4(:n)
    call sort_values(work(:n))
    q025 = sorted_quantile(work(:n), 0.025_dp)
    q975 = sorted_quantile(work(:n), 0.975_dp)
    exact = cubic_law_applies(scene)
    ks = -1.0_dp
    if (exact) ks = ks_distance(cubic_law_cdf(work(:n), mean, sd, scene%v0))
    redraws_expected = n*real(normal_mass_outside_unit(mean, sd), qp) &
        /(1.0_qp - real(normal_mass_outside_unit(mean, sd), qp))
    if (exact) call check_closed_form()

    call write_tables()
    write (output_unit, "(a)") name//": "//itoa(nmax)//" runs in "//fixed(seconds) &
        //" s ("//fixed(1.0e6_dp*seconds/nmax)//" us per run); tables in "//out

contains

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
            "again and counted); each row is run in real(16). Writes c2_answers.tsv,"//nl// &
            "c2_ecdf.tsv, c2_histogram.tsv and c2_convergence.tsv into the directory out.")
        call cli%add_int("n", "1000000", "main sample size", lo=n_least, hi=n_most)
        call cli%add_int("nmax", "", "largest N of the convergence table (rows 10^2, 10^3," &
            //" ..., n, nmax; one stream), at least n", lo=n_least, hi=n_most, shown="n")
        call cli%add_int("seed", "12", "MT19937 seed", lo=1)
        call cli%add_real("mean", "0.5", "mean of e; at least 10 % of the law in [0, 1]")
        call cli%add_real("sd", "0.05", "standard deviation of e", lo=0.0_qp, lo_open=.true.)
        call cli%add_int("bins", "100", "histogram bins", lo=1, hi=bins_most)
        call add_scene_keys(cli, e_set_by="the normal law of e")
    end subroutine define_keys

    !> What the keys' own ranges cannot say: nmax >= n, and enough of the law
    !> of e inside [0, 1] for the truncation to draw again rarely.
    subroutine check_settings()
        if (nmax < n) call fail("nmax = "//cli%get_text("nmax")//": allowed an integer " &
            //"n <= nmax <= "//itoa(n_most)//" (n = "//itoa(n)//")")
        if (.not. (1.0_dp - normal_mass_outside_unit(mean, sd) >= min_acceptance)) then
            call fail("mean = "//cli%get_text("mean")//", sd = "//cli%get_text("sd") &
                //": under 10 % of the normal law lies in 0 <= e <= 1; allowed at least 10 %")
        end if
    end subroutine check_settings

    !> Where the exact law applies: the bound of the region of one impact on
    !> sphere 4 (bisection with the engine), the samples below it, the engine
    !> against v0 ((1+e)/2)^3 in real128 on a subset re-run, and the stored v4
    !> of every (n/closed_form_checks)-th sample against the closed form rounded
    !> to a double (a subsample: in real128 each check costs a tenth of a run).
    subroutine check_closed_form()
        type(scene_t) :: trial
        type(run_t) :: run
        real(qp) :: e_q, inside
        integer :: stride, i, j
        call single_impact_bound(scene, bracket_lo, bracket_hi, bound, stat, msg)
        call stop_unless_normal(stat, msg)
        outside = count(e(:n) < bound)
        inside = 1.0_qp - real(normal_mass_outside_unit(mean, sd), qp)
        outside_expected = n*(real(normal_cdf(real(bound, dp), mean, sd), qp) &
            - real(normal_cdf(0.0_dp, mean, sd), qp))/inside

        trial = scene
        stride = max(1, n/closed_form_reruns)
        max_diff = 0.0_qp
        reruns = 0
        do i = 1, n + 2
            if (i <= n) then
                if (mod(i, stride) /= 0) cycle
                j = i
            else if (i == n + 1) then
                j = minloc(e(:n), 1)
            else
                j = maxloc(e(:n), 1)
            end if
            e_q = real(e(j), qp)
            if (e_q < bound) cycle
            trial%e = e_q
            call simulate(trial, run)
            max_diff = max(max_diff, abs(run%v(4) - cubic_law_v4(e_q, scene%v0)))
            reruns = reruns + 1
        end do

        mismatches = 0
        checks = 0
        do i = max(1, n/closed_form_checks), n, max(1, n/closed_form_checks)
            checks = checks + 1
            e_q = real(e(i), qp)
            if (e_q < bound) cycle
            if (v4(i) /= real(cubic_law_v4(e_q, scene%v0), dp)) mismatches = mismatches + 1
        end do
    end subroutine check_closed_form

    !> Open every table first, so that a directory that cannot be written is
    !> refused before anything is in it; then write them.
    subroutine write_tables()
        integer :: units(4), ios, i, k, exitstat, cmdstat
        logical :: there
        character(len=*), parameter :: names(4) = [character(len=20) :: &
            "c2_answers.tsv", "c2_ecdf.tsv", "c2_histogram.tsv", "c2_convergence.tsv"]
        inquire (file=out//"/.", exist=there)
        if (.not. there) then
            call execute_command_line("mkdir -p '"//out//"' 2>/dev/null", exitstat=exitstat, &
                cmdstat=cmdstat)
            if (cmdstat /= 0 .or. exitstat /= 0) &
                call fail("out = '"//out//"': the directory cannot be created")
        end if
        units = -1
        do k = 1, size(names)
            open (newunit=units(k), file=out//"/"//trim(names(k)), status="replace", &
                action="write", iostat=ios)
            if (ios /= 0) then
                do i = 1, k - 1
                    close (units(i), status="delete")
                end do
                call fail("out = '"//out//"': "//trim(names(k))//" cannot be written")
            end if
        end do
        call write_answers(units(1))
        call write_ecdf(units(2))
        call write_histogram(units(3))
        call write_convergence(units(4))
        do k = 1, size(units)
            close (units(k))
        end do
    end subroutine write_tables

    !> c2_answers.tsv: one row per answer with its independent check. The
    !> checks by the exact law exist for the definition's row only; elsewhere
    !> their columns are `-` and the rows about its region are left out.
    subroutine write_answers(unit)
        integer, intent(in) :: unit
        real(qp) :: m_exact, s_exact
        m_exact = cubic_law_mean(mean, sd, scene%v0)
        s_exact = cubic_law_sd(mean, sd, scene%v0)
        write (unit, "(a)") "key"//tab//"value"//tab//"check"//tab//"check_value"//tab &
            //"difference"//tab//"how"
        call answer(unit, "c2.n", itoa(n), "Size of the main sample: the first n runs of" &
            //" the stream, from which every statistic below is taken.")
        call answer(unit, "c2.nmax", itoa(nmax), "Largest N of the convergence table;" &
            //" runs n+1..nmax continue the same stream.")
        call answer(unit, "c2.seed", itoa(seed), "Seed of GSL's MT19937 whose uniforms" &
            //" give e by Box-Muller (both normals of each pair used).")
        call answer(unit, "c2.e_mean", dstr(e_mean), "Mean of the sampled e (shifted sums" &
            //" in double)", "normal_mean", real(e_mean, qp), mean, &
            ", against the mean of the normal law.")
        call answer(unit, "c2.e_sd", dstr(e_sd), "Standard deviation of the sampled e", &
            "normal_sd", real(e_sd, qp), sd, ", against that of the normal law.")
        call answer(unit, "c2.redraws", itoa(counts%redraws), "Normal draws outside" &
            //" 0 <= e <= 1, discarded and drawn again (the law is truncated to [0,1])", &
            "expected_count", real(counts%redraws, qp), redraws_expected, &
            ", against n P(outside)/P(inside).")
        call answer(unit, "c2.collapsed", itoa(counts%collapsed), "Runs of the main" &
            //" sample that ended in the quasi-plastic case (collapse limit taken).")
        call answer(unit, "c2.incomplete", itoa(counts%incomplete), "Runs of the main" &
            //" sample stopped by max_collisions before their end.")
        call answer(unit, "c2.collisions", itoa(counts%collisions), "Binary collisions of" &
            //" the runs of the main sample, all together.")
        if (exact) then
            call answer(unit, "c2.region_e_min", str(bound), "Smallest e above which" &
                //" sphere 4 is struck once, so that v4 = v0((1+e)/2)^3, by bisection on" &
                //" the engine's collision record in real128", "two_minus_sqrt3", bound, &
                2.0_qp - sqrt(3.0_qp), "; the check, the root of e^2-4e+1, is matched," &
                //" not derived here.")
            call answer(unit, "c2.outside_region", itoa(outside), "Sampled e below" &
                //" region_e_min, where the exact law does not hold", "expected_count", &
                real(outside, qp), outside_expected, ", against n P(0 <= e < bound)/P(inside).")
            call answer(unit, "c2.closed_form_reruns", itoa(reruns), "Sampled e (every" &
                //" n/1000-th and the extremes, inside the region) re-run in real128 for" &
                //" the next row.")
            call answer(unit, "c2.closed_form_max_diff", str(max_diff), "Largest" &
                //" |v4 - v0((1+e)/2)^3| over those re-runs, both in real128.")
            call answer(unit, "c2.closed_form_checks", itoa(checks), "Samples (every" &
                //" n/"//itoa(closed_form_checks)//"-th of the main sample) whose stored" &
                //" v4 is compared with the closed form in the next row.")
            call answer(unit, "c2.closed_form_mismatches", itoa(mismatches), "Stored v4" &
                //" (doubles) of those samples inside the region that differ from the" &
                //" closed form rounded to a double.")
        end if
        call answer(unit, "c2.mean", dstr(v_mean), "Sample mean of v4 (shifted sums in" &
            //" double, good to 1e-11 of sd)", "closed_form", real(v_mean, qp), m_exact, &
            ", against v0((1+m)^3+3(1+m)s^2)/8.")
        call answer(unit, "c2.sd", dstr(v_sd), "Sample standard deviation (divisor n-1)" &
            //" in double", "closed_form", real(v_sd, qp), s_exact, ", against" &
            //" v0 sqrt(9u^4s^2+36u^2s^4+15s^6)/8, u = 1+m.")
        call answer(unit, "c2.z975", str(z975), "Normal quantile z_0.975 from GSL's" &
            //" gsl_cdf_ugaussian_Pinv, used for the interval of the mean (n >= 100).")
        call answer(unit, "c2.mean_ci_half_width", str(half_width), "z_0.975 sd/sqrt(n)" &
            //" with the sample sd", "closed_form", half_width, &
            z975*s_exact/sqrt(real(n, qp)), ", against the same with the exact sd.")
        call answer(unit, "c2.mean_ci_low", str(v_mean - half_width), "Lower end of the" &
            //" 95 % interval of the mean", "closed_form_mean", v_mean - half_width, m_exact, &
            "; a negative difference means the exact mean lies above it.")
        call answer(unit, "c2.mean_ci_high", str(v_mean + half_width), "Upper end of the" &
            //" 95 % interval of the mean", "closed_form_mean", v_mean + half_width, m_exact, &
            "; a positive difference means the exact mean lies below it.")
        call answer(unit, "c2.q025", dstr(q025), "2.5 % quantile of v4 by a radix sort and" &
            //" gsl_stats_quantile_from_sorted_data", "closed_form", real(q025, qp), &
            cubic_law_quantile(0.025_qp, mean, sd, scene%v0), &
            ", against v0((1+m+s z_0.025)/2)^3.")
        call answer(unit, "c2.q975", dstr(q975), "97.5 % quantile of v4 likewise", &
            "closed_form", real(q975, qp), cubic_law_quantile(0.975_qp, mean, sd, scene%v0), &
            ", against v0((1+m+s z_0.975)/2)^3.")
        if (exact) then
            call answer(unit, "c2.ks_distance", dstr(ks), "Sup distance of the empirical" &
                //" distribution of v4 to the exact law Phi((2(v/v0)^(1/3)-1-m)/s)", &
                "ks_critical_95", real(ks, qp), ks_95/sqrt(real(n, qp)), &
                ", against the 5 % critical value 1.3581/sqrt(n).")
        end if
    end subroutine write_answers

    !> One row of c2_answers.tsv: `text` is the value as printed, `how` says
    !> how it was obtained. With a check (and, for a check by the exact law,
    !> only on the definition's row), `value` - `check_value` is the
    !> difference and `how_check` ends the sentence.
    subroutine answer(unit, key_, text, how, check, value_, check_value, how_check)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: key_, text, how
        character(len=*), intent(in), optional :: check, how_check
        real(qp), intent(in), optional :: value_, check_value
        character(len=:), allocatable :: checks
        logical :: checked
        checked = present(check)
        if (checked) checked = exact .or. index(check, "normal") == 1 &
            .or. check == "expected_count"
        if (checked) then
            checks = check//tab//str(check_value)//tab//str(value_ - check_value)//tab &
                //how//how_check
        else if (present(check)) then
            checks = "-"//tab//"-"//tab//"-"//tab//how//"; this row has no closed form."
        else
            checks = "-"//tab//"-"//tab//"-"//tab//how
        end if
        write (unit, "(a)") key_//tab//text//tab//checks
    end subroutine answer

    !> c2_ecdf.tsv: the empirical distribution function at every k-th order
    !> statistic (and the first and last), with the normal law of the sample's
    !> mean and deviation and the exact law at the same v4.
    subroutine write_ecdf(unit)
        integer, intent(in) :: unit
        integer :: i, k
        character(len=:), allocatable :: exact_text
        write (unit, "(a)") "rank[1]"//tab//"v4[V]"//tab//"ecdf[1]"//tab//"normal_cdf[1]" &
            //tab//"exact_cdf[1]"
        k = max(1, n/ecdf_rows)
        do i = 1, n
            if (.not. ecdf_row(i, k)) cycle
            exact_text = "-"
            if (exact) exact_text = dstr(cubic_law_cdf(work(i), mean, sd, scene%v0))
            write (unit, "(a)") itoa(i)//tab//dstr(work(i))//tab &
                //dstr(real(i, dp)/real(n, dp))//tab &
                //dstr(normal_cdf(work(i), real(v_mean, qp), real(v_sd, qp)))//tab//exact_text
        end do
    end subroutine write_ecdf

    !> Rows of the distribution function table: every k-th order statistic,
    !> the first and last, and in the outer k of each tail every k/20-th, so
    !> that the tails (where the laws differ most in relative terms) are drawn
    !> with points too.
    pure logical function ecdf_row(i, k)
        integer, intent(in) :: i, k
        ecdf_row = i == 1 .or. i == n .or. mod(i, k) == 0
        if (i < k .or. i > n - k) ecdf_row = ecdf_row .or. mod(i, max(1, k/20)) == 0
    end function ecdf_row

    !> c2_histogram.tsv: `bins` equal bins from the smallest to the largest v4
    !> of the main sample, with the exact density and the normal density of the
    !> sample's mean and deviation at each centre.
    subroutine write_histogram(unit)
        integer, intent(in) :: unit
        integer, allocatable :: hits(:)
        real(dp) :: low, width, centre, density
        character(len=:), allocatable :: exact_text
        integer :: i, j
        allocate (hits(bins), source=0)
        low = work(1)
        width = (work(n) - low)/bins
        if (.not. (width > 0.0_dp)) width = 1.0_dp
        do i = 1, n
            j = min(bins, 1 + int((work(i) - low)/width))
            hits(j) = hits(j) + 1
        end do
        write (unit, "(a)") "v4_centre[V]"//tab//"count[1]"//tab//"density[1/V]"//tab &
            //"exact_density[1/V]"//tab//"normal_density[1/V]"
        do j = 1, bins
            centre = low + (j - 0.5_dp)*width
            density = real(hits(j), dp)/(real(n, dp)*width)
            exact_text = "-"
            if (exact) exact_text = dstr(cubic_law_density(centre, mean, sd, scene%v0))
            write (unit, "(a)") dstr(centre)//tab//itoa(hits(j))//tab//dstr(density)//tab &
                //exact_text//tab//dstr(normal_density(centre, real(v_mean, qp), &
                real(v_sd, qp)))
        end do
    end subroutine write_histogram

    !> c2_convergence.tsv: the statistics of the prefixes N = 10^2, 10^3, ...
    !> (and n and nmax) of the stream; the row N = n is the main sample's.
    !> `work` is reused for each sorted prefix, so this table is written last.
    subroutine write_convergence(unit)
        integer, intent(in) :: unit
        integer, allocatable :: sizes(:)
        integer :: j, m
        real(dp) :: p_mean, p_sd
        real(qp) :: p_half, m_exact
        real(dp) :: p_q025, p_q975
        character(len=:), allocatable :: exact_text
        write (unit, "(a)") "n[1]"//tab//"mean[V]"//tab//"sd[V]"//tab//"ci_half_width[V]" &
            //tab//"half_width_sqrt_n[V]"//tab//"q025[V]"//tab//"q975[V]"//tab &
            //"mean_minus_exact[V]"
        sizes = [integer ::]
        m = 100
        do while (m <= nmax)
            sizes = [sizes, m]
            if (m > nmax/10) exit
            m = 10*m
        end do
        if (all(sizes /= n)) sizes = [sizes, n]
        if (all(sizes /= nmax)) sizes = [sizes, nmax]
        call sort_sizes(sizes)
        m_exact = cubic_law_mean(mean, sd, scene%v0)
        do j = 1, size(sizes)
            m = sizes(j)
            if (m == n) then
                ! the main sample is this very prefix: its statistics are known
                p_mean = v_mean
                p_sd = v_sd
                p_q025 = q025
                p_q975 = q975
            else
                call sample_moments(v4(:m), p_mean, p_sd)
                work(:m) = v4(:m)
                call sort_values(work(:m))
                p_q025 = sorted_quantile(work(:m), 0.025_dp)
                p_q975 = sorted_quantile(work(:m), 0.975_dp)
            end if
            p_half = mean_ci_half_width(real(p_sd, qp), m, confidence)
            exact_text = "-"
            if (exact) exact_text = str(p_mean - m_exact)
            write (unit, "(a)") itoa(m)//tab//dstr(p_mean)//tab//dstr(p_sd)//tab//str(p_half) &
                //tab//str(p_half*sqrt(real(m, qp)))//tab//dstr(p_q025)//tab//dstr(p_q975) &
                //tab//exact_text
        end do
    end subroutine write_convergence

    !> Insertion sort of the few table sizes.
    pure subroutine sort_sizes(sizes)
        integer, intent(inout) :: sizes(:)
        integer :: j, k, t
        do j = 2, size(sizes)
            t = sizes(j)
            k = j - 1
            do while (k >= 1)
                if (sizes(k) <= t) exit
                sizes(k + 1) = sizes(k)
                k = k - 1
            end do
            sizes(k + 1) = t
        end do
    end subroutine sort_sizes

    !> A double with 17 significant digits, enough to give back its bits.
    pure function dstr(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        s = real_str(real(x, qp), 17)
    end function dstr

    !> Three decimals with the leading zero that f0.3 leaves out.
    pure function fixed(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        character(len=32) :: buf
        write (buf, "(f32.3)") x
        s = trim(adjustl(buf))
    end function fixed

end program c12_c2
