!> The space-time diagram of any scene: the world lines x_i(t) of its
!> spheres, its collisions and collapse limits, as the tables that
!> study/spacetime.gp draws (see sphere_row_spacetime).
!>
!> The scene is run twice: first without the event log, which costs O(p)
!> memory however long the run, to learn its number of events and refuse a
!> log that would not fit; then with it.
program c12_spacetime
    use sphere_row, only: qp, scene_t, run_t, event_log_t, simulate, status_invalid, &
        status_max_collisions, status_normal, itoa, short_text
    use sphere_row_study_cli, only: nl, cli_t, add_scene_keys, start_program, read_keys, fail, &
        stop_unless_normal, stop_unless_written, say
    use sphere_row_spacetime, only: spacetime_t, write_spacetime, default_every, &
        check_log_size, spheres_most, drawable_collisions
    implicit none
    !> Default end of the window, past the last event by this part of its time,
    !> so that the motion after it shows.
    real(qp), parameter :: window_past_end = 0.1_qp
    type(cli_t) :: cli
    type(scene_t) :: scene
    type(run_t) :: run
    type(event_log_t) :: log
    type(spacetime_t) :: diagram
    character(len=:), allocatable :: out, name, msg
    real(qp) :: t_max
    integer :: every, stat

    call start_program(cli, "c12-spacetime", &
        "The space-time diagram of a scene: the world line x_i(t) of every sphere"//nl// &
        "(every k-th one in long rows), exact polygons with a vertex wherever a sphere's"//nl// &
        "velocity changes, the collisions (time, point of contact) and the collapse"//nl// &
        "limits (time, group). Writes OUT/NAME_lines.tsv, NAME_collisions.tsv,"//nl// &
        "NAME_collapses.tsv and NAME_info.tsv; study/spacetime.gp draws them"//nl// &
        "(make plot ARGS=""p=30 e=0.6"").")
    call cli%add_word("name", "spacetime", "base name of the tables")
    call cli%add_int("every", "", "draw every k-th sphere (the first and the last always); " &
        //"auto: 1 up to "//itoa(spheres_most)//" spheres, else p/"//itoa(spheres_most) &
        //" rounded up", lo=1, shown="auto")
    call cli%add_real("t_max", "", "end of the time window [L/V]; a run cut by " &
        //"max_collisions ends at its last collision", lo=0.0_qp, lo_open=.true., &
        shown="1.1 t_end")
    call add_scene_keys(cli)
    call read_keys(cli, scene)
    out = cli%get_word("out")
    name = cli%get_word("name")
    if (scan(name, "/") > 0) call fail("name = "//name//": allowed a file name without /")
    every = default_every(scene%p)
    if (cli%given("every")) every = cli%get_int("every")

    call simulate(scene, run)
    if (run%status == status_invalid) call fail(run%message)
    call check_log_size(scene, run%n, run%limits%n, 0, stat, msg)
    ! the largest budget whose log fits, searched only when this one's does not
    if (stat /= status_normal) then
        call check_log_size(scene, run%n, run%limits%n, drawable_collisions(scene), stat, msg)
        call stop_unless_normal(stat, msg)
    end if
    call simulate(scene, run, log)
    if (run%status == status_invalid) call fail(run%message)
    ! past the last event by a part of its time (a run of closed gaps may
    ! end at t = 0: then one unit of time)
    t_max = (1 + window_past_end)*run%t_end
    if (.not. t_max > 0) t_max = 1
    if (cli%given("t_max")) t_max = cli%get_real("t_max")
    ! a run cut by max_collisions is known only up to its last collision
    if (run%status == status_max_collisions) t_max = min(t_max, run%t_end)

    call write_spacetime(scene, run, log, out, name, every, t_max, diagram, stat, msg)
    call stop_unless_written(stat, msg)
    call say("c12-spacetime: "//itoa(diagram%spheres)//" of "//itoa(scene%p) &
        //" world lines (every="//itoa(every)//"), up to t_max = "//short_text(t_max, 6) &
        //": pieces "//itoa(diagram%pieces)//", collisions "//itoa(diagram%collisions) &
        //", collapse limits "//itoa(diagram%collapses)//"; tables "//out//"/"//name &
        //"_*.tsv")

end program c12_spacetime
