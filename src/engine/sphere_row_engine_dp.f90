!> The engine instantiated in real64, the first try of `simulate_auto`
!> (sphere_row_auto), kept where its rounding certificate holds: the event
!> loop (sphere_row_engine.inc) and its parts, and the collapse rules
!> (src/collapse/), each written once for a kind `wp`.
module sphere_row_engine_dp
    use sphere_row_kinds, only: wp => dp, qp
    use sphere_row_engine_uses
    include "sphere_row_instance.inc"
end module sphere_row_engine_dp
