!> Output of the study programs: TSV tables with one header row, and the
!> per-task answer tables that results/answers.tsv and the summary are made of.
!>
!> A table is written under a temporary name (`name.tmp` beside it) and
!> renamed when it is complete: a program that fails, or a disk that fills,
!> leaves the previous table or none, never a partial one. gfortran's run-time
!> library does not report a write that fails, so `close_table` compares the
!> bytes written with the size of the file on disk. A program that called
!> `report_tables` says on stdout where each table went, as it gets its name.
module sphere_row_tables
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, status_normal, status_invalid, real_text, int_text, &
        number_text_length, status_words
    use sphere_row_system, only: rename_file, remove_file, system_error_text, text_out_t
    use sphere_row_error, only: error_t
    implicit none
    private
    public :: open_table, close_table, discard_tables, write_answer, answer_header, tab, &
        split_tabs, cpu_model, yes_no, report_tables, file_exists
    public :: row_t, write_rows

    !> The field separator.
    character(len=*), parameter :: tab = achar(9)
    !> Header of every `<task>_answers.tsv`: the answer, an independent
    !> cross-check of it (a closed form, another method) and how both were made.
    character(len=*), parameter :: answer_header = "key"//tab//"value"//tab//"check"//tab &
        //"check_value"//tab//"difference"//tab//"how"

    !> A table being written: its unit and the name it gets when complete.
    type :: open_table_t
        integer :: unit = -1
        character(len=:), allocatable :: dir, name
    end type open_table_t

    !> The tables open now.
    type(open_table_t), allocatable :: open_tables(:)
    !> The program that reports each table it wrote (unset: no report).
    character(len=:), allocatable :: reporter

    !> One row of a table, built field by field (tab-separated) where OpenMP
    !> threads build rows at once: numbers are written into buffers of fixed
    !> length by real_text and int_text, words trimmed from status_words, and
    !> appended, never made by a character function of deferred length
    !> (gfortran 12 keeps the length of such a result in a static variable of
    !> the caller, which two threads then share).
    type :: row_t
        !> The fields so far, without the line's end.
        character(len=:), allocatable :: text
    contains
        procedure, private :: add_text => row_add_text
        procedure, private :: add_real => row_add_real
        procedure, private :: add_int => row_add_int
        procedure, private :: add_int64 => row_add_int64
        !> Append a field: a text, a real(16) with every significant digit
        !> (or `digits` of them, as real_str writes it), an integer.
        generic :: add => add_text, add_real, add_int, add_int64
        !> Append the word of a status code (status_word) as a field.
        procedure :: add_status => row_add_status
    end type row_t

contains

    !> Append `field` to the row, after a tab unless it is the first.
    pure subroutine row_add_text(row, field)
        class(row_t), intent(inout) :: row
        character(len=*), intent(in) :: field
        if (allocated(row%text)) then
            row%text = row%text//tab//field
        else
            row%text = field
        end if
    end subroutine row_add_text

    !> Append x with `digits` significant digits (default every one of
    !> real(16), as str writes it).
    pure subroutine row_add_real(row, x, digits)
        class(row_t), intent(inout) :: row
        real(qp), intent(in) :: x
        integer, intent(in), optional :: digits
        character(len=number_text_length) :: text
        integer :: length
        if (present(digits)) then
            call real_text(x, digits, text, length)
        else
            call real_text(x, precision(x) + 1, text, length)
        end if
        call row%add_text(text(:length))
    end subroutine row_add_real

    !> Append a default integer.
    pure subroutine row_add_int(row, i)
        class(row_t), intent(inout) :: row
        integer, intent(in) :: i
        call row%add_int64(int(i, int64))
    end subroutine row_add_int

    !> Append a 64-bit integer.
    pure subroutine row_add_int64(row, i)
        class(row_t), intent(inout) :: row
        integer(int64), intent(in) :: i
        character(len=number_text_length) :: text
        integer :: length
        call int_text(i, text, length)
        call row%add_text(text(:length))
    end subroutine row_add_int64

    !> Append the word of a status code.
    pure subroutine row_add_status(row, status)
        class(row_t), intent(inout) :: row
        integer, intent(in) :: status
        if (status < lbound(status_words, 1) .or. status > ubound(status_words, 1)) then
            call row%add_text("unknown")
        else
            call row%add_text(trim(status_words(status)))
        end if
    end subroutine row_add_status

    !> The rows' texts, one line each and in order, onto the formatted `unit`:
    !> a block of rows is joined by line ends into one record, so the file
    !> gets the same bytes in a fraction of the write statements (each costs
    !> about as much as a row of 300 characters).
    subroutine write_rows(unit, rows)
        integer, intent(in) :: unit
        type(row_t), intent(in) :: rows(:)
        !> Rows per record.
        integer, parameter :: block = 64
        character(len=:), allocatable :: joined
        integer :: first, j, length, at
        do first = 1, size(rows), block
            length = 0
            do j = first, min(size(rows), first + block - 1)
                length = length + len(rows(j)%text) + 1
            end do
            if (allocated(joined)) deallocate (joined)
            allocate (character(len=length - 1) :: joined)
            at = 0
            do j = first, min(size(rows), first + block - 1)
                if (at > 0) then
                    at = at + 1
                    joined(at:at) = new_line("a")
                end if
                joined(at + 1:at + len(rows(j)%text)) = rows(j)%text
                at = at + len(rows(j)%text)
            end do
            write (unit, "(a)") joined
        end do
    end subroutine write_rows

    !> Create directory `dir` if needed and open `dir/name` for writing, with
    !> `header` as its first line (none if it is ""); the table is `dir/name.tmp` until
    !> close_table. `stat` is status_invalid (and `msg` says why) if that is
    !> impossible. The shell that makes the directory is started only where
    !> it is missing (a shell costs milliseconds).
    subroutine open_table(dir, name, header, unit, stat, msg)
        character(len=*), intent(in) :: dir, name, header
        integer, intent(out) :: unit, stat
        character(len=*), intent(out) :: msg
        integer :: ios
        character(len=200) :: iomsg
        logical :: there
        inquire (file=dir//"/.", exist=there)
        if (.not. there) call execute_command_line("mkdir -p '"//dir//"'", exitstat=ios)
        stat = status_invalid
        open (newunit=unit, file=dir//"/"//name//".tmp", status="replace", action="write", &
            access="stream", form="formatted", iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            msg = "out = "//dir//": cannot write "//name//" ("//trim(iomsg)//")"
            return
        end if
        if (.not. allocated(open_tables)) allocate (open_tables(0))
        open_tables = [open_tables, open_table_t(unit, dir, name)]
        if (len(header) > 0) write (unit, "(a)") header
        stat = status_normal
        msg = ""
    end subroutine open_table

    !> Close a table that open_table opened and give it its name; `stat` is
    !> status_invalid (and `msg` says why) if any write did not reach the
    !> disk, and then the table is removed.
    subroutine close_table(unit, stat, msg)
        integer, intent(in) :: unit
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        integer :: k, ios, errno
        integer(int64) :: pos, bytes
        character(len=:), allocatable :: path
        type(text_out_t) :: out
        type(error_t), allocatable :: error
        stat = status_invalid
        k = table_index(unit)
        if (k == 0) then
            msg = "close_table: unit "//int_str(unit)//" is not a table of open_table"
            return
        end if
        path = open_tables(k)%dir//"/"//open_tables(k)%name
        inquire (unit=unit, pos=pos)
        close (unit, iostat=ios)
        inquire (file=path//".tmp", size=bytes)
        open_tables = [open_tables(:k - 1), open_tables(k + 1:)]
        if (ios /= 0 .or. bytes /= pos - 1) then
            errno = remove_file(path//".tmp")
            msg = "out = "//path//": cannot be written (only "//int_str(bytes)//" of " &
                //int_str(pos - 1)//" bytes reached the disk); allowed a directory with room"
            return
        end if
        errno = rename_file(path//".tmp", path)
        if (errno /= 0) then
            msg = "out = "//path//": cannot be written ("//system_error_text(errno) &
                //"); allowed a writable directory"
            errno = remove_file(path//".tmp")
            return
        end if
        if (allocated(reporter)) then
            call out%put(reporter//": wrote "//path)
            call out%finish(error)
            if (allocated(error)) then
                msg = error%message
                return
            end if
        end if
        stat = status_normal
        msg = ""
    end subroutine close_table

    !> From now on, every table that gets its name is told on stdout as
    !> `program: wrote dir/name` (the directory as the key `out` gave it).
    subroutine report_tables(program)
        character(len=*), intent(in) :: program
        reporter = program
    end subroutine report_tables

    !> Close and remove every table still being written (a program that
    !> stops on an error leaves none behind).
    subroutine discard_tables()
        integer :: k, ios, errno
        if (.not. allocated(open_tables)) return
        do k = 1, size(open_tables)
            close (open_tables(k)%unit, status="delete", iostat=ios)
            if (ios /= 0) errno = remove_file(open_tables(k)%dir//"/"//open_tables(k)%name//".tmp")
        end do
        deallocate (open_tables)
    end subroutine discard_tables

    integer function table_index(unit)
        integer, intent(in) :: unit
        integer :: k
        table_index = 0
        if (.not. allocated(open_tables)) return
        do k = 1, size(open_tables)
            if (open_tables(k)%unit == unit) table_index = k
        end do
    end function table_index

    function int_str(i) result(text)
        class(*), intent(in) :: i
        character(len=:), allocatable :: text
        character(len=number_text_length) :: buf
        integer :: length
        select type (i)
        type is (integer)
            call int_text(int(i, int64), buf, length)
        type is (integer(int64))
            call int_text(i, buf, length)
        class default
            buf = "?"
            length = 1
        end select
        text = buf(:length)
    end function int_str

    !> One row of an answer table; numbers come already as text with all
    !> their digits, '-' where there is no cross-check.
    subroutine write_answer(unit, key, value, check, check_value, difference, how)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: key, value, check, check_value, difference, how
        write (unit, "(a)") key//tab//value//tab//check//tab//check_value//tab//difference &
            //tab//how
    end subroutine write_answer

    !> The tab-separated fields of `line` (trailing blanks of `line` ignored).
    pure subroutine split_tabs(line, fields)
        character(len=*), intent(in) :: line
        character(len=:), allocatable, intent(out) :: fields(:)
        integer :: n, i, start, k
        n = 1
        do i = 1, len_trim(line)
            if (line(i:i) == tab) n = n + 1
        end do
        allocate (character(len=max(1, len_trim(line))) :: fields(n))
        start = 1
        k = 0
        do i = 1, len_trim(line) + 1
            if (i > len_trim(line)) then
                k = k + 1
                fields(k) = line(start:len_trim(line))
            else if (line(i:i) == tab) then
                k = k + 1
                fields(k) = line(start:i - 1)
                start = i + 1
            end if
        end do
    end subroutine split_tabs

    !> The CPU model named in /proc/cpuinfo ("unknown" where there is none),
    !> to describe the machine beside timings.
    function cpu_model() result(model)
        character(len=:), allocatable :: model
        character(len=512) :: line
        integer :: unit, ios
        model = "unknown"
        open (newunit=unit, file="/proc/cpuinfo", status="old", action="read", iostat=ios)
        if (ios /= 0) return
        do
            read (unit, "(a)", iostat=ios) line
            if (ios /= 0) exit
            if (index(line, "model name") == 1) then
                model = trim(adjustl(line(index(line, ":") + 1:)))
                exit
            end if
        end do
        close (unit)
    end function cpu_model

    !> "yes" or "no", a flag as a table writes it.
    pure function yes_no(flag) result(word)
        logical, intent(in) :: flag
        character(len=:), allocatable :: word
        if (flag) then
            word = "yes"
        else
            word = "no"
        end if
    end function yes_no

    !> True when a file (or directory) `path` exists.
    logical function file_exists(path)
        character(len=*), intent(in) :: path
        inquire (file=path, exist=file_exists)
    end function file_exists

end module sphere_row_tables
