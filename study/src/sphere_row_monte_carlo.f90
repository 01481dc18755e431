!> Monte Carlo over the restitution coefficient (task c2) and the statistics
!> of its result.
!>
!> e is drawn from a normal law by the Box–Muller transform of MT19937
!> uniforms from GSL, as a double; each draw is converted exactly to real128
!> and the row is run in real128. The final velocity of the last sphere is
!> kept as a double: the statistics have widths of order 1e-4 of v0, so digits
!> beyond a double's carry no information, while the sums over samples are
!> accumulated in real128 so that their rounding never competes with that.
!>
!> The library never stops: refusals come back as status_invalid and a
!> one-line message naming the input, its value and what is allowed.
module sphere_row_monte_carlo
    use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_long, c_size_t
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use sphere_row, only: dp, qp, scene_t, run_t, event_log_t, scene_check, simulate, &
        status_normal, status_collapsed, status_invalid, event_collision, str, real_str
    use sphere_row_gsl, only: gsl_rng_mt19937, gsl_rng_alloc, gsl_rng_set, gsl_rng_uniform_pos, &
        gsl_rng_free, gsl_sort, gsl_stats_quantile_from_sorted_data, gsl_cdf_ugaussian_p, &
        gsl_cdf_ugaussian_pinv
    implicit none
    private
    public :: normal_sampler_t, mc_counts_t, min_acceptance
    public :: monte_carlo_v4, normal_mass_outside_unit, normal_cdf, normal_density
    public :: sample_moments, normal_quantile, mean_ci_half_width, sort_values, sorted_quantile
    public :: ks_distance
    public :: cubic_law_applies, cubic_law_mean, cubic_law_sd, cubic_law_quantile
    public :: cubic_law_cdf, cubic_law_density, cubic_law_v4, single_impact_bound

    !> Smallest share of the normal law that must lie in [0, 1]: samples outside
    !> are drawn again, so a smaller share would multiply the cost (by up to
    !> 1/min_acceptance) and describe a law that is mostly cut away.
    real(dp), parameter :: min_acceptance = 0.1_dp

    ! 2 pi and 1/sqrt(2 pi), to more digits than a double holds
    real(dp), parameter :: two_pi = 6.283185307179586476925286766559005768_dp
    real(dp), parameter :: inv_sqrt_two_pi = 0.3989422804014326779399460599343818685_dp

    !> Standard normal variates by the Box–Muller transform of MT19937 uniforms.
    !>
    !> Each pair of uniforms (u1, u2) gives two independent normals,
    !> r cos(2 pi u2) and r sin(2 pi u2) with r = sqrt(-2 ln u1); both are used,
    !> the second on the next draw. The GSL generator is owned by the object:
    !> call `release` when done, and do not copy a seeded sampler (the copy
    !> would share the generator).
    type :: normal_sampler_t
        private
        type(c_ptr) :: rng = c_null_ptr
        real(dp) :: spare = 0.0_dp
        logical :: have_spare = .false.
    contains
        !> Create the generator if needed and (re)start its stream from a seed.
        procedure :: seed => sampler_seed
        !> Next standard normal variate.
        procedure :: draw => sampler_draw
        !> Free the generator.
        procedure :: release => sampler_release
        !> True once seeded (and not released).
        procedure :: seeded => sampler_seeded
    end type normal_sampler_t

    !> What a Monte Carlo call did besides its samples.
    type :: mc_counts_t
        !> Runs of the engine, one per sample.
        integer(int64) :: runs = 0
        !> Normal draws outside [0, 1] that were discarded and drawn again.
        integer(int64) :: redraws = 0
        !> Runs that ended in the quasi-plastic case (status_collapsed).
        integer(int64) :: collapsed = 0
        !> Runs stopped by the scene's max_collisions (v4 is then the value
        !> after the last collision computed); expected 0.
        integer(int64) :: incomplete = 0
    end type mc_counts_t

contains

    !> Create the generator if needed and start its stream from `seed` >= 1
    !> (MT19937 in GSL maps seed 0 to its default 4357, so 0 is refused to keep
    !> one stream per seed). Clears the stored second normal.
    subroutine sampler_seed(self, seed, stat, msg)
        class(normal_sampler_t), intent(inout) :: self
        integer, intent(in) :: seed
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        stat = status_invalid
        if (seed < 1) then
            write (msg, "(a, i0, a)") "seed = ", seed, ": allowed an integer >= 1"
            return
        end if
        if (.not. c_associated(self%rng)) self%rng = gsl_rng_alloc(gsl_rng_mt19937)
        if (.not. c_associated(self%rng)) then
            msg = "gsl_rng_alloc: no memory for the MT19937 generator"
            return
        end if
        call gsl_rng_set(self%rng, int(seed, c_long))
        self%have_spare = .false.
        stat = status_normal
        msg = ""
    end subroutine sampler_seed

    !> Next standard normal variate; NaN if the sampler was never seeded.
    subroutine sampler_draw(self, z)
        class(normal_sampler_t), intent(inout) :: self
        real(dp), intent(out) :: z
        real(dp) :: radius, angle
        if (self%have_spare) then
            z = self%spare
            self%have_spare = .false.
            return
        end if
        if (.not. c_associated(self%rng)) then
            z = ieee_value(z, ieee_quiet_nan)
            return
        end if
        ! two statements, so that u1 is always the first uniform of the pair
        radius = sqrt(-2.0_dp*log(gsl_rng_uniform_pos(self%rng)))
        angle = two_pi*gsl_rng_uniform_pos(self%rng)
        z = radius*cos(angle)
        self%spare = radius*sin(angle)
        self%have_spare = .true.
    end subroutine sampler_draw

    !> True once seeded (and not released): draws are then defined.
    pure logical function sampler_seeded(self)
        class(normal_sampler_t), intent(in) :: self
        sampler_seeded = c_associated(self%rng)
    end function sampler_seeded

    !> Free the generator (harmless if there is none).
    subroutine sampler_release(self)
        class(normal_sampler_t), intent(inout) :: self
        if (c_associated(self%rng)) call gsl_rng_free(self%rng)
        self%rng = c_null_ptr
        self%have_spare = .false.
    end subroutine sampler_release

    !> Share of the normal law N(mean, sd^2) that lies outside [0, 1], summed
    !> from its two lower tails so that tiny shares keep their digits.
    pure function normal_mass_outside_unit(mean, sd) result(mass)
        real(qp), intent(in) :: mean, sd
        real(dp) :: mass
        mass = gsl_cdf_ugaussian_p(real(-mean/sd, dp)) &
            + gsl_cdf_ugaussian_p(real((mean - 1.0_qp)/sd, dp))
    end function normal_mass_outside_unit

    !> Distribution function of N(mean, sd^2) at x.
    elemental function normal_cdf(x, mean, sd) result(p)
        real(dp), intent(in) :: x
        real(qp), intent(in) :: mean, sd
        real(dp) :: p
        p = gsl_cdf_ugaussian_p((x - real(mean, dp))/real(sd, dp))
    end function normal_cdf

    !> Density of N(mean, sd^2) at x.
    elemental function normal_density(x, mean, sd) result(f)
        real(dp), intent(in) :: x
        real(qp), intent(in) :: mean, sd
        real(dp) :: f
        real(dp) :: z
        z = (x - real(mean, dp))/real(sd, dp)
        f = inv_sqrt_two_pi*exp(-0.5_dp*z*z)/real(sd, dp)
    end function normal_density

    !> Run the row once per element of `v4`, with e drawn from N(mean, sd^2)
    !> truncated to [0, 1], and store the final velocity of the last sphere.
    !>
    !> Rule for draws outside [0, 1], the range the definition allows for e:
    !> they are discarded and drawn again (counted in `counts%redraws`), so the
    !> law sampled is the normal truncated to [0, 1]. The draws come from
    !> `sampler`, which the caller seeds; successive calls continue its stream,
    !> so one stream can be cut into pieces with identical results.
    !>
    !> Each e is drawn as a double, `mean + sd*z` evaluated in double, and
    !> converted exactly to real128 for the run; `e_samples`, if present, gets
    !> the doubles. Nothing is allocated per sample.
    subroutine monte_carlo_v4(sampler, scene, mean, sd, v4, counts, stat, msg, e_samples)
        type(normal_sampler_t), intent(inout) :: sampler
        type(scene_t), intent(in) :: scene
        real(qp), intent(in) :: mean, sd
        real(dp), intent(out) :: v4(:)
        type(mc_counts_t), intent(out) :: counts
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        real(dp), intent(out), optional :: e_samples(:)
        type(scene_t) :: trial
        type(run_t) :: run
        real(dp) :: mean_d, sd_d, z, e
        real(dp) :: mass
        integer :: i

        call scene_check(scene, stat, msg)
        if (stat /= status_normal) return
        stat = status_invalid
        if (.not. sampler%seeded()) then
            ! its draws would be NaN, and the redraw loop would never end
            msg = "sampler: not seeded; allowed only after its seed(...)"
            return
        end if
        if (.not. (abs(mean) <= huge(1.0_dp))) then
            msg = "mean = "//short(mean)//": allowed a finite number"
            return
        end if
        if (.not. (sd > 0.0_qp .and. sd <= huge(1.0_dp))) then
            msg = "sd = "//short(sd)//": allowed a finite sd > 0"
            return
        end if
        mass = 1.0_dp - normal_mass_outside_unit(mean, sd)
        if (.not. (mass >= min_acceptance)) then
            msg = "mean = "//short(mean)//", sd = "//short(sd)//": only " &
                //short(real(mass, qp))//" of the law lies in 0 <= e <= 1; allowed at least 0.1"
            return
        end if
        if (present(e_samples)) then
            if (size(e_samples) /= size(v4)) then
                write (msg, "(a, i0, a, i0)") "e_samples: size ", size(e_samples), &
                    ": allowed the size of v4, ", size(v4)
                return
            end if
        end if
        stat = status_normal
        msg = ""

        trial = scene
        mean_d = real(mean, dp)
        sd_d = real(sd, dp)
        do i = 1, size(v4)
            do
                call sampler%draw(z)
                e = mean_d + sd_d*z
                if (e >= 0.0_dp .and. e <= 1.0_dp) exit
                counts%redraws = counts%redraws + 1
            end do
            if (present(e_samples)) e_samples(i) = e
            trial%e = real(e, qp)
            call simulate(trial, run)
            if (run%status == status_collapsed) then
                counts%collapsed = counts%collapsed + 1
            else if (run%status /= status_normal) then
                counts%incomplete = counts%incomplete + 1
            end if
            v4(i) = real(run%v(trial%p), dp)
        end do
        counts%runs = size(v4)

    contains

        !> Six significant digits are enough to name a value in a message.
        pure function short(x) result(s)
            real(qp), intent(in) :: x
            character(len=:), allocatable :: s
            s = real_str(x, 6)
        end function short

    end subroutine monte_carlo_v4

    !> Sample mean and standard deviation (divisor n-1; 0 for one value),
    !> summed in real128 in two passes so that neither rounding nor the
    !> cancellation of a one-pass formula reaches the digits printed.
    pure subroutine sample_moments(x, mean, sd)
        real(dp), intent(in) :: x(:)
        real(qp), intent(out) :: mean, sd
        real(qp) :: total, deviation
        integer :: i
        mean = 0.0_qp
        sd = 0.0_qp
        if (size(x) == 0) return
        total = 0.0_qp
        do i = 1, size(x)
            total = total + real(x(i), qp)
        end do
        mean = total/size(x)
        if (size(x) == 1) return
        total = 0.0_qp
        do i = 1, size(x)
            deviation = real(x(i), qp) - mean
            total = total + deviation*deviation
        end do
        sd = sqrt(total/(size(x) - 1))
    end subroutine sample_moments

    !> Standard normal quantile z_p from GSL (a double, held exactly in real128).
    pure function normal_quantile(p) result(z)
        real(qp), intent(in) :: p
        real(qp) :: z
        z = real(gsl_cdf_ugaussian_pinv(real(p, dp)), qp)
    end function normal_quantile

    !> Half-width z sd/sqrt(n) of the two-sided confidence interval of a mean
    !> at the given confidence (0.95 for 95 %).
    !>
    !> The normal quantile is used rather than Student's t because the interval
    !> rests on the central limit theorem anyway (v4 is not normal), and for
    !> the sample sizes of a Monte Carlo (n >= 100, the smallest the study
    !> allows) t_{0.975,n-1}/z_{0.975} - 1 is at most 1.2 % (n = 100), below
    !> 1.3e-4 for n >= 10^4 and 1.3e-6 at the study's n = 10^6.
    pure function mean_ci_half_width(sd, n, confidence) result(half_width)
        real(qp), intent(in) :: sd
        integer, intent(in) :: n
        real(qp), intent(in) :: confidence
        real(qp) :: half_width
        half_width = normal_quantile(0.5_qp + confidence/2)*sd/sqrt(real(n, qp))
    end function mean_ci_half_width

    !> Sort into ascending order in place (GSL's gsl_sort).
    subroutine sort_values(x)
        real(dp), contiguous, intent(inout) :: x(:)
        if (size(x) > 1) call gsl_sort(x, 1_c_size_t, int(size(x), c_size_t))
    end subroutine sort_values

    !> Quantile of level f (0 <= f <= 1) of sorted data, GSL's definition:
    !> linear interpolation between the order statistics around position
    !> 1 + f(n-1).
    pure function sorted_quantile(sorted, f) result(q)
        real(dp), contiguous, intent(in) :: sorted(:)
        real(dp), intent(in) :: f
        real(dp) :: q
        q = gsl_stats_quantile_from_sorted_data(sorted, 1_c_size_t, &
            int(size(sorted), c_size_t), f)
    end function sorted_quantile

    !> Kolmogorov–Smirnov distance sup |F_n - F| of a sample to a continuous
    !> law F, from F at the sorted sample: the empirical function jumps from
    !> (i-1)/n to i/n at the i-th order statistic, so the supremum is attained
    !> at one side of a jump.
    pure function ks_distance(cdf_at_sorted) result(distance)
        real(dp), intent(in) :: cdf_at_sorted(:)
        real(dp) :: distance
        real(dp) :: n
        integer :: i
        n = real(size(cdf_at_sorted), dp)
        distance = 0.0_dp
        do i = 1, size(cdf_at_sorted)
            distance = max(distance, real(i, dp)/n - cdf_at_sorted(i), &
                cdf_at_sorted(i) - real(i - 1, dp)/n)
        end do
    end function ks_distance

    !> True for the rows whose last sphere ends at v0 ((1+e)/2)^3 wherever it
    !> is struck only once: the definition's four equal spheres at equal,
    !> positive gaps, where the first impacts run 1-2, 2-3, 3-4 and each passes
    !> on the fraction (1+e)/2 of the striker's speed. Other rows (other
    !> masses, gap ratios or p) have no such closed form.
    pure logical function cubic_law_applies(scene)
        type(scene_t), intent(in) :: scene
        cubic_law_applies = .false.
        if (scene%p /= 4 .or. .not. allocated(scene%m) .or. .not. allocated(scene%a)) return
        if (size(scene%m) /= 4 .or. size(scene%a) /= 3) return
        cubic_law_applies = all(scene%m == scene%m(1)) .and. all(scene%a == scene%a(1)) &
            .and. scene%a(1) > 0.0_qp
    end function cubic_law_applies

    !> v4 = v0 ((1+e)/2)^3: three equal-mass impacts in a row, each passing on
    !> the fraction (1+e)/2 of the striker's speed.
    elemental function cubic_law_v4(e, v0) result(v4)
        real(qp), intent(in) :: e, v0
        real(qp) :: v4
        v4 = v0*((1.0_qp + e)/2.0_qp)**3
    end function cubic_law_v4

    !> Mean of v0 ((1+e)/2)^3 for e ~ N(m, s^2): with u = 1+e ~ N(1+m, s^2),
    !> E u^3 = (1+m)^3 + 3(1+m)s^2. Exact for the untruncated normal; the
    !> mass cut away by [0, 1] and by the region of one impact is ignored.
    pure function cubic_law_mean(m, s, v0) result(mean)
        real(qp), intent(in) :: m, s, v0
        real(qp) :: mean
        real(qp) :: mu
        mu = 1.0_qp + m
        mean = v0*(mu**3 + 3.0_qp*mu*s**2)/8.0_qp
    end function cubic_law_mean

    !> Standard deviation of v0 ((1+e)/2)^3 for e ~ N(m, s^2): with
    !> u ~ N(mu, s^2), mu = 1+m, Var u^3 = E u^6 - (E u^3)^2
    !> = 9 mu^4 s^2 + 36 mu^2 s^4 + 15 s^6.
    pure function cubic_law_sd(m, s, v0) result(sd)
        real(qp), intent(in) :: m, s, v0
        real(qp) :: sd
        real(qp) :: mu
        mu = 1.0_qp + m
        sd = v0*sqrt(9.0_qp*mu**4*s**2 + 36.0_qp*mu**2*s**4 + 15.0_qp*s**6)/8.0_qp
    end function cubic_law_sd

    !> Quantile of level q of v0 ((1+e)/2)^3, e ~ N(m, s^2): the map is
    !> increasing, so it is the image of the normal quantile m + s z_q (z_q from
    !> GSL, good to a double's precision).
    pure function cubic_law_quantile(q, m, s, v0) result(v)
        real(qp), intent(in) :: q, m, s, v0
        real(qp) :: v
        v = cubic_law_v4(m + s*normal_quantile(q), v0)
    end function cubic_law_quantile

    !> Distribution function of v0 ((1+e)/2)^3, e ~ N(m, s^2):
    !> P(v4 <= v) = Phi((2 (v/v0)^(1/3) - 1 - m)/s).
    elemental function cubic_law_cdf(v, m, s, v0) result(p)
        real(dp), intent(in) :: v
        real(qp), intent(in) :: m, s, v0
        real(dp) :: p
        p = gsl_cdf_ugaussian_p(standard_score(v, m, s, v0))
    end function cubic_law_cdf

    !> Density of v0 ((1+e)/2)^3, e ~ N(m, s^2): phi(z) dz/dv with
    !> z = (2 (v/v0)^(1/3) - 1 - m)/s, dz/dv = 2 (v/v0)^(-2/3) / (3 s v0).
    elemental function cubic_law_density(v, m, s, v0) result(f)
        real(dp), intent(in) :: v
        real(qp), intent(in) :: m, s, v0
        real(dp) :: f
        real(dp) :: z, r
        if (.not. (v > 0.0_dp)) then
            f = 0.0_dp
            return
        end if
        z = standard_score(v, m, s, v0)
        r = (v/real(v0, dp))**(1.0_dp/3.0_dp)
        f = inv_sqrt_two_pi*exp(-0.5_dp*z*z)*2.0_dp/(3.0_dp*real(s, dp)*real(v0, dp)*r*r)
    end function cubic_law_density

    !> The normal score of e = 2 (v/v0)^(1/3) - 1, the inverse of the cubic map.
    elemental function standard_score(v, m, s, v0) result(z)
        real(dp), intent(in) :: v
        real(qp), intent(in) :: m, s, v0
        real(dp) :: z
        real(dp) :: r
        r = 0.0_dp
        if (v > 0.0_dp) r = (v/real(v0, dp))**(1.0_dp/3.0_dp)
        z = (2.0_dp*r - 1.0_dp - real(m, dp))/real(s, dp)
    end function standard_score

    !> The smallest e in [e_lo, e_hi], to real128 resolution, above which the
    !> last sphere is struck exactly once: bisection on that property of the
    !> collision record, which must be false at e_lo and true at e_hi.
    !>
    !> Bisection finds one change of the property; that it changes only once
    !> in the bracket is an assumption the caller checks (for the definition's
    !> row, by comparing the engine with the cubic law above the bound).
    subroutine single_impact_bound(scene, e_lo, e_hi, bound, stat, msg)
        type(scene_t), intent(in) :: scene
        real(qp), intent(in) :: e_lo, e_hi
        real(qp), intent(out) :: bound
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        type(scene_t) :: trial
        type(run_t) :: run
        type(event_log_t) :: log
        real(qp) :: lo, hi, mid
        bound = e_hi
        call scene_check(scene, stat, msg)
        if (stat /= status_normal) return
        stat = status_invalid
        trial = scene
        if (.not. (0.0_qp <= e_lo .and. e_lo < e_hi .and. e_hi <= 1.0_qp)) then
            msg = "e_lo = "//str(e_lo)//", e_hi = "//str(e_hi) &
                //": allowed 0 <= e_lo < e_hi <= 1"
            return
        end if
        if (struck_once(e_lo)) then
            msg = "e_lo = "//str(e_lo)//": the last sphere is struck once there already;" &
                //" allowed an e_lo below the bound"
            return
        end if
        if (.not. struck_once(e_hi)) then
            msg = "e_hi = "//str(e_hi)//": the last sphere is struck more than once there;" &
                //" allowed an e_hi above the bound"
            return
        end if
        lo = e_lo
        hi = e_hi
        do while (hi - lo > 2.0_qp*epsilon(1.0_qp)*hi)
            mid = lo + (hi - lo)/2.0_qp
            if (mid <= lo .or. mid >= hi) exit
            if (struck_once(mid)) then
                hi = mid
            else
                lo = mid
            end if
        end do
        bound = hi
        stat = status_normal
        msg = ""

    contains

        !> The run at e ends normally with exactly one impact on the last pair.
        logical function struck_once(e)
            real(qp), intent(in) :: e
            integer :: j, impacts
            trial%e = e
            call simulate(trial, run, log)
            impacts = 0
            do j = 1, log%n
                if (log%kind(j) == event_collision .and. log%first(j) == trial%p - 1) &
                    impacts = impacts + 1
            end do
            struck_once = run%status == status_normal .and. impacts == 1
        end function struck_once

    end subroutine single_impact_bound

end module sphere_row_monte_carlo
