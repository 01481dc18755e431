!> Tests of the calendar of impacts (a heap of impact times, used in long
!> rows) against the scan of every gap: the same collisions in the same order,
!> the same status, and final states equal to within the rounding of the two
!> ways of moving a gap (at every step, or once from its own time).
module test_calendar
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan
    use sphere_row, only: qp, dp, scene_t, run_t, event_log_t, observer_t, scene_init, simulate, &
        str, status_normal, status_collapsed, itoa, event_collision, comparisons
    use sphere_row_pattern_dp, only: cascade_t, cascade_start, cascade_collide, rescale, &
        rule_choice, choice_part_t, choice_parts, parts_choice
    use sphere_row_cascade, only: repeats_t, watch_repeats, block_period
    use sphere_row_policy, only: policy
    use testsuite, only: error_t, unittest_t, new_unittest, check, seed_random, cases
    use test_support, only: random_row
    implicit none
    private
    public :: collect_calendar

    !> Unit roundoff of the working precision.
    real(qp), parameter :: eps = epsilon(1.0_qp)
    !> calendar_from values that force the calendar and the scan.
    integer, parameter :: always = 2, never = huge(1)

    !> How a run went with the calendar and with the scan.
    type :: pair_t
        type(run_t) :: cal, scan
        type(event_log_t) :: log_cal, log_scan
    end type pair_t

    !> Checks the calendar's heap after every collision: each entry no
    !> earlier than its parent (impact time, then approach rate, then the
    !> gap's index), where neither is a gap whose rate the collision has just
    !> changed (those are re-keyed after it). Keeps the first collision with
    !> an entry out of order (0: none).
    type, extends(observer_t) :: heap_watch_t
        integer :: out_of_order = 0
    contains
        procedure :: notify => heap_notify
    end type heap_watch_t

contains

    !> The calendar tests.
    function collect_calendar() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("try_choice_by_parts_as_one_pass", test_choice_parts), &
            new_unittest("try_period_watch_as_one_pass", test_watch_repeats), &
            new_unittest("random_rows_same_sequence", test_random_rows), &
            new_unittest("elastic_row_hands_on", test_elastic_row), &
            new_unittest("long_rows_same_answer", test_long_rows), &
            new_unittest("tiny_tol_keeps_the_scan", test_tiny_tol), &
            new_unittest("clock_carries_the_exact_time", test_exact_clock), &
            new_unittest("heap_in_order_at_ties", test_heap_order), &
            new_unittest("comparisons_agree_with_operators", test_comparisons) &
            ]
    end function collect_calendar

    !> Run `scene` with the calendar and with the scan (with event logs if
    !> `logged`).
    subroutine run_both(scene, both, logged)
        type(scene_t), intent(inout) :: scene
        type(pair_t), intent(inout) :: both
        logical, intent(in) :: logged
        scene%calendar_from = always
        call run_one(both%cal, both%log_cal)
        scene%calendar_from = never
        call run_one(both%scan, both%log_scan)
    contains
        subroutine run_one(run, log)
            type(run_t), intent(inout) :: run
            type(event_log_t), intent(inout) :: log
            if (logged) then
                call simulate(scene, run, log)
            else
                call simulate(scene, run)
            end if
        end subroutine run_one
    end subroutine run_both

    !> A run without collapse: the same count, status, events (kind and
    !> spheres) if logged, and final velocities and gaps to within a rounding
    !> bound that grows with the number of collisions.
    subroutine check_same_run(scene, both, logged, error)
        type(scene_t), intent(in) :: scene
        type(pair_t), intent(in) :: both
        logical, intent(in) :: logged
        type(error_t), allocatable, intent(out) :: error
        real(qp) :: v_scale, y_scale
        integer :: n
        n = both%scan%n
        call check(error, both%cal%cal%on .and. .not. both%scan%cal%on, &
            "calendar not chosen as asked")
        if (allocated(error)) return
        call check(error, both%cal%n == n .and. both%cal%status == both%scan%status, &
            "p = "//itoa(scene%p)//": calendar and scan differ: collisions "// &
            itoa(both%cal%n)//", "//itoa(n)//"; status "//itoa(both%cal%status)//", " &
            //itoa(both%scan%status))
        if (allocated(error)) return
        if (logged) then
            call check(error, all(both%log_cal%first(:n) == both%log_scan%first(:n)), &
                "p = "//itoa(scene%p)//": calendar and scan: the order of collisions differs")
            if (allocated(error)) return
        end if
        v_scale = (n + 1)*maxval(abs(both%scan%v))*maxval(scene%m)/minval(scene%m)
        y_scale = (n + 1)*(maxval(scene%a) + scene%d + both%scan%t_end*maxval(abs(both%scan%v)))
        call check(error, all(abs(both%cal%v - both%scan%v) <= 64*eps*v_scale), &
            "calendar and scan: velocities differ beyond rounding")
        call check(error, all(abs(both%cal%y - both%scan%y) <= 64*eps*y_scale), &
            "calendar and scan: gaps differ beyond rounding")
    end subroutine check_same_run

    !> Seeded random rows (p = 2..20, masses log-uniform over 1e-3..1e3 or all
    !> equal, e uniform in [0, 1], a fifth of the gaps closed). Every run that
    !> ends without a collapse takes the same collisions in the same order
    !> with the calendar as with the scan. A collapse limit is taken when its
    !> certificate (or the fallback) first holds, which the last bits of the
    !> gaps can shift by a few periods, and a long run cut at the cap has been
    !> steered by rounding: these are counted, and their final velocities
    !> must agree to rounding in most of them.
    subroutine test_random_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(pair_t) :: both
        real(qp) :: spread
        integer :: i, bits, compared, collapsed, apart
        integer, parameter :: cap = 3000
        integer :: scenes
        scenes = cases(100, 3000)
        call seed_random(2468, 13)
        bits = 0
        compared = 0
        collapsed = 0
        apart = 0
        do i = 1, scenes
            call random_row(scene, 0.2_qp, cap)
            call run_both(scene, both, .true.)
            if (both%scan%status == status_normal .or. both%cal%status == status_normal) then
                call check_same_run(scene, both, .true., error)
                if (allocated(error)) return
                compared = compared + 1
                if (all(both%cal%v == both%scan%v) .and. all(both%cal%y == both%scan%y)) then
                    bits = bits + 1
                end if
            else if (both%scan%status == status_collapsed .and. &
                both%cal%status == status_collapsed) then
                collapsed = collapsed + 1
                spread = maxval(abs(both%cal%v - both%scan%v))
                if (spread > 64*eps*(both%scan%n + 1)*maxval(abs(both%scan%v))) apart = apart + 1
            end if
        end do
        print "(4x, i0, a, i0, a, i0, a)", compared, " runs without collapse compared (", bits, &
            " bit for bit)"
        print "(4x, i0, a, i0, a)", collapsed, " collapsed runs, ", apart, &
            " with velocities apart beyond rounding"
        call check(error, compared > scenes/4, "calendar and scan: too few runs compared")
        ! the two ways of moving gaps round differently: some runs must differ
        ! in the last bits, or the calendar was not what ran
        call check(error, bits < compared, "calendar and scan: never a different rounding")
        call check(error, collapsed > scenes/20 .and. apart <= collapsed/100, &
            "calendar and scan: collapsed runs apart in more than 1 %")
    end subroutine test_random_rows

    !> A long elastic row passes the impulse on: n = p - 1 collisions, the
    !> last sphere leaves with v0, every other one rests.
    subroutine test_elastic_row(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        integer, parameter :: p = 20000
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=p, e=1.0_qp)
        call simulate(scene, run)
        call check(error, run%cal%on .and. run%status == status_normal .and. run%n == p - 1, &
            "elastic row: calendar, status normal and p - 1 collisions")
        if (allocated(error)) return
        call check(error, run%v(p) == 1.0_qp .and. all(run%v(:p - 1) == 0.0_qp), &
            "elastic row: v_p = v0, the others at rest")
    end subroutine test_elastic_row

    !> Rows of 300 spheres, nearly elastic, with equal and with uneven gaps
    !> (tens of thousands of collisions each): the same answer either way.
    subroutine test_long_rows(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(pair_t) :: both
        real(qp) :: u(299)
        real(qp), parameter :: e_values(3) = [0.99_qp, 0.995_qp, 0.999_qp]
        integer :: stat, i
        character(len=200) :: msg
        call seed_random(97531, 3)
        do i = 1, size(e_values)
            call random_number(u)
            call scene_init(scene, stat, msg, p=300, e=e_values(i), &
                gaps=merge(1.0_qp, 0.5_qp + u, i == 1), max_collisions=200000)
            call run_both(scene, both, .false.)
            call check(error, both%scan%status == status_normal .and. both%scan%n > 1000, &
                "long row: no finite run of many collisions to compare")
            if (allocated(error)) return
            call check_same_run(scene, both, .false., error)
            if (allocated(error)) return
        end do
    end subroutine test_long_rows

    !> Below the kind's epsilon, tol asks for time steps finer than the
    !> calendar's clock resolves: such a run scans, whatever calendar_from.
    subroutine test_tiny_tol(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=4, e=0.172_qp, tol=1.0e-100_qp)
        scene%calendar_from = always
        call simulate(scene, run)
        call check(error, .not. run%cal%on .and. run%n == 115, &
            "tiny tol: the scan runs, 115 collisions at e = 0.172")
        if (allocated(error)) return
        scene%tol = eps
        call simulate(scene, run)
        call check(error, run%cal%on .and. run%n == 115, &
            "tol = eps: the calendar runs, 115 collisions at e = 0.172")
    end subroutine test_tiny_tol

    !> The calendar's clock is a pair t + t_lo that holds the sum of the
    !> collision intervals exactly. In an elastic row of equal spheres each
    !> collision hands v0 on exactly, and each interval is its gap: gaps
    !> g_k = 1 + m_k 2^-112 (m_k from 1 to 1000, the last bit of real(16)
    !> near 1) put the sum at 2000 + sum(m_k) 2^-112 after 2000 collisions,
    !> which t alone (whose last place there is 2^-101) cannot hold and t + t_lo
    !> must, to within far less than t's last place (the rounding of t_lo's
    !> own additions; a clock without its low part is off by 0.46 of it). The
    !> reference is formed exactly: t - 2000 and sum(m_k) 2^-112 are exact.
    subroutine test_exact_clock(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        integer :: stat, k
        character(len=200) :: msg
        integer, parameter :: p = 2001
        integer :: m(p - 1)
        real(qp) :: off
        m = [(mod(7919*k, 1000) + 1, k = 1, p - 1)]
        call scene_init(scene, stat, msg, p=p, e=1.0_qp, gaps=1 + scale(real(m, qp), -112))
        scene%calendar_from = always
        call simulate(scene, run)
        off = ((run%clock%t - (p - 1)) - scale(real(sum(m), qp), -112)) + run%clock%t_lo
        call check(error, run%cal%on .and. run%n == p - 1 .and. &
            abs(off) < 1.0e-3_qp*spacing(run%clock%t), &
            "t - 2000 = "//str(run%clock%t - (p - 1))//", t_lo = "//str(run%clock%t_lo)// &
            ": the clock after "//itoa(run%n)//" collisions is off the sum of its gaps by "// &
            itoa(nint(off/spacing(run%clock%t)*1000))//"/1000 of t's last place")
    end subroutine test_exact_clock

    !> A struck row of 48 equal spheres at e = 0.5 (the calendar's shortest
    !> row): its touching blocks give impacts at one instant, keyed at the
    !> same time, which the approach rate orders. The heap stays in that
    !> order through the run's 3 x 10^4 collisions (a heap that compared a
    !> rate changed before its gap was re-keyed was out of order after
    !> collision 4649).
    subroutine test_heap_order(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(heap_watch_t) :: watch
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=48, e=0.5_qp, max_collisions=30000)
        call simulate(scene, run, observer=watch)
        call check(error, run%cal%on .and. run%n > 5000, &
            "p = 48, e = 0.5: the calendar runs past collision 5000 ("//itoa(run%n)//")")
        if (allocated(error)) return
        call check(error, watch%out_of_order == 0, &
            "p = 48, e = 0.5: the heap out of order after collision "//itoa(watch%out_of_order))
    end subroutine test_heap_order

    !> The engine's comparisons (in real(16) from the bits, in real(8) the
    !> operators) give what a == 0, a == b, a < b and a <= b give, for every
    !> pair of both signs of zero, the smallest subnormal, tiny, 1 and its
    !> neighbours, huge, infinity and NaN, each with either sign.
    subroutine test_comparisons(error)
        type(error_t), allocatable, intent(out) :: error
        real(qp), allocatable :: q(:)
        real(dp), allocatable :: d(:)
        integer :: i, j
        q = [0.0_qp, tiny(1.0_qp)*epsilon(1.0_qp), tiny(1.0_qp), 1.0_qp, &
            1.0_qp + epsilon(1.0_qp), 1.0_qp - epsilon(1.0_qp)/2, huge(1.0_qp), &
            ieee_value(1.0_qp, ieee_positive_inf), ieee_value(1.0_qp, ieee_quiet_nan)]
        d = [0.0_dp, tiny(1.0_dp)*epsilon(1.0_dp), tiny(1.0_dp), 1.0_dp, &
            1.0_dp + epsilon(1.0_dp), 1.0_dp - epsilon(1.0_dp)/2, huge(1.0_dp), &
            ieee_value(1.0_dp, ieee_positive_inf), ieee_value(1.0_dp, ieee_quiet_nan)]
        q = [q, -q]
        d = [d, -d]
        do i = 1, size(q)
            do j = 1, size(q)
                call check(error, all(comparisons(q(i), q(j)) .eqv. &
                    [q(i) == 0, q(i) == q(j), q(i) < q(j), q(i) <= q(j)]), &
                    "real(16): values "//itoa(i)//" and "//itoa(j)//" compare otherwise")
                if (allocated(error)) return
                call check(error, all(comparisons(d(i), d(j)) .eqv. &
                    [d(i) == 0, d(i) == d(j), d(i) < d(j), d(i) <= d(j)]), &
                    "real(8): values "//itoa(i)//" and "//itoa(j)//" compare otherwise")
                if (allocated(error)) return
            end do
        end do
    end subroutine test_comparisons

    !> The rule's choice in a try, kept by parts of the rates (choice_parts,
    !> parts_choice) and in rule_choice, against one pass over the rates
    !> written here: the same contact and the same slack, to the bit, on
    !> random rates with ties, zeros of both signs and negative ones, for
    !> every size of part, and along a cascade that keeps its parts as a try
    !> does (the parts beside each collision, all after a rescale).
    subroutine test_choice_parts(error)
        type(error_t), allocatable, intent(out) :: error
        type(cascade_t) :: cs
        type(choice_part_t), allocatable :: parts(:)
        real(dp), allocatable :: w(:), kl(:), kr(:), draw(:)
        real(dp) :: scale, slack
        integer :: trial, n, chunk, step, c, q, st
        call seed_random(8642, 7)
        do trial = 1, 300
            n = 2 + mod(trial, 40)
            allocate (draw(n))
            call random_number(draw)
            ! rates in [-1, 1] on a grid of 1/8 (ties), zeros of both signs
            w = anint(16*draw - 8)/8
            where (w == 0) w = merge(0.0_dp, -0.0_dp, draw > 0.5_dp)
            do chunk = 1, n
                parts = [(choice_part_t(), q=1, (n - 1)/chunk + 1)]
                call choice_parts(w, parts, 1, n, chunk)
                call agrees("trial "//itoa(trial)//", parts of "//itoa(chunk))
                if (allocated(error)) return
            end do
            call rule_choice(w, c, slack)
            call check(error, c == reference_c(w) .and. slack == reference_slack(w), &
                "trial "//itoa(trial)//": rule_choice chose otherwise")
            if (allocated(error)) return
            ! a cascade with the kicks of unequal masses, e = 0.9
            call random_number(draw)
            kl = 0.5_dp + draw
            kr = 2 - kl
            call cascade_start(cs, kl, kr, 0.9_dp, 4, st)
            call check(error, st == 0, "cascade_start: no memory")
            if (allocated(error)) return
            w = abs(w) + 1.0_dp/16
            scale = 1
            chunk = ceiling(sqrt(real(n)))
            parts = [(choice_part_t(), q=1, (n - 1)/chunk + 1)]
            call choice_parts(w, parts, 1, n, chunk)
            do step = 1, 200
                call agrees("trial "//itoa(trial)//", step "//itoa(step))
                if (allocated(error)) return
                call parts_choice(parts, c, slack)
                if (c == 0) exit
                ! (as ordered_cascade_merges keeps them)
                call cascade_collide(w, cs, c)
                call choice_parts(w, parts, c - 1, c + 1, chunk)
                if (mod(step, 8) == 0) then
                    call rescale(w, scale)
                    call choice_parts(w, parts, 1, n, chunk)
                end if
            end do
            deallocate (draw)
        end do
    contains
        !> The parts' choice against the reference on the rates w.
        subroutine agrees(where)
            character(len=*), intent(in) :: where
            real(dp) :: slack
            call parts_choice(parts, c, slack)
            call check(error, c == reference_c(w) .and. slack == reference_slack(w), &
                where//": chose "//itoa(c)//", one pass "//itoa(reference_c(w)))
        end subroutine agrees
    end subroutine test_choice_parts

    !> A try's watch for a repeating period (watch_repeats) against one pass
    !> over the periods written here, entry by entry of sequences that repeat
    !> a pattern of 1 to 20 contacts with a random entry now and then: the
    !> same period found at every entry, with a found period blocked or
    !> every count reset (as after a jump) now and then.
    subroutine test_watch_repeats(error)
        type(error_t), allocatable, intent(out) :: error
        integer, parameter :: top = policy%jump_period_most, need = policy%jump_need
        type(repeats_t) :: repeats
        integer :: seq(600), pattern(20), agree(top), trial, l, i, k, per, per_ref
        logical :: blocked(top)
        real(dp) :: u(3)
        call seed_random(1357, 11)
        do trial = 1, 200
            call random_number(u)
            k = 1 + int(20*u(1))
            pattern(:k) = [(1 + mod(7*i, 5), i=1, k)]
            repeats = repeats_t()
            agree = 0
            blocked = .false.
            do l = 1, size(seq)
                call random_number(u)
                seq(l) = pattern(1 + mod(l, k))
                if (u(1) < 0.01_dp) seq(l) = 1 + int(5*u(2))
                call watch_repeats(seq(:l), repeats, per)
                call reference_watch(seq(:l), agree, blocked, per_ref)
                call check(error, per == per_ref, "trial "//itoa(trial)//", entry "//itoa(l)// &
                    ": period "//itoa(per)//", one pass "//itoa(per_ref))
                if (allocated(error)) return
                if (per == 0) cycle
                ! (mostly neither, so that two periods come to be due at
                ! once, and the shortest must be the one found)
                if (u(3) < 0.1_dp) then
                    call block_period(repeats, per)
                    blocked(per) = .true.
                else if (u(3) < 0.15_dp) then
                    repeats = repeats_t()
                    agree = 0
                    blocked = .false.
                end if
            end do
        end do
    contains
        !> The watch by one pass over the periods k = 1, 2, ...
        subroutine reference_watch(seq, agree, blocked, per)
            integer, intent(in) :: seq(:)
            integer, intent(inout) :: agree(:)
            logical, intent(inout) :: blocked(:)
            integer, intent(out) :: per
            integer :: k, n
            per = 0
            n = size(seq)
            do k = 1, min(size(agree), n - 1)
                if (seq(n) == seq(n - k)) then
                    agree(k) = agree(k) + 1
                else
                    agree(k) = 0
                    blocked(k) = .false.
                end if
                if (per == 0 .and. agree(k) >= (need - 1)*k .and. .not. blocked(k)) per = k
            end do
        end subroutine reference_watch
    end subroutine test_watch_repeats

    !> The engine's choice at equal times by one pass: the largest rate above
    !> 0, the leftmost of equals (0: none).
    pure integer function reference_c(w) result(c)
        real(dp), intent(in) :: w(:)
        integer :: j
        c = 0
        do j = 1, size(w)
            if (w(j) > 0 .and. (c == 0 .or. w(j) > w(max(c, 1)))) c = j
        end do
    end function reference_c

    !> Its slack: the choice's rate less the largest other rate (and 0), over
    !> the largest size; 0 if none is chosen.
    pure real(dp) function reference_slack(w) result(slack)
        real(dp), intent(in) :: w(:)
        real(dp) :: others
        integer :: c, j
        c = reference_c(w)
        slack = 0
        if (c == 0) return
        others = 0
        do j = 1, size(w)
            if (j /= c) others = max(others, w(j))
        end do
        slack = min(w(c), w(c) - others)/maxval(abs(w))
    end function reference_slack

    !> heap_watch_t's check after a collision at gap `first` (its left sphere;
    !> `last` and the approach rate `w` are not needed).
    subroutine heap_notify(self, run, kind, first, last, w)
        class(heap_watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        integer, intent(in) :: kind, first, last
        real(qp), intent(in) :: w
        integer :: c, i, j
        logical :: later
        if (kind /= event_collision .or. self%out_of_order > 0) return
        do c = 2, run%cal%heap_n
            i = run%cal%heap(c/2)
            j = run%cal%heap(c)
            if (min(i, j) == 0 .or. abs(i - first) <= 1 .or. abs(j - first) <= 1) cycle
            if (run%cal%key(c/2) /= run%cal%key(c)) then
                later = run%cal%key(c/2) > run%cal%key(c)
            else if (run%cal%key_lo(c/2) /= run%cal%key_lo(c)) then
                later = run%cal%key_lo(c/2) > run%cal%key_lo(c)
            else if (run%dy(i) /= run%dy(j)) then
                later = run%dy(i) > run%dy(j)
            else
                later = i > j
            end if
            if (later) then
                self%out_of_order = run%n
                return
            end if
        end do
    end subroutine heap_notify

end module test_calendar
