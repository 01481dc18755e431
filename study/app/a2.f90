!> C12 task a2: final velocities in the elastic case (e = 1) and in the
!> quasi-plastic case, where the velocities are equal to within `spread_max`.
program c12_a2
    use sphere_row, only: qp, scene_t, run_t, simulate, str, status_word, status_normal, &
        status_collapsed, itoa
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab
    use sphere_row_study_cli, only: nl, cli_t, add_scene_keys, start_program, read_keys, fail, &
        stop_unless_normal, close_tables
    implicit none
    type(cli_t) :: cli
    character(len=:), allocatable :: out, header
    character(len=300) :: msg
    type(scene_t) :: scene
    type(run_t) :: elastic, plastic
    real(qp) :: e_plastic, spread_max, spread, plain
    real(qp), allocatable :: v_elastic(:)
    integer :: stat, unit, i, p

    call start_program(cli, "c12-a2", &
        "C12 task a2: final velocities for e = 1 and for the quasi-plastic case."//nl// &
        "Writes OUT/a2_velocities.tsv and OUT/a2_answers.tsv.")
    call cli%add_real("e_plastic", "0.1", "restitution of the quasi-plastic case", &
        lo=0.0_qp, hi=1.0_qp)
    call cli%add_real("spread_max", "1e-30", &
        "velocities count as equal if (max v - min v)/v0 <= this", lo=0.0_qp, lo_open=.true.)
    call add_scene_keys(cli, e_set_by="each case (1 and e_plastic)")
    call read_keys(cli, scene)
    out = cli%get_word("out")
    e_plastic = cli%get_real("e_plastic")
    spread_max = cli%get_real("spread_max")

    p = scene%p
    scene%e = 1.0_qp
    call simulate(scene, elastic)
    if (elastic%status /= status_normal .and. elastic%n == 0) call fail(elastic%message)
    scene%e = e_plastic
    call simulate(scene, plastic)
    spread = (maxval(plastic%v) - minval(plastic%v))/scene%v0
    plain = sum(scene%m)

    ! by hand for equal masses at e = 1: each collision swaps the two velocities
    allocate (v_elastic(p), source=0.0_qp)
    v_elastic(p) = scene%v0

    header = "case"//tab//"e"//tab//"collisions"//tab//"status"
    do i = 1, p
        header = header//tab//"v"//itoa(i)//"[V]"
    end do
    header = header//tab//"spread[V]"
    call open_table(out, "a2_velocities.tsv", header, unit, stat, msg)
    call stop_unless_normal(stat, msg)
    call row("elastic", 1.0_qp, elastic)
    call row("quasi_plastic", e_plastic, plastic)
    call close_tables([unit])

    call open_table(out, "a2_answers.tsv", answer_header, unit, stat, msg)
    call stop_unless_normal(stat, msg)
    do i = 1, p
        if (all(scene%m == scene%m(1))) then
            call write_answer(unit, "a2.elastic.v"//itoa(i), str(elastic%v(i)), "closed_form", &
                str(v_elastic(i)), str(elastic%v(i) - v_elastic(i)), &
                "e = 1, "//itoa(elastic%n)//" collisions; equal masses swap velocities, "// &
                "so all motion ends in the last sphere")
        else
            call write_answer(unit, "a2.elastic.v"//itoa(i), str(elastic%v(i)), "-", "-", "-", &
                "e = 1, "//itoa(elastic%n)//" collisions")
        end if
    end do
    call write_answer(unit, "a2.plastic.e", str(e_plastic), "-", "-", "-", &
        "restitution used for the quasi-plastic case: below the critical value of b1, "// &
        "where the row collapses")
    call write_answer(unit, "a2.plastic.status", status_word(plastic%status), "-", "-", "-", &
        "quasi_plastic: the engine detected inelastic collapse of spheres "// &
        itoa(plastic%limits%first)//"-"//itoa(plastic%limits%last)//" first (t = "// &
        str(plastic%limits%t)//"), "//itoa(plastic%limits%n)//" collapse limits in all, "// &
        itoa(plastic%n)//" collisions")
    call write_answer(unit, "a2.plastic.spread", str(spread), "spread_max", str(spread_max), &
        str(spread - spread_max), "(max v - min v)/v0, the measure of 'sufficiently equal'; "// &
        trim(merge("qualifies: spread <= spread_max      ", &
        "does NOT qualify: spread > spread_max", spread <= spread_max)))
    do i = 1, p
        call write_answer(unit, "a2.plastic.v"//itoa(i), str(plastic%v(i)), "closed_form", &
            str(scene%m(1)*scene%v0/plain), str(plastic%v(i) - scene%m(1)*scene%v0/plain), &
            "perfectly plastic limit: common velocity m1 v0 / sum(m) by momentum")
    end do
    call close_tables([unit])

contains

    subroutine row(label, e, run)
        character(len=*), intent(in) :: label
        real(qp), intent(in) :: e
        type(run_t), intent(in) :: run
        character(len=:), allocatable :: line
        integer :: j
        line = label//tab//str(e)//tab//itoa(run%n)//tab//status_word(run%status)
        do j = 1, p
            line = line//tab//str(run%v(j))
        end do
        write (unit, "(a)") line//tab//str(maxval(run%v) - minval(run%v))
    end subroutine row

end program c12_a2
