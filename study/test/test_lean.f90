!> Tests of the lean real(16) path of c2 against the engine: the same
!> collision sequence and a bit-identical v4 on many e, with and without a
!> collapse, in the definition's scene and in others of the family.
module test_lean
    use sphere_row, only: qp, scene_t, run_t, event_log_t, scene_init, simulate, str, &
        status_normal, status_collapsed, status_invalid, event_collision
    use sphere_row, only: dp
    use sphere_row_lean, only: lean_row_t, lean_collisions_max
    use sphere_row_minimal, only: minimal_v4
    use sphere_row_monte_carlo, only: monte_carlo_v4, mc_counts_t
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_lean

    !> e_crit = 3 - 2 sqrt 2: below it the row collapses.
    real(qp), parameter :: e_crit = 0.1715728752538099023966225515806039_qp
    !> 2 - sqrt 3: above it sphere 4 is struck once.
    real(qp), parameter :: e_single = 0.2679491924311227064725536584941276_qp
    !> Points of the even grid of e and of the scattered e values.
    integer, parameter :: n_grid = 4001, n_scatter = 3000
    !> The golden ratio's fraction, for e values that fill [0, 1] evenly.
    real(qp), parameter :: golden = 0.6180339887498948482045868343656381_qp

contains

    !> The lean path's tests.
    function collect_lean() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("lean_equals_engine_definition", test_definition), &
            new_unittest("lean_equals_engine_family", test_family), &
            new_unittest("lean_collapse_quarter", test_collapse), &
            new_unittest("lean_refuses_other_rows", test_refusals), &
            new_unittest("minimal_loop_equals_lean_on_c2", test_minimal) &
            ]
    end function collect_lean

    !> The definition's scene on an even grid of e, scattered e, e at
    !> the region bounds and e a few ulps around them.
    subroutine test_definition(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg)
        call compare_on(error, scene, e_values(), .true.)
    end subroutine test_definition

    !> Other scenes of the family: other equal masses, unequal gaps, v0, a
    !> touching pair, a small max_collisions, and a tolerance of 0 (where a
    !> collapse without a certified cycle runs to max_collisions: every 10th e).
    subroutine test_family(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, masses=[2.5_qp, 2.5_qp, 2.5_qp, 2.5_qp], &
            gaps=[0.5_qp, 1.0_qp, 2.0_qp], v0=3.0_qp)
        call check(error, stat == status_normal, "scene refused: "//trim(msg))
        call compare_on(error, scene, e_values(), .false.)
        call scene_init(scene, stat, msg, gaps=[1.0_qp, 0.0_qp, 0.25_qp])
        call compare_on(error, scene, e_values(), .false.)
        call scene_init(scene, stat, msg, max_collisions=7)
        call compare_on(error, scene, e_values(), .false.)
        call scene_init(scene, stat, msg, tol=0.0_qp, max_collisions=2000)
        call compare_on(error, scene, every_tenth(e_values()), .false.)
    end subroutine test_family

    !> Below e_crit the engine takes the collapse limit and every sphere ends
    !> at v0/4 (momentum shared by four equal masses), to a few roundings; the
    !> lean path gives the same, bit for bit, also at e = 0 (the plastic
    !> cascade).
    subroutine test_collapse(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(lean_row_t) :: lean
        real(qp) :: e, v4
        integer :: stat, status, j
        logical :: deferred
        character(len=200) :: msg
        type(run_t) :: run
        call scene_init(scene, stat, msg)
        call lean%prepare(scene, stat, msg)
        do j = 0, 200
            e = e_crit*real(j, qp)/201.0_qp
            call lean%v4(e, v4, status, deferred)
            scene%e = e
            call simulate(scene, run)
            call check(error, status == status_collapsed, "e = "//str(e)//": not collapsed")
            call check(error, abs(v4 - 0.25_qp) <= 8*epsilon(1.0_qp), &
                "e = "//str(e)//": v4 = "//str(v4))
            call check(error, v4 == run%v(4), "e = "//str(e)//": lean /= engine")
        end do
    end subroutine test_collapse

    !> The yardstick of bench.tsv, the minimal loop, does c2's job: on 20000
    !> samples of c2's stream its v4 is the lean path's (and so the engine's).
    subroutine test_minimal(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: n = 20000
        type(scene_t) :: scene
        type(mc_counts_t) :: counts
        real(dp) :: v4(n), e(n)
        integer :: stat, i
        character(len=200) :: msg
        call scene_init(scene, stat, msg)
        call monte_carlo_v4(scene, 0.5_qp, 0.05_qp, 12, 1, v4, e, counts, stat, msg)
        call check(error, stat == status_normal, "refused: "//trim(msg))
        do i = 1, n
            call check(error, real(minimal_v4(real(e(i), qp)), dp) == v4(i), &
                "e = "//str(e(i))//": minimal loop /= lean path")
        end do
    end subroutine test_minimal

    !> A row of other length or unequal masses is not of the family.
    subroutine test_refusals(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(lean_row_t) :: lean
        real(qp) :: v4
        integer :: stat, status
        logical :: deferred
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=5)
        call lean%prepare(scene, stat, msg)
        call check(error, stat == status_invalid .and. index(msg, "p = 4") > 0, &
            "p = 5 taken: "//trim(msg))
        call lean%v4(0.5_qp, v4, status, deferred)
        call check(error, status == status_invalid, "unprepared lean row ran")
        call scene_init(scene, stat, msg, masses=[1.0_qp, 1.0_qp, 2.0_qp, 1.0_qp])
        call lean%prepare(scene, stat, msg)
        call check(error, stat == status_invalid .and. index(msg, "equal masses") > 0, &
            "unequal masses taken: "//trim(msg))
    end subroutine test_refusals

    !> The e values of the comparisons.
    function e_values() result(e)
        real(qp), allocatable :: e(:)
        real(qp) :: special(6)
        integer :: j, k
        allocate (e(n_grid + n_scatter))
        do j = 1, n_grid
            e(j) = real(j - 1, qp)/real(n_grid - 1, qp)
        end do
        do j = 1, n_scatter
            e(n_grid + j) = modulo(j*golden, 1.0_qp)
        end do
        special = [e_crit, e_single, 0.5_qp, 1.0_qp, 0.0_qp, tiny(1.0_qp)]
        do k = 1, size(special)
            do j = -3, 3
                e = [e, min(1.0_qp, max(0.0_qp, special(k) + j*spacing(special(k))))]
            end do
        end do
    end function e_values

    !> Every tenth of the values.
    pure function every_tenth(e) result(part)
        real(qp), intent(in) :: e(:)
        real(qp), allocatable :: part(:)
        part = e(::10)
    end function every_tenth

    !> At every e: the lean path's v4 and status are the engine's, bit for bit;
    !> a lean run (not handed over) has the engine's collision sequence. With
    !> `mostly_lean`, every e >= 0.2 runs on the lean path.
    subroutine compare_on(error, scene, e, mostly_lean)
        type(error_t), allocatable, intent(inout) :: error
        type(scene_t), intent(in) :: scene
        real(qp), intent(in) :: e(:)
        logical, intent(in) :: mostly_lean
        type(lean_row_t) :: lean
        type(scene_t) :: trial
        type(run_t) :: run
        type(event_log_t) :: log
        real(qp) :: v4
        integer :: stat, status, j, n, i, lean_runs
        integer :: sequence(lean_collisions_max)
        integer, allocatable :: pairs(:)
        logical :: deferred
        character(len=200) :: msg
        call lean%prepare(scene, stat, msg)
        call check(error, stat == status_normal, "prepare refused: "//trim(msg))
        if (allocated(error)) return
        trial = scene
        lean_runs = 0
        do j = 1, size(e)
            trial%e = e(j)
            call simulate(trial, run, log)
            call lean%v4(e(j), v4, status, deferred, n, sequence)
            call check(error, v4 == run%v(4) .and. status == run%status .and. n == run%n, &
                "e = "//str(e(j))//": lean v4 "//str(v4)//" vs engine "//str(run%v(4)))
            if (allocated(error)) return
            if (deferred) then
                call check(error, .not. (mostly_lean .and. e(j) >= 0.2_qp), &
                    "e = "//str(e(j))//": handed to the engine")
                cycle
            end if
            lean_runs = lean_runs + 1
            pairs = pack(log%first(1:log%n), log%kind(1:log%n) == event_collision)
            call check(error, size(pairs) == n, "e = "//str(e(j))//": collision count")
            if (allocated(error)) return
            do i = 1, n
                call check(error, pairs(i) == sequence(i), "e = "//str(e(j)) &
                    //": sequence differs at collision "//str(real(i, qp)))
            end do
        end do
        call check(error, lean_runs > size(e)/2, "lean path used for too few runs")
    end subroutine compare_on

end module test_lean
