!> The engine instantiated in real32, the coarsest kind, there to chart
!> accuracy against speed: the event loop (sphere_row_engine.inc) and its
!> parts, and the collapse rules (src/collapse/), each written once for a
!> kind `wp`.
module sphere_row_engine_sp
    use sphere_row_kinds, only: wp => sp, qp
    use sphere_row_engine_uses
    include "sphere_row_instance.inc"
end module sphere_row_engine_sp
