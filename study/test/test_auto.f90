!> Tests of c2's precision=auto: the certified real(64) lean run against the
!> real(16) lean path (collision count and sequence equal, v4 within the
!> certified bound, escalation where a decision is too close to call), the
!> Monte Carlo statistics of both precisions, and the c12-c2 program giving
!> the same files on one thread and on two.
module test_auto
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp, scene_t, scene_init, str, itoa, status_normal
    use sphere_row_lean, only: lean_row_t, lean_collisions_max
    use sphere_row_analysis, only: sequence_hash
    use sphere_row_bisection, only: bisect_changes
    use sphere_row_monte_carlo, only: monte_carlo_v4, mc_counts_t, sample_moments, sort_values, &
        sorted_quantile
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text, count_lines
    implicit none
    private
    public :: collect_auto

    !> e_crit = 3 - 2 sqrt 2: below it the row collapses.
    real(qp), parameter :: e_crit = 0.1715728752538099023966225515806039_qp
    !> The golden ratio's fraction, for e values that fill [0, 1] evenly.
    real(dp), parameter :: golden = 0.6180339887498948482045868343656381_dp
    !> Largest difference allowed between the statistics of both precisions:
    !> each v4 differs by its bound (about 1e-14 at most), far below it.
    real(dp), parameter :: stats_tolerance = 1.0e-12_dp
    !> Lower end of the scan for changes of the collision sequence: above
    !> e_crit by enough that the real(16) lean path answers every run.
    real(qp), parameter :: scan_lo = 0.18_qp
    !> The lean row whose sequences the scan labels (the class function of
    !> bisect_changes takes e alone).
    type(lean_row_t) :: scan_row

contains

    !> The suite.
    function collect_auto() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("auto_statistics_equal_qp", test_statistics), &
            new_unittest("auto_definition_decisions", test_definition), &
            new_unittest("auto_family_decisions", test_family), &
            new_unittest("c2_one_and_two_threads_identical", test_threads), &
            new_unittest("c2_precision_key_refused", test_precision_key), &
            new_unittest("sweeps_one_and_two_threads_identical", test_sweep_threads), &
            new_unittest("collapse_survey_one_and_two_threads_identical", &
            test_collapse_threads), &
            new_unittest("b1_auto_tables_equal_qp", test_b1_auto), &
            new_unittest("b1_intervals_split_at_e_crit_and_joined", test_b1_intervals) &
            ]
    end function collect_auto

    !> 2 10^4 samples of c2's stream with precision auto and qp: the same
    !> collision count, each v4 within the certified bound, and mean, sd and
    !> quantiles equal to stats_tolerance.
    subroutine test_statistics(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: n = 20000
        real(dp), parameter :: levels(5) = [0.025_dp, 0.25_dp, 0.5_dp, 0.75_dp, 0.975_dp]
        type(scene_t) :: scene
        type(mc_counts_t) :: c_auto, c_qp
        real(dp) :: v_auto(n), v_qp(n), e_auto(n), e_qp(n), m(2), s(2)
        integer :: stat, j
        character(len=200) :: msg
        call scene_init(scene, stat, msg)
        call monte_carlo_v4(scene, 0.5_qp, 0.05_qp, 12, 1, v_auto, e_auto, c_auto, stat, msg, &
            auto=.true.)
        call check(error, stat == status_normal, "auto refused: "//trim(msg))
        call monte_carlo_v4(scene, 0.5_qp, 0.05_qp, 12, 1, v_qp, e_qp, c_qp, stat, msg)
        call check(error, stat == status_normal, "qp refused: "//trim(msg))
        if (allocated(error)) return
        call check(error, all(e_auto == e_qp), "the samples of e differ")
        call check(error, c_auto%collisions == c_qp%collisions .and. &
            c_auto%collapsed == c_qp%collapsed, "collision counts differ")
        call check(error, c_auto%bound_max > 0.0_dp .and. c_auto%bound_max < stats_tolerance, &
            "bound_max = "//str(c_auto%bound_max)//": not in (0, 1e-12)")
        call check(error, all(abs(v_auto - v_qp) <= c_auto%bound_max + spacing(v_qp)), &
            "a v4 beyond the bound")
        call check(error, any(v_auto /= v_qp), "no v4 from real(64): nothing compared")
        call sample_moments(v_auto, m(1), s(1))
        call sample_moments(v_qp, m(2), s(2))
        call check(error, abs(m(1) - m(2)) <= stats_tolerance, "means differ: " &
            //str(m(1))//" vs "//str(m(2)))
        call check(error, abs(s(1) - s(2)) <= stats_tolerance, "sd differ: " &
            //str(s(1))//" vs "//str(s(2)))
        call sort_values(v_auto)
        call sort_values(v_qp)
        do j = 1, size(levels)
            call check(error, abs(sorted_quantile(v_auto, levels(j)) - &
                sorted_quantile(v_qp, levels(j))) <= stats_tolerance, &
                "quantile "//str(levels(j))//" differs")
        end do
    end subroutine test_statistics

    !> The definition's row over about 5000 e: an even grid, scattered e, e
    !> within 1 ulp ... 1e-3 of every change of the real(16) collision
    !> sequence found above scan_lo, and e around e_crit. Every certified run
    !> has real(16)'s count and sequence and v4 within its bound; escalation
    !> happens at every change (at one of the doubles nearest it) and around
    !> e_crit, and real(64) answers nearly all of the even grid above 0.2.
    subroutine test_definition(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        real(qp), allocatable :: changes(:)
        real(dp), allocatable :: e(:)
        logical, allocatable :: escalated(:)
        integer :: stat, j, near, certified_grid
        integer, parameter :: n_grid = 2001, n_scatter = 1000, per_change = 21, n_crit = 200
        character(len=200) :: msg
        call scene_init(scene, stat, msg)
        changes = sequence_changes(scene)
        call check(error, size(changes) >= 5, "only "//itoa(size(changes)) &
            //" changes of the sequence found above e = 0.18")
        if (allocated(error)) return
        e = [(real(j, dp)/(n_grid - 1), j=0, n_grid - 1), &
            (modulo(j*golden, 1.0_dp), j=1, n_scatter)]
        do j = 1, size(changes)
            e = [e, around(changes(j))]
        end do
        e = [e, around_crit()]
        call compare_auto(error, scene, e, escalated)
        if (allocated(error)) return
        ! above e = 0.2 (no collapse), real(64) answers nearly every run
        certified_grid = count(.not. escalated(:n_grid) .and. e(:n_grid) >= 0.2_dp)
        call check(error, certified_grid > 0.95_dp*count(e(:n_grid) >= 0.2_dp), &
            "real(64) certified only "//itoa(certified_grid)//" of the even grid above 0.2")
        do j = 1, size(changes)
            near = n_grid + n_scatter + (j - 1)*per_change
            ! the 7 doubles nearest the change come first in around()
            call check(error, any(escalated(near + 1:near + 7)), "no escalation at the change" &
                //" of sequence at e = "//str(changes(j)))
        end do
        call check(error, all(escalated(size(e) - n_crit + 1:)), &
            "a run within 1e-4 of e_crit certified in real(64)")
    contains
        !> The 7 doubles nearest b, then b (1 +- 10^-k), k = 15, 13, ..., 3.
        function around(b) result(es)
            real(qp), intent(in) :: b
            real(dp) :: es(per_change)
            real(dp) :: bd
            integer :: i
            bd = real(b, dp)
            es(:7) = [(bd + i*spacing(bd), i=-3, 3)]
            do i = 1, 7
                es(6 + 2*i) = bd*(1.0_dp - 10.0_dp**(-17 + 2*i))
                es(7 + 2*i) = bd*(1.0_dp + 10.0_dp**(-17 + 2*i))
            end do
        end function around
        !> n_crit values within 1e-4 of e_crit, on both sides.
        function around_crit() result(es)
            real(dp) :: es(n_crit)
            integer :: i
            es = [(real(e_crit, dp)*(1.0_dp + 1.0e-4_dp*(2*i - n_crit - 1)/n_crit), i=1, n_crit)]
        end function around_crit
    end subroutine test_definition

    !> Other rows of the lean family (other equal masses, unequal gaps, v0;
    !> a touching pair; a coarse tolerance): certified runs agree with
    !> real(16), on an even grid and scattered e.
    subroutine test_family(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        real(dp), allocatable :: e(:)
        logical, allocatable :: escalated(:)
        integer :: stat, j
        character(len=200) :: msg
        e = [(real(j, dp)/400, j=0, 400), (modulo(j*golden, 1.0_dp), j=1, 400)]
        call scene_init(scene, stat, msg, masses=[2.5_qp, 2.5_qp, 2.5_qp, 2.5_qp], &
            gaps=[0.5_qp, 1.0_qp, 2.0_qp], v0=3.0_qp)
        call compare_auto(error, scene, e, escalated)
        call check(error, count(.not. escalated) > size(e)/2, "unequal gaps: few certified")
        call scene_init(scene, stat, msg, gaps=[1.0_qp, 0.0_qp, 0.25_qp])
        call compare_auto(error, scene, e, escalated)
        call scene_init(scene, stat, msg, tol=1.0e-3_qp)
        call compare_auto(error, scene, e, escalated)
        call check(error, count(.not. escalated) > size(e)/2, "tol = 1e-3: few certified")
    end subroutine test_family

    !> At every e: auto answers with real(16)'s status, count and v4 (to its
    !> bound, or exactly when escalated); a certified real(64) run has
    !> real(16)'s sequence and a run real(16) hands to the engine is never
    !> certified. `escalated` tells which e were run again in real(16).
    subroutine compare_auto(error, scene, e, escalated)
        type(error_t), allocatable, intent(inout) :: error
        type(scene_t), intent(in) :: scene
        real(dp), intent(in) :: e(:)
        logical, allocatable, intent(out) :: escalated(:)
        type(lean_row_t) :: lean
        integer :: seq_64(lean_collisions_max), seq_128(lean_collisions_max)
        real(qp) :: v4_128
        real(dp) :: v4_64, bound, v4_auto
        integer :: stat, j, n_64, n_128, status_128, status_auto, n_auto
        logical :: certified, deferred
        character(len=200) :: msg
        allocate (escalated(size(e)))
        escalated = .true.
        call lean%prepare(scene, stat, msg)
        call check(error, stat == status_normal, "prepare refused: "//trim(msg))
        if (allocated(error)) return
        do j = 1, size(e)
            call lean%v4(real(e(j), qp), v4_128, status_128, deferred, n_128, seq_128)
            call lean%certified_v4(e(j), v4_64, bound, certified, n_64, seq_64)
            call lean%auto_v4(e(j), v4_auto, status_auto, escalated(j), bound, n_auto)
            call check(error, escalated(j) .eqv. .not. certified, "e = "//str(e(j)) &
                //": auto escalates a certified run or keeps an uncertified one")
            call check(error, status_auto == status_128 .and. n_auto == n_128, "e = " &
                //str(e(j))//": auto's status or count is not real(16)'s")
            if (.not. certified) then
                call check(error, v4_auto == real(v4_128, dp), "e = "//str(e(j)) &
                    //": escalated v4 is not real(16)'s")
            else
                call check(error, .not. deferred, "e = "//str(e(j)) &
                    //": certified a run that real(16) hands to the engine")
                if (allocated(error)) return
                call check(error, n_64 == n_128 .and. all(seq_64(:n_64) == seq_128(:n_128)), &
                    "e = "//str(e(j))//": certified sequence differs from real(16)'s")
                call check(error, abs(real(v4_64, qp) - v4_128) <= bound .and. v4_auto == v4_64, &
                    "e = "//str(e(j))//": v4 = "//str(v4_64)//" beyond its bound " &
                    //str(bound)//" of "//str(v4_128))
            end if
            if (allocated(error)) return
        end do
    end subroutine compare_auto

    !> The changes of the real(16) lean path's collision sequence between
    !> scan_lo and 1, on a grid of 2001 e and bisected to real(16)'s resolution.
    function sequence_changes(scene) result(changes)
        type(scene_t), intent(in) :: scene
        real(qp), allocatable :: changes(:)
        integer, parameter :: n_scan = 2001
        real(qp) :: a, b
        integer(int64) :: ca, cb
        integer :: stat, j
        character(len=200) :: msg
        allocate (changes(0))
        call scan_row%prepare(scene, stat, msg)
        if (stat /= status_normal) return
        a = scan_lo
        ca = sequence_class(a)
        do j = 1, n_scan - 1
            b = scan_lo + (1.0_qp - scan_lo)*j/(n_scan - 1)
            cb = sequence_class(b)
            if (cb /= ca) call bisect_changes(sequence_class, a, b, ca, cb, &
                4*epsilon(1.0_qp), changes)
            a = b
            ca = cb
        end do
    end function sequence_changes

    !> Label of the real(16) lean run at e: its sequence's fingerprint (0 if
    !> handed to the engine).
    function sequence_class(e) result(class)
        real(qp), intent(in) :: e
        integer(int64) :: class
        integer :: seq(lean_collisions_max), status, n
        real(qp) :: v4
        logical :: deferred
        call scan_row%v4(e, v4, status, deferred, n, seq)
        class = 0
        if (.not. deferred) class = sequence_hash(seq(:n))
    end function sequence_class

    !> c12-c2 (n = 30000, three blocks of the stream) on one thread and on
    !> two writes the same four tables, byte for byte.
    subroutine test_threads(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: tables(4) = [character(len=20) :: "c2_answers.tsv", &
            "c2_ecdf.tsv", "c2_histogram.tsv", "c2_convergence.tsv"]
        character(len=*), parameter :: dir = "build/test-c2-threads"
        character(len=:), allocatable :: path
        integer :: j, status
        path = c2_path()
        call check(error, len(path) > 0, "c12-c2 not built")
        if (allocated(error)) return
        call execute_command_line("rm -rf "//dir//" && mkdir -p "//dir)
        do j = 1, 2
            call execute_command_line("OMP_NUM_THREADS="//achar(48 + j)//" "//path &
                //" n=30000 out="//dir//"/t"//achar(48 + j)//" > /dev/null", exitstat=status)
            call check(error, status == 0, "c12-c2 on "//achar(48 + j)//" threads failed")
        end do
        do j = 1, size(tables)
            if (allocated(error)) exit
            call execute_command_line("cmp -s "//dir//"/t1/"//trim(tables(j))//" "//dir//"/t2/" &
                //trim(tables(j)), exitstat=status)
            call check(error, status == 0, trim(tables(j))//" differs between 1 and 2 threads")
        end do
        if (.not. allocated(error)) call check(error, index(read_text(dir//"/t1/c2_answers.tsv"), &
            "c2.escalated"//achar(9)) > 0, "c2_answers.tsv has no row c2.escalated")
        call execute_command_line("rm -rf "//dir)
    end subroutine test_threads

    !> precision=dp is refused: exit status 2, one line on stderr naming the
    !> key, its value and what is allowed, and no table written.
    subroutine test_precision_key(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: dir = "build/test-c2-precision"
        character(len=:), allocatable :: path, err
        integer :: status, exists
        path = c2_path()
        call check(error, len(path) > 0, "c12-c2 not built")
        if (allocated(error)) return
        call execute_command_line("rm -rf "//dir)
        call execute_command_line(path//" precision=dp out="//dir//" > /dev/null 2> " &
            //dir//".err", exitstat=status)
        err = read_text(dir//".err")
        call check(error, status == 2, "exit status not 2")
        call check(error, count_lines(err) == 1 .and. index(err, "precision = dp") > 0 .and. &
            index(err, "allowed auto or qp") > 0, "message: "//err)
        call execute_command_line("test -e "//dir, exitstat=exists)
        call check(error, exists /= 0, "the output directory was made")
        call execute_command_line("rm -rf "//dir//" "//dir//".err")
    end subroutine test_precision_key

    !> The sweeps of c12-b1 (scan and bisections, critical=no) and c12-b2
    !> (grid) on a coarse grid, on one thread and on two: the same tables,
    !> byte for byte.
    subroutine test_sweep_threads(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: dir = "build/test-sweep-threads"
        character(len=*), parameter :: tables(5) = [character(len=20) :: "b1_scan.tsv", &
            "b1_intervals.tsv", "b1_answers.tsv", "b2_velocities.tsv", "b2_answers.tsv"]
        call run_twice(error, dir, "c12-b1", "n_scan=201 critical=no", "c12-b2", &
            "n_grid=201", "OMP_NUM_THREADS=1 ", "OMP_NUM_THREADS=2 ", "", "", tables)
    end subroutine test_sweep_threads

    !> c12-collapse on 1 and 2 threads counts the same rows (its rows run on
    !> the threads): the same unanswered rows, rows of order computed,
    !> answers, table per p and survey table (its wall times are in
    !> timing/collapse_survey.tsv, not compared).
    subroutine test_collapse_threads(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: dir = "build/test-collapse-threads"
        character(len=*), parameter :: tables(5) = [character(len=28) :: &
            "collapse_unanswered.tsv", "collapse_order_computed.tsv", "collapse_answers.tsv", &
            "collapse_by_p.tsv", "collapse_survey.tsv"]
        call run_twice(error, dir, "c12-collapse", "n=60 n_before=20 cap=3000", &
            "", "", &
            "OMP_NUM_THREADS=1 ", "OMP_NUM_THREADS=2 ", "", "", tables)
    end subroutine test_collapse_threads

    !> c12-b1 with precision=auto (real(8) where certified) and precision=qp
    !> writes the same scan, intervals and answers, byte for byte: the
    !> certificate makes counts and sequences exact.
    subroutine test_b1_auto(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: dir = "build/test-b1-auto"
        character(len=*), parameter :: tables(3) = [character(len=20) :: "b1_scan.tsv", &
            "b1_intervals.tsv", "b1_answers.tsv"]
        call run_twice(error, dir, "c12-b1", "n_scan=401 critical=no", "", "", "", "", &
            " precision=auto", " precision=qp", tables)
    end subroutine test_b1_auto

    !> c12-b1's intervals: the quasi-plastic range is two rows split at the
    !> cycle's e_crit (collapses below, separates above), with no count or
    !> sequence; no two neighbours have one count and sequence (a change
    !> bisected towards e = 1 once split [0.268, 1) at 1 - 4.7e-13); the
    !> interval below e = 1 reaches 1, and e = 1 is a point of its own.
    subroutine test_b1_intervals(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: dir = "build/test-b1-intervals", one = &
            "1.000000000000000000000000000000000E+00"
        character(len=:), allocatable :: path, table, answers, e_crit, line
        character(len=200), allocatable :: rows(:, :)
        integer :: status, n, k, start, finish
        path = program_path("c12-b1")
        call check(error, len(path) > 0, "c12-b1 is not built")
        if (allocated(error)) return
        call execute_command_line("rm -rf "//dir//" && "//path//" n_scan=101 resolution=1e-8 " &
            //"out="//dir//" > /dev/null", exitstat=status)
        call check(error, status == 0, "c12-b1 n_scan=101 resolution=1e-8 failed")
        if (allocated(error)) return
        answers = read_text(dir//"/b1_answers.tsv")
        start = index(answers, new_line("a")//"b1.e_crit"//achar(9)) + 11
        e_crit = answers(start:start + index(answers(start:), achar(9)) - 2)
        table = read_text(dir//"/b1_intervals.tsv")
        n = count_lines(table) - 1
        allocate (rows(7, n))
        rows = ""
        start = index(table, new_line("a")) + 1
        do k = 1, n
            finish = start + index(table(start:), new_line("a")) - 2
            line = table(start:finish)
            read (line, *) rows(1:6, k)
            rows(7, k) = line(index(line, achar(9), back=.true.) + 1:)
            start = finish + 2
        end do
        call check(error, all(rows(:, 1) == [character(len=200) :: "0.000000000000000000000000" &
            //"000000000E+00", e_crit, rows(3, 1), "-", "quasi_plastic", "collapses", "-"]), &
            "first row: "//trim(rows(1, 1))//" "//trim(rows(2, 1))//" "//trim(rows(6, 1)))
        call check(error, rows(1, 2) == e_crit .and. rows(4, 2) == "-" .and. &
            rows(5, 2) == "quasi_plastic" .and. rows(6, 2) == "separates", "second row from " &
            //trim(rows(1, 2))//": "//trim(rows(6, 2)))
        call check(error, rows(2, n - 1) == one .and. rows(1, n) == one .and. &
            rows(2, n) == one .and. rows(4, n) == "3", "the rows at e = 1: "//trim(rows(2, n - 1)) &
            //", "//trim(rows(1, n))//" "//trim(rows(4, n)))
        do k = 3, n - 1
            call check(error, rows(2, k - 1) == rows(1, k), "a gap between rows before " &
                //trim(rows(1, k)))
            call check(error, rows(4, k) /= rows(4, k - 1) .or. rows(7, k) /= rows(7, k - 1), &
                "neighbours of one count and sequence at "//trim(rows(1, k)))
            if (allocated(error)) return
        end do
        call execute_command_line("rm -rf "//dir)
    end subroutine test_b1_intervals

    !> Programs a (and b, if named) with their keys, once with prefix p1 and
    !> suffix s1 into dir/t1, once with p2 and s2 into dir/t2; then each of
    !> `tables` compared between the two, byte for byte.
    subroutine run_twice(error, dir, a, a_keys, b, b_keys, p1, p2, s1, s2, tables)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in) :: dir, a, a_keys, b, b_keys, p1, p2, s1, s2
        character(len=*), intent(in) :: tables(:)
        character(len=:), allocatable :: path_a, path_b
        integer :: j, status
        path_a = program_path(a)
        path_b = ""
        if (len(b) > 0) path_b = program_path(b)
        call check(error, len(path_a) > 0 .and. (len(b) == 0 .or. len(path_b) > 0), &
            "the programs are not built")
        if (allocated(error)) return
        call execute_command_line("rm -rf "//dir//" && mkdir -p "//dir)
        do j = 1, 2
            call one(path_a, a_keys)
            if (len(b) > 0) call one(path_b, b_keys)
        end do
        do j = 1, size(tables)
            if (allocated(error)) exit
            call execute_command_line("cmp -s "//dir//"/t1/"//trim(tables(j))//" "//dir//"/t2/" &
                //trim(tables(j)), exitstat=status)
            call check(error, status == 0, trim(tables(j))//" differs between the two runs")
        end do
        call execute_command_line("rm -rf "//dir)
    contains
        subroutine one(path, keys)
            character(len=*), intent(in) :: path, keys
            character(len=:), allocatable :: run
            if (j == 1) then
                run = p1//path//" "//keys//" out="//dir//"/t1"//s1
            else
                run = p2//path//" "//keys//" out="//dir//"/t2"//s2
            end if
            call execute_command_line(run//" > /dev/null", exitstat=status)
            call check(error, status == 0, "failed: "//run)
        end subroutine one
    end subroutine run_twice

    !> Path of the c12-c2 executable (see program_path), looked up once.
    function c2_path() result(path)
        character(len=:), allocatable :: path
        character(len=:), allocatable, save :: found
        if (.not. allocated(found)) found = program_path("c12-c2")
        path = found
    end function c2_path

    !> Path of a study program as fpm builds it for the tests' profile,
    !> linked anew (fpm relinks a program only when its own source changes, so
    !> the old one is removed first); "" if it cannot be built.
    function program_path(name) result(path)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: path
        path = built_path(name)
        if (len(path) > 0) call execute_command_line("rm -f "//path)
        path = built_path(name)
    end function program_path

    !> What `fpm run --runner echo <name>` names (building it if needed).
    function built_path(name) result(path)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: path
        character(len=*), parameter :: list = "build/test-program-path.txt"
        character(len=:), allocatable :: text
        integer :: status, last
        path = ""
        call execute_command_line("mkdir -p build && fpm run --runner echo "//name//" > "//list &
            //" 2> /dev/null", exitstat=status)
        if (status /= 0) return
        text = read_text(list)
        call execute_command_line("rm -f "//list)
        ! the last non-empty line
        text = trim(adjustl(text))
        do while (len(text) > 0)
            if (text(len(text):) /= new_line("a")) exit
            text = text(:len(text) - 1)
        end do
        last = index(text, new_line("a"), back=.true.)
        path = trim(adjustl(text(last + 1:)))
    end function built_path

end module test_auto
