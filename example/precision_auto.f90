!> precision=auto from the library: each scene runs in real(8) where a
!> rounding certificate shows that real(8) takes every decision real(16)
!> takes (then the answer comes with a bound on its velocities), else in
!> real(16), and auto_t says why real(8) was not enough. v4 is printed down
!> to the decade of its bound, and no further (earned_str, with the bound
!> sphere-row gives a sphere: velocity_bound).
!>
!>     fpm run --example precision-auto
program precision_auto
    use sphere_row, only: qp, scene_t, run_t, auto_t, scene_init, simulate_auto, &
        status_normal, status_word, real_str, short_text, itoa, earned_str, velocity_bound
    implicit none
    type(scene_t) :: scene
    type(run_t) :: run
    type(auto_t) :: auto
    character(len=200) :: msg
    real(qp), parameter :: es(3) = [0.5_qp, 0.2_qp, 0.1_qp]
    integer :: stat, k

    do k = 1, size(es)
        call scene_init(scene, stat, msg, p=4, e=es(k))
        if (stat /= status_normal) error stop trim(msg)
        call simulate_auto(scene, run, auto)
        print "(a)", "e = "//short_text(es(k))//": "//status_word(run%status)//", " &
            //itoa(run%n)//" collisions, v4 = "//earned_str(run%v(scene%p), &
            velocity_bound(run, auto, scene%p))
        if (auto%answered == "dp") then
            print "(a)", "    real(8), certified; every velocity within " &
                //real_str(auto%v_bound, 2)//" v0 of exact arithmetic"
        else
            print "(a)", "    real(16): "//auto%why_not_dp
        end if
    end do
end program precision_auto
