#include "sphere_row_kinds.h"
#ifdef SPHERE_ROW_XDP
!> The engine instantiated in the 80-bit extended kind: the event loop
!> (sphere_row_engine.inc) and its parts, and the collapse rules
!> (src/collapse/), each written once for a kind `wp`.
module sphere_row_engine_xdp
    use sphere_row_kinds, only: wp => xdp, qp
    use sphere_row_engine_uses
    include "sphere_row_instance.inc"
end module sphere_row_engine_xdp
#endif
