!> Scene files as text: reading one (a regular file, or standard input named
!> `-`), and splitting its namelist group `&scene name = values ... /` into
!> items. What the names and values mean is the key registry's business
!> (`sphere_row_cli`).
!>
!> Everything here takes time linear in the file's length: the file is read
!> in one piece (standard input in blocks, into a buffer that doubles), and
!> every later pass visits each character a bounded number of times, so a
!> list of a million masses reads as fast from a file as from the command
!> line. A device (/dev/zero never ends), a FIFO (opening one without a
!> writer blocks) or a directory is refused before it is opened; so is a file
!> longer than max_file_bytes or holding a control character (a binary file).
module sphere_row_scene_file
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_format, only: itoa
    use sphere_row_error, only: error_t, fatal_error, error_io
    use sphere_row_read, only: printable, lower
    use sphere_row_system, only: path_kind, path_regular, path_directory, path_other, &
        system_error_text, read_some, read_block
    implicit none
    private
    public :: scene_item_t, read_scene_text, scene_items, join_values, file_origin
    public :: max_file_bytes

    !> The longest scene file: two lists of a million numbers of some 40
    !> characters each, with room to spare.
    integer, parameter :: max_file_bytes = 2**28

    !> One item `name = values` of a scene file, as written.
    type :: scene_item_t
        !> The name, in lower case, blanks around it removed.
        character(len=:), allocatable :: name
        !> The values as written, blanks around them removed.
        character(len=:), allocatable :: values
    end type scene_item_t

contains

    !> "file 'path': ", the beginning of every message about a scene file.
    pure function file_origin(path) result(text)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: text
        text = "file '"//printable(path)//"': "
    end function file_origin

    !> The text of the scene file `path` ("-": standard input) as one line:
    !> `!` comments removed, line ends, tabs and carriage returns made blanks.
    subroutine read_scene_text(path, text, error)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: text
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: raw
        if (path == "-" .and. len(path) == 1) then
            call read_stdin(raw, error)
        else
            call read_regular_file(path, raw, error)
        end if
        if (allocated(error)) return
        if (path /= "-") call check_bytes(path, raw, error)
        if (allocated(error)) return
        call blank_comments(raw, text)
    end subroutine read_scene_text

    !> A regular file, whole, in one read.
    subroutine read_regular_file(path, raw, error)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: raw
        type(error_t), allocatable, intent(out) :: error
        character(len=512) :: iomsg
        integer(int64) :: bytes
        integer :: unit, ios, errno
        select case (path_kind(path, errno))
        case (path_regular)
        case (path_directory)
            call refuse("a directory")
            return
        case (path_other)
            call refuse("not a regular file (a device, a FIFO or a socket)")
            return
        case default
            call refuse("cannot be opened ("//system_error_text(errno)//")")
            return
        end select
        open (newunit=unit, file=path, status="old", action="read", access="stream", &
            form="unformatted", iostat=ios, iomsg=iomsg)
        if (ios /= 0) then
            call refuse("cannot be opened ("//trim(iomsg)//")")
            return
        end if
        inquire (unit=unit, size=bytes)
        if (bytes > max_file_bytes) then
            close (unit)
            call refuse("longer than "//itoa(max_file_bytes)//" bytes")
            return
        end if
        allocate (character(len=max(0, int(bytes))) :: raw)
        if (len(raw) > 0) read (unit, iostat=ios, iomsg=iomsg) raw
        close (unit)
        if (ios /= 0) call refuse("cannot be read ("//trim(iomsg)//")")
    contains
        subroutine refuse(reason)
            character(len=*), intent(in) :: reason
            call fatal_error(error, file_origin(path)//reason//"; allowed a readable regular " &
                //"file holding a scene, or - for standard input", error_io)
        end subroutine refuse
    end subroutine read_regular_file

    !> Standard input to its end, in blocks, into a buffer that doubles;
    !> refused as soon as it is longer than max_file_bytes or a block holds a
    !> control byte.
    subroutine read_stdin(raw, error)
        character(len=:), allocatable, intent(out) :: raw
        type(error_t), allocatable, intent(out) :: error
        character(len=read_block) :: block
        character(len=:), allocatable :: grown
        integer :: used, n, errno
        allocate (character(len=read_block) :: raw)
        used = 0
        do
            call read_some(0, block, n, errno)
            if (errno /= 0) then
                call fatal_error(error, file_origin("-")//"cannot be read (" &
                    //system_error_text(errno)//"); allowed a scene on standard input", error_io)
                return
            end if
            if (n == 0) exit
            if (used + n > max_file_bytes) then
                call fatal_error(error, file_origin("-")//"longer than "//itoa(max_file_bytes) &
                    //" bytes; allowed a scene file of at most that length", error_io)
                return
            end if
            call check_bytes("-", block(:n), error, used)
            if (allocated(error)) return
            if (used + n > len(raw)) then
                allocate (character(len=max(2*len(raw), used + n)) :: grown)
                grown(:used) = raw(:used)
                call move_alloc(grown, raw)
            end if
            raw(used + 1:used + n) = block(:n)
            used = used + n
        end do
        raw = raw(:used)
    end subroutine read_stdin

    !> Refuse a text holding a control character other than tab, line feed
    !> and carriage return: a binary file, not a scene.
    pure subroutine check_bytes(path, raw, error, before)
        character(len=*), intent(in) :: path, raw
        type(error_t), allocatable, intent(out) :: error
        !> Bytes of the file before `raw` (default 0).
        integer, intent(in), optional :: before
        integer :: i, c, offset
        offset = 0
        if (present(before)) offset = before
        do i = 1, len(raw)
            c = iachar(raw(i:i))
            if (c >= 32 .and. c /= 127) cycle
            if (c == 9 .or. c == 10 .or. c == 13) cycle
            call fatal_error(error, file_origin(path)//"byte "//itoa(offset + i) &
                //" is the control character "//printable(raw(i:i))//"; allowed a text file " &
                //"(tabs and line ends are the only control characters)")
            return
        end do
    end subroutine check_bytes

    !> The text with `!` comments (to the end of their line), line ends, tabs
    !> and carriage returns made blanks: one line of the same length.
    pure subroutine blank_comments(raw, text)
        character(len=*), intent(in) :: raw
        character(len=:), allocatable, intent(out) :: text
        integer :: i
        logical :: comment
        allocate (character(len=len(raw)) :: text)
        comment = .false.
        do i = 1, len(raw)
            select case (iachar(raw(i:i)))
            case (10)
                comment = .false.
                text(i:i) = " "
            case (9, 13)
                text(i:i) = " "
            case default
                if (raw(i:i) == "!") comment = .true.
                if (comment) then
                    text(i:i) = " "
                else
                    text(i:i) = raw(i:i)
                end if
            end select
        end do
    end subroutine blank_comments

    !> The items of the one group `&scene ... /` of a scene file's text (as
    !> read_scene_text gives it): what precedes the first `=` must be blank
    !> but for a name, nothing but blanks may follow the `/`.
    pure subroutine scene_items(path, text, items, error)
        character(len=*), intent(in) :: path, text
        type(scene_item_t), allocatable, intent(out) :: items(:)
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: where
        integer :: first, last, finish
        where = file_origin(path)
        allocate (items(0))
        first = verify(text, " ")
        if (first == 0) then
            call fatal_error(error, where//"empty; allowed a namelist group &scene ... /")
            return
        end if
        last = scan(text(first:), " ") + first - 1
        if (last < first) last = len(text) + 1
        if (lower(text(first:last - 1)) /= "&scene") then
            call fatal_error(error, where//"begins with '"//printable(text(first:last - 1)) &
                //"'; allowed a namelist group &scene ... /")
            return
        end if
        finish = index(text(last:), "/")
        if (finish == 0) then
            call fatal_error(error, where//"no '/' ends the group &scene; allowed " &
                //"&scene key = value, ... /")
            return
        end if
        finish = finish + last - 1
        if (verify(text(finish + 1:), " ") /= 0) then
            call fatal_error(error, where//"text after the '/' that ends &scene: '" &
                //printable(trim(adjustl(text(finish + 1:))))//"'; allowed only comments")
            return
        end if
        call split_group(where, text(last:finish - 1), items, error)
    end subroutine scene_items

    !> The items `name = values` of a group's body.
    pure subroutine split_group(where, body, items, error)
        character(len=*), intent(in) :: where, body
        type(scene_item_t), allocatable, intent(inout) :: items(:)
        type(error_t), allocatable, intent(out) :: error
        integer :: eq, next_eq, name_start, next_name, value_end, pos, n
        eq = index(body, "=")
        if (eq == 0) then
            if (verify(body, " ,") /= 0) call fatal_error(error, where//"'" &
                //printable(trim(adjustl(body)))//"' in &scene; allowed key = value items")
            return
        end if
        name_start = name_before(body, eq)
        if (verify(body(:name_start - 1), " ") /= 0) then
            call fatal_error(error, where//"'"//printable(trim(adjustl(body(:name_start - 1)))) &
                //"' before the first key; allowed key = value items")
            return
        end if
        n = 0
        pos = eq
        do
            next_eq = index(body(pos + 1:), "=")
            if (next_eq == 0) then
                value_end = len(body)
            else
                next_eq = next_eq + pos
                next_name = name_before(body, next_eq)
                value_end = next_name - 1
            end if
            if (n == size(items)) call grow(items)
            n = n + 1
            items(n)%name = lower(trim(adjustl(body(name_start:pos - 1))))
            items(n)%values = trim(adjustl(body(pos + 1:value_end)))
            if (next_eq == 0) exit
            name_start = next_name
            pos = next_eq
        end do
        items = items(:n)
    end subroutine split_group

    pure subroutine grow(items)
        type(scene_item_t), allocatable, intent(inout) :: items(:)
        type(scene_item_t), allocatable :: more(:)
        allocate (more(max(8, 2*size(items))))
        more(:size(items)) = items
        call move_alloc(more, items)
    end subroutine grow

    !> Start of the name that ends just before the `=` at position eq.
    pure integer function name_before(body, eq) result(start)
        character(len=*), intent(in) :: body
        integer, intent(in) :: eq
        integer :: i
        i = eq - 1
        do while (i >= 1)
            if (body(i:i) /= " ") exit
            i = i - 1
        end do
        do while (i >= 1)
            if (body(i:i) == " " .or. body(i:i) == ",") exit
            i = i - 1
        end do
        start = i + 1
    end function name_before

    !> The values of an item, separated by commas or blanks, joined by commas;
    !> `null` if two commas have no value between them (one trailing comma
    !> separates items and is allowed).
    pure subroutine join_values(values, text, count, null)
        character(len=*), intent(in) :: values
        character(len=:), allocatable, intent(out) :: text
        integer, intent(out) :: count
        logical, intent(out) :: null
        integer :: i, start, used
        logical :: after_comma
        allocate (character(len=len(values)) :: text)
        used = 0
        count = 0
        null = .false.
        after_comma = .true.
        i = 1
        do while (i <= len(values))
            if (values(i:i) == ",") then
                if (after_comma) null = .true.
                after_comma = .true.
                i = i + 1
            else if (values(i:i) == " ") then
                i = i + 1
            else
                start = i
                do while (i <= len(values))
                    if (values(i:i) == "," .or. values(i:i) == " ") exit
                    i = i + 1
                end do
                if (count > 0) then
                    used = used + 1
                    text(used:used) = ","
                end if
                text(used + 1:used + i - start) = values(start:i - 1)
                used = used + i - start
                count = count + 1
                after_comma = .false.
            end if
        end do
        text = text(:used)
    end subroutine join_values

end module sphere_row_scene_file
