!> The space-time diagram of a run: the world lines x_i(t) of the spheres, the
!> collisions on them and the collapse limits, as tables for a figure.
!>
!> Between two of its own collisions a sphere moves at constant velocity, so
!> its world line is exactly a polygon whose vertices are the events that
!> change its velocity: a collision of its pair, or a collapse limit of its
!> group. Only those vertices are written, one piece of constant velocity per
!> row, not every sphere at every event of the run. Each vertex's position is
!> the one of that event's row of the log, by the summation of the
!> definition's eq. (5), x_{i+1} = x_i + y_i + d; the end of the time window
!> cuts the last piece of every line.
!>
!> Tables written into directory `dir`, each with one header row:
!>
!> - `NAME_lines.tsv`: sphere, t0, x0, t1, x1, v: the sphere moves from
!>   (t0, x0) to (t1, x1) at velocity v;
!> - `NAME_collisions.tsv`: t, x, first, last, closing_speed: the time and
!>   point of contact (x_first + d/2) of the pair, its speed of approach;
!> - `NAME_collapses.tsv`: t, first, last, x_left, x_right, v: a collapse
!>   limit of spheres first..last, the group's extent from the left edge of
!>   its first sphere to the right edge of its last, its common velocity;
!> - `NAME_info.tsv`: key, value: the scene and the run in words and numbers
!>   (the figure's title is made of them).
module sphere_row_spacetime
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: qp, scene_t, run_t, event_log_t, event_collision, event_collapse, &
        status_normal, status_invalid, status_word, short_text, itoa, simulate
    use sphere_row_tables, only: open_table, close_table, row_t, tab, write_rows
    implicit none
    private
    public :: spacetime_t, write_spacetime, default_every, drawn, check_log_size, caption
    public :: drawable_collisions
    public :: spheres_most, log_bytes_most

    !> Rows of more spheres than this are drawn by every k-th sphere
    !> (default_every): a few hundred lines are what a figure of about a
    !> thousand pixels across keeps apart.
    integer, parameter :: spheres_most = 300
    !> Largest event log a diagram is made from [bytes]: the gaps and their
    !> rates, 2 (p-1) real(16) per event. The log doubles its capacity when
    !> full, so a run may hold about three times this while it grows.
    integer(int64), parameter :: log_bytes_most = 2_int64**28

    !> What a diagram holds: its window and how much of each table.
    type :: spacetime_t
        !> Every k-th sphere is drawn (1, 1+k, 1+2k, ... and p).
        integer :: every = 1
        !> End of the time window [L/V].
        real(qp) :: t_max = 0.0_qp
        !> Spheres drawn, pieces of world line, collisions and collapse
        !> limits written.
        integer :: spheres = 0, pieces = 0, collisions = 0, collapses = 0
    end type spacetime_t

contains

    !> The default k of `every` for a row of p spheres: 1 up to spheres_most
    !> spheres, else the smallest k that draws at most about that many.
    pure integer function default_every(p) result(every)
        integer, intent(in) :: p
        every = max(1, (p + spheres_most - 1)/spheres_most)
    end function default_every

    !> True if sphere i of a row of p is drawn with every k-th sphere: the
    !> first, every k-th after it, and the last, which carries the row's end.
    elemental logical function drawn(i, p, every)
        integer, intent(in) :: i, p, every
        drawn = mod(i - 1, every) == 0 .or. i == p
    end function drawn

    !> Events (collisions and collapse limits) whose rows, with the initial
    !> state's, fit log_bytes_most for a row of p spheres.
    pure integer(int64) function events_most(p)
        integer, intent(in) :: p
        events_most = log_bytes_most/(2_int64*(p - 1)*storage_size(1.0_qp)/8) - 1
    end function events_most

    !> The largest work budget max_collisions whose run's log fits
    !> log_bytes_most: its collisions and the collapse limits taken among them
    !> (0 if not even one collision fits). A run capped at N collisions is the
    !> first part of the run capped later, so its number of limits c(N) grows
    !> with N: N_0 = E - c(E) fits for E = events_most, none above E - c(N_0)
    !> does, and the bisection between them takes a few runs without a log
    !> (O(p) memory each, at most E collisions).
    integer function drawable_collisions(scene) result(cap)
        type(scene_t), intent(in) :: scene
        integer :: lo, hi, mid, at_e
        integer(int64) :: most
        most = min(events_most(scene%p), int(huge(1), int64))
        cap = 0
        if (most < 1) return
        if (events_of(int(most), at_e)) then
            cap = int(most)
            return
        end if
        lo = 0
        hi = int(most) - 1
        mid = int(most) - at_e
        if (mid >= 1) then
            if (events_of(mid, at_e)) then
                lo = mid
                hi = min(hi, int(most) - at_e)
            else
                hi = mid - 1
            end if
        end if
        do while (lo < hi)
            mid = lo + (hi - lo + 1)/2
            if (events_of(mid, at_e)) then
                lo = mid
            else
                hi = mid - 1
            end if
        end do
        cap = lo

    contains

        !> Whether the run capped at n collisions fits the log; `limits` its
        !> number of collapse limits.
        logical function events_of(n, limits) result(fits)
            integer, intent(in) :: n
            integer, intent(out) :: limits
            type(scene_t) :: capped
            type(run_t) :: run
            capped = scene
            capped%max_collisions = n
            call simulate(capped, run)
            limits = run%limits%n
            fits = int(run%n, int64) + limits <= most
        end function events_of

    end function drawable_collisions

    !> Refuse (stat = status_invalid, one line in msg naming what to change)
    !> a run whose event log would exceed log_bytes_most: `collisions` and
    !> `collapses` are its numbers of events, found by a run without a log,
    !> which costs O(p) memory however long it is; `cap` is the largest work
    !> budget whose run fits (drawable_collisions), suggested in the message.
    pure subroutine check_log_size(scene, collisions, collapses, cap, stat, msg)
        type(scene_t), intent(in) :: scene
        integer, intent(in) :: collisions, collapses, cap
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: msg
        integer(int64) :: bytes, per_event
        per_event = 2_int64*(scene%p - 1)*storage_size(1.0_qp)/8
        bytes = per_event*(int(collisions, int64) + collapses + 1)
        stat = status_normal
        msg = ""
        if (bytes <= log_bytes_most) return
        stat = status_invalid
        msg = "p = "//itoa(scene%p)//" with e = "//short_text(scene%e)//": the event log of " &
            //"its "//itoa(int(collisions, int64) + collapses)//" events would need " &
            //short_text(real(bytes, qp), 2)//" bytes; allowed at most " &
            //short_text(real(log_bytes_most, qp), 2)
        if (cap > 0) then
            msg = msg//" (fewer spheres, or max_collisions <= "//itoa(cap)//" to draw the " &
                //"run up to that collision)"
        else
            msg = msg//" (fewer spheres: not even one collision of this row fits)"
        end if
    end subroutine check_log_size

    !> The scene and its run in a few words, for the figure's title: the
    !> parameters that differ from row to row, the outcome.
    pure function caption(scene, run) result(text)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        character(len=:), allocatable :: text
        text = "p = "//itoa(scene%p)//", e = "//short_text(scene%e)//", d = " &
            //short_text(scene%d)
        if (all(scene%a == scene%a(1))) then
            text = text//", a = "//short_text(scene%a(1))
        else
            text = text//", gaps as given"
        end if
        text = text//", v0 = "//short_text(scene%v0)
        if (.not. all(scene%m == scene%m(1))) text = text//", masses as given"
        text = text//": "//status_word(run%status)//", "//counted(run%n, "collision")
        if (run%limits%n > 0) text = text//", "//counted(run%limits%n, "collapse limit")

    contains

        pure function counted(n, noun) result(words)
            integer, intent(in) :: n
            character(len=*), intent(in) :: noun
            character(len=:), allocatable :: words
            words = itoa(n)//" "//noun//trim(merge("  ", "s ", n == 1))
        end function counted

    end function caption

    !> Write the diagram's tables of `scene`, run into `run` with event log
    !> `log`, into directory `dir` under base name `name`, drawing every
    !> `every`-th sphere up to time `t_max`. `stat` is status_invalid (and
    !> `msg` says why) if a table cannot be written; the tables still open
    !> are then left to the program's discard_tables (its fail does that).
    subroutine write_spacetime(scene, run, log, dir, name, every, t_max, diagram, stat, msg)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        type(event_log_t), intent(in) :: log
        character(len=*), intent(in) :: dir, name
        integer, intent(in) :: every
        real(qp), intent(in) :: t_max
        type(spacetime_t), intent(out) :: diagram
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: msg
        character(len=400) :: why
        integer :: lines, marks, limits, info
        diagram%every = every
        diagram%t_max = t_max
        call open_table(dir, name//"_lines.tsv", "sphere"//tab//"t0[L/V]"//tab//"x0[L]"//tab &
            //"t1[L/V]"//tab//"x1[L]"//tab//"v[V]", lines, stat, why)
        if (stat == status_normal) call open_table(dir, name//"_collisions.tsv", "t[L/V]"//tab &
            //"x[L]"//tab//"first"//tab//"last"//tab//"closing_speed[V]", marks, stat, why)
        if (stat == status_normal) call open_table(dir, name//"_collapses.tsv", "t[L/V]"//tab &
            //"first"//tab//"last"//tab//"x_left[L]"//tab//"x_right[L]"//tab//"v[V]", limits, &
            stat, why)
        if (stat == status_normal) call open_table(dir, name//"_info.tsv", "key"//tab//"value", &
            info, stat, why)
        if (stat == status_normal) then
            call write_events(scene, log, lines, marks, limits, diagram)
            call write_info(scene, run, diagram, info)
            call close_table(lines, stat, why)
            if (stat == status_normal) call close_table(marks, stat, why)
            if (stat == status_normal) call close_table(limits, stat, why)
            if (stat == status_normal) call close_table(info, stat, why)
        end if
        msg = ""
        if (stat /= status_normal) msg = trim(why)
    end subroutine write_spacetime

    !> The rows of the three tables of events: every event up to t_max, in
    !> the order of the log, then the last piece of every line drawn.
    subroutine write_events(scene, log, lines, marks, limits, diagram)
        type(scene_t), intent(in) :: scene
        type(event_log_t), intent(in) :: log
        integer, intent(in) :: lines, marks, limits
        type(spacetime_t), intent(inout) :: diagram
        !> Rows kept before they are written in one record (write_rows).
        integer, parameter :: batch = 256
        real(qp), allocatable :: x(:), v(:), t_from(:), x_from(:), v_from(:)
        logical, allocatable :: shown(:)
        type(row_t) :: pieces(batch)
        type(row_t) :: row
        integer :: p, i, j, lo, hi, n_pieces
        p = scene%p
        allocate (x(p), v(p), t_from(p), x_from(p), v_from(p), shown(p))
        shown = drawn([(i, i=1, p)], p, diagram%every)
        diagram%spheres = count(shown)
        call state_at(0, p)
        t_from = log%t(0)
        x_from = x
        v_from = v
        n_pieces = 0
        do j = 1, log%n
            if (log%t(j) > diagram%t_max) exit
            lo = log%first(j)
            hi = log%last(j)
            call state_at(j, hi)
            do i = lo, hi
                ! a sphere of a collapsed group that kept its velocity has no
                ! vertex here: its line goes straight on
                if (shown(i) .and. v(i) /= v_from(i)) call vertex(i, log%t(j), x(i), v(i))
            end do
            select case (log%kind(j))
            case (event_collision)
                if (.not. (shown(lo) .or. shown(hi))) cycle
                row = row_t()
                call row%add(log%t(j))
                call row%add(x(lo) + scene%d/2)
                call row%add(lo)
                call row%add(hi)
                call row%add(-log%w(j))
                write (marks, "(a)") row%text
                diagram%collisions = diagram%collisions + 1
            case (event_collapse)
                row = row_t()
                call row%add(log%t(j))
                call row%add(lo)
                call row%add(hi)
                call row%add(x(lo) - scene%d/2)
                call row%add(x(hi) + scene%d/2)
                call row%add(v(lo))
                write (limits, "(a)") row%text
                diagram%collapses = diagram%collapses + 1
            case default
                ! the log holds no other kind after its start row
            end select
        end do
        ! the end of the window: each line's last piece, at its own velocity
        do i = 1, p
            if (shown(i)) call vertex(i, diagram%t_max, &
                x_from(i) + v_from(i)*(diagram%t_max - t_from(i)), v_from(i))
        end do
        call write_rows(lines, pieces(:n_pieces))

    contains

        !> Positions and velocities of spheres 1..last after event j, by the
        !> summation (5) from x_1 and the gaps of its row.
        subroutine state_at(j, last)
            integer, intent(in) :: j, last
            integer :: k
            x(1) = log%x1(j)
            v(1) = log%dx1(j)
            do k = 1, last - 1
                x(k + 1) = x(k) + log%y(k, j) + scene%d
                v(k + 1) = v(k) + log%dy(k, j)
            end do
        end subroutine state_at

        !> Sphere k reaches (t, xk) and moves on at vk: the piece since its
        !> last vertex is written, unless it takes no time (two events at
        !> one instant: the later one's position and velocity are kept), and
        !> (t, xk) becomes its last vertex.
        subroutine vertex(k, t, xk, vk)
            integer, intent(in) :: k
            real(qp), intent(in) :: t, xk, vk
            if (t > t_from(k)) then
                if (n_pieces == batch) then
                    call write_rows(lines, pieces)
                    n_pieces = 0
                end if
                n_pieces = n_pieces + 1
                pieces(n_pieces) = row_t()
                call pieces(n_pieces)%add(k)
                call pieces(n_pieces)%add(t_from(k))
                call pieces(n_pieces)%add(x_from(k))
                call pieces(n_pieces)%add(t)
                call pieces(n_pieces)%add(xk)
                call pieces(n_pieces)%add(v_from(k))
                diagram%pieces = diagram%pieces + 1
            end if
            t_from(k) = t
            x_from(k) = xk
            v_from(k) = vk
        end subroutine vertex

    end subroutine write_events

    !> The key-value table of the scene, the run and the window.
    subroutine write_info(scene, run, diagram, unit)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(in) :: run
        type(spacetime_t), intent(in) :: diagram
        integer, intent(in) :: unit
        call pair("caption", caption(scene, run))
        call pair("p", itoa(scene%p))
        call pair("e", short_text(scene%e))
        call pair("d", short_text(scene%d))
        call pair("v0", short_text(scene%v0))
        call pair("status", status_word(run%status))
        call pair("collisions", itoa(run%n))
        call pair("collapses", itoa(run%limits%n))
        call pair("t_end", short_text(run%t_end))
        call pair("t_max", short_text(diagram%t_max))
        call pair("every", itoa(diagram%every))
        call pair("spheres_drawn", itoa(diagram%spheres))
        call pair("pieces", itoa(diagram%pieces))
        call pair("collisions_drawn", itoa(diagram%collisions))
        call pair("collapses_drawn", itoa(diagram%collapses))
    contains
        subroutine pair(key, value)
            character(len=*), intent(in) :: key, value
            write (unit, "(a)") key//tab//value
        end subroutine pair
    end subroutine write_info

end module sphere_row_spacetime
