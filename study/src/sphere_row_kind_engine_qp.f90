!> The study's engine interface of sphere_row_kind_engine.inc instantiated in
!> real128.
module sphere_row_kind_engine_qp
    use sphere_row, only: wp => qp, qp, scene_t, scene_wp_t => scene_t, run_wp_t => run_t, &
        event_log_wp_t => event_log_t, scene_init, &
        simulate, event_collision, status_invalid
    use sphere_row_kind_base, only: kind_info_t, kind_engine_t
    use sphere_row_outcome, only: outcome_t, outcome_add
    implicit none
    private
    character(len=*), parameter :: kind_text = "qp", storage_text = "real128"
    include "sphere_row_kind_engine.inc"
end module sphere_row_kind_engine_qp
