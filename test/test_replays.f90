!> Runs checked against the same scene run another way: the calendar of
!> impacts against the scan of every gap, and limits taken in closed form (a
!> certified cycle, the plastic pool) against the collisions they stand for,
!> stepped without the closed-form rules.
module test_replays
    use sphere_row, only: qp, dp, scene_t, run_t, scene_dp_t, run_dp_t, event_log_dp_t, &
        scene_init, simulate, str, itoa, answer_word, answer_exact
    use testsuite, only: error_t, unittest_t, new_unittest, check
    use test_support, only: scene_of
    implicit none
    private
    public :: collect_replays

    !> Unit roundoff of real(16), the precision of the cycle's replay.
    real(qp), parameter :: eps = epsilon(1.0_qp)

    !> A scene whose closed-form limits are checked against their replay.
    type :: replay_t
        !> What it shows (the failure messages' prefix).
        character(len=:), allocatable :: what
        !> True if its limits must be exact and answered so.
        logical :: exact = .false.
        !> The scene as sphere-row's command line takes it (test_support).
        character(len=:), allocatable :: keys
    end type replay_t

contains

    !> The replay tests.
    function collect_replays() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("calendar_removals_keep_the_scan_order", test_calendar_removals), &
            new_unittest("closed_form_limits_as_their_replays", test_replay_rows) &
            ]
    end function collect_replays

    !> A row of 22 spheres in real(8) (masses 0.14 to 7.6, most gaps closed,
    !> e = 0.2565; a random row of the collapse survey's kind), the closed-form
    !> rules off, near collapse: a limit every 30 collisions, cascades through
    !> its touching blocks among impacts across its open gaps, so that up to
    !> 21 gaps close at once. The calendar keeps them in a heap, and a gap
    !> leaving it hands its place to the heap's last entry, which must move up
    !> where it is earlier than its new parent (first needed here at event
    !> 1072). The scan and the calendar move the gaps with different roundings,
    !> but on this row they take the same events, in the same order, for
    !> 24,000 events (measured); the first 4000 collisions are compared, every
    !> event's kind and spheres, and the count of collisions and limits.
    subroutine test_calendar_removals(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_dp_t) :: scene
        type(run_dp_t) :: cal, scan
        type(event_log_dp_t) :: log_cal, log_scan
        integer :: stat, n, i
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=22, e=2.56513479132827515e-01_dp, &
            masses=[3.38342178637945690e-01_dp, 3.09560396344082855e+00_dp, &
            8.53551563765691412e-01_dp, 4.23447400974810417e+00_dp, 4.45165295164592578e-01_dp, &
            1.35601474298226554e-01_dp, 1.56620326080563732e+00_dp, 2.03860288157129782e-01_dp, &
            1.22470608774871415e+00_dp, 3.08664609205132479e+00_dp, 1.58429541922109368e-01_dp, &
            4.76564807671647461e+00_dp, 7.62799053168926733e+00_dp, 4.03759223439661696e-01_dp, &
            2.43499187822420060e+00_dp, 3.90322893368356683e-01_dp, 8.05163260960830351e-01_dp, &
            9.31927528268147065e-01_dp, 6.54051996221225984e+00_dp, 7.20965737781260718e-01_dp, &
            1.03165811718082279e+00_dp, 6.27800857072610174e+00_dp], &
            gaps=[0.0_dp, 0.0_dp, 0.0_dp, 1.88490402914019328e+00_dp, 0.0_dp, 0.0_dp, &
            1.89920644182656062e+00_dp, 0.0_dp, 1.92138460415631895e+00_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp, 2.04120186052752350e+00_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
            0.0_dp, 0.0_dp, 0.0_dp], max_collisions=4000)
        call check(error, stat == 0, "calendar removals: scene refused: "//trim(msg))
        if (allocated(error)) return
        scene%closed_form_limits = .false.
        scene%calendar_from = 2
        call simulate(scene, cal, log_cal)
        scene%calendar_from = huge(1)
        call simulate(scene, scan, log_scan)
        call check(error, cal%cal%on .and. .not. scan%cal%on, &
            "calendar removals: calendar not chosen as asked")
        if (allocated(error)) return
        call check(error, cal%limits%n > 50, "calendar removals: the row is not near collapse (" &
            //itoa(cal%limits%n)//" limits)")
        n = min(log_cal%n, log_scan%n)
        do i = 1, n
            if (log_cal%kind(i) /= log_scan%kind(i) .or. log_cal%first(i) /= log_scan%first(i) &
                .or. log_cal%last(i) /= log_scan%last(i)) exit
        end do
        call check(error, i > n .and. log_cal%n == log_scan%n, &
            "calendar removals: calendar and scan part at event "//itoa(i)//" of " &
            //itoa(log_scan%n))
        call check(error, cal%n == scan%n .and. cal%limits%n == scan%limits%n, &
            "calendar removals: collisions "//itoa(cal%n)//" and "//itoa(scan%n)//", limits " &
            //itoa(cal%limits%n)//" and "//itoa(scan%limits%n))
    end subroutine test_calendar_removals

    !> Rows whose closed-form limits must end where their stepped replay
    !> ends (check_replay), each with what it shows and why it is here; a row
    !> marked exact must also take a limit and answer exact.
    subroutine test_replay_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(replay_t), allocatable :: rows(:)
        type(scene_t) :: scene
        type(run_t) :: closed
        integer :: i
        rows = [ &
            ! Seven spheres (masses 0.144 to 26.1): after 110 collisions spheres
            ! 3..5 (the light sphere 4 between the heavy 3 and 5) repeat a pattern
            ! of collisions at one instant, a cascade through touching spheres,
            ! and sphere 6 touches sphere 5. The relative kinetic energy of the
            ! group lets sphere 5 move on to sphere 6 faster than sphere 6
            ! recedes, so the pattern is no certified cycle: the cascade runs on
            ! through spheres 3..7. The replay (29,830 collisions) agrees to 1e-34
            ! in the velocities and 1e-30 in the end time (measured). A cycle
            ! certified while its right neighbour may strike it ends the run after
            ! 120 collisions, at t = 27.04 for 26.08, with velocities off by 1.7e-4.
            replay_t("cycle and neighbour", .false., "p=7 e=0.367 " &
                //"masses=4.838,2.886,26.125,0.144,18.4,6.16,2.728 " &
                //"gaps=0.369,0,0.312,0.3,0.372,0"), &
            ! Five touching spheres, two light ones (0.048 and 0.033) ahead of
            ! three heavy (6.6, 16 and 9.1), struck at t = 0 at e = 0.0913: all
            ! their collisions are at one instant. After 23 of them spheres 1..3
            ! repeat a pattern whose limit is at that same instant, while contact
            ! 3 (spheres 3 and 4) still closes at it: the limit may not be taken
            ! before that strike. The closed-form run (36 collisions) and its
            ! replay (234) end at velocities equal to the last bit here
            ! (measured); a cycle certified although another contact closes
            ! before its accumulation time ends 1.6e-6 away.
            replay_t("cycle and another contact", .false., "p=5 e=0.0913 " &
                //"masses=0.0479,0.0332,6.57,16.4,9.11 gaps=0,0,0,0"), &
            ! At e = 0 a cascade through touching spheres pools them
            ! (docs/collapse.md, rule 1): sphere 1 of five (masses 0.5 to 2)
            ! strikes the touching spheres 2..4, and the four merge at once into
            ! one block, which then strikes sphere 5 and takes it in (a second
            ! limit). These limits are exact: the answer says so, and the stepped
            ! replay, each plastic collision of the cascades taken until the
            ! rates are insignificant (1068 collisions), ends at the same
            ! velocities to within its bound.
            replay_t("plastic pool", .true., "p=5 e=0 masses=1,0.5,2,1.5,0.7 gaps=1,0,0,1") &
            ]
        do i = 1, size(rows)
            call scene_of(rows(i)%keys, scene, error)
            if (allocated(error)) return
            call check_replay(scene, rows(i)%what, closed, error)
            if (allocated(error)) return
            if (.not. rows(i)%exact) cycle
            call check(error, closed%limits%n > 0 .and. closed%answer == answer_exact, &
                rows(i)%what//": "//itoa(closed%limits%n)//" limits, answer " &
                //answer_word(closed%answer))
            if (allocated(error)) return
        end do
    end subroutine test_replay_rows

    !> Run `scene` with its closed-form limits (`closed`) and stepped without
    !> them (every collapse taken by the fallback or the bounded cascade):
    !> the same velocities to within the two runs' bounds and 64 roundings,
    !> and the same end time to 1e-20 of it.
    subroutine check_replay(scene, what, closed, error)
        type(scene_t), intent(in) :: scene
        character(len=*), intent(in) :: what
        type(run_t), intent(inout) :: closed
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: each
        type(run_t) :: stepped
        real(qp) :: apart
        each = scene
        call simulate(each, closed)
        each%closed_form_limits = .false.
        call simulate(each, stepped)
        call check(error, stepped%limits%n > 0 .and. stepped%limits%closed_form == 0, &
            what//": the stepped run took no limit, or one in closed form")
        if (allocated(error)) return
        apart = maxval(abs(closed%v - stepped%v))
        call check(error, apart <= closed%v_bound + stepped%v_bound + 64*eps, &
            what//": velocities "//str(apart)//" apart (bounds "//str(closed%v_bound) &
            //" and "//str(stepped%v_bound)//"; answers "//answer_word(closed%answer) &
            //" after "//itoa(closed%n)//" collisions and "//answer_word(stepped%answer) &
            //" after "//itoa(stepped%n)//")")
        call check(error, abs(closed%t_end - stepped%t_end) <= 1.0e-20_qp*stepped%t_end, &
            what//": end at "//str(closed%t_end)//", stepped to "//str(stepped%t_end))
    end subroutine check_replay

end module test_replays
