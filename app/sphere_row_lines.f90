!> What sphere-row writes, said in one place: every line of the answer (its
!> name and what it means, in the order the lines come), every column of the
!> event table with its unit, and the units. `--help` prints them from here;
!> docs/cli.md's table of the lines lists the same names (make check-docs
!> compares the two). A new output line is one more entry in answer_lines.
module sphere_row_lines
    use sphere_row_cli, only: wrapped, help_width
    implicit none
    private
    public :: line_t, answer_lines, event_columns, output_help, line_names

    !> One line of the answer, or one column of the event table.
    type :: line_t
        !> The line's first word (`v<i>`: v1 ... vp), or the column's header.
        character(len=:), allocatable :: name
        !> What it holds; a unit in brackets: [L/V] a time, [V] a velocity,
        !> [L] a length.
        character(len=:), allocatable :: what
    end type line_t

    !> Column of `--help` where the meaning of a line starts.
    integer, parameter :: what_column = 24
    !> The longest name of a line (separation_not_excluded_below), and more.
    integer, parameter :: line_name_length = 40

contains

    pure function entry(name, what) result(line)
        character(len=*), intent(in) :: name, what
        type(line_t) :: line
        line%name = name
        line%what = what
    end function entry

    !> The answer's lines, `name value` each, in the order they are written.
    function answer_lines() result(lines)
        type(line_t), allocatable :: lines(:)
        lines = [ &
            entry("collisions", "binary collisions of the run"), &
            entry("t_end", "time of the last event, collision or collapse limit [L/V]"), &
            entry("t", "with t_max only: the time of the state below [L/V] (t_max, or the " &
            //"last event's where the budget ran out first)"), &
            entry("status", "normal (no pair closes any more), quasi_plastic (the " &
            //"definition's case: some group's velocities were taken to one; whether it " &
            //"collapsed is the `collapse` line's), max_collisions (the work budget was " &
            //"spent) or horizon (t_max reached with collisions still to come)"), &
            entry("precision", "the kind that answered: qp (real(16)) or dp (real(8))"), &
            entry("certified", "precision=auto only: yes where real(8)'s rounding " &
            //"certificate held"), &
            entry("not_dp", "precision=auto answered in real(16): why real(8) was not enough"), &
            entry("answer", "what holds in exact arithmetic (docs/collapse.md): exact (the " &
            //"row separated, or e = 0's pools), certified (collapse limits taken on a " &
            //"certificate that rests on no tolerance), tolerance (something rests on tol: " &
            //"a group merged because its gaps and rates fell below it, a closing rate " &
            //"below tol*v0 passed over or left at the end), bounded (a limit taken within " &
            //"vtol) or unresolved (the work budget ran out)"), &
            entry("v_bound", "the largest distance of a final velocity from exact " &
            //"arithmetic's [V]: the run's own rounding (a running bound of the arithmetic " &
            //"it did, along its collisions) plus, where the answer is not exact or " &
            //"certified, the answer's bound; the velocities are printed to its decade"), &
            entry("order", "not unresolved: proven where exact arithmetic's order of the " &
            //"collisions the answer rests on is proven (precision=auto's certificate, or " &
            //"the order check to the first limit, or to the end, in the kind that " &
            //"answered: docs/collapse.md), computed where the answer rests on the run's " &
            //"own order"), &
            entry("order_stopped_by", "order computed only: the decision that stopped the " &
            //"order check (or that it was not run: a wall, a ring, a horizon, given " &
            //"velocities, over 200 spheres, or its cost)"), &
            entry("rests_on", "answer tolerance or bounded: each premise that makes it so " &
            //"(limits_tolerance, passed_below_tol: a collision closing slower than tol*v0 " &
            //"passed over, closing_below_tol: a closing rate below tol*v0 left at the end, " &
            //"horizon_margin: a collision within rounding of t_max, limits_bounded)"), &
            entry("collapses", "with collapse limits: how many limits were taken"), &
            entry("closed_form_limits", "limits taken in closed form"), &
            entry("limits_exact", "limits that are exact (e = 0's pools)"), &
            entry("limits_certified", "limits taken on a certificate (a cycle's, a touching " &
            //"block's)"), &
            entry("limits_tolerance", "limits taken because gaps and rates fell below tol"), &
            entry("limits_bounded", "limits taken within vtol (a long cascade at one instant)"), &
            entry("collapse", "proven (every limit certified or exact, no collision passed " &
            //"over) or unproven"), &
            entry("separation_not_excluded_below", "collapse unproven only: 2 v_bound/v0, the " &
            //"scale of final rates inside a merged group that the bound allows; a " &
            //"separation below it is not excluded"), &
            entry("collapse_spheres", "the first group's first and last sphere, as 1-4"), &
            entry("collapse_t", "its time [L/V]"), &
            entry("separation_scale", "a row that separates far below v0 (answer exact): " &
            //"its largest final rate over v0"), &
            entry("active", "unresolved only: the groups still active, first-last sphere each"), &
            entry("v<i>", "final velocity of sphere i = 1 ... p [V], down to the decade of " &
            //"its own bound (its rounding included); 3E-02 or 0E-02: a velocity rounded at " &
            //"its bound's decade"), &
            entry("x<i>", "position of sphere i at t_end (or t) [L], every digit of the kind"), &
            entry("y<i>", "gap i = 1 ... p-1 (between spheres i and i+1) at t_end (or t) [L]; " &
            //"with a right wall or a ring also gap p (sphere p to the wall, or the ring's " &
            //"seam to sphere 1)") &
            ]
    end function answer_lines

    !> The names by which print= asks for the answer's lines, in their order:
    !> each line's name, `v` for every v<i> (so `x`, `y`).
    function line_names() result(names)
        character(len=line_name_length), allocatable :: names(:)
        type(line_t), allocatable :: lines(:)
        integer :: i, at
        lines = answer_lines()
        allocate (names(size(lines)))
        do i = 1, size(lines)
            at = index(lines(i)%name, "<i>")
            if (at > 0) then
                names(i) = lines(i)%name(:at - 1)
            else
                names(i) = lines(i)%name
            end if
        end do
    end function line_names

    !> The columns of the event table: the fixed ones, then y<i> and dy<i>
    !> for i = 1 ... p-1 (the header writes each with its unit).
    function event_columns() result(lines)
        type(line_t), allocatable :: lines(:)
        lines = [ &
            entry("event", "the event's number: 0 the start, then one more per collision " &
            //"or collapse limit"), &
            entry("kind", "start, collision or collapse"), &
            entry("first", "a collision's left sphere i (0: the left wall), a collapse's " &
            //"first sphere"), &
            entry("last", "a collision's right sphere i+1 (p+1: the right wall; 1 across a " &
            //"ring's seam), a collapse's last sphere"), &
            entry("t[L/V]", "time of the event"), &
            entry("w[V]", "a collision's approach rate: the rate of its gap just before it " &
            //"(negative; 0 for start and collapse)"), &
            entry("x1[L]", "position of sphere 1 after the event"), &
            entry("dx1[V]", "velocity of sphere 1 after the event"), &
            entry("y<i>[L]", "gap i after the event"), &
            entry("dy<i>[V]", "rate of gap i after the event (its spheres' velocity " &
            //"difference v(i+1) - v(i))") &
            ]
    end function event_columns

    !> The section of `--help` on what sphere-row writes: the answer's lines,
    !> the event table's columns and the units, each within help_width.
    function output_help() result(text)
        character(len=:), allocatable :: text
        character(len=*), parameter :: nl = new_line("a")
        text = "Output on stdout, one quantity per line as `name value`, in this order (a " &
            //"line" //nl//"shows only where it applies):"//nl//listed(answer_lines()) &
            //nl//wrapped("Event table (events=yes: on stdout before the answer; " &
            //"events=FILE.tsv: alone in that file, written as FILE.tsv.tmp and renamed " &
            //"when complete, no file if the run or a write fails): TSV, one header row " &
            //"naming each column with its unit, then one row per event:", 0, 0, help_width) &
            //nl//listed(event_columns()) &
            //nl//wrapped("Units: L is the unit of the lengths d, a and gaps, V the unit of " &
            //"the speed v0, L/V the unit of time (d = a = v0 = 1 by default). Reals carry " &
            //"every digit of the kind that answered: 34 significant digits in real(16), " &
            //"16 in real(8).", 0, 0, help_width)
    end function output_help

    !> `  name  what` per entry, the meaning wrapped under what_column.
    function listed(lines) result(text)
        type(line_t), intent(in) :: lines(:)
        character(len=:), allocatable :: text
        character(len=*), parameter :: nl = new_line("a")
        character(len=:), allocatable :: head
        integer :: i
        text = ""
        do i = 1, size(lines)
            head = "  "//lines(i)%name
            if (len(head) < what_column - 1) then
                head = head//repeat(" ", what_column - 1 - len(head))
            else
                head = head//nl//repeat(" ", what_column - 1)
            end if
            text = text//head//wrapped(lines(i)%what, what_column - 1, what_column - 1, &
                help_width)//nl
        end do
    end function listed

end module sphere_row_lines
