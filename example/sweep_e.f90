!> A sweep over the restitution e of the definition's row: the status and
!> the number of collisions of each run. Below the critical e = 3 - 2 sqrt(2)
!> the row collapses (quasi-plastic): infinitely many collisions in finite
!> time, of which the engine counts those before it takes the limit.
!>
!>     fpm run --example sweep-e
program sweep_e
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, status_normal, &
        status_word
    implicit none
    type(scene_t) :: scene
    type(run_t) :: run
    character(len=200) :: msg
    real(qp) :: e
    integer :: stat, k

    print "(a)", "   e  status          collisions  v4 [v0]"
    do k = 10, 0, -1
        e = k/10.0_qp
        call scene_init(scene, stat, msg, p=4, e=e)
        if (stat /= status_normal) error stop trim(msg)
        ! `run` is reused: runs of the same p allocate nothing more
        call simulate(scene, run)
        print "(f4.1, 2x, a, t21, i10, 2x, f10.8)", e, status_word(run%status), run%n, &
            run%v(scene%p)
    end do
end program sweep_e
