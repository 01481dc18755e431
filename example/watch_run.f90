!> What a run holds, and a run watched while it goes: the definition's row at
!> e = 0.1, which collapses, its answer read from the fields of run_t as
!> sphere-row prints them, and an observer that hears every event and
!> samples the kinetic energy at t = 1, 2, 4, ... (docs/library.md).
!>
!>     fpm run --example watch-run
module watch_run_energy
    use sphere_row, only: qp, scene_t, run_t, observer_t, event_collision, event_collapse, &
        event_sample, velocities_now, kinetic_energy, itoa, real_str
    implicit none
    private
    public :: energy_watch_t

    !> An observer: counts the collisions and limits it hears of, and at
    !> each sample time (its wake, then twice that) prints the energy.
    type, extends(observer_t) :: energy_watch_t
        !> The scene being run: its masses weigh the energy.
        type(scene_t), pointer :: scene => null()
        !> Collisions and collapse limits heard so far.
        integer :: collisions = 0, limits = 0
    contains
        procedure :: notify => energy_notify
    end type energy_watch_t

contains

    !> One event of the run, or a sample time reached (the time in w).
    subroutine energy_notify(self, run, kind, first, last, w)
        class(energy_watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        integer, intent(in) :: kind, first, last
        real(qp), intent(in) :: w
        real(qp), allocatable :: v(:)
        real(qp) :: norm
        select case (kind)
        case (event_collision)
            self%collisions = self%collisions + 1
        case (event_collapse)
            self%limits = self%limits + 1
        case (event_sample)
            ! the velocities until the next event, within norm in the energy norm
            allocate (v(self%scene%p))
            call velocities_now(self%scene, run, v, norm)
            print "(a)", "t = "//real_str(w, 2)//": "//itoa(run%n)//" collisions, energy " &
                //real_str(kinetic_energy(self%scene, v), 6)
            self%wake = 2*w
        case default
            ! event_start: nothing to count
        end select
    end subroutine energy_notify

end module watch_run_energy

program watch_run
    use sphere_row, only: qp, scene_t, run_t, scene_init, simulate, status_normal, &
        status_invalid, status_word, answer_word, collapse_proven, kinetic_energy, itoa, str, &
        real_str
    use watch_run_energy, only: energy_watch_t
    implicit none
    type(scene_t), target :: scene
    type(run_t) :: run
    type(energy_watch_t) :: watch
    integer :: stat, i
    character(len=200) :: msg
    call scene_init(scene, stat, msg, p=4, e=0.1_qp)
    if (stat /= status_normal) error stop trim(msg)
    watch%scene => scene
    watch%wake = 1.0_qp
    call simulate(scene, run, observer=watch)
    if (run%status == status_invalid) error stop trim(run%message)
    print "(a)", "heard "//itoa(watch%collisions)//" collisions and "//itoa(watch%limits) &
        //" limits"
    print "(a)", "collisions "//itoa(run%n)
    print "(a)", "t_end "//str(run%t_end)
    print "(a)", "status "//status_word(run%status)
    print "(a)", "answer "//answer_word(run%answer)
    print "(a)", "v_bound "//real_str(run%v_bound, 2)
    if (run%limits%n > 0) then
        print "(a)", "collapses "//itoa(run%limits%n)//", in closed form " &
            //itoa(run%limits%closed_form)//", certified "//itoa(run%limits%certified)
        print "(a)", "collapse "//trim(merge("proven  ", "unproven", collapse_proven(run)))
        print "(a)", "collapse_spheres "//itoa(run%limits%first)//"-"//itoa(run%limits%last)
        print "(a)", "collapse_t "//str(run%limits%t)
    end if
    do i = 1, scene%p
        print "(a)", "v"//itoa(i)//" "//str(run%v(i))//" within "//real_str(run%v_bounds(i), 2)
    end do
    print "(a)", "energy "//real_str(kinetic_energy(scene, run%v), 6)//" of " &
        //real_str(0.5_qp*scene%m(1)*scene%v0**2, 6)
end program watch_run
