!> Error-free transformations of double precision numbers, for the few sums whose round-off in
!! double is the quantity measured (the equilibrium residual of a thin, stiff structure and
!! the solution held as z + z_lo: contact_system::equilibrium_residual,
!! newton_method::refine_equilibrium). A value is carried as an unevaluated sum hi + lo.
!!
!! two_sum (Knuth): s + e = a + b exactly, s = fl(a + b). two_product: p + e = a b exactly,
!! p = fl(a b), the error from one fused multiply-add of the C library (C99 fma, exact by
!! definition whatever the compiler's flags; Dekker's splitting is not, once a compiler fuses
!! its multiply and subtract). Ogita, Rump and Oishi, "Accurate sum and dot product", SIAM J.
!! Sci. Comput. 26 (2005): sums and dot products accumulated this way are as accurate as
!! computed in twice the working precision, binary128's 113 bits being a little more; software
!! binary128 cost 50 ns an operation.
module double_double
    use iso_c_binding, only: c_double
    use kinds, only: dp
    implicit none
    private
    public :: two_sum, two_product

    interface
        !> double fma(double x, double y, double z): x y + z rounded once (C99, libm).
        pure function c_fma(x, y, z) bind(c, name='fma') result(r)
            import :: c_double
            real(c_double), value, intent(in) :: x, y, z
            real(c_double) :: r
        end function c_fma
    end interface

contains

    !> s = fl(a + b) and its error e: s + e = a + b exactly.
    elemental subroutine two_sum(a, b, s, e)
        real(dp), intent(in) :: a, b    !! the terms
        real(dp), intent(out) :: s, e   !! the rounded sum and its error
        real(dp) :: b_virtual
        s = a + b
        b_virtual = s - a
        e = (a - (s - b_virtual)) + (b - b_virtual)
    end subroutine two_sum

    !> p = fl(a b) and its error e: p + e = a b exactly (no underflow).
    elemental subroutine two_product(a, b, p, e)
        real(dp), intent(in) :: a, b    !! the factors
        real(dp), intent(out) :: p, e   !! the rounded product and its error
        p = a*b
        e = c_fma(a, b, -p)
    end subroutine two_product
end module double_double
