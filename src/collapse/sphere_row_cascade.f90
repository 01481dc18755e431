!> The cascade at one instant through a touching block of spheres, run in the
!> engine's order at equal times, and the numerical certificate that it merges.
!>
!> It only decides whether a block merges (the engine takes the limit in its
!> own kind), so it is run in double precision for every kind, on the
!> collisions and patterns of sphere_row_pattern.inc (their rule and map are
!> described there), and a pattern's certificate that double precision
!> cannot resolve is run again in the finer kind of sphere_row_pattern_fine.
module sphere_row_cascade
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: dp
    use sphere_row_policy, only: policy
    use sphere_row_pattern_dp, only: cascade_t, jump_period_most, jump_levels, cascade_start, &
        rescale, cascade_collide, pattern_window, period_map, pattern_holds, pattern_contracts, &
        choice_part_t, choice_parts, parts_choice
    use sphere_row_pattern_fine, only: fine_t => cascade_t, fine_kind => pattern_kind, &
        fine_start => cascade_start, fine_contracts => pattern_contracts
    implicit none
    private
    public :: ordered_cascade_merges, cascade_jump, cascade_kind
    ! (the watch of a try's period: for its test)
    public :: repeats_t, watch_repeats, block_period

    !> The kind the cascade is run in, whatever the engine's.
    integer, parameter :: cascade_kind = dp

    !> The tries' constants (policy_t says where each comes from).
    integer, parameter :: order_steps_least = policy%order_steps_least, &
        order_work = policy%order_work, order_doublings = policy%order_doublings, &
        order_first_check = policy%order_first_check, quiet_more = policy%quiet_more, &
        jump_window_most = policy%jump_window_most, &
        jump_kinds_most = policy%jump_kinds_most, jump_need = policy%jump_need
    real(dp), parameter :: quiet_noise = real(policy%quiet_noise, dp)

    !> The watch of a try for a period k <= jump_period_most that its latest
    !> collisions repeat (watch_repeats), at place jump_period_most + 1 - k:
    !> how many entries in a row have matched the entry k before (`agree`),
    !> and whether k was tried since it last broke (`blocked`: -1, else 0;
    !> integers, as masks, so that the watch's loop vectorizes).
    type :: repeats_t
        integer :: agree(jump_period_most) = 0
        integer :: blocked(jump_period_most) = 0
    end type repeats_t

contains

    !> Whether (`merges`) the cascade at one instant through a touching block
    !> with approach rates `rates` and the kicks kl, kr of (6) at its contacts
    !> settles into a pattern that takes in every contact, repeats for ever
    !> and contracts the rates: then every sphere tends to the block's mean
    !> velocity. For blocks whose merge the engine's box, which asks for a
    !> merge in every order, does not prove (light spheres between heavy
    !> ones, where some order splits the block).
    !>
    !> With quiet > 0 (the engine's insignificant rate) the try watches for
    !> the point where the engine's own cascade would end, its fastest
    !> approach no longer above quiet, with every rate, opening ones too, at
    !> quiet or below: the engine, stepping its collisions, merges the block
    !> there by its fallback rule, so a try that goes on can save it no more
    !> than the collisions it takes to get there; it looks for a pattern for
    !> at most quiet_more times the work done up to there. With `quiet_merge`
    !> (passed only where the engine's own order is the one at equal times)
    !> the block is merged at that point at once. This holds
    !> only if the engine's collisions are those run here, so every choice on
    !> the way must have been clear by more than quiet_noise roundings per
    !> unit of work done (`steps`, which counts a jump's matrix work too; the
    !> slack of rule_choice, and of pattern_holds at the periods a jump
    !> checks: its two ends and the points of its search); if one was not, no
    !> merge is reported and the engine steps the cascade itself. Most
    !> cascades that end this way follow no repeating pattern (spheres that
    !> arrive one by one at a growing block, each setting off a cascade that
    !> falls 30 decades within a few thousand collisions). `quiet_end` says
    !> that the merge is this one, the fallback's.
    !>
    !> A pattern that only part of the block repeats (a light sphere shuttling
    !> between two heavy ones while other contacts wait) repeats for as long
    !> as its rates stay above the waiting ones, which, as its rates fall by a
    !> factor 1 - O(m/M) per period, can be 10^5 periods and more. Once such a
    !> pattern of at most jump_period_most contacts has run jump_need whole
    !> periods, it is jumped: its map over one period, M (a product of the
    !> collision matrices on the window of contacts it touches), is doubled
    !> (M, M^2, M^4, ...) while the pattern still holds from M^(2^j) w, and the
    !> count is then found bit by bit, so the rates after `times` periods
    !> are M^times w, with the pattern still holding there and not one period
    !> later. The sequence records the jump as one entry (its pattern and
    !> count), so that a cascade that alternates such stretches with single
    !> collisions shows its period in few entries. The sequence is searched
    !> for a period after order_first_check, twice as many, ... entries, and
    !> a period found is checked by pattern_merges: a numerical
    !> certificate. `steps` returns the work done, in collisions, and
    !> `spent` whether the try ended because its work ran out (not the bound
    !> past the engine's end of its cascade, which more work would not move;
    !> that bound is a multiple of `steps`, in 64 bits). `spent_before`
    !> is the number of tries that ran out since the engine last took a
    !> touching block's limit: each doubles the work this one may do (at
    !> most order_doublings times), so that a cascade whose rates fall
    !> slowly (light spheres between heavy ones: 10^5 collisions and more a
    !> decade) is run far enough by a later try, while the engine's wait
    !> before it tries the same block again, in proportion to the work, keeps
    !> the tries' share of its time bounded.
    pure subroutine ordered_cascade_merges(kl, kr, rates, e, quiet, quiet_merge, spent_before, &
        merges, steps, quiet_end, spent)
        real(dp), intent(in) :: kl(:), kr(:), rates(:), e, quiet
        logical, intent(in) :: quiet_merge
        integer, intent(in) :: spent_before
        logical, intent(out) :: merges, quiet_end, spent
        integer, intent(out) :: steps
        type(cascade_t) :: cs
        real(dp) :: w(size(rates)), scale, least, slack
        type(choice_part_t), allocatable :: parts(:)
        integer, allocatable :: seq(:)
        type(repeats_t) :: repeats
        logical :: stopped, watch
        integer :: n, most, check, period, c, items, per, id, cost, st, chunk
        merges = .false.
        quiet_end = .false.
        spent = .false.
        steps = 0
        n = size(rates)
        if (n < 2 .or. size(kl) /= n .or. size(kr) /= n) return
        if (.not. maxval(abs(rates)) > 0) return
        most = max(order_steps_least, order_work*2**min(max(spent_before, 0), order_doublings)/n)
        ! (one more: a jump adds a second entry in the last step)
        allocate (seq(most + 1), stat=st)
        if (st /= 0) return
        call cascade_start(cs, kl, kr, e, jump_kinds_most, st)
        if (st /= 0) return
        ! the rates are scale*w, w kept about 1
        scale = maxval(abs(rates))
        w = rates/scale
        ! the rule's choice kept by parts of `chunk` contacts: a collision
        ! rescans the part or two that hold its contacts, then the parts,
        ! about chunk + n/chunk values, least at chunk = sqrt(n)
        chunk = ceiling(sqrt(real(n)))
        allocate (parts((n - 1)/chunk + 1), stat=st)
        if (st /= 0) return
        call choice_parts(w, parts, 1, n, chunk)
        least = 1
        stopped = .false.
        watch = quiet > 0
        check = order_first_check
        items = 0
        ! until the budget is spent or, with quiet > 0, the engine's cascade
        ! stops, its fastest approach insignificant, with every rate so
        do while (steps < most)
            call parts_choice(parts, c, slack)
            ! no contact closes: the cascade ends, a finite one
            if (c == 0) return
            if (watch) then
                if (scale*w(c) <= quiet) then
                    stopped = scale*maxval(abs(w)) <= quiet
                    if (stopped .and. quiet_merge) exit
                    ! the engine merges by its fallback here, after about
                    ! `steps` collisions: a pattern is looked for a while
                    ! longer, for a bounded multiple of that work
                    if (stopped) most = int(min(int(most, int64), &
                        max(quiet_more*int(steps, int64), int(2*order_first_check, int64))))
                    ! (the engine stops short of a merge if an opening rate
                    ! is significant: the try goes on without the rule)
                    watch = .false.
                end if
            end if
            least = min(least, slack)
            call cascade_collide(w, cs, c)
            call choice_parts(w, parts, c - 1, c + 1, chunk)
            steps = steps + 1
            items = items + 1
            seq(items) = c
            ! the rates fall by up to e per collision: kept about 1
            if (mod(items, 8) == 0) then
                call rescale(w, scale)
                call choice_parts(w, parts, 1, n, chunk)
            end if
            call watch_repeats(seq(:items), repeats, per)
            if (per > 0) then
                call jump_ahead(cs, w, seq(items - per + 1:items), id, cost, slack)
                steps = steps + cost
                ! a part of the block that repeats its pattern for ever
                if (id < 0) return
                if (id == 0) then
                    call block_period(repeats, per)
                else
                    least = min(least, slack)
                    items = items + 1
                    seq(items) = -id
                    repeats = repeats_t()
                    call rescale(w, scale)
                    call choice_parts(w, parts, 1, n, chunk)
                end if
            end if
            if (items < check) cycle
            check = 2*check
            call cascade_period(seq(items/2 + 1:items), period)
            if (period == 0) cycle
            call pattern_merges(w, cs, seq(items - period + 1:items), merges)
            if (merges) return
        end do
        spent = steps >= most .and. .not. stopped
        ! a last look at the whole sequence: a certified pattern is the better
        ! reason to merge
        call cascade_period(seq(items/2 + 1:items), period)
        if (period > 0) call pattern_merges(w, cs, seq(items - period + 1:items), merges)
        if (merges .or. .not. (stopped .and. quiet_merge)) return
        ! the block merges by the engine's fallback rule if every choice on
        ! the way was clear (if one was not, the engine steps it)
        merges = least > quiet_noise*steps*epsilon(w)
        quiet_end = merges
    end subroutine ordered_cascade_merges

    !> One jump of a pattern of contacts, as the ordered cascade takes it once
    !> the pattern has run jump_need periods: the rates w become those after
    !> `times` more periods, the most after which the pattern still holds for
    !> one period (0: not taken; -1: it holds for 2^jump_levels periods).
    pure subroutine cascade_jump(kl, kr, e, pattern, w, times)
        real(dp), intent(in) :: kl(:), kr(:), e
        integer, intent(in) :: pattern(:)
        real(dp), intent(inout) :: w(:)
        integer, intent(out) :: times
        type(cascade_t) :: cs
        real(dp) :: least
        integer :: id, cost, st
        times = 0
        if (size(pattern) < 1 .or. size(pattern) > jump_period_most) return
        if (size(kl) /= size(w) .or. size(kr) /= size(w)) return
        if (any(pattern < 1 .or. pattern > size(w))) return
        call cascade_start(cs, kl, kr, e, 1, st)
        if (st /= 0) return
        call jump_ahead(cs, w, pattern, id, cost, least)
        times = min(id, 0)
        if (id > 0) times = cs%jump(id)%times
    end subroutine cascade_jump

    !> After the latest entry of seq: for each period k, how many entries in
    !> a row have matched the entry k before (agree), and `per`, the shortest
    !> period that has now run jump_need whole periods and has not been tried
    !> since it last broke (blocked), 0 if none.
    pure subroutine watch_repeats(seq, repeats, per)
        integer, contiguous, intent(in) :: seq(:)
        type(repeats_t), intent(inout) :: repeats
        integer, intent(out) :: per
        integer, parameter :: top = jump_period_most
        integer :: j, l, m, s, most, match
        per = 0
        l = size(seq)
        m = min(top, l - 1)
        s = seq(l)
        most = 0
        ! (place j holds period top + 1 - j, which compares entry l with
        ! entry l - top - 1 + j: the places run with the entries, and the
        ! loop vectorizes)
        do j = top + 1 - m, top
            match = merge(-1, 0, s == seq(l - top - 1 + j))
            repeats%agree(j) = iand(repeats%agree(j) + 1, match)
            repeats%blocked(j) = iand(repeats%blocked(j), match)
            most = max(most, repeats%agree(j))
        end do
        if (most < jump_need - 1) return
        do j = top, top + 1 - m, -1
            per = top + 1 - j
            if (repeats%agree(j) >= (jump_need - 1)*per .and. repeats%blocked(j) == 0) return
        end do
        per = 0
    end subroutine watch_repeats

    !> Period per is not looked at again until it breaks (its jump was not
    !> taken).
    pure subroutine block_period(repeats, per)
        type(repeats_t), intent(inout) :: repeats
        integer, intent(in) :: per
        repeats%blocked(jump_period_most + 1 - per) = -1
    end subroutine block_period

    !> Jump the pattern of contacts (which has just run jump_need periods) as many
    !> whole periods ahead as it still holds: w becomes M^times w on the
    !> window of contacts the pattern touches, and id the jump's entry in
    !> cs%jump (0: not jumped, the pattern takes in every contact, its window
    !> is too wide, it does not hold one period on, or the table is full; -1:
    !> it holds for 2^jump_levels periods, i.e. it repeats for ever while the
    !> rest of the block waits). `cost` is the work in collisions; `least` is
    !> the smallest slack of a choice (pattern_holds) where the pattern was
    !> checked on the way to the jump's end.
    pure subroutine jump_ahead(cs, w, pattern, id, cost, least)
        type(cascade_t), intent(inout) :: cs
        real(dp), intent(inout) :: w(:)
        integer, intent(in) :: pattern(:)
        integer, intent(out) :: id, cost
        real(dp), intent(out) :: least
        real(dp), allocatable :: pw(:, :, :)
        real(dp) :: x(size(w)), y(size(w)), slack
        logical :: seen(size(w)), ok
        integer :: a, b, nw, j, top, times, st
        id = 0
        cost = 1
        least = 1
        seen = .false.
        seen(pattern) = .true.
        if (all(seen)) return
        call pattern_window(pattern, size(w), a, b)
        nw = b - a + 1
        if (nw > jump_window_most) return
        ! (the table full: no more jumps)
        if (cs%jumps == size(cs%jump)) return
        allocate (pw(nw, nw, 0:jump_levels), stat=st)
        if (st /= 0) return
        call period_map(cs, pattern, a, b, pw(:, :, 0))
        ! the largest 2^top periods after which the pattern still holds (x
        ! after them, y tried)
        top = -1
        x = w
        y = w
        do j = 0, jump_levels
            if (j > 0) pw(:, :, j) = matmul(pw(:, :, j - 1), pw(:, :, j - 1))
            y(a:b) = matmul(pw(:, :, j), w(a:b))
            call pattern_holds(cs, y, pattern, ok, slack)
            if (.not. ok) exit
            least = min(least, slack)
            x(a:b) = y(a:b)
            top = j
        end do
        ! in collisions, each counted as a scan of the n rates and a few
        ! operations (the unit of a try's work, whatever a collision of it
        ! takes: the rule's choice scans fewer, choice_parts)
        cost = 1 + (nw*(size(w) + size(pattern)) + (2*top + 3)*(nw*nw*nw + size(pattern)*size(w))) &
            /(size(w) + 4)
        if (top < 0) return
        if (top == jump_levels) then
            id = -1
            return
        end if
        ! then the rest of the count, bit by bit
        times = 2**top
        do j = top - 1, 0, -1
            y(a:b) = matmul(pw(:, :, j), x(a:b))
            call pattern_holds(cs, y, pattern, ok, slack)
            if (ok) then
                least = min(least, slack)
                times = times + 2**j
                x(a:b) = y(a:b)
            end if
        end do
        call record_jump(cs, pattern, times, id)
        if (id > 0) w = x
    end subroutine jump_ahead

    !> The entry of the jump (pattern, times) in cs%jump, added if new (0 if
    !> the table is full).
    pure subroutine record_jump(cs, pattern, times, id)
        type(cascade_t), intent(inout) :: cs
        integer, intent(in) :: pattern(:), times
        integer, intent(out) :: id
        integer :: l
        l = size(pattern)
        do id = 1, cs%jumps
            associate (jp => cs%jump(id))
                if (jp%length == l .and. jp%times == times) then
                    if (all(jp%contact(:l) == pattern)) return
                end if
            end associate
        end do
        id = 0
        if (cs%jumps == size(cs%jump)) return
        cs%jumps = cs%jumps + 1
        id = cs%jumps
        cs%jump(id)%length = l
        cs%jump(id)%times = times
        cs%jump(id)%contact(:l) = pattern
    end subroutine record_jump

    !> The period of the longest tail of seq that repeats itself at least three
    !> times (0 if none): with the prefix function of seq read backwards, the
    !> last l entries have period l - pi(l).
    pure subroutine cascade_period(seq, period)
        integer, intent(in) :: seq(:)
        integer, intent(out) :: period
        ! (on the heap: a sequence of 2^20 would not fit a thread's stack)
        integer, allocatable :: pi(:)
        integer :: l, k, i, n, st
        n = size(seq)
        period = 0
        if (n < 3) return
        allocate (pi(n), stat=st)
        if (st /= 0) return
        pi(1) = 0
        do i = 2, n
            k = pi(i - 1)
            do while (k > 0)
                if (seq(n + 1 - i) == seq(n - k)) exit
                k = pi(k)
            end do
            if (seq(n + 1 - i) == seq(n - k)) k = k + 1
            pi(i) = k
        end do
        do l = n, 3, -1
            if (l >= 3*(l - pi(l))) then
                period = l - pi(l)
                return
            end if
        end do
    end subroutine cascade_period

    !> Whether the pattern of entries repeats for ever from the rates w and
    !> merges the block, by pattern_contracts in double precision or, where
    !> that fails only because the drift of the direction is down to double
    !> precision's rounding, which is too coarse for the pattern's margins
    !> (a long pattern with a near tie), by pattern_contracts in the finer
    !> kind from the same rates.
    pure subroutine pattern_merges(w, cs, pattern, merges)
        real(dp), intent(in) :: w(:)
        type(cascade_t), intent(in) :: cs
        integer, intent(in) :: pattern(:)
        logical, intent(out) :: merges
        type(fine_t) :: fine
        logical :: floor
        integer :: j, st
        call pattern_contracts(w, cs, pattern, merges, floor)
        if (merges .or. .not. floor) return
        call fine_start(fine, real(cs%kl, fine_kind), real(cs%kr, fine_kind), &
            real(cs%e, fine_kind), cs%jumps, st)
        if (st /= 0) return
        fine%jumps = cs%jumps
        do j = 1, cs%jumps
            fine%jump(j)%length = cs%jump(j)%length
            fine%jump(j)%times = cs%jump(j)%times
            fine%jump(j)%contact = cs%jump(j)%contact
        end do
        call fine_contracts(real(w, fine_kind), fine, pattern, merges, floor)
    end subroutine pattern_merges

end module sphere_row_cascade
