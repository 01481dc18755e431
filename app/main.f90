!> sphere-row: run one scene of a row of spheres and print the complete answer.
program sphere_row_main
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    use sphere_row, only: scene_t, run_t, event_log_t, simulate, str, status_word, &
        status_normal, status_collapsed, event_collision, event_collapse
    use sphere_row_args, only: get_args, scene_from_args, split_key_value, parse_flag, &
        unused_arg, scene_help, wants_help
    use sphere_row_output, only: itoa
    implicit none
    character(len=*), parameter :: name = "sphere-row"
    character(len=*), parameter :: own_keys = "events"
    character(len=*), parameter :: all_keys = &
        "p, e, d, a, gaps, v0, masses, tol, max_collisions, events"
    character(len=:), allocatable :: args(:), key, value
    character(len=300) :: msg
    logical, allocatable :: used(:)
    type(scene_t) :: scene
    type(run_t) :: run
    type(event_log_t) :: log
    logical :: events
    integer :: stat, i

    call get_args(args)
    if (wants_help(args)) then
        call usage()
        stop
    end if
    allocate (used(size(args)))
    call scene_from_args(args, scene, used, stat, msg)
    if (stat /= status_normal) call fail(msg)
    events = .false.
    do i = 1, size(args)
        if (used(i) .or. index(args(i), "=") == 0) cycle
        call split_key_value(args(i), key, value, stat, msg)
        if (key == own_keys) then
            call parse_flag(key, value, events, stat, msg)
            if (stat /= status_normal) call fail(msg)
            used(i) = .true.
        end if
    end do
    call unused_arg(args, used, all_keys, stat, msg)
    if (stat /= status_normal) call fail(msg)

    if (events) then
        call simulate(scene, run, log)
    else
        call simulate(scene, run)
    end if
    if (run%status /= status_normal .and. run%status /= status_collapsed &
        .and. run%n == 0) call fail(run%message)

    write (output_unit, "(a, 1x, i0)") "collisions", run%n
    write (output_unit, "(a, 1x, a)") "t_end", str(run%t_end)
    write (output_unit, "(a, 1x, a)") "status", status_word(run%status)
    if (run%collapses > 0) then
        write (output_unit, "(a, 1x, i0)") "collapses", run%collapses
        write (output_unit, "(a, 1x, i0)") "closed_form_limits", run%closed_limits
        write (output_unit, "(a, 1x, i0, '-', i0)") "collapse_spheres", &
            run%collapse_first, run%collapse_last
        write (output_unit, "(a, 1x, a)") "collapse_t", str(run%collapse_t)
    end if
    do i = 1, scene%p
        write (output_unit, "('v', i0, 1x, a)") i, str(run%v(i))
    end do
    do i = 1, scene%p
        write (output_unit, "('x', i0, 1x, a)") i, str(run%x(i))
    end do
    do i = 1, scene%p - 1
        write (output_unit, "('y', i0, 1x, a)") i, str(run%y(i))
    end do
    if (events) call write_events()

contains

    !> One line on stderr, exit status 2, nothing on stdout.
    subroutine fail(text)
        character(len=*), intent(in) :: text
        write (error_unit, "(a)") name//": "//trim(text)
        stop 2, quiet=.true.
    end subroutine fail

    !> The event record as TSV, one header row naming each column and its unit
    !> (L: the unit of d and a; V: the unit of v0).
    subroutine write_events()
        integer :: j, k
        character(len=:), allocatable :: line
        line = "event"//achar(9)//"kind"//achar(9)//"first"//achar(9)//"last" &
            //achar(9)//"t[L/V]"//achar(9)//"w[V]"//achar(9)//"x1[L]"//achar(9)//"dx1[V]"
        do k = 1, scene%p - 1
            line = line//achar(9)//"y"//itoa(k)//"[L]"
        end do
        do k = 1, scene%p - 1
            line = line//achar(9)//"dy"//itoa(k)//"[V]"
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
            line = itoa(j)//achar(9)//line//achar(9)//itoa(log%first(j))//achar(9) &
                //itoa(log%last(j))//achar(9)//str(log%t(j))//achar(9)//str(log%w(j)) &
                //achar(9)//str(log%x1(j))//achar(9)//str(log%dx1(j))
            do k = 1, scene%p - 1
                line = line//achar(9)//str(log%y(k, j))
            end do
            do k = 1, scene%p - 1
                line = line//achar(9)//str(log%dy(k, j))
            end do
            write (output_unit, "(a)") line
        end do
    end subroutine write_events

    subroutine usage()
        write (output_unit, "(a)") &
            "usage: "//name//" [FILE] [key=value ...]", &
            "", &
            "Runs one row of spheres struck by sphere 1 (ARGESIM Comparison 12) in", &
            "real(16) and prints the number of collisions, the end time, the status", &
            "(normal, quasi_plastic, max_collisions), the final velocities v1..vp,", &
            "positions x1..xp and gaps y1..y(p-1). Keys and defaults:", &
            "", &
            scene_help(), &
            "  events=no           yes adds the event table (TSV with a header row)", &
            "", &
            "Bad input: one line on stderr naming the key, exit status 2."
    end subroutine usage

end program sphere_row_main
