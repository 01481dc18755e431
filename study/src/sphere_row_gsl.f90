!> The few GNU Scientific Library (GSL) routines the package calls, declared
!> through bind(C) interfaces written against the GSL 2 headers (gsl_rng.h,
!> gsl_sort_double.h, gsl_statistics_double.h, gsl_cdf.h).
!>
!> The C types (`c_double`, `c_size_t`, `c_long`) appear only here and at the
!> other C boundary, the ODE integrator (sphere_row_gsl_ode and its callbacks in
!> sphere_row_continuous): the rest of the package passes `real(dp)` and
!> converts sizes here, and a build on a platform where `dp` were not
!> `c_double` would fail to compile at the call sites instead of passing wrong
!> bits.
!>
!> The CDF routines and the quantile of sorted data only read their
!> arguments, so they are declared `pure`, which lets the statistics helpers
!> that call them be pure as well.
module sphere_row_gsl
    use, intrinsic :: iso_c_binding, only: c_ptr, c_double, c_size_t, c_long
    implicit none
    private
    public :: gsl_rng_mt19937
    public :: gsl_rng_alloc, gsl_rng_set, gsl_rng_uniform_pos, gsl_rng_free
    public :: gsl_sort, gsl_stats_quantile_from_sorted_data
    public :: gsl_cdf_ugaussian_p, gsl_cdf_ugaussian_pinv

    !> The generator type of the Mersenne Twister MT19937, a global `const
    !> gsl_rng_type *` of the C library; pass it to gsl_rng_alloc.
    type(c_ptr), bind(C, name="gsl_rng_mt19937"), protected :: gsl_rng_mt19937

    interface

        !> `gsl_rng *gsl_rng_alloc(const gsl_rng_type *T)`: a new generator of
        !> type `T` with the default seed; a null pointer if memory ran out.
        function gsl_rng_alloc(rng_type) bind(C, name="gsl_rng_alloc") result(rng)
            import :: c_ptr
            type(c_ptr), value :: rng_type
            type(c_ptr) :: rng
        end function gsl_rng_alloc

        !> `void gsl_rng_set(const gsl_rng *r, unsigned long int seed)`. For
        !> MT19937 the seed 0 stands for the library's default seed 4357.
        subroutine gsl_rng_set(rng, seed) bind(C, name="gsl_rng_set")
            import :: c_ptr, c_long
            type(c_ptr), value :: rng
            integer(c_long), value :: seed
        end subroutine gsl_rng_set

        !> `double gsl_rng_uniform_pos(const gsl_rng *r)`: uniform on the open
        !> interval (0, 1), so that its logarithm is always finite.
        function gsl_rng_uniform_pos(rng) bind(C, name="gsl_rng_uniform_pos") result(u)
            import :: c_ptr, c_double
            type(c_ptr), value :: rng
            real(c_double) :: u
        end function gsl_rng_uniform_pos

        !> `void gsl_rng_free(gsl_rng *r)`.
        subroutine gsl_rng_free(rng) bind(C, name="gsl_rng_free")
            import :: c_ptr
            type(c_ptr), value :: rng
        end subroutine gsl_rng_free

        !> `void gsl_sort(double *data, const size_t stride, const size_t n)`:
        !> sorts in place into ascending order (heapsort, so not stable; equal
        !> values are indistinguishable anyway).
        subroutine gsl_sort(data, stride, n) bind(C, name="gsl_sort")
            import :: c_double, c_size_t
            real(c_double), intent(inout) :: data(*)
            integer(c_size_t), value :: stride, n
        end subroutine gsl_sort

        !> `double gsl_stats_quantile_from_sorted_data(const double sorted_data[],
        !> const size_t stride, const size_t n, const double f)`: the quantile
        !> of level f, interpolated linearly between the order statistics at
        !> zero-based positions floor(f(n-1)) and the next one.
        pure function gsl_stats_quantile_from_sorted_data(sorted_data, stride, n, f) &
            bind(C, name="gsl_stats_quantile_from_sorted_data") result(q)
            import :: c_double, c_size_t
            real(c_double), intent(in) :: sorted_data(*)
            integer(c_size_t), value :: stride, n
            real(c_double), value :: f
            real(c_double) :: q
        end function gsl_stats_quantile_from_sorted_data

        !> `double gsl_cdf_ugaussian_P(const double x)`: the standard normal
        !> distribution function Phi(x).
        pure function gsl_cdf_ugaussian_p(x) bind(C, name="gsl_cdf_ugaussian_P") result(p)
            import :: c_double
            real(c_double), value :: x
            real(c_double) :: p
        end function gsl_cdf_ugaussian_p

        !> `double gsl_cdf_ugaussian_Pinv(const double P)`: the standard normal
        !> quantile, the inverse of Phi.
        pure function gsl_cdf_ugaussian_pinv(p) bind(C, name="gsl_cdf_ugaussian_Pinv") &
            result(x)
            import :: c_double
            real(c_double), value :: p
            real(c_double) :: x
        end function gsl_cdf_ugaussian_pinv

    end interface

end module sphere_row_gsl
