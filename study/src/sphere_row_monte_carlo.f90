!> Monte Carlo over the restitution coefficient (task c2) and the statistics
!> of its result.
!>
!> e is drawn from a normal law by the Box–Muller transform of MT19937
!> uniforms from GSL, as a double; each draw is converted exactly to real128
!> and the row is run in real128 (the lean path of sphere_row_lean where the
!> scene allows), or with precision auto in real64 where a rounding
!> certificate shows that real64 takes real128's decisions (sphere_row_lean's
!> certified run; the engine's simulate_auto for other rows), else in
!> real128 (escalated). The final velocity of the last sphere is kept as a double:
!> the statistics have widths of order 1e-4 of v0, so digits beyond a double's
!> carry no information; for the same reason the statistics themselves (sums,
!> sort) are taken in double, off the critical path (see sample_moments).
!>
!> The library never stops: refusals come back as status_invalid and a
!> one-line message naming the input, its value and what is allowed.
module sphere_row_monte_carlo
    use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_associated, c_long, c_size_t
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use sphere_row, only: dp, qp, scene_t, run_t, event_log_t, scene_check, simulate, &
        status_normal, status_collapsed, status_invalid, event_collision, str, real_str, &
        auto_t, simulate_auto
    use sphere_row_lean, only: lean_row_t
    use sphere_row_sorting, only: radix_sort
    use sphere_row_gsl, only: gsl_rng_mt19937, gsl_rng_alloc, gsl_rng_set, gsl_rng_uniform_pos, &
        gsl_rng_free, gsl_stats_quantile_from_sorted_data, gsl_cdf_ugaussian_p, &
        gsl_cdf_ugaussian_pinv
    implicit none
    private
    public :: normal_sampler_t, mc_counts_t, min_acceptance, mc_block_size, progress_report
    public :: mc_block_seed
    public :: monte_carlo_v4, normal_mass_outside_unit, normal_cdf, normal_density
    public :: sample_moments, normal_quantile, mean_ci_half_width, sort_values, sorted_quantile
    public :: ks_distance
    public :: cubic_law_applies, cubic_law_mean, cubic_law_sd, cubic_law_quantile
    public :: cubic_law_cdf, cubic_law_density, cubic_law_v4, single_impact_bound
    public :: cubic_law_ks_distance

    !> Smallest share of the normal law that must lie in [0, 1]: samples outside
    !> are drawn again, so a smaller share would multiply the cost (by up to
    !> 1/min_acceptance) and describe a law that is mostly cut away.
    real(dp), parameter :: min_acceptance = 0.1_dp
    !> Samples per block of the Monte Carlo stream, each block with its own
    !> generator (see monte_carlo_v4): large against the generator's seeding
    !> (624 words), small enough to share out 10^6 samples among many threads.
    integer, parameter :: mc_block_size = 10000

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
        !> The same for a block's seed in 1 .. 2^32-1 (see mc_block_seed).
        procedure :: seed_block => sampler_seed_block
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
        !> Binary collisions of all runs (the engine's run%n summed).
        integer(int64) :: collisions = 0
        !> Runs that ended in the quasi-plastic case (status_collapsed).
        integer(int64) :: collapsed = 0
        !> Runs stopped by the scene's max_collisions (v4 is then the value
        !> after the last collision computed); expected 0.
        integer(int64) :: incomplete = 0
        !> With precision auto: runs whose real(64) certificate failed, run
        !> again in real(16) (escalated), and the largest bound on
        !> |v4 - v4 in real(16)| of the others [v0 units].
        integer(int64) :: escalated = 0
        real(dp) :: bound_max = 0.0_dp
    end type mc_counts_t

    abstract interface
        !> Told after each block of a Monte Carlo: `done` of `total` samples.
        subroutine progress_report(done, total)
            import :: int64
            integer(int64), intent(in) :: done, total
        end subroutine progress_report
    end interface

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

    !> Create the generator if needed and start its stream from a block's seed
    !> (1 <= seed < 2^32, as block_seed gives; no memory leaves it unseeded).
    subroutine sampler_seed_block(self, seed)
        class(normal_sampler_t), intent(inout) :: self
        integer(int64), intent(in) :: seed
        if (.not. c_associated(self%rng)) self%rng = gsl_rng_alloc(gsl_rng_mt19937)
        if (.not. c_associated(self%rng)) return
        call gsl_rng_set(self%rng, int(seed, c_long))
        self%have_spare = .false.
    end subroutine sampler_seed_block

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

    !> Samples i = first, ..., first+size(v4)-1 of the stream of `seed`: for
    !> each, e drawn from N(mean, sd^2) truncated to [0, 1], the row run once
    !> in real128 and the final velocity of its last sphere stored (as a
    !> double); `e_samples` gets the e (doubles, exact in real128).
    !>
    !> The stream is cut into blocks of mc_block_size samples; block b
    !> (samples (b-1) B + 1 ... b B) draws its own normals, by Box-Muller, from
    !> its own MT19937 generator seeded with mc_block_seed(seed, b). So sample i
    !> depends on (seed, i) alone: blocks run in parallel (OpenMP, any number
    !> of threads, or none) give the same samples, and the first n samples do
    !> not depend on how many follow. A block that starts before `first` draws
    !> its earlier e without running them.
    !>
    !> Rule for draws outside [0, 1], the range the definition allows for e:
    !> they are discarded and drawn again (counted in `counts%redraws`), so the
    !> law sampled is the normal truncated to [0, 1]. Each e is drawn as a
    !> double, `mean + sd*z` evaluated in double, and converted exactly to
    !> real128 for the run.
    !>
    !> The runs take the lean path of sphere_row_lean (the engine's v4, bit for
    !> bit, at a fraction of its cost) where the scene is of its family, unless
    !> `lean` is false; otherwise the engine. With `auto` true, each run is
    !> first made in real64 with a rounding certificate and made again in
    !> real128 only where the certificate fails (counted in
    !> `counts%escalated`): the collision sequence and count are real128's,
    !> and v4 lies within `counts%bound_max` of real128's. `progress`, if
    !> present, is called (by one thread at a time) after each block with the
    !> samples done. `per_block`, if present, gets the counts of each block
    !> that first..last touches, in block order (b_last - b_first + 1 of them):
    !> `counts` is their sum, so partial results of several calls (or
    !> processes) add up in block order to the counts of one call.
    subroutine monte_carlo_v4(scene, mean, sd, seed, first, v4, e_samples, counts, stat, msg, &
        lean, progress, auto, per_block)
        type(scene_t), intent(in) :: scene
        real(qp), intent(in) :: mean, sd
        integer, intent(in) :: seed, first
        real(dp), intent(out) :: v4(:), e_samples(:)
        type(mc_counts_t), intent(out) :: counts
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        logical, intent(in), optional :: lean, auto
        procedure(progress_report), optional :: progress
        type(mc_counts_t), intent(out), optional :: per_block(:)
        type(mc_counts_t), allocatable :: block_counts(:)
        type(lean_row_t) :: probe
        real(dp) :: mean_d, sd_d
        integer(int64) :: done, total
        integer :: b, b_first, b_last, last
        logical :: use_lean, use_auto, report

        call check_inputs(scene, mean, sd, seed, first, size(v4), size(e_samples), stat, msg)
        if (stat /= status_normal .or. size(v4) == 0) return

        use_lean = .true.
        if (present(lean)) use_lean = lean
        use_auto = .false.
        if (present(auto)) use_auto = auto
        if (use_lean) then
            call probe%prepare(scene, stat, msg)
            use_lean = stat == status_normal
            stat = status_normal
            msg = ""
        end if
        report = present(progress)
        mean_d = real(mean, dp)
        sd_d = real(sd, dp)
        last = first + size(v4) - 1
        b_first = (first - 1)/mc_block_size + 1
        b_last = (last - 1)/mc_block_size + 1
        if (present(per_block)) then
            if (size(per_block) < b_last - b_first + 1) then
                stat = status_invalid
                write (msg, "(a, i0, a, i0)") "per_block: size ", size(per_block), &
                    ": allowed at least the blocks touched, ", b_last - b_first + 1
                return
            end if
        end if
        allocate (block_counts(b_first:b_last))
        done = 0
        total = size(v4)
        !$omp parallel do schedule(dynamic, 1) default(shared) private(b)
        do b = b_first, b_last
            call run_block(b, block_counts(b))
            if (report) then
                !$omp critical (mc_progress)
                done = done + block_counts(b)%runs
                call progress(done, total)
                !$omp end critical (mc_progress)
            end if
        end do
        !$omp end parallel do
        do b = b_first, b_last
            counts%runs = counts%runs + block_counts(b)%runs
            counts%redraws = counts%redraws + block_counts(b)%redraws
            counts%collapsed = counts%collapsed + block_counts(b)%collapsed
            counts%incomplete = counts%incomplete + block_counts(b)%incomplete
            counts%collisions = counts%collisions + block_counts(b)%collisions
            counts%escalated = counts%escalated + block_counts(b)%escalated
            counts%bound_max = max(counts%bound_max, block_counts(b)%bound_max)
        end do
        if (present(per_block)) per_block(:b_last - b_first + 1) = block_counts

    contains

        !> The samples of block b that lie in first..last, with their counts;
        !> everything it changes is its own (locals) or its own slice of v4
        !> and e_samples.
        subroutine run_block(b, block)
            integer, intent(in) :: b
            type(mc_counts_t), intent(out) :: block
            type(normal_sampler_t) :: sampler
            type(lean_row_t) :: lean_row
            type(scene_t) :: trial
            type(run_t) :: run
            real(dp) :: z, e
            integer :: i, i_lo, i_hi, status, block_stat, n
            character(len=80) :: block_msg
            i_lo = max((b - 1)*mc_block_size + 1, first)
            i_hi = min(b*mc_block_size, last)
            call sampler%seed_block(mc_block_seed(seed, b))
            if (use_lean) call lean_row%prepare(scene, block_stat, block_msg)
            trial = scene
            do i = (b - 1)*mc_block_size + 1, i_hi
                do
                    call sampler%draw(z)
                    e = mean_d + sd_d*z
                    if (e >= 0.0_dp .and. e <= 1.0_dp) exit
                    if (i >= i_lo) block%redraws = block%redraws + 1
                end do
                if (i < i_lo) cycle
                e_samples(i - first + 1) = e
                call run_one(e, lean_row, trial, run, v4(i - first + 1), status, n, block)
                block%collisions = block%collisions + n
                if (status == status_collapsed) then
                    block%collapsed = block%collapsed + 1
                else if (status /= status_normal) then
                    block%incomplete = block%incomplete + 1
                end if
            end do
            block%runs = i_hi - i_lo + 1
            call sampler%release()
        end subroutine run_block

        !> One run at restitution e in the precision chosen: v4 (as a double),
        !> the run's status and collision count; an escalation and the bound
        !> of a certified real64 run are entered into `block`.
        subroutine run_one(e, lean_row, trial, run, v4_d, status, n, block)
            real(dp), intent(in) :: e
            type(lean_row_t), intent(inout) :: lean_row
            type(scene_t), intent(inout) :: trial
            type(run_t), intent(inout) :: run
            real(dp), intent(out) :: v4_d
            integer, intent(out) :: status, n
            type(mc_counts_t), intent(inout) :: block
            type(auto_t) :: info
            real(qp) :: v4_q
            real(dp) :: bound
            logical :: deferred, escalated
            if (use_lean .and. use_auto) then
                call lean_row%auto_v4(e, v4_d, status, escalated, bound, n)
            else if (use_lean) then
                call lean_row%v4(real(e, qp), v4_q, status, deferred, n)
                v4_d = real(v4_q, dp)
                return
            else
                trial%e = real(e, qp)
                if (use_auto) then
                    call simulate_auto(trial, run, info)
                    escalated = info%answered /= "dp"
                    bound = 0.0_dp
                    if (.not. escalated) bound = real(info%v_bound, dp)
                else
                    call simulate(trial, run)
                end if
                v4_d = real(run%v(trial%p), dp)
                status = run%status
                n = run%n
                if (.not. use_auto) return
            end if
            if (escalated) block%escalated = block%escalated + 1
            block%bound_max = max(block%bound_max, bound)
        end subroutine run_one

    end subroutine monte_carlo_v4

    !> The checks of monte_carlo_v4's inputs: a valid scene, seed and first
    !> >= 1, a finite law with at least min_acceptance of it in [0, 1], and as
    !> many e samples (n_e) as v4 samples (n_v4).
    subroutine check_inputs(scene, mean, sd, seed, first, n_v4, n_e, stat, msg)
        type(scene_t), intent(in) :: scene
        real(qp), intent(in) :: mean, sd
        integer, intent(in) :: seed, first, n_v4, n_e
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        real(dp) :: mass
        call scene_check(scene, stat, msg)
        if (stat /= status_normal) return
        stat = status_invalid
        if (seed < 1) then
            write (msg, "(a, i0, a)") "seed = ", seed, ": allowed an integer >= 1"
            return
        end if
        if (first < 1) then
            write (msg, "(a, i0, a)") "first = ", first, ": allowed an integer >= 1"
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
        if (n_e /= n_v4) then
            write (msg, "(a, i0, a, i0)") "e_samples: size ", n_e, &
                ": allowed the size of v4, ", n_v4
            return
        end if
        stat = status_normal
        msg = ""

    contains

        !> Six significant digits are enough to name a value in a message.
        pure function short(x) result(s)
            real(qp), intent(in) :: x
            character(len=:), allocatable :: s
            s = real_str(x, 6)
        end function short

    end subroutine check_inputs

    !> The MT19937 seed of block b of the stream of `seed`:
    !> 1 + (seed k1 + (b-1) k2) mod (2^32 - 1), with k1, k2 prime to 2^32 - 1,
    !> so that the blocks of one stream have distinct seeds in 1 .. 2^32-1
    !> (MT19937 reads 32 bits of its seed, and GSL takes 0 for its default).
    pure function mc_block_seed(seed, b) result(s)
        integer, intent(in) :: seed, b
        integer(int64) :: s
        integer(int64), parameter :: modulus = 4294967295_int64
        integer(int64), parameter :: k1 = 1640531527_int64, k2 = 2147483647_int64
        s = 1 + modulo(modulo(int(seed, int64)*k1, modulus) + int(b - 1, int64)*k2, modulus)
    end function mc_block_seed

    !> Sample mean and standard deviation (divisor n-1; 0 for one value) in
    !> double, by sums of the values shifted by the first one, added in chunks.
    !>
    !> Why double suffices (v4 in [0, 1], the statistics' standard errors of
    !> order 4e-5 for 10^6 samples, 1e-5 for 10^7): the shifted sums carry
    !> relative rounding errors of order (chunk + n/chunk) epsilon, about 1e-12,
    !> and the shift (within a few sd of the mean) keeps the cancellation in
    !> sum d^2 - (sum d)^2/n to a factor of about 20; so mean and sd are good to
    !> about 1e-11 of sd, six orders below their own standard errors.
    !>
    !> The chunks of a long sample are summed on the OpenMP threads and their
    !> sums added in chunk order: the same bits for any number of threads.
    subroutine sample_moments(x, mean, sd)
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: mean, sd
        !> Values per chunk, and the fewest chunks worth sharing among threads.
        integer, parameter :: chunk = 4096, shared_chunks = 64
        real(dp), allocatable :: c1(:), c2(:)
        real(dp) :: shift, s1, s2
        integer :: j, n, chunks
        mean = 0.0_dp
        sd = 0.0_dp
        n = size(x)
        if (n == 0) return
        shift = x(1)
        chunks = (n - 1)/chunk + 1
        allocate (c1(chunks), c2(chunks))
        !$omp parallel do schedule(static) default(shared) private(j) &
        !$omp if (chunks >= shared_chunks)
        do j = 1, chunks
            call shifted_sums(x((j - 1)*chunk + 1:min(n, j*chunk)), shift, c1(j), c2(j))
        end do
        !$omp end parallel do
        s1 = 0.0_dp
        s2 = 0.0_dp
        do j = 1, chunks
            s1 = s1 + c1(j)
            s2 = s2 + c2(j)
        end do
        mean = shift + s1/n
        if (n == 1) return
        sd = sqrt(max(0.0_dp, (s2 - s1*(s1/n))/(n - 1)))
    end subroutine sample_moments

    !> The sums of x - shift and of its square, added in the order of x.
    pure subroutine shifted_sums(x, shift, s1, s2)
        real(dp), intent(in) :: x(:), shift
        real(dp), intent(out) :: s1, s2
        real(dp) :: d
        integer :: i
        s1 = 0.0_dp
        s2 = 0.0_dp
        do i = 1, size(x)
            d = x(i) - shift
            s1 = s1 + d
            s2 = s2 + d*d
        end do
    end subroutine shifted_sums

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

    !> Sort into ascending order in place, or into x the values of `source`:
    !> a radix sort, O(n) (10^7 values in a fraction of a second where a
    !> heapsort takes seconds).
    subroutine sort_values(x, source)
        real(dp), contiguous, intent(inout) :: x(:)
        real(dp), intent(in), optional :: source(:)
        call radix_sort(x, source)
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
    !> at one side of a jump. A maximum does not depend on the order it is
    !> taken in: the sample is shared among the OpenMP threads.
    function ks_distance(cdf_at_sorted) result(distance)
        real(dp), intent(in) :: cdf_at_sorted(:)
        real(dp) :: distance
        real(dp) :: n
        integer :: i
        n = real(size(cdf_at_sorted), dp)
        distance = 0.0_dp
        !$omp parallel do schedule(static) default(shared) private(i) reduction(max: distance)
        do i = 1, size(cdf_at_sorted)
            distance = max(distance, ks_gap(i, n, cdf_at_sorted(i)))
        end do
        !$omp end parallel do
    end function ks_distance

    !> |F_n - F| on either side of the jump of F_n at the i-th of n order
    !> statistics, where F is f: the larger of i/n - f and f - (i-1)/n.
    elemental real(dp) function ks_gap(i, n, f)
        integer, intent(in) :: i
        real(dp), intent(in) :: n, f
        ks_gap = max(real(i, dp)/n - f, f - real(i - 1, dp)/n)
    end function ks_gap

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

    !> ks_distance of a sorted sample to the law of v0 ((1+e)/2)^3, e ~ N(m,
    !> s^2), whose distribution function (cubic_law_cdf) is taken at each
    !> value as it is needed: the law's parameters converted to double once,
    !> the values shared among threads (a maximum, the same for any number of
    !> them).
    function cubic_law_ks_distance(sorted, m, s, v0) result(distance)
        real(dp), intent(in) :: sorted(:)
        real(qp), intent(in) :: m, s, v0
        real(dp) :: distance
        real(dp) :: m_d, s_d, v0_d, n
        integer :: i
        m_d = real(m, dp)
        s_d = real(s, dp)
        v0_d = real(v0, dp)
        n = real(size(sorted), dp)
        distance = 0.0_dp
        !$omp parallel do schedule(static) default(shared) private(i) reduction(max: distance)
        do i = 1, size(sorted)
            distance = max(distance, ks_gap(i, n, &
                gsl_cdf_ugaussian_p(score(sorted(i), m_d, s_d, v0_d))))
        end do
        !$omp end parallel do
    end function cubic_law_ks_distance

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
        z = score(v, real(m, dp), real(s, dp), real(v0, dp))
    end function standard_score

    !> standard_score with the law's parameters as doubles.
    elemental function score(v, m, s, v0) result(z)
        real(dp), intent(in) :: v, m, s, v0
        real(dp) :: z
        real(dp) :: r
        r = 0.0_dp
        if (v > 0.0_dp) r = (v/v0)**(1.0_dp/3.0_dp)
        z = (2.0_dp*r - 1.0_dp - m)/s
    end function score

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
