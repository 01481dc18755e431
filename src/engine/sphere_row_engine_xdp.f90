#include "sphere_row_kinds.h"
#ifdef SPHERE_ROW_XDP
!> The engine instantiated in the 80-bit extended kind: the event loop
!> (sphere_row_engine.inc) and its parts, and the collapse rules
!> (src/collapse/), each written once for a kind `wp`.
module sphere_row_engine_xdp
    use sphere_row_kinds, only: wp => xdp, qp
    use sphere_row_format, only: real_str, itoa, int_text, number_text_length
    use sphere_row_policy, only: policy
    use sphere_row_cascade, only: ordered_cascade_merges, cascade_kind
    use sphere_row_status, only: status_normal, status_collapsed, status_max_collisions, &
        status_invalid, status_horizon, event_start, event_collision, event_collapse, &
        event_sample, answer_exact, &
        answer_certified, answer_tolerance, answer_bounded, answer_unresolved
    implicit none
    private
    include "sphere_row_instance.inc"
end module sphere_row_engine_xdp
#endif
