!> The tight event loop (sphere_row_tight.inc) in real(8).
module sphere_row_tight_dp
    use sphere_row, only: wp => dp
    implicit none
    private
    include "sphere_row_tight.inc"
end module sphere_row_tight_dp
