!> Operations on a given mesh for adaptive refinement (ADAPT; doc/CHOICES.md, Adaptive
!! meshing): bisect marked elements, keep neighbouring elements within a size ratio of 2, move
!! (snap) a node onto a
!! located boundary, and coarsen by removing every other node between pinned nodes.
!!
!! Pinned nodes are positions the mesh must keep: the ends of the interface, the load
!! positions and patch edges, and the nodes snapped onto a contact or stick/slip boundary.
!! Keeping them in the coarsened meshes makes the nested family used by the error estimate
!! (error_estimate) cut no boundary inside an element, so its three solutions converge
!! smoothly instead of erratically (doc/OUTPUT.md, "Error estimates").
module mesh_refinement
    use kinds, only: dp
    use mesh, only: mesh_t
    implicit none
    private

    public :: bisected, balance_marks, snap_node, coarsened, pinned_nodes, nearest_node, &
              same_nodes

    real(dp), parameter :: max_ratio = 2.0_dp   !! largest size ratio of neighbouring elements

contains

    !> The mesh with every marked element cut in two equal halves.
    pure function bisected(msh, marked) result(fine)
        type(mesh_t), intent(in) :: msh            !! the mesh
        logical, intent(in) :: marked(:)           !! (ne) element e is cut
        type(mesh_t) :: fine
        integer :: e, k
        fine%ne = msh%ne + count(marked)
        allocate (fine%x(0:fine%ne))
        fine%x(0) = msh%x(0)
        k = 0
        elements: do e = 1, msh%ne
            if (marked(e)) then
                k = k + 1
                fine%x(k) = 0.5_dp*(msh%x(e - 1) + msh%x(e))
            end if
            k = k + 1
            fine%x(k) = msh%x(e)
        end do elements
    end function bisected

    !> Add marks until no element would end up more than max_ratio times the length of a
    !! neighbour: a graded mesh without jumps, so that refinement towards a singular end or a
    !! boundary stays a smooth geometric grading (and the interpolation error stays local).
    pure subroutine balance_marks(msh, marked)
        type(mesh_t), intent(in) :: msh       !! the mesh
        logical, intent(inout) :: marked(:)   !! per element: to be bisected; marks added
        real(dp), allocatable :: h_new(:)
        logical :: changed
        integer :: e
        changed = .true.
        sweeps: do while (changed)
            changed = .false.
            h_new = (msh%x(1:) - msh%x(:msh%ne - 1))*merge(0.5_dp, 1.0_dp, marked)
            elements: do e = 1, msh%ne
                if (marked(e)) cycle elements
                if (e > 1) then
                    if (h_new(e) > max_ratio*h_new(e - 1)*(1.0_dp + 1.0e-9_dp)) marked(e) = .true.
                end if
                if (e < msh%ne) then
                    if (h_new(e) > max_ratio*h_new(e + 1)*(1.0_dp + 1.0e-9_dp)) marked(e) = .true.
                end if
                if (marked(e)) changed = .true.
            end do elements
        end do sweeps
    end subroutine balance_marks

    !> Index of the node nearest to x.
    pure integer function nearest_node(msh, x) result(i)
        type(mesh_t), intent(in) :: msh   !! the mesh
        real(dp), intent(in) :: x         !! a position [L]
        i = minloc(abs(msh%x - x), dim=1) - 1
    end function nearest_node

    !> Move a node onto x (a located boundary): the nearer end of the element holding x unless
    !! it is pinned, else the other end if that keeps the element at least a quarter of its
    !! length. The node moves inside that element, so nodes keep their order and the element
    !! keeps at least a quarter of its length. node: the node moved (-1 if none could be).
    pure subroutine snap_node(msh, x, pinned, node)
        type(mesh_t), intent(inout) :: msh          !! the mesh, one node moved
        real(dp), intent(in) :: x                   !! the position (a located boundary) [L]
        logical, intent(in) :: pinned(0:)           !! (0:ne) nodes that must stay
        integer, intent(out) :: node                !! the node moved (-1: none)
        integer :: e, near, far
        real(dp) :: h
        node = -1
        if (x <= msh%x(0) .or. x >= msh%x(msh%ne)) return
        e = count(msh%x(1:msh%ne) < x) + 1          ! x(e-1) <= x < x(e)
        h = msh%x(e) - msh%x(e - 1)
        near = merge(e - 1, e, x - msh%x(e - 1) <= msh%x(e) - x)
        far = 2*e - 1 - near
        if (.not. pinned(near)) then
            node = near
        else if (.not. pinned(far) .and. abs(x - msh%x(near)) >= 0.25_dp*h) then
            node = far
        else
            return
        end if
        msh%x(node) = x
    end subroutine snap_node

    !> Nodes at the given positions (to within 1e-9 of the length) and the two ends.
    pure function pinned_nodes(msh, positions) result(pinned)
        type(mesh_t), intent(in) :: msh        !! the mesh
        real(dp), intent(in) :: positions(:)   !! positions whose nodes stay (load positions) [L]
        logical :: pinned(0:msh%ne)
        real(dp) :: tol
        integer :: k, i
        tol = 1.0e-9_dp*(msh%x(msh%ne) - msh%x(0))
        pinned = .false.
        pinned(0) = .true.
        pinned(msh%ne) = .true.
        do k = 1, size(positions)
            i = nearest_node(msh, positions(k))
            if (abs(msh%x(i) - positions(k)) <= tol) pinned(i) = .true.
        end do
    end function pinned_nodes

    !> Every other node removed between consecutive pinned nodes (a segment of an odd number
    !! of elements keeps its last element whole): about half the elements, the pinned nodes
    !! kept. pinned_out: the pinned flags on the coarse mesh.
    pure subroutine coarsened(msh, pinned, coarse, pinned_out)
        type(mesh_t), intent(in) :: msh                      !! the mesh
        logical, intent(in) :: pinned(0:)                    !! per node: pinned (kept)
        type(mesh_t), intent(out) :: coarse                  !! the coarser mesh
        logical, allocatable, intent(out) :: pinned_out(:)   !! per node of coarse: pinned
        logical :: keep(0:msh%ne)
        integer :: i, last_pin, k
        keep = .false.
        last_pin = 0
        keep(0) = .true.
        nodes: do i = 1, msh%ne
            if (pinned(i)) then
                keep(i) = .true.
                last_pin = i
            else
                keep(i) = mod(i - last_pin, 2) == 0
            end if
        end do nodes
        coarse%ne = count(keep) - 1
        allocate (coarse%x(0:coarse%ne), pinned_out(0:coarse%ne))
        k = -1
        do i = 0, msh%ne
            if (.not. keep(i)) cycle
            k = k + 1
            coarse%x(k) = msh%x(i)
            pinned_out(k) = pinned(i)
        end do
    end subroutine coarsened

    !> Whether two meshes have the same nodes (to 1e-12 of the second one's length).
    pure logical function same_nodes(x1, x2)
        real(dp), intent(in) :: x1(:)   !! the nodes of one mesh [L]
        real(dp), intent(in) :: x2(:)   !! the nodes of the other [L]
        same_nodes = size(x1) == size(x2)
        if (same_nodes) same_nodes = all(abs(x1 - x2) <= 1.0e-12_dp*(x2(size(x2)) - x2(1)))
    end function same_nodes

end module mesh_refinement
