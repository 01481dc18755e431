!> The four methods of issue 4 behind one interface, for studies that compare
!> them: (1) the event engine in any kind, (2) absolute variables in real64 or
!> real128, (3) ODE integration with GSL, (4) fixed time steps.
!>
!> A `method_t` names a method and its setting; `method_prepare` converts a
!> real128 scene to the method's kind once, so that `method_run` can be timed
!> on its own; every run reports into an `outcome_t` (sphere_row_outcome).
!> The reference of a scene is the engine in real128 with tol = 0.
module sphere_row_methods
    use, intrinsic :: iso_fortran_env, only: int64
    use sphere_row_kinds, only: sp, dp, xdp, qp
    use sphere_row_status, only: status_normal, status_invalid, event_collision
    use sphere_row, only: scene_t, run_t, event_log_t, scene_xdp_t, run_xdp_t, &
        event_log_xdp_t, scene_dp_t, run_dp_t, event_log_dp_t, scene_sp_t, run_sp_t, &
        event_log_sp_t, scene_init, simulate
    use sphere_row_outcome, only: outcome_t, outcome_start, outcome_add
    use sphere_row_absolute_dp, only: simulate_absolute_dp => simulate_absolute_wp
    use sphere_row_absolute_qp, only: simulate_absolute_qp => simulate_absolute_wp
    use sphere_row_continuous, only: simulate_ode, stepper_rk8pd, stepper_rkf45, stepper_name
    use sphere_row_stepping, only: simulate_stepping, default_max_steps
    implicit none
    private
    public :: method_t, method_engine, method_absolute, method_ode, method_stepping
    public :: stepper_rk8pd, stepper_rkf45
    public :: reference_tol
    public :: new_method, reference_method, method_prepare, method_run
    public :: method_name, method_label, method_setting, method_v_tol, kind_name

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

    !> A method with its setting and, once prepared, its scene and work space.
    type :: method_t
        !> One of method_engine, method_absolute, method_ode, method_stepping.
        integer :: id = method_engine
        !> Real kind the method computes in (sp, dp, xdp or qp).
        integer :: precision = qp
        !> Engine: tolerance of insignificant rates and gaps (negative: the
        !> kind's epsilon, the engine's default). ODE: the accuracy asked for.
        real(qp) :: tol = -1.0_qp
        !> Time stepping: the step h [L/V].
        real(qp) :: h = 0.0_qp
        !> ODE: stepper_rk8pd or stepper_rkf45.
        integer :: stepper = stepper_rk8pd
        !> Time stepping: the step budget.
        integer(int64) :: max_steps = default_max_steps
        !> Number of spheres of the prepared scene (0: not prepared).
        integer :: p = 0
        ! The prepared scene in the method's kind and the engine's work space,
        ! kept here so that a timed run allocates nothing; only the entries of
        ! the method's kind are used.
        !> Prepared scene, real32 (engine).
        type(scene_sp_t) :: scene_sp
        !> Engine run, real32.
        type(run_sp_t) :: run_sp
        !> Engine event log, real32 (recorded runs).
        type(event_log_sp_t) :: log_sp
        !> Prepared scene, real64 (engine, absolute, ODE, stepping).
        type(scene_dp_t) :: scene_dp
        !> Engine run, real64.
        type(run_dp_t) :: run_dp
        !> Engine event log, real64 (recorded runs).
        type(event_log_dp_t) :: log_dp
        !> Prepared scene, 80-bit extended (engine).
        type(scene_xdp_t) :: scene_xdp
        !> Engine run, 80-bit extended.
        type(run_xdp_t) :: run_xdp
        !> Engine event log, 80-bit extended (recorded runs).
        type(event_log_xdp_t) :: log_xdp
        !> Prepared scene, real128 (engine, absolute).
        type(scene_t) :: scene_qp
        !> Engine run, real128.
        type(run_t) :: run_qp
        !> Engine event log, real128 (recorded runs).
        type(event_log_t) :: log_qp
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
        logical :: own_tol
        method%p = 0
        stat = status_invalid
        if (.not. valid_choice(method)) then
            msg = "method "//method_name(method)//": not available in kind " &
                //kind_name(method%precision)
            return
        end if
        ! Only the engine takes a tolerance of its own; the other methods keep
        ! the default of scene_init, their kind's epsilon.
        own_tol = method%id == method_engine .and. method%tol >= 0.0_qp
        select case (method%precision)
        case (sp)
            call scene_init(method%scene_sp, stat, msg, p=scene%p, e=real(scene%e, sp), &
                d=real(scene%d, sp), v0=real(scene%v0, sp), masses=real(scene%m, sp), &
                gaps=real(scene%a, sp), max_collisions=scene%max_collisions)
            if (own_tol) method%scene_sp%tol = real(method%tol, sp)
        case (dp)
            call scene_init(method%scene_dp, stat, msg, p=scene%p, e=real(scene%e, dp), &
                d=real(scene%d, dp), v0=real(scene%v0, dp), masses=real(scene%m, dp), &
                gaps=real(scene%a, dp), max_collisions=scene%max_collisions)
            if (own_tol) method%scene_dp%tol = real(method%tol, dp)
        case (xdp)
            call scene_init(method%scene_xdp, stat, msg, p=scene%p, e=real(scene%e, xdp), &
                d=real(scene%d, xdp), v0=real(scene%v0, xdp), masses=real(scene%m, xdp), &
                gaps=real(scene%a, xdp), max_collisions=scene%max_collisions)
            if (own_tol) method%scene_xdp%tol = real(method%tol, xdp)
        case (qp)
            call scene_init(method%scene_qp, stat, msg, p=scene%p, e=scene%e, d=scene%d, &
                v0=scene%v0, masses=scene%m, gaps=scene%a, max_collisions=scene%max_collisions)
            if (own_tol) method%scene_qp%tol = method%tol
        end select
        if (stat == status_normal) method%p = scene%p
    end subroutine method_prepare

    !> Run the prepared scene once; `record` asks for every collision in `out`.
    !> A method that was not prepared comes back with status_invalid.
    subroutine method_run(method, out, record)
        type(method_t), intent(inout) :: method
        type(outcome_t), intent(inout) :: out
        logical, intent(in), optional :: record
        logical :: keep
        integer :: j
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
                call simulate_absolute_dp(method%scene_dp, out, keep)
            else
                call simulate_absolute_qp(method%scene_qp, out, keep)
            end if
        case (method_ode)
            call simulate_ode(method%scene_dp, real(method%tol, dp), out, keep, method%stepper)
        case (method_stepping)
            call simulate_stepping(method%scene_dp, real(method%h, dp), out, keep, &
                method%max_steps)
        case default
            call outcome_start(out, method%p, keep)
            ! One branch per kind: the engine's types differ by kind.
            select case (method%precision)
            case (sp)
                associate (run => method%run_sp, log => method%log_sp)
                    if (keep) then
                        call simulate(method%scene_sp, run, log)
                        do j = 1, log%n
                            if (log%kind(j) == event_collision) &
                                call outcome_add(out, real(log%t(j), qp), log%first(j))
                        end do
                    else
                        call simulate(method%scene_sp, run)
                    end if
                    call copy_end(out, run%status, run%n, real(run%t_end, qp))
                    if (out%status /= status_invalid) then
                        out%v(:) = run%v
                        out%y(:) = run%y
                    end if
                end associate
            case (dp)
                associate (run => method%run_dp, log => method%log_dp)
                    if (keep) then
                        call simulate(method%scene_dp, run, log)
                        do j = 1, log%n
                            if (log%kind(j) == event_collision) &
                                call outcome_add(out, real(log%t(j), qp), log%first(j))
                        end do
                    else
                        call simulate(method%scene_dp, run)
                    end if
                    call copy_end(out, run%status, run%n, real(run%t_end, qp))
                    if (out%status /= status_invalid) then
                        out%v(:) = run%v
                        out%y(:) = run%y
                    end if
                end associate
            case (xdp)
                associate (run => method%run_xdp, log => method%log_xdp)
                    if (keep) then
                        call simulate(method%scene_xdp, run, log)
                        do j = 1, log%n
                            if (log%kind(j) == event_collision) &
                                call outcome_add(out, real(log%t(j), qp), log%first(j))
                        end do
                    else
                        call simulate(method%scene_xdp, run)
                    end if
                    call copy_end(out, run%status, run%n, real(run%t_end, qp))
                    if (out%status /= status_invalid) then
                        out%v(:) = run%v
                        out%y(:) = run%y
                    end if
                end associate
            case (qp)
                associate (run => method%run_qp, log => method%log_qp)
                    if (keep) then
                        call simulate(method%scene_qp, run, log)
                        do j = 1, log%n
                            if (log%kind(j) == event_collision) &
                                call outcome_add(out, log%t(j), log%first(j))
                        end do
                    else
                        call simulate(method%scene_qp, run)
                    end if
                    call copy_end(out, run%status, run%n, run%t_end)
                    if (out%status /= status_invalid) then
                        out%v(:) = run%v
                        out%y(:) = run%y
                    end if
                end associate
            end select
        end select

    contains

        !> The engine's count, end time and status (its own count is kept: a
        !> recorded run counts the same collisions once more from the log).
        pure subroutine copy_end(outcome, status, n, t_end)
            type(outcome_t), intent(inout) :: outcome
            integer, intent(in) :: status, n
            real(qp), intent(in) :: t_end
            outcome%status = status
            outcome%n = n
            outcome%t_end = t_end
        end subroutine copy_end

    end subroutine method_run

    !> Whether the method exists in its kind.
    pure logical function valid_choice(method)
        type(method_t), intent(in) :: method
        select case (method%id)
        case (method_engine)
            valid_choice = any(method%precision == [sp, dp, xdp, qp])
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

    !> Short name of a real kind: sp, dp, xdp or qp.
    pure function kind_name(precision) result(name)
        integer, intent(in) :: precision
        character(len=:), allocatable :: name
        select case (precision)
        case (sp)
            name = "sp"
        case (dp)
            name = "dp"
        case (xdp)
            name = "xdp"
        case (qp)
            name = "qp"
        case default
            name = "unknown"
        end select
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

    pure real(qp) function kind_epsilon(precision) result(eps)
        integer, intent(in) :: precision
        select case (precision)
        case (sp)
            eps = real(epsilon(1.0_sp), qp)
        case (dp)
            eps = real(epsilon(1.0_dp), qp)
        case (xdp)
            eps = real(epsilon(1.0_xdp), qp)
        case default
            eps = epsilon(1.0_qp)
        end select
    end function kind_epsilon

end module sphere_row_methods
