!> Interpolations of one field on a 1-D mesh (SPEC §5): P1, P2 and S2.
!!
!! * P1: linear Lagrange, one coefficient per node (n_dof = ne + 1).
!! * P2: quadratic C0 Lagrange, nodes at element ends and mid-points (n_dof = 2 ne + 1);
!!       local order (left, middle, right).
!! * S2: quadratic B-splines on the open knot vector (x0, x0, x0, x1, ..., x_{ne-1}, xne, xne, xne)
!!       (n_dof = ne + 2), C1 at every interior node: the paper's "parabolic" functions of
!!       its Fig. 8. Coefficients are control values, not nodal values. A displacement
!!       field may ask for C0 at given interior nodes (c0_nodes: a concentrated load acts
!!       there, so the slope jumps): the knot is doubled there, one coefficient more each.
!!
!! For all three the first coefficient is the field value at the left end and the last one the
!! value at the right end (the other functions vanish there), so end conditions such as
!! u_s(0) = psi(0) = 0 of the plate are imposed by removing one coefficient.
module shape_functions
    use kinds, only: dp
    use mesh, only: mesh_t
    implicit none
    private

    integer, parameter, public :: INTERP_P1 = 1, INTERP_P2 = 2, INTERP_S2 = 3
    integer, parameter, public :: max_local = 3     !! most functions nonzero on one element

    !> One field's interpolation on a mesh.
    type, public :: basis_t
        integer :: family = INTERP_P1              !! INTERP_P1, INTERP_P2 or INTERP_S2
        integer :: ne = 0                          !! number of elements
        integer :: n_dof = 0                       !! number of coefficients
        integer :: n_local = 0                     !! functions nonzero on each element
        integer :: degree = 1                      !! polynomial degree on an element
        real(dp), allocatable :: x(:)              !! mesh nodes x(0:ne) [length]
        real(dp), allocatable :: knots(:)          !! S2 knot vector t(1:n_dof+3) [length]
        integer, allocatable :: span(:)            !! S2: element e is knot span
                                                   !! [t(span(e)), t(span(e)+1)]
    end type basis_t

    public :: new_basis, eval_basis, interp_name, interp_code

contains

    !> Build the basis of the given family on the mesh.
    pure subroutine new_basis(basis, msh, family, c0_nodes)
        type(basis_t), intent(out) :: basis    !! the basis
        type(mesh_t), intent(in) :: msh        !! the mesh
        integer, intent(in) :: family          !! INTERP_P1, INTERP_P2 or INTERP_S2
        integer, intent(in), optional :: c0_nodes(:)  !! S2: interior nodes made C0
        integer :: ne
        ne = msh%ne
        basis%family = family
        basis%ne = ne
        allocate (basis%x(0:ne), source=msh%x)
        select case (family)
        case (INTERP_P2)
            basis%n_dof = 2*ne + 1
            basis%n_local = 3
            basis%degree = 2
        case (INTERP_S2)
            basis%n_local = 3
            basis%degree = 2
            call spline_knots(msh, basis, c0_nodes)
        case default
            basis%n_dof = ne + 1
            basis%n_local = 2
            basis%degree = 1
        end select
    end subroutine new_basis

    !> The open knot vector of S2 (interior knots single, doubled at c0_nodes) and the knot
    !! span of every element.
    pure subroutine spline_knots(msh, basis, c0_nodes)
        type(mesh_t), intent(in) :: msh
        type(basis_t), intent(inout) :: basis
        integer, intent(in), optional :: c0_nodes(:)
        logical :: double(0:msh%ne)
        integer :: k, e, n
        double = .false.
        if (present(c0_nodes)) then
            do k = 1, size(c0_nodes)
                if (c0_nodes(k) > 0 .and. c0_nodes(k) < msh%ne) double(c0_nodes(k)) = .true.
            end do
        end if
        ! 3 knots at each end, one at each interior node, one more at each doubled node
        allocate (basis%knots(msh%ne + 5 + count(double)), basis%span(msh%ne))
        basis%knots(1:2) = msh%x(0)
        n = 2
        elements: do e = 1, msh%ne
            n = n + 1
            basis%knots(n) = msh%x(e - 1)
            if (double(e - 1)) then
                n = n + 1
                basis%knots(n) = msh%x(e - 1)
            end if
            basis%span(e) = n
        end do elements
        basis%knots(n + 1:n + 3) = msh%x(msh%ne)
        basis%n_dof = n
    end subroutine spline_knots

    !> Values and x-derivatives of the functions nonzero on element e at local xi in [-1, 1].
    pure subroutine eval_basis(basis, e, xi, idx, val, der, x)
        type(basis_t), intent(in) :: basis        !! the basis
        integer, intent(in) :: e                  !! element, 1..ne
        real(dp), intent(in) :: xi                !! local coordinate in [-1, 1]
        integer, intent(out) :: idx(max_local)    !! global coefficient numbers (first n_local)
        real(dp), intent(out) :: val(max_local)   !! function values
        real(dp), intent(out) :: der(max_local)   !! d/dx [1/length]
        real(dp), intent(out) :: x                !! physical coordinate of xi [length]
        real(dp) :: h
        h = basis%x(e) - basis%x(e - 1)
        x = basis%x(e - 1) + 0.5_dp*(xi + 1.0_dp)*h
        idx = 0
        val = 0.0_dp
        der = 0.0_dp
        select case (basis%family)
        case (INTERP_P2)
            idx(1:3) = [2*e - 1, 2*e, 2*e + 1]
            val(1:3) = [0.5_dp*xi*(xi - 1.0_dp), 1.0_dp - xi*xi, 0.5_dp*xi*(xi + 1.0_dp)]
            der(1:3) = [xi - 0.5_dp, -2.0_dp*xi, xi + 0.5_dp]*(2.0_dp/h)
        case (INTERP_S2)
            associate (span => basis%span(e))
                idx(1:3) = [span - 2, span - 1, span]
                call quadratic_bspline(basis%knots, span, x, val(1:3), der(1:3))
            end associate
        case default
            idx(1:2) = [e, e + 1]
            val(1:2) = [0.5_dp*(1.0_dp - xi), 0.5_dp*(1.0_dp + xi)]
            der(1:2) = [-1.0_dp, 1.0_dp]/h
        end select
    end subroutine eval_basis

    !> The three quadratic B-splines nonzero on knot span [t(s), t(s+1)] (Cox–de Boor).
    pure subroutine quadratic_bspline(t, s, x, val, der)
        real(dp), intent(in) :: t(:)       !! knot vector
        integer, intent(in) :: s           !! span index, t(s) <= x <= t(s+1), t(s) < t(s+1)
        real(dp), intent(in) :: x
        real(dp), intent(out) :: val(3), der(3)
        real(dp) :: n_left, n_right, d_left, d_right
        ! degree-1 functions on the span
        n_left = (t(s + 1) - x)/(t(s + 1) - t(s))
        n_right = (x - t(s))/(t(s + 1) - t(s))
        d_left = t(s + 1) - t(s - 1)
        d_right = t(s + 2) - t(s)
        val(1) = (t(s + 1) - x)/d_left*n_left
        val(2) = (x - t(s - 1))/d_left*n_left + (t(s + 2) - x)/d_right*n_right
        val(3) = (x - t(s))/d_right*n_right
        der(1) = -2.0_dp/d_left*n_left
        der(2) = 2.0_dp/d_left*n_left - 2.0_dp/d_right*n_right
        der(3) = 2.0_dp/d_right*n_right
    end subroutine quadratic_bspline

    !> Deck word of an interpolation code.
    pure function interp_name(family) result(name)
        integer, intent(in) :: family   !! interpolation code (INTERP_P1, INTERP_P2, INTERP_S2)
        character(len=2) :: name
        select case (family)
        case (INTERP_P2)
            name = 'P2'
        case (INTERP_S2)
            name = 'S2'
        case default
            name = 'P1'
        end select
    end function interp_name

    !> Interpolation code of a deck word (P1, P2, S2); 0 when unknown.
    pure integer function interp_code(word)
        character(len=*), intent(in) :: word   !! a deck word
        select case (trim(adjustl(word)))
        case ('P1')
            interp_code = INTERP_P1
        case ('P2')
            interp_code = INTERP_P2
        case ('S2')
            interp_code = INTERP_S2
        case default
            interp_code = 0
        end select
    end function interp_code
end module shape_functions
