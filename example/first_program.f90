!> The first program of docs/library.md, as printed there: one scene, the
!> status checked at each step, the answer and its bound.
!>
!>     fpm run --example first-program
program first_program
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, status_normal, &
        status_invalid, status_word, answer_word, real_str, str
    implicit none
    type(scene_t) :: scene
    type(run_t) :: run
    integer :: stat
    character(len=200) :: msg
    call scene_init(scene, stat, msg, p=4, e=0.2_qp)
    if (stat /= status_normal) then           ! e = 1.5, say: msg names e and its range
        print "(a)", "refused: "//trim(msg)
        stop 2
    end if
    call simulate(scene, run)
    if (run%status == status_invalid) then    ! a run the engine refused: run%message says why
        print "(a)", "refused: "//trim(run%message)
        stop 2
    end if
    print "(a)", "status "//status_word(run%status)//", answer "//answer_word(run%answer)
    print "(a)", "v4 = "//str(run%v(4))//" within "//real_str(run%v_bound, 2)
end program first_program
