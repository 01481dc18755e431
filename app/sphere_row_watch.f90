!> What sphere-row watches of a run while it goes: the event table, written
!> row by row as the events happen (constant memory, however long the run),
!> the samples of a time series at the times asked for, and progress lines on
!> stderr for a long run: every few seconds on a terminal, now and then into
!> a file or a pipe (a log of a long job).
module sphere_row_watch
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use sphere_row, only: qp, run_t, scene_t, observer_t, state_now, itoa, event_collision, &
        event_collapse, event_sample, real_text, int_text, number_text_length, real_str, &
        earned_str, gaps_at_time, velocities_now
    use sphere_row_system, only: text_out_t
    implicit none
    private
    public :: watch_t, event_header, sample_header, progress_on_terminal, progress_elsewhere

    !> The columns of the samples' table (their units: T and the energy in
    !> those of m v0^2).
    character(len=*), parameter :: sample_header = "t"//achar(9)//"temperature"//achar(9) &
        //"energy"//achar(9)//"collisions_per_sphere"//achar(9)//"clusters"

    !> Seconds between progress lines on a terminal and elsewhere (a log
    !> wants fewer), and the collisions between looks at the clock (a look
    !> costs about as much as a collision).
    real, parameter :: progress_on_terminal = 2.0, progress_elsewhere = 10.0
    integer, parameter :: look_every = 65536

    !> The observer of sphere-row: rows of the event table onto `out` (if
    !> `events`), progress lines on stderr (if `progress`), every
    !> `progress_every` seconds, against the run's work budget `budget` (in
    !> collisions) and its speed v0.
    type, extends(observer_t) :: watch_t
        logical :: events = .false., progress = .false.
        real :: progress_every = progress_on_terminal
        integer :: budget = 0
        real(qp) :: v0 = 1.0_qp
        type(text_out_t), pointer :: out => null()
        !> The first event whose row would hold a number beyond real(16) (0 if
        !> none): no row is written from it on.
        integer :: overflow = 0
        integer(int64) :: started = 0, last = 0
        real(qp), allocatable :: y(:)
        !> The row being built, and its length so far.
        character(len=:), allocatable :: row
        integer :: at = 0
        !> The samples' table (if `samples`), of the scene `scene` up to its
        !> horizon, every `sample_every` (0: log-spaced, `per_decade` a decade
        !> from t_max/10^decades on, after t = 0), the k-th next.
        logical :: samples = .false.
        type(text_out_t), pointer :: sample_out => null()
        type(scene_t), pointer :: scene => null()
        real(qp) :: sample_every = 0.0_qp
        integer :: per_decade = 10, decades = 4, k = 0
    contains
        procedure :: notify => watch_notify
        procedure, private :: add_word => watch_add_word
        procedure, private :: add_real => watch_add_real
    end type watch_t

contains

    !> The header of the event table for p spheres (L: the unit of d and a;
    !> V: the unit of v0; the columns as sphere_row_lines describes them),
    !> assembled in one buffer of its full length: appending column by
    !> column would copy the header once per column, time quadratic in p.
    function event_header(p, last_gap) result(line)
        integer, intent(in) :: p
        !> Gap p is carried (a wall on the right, or a ring's seam).
        logical, intent(in) :: last_gap
        character(len=:), allocatable :: line
        character(len=*), parameter :: tab = achar(9), fixed = "event"//tab//"kind"//tab &
            //"first"//tab//"last"//tab//"t[L/V]"//tab//"w[V]"//tab//"x1[L]"//tab//"dx1[V]"
        character(len=number_text_length) :: digits
        character(len=:), allocatable :: buffer
        integer :: k, n, at
        ! every column name is its prefix, at most len(itoa(p)) digits and its unit
        integer :: ng
        ng = p - 1
        if (last_gap) ng = p
        allocate (character(len=len(fixed) + 2*max(ng, 0)*(len(itoa(p)) + 6)) :: buffer)
        buffer(:len(fixed)) = fixed
        at = len(fixed)
        do k = 1, ng
            call int_text(int(k, int64), digits, n)
            call put(tab//"y"//digits(:n)//"[L]")
        end do
        do k = 1, ng
            call int_text(int(k, int64), digits, n)
            call put(tab//"dy"//digits(:n)//"[V]")
        end do
        line = buffer(:at)
    contains
        subroutine put(name)
            character(len=*), intent(in) :: name
            buffer(at + 1:at + len(name)) = name
            at = at + len(name)
        end subroutine put
    end function event_header

    !> An event: its row of the table, and now and then a progress line.
    subroutine watch_notify(self, run, kind, first, last, w)
        class(watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        integer, intent(in) :: kind, first, last
        real(qp), intent(in) :: w
        real(qp) :: x1
        integer(int64) :: now, rate
        integer :: k
        if (self%events .and. self%overflow == 0) then
            if (.not. allocated(self%y)) allocate (self%y(size(run%y)))
            call state_now(run, self%y, x1)
            if (.not. all(abs([self%y, run%dy, x1, run%dx1, run%clock%t, w]) <= huge(x1))) then
                self%overflow = run%n + run%limits%n
            end if
        end if
        if (self%events .and. self%overflow == 0) then
            ! the row built in a buffer of its full length (appending to a
            ! text would copy it once per number: quadratic in p)
            if (.not. allocated(self%row)) allocate (character(len=(2*size(run%y) + 8) &
                *(number_text_length + 1)) :: self%row)
            self%at = 0
            ! events so far: the start is 0, every collision and limit one more
            call self%add_word(itoa(run%n + run%limits%n))
            select case (kind)
            case (event_collision)
                call self%add_word("collision")
            case (event_collapse)
                call self%add_word("collapse")
            case default
                call self%add_word("start")
            end select
            call self%add_word(itoa(first))
            call self%add_word(itoa(last))
            call self%add_real(run%clock%t)
            call self%add_real(w)
            call self%add_real(x1)
            call self%add_real(run%dx1)
            do k = 1, size(self%y)
                call self%add_real(self%y(k))
            end do
            do k = 1, size(run%dy)
                call self%add_real(run%dy(k))
            end do
            call self%out%put(self%row(:self%at))
        end if
        if (kind == event_sample) then
            if (self%samples) call write_sample(self, run, w)
            return
        end if
        if (.not. self%progress .or. kind /= event_collision) return
        if (mod(run%n, look_every) /= 0) return
        call system_clock(now, rate)
        if (self%started == 0) then
            self%started = now
            self%last = now
            return
        end if
        if (real(now - self%last)/real(rate) < self%progress_every) return
        self%last = now
        call write_progress(self, run, (now - self%started)/rate)
    end subroutine watch_notify

    !> The sample at time t (the run's velocities, its gaps moved on to t): t,
    !> the temperature sum m (v - V)^2/p (twice the kinetic energy about the
    !> centre of mass, per sphere), the kinetic energy, the collisions per
    !> sphere 2n/p, and the clusters: runs of two or more spheres touching
    !> (gaps 0, a ring's seam too). The temperature and the energy are
    !> written to the decade of their bounds (velocities_now's); then the
    !> next sample's time.
    subroutine write_sample(self, run, t)
        class(watch_t), intent(inout) :: self
        type(run_t), intent(in) :: run
        real(qp), intent(in) :: t
        real(qp), allocatable :: v(:), y(:)
        real(qp) :: norm, mass, mean, temperature, energy, t_bound, e_bound
        integer :: p, clusters, i
        logical :: touching, before
        p = self%scene%p
        allocate (v(p), y(size(run%y)))
        call velocities_now(self%scene, run, v, norm)
        mass = sum(self%scene%m)
        mean = sum(self%scene%m*v)/mass
        temperature = sum(self%scene%m*(v - mean)**2)/p
        energy = 0.5_qp*sum(self%scene%m*v**2)
        t_bound = (2*sqrt(p*temperature)*norm + norm**2)/p
        e_bound = sqrt(2*energy)*norm + norm**2/2
        call gaps_at_time(run, t, y)
        clusters = 0
        before = .false.
        do i = 1, p - 1
            touching = y(i) == 0.0_qp
            if (touching .and. .not. before) clusters = clusters + 1
            before = touching
        end do
        ! (a ring's cluster across the seam is one, not two)
        if (size(y) == p .and. self%scene%ring >= 0) then
            if (y(p) == 0.0_qp) then
                if (y(1) == 0.0_qp .and. y(p - 1) == 0.0_qp .and. clusters > 1) then
                    clusters = clusters - 1
                else if (y(1) /= 0.0_qp .and. y(p - 1) /= 0.0_qp) then
                    clusters = clusters + 1
                end if
            end if
        end if
        call self%sample_out%put(real_str(t, precision(t) + 1)//achar(9) &
            //earned_str(temperature, t_bound)//achar(9)//earned_str(energy, e_bound)//achar(9) &
            //real_str(2.0_qp*real(run%n, qp)/p, 6)//achar(9)//itoa(clusters))
        self%k = self%k + 1
        self%wake = next_sample(self)
    end subroutine write_sample

    !> The time of sample k (k = 0 the first, at t = 0) of a table up to the
    !> scene's horizon; huge past it.
    pure real(qp) function next_sample(self) result(t)
        class(watch_t), intent(in) :: self
        integer :: last
        t = huge(1.0_qp)
        if (self%sample_every > 0) then
            t = self%k*self%sample_every
            if (t > self%scene%t_max) t = huge(1.0_qp)
            return
        end if
        last = self%per_decade*self%decades
        if (self%k == 0) then
            t = 0
        else if (self%k <= last + 1) then
            t = self%scene%t_max*10.0_qp**(real(self%k - 1 - last, qp)/self%per_decade)
        end if
    end function next_sample

    !> The progress line: the collisions against the work budget, the time
    !> reached, and the fastest rate at which neighbours still close (the
    !> run is over when none closes faster than tol v0; a budget spent first
    !> ends it `unresolved`), then the wall seconds since the first look.
    subroutine write_progress(self, run, seconds)
        class(watch_t), intent(in) :: self
        type(run_t), intent(in) :: run
        integer(int64), intent(in) :: seconds
        real(qp) :: closing
        integer :: percent
        closing = 0
        if (size(run%dy) > 0) closing = max(0.0_qp, -minval(run%dy))/self%v0
        percent = int(100.0_qp*real(run%n, qp)/real(max(self%budget, 1), qp))
        write (error_unit, "(a)") "sphere-row: progress: "//itoa(run%n)//" of " &
            //itoa(self%budget)//" collisions (max_collisions, "//itoa(percent)//" %), t = " &
            //real_str(run%clock%t, 4)//", fastest closing rate "//real_str(closing, 2) &
            //" v0, "//itoa(seconds)//" s"
    end subroutine write_progress

    !> Append a field to the row (after a tab unless it is the first).
    subroutine watch_add_word(self, word)
        class(watch_t), intent(inout) :: self
        character(len=*), intent(in) :: word
        if (self%at > 0) then
            self%at = self%at + 1
            self%row(self%at:self%at) = achar(9)
        end if
        self%row(self%at + 1:self%at + len(word)) = word
        self%at = self%at + len(word)
    end subroutine watch_add_word

    !> Append a real with every digit of real(16) (as str writes it).
    subroutine watch_add_real(self, x)
        class(watch_t), intent(inout) :: self
        real(qp), intent(in) :: x
        character(len=number_text_length) :: text
        integer :: length
        call real_text(x, precision(x) + 1, text, length)
        call self%add_word(text(:length))
    end subroutine watch_add_real

end module sphere_row_watch
