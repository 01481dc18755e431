!> The collision update (6) in relative variables, shared by the real64
!> methods that carry gaps and rates (ODE integration and time stepping).
module sphere_row_impact
    use sphere_row, only: dp
    use sphere_row_rule_dp, only: collide_at
    implicit none
    private
    public :: impact

contains

    !> Collision of spheres k and k+1: the definition's (6a-c), generalised to
    !> p spheres and any masses. `dy` holds the p-1 rates of the gaps and `dx1`
    !> the velocity of sphere 1; only the rates next to the pair change, so no
    !> absolute velocity is formed.
    pure subroutine impact(e, m, k, dy, dx1)
        real(dp), intent(in) :: e
        real(dp), intent(in) :: m(:)
        integer, intent(in) :: k
        real(dp), intent(inout) :: dy(:)
        real(dp), intent(inout) :: dx1
        call collide_at(dy, k, (1.0_dp + e)*(m(k + 1)/(m(k) + m(k + 1))), &
            (1.0_dp + e)*(m(k)/(m(k) + m(k + 1))), e, dx1)
    end subroutine impact

end module sphere_row_impact
