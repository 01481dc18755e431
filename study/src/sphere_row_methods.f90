!> The four methods of the comparison behind one interface, for studies that
!> compare them: (1) the event engine in any kind built, (2) absolute variables
!> in real64 or real128, (3) ODE integration with GSL, (4) fixed time steps.
!>
!> A `method_t` names a method and its setting; `method_prepare` converts a
!> real128 scene to the method's kind once, so that `method_run` can be timed
!> on its own; every run reports into an `outcome_t` (sphere_row_outcome).
!> The reference of a scene is the engine in real128 with tol = reference_tol,
!> sqrt(tiny).
module sphere_row_methods
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row, only: dp, qp, scene_t, scene_dp_t, status_normal, status_invalid
    use sphere_row_outcome, only: outcome_t, outcome_start
    use sphere_row_kind_engines, only: kind_engine_t, new_kind_engine, convert_scene, &
        kind_built, kind_info, kind_info_t, built_kinds
    use sphere_row_absolute_dp, only: simulate_absolute
    use sphere_row_absolute_qp, only: simulate_absolute
    use sphere_row_continuous, only: simulate_ode, stepper_rk8pd, stepper_rkf45, stepper_name
    use sphere_row_stepping, only: simulate_stepping, default_max_steps
    use sphere_row_sorting, only: median
    implicit none
    private
    public :: method_t, method_engine, method_absolute, method_ode, method_stepping
    public :: stepper_rk8pd, stepper_rkf45
    public :: reference_tol
    public :: new_method, reference_method, method_prepare, method_run
    public :: method_name, method_label, method_setting, method_v_tol, kind_name
    public :: engine_methods, method_time

    !> Method 1: the event engine in relative variables (sphere_row).
    integer, parameter :: method_engine = 1
    !> Method 2: discrete events in absolute variables.
    integer, parameter :: method_absolute = 2
    !> Method 3: ODE integration with state events (GSL).
    integer, parameter :: method_ode = 3
    !> Method 4: fixed time steps.
    integer, parameter :: method_stepping = 4

    !> A run whose collision sequence is right carries only roundoff of its kind
    !> (and, for the ODE method, its end tolerance) into the final velocities; a
    !> velocity error beyond this many such units makes its final state wrong.
    real(qp), parameter :: state_margin = 1.0e4_qp
    !> The ODE method ends when no rate is below -tol*v0; the rates left over
    !> can move each final velocity by a few times tol*v0, fewer than this many.
    real(qp), parameter :: end_margin = 10.0_qp

    !> Insignificance tolerance of the reference, relative to the scene's
    !> scales: near a collapse the gaps shrink like the square of the rates, so
    !> rates below sqrt(tiny) would leave gaps that underflow real128.
    real(qp), parameter :: reference_tol = sqrt(tiny(1.0_qp))

    !> Most runs in one timing batch: a run too fast for the clock even then
    !> is timed as this many.
    integer, parameter :: max_batch_runs = 2**24
    !> A batch size counts as calibrated once its runs take this part of a
    !> batch's time, well above the clock's resolution.
    real(dp), parameter :: calibrated_part = 0.25_dp

    !> A method with its setting and, once prepared, its scene and work space.
    type :: method_t
        !> One of method_engine, method_absolute, method_ode, method_stepping.
        integer :: id = method_engine
        !> Real kind the method computes in (sp, dp, xdp or qp).
        integer :: precision = qp
        !> The engine's tolerance of insignificant rates and gaps (negative: the
        !> kind's epsilon, the engine's default), or the ODE's accuracy asked for.
        real(qp) :: tol = -1.0_qp
        !> The step h [L/V] of time stepping.
        real(qp) :: h = 0.0_qp
        !> The ODE's stepper: stepper_rk8pd or stepper_rkf45.
        integer :: stepper = stepper_rk8pd
        !> The step budget of time stepping.
        integer(int64) :: max_steps = default_max_steps
        !> Number of spheres of the prepared scene (0: not prepared).
        integer :: p = 0
        !> The engine in the method's kind with its prepared scene and work
        !> space, kept here so that a timed run allocates nothing.
        class(kind_engine_t), allocatable :: engine
        !> Prepared scene of the real64 methods (absolute, ODE, stepping).
        type(scene_dp_t) :: scene_dp
        !> Prepared scene of absolute variables in real128.
        type(scene_t) :: scene_qp
    end type method_t

contains

    !> A method and its setting. `precision` is the real kind (engine: sp, dp,
    !> xdp or qp; absolute: dp or qp; ODE and stepping: dp only); `tol` the
    !> engine's insignificance tolerance (default: the kind's epsilon) or the
    !> ODE accuracy; `h` and `max_steps` the step and budget of time stepping.
    pure function new_method(id, precision, tol, h, stepper, max_steps) result(method)
        integer, intent(in) :: id
        integer, intent(in), optional :: precision, stepper
        real(qp), intent(in), optional :: tol, h
        integer(int64), intent(in), optional :: max_steps
        type(method_t) :: method
        method%id = id
        if (id == method_ode .or. id == method_stepping) method%precision = dp
        if (present(precision)) method%precision = precision
        if (present(tol)) method%tol = tol
        if (present(h)) method%h = h
        if (present(stepper)) method%stepper = stepper
        if (present(max_steps)) method%max_steps = max_steps
    end function new_method

    !> The reference: the engine in real128 with tol = reference_tol. The
    !> relative variables carry each rate with its own relative precision, so
    !> no collision near the collapse threshold is dropped merely because its
    !> rate is below epsilon (the engine's default tolerance drops them from
    !> e - e_c ~ 1e-4 on); below the threshold the collapse limit is taken once
    !> the rates reach reference_tol. The count is right down to e - e_c ~ 1e-7.
    pure function reference_method() result(method)
        type(method_t) :: method
        method = new_method(method_engine, qp, tol=reference_tol)
    end function reference_method

    !> Convert `scene` (real128) to the method's kind and check it; `stat` is
    !> status_normal or status_invalid with `msg` naming the fault.
    subroutine method_prepare(method, scene, stat, msg)
        type(method_t), intent(inout) :: method
        type(scene_t), intent(in) :: scene
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        method%p = 0
        stat = status_invalid
        if (.not. valid_choice(method)) then
            msg = "method "//method_name(method)//": not available in kind " &
                //kind_name(method%precision)
            return
        end if
        if (method%id == method_engine) then
            ! only the engine takes a tolerance of its own (negative: its
            ! kind's epsilon); the other methods keep their kind's epsilon
            call new_kind_engine(method%precision, method%engine)
            call method%engine%prepare(scene, method%tol, stat, msg)
        else if (method%precision == dp) then
            call convert_scene(scene, method%scene_dp, stat, msg)
        else
            call convert_scene(scene, method%scene_qp, stat, msg)
        end if
        if (stat == status_normal) method%p = scene%p
    end subroutine method_prepare

    !> Run the prepared scene once; `record` asks for every collision in `out`.
    !> A method that was not prepared comes back with status_invalid.
    subroutine method_run(method, out, record)
        type(method_t), intent(inout) :: method
        type(outcome_t), intent(inout) :: out
        logical, intent(in), optional :: record
        logical :: keep
        keep = .false.
        if (present(record)) keep = record
        if (method%p == 0) then
            call outcome_start(out, 2, keep)
            out%message = "method_run: the method was not prepared with a valid scene"
            return
        end if
        select case (method%id)
        case (method_absolute)
            if (method%precision == dp) then
                call simulate_absolute(method%scene_dp, out, keep)
            else
                call simulate_absolute(method%scene_qp, out, keep)
            end if
        case (method_ode)
            call simulate_ode(method%scene_dp, real(method%tol, dp), out, keep, method%stepper)
        case (method_stepping)
            call simulate_stepping(method%scene_dp, real(method%h, dp), out, keep, &
                method%max_steps)
        case default
            call outcome_start(out, method%p, keep)
            call method%engine%run_into(out, keep)
        end select
    end subroutine method_run

    !> Whether the method exists in its kind.
    pure logical function valid_choice(method)
        type(method_t), intent(in) :: method
        select case (method%id)
        case (method_engine)
            valid_choice = kind_built(method%precision)
        case (method_absolute)
            valid_choice = any(method%precision == [dp, qp])
        case (method_ode)
            valid_choice = method%precision == dp .and. method%tol > 0.0_qp &
                .and. method%tol < 1.0_qp .and. &
                any(method%stepper == [stepper_rk8pd, stepper_rkf45])
        case (method_stepping)
            valid_choice = method%precision == dp .and. method%h > 0.0_qp &
                .and. method%max_steps > 0
        case default
            valid_choice = .false.
        end select
    end function valid_choice

    !> Short name of a real kind: sp, dp, xdp or qp ("unknown" if not built).
    pure function kind_name(precision) result(name)
        integer, intent(in) :: precision
        character(len=:), allocatable :: name
        type(kind_info_t) :: info
        info = kind_info(precision)
        name = trim(info%name)
    end function kind_name

    !> Name of the method (without kind or setting): engine, absolute,
    !> ode_rk8pd, ode_rkf45 or stepping.
    pure function method_name(method) result(name)
        type(method_t), intent(in) :: method
        character(len=:), allocatable :: name
        select case (method%id)
        case (method_engine)
            name = "engine"
        case (method_absolute)
            name = "absolute"
        case (method_ode)
            name = "ode_"//stepper_name(method%stepper)
        case (method_stepping)
            name = "stepping"
        case default
            name = "unknown"
        end select
    end function method_name

    !> The method's setting: the tolerance of the engine (its kind's epsilon if
    !> not set), absolute and ODE methods, or the step h of time stepping.
    pure real(qp) function method_setting(method) result(setting)
        type(method_t), intent(in) :: method
        select case (method%id)
        case (method_stepping)
            setting = method%h
        case (method_ode)
            setting = method%tol
        case (method_engine)
            setting = method%tol
            if (setting < 0.0_qp) setting = kind_epsilon(method%precision)
        case default
            setting = kind_epsilon(method%precision)
        end select
    end function method_setting

    !> One-word label for tables and plots, e.g. engine_dp, ode_rk8pd_1.0e-6,
    !> stepping_1.0e-3, engine_dp_tol1.5e-154 (an engine with its own tol).
    pure function method_label(method) result(label)
        type(method_t), intent(in) :: method
        character(len=:), allocatable :: label
        select case (method%id)
        case (method_engine, method_absolute)
            label = method_name(method)//"_"//kind_name(method%precision)
            if (method%id == method_engine .and. method%tol >= 0.0_qp) &
                label = label//"_tol"//short_str(method%tol)
        case default
            label = method_name(method)//"_"//short_str(method_setting(method))
        end select
    end function method_label

    !> Two significant digits and the exponent, e.g. 1.0e-6: short enough for a
    !> label, whatever the exponent's size.
    pure function short_str(x) result(text)
        real(qp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=32) :: buf
        integer :: exponent
        real(qp) :: mantissa
        if (.not. (x > 0.0_qp)) then
            write (buf, "(f0.1)") x
        else
            exponent = floor(log10(x))
            mantissa = x/10.0_qp**exponent
            if (nint(10*mantissa) >= 100) then
                exponent = exponent + 1
                mantissa = mantissa/10
            end if
            write (buf, "(f3.1, 'e', i0)") mantissa, exponent
        end if
        text = trim(buf)
    end function short_str

    !> Largest final-velocity error [V] of a run that is still right, for the
    !> scene speed v0: state_margin roundoffs of the method's kind and, for the
    !> ODE method, end_margin times its tolerance (the rates it leaves
    !> unresolved at the end).
    pure real(qp) function method_v_tol(method, v0) result(v_tol)
        type(method_t), intent(in) :: method
        real(qp), intent(in) :: v0
        v_tol = state_margin*kind_epsilon(method%precision)*v0
        if (method%id == method_ode) v_tol = max(v_tol, end_margin*method%tol*v0)
    end function method_v_tol

    !> Epsilon of a real kind built, in real128.
    pure real(qp) function kind_epsilon(precision) result(eps)
        integer, intent(in) :: precision
        type(kind_info_t) :: info
        info = kind_info(precision)
        eps = info%epsilon
    end function kind_epsilon

    !> The engine in every kind built, each with its kind's epsilon as
    !> tolerance; with `tiny_tol`, instead the kinds narrower than the
    !> reference's (the widest, last of built_kinds), each with tol = sqrt(tiny)
    !> of its kind: how far the relative variables reach.
    pure function engine_methods(tiny_tol) result(engines)
        logical, intent(in) :: tiny_tol
        type(method_t), allocatable :: engines(:)
        integer :: k
        if (tiny_tol) then
            engines = [(new_method(method_engine, built_kinds(k)%precision, &
                tol=built_kinds(k)%sqrt_tiny), k=1, size(built_kinds) - 1)]
        else
            engines = [(new_method(method_engine, built_kinds(k)%precision), &
                k=1, size(built_kinds))]
        end if
    end function engine_methods

    !> Median CPU time per run of a prepared method: `batches` batches of
    !> `runs` runs each, so that the whole takes about `min_time` seconds
    !> spread over `repeats` batches; a run slower than min_time is timed once.
    !> The batch size is calibrated by doubling the number of runs until they
    !> take a measurable part of a batch, so that a coarse clock cannot make a
    !> fast run look free.
    subroutine method_time(method, min_time, repeats, seconds, batches, runs)
        type(method_t), intent(inout) :: method
        real(qp), intent(in) :: min_time
        integer, intent(in) :: repeats
        real(qp), intent(out) :: seconds
        integer, intent(out) :: batches, runs
        type(outcome_t) :: run
        real(dp), allocatable :: samples(:)
        real(dp) :: t0, t1, single, batch_time
        integer :: b, j
        batch_time = real(min_time, dp)/repeats
        call method_run(method, run)
        runs = 1
        do
            call cpu_time(t0)
            do j = 1, runs
                call method_run(method, run)
            end do
            call cpu_time(t1)
            if (t1 - t0 >= calibrated_part*batch_time .or. runs >= max_batch_runs) exit
            runs = 2*runs
        end do
        single = (t1 - t0)/runs
        if (runs == 1 .and. single >= real(min_time, dp)) then
            seconds = single
            batches = 1
            return
        end if
        batches = repeats
        runs = max(1, min(max_batch_runs, ceiling(batch_time/max(single, tiny(1.0_dp)))))
        allocate (samples(batches))
        do b = 1, batches
            call cpu_time(t0)
            do j = 1, runs
                call method_run(method, run)
            end do
            call cpu_time(t1)
            samples(b) = (t1 - t0)/runs
        end do
        seconds = median(samples)
    end subroutine method_time

end module sphere_row_methods
