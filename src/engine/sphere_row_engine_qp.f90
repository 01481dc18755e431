!> The engine instantiated in real128, the working precision: the event loop
!> (sphere_row_engine.inc) and its parts, and the collapse rules
!> (src/collapse/), each written once for a kind `wp`.
module sphere_row_engine_qp
    use sphere_row_kinds, only: wp => qp, qp
    use sphere_row_format, only: real_str, itoa
    use sphere_row_policy, only: policy
    use sphere_row_cascade, only: ordered_cascade_merges, cascade_kind
    use sphere_row_status, only: status_normal, status_collapsed, status_max_collisions, &
        status_invalid, event_start, event_collision, event_collapse, answer_exact, &
        answer_certified, answer_tolerance, answer_bounded, answer_unresolved
    implicit none
    private
    include "sphere_row_types.inc"
contains
    include "sphere_row_engine.inc"
    include "sphere_row_rule.inc"
    include "sphere_row_scene.inc"
    include "sphere_row_calendar.inc"
    include "sphere_row_log.inc"
    include "sphere_row_certified.inc"
    include "../collapse/sphere_row_rules.inc"
    include "../collapse/sphere_row_plastic.inc"
    include "../collapse/sphere_row_block.inc"
    include "../collapse/sphere_row_box.inc"
    include "../collapse/sphere_row_fallback.inc"
    include "../collapse/sphere_row_cycle.inc"
    include "../collapse/sphere_row_bounds.inc"
    include "../collapse/sphere_row_bounded.inc"
end module sphere_row_engine_qp
