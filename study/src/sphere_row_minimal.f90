!> The minimal hand-written real(16) loop of task c2, the yardstick of the
!> lean path's speed (c12-minimal-loop, bench.tsv): the definition's row only
!> (four unit masses, unit gaps, v0 = 1, tol = epsilon), no checks, no
!> collapse, no ties; each step looks at every gap. For the e of c2 it gives
!> the engine's v4 bit for bit (the tests compare it with the lean path).
module sphere_row_minimal
    use sphere_row, only: qp
    implicit none
    private
    public :: minimal_v4

contains

    !> v4 of the definition's row at restitution e (0 < e <= 1, no collapse).
    pure function minimal_v4(e) result(v4)
        real(qp), intent(in) :: e
        real(qp) :: v4
        real(qp), parameter :: tv = epsilon(1.0_qp)
        real(qp) :: y(3), dy(3), v1, kick, dt, ti, w, u
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
            w = dy(k)
            u = kick*w
            if (k > 1) then
                dy(k - 1) = dy(k - 1) + u
            else
                v1 = v1 + u
            end if
            if (k < 3) dy(k + 1) = dy(k + 1) + u
            dy(k) = -e*w
        end do
        v4 = ((v1 + dy(1)) + dy(2)) + dy(3)
    end function minimal_v4

end module sphere_row_minimal
