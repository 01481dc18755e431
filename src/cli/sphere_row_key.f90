!> One key of a program's command line: what it takes (an integer, a real, a
!> list of reals, yes or no, one word of a fixed set, a list of words of a
!> fixed set, any word, yes or no or the name of a table file), its allowed
!> range, and its value read from the text as given and checked.
!>
!> A range is decided on the number as written, not on its rounding to
!> real(16): `e=1.00000000000000000000000000000000001` is above 1 and
!> refused, `tol=0.99999999999999999999999999999999999999` is below 1 and
!> taken, as the real(16) next below 1 (its rounding, 1, is not allowed).
module sphere_row_key
    use sphere_row_kinds, only: qp
    use sphere_row_format, only: itoa, short_text
    use sphere_row_error, only: error_t, fatal_error
    use sphere_row_read, only: read_real, read_int, read_reals, printable, has_control, &
        compare_decimal
    implicit none
    private
    public :: key_t, new_key, set_range, range_text, read_value, origin, same_text
    public :: key_int, key_real, key_reals, key_flag, key_word, key_choice, key_table, &
        key_choices
    public :: table_suffix

    !> Kinds of value a key takes (key_table: yes, no, or the name of a file
    !> ending in table_suffix; key_choices: a comma-separated list of words
    !> of a fixed set, each once, or one word that names them all).
    integer, parameter :: key_int = 1, key_real = 2, key_reals = 3, key_flag = 4, key_word = 5, &
        key_choice = 6, key_table = 7, key_choices = 8

    !> How the name of a table file given to a key_table ends: a word
    !> mistyped (`Yes`) is refused rather than taken for a file name.
    character(len=*), parameter :: table_suffix = ".tsv"

    !> One key of a program: what it takes and, after parsing, its value.
    type :: key_t
        !> The key as typed before `=`.
        character(len=:), allocatable :: name
        !> key_int, key_real, key_reals, key_flag, key_word, key_choice, key_table
        !> or key_choices.
        integer :: kind = key_real
        !> Text read as the value when the key is not given ("" : no value).
        character(len=:), allocatable :: default
        !> How `--help` shows the value after `name=` (usually the default).
        character(len=:), allocatable :: shown
        !> What is allowed, as messages and `--help` say it.
        character(len=:), allocatable :: allowed
        !> One line of `--help`.
        character(len=:), allocatable :: help
        !> A key that this one overrides: giving both is refused ("" : none).
        character(len=:), allocatable :: overrides
        !> The words a key_choice takes, each between commas: ",qp,dp,auto,"
        !> (a key_choices: the words of its list).
        character(len=:), allocatable :: choices
        !> The word that names every word of a key_choices' set ("": none).
        character(len=:), allocatable :: every
        !> True if a scene file may set the key.
        logical :: in_file = .false.
        !> Range of a number (of every entry of a list): lo <= x <= hi, with
        !> strict inequalities where the side is open; the bounds as the
        !> messages write them, which is what the texts are compared with.
        real(qp) :: lo = 0.0_qp, hi = 0.0_qp
        character(len=:), allocatable :: lo_text, hi_text
        logical :: has_lo = .false., has_hi = .false., lo_open = .false., hi_open = .false.
        !> Range of an integer.
        integer :: ilo = -huge(1), ihi = huge(1)
        !> True once the user gave the key.
        logical :: given = .false.
        !> Where the value came from: "" (command line) or the scene file's path.
        character(len=:), allocatable :: source
        !> The value as text, as given (or the default).
        character(len=:), allocatable :: text
        !> The value, in the member of its kind.
        integer :: n = 0
        real(qp) :: x = 0.0_qp
        real(qp), allocatable :: xs(:)
        logical :: flag = .false.
    end type key_t

contains

    !> A key without a range.
    pure subroutine new_key(key, name, kind, default, help, in_file)
        type(key_t), intent(out) :: key
        character(len=*), intent(in) :: name, default, help
        integer, intent(in) :: kind
        logical, intent(in), optional :: in_file
        key%name = name
        key%kind = kind
        key%default = default
        key%shown = default
        key%help = help
        key%overrides = ""
        key%choices = ""
        key%every = ""
        key%source = ""
        key%text = ""
        if (present(in_file)) key%in_file = in_file
    end subroutine new_key

    !> The range of a real key (of each entry of a list key).
    pure subroutine set_range(key, lo, hi, lo_open, hi_open)
        type(key_t), intent(inout) :: key
        real(qp), intent(in), optional :: lo, hi
        logical, intent(in), optional :: lo_open, hi_open
        key%has_lo = present(lo)
        key%has_hi = present(hi)
        if (present(lo)) then
            key%lo = lo
            key%lo_text = short_text(lo)
        end if
        if (present(hi)) then
            key%hi = hi
            key%hi_text = short_text(hi)
        end if
        if (present(lo_open)) key%lo_open = lo_open
        if (present(hi_open)) key%hi_open = hi_open
    end subroutine set_range

    !> "lo <= name <= hi" and its one-sided forms, from a key's range.
    pure function range_text(key, name) result(text)
        type(key_t), intent(in) :: key
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        character(len=*), parameter :: le(2) = ["<=", "< "], ge(2) = [">=", "> "]
        if (key%has_lo .and. key%has_hi) then
            text = key%lo_text//" "//trim(le(merge(2, 1, key%lo_open)))//" "//name &
                //" "//trim(le(merge(2, 1, key%hi_open)))//" "//key%hi_text
        else if (key%has_lo) then
            text = name//" "//trim(ge(merge(2, 1, key%lo_open)))//" "//key%lo_text
        else if (key%has_hi) then
            text = name//" "//trim(le(merge(2, 1, key%hi_open)))//" "//key%hi_text
        else
            text = "a finite number"
        end if
    end function range_text

    !> "file 'path': " for a value from a scene file, "" for the command line.
    pure function origin(key) result(text)
        type(key_t), intent(in) :: key
        character(len=:), allocatable :: text
        text = ""
        if (len(key%source) > 0) text = "file '"//printable(key%source)//"': "
    end function origin

    !> True if a and b are the same text, of the same length (Fortran's `==`
    !> pads the shorter with blanks: "yes " == "yes").
    pure logical function same_text(a, b)
        character(len=*), intent(in) :: a, b
        same_text = len(a) == len(b)
        if (same_text) same_text = a == b
    end function same_text

    !> Read key%text as the key's value and check its range; `where` prefixes
    !> the message (the scene file a value came from).
    pure subroutine read_value(key, where, error)
        type(key_t), intent(inout) :: key
        character(len=*), intent(in) :: where
        type(error_t), allocatable, intent(out) :: error
        select case (key%kind)
        case (key_int)
            call read_int(key%name, key%text, key%n, error, key%allowed)
            if (.not. allocated(error) .and. (key%n < key%ilo .or. key%n > key%ihi)) then
                call refuse(key, "", error)
            end if
        case (key_real)
            call read_real(key%name, key%text, key%x, error, key%allowed)
            if (.not. allocated(error)) call check_real(key, key%text, "", key%x, error)
        case (key_reals)
            call read_reals(key%name, key%text, key%xs, error, key%allowed)
            if (.not. allocated(error)) call check_list(key, error)
        case (key_flag)
            key%flag = same_text(key%text, "yes")
            if (.not. key%flag .and. .not. same_text(key%text, "no")) call refuse(key, "", error)
        case (key_choice)
            if (index(key%text, ",") > 0 .or. index(key%choices, ","//key%text//",") == 0) then
                call refuse(key, "", error)
            end if
        case (key_choices)
            call check_choices(key, error)
        case (key_table)
            key%flag = same_text(key%text, "yes")
            if (key%flag .or. same_text(key%text, "no")) return
            if (.not. is_word(key%text) .or. len(key%text) <= len(table_suffix)) then
                call refuse(key, "", error)
            else if (key%text(len(key%text) - len(table_suffix) + 1:) /= table_suffix) then
                call refuse(key, "", error)
            end if
        case default
            if (.not. is_word(key%text)) call refuse(key, "", error)
        end select
        if (allocated(error)) error%message = where//error%message
    end subroutine read_value

    !> A key_choices' list: its `every` word alone, or words of its set
    !> separated by commas, none empty, none twice (the refusal names the
    !> first entry at fault by its place).
    pure subroutine check_choices(key, error)
        type(key_t), intent(in) :: key
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: item, seen
        integer :: j, start, finish
        if (len(key%every) > 0 .and. same_text(key%text, key%every)) return
        seen = ","
        start = 1
        j = 0
        do while (start <= len(key%text) + 1)
            j = j + 1
            finish = index(key%text(start:), ",")
            if (finish == 0) then
                finish = len(key%text) + 1
            else
                finish = start + finish - 1
            end if
            item = key%text(start:finish - 1)
            if (len(item) == 0) then
                call refuse(key, "value "//itoa(j)//" is empty; ", error)
            else if (index(key%choices, ","//item//",") == 0) then
                call refuse(key, "value "//itoa(j)//" = "//printable(item)//": not one of " &
                    //"the names; ", error)
            else if (index(seen, ","//item//",") > 0) then
                call refuse(key, "value "//itoa(j)//" = "//item//": named twice; ", error)
            end if
            if (allocated(error)) return
            seen = seen//item//","
            start = finish + 1
        end do
    end subroutine check_choices

    !> A word: printable text, no blank at either end.
    pure logical function is_word(text)
        character(len=*), intent(in) :: text
        is_word = .false.
        if (len(text) == 0 .or. has_control(text)) return
        is_word = text(1:1) /= " " .and. text(len(text):) /= " "
    end function is_word

    !> The message `key = value: [reason; ]allowed ...`.
    pure subroutine refuse(key, reason, error)
        type(key_t), intent(in) :: key
        character(len=*), intent(in) :: reason
        type(error_t), allocatable, intent(out) :: error
        call fatal_error(error, key%name//" = "//printable(key%text)//": "//reason &
            //"allowed "//key%allowed)
    end subroutine refuse

    !> The range of a real written `text`, read as x; x is moved off an open
    !> bound that only its rounding reached.
    pure subroutine check_real(key, text, reason, x, error)
        type(key_t), intent(in) :: key
        character(len=*), intent(in) :: text, reason
        real(qp), intent(inout) :: x
        type(error_t), allocatable, intent(out) :: error
        if (.not. text_in_range(key, text)) then
            call refuse(key, reason, error)
            return
        end if
        if (key%has_lo .and. key%lo_open) then
            if (x <= key%lo) x = nearest(key%lo, 1.0_qp)
        end if
        if (key%has_hi .and. key%hi_open) then
            if (x >= key%hi) x = nearest(key%hi, -1.0_qp)
        end if
    end subroutine check_real

    !> Each entry of a list in the key's range.
    pure subroutine check_list(key, error)
        type(key_t), intent(inout) :: key
        type(error_t), allocatable, intent(out) :: error
        integer :: i, start, finish
        start = 1
        do i = 1, size(key%xs)
            finish = index(key%text(start:), ",")
            if (finish == 0) then
                finish = len(key%text)
            else
                finish = start + finish - 2
            end if
            call check_real(key, key%text(start:finish), "value "//itoa(i)//" is " &
                //key%text(start:finish)//"; ", key%xs(i), error)
            if (allocated(error)) return
            start = finish + 2
        end do
    end subroutine check_list

    !> True if the number written `text` is in the key's range, decided on
    !> its decimal digits against the bounds as the messages write them.
    pure logical function text_in_range(key, text)
        type(key_t), intent(in) :: key
        character(len=*), intent(in) :: text
        integer :: c
        text_in_range = .true.
        if (key%has_lo) then
            c = compare_decimal(text, key%lo_text)
            text_in_range = c > 0 .or. (c == 0 .and. .not. key%lo_open)
        end if
        if (key%has_hi .and. text_in_range) then
            c = compare_decimal(text, key%hi_text)
            text_in_range = c < 0 .or. (c == 0 .and. .not. key%hi_open)
        end if
    end function text_in_range

end module sphere_row_key
