!> Shape functions and quadrature: partition of unity, derivatives, C1 continuity of S2,
!! polynomial exactness.
module test_shape_functions
    use kinds, only: dp
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use quadrature, only: gauss_legendre
    use mesh, only: mesh_t, new_mesh
    use shape_functions, only: basis_t, new_basis, eval_basis, max_local, INTERP_P1, &
                               INTERP_P2, INTERP_S2
    implicit none
    private
    public :: collect_shape_functions

contains

    subroutine collect_shape_functions(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('gauss_legendre_exactness', test_gauss), &
                 new_unittest('partition_of_unity', test_partition), &
                 new_unittest('derivative_consistency', test_derivatives), &
                 new_unittest('s2_c1_continuity', test_s2_continuity), &
                 new_unittest('quadratic_reproduction', test_reproduction), &
                 new_unittest('loads_grading', test_loads_grading)]
    end subroutine collect_shape_functions

    !> n points integrate x^k exactly for k <= 2n-1: int_{-1}^{1} x^k = 2/(k+1) (k even), 0 (odd).
    subroutine test_gauss(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: xi(:), w(:)
        integer :: n, k
        real(dp) :: exact
        do n = 1, 20
            allocate (xi(n), w(n))
            call gauss_legendre(n, xi, w)
            do k = 0, 2*n - 1
                exact = merge(2.0_dp/real(k + 1, dp), 0.0_dp, mod(k, 2) == 0)
                call check_close(err, sum(w*xi**k), exact, 1.0e-14_dp, 1.0e-14_dp, &
                                 'Gauss-Legendre moment')
                if (allocated(err)) return
            end do
            deallocate (xi, w)
        end do
    end subroutine test_gauss

    subroutine graded_mesh(msh, err)
        type(mesh_t), intent(out) :: msh
        type(error_t), allocatable, intent(out) :: err
        call new_mesh(msh, -0.5_dp, 0.5_dp, 7, 'EDGES', err)
    end subroutine graded_mesh

    !> Sum of the functions is 1 and of their derivatives 0, everywhere, for every family.
    subroutine test_partition(err)
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        type(basis_t) :: b
        integer :: family, e, k, idx(max_local)
        real(dp) :: val(max_local), der(max_local), x, xi
        call graded_mesh(msh, err)
        if (allocated(err)) return
        do family = INTERP_P1, INTERP_S2
            call new_basis(b, msh, family)
            do e = 1, msh%ne
                do k = 0, 10
                    xi = -1.0_dp + 0.2_dp*real(k, dp)
                    call eval_basis(b, e, xi, idx, val, der, x)
                    call check(err, abs(sum(val) - 1.0_dp) < 1.0e-14_dp .and. &
                               abs(sum(der)) < 1.0e-12_dp, 'partition of unity')
                    if (allocated(err)) return
                end do
            end do
        end do
    end subroutine test_partition

    !> Derivatives against central differences of the values (h = 1e-6: error ~ 1e-10).
    subroutine test_derivatives(err)
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        type(basis_t) :: b
        integer :: family, e, i, idx(max_local)
        real(dp) :: vp(max_local), vm(max_local), val(max_local), der(max_local), dd(max_local)
        real(dp) :: x, xi, dxi, h
        call graded_mesh(msh, err)
        if (allocated(err)) return
        dxi = 1.0e-6_dp
        xi = 0.3_dp
        do family = INTERP_P1, INTERP_S2
            call new_basis(b, msh, family)
            do e = 1, msh%ne
                h = msh%x(e) - msh%x(e - 1)
                call eval_basis(b, e, xi + dxi, idx, vp, dd, x)
                call eval_basis(b, e, xi - dxi, idx, vm, dd, x)
                call eval_basis(b, e, xi, idx, val, der, x)
                do i = 1, b%n_local
                    call check_close(err, der(i), (vp(i) - vm(i))/(dxi*h), 1.0e-7_dp, 1.0e-6_dp, &
                                     'derivative vs finite difference')
                    if (allocated(err)) return
                end do
            end do
        end do
    end subroutine test_derivatives

    !> Each S2 function has the same value and slope on both sides of every interior node.
    subroutine test_s2_continuity(err)
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        type(basis_t) :: b
        integer :: e, i, j, il(max_local), ir(max_local)
        real(dp) :: vl(max_local), dl(max_local), vr(max_local), dr(max_local), x
        real(dp) :: left_v, left_d
        call graded_mesh(msh, err)
        if (allocated(err)) return
        call new_basis(b, msh, INTERP_S2)
        do e = 1, msh%ne - 1
            call eval_basis(b, e, 1.0_dp, il, vl, dl, x)
            call eval_basis(b, e + 1, -1.0_dp, ir, vr, dr, x)
            do j = 1, 3
                left_v = 0.0_dp
                left_d = 0.0_dp
                do i = 1, 3
                    if (il(i) == ir(j)) then
                        left_v = vl(i)
                        left_d = dl(i)
                    end if
                end do
                call check(err, abs(left_v - vr(j)) < 1.0e-14_dp .and. &
                           abs(left_d - dr(j)) < 1.0e-10_dp*maxval(abs(dr)), &
                           'S2 not C1 at an interior node')
                if (allocated(err)) return
            end do
        end do
    end subroutine test_s2_continuity

    !> P2 and S2 reproduce x^2 (P2 by nodal values, S2 by Greville-type control values from a
    !! collocation solve is not needed: the quadratic B-spline coefficients of x^2 are
    !! t_{i+1} t_{i+2}, Marsden's identity).
    subroutine test_reproduction(err)
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        type(basis_t) :: b
        integer :: e, k, idx(max_local)
        real(dp) :: val(max_local), der(max_local), x, coef(20), xi, s
        call graded_mesh(msh, err)
        if (allocated(err)) return
        call new_basis(b, msh, INTERP_S2)
        do k = 1, b%n_dof
            coef(k) = b%knots(k + 1)*b%knots(k + 2)
        end do
        do e = 1, msh%ne
            do k = 0, 4
                xi = -1.0_dp + 0.5_dp*real(k, dp)
                call eval_basis(b, e, xi, idx, val, der, x)
                s = sum(val(1:3)*coef(idx(1:3)))
                call check_close(err, s, x*x, 1.0e-13_dp, 1.0e-14_dp, 'S2 reproduces x^2')
                if (allocated(err)) return
            end do
        end do
    end subroutine test_reproduction

    !> LOADS grading: every load position is a node, N_e is kept, neighbouring elements inside
    !! a piece differ by the ratio 1.1 (or are mirror images at the piece centre).
    subroutine test_loads_grading(err)
        type(error_t), allocatable, intent(out) :: err
        type(mesh_t) :: msh
        type(error_t), allocatable :: mesh_err
        real(dp), parameter :: loads(3) = [-0.1_dp, 0.25_dp, 0.5_dp]   ! 0.5 is the end
        real(dp) :: ratio
        integer :: i, e
        call new_mesh(msh, -0.5_dp, 0.5_dp, 30, 'LOADS', err, loads)
        if (allocated(err)) return
        call check(err, msh%ne == 30 .and. abs(msh%x(0) + 0.5_dp) < 1.0e-15_dp .and. &
                   abs(msh%x(30) - 0.5_dp) < 1.0e-15_dp, 'LOADS mesh ends or size wrong')
        if (allocated(err)) return
        do i = 1, 2
            call check(err, minval(abs(msh%x - loads(i))) < 1.0e-14_dp, &
                       'a load position is not a node')
            if (allocated(err)) return
        end do
        do e = 2, msh%ne
            ratio = (msh%x(e) - msh%x(e - 1))/(msh%x(e - 1) - msh%x(e - 2))
            call check(err, any(abs(ratio - [1.1_dp, 1.0_dp/1.1_dp, 1.0_dp]) < 1.0e-12_dp) .or. &
                       any(abs(msh%x(e - 1) - loads(1:2)) < 1.0e-14_dp), 'LOADS grading ratio')
            if (allocated(err)) return
        end do
        call new_mesh(msh, -0.5_dp, 0.5_dp, 2, 'LOADS', mesh_err, loads)
        call check(err, allocated(mesh_err), 'LOADS with fewer elements than pieces was accepted')
    end subroutine test_loads_grading
end module test_shape_functions
