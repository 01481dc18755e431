!> A reproducible random initial state of a one-dimensional granular gas: p
!> hard rods of diameter d at a given density n (rods per unit length, n d <
!> 1), placed uniformly without overlap, with Gaussian velocities of a given
!> temperature and zero total momentum, from a seed.
!>
!> Rods of diameter d on a length L move as points on the free length L - p d
!> (docs/scenes.md), so a uniform placement without overlap is a uniform
!> placement of points on the free length: the gaps are that length split by
!> independent exponential variates, normalised (the spacings of uniform
!> points). Every random number is a function of the seed and of the
!> sphere's index alone (a counter-based generator: splitmix64 of the seed
!> and the index), so the state is the same however many threads or ranks
!> make it. The velocities are Box-Muller normal variates, shifted to zero
!> momentum and scaled so that the temperature, m <(v - V)^2>, is exactly the
!> one asked for (to the rounding of real(16)).
module sphere_row_gas
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: dp, qp
    implicit none
    private
    public :: gas_state, gas_uniform

    !> The golden-ratio increment of splitmix64 (2^64 / phi, odd).
    integer(int64), parameter :: golden = int(z'9E3779B97F4A7C15', int64)

contains

    !> The gas of `p` spheres of diameter `d` and masses `m` (size p) at density
    !> `density`, temperature `temperature`, from `seed`: `gaps` (size n_gaps,
    !> p on a ring, p + 1 between two walls: the free length L - p d, L =
    !> p/density, split at random) and velocities `v` (size p). `ok` false if
    !> the density leaves no free length (density d >= 1) or p < 2.
    pure subroutine gas_state(p, d, m, density, temperature, seed, gaps, v, ok)
        integer, intent(in) :: p
        real(qp), intent(in) :: d, m(:), density, temperature
        integer(int64), intent(in) :: seed
        real(qp), intent(out) :: gaps(:), v(:)
        logical, intent(out) :: ok
        real(qp) :: free, total, mean, mass, spread
        integer :: i
        ok = p >= 2 .and. density > 0.0_qp .and. density*d < 1.0_qp .and. temperature > 0.0_qp
        if (.not. ok) return
        free = real(p, qp)*(1.0_qp/density - d)
        ! (an exponential variate per gap: -log of a uniform in (0, 1])
        do i = 1, size(gaps)
            gaps(i) = -log(real(gas_uniform(seed, 2_int64*i), qp))
        end do
        total = sum(gaps)
        gaps = free*(gaps/total)
        do i = 1, p
            v(i) = real(normal(seed, i), qp)/sqrt(m(i))
        end do
        mass = sum(m)
        mean = sum(m*v)/mass
        v = v - mean
        spread = sum(m*v**2)/real(p, qp)
        v = v*sqrt(temperature/spread)
    end subroutine gas_state

    !> A uniform number in (0, 1] from the seed and a counter: the top 53 bits
    !> of splitmix64(seed + counter golden), plus one, over 2^53.
    pure real(dp) function gas_uniform(seed, counter) result(u)
        integer(int64), intent(in) :: seed, counter
        integer(int64) :: z
        z = seed + counter*golden
        z = ieor(z, shiftr(z, 30))*int(z'BF58476D1CE4E5B9', int64)
        z = ieor(z, shiftr(z, 27))*int(z'94D049BB133111EB', int64)
        z = ieor(z, shiftr(z, 31))
        u = (real(shiftr(z, 11), dp) + 1.0_dp)*2.0_dp**(-53)
    end function gas_uniform

    !> A standard normal variate for sphere i: Box-Muller from two uniforms of
    !> its own counters.
    pure real(dp) function normal(seed, i)
        integer(int64), intent(in) :: seed
        integer, intent(in) :: i
        real(dp), parameter :: two_pi = 6.283185307179586476925286766559_dp
        real(dp) :: u1, u2
        u1 = gas_uniform(seed, 2_int64*i + 1_int64)
        u2 = gas_uniform(seed, -2_int64*i - 1_int64)
        normal = sqrt(-2.0_dp*log(u1))*cos(two_pi*u2)
    end function normal

end module sphere_row_gas
