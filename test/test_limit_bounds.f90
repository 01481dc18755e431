!> Tests of the bound a run reports for the collapse limits it took by pooling
!> (the fallback and the bounded cascade), against what each limit's own
!> argument requires, computed here from the state before and after it.
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
!> These tests check that lower bound, limit by limit, against the v_bound the
!> run ends with, which must cover every limit it took.
module test_limit_bounds
    use sphere_row, only: qp, scene_t, run_t, observer_t, scene_init, simulate, str, itoa, &
        event_collision, event_collapse
    use testsuite, only: error_t, unittest_t, new_unittest, check
    implicit none
    private
    public :: collect_limit_bounds

    !> Unit roundoff of the working precision: the bound and the lower bound
    !> here are two roundings of one sum, a few eps apart.
    real(qp), parameter :: eps = epsilon(1.0_qp)

    !> Watches a run and keeps, for every limit taken by pooling, its spheres
    !> and the lower bound d/sqrt(min(m_lo, m_(hi+1))) its bound must reach.
    type, extends(observer_t) :: pooling_watch_t
        !> The scene's masses.
        real(qp), allocatable :: m(:)
        !> The rates just after the latest collision: the state a rule looked at.
        real(qp), allocatable :: dy(:)
        !> Limits seen, and for each its first and last sphere and lower bound.
        integer :: n = 0
        integer, allocatable :: first(:), last(:)
        real(qp), allocatable :: lower(:)
    contains
        procedure :: notify => watch_notify
    end type pooling_watch_t

contains

    !> The tests of the bounds of pooled limits.
    function collect_limit_bounds() result(tests)
        type(unittest_t), allocatable :: tests(:)
        tests = [ &
            new_unittest("v_bound_covers_the_largest_limit", test_largest_limit), &
            new_unittest("bounded_cascade_covers_its_light_end", test_light_end) &
            ]
    end function collect_limit_bounds

    !> Keep the rates after each collision; at each limit, the distance d the
    !> limit moved spheres first..last (each state taken about the group's
    !> momentum-weighted mean, which the limit keeps) and d/sqrt of the
    !> lighter end mass.
    subroutine watch_notify(self, run, kind, first, last, w)
        class(pooling_watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        integer, intent(in) :: kind, first, last
        real(qp), intent(in) :: w
        real(qp) :: u(first:last), c(first:last), mass, d
        integer :: j
        if (kind == event_collision) then
            self%dy = run%dy
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
    end subroutine watch_notify

    !> Run `scene` with a fresh watch.
    subroutine watched_run(scene, run, watch)
        type(scene_t), intent(in) :: scene
        type(run_t), intent(inout) :: run
        type(pooling_watch_t), intent(out) :: watch
        watch%m = scene%m
        allocate (watch%dy(scene%p - 1), watch%first(0), watch%last(0), watch%lower(0))
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
        type(scene_t) :: scene
        type(run_t) :: run
        type(pooling_watch_t) :: watch
        integer :: stat, big
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=12, e=0.25_qp, &
            masses=[1.0_qp, 3.0_qp, 0.05_qp, 2.0_qp, 0.3_qp, 5.0_qp, 4.0_qp, 0.1_qp, 1.5_qp, &
            0.02_qp, 2.5_qp, 1.0_qp], &
            gaps=[1.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, 1.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, &
            0.0_qp, 0.0_qp])
        scene%closed_form_limits = .false.
        scene%vtol = 1.0e-3_qp
        call watched_run(scene, run, watch)
        call check(error, watch%n >= 2, "several limits: "//itoa(watch%n)//" taken")
        if (allocated(error)) return
        big = maxloc(watch%lower, 1)
        ! the scene is one where the largest bound comes before a smaller last one
        call check(error, big < watch%n .and. watch%lower(big) > 10*watch%lower(watch%n), &
            "several limits: the largest lower bound "//str(watch%lower(big))// &
            " is not ahead of a last one ten times smaller ("//str(watch%lower(watch%n))//")")
        call check(error, run%v_bound >= watch%lower(big)*(1 - 64*eps), &
            "several limits: v_bound "//str(run%v_bound)//" below the lower bound " &
            //str(watch%lower(big))//" of limit "//itoa(big)//" of "//itoa(watch%n) &
            //" (spheres "//itoa(watch%first(big))//"-"//itoa(watch%last(big))//")")
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
        type(scene_t) :: scene
        type(run_t) :: run
        type(pooling_watch_t) :: watch
        integer :: stat
        character(len=200) :: msg
        call scene_init(scene, stat, msg, p=7, e=0.3_qp, &
            masses=[5.0_qp, 4.0_qp, 0.1_qp, 2.0_qp, 1.0_qp, 5.0_qp, 0.01_qp], &
            gaps=[1.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, 0.0_qp, 0.0_qp])
        scene%closed_form_limits = .false.
        scene%vtol = 1.0e-3_qp
        call watched_run(scene, run, watch)
        call check(error, watch%n >= 1, "light end: no limit taken")
        if (allocated(error)) return
        call check(error, run%v_bound >= maxval(watch%lower)*(1 - 64*eps), &
            "light end: v_bound "//str(run%v_bound)//" below the lower bound " &
            //str(maxval(watch%lower))//" of its limit")
    end subroutine test_light_end

end module test_limit_bounds
