!> Method 2 (absolute variables) of sphere_row_absolute.inc instantiated in real64.
module sphere_row_absolute_dp
    use sphere_row, only: wp => dp, qp, scene_wp_t => scene_dp_t, scene_check, budget, &
        status_normal, status_max_collisions
    use sphere_row_outcome, only: outcome_t, outcome_start, outcome_add
    use sphere_row_status, only: status_negative_gap
    implicit none
    private
    include "sphere_row_absolute.inc"
end module sphere_row_absolute_dp
