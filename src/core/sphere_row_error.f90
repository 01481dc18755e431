!> Errors of input and I/O, as objects handed back to the caller.
!>
!> A procedure that can fail takes `type(error_t), allocatable, intent(out) :: error`
!> and leaves it unallocated on success. The message is allocatable, so it is
!> never cut; it names the input at fault, its value and what is allowed. What
!> to do with an error (stop, print, retry) is the caller's decision: only
!> programs stop.
module sphere_row_error
    implicit none
    private
    public :: error_t, fatal_error, error_input, error_io, error_output

    !> Code of an error in what the user gave: a key, a value, a file's content.
    integer, parameter :: error_input = 1
    !> Code of an error reading or writing a file.
    integer, parameter :: error_io = 2
    !> Code of a failed write of a program's output (a full disk, a closed
    !> stdout): programs stop with exit status 1 rather than 2, the status of
    !> refused input.
    integer, parameter :: error_output = 3

    !> Why something could not be done.
    type :: error_t
        !> error_input, error_io or error_output.
        integer :: code = error_input
        !> One line, complete: the input at fault, its value, what is allowed.
        character(len=:), allocatable :: message
    end type error_t

contains

    !> Allocate `error` with `message` (and `code`, error_input if absent).
    pure subroutine fatal_error(error, message, code)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in) :: message
        integer, intent(in), optional :: code
        allocate (error)
        error%message = message
        if (present(code)) error%code = code
    end subroutine fatal_error

end module sphere_row_error
