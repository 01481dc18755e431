!> The collision rule (6) of src/engine/sphere_row_rule.inc in real64, for the
!> study's real64 paths that carry gaps and rates (the certified real64 run of
!> c2's lean path, the ODE and time-stepping methods).
module sphere_row_rule_dp
    use sphere_row, only: wp => dp
    implicit none
    private
    public :: collide_rates, collide_at

contains

    include "../../src/engine/sphere_row_rule.inc"

end module sphere_row_rule_dp
