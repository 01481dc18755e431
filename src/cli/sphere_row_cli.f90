!> The registry of keys of every program: it drives parsing, validation and
!> `--help`, and applies scene files (one `&scene` group of whole keys). One
!> key and the checks of its value are `sphere_row_key`; numbers are read by
!> `sphere_row_read`; scene files are read and split into items by
!> `sphere_row_scene_file`; the scene keys are in `sphere_row_scene_keys`; the
!> text of `--help` is assembled from `sphere_row_help`.
!>
!> A program registers its keys in a `cli_t` (name, kind of value, default,
!> allowed range, help line), calls `read_command_line` and then asks the
!> registry for values. Everything a user can give is checked against that one
!> table: the key must be known and given once, its value must be written as a
!> value of the key's kind (the whole text, nothing more) and lie in the
!> key's range, and two keys of which one overrides the other may not both be
!> given. A refusal is an `error_t` whose message names the key, the value as
!> given and what is allowed; `fail` prints it as one line and stops with
!> exit status 2 (1 for output that could not be written).
!>
!> A program with the scene keys and keys of its own:
!>
!>     type(cli_t) :: cli
!>     type(scene_t) :: scene
!>     type(error_t), allocatable :: error
!>     cli%name = "c12-b2"
!>     cli%synopsis = "[FILE] [key=value ...]"
!>     call add_scene_keys(cli)
!>     call cli%add_word("out", "results", "directory of the tables")
!>     call cli%add_int("n_grid", "801", "values of e on the grid", lo=2)
!>     call read_command_line(cli)
!>     call scene_from_cli(cli, scene, error)
!>     if (allocated(error)) call fail(cli%name, error)
!>     n_grid = cli%get_int("n_grid")
module sphere_row_cli
    use, intrinsic :: iso_fortran_env, only: error_unit
    use sphere_row_kinds, only: qp
    use sphere_row_format, only: itoa
    use sphere_row_error, only: error_t, fatal_error, error_output
    use sphere_row_read, only: printable, lower
    use sphere_row_key, only: key_t, new_key, set_range, range_text, read_value, origin, &
        same_text, key_int, key_real, key_reals, key_flag, key_word, key_choice, key_table, &
        key_choices, table_suffix
    use sphere_row_scene_file, only: scene_item_t, read_scene_text, scene_items, join_values, &
        file_origin
    use sphere_row_system, only: text_out_t, launcher_rank
    use sphere_row_help, only: wrapped, help_width, key_lines, input_rules
    use sphere_row_args, only: string_t, check_split, edit_distance
    implicit none
    private
    public :: cli_t, string_t, read_command_line, fail, command_args, wrapped, help_width
    ! for the modules that register keys of their own kind (sphere_row_scene_keys)
    public :: find_key, key_index, origin

    character(len=*), parameter :: nl = new_line("a")


    !> A program's command line: its keys and the text of its `--help`.
    type :: cli_t
        !> Program name, the first word of every message.
        character(len=:), allocatable :: name
        !> What follows `usage: name` in `--help`.
        character(len=:), allocatable :: synopsis
        !> Paragraph of `--help` before the key list (lines separated by new_line).
        character(len=:), allocatable :: about
        !> Text of `--help` after the input rules (what the program writes).
        character(len=:), allocatable :: epilogue
        !> Registered keys, in the order `--help` lists them.
        type(key_t), allocatable :: keys(:)
        !> True if a bare argument names a scene file (a `&scene` namelist group).
        logical :: files = .false.
        !> True after parse if `--help`, `-h` or `help` was given.
        logical :: help = .false.
        !> The program's version, printed by `--version` (which a program
        !> without one refuses as any other stray argument).
        character(len=:), allocatable :: version
        !> True after parse if `--version` was given to a program with one.
        logical :: show_version = .false.
    contains
        !> Register a key taking an integer.
        procedure :: add_int => cli_add_int
        !> Register a key taking a real.
        procedure :: add_real => cli_add_real
        !> Register a key taking a comma-separated list of reals.
        procedure :: add_reals => cli_add_reals
        !> Register a key taking yes or no.
        procedure :: add_flag => cli_add_flag
        !> Register a key taking a word (a name, a path).
        procedure :: add_word => cli_add_word
        !> Register a key taking one word of a fixed set.
        procedure :: add_choice => cli_add_choice
        !> Register a key taking a list of words of a fixed set.
        procedure :: add_choices => cli_add_choices
        !> Register a key taking yes, no or the name of a table file.
        procedure :: add_table => cli_add_table
        !> Read arguments into the keys' values.
        procedure :: parse => cli_parse
        !> The text of `--help`.
        procedure :: usage => cli_usage
        !> True if the user gave the key.
        procedure :: given => cli_given
        !> The value of an integer key.
        procedure :: get_int => cli_get_int
        !> The value of a real key.
        procedure :: get_real => cli_get_real
        !> The value of a list key (size 0 if unset).
        procedure :: get_reals => cli_get_reals
        !> The value of a flag key.
        procedure :: get_flag => cli_get_flag
        !> The value of a word or choice key.
        procedure :: get_word => cli_get_word
        !> The value of a key as given (or its default), for messages.
        procedure :: get_text => cli_get_text
        !> Names of every key, comma-separated.
        procedure :: key_list => cli_key_list
    end type cli_t

contains

    ! ------------------------------------------------------------------
    ! the program kit: registration
    ! ------------------------------------------------------------------

    !> Register an integer key, allowed in [lo, hi] (bounds optional);
    !> `shown` replaces the default in `--help` (a default of "" is no value).
    pure subroutine cli_add_int(this, name, default, help, lo, hi, in_file, shown)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, default, help
        integer, intent(in), optional :: lo, hi
        logical, intent(in), optional :: in_file
        character(len=*), intent(in), optional :: shown
        type(key_t) :: key
        call new_key(key, name, key_int, default, help, in_file)
        if (present(shown)) key%shown = shown
        if (present(lo)) key%ilo = lo
        if (present(hi)) key%ihi = hi
        if (key%ilo > -huge(1) .and. key%ihi < huge(1)) then
            key%allowed = "an integer "//itoa(key%ilo)//" <= "//name//" <= "//itoa(key%ihi)
        else if (key%ilo > -huge(1)) then
            key%allowed = "an integer "//name//" >= "//itoa(key%ilo)
        else if (key%ihi < huge(1)) then
            key%allowed = "an integer "//name//" <= "//itoa(key%ihi)
        else
            key%allowed = "an integer"
        end if
        call append_key(this, key)
    end subroutine cli_add_int

    !> Register a real key, allowed in the range given by lo and hi (each
    !> optional, each closed unless said open); `allowed` replaces the text
    !> made from the range; `shown` replaces the default in `--help`.
    pure subroutine cli_add_real(this, name, default, help, lo, hi, lo_open, hi_open, allowed, &
        shown, in_file)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, default, help
        real(qp), intent(in), optional :: lo, hi
        logical, intent(in), optional :: lo_open, hi_open, in_file
        character(len=*), intent(in), optional :: allowed, shown
        type(key_t) :: key
        call new_key(key, name, key_real, default, help, in_file)
        call set_range(key, lo, hi, lo_open, hi_open)
        key%allowed = range_text(key, name)
        if (present(allowed)) key%allowed = allowed
        if (present(shown)) key%shown = shown
        call append_key(this, key)
    end subroutine cli_add_real

    !> Register a key taking a comma-separated list of reals, each in the range
    !> given by lo and hi; `shown` is how `--help` shows the list.
    pure subroutine cli_add_reals(this, name, shown, help, lo, hi, lo_open, hi_open, overrides, &
        in_file)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, shown, help
        real(qp), intent(in), optional :: lo, hi
        logical, intent(in), optional :: lo_open, hi_open, in_file
        character(len=*), intent(in), optional :: overrides
        type(key_t) :: key
        call new_key(key, name, key_reals, "", help, in_file)
        call set_range(key, lo, hi, lo_open, hi_open)
        key%allowed = "comma-separated numbers, each "//range_text(key, "value")
        key%shown = shown
        if (present(overrides)) key%overrides = overrides
        call append_key(this, key)
    end subroutine cli_add_reals

    !> Register a key taking `yes` or `no`.
    pure subroutine cli_add_flag(this, name, default, help)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, default, help
        type(key_t) :: key
        call new_key(key, name, key_flag, default, help)
        key%allowed = "yes or no"
        call append_key(this, key)
    end subroutine cli_add_flag

    !> Register a key taking a word: any non-empty text of printable characters
    !> without a blank at either end (a name, a directory).
    pure subroutine cli_add_word(this, name, default, help)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, default, help
        type(key_t) :: key
        call new_key(key, name, key_word, default, help)
        key%allowed = "a non-empty text of printable characters, no blank at either end"
        call append_key(this, key)
    end subroutine cli_add_word

    !> Register a key taking one of the words `choices` (exactly as written).
    pure subroutine cli_add_choice(this, name, default, choices, help)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, default, choices(:), help
        type(key_t) :: key
        integer :: i
        call new_key(key, name, key_choice, default, help)
        key%choices = ","
        key%allowed = ""
        do i = 1, size(choices)
            key%choices = key%choices//trim(choices(i))//","
            if (i > 1) key%allowed = key%allowed//trim(merge(" or", ",  ", i == size(choices))) &
                //" "
            key%allowed = key%allowed//trim(choices(i))
        end do
        call append_key(this, key)
    end subroutine cli_add_choice

    !> Register a key taking a comma-separated list of the words `choices`
    !> (each exactly as written, each at most once), or the word `every`
    !> alone for all of them; get_word gives the text, `every` or the list.
    pure subroutine cli_add_choices(this, name, every, choices, help)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, every, choices(:), help
        type(key_t) :: key
        integer :: i
        call new_key(key, name, key_choices, every, help)
        key%every = every
        key%choices = ","
        key%allowed = every//", or a comma-separated list of these, each once:"
        do i = 1, size(choices)
            key%choices = key%choices//trim(choices(i))//","
            key%allowed = key%allowed//" "//trim(choices(i))//trim(merge(", ", "  ", &
                i < size(choices)))
        end do
        call append_key(this, key)
    end subroutine cli_add_choices

    !> Register a key taking `yes`, `no` or the name of a file ending in
    !> `.tsv` (a table the program writes there instead of on stdout):
    !> get_flag is true for yes, get_word gives the text.
    pure subroutine cli_add_table(this, name, default, help)
        class(cli_t), intent(inout) :: this
        character(len=*), intent(in) :: name, default, help
        type(key_t) :: key
        call new_key(key, name, key_table, default, help)
        key%allowed = "yes, no or the name of a file ending in "//table_suffix
        call append_key(this, key)
    end subroutine cli_add_table

    pure subroutine append_key(cli, key)
        type(cli_t), intent(inout) :: cli
        type(key_t), intent(in) :: key
        type(key_t), allocatable :: keys(:)
        integer :: n
        if (.not. allocated(cli%keys)) allocate (cli%keys(0))
        n = size(cli%keys)
        allocate (keys(n + 1))
        keys(:n) = cli%keys
        keys(n + 1) = key
        call move_alloc(keys, cli%keys)
    end subroutine append_key

    ! ------------------------------------------------------------------
    ! the program kit: parsing
    ! ------------------------------------------------------------------

    !> Read `args` into the keys. A key may be given once; its value must be
    !> of the key's kind and in its range; a key and the key it overrides may
    !> not both be given; keys not given take their defaults. With `files`, a
    !> bare argument names a scene file whose keys the command line overrides.
    !> `--help`, `-h` or `help` only sets `help`. With `used` (one flag per
    !> argument), keys this registry does not know are left for the caller,
    !> their flags false, instead of being refused.
    subroutine cli_parse(this, args, error, used)
        class(cli_t), intent(inout) :: this
        type(string_t), intent(in) :: args(:)
        type(error_t), allocatable, intent(out) :: error
        logical, intent(out), optional :: used(:)
        integer :: i, j, k
        character(len=:), allocatable :: file
        if (.not. allocated(this%keys)) allocate (this%keys(0))
        if (present(used)) used = .false.
        do k = 1, size(this%keys)
            call reset_value(this%keys(k))
        end do
        this%help = .false.
        this%show_version = .false.
        do i = 1, size(args)
            if (is_help(args(i)%s)) this%help = .true.
            if (args(i)%s == "--version" .and. allocated(this%version)) this%show_version = .true.
        end do
        if (this%help .or. this%show_version) return
        call check_split(args, error)
        if (allocated(error)) return
        file = ""
        do i = 1, size(args)
            associate (arg => args(i)%s)
                j = index(arg, "=")
                if (j == 0) then
                    if (present(used) .and. (.not. this%files .or. starts_with_dash(arg))) cycle
                    call bare_argument(this, arg, file, error)
                    if (allocated(error)) return
                else
                    k = find_key(this, arg(:j - 1))
                    if (k == 0 .and. present(used)) cycle
                    call take_argument(this, arg, j, k, error)
                    if (allocated(error)) return
                end if
                if (present(used)) used(i) = .true.
            end associate
        end do
        call check_overrides(this, error)
        if (allocated(error)) return
        do k = 1, size(this%keys)
            associate (key => this%keys(k))
                if (key%given .or. len(key%default) == 0) cycle
                key%text = key%default
                call read_value(key, "", error)
                if (allocated(error)) return
            end associate
        end do
    end subroutine cli_parse

    subroutine reset_value(key)
        type(key_t), intent(inout) :: key
        key%given = .false.
        key%source = ""
        key%text = ""
        key%n = 0
        key%x = 0.0_qp
        key%flag = .false.
        if (allocated(key%xs)) deallocate (key%xs)
    end subroutine reset_value

    !> A bare argument: a scene file if the program takes one (`-`: standard
    !> input), else refused.
    subroutine bare_argument(cli, arg, file, error)
        type(cli_t), intent(inout) :: cli
        character(len=*), intent(in) :: arg
        character(len=:), allocatable, intent(inout) :: file
        type(error_t), allocatable, intent(out) :: error
        if ((starts_with_dash(arg) .and. .not. same_text(arg, "-")) .or. len(arg) == 0 &
            .or. .not. cli%files) then
            call fatal_error(error, "argument '"//printable(arg)//"': allowed " &
                //allowed_arguments(cli))
        else if (len(file) > 0) then
            call fatal_error(error, file_origin(arg)//"a second scene file (the first is '" &
                //printable(file)//"'); allowed one scene file")
        else
            file = arg
            call read_scene_file(cli, arg, error)
        end if
    end subroutine bare_argument

    !> A `key=value` argument (`=` at position j) for key number k (0: unknown).
    subroutine take_argument(cli, arg, j, k, error)
        type(cli_t), intent(inout) :: cli
        character(len=*), intent(in) :: arg
        integer, intent(in) :: j, k
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: name, value
        name = arg(:j - 1)
        value = arg(j + 1:)
        if (j == 1) then
            call fatal_error(error, "argument '"//printable(arg)//"': no key before '='; " &
                //"allowed "//allowed_arguments(cli))
            return
        end if
        if (k == 0) then
            call fatal_error(error, printable(name)//" = "//printable(value) &
                //": unknown key"//did_you_mean(cli, name, .false.)//"; allowed keys: " &
                //cli%key_list())
            return
        end if
        associate (key => cli%keys(k))
            if (key%given .and. len(key%source) == 0) then
                call fatal_error(error, printable(name)//" = "//printable(value)//": " &
                    //name//" is given twice (first "//name//" = "//printable(key%text) &
                    //"); allowed each key once")
                return
            end if
            key%given = .true.
            key%source = ""
            key%text = value
            call read_value(key, "", error)
        end associate
    end subroutine take_argument

    !> " (did you mean NAME?)" for the key of `cli` (only those a file may
    !> set, with `in_file`) nearest to an unknown `name`: the same letters
    !> in another case, or in names of three letters and more one letter
    !> changed, left out, added or two swapped (two such in names of five
    !> and more); "" if none.
    pure function did_you_mean(cli, name, in_file) result(text)
        type(cli_t), intent(in) :: cli
        character(len=*), intent(in) :: name
        logical, intent(in) :: in_file
        character(len=:), allocatable :: text
        integer :: k, best, distance, most
        text = ""
        best = 0
        if (len(name) < 1) return
        ! the largest distance taken; then the nearest key so far
        most = 0
        if (len(name) >= 3) most = 1
        if (len(name) >= 5) most = 2
        do k = 1, size(cli%keys)
            if (in_file .and. .not. cli%keys(k)%in_file) cycle
            distance = edit_distance(lower(name), lower(cli%keys(k)%name))
            if (distance > most) cycle
            if (best > 0 .and. distance >= most) cycle
            best = k
            most = distance
        end do
        if (best > 0) text = " (did you mean "//cli%keys(best)%name//"?)"
    end function did_you_mean

    !> Refuse a key given together with a key it overrides.
    subroutine check_overrides(cli, error)
        type(cli_t), intent(in) :: cli
        type(error_t), allocatable, intent(out) :: error
        integer :: k, m
        do k = 1, size(cli%keys)
            associate (key => cli%keys(k))
                if (.not. key%given .or. len(key%overrides) == 0) cycle
                m = find_key(cli, key%overrides)
                if (m == 0) cycle
                if (.not. cli%keys(m)%given) cycle
                call fatal_error(error, origin(cli%keys(m))//cli%keys(m)%name//" = " &
                    //printable(cli%keys(m)%text)//": "//key%name//" = " &
                    //printable(key%text)//" is given too and overrides it; allowed one of " &
                    //cli%keys(m)%name//" and "//key%name)
                return
            end associate
        end do
    end subroutine check_overrides

    !> What a command line may hold, for messages about a stray argument.
    function allowed_arguments(cli) result(text)
        type(cli_t), intent(in) :: cli
        character(len=:), allocatable :: text
        text = "key=value with keys "//cli%key_list()
        if (cli%files) text = text//", one scene file"
        if (allocated(cli%version)) then
            text = text//", --help or --version"
        else
            text = text//", or --help"
        end if
    end function allowed_arguments

    pure logical function is_help(arg)
        character(len=*), intent(in) :: arg
        is_help = arg == "--help" .or. arg == "-h" .or. arg == "help"
    end function is_help

    pure logical function starts_with_dash(arg)
        character(len=*), intent(in) :: arg
        starts_with_dash = .false.
        if (len(arg) > 0) starts_with_dash = arg(1:1) == "-"
    end function starts_with_dash

    !> Index of the key called `name` (exactly), 0 if none.
    pure integer function find_key(cli, name)
        type(cli_t), intent(in) :: cli
        character(len=*), intent(in) :: name
        integer :: k
        find_key = 0
        if (.not. allocated(cli%keys)) return
        do k = 1, size(cli%keys)
            if (cli%keys(k)%name == name .and. len(cli%keys(k)%name) == len(name)) then
                find_key = k
                return
            end if
        end do
    end function find_key

    ! ------------------------------------------------------------------
    ! the program kit: scene files
    ! ------------------------------------------------------------------

    !> Apply a scene file: one namelist group `&scene ... /` holding whole
    !> keys (`name = value`, lists as `name = v1, v2, ...`), `!` comments.
    !> Every value passes the same checks as on the command line; what
    !> Fortran's namelist input would also take (elements `masses(2) = 1`,
    !> repeat counts `3*1`, null values `1,,2`, list-directed numbers like
    !> `1-5`) is refused. A key given on the command line too keeps that value.
    subroutine read_scene_file(cli, path, error)
        type(cli_t), intent(inout) :: cli
        character(len=*), intent(in) :: path
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: text
        type(scene_item_t), allocatable :: items(:)
        logical, allocatable :: seen(:)
        integer :: i
        call read_scene_text(path, text, error)
        if (allocated(error)) return
        call scene_items(path, text, items, error)
        if (allocated(error)) return
        allocate (seen(size(cli%keys)), source=.false.)
        do i = 1, size(items)
            call file_item(cli, path, items(i), seen, error)
            if (allocated(error)) return
        end do
    end subroutine read_scene_file

    !> One item of a scene file: a whole key, known, settable in a file and
    !> set once, with as many values as it takes.
    subroutine file_item(cli, path, item, seen, error)
        type(cli_t), intent(inout) :: cli
        character(len=*), intent(in) :: path
        type(scene_item_t), intent(in) :: item
        logical, intent(inout) :: seen(:)
        type(error_t), allocatable, intent(out) :: error
        character(len=:), allocatable :: text, where
        type(key_t) :: scratch
        integer :: k, count
        logical :: null
        where = file_origin(path)
        if (len(item%name) == 0) then
            call refuse("'= "//printable(item%values)//"' without a key; allowed key = value " &
                //"items", .false.)
            return
        end if
        if (verify(item%name, "abcdefghijklmnopqrstuvwxyz0123456789_") /= 0) then
            call refuse("not a key name (single elements and components cannot be set); " &
                //"allowed whole keys: "//file_keys(cli))
            return
        end if
        k = find_key(cli, item%name)
        if (k > 0) then
            if (.not. cli%keys(k)%in_file) k = 0
        end if
        if (k == 0) then
            call refuse("unknown key"//did_you_mean(cli, item%name, .true.)//"; allowed in a " &
                //"file: "//file_keys(cli))
            return
        end if
        if (seen(k)) then
            call refuse(item%name//" is given twice in the file; allowed each key once")
            return
        end if
        seen(k) = .true.
        call join_values(item%values, text, count, null)
        if (null .or. count == 0) then
            call refuse("an empty value; allowed "//cli%keys(k)%allowed)
            return
        end if
        if (count > 1 .and. cli%keys(k)%kind /= key_reals) then
            call refuse(itoa(count)//" values; allowed one value, "//cli%keys(k)%allowed)
            return
        end if
        if (cli%keys(k)%given) then
            ! the command line overrides the file; the file's value must still be valid
            scratch = cli%keys(k)
            scratch%text = text
            call read_value(scratch, where, error)
            return
        end if
        associate (key => cli%keys(k))
            key%given = .true.
            key%source = path
            key%text = text
            call read_value(key, where, error)
        end associate
    contains
        !> "file 'path': name = values: reason" (without the name and
        !> values if `named` is false).
        subroutine refuse(reason, named)
            character(len=*), intent(in) :: reason
            logical, intent(in), optional :: named
            logical :: with_name
            with_name = .true.
            if (present(named)) with_name = named
            if (with_name) then
                call fatal_error(error, where//printable(item%name)//" = " &
                    //printable(item%values)//": "//reason)
            else
                call fatal_error(error, where//reason)
            end if
        end subroutine refuse
    end subroutine file_item

    !> Names of the keys a scene file may set.
    pure function file_keys(cli) result(text)
        type(cli_t), intent(in) :: cli
        character(len=:), allocatable :: text
        integer :: k
        text = ""
        do k = 1, size(cli%keys)
            if (.not. cli%keys(k)%in_file) cycle
            if (len(text) > 0) text = text//", "
            text = text//cli%keys(k)%name
        end do
    end function file_keys

    ! ------------------------------------------------------------------
    ! the program kit: values, help, failure
    ! ------------------------------------------------------------------

    !> Index of a registered key; a name the program never registered is a
    !> mistake in the program, not in its input.
    integer function key_index(cli, name)
        type(cli_t), intent(in) :: cli
        character(len=*), intent(in) :: name
        key_index = find_key(cli, name)
        if (key_index == 0) error stop "sphere_row_cli: no key registered as '"//name//"'"
    end function key_index

    logical function cli_given(this, name)
        class(cli_t), intent(in) :: this
        character(len=*), intent(in) :: name
        cli_given = this%keys(key_index(this, name))%given
    end function cli_given

    integer function cli_get_int(this, name)
        class(cli_t), intent(in) :: this
        character(len=*), intent(in) :: name
        cli_get_int = this%keys(key_index(this, name))%n
    end function cli_get_int

    real(qp) function cli_get_real(this, name)
        class(cli_t), intent(in) :: this
        character(len=*), intent(in) :: name
        cli_get_real = this%keys(key_index(this, name))%x
    end function cli_get_real

    function cli_get_reals(this, name) result(xs)
        class(cli_t), intent(in) :: this
        character(len=*), intent(in) :: name
        real(qp), allocatable :: xs(:)
        integer :: k
        k = key_index(this, name)
        if (allocated(this%keys(k)%xs)) then
            xs = this%keys(k)%xs
        else
            allocate (xs(0))
        end if
    end function cli_get_reals

    logical function cli_get_flag(this, name)
        class(cli_t), intent(in) :: this
        character(len=*), intent(in) :: name
        cli_get_flag = this%keys(key_index(this, name))%flag
    end function cli_get_flag

    function cli_get_word(this, name) result(word)
        class(cli_t), intent(in) :: this
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: word
        word = this%keys(key_index(this, name))%text
    end function cli_get_word

    function cli_get_text(this, name) result(text)
        class(cli_t), intent(in) :: this
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: text
        text = this%keys(key_index(this, name))%text
    end function cli_get_text

    function cli_key_list(this) result(text)
        class(cli_t), intent(in) :: this
        character(len=:), allocatable :: text
        integer :: k
        text = ""
        do k = 1, size(this%keys)
            if (k > 1) text = text//", "
            text = text//this%keys(k)%name
        end do
    end function cli_key_list

    !> The text of `--help`: synopsis, the program's paragraph, every key with
    !> its default, help line and what is allowed, and the input rules.
    function cli_usage(this) result(text)
        class(cli_t), intent(in) :: this
        character(len=:), allocatable :: text
        text = "usage: "//this%name//" "//this%synopsis//nl
        if (allocated(this%about)) text = text//nl//this%about//nl
        text = text//nl//"Keys (key=default):"//nl &
            //key_lines(this%keys, this%files, file_keys(this))//nl//input_rules(this%name)
        if (allocated(this%epilogue)) text = text//nl//nl//this%epilogue
    end function cli_usage

    !> All command-line arguments, each with its own length.
    subroutine command_args(args)
        type(string_t), allocatable, intent(out) :: args(:)
        integer :: i, length
        allocate (args(command_argument_count()))
        do i = 1, size(args)
            call get_command_argument(i, length=length)
            allocate (character(len=length) :: args(i)%s)
            if (length > 0) call get_command_argument(i, args(i)%s)
        end do
    end subroutine command_args

    !> For programs: read the command line into `cli`; on `--help` print the
    !> usage on stdout and stop (on `--version`, the name and version); on
    !> bad input, or help that cannot be written, `fail`.
    subroutine read_command_line(cli)
        type(cli_t), intent(inout) :: cli
        type(string_t), allocatable :: args(:)
        type(error_t), allocatable :: error
        type(text_out_t) :: out
        call command_args(args)
        call cli%parse(args, error)
        if (cli%help .or. cli%show_version) then
            if (cli%help) then
                call out%put_text(cli%usage()//new_line("a"))
            else
                call out%put_text(cli%name//" "//cli%version//new_line("a"))
            end if
            call out%finish(error)
            if (allocated(error)) call fail(cli%name, error)
            stop
        end if
        if (.not. allocated(error)) return
        ! under an MPI launcher every rank reads the same command line: one
        ! message, from the first rank, and every rank stops
        if (launcher_rank() /= 0) stop 2, quiet=.true.
        call fail(cli%name, error)
    end subroutine read_command_line

    !> For programs: print `name: message` as one line on stderr (control
    !> characters shown escaped) and stop with exit status 2, or 1 if the
    !> error is output that could not be written.
    subroutine fail(name, error)
        character(len=*), intent(in) :: name
        type(error_t), intent(in) :: error
        write (error_unit, "(a)") name//": "//printable(error%message)
        if (error%code == error_output) stop 1, quiet=.true.
        stop 2, quiet=.true.
    end subroutine fail

end module sphere_row_cli
