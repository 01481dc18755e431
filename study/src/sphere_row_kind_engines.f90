#include "sphere_row_kinds.h"
!> The real kinds the engine is built in, and the engine of each behind one
!> interface: the one place of the study that names the per-kind modules.
!>
!> A kind the compiler lacks is not built (include/sphere_row_kinds.h), so it
!> is missing from `built_kinds` and `new_kind_engine` refuses it; everything
!> else asks this module which kinds there are.
module sphere_row_kind_engines
    use sphere_row, only: sp, dp, xdp, qp
    use sphere_row_kind_base, only: kind_info_t, kind_engine_t
    use sphere_row_kind_engine_sp, only: engine_sp_t => engine_wp_t, convert_scene, &
        kind_info_sp => kind_info_wp
    use sphere_row_kind_engine_dp, only: engine_dp_t => engine_wp_t, convert_scene, &
        kind_info_dp => kind_info_wp
#ifdef SPHERE_ROW_XDP
    use sphere_row_kind_engine_xdp, only: engine_xdp_t => engine_wp_t, convert_scene, &
        kind_info_xdp => kind_info_wp
#endif
    use sphere_row_kind_engine_qp, only: engine_qp_t => engine_wp_t, convert_scene, &
        kind_info_qp => kind_info_wp
    implicit none
    private
    public :: kind_info_t, kind_engine_t, built_kinds, kind_built, kind_info
    public :: new_kind_engine, convert_scene

#ifdef SPHERE_ROW_XDP
    !> Every kind built, from the narrowest to the widest.
    type(kind_info_t), parameter :: built_kinds(*) = [kind_info_sp, kind_info_dp, &
        kind_info_xdp, kind_info_qp]
#else
    !> Every kind built, from the narrowest to the widest.
    type(kind_info_t), parameter :: built_kinds(*) = [kind_info_sp, kind_info_dp, &
        kind_info_qp]
#endif

contains

    !> Whether the engine is built in kind `precision`.
    pure logical function kind_built(precision)
        integer, intent(in) :: precision
        kind_built = any(built_kinds%precision == precision)
    end function kind_built

    !> The description of kind `precision`; name "unknown" and zero
    !> resolution for a kind that is not built.
    pure function kind_info(precision) result(info)
        integer, intent(in) :: precision
        type(kind_info_t) :: info
        integer :: k
        info = kind_info_t(precision, "unknown", "unknown", 0.0_qp, 0.0_qp)
        do k = 1, size(built_kinds)
            if (built_kinds(k)%precision == precision) info = built_kinds(k)
        end do
    end function kind_info

    !> The engine in kind `precision`; `engine` stays unallocated for a kind
    !> that is not built.
    subroutine new_kind_engine(precision, engine)
        integer, intent(in) :: precision
        class(kind_engine_t), allocatable, intent(out) :: engine
        select case (precision)
        case (sp)
            allocate (engine_sp_t :: engine)
        case (dp)
            allocate (engine_dp_t :: engine)
#ifdef SPHERE_ROW_XDP
        case (xdp)
            allocate (engine_xdp_t :: engine)
#endif
        case (qp)
            allocate (engine_qp_t :: engine)
        case default
            ! a kind not built: engine stays unallocated
        end select
    end subroutine new_kind_engine

end module sphere_row_kind_engines
