!> Real kinds used throughout the package, defined once.
!>
!> `qp` (real128) is the working precision of the engine; `sp`, `dp` and `xdp`
!> (the x87 80-bit extended kind) exist so that accuracy can be charted against
!> speed with the same algorithm.
module sphere_row_kinds
    use, intrinsic :: iso_fortran_env, only: real32, real64, real128
    implicit none
    private
    public :: sp, dp, xdp, qp

    !> Single precision (real32).
    integer, parameter :: sp = real32
    !> Double precision (real64).
    integer, parameter :: dp = real64
    !> Extended precision (x87 80-bit, gfortran kind 10).
    integer, parameter :: xdp = selected_real_kind(18, 4931)
    !> Quadruple precision (real128), the working precision.
    integer, parameter :: qp = real128
end module sphere_row_kinds
