!> Seeded random rows of spheres, run to their end with their invariants
!> checked: the collapse study and the collapse tests draw their scenes here.
!>
!> A scene of the survey: p uniform in p_min..p_max; with probability 1/2
!> equal masses 1, else each mass log-uniform over [1/mass_span, mass_span];
!> e uniform in [0, 1]; each gap 0 with probability zero_gap_share, else
!> uniform in (0, 2]; d = 1, v0 = 1. The numbers come from GSL's MT19937,
!> seeded once per survey, drawn in a fixed order, so a survey is the same on
!> every machine.
module sphere_row_survey
    use, intrinsic :: iso_c_binding, only: c_ptr, c_double, c_long
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, momentum, &
        kinetic_energy, status_normal, status_collapsed, short_text, itoa
    use sphere_row_gsl, only: gsl_rng_mt19937, gsl_rng_alloc, gsl_rng_set, &
        gsl_rng_uniform_pos, gsl_rng_free
    implicit none
    private
    public :: survey_t, survey_open, survey_close, survey_scene, check_invariants, &
        scene_command

    !> A stream of random scenes.
    type :: survey_t
        type(c_ptr) :: rng
        integer :: p_min = 2, p_max = 20
        real(qp) :: mass_span = 1.0e3_qp
        real(qp) :: zero_gap_share = 0.2_qp
    end type survey_t

contains

    !> Start a survey with its seed and ranges.
    subroutine survey_open(survey, seed, p_min, p_max, mass_span)
        type(survey_t), intent(out) :: survey
        integer, intent(in) :: seed, p_min, p_max
        real(qp), intent(in) :: mass_span
        survey%rng = gsl_rng_alloc(gsl_rng_mt19937)
        call gsl_rng_set(survey%rng, int(seed, c_long))
        survey%p_min = p_min
        survey%p_max = p_max
        survey%mass_span = mass_span
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
        if (uniform() < 0.5_qp) then
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
    !> (a collision's rounding moves momentum by a few epsilon of the largest
    !> m v0 at most: no sphere's momentum exceeds it, since m |v| <=
    !> sqrt(2 m E) <= sqrt(m m_1) v_0; measured 0.17 and 0.44 epsilon per
    !> collision in two survey rows of 293,718 and 23,009 collisions), no gap
    !> is negative and no pair is still closing faster than tol*v0. `why`
    !> names the first invariant broken (blank if none).
    pure subroutine check_invariants(scene, run, slack, per_collision, why)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        real(qp), intent(in) :: slack, per_collision
        character(len=:), allocatable, intent(out) :: why
        real(qp) :: v0(scene%p), p_scale, e_start, resolution
        why = ""
        v0 = 0.0_qp
        v0(1) = scene%v0
        p_scale = maxval(scene%m)*scene%v0
        e_start = kinetic_energy(scene, v0)
        resolution = (slack + per_collision*run%n)*epsilon(1.0_qp)
        if (run%status /= status_normal .and. run%status /= status_collapsed) then
            why = "status"
        else if (abs(momentum(scene, run%v) - momentum(scene, v0)) > resolution*p_scale) then
            why = "momentum"
        else if (kinetic_energy(scene, run%v) > e_start*(1.0_qp + resolution)) then
            why = "energy"
        else if (any(run%y < 0.0_qp)) then
            why = "negative_gap"
        else if (any(run%dy < -scene%tol*scene%v0)) then
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

end module sphere_row_survey
