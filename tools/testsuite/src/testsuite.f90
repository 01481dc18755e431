!> A small test harness: tests are `subroutine test_x(error)`, collected into
!> suites; the driver hands its suites to `run_suites`, which runs them all and
!> ends with `N passed, N failed`.
!>
!> Each test's line gives its wall time (`make test-times` tabulates them). The
!> driver's command line may hold `long`: the deep versions of the property
!> tests, more cases and longer runs (`make test-long`); and `fail-fast`: no
!> test runs after the first that fails (the mutation check, tools/mutants,
!> needs only to know whether one does); and `suite=NAME`: only that suite's
!> tests (may be given more than once), to look at one part quickly.
module testsuite
    use, intrinsic :: iso_fortran_env, only: output_unit, int64
    implicit none
    private
    public :: error_t, unittest_t, test_proc, new_unittest, check, run_tests
    public :: suite_t, new_suite, run_suites
    public :: read_text, count_lines, seed_random, read_test_options, long_tests, cases

    !> True when the driver was asked for the deep versions of the tests.
    logical, protected :: long_tests = .false.
    !> True when the driver was asked to stop at the first failed test.
    logical :: fail_fast = .false.
    !> The suites asked for (`suite=NAME`, blank-separated, each between
    !> blanks); empty: every suite.
    character(len=:), allocatable :: only_suites

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

    !> A named suite: one test module's collection.
    type :: suite_t
        !> The suite's name, the prefix of its tests' lines.
        character(len=:), allocatable :: name
        !> Its tests, in the order they run.
        type(unittest_t), allocatable :: tests(:)
    end type suite_t

contains

    !> Pair a suite's name with its collection of tests.
    function new_suite(name, tests) result(suite)
        character(len=*), intent(in) :: name
        type(unittest_t), intent(in) :: tests(:)
        type(suite_t) :: suite
        suite%name = name
        suite%tests = tests
    end function new_suite

    !> The whole of a test driver after its list of suites: read the command
    !> line (read_test_options), run every suite in order, print the last line
    !> `N passed, N failed` (the line the Makefile and tools read) and end the
    !> program with status 1 if any test failed, so that `fpm test` fails.
    subroutine run_suites(suites)
        type(suite_t), intent(in) :: suites(:)
        integer :: passed, failed, i
        passed = 0
        failed = 0
        call read_test_options(failed)
        do i = 1, size(suites)
            call run_tests(suites(i)%name, suites(i)%tests, passed, failed)
        end do
        write (output_unit, "(i0, ' passed, ', i0, ' failed')") passed, failed
        if (failed > 0) stop 1, quiet=.true.
    end subroutine run_suites

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

    !> Read the driver's command line: `long` asks for the deep tests,
    !> `fail-fast` for no test after the first failure; any other argument
    !> fails the run (reported as one failed test).
    subroutine read_test_options(failed)
        integer, intent(inout) :: failed
        integer :: i, n
        character(len=4096) :: arg
        do i = 1, command_argument_count()
            call get_command_argument(i, arg, length=n)
            if (arg(:n) == "long") then
                long_tests = .true.
            else if (arg(:n) == "fail-fast") then
                fail_fast = .true.
            else if (n > 6 .and. index(arg(:n), "suite=") == 1) then
                if (.not. allocated(only_suites)) only_suites = " "
                only_suites = only_suites//arg(7:n)//" "
            else
                failed = failed + 1
                write (output_unit, "(a)") "FAIL testsuite: argument "//arg(:n)// &
                    ": allowed long, fail-fast or suite=NAME"
            end if
        end do
    end subroutine read_test_options

    !> The number of random cases of a property test: `quick` in the default
    !> run, `deep` when the driver was asked for the long tests.
    pure integer function cases(quick, deep)
        integer, intent(in) :: quick, deep
        cases = merge(deep, quick, long_tests)
    end function cases

    !> Run every test of a suite, print one line per test with its wall time,
    !> add up the counts (with fail-fast, none once a test has failed).
    subroutine run_tests(suite, tests, passed, failed)
        character(len=*), intent(in) :: suite
        type(unittest_t), intent(in) :: tests(:)
        integer, intent(inout) :: passed, failed
        type(error_t), allocatable :: error
        integer :: i
        integer(int64) :: t0, t1, rate
        real :: seconds
        character(len=16) :: time_text
        if (allocated(only_suites)) then
            if (index(only_suites, " "//suite//" ") == 0) return
        end if
        do i = 1, size(tests)
            if (fail_fast .and. failed > 0) return
            call system_clock(t0, rate)
            call tests(i)%test(error)
            call system_clock(t1)
            seconds = real(t1 - t0)/real(rate)
            write (time_text, "(f8.2)") seconds
            time_text = adjustl(time_text)
            if (allocated(error)) then
                failed = failed + 1
                write (output_unit, "(a)") "FAIL "//suite//"/"//tests(i)%name//" ("// &
                    trim(time_text)//" s): "//error%message
                deallocate (error)
            else
                passed = passed + 1
                write (output_unit, "(a)") "ok   "//suite//"/"//tests(i)%name//" ("// &
                    trim(time_text)//" s)"
            end if
        end do
    end subroutine run_tests

    !> The whole text of `file`, each line ended by a new line and trailing
    !> blanks dropped; "" if the file cannot be read.
    function read_text(file) result(text)
        character(len=*), intent(in) :: file
        character(len=:), allocatable :: text
        character(len=8000) :: line
        integer :: unit, ios
        text = ""
        open (newunit=unit, file=file, status="old", action="read", iostat=ios)
        if (ios /= 0) return
        do
            read (unit, "(a)", iostat=ios) line
            if (ios /= 0) exit
            text = text//trim(line)//new_line("a")
        end do
        close (unit)
    end function read_text

    !> The lines of `text`: its new-line characters.
    pure integer function count_lines(text)
        character(len=*), intent(in) :: text
        integer :: i
        count_lines = 0
        do i = 1, len(text)
            if (text(i:i) == new_line("a")) count_lines = count_lines + 1
        end do
    end function count_lines

    !> Seed the intrinsic generator with first + step*i, i = 1 ... its seed
    !> size, so that a test's random cases are the same on every run.
    subroutine seed_random(first, step)
        integer, intent(in) :: first, step
        integer :: n, i
        call random_seed(size=n)
        call random_seed(put=[(first + step*i, i=1, n)])
    end subroutine seed_random
end module testsuite
