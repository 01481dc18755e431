!> Output of the study programs: TSV tables with one header row, and the
!> per-task answer tables that results/answers.tsv and the summary are made of.
module sphere_row_tables
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, status_normal, status_invalid, real_text, int_text, &
        number_text_length, status_text, status_word_length
    implicit none
    private
    public :: open_table, write_answer, answer_header, tab, split_tabs, cpu_model, yes_no
    public :: row_t, write_rows

    !> The field separator.
    character(len=*), parameter :: tab = achar(9)
    !> Header of every `<task>_answers.tsv`: the answer, an independent
    !> cross-check of it (a closed form, another method) and how both were made.
    character(len=*), parameter :: answer_header = "key"//tab//"value"//tab//"check"//tab &
        //"check_value"//tab//"difference"//tab//"how"

    !> One row of a table, built field by field (tab-separated) where OpenMP
    !> threads build rows at once: numbers and words are written into
    !> buffers of fixed length by real_text, int_text and status_text and
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
        character(len=status_word_length) :: text
        integer :: length
        call status_text(status, text, length)
        call row%add_text(text(:length))
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
    !> `header` as its first line. `stat` is status_invalid (and `msg` says
    !> why) if that is impossible. The shell that makes the directory is
    !> started only where it is missing (a shell costs milliseconds).
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
        open (newunit=unit, file=dir//"/"//name, status="replace", action="write", &
            iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            msg = "out = "//dir//": cannot write "//name//" ("//trim(iomsg)//")"
            return
        end if
        write (unit, "(a)") header
        stat = status_normal
        msg = ""
    end subroutine open_table

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

end module sphere_row_tables
