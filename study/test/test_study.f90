!> Tests of the study's core computations on small cases: the secant solver,
!> the bisection of changes, the collapse-cycle analysis, the closed forms.
module test_study
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp, scene_t, run_t, event_log_t, scene_init, simulate, str, &
        status_normal
    use sphere_row_analysis, only: sequence_of, sequence_hash, sequence_text, tail_period, &
        rate_map, cubic_discriminant, critical_restitution, sequence_polynomials, poly_eval
    use sphere_row_bisection, only: bisect, bisect_ahead, bisect_changes
    !$ use omp_lib, only: omp_set_num_threads, omp_get_max_threads
    use sphere_row_secant, only: secant, secant_result_t, secant_converged, secant_flat, &
        secant_left_interval, secant_invalid, secant_max_iterations
    use sphere_row, only: itoa, status_word, status_collapsed, real_str
    use sphere_row_tables, only: row_t, tab, write_rows
    use sphere_row_survey, only: survey_t, survey_open, survey_close, survey_scene, &
        scene_command, further_t, step_further, further_merges, further_ends, further_going
    use sphere_row_cli, only: cli_t, string_t
    use sphere_row_scene_keys, only: add_scene_keys, scene_from_cli
    use sphere_row_error, only: input_error_t => error_t
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_study

    real(qp), parameter :: eps = epsilon(1.0_qp)
    !> Shared by the class functions below (they take e only).
    type(scene_t), save :: scene
    type(run_t), save :: run
    type(event_log_t), save :: events

contains

    !> The study's tests.
    function collect_study() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("secant_known_root", test_secant_root), &
            new_unittest("secant_flat_function", test_secant_flat), &
            new_unittest("secant_steps_to_its_cap", test_secant_cap), &
            new_unittest("secant_small_slope_leaves", test_secant_leaves), &
            new_unittest("secant_bad_start", test_secant_bad_start), &
            new_unittest("bisect_staircase", test_bisect_staircase), &
            new_unittest("bisect_change_of_n", test_bisect_n), &
            new_unittest("bisect_ahead_takes_bisects_steps", test_bisect_ahead), &
            new_unittest("write_rows_same_bytes", test_write_rows), &
            new_unittest("survey_command_reads_back", test_survey_command), &
            new_unittest("further_steps_are_the_engines", test_further_steps), &
            new_unittest("further_ends_as_the_engine", test_further_ends), &
            new_unittest("further_tie_leftmost", test_further_tie), &
            new_unittest("critical_restitution_4", test_critical), &
            new_unittest("tail_period", test_tail_period), &
            new_unittest("sequence_polynomials", test_polynomials), &
            new_unittest("table_rows_on_threads", test_rows_on_threads) &
            ]
    end function collect_study

    !> 2 10^4 table rows built at once on the OpenMP threads (where built with
    !> it) by row_t: each the same bytes as str, itoa and status_word write
    !> on one thread, for reals of every size (with exponents of four digits,
    !> nan and inf), integers of both signs (the most negative int64 too) and
    !> status words.
    subroutine test_rows_on_threads(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: n = 20000
        type(row_t), allocatable :: rows(:)
        character(len=:), allocatable :: expected, first_bad
        real(qp) :: zero
        integer :: i, bad
        allocate (rows(n))
        zero = 0
        !$omp parallel do schedule(dynamic, 7) default(shared) private(i)
        do i = 1, n
            call rows(i)%add(value_of(i))
            call rows(i)%add(i - n/2)
            call rows(i)%add(-huge(1_8) - 1_8 + i)
            call rows(i)%add_status(mod(i, 3))
            call rows(i)%add("-")
            call rows(i)%add(value_of(i)/3, 17)
        end do
        !$omp end parallel do
        bad = 0
        do i = 1, n
            expected = str(value_of(i))//tab//itoa(i - n/2)//tab//itoa(-huge(1_8) - 1_8 + i) &
                //tab//status_word(mod(i, 3))//tab//"-"//tab//real_str(value_of(i)/3, 17)
            if (rows(i)%text == expected) cycle
            bad = bad + 1
            if (bad == 1) first_bad = "; row "//itoa(i)//" is '"//rows(i)%text//"', not '" &
                //expected//"'"
        end do
        if (bad > 0) call check(error, .false., itoa(bad)//" rows differ from str, itoa and " &
            //"status_word"//first_bad)
        call check(error, status_word(status_collapsed) == "quasi_plastic", "status word")

    contains

        !> Reals of every size: i-th power of -3/2 scaled into and beyond
        !> four-digit exponents, and nan and inf among them.
        real(qp) function value_of(i)
            integer, intent(in) :: i
            value_of = (-1.5_qp)**mod(i, 400)*10.0_qp**(mod(i, 401) - 200)/7
            if (mod(i, 997) == 0) value_of = zero/zero
            if (mod(i, 991) == 0) value_of = -1/zero
            if (mod(i, 983) == 0) value_of = 1.0e-200_qp*value_of**10
        end function value_of

    end subroutine test_rows_on_threads

    function cubic_minus_two(x) result(f)
        real(qp), intent(in) :: x
        real(qp) :: f
        f = x**3 - 2
    end function cubic_minus_two

    function plateau(x) result(f)
        real(qp), intent(in) :: x
        real(qp) :: f
        f = 0.25_qp + 0*x
    end function plateau

    function gentle(x) result(f)
        real(qp), intent(in) :: x
        real(qp) :: f
        f = 1 + 1.0e-3_qp*x
    end function gentle

    !> x^3 = 2 from 1, 2: converges to 2^(1/3) within the residual tolerance.
    subroutine test_secant_root(error)
        type(error_t), allocatable, intent(out) :: error
        type(secant_result_t) :: r
        call secant(cubic_minus_two, 1.0_qp, 2.0_qp, 0.0_qp, 3.0_qp, 1.0e-30_qp, 64*eps, 50, r)
        call check(error, r%status == secant_converged, "x^3 - 2: not converged")
        call check(error, abs(r%x - 2.0_qp**(1.0_qp/3)) <= 1.0e-30_qp, &
            "x^3 - 2: root "//str(r%x))
        call check(error, r%iterations < 15, "x^3 - 2: too many iterations")
    end subroutine test_secant_root

    !> x^2 = 2 from 1, 2 with at most 3 steps: the secant's iterates, by hand
    !> in rationals, are 4/3, 7/5 and 58/41; the third is returned with the
    !> status of the cap.
    subroutine test_secant_cap(error)
        type(error_t), allocatable, intent(out) :: error
        type(secant_result_t) :: r
        real(qp), parameter :: by_hand(0:4) = [1.0_qp, 2.0_qp, 4.0_qp/3, 7.0_qp/5, 58.0_qp/41]
        call secant(square_minus_two, 1.0_qp, 2.0_qp, 0.0_qp, 3.0_qp, 1.0e-30_qp, 64*eps, 3, r)
        call check(error, r%status == secant_max_iterations .and. r%iterations == 3, &
            "x^2 - 2, 3 steps: not stopped by the cap after 3 steps")
        call check(error, all(abs(r%xs(0:4) - by_hand) <= 8*eps), &
            "x^2 - 2, 3 steps: iterates other than 4/3, 7/5, 58/41")
        call check(error, abs(r%x - 58.0_qp/41) <= 8*eps, "x^2 - 2, 3 steps: x "//str(r%x))
    end subroutine test_secant_cap

    function square_minus_two(x) result(f)
        real(qp), intent(in) :: x
        real(qp) :: f
        f = x*x - 2
    end function square_minus_two

    !> A constant residual is reported as flat, not returned as a root.
    subroutine test_secant_flat(error)
        type(error_t), allocatable, intent(out) :: error
        type(secant_result_t) :: r
        call secant(plateau, 0.1_qp, 0.2_qp, 0.0_qp, 1.0_qp, 1.0e-30_qp, 64*eps, 50, r)
        call check(error, r%status == secant_flat .and. r%iterations == 0, &
            "constant residual not reported flat")
    end subroutine test_secant_flat

    !> A root far outside the interval (tiny slope) is reported, not followed.
    subroutine test_secant_leaves(error)
        type(error_t), allocatable, intent(out) :: error
        type(secant_result_t) :: r
        call secant(gentle, 0.1_qp, 0.2_qp, 0.0_qp, 1.0_qp, 1.0e-30_qp, 64*eps, 50, r)
        call check(error, r%status == secant_left_interval, "step out of [0,1] not reported")
    end subroutine test_secant_leaves

    subroutine test_secant_bad_start(error)
        type(error_t), allocatable, intent(out) :: error
        type(secant_result_t) :: r
        call secant(gentle, 0.5_qp, 0.5_qp, 0.0_qp, 1.0_qp, 1.0e-30_qp, 64*eps, 50, r)
        call check(error, r%status == secant_invalid, "equal starts accepted")
        call secant(gentle, -1.0_qp, 0.5_qp, 0.0_qp, 1.0_qp, 1.0e-30_qp, 64*eps, 50, r)
        call check(error, r%status == secant_invalid, "start outside the interval accepted")
    end subroutine test_secant_bad_start

    function staircase(e) result(class)
        real(qp), intent(in) :: e
        integer(8) :: class
        class = int(floor(10*e), 8)
    end function staircase

    !> floor(10 e) between 0.05 and 0.35: three steps, each found to 1e-12.
    subroutine test_bisect_staircase(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: b(:)
        integer :: k
        allocate (b(0))
        call bisect_changes(staircase, 0.05_qp, 0.35_qp, 0_8, 3_8, 1.0e-12_qp, b)
        call check(error, size(b) == 3, "staircase: expected 3 changes")
        if (allocated(error)) return
        do k = 1, 3
            call check(error, abs(b(k) - k/10.0_qp) <= 1.0e-12_qp, "staircase: change at " &
                //str(b(k)))
        end do
    end subroutine test_bisect_staircase

    !> bisect_ahead on 1 to 4 threads leaves lo and hi bit for bit where
    !> bisect does: for a single change, for a test that changes side many
    !> times (the path, not the answer, decides), with a width that stops
    !> it early, and with few steps allowed.
    subroutine test_bisect_ahead(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), parameter :: widths(3) = [0.0_qp, 1.0e-12_qp, 0.01_qp]
        integer, parameter :: steps(3) = [1, 7, 300]
        real(qp) :: lo, hi, lo_ahead, hi_ahead
        character(len=:), allocatable :: first_bad
        integer :: threads, t, w, s, f
        first_bad = ""
        threads = 1
        !$ threads = omp_get_max_threads()
        do t = 1, 4
            !$ call omp_set_num_threads(t)
            do f = 1, 2
                do w = 1, size(widths)
                    do s = 1, size(steps)
                        lo = 0.05_qp
                        hi = 0.95_qp
                        lo_ahead = lo
                        hi_ahead = hi
                        if (f == 1) then
                            call bisect(below_root, lo, hi, widths(w), steps(s))
                            call bisect_ahead(below_root, lo_ahead, hi_ahead, widths(w), steps(s))
                        else
                            call bisect(below_ragged, lo, hi, widths(w), steps(s))
                            call bisect_ahead(below_ragged, lo_ahead, hi_ahead, widths(w), &
                                steps(s))
                        end if
                        if (len(first_bad) == 0 .and. (lo_ahead /= lo .or. hi_ahead /= hi)) then
                            first_bad = "threads "//itoa(t)//", test "//itoa(f)//", width " &
                                //str(widths(w))//", steps "//itoa(steps(s))//": [" &
                                //str(lo_ahead)//", "//str(hi_ahead)//"], bisect [" &
                                //str(lo)//", "//str(hi)//"]"
                        end if
                    end do
                end do
            end do
        end do
        !$ call omp_set_num_threads(threads)
        call check(error, len(first_bad) == 0, first_bad)
    end subroutine test_bisect_ahead

    !> One change, at 1/3.
    pure logical function below_root(x)
        real(qp), intent(in) :: x
        below_root = x < 1.0_qp/3.0_qp
    end function below_root

    !> Changes side wherever the 10^4 x's integer part changes parity.
    pure logical function below_ragged(x)
        real(qp), intent(in) :: x
        below_ragged = mod(int(1.0e4_qp*x), 2) == 0
    end function below_ragged

    !> write_rows writes the bytes of one write per row, for no rows, one,
    !> a block of them and a block and a bit (rows of different lengths).
    subroutine test_write_rows(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: path = "build/test-write-rows"
        integer, parameter :: counts(4) = [0, 1, 64, 130]
        type(row_t), allocatable :: rows(:)
        integer :: unit, c, i, status
        do c = 1, size(counts)
            allocate (rows(counts(c)))
            do i = 1, counts(c)
                call rows(i)%add(i)
                call rows(i)%add(repeat("x", mod(7*i, 23)))
            end do
            open (newunit=unit, file=path//".a", status="replace", action="write")
            write (unit, "(a)") "head"
            call write_rows(unit, rows)
            close (unit)
            open (newunit=unit, file=path//".b", status="replace", action="write")
            write (unit, "(a)") "head"
            do i = 1, counts(c)
                write (unit, "(a)") rows(i)%text
            end do
            close (unit)
            call execute_command_line("cmp -s "//path//".a "//path//".b", exitstat=status)
            call check(error, status == 0, itoa(counts(c))//" rows: the files differ")
            deallocate (rows)
            if (allocated(error)) exit
        end do
        call execute_command_line("rm -f "//path//".a "//path//".b")
    end subroutine test_write_rows

    !> The command of collapse_unanswered.tsv gives back its row bit for bit:
    !> 300 rows of the survey (masses over six decades, closed gaps), each
    !> command read by sphere-row's own keys, every field compared exactly.
    subroutine test_survey_command(error)
        type(error_t), allocatable, intent(out) :: error
        type(survey_t) :: survey
        type(scene_t) :: drawn, read_back
        type(cli_t) :: cli
        type(input_error_t), allocatable :: refused
        type(string_t), allocatable :: args(:)
        character(len=:), allocatable :: command
        integer :: i, start, blank
        call survey_open(survey, 12, 2, 20, 1.0e3_qp)
        do i = 1, 300
            call survey_scene(survey, drawn)
            drawn%max_collisions = 10000 + i
            command = scene_command(drawn)
            allocate (args(0))
            start = index(command, " ") + 1
            do
                blank = index(command(start:), " ")
                if (blank == 0) exit
                args = [args, string_t(command(start:start + blank - 2))]
                start = start + blank
            end do
            args = [args, string_t(command(start:))]
            cli = cli_t()
            call add_scene_keys(cli)
            call cli%parse(args, refused)
            if (.not. allocated(refused)) call scene_from_cli(cli, read_back, refused)
            deallocate (args)
            call check(error, .not. allocated(refused), "row "//itoa(i)//": refused: "//command)
            if (allocated(error)) exit
            call check(error, read_back%p == drawn%p .and. read_back%e == drawn%e .and. &
                all(read_back%m == drawn%m) .and. all(read_back%a == drawn%a) .and. &
                read_back%max_collisions == drawn%max_collisions, &
                "row "//itoa(i)//" reads back otherwise: "//command)
            if (allocated(error)) exit
        end do
        call survey_close(survey)
    end subroutine test_survey_command

    !> step_further steps the engine's own cascade: sphere 1 strikes a touching
    !> block of two heavy spheres with a light one between them (masses 1;
    !> 100, 0.001, 100; e = 0.5; fallback rule only, so that the engine steps
    !> the cascade itself). Stopped at its 50th collision (sphere 1, bounced
    !> back, still touches: the block is all four) and stepped 3000 more in
    !> double precision, the block's rates are those of the engine stopped at
    !> its 3050th, at the same time, within 10 roundings of double per
    !> collision stepped, relative to the closing rates (an e off by 1e-12
    !> is 5e-9 off).
    subroutine test_further_steps(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: steps = 3000
        type(scene_t) :: row
        type(run_t) :: early, late
        type(further_t) :: further
        integer :: stat
        character(len=200) :: msg
        real(qp), allocatable :: rates(:)
        real(qp) :: drift, allowed
        call scene_init(row, stat, msg, p=4, e=0.5_qp, masses=[1.0_qp, 100.0_qp, &
            0.001_qp, 100.0_qp], gaps=[1.0_qp, 0.0_qp, 0.0_qp])
        row%closed_form_limits = .false.
        row%max_collisions = 50
        call simulate(row, early)
        row%max_collisions = 50 + steps
        call simulate(row, late)
        call step_further(row, early, int(steps, int64), further, rates)
        call check(error, further%first == 1 .and. further%last == 4 .and. &
            further%n == steps .and. further%end == further_going, "block "// &
            itoa(further%first)//"-"//itoa(further%last)//", "//itoa(further%n)//" collisions")
        if (allocated(error)) return
        call check(error, late%clock%t == early%clock%t .and. late%n == 50 + steps, &
            "the cascade is not "// &
            "at one instant: t "//str(early%clock%t)//" and "//str(late%clock%t))
        if (allocated(error)) return
        drift = maxval(abs(rates - late%dy))/maxval(abs(late%dy(2:3)))
        allowed = 10*steps*real(epsilon(1.0_dp), qp)
        call check(error, drift < allowed, "rates "//str(drift)//" apart, allowed "//str(allowed))
    end subroutine test_further_steps

    !> step_further ends where the engine's own cascade ends: each row below
    !> is run one collision by the engine (fallback rule only), stepped
    !> further to the end of its cascade, and run to its end by the engine,
    !> which takes exactly one collision more than step_further (nothing
    !> collides after these cascades); allowed exactly its collisions it ends,
    !> one fewer and it is going. Heavy, light, heavy spheres touching,
    !> struck at one end: merges, every rate quiet. The same struck by a
    !> light sphere from a gap, which bounces back: the cascade ends with
    !> the heavy spheres and the light one between them at one velocity, the
    !> striker moving away (ends). Three equal spheres touching, struck at
    !> e = 0.5 (above the threshold 7 - 4 sqrt 3 of three): they come apart
    !> (ends).
    subroutine test_further_ends(error)
        type(error_t), allocatable, intent(out) :: error
        call one_row([100.0_qp, 1.0_qp, 100.0_qp], [0.0_qp, 0.0_qp], further_merges)
        if (allocated(error)) return
        call one_row([1.0_qp, 100.0_qp, 1.0_qp, 100.0_qp], [1.0_qp, 0.0_qp, 0.0_qp], &
            further_ends)
        if (allocated(error)) return
        call one_row([1.0_qp, 1.0_qp, 1.0_qp], [0.0_qp, 0.0_qp], further_ends)
    contains
        subroutine one_row(masses, gaps, end)
            real(qp), intent(in) :: masses(:), gaps(:)
            integer, intent(in) :: end
            type(scene_t) :: row
            type(run_t) :: run, whole
            type(further_t) :: further
            integer(int64) :: n
            integer :: stat
            character(len=200) :: msg
            call scene_init(row, stat, msg, p=size(masses), e=0.5_qp, masses=masses, gaps=gaps)
            row%closed_form_limits = .false.
            call simulate(row, whole)
            row%max_collisions = 1
            call simulate(row, run)
            call step_further(row, run, 10000000_int64, further)
            call check(error, further%end == end .and. whole%n == 1 + further%n, &
                itoa(size(masses))//" spheres: end "//itoa(further%end)//" after "// &
                itoa(further%n)//" more; the engine ends after "//itoa(whole%n))
            if (allocated(error)) return
            ! allowed exactly the collisions it takes, it ends; one fewer, it goes on
            n = further%n
            call step_further(row, run, n, further)
            call check(error, further%end == end .and. further%n == n, &
                itoa(size(masses))//" spheres, "//itoa(n)//" allowed: end "//itoa(further%end))
            if (allocated(error)) return
            call step_further(row, run, n - 1, further)
            call check(error, further%end == further_going .and. further%n == n - 1, &
                itoa(size(masses))//" spheres, "//itoa(n - 1)//" allowed: end "// &
                itoa(further%end))
        end subroutine one_row
    end subroutine test_further_ends

    !> Of two contacts closing equally fast the leftmost collides first, as
    !> in the engine: three equal spheres touching, rates -1 and -1, e = 0.5;
    !> after one collision the left contact opens at 0.5 and the right one
    !> closes at 1 + 0.75 (the other order would open the right one).
    subroutine test_further_tie(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: row
        type(run_t) :: run
        type(further_t) :: further
        real(qp), allocatable :: rates(:)
        integer :: stat
        character(len=200) :: msg
        call scene_init(row, stat, msg, p=3, e=0.5_qp, gaps=[0.0_qp, 0.0_qp])
        run%y = [0.0_qp, 0.0_qp]
        run%dy = [-1.0_qp, -1.0_qp]
        run%ratios%kick_left = [0.75_qp, 0.75_qp]
        run%ratios%kick_right = [0.75_qp, 0.75_qp]
        call step_further(row, run, 1_int64, further, rates)
        call check(error, further%n == 1 .and. size(rates) == 2, "no collision stepped")
        if (allocated(error)) return
        call check(error, rates(1) == 0.5_qp .and. rates(2) == -1.75_qp, "rates after the "// &
            "tie: "//str(rates(1))//", "//str(rates(2)))
    end subroutine test_further_tie

    function n_class(e) result(class)
        real(qp), intent(in) :: e
        integer(8) :: class
        scene%e = e
        call simulate(scene, run, events)
        class = int(run%n, 8)
    end function n_class

    !> The change of n between e = 0.25 and 0.3 of the definition's scene: on
    !> each side of the bisected point, within the resolution, n differs.
    subroutine test_bisect_n(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: b(:)
        integer :: stat, n_lo, n_hi
        character(len=200) :: msg
        call scene_init(scene, stat, msg)
        allocate (b(0))
        call bisect_changes(n_class, 0.25_qp, 0.3_qp, n_class(0.25_qp), n_class(0.3_qp), &
            1.0e-12_qp, b)
        call check(error, size(b) >= 1, "no change of n found in [0.25, 0.3]")
        if (allocated(error)) return
        scene%e = b(1) - 1.0e-12_qp
        call simulate(scene, run)
        n_lo = run%n
        scene%e = b(1) + 1.0e-12_qp
        call simulate(scene, run)
        n_hi = run%n
        call check(error, n_lo /= n_hi, "n does not change across the bisected point")
    end subroutine test_bisect_n

    !> Four equal spheres, cycle 1,2,1,2,3,2,3,2: the eigenvalues of its rate
    !> map merge at tan(pi/8)^2 = 3 - 2 sqrt(2) (the known collapse threshold),
    !> and the discriminant is positive below and negative above.
    subroutine test_critical(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp) :: e_c, a(3, 3), m(4)
        integer :: stat
        m = 1
        call critical_restitution(m, [1, 2, 1, 2, 3, 2, 3, 2], 0.1_qp, 0.3_qp, e_c, stat)
        call check(error, stat == status_normal, "no sign change in [0.1, 0.3]")
        call check(error, abs(e_c - (3 - 2*sqrt(2.0_qp))) <= 1.0e-30_qp, "e_c = "//str(e_c))
        call rate_map(m, 0.15_qp, [1, 2, 1, 2, 3, 2, 3, 2], a)
        call check(error, cubic_discriminant(a) > 0, "discriminant not > 0 below e_c")
        call rate_map(m, 0.2_qp, [1, 2, 1, 2, 3, 2, 3, 2], a)
        call check(error, cubic_discriminant(a) < 0, "discriminant not < 0 above e_c")
        call critical_restitution([1.0_qp, 1.0_qp, 1.0_qp], [1, 2], 0.01_qp, 0.5_qp, e_c, stat)
        call check(error, stat /= status_normal, "three spheres accepted by the 3x3 analysis")
    end subroutine test_critical

    subroutine test_tail_period(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: cycle(6) = [1, 2, 1, 3, 2, 3]
        integer :: s(60), j
        s(1:6) = [3, 1, 3, 3, 2, 1]
        do j = 7, 60
            s(j) = cycle(mod(j - 7, 6) + 1)
        end do
        call check(error, tail_period(s, 48, 24) == 6, "period of 121323... not 6")
        call check(error, tail_period(s(1:20), 48, 24) == 0, "short sequence given a period")
        call check(error, sequence_text([1, 2, 3]) == "123", "sequence_text")
        call check(error, sequence_hash([1, 2]) /= sequence_hash([2, 1]), "hash ignores order")
    end subroutine test_tail_period

    !> The polynomials of a run's own sequence reproduce its final velocities,
    !> and for 1,2,3 they are v4 = ((1+e)/2)^3 by hand.
    subroutine test_polynomials(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: coef(:, :)
        integer, allocatable :: pairs(:)
        integer :: stat, i
        character(len=200) :: msg
        call sequence_polynomials([1.0_qp, 1.0_qp, 1.0_qp, 1.0_qp], 1.0_qp, [1, 2, 3], coef)
        call check(error, all(abs(coef(:, 4) - [1, 3, 3, 1]/8.0_qp) <= eps), &
            "123: v4 coefficients not (1,3,3,1)/8")
        call scene_init(scene, stat, msg, e=0.37_qp, masses=[1.0_qp, 2.0_qp, 1.5_qp, 0.5_qp])
        call simulate(scene, run, events)
        call sequence_of(events, pairs)
        call sequence_polynomials(scene%m, scene%v0, pairs, coef)
        do i = 1, 4
            call check(error, abs(poly_eval(coef(:, i), scene%e) - run%v(i)) <= 64*eps, &
                "polynomial of the run's sequence differs from the run")
        end do
    end subroutine test_polynomials

end module test_study
