!> Hand-written C interfaces to the part of GSL's `gsl_odeiv2` that the
!> continuous method uses (no FGSL): the system struct, two explicit
!> Runge-Kutta step types, and the step, control and evolve objects.
!>
!> Names and argument lists follow `gsl/gsl_odeiv2.h` of GSL 2.x. GSL objects
!> are opaque and held as `type(c_ptr)`; arrays are passed by address.
module sphere_row_gsl_ode
    use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_funptr
    implicit none
    private
    public :: gsl_odeiv2_system, gsl_success
    public :: gsl_odeiv2_step_rk8pd, gsl_odeiv2_step_rkf45
    public :: gsl_odeiv2_step_alloc, gsl_odeiv2_step_apply, gsl_odeiv2_step_reset, &
        gsl_odeiv2_step_free
    public :: gsl_odeiv2_control_scaled_new, gsl_odeiv2_control_free
    public :: gsl_odeiv2_evolve_alloc, gsl_odeiv2_evolve_apply, gsl_odeiv2_evolve_reset, &
        gsl_odeiv2_evolve_free
    public :: gsl_set_error_handler_off, gsl_set_error_handler

    !> GSL's return code for success (GSL_SUCCESS).
    integer(c_int), parameter :: gsl_success = 0_c_int

    !> The ODE system dy/dt = f(t, y): `function` is
    !> `int f(double t, const double y[], double dydt[], void *params)`;
    !> `jacobian` may be null for explicit steppers.
    type, bind(C) :: gsl_odeiv2_system
        !> Right-hand side f.
        type(c_funptr) :: function
        !> Jacobian (unused by explicit steppers).
        type(c_funptr) :: jacobian
        !> Number of equations.
        integer(c_size_t) :: dimension
        !> Passed unchanged to `function`.
        type(c_ptr) :: params
    end type gsl_odeiv2_system

    !> Embedded Runge-Kutta Prince-Dormand (8, 9): GSL's global step-type
    !> pointer, resolved by the linker against libgsl.
    type(c_ptr), bind(C, name="gsl_odeiv2_step_rk8pd"), protected :: gsl_odeiv2_step_rk8pd
    !> Embedded Runge-Kutta-Fehlberg (4, 5).
    type(c_ptr), bind(C, name="gsl_odeiv2_step_rkf45"), protected :: gsl_odeiv2_step_rkf45

    interface

        !> A stepping object of step type `t` for `dim` equations.
        function gsl_odeiv2_step_alloc(t, dim) bind(C, name="gsl_odeiv2_step_alloc") &
            result(step)
            import :: c_ptr, c_size_t
            type(c_ptr), value :: t
            integer(c_size_t), value :: dim
            type(c_ptr) :: step
        end function gsl_odeiv2_step_alloc

        !> One step of size h from (t, y) without error control; y is replaced
        !> by the state at t+h and yerr by the error estimate. dydt_in and
        !> dydt_out may be null.
        function gsl_odeiv2_step_apply(step, t, h, y, yerr, dydt_in, dydt_out, sys) &
            bind(C, name="gsl_odeiv2_step_apply") result(status)
            import :: c_ptr, c_double, c_int, gsl_odeiv2_system
            type(c_ptr), value :: step
            real(c_double), value :: t, h
            real(c_double), intent(inout) :: y(*)
            real(c_double), intent(out) :: yerr(*)
            type(c_ptr), value :: dydt_in, dydt_out
            type(gsl_odeiv2_system), intent(in) :: sys
            integer(c_int) :: status
        end function gsl_odeiv2_step_apply

        !> Forget any history of a stepping object.
        function gsl_odeiv2_step_reset(step) bind(C, name="gsl_odeiv2_step_reset") &
            result(status)
            import :: c_ptr, c_int
            type(c_ptr), value :: step
            integer(c_int) :: status
        end function gsl_odeiv2_step_reset

        !> Free a stepping object.
        subroutine gsl_odeiv2_step_free(step) bind(C, name="gsl_odeiv2_step_free")
            import :: c_ptr
            type(c_ptr), value :: step
        end subroutine gsl_odeiv2_step_free

        !> Step-size control keeping the local error of component i below
        !> eps_abs*scale_abs(i) + eps_rel*(a_y*|y_i| + a_dydt*h*|y'_i|).
        function gsl_odeiv2_control_scaled_new(eps_abs, eps_rel, a_y, a_dydt, scale_abs, dim) &
            bind(C, name="gsl_odeiv2_control_scaled_new") result(control)
            import :: c_ptr, c_double, c_size_t
            real(c_double), value :: eps_abs, eps_rel, a_y, a_dydt
            real(c_double), intent(in) :: scale_abs(*)
            integer(c_size_t), value :: dim
            type(c_ptr) :: control
        end function gsl_odeiv2_control_scaled_new

        !> Free a control object.
        subroutine gsl_odeiv2_control_free(control) bind(C, name="gsl_odeiv2_control_free")
            import :: c_ptr
            type(c_ptr), value :: control
        end subroutine gsl_odeiv2_control_free

        !> An evolution object for `dim` equations.
        function gsl_odeiv2_evolve_alloc(dim) bind(C, name="gsl_odeiv2_evolve_alloc") &
            result(evolve)
            import :: c_ptr, c_size_t
            integer(c_size_t), value :: dim
            type(c_ptr) :: evolve
        end function gsl_odeiv2_evolve_alloc

        !> One accepted adaptive step from (t, y) towards t1 (never beyond it),
        !> starting with step size h; t, h and y are updated.
        function gsl_odeiv2_evolve_apply(evolve, control, step, sys, t, t1, h, y) &
            bind(C, name="gsl_odeiv2_evolve_apply") result(status)
            import :: c_ptr, c_double, c_int, gsl_odeiv2_system
            type(c_ptr), value :: evolve, control, step
            type(gsl_odeiv2_system), intent(in) :: sys
            real(c_double), intent(inout) :: t
            real(c_double), value :: t1
            real(c_double), intent(inout) :: h
            real(c_double), intent(inout) :: y(*)
            integer(c_int) :: status
        end function gsl_odeiv2_evolve_apply

        !> Forget the history of an evolution object (after a discontinuity).
        function gsl_odeiv2_evolve_reset(evolve) bind(C, name="gsl_odeiv2_evolve_reset") &
            result(status)
            import :: c_ptr, c_int
            type(c_ptr), value :: evolve
            integer(c_int) :: status
        end function gsl_odeiv2_evolve_reset

        !> Free an evolution object.
        subroutine gsl_odeiv2_evolve_free(evolve) bind(C, name="gsl_odeiv2_evolve_free")
            import :: c_ptr
            type(c_ptr), value :: evolve
        end subroutine gsl_odeiv2_evolve_free

        !> Make GSL return error codes instead of aborting; returns the previous
        !> handler.
        function gsl_set_error_handler_off() bind(C, name="gsl_set_error_handler_off") &
            result(previous)
            import :: c_funptr
            type(c_funptr) :: previous
        end function gsl_set_error_handler_off

        !> Install `handler` as GSL's error handler (a null one restores the
        !> default, which aborts); returns the previous handler.
        function gsl_set_error_handler(handler) bind(C, name="gsl_set_error_handler") &
            result(previous)
            import :: c_funptr
            type(c_funptr), value :: handler
            type(c_funptr) :: previous
        end function gsl_set_error_handler

    end interface

end module sphere_row_gsl_ode
