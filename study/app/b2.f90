!> C12 task b2: final velocities of all spheres against e, from e = 1 into the
!> quasi-plastic regime, compared with their closed forms: on an interval of
!> constant collision sequence every final velocity is a polynomial in e.
program c12_b2
    use sphere_row, only: qp, scene_t, run_t, event_log_t, simulate, str, &
        status_normal, itoa, auto_t, simulate_auto
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab, &
        row_t, write_rows
    use sphere_row_analysis, only: sequence_of, sequence_text, sequence_hash, &
        sequence_polynomials, poly_eval
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, &
        stop_unless_normal, close_tables, add_row_keys, precision_is_auto
    implicit none
    !> Sequences longer than this are not written out as polynomials.
    integer, parameter :: max_listed = 20
    !> Allowance for the rounding of a polynomial's evaluation in real(16),
    !> in units of v0, above a grid point's certified bound.
    real(qp), parameter :: eval_allowance = 1.0e-30_qp
    !> One point of the grid: its run's count, status, final velocities,
    !> collision sequence, the precision that answered and its bound.
    type :: point_t
        integer :: n = 0, status = 0
        real(qp), allocatable :: v(:)
        integer, allocatable :: pairs(:)
        logical :: in_dp = .false.
        !> The certified bound on the final velocities, and (a finite run)
        !> the largest |v_i - P_i(e)|, P_i the polynomials of its sequence.
        real(qp) :: v_bound = 0.0_qp, diff = 0.0_qp
        !> Sphere p hit once (see single_hit_of); a listable sequence's fingerprint (else 0).
        logical :: single_hit = .false.
        integer(8) :: hash = 0
    end type point_t
    type(point_t), allocatable :: points(:)
    !> The points' rows of b2_velocities.tsv.
    type(row_t), allocatable :: rows(:)
    type(cli_t) :: cli
    character(len=:), allocatable :: out, header
    character(len=300) :: msg
    logical :: equal, contiguous, auto_runs
    type(scene_t) :: scene
    type(run_t) :: run
    integer, allocatable :: pairs(:)
    real(qp), allocatable :: coef(:, :)
    integer :: stat, unit, unit_forms, i, j, n_grid, p, n_poly, n_single, n_beyond, n_dp
    integer(8), allocatable :: seen(:)
    real(qp) :: e, max_diff, max_single, e_single_min, v_plain

    call start_program(cli, "c12-b2", &
        "C12 task b2: final velocities v_i(e) from e = 1 down to 0, each compared"//nl// &
        "with the polynomial in e of its own collision sequence."//nl// &
        "Writes OUT/b2_velocities.tsv, b2_closed_forms.tsv, b2_answers.tsv.")
    call cli%add_int("n_grid", "1001", "points of the grid of e in [0, 1]", lo=2)
    call add_row_keys(cli, e_set_by="the grid of e")
    call read_keys(cli, scene)
    auto_runs = precision_is_auto(cli)
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
    !> p is hit once, against the single-hit closed form. The points run, are
    !> compared and formatted in parallel (OpenMP); the rows are written and
    !> counted in order, so the tables do not depend on the threads.
    subroutine tabulate()
        allocate (points(n_grid), rows(n_grid))
        call run_grid()
        allocate (seen(0))
        max_diff = 0
        max_single = 0
        n_poly = 0
        n_single = 0
        n_beyond = 0
        n_dp = count(points%in_dp)
        e_single_min = 1
        contiguous = .true.
        do j = 1, n_grid
            e = grid_e(j)
            if (points(j)%status == status_normal) then
                call count_closed_forms(points(j))
            else
                contiguous = .false.
            end if
        end do
        call write_rows(unit, rows)
        call close_tables([unit, unit_forms])
    end subroutine tabulate

    !> Every point's run, in the precision it needs (precision = auto) or in
    !> real(16), each thread on its own scene and run, the slow ones near e = 0
    !> first; then its comparison with the closed forms and its row.
    subroutine run_grid()
        type(scene_t) :: mine
        type(run_t) :: got
        type(event_log_t) :: log
        type(auto_t) :: auto
        integer :: k
        !$omp parallel do schedule(dynamic, 8) default(shared) &
        !$omp private(k, mine, got, log, auto)
        do k = n_grid, 1, -1
            mine = scene
            mine%e = grid_e(k)
            associate (pt => points(k))
                if (auto_runs) then
                    call simulate_auto(mine, got, auto, pt%pairs, certify_qp=.false.)
                    pt%in_dp = auto%answered == "dp"
                    pt%v_bound = auto%v_bound
                else
                    call simulate(mine, got, log)
                    call sequence_of(log, pt%pairs)
                end if
                pt%n = got%n
                pt%status = got%status
                pt%v = got%v
                if (pt%status == status_normal) then
                    pt%diff = polynomial_difference(pt, mine%e)
                    pt%single_hit = single_hit_of(pt%pairs)
                    if (size(pt%pairs) <= max_listed) pt%hash = sequence_hash(pt%pairs)
                end if
                call format_row(pt, mine%e, rows(k))
            end associate
        end do
        !$omp end parallel do
    end subroutine run_grid

    !> The row of b2_velocities.tsv of the point at e_pt: e, count, status, final
    !> velocities, difference from the polynomials and single-hit closed form.
    subroutine format_row(pt, e_pt, row)
        type(point_t), intent(in) :: pt
        real(qp), intent(in) :: e_pt
        type(row_t), intent(inout) :: row
        integer :: q
        call row%add(e_pt)
        call row%add(pt%n)
        call row%add_status(pt%status)
        do q = 1, p
            call row%add(pt%v(q))
        end do
        if (pt%status /= status_normal) then
            call row%add("-")
            call row%add("-")
        else
            call row%add(pt%diff)
            if (pt%single_hit) then
                call row%add(single_hit_v(e_pt))
            else
                call row%add("-")
            end if
        end if
    end subroutine format_row

    !> The largest |v_i - P_i(e)| of a finite run at e, P_i the polynomials in
    !> e of its own collision sequence.
    real(qp) function polynomial_difference(pt, e_pt) result(d)
        type(point_t), intent(in) :: pt
        real(qp), intent(in) :: e_pt
        real(qp), allocatable :: c(:, :)
        integer :: q
        call sequence_polynomials(scene%m, scene%v0, pt%pairs, c)
        d = 0
        do q = 1, size(pt%v)
            d = max(d, abs(pt%v(q) - poly_eval(c(:, q), e_pt)))
        end do
    end function polynomial_difference

    !> Whether sphere p is hit once, by sphere p-1, after the impulse ran down
    !> the row of equal spheres: the closed form v_p = v0 ((1+e)/2)^(p-1).
    pure logical function single_hit_of(seq) result(single_hit)
        integer, intent(in) :: seq(:)
        integer :: q
        single_hit = equal .and. count(seq == p - 1) == 1 .and. size(seq) >= p - 1
        if (single_hit) single_hit = all(seq(:p - 1) == [(q, q=1, p - 1)])
    end function single_hit_of

    !> The single-hit closed form of v_p at e.
    pure real(qp) function single_hit_v(e_pt)
        real(qp), intent(in) :: e_pt
        single_hit_v = scene%v0*((1 + e_pt)/2)**(p - 1)
    end function single_hit_v

    !> Point j of the grid: e from 1 down to 0 in equal steps.
    pure real(qp) function grid_e(j)
        integer, intent(in) :: j
        grid_e = 1.0_qp - real(j - 1, qp)/real(n_grid - 1, qp)
    end function grid_e

    !> A finite point at e, in grid order: its difference from its
    !> polynomials against its certified bound, its single-hit closed form,
    !> and its sequence's polynomials listed when first met.
    subroutine count_closed_forms(pt)
        type(point_t), intent(in) :: pt
        max_diff = max(max_diff, pt%diff)
        if (pt%diff > pt%v_bound + eval_allowance*scene%v0) n_beyond = n_beyond + 1
        n_poly = n_poly + 1
        if (pt%single_hit) then
            max_single = max(max_single, abs(pt%v(p) - single_hit_v(e)))
            n_single = n_single + 1
            if (contiguous) e_single_min = e
        else
            contiguous = .false.
        end if
        if (size(pt%pairs) > max_listed) return
        if (any(seen == pt%hash)) return
        seen = [seen, pt%hash]
        pairs = pt%pairs
        call sequence_polynomials(scene%m, scene%v0, pairs, coef)
        call list_forms(e)
    end subroutine count_closed_forms

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
        call write_answer(unit, "b2.points_in_real64", itoa(n_dp), "-", "-", "-", &
            "grid points answered in real(8) under the rounding certificate (precision = "// &
            "auto); the others in real(16)")
        call write_answer(unit, "b2.beyond_bound", itoa(n_beyond), "required", "0", &
            itoa(n_beyond), "finite grid points whose |v_i(e) - P_i(e)| exceeds the run's "// &
            "certified bound (points answered in real(16) are held to the allowance alone) "// &
            "by more than "//str(eval_allowance)//" v0, the allowance for evaluating P_i "// &
            "in real(16)")
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
        call close_tables([unit])
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
