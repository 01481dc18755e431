!> What Fortran's own I/O cannot do, through the few system calls of
!> `sphere_row_system.c`: tell a regular file from a device, a FIFO or a
!> directory before opening it (reading /dev/zero never ends, opening a FIFO
!> without a writer blocks), write with every failure reported (gfortran's
!> run-time library drops the error of a failed write, so a full disk or a
!> closed stdout would lose output without a word), rename and remove files.
!>
!> `text_out_t` collects lines for a file descriptor (standard output by
!> default) and writes them a block at a time; the first failure is kept and
!> every later line dropped, so a program checks once, at `finish`. Made by
!> `create`, it writes a file under a temporary name (`path.tmp`) that
!> `commit` renames to `path` once everything is written and `discard`
!> removes, so that a failed run or write never leaves a partial file.
module sphere_row_system
    use, intrinsic :: iso_c_binding, only: c_int, c_long, c_char, c_size_t, c_null_char, &
        c_ptr, c_loc
    use sphere_row_error, only: error_t, fatal_error, error_output
    implicit none
    private
    public :: path_kind, path_missing, path_regular, path_directory, path_other
    public :: rename_file, remove_file, system_error_text, text_out_t, read_some, read_block
    public :: stderr_is_terminal, launcher_rank

    !> Kinds of what a path names (path_kind).
    integer, parameter :: path_missing = 0, path_regular = 1, path_directory = 2, path_other = 3

    !> Bytes collected before a write to the file descriptor.
    integer, parameter :: out_block = 65536
    !> Bytes read_some reads at most.
    integer, parameter :: read_block = 65536

    !> Lines for a file descriptor, written a block at a time, every failure
    !> kept.
    type :: text_out_t
        !> The file descriptor (1: standard output).
        integer(c_int) :: fd = 1_c_int
        !> What the messages call the destination.
        character(len=:), allocatable :: name
        !> Bytes not yet written: the first `used` of `buffer`.
        character(len=:), allocatable :: buffer
        !> How many bytes of `buffer` are in use.
        integer :: used = 0
        !> errno of the first failed write, 0 while none failed.
        integer :: errno = 0
        !> A file made by `create`: its final path and the temporary one
        !> written ("" for standard output); true while the file is open.
        character(len=:), allocatable :: path, temp
        logical :: is_open = .false.
    contains
        !> Create the file `path` (written as path.tmp until `commit`).
        procedure :: create => out_create
        !> Rename the finished file to its path.
        procedure :: commit => out_commit
        !> Close and remove the file (a failed run or write).
        procedure :: discard => out_discard
        !> Append a line (its end added).
        procedure :: put => out_put
        !> Append text as it is (line ends included by the caller).
        procedure :: put_text => out_put_text
        !> Write what is left; an error if any write failed.
        procedure :: finish => out_finish
    end type text_out_t

    ! The C functions take their texts by address: a zero-ended copy made by
    ! c_text, or the buffer of the caller.
    interface
        function c_path_kind(path) result(kind) bind(c, name="sphere_row_path_kind")
            import :: c_int, c_ptr
            type(c_ptr), value :: path
            integer(c_int) :: kind
        end function c_path_kind

        function c_write_all(fd, text, n) result(errno) bind(c, name="sphere_row_write_all")
            import :: c_int, c_ptr, c_size_t
            integer(c_int), value :: fd
            type(c_ptr), value :: text
            integer(c_size_t), value :: n
            integer(c_int) :: errno
        end function c_write_all

        function c_read_some(fd, text, n) result(count) bind(c, name="sphere_row_read_some")
            import :: c_int, c_long, c_ptr, c_size_t
            integer(c_int), value :: fd
            type(c_ptr), value :: text
            integer(c_size_t), value :: n
            integer(c_long) :: count
        end function c_read_some

        function c_create(path) result(fd) bind(c, name="sphere_row_create")
            import :: c_int, c_ptr
            type(c_ptr), value :: path
            integer(c_int) :: fd
        end function c_create

        function c_close(fd) result(errno) bind(c, name="sphere_row_close")
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: errno
        end function c_close

        function c_rename(from, to) result(errno) bind(c, name="sphere_row_rename")
            import :: c_int, c_ptr
            type(c_ptr), value :: from, to
            integer(c_int) :: errno
        end function c_rename

        function c_remove(path) result(errno) bind(c, name="sphere_row_remove")
            import :: c_int, c_ptr
            type(c_ptr), value :: path
            integer(c_int) :: errno
        end function c_remove

        subroutine c_error_text(code, text, n) bind(c, name="sphere_row_error_text")
            import :: c_int, c_ptr, c_size_t
            integer(c_int), value :: code
            type(c_ptr), value :: text
            integer(c_size_t), value :: n
        end subroutine c_error_text

        !> `int isatty(int fd)` of the C library (unistd.h): 1 if fd is a terminal.
        function c_isatty(fd) result(yes) bind(c, name="isatty")
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: yes
        end function c_isatty
    end interface

contains

    !> True if standard error (file descriptor 2) is a terminal: progress
    !> lines of long runs are for a person watching, never for a log.
    logical function stderr_is_terminal()
        stderr_is_terminal = c_isatty(2_c_int) == 1_c_int
    end function stderr_is_terminal

    !> What `path` names: path_regular, path_directory, path_other (a device,
    !> a FIFO, a socket) or path_missing (nothing, or nothing this process
    !> may look at; `errno` says why).
    integer function path_kind(path, errno)
        character(len=*), intent(in) :: path
        integer, intent(out) :: errno
        character(kind=c_char, len=:), allocatable, target :: z
        integer(c_int) :: kind
        z = path//c_null_char
        kind = c_path_kind(c_loc(z))
        errno = 0
        select case (kind)
        case (1)
            path_kind = path_regular
        case (2)
            path_kind = path_directory
        case (3)
            path_kind = path_other
        case default
            path_kind = path_missing
            errno = -int(kind)
        end select
    end function path_kind

    !> Read what file descriptor `fd` (0: standard input) has, up to
    !> read_block bytes: `count` bytes (0 at the end of the input) at the
    !> start of `text`, or `errno` not 0 if the read failed.
    subroutine read_some(fd, text, count, errno)
        integer, intent(in) :: fd
        character(kind=c_char, len=read_block), intent(out), target :: text
        integer, intent(out) :: count, errno
        integer(c_long) :: got
        got = c_read_some(int(fd, c_int), c_loc(text), int(read_block, c_size_t))
        count = int(max(0_c_long, got))
        errno = int(max(0_c_long, -got))
    end subroutine read_some

    !> Rename `from` to `to` (replacing it); 0 or the errno of the failure.
    integer function rename_file(from, to)
        character(len=*), intent(in) :: from, to
        character(kind=c_char, len=:), allocatable, target :: z_from, z_to
        z_from = from//c_null_char
        z_to = to//c_null_char
        rename_file = int(c_rename(c_loc(z_from), c_loc(z_to)))
    end function rename_file

    !> Remove the file `path`; 0 or the errno of the failure.
    integer function remove_file(path)
        character(len=*), intent(in) :: path
        character(kind=c_char, len=:), allocatable, target :: z
        z = path//c_null_char
        remove_file = int(c_remove(c_loc(z)))
    end function remove_file

    !> The system's text of an errno ("No space left on device").
    function system_error_text(errno) result(text)
        integer, intent(in) :: errno
        character(len=:), allocatable :: text
        character(kind=c_char, len=200), target :: buffer
        integer :: zero
        buffer = ""
        call c_error_text(int(errno, c_int), c_loc(buffer), int(len(buffer), c_size_t))
        zero = index(buffer, c_null_char)
        if (zero == 0) zero = len(buffer) + 1
        text = buffer(:zero - 1)
    end function system_error_text

    subroutine out_put(this, line)
        class(text_out_t), intent(inout) :: this
        character(len=*), intent(in) :: line
        call this%put_text(line//new_line("a"))
    end subroutine out_put

    subroutine out_put_text(this, text)
        class(text_out_t), intent(inout) :: this
        character(len=*), intent(in) :: text
        if (.not. allocated(this%buffer)) allocate (character(len=out_block) :: this%buffer)
        if (this%used + len(text) > len(this%buffer)) call write_buffer(this)
        if (len(text) > len(this%buffer)) then
            call write_bytes(this, text)
        else
            this%buffer(this%used + 1:this%used + len(text)) = text
            this%used = this%used + len(text)
        end if
    end subroutine out_put_text

    !> Create the file `path` for writing, under the name path.tmp until
    !> `commit`: `errno` is 0, or the system's reason why it cannot be made
    !> (then nothing was created).
    subroutine out_create(this, path, errno)
        class(text_out_t), intent(inout) :: this
        character(len=*), intent(in) :: path
        integer, intent(out) :: errno
        character(kind=c_char, len=:), allocatable, target :: z
        integer(c_int) :: fd
        this%path = path
        this%temp = path//".tmp"
        this%name = path
        z = this%temp//c_null_char
        fd = c_create(c_loc(z))
        errno = int(max(0_c_int, -fd))
        if (errno /= 0) return
        this%fd = fd
        this%is_open = .true.
    end subroutine out_create

    !> Write the rest (and close a file made by `create`); `error` (code
    !> error_output) names the destination and the system's reason if any
    !> write failed.
    subroutine out_finish(this, error)
        class(text_out_t), intent(inout) :: this
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: name
        integer :: errno
        call write_buffer(this)
        if (this%is_open) then
            this%is_open = .false.
            errno = int(c_close(this%fd))
            if (this%errno == 0) this%errno = errno
        end if
        if (this%errno == 0) return
        name = "standard output"
        if (allocated(this%name)) name = this%name
        call fatal_error(error, "output = "//name//": cannot be written (" &
            //system_error_text(this%errno)//"); allowed a writable output", error_output)
    end subroutine out_finish

    !> Give a finished file its path (rename path.tmp to path); an error, and
    !> the temporary file removed, if the rename fails.
    subroutine out_commit(this, error)
        class(text_out_t), intent(inout) :: this
        type(error_t), allocatable, intent(out) :: error
        integer :: errno
        if (.not. allocated(this%temp)) return
        errno = rename_file(this%temp, this%path)
        if (errno == 0) return
        call this%discard()
        call fatal_error(error, "output = "//this%path//": cannot be written (" &
            //system_error_text(errno)//"); allowed a writable output", error_output)
    end subroutine out_commit

    !> Drop a file made by `create`: close it and remove its temporary name,
    !> so that a run or write that failed leaves nothing behind.
    subroutine out_discard(this)
        class(text_out_t), intent(inout) :: this
        integer :: errno
        if (.not. allocated(this%temp)) return
        if (this%is_open) errno = int(c_close(this%fd))
        this%is_open = .false.
        this%used = 0
        errno = remove_file(this%temp)
    end subroutine out_discard

    subroutine write_buffer(this)
        class(text_out_t), intent(inout) :: this
        if (this%used > 0) call write_bytes(this, this%buffer(:this%used))
        this%used = 0
    end subroutine write_buffer

    subroutine write_bytes(this, text)
        class(text_out_t), intent(inout) :: this
        character(len=*), intent(in) :: text
        character(kind=c_char, len=:), allocatable, target :: copy
        if (this%errno /= 0 .or. len(text) == 0) return
        copy = text
        this%errno = int(c_write_all(this%fd, c_loc(copy), int(len(copy), c_size_t)))
    end subroutine write_bytes

    !> The rank an MPI launcher gave this process (OpenMPI, MPICH/Hydra, PMIx
    !> name it in the environment), 0 if there is none.
    integer function launcher_rank()
        character(len=*), parameter :: names(3) = [character(len=20) :: &
            "OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"]
        character(len=16) :: value
        integer :: i, length, stat, rank
        launcher_rank = 0
        do i = 1, size(names)
            call get_environment_variable(trim(names(i)), value, length, stat)
            if (stat /= 0 .or. length == 0) cycle
            read (value, *, iostat=stat) rank
            if (stat == 0) launcher_rank = rank
            return
        end do
    end function launcher_rank

end module sphere_row_system
