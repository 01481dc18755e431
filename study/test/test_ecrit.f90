!> Tests of the critical restitution of the struck row: the rate map of the
!> collapse cycle against the closed forms of p = 3 and p = 4, the bisected
!> edge around them, and e_c growing with p.
module test_ecrit
    use sphere_row, only: qp, str, itoa, status_normal
    use sphere_row_ecrit, only: ecrit_settings_t, ecrit_row_t, ecrit_row, rate_map_critical, &
        row_estimate, outcome_word
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_ecrit

    !> Agreement asked of the rate map with a closed form (30-digit kind).
    real(qp), parameter :: closed_tol = 1.0e-25_qp
    !> Cheap settings for the tests: no fit runs, a coarse scan.
    integer, parameter :: test_grid = 10, test_fit = 2

contains

    !> The e_c tests.
    function collect_ecrit() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("rate_map_cycle_p3", test_map_p3), &
            new_unittest("rate_map_cycle_p4", test_map_p4), &
            new_unittest("rows_3_and_4", test_rows), &
            new_unittest("e_crit_increases", test_increasing) &
            ]
    end function collect_ecrit

    !> p = 3: the cycle 12 gives 7 - 4 sqrt(3).
    subroutine test_map_p3(error)
        type(error_t), allocatable, intent(out) :: error
        call check_rate_map(error, 3, [1, 2], 7.0_qp - 4.0_qp*sqrt(3.0_qp))
    end subroutine test_map_p3

    !> p = 4: the cycle 32121232 of task b1 gives 3 - 2 sqrt(2).
    subroutine test_map_p4(error)
        type(error_t), allocatable, intent(out) :: error
        call check_rate_map(error, 4, [3, 2, 1, 2, 1, 2, 3, 2], 3.0_qp - 2.0_qp*sqrt(2.0_qp))
    end subroutine test_map_p4

    !> The rate map of collapse cycle `cycle` of p equal spheres finds its e_c
    !> within closed_tol of the closed form `closed`, searched near it.
    subroutine check_rate_map(error, p, cycle, closed)
        type(error_t), allocatable, intent(inout) :: error
        integer, intent(in) :: p, cycle(:)
        real(qp), intent(in) :: closed
        real(qp), parameter :: window = 1.0e-3_qp, probe = 1.0e-8_qp
        real(qp) :: e_c, m(p)
        integer :: stat
        m = 1.0_qp
        call rate_map_critical(m, cycle, closed - window, closed + window, probe, e_c, stat)
        call check(error, stat == status_normal, "p = "//itoa(p)//": no sign change of the pair")
        if (allocated(error)) return
        call check(error, abs(e_c - closed) <= closed_tol, "p = "//itoa(p)//": e_c = "//str(e_c))
    end subroutine check_rate_map

    !> The whole row procedure for p = 3 and 4: the rate map found from the
    !> row's own run matches the closed form, and the bisected bracket
    !> [e_low, e_high], shifted up by the fallback's bias, contains it.
    subroutine test_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(ecrit_settings_t) :: s
        type(ecrit_row_t) :: row
        real(qp) :: closed(3:4), e_c
        character(len=:), allocatable :: method
        !> The fallback's upward bias of the edge (about 2e-8 here), allowed.
        real(qp), parameter :: bias = 1.0e-7_qp
        integer :: p
        closed = [7.0_qp - 4.0_qp*sqrt(3.0_qp), 3.0_qp - 2.0_qp*sqrt(2.0_qp)]
        s%n_grid = test_grid
        s%n_fit = test_fit
        do p = 3, 4
            call ecrit_row(p, s, row)
            call row_estimate(row, s%map_window, e_c, method)
            call check(error, row%has_map .and. method == "rate_map", "p = "//str(real(p, qp)) &
                //": no rate-map value; edge outcome "//outcome_word(row%b%outcome_low))
            if (allocated(error)) return
            call check(error, abs(row%e_map - closed(p)) <= closed_tol, &
                "rate map "//str(row%e_map))
            if (allocated(error)) return
            call check(error, row%b%e_low - bias <= closed(p) .and. closed(p) <= row%b%e_high, &
                "bracket ["//str(row%b%e_low)//", "//str(row%b%e_high)//"]")
            if (allocated(error)) return
            call check(error, row%b%e_cycle > 0.0_qp .and. row%b%e_cycle <= closed(p), &
                "largest certified collapse "//str(row%b%e_cycle))
            if (allocated(error)) return
        end do
    end subroutine test_rows

    !> e_c(p) grows with p over a short range of the real64 stage.
    subroutine test_increasing(error)
        type(error_t), allocatable, intent(out) :: error
        type(ecrit_settings_t) :: s
        type(ecrit_row_t) :: row
        real(qp) :: e_c, last
        character(len=:), allocatable :: method
        integer :: p
        integer, parameter :: p_last = 12
        s%n_grid = test_grid
        s%n_fit = test_fit
        s%p_fine = 0
        s%map_p_max = 0
        last = 0.0_qp
        do p = 3, p_last
            call ecrit_row(p, s, row)
            call row_estimate(row, s%map_window, e_c, method)
            call check(error, e_c > last, "e_c does not grow at p = "//str(real(p, qp)))
            if (allocated(error)) return
            last = e_c
        end do
    end subroutine test_increasing

end module test_ecrit
