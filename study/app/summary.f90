!> The study's summary: results/answers.tsv (key, value) and results/summary.md
!> (every answer with its cross-check, how it was obtained, the figures), made
!> from the per-task answer tables.
program c12_summary
    use sphere_row_tables, only: open_table, tab, split_tabs, file_exists
    use sphere_row, only: qp, short_text
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, fail, &
        stop_unless_normal, close_tables
    implicit none
    character(len=*), parameter :: tasks(8) = ["a1      ", "a2      ", "b1      ", &
        "b2      ", "c1      ", "c2      ", "collapse", "ecrit   "]
    !> Columns of an answer table whose numbers the prose quotes.
    integer, parameter :: value = 2, check_value = 4, difference = 5, how_col = 6
    type(cli_t) :: cli
    character(len=:), allocatable :: out
    character(len=300) :: msg
    integer :: stat, answers, md, i

    call start_program(cli, "c12-summary", &
        "Reads OUT/<task>_answers.tsv of tasks a1 a2 b1 b2 c1 c2 collapse ecrit and"//nl// &
        "writes OUT/answers.tsv and OUT/summary.md.")
    call read_keys(cli)
    out = cli%get_word("out")
    call check_inputs()

    call write_overview()

    call sections_a()
    call sections_b()
    call sections_c()
    call sections_beyond()
    call close_tables([md])

contains

    !> The sections of tasks a1 and a2: the gaps of one run, the final velocities
    !> of two.
    subroutine sections_a()
        call section("a1", "Task a1: the gaps y_i(t) for e = "//short("a1", "a1.e"), &
            [character(len=60) :: "a1_paths"], &
            "The engine carries the gaps y_i and their rates in real(16) and finds each "// &
            "next collision in closed form (t_i = y_i / (-dy_i), the earliest wins); between "// &
            "events the paths are exactly linear, so a1_paths.tsv lists the breakpoints "// &
            "(every collision) and the window's ends. By hand: sphere 1 reaches sphere 2 at "// &
            "t1 = a/v0; sphere 2 leaves with (1+e) v0/2 and reaches sphere 3 at "// &
            "t2 = a/v0 (1 + 2/(1+e)).")
        call section("a2", "Task a2: final velocities, elastic and quasi-plastic", &
            [character(len=60) :: ""], &
            "For e = 1 and equal masses each collision exchanges the two velocities, so the "// &
            "motion is handed down the row in p - 1 collisions and ends in the last "// &
            "sphere. Below the critical restitution of b1 the row collapses: infinitely "// &
            "many collisions in finite time, whose limit the engine takes (the group moves "// &
            "on with its momentum-weighted velocity). By momentum all p spheres then move "// &
            "with m1 v0/sum(m) (v0/p for equal masses); the measure of 'sufficiently equal' "// &
            "is the spread (max v - min v)/v0.")
    end subroutine sections_a

    !> The sections of tasks b1 and b2: the collisions and the final velocities
    !> over e.
    subroutine sections_b()
        call section("b1", "Task b1: number of collisions n(e) and the critical restitution", &
            [character(len=60) :: "b1_n", "b1_critical"], &
            "A scan of e from 1 to 0 (b1_scan.tsv) finds every change of the collision "// &
            "sequence between neighbours and bisects it to "//short("b1", "b1.resolution")// &
            " (b1_intervals.tsv: each interval of constant n with its sequence, each "// &
            "collision named by its pair, k for spheres k and k+1: 123121 is 1-2, 2-3, "// &
            "3-4, 1-2, 2-3, 1-2). As e "// &
            "falls towards e_crit, n grows without bound: near e_crit the run follows a "// &
            "cycle of collisions (b1.e_crit names the one found) whose linear map M(e) on "// &
            "the gap rates, a product of the collision maps (6) (the rule (2) written for "// &
            "the gap rates), has three real eigenvalues below "// &
            "e_crit and a complex pair r exp(+-i theta) above it. A self-similar collapse "// &
            "needs a real dominant eigenvector, so below e_crit the collisions never end; "// &
            "above it the phase theta ~ sqrt(e - e_crit) turns the state out of the cycle "// &
            "after about pi/theta cycles, hence n ~ (e - e_crit)^(-1/2). e_crit is the sign "// &
            "change of the discriminant of det(M(e) - lambda) bisected in real(16); it "// &
            "agrees with tan^2(pi/8) = 3 - 2 sqrt(2) to all digits. The simulation alone "// &
            "(collapsed against finite runs, tolerance "//short("b1", "b1.tol_fine")// &
            ") brackets it from above to ~"//short("b1", "b1.e_crit_simulation", difference, 1) &
            //": a finite run this close to e_crit shrinks its relative velocities below "// &
            "any fixed tolerance. With the default tolerance (epsilon v0) the quasi-plastic "// &
            "case is reported from b1.e_quasi_plastic down; the table splits that range at "// &
            "e_crit: below it the row collapses, above it the row separates in exact "// &
            "arithmetic after more collisions than the tolerance follows (b1_critical.tsv).")
        call section("b2", "Task b2: final velocities against e", &
            [character(len=60) :: "b2_velocities"], &
            "On an interval of constant collision sequence each final velocity is a "// &
            "polynomial in e, the product of the collision rule (2) on the velocities "// &
            "(the same rule as (6) on the gap rates), whose coefficients "// &
            "(b2_closed_forms.tsv) are exact dyadic rationals for equal masses. From e = 1 "// &
            "down to b2.single_hit_e_min the last sphere p is hit once, after each pair "// &
            "before it has passed on the factor (1+e)/2, so v_p = v0 ((1+e)/2)^(p-1) there. "// &
            "Below e_crit all velocities are m1 v0/sum(m). Each point runs in the precision "// &
            "it needs (precision = auto): b2.points_in_real64 of them in real(8) under the "// &
            "rounding certificate, the others in real(16); b2.beyond_bound finite points lie "// &
            "farther from their polynomials than their certified bounds allow.")
    end subroutine sections_b

    !> The sections of tasks c1 and c2: the boundary value problem and the Monte
    !> Carlo.
    subroutine sections_c()
        call section("c1", "Task c1: e for v_p = "//short("c1", "c1.v4", check_value)// &
            " (boundary value problem)", &
            [character(len=60) :: "c1_secant"], &
            "A secant iteration of our own in real(16) on r(e) = v_p(e) - target v0, each "// &
            "evaluation a full run. Where the root lies in the range in which the last "// &
            "sphere is hit once, by hand ((1+e)/2)^(p-1) = target, so "// &
            "e = 2 target^(1/(p-1)) - 1 (c1.e). v_p(e) is only piecewise smooth and flat "// &
            "(m1 v0/sum(m)) below e_crit: the solver reports a flat residual, a step out of "// &
            "[0, 1] and stagnation instead of returning a root (c1_starts.tsv).")
        call section("c2", "Task c2: e normally distributed (Monte Carlo)", &
            [character(len=60) :: "c2_ecdf", "c2_histogram", "c2_convergence"], &
            "e ~ N("//short("c2", "c2.e_mean", check_value)//", "// &
            short("c2", "c2.e_sd", check_value)//") by Box-Muller from GSL's mt19937 "// &
            "uniforms (seeded), one run per sample "//c2_precision()//". Where sphere 4 "// &
            "is hit once "// &
            "(all but about "//outside_share()//" of the mass of this law) "// &
            "v4 = v0 ((1+e)/2)^3 is monotone in e, so its exact law is "// &
            "P(v4 <= v) = Phi((2 (v/v0)^(1/3) - 1 - m)/s), with mean "// &
            "((1+m)^3 + 3 (1+m) s^2)/8 "// &
            "and quantiles ((1 + m + s z_q)/2)^3: the checks of the table.")
    end subroutine sections_c

    !> The sections beyond the benchmark: collapse in general rows, and the
    !> critical restitution of rows of any length.
    subroutine sections_beyond()
        call section("collapse", "Collapse in general rows", &
            [character(len=60) :: "collapse_by_p"], &
            "Seeded random rows (p from 2, masses equal or log-uniform over six decades, "// &
            "e uniform in [0, 1], a fifth of the gaps closed) run to their end by every "// &
            "collapse rule (docs/collapse.md). Every run ends with an answer and a bound: "// &
            field("collapse", "collapse.exact")//" rows exact, "// &
            field("collapse", "collapse.certified")//" certified, "// &
            field("collapse", "collapse.tolerance")//" ended at tolerance, "// &
            field("collapse", "collapse.bounded")//" bounded and "// &
            field("collapse", "collapse.unresolved")//" unresolved of "// &
            field("collapse", "collapse.answered", check_value)//" (collapse_survey.tsv); "// &
            "the largest bound on the final velocities of a row with an answer is "// &
            field("collapse", "collapse.v_bound_max")//" v0. The unresolved rows spent their "// &
            "budget in cascades through touching blocks of light and heavy spheres whose "// &
            "relaxation is slow; each is listed with the groups still active, the bound "// &
            "reached on them and the command that runs it again "// &
            "(collapse_unanswered.tsv).")
        call section("ecrit", "e_crit(p): critical restitution of the struck row of p spheres", &
            [character(len=60) :: "ecrit", "ecrit_map"], &
            "For rows of p equal spheres (a = d = v0 = 1) a fine scan of e around the edge "// &
            "decides each point by the engine's labelled answer: separated (with the scale of "// &
            "its last closing rates), collapse (certified, or bounded), or undecided, counted "// &
            "apart and never as either ("//field("ecrit", "ecrit.rows", how_col)//"; "// &
            "ecrit.tsv, the runs of outcomes in ecrit_map.tsv). Each edge is printed with "// &
            "only the decimals its bracket earns. What was found: the collapse set is not "// &
            "one interval [0, e_c) near its edge. "//field("ecrit", "ecrit.mixed_rows")// &
            " rows have a separated point below a collapsing one, the first at p = "// &
            field("ecrit", "ecrit.first_mixed_p")//"; the widest such band spans "// &
            short("ecrit", "ecrit.band_relative_max")//" (1 - e_c). "// &
            field("ecrit", "ecrit.undecided_rows")//" rows have undecided points: in long "// &
            "rows the "// &
            "collapse side is not decided within the collision cap, and the lowest "// &
            "separated point is only an upper bound that falls when the cap is raised. "// &
            "The edge depends on tol (a row that separates at "// &
            "rates below tol reads as a collapse): from tol = 2e-34 to 1e-300 the lowest "// &
            "separated point falls by up to "//short("ecrit", "ecrit.deep_shift_max")// &
            " (1 - e_c) (ecrit_robust.tsv); real64 at the same tol differs from real(16) at "// &
            field("ecrit", "ecrit.real64_differ")//" points. The rate map of the collapse "// &
            "cycle of the shortest rows gives e_c where its two dominant eigenvalues merge: "// &
            short("ecrit", "ecrit.p3")//" = 7 - 4 sqrt(3) for p = 3 and "// &
            short("ecrit", "ecrit.p4")//" = 3 - 2 sqrt(2) for p = 4. Fits of the lowest "// &
            "separated point over this run's rows from p = 8: 1 - e_c ~ "// &
            short("ecrit", "ecrit.power_c")//" p^(-"// &
            short("ecrit", "ecrit.power_beta")//"), "//short("ecrit", "ecrit.c_over_p")// &
            "/p, McNamara-Young K = "//short("ecrit", "ecrit.mcnamara_young_k")//". The "// &
            "full sweep p = 3 ... 128 is `make ecrit-full` (results/ecrit_full/).")
    end subroutine sections_beyond

    !> answers.tsv, and the head of summary.md with the table of every answer.
    subroutine write_overview()
        call open_table(out, "answers.tsv", "key"//tab//"value", answers, stat, msg)
        call stop_unless_normal(stat, msg)
        call open_table(out, "summary.md", "# ARGESIM Comparison 12: results", md, stat, msg)
        call stop_unless_normal(stat, msg)
        write (md, "(a)") "", &
            "Generated by `make study` from the tables in this directory; do not edit by hand.", &
            "Every real is printed with all the digits of the precision it was computed in.", &
            "`check` names an independent cross-check of the answer (a closed form derived by", &
            "hand, another precision, theory) and `difference` is answer minus check.", "", &
            "## All answers", "", &
            "| key | value | check | check value | difference |", "|---|---|---|---|---|"
        do i = 1, size(tasks)
            call answer_rows(trim(tasks(i)), "table")
        end do
        call close_tables([answers])
    end subroutine write_overview

    !> Every task's answer table must be there.
    subroutine check_inputs()
        do i = 1, size(tasks)
            if (.not. file_exists(out//"/"//trim(tasks(i))//"_answers.tsv")) call fail( &
                "out = "//out//": "//trim(tasks(i))//"_answers.tsv missing: run make study")
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

    !> Column `col` of the row `key` in the answer table of `task`, shortened to
    !> the digits that read back (at most `digits`): the prose quotes the run's
    !> own parameters and results, not fixed numbers.
    function short(task, key, col, digits) result(text)
        character(len=*), intent(in) :: task, key
        integer, intent(in), optional :: col, digits
        character(len=:), allocatable :: text
        real(qp) :: x
        integer :: ios
        text = field(task, key, col)
        read (text, *, iostat=ios) x
        if (ios == 0) text = short_text(x, digits)
    end function short

    !> The precision of c2's runs, in words: real(16), or (precision auto)
    !> real(64) where certified and the count escalated to real(16).
    function c2_precision() result(text)
        character(len=:), allocatable :: text
        text = "in real(16)"
        if (field("c2", "c2.precision") /= "auto") return
        text = "in real(64) where a rounding certificate shows that it takes real(16)'s "// &
            "decisions, else again in real(16) ("//field("c2", "c2.escalated")//" of "// &
            field("c2", "c2.n")//" escalated)"
    end function c2_precision

    !> The share of the law of e outside the range where sphere 4 is struck
    !> once, from c2's expected count of such draws in its sample, to one digit.
    function outside_share() result(text)
        character(len=:), allocatable :: text
        character(len=:), allocatable :: expected_text, n_text
        real(qp) :: expected, n
        integer :: ios_1, ios_2
        text = "?"
        expected_text = field("c2", "c2.outside_region", check_value)
        n_text = field("c2", "c2.n", value)
        read (expected_text, *, iostat=ios_1) expected
        read (n_text, *, iostat=ios_2) n
        if (ios_1 == 0 .and. ios_2 == 0) text = short_text(expected/n, 1)
    end function outside_share

    !> Column `col` (default the value) of the row `key` in the answer table
    !> of `task`; the run stops if the row is missing.
    function field(task, key, col) result(text)
        character(len=*), intent(in) :: task, key
        integer, intent(in), optional :: col
        character(len=:), allocatable :: text
        character(len=:), allocatable :: f(:)
        character(len=4000) :: line
        integer :: u, ios, c
        c = value
        if (present(col)) c = col
        open (newunit=u, file=out//"/"//task//"_answers.tsv", status="old", action="read")
        do
            read (u, "(a)", iostat=ios) line
            if (ios /= 0) exit
            call split_tabs(trim(line), f)
            if (size(f) < c) cycle
            if (trim(f(1)) /= key) cycle
            text = trim(f(c))
            close (u)
            return
        end do
        close (u)
        call fail("out = "//out//": "//task//"_answers.tsv has no row "//key// &
            ": run make study")
    end function field

end program c12_summary
