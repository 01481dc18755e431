!> Tests of the front door: one table of malformed inputs
!> (test/malformed_inputs.tsv), each run against the real `sphere-row`
!> executable and through the parser in this process, plus accepted inputs and
!> the strict readers on their own.
!>
!> A row's argument list is written with blanks between arguments; inside an
!> argument `\s` stands for a blank, `\n` for a line feed, `\t` for a tab,
!> `\xHH` for the byte of hexadecimal code HH and `\e` alone for an empty
!> argument. Files named `F/...` are written by write_scene_files into
!> build/test_front/.
module test_front
    use, intrinsic :: iso_fortran_env, only: int64
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    use sphere_row, only: qp, scene_t, itoa
    use sphere_row_cli, only: cli_t, string_t
    use sphere_row_scene_keys, only: add_scene_keys, scene_from_cli, check_scene_in_dp
    use sphere_row_read, only: read_real, read_int, read_reals, is_real_text, is_int_text, &
        printable
    use sphere_row_format, only: short_text, real_text, number_text_length, earned_str, &
        real_str
    use sphere_row_error, only: input_error_t => error_t
    use testsuite, only: error_t, unittest_t, new_unittest, check, read_text, count_lines
    use test_cli, only: program_path
    use test_support, only: words
    implicit none
    private
    public :: collect_front, malformed_inputs, bad_case_t

    character(len=*), parameter :: dir = "build/test_front"
    character(len=*), parameter :: out_file = dir//"/out", err_file = dir//"/err"
    !> The table of malformed inputs (read_bad_rows).
    character(len=*), parameter :: bad_table = "test/malformed_inputs.tsv"

    !> One malformed input: the arguments, the exit status expected of
    !> `sphere-row` and a text its one-line message must contain.
    type :: bad_case_t
        character(len=:), allocatable :: args
        integer :: status = 2
        character(len=:), allocatable :: expect
    end type bad_case_t

contains

    !> The front door's tests.
    function collect_front() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("table_size", test_table_size), &
            new_unittest("malformed_inputs_cli", test_malformed_cli), &
            new_unittest("malformed_inputs_parser", test_malformed_parser), &
            new_unittest("accepted_inputs", test_accepted), &
            new_unittest("scene_file_and_overrides", test_scene_file), &
            new_unittest("real_syntax", test_real_syntax), &
            new_unittest("int_syntax", test_int_syntax), &
            new_unittest("printable_and_short_text", test_printable), &
            new_unittest("real_text_as_formatted_write", test_real_text), &
            new_unittest("earned_digits_down_to_the_bound", test_earned), &
            new_unittest("help_from_registry", test_help), &
            new_unittest("range_on_the_digits", test_range_digits), &
            new_unittest("scene_file_linear_time", test_linear_reading), &
            new_unittest("stdin_scene", test_stdin), &
            new_unittest("output_write_checked", test_output_checked), &
            new_unittest("time_overflow_names_v0", test_time_overflow), &
            new_unittest("no_trailing_blank", test_no_trailing_blank), &
            new_unittest("dp_tol_and_digits", test_dp_tol) &
            ]
    end function collect_front

    !> Every malformed input the front door must refuse: the rows of
    !> test/malformed_inputs.tsv (read_bad_rows), and one row too long to write
    !> there.
    function malformed_inputs() result(rows)
        type(bad_case_t), allocatable :: rows(:)
        rows = [read_bad_rows(bad_table), &
            bad_case_t("e="//repeat("7x", 600), 2, "e = "//repeat("7x", 600)//": not a number")]
    end function malformed_inputs

    !> The rows of a table of malformed inputs: a header row, then one row a
    !> refusal with the columns group (which kind of refusal: number_syntax,
    !> not_numbers, beyond_real16, out_of_range, integers, lists, keys_twice,
    !> unknown_keys, scales, scene_files, real8 with precision = dp, subnormal,
    !> words, hostile_files), args (see the module's comment), status (the
    !> exit status expected) and expect (a text the message must contain). A
    !> line that is not four fields, or a file without the header (or not
    !> readable), comes back as a row of status -1 naming what is wrong, which
    !> test_table_size refuses.
    function read_bad_rows(file) result(rows)
        character(len=*), intent(in) :: file
        type(bad_case_t), allocatable :: rows(:)
        character(len=:), allocatable :: text
        character(len=*), parameter :: tab = achar(9), header = "group"//tab//"args"//tab &
            //"status"//tab//"expect"
        integer :: first, last, n, t1, t2, t3, ios
        text = read_text(file)
        last = index(text, new_line("a")) - 1
        if (last < 0 .or. text(:max(last, 0)) /= header) then
            rows = [bad_case_t(file//": no header row '"//header//"'", -1, "")]
            return
        end if
        allocate (rows(count_lines(text) - 1))
        do n = 1, size(rows)
            first = last + 2
            last = first + index(text(first:), new_line("a")) - 2
            t1 = index(text(first:last), tab) + first - 1
            t2 = index(text(t1 + 1:last), tab) + t1
            t3 = index(text(t2 + 1:last), tab) + t2
            rows(n)%args = text(t1 + 1:t2 - 1)
            rows(n)%expect = text(t3 + 1:last)
            read (text(t2 + 1:t3 - 1), *, iostat=ios) rows(n)%status
            if (t1 < first .or. t2 <= t1 .or. t3 <= t2 .or. index(text(t3 + 1:last), tab) > 0 &
                .or. ios /= 0) then
                rows(n)%status = -1
                rows(n)%args = file//" line "//itoa(n + 1)//": not four tab-separated fields"
            end if
        end do
    end function read_bad_rows

    !> The scene files the table names.
    subroutine write_scene_files()
        call execute_command_line("mkdir -p "//dir)
        call write_file("good.nml", "&scene p=6, e=1.0, masses=1,1,1,1,1,1 /")
        call write_file("element.nml", "&scene masses(4)=2 /")
        call write_file("list_directed.nml", "&scene e=1-5 /")
        call write_file("repeat.nml", "&scene masses=4*1 /")
        call write_file("null.nml", "&scene masses=1,,1,1 /")
        call write_file("unknown.nml", "&scene foo=1 /")
        call write_file("twice.nml", "&scene e=0.5, e=0.6 /")
        call write_file("events.nml", "&scene events=yes /")
        call write_file("no_group.nml", "e=0.5")
        call write_file("other_group.nml", "&other e=0.5 /")
        call write_file("unended.nml", "&scene e=0.5")
        call write_file("after_end.nml", "&scene e=0.5 / p=3")
        call write_file("two_values.nml", "&scene e=0.5, 0.6 /")
        call write_file("empty.nml", "")
        call write_file("range.nml", "&scene e=2 /")
        call write_file("gaps.nml", "&scene gaps=1,2,3 /")
        call write_file("masses.nml", "&scene masses=1,1,1 /")
        call write_file("misspelt.nml", "&scene Mases=1,1,1,1 /")
        call write_file("scale.nml", "&scene d=1e4932 /")
        call write_file("binary.nml", "&scene e="//achar(0)//"0.5 /")
        call write_file("escape.nml", "&scene"//achar(27)//" e=0.5 /")
        call write_file("unicode.nml", "&scene e=0."//achar(194)//achar(189)//" /")
        call execute_command_line("rm -f "//dir//"/fifo && mkfifo "//dir//"/fifo")
        call write_file("commented.nml", "! the definition's row, heavier last sphere" &
            //new_line("a")//"&SCENE  P = 4,  E = 0.5,   ! restitution"//new_line("a") &
            //"  masses = 1, 1, 1,"//new_line("a")//"    2, gaps=1 2 3, /"//new_line("a"))
    end subroutine write_scene_files

    subroutine write_file(name, text)
        character(len=*), intent(in) :: name, text
        integer :: unit
        open (newunit=unit, file=dir//"/"//name, status="replace", action="write")
        if (len(text) > 0) write (unit, "(a)") text
        close (unit)
    end subroutine write_file

    !> The arguments of a row (see the module's comment).
    function decode(row) result(args)
        character(len=*), intent(in) :: row
        type(string_t), allocatable :: args(:)
        integer :: n
        args = words(row)
        do n = 1, size(args)
            args(n)%s = unescape(args(n)%s)
        end do
    end function decode

    pure function unescape(text) result(arg)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: arg
        integer :: i
        arg = ""
        if (text == "\e") return
        if (len(text) >= 2) then
            if (text(1:2) == "F/") then
                arg = dir//"/"//text(3:)
                return
            end if
        end if
        if (text == "F") then
            arg = dir
            return
        end if
        i = 1
        do while (i <= len(text))
            if (text(i:i) == "\" .and. i < len(text)) then
                select case (text(i + 1:i + 1))
                case ("s")
                    arg = arg//" "
                case ("n")
                    arg = arg//new_line("a")
                case ("t")
                    arg = arg//achar(9)
                case ("x")
                    arg = arg//achar(hex_value(text(i + 2:i + 3)))
                    i = i + 2
                case default
                    arg = arg//text(i:i + 1)
                end select
                i = i + 2
            else
                arg = arg//text(i:i)
                i = i + 1
            end if
        end do
    end function unescape

    !> The value of two hexadecimal digits (lower case).
    pure integer function hex_value(digits)
        character(len=2), intent(in) :: digits
        hex_value = 16*(index("0123456789abcdef", digits(1:1)) - 1) &
            + index("0123456789abcdef", digits(2:2)) - 1
    end function hex_value

    !> The arguments quoted for the shell.
    pure function quoted(args) result(line)
        type(string_t), intent(in) :: args(:)
        character(len=:), allocatable :: line
        integer :: i, j
        line = ""
        do i = 1, size(args)
            line = line//" '"
            do j = 1, len(args(i)%s)
                if (args(i)%s(j:j) == "'") then
                    line = line//"'\''"
                else
                    line = line//args(i)%s(j:j)
                end if
            end do
            line = line//"'"
        end do
    end function quoted

    !> Path of an executable linked with the library as it is now: fpm 0.12
    !> relinks an executable only when its own sources change, so after an
    !> edit of the library alone `fpm test` would run the old one. Removing it
    !> makes fpm link it again.
    function fresh_program_path(name) result(path)
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: path
        integer :: unit, ios
        path = program_path(name)
        if (len(path) == 0) return
        open (newunit=unit, file=path, status="old", action="read", iostat=ios)
        if (ios == 0) close (unit, status="delete")
        path = program_path(name)
    end function fresh_program_path

    !> A registry like the CLI's: the scene keys, `events` and `precision`.
    subroutine cli_keys(cli)
        type(cli_t), intent(out) :: cli
        cli%name = "sphere-row"
        cli%synopsis = "[FILE] [key=value ...]"
        call add_scene_keys(cli)
        call cli%add_table("events", "no", "yes adds the event table, FILE.tsv writes it there")
        call cli%add_choice("precision", "qp", [character(len=4) :: "qp", "dp", "auto"], &
            "the precision of the run")
    end subroutine cli_keys

    !> The scene of a registry as sphere-row takes it: scene_from_cli, the
    !> event table only in real(16), and the checks of real(8) for dp.
    subroutine cli_scene(cli, scene, refused)
        type(cli_t), intent(in) :: cli
        type(scene_t), intent(out) :: scene
        type(input_error_t), allocatable, intent(out) :: refused
        call scene_from_cli(cli, scene, refused)
        if (allocated(refused)) return
        if (cli%get_word("events") /= "no" .and. cli%get_word("precision") /= "qp") then
            allocate (refused)
            refused%message = "events = "//cli%get_word("events")//" with precision = " &
                //cli%get_word("precision") &
                //": allowed only with precision = qp"
        else if (cli%get_word("precision") == "dp") then
            call check_scene_in_dp(cli, scene, refused)
        end if
    end subroutine cli_scene

    !> The table holds at least 60 malformed inputs, each expecting exit status 2.
    subroutine test_table_size(error)
        type(error_t), allocatable, intent(out) :: error
        type(bad_case_t), allocatable :: rows(:)
        integer :: i
        rows = malformed_inputs()
        call check(error, size(rows) >= 60, "fewer than 60 malformed inputs")
        do i = 1, size(rows)
            call check(error, rows(i)%status == 2, rows(i)%args//": expected status not 2")
        end do
    end subroutine test_table_size

    !> Each malformed input, given to the real `sphere-row`: the expected exit
    !> status, nothing on stdout, one line on stderr holding the expected text.
    subroutine test_malformed_cli(error)
        type(error_t), allocatable, intent(out) :: error
        type(bad_case_t), allocatable :: rows(:)
        character(len=:), allocatable :: path, out, err
        integer :: i, status
        call write_scene_files()
        path = fresh_program_path("sphere-row")
        call check(error, len(path) > 0, "sphere-row: no executable found")
        if (allocated(error)) return
        rows = malformed_inputs()
        do i = 1, size(rows)
            call execute_command_line(path//quoted(decode(rows(i)%args))//" > "//out_file &
                //" 2> "//err_file, exitstat=status)
            out = read_text(out_file)
            err = read_text(err_file)
            call check(error, status == rows(i)%status, rows(i)%args//": exit status " &
                //itoa(status))
            call check(error, len(out) == 0, rows(i)%args//": wrote to stdout: "//out)
            call check(error, count_lines(err) == 1, rows(i)%args//": not one stderr line: " &
                //err)
            call check(error, index(err, "sphere-row: ") == 1, rows(i)%args &
                //": message does not begin with the program's name: "//err)
            call check(error, index(err, rows(i)%expect) > 0, rows(i)%args &
                //": message lacks '"//rows(i)%expect//"': "//err)
            if (allocated(error)) return
        end do
    end subroutine test_malformed_cli

    !> The same table through the parser and scene_from_cli in this process:
    !> an error whose message holds the expected text and no control character.
    subroutine test_malformed_parser(error)
        type(error_t), allocatable, intent(out) :: error
        type(bad_case_t), allocatable :: rows(:)
        type(input_error_t), allocatable :: refused
        type(cli_t) :: cli
        type(scene_t) :: scene
        integer :: i
        call write_scene_files()
        rows = malformed_inputs()
        do i = 1, size(rows)
            call cli_keys(cli)
            call cli%parse(decode(rows(i)%args), refused)
            if (.not. allocated(refused)) call cli_scene(cli, scene, refused)
            call check(error, allocated(refused), rows(i)%args//": accepted by the parser")
            if (allocated(error)) return
            call check(error, index(refused%message, rows(i)%expect) > 0, rows(i)%args &
                //": message lacks '"//rows(i)%expect//"': "//refused%message)
            call check(error, printable(refused%message) == refused%message, rows(i)%args &
                //": message holds a control character")
            if (allocated(error)) return
        end do
    end subroutine test_malformed_parser

    !> Inputs in every allowed spelling give the values they say.
    subroutine test_accepted(error)
        type(error_t), allocatable, intent(out) :: error
        type(input_error_t), allocatable :: refused
        type(cli_t) :: cli
        type(scene_t) :: scene
        call cli_keys(cli)
        call cli%parse(decode("e=.5 v0=2.5d0 d=+1E+2 tol=0 p=+0005 masses=1,2.,3e0,4D-0,5" &
            //" max_collisions=007 events=yes"), refused)
        call check(error, .not. allocated(refused), "spellings refused: "//message(refused))
        if (allocated(error)) return
        call scene_from_cli(cli, scene, refused)
        call check(error, .not. allocated(refused), "scene refused: "//message(refused))
        if (allocated(error)) return
        call check(error, scene%e == 0.5_qp .and. scene%v0 == 2.5_qp .and. scene%d == 100.0_qp &
            .and. scene%tol == 0.0_qp .and. scene%p == 5 .and. scene%max_collisions == 7, &
            "values of e, v0, d, tol, p, max_collisions")
        call check(error, all(scene%m == [1.0_qp, 2.0_qp, 3.0_qp, 4.0_qp, 5.0_qp]), "masses")
        call check(error, all(scene%a == 1.0_qp), "default gaps")
        call check(error, cli%get_flag("events"), "events=yes")
        ! defaults: the definition's scene, tol the kind's epsilon exactly
        call cli_keys(cli)
        call cli%parse([string_t ::], refused)
        if (.not. allocated(refused)) call scene_from_cli(cli, scene, refused)
        call check(error, .not. allocated(refused), "defaults refused: "//message(refused))
        if (allocated(error)) return
        call check(error, scene%p == 4 .and. scene%e == 0.2_qp .and. scene%d == 1.0_qp .and. &
            scene%v0 == 1.0_qp .and. scene%tol == epsilon(1.0_qp) .and. all(scene%a == 1.0_qp) &
            .and. all(scene%m == 1.0_qp) .and. .not. cli%get_flag("events"), "defaults")
        ! the smallest normal real(16) and a value just above it are taken
        call cli_keys(cli)
        call cli%parse(decode("tol=3.3621031431120935062626778173217526e-4932 v0=1e-4931"), &
            refused)
        call check(error, .not. allocated(refused), "tol=tiny refused: "//message(refused))
    end subroutine test_accepted

    !> A scene file with comments, upper case, blanks and line breaks; keys on
    !> the command line override the file's.
    subroutine test_scene_file(error)
        type(error_t), allocatable, intent(out) :: error
        type(input_error_t), allocatable :: refused
        type(cli_t) :: cli
        type(scene_t) :: scene
        call write_scene_files()
        call cli_keys(cli)
        call cli%parse(decode("F/commented.nml e=0.25"), refused)
        if (.not. allocated(refused)) call scene_from_cli(cli, scene, refused)
        call check(error, .not. allocated(refused), "commented.nml: "//message(refused))
        if (allocated(error)) return
        call check(error, scene%p == 4 .and. scene%e == 0.25_qp, "p from file, e from argument")
        call check(error, all(scene%m == [1.0_qp, 1.0_qp, 1.0_qp, 2.0_qp]), "masses from file")
        call check(error, all(scene%a == [1.0_qp, 2.0_qp, 3.0_qp]), "gaps from file")
        call check(error, cli%given("gaps") .and. .not. cli%given("a"), "gaps given, a not")
    end subroutine test_scene_file

    !> The real syntax: what is a number and what is not.
    subroutine test_real_syntax(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: good(*) = [character(len=12) :: "0", "-0", "+1.", &
            ".5", "1.5", "1e5", "1E-5", "1d+5", "1D5", "-2.5e-3", "007", "1.e3"]
        character(len=*), parameter :: wrong(*) = [character(len=12) :: ".", "+", "-", "e", &
            "1e", "1e+", ".e1", "1-5", "1+2", "1.2.3", "1e5.0", "0x10", "nan", "inf", "1q5", &
            "1,0", "++1", "1e--5", "1_16", "1.5f", "-.", "1e5e5"]
        type(input_error_t), allocatable :: refused
        real(qp) :: x
        real(qp), allocatable :: xs(:)
        integer :: i
        do i = 1, size(good)
            call check(error, is_real_text(trim(good(i))), trim(good(i))//" refused")
        end do
        do i = 1, size(wrong)
            call check(error, .not. is_real_text(trim(wrong(i))), trim(wrong(i))//" accepted")
        end do
        call check(error, .not. is_real_text("1 ") .and. .not. is_real_text(" 1") .and. &
            .not. is_real_text(""), "blanks or empty accepted")
        call read_real("x", "-2.5e-3", x, refused)
        call check(error, .not. allocated(refused) .and. x == -2.5e-3_qp, "-2.5e-3")
        call read_real("x", "1.2e4933", x, refused)
        call check(error, allocated(refused), "1.2e4933 accepted")
        call read_reals("xs", "1,2.5,-3", xs, refused)
        call check(error, .not. allocated(refused), "list refused")
        if (allocated(error)) return
        call check(error, size(xs) == 3 .and. all(xs == [1.0_qp, 2.5_qp, -3.0_qp]), "list values")
    end subroutine test_real_syntax

    !> The integer syntax and the range of the default integer.
    subroutine test_int_syntax(error)
        type(error_t), allocatable, intent(out) :: error
        type(input_error_t), allocatable :: refused
        integer :: n
        call check(error, is_int_text("12") .and. is_int_text("-3") .and. is_int_text("+0"), &
            "integers refused")
        call check(error, .not. (is_int_text("1.") .or. is_int_text("1e3") .or. &
            is_int_text("+") .or. is_int_text("") .or. is_int_text("1 ")), "non-integers accepted")
        call read_int("n", "2147483647", n, refused)
        call check(error, .not. allocated(refused) .and. n == huge(n), "huge(n) refused")
        call read_int("n", "-0000000000000000000000012", n, refused)
        call check(error, .not. allocated(refused) .and. n == -12, "leading zeros")
        call read_int("n", "2147483648", n, refused)
        call check(error, allocated(refused), "huge(n) + 1 accepted")
        call read_int("n", "123456789012345678901234567890", n, refused)
        call check(error, allocated(refused), "30 digits accepted")
    end subroutine test_int_syntax

    !> Control characters are shown escaped; short_text reads back exactly.
    subroutine test_printable(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp) :: x
        character(len=:), allocatable :: text
        call check(error, printable("a"//new_line("a")//"b"//achar(9)//achar(0)) == &
            "a\nb\t\x00", "printable: "//printable("a"//new_line("a")//"b"//achar(9)//achar(0)))
        call check(error, short_text(0.2_qp) == "0.2" .and. short_text(1.0_qp) == "1" .and. &
            short_text(1.0e6_qp) == "1000000", "short_text of 0.2, 1, 1e6: " &
            //short_text(0.2_qp)//" "//short_text(1.0_qp)//" "//short_text(1.0e6_qp))
        text = short_text(epsilon(1.0_qp))
        read (text, *) x
        call check(error, x == epsilon(1.0_qp), "short_text(epsilon) does not read back")
        call check(error, short_text(huge(1.0_qp), 3, "down") == "1.18e4932", &
            "huge rounded down: "//short_text(huge(1.0_qp), 3, "down"))
    end subroutine test_printable

    !> earned_str writes x down to its bound's decade: every digit asked for
    !> where the bound is 0; the digits from x's decade to the bound's; below
    !> two of them, x rounded at the bound's decade (a carry to the next
    !> decade, a zero, an exponent of four places, none earned by huge). A
    !> bound 1e-20 below 1e-33, relatively, has decade -34, though it rounds
    !> to real(8)'s 1e-33, whose log10 is -33.
    subroutine test_earned(error)
        type(error_t), allocatable, intent(out) :: error
        type :: case_t
            real(qp) :: x, bound
            character(len=12) :: text
        end type case_t
        type(case_t), parameter :: cases(*) = [ &
            case_t(2.5_qp, 0.0_qp, "2.50E+00"), &
            case_t(2.5_qp, huge(1.0_qp), "0E+4932"), &
            case_t(0.123456_qp, 1.0e-2_qp, "1.2E-01"), &
            case_t(0.123456_qp, 9.9e-3_qp, "1.23E-01"), &
            case_t(0.123456_qp, 1.0e-10_qp, "1.23E-01"), &
            case_t(1.5e-99_qp, 1.0e-100_qp, "1.5E-99"), &
            case_t(-0.34_qp, 0.2_qp, "-3E-01"), &
            case_t(0.96_qp, 0.1_qp, "1E+00"), &
            case_t(1.0_qp, 1.0_qp, "1E+00"), &
            case_t(0.003_qp, 0.1_qp, "0E-01"), &
            case_t(0.0_qp, 1.0e-33_qp, "0E-33"), &
            case_t(0.0_qp, 1.0e-33_qp*(1 - 1.0e-20_qp), "0E-34"), &
            case_t(7.0e-120_qp, 1.0e-120_qp, "7E-0120")]
        integer :: i
        character(len=:), allocatable :: got
        do i = 1, size(cases)
            got = earned_str(cases(i)%x, cases(i)%bound, 3)
            call check(error, got == trim(cases(i)%text), short_text(cases(i)%x)//" within " &
                //short_text(cases(i)%bound)//": "//got//", not "//trim(cases(i)%text))
            if (allocated(error)) return
        end do
        call check(error, earned_str(1.0_qp/3, 0.0_qp) == real_str(1.0_qp/3, &
            precision(1.0_qp) + 1), "an exact third: not every digit of real(16)")
        call check(error, earned_str(ieee_value(1.0_qp, ieee_quiet_nan), 1.0e-3_qp) == "nan" &
            .and. earned_str(-ieee_value(1.0_qp, ieee_positive_inf), 1.0e-3_qp) == "-inf", &
            "a value that is not finite, within 1e-3: not nan, -inf")
        call check(error, earned_str(0.123_qp, 1.0e-30_qp, 1) == "1.2E-01", &
            "0.123 within 1e-30 at most 1 digit: "//earned_str(0.123_qp, 1.0e-30_qp, 1) &
            //", not 1.2E-01 (2 digits at the least)")
    end subroutine test_earned

    !> real_text, made without formatted I/O, gives the very text of Fortran's
    !> ES edit descriptor that it stands for: random significands with binary
    !> exponents up to +-1100 (beyond 1e+-300), edge values (0, -0, huge, the
    !> smallest subnormal, the two sides of 1e99 and 1e-99 where the exponent
    !> gets four places) and exact ties of the rounding (k + 1/2, 0.125: to
    !> even), at 1 to 40 significant digits, and as many random numbers of
    !> binary exponents -70 ... 100, where the digits take the short road of
    !> int128 products (fast_digits); and, at 1, 17 and 34 digits,
    !> random numbers over the whole range of real128, subnormals too (whose
    !> exact digits, up to some 11,600 of them, take up to a millisecond).
    subroutine test_real_text(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: places(*) = [1, 2, 3, 4, 7, 17, 33, 34, 35, 40], &
            wide_places(*) = [1, 17, 34]
        real(qp), allocatable :: xs(:), wide(:)
        real(qp) :: u, v
        integer :: i, j, wrong, seed_size, texts
        integer, allocatable :: seed(:)
        character(len=:), allocatable :: first
        xs = [0.0_qp, -0.0_qp, huge(1.0_qp), -huge(1.0_qp), tiny(1.0_qp), &
            tiny(1.0_qp)*epsilon(1.0_qp), 1.0e99_qp, nearest(1.0e99_qp, -1.0_qp), &
            1.0e-99_qp, nearest(1.0e-99_qp, 1.0_qp), 0.125_qp, 0.375_qp, 2.5_qp, 9.5_qp, &
            99.5_qp, 0.1_qp, 1.0_qp/3, 9.999999999999999999999999999999999e5_qp, &
            [(real(i, qp) + 0.5_qp, i=0, 40)], [(2.0_qp**i, i=-120, 120, 7)]]
        call random_seed(size=seed_size)
        seed = [(7919*i + 12, i=1, seed_size)]
        call random_seed(put=seed)
        allocate (wide(300))
        do i = 1, 3000
            call random_number(u)
            call random_number(v)
            xs = [xs, sign(scale(0.5_qp + u/2, nint(-1100 + v*2200)), u - 0.5_qp)]
            ! and the ordinary numbers of a run's output (1e-21 ... 1e30)
            xs = [xs, sign(scale(0.5_qp + v/2, nint(-70 + u*170)), v - 0.5_qp)]
            if (i > size(wide)) cycle
            wide(i) = sign(scale(0.5_qp + v/2, nint(-16500 + u*32884)), v - 0.5_qp)
        end do
        wrong = 0
        texts = 0
        first = ""
        do i = 1, size(xs)
            do j = 1, size(places)
                call compare(xs(i), places(j))
            end do
        end do
        do i = 1, size(wide)
            do j = 1, size(wide_places)
                call compare(wide(i), wide_places(j))
            end do
        end do
        call check(error, wrong == 0, itoa(wrong)//" of "//itoa(texts)// &
            " texts differ, first "//first)
    contains
        !> real_text of x at `digits` against the formatted write; a text
        !> that differs is counted (the first kept).
        subroutine compare(x, digits)
            real(qp), intent(in) :: x
            integer, intent(in) :: digits
            character(len=number_text_length) :: got
            character(len=:), allocatable :: want
            integer :: length
            call real_text(x, digits, got, length)
            want = es_write(x, digits)
            texts = texts + 1
            if (got(:length) == want) return
            wrong = wrong + 1
            if (wrong == 1) first = got(:length)//" against "//want
        end subroutine compare

        !> The ES text that real_text stands for, by a formatted write.
        function es_write(x, digits) result(text)
            real(qp), intent(in) :: x
            integer, intent(in) :: digits
            character(len=:), allocatable :: text
            character(len=80) :: buf
            character(len=40) :: form
            integer :: ew
            ew = 2
            if (x /= 0.0_qp .and. (abs(x) >= 1.0e99_qp .or. abs(x) <= 1.0e-99_qp)) ew = 4
            write (form, "('(es', i0, '.', i0, 'e', i0, ')')") digits + ew + 8, digits - 1, ew
            write (buf, form) x
            text = trim(adjustl(buf))
        end function es_write
    end subroutine test_real_text

    !> `--help` lists every registered key with its default and range.
    subroutine test_help(error)
        type(error_t), allocatable, intent(out) :: error
        type(cli_t) :: cli
        character(len=:), allocatable :: text
        call cli_keys(cli)
        text = cli%usage()
        call check(error, index(text, "usage: sphere-row [FILE]") == 1, "usage line")
        call check(error, index(text, "  p=4 ") > 0 .and. index(text, "  e=0.2 ") > 0 .and. &
            index(text, "  tol=1.93e-34 ") > 0 .and. index(text, "max_collisions=0 ") > 0 &
            .and. index(text, "events=no") > 0 .and. index(text, "masses=m1,m2,...") > 0, &
            "keys with defaults: "//text)
        call check(error, index(text, "allowed 0 <= e <= 1") > 0 .and. &
            index(text, "allowed v0 > 0") > 0 .and. index(text, "allowed 0 <= tol < 1") > 0, &
            "ranges")
    end subroutine test_help

    !> A range is decided on the number as written: just above a closed
    !> bound is refused (in the table), just below an open one is taken, as
    !> the real(16) next inside (its rounding is the bound itself).
    subroutine test_range_digits(error)
        type(error_t), allocatable, intent(out) :: error
        type(input_error_t), allocatable :: refused
        type(cli_t) :: cli
        type(scene_t) :: scene
        integer :: status
        character(len=:), allocatable :: out, err
        call cli_keys(cli)
        call cli%parse(decode("tol=0.99999999999999999999999999999999999999 " &
            //"e=0.99999999999999999999999999999999999999"), refused)
        if (.not. allocated(refused)) call scene_from_cli(cli, scene, refused)
        call check(error, .not. allocated(refused), "tol just below 1 refused: " &
            //message(refused))
        if (allocated(error)) return
        call check(error, scene%tol == nearest(1.0_qp, -1.0_qp), "tol is not the real(16) " &
            //"next below 1: "//short_text(scene%tol))
        call check(error, scene%e == 1.0_qp, "e just below 1 is not 1: "//short_text(scene%e))
        ! in real(8) too, where that tol rounds to 1 once more (it crashed the
        ! run in real(8), found by the fuzz)
        call run_program("tol=0.99999999999999999999999999999999999999 precision=dp", status, &
            out, err)
        call check(error, status == 0 .and. index(out, "precision dp") > 0, &
            "tol just below 1, precision=dp: status "//itoa(status)//": "//err)
    end subroutine test_range_digits

    !> precision=dp takes real(8)'s epsilon as tol unless tol is given: the
    !> same answer as tol = 2^-52 given, and another than real(16)'s tol given
    !> on a row near e_c whose collisions follow rates below 2e-16 (p = 7,
    !> e = 0.3936: 335 collisions at real(8)'s epsilon, 740 at 1.93e-34); and
    !> its numbers have real(8)'s 16 digits, not real(16)'s 34.
    subroutine test_dp_tol(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: plain, own, fine, err
        integer :: status
        call run_program("p=7 e=0.3936 precision=dp", status, plain, err)
        call check(error, status == 0, "p=7 e=0.3936 precision=dp: "//err)
        if (allocated(error)) return
        call run_program("p=7 e=0.3936 precision=dp " &
            //"tol=2.220446049250313080847263336181640625e-16", status, own, err)
        call check(error, status == 0 .and. own == plain, "tol = 2^-52 given differs from " &
            //"the default: "//plain//" | "//own)
        if (allocated(error)) return
        call check(error, index(plain, new_line("a")//"t_end 4.070596753699510E+01" &
            //new_line("a")) > 0 .and. index(plain, new_line("a")//"v1 1.4285714285714E-01" &
            //new_line("a")) > 0, "real(8)'s numbers not in 16 digits, or a velocity with " &
            //"more than its bound leaves: "//plain(:200))
        if (allocated(error)) return
        call run_program("p=7 e=0.3936 precision=dp tol=1.93e-34", status, fine, err)
        call check(error, status == 0 .and. index(plain, "collisions 335"//new_line("a")) == 1 &
            .and. index(fine, "collisions 740"//new_line("a")) == 1, "collisions at the two " &
            //"tolerances: "//plain(:index(plain, new_line("a"))) &
            //fine(:index(fine, new_line("a"))))
    end subroutine test_dp_tol

    !> A scene file of 400,000 line ends and a list of 40,000 masses is read
    !> in well under a second (reading it took 14 s when each line was
    !> appended to the text read so far).
    subroutine test_linear_reading(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: p = 40000
        type(input_error_t), allocatable :: refused
        type(cli_t) :: cli
        type(scene_t) :: scene
        character(len=:), allocatable :: masses
        integer :: unit, i
        integer(int64) :: start, finish, rate
        call write_scene_files()
        allocate (character(len=2*p - 1) :: masses)
        do i = 1, p
            masses(2*i - 1:2*i - 1) = "1"
            if (i < p) masses(2*i:2*i) = ","
        end do
        open (newunit=unit, file=dir//"/long.nml", status="replace", action="write", &
            access="stream", form="unformatted")
        write (unit) repeat(new_line("a"), 400000)//"&scene p = "//itoa(p)//", masses = " &
            //masses//" /"//new_line("a")
        close (unit)
        call system_clock(start, rate)
        call cli_keys(cli)
        call cli%parse(decode("F/long.nml"), refused)
        if (.not. allocated(refused)) call scene_from_cli(cli, scene, refused)
        call system_clock(finish)
        call check(error, .not. allocated(refused), "long.nml refused: "//message(refused))
        if (allocated(error)) return
        call check(error, scene%p == p .and. size(scene%m) == p, "long.nml: p or masses")
        call check(error, real(finish - start)/real(rate) < 1.0, "long.nml read in " &
            //short_text(real(finish - start, qp)/rate, 3)//" s")
    end subroutine test_linear_reading

    !> `-` reads the scene from standard input; a binary stream is refused at
    !> its first control byte, not read to its end.
    subroutine test_stdin(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        character(len=:), allocatable :: out, err
        call write_scene_files()
        call run_program("- < "//dir//"/good.nml", status, out, err)
        call check(error, status == 0 .and. index(out, "collisions 5"//new_line("a")) == 1, &
            "- < good.nml: "//out//err)
        call run_program("- e=0 < "//dir//"/good.nml", status, out, err)
        call check(error, status == 0 .and. index(out, "status quasi_plastic") > 0, &
            "- e=0 < good.nml: "//err)
        call run_program("- < /dev/zero", status, out, err)
        call check(error, status == 2 .and. len(out) == 0 .and. count_lines(err) == 1 .and. &
            index(err, "file '-': byte 1 is the control character \x00") > 0, &
            "- < /dev/zero: "//err)
        call run_program("- < /dev/null", status, out, err)
        call check(error, status == 2 .and. count_lines(err) == 1 .and. &
            index(err, "file '-': empty") > 0, "- < /dev/null: "//err)
    end subroutine test_stdin

    !> Output that cannot be written (a full device, a closed stdout) is an
    !> error: exit status 1 and one line on stderr, not exit 0 and nothing.
    subroutine test_output_checked(error)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), parameter :: cases(3) = [character(len=30) :: &
            "e=0.2 > /dev/full", "e=0.2 >&-", "--help > /dev/full"]
        integer :: status, i
        character(len=:), allocatable :: out, err
        do i = 1, size(cases)
            call run_program(trim(cases(i)), status, out, err, stdout=.false.)
            call check(error, status == 1, trim(cases(i))//": exit status "//itoa(status))
            call check(error, count_lines(err) == 1 .and. index(err, "sphere-row: output = " &
                //"standard output: cannot be written (") == 1, trim(cases(i))//": "//err)
        end do
        call run_program("e=0.2 > /dev/full", status, out, err, stdout=.false.)
        call check(error, index(err, "No space left on device") > 0, "/dev/full: "//err)
    end subroutine test_output_checked

    !> A run whose times overflow real(16) is refused naming v0 and the
    !> smallest v0 whose times stay finite (v0 = 1e-4931 passes the a priori
    !> time scale sum(gaps)/v0, but t_end = 14.9/v0 does not fit).
    subroutine test_time_overflow(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        character(len=:), allocatable :: out, err
        call run_program("v0=1e-4931", status, out, err)
        call check(error, status == 2 .and. len(out) == 0 .and. count_lines(err) == 1, &
            "v0=1e-4931: status "//itoa(status)//": "//out//err)
        call check(error, index(err, "sphere-row: v0 = 1e-4931: the run's times (t_end = " &
            //"14.9") == 1 .and. index(err, "overflow real(16); allowed v0 >= 1.26e-4931") > 0, &
            "v0=1e-4931: "//err)
        call run_program("v0=1.26e-4931", status, out, err)
        call check(error, status == 0 .and. index(out, "collisions 13") == 1, &
            "v0=1.26e-4931, the bound given, refused: "//err)
    end subroutine test_time_overflow

    !> An answer's lines end without a blank: `certified no` too (e = 0.05 is
    !> not certified).
    subroutine test_no_trailing_blank(error)
        type(error_t), allocatable, intent(out) :: error
        integer :: status
        character(len=:), allocatable :: out, err
        call run_program("e=0.05 precision=auto", status, out, err)
        call check(error, status == 0 .and. index(out, new_line("a")//"certified no" &
            //new_line("a")) > 0, "certified no: "//out//err)
        call check(error, index(out, " "//new_line("a")) == 0, "a line ends in a blank: "//out)
    end subroutine test_no_trailing_blank

    !> Run `sphere-row args` (shell redirections allowed) with stdout and
    !> stderr to files unless `stdout` is false (the caller redirects it).
    subroutine run_program(args, status, out, err, stdout)
        character(len=*), intent(in) :: args
        integer, intent(out) :: status
        character(len=:), allocatable, intent(out) :: out, err
        logical, intent(in), optional :: stdout
        character(len=:), allocatable, save :: path
        character(len=:), allocatable :: to_out
        if (.not. allocated(path)) path = program_path("sphere-row")
        to_out = " > "//out_file
        if (present(stdout)) then
            if (.not. stdout) to_out = ""
        end if
        call execute_command_line("rm -f "//out_file//"; "//path//" "//args//to_out//" 2> " &
            //err_file, exitstat=status)
        out = read_text(out_file)
        err = read_text(err_file)
    end subroutine run_program

    function message(refused) result(text)
        type(input_error_t), allocatable, intent(in) :: refused
        character(len=:), allocatable :: text
        text = ""
        if (allocated(refused)) text = refused%message
    end function message

end module test_front
