!> C12 study e_crit(p): the critical restitution of the struck resting row of
!> p equal spheres, for p = p_min ... p_max: the edge between collapse and
!> separation as a fine scan of e decided by the engine's labelled answers
!> (its two ends, the band where they mix, the digits each end earns), for
!> small p also the rate map of the collapse cycle; fits of e_c(p).
!>
!> The rows are independent: they run in parallel with OpenMP and, built with
!> MPI, are shared out over the ranks (cyclically, since the cost grows with
!> p); rank 0 gathers them and alone writes the tables, which are the same
!> bits for any number of threads and ranks.
program c12_ecrit
    use sphere_row, only: qp, itoa, real_str
    use sphere_row_tables, only: open_table, write_answer, answer_header, tab
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, fail, &
        stop_unless_normal, close_tables
    use sphere_row_ecrit, only: ecrit_settings_t, ecrit_row_t, ecrit_row, power_fit, &
        mcnamara_young_k, mcnamara_young_e, outcome_word, row_bytes, row_from_bytes, edge_t, &
        edge_of, scan_point, decimal_text, digits_of, outcome_finite, outcome_certified, &
        outcome_unproven, outcome_undecided
    use sphere_row_ranks, only: ranks_t, record_t, ranks_start, ranks_finish, owner_of, &
        gather_records, layout_cyclic
    implicit none
    type(cli_t) :: cli
    type(ranks_t) :: ranks
    !> The rows whose rate-map e_c has a published or derived closed form.
    real(qp), parameter :: closed_3 = 7.0_qp - 4.0_qp*sqrt(3.0_qp), &
        closed_4 = 3.0_qp - 2.0_qp*sqrt(2.0_qp)
    character(len=:), allocatable :: out, rank_msg
    character(len=300) :: msg
    logical, allocatable :: large(:)
    type(ecrit_settings_t) :: s
    type(ecrit_row_t), allocatable :: rows(:)
    type(edge_t), allocatable :: edges(:)
    integer :: stat, p_min, p_max, p_fit_min, unit, n_large, n_mixed, n_decrease
    integer, allocatable :: ps(:)
    real(qp), allocatable :: e_c(:), p_real(:)
    real(qp) :: c_fit, slope, k_my, c_inverse
    !> Significant digits of a fitted value (a fit is good to a few digits).
    integer, parameter :: fit_digits = 4

    call ranks_start(ranks, stat, rank_msg)
    call stop_unless_normal(stat, rank_msg)
    call define_keys()
    call read_settings()
    call compute_rows()
    call gather_rows()
    if (ranks%rank == 0) then
        call fit_rows()
        call write_rows()
        call write_map()
        call write_robust()
        call write_answers()
    end if
    call ranks_finish(ranks, stat, rank_msg)
    call stop_unless_normal(stat, rank_msg)

contains

    !> The settings of the keys; p_max >= p_min is what their ranges cannot say.
    subroutine read_settings()
        call read_keys(cli)
        out = cli%get_word("out")
        p_min = cli%get_int("p_min")
        p_max = cli%get_int("p_max")
        p_fit_min = cli%get_int("p_fit_min")
        s%n_grid = cli%get_int("n_grid")
        s%resolution = cli%get_real("resolution")
        s%resolution_coarse = cli%get_real("resolution_coarse")
        s%max_steps = cli%get_int("max_steps")
        s%tol = cli%get_real("tol")
        s%max_collisions = cli%get_int("max_collisions")
        s%max_collisions_fine = cli%get_int("max_collisions_fine")
        s%p_fine = cli%get_int("p_fine")
        s%map_p_max = cli%get_int("map_p_max")
        s%n_scan = cli%get_int("n_scan")
        s%n_scan_long = cli%get_int("n_scan_long")
        s%p_long = cli%get_int("p_long")
        s%tol_scan = cli%get_real("tol_scan")
        s%tol_scan_long = cli%get_real("tol_scan_long")
        s%max_collisions_scan = cli%get_int("max_collisions_scan")
        s%window = cli%get_real("window")
        s%widen_max = cli%get_int("widen_max")
        s%robust_p_max = cli%get_int("robust_p_max")
        s%tol_deep = cli%get_real("tol_deep")
        s%period_max = cli%get_int("period_max")
        if (p_max < p_min) call fail("p_max = "//itoa(p_max)//": allowed p_max >= p_min = " &
            //itoa(p_min))
    end subroutine read_settings

    !> The e_c of this rank's rows, longest rows first so that the threads
    !> end together (each row's result does not depend on who computes it).
    subroutine compute_rows()
        integer, allocatable :: mine(:)
        integer :: j, k
        ps = [(j, j=p_min, p_max)]
        allocate (rows(size(ps)))
        mine = pack([(j, j=size(ps), 1, -1)], &
            owner_of([(j, j=size(ps), 1, -1)], size(ps), ranks%n_ranks, layout_cyclic) &
            == ranks%rank)
        !$omp parallel do schedule(dynamic, 1) default(shared) private(k)
        do k = 1, size(mine)
            call ecrit_row(ps(mine(k)), s, rows(mine(k)))
        end do
        !$omp end parallel do
    end subroutine compute_rows

    !> Every row on rank 0, each at its p, whichever rank computed it.
    subroutine gather_rows()
        type(record_t), allocatable :: records(:)
        integer :: j
        if (ranks%n_ranks == 1) return
        allocate (records(size(ps)))
        do j = 1, size(ps)
            if (owner_of(j, size(ps), ranks%n_ranks, layout_cyclic) == ranks%rank) then
                records(j)%bytes = row_bytes(rows(j))
            end if
        end do
        call gather_records(ranks, layout_cyclic, records, stat, rank_msg)
        call stop_unless_normal(stat, rank_msg)
        if (ranks%rank /= 0) return
        do j = 1, size(ps)
            call row_from_bytes(records(j)%bytes, rows(j), stat)
            call stop_unless_normal(stat, "p = "//itoa(ps(j))//": the row gathered from rank " &
                //itoa(owner_of(j, size(ps), ranks%n_ranks, layout_cyclic))//" is damaged")
        end do
    end subroutine gather_rows

    !> Each row's edge from its scan, then the fits of e_c(p) over the rows
    !> p >= p_fit_min that separate somewhere on their scan, e_c taken as the
    !> lowest separated point (the side that every row decides):
    !> 1 - e_c = c p^(-beta), 1 - e_c = C/p, and McNamara and Young's form.
    subroutine fit_rows()
        real(qp), allocatable :: one_minus(:)
        integer :: j
        allocate (edges(size(ps)))
        do j = 1, size(ps)
            edges(j) = edge_of(rows(j)%e_from, rows(j)%e_to, rows(j)%outcomes, rows(j)%decades)
        end do
        e_c = edges%finite_min
        large = ps >= p_fit_min .and. e_c < 1.0_qp
        one_minus = merge(1.0_qp - e_c, 1.0_qp, large)
        p_real = real(ps, qp)
        call power_fit(p_real, one_minus, large, c_fit, slope, n_large)
        c_inverse = 0.0_qp
        k_my = 0.0_qp
        if (n_large > 0) then
            c_inverse = exp(sum(log(one_minus*p_real), mask=large)/n_large)
            k_my = mcnamara_young_k(ps, merge(e_c, 0.5_qp, large), large)
        end if
        n_mixed = count(edges%mixed)
        n_decrease = count(e_c(2:) <= e_c(:size(ps) - 1))
    end subroutine fit_rows

    !> ecrit.tsv: one row per p with the two ends of its edge (each with the
    !> width it is known to within and only the decimals that width earns),
    !> the highest certified and the highest unproven collapse,
    !> the mixed band, the counts of the scan, the rate map where there is
    !> one (30 digits), the three fits of 1 - e_c, and the scan's highest
    !> certified and lowest separated points (20 digits: the points run, not
    !> estimates of e_c; tools/replay-ecrit runs them again).
    subroutine write_rows()
        integer :: j
        call open_table(out, "ecrit.tsv", "p"//tab//"e_collapse_max[1]"//tab// &
            "collapse_width[1]"//tab//"e_certified_max[1]"//tab//"e_unproven_max[1]"//tab// &
            "e_finite_min[1]"//tab// &
            "finite_width[1]"//tab// &
            "band"//tab//"band_points"//tab//"band_collapse_share"//tab//"points"//tab// &
            "separated"//tab//"certified"//tab//"unproven"//tab//"undecided"//tab// &
            "finite_scale_decade"//tab//"window_from[1]"//tab//"window_to[1]"//tab// &
            "widenings"//tab//"e_crit_rate_map[1]"//tab//"closed_form"//tab// &
            "closed_form_value[1]"//tab//"fit_power[1]"//tab//"fit_c_over_p[1]"//tab// &
            "fit_mcnamara_young[1]"//tab//"certified_point[1]"//tab//"separated_point[1]", &
            unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do j = 1, size(ps)
            associate (r => rows(j), g => edges(j))
                write (unit, "(a)") itoa(r%p)//tab// &
                    optional_text(decimal_text(g%collapse_max, g%collapse_digits), &
                    g%collapse_max >= 0.0_qp)//tab// &
                    optional_text(real_str(g%collapse_width, 2), g%collapse_max >= 0.0_qp)//tab// &
                    optional_text(grid_text(r, g%certified_max), g%certified_max >= 0.0_qp)//tab// &
                    optional_text(grid_text(r, g%unproven_max), g%unproven_max >= 0.0_qp)//tab// &
                    optional_text(decimal_text(g%finite_min, g%finite_digits), &
                    g%finite_min <= 1.0_qp)//tab// &
                    optional_text(real_str(g%finite_width, 2), g%finite_min <= 1.0_qp)//tab// &
                    trim(merge("mixed", "clean", g%mixed))//tab//itoa(g%band_points)//tab// &
                    optional_text(real_str(real(g%band_collapses, qp)/max(1, g%band_points), 2), &
                    g%mixed)//tab//itoa(size(r%outcomes))//tab//itoa(g%counts(outcome_finite)) &
                    //tab//itoa(g%counts(outcome_certified))//tab// &
                    itoa(g%counts(outcome_unproven))//tab// &
                    itoa(g%counts(outcome_undecided))//tab// &
                    optional_text(itoa(g%finite_decade), g%finite_min <= 1.0_qp)//tab// &
                    grid_text(r, r%e_from)//tab//grid_text(r, r%e_to)//tab//itoa(r%widenings) &
                    //tab//optional_text(real_str(r%e_map, 30), r%has_map)//tab// &
                    trim(r%form%text)//tab//optional_text(real_str(r%form%value, 30), &
                    r%form%found)//tab//fit_text(c_fit*p_real(j)**slope, n_large >= 2)//tab// &
                    fit_text(c_inverse/p_real(j), n_large >= 1)//tab// &
                    fit_text(1.0_qp - mcnamara_young_e(r%p, k_my), k_my > 0.0_qp)//tab// &
                    optional_text(real_str(g%certified_max, 36), g%certified_max >= 0.0_qp) &
                    //tab//optional_text(real_str(g%finite_min, 36), g%finite_min <= 1.0_qp)
            end associate
        end do
        call close_tables([unit])
    end subroutine write_rows

    !> ecrit_map.tsv: every scan as runs of equal outcomes (first and last
    !> point of a run, its outcome, its points, the range of decades of the
    !> separation scales of a separated run): the scan itself, and for the
    !> rows that have them its real64 and deep-tolerance twins.
    subroutine write_map()
        integer :: j
        call open_table(out, "ecrit_map.tsv", "p"//tab//"scan"//tab//"e_first[1]"//tab// &
            "e_last[1]"//tab//"outcome"//tab//"points"//tab//"decade_min"//tab//"decade_max", &
            unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do j = 1, size(ps)
            call write_runs(rows(j), "real16", rows(j)%outcomes, rows(j)%decades)
            if (size(rows(j)%outcomes_dp) == 0) cycle
            call write_runs(rows(j), "real64", rows(j)%outcomes_dp)
            call write_runs(rows(j), "real16_deep", rows(j)%outcomes_deep)
        end do
        call close_tables([unit])
    end subroutine write_map

    !> The runs of equal outcomes of one scan of row r.
    subroutine write_runs(r, scan, outcomes, decades)
        type(ecrit_row_t), intent(in) :: r
        character(len=*), intent(in) :: scan
        integer, intent(in) :: outcomes(:)
        integer, intent(in), optional :: decades(:)
        integer :: first, last
        character(len=:), allocatable :: scales
        first = 1
        do while (first <= size(outcomes))
            last = first
            do while (last < size(outcomes))
                if (outcomes(last + 1) /= outcomes(first)) exit
                last = last + 1
            end do
            scales = "-"//tab//"-"
            if (present(decades) .and. outcomes(first) == outcome_finite) scales = &
                itoa(minval(decades(first:last)))//tab//itoa(maxval(decades(first:last)))
            write (unit, "(a)") itoa(r%p)//tab//scan//tab//grid_text(r, scan_point(r, first)) &
                //tab//grid_text(r, scan_point(r, last))//tab//outcome_word(outcomes(first)) &
                //tab//itoa(last - first + 1)//tab//scales
            first = last + 1
        end do
    end subroutine write_runs

    !> ecrit_robust.tsv: the edge of each row up to robust_p_max from its
    !> scan, the same points in real64 at the same tol, and in real(16) at
    !> tol_deep; the points whose outcome differs from the scan's.
    subroutine write_robust()
        integer :: j
        call open_table(out, "ecrit_robust.tsv", "p"//tab//"scan"//tab//"tol"//tab// &
            "e_collapse_max[1]"//tab//"e_finite_min[1]"//tab//"band"//tab//"differ"//tab// &
            "undecided", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do j = 1, size(ps)
            if (size(rows(j)%outcomes_dp) == 0) cycle
            call robust_line(rows(j), "real16", s%tol_scan, rows(j)%outcomes)
            call robust_line(rows(j), "real64", s%tol_scan, rows(j)%outcomes_dp)
            call robust_line(rows(j), "real16_deep", s%tol_deep, rows(j)%outcomes_deep)
        end do
        call close_tables([unit])
    end subroutine write_robust

    !> One line of ecrit_robust.tsv.
    subroutine robust_line(r, scan, tol, outcomes)
        type(ecrit_row_t), intent(in) :: r
        character(len=*), intent(in) :: scan
        real(qp), intent(in) :: tol
        integer, intent(in) :: outcomes(:)
        type(edge_t) :: g
        g = edge_of(r%e_from, r%e_to, outcomes, 0*outcomes)
        write (unit, "(a)") itoa(r%p)//tab//scan//tab//real_str(tol, 2)//tab// &
            optional_text(decimal_text(g%collapse_max, g%collapse_digits), &
            g%collapse_max >= 0.0_qp)//tab// &
            optional_text(decimal_text(g%finite_min, g%finite_digits), g%finite_min <= 1.0_qp) &
            //tab//trim(merge("mixed", "clean", g%mixed))//tab// &
            itoa(count(outcomes /= r%outcomes))//tab//itoa(g%counts(outcome_undecided))
    end subroutine robust_line

    !> ecrit_answers.tsv: the rate-map answers, the counts over the rows, the
    !> band's width relative to 1 - e_c, the shift of the edge with tol.
    subroutine write_answers()
        integer :: j, n_points, n_undecided, n_differ_dp, n_undecided_rows, first_mixed, &
            first_undecided, widest
        real(qp) :: band(size(ps)), shift, shift_max
        type(edge_t) :: deep
        n_points = sum([(size(rows(j)%outcomes), j=1, size(ps))])
        n_undecided = sum(edges%counts(outcome_undecided))
        n_undecided_rows = count(edges%counts(outcome_undecided) > 0)
        first_mixed = first_p(edges%mixed)
        first_undecided = first_p(edges%counts(outcome_undecided) > 0)
        band = merge((edges%collapse_max - edges%finite_min)/(1.0_qp - edges%finite_min), &
            0.0_qp, edges%mixed)
        widest = maxloc(band, dim=1)
        n_differ_dp = 0
        shift_max = 0.0_qp
        do j = 1, size(ps)
            if (size(rows(j)%outcomes_dp) == 0) cycle
            n_differ_dp = n_differ_dp + count(rows(j)%outcomes_dp /= rows(j)%outcomes)
            deep = edge_of(rows(j)%e_from, rows(j)%e_to, rows(j)%outcomes_deep, &
                0*rows(j)%outcomes_deep)
            if (deep%finite_min > 1.0_qp .or. edges(j)%finite_min > 1.0_qp) cycle
            shift = (edges(j)%finite_min - deep%finite_min)/(1.0_qp - edges(j)%finite_min)
            shift_max = max(shift_max, shift)
        end do
        call open_table(out, "ecrit_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call map_answer(3, closed_3, "closed_form_7-4sqrt3")
        call map_answer(4, closed_4, "closed_form_3-2sqrt2")
        do j = 1, size(ps)
            if (ps(j) < 5 .or. .not. rows(j)%has_map) cycle
            call map_answer(ps(j), 0.0_qp, "-")
        end do
        call write_answer(unit, "ecrit.rows", itoa(size(ps)), "-", "-", "-", &
            "p = "//itoa(p_min)//" ... "//itoa(p_max)//"; "//itoa(n_points)//" points in all, "// &
            "each row's scan "//itoa(s%n_scan)//" points ("//itoa(s%n_scan_long)//" from p = "// &
            itoa(s%p_long)//") in real(16) at tol = "// &
            real_str(s%tol_scan, 2)//" ("//real_str(s%tol_scan_long, 2)//" from p = "// &
            itoa(s%p_long)//"), max_collisions = "//itoa(s%max_collisions_scan))
        call write_answer(unit, "ecrit.mixed_rows", itoa(n_mixed), "-", "-", "-", &
            "rows whose scan has a separated point below one certified to collapse (in "// &
            "exact arithmetic): the collapse set is not one interval [0, e_c) on the scan")
        call write_answer(unit, "ecrit.undecided_points", itoa(n_undecided), "-", "-", "-", &
            "scan points that neither separated nor took a collapse limit within "// &
            itoa(s%max_collisions_scan)//" collisions: counted apart, never as either "// &
            "(points merged at tol, collapse unproven, are counted apart too)")
        call write_answer(unit, "ecrit.first_mixed_p", optional_text(itoa(first_mixed), &
            first_mixed > 0), "-", "-", "-", "the shortest row whose scan is mixed")
        call write_answer(unit, "ecrit.band_relative_max", real_str(band(widest), 2), "-", &
            "-", "-", "the widest mixed band, (e_collapse_max - e_finite_min)/(1 - "// &
            "e_finite_min), at p = "//itoa(ps(widest))//" (0: no row is mixed)")
        call write_answer(unit, "ecrit.undecided_rows", itoa(n_undecided_rows), "-", "-", &
            "-", "rows with undecided points; the first is p = "//optional_text( &
            itoa(first_undecided), first_undecided > 0))
        call write_answer(unit, "ecrit.deep_shift_max", real_str(shift_max, 2), "-", "-", &
            "-", "the largest fall of the lowest separated point from tol = "// &
            real_str(s%tol_scan, 2)//" to tol = "//real_str(s%tol_deep, 2)//" (same "// &
            "points, real(16)), over 1 - e_c, rows p <= "//itoa(s%robust_p_max))
        call write_answer(unit, "ecrit.real64_differ", itoa(n_differ_dp), "-", "-", "-", &
            "points of the rows p <= "//itoa(s%robust_p_max)//" whose outcome in real64 "// &
            "(same tol) differs from real(16)'s")
        call write_answer(unit, "ecrit.not_increasing", itoa(n_decrease), "increasing", "0", &
            itoa(n_decrease), "steps p -> p+1 where the lowest separated point does not "// &
            "increase")
        call write_answer(unit, "ecrit.power_beta", real_str(-slope, fit_digits), "-", "-", "-", &
            "1 - e_c = c p^(-beta), least squares of log(1 - e_c) on log p over "// &
            itoa(n_large)//" rows with p >= "//itoa(p_fit_min)//", e_c the lowest separated "// &
            "point of each scan")
        call write_answer(unit, "ecrit.power_c", real_str(c_fit, fit_digits), "-", "-", "-", &
            "c of that fit")
        call write_answer(unit, "ecrit.c_over_p", real_str(c_inverse, fit_digits), "-", "-", &
            "-", "C of 1 - e_c = C/p, least squares of log(1 - e_c) + log p over the same rows")
        call write_answer(unit, "ecrit.mcnamara_young_k", real_str(k_my, fit_digits), "-", &
            "-", "-", "K of p = K (-ln(1 - e_c))/(1 - e_c), McNamara and Young's scaling, "// &
            "least squares through the origin over the same rows")
        call close_tables([unit])
    end subroutine write_answers

    !> The rate-map answer of row p, with the closed form `check` if given.
    subroutine map_answer(p, closed, check)
        integer, intent(in) :: p
        real(qp), intent(in) :: closed
        character(len=*), intent(in) :: check
        integer :: i
        character(len=:), allocatable :: form
        i = p - p_min + 1
        if (i < 1 .or. i > size(ps)) return
        if (.not. rows(i)%has_map) return
        form = "no closed form found among tan^2(j pi/k) and roots of integer polynomials "// &
            "of degree <= 4 with small coefficients"
        if (rows(i)%form%found) form = "closed form found: "//trim(rows(i)%form%text)
        if (check == "-") then
            associate (g => edges(i))
                call write_answer(unit, "ecrit.p"//itoa(p), real_str(rows(i)%e_map, 30), &
                    "scan_finite_min", decimal_text(g%finite_min, g%finite_digits), &
                    real_str(rows(i)%e_map - g%finite_min, 2), how(i)//"; "//form)
            end associate
        else
            call write_answer(unit, "ecrit.p"//itoa(p), real_str(rows(i)%e_map, 30), check, &
                real_str(closed, 30), real_str(rows(i)%e_map - closed, 2), how(i)//"; "//form)
        end if
    end subroutine map_answer

    !> How the rate-map value of row i was found.
    function how(i) result(text)
        integer, intent(in) :: i
        character(len=:), allocatable :: text
        text = "e where the two dominant eigenvalues of the rate map of the collapse cycle "// &
            "(period "//itoa(size(rows(i)%cycle))//", from the run at e = "// &
            decimal_text(rows(i)%e_pattern, 8)//") merge into a complex pair, bisected in "// &
            "real(16); on the scan (tol = "//real_str(s%tol_scan, 2)//") the highest "// &
            "collapse is "//scan_text(edges(i)%collapse_max, edges(i)%collapse_digits)// &
            ", the lowest separation "//scan_text(edges(i)%finite_min, edges(i)%finite_digits)
    end function how

    !> A point of a scan's edge with its decimals, or '-' if there is none.
    function scan_text(e, decimals) result(text)
        real(qp), intent(in) :: e
        integer, intent(in) :: decimals
        character(len=:), allocatable :: text
        text = optional_text(decimal_text(e, decimals), e >= 0.0_qp .and. e <= 1.0_qp)
    end function scan_text

    !> The first p whose row has `has`, 0 if none.
    integer function first_p(has) result(p)
        logical, intent(in) :: has(:)
        integer :: j
        p = 0
        j = findloc(has, .true., dim=1)
        if (j > 0) p = ps(j)
    end function first_p

    !> A text, or '-' if its value does not exist.
    function optional_text(text, exists) result(shown)
        character(len=*), intent(in) :: text
        logical, intent(in) :: exists
        character(len=:), allocatable :: shown
        shown = "-"
        if (exists) shown = text
    end function optional_text

    !> A fitted value with the digits of a fit, or '-'.
    function fit_text(x, exists) result(shown)
        real(qp), intent(in) :: x
        logical, intent(in) :: exists
        character(len=:), allocatable :: shown
        shown = "-"
        if (exists) shown = real_str(x, fit_digits)
    end function fit_text

    !> A point of row r's scan grid, with one decimal more than its spacing
    !> earns (enough to tell neighbours apart).
    function grid_text(r, e) result(text)
        type(ecrit_row_t), intent(in) :: r
        real(qp), intent(in) :: e
        character(len=:), allocatable :: text
        text = decimal_text(e, digits_of((r%e_to - r%e_from)/(size(r%outcomes) - 1)) + 1)
    end function grid_text

    !> The keys of c12-ecrit.
    subroutine define_keys()
        call start_program(cli, "c12-ecrit", &
            "C12 study e_crit(p): the critical restitution of the struck resting row of p"//nl// &
            "equal spheres (a = d = v0 = 1) for p = p_min ... p_max. Writes OUT/ecrit.tsv"//nl// &
            "and OUT/ecrit_answers.tsv.")
        call cli%add_int("p_min", "3", "first row length", lo=3, hi=4096)
        call cli%add_int("p_max", "24", "last row length (>= p_min)", lo=3, hi=4096)
        call cli%add_int("p_fit_min", "8", "rows in the fits of e_crit(p)", lo=3, hi=4096)
        call cli%add_int("n_grid", "20", "scan e = j/n_grid, j = 1 ... n_grid-1", lo=3, hi=100000)
        call cli%add_real("resolution_coarse", "1e-6", "relative width of the real64 bisection", &
            lo=1.0e-15_qp, hi=0.1_qp)
        call cli%add_real("resolution", "1e-10", "relative width of the real(16) bisection", &
            lo=1.0e-32_qp, hi=0.1_qp)
        call cli%add_int("max_steps", "40", "most runs of one bisection", lo=1, hi=1000)
        call cli%add_real("tol", "1e-4000", "tolerance of the real(16) runs", &
            lo=1.0e-4900_qp, hi=0.5_qp)
        call cli%add_int("max_collisions", "50000", "safety net of the real64 runs: a run " &
            //"that reaches it is undecided (never counted as a collapse)", lo=1)
        call cli%add_int("max_collisions_fine", "1000000", "safety net of the real(16) runs", &
            lo=1)
        call cli%add_int("p_fine", "6", "rows with the real(16) bisection", lo=0, hi=4096)
        call cli%add_int("map_p_max", "6", "rows with the rate map of the collapse cycle", &
            lo=0, hi=4096)
        call cli%add_int("n_scan", "60", "points of the scan of the edge", lo=3, hi=1000000)
        call cli%add_int("n_scan_long", "30", "points of the scan of rows p >= p_long", lo=3, &
            hi=1000000)
        call cli%add_int("p_long", "21", "first row with n_scan_long points (4097: none)", &
            lo=3, hi=4097)
        call cli%add_real("tol_scan", "1e-300", "tolerance of the scan's runs up to p_long - 1",&
            lo=1.0e-4900_qp, hi=0.5_qp)
        call cli%add_real("tol_scan_long", "2e-34", "tolerance of the scan's runs from p_long " &
            //"on (real(16)'s epsilon rounded up: a tol below it turns the calendar off)", &
            lo=1.0e-4900_qp, hi=0.5_qp)
        call cli%add_int("max_collisions_scan", "100000", "safety net of the scan's runs: a " &
            //"run that reaches it is undecided", lo=1)
        call cli%add_real("window", "0.02", "half-width of the scan over 1 - e at the edge", &
            lo=1.0e-12_qp, hi=0.5_qp)
        call cli%add_int("widen_max", "3", "most doublings of the window", lo=0, hi=20)
        call cli%add_int("robust_p_max", "8", "rows scanned again in real64 and at tol_deep", &
            lo=0, hi=4096)
        call cli%add_real("tol_deep", "1e-4000", "tolerance of the deep scan (real(16))", &
            lo=1.0e-4900_qp, hi=0.5_qp)
        call cli%add_int("period_max", "128", "longest collapse cycle looked for", &
            lo=1, hi=100000)
    end subroutine define_keys

end program c12_ecrit
