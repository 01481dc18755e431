!> A small test harness: tests are `subroutine test_x(error)`, collected into
!> suites; the driver runs them all and ends with `N passed, N failed`.
module testsuite
    use, intrinsic :: iso_fortran_env, only: output_unit
    implicit none
    private
    public :: error_t, unittest_t, test_proc, new_unittest, check, run_tests

    !> A failed check: its message.
    type :: error_t
        character(len=:), allocatable :: message
    end type error_t

    abstract interface
        !> One test; it leaves `error` unallocated on success.
        subroutine test_proc(error)
            import :: error_t
            type(error_t), allocatable, intent(out) :: error
        end subroutine test_proc
    end interface

    !> A named test.
    type :: unittest_t
        character(len=:), allocatable :: name
        procedure(test_proc), pointer, nopass :: test => null()
    end type unittest_t

contains

    !> Pair a name with a test procedure.
    function new_unittest(name, test) result(unit)
        character(len=*), intent(in) :: name
        procedure(test_proc) :: test
        type(unittest_t) :: unit
        unit%name = name
        unit%test => test
    end function new_unittest

    !> Record a failure with `message` unless `condition` holds (first failure wins).
    subroutine check(error, condition, message)
        type(error_t), allocatable, intent(inout) :: error
        logical, intent(in) :: condition
        character(len=*), intent(in) :: message
        if (allocated(error)) return
        if (.not. condition) then
            allocate (error)
            error%message = message
        end if
    end subroutine check

    !> Run every test of a suite, print one line per test, add up the counts.
    subroutine run_tests(suite, tests, passed, failed)
        character(len=*), intent(in) :: suite
        type(unittest_t), intent(in) :: tests(:)
        integer, intent(inout) :: passed, failed
        type(error_t), allocatable :: error
        integer :: i
        do i = 1, size(tests)
            call tests(i)%test(error)
            if (allocated(error)) then
                failed = failed + 1
                write (output_unit, "(a)") "FAIL "//suite//"/"//tests(i)%name//": "//error%message
                deallocate (error)
            else
                passed = passed + 1
                write (output_unit, "(a)") "ok   "//suite//"/"//tests(i)%name
            end if
        end do
    end subroutine run_tests
end module testsuite
