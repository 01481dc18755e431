!> The text of `--help`: each key's line with its help and what is allowed,
!> wrapped under a help column, and the rules of the input every program
!> reads. `sphere_row_cli` assembles it from its registry of keys.
module sphere_row_help
    use sphere_row_key, only: key_t
    implicit none
    private
    public :: wrapped, help_width, key_lines, input_rules

    !> Column where the help text of a key starts in `--help`.
    integer, parameter :: help_column = 22
    !> The widest line of `--help`, in columns: it reads in a terminal of 100.
    integer, parameter :: help_width = 100

    character(len=*), parameter :: nl = new_line("a")

contains

    !> Per key: `key=default  help`, then what is allowed, each wrapped
    !> within help_width columns under the help column.
    !> `files`: the program reads scene files, of the keys `file_names`.
    pure function key_lines(keys, files, file_names) result(text)
        type(key_t), intent(in) :: keys(:)
        logical, intent(in) :: files
        character(len=*), intent(in) :: file_names
        character(len=:), allocatable :: text
        character(len=:), allocatable :: head
        integer, parameter :: indent = help_column - 1
        integer :: k
        text = ""
        do k = 1, size(keys)
            associate (key => keys(k))
                head = "  "//key%name//"="//key%shown
                if (len(head) < indent) then
                    head = head//repeat(" ", indent - len(head))
                else
                    head = head//nl//repeat(" ", indent)
                end if
                text = text//head//wrapped(key%help, indent, indent, help_width)//nl &
                    //repeat(" ", indent)//wrapped("allowed "//key%allowed, indent, indent, &
                    help_width)//nl
            end associate
        end do
        if (files) text = text//"  FILE"//repeat(" ", indent - 6) &
            //wrapped("a scene file (- : standard input): a namelist group " &
            //"&scene key = value, ... / of the keys "//file_names//"; keys on the " &
            //"command line override the file's", indent, indent, help_width)//nl
    end function key_lines

    !> `text` broken at its blanks into lines of at most `width` columns: the
    !> first goes on from column `first`, each further one starts after
    !> `indent` blanks (a word longer than a line stays whole).
    pure function wrapped(text, first, indent, width) result(lines)
        character(len=*), intent(in) :: text
        integer, intent(in) :: first, indent, width
        character(len=:), allocatable :: lines
        integer :: start, finish, column
        logical :: fresh
        lines = ""
        column = first
        fresh = .true.
        start = 1
        do
            do while (start <= len(text))
                if (text(start:start) /= " ") exit
                start = start + 1
            end do
            if (start > len(text)) exit
            finish = index(text(start:), " ")
            if (finish == 0) then
                finish = len(text)
            else
                finish = start + finish - 2
            end if
            if (.not. fresh .and. column + 1 + finish - start + 1 > width) then
                lines = lines//nl//repeat(" ", indent)
                column = indent
                fresh = .true.
            end if
            if (.not. fresh) then
                lines = lines//" "
                column = column + 1
            end if
            lines = lines//text(start:finish)
            column = column + finish - start + 1
            fresh = .false.
            start = finish + 2
        end do
    end function wrapped

    !> The rules of the input every program reads, `program` naming it.
    pure function input_rules(program) result(text)
        character(len=*), intent(in) :: program
        character(len=:), allocatable :: text
        text = "Input: each key at most once, as key=value with nothing around the value;" &
            //nl//"numbers in full: an optional sign, digits with an optional '.', an optional" &
            //nl//"exponent e, E, d or D with optional sign and digits (0.25, -3, 1e-5, 2.5d3)," &
            //nl//"0 or of magnitude between the smallest and the largest normal real(16)" &
            //nl//"(3.3621e-4932 and 1.1897e4932); a range is decided on the number as" &
            //" written;" &
            //nl//"integers: an optional sign and digits; lists: comma-separated numbers, no" &
            //" blank." &
            //nl//"Bad input: one line on stderr ("//program//": key = value: allowed ...)," &
            //nl//"exit status 2, nothing on stdout; output that cannot be written: one line" &
            //nl//"on stderr, exit status 1."
    end function input_rules

end module sphere_row_help
