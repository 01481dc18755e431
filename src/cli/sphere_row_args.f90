!> The command line's arguments as strings of their own lengths, the
!> refusal of a key or a list split by blanks (check_split), and the edit
!> distance by which an unknown key finds the nearest known one.
module sphere_row_args
    use sphere_row_format, only: itoa
    use sphere_row_error, only: error_t, fatal_error
    use sphere_row_read, only: printable
    implicit none
    private
    public :: string_t, check_split, edit_distance

    !> A string of its own length (command-line arguments keep trailing blanks).
    type :: string_t
        !> The text.
        character(len=:), allocatable :: s
    end type string_t

contains

    !> Refuse `key = value` written with blanks around `=`: the shell hands
    !> it over as two or three arguments (`e`, `=`, `0.5`), of which the
    !> bare key would be read as a scene file, so the refusal says what the
    !> blanks did and the one argument meant. So too a list written with
    !> blanks after or before its commas (`masses=1, 2, 3, 4`: `masses=1,`,
    !> `2,`, `3,`, `4`), which would be refused as an empty value 2.
    subroutine check_split(args, error)
        type(string_t), intent(in) :: args(:)
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: shown, meant, blanks
        integer :: i, n, last
        logical :: around, listed
        n = size(args)
        do i = 1, n - 1
            ! the arguments i..last are the pieces of one; around: split at '='
            around = .true.
            last = i + 1
            associate (a => args(i)%s, b => args(i + 1)%s)
                if (b == "=" .and. len(b) == 1 .and. index(a, "=") == 0 .and. len(a) > 0) then
                    ! key = value (three arguments), or key = at the end
                    shown = a//" ="
                    meant = a//"="
                    if (i + 2 <= n) then
                        shown = shown//" "//args(i + 2)%s
                        meant = meant//args(i + 2)%s
                        last = i + 2
                    end if
                else if (len(a) > 1 .and. index(a, "=") == len(a) .and. index(b, "=") == 0) then
                    ! key= value
                    shown = a//" "//b
                    meant = a//b
                else if (len(b) > 1 .and. index(b, "=") == 1 .and. index(a, "=") == 0 .and. &
                         len(a) > 0) then
                    ! key =value
                    shown = a//" "//b
                    meant = a//b
                else if (index(a, "=") > 1) then
                    ! key=value, whose list may go on in the next arguments
                    shown = a
                    meant = a
                    around = .false.
                    last = i
                else
                    cycle
                end if
            end associate
            listed = .false.
            do while (last < n)
                if (.not. list_goes_on(meant, args(last + 1)%s)) exit
                shown = shown//" "//args(last + 1)%s
                meant = meant//args(last + 1)%s
                last = last + 1
                listed = .true.
            end do
            if (.not. (around .or. listed)) cycle
            if (around .and. listed) then
                blanks = "the blanks around '=' and in the list"
            else if (around) then
                blanks = "the blanks around '='"
            else
                blanks = "the blanks in the list"
            end if
            call fatal_error(error, "argument '"//printable(shown)//"': "//blanks &
                //" split it into "//itoa(count_words(shown))//" arguments; allowed " &
                //"key=value as one argument: "//printable(meant))
            return
        end do
    contains
        pure integer function count_words(text)
            character(len=*), intent(in) :: text
            integer :: j
            count_words = 1
            do j = 1, len(text)
                if (text(j:j) == " ") count_words = count_words + 1
            end do
        end function count_words

        !> `next` is the rest of the list that `text` (key=value) begins: it
        !> ends in a comma or `next` begins with one, and `next` is an entry
        !> of a list (it begins as a number or a comma and holds no '=').
        pure logical function list_goes_on(text, next)
            character(len=*), intent(in) :: text, next
            list_goes_on = .false.
            if (len(next) == 0 .or. len(text) == 0) return
            if (index(next, "=") > 0 .or. next == "-") return
            if (scan(next(1:1), "0123456789+-.,") == 0) return
            list_goes_on = text(len(text):) == "," .or. next(1:1) == ","
        end function list_goes_on
    end subroutine check_split

    !> The optimal string alignment distance of a and b: letters changed,
    !> left out, added or two neighbours swapped, each counting one.
    pure integer function edit_distance(a, b) result(dist)
        character(len=*), intent(in) :: a, b
        integer :: d(0:len(a), 0:len(b))
        integer :: i, j, cost
        do i = 0, len(a)
            d(i, 0) = i
        end do
        do j = 0, len(b)
            d(0, j) = j
        end do
        do j = 1, len(b)
            do i = 1, len(a)
                cost = merge(0, 1, a(i:i) == b(j:j))
                d(i, j) = min(d(i - 1, j) + 1, d(i, j - 1) + 1, d(i - 1, j - 1) + cost)
                if (i > 1 .and. j > 1) then
                    if (a(i:i) == b(j - 1:j - 1) .and. a(i - 1:i - 1) == b(j:j)) then
                        d(i, j) = min(d(i, j), d(i - 2, j - 2) + 1)
                    end if
                end if
            end do
        end do
        dist = d(len(a), len(b))
    end function edit_distance

end module sphere_row_args
