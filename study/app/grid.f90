!> The collapse region of a struck row: the definition's scene with more
!> spheres (equal masses, d = a = v0 = 1, every other setting the engine's
!> default unless cap, vtol or tol is given) over a grid of row lengths p
!> and restitutions e, most of it below the edge e_c(p). Each run's answer,
!> status, collisions, bound and limits, whether its final velocities keep
!> the momentum and approach nowhere within their bounds, the least length
!> q0 from which a struck block is proven to merge at its e, and its wall
!> time (apart, in timing/).
program c12_grid
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, str, itoa, real_str, &
        answer_word, status_word, struck_least, short_text
    use sphere_row_survey, only: check_invariants
    use sphere_row_tables, only: open_table, tab
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, stop_unless_normal, &
        close_tables, fail, add_run_keys, set_run_keys
    implicit none
    !> Multiple of the kind's epsilon by which the invariants may miss, and
    !> the multiple more for each collision a run takes (as c12-collapse).
    real(qp), parameter :: slack = 1.0e4_qp, per_collision = 4.0_qp
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    real(qp), allocatable :: ps(:), es(:)
    real(qp) :: again, gap
    integer :: unit, unit_time, unit_again, stat, i, j, p, disagree
    character(len=300) :: msg
    type(scene_t) :: scene
    type(run_t) :: run, second
    character(len=:), allocatable :: why
    integer(int64) :: c0, c1, rate

    call start_program(cli, "c12-grid", &
        "The collapse region: struck rows of equal spheres (d = a = v0 = 1) over a grid of"//nl// &
        "row lengths p and restitutions e, each run at the engine's default settings"//nl// &
        "unless cap, vtol or tol is given."//nl// &
        "Writes OUT/collapse_grid.tsv (answer, status, collisions, bound, limits, invariants)"// &
        nl//"and the runs' wall times in OUT/timing/collapse_grid.tsv.")
    call cli%add_reals("ps", "50,100,200,1000,10000,100000", "the row lengths p", lo=2.0_qp, &
        hi=1.0e6_qp)
    call cli%add_reals("es", "0.2,0.3,0.5,0.7,0.8,0.9,0.95", "the restitutions e", lo=0.0_qp, &
        hi=1.0_qp)
    call add_run_keys(cli)
    call cli%add_real("again", "0", "above 0: every row run again at vtol times this, and "// &
        "OUT/collapse_grid_again.tsv says whether the two answers' velocities agree within "// &
        "the sum of their bounds", lo=0.0_qp, hi=1.0_qp, hi_open=.true.)
    call read_keys(cli)
    out = cli%get_word("out")
    ps = [50.0_qp, 100.0_qp, 200.0_qp, 1.0e3_qp, 1.0e4_qp, 1.0e5_qp]
    es = [0.2_qp, 0.3_qp, 0.5_qp, 0.7_qp, 0.8_qp, 0.9_qp, 0.95_qp]
    if (cli%given("ps")) ps = cli%get_reals("ps")
    if (cli%given("es")) es = cli%get_reals("es")
    again = cli%get_real("again")
    if (any(ps /= aint(ps))) call fail("c12-grid: ps = "//cli%get_text("ps")// &
        ": allowed whole numbers")

    call open_tables()
    disagree = 0
    do i = 1, size(ps)
        p = nint(ps(i))
        do j = 1, size(es)
            call scene_init(scene, stat, msg, p=p, e=es(j))
            call stop_unless_normal(stat, msg)
            call set_run_keys(cli, scene)
            call system_clock(c0, rate)
            call simulate(scene, run)
            call system_clock(c1)
            call check_invariants(scene, run, slack, per_collision, why)
            if (why == "") why = "hold"
            write (unit, "(a)") itoa(p)//tab//short_text(es(j))//tab// &
                answer_word(run%answer)//tab//status_word(run%status)//tab//itoa(run%n)//tab// &
                real_str(run%v_bound, 2)//tab// &
                itoa(run%limits%certified)//tab//itoa(run%limits%tolerance)//tab// &
                itoa(run%limits%bounded)//tab//why//tab//q0_text(es(j))
            write (unit_time, "(a)") itoa(p)//tab//short_text(es(j))//tab// &
                short_text(real(c1 - c0, qp)/real(rate, qp), 3)//tab// &
                short_text(1.0e6_qp*real(c1 - c0, qp)/real(rate, qp)/max(run%n, 1), 3)
            flush (unit)
            if (again > 0) call run_again()
        end do
    end do
    call close_tables([unit])
    if (again > 0) then
        call close_tables([unit_again])
        write (*, "(a)") "c12-grid: "//itoa(size(ps)*size(es) - disagree)//" agree, "// &
            itoa(disagree)//" differ at vtol times "//short_text(again)
        if (disagree > 0) call fail("c12-grid: "//itoa(disagree)//" rows differ by more "// &
            "than the sum of their bounds at vtol times "//short_text(again))
    end if
    call close_tables([unit_time])
contains
    !> Open the grid's table, its timings and (with `again`) the second runs'.
    subroutine open_tables()
        call open_table(out, "collapse_grid.tsv", "p"//tab//"e"//tab//"answer"//tab//"status"// &
            tab//"collisions"//tab//"v_bound[V]"//tab//"limits_certified"//tab// &
            "limits_tolerance"//tab//"limits_bounded"//tab//"invariants"//tab//"struck_q0", &
            unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call open_table(out//"/timing", "collapse_grid.tsv", "p"//tab//"e"//tab//"run[s]"// &
            tab//"per_collision[us]", &
            unit_time, stat, msg)
        call stop_unless_normal(stat, msg)
        if (again > 0) then
            call open_table(out, "collapse_grid_again.tsv", "p"//tab//"e"//tab//"answer"//tab// &
                "v_bound[V]"//tab//"answer_again"//tab//"v_bound_again[V]"//tab// &
                "difference[V]"//tab//"agree", unit_again, stat, msg)
            call stop_unless_normal(stat, msg)
        end if
    end subroutine open_tables

    !> The row once more at vtol times `again`: its velocities must lie within
    !> the sum of the two bounds of the first run's, sphere by sphere.
    subroutine run_again()
        type(scene_t) :: deeper
        logical :: agree
        deeper = scene
        deeper%vtol = scene%vtol*again
        call simulate(deeper, second)
        gap = maxval(abs(second%v - run%v) - (second%v_bounds + run%v_bounds))
        agree = gap <= 0
        if (.not. agree) disagree = disagree + 1
        write (unit_again, "(a)") itoa(p)//tab//short_text(es(j))//tab// &
            answer_word(run%answer)//tab//real_str(run%v_bound, 2)//tab// &
            answer_word(second%answer)//tab//real_str(second%v_bound, 2)//tab// &
            real_str(maxval(abs(second%v - run%v)), 2)//tab//merge("yes", "no ", agree)
        flush (unit_again)
    end subroutine run_again

    !> The least length from which a struck block of equal spheres is proven
    !> to merge at e (the struck rule's proof), or none.
    function q0_text(e) result(text)
        real(qp), intent(in) :: e
        character(len=:), allocatable :: text
        integer :: q0
        q0 = struck_least(e)
        text = "none"
        if (q0 < huge(1)) text = itoa(q0)
    end function q0_text
end program c12_grid
