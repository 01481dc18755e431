!> One scene and its result: the definition's row of four spheres struck at
!> e = 0.2, the status, the number of collisions and the final velocities.
!>
!>     fpm run --example one-scene
program one_scene
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, status_normal, &
        status_word, str, itoa
    implicit none
    type(scene_t) :: scene
    type(run_t) :: run
    character(len=200) :: msg
    integer :: stat, i

    ! p = 4 equal spheres of diameter d = 1, gaps a = 1; sphere 1 comes at v0 = 1
    call scene_init(scene, stat, msg, p=4, e=0.2_qp, d=1.0_qp, a=1.0_qp, v0=1.0_qp)
    if (stat /= status_normal) error stop trim(msg)
    call simulate(scene, run)

    print "(a)", "status     "//status_word(run%status)
    print "(a)", "collisions "//itoa(run%n)
    print "(a)", "t_end      "//str(run%t_end)
    do i = 1, scene%p
        print "(a)", "v"//itoa(i)//"         "//str(run%v(i))
    end do
end program one_scene
