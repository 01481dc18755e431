!> sphere-row: run one scene of a row of spheres and print the complete answer.
program sphere_row_main
    use, intrinsic :: iso_fortran_env, only: output_unit
    use sphere_row, only: qp, scene_t, run_t, event_log_t, simulate, str, status_word, &
        status_invalid, event_collision, event_collapse, itoa, auto_t, simulate_auto, &
        simulate_in_dp
    use sphere_row_cli, only: cli_t, read_command_line, fail
    use sphere_row_scene_keys, only: add_scene_keys, scene_from_cli
    use sphere_row_error, only: error_t, fatal_error
    implicit none
    type(cli_t) :: cli
    type(scene_t) :: scene
    type(run_t) :: run
    type(event_log_t) :: log
    type(error_t), allocatable :: error
    type(auto_t) :: auto
    logical :: events
    character(len=:), allocatable :: precision

    call define_keys()
    call read_command_line(cli)
    call scene_from_cli(cli, scene, error)
    if (allocated(error)) call fail(cli%name, error)
    events = cli%get_flag("events")
    call choose_precision(error)
    if (allocated(error)) call fail(cli%name, error)
    select case (precision)
    case ("auto")
        call simulate_auto(scene, run, auto)
    case ("dp")
        call simulate_in_dp(scene, run)
    case default
        if (events) then
            call simulate(scene, run, log)
        else
            call simulate(scene, run)
        end if
    end select
    call check_run(error)
    if (allocated(error)) call fail(cli%name, error)
    call write_run()
    if (events) call write_events()

contains

    !> The keys of sphere-row: the scene keys and `events`.
    subroutine define_keys()
        character(len=*), parameter :: nl = new_line("a")
        cli%name = "sphere-row"
        cli%synopsis = "[FILE] [key=value ...]"
        cli%about = &
            "Runs one row of spheres struck by sphere 1 (ARGESIM Comparison 12) in"//nl// &
            "real(16) and prints the number of collisions, the end time, the status"//nl// &
            "(normal, quasi_plastic, max_collisions), the final velocities v1..vp,"//nl// &
            "positions x1..xp and gaps y1..y(p-1)."
        call add_scene_keys(cli)
        call cli%add_flag("events", "no", "yes adds the event table (TSV with a header row)")
        call cli%add_word("precision", "qp", "qp: real(16); dp: real(8); auto: real(8) where" &
            //" a rounding certificate holds, else real(16)")
    end subroutine define_keys

    !> The precision asked for: qp, dp or auto; the event table only with qp.
    subroutine choose_precision(error)
        type(error_t), allocatable, intent(out) :: error
        precision = cli%get_word("precision")
        select case (precision)
        case ("qp", "dp", "auto")
        case default
            call fatal_error(error, "precision = "//precision//": allowed qp, dp or auto")
            return
        end select
        if (events .and. precision /= "qp") call fatal_error(error, "events = yes with " &
            //"precision = "//precision//": allowed only with precision = qp")
    end subroutine choose_precision

    !> Refuse a run the engine did not accept, or one whose output would hold
    !> a number that is not finite (the scene checks are meant to make that
    !> impossible; this keeps inf and nan out of the output whatever happens).
    subroutine check_run(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: j
        if (run%status == status_invalid) then
            call fatal_error(error, trim(run%message))
            return
        end if
        if (.not. finite([run%t_end, run%collapse_t, run%v, run%x, run%y])) then
            call fatal_error(error, "scene = "//scene_text()//": the run's times, positions " &
                //"or velocities overflow real(16); allowed a scene of smaller scales")
            return
        end if
        if (.not. events) return
        do j = 0, log%n
            if (finite([log%t(j), log%w(j), log%x1(j), log%dx1(j), log%y(:, j), &
                log%dy(:, j)])) cycle
            call fatal_error(error, "scene = "//scene_text()//": event "//itoa(j) &
                //" overflows real(16); allowed a scene of smaller scales")
            return
        end do
    end subroutine check_run

    pure logical function finite(xs)
        real(qp), intent(in) :: xs(:)
        finite = all(abs(xs) <= huge(xs))
    end function finite

    !> The scene's keys as given, for a message.
    function scene_text() result(text)
        character(len=:), allocatable :: text
        text = "p="//cli%get_text("p")//" d="//cli%get_text("d")//" v0="//cli%get_text("v0")
    end function scene_text

    !> The answer, one quantity per line.
    subroutine write_run()
        integer :: i
        write (output_unit, "(a, 1x, i0)") "collisions", run%n
        write (output_unit, "(a, 1x, a)") "t_end", str(run%t_end)
        write (output_unit, "(a, 1x, a)") "status", status_word(run%status)
        if (precision == "auto") then
            write (output_unit, "(a, 1x, a)") "precision", auto%answered
            write (output_unit, "(a, 1x, a)") "certified", merge("yes", "no ", auto%certified)
            if (auto%certified) write (output_unit, "(a, 1x, a)") "v_bound", str(auto%v_bound)
            if (auto%answered /= "dp") write (output_unit, "(a, 1x, a)") "not_dp", &
                auto%why_not_dp
        else
            write (output_unit, "(a, 1x, a)") "precision", precision
        end if
        if (run%collapses > 0) then
            write (output_unit, "(a, 1x, i0)") "collapses", run%collapses
            write (output_unit, "(a, 1x, i0)") "closed_form_limits", run%closed_limits
            write (output_unit, "(a, 1x, i0, '-', i0)") "collapse_spheres", &
                run%collapse_first, run%collapse_last
            write (output_unit, "(a, 1x, a)") "collapse_t", str(run%collapse_t)
        end if
        call write_numbered("v", run%v)
        call write_numbered("x", run%x)
        call write_numbered("y", run%y)
    end subroutine write_run

    !> Lines `<name><i> <values(i)>`, written a block of lines at a time (one
    !> write per line would be one system call per line in a row of 10^6).
    subroutine write_numbered(name, values)
        character(len=*), intent(in) :: name
        real(qp), intent(in) :: values(:)
        integer, parameter :: block = 65536
        character(len=block) :: buf
        character(len=:), allocatable :: line
        integer :: i, at
        at = 0
        do i = 1, size(values)
            line = name//itoa(i)//" "//str(values(i))
            if (at > 0 .and. at + 1 + len(line) > block) then
                write (output_unit, "(a)") buf(:at)
                at = 0
            end if
            if (at > 0) then
                buf(at + 1:at + 1) = new_line("a")
                at = at + 1
            end if
            buf(at + 1:at + len(line)) = line
            at = at + len(line)
        end do
        if (at > 0) write (output_unit, "(a)") buf(:at)
    end subroutine write_numbered

    !> The event record as TSV, one header row naming each column and its unit
    !> (L: the unit of d and a; V: the unit of v0).
    subroutine write_events()
        character(len=*), parameter :: tab = achar(9)
        integer :: j, k
        character(len=:), allocatable :: line
        line = "event"//tab//"kind"//tab//"first"//tab//"last"//tab//"t[L/V]"//tab//"w[V]" &
            //tab//"x1[L]"//tab//"dx1[V]"
        do k = 1, scene%p - 1
            line = line//tab//"y"//itoa(k)//"[L]"
        end do
        do k = 1, scene%p - 1
            line = line//tab//"dy"//itoa(k)//"[V]"
        end do
        write (output_unit, "(a)") line
        do j = 0, log%n
            select case (log%kind(j))
            case (event_collision)
                line = "collision"
            case (event_collapse)
                line = "collapse"
            case default
                line = "start"
            end select
            line = itoa(j)//tab//line//tab//itoa(log%first(j))//tab//itoa(log%last(j)) &
                //tab//str(log%t(j))//tab//str(log%w(j))//tab//str(log%x1(j))//tab &
                //str(log%dx1(j))
            do k = 1, scene%p - 1
                line = line//tab//str(log%y(k, j))
            end do
            do k = 1, scene%p - 1
                line = line//tab//str(log%dy(k, j))
            end do
            write (output_unit, "(a)") line
        end do
    end subroutine write_events

end program sphere_row_main
