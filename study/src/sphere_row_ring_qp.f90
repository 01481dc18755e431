!> The tight event loop of a ring of equal spheres (sphere_row_ring.inc) in
!> real(16).
module sphere_row_ring_qp
    use sphere_row, only: wp => qp
    implicit none
    private
    include "sphere_row_ring.inc"
end module sphere_row_ring_qp
