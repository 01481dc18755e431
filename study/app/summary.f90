!> The study's summary: results/answers.tsv (key, value) and results/summary.md
!> (every answer with its cross-check, how it was obtained, the figures), made
!> from the per-task answer tables.
program c12_summary
    use sphere_row_tables, only: open_table, tab, split_tabs
    use sphere_row_study_cli, only: cli_t, start_program, read_keys, fail, stop_unless_normal
    implicit none
    character(len=*), parameter :: nl = new_line("a")
    character(len=*), parameter :: tasks(7) = ["a1   ", "a2   ", "b1   ", "b2   ", "c1   ", &
        "c2   ", "ecrit"]
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    character(len=300) :: msg
    integer :: stat, answers, md, i

    call start_program(cli, "c12-summary", &
        "Reads OUT/<task>_answers.tsv of tasks a1 a2 b1 b2 c1 c2 ecrit and writes"//nl// &
        "OUT/answers.tsv and OUT/summary.md.")
    call read_keys(cli)
    out = cli%get_word("out")
    call check_inputs()

    call write_overview()

    call section("a1", "Task a1: the gaps y_i(t) for e = 0.2", [character(len=60) :: &
        "a1_paths"], &
        "The engine carries the gaps y_i and their rates in real(16) and finds each "// &
        "next collision in closed form (t_i = y_i / (-dy_i), the earliest wins); between "// &
        "events the paths are exactly linear, so a1_paths.tsv lists the breakpoints "// &
        "(every collision) and the window's ends. By hand: sphere 1 reaches sphere 2 at "// &
        "t1 = a/v0; sphere 2 leaves with (1+e) v0/2 and reaches sphere 3 at "// &
        "t2 = a/v0 (1 + 2/(1+e)).")
    call section("a2", "Task a2: final velocities, elastic and quasi-plastic", &
        [character(len=60) :: ""], &
        "For e = 1 and equal masses each collision exchanges the two velocities, so the "// &
        "motion is handed down the row in three collisions and ends in sphere 4. Below "// &
        "the critical restitution of b1 the row collapses: infinitely many collisions "// &
        "in finite time, whose limit the engine takes (the group moves on with its "// &
        "momentum-weighted velocity). By momentum all four then move with m1 v0/sum(m) "// &
        "= v0/4; the measure of 'sufficiently equal' is the spread (max v - min v)/v0.")
    call section("b1", "Task b1: number of collisions n(e) and the critical restitution", &
        [character(len=60) :: "b1_n", "b1_critical"], &
        "A scan of e from 1 to 0 (b1_scan.tsv) finds every change of the collision "// &
        "sequence between neighbours and bisects it to 1e-12 (b1_intervals.tsv: each "// &
        "interval of constant n with its sequence). As e falls towards e_crit, n grows "// &
        "without bound: near e_crit the run follows a cycle of collisions (e.g. "// &
        "12123232 or 121323) whose linear map M(e) on the gap rates, a product of the "// &
        "maps (6), has three real eigenvalues below e_crit and a complex pair "// &
        "r exp(+-i theta) above it. A self-similar collapse needs a real dominant "// &
        "eigenvector, so below e_crit the collisions never end; above it the phase "// &
        "theta ~ sqrt(e - e_crit) turns the state out of the cycle after about "// &
        "pi/theta cycles, hence n ~ (e - e_crit)^(-1/2). e_crit is the sign change of "// &
        "the discriminant of det(M(e) - lambda) bisected in real(16); it agrees with "// &
        "tan^2(pi/8) = 3 - 2 sqrt(2) to all digits. The simulation alone (collapsed "// &
        "against finite runs, tolerance 1e-4000) brackets it from above to ~1e-8: a "// &
        "finite run this close to e_crit shrinks its relative velocities below any "// &
        "fixed tolerance. With the default tolerance (epsilon v0) the quasi-plastic "// &
        "case is reported from b1.e_quasi_plastic down.")
    call section("b2", "Task b2: final velocities against e", &
        [character(len=60) :: "b2_velocities"], &
        "On an interval of constant collision sequence each final velocity is a "// &
        "polynomial in e, the product of the collision maps (2), whose coefficients "// &
        "(b2_closed_forms.tsv) are exact dyadic rationals for equal masses. From e = 1 "// &
        "down to b2.single_hit_e_min sphere 4 is hit once, after 1-2 and 2-3 have each "// &
        "passed on the factor (1+e)/2, so v4 = v0 ((1+e)/2)^3 there. Below e_crit all "// &
        "velocities are v0/4.")
    call section("c1", "Task c1: e for v4 = v0/2 (boundary value problem)", &
        [character(len=60) :: "c1_secant"], &
        "A secant iteration of our own in real(16) on r(e) = v4(e) - v0/2, each "// &
        "evaluation a full run. The root lies where sphere 4 is hit once, so by hand "// &
        "((1+e)/2)^3 = 1/2, e = 4^(1/3) - 1. v4(e) is only piecewise smooth and flat "// &
        "(v0/4) below e_crit: the solver reports a flat residual, a step out of [0, 1] "// &
        "and stagnation instead of returning a root (c1_starts.tsv).")
    call section("c2", "Task c2: e normally distributed (Monte Carlo)", &
        [character(len=60) :: "c2_ecdf", "c2_histogram", "c2_convergence"], &
        "e ~ N(0.5, 0.05) by Box-Muller from GSL's mt19937 uniforms (seeded), one "// &
        "real(16) run per sample. Where sphere 4 is hit once (all but about 3e-5 of "// &
        "the mass of this law) v4 = v0 ((1+e)/2)^3 is monotone in e, so its exact law is "// &
        "P(v4 <= v) = Phi((2 (v/v0)^(1/3) - 1 - m)/s), with mean ((1+m)^3 + 3 (1+m) s^2)/8 "// &
        "and quantiles ((1 + m + s z_q)/2)^3: the checks of the table.")
    call section("ecrit", "Study e_crit(p): critical restitution of the struck row of p spheres", &
        [character(len=60) :: "ecrit"], &
        "For p = 3 ... 64 equal spheres (a = d = v0 = 1) a scan of e decides each run by the "// &
        "engine's collapse machinery (certified cycle limit, fallback limit, finite end, or "// &
        "undecided at max_collisions; ecrit.tsv) and bisects the edge of the finite region: "// &
        "in real64 (tol = sqrt(tiny)) for every p, again in real(16) with tol = 1e-4000 for "// &
        "p <= 6. For p <= 6 the collision pattern of a run just below the edge gives the "// &
        "rate map M(e) of the collapse cycle, and e_c is where its two dominant eigenvalues "// &
        "merge into a complex pair (bisected in real(16)): tan^2(pi/12) = 7 - 4 sqrt(3) for "// &
        "p = 3 and tan^2(pi/8) = 3 - 2 sqrt(2) for p = 4. The fallback edge lies about "// &
        "2e-8 above these values (finite runs that close to e_c exhaust even 4000 decades); "// &
        "for p >= 14 the real64 edge is bisected against runs that stay undecided at "// &
        "max_collisions, so there it is a cap-dependent estimate, not a certified bound.")
    close (md)

contains

    !> answers.tsv, and the head of summary.md with the table of every answer.
    subroutine write_overview()
        call open_table(out, "answers.tsv", "key"//tab//"value", answers, stat, msg)
        call stop_unless_normal(stat, msg)
        open (newunit=md, file=out//"/summary.md", status="replace", action="write")
        write (md, "(a)") "# ARGESIM Comparison 12: results", "", &
            "Generated by `make study` from the tables in this directory; do not edit by hand.", &
            "Every real is printed with all the digits of the precision it was computed in.", &
            "`check` names an independent cross-check of the answer (a closed form derived by", &
            "hand, another precision, theory) and `difference` is answer minus check.", "", &
            "## All answers", "", &
            "| key | value | check | check value | difference |", "|---|---|---|---|---|"
        do i = 1, size(tasks)
            call answer_rows(trim(tasks(i)), "table")
        end do
        close (answers)
    end subroutine write_overview

    !> Every task's answer table must be there.
    subroutine check_inputs()
        do i = 1, size(tasks)
            if (.not. exists(out//"/"//trim(tasks(i))//"_answers.tsv")) call fail("out = " &
                //out//": "//trim(tasks(i))//"_answers.tsv missing: run make study")
        end do
    end subroutine check_inputs

    !> A task's section: what was done and derived, its figures, and each
    !> answer with how it was obtained and checked.
    subroutine section(task, title, figures, text)
        character(len=*), intent(in) :: task, title, figures(:), text
        integer :: j
        write (md, "(a)") "", "## "//title, "", text, ""
        do j = 1, size(figures)
            if (len_trim(figures(j)) == 0) cycle
            write (md, "(a)") "![C12 "//task//": "//trim(figures(j))//"]("// &
                trim(figures(j))//".png)", ""
        end do
        call answer_rows(task, "list")
    end subroutine section

    !> Each row of one task's answer table, written in `form`: "table" into
    !> answers.tsv and the markdown table of all answers, "list" as the
    !> bullets of the task's section.
    subroutine answer_rows(task, form)
        character(len=*), intent(in) :: task, form
        character(len=:), allocatable :: f(:)
        character(len=4000) :: line
        integer :: u, ios
        open (newunit=u, file=out//"/"//task//"_answers.tsv", status="old", action="read")
        read (u, "(a)", iostat=ios) line
        do
            read (u, "(a)", iostat=ios) line
            if (ios /= 0) exit
            call split_tabs(trim(line), f)
            if (size(f) < 6) cycle
            if (form == "table") then
                write (answers, "(a)") trim(f(1))//tab//trim(f(2))
                write (md, "(a)") "| "//trim(f(1))//" | "//trim(f(2))//" | "//trim(f(3)) &
                    //" | "//trim(f(4))//" | "//trim(f(5))//" |"
            else
                write (md, "(a)") "- `"//trim(f(1))//"` = "//trim(f(2))//": "//trim(f(6))
            end if
        end do
        close (u)
    end subroutine answer_rows

    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists


end program c12_summary
