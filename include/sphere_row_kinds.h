! Which optional real kinds are built (C preprocessor, #included at the top of
! every source that names one). The 80-bit extended kind xdp exists only where
! the compiler has it: gfortran defines __GFC_REAL_10__ exactly where
! selected_real_kind(18, 4931) > 0 (x86, not aarch64). Defining
! SPHERE_ROW_NO_XDP (make NO_XDP=1) leaves it out on purpose, to test a build
! without it.
#if defined(__GFC_REAL_10__) && !defined(SPHERE_ROW_NO_XDP)
#define SPHERE_ROW_XDP 1
#endif
