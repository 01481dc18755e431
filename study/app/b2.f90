!> C12 task b2: final velocities of all spheres against e, from e = 1 into the
!> quasi-plastic regime, compared with their closed forms: on an interval of
!> constant collision sequence every final velocity is a polynomial in e.
program c12_b2
    use sphere_row, only: qp, scene_t, run_t, event_log_t, simulate, str, status_word, &
        status_normal, itoa
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab
    use sphere_row_analysis, only: sequence_of, sequence_text, sequence_hash, &
        sequence_polynomials, poly_eval
    use sphere_row_study_cli, only: cli_t, add_scene_keys, start_program, read_keys, &
        stop_unless_normal
    implicit none
    character(len=*), parameter :: nl = new_line("a")
    !> Sequences longer than this are not written out as polynomials.
    integer, parameter :: max_listed = 20
    type(cli_t) :: cli
    character(len=:), allocatable :: out, header, line
    character(len=300) :: msg
    logical :: single_hit, equal, contiguous
    type(scene_t) :: scene
    type(run_t) :: run
    type(event_log_t) :: events
    integer, allocatable :: pairs(:)
    real(qp), allocatable :: coef(:, :)
    integer :: stat, unit, unit_forms, i, j, n_grid, p, n_poly, n_single
    integer(8), allocatable :: seen(:)
    real(qp) :: e, diff, max_diff, single, max_single, e_single_min, v_plain

    call start_program(cli, "c12-b2", &
        "C12 task b2: final velocities v_i(e) from e = 1 down to 0, each compared"//nl// &
        "with the polynomial in e of its own collision sequence."//nl// &
        "Writes OUT/b2_velocities.tsv, b2_closed_forms.tsv, b2_answers.tsv.")
    call cli%add_int("n_grid", "1001", "points of the grid of e in [0, 1]", lo=2)
    call add_scene_keys(cli, e_set_by="the grid of e")
    call read_keys(cli, scene)
    out = cli%get_word("out")
    n_grid = cli%get_int("n_grid")

    p = scene%p
    equal = all(scene%m == scene%m(1))
    call open_tables()
    call tabulate()
    call write_answers()

contains

    !> b2_velocities.tsv and b2_closed_forms.tsv, with their headers.
    subroutine open_tables()
        header = "e"//tab//"collisions"//tab//"status"
        do i = 1, p
            header = header//tab//"v"//itoa(i)//"[V]"
        end do
        header = header//tab//"max|v-polynomial|[V]"//tab//"v"//itoa(p)//"_single_hit[V]"
        call open_table(out, "b2_velocities.tsv", header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call open_table(out, "b2_closed_forms.tsv", "sequence"//tab//"collisions"//tab// &
            "e_first_on_grid"//tab//"sphere"//tab// &
            "coefficients_of_e^0,e^1,...[V]", unit_forms, stat, msg)
        call stop_unless_normal(stat, msg)
    end subroutine open_tables

    !> The grid of e from 1 down to 0: one row of final velocities per point,
    !> each finite run against the polynomials of its sequence and, where sphere
    !> p is hit once, against the single-hit closed form.
    subroutine tabulate()
        allocate (seen(0))
        max_diff = 0
        max_single = 0
        n_poly = 0
        n_single = 0
        e_single_min = 1
        contiguous = .true.
        do j = 1, n_grid
            e = 1.0_qp - real(j - 1, qp)/real(n_grid - 1, qp)
            scene%e = e
            call simulate(scene, run, events)
            line = str(e)//tab//itoa(run%n)//tab//status_word(run%status)
            do i = 1, p
                line = line//tab//str(run%v(i))
            end do
            if (run%status == status_normal) then
                call compare_closed_forms()
            else
                contiguous = .false.
                line = line//tab//"-"//tab//"-"
            end if
            write (unit, "(a)") line
        end do
        close (unit)
        close (unit_forms)
    end subroutine tabulate

    !> The finite run at grid point e against the polynomials of its own
    !> sequence (listed once per sequence) and the single-hit closed form.
    subroutine compare_closed_forms()
        call sequence_of(events, pairs)
        call sequence_polynomials(scene%m, scene%v0, pairs, coef)
        diff = 0
        do i = 1, p
            diff = max(diff, abs(run%v(i) - poly_eval(coef(:, i), e)))
        end do
        max_diff = max(max_diff, diff)
        n_poly = n_poly + 1
        line = line//tab//str(diff)
        ! sphere p is hit once, by sphere p-1, after the impulse ran down the row
        single_hit = equal .and. count(pairs == p - 1) == 1 .and. size(pairs) >= p - 1
        if (single_hit) single_hit = all(pairs(:p - 1) == [(i, i=1, p - 1)])
        if (single_hit) then
            single = scene%v0*((1 + e)/2)**(p - 1)
            max_single = max(max_single, abs(run%v(p) - single))
            n_single = n_single + 1
            if (contiguous) e_single_min = e
            line = line//tab//str(single)
        else
            contiguous = .false.
            line = line//tab//"-"
        end if
        if (size(pairs) <= max_listed .and. .not. any(seen == sequence_hash(pairs))) then
            seen = [seen, sequence_hash(pairs)]
            call list_forms(e)
        end if
    end subroutine compare_closed_forms

    !> The answers of task b2: how far the grid agrees with the closed forms, and
    !> the plastic limit e = 0 against momentum conservation.
    subroutine write_answers()
        v_plain = scene%m(1)*scene%v0/sum(scene%m)
        scene%e = 0
        call simulate(scene, run)
        call open_table(out, "b2_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call write_answer(unit, "b2.grid_points", itoa(n_grid), "-", "-", "-", &
            "e from 1 down to 0 in equal steps; final velocities by the event-driven engine")
        call write_answer(unit, "b2.max_polynomial_difference", str(max_diff), "closed_form", &
            "0", str(max_diff), "largest |v_i(e) - P_i(e)| over the "//itoa(n_poly)// &
            " grid points with a finite run, P_i the polynomial in e of that run's own "// &
            "collision sequence (product of the maps (2)); listed in b2_closed_forms.tsv")
        if (equal) then
            call write_answer(unit, "b2.single_hit_e_min", str(e_single_min), "-", "-", "-", &
                "smallest grid e of the range from e = 1 down in which sphere "//itoa(p)// &
                " is hit once, after the impulse ran down the row: there v"//itoa(p)// &
                " = v0 ((1+e)/2)^"//itoa(p - 1))
            call write_answer(unit, "b2.single_hit_max_difference", str(max_single), &
                "closed_form", "0", str(max_single), "largest |v"//itoa(p)// &
                " - v0 ((1+e)/2)^"//itoa(p - 1)//"| over the "//itoa(n_single)//" grid points "// &
                "where sphere "//itoa(p)//" is hit once")
        end if
        do i = 1, p
            call write_answer(unit, "b2.e0.v"//itoa(i), str(run%v(i)), "closed_form", &
                str(v_plain), str(run%v(i) - v_plain), "e = 0: the quasi-plastic limit, "// &
                "common velocity m1 v0 / sum(m)")
        end do
        close (unit)
    end subroutine write_answers

    !> One row per sphere: the polynomial of the current sequence and the grid
    !> e at which it was first met (from e = 1 down).
    subroutine list_forms(e_first)
        real(qp), intent(in) :: e_first
        character(len=:), allocatable :: cs
        integer :: q, d
        do q = 1, p
            cs = str(coef(0, q))
            do d = 1, ubound(coef, 1)
                cs = cs//","//str(coef(d, q))
            end do
            write (unit_forms, "(a)") sequence_text(pairs)//tab//itoa(size(pairs))//tab// &
                str(e_first)//tab//itoa(q)//tab//cs
        end do
    end subroutine list_forms

end program c12_b2
