!> Tests of the sphere-row command line, run as a separate process.
module test_cli
    use, intrinsic :: iso_fortran_env, only: int64, real64
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text, count_lines
    implicit none
    private
    public :: collect_cli, program_path

    character(len=*), parameter :: out_file = "build/test_cli.out", err_file = "build/test_cli.err"
    character(len=*), parameter :: table_file = "build/test_cli_events.tsv"
    character(len=*), parameter :: tab = achar(9), nl = new_line("a")

contains

    !> The CLI's tests.
    function collect_cli() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("bad_input_refused", test_bad_input), &
            new_unittest("bad_scene_keys_refused", test_bad_scene_keys), &
            new_unittest("spheres_table_runs", test_spheres_table), &
            new_unittest("samples_zero_temperature_earned", test_samples_earned), &
            new_unittest("definition_scene_output", test_good_output), &
            new_unittest("print_lines_asked_for", test_print), &
            new_unittest("answer_says_what_it_rests_on", test_premises), &
            new_unittest("heavy_sphere_keeps_its_digits", test_heavy_first), &
            new_unittest("namelist_file", test_namelist), &
            new_unittest("event_table", test_events), &
            new_unittest("event_table_file", test_events_file), &
            new_unittest("event_table_file_never_partial", test_events_file_failures), &
            new_unittest("event_header_linear_in_p", test_events_long_row), &
            new_unittest("help", test_help), &
            new_unittest("help_describes_output", test_help_output), &
            new_unittest("version_as_fpm_toml", test_version), &
            new_unittest("progress_without_terminal", test_progress) &
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

    !> Each bad input: exit status 2, one stderr line holding the text beside it (the key
    !> it names; for an argument the shell split at blanks, what they did), no stdout.
    subroutine test_bad_input(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: cases(*, *) = reshape([character(len=80) :: &
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
            "no_such_file.nml", "no_such_file.nml", &
            "masses=1, 2, 3, 4", "blanks in the list", &
            "gaps=1 ,2,3", "blanks in the list", &
            "print=w", "print = w: value 1 = w: not one of the names; allowed all, or a", &
            "print=v,x,V", "print = v,x,V: value 3 = V: not one of the names", &
            "print=v,v", "print = v,v: value 2 = v: named twice", &
            "print=v,,x", "print = v,,x: value 2 is empty", &
            "print=v,", "print = v,: value 2 is empty", &
            "print=", "print = : value 1 is empty", &
            "print=all,v", "print = all,v: value 1 = all: not one of the names", &
            "'print=v<i>'", "print = v<i>: value 1 = v<i>: not one of the names", &
            "e=2 print=v", "e = 2: allowed 0 <= e <= 1", &
            "print=w", "each once: collisions, t_end, t, status, precision,"], [2, 31])
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

    !> Each bad input of the keys of any initial state (velocities, walls, a
    !> ring, a table of spheres, a gas, a horizon, samples): exit status 2, one
    !> stderr line naming the key, no stdout, and no samples file left.
    subroutine test_bad_scene_keys(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: tsv = "build/test_samples.tsv"
        character(len=*), parameter :: cases(*, *) = reshape([character(len=64) :: &
            "velocities=1,2", "velocities", &
            "v0=2 velocities=1,0,0,0", "v0", &
            "velocities=1,x,0,0", "velocities", &
            "ring=1 wall_left=1", "ring", &
            "ring=1 wall_right=0", "ring", &
            "wall_left=-1", "wall_left", &
            "wall_right=inf", "wall_right", &
            "e_wall=1.5", "e_wall", &
            "t_max=0", "t_max", &
            "t_max=-1", "t_max", &
            "spheres=build/test_overlap.tsv", "line 3", &
            "spheres=build/test_bad_line.tsv", "line 2", &
            "spheres=build/test_bad_header.tsv", "header", &
            "spheres=build/no_such_table.tsv", "spheres", &
            "spheres=build/test_overlap.tsv p=3", "spheres", &
            "gas=ring density=2", "density", &
            "density=0.3", "density", &
            "gas=ring gaps=1,1,1", "gas", &
            "gas=box velocities=1,1,1,1", "gas", &
            "gas=cube", "gas", &
            "samples="//tsv, "samples", &
            "samples="//tsv//" t_max=1 precision=dp", "samples", &
            "sample_every=1 t_max=1", "sample_every", &
            "velocities=1,0,0,0 e_wall=0.5", "e_wall", &
            "velocities=1,0,0,0 t_max=1e-400 precision=dp", "t_max", &
            "velocities=1,0,0,0 ring=1e-400 precision=dp", "ring", &
            "t_max=1 events="//tsv//" samples="//tsv, "samples"], [2, 27])
        integer :: i, status, unit
        logical :: there
        character(len=:), allocatable :: out, err
        open (newunit=unit, file="build/test_overlap.tsv", status="replace", action="write")
        write (unit, "(a)") "x"//achar(9)//"v"//achar(9)//"m", "0"//achar(9)//"1"//achar(9) &
            //"1", "0.5"//achar(9)//"0"//achar(9)//"1"
        close (unit)
        open (newunit=unit, file="build/test_bad_line.tsv", status="replace", action="write")
        write (unit, "(a)") "x"//achar(9)//"v"//achar(9)//"m", "0"//achar(9)//"1", &
            "3"//achar(9)//"0"//achar(9)//"1"
        close (unit)
        open (newunit=unit, file="build/test_bad_header.tsv", status="replace", action="write")
        write (unit, "(a)") "x v m", "0"//achar(9)//"1"//achar(9)//"1", &
            "3"//achar(9)//"0"//achar(9)//"1"
        close (unit)
        call execute_command_line("rm -f "//tsv)
        do i = 1, size(cases, 2)
            call run_cli(trim(cases(1, i)), status, out, err)
            call check(error, status == 2, trim(cases(1, i))//": exit status not 2")
            if (allocated(error)) return
            call check(error, len(out) == 0, trim(cases(1, i))//": wrote to stdout")
            if (allocated(error)) return
            call check(error, count_lines(err) == 1, trim(cases(1, i))//": not one stderr line")
            if (allocated(error)) return
            call check(error, index(err, trim(cases(2, i))) > 0, &
                trim(cases(1, i))//": message does not name "//trim(cases(2, i))//": "//err)
            if (allocated(error)) return
            inquire (file=tsv, exist=there)
            call check(error, .not. there, trim(cases(1, i))//": left a samples file")
            if (allocated(error)) return
        end do
    end subroutine test_bad_scene_keys

    !> A table of spheres runs as the same scene given by keys: the same
    !> answer, line for line, and a samples table with its header, from t =
    !> 0 to t_max.
    subroutine test_spheres_table(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: tsv = "build/test_samples.tsv"
        integer :: status, unit
        character(len=:), allocatable :: out, err, out_keys, samples
        open (newunit=unit, file="build/test_spheres.tsv", status="replace", action="write")
        write (unit, "(a)") "x"//achar(9)//"v"//achar(9)//"m", &
            "0"//achar(9)//"1"//achar(9)//"1", "2.5"//achar(9)//"0"//achar(9)//"2", &
            "4"//achar(9)//"-0.5"//achar(9)//"1"
        close (unit)
        call run_cli("spheres=build/test_spheres.tsv e=0.5 wall_right=1 t_max=10 samples=" &
            //tsv, status, out, err)
        call check(error, status == 0 .and. len(err) == 0, "spheres table: exit status " &
            //itoa_local(status)//": "//err)
        if (allocated(error)) return
        call run_cli("p=3 e=0.5 gaps=1.5,0.5 masses=1,2,1 velocities=1,0,-0.5 wall_right=1 " &
            //"t_max=10", status, out_keys, err)
        call check(error, out == out_keys, "spheres table: the answer differs from the keys'")
        if (allocated(error)) return
        samples = read_text(tsv)
        call check(error, index(samples, "t"//achar(9)//"temperature"//achar(9)//"energy" &
            //achar(9)//"collisions_per_sphere"//achar(9)//"clusters"//new_line("a")) == 1 &
            .and. count_lines(samples) == 43, "spheres table: the samples' table: " &
            //samples(:min(200, len(samples))))
    end subroutine test_spheres_table

    !> Four spheres moving together have a temperature of exactly 0 at every
    !> sample, known to within the run's rounding bound: each row writes it as
    !> 0 at that bound's decade (0E-67), not with every digit of real(16).
    subroutine test_samples_earned(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: tsv = "build/test_samples_zero.tsv", &
            zero = achar(9)//"0E-"
        integer :: status, n, at, next
        character(len=:), allocatable :: out, err, samples
        call run_cli("p=4 e=0.1 velocities=1,1,1,1 t_max=10 samples="//tsv, status, out, err)
        call check(error, status == 0 .and. len(err) == 0, "four together: exit status " &
            //itoa_local(status)//": "//err)
        if (allocated(error)) return
        samples = read_text(tsv)
        n = 0
        at = 1
        do
            next = index(samples(at:), zero)
            if (next == 0) exit
            n = n + 1
            at = at + next + len(zero) - 1
        end do
        call check(error, n == count_lines(samples) - 1 .and. n > 1, "four together: " &
            //itoa_local(n)//" temperatures written as 0E-..., of " &
            //itoa_local(count_lines(samples) - 1)//" rows: "//samples(:min(300, len(samples))))
    end subroutine test_samples_earned

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

    !> print= prints the answer's lines it names and no other: each run's
    !> output is the whole answer's lines of those names (v, x, y: v<i>, x<i>,
    !> y<i>), in the answer's order; with events=yes the table comes first.
    subroutine test_print(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: cases(*, *) = reshape([character(len=48) :: &
            "e=0.1", "v", &
            "e=0.1", "answer,v_bound,v", &
            "e=0.1", "y,collisions,x", &
            "e=0.1", "collapse_t,collapse,collapses,limits_certified", &
            "e=0.2", "collapse_t", &
            "p=7 e=0.39", "separation_not_excluded_below,collapse_spheres", &
            "p=5 e=0.2593", "separation_scale,status", &
            "p=40 e=0.8 max_collisions=2000", "active,v_bound,t_end", &
            "e=0.5 precision=auto", "precision,certified,v", &
            "e=0.5 precision=dp", "not_dp,precision,t_end", &
            "p=3 e=0.5 ring=1 t_max=2", "t,y"], [2, 11])
        integer :: i, status
        character(len=:), allocatable :: whole, out, err
        do i = 1, size(cases, 2)
            call run_cli(trim(cases(1, i)), status, whole, err)
            call check(error, status == 0, trim(cases(1, i))//": exit status")
            if (allocated(error)) return
            call run_cli(trim(cases(1, i))//" print="//trim(cases(2, i)), status, out, err)
            call check(error, status == 0 .and. len(err) == 0, trim(cases(1, i))//" print=" &
                //trim(cases(2, i))//": exit status "//itoa_local(status)//": "//err)
            if (allocated(error)) return
            call check(error, out == named_lines(whole, ","//trim(cases(2, i))//","), &
                trim(cases(1, i))//" print="//trim(cases(2, i))//" printed:"//nl//out)
            if (allocated(error)) return
        end do
        call run_cli("e=1 events=yes print=collisions", status, out, err)
        call check(error, status == 0 .and. index(out, "event"//tab//"kind") == 1 .and. &
            count_lines(out) == 3 + 1 + 1 + 1 .and. index(out, nl//"collisions 3"//nl) > 0, &
            "e=1 events=yes print=collisions: the table, then the one line: "//out)
    contains
        !> The lines of `text` whose name (its first word, v<i>, x<i>, y<i>
        !> read as v, x, y) is in `names` (",name,...,").
        pure function named_lines(text, names) result(kept)
            character(len=*), intent(in) :: text, names
            character(len=:), allocatable :: kept, name
            integer :: start, finish
            kept = ""
            start = 1
            do while (start <= len(text))
                finish = start + index(text(start:), nl) - 1
                if (finish < start) finish = len(text)
                name = text(start:start + index(text(start:finish), " ") - 2)
                if (len(name) > 1 .and. scan(name(1:1), "vxy") == 1 .and. &
                    verify(name(2:), "0123456789") == 0) name = name(1:1)
                if (index(names, ","//name//",") > 0) kept = kept//text(start:finish)
                start = finish + 1
            end do
        end function named_lines
    end subroutine test_print

    !> What an answer rests on, in its own lines: each scene, a line its
    !> answer must print, and one it must not. `order proven` only where the
    !> order check reaches the answer's premise: the definition's row (and in
    !> real(8), and precision=auto's certificate), a certified cycle it
    !> proves (p = 5, e = 0.258); computed where it does not (p = 4 of mixed
    !> masses: real(16) leaves exact arithmetic's order at 587 collisions, the
    !> check stops at 271, the limit is at 11,734), or where it does not
    !> apply (a ring). An answer at tolerance names why (a collision passed
    !> over below tol: with tol=0 the row is certified), in real(8) as in
    !> real(16) (the premises are judged with the answer, in the kind that
    !> answered, and a run in real(8) whose one limit is certified but which
    !> passed a collision over is not a proven collapse).
    subroutine test_premises(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: cases(*, *) = reshape([character(len=70) :: &
            "e=0.2", "order proven", "rests_on", &
            "e=0.2 precision=dp", "order proven", "order_stopped_by", &
            "e=0.2 precision=auto", "order proven", "order computed", &
            "p=5 e=0.258", "answer certified", "order computed", &
            "p=5 e=0.258", "order proven", "rests_on", &
            "masses=1,2,1.5,1 e=0.1", "answer certified", "order proven", &
            "masses=1,2,1.5,1 e=0.1", "order computed", "rests_on", &
            "masses=1,2,1.5,1 e=0.1", "order_stopped_by which of gaps 3 and 1 closes", "", &
            "p=4 ring=10 velocities=1,0,0,-1 e=0.5", "order computed", "order proven", &
            "p=4 ring=10 velocities=1,0,0,-1 e=0.5", "order_stopped_by given velocities", "", &
            "masses=10,1,1,1 e=0.2", "answer tolerance", "limits_tolerance 1", &
            "masses=10,1,1,1 e=0.2", "rests_on passed_below_tol", "closing_below_tol", &
            "masses=10,1,1,1 e=0.2 tol=0", "answer certified", "rests_on", &
            "p=20 e=0.5", "rests_on limits_tolerance passed_below_tol", "order proven", &
            "p=20 e=0.5 precision=dp", "rests_on limits_tolerance passed_below_tol", "", &
            "p=5 e=0.385 masses=0.052,1.086,0.099,0.336,19.944 precision=dp", &
            "collapse unproven", "collapse proven", &
            "p=100 e=0.5", "order_stopped_by not checked: its cost", "order proven"], [3, 17])
        integer :: i, status
        character(len=:), allocatable :: out, err
        do i = 1, size(cases, 2)
            call run_cli(trim(cases(1, i)), status, out, err)
            call check(error, status == 0, trim(cases(1, i))//": exit status")
            call check(error, index(out, nl//trim(cases(2, i))) > 0, trim(cases(1, i)) &
                //": no line '"//trim(cases(2, i))//"' in"//nl//out)
            if (len_trim(cases(3, i)) > 0) call check(error, index(out, nl//trim(cases(3, i))) &
                == 0, trim(cases(1, i))//": a line '"//trim(cases(3, i))//"' in"//nl//out)
            if (allocated(error)) return
        end do
    end subroutine test_premises

    !> A heavy sphere 1 standing in for a wall (masses 1e100, 1, 1, 1): its
    !> own rounding is one shift of every velocity, not a bound that grows
    !> with the mass ratio, so the answer keeps real(16)'s digits; the
    !> velocities are tools/replay's (450 digits) to the 16 printed here.
    subroutine test_heavy_first(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status, at
        real(real64) :: bound
        character(len=:), allocatable :: out, err
        call run_cli("masses=1e100,1,1,1 e=0.5 print=answer,v_bound,v", status, out, err)
        call check(error, status == 0 .and. index(out, "answer exact") == 1, out//err)
        if (allocated(error)) return
        at = index(out, "v_bound ") + len("v_bound ")
        read (out(at:index(out(at:), nl) + at - 2), *) bound
        call check(error, bound < 1.0e-20_real64, "masses=1e100,1,1,1: v_bound "//out)
        call check(error, index(out, "v2 1.010009765625000") > 0 .and. &
            index(out, "v4 1.110717773437500") > 0, "masses=1e100,1,1,1: velocities "//out)
    end subroutine test_heavy_first

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
        ! 3 collision lines + start + header + 4 + 4 + 3 + 8 quantity lines
        ! (collisions, t_end, status, precision, answer, v_bound, order,
        ! order_stopped_by: a rate of exactly 0 within its rounding's bound;
        ! v, x; y)
        call check(error, count_lines(out) == 3 + 4 + 4 + 3 + 1 + 1 + 8, &
            "events=yes: wrong number of lines")
    end subroutine test_events

    !> `events=FILE.tsv` writes the event table alone into the file, a TSV
    !> table with one header row naming each column and its unit, one row
    !> per event with as many fields; the answer goes to stdout, without
    !> the table.
    subroutine test_events_file(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status, rows, i, start, finish
        character(len=:), allocatable :: out, err, table, header, line
        call execute_command_line("rm -f "//table_file)
        call run_cli("p=5 e=0.3 events="//table_file, status, out, err)
        call check(error, status == 0 .and. len(err) == 0, "events=FILE: exit status "// &
            itoa_local(status)//": "//err)
        if (allocated(error)) return
        call check(error, index(out, "event"//tab) == 0 .and. index(out, tab) == 0 .and. &
            index(out, "collisions ") == 1, "events=FILE: the table on stdout: "//out)
        table = read_text(table_file)
        header = table(:index(table, nl) - 1)
        call check(error, header == "event"//tab//"kind"//tab//"first"//tab//"last"//tab// &
            "t[L/V]"//tab//"w[V]"//tab//"x1[L]"//tab//"dx1[V]"//tab//"y1[L]"//tab//"y2[L]" &
            //tab//"y3[L]"//tab//"y4[L]"//tab//"dy1[V]"//tab//"dy2[V]"//tab//"dy3[V]"//tab// &
            "dy4[V]", "events=FILE: header "//header)
        ! every row: as many fields as the header, the start first
        rows = 0
        start = len(header) + 2
        do while (start <= len(table))
            finish = start + index(table(start:), nl) - 2
            line = table(start:finish)
            call check(error, count_tabs(line) == count_tabs(header), "events=FILE: a row " &
                //"of another width: "//line)
            if (allocated(error)) return
            if (rows == 0) call check(error, index(line, "0"//tab//"start"//tab) == 1, &
                "events=FILE: first row "//line)
            rows = rows + 1
            start = finish + 2
        end do
        ! the start, each collision and each collapse limit
        i = index(out, "collisions ") + len("collisions ")
        call check(error, rows == 1 + read_int_at(out, i) + count_word(out, "collapses"), &
            "events=FILE: "//itoa_local(rows)//" rows for "//out(:index(out, nl)))
        call check(error, table(len(table):) == nl, "events=FILE: last line unended")
    end subroutine test_events_file

    !> A run refused after it ran (its times overflow), an answer that cannot
    !> be written, or a file that cannot be made: no table file is left, nor
    !> its temporary name.
    subroutine test_events_file_failures(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        character(len=:), allocatable :: out, err
        call execute_command_line("rm -f "//table_file//" "//table_file//".tmp")
        call run_cli("v0=1e-4931 events="//table_file, status, out, err)
        call check(error, status == 2 .and. count_lines(err) == 1 .and. len(out) == 0, &
            "refused run: status "//itoa_local(status)//": "//err)
        call check(error, .not. exists(table_file) .and. .not. exists(table_file//".tmp"), &
            "refused run left a table file")
        call execute_command_line(program_path_cached()//" e=0.2 events="//table_file &
            //" > /dev/full 2> "//err_file, exitstat=status)
        err = read_text(err_file)
        call check(error, status == 1 .and. count_lines(err) == 1, "stdout on /dev/full: " &
            //"status "//itoa_local(status)//": "//err)
        call check(error, .not. exists(table_file) .and. .not. exists(table_file//".tmp"), &
            "a failed write left a table file")
        call execute_command_line("mkdir -p build/test_cli_dir.tsv")
        call run_cli("events=build/test_cli_dir.tsv", status, out, err)
        call check(error, status == 2 .and. count_lines(err) == 1 .and. len(out) == 0 .and. &
            index(err, "sphere-row: events = build/test_cli_dir.tsv: not a regular file") == 1, &
            "a directory: "//err)
        call check(error, .not. exists("build/test_cli_dir.tsv.tmp"), "a directory: .tmp left")
        call run_cli("events=build/no_such_directory/x.tsv", status, out, err)
        call check(error, status == 2 .and. count_lines(err) == 1 .and. len(out) == 0 .and. &
            index(err, "sphere-row: events = build/no_such_directory/x.tsv: cannot be " &
            //"written (No such file or directory); allowed") == 1, "no directory: "//err)
    end subroutine test_events_file_failures

    !> The event table's header of a long row comes at once: p = 50,000 with
    !> its first collision (a header of 10^5 columns and three rows of 10^5
    !> numbers) in well under the 40 s a header assembled column by column
    !> took at this length.
    subroutine test_events_long_row(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        integer(int64) :: start, finish, rate
        real :: seconds
        character(len=:), allocatable :: err
        call system_clock(start, rate)
        call execute_command_line(program_path_cached()//" p=50000 e=1 max_collisions=1 " &
            //"events="//table_file//" > /dev/null 2> "//err_file, exitstat=status)
        call system_clock(finish)
        seconds = real(finish - start)/real(rate)
        err = read_text(err_file)
        call check(error, status == 0, "p=50000 events: status "//itoa_local(status)//": "//err)
        call check(error, seconds < 10.0, "p=50000 events: header and 3 rows took more than " &
            //"10 s")
        ! what the rows cost is a note, not a refusal: it says so
        call check(error, index(err, "sphere-row: note (the run goes on): events = ") == 1, &
            "p=50000 events: the note on stderr reads: "//err)
        call execute_command_line("rm -f "//table_file)
    end subroutine test_events_long_row

    !> `--help` describes every line of the answer and every column of the
    !> event table with its unit, within 100 columns a line.
    subroutine test_help_output(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: names(*) = [character(len=32) :: "collisions", &
            "t_end", "status", "precision", "certified", "not_dp", "answer", "v_bound", &
            "collapses", "closed_form_limits", "limits_exact", "limits_certified", &
            "limits_bounded", "limits_tolerance", "collapse", "collapse_spheres", "collapse_t", &
            "separation_scale", "separation_not_excluded_below", "active", "v<i>", "x<i>", &
            "y<i>", "event", "kind", "first", "last", "t[L/V]", "w[V]", "x1[L]", "dx1[V]", &
            "y<i>[L]", "dy<i>[V]"]
        integer :: status, i, start, finish
        character(len=:), allocatable :: out, err
        call run_cli("--help", status, out, err)
        call check(error, status == 0, "--help: exit status")
        do i = 1, size(names)
            call check(error, index(out, nl//"  "//trim(names(i))//" ") > 0 .or. &
                index(out, nl//"  "//trim(names(i))//nl) > 0, "--help does " &
                //"not describe the output line or column "//trim(names(i)))
        end do
        call check(error, index(out, "Units: L is the unit") > 0, "--help: units")
        start = 1
        do while (start <= len(out))
            finish = start + index(out(start:), nl) - 2
            if (finish < start - 1) finish = len(out)
            call check(error, finish - start + 1 <= 100, "--help: a line of " &
                //itoa_local(finish - start + 1)//" columns: "//out(start:finish))
            if (allocated(error)) return
            start = finish + 2
        end do
    end subroutine test_help_output

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
        call check(error, index(out, "print=all") > 0 .and. index(out, "allowed all, or a " &
            //"comma-separated list of these, each once: collisions, t_end,") > 0, &
            "--help: print and the names it takes")
    end subroutine test_help

    !> `--version` prints the name and the version fpm.toml states, exit 0,
    !> nothing on stderr (among other arguments too).
    subroutine test_version(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status, at
        character(len=:), allocatable :: out, err, toml, version
        toml = read_text("fpm.toml")
        at = index(toml, nl//"version = """)
        call check(error, at > 0, "fpm.toml states no version")
        if (allocated(error)) return
        version = toml(at + 12:)
        version = version(:index(version, """") - 1)
        call run_cli("--version", status, out, err)
        call check(error, status == 0 .and. out == "sphere-row "//version//nl .and. &
            len(err) == 0, "--version: status "//itoa_local(status)//", stdout '"//out &
            //"', stderr '"//err//"', fpm.toml's version "//version)
        if (allocated(error)) return
        call run_cli("e=0.5 --version", status, out, err)
        call check(error, status == 0 .and. out == "sphere-row "//version//nl, &
            "e=0.5 --version: "//out//err)
    end subroutine test_version

    !> A long run prints progress lines on stderr without a terminal too
    !> (SPHERE_ROW_PROGRESS=0: at every look at the clock, each 65536
    !> collisions), naming the budget and the fastest closing rate, and the
    !> answer on stdout is that of the run without them.
    subroutine test_progress(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: scene = "p=40 e=0.8 max_collisions=140000"
        integer :: status
        character(len=:), allocatable :: out, err, quiet
        call run_cli(scene, status, quiet, err)
        call check(error, status == 0 .and. len(err) == 0, scene//": "//err)
        if (allocated(error)) return
        call execute_command_line("SPHERE_ROW_PROGRESS=0 "//program_path_cached()//" " &
            //scene//" > "//out_file//" 2> "//err_file, exitstat=status)
        out = read_text(out_file)
        err = read_text(err_file)
        call check(error, status == 0 .and. out == quiet, "SPHERE_ROW_PROGRESS=0: status " &
            //itoa_local(status)//", or stdout changed")
        call check(error, index(err, "sphere-row: progress: 131072 of 140000 collisions " &
            //"(max_collisions, 93 %), t = ") == 1 .and. index(err, ", fastest closing rate ") &
            > 0 .and. count_lines(err) == 1, "the progress line: "//err)
        if (allocated(error)) return
        call execute_command_line("SPHERE_ROW_PROGRESS=x "//program_path_cached()//" " &
            //scene//" > "//out_file//" 2> "//err_file, exitstat=status)
        err = read_text(err_file)
        call check(error, status == 2 .and. index(err, "sphere-row: SPHERE_ROW_PROGRESS = x: " &
            //"not a number; allowed seconds >= 0 or off") == 1 .and. &
            len(read_text(out_file)) == 0, "SPHERE_ROW_PROGRESS=x: "//err)
    end subroutine test_progress

    function program_path_cached() result(path)
        character(len=:), allocatable :: path
        character(len=:), allocatable, save :: saved
        if (.not. allocated(saved)) saved = program_path("sphere-row")
        path = saved
    end function program_path_cached

    logical function exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=exists)
    end function exists

    pure integer function count_tabs(line)
        character(len=*), intent(in) :: line
        integer :: i
        count_tabs = 0
        do i = 1, len(line)
            if (line(i:i) == tab) count_tabs = count_tabs + 1
        end do
    end function count_tabs

    !> The integer that starts at position `at` of `text` (0 if none).
    integer function read_int_at(text, at)
        character(len=*), intent(in) :: text
        integer, intent(in) :: at
        integer :: ios, finish
        finish = at + verify(text(at:), "0123456789") - 2
        read (text(at:finish), *, iostat=ios) read_int_at
        if (ios /= 0) read_int_at = 0
    end function read_int_at

    !> The value of the answer line `word N`, 0 if there is none.
    integer function count_word(text, word)
        character(len=*), intent(in) :: text, word
        integer :: at
        count_word = 0
        at = index(text, nl//word//" ")
        if (at > 0) count_word = read_int_at(text, at + len(word) + 2)
    end function count_word

    pure function itoa_local(i) result(text)
        integer, intent(in) :: i
        character(len=:), allocatable :: text
        character(len=16) :: buffer
        write (buffer, "(i0)") i
        text = trim(buffer)
    end function itoa_local

end module test_cli
