!> precision=auto from the library: each scene runs in real(8) where a
!> rounding certificate shows that real(8) takes every decision real(16)
!> takes (then the answer comes with a bound on its velocities), else in
!> real(16), and auto_t says why real(8) was not enough. v4 is printed as
!> sphere-row prints it: down to the decade of its bound where it has one,
!> with every digit of real(16) where it is exact.
!>
!>     fpm run --example precision-auto
program precision_auto
    use sphere_row, only: qp, scene_t, run_t, auto_t, scene_init, simulate_auto, &
        status_normal, status_word, real_str, short_text, itoa
    implicit none
    type(scene_t) :: scene
    type(run_t) :: run
    type(auto_t) :: auto
    character(len=200) :: msg
    real(qp), parameter :: es(3) = [0.5_qp, 0.2_qp, 0.1_qp]
    real(qp) :: bound, v
    integer :: stat, k, digits

    do k = 1, size(es)
        call scene_init(scene, stat, msg, p=4, e=es(k))
        if (stat /= status_normal) error stop trim(msg)
        call simulate_auto(scene, run, auto)
        v = run%v(scene%p)
        ! the bound on v4: the run's own, plus the certificate's in real(8)
        bound = run%v_bound
        if (auto%certified) bound = bound + auto%v_bounds(scene%p)
        digits = precision(1.0_qp) + 1
        if (bound > 0 .and. v /= 0) digits = min(digits, floor(log10(abs(v))) &
            - floor(log10(bound)) + 1)
        print "(a)", "e = "//short_text(es(k))//": "//status_word(run%status)//", " &
            //itoa(run%n)//" collisions, v4 = "//real_str(v, max(digits, 1))
        if (auto%answered == "dp") then
            print "(a)", "    real(8), certified; every velocity within " &
                //real_str(auto%v_bound, 2)//" v0 of exact arithmetic"
        else
            print "(a)", "    real(16): "//auto%why_not_dp
        end if
    end do
end program precision_auto
