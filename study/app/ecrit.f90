!> C12 study e_crit(p): the critical restitution of the struck resting row of
!> p equal spheres, for p = p_min ... p_max, by the collapse machinery of the
!> engine (bisection of the edge of the finite region) and, for small p, by
!> the rate map of the collapse cycle; fits of n above e_c and of e_c(p).
!>
!> The rows are independent: they run in parallel with OpenMP and, built with
!> MPI, are shared out over the ranks (cyclically, since the cost grows with
!> p); rank 0 gathers them and alone writes the tables, which are the same
!> bits for any number of threads and ranks.
program c12_ecrit
    use sphere_row, only: qp, str, itoa
    use sphere_row_tables, only: open_table, close_table, write_answer, answer_header, tab
    use sphere_row_study_cli, only: cli_t, start_program, read_keys, fail, stop_unless_normal, &
        stop_unless_written
    use sphere_row_ecrit, only: ecrit_settings_t, ecrit_row_t, ecrit_row, row_estimate, &
        power_fit, mcnamara_young_k, mcnamara_young_e, outcome_word, row_bytes, row_from_bytes
    use sphere_row_ranks, only: ranks_t, record_t, ranks_start, ranks_finish, owner_of, &
        gather_records, layout_cyclic
    implicit none
    character(len=*), parameter :: nl = new_line("a")
    type(cli_t) :: cli
    type(ranks_t) :: ranks
    !> The rows whose rate-map e_c has a published or derived closed form.
    real(qp), parameter :: closed_3 = 7.0_qp - 4.0_qp*sqrt(3.0_qp)
    real(qp), parameter :: closed_4 = 3.0_qp - 2.0_qp*sqrt(2.0_qp)
    character(len=:), allocatable :: out
    character(len=300) :: msg
    character(len=:), allocatable :: rank_msg
    logical, allocatable :: large(:)
    type(ecrit_settings_t) :: s
    type(ecrit_row_t), allocatable :: rows(:)
    integer :: stat, p_min, p_max, p_fit_min, unit, n_large, n_multi, n_decrease
    integer, allocatable :: ps(:)
    real(qp), allocatable :: e_c(:), p_real(:)
    real(qp) :: c_fit, slope, k_my
    character(len=16), allocatable :: methods(:)

    call ranks_start(ranks, stat, rank_msg)
    call stop_unless_normal(stat, rank_msg)
    call define_keys()
    call read_settings()
    call compute_rows()
    call gather_rows()
    if (ranks%rank == 0) then
        call fit_rows()
        call write_rows()
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
        s%n_fit = cli%get_int("n_fit")
        s%fit_n_min = cli%get_int("fit_n_min")
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

    !> Each row's estimate of e_c, then the fits over the large p:
    !> 1 - e_c = c p^(-beta), and McNamara and Young's form.
    subroutine fit_rows()
        character(len=:), allocatable :: method
        real(qp), allocatable :: one_minus(:)
        integer :: j
        allocate (e_c(size(ps)), methods(size(ps)))
        do j = 1, size(ps)
            call row_estimate(rows(j), s%map_window, e_c(j), method)
            methods(j) = method
        end do
        large = ps >= p_fit_min
        n_large = count(large)
        one_minus = 1.0_qp - e_c
        p_real = real(ps, qp)
        call power_fit(p_real, one_minus, large, c_fit, slope, n_large)
        k_my = 0.0_qp
        if (n_large > 0) k_my = mcnamara_young_k(ps, e_c, large)
        n_multi = count(rows%changes > 1)
        n_decrease = count(e_c(2:) <= e_c(:size(ps) - 1))
    end subroutine fit_rows

    !> ecrit.tsv: one row per p with its edge, rate map and fits.
    subroutine write_rows()
        real(qp) :: width
        integer :: j
        call open_table(out, "ecrit.tsv", "p"//tab//"e_crit[1]"//tab//"method"//tab// &
            "e_low[1]"//tab//"e_high[1]"//tab//"bracket_width[1]"//tab//"bracket_digits"//tab// &
            "outcome_low"//tab//"kind"//tab//"e_cycle_certified[1]"//tab//"changes"//tab// &
            "capped"//tab//"C"//tab//"alpha"//tab//"n_fit"//tab//"e_crit_rate_map[1]"//tab// &
            "period"//tab//"closed_form"//tab//"closed_form_value[1]"//tab// &
            "e_crit_power_fit[1]"//tab//"e_crit_mcnamara_young[1]", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        do j = 1, size(ps)
            associate (r => rows(j))
                width = r%b%e_high - r%b%e_low
                write (unit, "(a)") itoa(r%p)//tab//str(e_c(j))//tab//trim(methods(j))//tab// &
                    str(r%b%e_low)//tab//str(r%b%e_high)//tab//str(width)//tab// &
                    itoa(int(log10(e_c(j)/width)))//tab//outcome_word(r%b%outcome_low)//tab// &
                    merge("real(16)", "real64  ", r%precision == qp)//tab// &
                    optional_real(r%b%e_cycle, r%b%e_cycle > 0)//tab//itoa(r%changes)//tab// &
                    itoa(r%capped)//tab//optional_real(r%c, r%n_fit_used >= 2)//tab// &
                    optional_real(r%alpha, r%n_fit_used >= 2)//tab//itoa(r%n_fit_used)//tab// &
                    optional_real(r%e_map, r%has_map)//tab//itoa(size(r%cycle))//tab// &
                    trim(r%form%text)//tab//optional_real(r%form%value, r%form%found)//tab// &
                    optional_real(1.0_qp - c_fit*p_real(j)**slope, n_large >= 2)//tab// &
                    optional_real(mcnamara_young_e(r%p, k_my), k_my > 0.0_qp)
            end associate
        end do
        call close_table(unit, stat, msg)
        call stop_unless_written(stat, msg)
    end subroutine write_rows

    !> ecrit_answers.tsv: the rate-map answers and the counts over the rows.
    subroutine write_answers()
        integer :: j
        call open_table(out, "ecrit_answers.tsv", answer_header, unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call map_answer(3, closed_3, "closed_form_7-4sqrt3")
        call map_answer(4, closed_4, "closed_form_3-2sqrt2")
        do j = 1, size(ps)
            if (ps(j) < 5 .or. .not. rows(j)%has_map) cycle
            call map_answer(ps(j), 0.0_qp, "-")
        end do
        call write_answer(unit, "ecrit.rows", itoa(size(ps)), "-", "-", "-", &
            "p = "//itoa(p_min)//" ... "//itoa(p_max)//"; edge kinds: "// &
            itoa(count(rows%precision == qp))//" real(16) (tol = "//str(s%tol)//"), the "// &
            "others real64 (tol = "//str(s%tol_coarse)//", max_collisions = "// &
            itoa(s%max_collisions)//")")
        call write_answer(unit, "ecrit.several_changes", itoa(n_multi), "one_interval", "0", &
            itoa(n_multi), "rows whose scan of "//itoa(s%n_grid - 1)//" points changes " &
            //"between finite and not finite more than once (the collapse region is then " &
            //"not one interval [0, e_c) on the grid)")
        call write_answer(unit, "ecrit.not_increasing", itoa(n_decrease), "increasing", "0", &
            itoa(n_decrease), "steps p -> p+1 where e_crit does not increase")
        call write_answer(unit, "ecrit.edges_capped", itoa(count(rows%b%outcome_low == 4)), "-", &
            "-", "-", "rows whose edge is bisected against runs that reached max_collisions "// &
            "undecided: there the edge depends on max_collisions and is only an estimate of e_c")
        call write_answer(unit, "ecrit.power_beta", str(-slope), "-", "-", "-", &
            "1 - e_crit = c p^(-beta), least squares of log(1 - e_crit) on log p over "// &
            itoa(n_large)//" rows with p >= "//itoa(p_fit_min))
        call write_answer(unit, "ecrit.power_c", str(c_fit), "-", "-", "-", "c of that fit")
        call write_answer(unit, "ecrit.mcnamara_young_k", str(k_my), "-", "-", "-", &
            "K of p = K (-ln(1 - e_crit))/(1 - e_crit), McNamara and Young's scaling, least "// &
            "squares through the origin over the same rows")
        call close_table(unit, stat, msg)
        call stop_unless_written(stat, msg)
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
            call write_answer(unit, "ecrit.p"//itoa(p), str(rows(i)%e_map), "edge_"// &
                outcome_word(rows(i)%b%outcome_low), str(rows(i)%b%e_high), &
                str(rows(i)%e_map - rows(i)%b%e_high), how(i)//"; "//form)
        else
            call write_answer(unit, "ecrit.p"//itoa(p), str(rows(i)%e_map), check, &
                str(closed), str(rows(i)%e_map - closed), how(i)//"; "//form)
        end if
    end subroutine map_answer

    !> How the rate-map value of row i was found.
    function how(i) result(text)
        integer, intent(in) :: i
        character(len=:), allocatable :: text
        text = "e where the two dominant eigenvalues of the rate map of the collapse cycle "// &
            "(period "//itoa(size(rows(i)%cycle))//", from the run at e = "// &
            str(rows(i)%e_pattern)//") merge into a complex pair, bisected in real(16); "// &
            "the simulated edge (tol = "//str(s%tol)//") is ["//str(rows(i)%b%e_low)// &
            ", "//str(rows(i)%b%e_high)//"]"
    end function how

    !> A real as text, or '-' if it does not exist.
    function optional_real(x, exists) result(text)
        real(qp), intent(in) :: x
        logical, intent(in) :: exists
        character(len=:), allocatable :: text
        text = "-"
        if (exists) text = str(x)
    end function optional_real

    !> The keys of c12-ecrit.
    subroutine define_keys()
        call start_program(cli, "c12-ecrit", &
            "C12 study e_crit(p): the critical restitution of the struck resting row of p"//nl// &
            "equal spheres (a = d = v0 = 1) for p = p_min ... p_max. Writes OUT/ecrit.tsv"//nl// &
            "and OUT/ecrit_answers.tsv.")
        call cli%add_int("p_min", "3", "first row length", lo=3, hi=4096)
        call cli%add_int("p_max", "64", "last row length (>= p_min)", lo=3, hi=4096)
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
        call cli%add_int("n_fit", "8", "runs of the fit of n ~ C (e - e_c)^(-alpha)", &
            lo=2, hi=1000)
        call cli%add_int("fit_n_min", "200", "fewer collisions: left out of that fit", lo=1)
        call cli%add_int("period_max", "128", "longest collapse cycle looked for", &
            lo=1, hi=100000)
    end subroutine define_keys

end program c12_ecrit
