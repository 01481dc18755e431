!> The cascade at one instant of sphere_row_pattern.inc in real64, the kind
!> the tries of sphere_row_cascade run in.
module sphere_row_pattern_dp
    use sphere_row_kinds, only: ck => dp, wp => dp
    use sphere_row_policy, only: policy
    implicit none
    private
    include "sphere_row_pattern.inc"
    include "../engine/sphere_row_rule.inc"
end module sphere_row_pattern_dp
