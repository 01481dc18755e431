!> Method 2 (absolute variables) of sphere_row_absolute.inc instantiated in real128.
module sphere_row_absolute_qp
    use sphere_row_kinds, only: wp => qp, qp
    use sphere_row_engine_qp, only: scene_t, scene_check_wp
    use sphere_row_outcome, only: outcome_t, outcome_start, outcome_add
    use sphere_row_status, only: status_normal, status_max_collisions, status_negative_gap
    implicit none
    private
    include "sphere_row_absolute.inc"
end module sphere_row_absolute_qp
