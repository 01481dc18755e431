!> Task c2's statistics and tables from a Monte Carlo stream of v4 (the
!> sampling itself is monte_carlo_v4's): the main answers from the first n
!> samples, their checks against the exact law v4 = v0 ((1+e)/2)^3 where it
!> applies, and c2_answers.tsv, c2_ecdf.tsv, c2_histogram.tsv and
!> c2_convergence.tsv, whose row N = n of the prefixes is the main answer.
module sphere_row_c2_tables
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp, scene_t, run_t, simulate, str, real_str, itoa, &
        status_normal
    use sphere_row_monte_carlo, only: mc_counts_t, normal_mass_outside_unit, normal_cdf, &
        normal_density, sample_moments, normal_quantile, mean_ci_half_width, sort_values, &
        sorted_quantile, cubic_law_applies, cubic_law_mean, cubic_law_sd, &
        cubic_law_quantile, cubic_law_cdf, cubic_law_density, cubic_law_v4, single_impact_bound, &
        cubic_law_ks_distance
    use sphere_row_tables, only: tab, row_t, write_rows, open_table, close_table, discard_tables
    use sphere_row_error, only: error_t, fatal_error, error_io, error_output
    implicit none
    private
    public :: c2_sample_t, c2_statistics, c2_write_tables

    !> Rows of the empirical distribution function table (every k-th order statistic).
    integer, parameter :: ecdf_rows = 1000
    !> Significant digits of a double in the tables, enough to give back its bits.
    integer, parameter :: dp_digits = 17
    !> Sampled e re-run to compare the engine with the closed form in real128,
    !> and stored v4 compared with the closed form rounded to a double.
    integer, parameter :: closed_form_reruns = 1000, closed_form_checks = 100000
    real(qp), parameter :: confidence = 0.95_qp
    !> Asymptotic 95 % quantile of the Kolmogorov distribution: a sample of the
    !> law itself exceeds ks_95/sqrt(n) with probability 5 %.
    real(qp), parameter :: ks_95 = 1.3581_qp
    !> Bracket of the bisection for the region of one impact on sphere 4: at
    !> e = 0.2 it is struck three times, at e = 1 (elastic) once.
    real(qp), parameter :: bracket_lo = 0.2_qp, bracket_hi = 1.0_qp

    !> One stream of c2 (its settings and samples, set by the program) and
    !> the answers c2_statistics finds in it.
    type :: c2_sample_t
        !> Main sample size, stream length, seed of the stream, histogram bins.
        integer :: n = 0, nmax = 0, seed = 0, bins = 0
        !> The normal law of e and the scene's v0.
        real(qp) :: mean = 0.0_qp, sd = 0.0_qp, v0 = 0.0_qp
        !> Counts of the main sample's runs.
        type(mc_counts_t) :: counts
        !> The precision of the runs ("auto" or "qp") and, with auto, the runs
        !> escalated to real(16) in the whole stream (nmax runs).
        character(len=:), allocatable :: precision
        integer(int64) :: escalated_nmax = 0
        !> v4 and e of the stream (size nmax), and work space for sorted prefixes.
        real(dp), allocatable :: v4(:), e(:), work(:)
        !> Whether the exact law applies (the definition's row).
        logical :: exact = .false.
        !> The answers of the main sample (statistics in double: see sample_moments).
        real(dp) :: v_mean = 0.0_dp, v_sd = 0.0_dp, e_mean = 0.0_dp, e_sd = 0.0_dp
        real(qp) :: half_width = 0.0_qp, z975 = 0.0_qp
        real(dp) :: q025 = 0.0_dp, q975 = 0.0_dp, ks = 0.0_dp
        !> Checks against the exact law (definition's row only).
        real(qp) :: bound = 0.0_qp, max_diff = 0.0_qp, redraws_expected = 0.0_qp
        real(qp) :: outside_expected = 0.0_qp
        integer :: outside = 0, reruns = 0, mismatches = 0, checks = 0
    end type c2_sample_t

contains

    !> The main answers from the first n samples of `c` and, where the exact
    !> law applies to `scene`, their checks against it; `error` says why if the
    !> region of the law is not found.
    subroutine c2_statistics(c, scene, error)
        type(c2_sample_t), intent(inout) :: c
        type(scene_t), intent(in) :: scene
        type(error_t), allocatable, intent(out) :: error
        allocate (c%work(c%nmax))
        call sample_moments(c%v4(:c%n), c%v_mean, c%v_sd)
        call sample_moments(c%e(:c%n), c%e_mean, c%e_sd)
        c%z975 = normal_quantile(0.5_qp + confidence/2)
        c%half_width = mean_ci_half_width(real(c%v_sd, qp), c%n, confidence)
        call sort_prefix(c, c%n)
        c%q025 = sorted_quantile(c%work(:c%n), 0.025_dp)
        c%q975 = sorted_quantile(c%work(:c%n), 0.975_dp)
        c%exact = cubic_law_applies(scene)
        c%ks = -1.0_dp
        if (c%exact) c%ks = cubic_law_ks_distance(c%work(:c%n), c%mean, c%sd, c%v0)
        c%redraws_expected = c%n*real(normal_mass_outside_unit(c%mean, c%sd), qp) &
            /(1.0_qp - real(normal_mass_outside_unit(c%mean, c%sd), qp))
        if (c%exact) call c2_check_closed_form(c, scene, error)
    end subroutine c2_statistics

    !> Where the exact law applies: the bound of the region of one impact on
    !> sphere 4 (bisection with the engine), the samples below it, the engine
    !> against v0 ((1+e)/2)^3 in real128 on a subset re-run, and the stored v4
    !> of every (n/closed_form_checks)-th sample against the closed form (a
    !> subsample: in real128 each check costs a tenth of a run): a stored v4
    !> must be no farther from it than the closed form rounded to a double is,
    !> plus the largest certified bound of a real(64) run (0 in real(16) only,
    !> where the test is equality with the rounded closed form).
    !> `error` says why if the bound is not found.
    subroutine c2_check_closed_form(c, scene, error)
        type(c2_sample_t), intent(inout) :: c
        type(scene_t), intent(in) :: scene
        type(error_t), allocatable, intent(out) :: error
        character(len=300) :: msg
        integer :: stat
        real(qp) :: inside
        call single_impact_bound(scene, bracket_lo, bracket_hi, c%bound, stat, msg)
        if (stat /= status_normal) then
            call fatal_error(error, trim(msg))
            return
        end if
        c%outside = count_below(c%e(:c%n), c%bound)
        inside = 1.0_qp - real(normal_mass_outside_unit(c%mean, c%sd), qp)
        c%outside_expected = c%n*(real(normal_cdf(real(c%bound, dp), c%mean, c%sd), qp) &
            - real(normal_cdf(0.0_dp, c%mean, c%sd), qp))/inside
        call rerun_closed_form(c, scene)
        call check_stored_v4(c)
    end subroutine c2_check_closed_form

    !> Every n/closed_form_reruns-th sample of the main sample and those of the
    !> smallest and the largest e, where inside the region of one impact,
    !> re-run with the engine in real128 and compared with the closed form:
    !> `c%reruns` of them, the largest difference `c%max_diff`. The runs are
    !> shared among the OpenMP threads; a maximum and a count do not depend
    !> on the order they are taken in.
    subroutine rerun_closed_form(c, scene)
        type(c2_sample_t), intent(inout) :: c
        type(scene_t), intent(in) :: scene
        type(scene_t) :: trial
        type(run_t) :: run
        integer, allocatable :: picks(:)
        real(qp), allocatable :: diff(:)
        integer :: stride, i, k, i_min, i_max
        stride = max(1, c%n/closed_form_reruns)
        call extreme_places(c%e(:c%n), i_min, i_max)
        picks = [(i, i=stride, c%n, stride), i_min, i_max]
        ! -1 marks a sample outside the region, not re-run
        allocate (diff(size(picks)), source=-1.0_qp)
        !$omp parallel do schedule(dynamic, 8) default(shared) private(k, trial, run)
        do k = 1, size(picks)
            trial = scene
            trial%e = real(c%e(picks(k)), qp)
            if (trial%e < c%bound) cycle
            call simulate(trial, run)
            diff(k) = abs(run%v(4) - cubic_law_v4(trial%e, c%v0))
        end do
        !$omp end parallel do
        c%reruns = count(diff >= 0.0_qp)
        c%max_diff = max(0.0_qp, maxval(diff))
    end subroutine rerun_closed_form

    !> The places of the smallest and the largest of x, the first of each as
    !> minloc and maxloc give them: each chunk's on an OpenMP thread, the
    !> chunks' joined in chunk order (a later chunk wins only with a strictly
    !> smaller or larger value), so the same places on any number of threads.
    subroutine extreme_places(x, i_min, i_max)
        real(dp), intent(in) :: x(:)
        integer, intent(out) :: i_min, i_max
        !> Values per chunk.
        integer, parameter :: chunk = 65536
        integer, allocatable :: at_min(:), at_max(:)
        integer :: j, chunks, before, last
        chunks = max(1, (size(x) - 1)/chunk + 1)
        allocate (at_min(chunks), at_max(chunks))
        !$omp parallel do schedule(static) default(shared) private(j, before, last)
        do j = 1, chunks
            before = (j - 1)*chunk
            last = min(size(x), before + chunk)
            at_min(j) = before + minloc(x(before + 1:last), 1)
            at_max(j) = before + maxloc(x(before + 1:last), 1)
        end do
        !$omp end parallel do
        i_min = at_min(1)
        i_max = at_max(1)
        do j = 2, chunks
            if (x(at_min(j)) < x(i_min)) i_min = at_min(j)
            if (x(at_max(j)) > x(i_max)) i_max = at_max(j)
        end do
    end subroutine extreme_places

    !> The stored v4 of every (n/closed_form_checks)-th sample of the main
    !> sample inside the region against the closed form: `c%checks` samples
    !> looked at, `c%mismatches` of them farther from it than the closed form
    !> rounded to a double plus the largest certified bound (counted on the
    !> OpenMP threads: a sum of integers).
    subroutine check_stored_v4(c)
        type(c2_sample_t), intent(inout) :: c
        real(qp) :: e_q, exact
        integer :: stride, i, mismatches
        stride = max(1, c%n/closed_form_checks)
        mismatches = 0
        !$omp parallel do schedule(static) default(shared) private(i, e_q, exact) &
        !$omp reduction(+: mismatches)
        do i = stride, c%n, stride
            e_q = real(c%e(i), qp)
            if (e_q < c%bound) cycle
            exact = cubic_law_v4(e_q, c%v0)
            if (abs(c%v4(i) - exact) > abs(real(exact, dp) - exact) + c%counts%bound_max) then
                mismatches = mismatches + 1
            end if
        end do
        !$omp end parallel do
        c%mismatches = mismatches
        c%checks = c%n/stride
    end subroutine check_stored_v4

    !> The first m samples of v4 sorted into `c%work`.
    subroutine sort_prefix(c, m)
        type(c2_sample_t), intent(inout) :: c
        integer, intent(in) :: m
        call sort_values(c%work(:m), c%v4(:m))
    end subroutine sort_prefix

    !> How many of the doubles x lie below the real(16) number b, compared in
    !> double: with b_d the double nearest b, x < b if and only if x < b_d
    !> where b_d >= b, and x <= b_d where b_d < b (no double lies between b
    !> and b_d). Counted on the OpenMP threads (a sum of integers).
    integer function count_below(x, b) result(below)
        real(dp), intent(in) :: x(:)
        real(qp), intent(in) :: b
        real(dp) :: b_d
        logical :: or_equal
        integer :: i
        b_d = real(b, dp)
        or_equal = real(b_d, qp) < b
        below = 0
        !$omp parallel do schedule(static) default(shared) private(i) reduction(+: below)
        do i = 1, size(x)
            if (x(i) < b_d .or. (or_equal .and. x(i) == b_d)) below = below + 1
        end do
        !$omp end parallel do
    end function count_below

    !> Open every table first, so that a directory that cannot be written is
    !> refused before anything is in it; then write them. `error` names the
    !> directory or table that cannot be written.
    subroutine c2_write_tables(c, out, error)
        type(c2_sample_t), intent(inout) :: c
        character(len=*), intent(in) :: out
        type(error_t), allocatable, intent(out) :: error
        integer :: units(4), ios, k, exitstat, cmdstat
        character(len=300) :: msg
        logical :: there
        character(len=*), parameter :: names(4) = [character(len=20) :: &
            "c2_answers.tsv", "c2_ecdf.tsv", "c2_histogram.tsv", "c2_convergence.tsv"]
        inquire (file=out//"/.", exist=there)
        if (.not. there) then
            call execute_command_line("mkdir -p '"//out//"' 2>/dev/null", exitstat=exitstat, &
                cmdstat=cmdstat)
            if (cmdstat /= 0 .or. exitstat /= 0) then
                call fatal_error(error, "out = '"//out//"': the directory cannot be created", &
                    error_io)
                return
            end if
        end if
        units = -1
        do k = 1, size(names)
            call open_table(out, trim(names(k)), "", units(k), ios, msg)
            if (ios /= status_normal) then
                call discard_tables()
                call fatal_error(error, trim(msg), error_io)
                return
            end if
        end do
        call write_answers(c, units(1))
        call write_ecdf(c, units(2))
        call write_histogram(c, units(3))
        call write_convergence(c, units(4))
        do k = 1, size(units)
            call close_table(units(k), ios, msg)
            if (ios /= status_normal) then
                call discard_tables()
                call fatal_error(error, trim(msg), error_output)
                return
            end if
        end do
    end subroutine c2_write_tables

    !> c2_answers.tsv: one row per answer with its independent check. The
    !> checks by the exact law exist for the definition's row only; elsewhere
    !> their columns are `-` and the rows about its region are left out.
    subroutine write_answers(c, unit)
        type(c2_sample_t), intent(in) :: c
        integer, intent(in) :: unit
        real(qp) :: m_exact, s_exact
        m_exact = cubic_law_mean(c%mean, c%sd, c%v0)
        s_exact = cubic_law_sd(c%mean, c%sd, c%v0)
        write (unit, "(a)") "key"//tab//"value"//tab//"check"//tab//"check_value"//tab &
            //"difference"//tab//"how"
        call answer(unit, "c2.n", itoa(c%n), "Size of the main sample: the first n runs of" &
            //" the stream, from which every statistic below is taken.")
        call answer(unit, "c2.nmax", itoa(c%nmax), "Largest N of the convergence table;" &
            //" runs n+1..nmax continue the same stream.")
        call answer(unit, "c2.seed", itoa(c%seed), "Seed of GSL's MT19937 whose uniforms" &
            //" give e by Box-Muller (both normals of each pair used).")
        call answer(unit, "c2.e_mean", dstr(c%e_mean), "Mean of the sampled e (shifted sums" &
            //" in double)", "normal_mean", real(c%e_mean, qp), c%mean, &
            ", against the mean of the normal law.")
        call answer(unit, "c2.e_sd", dstr(c%e_sd), "Standard deviation of the sampled e", &
            "normal_sd", real(c%e_sd, qp), c%sd, ", against that of the normal law.")
        call answer(unit, "c2.redraws", itoa(c%counts%redraws), "Normal draws outside" &
            //" 0 <= e <= 1, discarded and drawn again (the law is truncated to [0,1])", &
            "expected_count", real(c%counts%redraws, qp), c%redraws_expected, &
            ", against n P(outside)/P(inside).")
        call answer(unit, "c2.collapsed", itoa(c%counts%collapsed), "Runs of the main" &
            //" sample that ended in the quasi-plastic case (collapse limit taken).")
        call answer(unit, "c2.incomplete", itoa(c%counts%incomplete), "Runs of the main" &
            //" sample stopped by max_collisions before their end.")
        call answer(unit, "c2.collisions", itoa(c%counts%collisions), "Binary collisions of" &
            //" the runs of the main sample, all together.")
        call precision_answers(c, unit)
        if (c%exact) then
            call answer(unit, "c2.region_e_min", str(c%bound), "Smallest e above which" &
                //" sphere 4 is struck once, so that v4 = v0((1+e)/2)^3, by bisection on" &
                //" the engine's collision record in real128", "two_minus_sqrt3", c%bound, &
                2.0_qp - sqrt(3.0_qp), "; the check, the root of e^2-4e+1, is matched," &
                //" not derived here.")
            call answer(unit, "c2.outside_region", itoa(c%outside), "Sampled e below" &
                //" region_e_min, where the exact law does not hold", "expected_count", &
                real(c%outside, qp), c%outside_expected, &
                ", against n P(0 <= e < bound)/P(inside).")
            call answer(unit, "c2.closed_form_reruns", itoa(c%reruns), "Sampled e (every" &
                //" n/1000-th and the extremes, inside the region) re-run in real128 for" &
                //" the next row.")
            call answer(unit, "c2.closed_form_max_diff", str(c%max_diff), "Largest" &
                //" |v4 - v0((1+e)/2)^3| over those re-runs, both in real128.")
            call answer(unit, "c2.closed_form_checks", itoa(c%checks), "Samples (every" &
                //" n/"//itoa(closed_form_checks)//"-th of the main sample) whose stored" &
                //" v4 is compared with the closed form in the next row.")
            call answer(unit, "c2.closed_form_mismatches", itoa(c%mismatches), "Stored v4" &
                //" (doubles) of those samples inside the region farther from the closed" &
                //" form than its rounding to a double plus v4_bound_max.")
        end if
        call answer(unit, "c2.mean", dstr(c%v_mean), "Sample mean of v4 (shifted sums in" &
            //" double, good to 1e-11 of sd)", "closed_form", real(c%v_mean, qp), m_exact, &
            ", against v0((1+m)^3+3(1+m)s^2)/8.")
        call answer(unit, "c2.sd", dstr(c%v_sd), "Sample standard deviation (divisor n-1)" &
            //" in double", "closed_form", real(c%v_sd, qp), s_exact, ", against" &
            //" v0 sqrt(9u^4s^2+36u^2s^4+15s^6)/8, u = 1+m.")
        call answer(unit, "c2.z975", str(c%z975), "Normal quantile z_0.975 from GSL's" &
            //" gsl_cdf_ugaussian_Pinv, used for the interval of the mean (n >= 100).")
        call answer(unit, "c2.mean_ci_half_width", str(c%half_width), "z_0.975 sd/sqrt(n)" &
            //" with the sample sd", "closed_form", c%half_width, &
            c%z975*s_exact/sqrt(real(c%n, qp)), ", against the same with the exact sd.")
        call answer(unit, "c2.mean_ci_low", str(c%v_mean - c%half_width), "Lower end of the" &
            //" 95 % interval of the mean", "closed_form_mean", c%v_mean - c%half_width, m_exact, &
            "; a negative difference means the exact mean lies above it.")
        call answer(unit, "c2.mean_ci_high", str(c%v_mean + c%half_width), "Upper end of the" &
            //" 95 % interval of the mean", "closed_form_mean", c%v_mean + c%half_width, m_exact, &
            "; a positive difference means the exact mean lies below it.")
        call answer(unit, "c2.q025", dstr(c%q025), "2.5 % quantile of v4 by a radix sort and" &
            //" gsl_stats_quantile_from_sorted_data", "closed_form", real(c%q025, qp), &
            cubic_law_quantile(0.025_qp, c%mean, c%sd, c%v0), &
            ", against v0((1+m+s z_0.025)/2)^3.")
        call answer(unit, "c2.q975", dstr(c%q975), "97.5 % quantile of v4 likewise", &
            "closed_form", real(c%q975, qp), cubic_law_quantile(0.975_qp, c%mean, c%sd, c%v0), &
            ", against v0((1+m+s z_0.975)/2)^3.")
        if (c%exact) then
            call answer(unit, "c2.ks_distance", dstr(c%ks), "Sup distance of the empirical" &
                //" distribution of v4 to the exact law Phi((2(v/v0)^(1/3)-1-m)/s)", &
                "ks_critical_95", real(c%ks, qp), ks_95/sqrt(real(c%n, qp)), &
                ", against the 5 % critical value 1.3581/sqrt(n).")
        end if

    contains

        !> One row of c2_answers.tsv: `text` is the value as printed, `how` says
        !> how it was obtained. With a check (and, for a check by the exact law,
        !> only on the definition's row), `value` - `check_value` is the
        !> difference and `how_check` ends the sentence.
        subroutine answer(unit, key_, text, how, check, value_, check_value, how_check)
            integer, intent(in) :: unit
            character(len=*), intent(in) :: key_, text, how
            character(len=*), intent(in), optional :: check, how_check
            real(qp), intent(in), optional :: value_, check_value
            character(len=:), allocatable :: columns
            logical :: checked
            checked = present(check)
            if (checked) checked = c%exact .or. index(check, "normal") == 1 &
                .or. check == "expected_count"
            if (checked) then
                columns = check//tab//str(check_value)//tab//str(value_ - check_value)//tab &
                    //how//how_check
            else if (present(check)) then
                columns = "-"//tab//"-"//tab//"-"//tab//how//"; this row has no closed form."
            else
                columns = "-"//tab//"-"//tab//"-"//tab//how
            end if
            write (unit, "(a)") key_//tab//text//tab//columns
        end subroutine answer

    end subroutine write_answers

    !> The rows of c2_answers.tsv on the precision of the runs: which one was
    !> asked for and, with auto, the runs escalated to real(16) (the main
    !> sample's and the whole stream's) and the largest certified bound.
    subroutine precision_answers(c, unit)
        type(c2_sample_t), intent(in) :: c
        integer, intent(in) :: unit
        character(len=*), parameter :: none = "-"//tab//"-"//tab//"-"//tab
        write (unit, "(a)") "c2.precision"//tab//c%precision//tab//none//"Precision of the" &
            //" runs: auto (real64 where its rounding certificate holds, else real128) or qp" &
            //" (real128 throughout)."
        if (c%precision /= "auto") return
        write (unit, "(a)") "c2.escalated"//tab//itoa(c%counts%escalated)//tab//none &
            //"Runs of the main sample whose real64 certificate failed (a decision too close" &
            //" to call, or a run the engine must finish), run again in real128."
        write (unit, "(a)") "c2.escalated_nmax"//tab//itoa(c%escalated_nmax)//tab//none &
            //"The same over the whole stream of nmax runs."
        write (unit, "(a)") "c2.v4_bound_max"//tab//dstr(c%counts%bound_max)//tab//none &
            //"Largest certified bound on |v4(real64) - v4(real128)| over the real64 runs of" &
            //" the main sample; their collision sequences are real128's."
    end subroutine precision_answers

    !> c2_ecdf.tsv: the empirical distribution function at every k-th order
    !> statistic (and the first and last), with the normal law of the sample's
    !> mean and deviation and the exact law at the same v4. The rows are
    !> formatted on the OpenMP threads (see row_t) and written in order.
    subroutine write_ecdf(c, unit)
        type(c2_sample_t), intent(in) :: c
        integer, intent(in) :: unit
        integer, allocatable :: ranks(:)
        type(row_t), allocatable :: rows(:)
        integer :: i, j
        write (unit, "(a)") "rank[1]"//tab//"v4[V]"//tab//"ecdf[1]"//tab//"normal_cdf[1]" &
            //tab//"exact_cdf[1]"
        ranks = ecdf_ranks(c%n)
        allocate (rows(size(ranks)))
        !$omp parallel do schedule(static) default(shared) private(i, j)
        do j = 1, size(ranks)
            i = ranks(j)
            call rows(j)%add(i)
            call rows(j)%add(real(c%work(i), qp), dp_digits)
            call rows(j)%add(real(real(i, dp)/real(c%n, dp), qp), dp_digits)
            call rows(j)%add(real(normal_cdf(c%work(i), real(c%v_mean, qp), &
                real(c%v_sd, qp)), qp), dp_digits)
            if (c%exact) then
                call rows(j)%add(real(cubic_law_cdf(c%work(i), c%mean, c%sd, c%v0), qp), &
                    dp_digits)
            else
                call rows(j)%add("-")
            end if
        end do
        !$omp end parallel do
        call write_rows(unit, rows)
    end subroutine write_ecdf

    !> The ranks of the rows of c2_ecdf.tsv for a sample of n: every k-th
    !> order statistic (k = n/ecdf_rows), the first and last, and in the outer
    !> k of each tail every k/20-th, so that the tails (where the laws differ
    !> most in relative terms) are drawn with points too. Between the tails
    !> only the multiples of k are looked at.
    pure function ecdf_ranks(n) result(ranks)
        integer, intent(in) :: n
        integer, allocatable :: ranks(:)
        integer :: k, fine, i, rows
        k = max(1, n/ecdf_rows)
        fine = max(1, k/20)
        allocate (ranks(n/k + 2*k + 2))
        rows = 0
        i = 1
        do while (i <= n)
            if (i == 1 .or. i == n .or. mod(i, k) == 0 .or. &
                ((i < k .or. i > n - k) .and. mod(i, fine) == 0)) then
                rows = rows + 1
                ranks(rows) = i
            end if
            if (i + 1 < k .or. i + 1 > n - k) then
                i = i + 1
            else
                i = min((i/k + 1)*k, n - k + 1)
            end if
        end do
        ranks = ranks(:rows)
    end function ecdf_ranks

    !> c2_histogram.tsv: `bins` equal bins from the smallest to the largest v4
    !> of the main sample, with the exact density and the normal density of the
    !> sample's mean and deviation at each centre. The rows are formatted on
    !> the OpenMP threads (see row_t) and written in order.
    subroutine write_histogram(c, unit)
        type(c2_sample_t), intent(in) :: c
        integer, intent(in) :: unit
        integer, allocatable :: hits(:)
        type(row_t), allocatable :: rows(:)
        real(dp) :: low, width, centre, density
        integer :: i, j
        allocate (hits(c%bins), source=0)
        low = c%work(1)
        width = (c%work(c%n) - low)/c%bins
        if (.not. (width > 0.0_dp)) width = 1.0_dp
        ! counts: the same sums on any number of threads
        !$omp parallel do schedule(static) default(shared) private(i, j) reduction(+: hits)
        do i = 1, c%n
            j = min(c%bins, 1 + int((c%work(i) - low)/width))
            hits(j) = hits(j) + 1
        end do
        !$omp end parallel do
        write (unit, "(a)") "v4_centre[V]"//tab//"count[1]"//tab//"density[1/V]"//tab &
            //"exact_density[1/V]"//tab//"normal_density[1/V]"
        allocate (rows(c%bins))
        !$omp parallel do schedule(static) default(shared) private(j, centre, density)
        do j = 1, c%bins
            centre = low + (j - 0.5_dp)*width
            density = real(hits(j), dp)/(real(c%n, dp)*width)
            call rows(j)%add(real(centre, qp), dp_digits)
            call rows(j)%add(hits(j))
            call rows(j)%add(real(density, qp), dp_digits)
            if (c%exact) then
                call rows(j)%add(real(cubic_law_density(centre, c%mean, c%sd, c%v0), qp), &
                    dp_digits)
            else
                call rows(j)%add("-")
            end if
            call rows(j)%add(real(normal_density(centre, real(c%v_mean, qp), &
                real(c%v_sd, qp)), qp), dp_digits)
        end do
        !$omp end parallel do
        call write_rows(unit, rows)
    end subroutine write_histogram

    !> c2_convergence.tsv: the statistics of the prefixes N = 10^2, 10^3, ...
    !> (and n and nmax) of the stream; the row N = n is the main sample's.
    !> The prefixes shorter than n are taken at once, each by one OpenMP
    !> thread into a buffer of its own; the longer ones one after the other,
    !> each on every thread, in `work`, so this table is written last.
    subroutine write_convergence(c, unit)
        type(c2_sample_t), intent(inout) :: c
        integer, intent(in) :: unit
        integer, allocatable :: sizes(:)
        integer :: j, m
        real(dp), allocatable :: p_mean(:), p_sd(:), p_q025(:), p_q975(:), sorted(:)
        real(qp) :: p_half, m_exact
        character(len=:), allocatable :: exact_text
        write (unit, "(a)") "n[1]"//tab//"mean[V]"//tab//"sd[V]"//tab//"ci_half_width[V]" &
            //tab//"half_width_sqrt_n[V]"//tab//"q025[V]"//tab//"q975[V]"//tab &
            //"mean_minus_exact[V]"
        sizes = [integer ::]
        m = 100
        do while (m <= c%nmax)
            sizes = [sizes, m]
            if (m > c%nmax/10) exit
            m = 10*m
        end do
        ! n and nmax put in their places among the ascending powers, once each
        sizes = [pack(sizes, sizes < c%n), c%n, pack(sizes, sizes > c%n)]
        sizes = [pack(sizes, sizes < c%nmax), c%nmax, pack(sizes, sizes > c%nmax)]
        allocate (p_mean(size(sizes)), p_sd(size(sizes)), p_q025(size(sizes)), &
            p_q975(size(sizes)))
        ! the longest first; the sorts and sums inside run on this thread alone
        !$omp parallel do schedule(dynamic, 1) default(shared) private(j, m, sorted)
        do j = size(sizes), 1, -1
            m = sizes(j)
            if (m >= c%n) cycle
            allocate (sorted(m))
            call sample_moments(c%v4(:m), p_mean(j), p_sd(j))
            call sort_values(sorted, c%v4(:m))
            p_q025(j) = sorted_quantile(sorted, 0.025_dp)
            p_q975(j) = sorted_quantile(sorted, 0.975_dp)
            deallocate (sorted)
        end do
        !$omp end parallel do
        do j = 1, size(sizes)
            m = sizes(j)
            if (m == c%n) then
                ! the main sample is this very prefix: its statistics are known
                p_mean(j) = c%v_mean
                p_sd(j) = c%v_sd
                p_q025(j) = c%q025
                p_q975(j) = c%q975
            else if (m > c%n) then
                call sample_moments(c%v4(:m), p_mean(j), p_sd(j))
                call sort_prefix(c, m)
                p_q025(j) = sorted_quantile(c%work(:m), 0.025_dp)
                p_q975(j) = sorted_quantile(c%work(:m), 0.975_dp)
            end if
        end do
        m_exact = cubic_law_mean(c%mean, c%sd, c%v0)
        do j = 1, size(sizes)
            m = sizes(j)
            p_half = mean_ci_half_width(real(p_sd(j), qp), m, confidence)
            exact_text = "-"
            if (c%exact) exact_text = str(p_mean(j) - m_exact)
            write (unit, "(a)") itoa(m)//tab//dstr(p_mean(j))//tab//dstr(p_sd(j))//tab &
                //str(p_half)//tab//str(p_half*sqrt(real(m, qp)))//tab//dstr(p_q025(j))//tab &
                //dstr(p_q975(j))//tab//exact_text
        end do
    end subroutine write_convergence

    !> A double with dp_digits significant digits.
    pure function dstr(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        s = real_str(real(x, qp), dp_digits)
    end function dstr

end module sphere_row_c2_tables
