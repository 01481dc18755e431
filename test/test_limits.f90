!> Tests of the collapse limits a run takes, watched by an observer that sees
!> the state before and after each: the bound the run reports for the limits
!> it took by pooling (the fallback and the bounded cascade), against what
!> each limit's own argument requires; the gaps a limit closes at once; when
!> the bounded cascade looks at its bound; that no proof is claimed for a
!> group joined to a closed wall or across the ring's closed seam.
!>
!> A pooling moves the velocities u of spheres lo..hi+1 to their pools' c,
!> keeping the group's momentum. Its argument (docs/collapse.md) puts the
!> velocities the group would have reached within d of c, d = ||u - c|| in the
!> kinetic-energy metric: the cone bound for a cascade at one instant, the
!> energy bound (d = sqrt(2E), every sphere at the mean) for the fallback.
!> The end spheres of a block can move alone without leaving the cone of
!> non-approaching velocities (the first down, the last up), so any bound
!> drawn from that argument covers c_lo - d/sqrt(m_lo) and
!> c_(hi+1) + d/sqrt(m_(hi+1)): it is at least d/sqrt(min(m_lo, m_(hi+1))).
!> The bound tests check that lower bound, limit by limit, against the
!> v_bound the run ends with, which must cover every limit it took.
module test_limits
    use sphere_row, only: qp, scene_t, run_t, observer_t, scene_init, simulate, str, itoa, &
        event_collision, event_collapse, state_now
    use testsuite, only: error_t, unittest_t, new_unittest, check
    use test_support, only: scene_of
    implicit none
    private
    public :: collect_limits

    !> Unit roundoff of the working precision: the bound and the lower bound
    !> here are two roundings of one sum, a few eps apart.
    real(qp), parameter :: eps = epsilon(1.0_qp)

    !> Watches a run and keeps, for every limit, its spheres, the lower bound
    !> d/sqrt(min(m_lo, m_(hi+1))) its bound must reach if it pools them, and
    !> the widest gap among them that it closed at the instant of the
    !> collision before it.
    type, extends(observer_t) :: pooling_watch_t
        !> The scene's masses.
        real(qp), allocatable :: m(:)
        !> The gaps and rates just after the latest collision, the state a rule
        !> looked at, and its time.
        real(qp), allocatable :: y(:), dy(:)
        real(qp) :: t = 0.0_qp
        !> Limits seen, and for each its first and last sphere, lower bound and
        !> widest gap closed at once (0 for a limit after a further time).
        integer :: n = 0
        integer, allocatable :: first(:), last(:)
        real(qp), allocatable :: lower(:), closed(:)
    contains
        procedure :: notify => watch_notify
    end type pooling_watch_t

    !> Watches a row with a left wall or a ring, whose end gap is the wall's
    !> (x_1, the scene's wall placed at x = 0) or the seam's (gap p), as the
    !> rules saw it: just after the collision that a limit completes. It
    !> counts the collisions at the right end of a touching row 1..i joined
    !> to the closed end, the limits whose group was joined to it (sphere 1
    !> at it, or sphere p of the ring), and those among them that raised the
    !> run's count of limits labelled exact, certified or bounded.
    type, extends(observer_t) :: end_watch_t
        integer :: p = 0
        logical :: ring = .false.
        integer :: struck = 0, joined = 0, proven = 0
        !> The end closed just after the latest collision.
        logical :: closed = .false.
        !> The run's limits labelled exact, certified or bounded so far.
        integer :: labelled = 0
        !> The first group found proven while joined (0: none).
        integer :: first = 0, last = 0
    contains
        procedure :: notify => end_notify
    end type end_watch_t

contains

    !> The tests of the bounds of pooled limits.
    function collect_limits() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("v_bound_covers_the_largest_limit", test_largest_limit), &
            new_unittest("bounded_cascade_covers_its_light_end", test_light_end), &
            new_unittest("fallback_covers_its_light_end", test_fallback_group), &
            new_unittest("limit_closes_no_open_gap", test_open_gap), &
            new_unittest("bounded_cascade_looks_again", test_looks_again), &
            new_unittest("no_proof_at_a_closed_end", test_closed_ends) &
            ]
    end function collect_limits

    !> Keep the state after each collision; at each limit, the distance d the
    !> limit moved spheres first..last (each state taken about the group's
    !> momentum-weighted mean, which the limit keeps), d/sqrt of the lighter
    !> end mass, and, if the limit is at the collision's instant, the widest
    !> of the group's gaps before it.
    subroutine watch_notify(self, run, kind, first, last, w)
        class(pooling_watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        integer, intent(in) :: kind, first, last
        real(qp), intent(in) :: w
        real(qp) :: u(first:last), c(first:last), mass, d, x1
        integer :: j
        if (kind == event_collision) then
            call state_now(run, self%y, x1)
            self%dy = run%dy
            self%t = run%t_end
            return
        end if
        if (kind /= event_collapse) return
        u(first) = 0.0_qp
        c(first) = 0.0_qp
        do j = first, last - 1
            u(j + 1) = u(j) + self%dy(j)
            c(j + 1) = c(j) + run%dy(j)
        end do
        associate (m => self%m(first:last))
            mass = sum(m)
            u = u - sum(m*u)/mass
            c = c - sum(m*c)/mass
            d = sqrt(sum(m*(u - c)**2))
        end associate
        self%n = self%n + 1
        self%first = [self%first, first]
        self%last = [self%last, last]
        self%lower = [self%lower, d/sqrt(min(self%m(first), self%m(last)))]
        self%closed = [self%closed, merge(maxval(self%y(first:last - 1)), 0.0_qp, &
            run%t_end == self%t)]
    end subroutine watch_notify

    !> Run `scene` with a fresh watch.
    subroutine watched_run(scene, run, watch)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(inout) :: run
        type(pooling_watch_t), intent(out) :: watch
        watch%m = scene%m
        allocate (watch%y(scene%p - 1), watch%dy(scene%p - 1), watch%first(0), watch%last(0), &
            watch%lower(0), watch%closed(0))
        call simulate(scene, run, observer=watch)
    end subroutine watched_run

    !> Sphere 1 strikes a touching block of five spheres (masses over two
    !> decades) that then strikes a second block of six; the closed-form
    !> rules are off and vtol = 1e-3, so every limit is a cascade at one
    !> instant taken bounded when its cone bound falls within vtol (or the
    !> fallback's). The run takes three limits: the first block's (d/sqrt(m)
    !> about 1e-18), the struck second block's (about 9e-4) and a last one
    !> (about 3e-5): v_bound must cover the largest, not the last.
    subroutine test_largest_limit(error)
        type(error_t), allocatable, intent(out) :: error
        type(pooling_watch_t) :: watch
        integer :: big
        call check_limits_covered(error, "several limits", "p=12 e=0.25 " &
            //"masses=1,3,0.05,2,0.3,5,4,0.1,1.5,0.02,2.5,1 gaps=1,0,0,0,0,1,0,0,0,0,0 " &
            //"vtol=1e-3", 2, watch=watch)
        if (allocated(error)) return
        big = maxloc(watch%lower, 1)
        ! the scene is one where the largest bound comes before a smaller last one
        call check(error, big < watch%n .and. watch%lower(big) > 10*watch%lower(watch%n), &
            "several limits: the largest lower bound "//str(watch%lower(big))// &
            " is not ahead of a last one ten times smaller ("//str(watch%lower(watch%n))//")")
    end subroutine test_largest_limit

    !> A touching row struck at its left end, its last sphere the lightest
    !> (masses 0.01 to 5), the closed-form rules off: its cascade at one
    !> instant is taken as one bounded limit at its first look, after 4096
    !> collisions, its cone bound then within vtol = 1e-3 (d/sqrt(m) of the
    !> light end about 4e-18). That bound is the largest over the block's
    !> spheres, so at least d/sqrt(0.01), twenty times d/sqrt(m) of the
    !> heaviest sphere, to which the smallest of the spheres' bounds comes.
    subroutine test_light_end(error)
        type(error_t), allocatable, intent(out) :: error
        call check_limits_covered(error, "light end", "p=7 e=0.3 " &
            //"masses=5,4,0.1,2,1,5,0.01 gaps=1,0,0,0,0,0 vtol=1e-3", 1)
    end subroutine test_light_end

    !> Six spheres (masses 0.15 to 8.8, the last three gaps closed) at
    !> e = 0.37 with the closed-form rules and the bounded cascade off (vtol =
    !> 0) and tol = 1e-10: the fallback alone takes its collapses (eight),
    !> each once a group's gaps and rates are within tol, and the row then
    !> separates, so that v_bound is its limits' alone (no cone bound of a
    !> run's end is added). A fallback's bound, the energy bound sqrt(2E/m)
    !> of the group's lightest sphere, is at least d/sqrt(m) of either end (d
    !> = sqrt(2E): every sphere goes to the mean), here 1.9e-10 at the
    !> largest; sqrt(2E/m) of the heaviest sphere is not (6e-11).
    subroutine test_fallback_group(error)
        type(error_t), allocatable, intent(out) :: error
        type(run_t) :: run
        call check_limits_covered(error, "fallback", "p=6 e=0.37 masses=0.23,0.15,0.23," &
            //"0.35,8.8,0.16 gaps=1,1,0,0,0 tol=1e-10 vtol=0", 2, run=run)
        if (allocated(error)) return
        call check(error, all(run%dy >= 0.0_qp), "fallback: the row does not separate")
    end subroutine test_fallback_group

    !> The scene of `keys` (key=value words), the closed-form rules off, run
    !> watched: it takes at least `least` limits, and the v_bound it ends with
    !> covers the largest of their lower bounds; `run` and `watch` are what
    !> it ran and saw.
    subroutine check_limits_covered(error, what, keys, least, run, watch)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in) :: what, keys
        integer, intent(in) :: least
        type(run_t), intent(out), optional :: run
        type(pooling_watch_t), intent(out), optional :: watch
        type(scene_t) :: scene
        type(run_t) :: ran
        type(pooling_watch_t) :: seen
        integer :: big
        call scene_of(keys, scene, error)
        if (allocated(error)) return
        scene%closed_form_limits = .false.
        call watched_run(scene, ran, seen)
        if (present(run)) run = ran
        if (present(watch)) watch = seen
        call check(error, seen%n >= least, &
            what//": "//itoa(seen%n)//" limits taken, fewer than "//itoa(least))
        if (allocated(error)) return
        big = maxloc(seen%lower, 1)
        call check(error, ran%v_bound >= seen%lower(big)*(1 - 64*eps), &
            what//": v_bound "//str(ran%v_bound)//" below the lower bound " &
            //str(seen%lower(big))//" of limit "//itoa(big)//" of "//itoa(seen%n) &
            //" (spheres "//itoa(seen%first(big))//"-"//itoa(seen%last(big))//")")
    end subroutine check_limits_covered

    !> Three spheres at e = 0, the middle one heavy (masses 1, 1e4, 1), tol =
    !> 1e-3: sphere 1 strikes sphere 2 and moves on with it, at one velocity,
    !> closing on sphere 3 at 1e-4 v0, a rate below tol v0 that ends the run.
    !> Gap 2 is still 1 (of the scene's 1), not closed: no limit may pool
    !> sphere 3 with the others. Every limit a run takes at the instant of a
    !> collision (the plastic pool, a touching block, the fallback, the
    !> bounded cascade) closes only gaps within tol max(a) of closed; only a
    !> cycle's limit, after its further time, closes open ones.
    subroutine test_open_gap(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: run
        type(pooling_watch_t) :: watch
        integer :: j
        call scene_of("p=3 e=0 masses=1,1e4,1 tol=1e-3", scene, error)
        if (allocated(error)) return
        call watched_run(scene, run, watch)
        if (watch%n == 0) return
        j = maxloc(watch%closed, 1)
        call check(error, watch%closed(j) <= scene%tol*maxval(scene%a), &
            "open gap: a limit at a collision's instant closed a gap of " &
            //str(watch%closed(j))//" (spheres "//itoa(watch%first(j))//"-" &
            //itoa(watch%last(j))//")")
    end subroutine test_open_gap

    !> A touching row of 20 equal spheres struck at one end, the closed-form
    !> rules off: its cascade at one instant is looked at by the bounded
    !> cascade after 4096 collisions, then after 8192, 16384, ... With vtol
    !> at a third of the bound b of the first look (2.1e-9), the cascade is
    !> taken at the next look, after 8192 collisions (its bound then 1.9e-17,
    !> measured), not stepped on to the fallback's insignificant rates (16,249
    !> collisions).
    subroutine test_looks_again(error)
        type(error_t), allocatable, intent(out) :: error
        type(scene_t) :: scene
        type(run_t) :: first, later
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=20, e=0.5_qp, gaps=spread(0.0_qp, 1, 19))
        scene%closed_form_limits = .false.
        scene%vtol = 0.999_qp
        call simulate(scene, first)
        scene%vtol = first%v_bound/3
        call simulate(scene, later)
        call check(error, first%limits%n == 1 .and. later%limits%n == 1 .and. &
            later%n > first%n .and. later%n <= 2*first%n .and. later%v_bound <= scene%vtol, &
            "looks again: at vtol "//str(scene%vtol)//" taken after "//itoa(later%n) &
            //" collisions with the bound "//str(later%v_bound)//"; at its first look after " &
            //itoa(first%n))
    end subroutine test_looks_again

    !> A collision or a limit of a row with a left wall or a ring (end_watch_t).
    subroutine end_notify(self, run, kind, first, last, w)
        class(end_watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        integer, intent(in) :: kind, first, last
        real(qp), intent(in) :: w
        real(qp) :: y(size(run%y)), x1
        integer :: labelled
        if (kind == event_collision) then
            call state_now(run, y, x1)
            self%closed = .not. x1 > 0.0_qp
            if (self%ring) self%closed = .not. y(self%p) > 0.0_qp
            if (self%closed .and. first >= 2 .and. last == first + 1) then
                if (all(y(:first - 1) == 0.0_qp)) self%struck = self%struck + 1
            end if
        else if (kind == event_collapse) then
            labelled = run%limits%exact + run%limits%certified + run%limits%bounded
            if (self%closed .and. (first == 1 .or. (self%ring .and. last == self%p))) then
                self%joined = self%joined + 1
                if (labelled > self%labelled) then
                    self%proven = self%proven + 1
                    if (self%first == 0) then
                        self%first = first
                        self%last = last
                    end if
                end if
            end if
            self%labelled = labelled
        end if
    end subroutine end_notify

    !> The rules prove a limit for a group with open ends: a wall is a
    !> sphere of infinite mass that no group's mean velocity holds, and the
    !> seam is a gap no group crosses (docs/scenes.md). A group joined to a
    !> closed wall or seam is taken only at tolerance (the wall's group, the
    !> fallback's parts), never exact, certified or bounded. Each scene
    !> throws a touching row at the closed end (a wall of restitution 0, or
    !> a sphere at rest across the seam) with one more sphere behind it, and
    !> its cascades there strike touching rows against the end. Measured by
    !> dropping one rule's check of the ends (ends_open), the first scene
    !> that fails and its limits joined to the end labelled so: the struck
    !> block's, the wall at e = 0 (2 of its 5, spheres 1-3, exact; the ring
    !> at e = 0 alone: 2 of 4); the plastic pooling's, the wall at e = 0 (187
    !> of 189); the touching block's, the wall at e = 0.1 (287 of 296); the
    !> bounded cascade's, the wall at e = 0.1 (1 of 13).
    subroutine test_closed_ends(error)
        type(error_t), allocatable, intent(out) :: error
        call check_closed_end(error, "wall", &
            "p=3 e=0 e_wall=0 wall_left=0.5 velocities=-1,-1,-0.5 gaps=0,1")
        if (allocated(error)) return
        call check_closed_end(error, "ring", &
            "p=6 e=0 ring=0.5 velocities=-1,-1,-1,-1,-0.5,0 gaps=0,0,0,1,1")
        if (allocated(error)) return
        call check_closed_end(error, "wall, e = 0.1", "p=6 e=0.1 e_wall=0 wall_left=0.5 " &
            //"velocities=-1,-1,-1,-1,-1,-0.5 gaps=0,0,0,0,1")
        if (allocated(error)) return
        call check_closed_end(error, "ring, e = 0.1", "p=10 e=0.1 ring=0.5 " &
            //"velocities=-1,-1,-1,-1,-1,-1,-1,-1,-0.5,0 gaps=0,0,0,0,0,0,0,1,1")
    end subroutine test_closed_ends

    !> The scene of `keys`, run watched by an end_watch_t: it strikes a
    !> touching row against its closed end and takes limits of groups joined
    !> to that end, none of them labelled exact, certified or bounded.
    subroutine check_closed_end(error, what, keys)
        type(error_t), allocatable, intent(out) :: error
        character(len=*), intent(in) :: what, keys
        type(scene_t) :: scene
        type(run_t) :: run
        type(end_watch_t) :: watch
        call scene_of(keys, scene, error)
        if (allocated(error)) return
        ! (the wall at x = 0: x_1 is then sphere 1's gap to it, unrounded)
        if (scene%wall_left >= 0.0_qp) scene%x1 = scene%wall_left
        watch%p = scene%p
        watch%ring = scene%ring >= 0.0_qp
        call simulate(scene, run, observer=watch)
        call check(error, watch%struck > 0 .and. watch%joined > 0, what//": " &
            //itoa(watch%struck)//" collisions at the end of a touching row against the " &
            //"closed end and "//itoa(watch%joined)//" limits joined to it, in " &
            //itoa(run%n)//" collisions")
        if (allocated(error)) return
        call check(error, watch%proven == 0, what//": "//itoa(watch%proven)//" of " &
            //itoa(watch%joined)//" limits joined to the closed end labelled exact, " &
            //"certified or bounded, the first of spheres "//itoa(watch%first)//"-" &
            //itoa(watch%last))
    end subroutine check_closed_end

end module test_limits
