!> Output of the study programs: TSV tables with one header row, and the
!> per-task answer tables that results/answers.tsv and the summary are made of.
module sphere_row_tables
    use sphere_row, only: status_normal, status_invalid
    implicit none
    private
    public :: open_table, write_answer, answer_header, tab, split_tabs, cpu_model, yes_no

    !> The field separator.
    character(len=*), parameter :: tab = achar(9)
    !> Header of every `<task>_answers.tsv`: the answer, an independent
    !> cross-check of it (a closed form, another method) and how both were made.
    character(len=*), parameter :: answer_header = "key"//tab//"value"//tab//"check"//tab &
        //"check_value"//tab//"difference"//tab//"how"

contains

    !> Create directory `dir` if needed and open `dir/name` for writing, with
    !> `header` as its first line. `stat` is status_invalid (and `msg` says
    !> why) if that is impossible.
    subroutine open_table(dir, name, header, unit, stat, msg)
        character(len=*), intent(in) :: dir, name, header
        integer, intent(out) :: unit, stat
        character(len=*), intent(out) :: msg
        integer :: ios
        character(len=200) :: iomsg
        call execute_command_line("mkdir -p '"//dir//"'", exitstat=ios)
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
