!> The differential test of the engine: a seeded set of random rows (the
!> collapse survey's generator), each run to its end or its cap, written with
!> every digit, so that the same rows run by two versions of the engine can be
!> compared (tools/differential builds a git revision beside the working tree
!> and compares the two tables).
!>
!> `mode=run` writes OUT/differential.tsv: per row its length, status,
!> collisions, end time and final velocities. `mode=compare` reads
!> BEFORE/differential.tsv and AFTER/differential.tsv of the same rows and
!> reports: every row that ended without a collapse before (status normal)
!> must be the same run after, bit for bit; rows that collapse both times
!> are counted by the largest difference of their velocities; rows answered
!> only before or only after are listed. It exits 1 if a finite run changed.
program c12_differential
    use sphere_row, only: qp, scene_t, run_t, simulate, itoa, str, status_word, real_str, &
        status_normal, status_collapsed
    use sphere_row_survey, only: survey_t, survey_open, survey_close, survey_scene
    use sphere_row_tables, only: open_table, tab, split_tabs, row_t, write_rows
    use sphere_row_study_cli, only: nl, cli_t, start_program, read_keys, stop_unless_normal, &
        close_tables, fail
    implicit none
    type(cli_t) :: cli
    character(len=:), allocatable :: mode

    call start_program(cli, "c12-differential", &
        "The differential test: mode=run writes OUT/differential.tsv, the end of every"//nl// &
        "seeded random row (p = 2..p_max, masses equal or log-uniform over"//nl// &
        "[1/span, span], e uniform, a fifth of the gaps closed) run by this engine;"//nl// &
        "mode=compare reads BEFORE/ and AFTER/differential.tsv of the same rows: every"//nl// &
        "run finite before must be the same after, bit for bit (exit 1 if not).")
    call cli%add_word("mode", "run", "run (write OUT/differential.tsv) or compare")
    call cli%add_int("n", "6000", "random rows", lo=1)
    call cli%add_int("seed", "2027", "seed of the rows", lo=0)
    call cli%add_int("cap", "200000", "collisions after which a run counts as unanswered", &
        lo=1)
    call cli%add_int("p_max", "14", "longest row drawn (p from 3)", lo=3)
    call cli%add_real("span", "1000", "masses log-uniform over [1/span, span] (half the rows)", &
        lo=1.0_qp)
    call cli%add_word("before", "build/differential/before", "compare: the first table's directory")
    call cli%add_word("after", "build/differential/after", "compare: the second table's directory")
    call cli%add_real("rel", "0", "compare: a finite run's velocities may differ by this much, "// &
        "relative to its largest (0: bit for bit; its count, status and end time never)", &
        lo=0.0_qp)
    call read_keys(cli)
    mode = cli%get_word("mode")
    select case (mode)
    case ("run")
        call run_rows()
    case ("compare")
        call compare_tables()
    case default
        call fail("mode = "//mode//": allowed run or compare")
    end select

contains

    !> Draw the rows, run them on the threads, write one line per row in row
    !> order (each built by row_t: the threads make their texts at once).
    subroutine run_rows()
        type(survey_t) :: survey
        type(scene_t), allocatable :: rows(:)
        type(row_t), allocatable :: lines(:)
        type(run_t) :: run
        integer :: n, i, j, unit, stat
        character(len=200) :: msg
        n = cli%get_int("n")
        allocate (rows(n), lines(n))
        call survey_open(survey, cli%get_int("seed"), 3, cli%get_int("p_max"), cli%get_real("span"))
        do i = 1, n
            call survey_scene(survey, rows(i))
            rows(i)%max_collisions = cli%get_int("cap")
        end do
        call survey_close(survey)
        !$omp parallel do schedule(dynamic, 1) default(shared) private(i, j, run)
        do i = 1, n
            call simulate(rows(i), run)
            call lines(i)%add(i)
            call lines(i)%add(rows(i)%p)
            call lines(i)%add_status(run%status)
            call lines(i)%add(run%n)
            call lines(i)%add(run%t_end)
            do j = 1, rows(i)%p
                call lines(i)%add(run%v(j))
            end do
        end do
        !$omp end parallel do
        call open_table(cli%get_word("out"), "differential.tsv", &
            "row"//tab//"p"//tab//"status"//tab//"collisions"//tab//"t_end[L/V]"//tab// &
            "v1..vp[V]", unit, stat, msg)
        call stop_unless_normal(stat, msg)
        call write_rows(unit, lines)
        call close_tables([unit])
    end subroutine run_rows

    !> Compare two tables of the same rows.
    subroutine compare_tables()
        character(len=:), allocatable :: before(:), after(:), a(:), b(:)
        integer :: i, j, changed_finite, gained, lost, both, count_rows
        real(qp) :: dv, worst, x, y
        call read_lines(cli%get_word("before")//"/differential.tsv", before)
        call read_lines(cli%get_word("after")//"/differential.tsv", after)
        if (size(before) /= size(after)) call fail("before and after hold " &
            //itoa(size(before))//" and "//itoa(size(after))//" rows: allowed the same rows")
        changed_finite = 0
        gained = 0
        lost = 0
        both = 0
        worst = 0
        count_rows = size(before)
        do i = 1, count_rows
            call split_tabs(before(i), a)
            call split_tabs(after(i), b)
            if (a(3) == status_word(status_normal)) then
                if (.not. same_run(a, b)) then
                    changed_finite = changed_finite + 1
                    if (changed_finite <= 10) print "(a)", "finite run changed: row " &
                        //trim(a(1))//": "//trim(a(3))//" "//trim(a(4))//" -> " &
                        //trim(b(3))//" "//trim(b(4))//", velocities apart by " &
                        //real_str(apart(a, b), 2)//" of the largest"
                end if
            else if (a(3) == status_word(status_collapsed) .and. &
                b(3) == status_word(status_collapsed)) then
                both = both + 1
                dv = 0
                do j = 6, min(size(a), size(b))
                    read (a(j), *) x
                    read (b(j), *) y
                    dv = max(dv, abs(x - y))
                end do
                worst = max(worst, dv)
            else if (b(3) == status_word(status_collapsed) .or. &
                b(3) == status_word(status_normal)) then
                gained = gained + 1
            else if (a(3) == status_word(status_collapsed)) then
                lost = lost + 1
                if (lost <= 10) print "(a)", "answer lost: row "//trim(a(1))//": " &
                    //trim(a(3))//" -> "//trim(b(3))
            end if
        end do
        print "(a)", itoa(count_rows)//" rows: "//itoa(changed_finite)//" finite runs changed; " &
            //itoa(both)//" collapse both times, velocities within "//str(worst)//"; " &
            //itoa(gained)//" answered only after, "//itoa(lost)//" only before"
        if (changed_finite > 0) stop 1
    end subroutine compare_tables

    !> Two lines of the same finite run: the same fields, but the velocities
    !> (from the sixth) within `rel` of the largest of them.
    logical function same_run(a, b)
        character(len=*), intent(in) :: a(:), b(:)
        real(qp) :: x, y, rel, largest
        integer :: j
        same_run = size(a) == size(b)
        if (.not. same_run) return
        same_run = all(a(:5) == b(:5))
        if (.not. same_run) return
        rel = cli%get_real("rel")
        largest = 0
        do j = 6, size(a)
            read (a(j), *) x
            largest = max(largest, abs(x))
        end do
        do j = 6, size(a)
            if (a(j) == b(j)) cycle
            read (a(j), *) x
            read (b(j), *) y
            same_run = abs(x - y) <= rel*largest
            if (.not. same_run) return
        end do
    end function same_run

    !> The largest difference of two lines' velocities, relative to the largest.
    real(qp) function apart(a, b)
        character(len=*), intent(in) :: a(:), b(:)
        real(qp) :: x, y, largest
        integer :: j
        apart = 0
        largest = tiny(1.0_qp)
        do j = 6, min(size(a), size(b))
            read (a(j), *) x
            read (b(j), *) y
            largest = max(largest, abs(x))
            apart = max(apart, abs(x - y))
        end do
        apart = apart/largest
    end function apart

    !> The data lines of a table (its header dropped).
    subroutine read_lines(path, lines)
        character(len=*), intent(in) :: path
        character(len=:), allocatable, intent(out) :: lines(:)
        integer :: unit, ios, n, i
        character(len=4000) :: buffer
        open (newunit=unit, file=path, status="old", action="read", iostat=ios)
        if (ios /= 0) call fail("file '"//path//"': cannot be read; allowed a table of " &
            //"mode=run")
        n = 0
        do
            read (unit, "(a)", iostat=ios) buffer
            if (ios /= 0) exit
            n = n + 1
        end do
        rewind (unit)
        allocate (character(len=4000) :: lines(max(n - 1, 0)))
        read (unit, "(a)", iostat=ios) buffer
        do i = 1, n - 1
            if (ios == 0) read (unit, "(a)", iostat=ios) lines(i)
        end do
        close (unit)
        if (ios /= 0) call fail("file '"//path//"': cannot be read to its end")
    end subroutine read_lines

end program c12_differential
