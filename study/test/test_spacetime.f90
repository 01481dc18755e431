!> Tests of the space-time diagram's tables (sphere_row_spacetime): the world
!> lines against positions worked out by hand, the collapse limit in its
!> table, every k-th sphere, and the refusal of an event log too large.
module test_spacetime
    use sphere_row, only: qp, scene_t, run_t, event_log_t, scene_init, simulate, &
        status_normal, status_invalid, status_collapsed, str, itoa
    use sphere_row_spacetime, only: spacetime_t, write_spacetime, check_log_size, drawn, &
        default_every, drawable_collisions
    use sphere_row_tables, only: split_tabs
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_spacetime

    !> Where the tests write their tables (under the study package).
    character(len=*), parameter :: dir = "build/test_spacetime"
    !> Positions and times of these scenes are a few units: a difference of
    !> a few roundings of real(16) at that scale.
    real(qp), parameter :: tol = 64*epsilon(1.0_qp)

contains

    !> The space-time diagram's tests.
    function collect_spacetime() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("elastic_world_lines_by_hand", test_elastic_by_hand), &
            new_unittest("collapse_limit_in_its_table", test_collapse), &
            new_unittest("every_kth_sphere_lines_exact", test_every), &
            new_unittest("event_log_too_large_refused", test_log_size), &
            new_unittest("suggested_budget_fits_and_is_largest", test_drawable) &
            ]
    end function collect_spacetime

    !> The definition's row at e = 1 with d = 2.5, a = 0.5: sphere i rests at
    !> 3 (i-1) until t = (i-1)/2, moves at v0 = 1 until t = i/2 and rests
    !> again (the last one moves on); each collision at t = i/2 is at the
    !> contact point 3 (i-1) + 1/2 + d/2. Every number is exact in binary.
    subroutine test_elastic_by_hand(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), parameter :: d = 2.5_qp, t_max = 2
        real(qp), allocatable :: lines(:, :), marks(:, :), limits(:, :), expected(:, :)
        type(spacetime_t) :: diagram
        integer :: i, k
        call diagram_of(error, 4, 1.0_qp, d, 0.5_qp, t_max, 1, lines, marks, limits, diagram)
        if (allocated(error)) return
        ! pieces by hand: sphere, t0, x0, t1, x1, v
        allocate (expected(6, 0))
        do i = 1, 4
            if (i > 1) call add_piece(i, 0.0_qp, 3.0_qp*(i - 1), (i - 1)/2.0_qp, &
                3.0_qp*(i - 1), 0.0_qp)
            if (i < 4) then
                call add_piece(i, (i - 1)/2.0_qp, 3.0_qp*(i - 1), i/2.0_qp, &
                    3.0_qp*(i - 1) + 0.5_qp, 1.0_qp)
                call add_piece(i, i/2.0_qp, 3.0_qp*(i - 1) + 0.5_qp, t_max, &
                    3.0_qp*(i - 1) + 0.5_qp, 0.0_qp)
            else
                call add_piece(i, 1.5_qp, 9.0_qp, t_max, 9.0_qp + (t_max - 1.5_qp), 1.0_qp)
            end if
        end do
        call check(error, size(lines, 2) == size(expected, 2), "pieces: "// &
            itoa(size(lines, 2))//", by hand "//itoa(size(expected, 2)))
        if (allocated(error)) return
        do k = 1, size(expected, 2)
            call check(error, any([(all(abs(lines(:, i) - expected(:, k)) <= tol), &
                i=1, size(lines, 2))]), "piece of sphere "//itoa(nint(expected(1, k))) &
                //" from t = "//str(expected(2, k))//" not in the table, or not at x0 = " &
                //str(expected(3, k)))
            if (allocated(error)) return
        end do
        call check(error, size(marks, 2) == 3 .and. size(limits, 2) == 0, &
            "3 collisions and no collapse limit expected")
        if (allocated(error)) return
        do i = 1, 3
            call check(error, all(abs(marks(:, i) - [i/2.0_qp, 3.0_qp*(i - 1) + 0.5_qp + d/2, &
                real(i, qp), real(i + 1, qp), 1.0_qp]) <= tol), "collision "//itoa(i) &
                //": t, x, first, last, closing speed")
            if (allocated(error)) return
        end do
        call check(error, diagram%spheres == 4 .and. diagram%pieces == size(expected, 2), &
            "counts of the diagram")

    contains

        subroutine add_piece(sphere, t0, x0, t1, x1, v)
            integer, intent(in) :: sphere
            real(qp), intent(in) :: t0, x0, t1, x1, v
            expected = reshape([expected, [real(sphere, qp), t0, x0, t1, x1, v]], &
                [6, size(expected, 2) + 1])
        end subroutine add_piece

    end subroutine test_elastic_by_hand

    !> The definition's row at e = 0.1 collapses: the limit of spheres 1-4 is
    !> in the table at the run's collapse time, the group edge to edge 4 d
    !> long (its gaps closed), at the common velocity v0/4.
    subroutine test_collapse(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: lines(:, :), marks(:, :), limits(:, :)
        type(spacetime_t) :: diagram
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        call diagram_of(error, 4, 0.1_qp, 1.0_qp, 1.0_qp, 7.0_qp, 1, lines, marks, limits, &
            diagram)
        if (allocated(error)) return
        call scene_init(scene, stat, msg, p=4, e=0.1_qp)
        call simulate(scene, run)
        call check(error, run%status == status_collapsed .and. run%limits%first == 1 .and. &
            run%limits%last == 4, "the scene collapses as 1-4")
        if (allocated(error)) return
        call check(error, size(limits, 2) == 1, "one collapse limit in the table, found " &
            //itoa(size(limits, 2)))
        if (allocated(error)) return
        call check(error, abs(limits(1, 1) - run%limits%t) <= tol .and. &
            nint(limits(2, 1)) == 1 .and. nint(limits(3, 1)) == 4, &
            "limit at t = "//str(limits(1, 1))//" of "//itoa(nint(limits(2, 1)))//"-" &
            //itoa(nint(limits(3, 1)))//"; the run's at "//str(run%limits%t))
        if (allocated(error)) return
        call check(error, abs(limits(5, 1) - limits(4, 1) - 4) <= tol .and. &
            abs(limits(6, 1) - 0.25_qp) <= tol .and. abs(limits(4, 1) - (run%x(1) - 0.5_qp)) &
            <= tol, "extent "//str(limits(4, 1))//" .. "//str(limits(5, 1))//", v " &
            //str(limits(6, 1)))
        if (allocated(error)) return
        call check(error, size(marks, 2) == run%n, "every collision marked")
    end subroutine test_collapse

    !> A row of 10 spheres of unequal masses, every 4th drawn: the table holds
    !> spheres 1, 5, 9 and 10 only; each line is a chain of pieces from t = 0
    !> to t_max, and each piece's end (the position of a later event's row)
    !> is its start moved at its velocity for its duration. The default k:
    !> 1 up to 300 spheres.
    subroutine test_every(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), parameter :: t_max = 60
        integer, parameter :: shown(4) = [1, 5, 9, 10]
        real(qp), allocatable :: lines(:, :), marks(:, :), limits(:, :)
        type(spacetime_t) :: diagram
        real(qp) :: t_at, x_at, scale, clock
        integer :: i, k, sphere, n
        call diagram_of(error, 10, 0.5_qp, 1.0_qp, 1.0_qp, t_max, 4, lines, marks, limits, &
            diagram, masses=[1.0_qp, 3.0_qp, 1.0_qp, 0.5_qp, 2.0_qp, 1.0_qp, 1.0_qp, 4.0_qp, &
            1.0_qp, 2.0_qp], collisions=n)
        if (allocated(error)) return
        call check(error, all(drawn(nint(lines(1, :)), 10, 4)) .and. diagram%spheres == 4, &
            "only spheres 1, 5, 9, 10 drawn")
        if (allocated(error)) return
        scale = maxval(abs(lines(3, :)))
        ! the scan's clock is one real: a step below half its last place at t
        ! (a collapse's sub-resolution steps) is lost from t, not from the
        ! gaps, so a piece is straight to n such roundings of its speed
        clock = n*epsilon(1.0_qp)*t_max*maxval(abs(lines(6, :)))
        do k = 1, 4
            sphere = shown(k)
            t_at = 0
            x_at = 0
            do i = 1, size(lines, 2)
                if (nint(lines(1, i)) /= sphere) cycle
                call check(error, lines(2, i) == t_at .and. (t_at == 0 .or. lines(3, i) == x_at), &
                    "line of sphere "//itoa(sphere)//" broken at t = "//str(t_at))
                if (allocated(error)) return
                ! (a piece lasts; two times a few last places apart, as a
                ! collapse's steps below the clock's resolution leave them, may
                ! read back equal from 34 digits)
                call check(error, lines(4, i) >= lines(2, i) .and. abs(lines(5, i) - lines(3, i) &
                    - lines(6, i)*(lines(4, i) - lines(2, i))) <= tol*scale + clock, &
                    "piece of sphere "//itoa(sphere)//" from t = "//str(lines(2, i)) &
                    //" not straight: off by "//str(abs(lines(5, i) - lines(3, i) &
                    - lines(6, i)*(lines(4, i) - lines(2, i))))//", allowed " &
                    //str(tol*scale + clock))
                if (allocated(error)) return
                t_at = lines(4, i)
                x_at = lines(5, i)
            end do
            call check(error, t_at == t_max, "line of sphere "//itoa(sphere) &
                //" ends at t = "//str(t_at))
            if (allocated(error)) return
        end do
        call check(error, all(drawn(nint(marks(3, :)), 10, 4) .or. &
            drawn(nint(marks(4, :)), 10, 4)), "a collision marked without a drawn sphere")
        if (allocated(error)) return
        call check(error, default_every(300) == 1 .and. default_every(301) == 2 .and. &
            default_every(1000000) == 3334, "default every")
    end subroutine test_every

    !> A log of 10^6 events of a row of 10^6 spheres is refused with a way
    !> out named; the definition's row is not.
    subroutine test_log_size(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        integer :: stat
        character(len=400) :: text
        character(len=:), allocatable :: msg
        call scene_init(scene, stat, text, p=1000000, e=1.0_qp)
        call check_log_size(scene, 999999, 0, 82, stat, msg)
        call check(error, stat == status_invalid .and. index(msg, "p = 1000000") == 1 .and. &
            index(msg, "max_collisions <= 82 ") > 0, "refusal: "//trim(msg))
        if (allocated(error)) return
        call scene_init(scene, stat, text, p=4, e=0.1_qp)
        call check_log_size(scene, 57, 1, 0, stat, msg)
        call check(error, stat == status_normal, "the definition's row: "//trim(msg))
    end subroutine test_log_size

    !> The budget a refusal suggests is the largest whose run's log fits: a
    !> row of 10^5 spheres at e = 0.5, whose full run takes 2053 collapse
    !> limits among its 10^7 collisions, fits 82 events; its first 82
    !> collisions take no limit, so max_collisions = 82 fits and 83 does not
    !> (the suggestion once subtracted the whole run's limits and said 1).
    subroutine test_drawable(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat, cap
        character(len=400) :: text
        character(len=:), allocatable :: msg
        call scene_init(scene, stat, text, p=100000, e=0.5_qp)
        cap = drawable_collisions(scene)
        call check(error, cap == 82, "suggested max_collisions <= "//itoa(cap)//", not 82")
        if (allocated(error)) return
        scene%max_collisions = cap
        call simulate(scene, run)
        call check_log_size(scene, run%n, run%limits%n, cap, stat, msg)
        call check(error, stat == status_normal, "the suggested budget is refused: "//msg)
        if (allocated(error)) return
        scene%max_collisions = cap + 1
        call simulate(scene, run)
        call check_log_size(scene, run%n, run%limits%n, cap, stat, msg)
        call check(error, stat == status_invalid, "one collision more fits too: "//itoa(cap + 1))
    end subroutine test_drawable

    !> Run a row of p spheres (gaps a, diameter d, v0 = 1) with its log,
    !> write its diagram up to t_max with every k-th sphere, and read its
    !> three tables back: one column per row of the table, fields as reals.
    subroutine diagram_of(error, p, e, d, a, t_max, every, lines, marks, limits, diagram, masses, &
        collisions)
        type(error_t), allocatable, intent(out) :: error
        integer, intent(in) :: p, every
        real(qp), intent(in) :: e, d, a, t_max
        real(qp), allocatable, intent(out) :: lines(:, :), marks(:, :), limits(:, :)
        type(spacetime_t), intent(out) :: diagram
        real(qp), intent(in), optional :: masses(:)
        integer, intent(out), optional :: collisions
        type(scene_t) :: scene
        type(run_t) :: run
        type(event_log_t) :: log
        integer :: stat
        character(len=400) :: text
        character(len=:), allocatable :: msg
        call execute_command_line("rm -rf "//dir)
        call scene_init(scene, stat, text, p=p, e=e, d=d, a=a, masses=masses)
        call check(error, stat == status_normal, "scene: "//trim(text))
        if (allocated(error)) return
        call simulate(scene, run, log)
        if (present(collisions)) collisions = run%n
        call write_spacetime(scene, run, log, dir, "t", every, t_max, diagram, stat, msg)
        call check(error, stat == status_normal, "write_spacetime: "//trim(msg))
        if (allocated(error)) return
        call read_table(error, dir//"/t_lines.tsv", 6, lines)
        if (.not. allocated(error)) call read_table(error, dir//"/t_collisions.tsv", 5, marks)
        if (.not. allocated(error)) call read_table(error, dir//"/t_collapses.tsv", 6, limits)
    end subroutine diagram_of

    !> The rows of a TSV table of `columns` numeric fields after its header.
    subroutine read_table(error, path, columns, values)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in) :: path
        integer, intent(in) :: columns
        real(qp), allocatable, intent(out) :: values(:, :)
        character(len=1000) :: line
        character(len=:), allocatable :: fields(:)
        real(qp) :: row(columns)
        integer :: unit, ios, j
        allocate (values(columns, 0))
        open (newunit=unit, file=path, status="old", action="read", iostat=ios)
        call check(error, ios == 0, path//": cannot be read")
        if (allocated(error)) return
        read (unit, "(a)", iostat=ios) line
        call check(error, ios == 0, path//": no header")
        if (allocated(error)) return
        do
            read (unit, "(a)", iostat=ios) line
            if (ios /= 0) exit
            call split_tabs(line, fields)
            call check(error, size(fields) == columns, path//": "//trim(line))
            if (allocated(error)) exit
            do j = 1, columns
                read (fields(j), *, iostat=ios) row(j)
                call check(error, ios == 0, path//": field "//trim(fields(j)))
                if (allocated(error)) exit
            end do
            if (allocated(error)) exit
            values = reshape([values, row], [columns, size(values, 2) + 1])
        end do
        close (unit)
    end subroutine read_table

end module test_spacetime
