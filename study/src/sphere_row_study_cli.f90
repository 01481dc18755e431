!> What every study program does with its command line, on the key registry
!> of `sphere_row_cli` and the scene keys of `sphere_row_scene_keys`: the key
!> `out`, `--help` generated from the keys, the scene of the scene keys, and
!> one line on stderr with exit status 2 for bad input.
!>
!> A study program registers its keys between `start_program` and
!> `read_keys`:
!>
!>     call start_program(cli, "c12-b2", "C12 task b2: ..."//nl//"Writes ...")
!>     call cli%add_int("n_grid", "1001", "points of the grid of e in [0, 1]", lo=2)
!>     call add_row_keys(cli, e_set_by="the grid of e")
!>     call read_keys(cli, scene)
!>     n_grid = cli%get_int("n_grid")
!>
!> Groups of keys that several programs share: the scene keys
!> (add_scene_keys), with the key `precision` (add_row_keys), and a
!> survey's settings of every run (add_run_keys, set_run_keys).
!>
!> Programs only: the library reports errors by status or `error_t`, a
!> program decides to stop, and these are the procedures it stops with.
module sphere_row_study_cli
    use sphere_row, only: qp, scene_t, status_normal
    use sphere_row_cli, only: cli_t, read_command_line, fail_with => fail
    use sphere_row_scene_keys, only: scene_from_cli, add_scene_keys
    use sphere_row_error, only: error_t, fatal_error, error_output
    use sphere_row_tables, only: discard_tables, report_tables, close_table
    use sphere_row_system, only: text_out_t
    implicit none
    private
    public :: cli_t, add_scene_keys, start_program, read_keys, fail, stop_unless_normal, &
        stop_unless_written, close_tables
    public :: add_row_keys, precision_is_auto, add_run_keys, set_run_keys, say, nl

    !> The line break of a program's `about` text.
    character(len=*), parameter :: nl = new_line("a")

    !> The running program's name, the prefix of its messages.
    character(len=:), allocatable :: program_name
    !> True if the program writes tables, into the directory of key `out`.
    logical :: writes_tables = .true.

    !> Stop with one line on stderr: from a text or from an `error_t`.
    interface fail
        module procedure fail_text
        module procedure fail_error
    end interface fail

contains

    !> Register the keys of a program of many rows of one scene: the key
    !> `precision`, each run made in the precision it needs (auto, the default)
    !> or in real(16) (qp), and the scene keys, e set by `e_set_by`.
    pure subroutine add_row_keys(cli, e_set_by)
        type(cli_t), intent(inout) :: cli
        character(len=*), intent(in) :: e_set_by
        call cli%add_choice("precision", "auto", [character(len=4) :: "auto", "qp"], "auto: " &
            //"real(8) where a rounding certificate holds, else real(16); qp: real(16) for " &
            //"every run")
        call add_scene_keys(cli, e_set_by=e_set_by)
    end subroutine add_row_keys

    !> True for precision = auto, false for qp (the registry took no other).
    logical function precision_is_auto(cli) result(auto)
        type(cli_t), intent(in) :: cli
        auto = cli%get_word("precision") == "auto"
    end function precision_is_auto

    !> Register the keys `cap`, `vtol` and `tol` of a study whose runs take the
    !> engine's default settings unless these are given: one budget and one
    !> pair of tolerances for every run.
    pure subroutine add_run_keys(cli)
        type(cli_t), intent(inout) :: cli
        call cli%add_int("cap", "0", "the work budget of every run in collisions (0: the " &
            //"engine's default, max(10^6, 100 p))", lo=0)
        call cli%add_real("vtol", "-1", "the velocity tolerance of a bounded answer of every " &
            //"run (below 0: the engine's default)", hi=1.0_qp, hi_open=.true.)
        call cli%add_real("tol", "-1", "the insignificance tolerance of every run (below 0: " &
            //"the engine's default, real(16)'s epsilon)", hi=1.0_qp, hi_open=.true.)
    end subroutine add_run_keys

    !> Give `scene` the settings of the keys of add_run_keys.
    subroutine set_run_keys(cli, scene)
        type(cli_t), intent(in) :: cli
        type(scene_t), intent(inout) :: scene
        scene%max_collisions = cli%get_int("cap")
        if (cli%get_real("vtol") >= 0) scene%vtol = cli%get_real("vtol")
        if (cli%get_real("tol") >= 0) scene%tol = cli%get_real("tol")
    end subroutine set_run_keys

    !> Start the command line of program `name`: `about` is the paragraph of
    !> its `--help` (lines separated by new_line), and the key `out` names the
    !> directory of its tables unless `tables` is false.
    subroutine start_program(cli, name, about, tables)
        type(cli_t), intent(out) :: cli
        character(len=*), intent(in) :: name, about
        logical, intent(in), optional :: tables
        program_name = name
        cli%name = name
        cli%about = about
        writes_tables = .true.
        if (present(tables)) writes_tables = tables
        if (writes_tables) call cli%add_word("out", "results", &
            "directory of the tables (made if missing); each table is told on stdout as " &
            //"it is written")
        if (writes_tables) call report_tables(name)
    end subroutine start_program

    !> Read the command line into the keys registered: `--help` prints the
    !> usage made from them and stops, bad input fails. With `scene`, the
    !> scene of the scene keys. The output directory must not be empty and
    !> holds no quote, since it is handed to the shell to be made.
    subroutine read_keys(cli, scene)
        type(cli_t), intent(inout) :: cli
        type(scene_t), intent(out), optional :: scene
        type(error_t), allocatable :: error
        character(len=:), allocatable :: out
        if (cli%files) then
            cli%synopsis = "[FILE] [key=value ...]"
        else
            cli%synopsis = "[key=value ...]"
        end if
        call read_command_line(cli)
        if (writes_tables) then
            out = cli%get_word("out")
            if (scan(out, "'""") > 0) call fatal_error(error, "out = "//out &
                //": allowed a directory name without quotes")
        end if
        if (.not. allocated(error) .and. present(scene)) call scene_from_cli(cli, scene, error)
        if (allocated(error)) call fail_error(error)
    end subroutine read_keys

    !> One line on stderr, `program: text`, and exit status 2.
    subroutine fail_text(text)
        character(len=*), intent(in) :: text
        type(error_t), allocatable :: error
        call fatal_error(error, trim(text))
        call fail_error(error)
    end subroutine fail_text

    !> One line on stderr, `program: message`, and exit status 2 (1 if the
    !> program's output could not be written); no table being written is
    !> left behind.
    subroutine fail_error(error)
        type(error_t), intent(in) :: error
        if (.not. allocated(program_name)) program_name = "c12"
        call discard_tables()
        call fail_with(program_name, error)
    end subroutine fail_error

    !> One line on stdout (a program's report of what it did), written at
    !> once and checked: a line that cannot be written fails the program.
    subroutine say(line)
        character(len=*), intent(in) :: line
        type(text_out_t) :: out
        type(error_t), allocatable :: error
        call out%put(line)
        call out%finish(error)
        if (allocated(error)) call fail_error(error)
    end subroutine say

    !> fail(msg) unless `stat` is status_normal.
    subroutine stop_unless_normal(stat, msg)
        integer, intent(in) :: stat
        character(len=*), intent(in) :: msg
        if (stat /= status_normal) call fail_text(msg)
    end subroutine stop_unless_normal

    !> Fail with exit status 1 unless `stat` is status_normal: for a table
    !> that could not be written (close_table), not for bad input.
    subroutine stop_unless_written(stat, msg)
        integer, intent(in) :: stat
        character(len=*), intent(in) :: msg
        type(error_t), allocatable :: error
        if (stat == status_normal) return
        call fatal_error(error, trim(msg), error_output)
        call fail_error(error)
    end subroutine stop_unless_written

    !> Close the tables of `units` in order (close_table), each given its
    !> name; the first that did not reach the disk stops the program with its
    !> message, as stop_unless_written does, the ones after it left unnamed.
    subroutine close_tables(units)
        integer, intent(in) :: units(:)
        integer :: i, stat
        character(len=1000) :: msg
        do i = 1, size(units)
            call close_table(units(i), stat, msg)
            call stop_unless_written(stat, msg)
        end do
    end subroutine close_tables

end module sphere_row_study_cli
