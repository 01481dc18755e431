!> Tests of the sphere-row command line, run as a separate process.
module test_cli
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text, count_lines
    implicit none
    private
    public :: collect_cli, program_path

    character(len=*), parameter :: out_file = "build/test_cli.out", err_file = "build/test_cli.err"

contains

    !> The CLI's tests.
    function collect_cli() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("bad_input_refused", test_bad_input), &
            new_unittest("definition_scene_output", test_good_output), &
            new_unittest("namelist_file", test_namelist), &
            new_unittest("event_table", test_events), &
            new_unittest("help", test_help) &
            ]
    end function collect_cli

    !> Path of an executable of this package, as fpm built it for this profile.
    function program_path(name) result(path)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: path
        character(len=1000) :: line
        integer :: unit, ios, stat
        path = ""
        call execute_command_line("fpm run --runner echo "//name//" > build/test_path.txt " &
            //"2> /dev/null", exitstat=stat)
        if (stat /= 0) return
        open (newunit=unit, file="build/test_path.txt", status="old", action="read")
        do
            read (unit, "(a)", iostat=ios) line
            if (ios /= 0) exit
            if (len_trim(line) > 0) path = trim(line)
        end do
        close (unit)
    end function program_path

    !> Run the CLI with `args`; return its exit status, stdout and stderr.
    subroutine run_cli(args, status, out, err)
        character(len=*), intent(in) :: args
        integer, intent(out) :: status
        character(len=:), allocatable, intent(out) :: out, err
        character(len=:), allocatable, save :: path
        if (.not. allocated(path)) path = program_path("sphere-row")
        call execute_command_line(path//" "//args//" > "//out_file//" 2> "//err_file, &
            exitstat=status)
        out = read_text(out_file)
        err = read_text(err_file)
    end subroutine run_cli

    !> Each bad input: exit status 2, one stderr line naming the key, no stdout.
    subroutine test_bad_input(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: cases(*, *) = reshape([character(len=24) :: &
            "foo=1", "foo", &
            "e=abc", "e", &
            "e=nan", "e", &
            "v0=inf", "v0", &
            "e=1.5", "e", &
            "e=-0.1", "e", &
            "p=1", "p", &
            "p=2.5", "p", &
            "masses=1,1,1", "masses", &
            "gaps=1,1", "gaps", &
            "masses=1,0,1,1", "masses", &
            "masses=1,x,1,1", "masses", &
            "v0=0", "v0", &
            "v0=-1", "v0", &
            "a=-1", "a", &
            "gaps=1,-1,1", "gaps", &
            "d=-1", "d", &
            "events=maybe", "events", &
            "no_such_file.nml", "no_such_file.nml"], [2, 19])
        integer :: i, status
        character(len=:), allocatable :: out, err
        do i = 1, size(cases, 2)
            call run_cli(trim(cases(1, i)), status, out, err)
            call check(error, status == 2, trim(cases(1, i))//": exit status not 2")
            call check(error, len(out) == 0, trim(cases(1, i))//": wrote to stdout")
            call check(error, count_lines(err) == 1, trim(cases(1, i))//": not one stderr line")
            call check(error, index(err, trim(cases(2, i))) > 0, &
                trim(cases(1, i))//": message does not name the key: "//err)
        end do
    end subroutine test_bad_input

    !> `sphere-row e=0.2` prints the whole answer, one quantity per line.
    subroutine test_good_output(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        character(len=:), allocatable :: out, err
        call run_cli("e=0.2", status, out, err)
        call check(error, status == 0, "e=0.2: exit status not 0")
        call check(error, index(out, "collisions 13"//new_line("a")) == 1, "collisions line")
        call check(error, index(out, "status normal") > 0, "status line")
        call check(error, index(out, "t_end 1.491089664459656604197059813713") > 0, "t_end line")
        call check(error, index(out, "v4 2.502144") > 0 .and. index(out, "y3 ") > 0, &
            "velocity and gap lines")
        call check(error, len(err) == 0, "e=0.2 wrote to stderr")
    end subroutine test_good_output

    !> A namelist file gives the scene; key=value after it overrides.
    subroutine test_namelist(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status, unit
        character(len=:), allocatable :: out, err
        open (newunit=unit, file="build/test_scene.nml", status="replace", action="write")
        write (unit, "(a)") "&scene p=6, e=1.0, masses=1,1,1,1,1,1 /"
        close (unit)
        call run_cli("build/test_scene.nml", status, out, err)
        call check(error, status == 0 .and. index(out, "collisions 5") == 1, &
            "namelist p=6 e=1: "//out//err)
        call run_cli("build/test_scene.nml e=0", status, out, err)
        call check(error, status == 0 .and. index(out, "status quasi_plastic") > 0, &
            "namelist with e=0 override: "//out//err)
    end subroutine test_namelist

    !> `events=yes` adds a TSV table: header, start row and one row per event.
    subroutine test_events(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        character(len=:), allocatable :: out, err
        call run_cli("e=1 events=yes", status, out, err)
        call check(error, status == 0, "events=yes: exit status")
        call check(error, index(out, "event"//achar(9)//"kind") > 0, "events=yes: no header")
        ! 3 collision lines + start + header + 4 + 4 + 3 + 6 quantity lines
        ! (collisions, t_end, status, precision, answer, v_bound; v, x; y)
        call check(error, count_lines(out) == 3 + 4 + 4 + 3 + 1 + 1 + 6, &
            "events=yes: wrong number of lines")
    end subroutine test_events

    !> `--help` lists every key and exits 0.
    subroutine test_help(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        character(len=:), allocatable :: out, err
        call run_cli("--help", status, out, err)
        call check(error, status == 0, "--help: exit status")
        call check(error, index(out, "masses=") > 0 .and. index(out, "events=") > 0 .and. &
            index(out, "max_collisions=") > 0 .and. index(out, "tol=") > 0, "--help: keys")
        call check(error, index(out, "precision=qp") > 0 .and. &
            index(out, "allowed qp, dp or auto") > 0, "--help: the words of precision")
    end subroutine test_help

end module test_cli
