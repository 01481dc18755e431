!> Whether a program talks to a terminal: progress lines of long runs are
!> written to stderr only when a person watches it, never into a log.
module sphere_row_terminal
    use, intrinsic :: iso_c_binding, only: c_int
    implicit none
    private
    public :: stderr_is_terminal

    !> File descriptor of the standard error stream (POSIX).
    integer(c_int), parameter :: stderr_fd = 2_c_int

    interface
        !> `int isatty(int fd)` of the C library (unistd.h): 1 if fd is a terminal.
        function c_isatty(fd) bind(C, name="isatty") result(yes)
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: yes
        end function c_isatty
    end interface

contains

    !> True if the standard error stream is a terminal.
    logical function stderr_is_terminal()
        stderr_is_terminal = c_isatty(stderr_fd) == 1_c_int
    end function stderr_is_terminal

end module sphere_row_terminal
