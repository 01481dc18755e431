!> Seeded random rows of spheres, run to their end with their invariants
!> checked: the collapse study and the collapse tests draw their scenes here.
!>
!> A scene of the survey: p uniform in p_min..p_max; with probability 1/2
!> equal masses 1, else each mass log-uniform over [1/mass_span, mass_span];
!> e uniform in [0, 1]; each gap 0 with probability zero_gap_share, else
!> uniform in (0, 2]; d = 1, v0 = 1. The numbers come from GSL's MT19937,
!> seeded once per survey, drawn in a fixed order, so a survey is the same on
!> every machine.
!>
!> A row left at its collision cap inside a cascade at one instant (a touching
!> block, its gaps exactly 0) can be followed further by step_further: the
!> block's cascade stepped by the engine's rule alone, in double precision,
!> which tells how long that cascade still runs.
module sphere_row_survey
    use, intrinsic :: iso_c_binding, only: c_ptr, c_double, c_long
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp, scene_t, run_t, scene_init, simulate, momentum, &
        kinetic_energy, status_normal, status_collapsed, status_max_collisions, short_text, itoa
    use sphere_row_gsl, only: gsl_rng_mt19937, gsl_rng_alloc, gsl_rng_set, &
        gsl_rng_uniform_pos, gsl_rng_free
    ! the rule and collision of the cascade at one instant in double
    ! precision, as the engine's tries of a touching block step it
    use sphere_row_pattern_dp, only: cascade_t, cascade_start, rule_choice, cascade_collide
    implicit none
    private
    public :: survey_t, survey_open, survey_close, survey_scene, check_invariants, &
        scene_command
    public :: further_t, step_further, further_word
    public :: further_none, further_merges, further_ends, further_going

    !> How a cascade at one instant stepped further stands: no such cascade
    !> (the run was not in one); every rate of the block within the
    !> insignificant tol v0 (the whole block at one velocity, which the
    !> engine's fallback merges); no approach faster than tol v0 left but
    !> some rate beyond it (the cascade at that instant is over and the block
    !> comes apart, perhaps in parts at one velocity each); or still closing
    !> after the collisions allowed.
    integer, parameter :: further_none = 0, further_merges = 1, further_ends = 2, &
        further_going = 3

    !> A run left at its cap, followed further (step_further).
    type :: further_t
        !> First and last sphere of the touching block whose cascade the run
        !> was in (0, 0 if none).
        integer :: first = 0, last = 0
        !> Collisions stepped further, and how the cascade stood after them
        !> (further_none, further_merges, further_ends or further_going).
        integer(int64) :: n = 0
        integer :: end = further_none
        !> Decades by which the block's fastest approach fell over those
        !> collisions (to the insignificant rate at most).
        real(qp) :: decades = 0
    end type further_t

    !> A stream of random scenes.
    type :: survey_t
        type(c_ptr) :: rng
        integer :: p_min = 2, p_max = 20
        real(qp) :: mass_span = 1.0e3_qp
        real(qp) :: zero_gap_share = 0.2_qp
        !> Share of the rows of equal masses.
        real(qp) :: equal_share = 0.5_qp
    end type survey_t

contains

    !> Start a survey with its seed and ranges.
    subroutine survey_open(survey, seed, p_min, p_max, mass_span, equal_share)
        type(survey_t), intent(out) :: survey
        integer, intent(in) :: seed, p_min, p_max
        real(qp), intent(in) :: mass_span
        real(qp), intent(in), optional :: equal_share
        survey%rng = gsl_rng_alloc(gsl_rng_mt19937)
        call gsl_rng_set(survey%rng, int(seed, c_long))
        survey%p_min = p_min
        survey%p_max = p_max
        survey%mass_span = mass_span
        if (present(equal_share)) survey%equal_share = equal_share
    end subroutine survey_open

    !> Release the survey's generator.
    subroutine survey_close(survey)
        type(survey_t), intent(inout) :: survey
        call gsl_rng_free(survey%rng)
    end subroutine survey_close

    !> The next scene of the survey (always valid).
    subroutine survey_scene(survey, scene)
        type(survey_t), intent(inout) :: survey
        type(scene_t), intent(out) :: scene
        integer :: p, i, stat
        character(len=200) :: msg
        real(qp), allocatable :: m(:), a(:)
        real(qp) :: e
        p = survey%p_min + min(int(uniform()*(survey%p_max - survey%p_min + 1)), &
            survey%p_max - survey%p_min)
        allocate (m(p), a(p - 1))
        m = 1.0_qp
        if (uniform() < 1.0_qp - survey%equal_share) then
            do i = 1, p
                m(i) = survey%mass_span**(2.0_qp*uniform() - 1.0_qp)
            end do
        end if
        e = uniform()
        do i = 1, p - 1
            a(i) = 0.0_qp
            if (uniform() >= survey%zero_gap_share) a(i) = 2.0_qp*uniform()
        end do
        call scene_init(scene, stat, msg, p=p, e=e, masses=m, gaps=a)
    contains
        real(qp) function uniform()
            uniform = real(gsl_rng_uniform_pos(survey%rng), qp)
        end function uniform
    end subroutine survey_scene

    !> Check the end of a run: it ended normally or quasi-plastic, momentum is
    !> kept and energy has not grown to within the kind's resolution of their
    !> scales times `slack` plus per_collision for each collision the run took
    !> (a collapse limit sets up to p - 1 rates at once and counts as p
    !> collisions), no gap is negative and no pair is still closing faster
    !> than tol*v0. `why` names the first invariant broken (blank if none).
    !> The momentum is summed from the run's own state, x_1's rate and the
    !> rates dy_j, each weighted by the mass to its right: a collision rounds
    !> two or three rates by an epsilon of their size, and a rate is at most
    !> twice the largest speed, v0 sqrt(m_1/m_min) (no sphere's kinetic energy
    !> exceeds the initial one), so a collision moves momentum by a few
    !> epsilon of M v0 sqrt(m_1/m_min) at most, M the total mass; the scale of
    !> the check. (Measured on the 10,000 rows of seed 2026: row 1146, masses
    !> over 4.6e5, 20 epsilon of the largest m v0 per collision, well within
    !> this scale's 760.)
    pure subroutine check_invariants(scene, run, slack, per_collision, why)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        real(qp), intent(in) :: slack, per_collision
        character(len=:), allocatable, intent(out) :: why
        real(qp) :: v0(scene%p), path(scene%p), p_scale, e_start, resolution
        integer :: i
        why = ""
        v0 = 0.0_qp
        v0(1) = scene%v0
        p_scale = sum(scene%m)*scene%v0*sqrt(scene%m(1)/minval(scene%m))
        e_start = kinetic_energy(scene, v0)
        resolution = (slack + per_collision*(run%n + scene%p*run%limits%n))*epsilon(1.0_qp)
        ! the velocities along the run's own state, x_1's rate and the rates
        ! (run%v is anchored by the momentum where sphere 1 is not the
        ! heaviest, which would make its momentum right by construction)
        path(1) = run%dx1
        do i = 1, scene%p - 1
            path(i + 1) = path(i) + run%dy(i)
        end do
        if (run%status /= status_normal .and. run%status /= status_collapsed .and. &
            run%status /= status_max_collisions) then
            why = "status"
        else if (abs(momentum(scene, path) - momentum(scene, v0)) > resolution*p_scale) then
            why = "momentum"
        else if (kinetic_energy(scene, run%v) > e_start*(1.0_qp + resolution)) then
            why = "energy"
        else if (any(run%y < 0.0_qp)) then
            why = "negative_gap"
        else if (run%status /= status_max_collisions .and. &
            any(run%dy < -scene%tol*scene%v0)) then
            why = "closing"
        end if
    end subroutine check_invariants

    !> The sphere-row command that runs a survey row again: p, e, the masses
    !> (unless all 1), the gaps and max_collisions, each number in the
    !> shortest text that reads back as it, so the command gives the same
    !> scene bit for bit. Not for a parallel region (a character function of
    !> deferred length).
    function scene_command(scene) result(command)
        type(scene_t), intent(in) :: scene
        character(len=:), allocatable :: command
        integer :: i
        command = "sphere-row p="//itoa(scene%p)//" e="//short_text(scene%e)
        if (any(scene%m /= 1)) then
            command = command//" masses="//short_text(scene%m(1))
            do i = 2, scene%p
                command = command//","//short_text(scene%m(i))
            end do
        end if
        command = command//" gaps="//short_text(scene%a(1))
        do i = 2, scene%p - 1
            command = command//","//short_text(scene%a(i))
        end do
        command = command//" max_collisions="//itoa(scene%max_collisions)
    end function scene_command

    !> Follow a run that stopped at its cap inside a cascade at one instant:
    !> the touching block around the fastest approach among the gaps that
    !> are exactly 0 (its collisions all come before any other, at the same
    !> time; another such block elsewhere in the row is not followed), its
    !> cascade stepped by the engine's rule (the fastest approach first, then
    !> the leftmost; the collision (6) with the run's kicks) for at most
    !> `most` more collisions, until no approach is faster than the
    !> insignificant tol*v0. In double precision, so that 10^8 collisions
    !> take seconds: the engine's own sequence is in real(16), and the two
    !> sequences differ only at a near tie (the test
    !> further_steps_are_the_engines compares them). None of the engine's
    !> limits is taken on the way (the fallback's of a quiet part of the
    !> block, a proof of the merge), and the row itself goes on after the
    !> cascade: this measures how long the cascade at that instant runs, not
    !> how far the row is from its answer, and the engine does not use it.
    !> Where tol*v0 is below double's range relative to the block's rates
    !> (tol near 0), the cascade is stepped `most` collisions. `rates`, if
    !> present, receives the block's rates after the collisions stepped
    !> (contacts further%first..further%last - 1; size 0 if there is no block).
    pure subroutine step_further(scene, run, most, further, rates)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        integer(int64), intent(in) :: most
        type(further_t), intent(out) :: further
        real(qp), allocatable, intent(out), optional :: rates(:)
        type(cascade_t) :: cs
        real(dp), allocatable :: w(:)
        real(dp) :: quiet, start, slack
        integer :: i1, i2, c, shift, st
        if (present(rates)) allocate (rates(0))
        call touching_block(scene, run, i1, i2)
        if (i1 == 0) return
        call cascade_start(cs, real(run%ratios%kick_left(i1:i2), dp), &
            real(run%ratios%kick_right(i1:i2), dp), real(scene%e, dp), 0, st)
        if (st /= 0) return
        further%first = i1
        further%last = i2 + 1
        ! the approach rates (-dy), scaled by a power of 2 to below 1, which
        ! rounds as the unscaled ones do, so that double's range holds their
        ! fall to tol v0 from any scale
        shift = -exponent(maxval(abs(run%dy(i1:i2))))
        w = real(scale(-run%dy(i1:i2), shift), dp)
        quiet = real(min(scale(scene%tol*scene%v0, shift), 1.0_qp), dp)
        start = maxval(w)
        further%end = further_going
        do
            call rule_choice(w, c, slack)
            if (c == 0) then
                further%end = further_ends
            else if (w(c) <= quiet) then
                further%end = further_ends
            end if
            if (further%end == further_ends) then
                if (all(abs(w) <= quiet)) further%end = further_merges
                exit
            end if
            if (further%n >= most) exit
            call cascade_collide(w, cs, c)
            further%n = further%n + 1
        end do
        further%decades = log10(real(start, qp)/real(max(maxval(w), quiet, tiny(w)), qp))
        if (present(rates)) rates = -scale(real(w, qp), -shift)
    end subroutine step_further

    !> The contacts i1..i2 of the run of gaps exactly 0 around the fastest
    !> approach among them that is faster than tol v0 (i1 = i2 = 0 if none).
    pure subroutine touching_block(scene, run, i1, i2)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        integer, intent(out) :: i1, i2
        integer :: j, c
        i1 = 0
        i2 = 0
        c = 0
        do j = 1, scene%p - 1
            if (run%y(j) /= 0 .or. run%dy(j) >= -scene%tol*scene%v0) cycle
            if (c == 0) then
                c = j
            else if (run%dy(j) < run%dy(c)) then
                c = j
            end if
        end do
        if (c == 0) return
        i1 = c
        do while (i1 > 1)
            if (run%y(i1 - 1) /= 0) exit
            i1 = i1 - 1
        end do
        i2 = c
        do while (i2 < scene%p - 1)
            if (run%y(i2 + 1) /= 0) exit
            i2 = i2 + 1
        end do
    end subroutine touching_block

    !> The word of a further_t's end in the tables.
    pure function further_word(end) result(word)
        integer, intent(in) :: end
        character(len=:), allocatable :: word
        select case (end)
        case (further_merges)
            word = "merges"
        case (further_ends)
            word = "ends"
        case (further_going)
            word = "going"
        case default
            word = "-"
        end select
    end function further_word

end module sphere_row_survey
