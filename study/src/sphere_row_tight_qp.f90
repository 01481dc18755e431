!> The tight event loop (sphere_row_tight.inc) in real(16).
module sphere_row_tight_qp
    use sphere_row, only: wp => qp
    implicit none
    private
    include "sphere_row_tight.inc"
end module sphere_row_tight_qp
