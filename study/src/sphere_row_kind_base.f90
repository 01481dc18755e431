!> What every per-kind instantiation of the engine offers the study: a
!> description of its real kind and an engine object behind one interface, so
!> that the methods and the benchmark are written once for all kinds.
module sphere_row_kind_base
    use sphere_row, only: qp, scene_t
    use sphere_row_outcome, only: outcome_t
    implicit none
    private
    public :: kind_info_t, kind_engine_t

    !> A real kind the engine is built in.
    type :: kind_info_t
        !> The kind value (sp, dp, xdp or qp).
        integer :: precision = 0
        !> Short name in tables and labels: sp, dp, xdp or qp.
        character(len=7) :: name = ""
        !> Storage name in bench.tsv: real32, real64, real80 or real128.
        character(len=7) :: storage = ""
        !> The kind's epsilon, converted exactly to real128.
        real(qp) :: epsilon = 0.0_qp
        !> sqrt(tiny) of the kind, computed in the kind and converted exactly:
        !> the smallest insignificance tolerance whose gaps do not underflow.
        real(qp) :: sqrt_tiny = 0.0_qp
    end type kind_info_t

    !> The event engine in one real kind, with the scene it was prepared for
    !> and its work space, kept between runs so that a timed run allocates
    !> nothing.
    type, abstract :: kind_engine_t
    contains
        !> Convert a real128 scene to the kind and check it.
        procedure(prepare_proc), deferred :: prepare
        !> Run the prepared scene once and report into an outcome.
        procedure(run_into_proc), deferred :: run_into
        !> Run the prepared scene once and return only its collision count.
        procedure(count_proc), deferred :: count_collisions
    end type kind_engine_t

    abstract interface
        !> `tol` >= 0 replaces the kind's epsilon as the insignificance
        !> tolerance; `stat` is status_normal or status_invalid with `msg`.
        subroutine prepare_proc(self, scene, tol, stat, msg)
            import :: kind_engine_t, scene_t, qp
            class(kind_engine_t), intent(inout) :: self
            type(scene_t), intent(in) :: scene
            real(qp), intent(in) :: tol
            integer, intent(out) :: stat
            character(len=*), intent(out) :: msg
        end subroutine prepare_proc

        !> `out` was started for the scene's p; `record` asks for every collision.
        subroutine run_into_proc(self, out, record)
            import :: kind_engine_t, outcome_t
            class(kind_engine_t), intent(inout) :: self
            type(outcome_t), intent(inout) :: out
            logical, intent(in) :: record
        end subroutine run_into_proc

        !> Number of collisions of one run (nothing recorded).
        function count_proc(self) result(n)
            import :: kind_engine_t
            class(kind_engine_t), intent(inout) :: self
            integer :: n
        end function count_proc
    end interface

end module sphere_row_kind_base
