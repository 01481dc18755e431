!> Tests of the labels' own rules: when a collapse counts as proven, when a
!> collision passed over below tol is recorded (by the scan's step and by the
!> calendar), and the bound `separation_not_excluded_below` the CLI prints.
!>
!> Each scene is chosen so that exactly one premise of a rule decides it (a
!> limit at tolerance and nothing else, a bounded limit and nothing else,
!> certified limits and a collision passed over), and each test first checks
!> that premise, so that a scene that no longer has it fails loudly instead of
!> passing without testing anything. Where a label denies a proof, the same
!> scene at a finer tol shows why: exact arithmetic takes more collisions.
module test_labels
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, collapse_proven, str, itoa, &
        answer_tolerance, answer_certified, answer_bounded, answer_word
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text
    use test_cli, only: program_path
    use test_support, only: bounded_row
    implicit none
    private
    public :: collect_labels

    character(len=*), parameter :: out_file = "build/test_labels.out"
    !> Rows near p = 8's edge whose limits are all certified but whose steps
    !> pass over collisions closing slower than tol v0 (also in
    !> collapse/label_of_a_pass_below_tol): their restitution, masses, gaps.
    real(qp), parameter :: pass_e(2) = [0.427873_qp, 0.431267_qp]
    real(qp), parameter :: pass_masses(8, 2) = reshape([ &
        67.09_qp, 1.965_qp, 1.002_qp, 1.569_qp, 1.526_qp, 1.79_qp, 1.805_qp, 1.102_qp, &
        1.034_qp, 0.6691_qp, 0.3555_qp, 0.6543_qp, 0.794_qp, 0.002794_qp, 0.6175_qp, &
        1.253_qp], [8, 2])
    real(qp), parameter :: pass_gaps(7, 2) = reshape([ &
        1.046_qp, 1.121_qp, 1.486_qp, 0.0_qp, 0.03103_qp, 0.0_qp, 0.5512_qp, &
        0.0_qp, 1.199_qp, 0.6832_qp, 0.675_qp, 1.975_qp, 0.0_qp, 1.594_qp], [7, 2])
    !> A row of light spheres struck by a heavy one whose groups are merged
    !> at tolerance, with no collision passed over and no bounded limit.
    real(qp), parameter :: tol_masses(4) = [18.25_qp, 0.04349_qp, 0.02667_qp, 0.2489_qp]
    real(qp), parameter :: tol_gaps(3) = [0.6196_qp, 0.0_qp, 1.546_qp]
    real(qp), parameter :: tol_e = 0.555963_qp
    !> calendar_from for the scan of every gap (no row here comes near 1000
    !> spheres) and for the calendar from two spheres on.
    integer, parameter :: scan_only = 1000, calendar_always = 2

contains

    !> The labels' tests.
    function collect_labels() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("limit_at_tolerance_not_proven", test_tolerance_not_proven), &
            new_unittest("bounded_limit_not_proven", test_bounded_not_proven), &
            new_unittest("pass_below_tol_not_proven", test_pass_not_proven), &
            new_unittest("separation_not_excluded_below_printed", test_separation_printed) &
            ]
    end function collect_labels

    !> A group merged because its gaps and rates fell below tol proves no
    !> collapse, even where nothing else in the run rests on tol: the row
    !> tol_* takes only limits at tolerance, no collision is passed over and
    !> none is bounded, so collapse_proven turns on that one premise. At
    !> tol = 1e-60 the same row takes more collisions (1547 for 872): the
    !> merge was not exact arithmetic's end.
    subroutine test_tolerance_not_proven(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run, fine
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=4, e=tol_e, masses=tol_masses, gaps=tol_gaps)
        scene%calendar_from = scan_only
        call simulate(scene, run)
        call check(error, run%limits%tolerance > 0 .and. run%limits%bounded == 0 .and. &
            .not. run%clock%passed, "the premise: limits at tolerance "// &
            itoa(run%limits%tolerance)//", bounded "//itoa(run%limits%bounded)// &
            ", passed over "//merge("yes", "no ", run%clock%passed)// &
            "; expected limits at tolerance and nothing else")
        if (allocated(error)) return
        call check(error, .not. collapse_proven(run) .and. run%answer == answer_tolerance, &
            "a run with limits at tolerance: collapse "// &
            trim(merge("proven  ", "unproven", collapse_proven(run)))//", answer "// &
            answer_word(run%answer)//"; expected unproven, tolerance")
        if (allocated(error)) return
        scene%tol = 1.0e-60_qp
        call simulate(scene, fine)
        call check(error, fine%n > run%n, "at tol 1e-60: "//itoa(fine%n)// &
            " collisions, at the default tol "//itoa(run%n)//"; expected more")
    end subroutine test_tolerance_not_proven

    !> A bounded limit (a long cascade taken to its pooling because its cone
    !> bound is within vtol) proves no collapse either: the touching row of
    !> 20 at e = 1/2 with the closed-form limits off and vtol = 1e-6 takes one
    !> bounded limit and nothing at tolerance.
    subroutine test_bounded_not_proven(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        call bounded_row(scene)
        call simulate(scene, run)
        call check(error, run%limits%bounded > 0 .and. run%limits%tolerance == 0 .and. &
            .not. run%clock%passed, "the premise: bounded limits "//itoa(run%limits%bounded)// &
            ", at tolerance "//itoa(run%limits%tolerance)//", passed over "// &
            merge("yes", "no ", run%clock%passed)//"; expected bounded limits and nothing else")
        if (allocated(error)) return
        call check(error, .not. collapse_proven(run) .and. run%answer == answer_bounded, &
            "a run with a bounded limit: collapse "// &
            trim(merge("proven  ", "unproven", collapse_proven(run)))//", answer "// &
            answer_word(run%answer)//"; expected unproven, bounded")
    end subroutine test_bounded_not_proven

    !> A collision closing slower than tol v0 that reaches contact is one
    !> that exact arithmetic takes: the step that passes over it records it
    !> (clock%passed), in the scan's step and in the calendar's, and a run
    !> that did is at best at tolerance and proves no collapse, though every
    !> limit it took is certified. The rows pass_* at tol = 1e-60 take more
    !> collisions (1532 for 809, 833 for 503).
    subroutine test_pass_not_proven(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run, fine
        integer :: stat, i, k
        integer, parameter :: ways(2) = [scan_only, calendar_always]
        character(len=*), parameter :: way_names(2) = ["scan    ", "calendar"]
        character(len=200) :: msg
        do i = 1, size(pass_e)
            do k = 1, size(ways)
                call scene_init(scene, stat, msg, p=8, e=pass_e(i), masses=pass_masses(:, i), &
                    gaps=pass_gaps(:, i))
                scene%calendar_from = ways(k)
                call simulate(scene, run)
                call check(error, run%limits%n > 0 .and. run%limits%certified == run%limits%n, &
                    "e = "//str(pass_e(i))//" ("//trim(way_names(k))//"): the premise: "// &
                    itoa(run%limits%certified)//" of "//itoa(run%limits%n)// &
                    " limits certified; expected every limit certified")
                if (allocated(error)) return
                call check(error, run%clock%passed .and. .not. collapse_proven(run) .and. &
                    run%answer == answer_tolerance, "e = "//str(pass_e(i))//" ("// &
                    trim(way_names(k))//"): passed over "// &
                    merge("yes", "no ", run%clock%passed)//", collapse "// &
                    trim(merge("proven  ", "unproven", collapse_proven(run)))//", answer "// &
                    answer_word(run%answer)//"; expected yes, unproven, tolerance")
                if (allocated(error)) return
                scene%tol = 1.0e-60_qp
                call simulate(scene, fine)
                call check(error, fine%n > run%n, "e = "//str(pass_e(i))//" ("// &
                    trim(way_names(k))//") at tol 1e-60: "//itoa(fine%n)// &
                    " collisions, at the default tol "//itoa(run%n)//"; expected more")
                if (allocated(error)) return
            end do
        end do
    end subroutine test_pass_not_proven

    !> Where a collapse is unproven, the CLI prints the final rates inside a
    !> merged group that exact arithmetic can have given the bound: two
    !> velocities each within v_bound of theirs differ by at most 2 v_bound,
    !> in units of v0. At v0 = 4, so that a lost 1/v0 shows, for the row
    !> p = 7, e = 0.39 (merged at tolerance after 828 collisions) and the row tol_*
    !> at tol = 1e-12 (a bound far above the rounding); a proven collapse
    !> (p = 4, e = 0.1) prints no such line. Both numbers are printed to two
    !> digits: they agree within their rounding, 5 % each.
    subroutine test_separation_printed(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: unproven(2) = [character(len=110) :: &
            "p=7 e=0.39 v0=4", &
            "p=4 e=0.555963 gaps=0.6196,0,1.546 masses=18.25,0.04349,0.02667,0.2489 " &
            //"tol=1e-12 v0=4"]
        real(qp), parameter :: v0 = 4, printed = 0.1_qp
        character(len=:), allocatable :: out
        real(qp) :: bound, below
        integer :: i, status
        do i = 1, size(unproven)
            call run_cli(trim(unproven(i)), status, out)
            bound = value_of(out, "v_bound")
            below = value_of(out, "separation_not_excluded_below")
            call check(error, status == 0 .and. index(out, "collapse unproven") > 0 .and. &
                bound > 0 .and. abs(below - 2*bound/v0) <= printed*2*bound/v0, &
                trim(unproven(i))//": v_bound "//str(bound)// &
                ", separation_not_excluded_below "//str(below)//"; expected 2 v_bound/v0 = " &
                //str(2*bound/v0))
            if (allocated(error)) return
        end do
        call check(error, value_of(out, "v_bound") > 1.0e-12_qp, "tol=1e-12: v_bound " &
            //str(value_of(out, "v_bound"))//"; expected the merge's bound, above 1e-12")
        if (allocated(error)) return
        call run_cli("p=4 e=0.1", status, out)
        call check(error, status == 0 .and. index(out, "collapse proven") > 0 .and. &
            index(out, "separation_not_excluded_below") == 0, &
            "p=4 e=0.1: a proven collapse with separation_not_excluded_below, or none proven")
    end subroutine test_separation_printed

    !> Run the CLI with `args`: its exit status and stdout.
    subroutine run_cli(args, status, out)
        character(len=*), intent(in) :: args
        integer, intent(out) :: status
        character(len=:), allocatable, intent(out) :: out
        character(len=:), allocatable, save :: path
        if (.not. allocated(path)) path = program_path("sphere-row")
        call execute_command_line(path//" "//args//" > "//out_file//" 2> /dev/null", &
            exitstat=status)
        out = read_text(out_file)
    end subroutine run_cli

    !> The number on the line `name value` of an answer (-1 if there is none).
    real(qp) function value_of(text, name)
        character(len=*), intent(in) :: text, name
        character(len=*), parameter :: nl = new_line("a")
        integer :: at, ends, ios
        value_of = -1
        at = index(nl//text, nl//name//" ")
        if (at == 0) return
        at = at + len(name) + 1
        ends = index(text(at:), nl)
        if (ends == 0) ends = len(text) - at + 2
        read (text(at:at + ends - 2), *, iostat=ios) value_of
        if (ios /= 0) value_of = -1
    end function value_of
end module test_labels
