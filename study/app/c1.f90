!> C12 task c1: the restitution e for which the final v4 = v0/2, by a secant
!> iteration in real(16), from good and from bad starting values.
program c12_c1
    use, intrinsic :: iso_fortran_env, only: error_unit
    use sphere_row, only: qp, scene_t, run_t, event_log_t, simulate, str, status_normal, &
        itoa
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab
    use sphere_row_analysis, only: sequence_of, sequence_text
    use sphere_row_secant, only: secant, secant_result_t, secant_word, secant_converged
    use sphere_row_study_cli, only: nl, cli_t, add_scene_keys, start_program, read_keys, fail, &
        stop_unless_normal, close_tables
    implicit none
    character(len=*), parameter :: name = "c12-c1"
    !> Starting pairs of the robustness table: good ones around the root, and
    !> bad ones in the flat quasi-plastic range, astride the kink at the single-
    !> hit boundary, at the ends of [0, 1].
    real(qp), parameter :: starts(2, 9) = reshape([ &
        0.5_qp, 0.6_qp, 0.9_qp, 1.0_qp, 0.3_qp, 0.35_qp, 0.0_qp, 1.0_qp, &
        0.05_qp, 0.1_qp, 0.1_qp, 0.15_qp, 0.2_qp, 0.25_qp, 0.16_qp, 0.9_qp, &
        0.17_qp, 0.2_qp], [2, 9])
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    character(len=300) :: msg
    type(scene_t) :: scene
    type(run_t) :: run
    type(event_log_t) :: events
    type(secant_result_t) :: main_result, trial
    integer, allocatable :: pairs(:)
    real(qp) :: target, x0, x1, f_tol, closed
    integer :: stat, unit, k, max_iterations

    call start_program(cli, name, &
        "C12 task c1: secant iteration in real(16) for the e at which the final"//nl// &
        "velocity of the last sphere is target*v0; also a table of what the secant"//nl// &
        "does from good and from bad starting values."//nl// &
        "Writes OUT/c1_iterations.tsv, c1_starts.tsv, c1_answers.tsv.")
    call cli%add_real("target", "0.5", "wanted v_p/v0", lo=0.0_qp, hi=1.0_qp)
    call cli%add_real("x0", "0.5", "first starting value of e", lo=0.0_qp, hi=1.0_qp)
    call cli%add_real("x1", "0.6", "second starting value of e, not x0", lo=0.0_qp, hi=1.0_qp)
    call cli%add_real("f_tol", "1e-30", "stop when |v_p - target v0| <= f_tol v0", &
        lo=1.0e-33_qp, hi=1.0_qp)
    call cli%add_int("max_iterations", "50", "secant steps at most", lo=1)
    call add_scene_keys(cli, e_set_by="the secant")
    call read_keys(cli, scene)
    out = cli%get_word("out")
    target = cli%get_real("target")
    x0 = cli%get_real("x0")
    x1 = cli%get_real("x1")
    if (x0 == x1) call fail("x1 = "//cli%get_text("x1")//": allowed x1 /= x0 = " &
        //cli%get_text("x0"))
    f_tol = cli%get_real("f_tol")
    max_iterations = cli%get_int("max_iterations")

    call solve(x0, x1, main_result)
    call open_table(out, "c1_iterations.tsv", "k"//tab//"e_k"//tab//"residual=v4-target[V]", &
        unit, stat, msg)
    call stop_unless_normal(stat, msg)
    do k = 0, main_result%iterations + 1
        write (unit, "(a)") itoa(k)//tab//str(main_result%xs(k))//tab//str(main_result%fs(k))
    end do
    call close_tables([unit])

    call open_table(out, "c1_starts.tsv", "x0"//tab//"x1"//tab//"status"//tab//"iterations" &
        //tab//"e_last"//tab//"residual[V]", unit, stat, msg)
    call stop_unless_normal(stat, msg)
    do k = 1, size(starts, 2)
        call solve(starts(1, k), starts(2, k), trial)
        write (unit, "(a)") str(starts(1, k))//tab//str(starts(2, k))//tab// &
            secant_word(trial%status)//tab//itoa(trial%iterations)//tab//str(trial%x)//tab// &
            str(trial%f)
    end do
    call close_tables([unit])

    call write_answers()
    if (main_result%status /= secant_converged) then
        write (error_unit, "(a)") name//": the secant from x0, x1 did not converge: "// &
            secant_word(main_result%status)//" (tables written)"
    end if

contains

    !> The answers of task c1: the root, its residual, the iterations, checked
    !> against the closed form where sphere p is struck once.
    subroutine write_answers()
        ! by hand: where sphere p is hit once, v_p = v0 ((1+e)/2)^(p-1) = target v0
        closed = 2*target**(1.0_qp/(scene%p - 1)) - 1
        scene%e = main_result%x
        call simulate(scene, run, events)
        call sequence_of(events, pairs)
        call open_table(out, "c1_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        if (count(pairs == scene%p - 1) == 1 .and. all(scene%m == scene%m(1))) then
            call write_answer(unit, "c1.e", str(main_result%x), "closed_form", str(closed), &
                str(main_result%x - closed), "secant in real(16) from e = "//str(x0)//", "// &
                str(x1)//"; sequence at the root "//sequence_text(pairs)//" hits sphere "// &
                itoa(scene%p)//" once, so v"//itoa(scene%p)//" = v0 ((1+e)/2)^"// &
                itoa(scene%p - 1)//" there and e = 2 (target)^(1/"//itoa(scene%p - 1)//") - 1")
        else
            call write_answer(unit, "c1.e", str(main_result%x), "-", "-", "-", &
                "secant in real(16) from e = "//str(x0)//", "//str(x1)//"; sequence at the "// &
                "root "//sequence_text(pairs))
        end if
        call write_answer(unit, "c1.v4", str(run%v(scene%p)), "target", str(target*scene%v0), &
            str(run%v(scene%p) - target*scene%v0), "final velocity of the last sphere at c1.e")
        call write_answer(unit, "c1.iterations", itoa(main_result%iterations), "-", "-", "-", &
            "secant steps to |v4 - target| <= "//str(f_tol)//": "//secant_word(main_result%status))
        call write_answer(unit, "c1.status", secant_word(main_result%status), "-", "-", "-", &
            "flat, left_interval and stagnated are reported, not returned as roots; "// &
            "see c1_starts.tsv")
        call close_tables([unit])
    end subroutine write_answers

    !> v4(e) - target v0, the residual of the boundary value problem.
    function residual(e) result(f)
        real(qp), intent(in) :: e
        real(qp) :: f
        scene%e = e
        call simulate(scene, run)
        f = run%v(scene%p) - target*scene%v0
    end function residual

    subroutine solve(a, b, result)
        real(qp), intent(in) :: a, b
        type(secant_result_t), intent(out) :: result
        ! flat: residuals that differ by less than 64 units of roundoff
        call secant(residual, a, b, 0.0_qp, 1.0_qp, f_tol*scene%v0, &
            64*epsilon(1.0_qp), max_iterations, result)
    end subroutine solve

end program c12_c1
