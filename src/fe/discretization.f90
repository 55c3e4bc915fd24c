!> The discrete unknowns of one case: the mesh, one basis per field, and where each field's
!! coefficients sit in the global vector z = [v; r] = [u_s, w, psi, sigma_x, sigma_z].
module discretization
    use kinds, only: dp
    use errors, only: error_t
    use mesh, only: mesh_t, new_mesh, loads_pieces
    use shape_functions, only: basis_t, new_basis
    use model, only: load_t, model_t, MODEL_BEAM, LOAD_PATCH, FIELD_U, FIELD_W, FIELD_PSI, &
        FIELD_SX, &
                     FIELD_SZ
    use mesh_refinement, only: nearest_node
    use foundation_structure, only: interface_ends
    use applied_loads, only: load_positions
    implicit none
    private

    !> Mesh, bases and global numbering.
    type, public :: discretization_t
        type(mesh_t) :: msh
        type(basis_t) :: basis(5)          !! per field FIELD_U .. FIELD_SZ
        integer :: offset(5) = 0           !! global index of a field's coefficient 1 is offset+1
        integer :: nv = 0                  !! displacement unknowns
        integer :: nr = 0                  !! traction unknowns
        integer :: n = 0                   !! nv + nr
        !> constrained unknowns (plate: u_s(0), psi(0), sigma_x(0))
        integer, allocatable :: fixed(:)
    end type discretization_t

    public :: new_discretization, discretise_mesh, locate_element, loads_on_nodes, card_mesh
    public :: fewest_elements

contains

    !> Mesh and bases from the MESH card; plate symmetry u_s(0) = psi(0) = 0.
    subroutine new_discretization(m, d, err)
        type(model_t), intent(in) :: m                   !! the model
        type(discretization_t), intent(out) :: d         !! the discretisation
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(mesh_t) :: msh

        call card_mesh(m, m%mesh%ne, msh, err)
        if (allocated(err)) return
        call discretise_mesh(m, msh, d)
    end subroutine new_discretization

    !> The mesh of the model's MESH card with ne elements: its grading over the interface
    !! (LOADS: a node at every load position and patch edge).
    subroutine card_mesh(m, ne, msh, err)
        type(model_t), intent(in) :: m                   !! the model
        integer, intent(in) :: ne                        !! number of elements
        type(mesh_t), intent(out) :: msh                 !! the mesh
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        real(dp) :: x_left, x_right
        call interface_ends(m%structure, x_left, x_right)
        call new_mesh(msh, x_left, x_right, ne, m%mesh%grading, err, load_positions(m%loads))
    end subroutine card_mesh

    !> The fewest elements the model's MESH grading can make: one per piece between the load
    !! positions for LOADS, else 1 (the deck reader checks N_e against it).
    pure integer function fewest_elements(m) result(n)
        type(model_t), intent(in) :: m   !! the model
        real(dp) :: x_left, x_right
        n = 1
        if (trim(m%mesh%grading) /= 'LOADS') return
        call interface_ends(m%structure, x_left, x_right)
        n = loads_pieces(x_left, x_right, load_positions(m%loads))
    end function fewest_elements

    !> Bases, numbering and constraints of the model's fields on a given mesh (any nodes:
    !! the MESH card's, or an adapted mesh). The one place these rules live.
    subroutine discretise_mesh(m, msh, d)
        type(model_t), intent(in) :: m              !! the model
        type(mesh_t), intent(in) :: msh             !! nodes spanning the whole interface
        type(discretization_t), intent(out) :: d    !! the discretisation
        integer :: field
        d%msh = msh
        do field = FIELD_U, FIELD_SZ
            if (field <= FIELD_PSI) then
                call new_basis(d%basis(field), d%msh, m%mesh%interp(field), &
                    concentrated_nodes(m%loads, &
                    msh))
            else
                call new_basis(d%basis(field), d%msh, m%mesh%interp(field))
            end if
            if (field > FIELD_U) d%offset(field) = d%offset(field - 1) + d%basis(field - 1)%n_dof
        end do
        d%nv = d%offset(FIELD_SX)
        d%n = d%offset(FIELD_SZ) + d%basis(FIELD_SZ)%n_dof
        d%nr = d%n - d%nv
        if (m%structure%kind == MODEL_BEAM) then
            allocate (d%fixed(0))
        else
            ! axisymmetry: u_s, psi and the radial shear traction vanish on the axis
            d%fixed = [d%offset(FIELD_U) + 1, d%offset(FIELD_PSI) + 1, d%offset(FIELD_SX) + 1]
        end if
    end subroutine discretise_mesh

    !> Interior nodes at which a concentrated load (point, ring, moment) acts: there a
    !! shear force, axial force or moment jumps, so the slope of the displacement fields
    !! does, and an S2 displacement basis is made C0 there (shape_functions); P1 and P2 are
    !! C0 everywhere already. A load between nodes gets nothing (LOADS grading puts nodes on
    !! the loads).
    pure function concentrated_nodes(loads, msh) result(nodes)
        type(load_t), intent(in) :: loads(:)   !! the loads part of the model
        type(mesh_t), intent(in) :: msh
        integer, allocatable :: nodes(:)
        real(dp) :: tol
        integer :: i, k
        tol = 1.0e-9_dp*(msh%x(msh%ne) - msh%x(0))
        allocate (nodes(0))
        do i = 1, size(loads)
            if (loads(i)%kind == LOAD_PATCH) cycle
            k = nearest_node(msh, loads(i)%x1)
            if (abs(msh%x(k) - loads(i)%x1) <= tol .and. k > 0 .and. k < msh%ne .and. &
                .not. any(nodes == k)) nodes = [nodes, k]
        end do
    end function concentrated_nodes

    !> Whether every concentrated load (point, ring, moment) inside the interface sits on a
    !! node of msh, so that an S2 displacement basis has its slope jump there.
    pure logical function loads_on_nodes(loads, msh)
        type(load_t), intent(in) :: loads(:)   !! the loads part of the model
        type(mesh_t), intent(in) :: msh        !! the mesh
        real(dp) :: tol
        integer :: i
        tol = 1.0e-9_dp*(msh%x(msh%ne) - msh%x(0))
        loads_on_nodes = .true.
        do i = 1, size(loads)
            associate (x => loads(i)%x1)
                if (loads(i)%kind == LOAD_PATCH .or. x <= msh%x(0) + tol .or. &
                    x >= msh%x(msh%ne) - tol) cycle
                if (abs(msh%x(nearest_node(msh, x)) - x) > tol) loads_on_nodes = .false.
            end associate
        end do
    end function loads_on_nodes

    !> Element containing x and the local coordinate there (x clipped to the mesh).
    pure subroutine locate_element(msh, x, e, xi)
        type(mesh_t), intent(in) :: msh   !! the mesh
        real(dp), intent(in) :: x         !! a position on the structure [L]
        integer, intent(out) :: e         !! the element holding x
        real(dp), intent(out) :: xi       !! the local coordinate of x in e, in [-1, 1]
        integer :: lo, hi, mid
        lo = 1
        hi = msh%ne
        bisection: do while (lo < hi)
            mid = (lo + hi)/2
            if (x > msh%x(mid)) then
                lo = mid + 1
            else
                hi = mid
            end if
        end do bisection
        e = lo
        xi = 2.0_dp*(x - msh%x(e - 1))/(msh%x(e) - msh%x(e - 1)) - 1.0_dp
        xi = max(-1.0_dp, min(1.0_dp, xi))
    end subroutine locate_element
end module discretization
