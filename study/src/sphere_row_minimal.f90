!> The minimal hand-written real(16) loop of task c2, the yardstick of the
!> lean path's speed (c12-minimal-loop, bench.tsv): the definition's row only
!> (four unit masses, unit gaps, v0 = 1, tol = epsilon), no checks, no
!> collapse, no ties; each step looks at every gap. For the e of c2 it gives
!> the engine's v4 bit for bit (the tests compare it with the lean path).
module sphere_row_minimal
    use sphere_row, only: qp, wp => qp
    implicit none
    private
    public :: minimal_v4

contains

    !> v4 of the definition's row at restitution e (0 < e <= 1, no collapse).
    pure function minimal_v4(e) result(v4)
        real(qp), intent(in) :: e
        real(qp) :: v4
        real(qp), parameter :: tv = epsilon(1.0_qp)
        real(qp) :: y(3), dy(3), v1, kick, dt, ti
        integer :: i, k
        y = 1.0_qp
        dy = [-1.0_qp, 0.0_qp, 0.0_qp]
        v1 = 1.0_qp
        kick = (1.0_qp + e)*0.5_qp
        do
            k = 0
            dt = huge(1.0_qp)
            do i = 1, 3
                if (dy(i) < -tv) then
                    ti = y(i)/(-dy(i))
                    if (ti < dt) then
                        dt = ti
                        k = i
                    end if
                end if
            end do
            if (k == 0) exit
            do i = 1, 3
                y(i) = max(0.0_qp, y(i) + dy(i)*dt)
            end do
            y(k) = 0.0_qp
            call collide_at(dy, k, kick, kick, e, v1)
        end do
        v4 = ((v1 + dy(1)) + dy(2)) + dy(3)
    end function minimal_v4

    include "../../src/engine/sphere_row_rule.inc"

end module sphere_row_minimal
