!> Any initial state: two spheres thrown at a wall, and a ring of five run to
!> a horizon (docs/scenes.md). Each run ends with its answer and its bound.
program any_scene
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, status_normal, &
        status_invalid, status_word, answer_word, real_str, str, momentum, kinetic_energy
    implicit none
    type(scene_t) :: scene
    type(run_t) :: run
    integer :: stat
    character(len=200) :: msg
    ! two equal spheres at -1 towards a wall 0.5 away, e = e_wall = 0.1: they
    ! collapse against it, and the run takes them to rest there
    call scene_init(scene, stat, msg, p=2, e=0.1_qp, gaps=[0.5_qp], &
        velocities=[-1.0_qp, -1.0_qp], wall_left=0.5_qp)
    call check(stat, msg)
    call simulate(scene, run)
    call check(merge(status_invalid, status_normal, run%status == status_invalid), &
        run%message)
    print "(a)", "wall: status "//status_word(run%status)//", answer "// &
        answer_word(run%answer)//", v1 = "//str(run%v(1))//" within "//real_str(run%v_bound, 2)
    ! five spheres of two masses on a ring, run to t = 10
    call scene_init(scene, stat, msg, p=5, e=0.8_qp, masses=[1.0_qp, 2.0_qp, 1.0_qp, 2.0_qp, &
        1.0_qp], velocities=[0.5_qp, -0.3_qp, 0.1_qp, 0.4_qp, -0.2_qp], ring=0.5_qp, &
        t_max=10.0_qp)
    call check(stat, msg)
    call simulate(scene, run)
    call check(merge(status_invalid, status_normal, run%status == status_invalid), &
        run%message)
    print "(a)", "ring: status "//status_word(run%status)//" at t = "//real_str(run%clock%t, 3) &
        //", answer "//answer_word(run%answer)//" within "//real_str(run%v_bound, 2)
    print "(a)", "ring: momentum "//real_str(momentum(scene, run%v), 6)//", energy " &
        //real_str(kinetic_energy(scene, scene%v), 4)//" -> " &
        //real_str(kinetic_energy(scene, run%v), 4)
contains
    !> Stop with the message of a refusal.
    subroutine check(stat, msg)
        integer, intent(in) :: stat
        character(len=*), intent(in) :: msg
        if (stat == status_normal) return
        print "(a)", "refused: "//trim(msg)
        stop 2
    end subroutine check
end program any_scene
