!> What every study program does with its command line: `--help`, the output
!> directory, and one line on stderr with exit status 2 for bad input.
!>
!> Programs only: the library reports errors by status, a program decides to
!> stop, and these are the procedures it stops with.
module sphere_row_study_cli
    use, intrinsic :: iso_fortran_env, only: error_unit
    use sphere_row, only: status_normal
    use sphere_row_args, only: get_args, take_key, wants_help
    implicit none
    private
    public :: start_program, take_out, fail, stop_unless_normal

    !> The running program's name, the prefix of its messages.
    character(len=:), allocatable :: program_name

    abstract interface
        !> Print the program's usage on stdout.
        subroutine usage_proc()
        end subroutine usage_proc
    end interface

contains

    !> Start program `name`: its arguments, none of them used yet; with
    !> `--help` print `usage` and stop.
    subroutine start_program(name, usage, args, used)
        character(len=*), intent(in) :: name
        procedure(usage_proc) :: usage
        character(len=:), allocatable, intent(out) :: args(:)
        logical, allocatable, intent(out) :: used(:)
        program_name = name
        call get_args(args)
        if (wants_help(args)) then
            call usage()
            stop
        end if
        allocate (used(size(args)), source=.false.)
    end subroutine start_program

    !> The output directory, key `out` (default `results`).
    subroutine take_out(args, used, out)
        character(len=*), intent(in) :: args(:)
        logical, intent(inout) :: used(:)
        character(len=:), allocatable, intent(out) :: out
        character(len=:), allocatable :: text
        logical :: found
        out = "results"
        call take_key(args, used, "out", text, found)
        if (found) out = text
    end subroutine take_out

    !> One line on stderr, `program: text`, and exit status 2.
    subroutine fail(text)
        character(len=*), intent(in) :: text
        if (.not. allocated(program_name)) program_name = "c12"
        write (error_unit, "(a)") program_name//": "//trim(text)
        stop 2, quiet=.true.
    end subroutine fail

    !> fail(msg) unless `stat` is status_normal.
    subroutine stop_unless_normal(stat, msg)
        integer, intent(in) :: stat
        character(len=*), intent(in) :: msg
        if (stat /= status_normal) call fail(msg)
    end subroutine stop_unless_normal

end module sphere_row_study_cli
