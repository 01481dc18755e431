!> What the engine's tests share: a scene written as `sphere-row` takes it on
!> its command line (`p=5 e=0.3 masses=1,2,1,1,1 ...`), read by the CLI's own
!> registry and parser, so that a test's scene is one line of text and can be
!> given to the CLI or tools/replay as it stands; and the readers of
!> tools/replay's table line.
module test_support
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate
    use sphere_row_cli, only: cli_t, string_t
    use sphere_row_scene_keys, only: add_scene_keys, add_state_keys, scene_from_cli
    use sphere_row_error, only: input_error_t => error_t
    use testsuite, only: error_t
    implicit none
    private
    public :: scene_of, random_row, words, split_tabs, read_reals, run_and_rerun, bounded_row

contains

    !> The scene of `keys`, key=value words separated by blanks, as
    !> sphere-row reads them (its defaults for keys not given); a refusal is
    !> the test's failure, naming the keys and the CLI's message.
    subroutine scene_of(keys, scene, error)
        character(len=*), intent(in) :: keys
        type(scene_t), intent(out) :: scene
        type(error_t), allocatable, intent(out) :: error
        type(cli_t) :: cli
        type(input_error_t), allocatable :: refused
        cli%name = "sphere-row"
        call add_scene_keys(cli)
        call add_state_keys(cli)
        call cli%parse(words(keys), refused)
        if (.not. allocated(refused)) call scene_from_cli(cli, scene, refused)
        if (allocated(refused)) then
            allocate (error)
            error%message = "scene "//keys//" refused: "//refused%message
        end if
    end subroutine scene_of

    !> The touching row of 20 at e = 1/2 with the closed-form limits off and
    !> vtol = 1e-6: its cascade is taken to its pooling as a bounded limit
    !> (its cone bound within vtol), and nothing is taken at tolerance.
    subroutine bounded_row(scene)
        type(scene_t), intent(out) :: scene
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=20, e=0.5_qp, gaps=spread(0.0_qp, 1, 19))
        scene%closed_form_limits = .false.
        scene%vtol = 1.0e-6_qp
    end subroutine bounded_row

    !> The run of `scene` (`first`), then the run of the same scene with the
    !> settings given changed (`second`): a finer tol, another vtol or
    !> budget, the closed-form limits on or off. `scene` keeps the changes.
    subroutine run_and_rerun(scene, first, second, tol, vtol, max_collisions, &
        closed_form_limits)
        type(scene_t), intent(inout) :: scene
        type(run_t), intent(inout) :: first, second
        real(qp), intent(in), optional :: tol, vtol
        integer, intent(in), optional :: max_collisions
        logical, intent(in), optional :: closed_form_limits
        call simulate(scene, first)
        if (present(tol)) scene%tol = tol
        if (present(vtol)) scene%vtol = vtol
        if (present(max_collisions)) scene%max_collisions = max_collisions
        if (present(closed_form_limits)) scene%closed_form_limits = closed_form_limits
        call simulate(scene, second)
    end subroutine run_and_rerun

    !> A random row drawn from the intrinsic generator (42 numbers a row, so
    !> that a seeded test sees the same rows on every run): p from 2 to 20
    !> (from p_range(1) to p_range(2) where given), e uniform in [0, 1],
    !> masses all 1 or log-uniform in [1e-3, 1e3] (half the rows each; every
    !> row log-uniform where `unequal`), gaps uniform in [0, 2) and each
    !> closed with probability `closed`; at most `cap` collisions. `drawn`
    !> holds the 42 numbers. The rows of the random tests of the collapse
    !> rules and of the calendar.
    subroutine random_row(scene, closed, cap, p_range, unequal, drawn)
        type(scene_t), intent(out) :: scene
        real(qp), intent(in) :: closed
        integer, intent(in) :: cap
        integer, intent(in), optional :: p_range(2)
        logical, intent(in), optional :: unequal
        real(qp), intent(out), optional :: drawn(42)
        real(qp) :: u(42)
        integer :: p, stat, lo, hi
        logical :: equal
        character(len=200) :: msg
        lo = 2
        hi = 20
        if (present(p_range)) then
            lo = p_range(1)
            hi = p_range(2)
        end if
        call random_number(u)
        if (present(drawn)) drawn = u
        p = lo + int((hi - lo + 1)*u(1))
        equal = u(42) < 0.5_qp
        if (present(unequal)) equal = equal .and. .not. unequal
        call scene_init(scene, stat, msg, p=p, e=u(2), &
            masses=merge(1.0_qp, 1.0e3_qp**(2*u(3:p + 2) - 1), equal), &
            gaps=merge(0.0_qp, 2*u(23:p + 21), u(23:p + 21) < closed), max_collisions=cap)
    end subroutine random_row

    !> The blank-separated words of `text` (runs of blanks separate as one).
    pure function words(text) result(list)
        character(len=*), intent(in) :: text
        type(string_t), allocatable :: list(:)
        integer :: i, start
        allocate (list(0))
        start = 0
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= " ") then
                    if (start == 0) start = i
                    cycle
                end if
            end if
            if (start > 0) list = [list, string_t(text(start:i - 1))]
            start = 0
        end do
    end function words

    !> The fields of a line split at its tabs.
    subroutine split_tabs(text, fields)
        character(len=*), intent(in) :: text
        character(len=:), allocatable, intent(out) :: fields(:)
        integer :: n, i, at, from
        n = count([(text(i:i) == achar(9), i=1, len(text))]) + 1
        allocate (character(len=len(text)) :: fields(n))
        from = 1
        do i = 1, n
            at = index(text(from:), achar(9))
            if (at == 0) then
                fields(i) = text(from:)
            else
                fields(i) = text(from:from + at - 2)
                from = from + at
            end if
        end do
    end subroutine split_tabs

    !> Comma-separated reals.
    subroutine read_reals(text, xs)
        character(len=*), intent(in) :: text
        real(qp), allocatable, intent(out) :: xs(:)
        integer :: n, i
        n = count([(text(i:i) == ",", i=1, len_trim(text))]) + 1
        allocate (xs(n))
        read (text, *) xs
    end subroutine read_reals

end module test_support
