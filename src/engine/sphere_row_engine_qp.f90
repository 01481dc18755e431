!> The engine instantiated in real128, the working precision: the event loop
!> (sphere_row_engine.inc) and its parts, and the collapse rules
!> (src/collapse/), each written once for a kind `wp`.
module sphere_row_engine_qp
    use sphere_row_kinds, only: wp => qp, qp
    use sphere_row_engine_uses
    include "sphere_row_instance.inc"
end module sphere_row_engine_qp
