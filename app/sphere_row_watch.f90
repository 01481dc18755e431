!> What sphere-row watches of a run while it goes: the event table, written
!> row by row as the events happen (constant memory, however long the run),
!> and progress lines on stderr for a long run: every few seconds on a
!> terminal, now and then into a file or a pipe (a log of a long job).
module sphere_row_watch
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use sphere_row, only: qp, run_t, observer_t, state_now, itoa, event_collision, &
        event_collapse, real_text, int_text, number_text_length, real_str
    use sphere_row_system, only: text_out_t
    implicit none
    private
    public :: watch_t, event_header, progress_on_terminal, progress_elsewhere

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
    function event_header(p) result(line)
        integer, intent(in) :: p
        character(len=:), allocatable :: line
        character(len=*), parameter :: tab = achar(9), fixed = "event"//tab//"kind"//tab &
            //"first"//tab//"last"//tab//"t[L/V]"//tab//"w[V]"//tab//"x1[L]"//tab//"dx1[V]"
        character(len=number_text_length) :: digits
        character(len=:), allocatable :: buffer
        integer :: k, n, at
        ! every column name is its prefix, at most len(itoa(p)) digits and its unit
        allocate (character(len=len(fixed) + 2*max(p - 1, 0)*(len(itoa(p)) + 6)) :: buffer)
        buffer(:len(fixed)) = fixed
        at = len(fixed)
        do k = 1, p - 1
            call int_text(int(k, int64), digits, n)
            call put(tab//"y"//digits(:n)//"[L]")
        end do
        do k = 1, p - 1
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
