!> The critical restitution e_c(p) of the struck resting row of p equal
!> spheres (sphere 1 hits the row with v0, equal gaps a, diameter d): below it
!> the row collapses (infinitely many collisions in finite time), above it
!> every run ends after finitely many collisions.
!>
!> Two ways to it. (1) Simulation: the outcome of a run is told by the engine's
!> labelled answer (separated; a collapse proven in exact arithmetic; a merge
!> whose collapse is unproven, at tolerance or bounded; or undecided), never
!> by a collision count; a bisection locates the edge, and a fine scan of
!> e around it gives its two ends, the band where the outcomes mix, and the
!> digits each end earns (scan_edge, edge_of). (2) Rate map: the collisions of
!> a run just below e_c repeat one pattern; over one period the gap rates of
!> the pattern's group map linearly, w -> M(e) w, and a self-similar collapse
!> needs a real dominant eigenvalue of M. Where the two largest eigenvalues
!> merge into a complex pair the discriminant of det(M(e) - lambda) changes
!> sign: bisected in real(16), that is e_c of the pattern to the resolution of
!> the kind.
module sphere_row_ecrit
    use sphere_row, only: dp, qp, itoa, scene_t, run_t, event_log_t, scene_dp_t, run_dp_t, &
        simulate, status_normal, status_invalid, answer_exact, collapse_proven
    use sphere_row_analysis, only: rate_map, sequence_of
    use, intrinsic :: iso_fortran_env, only: int8
    implicit none
    private
    public :: outcome_finite, outcome_certified, outcome_unproven, outcome_undecided, n_outcomes
    public :: outcome_of, outcome_word, is_finite, outcome_changes
    public :: boundary_t, row_runner_t, runner_init, bisect_boundary, power_fit
    public :: collapse_cycle, group_map, char_poly, dominant_pair, dominant_is_real
    public :: rate_map_critical, closed_form_t, closed_form_search
    public :: ecrit_settings_t, ecrit_row_t, ecrit_row, mcnamara_young_k, &
        mcnamara_young_e, row_bytes, row_from_bytes, scan_point, edge_t, edge_of, digits_of, &
        decimal_text

    !> The run separated: it ended normally, no collapse limit taken, after
    !> finitely many collisions (its answer exact).
    integer, parameter :: outcome_finite = 1
    !> A collapse limit was taken and the collapse is proven in exact
    !> arithmetic: every limit exact or certified, no collision passed over.
    integer, parameter :: outcome_certified = 2
    !> A limit was taken whose collapse is not proven: at tolerance (the
    !> group's gaps and rates fell below tol, where a separation is not
    !> excluded) or bounded (its velocities known within vtol).
    integer, parameter :: outcome_unproven = 3
    !> No limit taken and the run did not separate: the work budget
    !> (max_collisions) was spent, or it ended at tolerance. Not decided.
    integer, parameter :: outcome_undecided = 4
    !> Number of outcome codes.
    integer, parameter :: n_outcomes = 4

    !> Bisection of the upper edge of the region that does not end finitely.
    type :: boundary_t
        !> Largest e seen that does not end finitely, and its outcome.
        real(qp) :: e_low = 0.0_qp
        integer :: outcome_low = outcome_undecided
        !> Smallest e above e_low seen to end finitely.
        real(qp) :: e_high = 1.0_qp
        !> Largest e seen with only exact or certified limits (-1 if none): the lower
        !> end of the bracket whose both ends the collapse machinery certifies.
        real(qp) :: e_certified = -1.0_qp
        !> Largest e seen with any collapse limit (-1 if none).
        real(qp) :: e_collapse = -1.0_qp
        !> Runs made by the bisection.
        integer :: steps = 0
    end type boundary_t

    !> Runs of the struck row of p equal spheres in one real kind (real64
    !> or real(16)) with a tolerance and a safety net: the outcome at any e.
    type :: row_runner_t
        !> dp or qp: which of the two scenes runs.
        integer :: precision = qp
        type(scene_t) :: scene
        type(run_t) :: run
        type(scene_dp_t) :: scene_dp
        type(run_dp_t) :: run_dp
    contains
        !> Run at e: its outcome and its number of collisions.
        procedure :: outcome => runner_outcome
    end type row_runner_t

    !> The outcome of a finished run of either kind.
    interface outcome_of
        module procedure outcome_of_qp, outcome_of_dp
    end interface outcome_of

    !> Length of the text of a closed form.
    integer, parameter :: form_text_len = 80

    !> A closed form found for a value: its text and its value in real(16).
    type :: closed_form_t
        !> True if a candidate matched.
        logical :: found = .false.
        !> The form, e.g. "tan^2(pi/12) = 7-4sqrt(3)" or "root of x^2-14x+1".
        character(len=form_text_len) :: text = "-"
        !> Its value in real(16).
        real(qp) :: value = 0.0_qp
    end type closed_form_t

    !> What ecrit_row does for each p; the defaults fit the whole study
    !> (p = 3 ... 64) into about a minute of one core.
    type :: ecrit_settings_t
        !> Points of the scan of e in (0, 1): e = j/n_grid, j = 1 ... n_grid-1.
        integer :: n_grid = 20
        !> Relative width to which the edge of the finite region is bisected,
        !> and the most runs the bisection may make.
        real(qp) :: resolution = 1.0e-10_qp
        integer :: max_steps = 40
        !> The coarse stage: its relative resolution and its tolerance
        !> (real64's sqrt(tiny): the smallest whose gaps do not underflow).
        real(qp) :: resolution_coarse = 1.0e-6_qp
        real(qp) :: tol_coarse = real(sqrt(tiny(1.0_dp)), qp)
        !> Rows up to this p get the fine stage, whose bracket is the coarse
        !> one widened by this relative margin on each side.
        integer :: p_fine = 6
        real(qp) :: fine_margin = 3.0e-2_qp
        !> The runs' insignificance tolerance (scene_t%tol): tiny, so that the
        !> fallback takes a limit only after the rates fell by its decades.
        real(qp) :: tol = 1.0e-4000_qp
        !> The engine's safety net: a run that reaches it undecided.
        integer :: max_collisions = 50000
        !> The safety net of the fine stage (its runs near e_c are long).
        integer :: max_collisions_fine = 1000000
        !> The scan of the edge: its points, its kind's tolerance and safety
        !> net, and its window, centred on the bisected edge e_b with a
        !> half-width of `window` (1 - e_b), doubled at most `widen_max` times
        !> while the outcomes reach an end of it (see scan_edge). Rows from
        !> p_long on take n_scan_long points: their collapse side is undecided
        !> within max_collisions_scan, so its points cost the whole budget and
        !> tell nothing more (measured with the defaults: p = 20 still decides
        !> its collapses at e = 0.690 and 0.697, p = 24 not at 0.725, 0.735).
        integer :: n_scan = 200, n_scan_long = 200, p_long = huge(1)
        !> The scan's tolerance: deep (1e-300), so that a point is called
        !> separated or certified from dynamics followed far below any rate a
        !> question of collapse turns on, and a merge at tol (unproven) is rare;
        !> from p_long on real(16)'s epsilon rounded up, at which a long row
        !> keeps its calendar of impacts (its collapses are undecided within
        !> max_collisions_scan whatever the tol: its scan tells separations).
        real(qp) :: tol_scan = 1.0e-300_qp, tol_scan_long = 2.0e-34_qp
        integer :: max_collisions_scan = 100000
        real(qp) :: window = 2.0e-2_qp
        integer :: widen_max = 3
        !> Rows up to this p are scanned again on the same points in real64
        !> at tol_scan and in real(16) at the deeper tol_deep: the band as a
        !> property of the row, not of the kind or the tolerance.
        integer :: robust_p_max = 10
        real(qp) :: tol_deep = 1.0e-4000_qp
        !> Rows up to this p also get e_c from the rate map of their cycle.
        integer :: map_p_max = 6
        !> Longest collision pattern looked for as the collapse cycle.
        integer :: period_max = 128
        !> Relative distance below the simulated edge of the run whose cycle
        !> is analysed, and the relative half-width of the window searched
        !> for the discriminant's sign change around the edge.
        real(qp) :: pattern_offset = 1.0e-3_qp
        real(qp) :: map_window = 1.0e-4_qp
    end type ecrit_settings_t

    !> Everything found for one p.
    type :: ecrit_row_t
        !> Number of spheres.
        integer :: p = 0
        !> The bisected edge of the finite region and the certified ends.
        type(boundary_t) :: b
        !> Changes between finite and not finite along the scan, and the scan
        !> points that reached max_collisions undecided.
        integer :: changes = 0, capped = 0
        !> Kind of the runs that gave the edge (dp or qp), and all runs made.
        integer :: precision = dp
        integer :: runs = 0
        !> The scan of the edge: its window [e_from, e_to] of size(outcomes)
        !> evenly spaced points and the doublings it took; each point's
        !> outcome and, if it separated, the decade of its separation scale
        !> (the largest final closing rate over v0; 0 otherwise). Rows up to
        !> robust_p_max also hold the outcomes of the same points in real64
        !> and at tol_deep (empty otherwise).
        real(qp) :: e_from = 0.0_qp, e_to = 0.0_qp
        integer :: widenings = 0
        integer, allocatable :: outcomes(:), decades(:), outcomes_dp(:), outcomes_deep(:)
        !> e_c from the rate map of the collapse cycle, if has_map.
        logical :: has_map = .false.
        real(qp) :: e_map = 0.0_qp
        !> The collapse cycle (gap indices) found below e_c, and where.
        integer, allocatable :: cycle(:)
        real(qp) :: e_pattern = 0.0_qp
        !> A closed form of e_map, if one was found.
        type(closed_form_t) :: form
    end type ecrit_row_t

    !> What a scan says of the edge (edge_of): the highest collapse and the
    !> lowest separation on it, each with the width of the interval it is
    !> known to within and the decimals that width earns; the mixed band
    !> between them where they cross; the counts of each outcome.
    type :: edge_t
        !> Highest point whose collapse is proven (-1 if none) and lowest that
        !> separated (2 if none); the interval [collapse_max, collapse_max +
        !> collapse_width] holds the top of the proven collapse set on this grid
        !> (unproven and undecided points above widen it), [finite_min -
        !> finite_width, finite_min] the bottom of the separating set; decimals
        !> of each, from those widths.
        real(qp) :: collapse_max = -1.0_qp, finite_min = 2.0_qp
        real(qp) :: collapse_width = 0.0_qp, finite_width = 0.0_qp
        integer :: collapse_digits = 0, finite_digits = 0
        !> Highest point whose collapse is certified (-1 if none): the same point
        !> as collapse_max (only a proven collapse counts as one), which the
        !> table writes once at its width's decimals and once with one more.
        real(qp) :: certified_max = -1.0_qp
        !> Highest point whose collapse is unproven (merged at tolerance or
        !> bounded, with its bound; -1 if none): where nothing is certified,
        !> the top of the collapse side the scan can state.
        real(qp) :: unproven_max = -1.0_qp
        !> True if finite_min < collapse_max: a proven collapse above a
        !> separation, outcomes mixing over that band of band_points points,
        !> band_collapses of them proven collapses.
        logical :: mixed = .false.
        integer :: band_points = 0, band_collapses = 0
        !> Points of each outcome (outcome_* order) over the whole window.
        integer :: counts(n_outcomes) = 0
        !> Decade of the separation scale of the lowest separated point.
        integer :: finite_decade = 0
    end type edge_t

    !> Largest integer coefficient of the candidate polynomials per degree
    !> (degrees 1 ... 4): kept small so the search stays a screen of a few
    !> million candidates.
    integer, parameter :: coef_bound(4) = [60, 40, 16, 8]
    !> Largest denominator k of the candidates tan^2(j pi/k).
    integer, parameter :: tan_denominator_max = 96
    !> Relative residual of the real64 screen of a candidate.
    real(dp), parameter :: screen_tol = 1.0e-11_dp
    !> Relative agreement that a closed form must reach (about 30 digits).
    real(qp), parameter :: closed_tol = 1.0e-29_qp
    !> Times a pattern must repeat at the end of a run to count as its cycle.
    integer, parameter :: cycle_repeats = 3
    !> Relative step at which the nature of the dominant eigenvalue is checked
    !> on either side of a rate-map e_c.
    real(qp), parameter :: probe_step = 1.0e-6_qp
    !> Iterations of the simultaneous root finder (Durand-Kerner).
    integer, parameter :: root_iterations = 2000
    !> The bytes of a row (row_bytes): its reals, its closed form's text, then
    !> its integers, whose count grows with its cycle.
    integer, parameter :: row_reals = 9, row_fixed_ints = 14
    integer, parameter :: row_text_bytes = form_text_len

contains

    !> e_c of the struck row of p equal spheres (a = d = v0 = 1) by the
    !> settings `s`. A coarse stage in real64 (fast, tolerance s%tol_coarse)
    !> scans e and bisects the edge of the finite region; for p <= s%p_fine a
    !> fine stage in real(16) with the tiny s%tol bisects it again from the
    !> coarse bracket widened by s%fine_margin. For p <= s%map_p_max the rate
    !> map of the collapse cycle with a search for its closed form. Last the
    !> scan of the edge (scan_edge) around the bisected bracket.
    subroutine ecrit_row(p, s, row)
        integer, intent(in) :: p
        type(ecrit_settings_t), intent(in) :: s
        type(ecrit_row_t), intent(out) :: row
        type(row_runner_t) :: coarse, fine
        type(event_log_t) :: log
        type(boundary_t) :: b_fine
        integer :: outcomes(s%n_grid - 1), j, top, stat, n, o_lo, o_hi
        real(qp) :: e_grid(s%n_grid - 1), e_lo, e_hi, w
        row%p = p
        call runner_init(coarse, p, dp, s%tol_coarse, s%max_collisions)
        ! 1. scan
        do j = 1, s%n_grid - 1
            e_grid(j) = real(j, qp)/s%n_grid
            call coarse%outcome(e_grid(j), outcomes(j), n)
        end do
        row%changes = outcome_changes([outcomes, outcome_finite])
        row%capped = count(outcomes == outcome_undecided)
        ! 2. the edge above the highest scan point that does not end finitely
        top = 0
        do j = s%n_grid - 1, 1, -1
            if (.not. is_finite(outcomes(j))) then
                top = j
                exit
            end if
        end do
        e_lo = 0.0_qp
        e_hi = e_grid(1)
        o_lo = outcome_undecided
        if (top > 0) then
            e_lo = e_grid(top)
            e_hi = 1.0_qp
            if (top < s%n_grid - 1) e_hi = e_grid(top + 1)
            o_lo = outcomes(top)
        end if
        do j = 1, top
            if (outcomes(j) == outcome_certified) row%b%e_certified = e_grid(j)
            if (outcomes(j) == outcome_certified .or. outcomes(j) == outcome_unproven) then
                row%b%e_collapse = e_grid(j)
            end if
        end do
        call bisect_boundary(coarse, e_lo, e_hi, o_lo, s%resolution_coarse, s%max_steps, row%b)
        row%precision = dp
        row%runs = s%n_grid - 1 + row%b%steps
        ! 3. the fine stage from the widened coarse bracket, if its ends hold
        if (p <= s%p_fine) then
            call runner_init(fine, p, qp, s%tol, s%max_collisions_fine)
            e_lo = row%b%e_low*(1.0_qp - s%fine_margin)
            e_hi = min(1.0_qp, row%b%e_high*(1.0_qp + s%fine_margin))
            call fine%outcome(e_lo, o_lo, n)
            call fine%outcome(e_hi, o_hi, n)
            row%runs = row%runs + 2
            if (.not. is_finite(o_lo) .and. is_finite(o_hi)) then
                b_fine%e_certified = row%b%e_certified
                b_fine%e_collapse = row%b%e_collapse
                call bisect_boundary(fine, e_lo, e_hi, o_lo, s%resolution, s%max_steps, b_fine)
                row%b = b_fine
                row%precision = qp
                row%runs = row%runs + b_fine%steps
            end if
        end if
        ! 4. e_c from the rate map of the cycle of a run just below the edge
        allocate (row%cycle(0))
        if (p <= s%map_p_max) then
            if (.not. allocated(fine%scene%m)) then
                call runner_init(fine, p, qp, s%tol, s%max_collisions_fine)
            end if
            row%e_pattern = row%b%e_low*(1.0_qp - s%pattern_offset)
            fine%scene%e = row%e_pattern
            call simulate(fine%scene, fine%run, log)
            call cycle_of(log, row%cycle)
            w = s%map_window*row%b%e_high
            call rate_map_critical(fine%scene%m, row%cycle, row%b%e_low - w, &
                row%b%e_high + w, probe_step*row%b%e_high, row%e_map, stat)
            row%has_map = stat == status_normal
            if (row%has_map) call closed_form_search(row%e_map, closed_tol, row%form)
        end if
        ! 5. the scan of the edge
        call scan_edge(p, s, row)

    contains

        !> The cycle of the logged run, from all its collisions before the
        !> first collapse (a certified limit follows its cycle to the end),
        !> else from their first three quarters (a fallback limit can end in a
        !> transient); a pattern counts once it repeats cycle_repeats times.
        subroutine cycle_of(events, cycle)
            type(event_log_t), intent(in) :: events
            integer, allocatable, intent(out) :: cycle(:)
            integer, allocatable :: pairs(:)
            integer :: n_kept, part
            integer, parameter :: parts(2, 2) = reshape([1, 1, 3, 4], [2, 2])
            call sequence_of(events, pairs, before_collapse=.true.)
            do part = 1, size(parts, 2)
                n_kept = parts(1, part)*size(pairs)/parts(2, part)
                call collapse_cycle(pairs(:n_kept), cycle_repeats, s%period_max, cycle)
                if (size(cycle) > 0) return
            end do
        end subroutine cycle_of

    end subroutine ecrit_row

    !> The scan of the edge: s%n_scan evenly spaced points (s%n_scan_long from
    !> p = s%p_long on) over a window
    !> centred on the bisected edge e_b with half-width s%window (1 - e_b),
    !> each run in real(16) at s%tol_scan (s%tol_scan_long from p = s%p_long
    !> on) and decided by its labelled answer
    !> (outcome_of). Where a separated point lies in the window's lowest tenth
    !> or a collapse in its highest, the band may reach past the window: its
    !> half-width doubles, at most s%widen_max times. Rows up to
    !> s%robust_p_max run the same points again in real64 at s%tol_scan and in
    !> real(16) at s%tol_deep.
    subroutine scan_edge(p, s, row)
        integer, intent(in) :: p
        type(ecrit_settings_t), intent(in) :: s
        type(ecrit_row_t), intent(inout) :: row
        type(row_runner_t) :: runner
        real(qp) :: centre, half
        integer :: n, tenth, lowest, highest, k
        centre = row%b%e_high
        half = s%window*(1.0_qp - centre)
        n = s%n_scan
        if (p >= s%p_long) n = s%n_scan_long
        tenth = max(1, n/10)
        if (p < s%p_long) then
            call runner_init(runner, p, qp, s%tol_scan, s%max_collisions_scan)
        else
            call runner_init(runner, p, qp, s%tol_scan_long, s%max_collisions_scan)
        end if
        do k = 0, s%widen_max
            row%widenings = k
            row%e_from = max(centre - half, 0.0_qp)
            row%e_to = min(centre + half, 0.5_qp*(1.0_qp + centre))
            call scan_points(runner, row%outcomes, row%decades)
            lowest = findloc(row%outcomes, outcome_finite, dim=1)
            highest = findloc(row%outcomes, outcome_certified, dim=1, back=.true.)
            if ((lowest == 0 .or. lowest > tenth) .and. highest <= n - tenth) exit
            if (row%e_from <= 0.0_qp) exit
            half = 2.0_qp*half
        end do
        allocate (row%outcomes_dp(0), row%outcomes_deep(0))
        if (p > s%robust_p_max) return
        call runner_init(runner, p, dp, s%tol_scan, s%max_collisions_scan)
        call scan_points(runner, row%outcomes_dp)
        call runner_init(runner, p, qp, s%tol_deep, s%max_collisions_scan)
        call scan_points(runner, row%outcomes_deep)

    contains

        !> The outcome of every point of the window by `run`, and the decade
        !> of each separation scale.
        subroutine scan_points(run, outcomes, decades)
            type(row_runner_t), intent(inout) :: run
            integer, allocatable, intent(out) :: outcomes(:)
            integer, allocatable, intent(out), optional :: decades(:)
            real(qp) :: scale, e
            integer :: j, collisions
            allocate (outcomes(n))
            if (present(decades)) allocate (decades(n), source=0)
            do j = 1, n
                e = grid_point(row%e_from, row%e_to, n, j)
                call run%outcome(e, outcomes(j), collisions)
                row%runs = row%runs + 1
                if (.not. present(decades) .or. outcomes(j) /= outcome_finite) cycle
                scale = maxval(abs(run%run%dy))
                if (scale > 0.0_qp) decades(j) = floor(log10(scale))
                if (scale <= 0.0_qp) decades(j) = floor(log10(tiny(scale)))
            end do
        end subroutine scan_points

    end subroutine scan_edge

    !> Point j of the row's scan window.
    pure real(qp) function scan_point(row, j) result(e)
        type(ecrit_row_t), intent(in) :: row
        integer, intent(in) :: j
        e = grid_point(row%e_from, row%e_to, size(row%outcomes), j)
    end function scan_point

    !> Point j of n evenly spaced points from e_from to e_to: the one formula
    !> of the scan's runs, its edge and its tables.
    pure real(qp) function grid_point(e_from, e_to, n, j) result(e)
        real(qp), intent(in) :: e_from, e_to
        integer, intent(in) :: n, j
        e = e_from + (e_to - e_from)*real(j - 1, qp)/real(n - 1, qp)
    end function grid_point

    !> The edge told by a scan of `outcomes` at evenly spaced points e_from
    !> ... e_to (see edge_t). The spacing h bounds each edge: the top of the
    !> collapse set lies below the next point above collapse_max that did not
    !> collapse and is not undecided, the bottom of the separating set above
    !> the point below finite_min that is not undecided.
    pure function edge_of(e_from, e_to, outcomes, decades) result(edge)
        real(qp), intent(in) :: e_from, e_to
        integer, intent(in) :: outcomes(:), decades(:)
        type(edge_t) :: edge
        real(qp) :: h
        integer :: n, i_c, j_c, i_f, j_f, k
        logical :: collapse(size(outcomes))
        n = size(outcomes)
        h = (e_to - e_from)/real(n - 1, qp)
        do k = 1, n_outcomes
            edge%counts(k) = count(outcomes == k)
        end do
        collapse = outcomes == outcome_certified
        i_c = findloc(collapse, .true., dim=1, back=.true.)
        i_f = findloc(outcomes, outcome_finite, dim=1)
        k = findloc(outcomes, outcome_certified, dim=1, back=.true.)
        if (k > 0) edge%certified_max = at(k)
        k = findloc(outcomes, outcome_unproven, dim=1, back=.true.)
        if (k > 0) edge%unproven_max = at(k)
        if (i_c > 0) then
            j_c = i_c
            do while (j_c < n)
                if (outcomes(j_c + 1) == outcome_finite) exit
                j_c = j_c + 1
            end do
            edge%collapse_max = at(i_c)
            edge%collapse_width = at(j_c) + h - at(i_c)
            edge%collapse_digits = digits_of(edge%collapse_width)
        end if
        if (i_f > 0) then
            j_f = i_f
            do while (j_f > 1)
                if (collapse(j_f - 1)) exit
                j_f = j_f - 1
            end do
            edge%finite_min = at(i_f)
            edge%finite_width = at(i_f) - at(j_f) + h
            edge%finite_digits = digits_of(edge%finite_width)
            edge%finite_decade = decades(i_f)
        end if
        edge%mixed = i_c > 0 .and. i_f > 0 .and. i_f < i_c
        if (edge%mixed) then
            edge%band_points = i_c - i_f + 1
            edge%band_collapses = count(collapse(i_f:i_c))
        end if

    contains

        pure real(qp) function at(j)
            integer, intent(in) :: j
            at = grid_point(e_from, e_to, n, j)
        end function at

    end function edge_of

    !> Decimals earned by a value known to within `width`: down to the place
    !> of the width's leading digit (at least 1), so that the last decimal
    !> written is the first uncertain one.
    elemental integer function digits_of(width) result(digits)
        real(qp), intent(in) :: width
        digits = 1
        if (width > 0.0_qp) digits = max(1, -floor(log10(width)))
    end function digits_of

    !> x rounded to `decimals` places, as text (0.3972).
    function decimal_text(x, decimals) result(text)
        real(qp), intent(in) :: x
        integer, intent(in) :: decimals
        character(len=:), allocatable :: text
        character(len=64) :: buffer
        write (buffer, "(f0."//itoa(decimals)//")") x
        text = trim(adjustl(buffer))
        if (text(1:1) == ".") text = "0"//text
    end function decimal_text
    !> The row as bytes, every number with all its bits (to move it between
    !> processes; row_from_bytes reads it back).
    pure function row_bytes(row) result(bytes)
        type(ecrit_row_t), intent(in) :: row
        integer(int8), allocatable :: bytes(:)
        real(qp) :: reals(row_reals)
        integer, allocatable :: ints(:)
        integer(int8), parameter :: mold(1) = 0_int8
        reals = [row%b%e_low, row%b%e_high, row%b%e_certified, row%b%e_collapse, row%e_from, &
            row%e_to, row%e_map, row%e_pattern, row%form%value]
        ints = [row%p, row%b%outcome_low, row%b%steps, row%changes, row%capped, row%precision, &
            row%runs, row%widenings, merge(1, 0, row%has_map), merge(1, 0, row%form%found), &
            size(row%cycle), size(row%outcomes), size(row%outcomes_dp), size(row%outcomes_deep), &
            row%cycle, row%outcomes, row%decades, row%outcomes_dp, row%outcomes_deep]
        bytes = [transfer(reals, mold), transfer(row%form%text, mold), transfer(ints, mold)]
    end function row_bytes

    !> The row written by row_bytes; `stat` is status_invalid if the bytes
    !> are not the length of one.
    pure subroutine row_from_bytes(bytes, row, stat)
        integer(int8), intent(in) :: bytes(:)
        type(ecrit_row_t), intent(out) :: row
        integer, intent(out) :: stat
        real(qp) :: reals(row_reals)
        integer, allocatable :: ints(:)
        integer :: real_bytes, int_bytes, n_ints, k, sizes(4)
        stat = status_invalid
        real_bytes = size(transfer(reals, [0_int8]))
        int_bytes = size(transfer(0, [0_int8]))
        if (size(bytes) < real_bytes + row_text_bytes + row_fixed_ints*int_bytes) return
        if (mod(size(bytes) - real_bytes - row_text_bytes, int_bytes) /= 0) return
        n_ints = (size(bytes) - real_bytes - row_text_bytes)/int_bytes
        reals = transfer(bytes(:real_bytes), reals)
        row%form%text = transfer(bytes(real_bytes + 1:real_bytes + row_text_bytes), row%form%text)
        allocate (ints(n_ints))
        ints = transfer(bytes(real_bytes + row_text_bytes + 1:), ints)
        sizes = ints(row_fixed_ints - 3:row_fixed_ints)
        if (any(sizes < 0) .or. any(sizes > n_ints)) return
        if (sum(sizes) + sizes(2) /= n_ints - row_fixed_ints) return
        row%b%e_low = reals(1)
        row%b%e_high = reals(2)
        row%b%e_certified = reals(3)
        row%b%e_collapse = reals(4)
        row%e_from = reals(5)
        row%e_to = reals(6)
        row%e_map = reals(7)
        row%e_pattern = reals(8)
        row%form%value = reals(9)
        row%p = ints(1)
        row%b%outcome_low = ints(2)
        row%b%steps = ints(3)
        row%changes = ints(4)
        row%capped = ints(5)
        row%precision = ints(6)
        row%runs = ints(7)
        row%widenings = ints(8)
        row%has_map = ints(9) == 1
        row%form%found = ints(10) == 1
        k = row_fixed_ints
        row%cycle = ints(k + 1:k + sizes(1))
        k = k + sizes(1)
        row%outcomes = ints(k + 1:k + sizes(2))
        k = k + sizes(2)
        row%decades = ints(k + 1:k + sizes(2))
        k = k + sizes(2)
        row%outcomes_dp = ints(k + 1:k + sizes(3))
        k = k + sizes(3)
        row%outcomes_deep = ints(k + 1:k + sizes(4))
        stat = status_normal
    end subroutine row_from_bytes

    !> The struck row of p equal spheres (a = d = v0 = 1) in kind `precision`,
    !> insignificance tolerance `tol` and safety net `max_collisions`.
    pure subroutine runner_init(runner, p, precision, tol, max_collisions)
        type(row_runner_t), intent(out) :: runner
        integer, intent(in) :: p, precision, max_collisions
        real(qp), intent(in) :: tol
        runner%precision = precision
        runner%scene%p = p
        runner%scene%tol = tol
        runner%scene%max_collisions = max_collisions
        allocate (runner%scene%m(p), source=1.0_qp)
        allocate (runner%scene%a(p - 1), source=1.0_qp)
        runner%scene_dp%p = p
        runner%scene_dp%tol = real(tol, dp)
        runner%scene_dp%max_collisions = max_collisions
        allocate (runner%scene_dp%m(p), source=1.0_dp)
        allocate (runner%scene_dp%a(p - 1), source=1.0_dp)
    end subroutine runner_init

    !> Run at e in the runner's kind; `n` is the number of collisions.
    subroutine runner_outcome(self, e, outcome, n)
        class(row_runner_t), intent(inout) :: self
        real(qp), intent(in) :: e
        integer, intent(out) :: outcome, n
        if (self%precision == dp) then
            self%scene_dp%e = real(e, dp)
            call simulate(self%scene_dp, self%run_dp)
            outcome = outcome_of(self%run_dp)
            n = self%run_dp%n
        else
            self%scene%e = e
            call simulate(self%scene, self%run)
            outcome = outcome_of(self%run)
            n = self%run%n
        end if
    end subroutine runner_outcome

    !> The constant K of the McNamara-Young scaling p = K (-ln(1-e_c))/(1-e_c)
    !> by least squares through the origin over the rows with use(j).
    pure real(qp) function mcnamara_young_k(p, e_c, use) result(k)
        integer, intent(in) :: p(:)
        real(qp), intent(in) :: e_c(:)
        logical, intent(in) :: use(:)
        real(qp) :: g(size(p))
        g = -log(1.0_qp - e_c)/(1.0_qp - e_c)
        k = sum(merge(p*g, 0.0_qp, use))/sum(merge(g**2, 0.0_qp, use))
    end function mcnamara_young_k

    !> The e_c of the McNamara-Young scaling for p spheres: the root in (0, 1)
    !> of K (-ln(1-e))/(1-e) = p (the left side grows with e), bisected.
    pure real(qp) function mcnamara_young_e(p, k) result(e)
        integer, intent(in) :: p
        real(qp), intent(in) :: k
        real(qp) :: lo, hi
        lo = 0.0_qp
        hi = 1.0_qp
        do
            e = 0.5_qp*(lo + hi)
            if (e <= lo .or. e >= hi) exit
            if (k*(-log(1.0_qp - e))/(1.0_qp - e) < p) then
                lo = e
            else
                hi = e
            end if
        end do
    end function mcnamara_young_e

    !> The outcome of a finished real(16) run (one of the outcome_* codes).
    pure integer function outcome_of_qp(run) result(outcome)
        type(run_t), intent(in) :: run
        outcome = outcome_code(run%limits%n, collapse_proven(run), run%status, run%answer)
    end function outcome_of_qp

    !> The outcome of a finished real64 run.
    pure integer function outcome_of_dp(run) result(outcome)
        type(run_dp_t), intent(in) :: run
        outcome = outcome_code(run%limits%n, collapse_proven(run), run%status, run%answer)
    end function outcome_of_dp

    !> The outcome told by a run's labelled answer: a collapse where a limit
    !> was taken (proven where no limit rests on tol or vtol and no collision
    !> was passed over, else unproven), a separation where it ended normally
    !> with an exact answer and no limit, else undecided (the budget spent,
    !> or the rates fell below tol without a limit).
    pure integer function outcome_code(collapses, proven, status, answer) result(outcome)
        integer, intent(in) :: collapses, status, answer
        logical, intent(in) :: proven
        if (collapses > 0) then
            if (proven) then
                outcome = outcome_certified
            else
                outcome = outcome_unproven
            end if
        else if (status == status_normal .and. answer == answer_exact) then
            outcome = outcome_finite
        else
            outcome = outcome_undecided
        end if
    end function outcome_code

    !> The word of an outcome in tables.
    pure function outcome_word(outcome) result(word)
        integer, intent(in) :: outcome
        character(len=:), allocatable :: word
        select case (outcome)
        case (outcome_finite)
            word = "separated"
        case (outcome_certified)
            word = "certified"
        case (outcome_unproven)
            word = "unproven"
        case default
            word = "undecided"
        end select
    end function outcome_word

    !> Whether the outcome is a finite run.
    elemental logical function is_finite(outcome)
        integer, intent(in) :: outcome
        is_finite = outcome == outcome_finite
    end function is_finite

    !> Number of changes between finite and not finite along a scan.
    pure integer function outcome_changes(outcomes) result(changes)
        integer, intent(in) :: outcomes(:)
        integer :: j
        changes = 0
        do j = 2, size(outcomes)
            if (is_finite(outcomes(j)) .neqv. is_finite(outcomes(j - 1))) changes = changes + 1
        end do
    end function outcome_changes

    !> Bisect between e_lo (does not end finitely, outcome `outcome_lo`) and
    !> e_hi (ends finitely) until the bracket is at most `resolution` times
    !> e_hi wide or `max_steps` runs were made, each by `runner`.
    subroutine bisect_boundary(runner, e_lo, e_hi, outcome_lo, resolution, max_steps, b)
        type(row_runner_t), intent(inout) :: runner
        real(qp), intent(in) :: e_lo, e_hi, resolution
        integer, intent(in) :: outcome_lo, max_steps
        type(boundary_t), intent(inout) :: b
        real(qp) :: mid
        integer :: outcome, n
        b%e_low = e_lo
        b%outcome_low = outcome_lo
        b%e_high = e_hi
        b%steps = 0
        call note(e_lo, outcome_lo)
        do while (b%e_high - b%e_low > resolution*b%e_high .and. b%steps < max_steps)
            mid = 0.5_qp*(b%e_low + b%e_high)
            if (mid <= b%e_low .or. mid >= b%e_high) exit
            call runner%outcome(mid, outcome, n)
            b%steps = b%steps + 1
            call note(mid, outcome)
            if (is_finite(outcome)) then
                b%e_high = mid
            else
                b%e_low = mid
                b%outcome_low = outcome
            end if
        end do

    contains

        !> Keep the largest e of each kind of collapse.
        subroutine note(e, o)
            real(qp), intent(in) :: e
            integer, intent(in) :: o
            if (o == outcome_certified) b%e_certified = max(b%e_certified, e)
            if (o == outcome_certified .or. o == outcome_unproven) then
                b%e_collapse = max(b%e_collapse, e)
            end if
        end subroutine note

    end subroutine bisect_boundary

    !> Least squares of log y = log c + slope log x over the points with
    !> use(j); `n_used` of them (slope and c are 0 if fewer than two).
    pure subroutine power_fit(x, y, use, c, slope, n_used)
        real(qp), intent(in) :: x(:), y(:)
        logical, intent(in) :: use(:)
        real(qp), intent(out) :: c, slope
        integer, intent(out) :: n_used
        real(qp) :: sx, sy, sxx, sxy, lx, ly
        integer :: j
        sx = 0.0_qp
        sy = 0.0_qp
        sxx = 0.0_qp
        sxy = 0.0_qp
        n_used = 0
        c = 0.0_qp
        slope = 0.0_qp
        do j = 1, size(x)
            if (.not. use(j)) cycle
            lx = log(x(j))
            ly = log(y(j))
            sx = sx + lx
            sy = sy + ly
            sxx = sxx + lx**2
            sxy = sxy + lx*ly
            n_used = n_used + 1
        end do
        if (n_used < 2) return
        if (n_used*sxx - sx**2 <= 0.0_qp) return
        slope = (n_used*sxy - sx*sy)/(n_used*sxx - sx**2)
        c = exp((sy - slope*sx)/n_used)
    end subroutine power_fit

    !> The collapse cycle of a collision sequence: the shortest pattern of at
    !> most `period_max` collisions that its end repeats `repeats` times in a
    !> row. `cycle` has size 0 if there is none.
    pure subroutine collapse_cycle(pairs, repeats, period_max, cycle)
        integer, intent(in) :: pairs(:), repeats, period_max
        integer, allocatable, intent(out) :: cycle(:)
        integer :: n, q
        n = size(pairs)
        do q = 1, min(period_max, n/repeats)
            if (all(pairs(n - (repeats - 1)*q + 1:) == pairs(n - repeats*q + 1:n - q))) then
                cycle = pairs(n - q + 1:)
                return
            end if
        end do
        allocate (cycle(0))
    end subroutine collapse_cycle

    !> The rate map of one period of `cycle` on the gaps it touches, lo..hi
    !> (spheres lo..hi+1, masses m): a of size (hi-lo+1, hi-lo+1). The impulses
    !> given to the gaps outside do not come back into the group.
    pure subroutine group_map(m, e, cycle, a)
        real(qp), intent(in) :: m(:), e
        integer, intent(in) :: cycle(:)
        real(qp), allocatable, intent(out) :: a(:, :)
        real(qp) :: full(size(m) - 1, size(m) - 1)
        integer :: lo, hi
        call rate_map(m, e, cycle, full)
        lo = minval(cycle)
        hi = maxval(cycle)
        a = full(lo:hi, lo:hi)
    end subroutine group_map

    !> Coefficients c(0:q) of det(lambda I - a) = sum_k c(k) lambda^k (c(q) =
    !> 1), by the Faddeev-LeVerrier recursion (q is small here and real(16)
    !> leaves room for its growth of rounding).
    pure subroutine char_poly(a, c)
        real(qp), intent(in) :: a(:, :)
        real(qp), intent(out) :: c(0:)
        real(qp) :: mk(size(a, 1), size(a, 1)), am(size(a, 1), size(a, 1))
        integer :: q, k, i
        q = size(a, 1)
        c(q) = 1.0_qp
        mk = 0.0_qp
        do k = 1, q
            ! M_k = A M_{k-1} + c_{q-k+1} I, c_{q-k} = -tr(A M_k)/k
            am = matmul(a, mk)
            do i = 1, q
                am(i, i) = am(i, i) + c(q - k + 1)
            end do
            mk = am
            am = matmul(a, mk)
            c(q - k) = 0.0_qp
            do i = 1, q
                c(q - k) = c(q - k) - am(i, i)
            end do
            c(q - k) = c(q - k)/k
        end do
    end subroutine char_poly

    !> The quadratic factor x^2 + u x + v of the monic polynomial sum c(k)
    !> x^k that holds its two roots of largest modulus, refined in place from
    !> a guess by Bairstow's method (Newton's method on u, v for a zero
    !> remainder). Unlike the two roots, the factor stays well conditioned
    !> where they meet, so u^2 - 4v changes sign there with the accuracy of
    !> the coefficients.
    pure subroutine dominant_pair(c, u, v)
        real(qp), intent(in) :: c(0:)
        real(qp), intent(inout) :: u, v
        real(qp) :: b(0:ubound(c, 1)), d(0:ubound(c, 1) + 1), du, dv, det
        integer :: q, k, it
        integer, parameter :: bairstow_steps = 100
        q = ubound(c, 1)
        if (q == 2) then
            u = c(1)
            v = c(0)
            return
        end if
        do it = 1, bairstow_steps
            b(q) = c(q)
            b(q - 1) = c(q - 1) - u*b(q)
            do k = q - 2, 0, -1
                b(k) = c(k) - u*b(k + 1) - v*b(k + 2)
            end do
            d(q + 1) = 0.0_qp
            d(q) = b(q)
            d(q - 1) = b(q - 1) - u*d(q)
            do k = q - 2, 1, -1
                d(k) = b(k) - u*d(k + 1) - v*d(k + 2)
            end do
            det = d(1)*d(3) - d(2)**2
            if (det == 0.0_qp) exit
            du = (b(0)*d(3) - b(1)*d(2))/det
            dv = (d(1)*b(1) - d(2)*b(0))/det
            u = u + du
            v = v + dv
            if (abs(du) <= epsilon(u)*abs(u) .and. abs(dv) <= epsilon(v)*abs(v)) exit
        end do
    end subroutine dominant_pair

    !> Roots of the monic polynomial sum c(k) x^k by the Durand-Kerner
    !> iteration in complex real(16), from points on a circle off the axis.
    pure subroutine poly_roots(c, z)
        real(qp), intent(in) :: c(0:)
        complex(qp), intent(out) :: z(:)
        complex(qp) :: num, den
        real(qp), parameter :: pi = acos(-1.0_qp), start_angle = 0.4_qp
        real(qp) :: radius
        integer :: q, it, i, j, k
        q = ubound(c, 1)
        radius = 1.0_qp + maxval(abs(c(:q - 1)))
        do i = 1, q
            z(i) = radius*exp(cmplx(0.0_qp, start_angle + 2*pi*(i - 1)/q, qp))
        end do
        do it = 1, root_iterations
            do i = 1, q
                num = c(q)
                do k = q - 1, 0, -1
                    num = num*z(i) + c(k)
                end do
                den = 1.0_qp
                do j = 1, q
                    if (j /= i) den = den*(z(i) - z(j))
                end do
                z(i) = z(i) - num/den
            end do
        end do
    end subroutine poly_roots

    !> Whether the eigenvalue of largest modulus of the polynomial sum c(k)
    !> x^k (monic) is real: roots by Durand-Kerner in complex real(16), a root
    !> counted real if its imaginary part is below `imag_tol` times its modulus.
    pure logical function dominant_is_real(c, imag_tol) result(real_dominant)
        real(qp), intent(in) :: c(0:), imag_tol
        complex(qp) :: z(ubound(c, 1))
        integer :: k
        call poly_roots(c, z)
        k = maxloc(abs(z), 1)
        real_dominant = abs(aimag(z(k))) <= imag_tol*abs(z(k))
    end function dominant_is_real

    !> The restitution in [e_lo, e_hi] where the two dominant eigenvalues of
    !> the group rate map of `cycle` (masses m) merge, from real below to a
    !> complex pair above: the sign change of u^2 - 4v of their quadratic
    !> factor (dominant_pair), bisected to the resolution of real(16). `stat`
    !> is status_invalid if it does not change sign in the bracket, or if the
    !> dominant eigenvalue is not real a step `probe` below the point found
    !> and complex a step above it (roots by poly_roots).
    subroutine rate_map_critical(m, cycle, e_lo, e_hi, probe, e_c, stat)
        real(qp), intent(in) :: m(:), e_lo, e_hi, probe
        integer, intent(in) :: cycle(:)
        real(qp), intent(out) :: e_c
        integer, intent(out) :: stat
        real(qp) :: lo, hi, mid, d_lo, u, v
        real(qp), allocatable :: c(:)
        complex(qp), allocatable :: z(:)
        logical, allocatable :: others(:)
        real(qp), parameter :: imag_tol = 1.0e-12_qp
        integer :: k1, k2
        e_c = 0.0_qp
        stat = status_invalid
        if (size(cycle) == 0) return
        if (maxval(cycle) == minval(cycle)) return
        allocate (c(0:maxval(cycle) - minval(cycle) + 1), z(maxval(cycle) - minval(cycle) + 1), &
            others(maxval(cycle) - minval(cycle) + 1))
        lo = e_lo
        hi = e_hi
        ! the dominant pair's factor at e_lo from all roots, then followed
        call coefficients(lo)
        call poly_roots(c, z)
        others = .true.
        k1 = maxloc(abs(z), 1)
        others(k1) = .false.
        k2 = maxloc(abs(z), 1, mask=others)
        u = -real(z(k1) + z(k2), qp)
        v = real(z(k1)*z(k2), qp)
        d_lo = pair_disc(lo)
        if (sign(1.0_qp, d_lo) == sign(1.0_qp, pair_disc(hi))) return
        do
            mid = 0.5_qp*(lo + hi)
            if (mid <= lo .or. mid >= hi) exit
            if (sign(1.0_qp, pair_disc(mid)) == sign(1.0_qp, d_lo)) then
                lo = mid
            else
                hi = mid
            end if
        end do
        e_c = 0.5_qp*(lo + hi)
        call coefficients(e_c - probe)
        if (.not. dominant_is_real(c, imag_tol)) return
        call coefficients(e_c + probe)
        if (dominant_is_real(c, imag_tol)) return
        stat = status_normal

    contains

        !> The characteristic polynomial at e into c.
        subroutine coefficients(e)
            real(qp), intent(in) :: e
            real(qp), allocatable :: a(:, :)
            call group_map(m, e, cycle, a)
            call char_poly(a, c)
        end subroutine coefficients

        !> u^2 - 4v of the dominant pair at e, followed from the last (u, v).
        real(qp) function pair_disc(e)
            real(qp), intent(in) :: e
            call coefficients(e)
            call dominant_pair(c, u, v)
            pair_disc = u**2 - 4*v
        end function pair_disc

    end subroutine rate_map_critical

    !> Simple closed forms of x in (0, 1) that agree with it to `rel_tol`
    !> relative: tan^2(j pi/k) with k <= tan_denominator_max, then the roots
    !> in (0, 1) of integer polynomials of degree 1 ... 4 with coefficients
    !> bounded by coef_bound (screened in real64, the candidate's root then
    !> polished by Newton's method in real(16) and compared). The first match
    !> is returned, the lowest degree first.
    subroutine closed_form_search(x, rel_tol, form)
        real(qp), intent(in) :: x, rel_tol
        type(closed_form_t), intent(out) :: form
        real(qp), parameter :: pi = acos(-1.0_qp)
        real(qp) :: t
        integer :: j, k, degree
        do k = 3, tan_denominator_max
            do j = 1, (k - 1)/2
                if (gcd(j, k) /= 1) cycle
                t = tan(j*pi/k)**2
                if (abs(t - x) <= rel_tol*x) then
                    form%found = .true.
                    form%value = t
                    if (j == 1) then
                        write (form%text, "(a, i0, a)") "tan^2(pi/", k, ")"
                    else
                        write (form%text, "(a, i0, a, i0, a)") "tan^2(", j, "pi/", k, ")"
                    end if
                    return
                end if
            end do
        end do
        do degree = 1, size(coef_bound)
            call polynomial_search(x, degree, coef_bound(degree), rel_tol, form)
            if (form%found) return
        end do
    end subroutine closed_form_search

    !> An integer polynomial of `degree` with coefficients in [-bound, bound]
    !> and a root that matches x (see closed_form_search).
    subroutine polynomial_search(x, degree, bound, rel_tol, form)
        real(qp), intent(in) :: x, rel_tol
        integer, intent(in) :: degree, bound
        type(closed_form_t), intent(inout) :: form
        integer :: coef(0:degree), total, idx, i, rest
        real(dp) :: xd, powers(0:degree), value, scale
        real(qp) :: root
        xd = real(x, dp)
        do i = 0, degree
            powers(i) = xd**i
        end do
        total = (2*bound + 1)**(degree + 1)
        do idx = 0, total - 1
            rest = idx
            do i = 0, degree
                coef(i) = mod(rest, 2*bound + 1) - bound
                rest = rest/(2*bound + 1)
            end do
            ! leading coefficient > 0 and no common factor: each polynomial once
            if (coef(degree) <= 0) cycle
            value = sum(coef*powers)
            scale = sum(abs(coef*powers))
            if (abs(value) > screen_tol*scale) cycle
            if (gcd_all(coef) /= 1) cycle
            root = newton_root(coef, x)
            if (abs(root - x) <= rel_tol*x) then
                form%found = .true.
                form%value = root
                form%text = "root of "//poly_text(coef)
                return
            end if
        end do
    end subroutine polynomial_search

    !> A root of the integer polynomial coef near x, by Newton's method in
    !> real(16).
    pure real(qp) function newton_root(coef, x) result(root)
        integer, intent(in) :: coef(0:)
        real(qp), intent(in) :: x
        real(qp) :: f, df
        integer :: it, k
        integer, parameter :: newton_steps = 60
        root = x
        do it = 1, newton_steps
            f = 0.0_qp
            df = 0.0_qp
            do k = ubound(coef, 1), 0, -1
                df = df*root + f
                f = f*root + coef(k)
            end do
            if (df == 0.0_qp) exit
            root = root - f/df
        end do
    end function newton_root

    !> The polynomial as text, e.g. "x^2-14x+1".
    pure function poly_text(coef) result(text)
        integer, intent(in) :: coef(0:)
        character(len=:), allocatable :: text
        character(len=16) :: buf
        integer :: k
        text = ""
        do k = ubound(coef, 1), 0, -1
            if (coef(k) == 0) cycle
            if (coef(k) < 0) then
                text = text//"-"
            else if (len(text) > 0) then
                text = text//"+"
            end if
            if (abs(coef(k)) /= 1 .or. k == 0) then
                write (buf, "(i0)") abs(coef(k))
                text = text//trim(buf)
            end if
            if (k >= 1) text = text//"x"
            if (k >= 2) then
                write (buf, "(i0)") k
                text = text//"^"//trim(buf)
            end if
        end do
    end function poly_text

    !> Greatest common divisor of two integers.
    pure recursive integer function gcd(a, b) result(g)
        integer, intent(in) :: a, b
        if (b == 0) then
            g = abs(a)
        else
            g = gcd(b, mod(a, b))
        end if
    end function gcd

    !> Greatest common divisor of all coefficients.
    pure integer function gcd_all(coef) result(g)
        integer, intent(in) :: coef(:)
        integer :: i
        g = 0
        do i = 1, size(coef)
            g = gcd(g, coef(i))
        end do
    end function gcd_all

end module sphere_row_ecrit
