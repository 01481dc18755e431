#include "sphere_row_kinds.h"
#ifdef SPHERE_ROW_XDP
!> The study's engine interface of sphere_row_kind_engine.inc instantiated in
!> the 80-bit extended kind.
module sphere_row_kind_engine_xdp
    use sphere_row, only: wp => xdp, qp, scene_t, scene_wp_t => scene_xdp_t, &
        run_wp_t => run_xdp_t, event_log_wp_t => event_log_xdp_t, scene_init, &
        simulate, event_collision, status_invalid
    use sphere_row_kind_base, only: kind_info_t, kind_engine_t
    use sphere_row_outcome, only: outcome_t, outcome_add
    implicit none
    private
    character(len=*), parameter :: kind_text = "xdp", storage_text = "real80"
    include "sphere_row_kind_engine.inc"
end module sphere_row_kind_engine_xdp
#endif
