#include "sphere_row_kinds.h"
!> The cascade at one instant of sphere_row_pattern.inc in a kind finer than
!> real64, for the certificates that real64 cannot resolve: the 80-bit
!> extended kind where the compiler has it (a step costs about 4 times a
!> real64 one), else real128 (about 22 times).
module sphere_row_pattern_fine
#ifdef SPHERE_ROW_XDP
    use sphere_row_kinds, only: ck => xdp, wp => xdp
#else
    use sphere_row_kinds, only: ck => qp, wp => qp
#endif
    use sphere_row_policy, only: policy
    implicit none
    private
    include "sphere_row_pattern.inc"
    include "../engine/sphere_row_rule.inc"
end module sphere_row_pattern_fine
