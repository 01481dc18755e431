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
module sphere_row_lean
    use sphere_row, only: qp, scene_t, run_t, scene_check, simulate, status_normal, &
        status_invalid
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
    contains
        !> Check a scene once and prepare its family; `stat` is status_invalid
        !> if the scene is refused or not of the family.
        procedure :: prepare => lean_prepare
        !> v4 of one run at a given e (and how the run ended).
        procedure :: v4 => lean_v4
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
        self%n_stop = min(scene%max_collisions, lean_collisions_max)
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
        real(qp) :: y(3), dt, ti, w, u, r
        integer :: cls(3), runlen(period_check)
        integer :: i, k, l

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
            w = dy(k)
            u = kick*w
            if (k > 1) then
                dy(k - 1) = dy(k - 1) + u
                cls(k - 1) = classify(dy(k - 1))
            else
                v1 = v1 + u
            end if
            if (k < 3) then
                dy(k + 1) = dy(k + 1) + u
                cls(k + 1) = classify(dy(k + 1))
            end if
            dy(k) = neg_e*w
            ! the engine's fallback looks for a quiet group only if this new
            ! rate (e |w| >= 0) is insignificant; a fast gap cannot get there
            if (cls(k) /= gap_fast) then
                if (dy(k) <= self%tv) return
            end if
            cls(k) = gap_open
            c = c + 1
            hist(c) = k
            ! the engine's record of repeats: hand over before it tries a cycle
            do l = 1, min(period_check, c - 1)
                if (hist(c - l) == k) then
                    runlen(l) = runlen(l) + 1
                    if (runlen(l) >= repeats_check*l) return
                else
                    runlen(l) = 0
                end if
            end do
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

end module sphere_row_lean
