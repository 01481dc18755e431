!> A lean real(16) path for many runs of one scene family: four spheres of
!> equal mass (any gaps, v0, tol and max_collisions), run again and again with
!> only e changed, of which only the final velocity v4 of the last sphere is
!> wanted (task c2).
!>
!> It follows the engine (simulate in sphere_row_engine.inc) operation for
!> operation wherever the engine's result depends on it, so that every run
!> gives the engine's collision sequence and a bit-identical v4, and leaves
!> out what v4 does not need:
!>
!> - the scene is checked and its family recognised once (`prepare`), not per
!>   run; the impact factor (1+e) m/(m+m) is the same for both neighbours of a
!>   pair (m/(m+m) = 1/2 exactly), so a collision forms one product for both;
!> - no time, no x_1 and no positions: v4 depends on the gaps only through
!>   which pair collides next, so gaps, rates and the rate of sphere 1 are
!>   carried, and v4 is summed from the rates at the end as the engine does;
!> - a gap's class (opening, closing, closing fast enough that its collision
!>   cannot end in a quiet group) is found when its rate changes, not at every
!>   step; sign and zero tests read the bit pattern (exact, and no soft-float
!>   call), and the colliding gap is not advanced only to be set to 0.
!>
!> Whenever the engine could do more than a binary collision, the run is
!> handed to the engine itself (`deferred`): e = 0 (the plastic cascade), a
!> collision whose new rate may be insignificant (the fallback for a quiet
!> group), a collision pattern that repeats long enough to be tried as a cycle
!> limit (every collapse, e < e_crit = 3 - 2 sqrt 2, ends this way or by the
!> fallback), and a run that reaches max_collisions or lean_collisions_max.
!> The handed-over run is the engine's own, so these cases agree by
!> construction; they are rare (none of the 10^7 runs of c2 in the study).
!>
!> **The certified real(64) run** (`certified_v4`, `auto_v4`). The same
!> lean run in real(64), carrying with every gap y, rate dy and the rate v1
!> of sphere 1 a first-order bound on its distance from the run in exact
!> arithmetic on the real(16) inputs (a, v0, tol v0 as real(16) numbers; e
!> a double, exact in both kinds). With u = 2^-53 and the standard model
!> |fl(a op b) - (a op b)| <= u |fl(a op b)| (to first order), for values in
!> real(64)'s normal range:
!>
!> - inputs: |a_64 - a| <= u |a_64|, likewise v0 and tol v0; the impact
!>   factor K = (1+e) m/(m+m) is rounded at most twice: |k - K| <= 2u k;
!> - impact time t = y/(-dy): with r = e_dy/|dy| < 1/2,
!>   e_t = (e_y/|dy| + t r)/(1 - r) + u t (exact y, dy within e_y, e_dy);
!> - advance y + dy dt: e_y + |dy| e_dt + e_dy (dt + e_dt) + u (|dy dt| +
!>   |y_new|); clamping at 0 moves a value towards the exact one, which is
!>   >= 0, and a gap whose rate is exactly 0 is not moved (its exact motion
!>   is within e_dy dt); the colliding gap is 0 in both arithmetics;
!> - collision: the impulse k w is within k e_w + |w| e_k + u |k w| of the
!>   exact one, each neighbour's rate adds it and u |dy_new|; the new rate
!>   -e w is within e e_w + u e |w|;
!> - v4 = ((v1 + dy1) + dy2) + dy3: the sum of the bounds and u per addition.
!>
!> Every decision the real(16) path takes is checked against these bounds
!> with a factor 2 to spare: a rate's class (dy < -tol v0, or not: the
!> difference beats twice the sum of both sides' bounds; a rate and
!> tolerance both exact decide exactly), which closing gap is hit first (the
!> other impact times exceed the smallest by more than twice the sum of their
!> bounds; an exact tie is not certified), and that the new rate e |w| of the
!> colliding pair is significant (above tol v0 beyond its bound), so that no
!> quiet group can form. A run that would be handed to the engine (e = 0, a
!> repeating pattern, the collision cap) is not certified either, nor one
!> whose impact times or steps leave real(64)'s normal range.
!>
!> Why that is enough: by induction over the decisions, while the decisions
!> agree, each real(64) value x_64 lies within its bound B of the exact
!> value X, and the real(16) value x_128 within B_128 of X, where B_128 has
!> the same form with u_128 = 2^-113 and exact inputs, so B_128 <= 2^-60 B
!> (to first order). A decision certified with |x_64 - c_64| > 2 (B + B_c)
!> has |X - C| > B + B_c and |x_128 - c_128| > B + B_c - (B_128 + B_c,128)
!> > 0 with the same sign: exact and real(16) arithmetic decide as real(64)
!> did. So a certified run has the real(16) path's collision sequence,
!> count and status, and |v4_64 - v4_128| <= B_v4 + B_v4,128. The reported
!> bound is B_v4 (1 + 2^-20): the factor covers the real(16) share (2^-60)
!> and the terms of second order in u dropped above (at most about
!> lean_collisions_max times 10 u relative, 1e-12).
module sphere_row_lean
    use sphere_row, only: dp, qp, wp => qp, scene_t, run_t, scene_check, budget, simulate, &
        status_normal, status_invalid
    use sphere_row_rule_dp, only: collide_at_dp => collide_at
    implicit none
    private
    public :: lean_row_t, lean_collisions_max

    !> Longest run the lean path carries; longer runs go to the engine.
    integer, parameter :: lean_collisions_max = 1024
    !> Periods checked for a repeating collision pattern: at least the longest
    !> the engine looks for with four spheres (max(8, 4 (p-1)) = 12), so that
    !> every run the engine tries a cycle on is handed over.
    integer, parameter :: period_check = 16
    !> Repeats of a period before the engine tries it as a cycle (its
    !> cycle_repeats); handing over at this point is conservative.
    integer, parameter :: repeats_check = 2
    !> Kind of the integer that holds the bits of a real(16).
    integer, parameter :: bits_kind = selected_int_kind(38)
    !> Classes of a gap from its rate dy: opening (dy >= 0, or an
    !> insignificant closing rate: not closing for the engine), closing, and
    !> closing fast: dy < -t_fast, so that after its collision the new rate
    !> e |dy| is certainly above tol v0 and no quiet group can form.
    integer, parameter :: gap_open = 0, gap_closing = 1, gap_fast = 2
    !> Rounding unit of real(64) (round to nearest).
    real(dp), parameter :: u64 = epsilon(1.0_dp)/2
    !> Relative slack of the reported bound on v4: the real(16) run's own
    !> rounding (2^-60 of the bound) and the dropped second-order terms.
    real(dp), parameter :: bound_slack = 2.0_dp**(-20)
    !> Smallest magnitude of a nonzero impact time, step dy dt or new rate
    !> in a certified run: above it the standard model of rounding holds for
    !> them and for their products with the impact factor (>= 1/2).
    real(dp), parameter :: normal_floor = 4*tiny(1.0_dp)/epsilon(1.0_dp)

    !> State of a certified real(64) run: gaps, rates, the rate of sphere 1,
    !> the bounds on their rounding errors, and which gaps are closing.
    type :: bounded_row_t
        real(dp) :: y(3) = 0.0_dp, dy(3) = 0.0_dp, v1 = 0.0_dp
        real(dp) :: ey(3) = 0.0_dp, ew(3) = 0.0_dp, ev1 = 0.0_dp
        logical :: closing(3) = .false.
    end type bounded_row_t

    !> One scene family prepared for lean runs: the scene with e left free.
    type :: lean_row_t
        private
        !> The scene as given (e is overwritten per run) and the engine's run,
        !> for the runs handed over.
        type(scene_t) :: scene
        type(run_t) :: run
        !> Initial gaps, v0, tol v0, the mass ratio of a pair (1/2 for equal
        !> masses), and the collision cap of a lean run.
        real(qp) :: a(3) = 0.0_qp, v0 = 0.0_qp, tv = 0.0_qp, ratio = 0.0_qp
        integer :: n_stop = 0
        logical :: ready = .false.
        !> The same in real(64) for the certified run, with the bounds of
        !> their rounding (tv: tol v0); `fits` if the scene's values lie in
        !> real(64)'s normal range.
        real(dp) :: a64(3) = 0.0_dp, ea(3) = 0.0_dp, v064 = 0.0_dp, ev0 = 0.0_dp
        real(dp) :: tv64 = 0.0_dp, etv = 0.0_dp, ratio64 = 0.0_dp
        logical :: fits = .false.
    contains
        !> Check a scene once and prepare its family; `stat` is status_invalid
        !> if the scene is refused or not of the family.
        procedure :: prepare => lean_prepare
        !> v4 of one run at a given e (and how the run ended).
        procedure :: v4 => lean_v4
        !> v4 of one run in real(64) with its certificate and bound.
        procedure :: certified_v4 => lean_certified_v4
        !> v4 of one run in real(64) where certified, else in real(16).
        procedure :: auto_v4 => lean_auto_v4
    end type lean_row_t

contains

    !> Check `scene` (as the engine would on every run) and recognise the
    !> family: four spheres whose every pair has the same mass ratio on both
    !> sides, m_{i+1}/(m_i+m_{i+1}) = m_i/(m_i+m_{i+1}), as the engine computes
    !> them; that holds exactly for equal masses.
    subroutine lean_prepare(self, scene, stat, msg)
        class(lean_row_t), intent(inout) :: self
        type(scene_t), intent(in) :: scene
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        real(qp) :: left(3), right(3)
        self%ready = .false.
        call scene_check(scene, stat, msg)
        if (stat /= status_normal) return
        stat = status_invalid
        if (scene%p /= 4) then
            msg = "scene: the lean path takes p = 4 only"
            return
        end if
        left = scene%m(2:)/(scene%m(:3) + scene%m(2:))
        right = scene%m(:3)/(scene%m(:3) + scene%m(2:))
        if (any(left /= left(1)) .or. any(right /= left(1))) then
            msg = "scene: the lean path takes equal masses only"
            return
        end if
        self%scene = scene
        self%a = scene%a
        self%v0 = scene%v0
        self%tv = scene%tol*scene%v0
        self%ratio = left(1)
        self%n_stop = min(budget(scene), lean_collisions_max)
        call prepare_real64(self)
        self%ready = .true.
        stat = status_normal
        msg = ""
    end subroutine lean_prepare

    !> The final velocity of the last sphere at restitution `e` (0 <= e <= 1,
    !> checked by the caller), bit-identical to simulate's run%v(4); `status`
    !> is the engine's run status; `deferred` tells that the engine ran it.
    !> `sequence`, if present, receives the pairs of a lean run in order
    !> (size >= lean_collisions_max; left alone when deferred) and `n` their
    !> number (the engine's run%n when deferred).
    subroutine lean_v4(self, e, v4, status, deferred, n, sequence)
        class(lean_row_t), intent(inout) :: self
        real(qp), intent(in) :: e
        real(qp), intent(out) :: v4
        integer, intent(out) :: status
        logical, intent(out) :: deferred
        integer, intent(out), optional :: n
        integer, intent(inout), optional :: sequence(:)
        real(qp) :: dy(3), v1, kick, t_fast
        integer :: hist(lean_collisions_max), c

        deferred = .true.
        status = status_invalid
        v4 = 0.0_qp
        if (present(n)) n = 0
        if (.not. self%ready) return
        if (e /= 0.0_qp) then
            ! once per run: the impact factor, and the rate below which a closing
            ! gap's collision leaves a rate e |dy| > 2 tv (1-u)^2 > tv: -2 tv / e,
            ! used only where tv is a normal number and the bound finite
            kick = (1.0_qp + e)*self%ratio
            t_fast = huge(1.0_qp)
            if (self%tv >= tiny(1.0_qp)) then
                t_fast = 2.0_qp*self%tv/e
                if (.not. (t_fast <= huge(1.0_qp))) t_fast = huge(1.0_qp)
            end if
            call lean_collide(self, kick, -e, t_fast, v1, dy, hist, c, deferred)
        end if
        if (deferred) then
            ! e = 0 or a run the engine must finish: the engine's own run
            self%scene%e = e
            call simulate(self%scene, self%run)
            v4 = self%run%v(4)
            status = self%run%status
            if (present(n)) n = self%run%n
            return
        end if
        ! run_finish: v_{i+1} = v_i + dy_i, summed from sphere 1
        v4 = ((v1 + dy(1)) + dy(2)) + dy(3)
        status = status_normal
        if (present(n)) n = c
        if (present(sequence)) sequence(:c) = hist(:c)
    end subroutine lean_v4

    !> The binary collisions of one lean run from the initial gaps, with the
    !> impact factor `kick`, `neg_e` = -e and the fast-closing bound `t_fast`
    !> of its e: on return the rate `v1` of sphere 1, the gap rates `dy`, the
    !> pairs `hist(:c)` in order; `deferred` if the engine must run it instead
    !> (see the module's description), the state then being of no use.
    subroutine lean_collide(self, kick, neg_e, t_fast, v1, dy, hist, c, deferred)
        type(lean_row_t), intent(in) :: self
        real(qp), intent(in) :: kick, neg_e, t_fast
        real(qp), intent(out) :: v1, dy(3)
        integer, intent(out) :: hist(lean_collisions_max), c
        logical, intent(out) :: deferred
        real(qp) :: y(3), dt, ti, r
        integer :: cls(3), runlen(period_check)
        integer :: i, k
        logical :: repeats

        deferred = .true.
        y = self%a
        dy = [-self%v0, 0.0_qp, 0.0_qp]
        v1 = self%v0
        cls = [classify(dy(1)), gap_open, gap_open]
        runlen = 0
        c = 0
        do
            ! the next impact, by the engine's rule: smallest y_i/(-dy_i)
            ! among closing gaps; at equal times the faster, then the leftmost
            ! (y_i/(-dy_i) < huge: gaps are bounded and rates above tol v0)
            k = 0
            dt = 0.0_qp
            do i = 1, 3
                if (cls(i) == gap_open) cycle
                ti = y(i)/(-dy(i))
                if (k == 0) then
                    k = i
                    dt = ti
                else if (ti < dt) then
                    k = i
                    dt = ti
                else if (ti == dt) then
                    if (dy(i) < dy(k)) k = i
                end if
            end do
            if (k == 0) exit
            if (c >= self%n_stop) return
            ! every other moving gap advances linearly; only a closing one can
            ! round below 0, where the engine's max(0, .) applies
            do i = 1, 3
                if (i == k .or. is_zero(dy(i))) cycle
                r = y(i) + dy(i)*dt
                if (is_negative(r)) r = 0.0_qp
                y(i) = r
            end do
            y(k) = 0.0_qp
            ! the collision (6): both neighbours take the same impulse
            call collide_at(dy, k, kick, kick, -neg_e, v1)
            if (k > 1) cls(k - 1) = classify(dy(k - 1))
            if (k < 3) cls(k + 1) = classify(dy(k + 1))
            ! the engine's fallback looks for a quiet group only if this new
            ! rate (e |w| >= 0) is insignificant; a fast gap cannot get there
            if (cls(k) /= gap_fast) then
                if (dy(k) <= self%tv) return
            end if
            cls(k) = gap_open
            c = c + 1
            hist(c) = k
            ! the engine's record of repeats: hand over before it tries a cycle
            call note_pattern(hist, c, runlen, repeats)
            if (repeats) return
        end do
        deferred = .false.

    contains

        !> The class of a gap with rate x: the sign bit first (no soft-float
        !> call for an opening gap), then the two thresholds.
        integer function classify(x) result(gap_class)
            real(qp), intent(in) :: x
            gap_class = gap_open
            if (.not. is_negative(x)) return
            if (x < -t_fast) then
                gap_class = gap_fast
            else if (x < -self%tv) then
                gap_class = gap_closing
            end if
        end function classify

    end subroutine lean_collide

    !> Enter the latest collision hist(c) into the runs of repeats: runlen(l)
    !> counts the latest collisions equal to the one l earlier; `repeats` once
    !> a period l <= period_check has repeated repeats_check times (the point
    !> where the run is handed to the engine).
    pure subroutine note_pattern(hist, c, runlen, repeats)
        integer, intent(in) :: hist(:), c
        integer, intent(inout) :: runlen(period_check)
        logical, intent(out) :: repeats
        integer :: l
        repeats = .false.
        do l = 1, min(period_check, c - 1)
            if (hist(c - l) == hist(c)) then
                runlen(l) = runlen(l) + 1
                if (runlen(l) >= repeats_check*l) then
                    repeats = .true.
                    return
                end if
            else
                runlen(l) = 0
            end if
        end do
    end subroutine note_pattern

    !> The scene's values in real(64) for the certified run, and the bounds
    !> of their rounding; `fits` is false (nothing is certified) if a value or
    !> the row's time scale lies outside real(64)'s normal range.
    subroutine prepare_real64(self)
        type(lean_row_t), intent(inout) :: self
        real(qp), parameter :: top = real(huge(1.0_dp), qp)/16, low = real(normal_floor, qp)
        real(qp) :: length
        length = sum(self%a)
        self%fits = length <= top .and. self%v0 >= low .and. self%v0 <= top .and. &
            length/self%v0 <= top .and. all(self%a == 0.0_qp .or. self%a >= low) .and. &
            self%tv <= top
        if (.not. self%fits) return
        self%a64 = real(self%a, dp)
        self%ea = u64*self%a64
        self%v064 = real(self%v0, dp)
        self%ev0 = u64*self%v064
        self%ratio64 = real(self%ratio, dp)
        ! tol v0 below real(64)'s normal range rounds with an absolute error
        ! of at most u tiny
        self%tv64 = real(self%tv, dp)
        self%etv = 0.0_dp
        if (self%tv > 0.0_qp) self%etv = u64*max(self%tv64, tiny(1.0_dp))
    end subroutine prepare_real64

    !> v4 of one run at restitution `e` (a double; 0 <= e <= 1) in real(64),
    !> with the certificate of the module's description: if `certified`, the
    !> run has the real(16) path's collision sequence, count and status
    !> (normal) and |v4 - v4_128| <= `bound`. Not certified: v4 and bound are
    !> of no use, and the real(16) path must answer. `n` and `sequence` as for
    !> lean_v4 (the real(64) run's, meaningful when certified).
    subroutine lean_certified_v4(self, e, v4, bound, certified, n, sequence)
        class(lean_row_t), intent(in) :: self
        real(dp), intent(in) :: e
        real(dp), intent(out) :: v4, bound
        logical, intent(out) :: certified
        integer, intent(out), optional :: n
        integer, intent(inout), optional :: sequence(:)
        type(bounded_row_t) :: s
        integer :: hist(lean_collisions_max), c
        real(dp) :: s1, s2
        v4 = 0.0_dp
        bound = 0.0_dp
        certified = .false.
        c = 0
        if (present(n)) n = 0
        if (.not. (self%ready .and. self%fits)) return
        ! e = 0 is the plastic cascade, the engine's
        if (.not. (e > 0.0_dp .and. e <= 1.0_dp)) return
        call bounded_collisions(self, e, s, hist, c, certified)
        if (.not. certified) return
        s1 = s%v1 + s%dy(1)
        s2 = s1 + s%dy(2)
        v4 = s2 + s%dy(3)
        bound = (s%ev1 + sum(s%ew) + u64*(abs(s1) + abs(s2) + abs(v4)))*(1.0_dp + bound_slack)
        if (present(n)) n = c
        if (present(sequence)) sequence(:c) = hist(:c)
    end subroutine lean_certified_v4

    !> v4 at restitution `e` (a double) in the precision the run needs: the
    !> certified real(64) run where its certificate holds (`escalated` false,
    !> `bound` its bound on |v4 - v4_128|), else the real(16) lean path
    !> (`escalated`, bound 0, v4 rounded to a double). `status` and `n` as
    !> for lean_v4.
    subroutine lean_auto_v4(self, e, v4, status, escalated, bound, n)
        class(lean_row_t), intent(inout) :: self
        real(dp), intent(in) :: e
        real(dp), intent(out) :: v4, bound
        integer, intent(out) :: status
        logical, intent(out) :: escalated
        integer, intent(out), optional :: n
        real(qp) :: v4_q
        logical :: certified, deferred
        call self%certified_v4(e, v4, bound, certified, n)
        escalated = .not. certified
        if (certified) then
            status = status_normal
            return
        end if
        bound = 0.0_dp
        call self%v4(real(e, qp), v4_q, status, deferred, n)
        v4 = real(v4_q, dp)
    end subroutine lean_auto_v4

    !> The collisions of one certified real(64) run from the initial gaps:
    !> on return the state `s`, the pairs hist(:c); `certified` false as soon
    !> as a decision cannot be certified or the run would go to the engine.
    subroutine bounded_collisions(self, e, s, hist, c, certified)
        type(lean_row_t), intent(in) :: self
        real(dp), intent(in) :: e
        type(bounded_row_t), intent(out) :: s
        integer, intent(out) :: hist(lean_collisions_max), c
        logical, intent(out) :: certified
        real(dp) :: kick, ek, dt, edt
        integer :: runlen(period_check), k
        logical :: ok, repeats

        certified = .false.
        c = 0
        kick = (1.0_dp + e)*self%ratio64
        ek = 2*u64*kick
        s%y = self%a64
        s%ey = self%ea
        s%dy = [-self%v064, 0.0_dp, 0.0_dp]
        s%ew = [self%ev0, 0.0_dp, 0.0_dp]
        s%v1 = self%v064
        s%ev1 = self%ev0
        do k = 1, 3
            call classify_bounded(self, s, k, ok)
            if (.not. ok) return
        end do
        runlen = 0
        do
            call bounded_next(s, k, dt, edt, ok)
            if (.not. ok) return
            if (k == 0) exit
            if (c >= self%n_stop) return
            call bounded_advance(s, k, dt, edt, ok)
            if (.not. ok) return
            call bounded_impact(self, s, k, kick, ek, e, ok)
            if (.not. ok) return
            c = c + 1
            hist(c) = k
            call note_pattern(hist, c, runlen, repeats)
            if (repeats) return
        end do
        certified = .true.
    end subroutine bounded_collisions

    !> Whether gap k closes (dy < -tol v0), certified: the margin beats twice
    !> the bounds of both sides, or both sides are exact.
    pure subroutine classify_bounded(self, s, k, ok)
        type(lean_row_t), intent(in) :: self
        type(bounded_row_t), intent(inout) :: s
        integer, intent(in) :: k
        logical, intent(out) :: ok
        ok = abs(s%dy(k) + self%tv64) > 2*(s%ew(k) + self%etv) .or. &
            (s%ew(k) == 0.0_dp .and. self%etv == 0.0_dp)
        s%closing(k) = s%dy(k) < -self%tv64
    end subroutine classify_bounded

    !> The next impact: the closing gap k of the smallest time dt = y/(-dy)
    !> (k = 0 if none), with the bound edt of dt; `ok` false if another
    !> closing gap's time is not beyond dt by twice the sum of both bounds.
    pure subroutine bounded_next(s, k, dt, edt, ok)
        type(bounded_row_t), intent(in) :: s
        integer, intent(out) :: k
        real(dp), intent(out) :: dt, edt
        logical, intent(out) :: ok
        real(dp) :: t(3), et
        integer :: i
        ok = .false.
        k = 0
        dt = 0.0_dp
        edt = 0.0_dp
        do i = 1, 3
            if (.not. s%closing(i)) cycle
            t(i) = s%y(i)/(-s%dy(i))
            if (k == 0) then
                k = i
            else if (t(i) < t(k)) then
                k = i
            end if
        end do
        if (k == 0) then
            ok = .true.
            return
        end if
        dt = t(k)
        if (dt /= 0.0_dp .and. .not. (dt >= normal_floor .and. dt <= huge(1.0_dp))) return
        edt = time_bound(k)
        if (edt < 0.0_dp) return
        do i = 1, 3
            if (i == k .or. .not. s%closing(i)) cycle
            et = time_bound(i)
            if (.not. (et >= 0.0_dp .and. t(i) - dt > 2*(et + edt))) return
        end do
        ok = .true.
    contains
        !> Bound on the computed impact time of gap j (-1: none, the rate's
        !> bound is not below half the rate).
        pure real(dp) function time_bound(j)
            integer, intent(in) :: j
            real(dp) :: r
            r = s%ew(j)/abs(s%dy(j))
            time_bound = -1.0_dp
            if (.not. (r < 0.5_dp)) return
            time_bound = (s%ey(j)/abs(s%dy(j)) + t(j)*r)/(1.0_dp - r) + u64*t(j)
        end function time_bound
    end subroutine bounded_next

    !> Every moving gap advanced by dt (bound edt), as the real(16) path does;
    !> gap k closes exactly. `ok` false if a step underflows.
    pure subroutine bounded_advance(s, k, dt, edt, ok)
        type(bounded_row_t), intent(inout) :: s
        integer, intent(in) :: k
        real(dp), intent(in) :: dt, edt
        logical, intent(out) :: ok
        real(dp) :: step
        integer :: i
        ok = .false.
        do i = 1, 3
            if (i == k) cycle
            if (s%dy(i) == 0.0_dp) then
                s%ey(i) = s%ey(i) + s%ew(i)*(dt + edt)
                cycle
            end if
            step = s%dy(i)*dt
            if (step /= 0.0_dp .and. abs(step) < normal_floor) return
            s%y(i) = max(0.0_dp, s%y(i) + step)
            s%ey(i) = s%ey(i) + abs(s%dy(i))*edt + s%ew(i)*(dt + edt) &
                + u64*(abs(step) + s%y(i))
        end do
        s%y(k) = 0.0_dp
        s%ey(k) = 0.0_dp
        ok = .true.
    end subroutine bounded_advance

    !> The collision at gap k (impact factor kick within ek, restitution e),
    !> its bounds, the certified classes of the rates it changed, and the
    !> certificate that the new rate e |w| is significant. `ok` false if any
    !> of them fails.
    pure subroutine bounded_impact(self, s, k, kick, ek, e, ok)
        type(lean_row_t), intent(in) :: self
        type(bounded_row_t), intent(inout) :: s
        integer, intent(in) :: k
        real(dp), intent(in) :: kick, ek, e
        logical, intent(out) :: ok
        real(dp) :: w, ew, imp, eimp
        w = s%dy(k)
        ew = s%ew(k)
        imp = kick*w
        eimp = kick*ew + abs(w)*ek + u64*abs(imp)
        ! the collision itself (a failed certificate drops the run, whatever
        ! the state), then the bounds of the rates it changed
        call collide_at_dp(s%dy, k, kick, kick, e, s%v1)
        if (k > 1) then
            s%ew(k - 1) = s%ew(k - 1) + eimp + u64*abs(s%dy(k - 1))
            call classify_bounded(self, s, k - 1, ok)
            if (.not. ok) return
        else
            s%ev1 = s%ev1 + eimp + u64*abs(s%v1)
        end if
        if (k < 3) then
            s%ew(k + 1) = s%ew(k + 1) + eimp + u64*abs(s%dy(k + 1))
            call classify_bounded(self, s, k + 1, ok)
            if (.not. ok) return
        end if
        s%ew(k) = e*ew + u64*s%dy(k)
        s%closing(k) = .false.
        ok = s%dy(k) >= normal_floor .and. s%dy(k) - self%tv64 > 2*(s%ew(k) + self%etv)
    end subroutine bounded_impact

    !> Sign bit of a real(16) set (negative numbers and -0).
    elemental logical function is_negative(x)
        real(qp), intent(in) :: x
        is_negative = transfer(x, 0_bits_kind) < 0_bits_kind
    end function is_negative

    !> A real(16) equal to 0 (either sign): all bits but the sign clear.
    elemental logical function is_zero(x)
        real(qp), intent(in) :: x
        is_zero = iand(transfer(x, 0_bits_kind), huge(0_bits_kind)) == 0_bits_kind
    end function is_zero

    include "../../src/engine/sphere_row_rule.inc"

end module sphere_row_lean
