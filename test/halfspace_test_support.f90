!> Helpers shared by the half-space test suites: a quadrature independent of the library's
!! singular quadrature (so that the tests check it rather than repeat it) and basis values.
module halfspace_test_support
    use kinds, only: dp
    use quadrature, only: gauss_legendre
    use shape_functions, only: basis_t, eval_basis, max_local
    implicit none
    private
    public :: graded_rule, basis_value

contains

    !> Composite Gauss rule on [a, b] graded geometrically (factor 0.2, 12 levels, 20 points
    !! each) towards both ends, for integrands with end-point singularities.
    subroutine graded_rule(a, b, nodes, weights)
        real(dp), intent(in) :: a, b
        real(dp), allocatable, intent(out) :: nodes(:), weights(:)
        integer, parameter :: levels = 12, n_gl = 20
        real(dp) :: xi(n_gl), wt(n_gl), half, lo, hi
        integer :: side, k, n
        call gauss_legendre(n_gl, xi, wt)
        allocate (nodes(2*(levels + 1)*n_gl), weights(2*(levels + 1)*n_gl))
        half = 0.5_dp*(b - a)
        n = 0
        sides: do side = 1, 2
            levels_loop: do k = 0, levels
                hi = half*0.2_dp**k
                lo = merge(0.0_dp, half*0.2_dp**(k + 1), k == levels)
                if (side == 1) then
                    nodes(n + 1:n + n_gl) = a + lo + 0.5_dp*(xi + 1.0_dp)*(hi - lo)
                else
                    nodes(n + 1:n + n_gl) = b - lo - 0.5_dp*(xi + 1.0_dp)*(hi - lo)
                end if
                weights(n + 1:n + n_gl) = 0.5_dp*(hi - lo)*wt
                n = n + n_gl
            end do levels_loop
        end do sides
    end subroutine graded_rule

    !> Value of basis function `dof` at x on element e (0 if not supported there).
    pure real(dp) function basis_value(basis, e, dof, x)
        type(basis_t), intent(in) :: basis
        integer, intent(in) :: e, dof
        real(dp), intent(in) :: x
        integer :: idx(max_local), i
        real(dp) :: val(max_local), der(max_local), x_out
        call eval_basis(basis, e, (2.0_dp*x - basis%x(e - 1) - basis%x(e))/ &
                        (basis%x(e) - basis%x(e - 1)), idx, val, der, x_out)
        basis_value = 0.0_dp
        do i = 1, basis%n_local
            if (idx(i) == dof) basis_value = val(i)
        end do
    end function basis_value
end module halfspace_test_support
