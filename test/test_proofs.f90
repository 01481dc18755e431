!> The conditions of the collapse rules' proofs, each tested where it decides:
!> a scene on which the rule must decline (or must take its limit), run with
!> the rules and again with the fallback alone (closed_form_limits off, every
!> collision stepped until a group merges below tol), the two answers within
!> the sum of their bounds. A rule that takes a limit its proof does not
!> cover ends elsewhere; one that declines what it should take costs work.
module test_proofs
    use sphere_row, only: qp, scene_t, run_t, simulate, itoa, str, answer_word, &
        status_max_collisions
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text
    use test_support, only: scene_of, split_tabs, read_reals
    implicit none
    private
    public :: collect_proofs

    !> A scene a rule must decline or take: why it is here, its keys.
    type :: case_t
        character(len=:), allocatable :: why, keys
    end type case_t

contains

    !> The tests of the proofs' conditions.
    function collect_proofs() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("rules_agree_with_the_fallback_where_they_decline", test_declines), &
            new_unittest("followed_group_struck_before_its_end", test_follow_struck) &
            ]
    end function collect_proofs

    !> Scenes at the edge of a rule's conditions, each run with the rules and
    !> with the fallback alone: the same velocities within the two bounds.
    subroutine test_declines(error)
        type(error_t), allocatable, intent(out) :: error
        type(case_t), allocatable :: cases(:)
        integer :: i
        cases = [ &
            ! the struck block (sphere_row_struck.inc) absorbs a sphere only
            ! with the gaps beside the cascade open: the front block strikes
            ! sphere 41, which touches the last, light, sphere 42, so the
            ! cascade runs on into it at the same instant (absorbed first,
            ! sphere 42 would leave at 0.0333 instead of 0.0256)
            case_t("a struck block's striker touching a light last sphere", &
                "p=42 e=0.5 masses="//list("1", 41)//",0.1 gaps="//list("1", 40)//",0"), &
            ! the same, turned round: sphere 42 strikes the row to its left,
            ! its block struck at its rear by sphere 2, which touches the
            ! light sphere 1 (the gap beside the cascade on its left closed)
            case_t("a block struck at its rear by a sphere touching a light first one", &
                "p=42 e=0.5 masses=0.1,"//list("1", 41)//" gaps=0,"//list("1", 40) &
                //" velocities="//list("0", 41)//",-1"), &
            ! a block absorbs only a sphere of its own mass: the block of 41
            ! moving left strikes a light sphere 1 at rest, which leaves
            ! faster than the block instead of joining it
            case_t("a block striking a light sphere", &
                "p=42 e=0.5 masses=0.1,"//list("1", 41)//" velocities="//list("0", 41)//",-1") &
            ]
        do i = 1, size(cases)
            call against_fallback(cases(i), error)
            if (allocated(error)) return
        end do
    end subroutine test_declines

    !> Run a case with the rules and with the fallback alone: both answer,
    !> and their velocities lie within the sum of their bounds.
    subroutine against_fallback(c, error)
        type(case_t), intent(in) :: c
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: fast, slow
        integer :: i
        call scene_of(c%keys, scene, error)
        if (allocated(error)) return
        scene%max_collisions = 2000000
        call simulate(scene, fast)
        scene%closed_form_limits = .false.
        call simulate(scene, slow)
        call check(error, fast%status /= status_max_collisions .and. &
            slow%status /= status_max_collisions, c%why//": no answer within the budget, "// &
            itoa(fast%n)//" and "//itoa(slow%n)//" collisions")
        if (allocated(error)) return
        do i = 1, scene%p
            call check(error, abs(fast%v(i) - slow%v(i)) <= fast%v_bounds(i) + slow%v_bounds(i), &
                c%why//": v"//itoa(i)//" = "//str(fast%v(i))//" ("//answer_word(fast%answer) &
                //"), the fallback's "//str(slow%v(i))//" ("//answer_word(slow%answer)//")")
            if (allocated(error)) return
        end do
    end subroutine against_fallback

    !> A group followed on its own scale (sphere_row_follow.inc) has its end
    !> taken only if nothing outside reaches it before that end: p = 5's
    !> shuttle near its edge (e = 0.260419, spheres 1..5 quiet below tol =
    !> 1e-6 at t = 16.17, their own run separating 0.11 later), with a light
    !> sphere 6 thrown at it to arrive halfway through. Taking the group's
    !> end at once, as if separated, leaves sphere 6 at 0.3750025 where exact
    !> arithmetic (tools/replay, 80 digits) gives 0.3750024, with a bound of
    !> 1e-32; declined, the run merges the group at tol and its velocities
    !> lie within its bound of the replay's.
    subroutine test_follow_struck(error)
        type(error_t), allocatable, intent(out) :: error
        ! (the replay takes no tol: it steps every collision exactly)
        character(len=*), parameter :: keys = "p=6 e=0.260419 gaps=1,1,1,1,17.49 " &
            //"velocities=1,0,0,0,0,-1 masses=1,1,1,1,1,0.1", &
            out_file = "build/test_proofs_replay.tsv"
        type(scene_t) :: scene
        type(run_t) :: run
        character(len=:), allocatable :: fields(:)
        real(qp), allocatable :: v(:)
        integer :: stat, i
        call scene_of(keys//" tol=1e-6", scene, error)
        if (allocated(error)) return
        call simulate(scene, run)
        call execute_command_line("python3 tools/replay dps=80 format=tsv "//keys//" > " &
            //out_file, exitstat=stat)
        call check(error, stat == 0, "followed group: tools/replay failed")
        if (allocated(error)) return
        call split_tabs(read_text(out_file), fields)
        call read_reals(fields(7), v)
        call check(error, size(v) == scene%p, "followed group: the replay's velocities unread")
        if (allocated(error)) return
        do i = 1, scene%p
            call check(error, abs(run%v(i) - v(i)) <= run%v_bounds(i), "followed group: v" &
                //itoa(i)//" = "//str(run%v(i))//" ("//answer_word(run%answer)//"), the " &
                //"replay's "//str(v(i))//", beyond the bound "//str(run%v_bounds(i)))
            if (allocated(error)) return
        end do
    end subroutine test_follow_struck

    !> n copies of `x`, comma-separated.
    pure function list(x, n) result(text)
        character(len=*), intent(in) :: x
        integer, intent(in) :: n
        character(len=:), allocatable :: text
        integer :: i
        text = x
        do i = 2, n
            text = text//","//x
        end do
    end function list

end module test_proofs
