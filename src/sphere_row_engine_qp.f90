!> The engine of sphere_row_engine.inc instantiated in real128, the working precision.
module sphere_row_engine_qp
    use sphere_row_kinds, only: wp => qp, qp
    use sphere_row_format, only: real_str, itoa
    use sphere_row_cascade, only: ordered_cascade_merges, cascade_kind
    use sphere_row_status, only: status_normal, status_collapsed, status_max_collisions, &
        status_invalid, event_start, event_collision, event_collapse
    implicit none
    private
    include "sphere_row_engine.inc"
end module sphere_row_engine_qp
