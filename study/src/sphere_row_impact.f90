!> The collision update (6) in relative variables, shared by the real64
!> methods that carry gaps and rates (ODE integration and time stepping).
module sphere_row_impact
    use sphere_row, only: dp
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
        real(dp) :: w, c
        w = dy(k)
        c = (1.0_dp + e)*w/(m(k) + m(k + 1))
        if (k > 1) then
            dy(k - 1) = dy(k - 1) + m(k + 1)*c
        else
            dx1 = dx1 + m(2)*c
        end if
        if (k < size(dy)) dy(k + 1) = dy(k + 1) + m(k)*c
        dy(k) = -e*w
    end subroutine impact

end module sphere_row_impact
