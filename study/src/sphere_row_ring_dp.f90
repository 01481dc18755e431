!> The tight event loop of a ring of equal spheres (sphere_row_ring.inc) in
!> real(8).
module sphere_row_ring_dp
    use sphere_row, only: wp => dp
    implicit none
    private
    include "sphere_row_ring.inc"
end module sphere_row_ring_dp
