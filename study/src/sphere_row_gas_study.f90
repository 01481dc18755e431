!> The freely cooling ring of hard rods (c12-gas): the random gas of the
!> library (sphere_row_gas) on a ring, its Haff time t0, and an observer that
!> records the engine's run at sample times: the temperature and its bound,
!> the collisions per sphere, the clusters of touching spheres, the limits
!> taken so far (docs/scenes.md; docs/study.md).
module sphere_row_gas_study
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, observer_t, scene_init, status_normal, &
        event_sample, gaps_at_time, velocities_now
    use sphere_row_gas, only: gas_state
    implicit none
    private
    public :: gas_watch_t, ring_gas, haff_t0

    !> pi, to real(16)'s digits.
    real(qp), parameter :: pi = 3.14159265358979323846264338327950288_qp

    !> The samples of a run: at times t(1..n) (the wake of each), the
    !> temperature sum m (v - V)^2/p, its bound (from the velocities' bound
    !> in the kinetic-energy norm), the collisions per sphere 2n/p, the
    !> clusters (runs of two or more touching spheres, across the seam too)
    !> and the limits taken so far, by label.
    type, extends(observer_t) :: gas_watch_t
        type(scene_t), pointer :: scene => null()
        real(qp), allocatable :: t(:), temperature(:), bound(:), per_sphere(:)
        integer, allocatable :: clusters(:), limits(:), certified(:), tolerance(:), bounded(:)
        integer :: n = 0
    contains
        procedure :: notify => gas_notify
    end type gas_watch_t

contains

    !> The ring gas of p spheres of diameter 1 and mass 1 at `density`, at
    !> restitution e and temperature T0, from `seed`, run to `t_max`
    !> (sphere_row_gas: uniform without overlap, Gaussian velocities of zero
    !> momentum, the temperature exact).
    subroutine ring_gas(p, e, density, temperature, seed, t_max, scene, stat, msg)
        integer, intent(in) :: p
        real(qp), intent(in) :: e, density, temperature, t_max
        integer(int64), intent(in) :: seed
        type(scene_t), intent(out) :: scene
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        real(qp), allocatable :: gaps(:), v(:), m(:)
        logical :: ok
        allocate (gaps(p), v(p), m(p))
        m = 1
        call gas_state(p, 1.0_qp, m, density, temperature, seed, gaps, v, ok)
        stat = status_normal + 1
        msg = "density = the gas's: no room between the spheres; allowed density < 1"
        if (.not. ok) return
        call scene_init(scene, stat, msg, p=p, e=e, gaps=gaps(:p - 1), velocities=v, &
            ring=gaps(p), t_max=t_max)
    end subroutine ring_gas

    !> Haff's time of hard rods of diameter d and mass 1 at density n,
    !> restitution e and temperature T0 (docs/scenes.md): sqrt(pi/T0) (1 - n
    !> d)/((1 - e^2) n).
    pure real(qp) function haff_t0(e, density, d, temperature) result(t0)
        real(qp), intent(in) :: e, density, d, temperature
        t0 = sqrt(pi/temperature)*(1 - density*d)/((1 - e**2)*density)
    end function haff_t0

    !> A sample: the run's velocities (those of every time until its next
    !> event), its gaps moved on to the sample's time w.
    subroutine gas_notify(self, run, kind, first, last, w)
        class(gas_watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        integer, intent(in) :: kind, first, last
        real(qp), intent(in) :: w
        real(qp), allocatable :: v(:), y(:)
        real(qp) :: norm, mean, temperature
        integer :: p, i, clusters, k
        logical :: touching, before
        if (kind /= event_sample) return
        p = self%scene%p
        allocate (v(p), y(size(run%y)))
        call velocities_now(self%scene, run, v, norm)
        mean = sum(v)/p
        temperature = sum((v - mean)**2)/p
        call gaps_at_time(run, w, y)
        clusters = 0
        before = y(p) == 0.0_qp
        ! (counted from the seam's far side: a cluster across the seam is one)
        do i = 1, p
            touching = y(i) == 0.0_qp
            if (touching .and. .not. before) clusters = clusters + 1
            before = touching
        end do
        if (all(y == 0.0_qp)) clusters = 1
        self%n = self%n + 1
        k = self%n
        self%t(k) = w
        self%temperature(k) = temperature
        self%bound(k) = (2*sqrt(p*temperature)*norm + norm**2)/p
        self%per_sphere(k) = 2.0_qp*run%n/p
        self%clusters(k) = clusters
        self%limits(k) = run%limits%n
        self%certified(k) = run%limits%certified + run%limits%exact
        self%tolerance(k) = run%limits%tolerance
        self%bounded(k) = run%limits%bounded
        self%wake = huge(1.0_qp)
        if (k < size(self%t)) self%wake = self%t(k + 1)
    end subroutine gas_notify

end module sphere_row_gas_study
