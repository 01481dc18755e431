!> C12 task a1: the gaps y_1, y_2, y_3 over 0 <= t <= t_max for e = 0.2.
!>
!> The paths are exactly piecewise linear, so the table holds their breakpoints
!> (every event) and the ends of the window, not a sampled grid.
program c12_a1
    use sphere_row, only: qp, dp, scene_t, run_t, event_log_t, scene_dp_t, run_dp_t, &
        scene_init, simulate, gaps_at, str, status_word, status_normal, event_collision, &
        event_collapse, itoa
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab
    use sphere_row_study_cli, only: nl, cli_t, add_scene_keys, start_program, read_keys, fail, &
        stop_unless_normal, close_tables
    implicit none
    type(cli_t) :: cli
    character(len=:), allocatable :: out, header, line
    character(len=300) :: msg
    type(scene_t) :: scene
    type(run_t) :: run
    type(event_log_t) :: log
    type(scene_dp_t) :: scene_dp
    type(run_dp_t) :: run_dp
    real(qp) :: t_max, t_last
    real(qp), allocatable :: y(:)
    integer :: stat, unit, i, j, n_window

    call start_program(cli, "c12-a1", &
        "C12 task a1: gaps y_i(t) of the definition's scene at e = 0.2, tabulated at"//nl// &
        "their breakpoints (every event) and at the ends of 0 <= t <= t_max."//nl// &
        "Writes OUT/a1_paths.tsv and OUT/a1_answers.tsv.")
    call cli%add_real("t_max", "15", "end of the time window", lo=0.0_qp, lo_open=.true.)
    call add_scene_keys(cli, e_default=0.2_qp)
    call read_keys(cli, scene)
    out = cli%get_word("out")
    t_max = cli%get_real("t_max")

    call simulate(scene, run, log)
    if (run%status /= status_normal .and. run%n == 0) call fail(run%message)

    call write_paths()

    call write_answers()

contains

    !> The answers of task a1, each with its cross-check: the same scene in
    !> real64, and the first two collision times by hand.
    subroutine write_answers()
        ! cross-check: the same scene in real64
        call scene_init(scene_dp, stat, msg, p=scene%p, e=real(scene%e, dp), d=real(scene%d, dp), &
            v0=real(scene%v0, dp), masses=real(scene%m, dp), gaps=real(scene%a, dp))
        call simulate(scene_dp, run_dp)

        call open_table(out, "a1_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call write_answer(unit, "a1.e", str(scene%e), "-", "-", "-", &
            "restitution of task a1 (d = "//str(scene%d)//", v0 = "//str(scene%v0)//")")
        call write_answer(unit, "a1.collisions", itoa(run%n), "real64_engine", itoa(run_dp%n), &
            itoa(run%n - run_dp%n), "all collisions of the run, event-driven in real(16); "// &
            "the same engine in real64 counts the same")
        call write_answer(unit, "a1.collisions_in_window", itoa(n_window), "-", "-", "-", &
            "collisions with t <= t_max = "//str(t_max))
        call write_answer(unit, "a1.t_last", str(run%t_end), "real64_engine", &
            str(real(run_dp%t_end, qp)), str(run%t_end - real(run_dp%t_end, qp)), &
            "time of the last collision; after it no gap closes (termination criterion), "// &
            "so the window t <= "//str(t_max)//" holds the whole process: "// &
            merge("yes", "no ", t_last == run%t_end))
        call write_answer(unit, "a1.status", status_word(run%status), "-", "-", "-", &
            "normal: ended by the definition's criterion without a collapse")
        if (all(scene%m == scene%m(1)) .and. all(scene%a == scene%a(1)) .and. log%n >= 2) then
            ! by hand: 1 reaches 2 after a/v0; 2 leaves with (1+e)/2 v0 and reaches 3
            call write_answer(unit, "a1.t1", str(log%t(1)), "closed_form", &
                str(scene%a(1)/scene%v0), str(log%t(1) - scene%a(1)/scene%v0), &
                "first collision (1-2); by hand a/v0")
            call write_answer(unit, "a1.t2", str(log%t(2)), "closed_form", &
                str(scene%a(1)/scene%v0*(1 + 2/(1 + scene%e))), &
                str(log%t(2) - scene%a(1)/scene%v0*(1 + 2/(1 + scene%e))), &
                "second collision (2-3); by hand a/v0 (1 + 2/(1+e))")
        end if
        do i = 1, scene%p - 1
            call write_answer(unit, "a1.y"//itoa(i)//"_end", str(run%y(i)), "-", "-", "-", &
                "gap at the last collision; afterwards it grows at dy = "//str(run%dy(i)))
        end do
        call close_tables([unit])
    end subroutine write_answers

    !> The gaps at their breakpoints: the start, every event inside the window,
    !> the window's end.
    subroutine write_paths()
        ! breakpoints: the start, every event inside the window, the window's end
        header = "t[L/V]"
        do i = 1, scene%p - 1
            header = header//tab//"y"//itoa(i)//"[L]"
        end do
        header = header//tab//"event"//tab//"first"//tab//"last"
        call open_table(out, "a1_paths.tsv", header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        allocate (y(scene%p - 1))
        n_window = 0
        t_last = 0.0_qp
        do j = 0, log%n
            if (log%t(j) > t_max) exit
            line = str(log%t(j))
            do i = 1, scene%p - 1
                line = line//tab//str(log%y(i, j))
            end do
            select case (log%kind(j))
            case (event_collision)
                line = line//tab//"collision"
                n_window = n_window + 1
                t_last = log%t(j)
            case (event_collapse)
                line = line//tab//"collapse"
            case default
                line = line//tab//"start"
            end select
            write (unit, "(a)") line//tab//itoa(log%first(j))//tab//itoa(log%last(j))
        end do
        call gaps_at(log, t_max, y)
        line = str(t_max)
        do i = 1, scene%p - 1
            line = line//tab//str(y(i))
        end do
        write (unit, "(a)") line//tab//"window_end"//tab//"0"//tab//"0"
        call close_tables([unit])
    end subroutine write_paths

end program c12_a1
