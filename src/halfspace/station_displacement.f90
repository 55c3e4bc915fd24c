!> Surface displacements at many points (the report stations) under a traction field:
!! u_i(x0) = int K_ij(x0, s) sigma_j(s) ds over the mesh, for every x0 in x_eval.
!!
!! The reference (`displacement_split_kernel_reference`) builds a line rule for every (point,
!! element) pair: O(points x elements) rules, kernel calls and kernel values (about 4 300 values
!! per point at N_e = 1000). Here the elements are grouped in a binary tree of clusters
!! (contiguous elements, halved by count) and, at each point x0:
!!  * a cluster [lo, hi] of at least `min_cluster` elements whose gap to x0 is at least
!!    `far_ratio` times its length is integrated as one piece: K(x0, s) is interpolated at the
!!    n_cheb Chebyshev points t_k of the cluster, so that
!!        int K(x0, s) sigma(s) ds ~= sum_k K(x0, t_k) M_k,   M_k = int l_k(s) sigma(s) ds,
!!    l_k the Lagrange polynomials. The moments M_k do not depend on x0: they are computed once
!!    per traction field, exactly (Gauss rule on every element, exact for the polynomial
!!    l_k sigma; the tractions are polynomials on each element but not across elements, which
!!    is why the kernel, not the integrand, is interpolated), and passed up the tree exactly
!!    (l_k of a parent restricted to a child is a polynomial of degree n_cheb - 1, reproduced by
!!    the child's interpolation);
!!  * the other elements (near x0, or in small clusters) get the reference's line rule
!!    (`build_line_rule`: log-weighted piece at the singular point, graded Gauss pieces),
!!    point for point, so that near x0 nothing changes.
!! The kernel is analytic in s inside the Bernstein ellipse of the cluster through x0 (the log
!! point and the jump of the kernels are at x0; the strip kernels' other singular points x0 +-
!! i b/2 and the ring kernels' circle |s| = x0 lie outside it), with rho = c + sqrt(c^2 - 1),
!! c = 1 + 2 gap/length >= 3, rho >= 5.8 (as `points_for_ratio`); Chebyshev interpolation
!! converges like rho^(-n_cheb): n_cheb = 24 gives about 5e-19 relative to the kernel, below
!! the rounding of the sums. All kernel values of one point go to the kernel in one call
!! (the ring kernels run their AGM on vectors of 32 points). About 300 to 600 kernel values per
!! point at N_e = 100 to 1000, O(log N_e) clusters per point.
submodule(singular_quadrature) station_displacement
    implicit none

    real(dp), parameter :: far_ratio = 1.0_dp   !! gap / length from which a cluster is one piece
    integer, parameter :: n_cheb = 24           !! interpolation points of a cluster
    integer, parameter :: leaf_max = 3          !! elements of a leaf cluster, at most (a cluster
                                                !! of 4 elements at gap = length needs 27 GL
                                                !! points element by element, > n_cheb)

    !> Binary tree of clusters of contiguous elements; cluster 1 is the whole mesh.
    type :: cluster_tree_t
        integer :: n = 0                          !! clusters
        integer, allocatable :: first(:), last(:) !! elements first..last
        integer, allocatable :: child(:, :)       !! child(1:2, c); 0: a leaf (<= leaf_max)
        real(dp), allocatable :: lo(:), hi(:)     !! extent [x(first - 1), x(last)]
        real(dp), allocatable :: t(:, :)          !! t(k, c): Chebyshev points (not leaves)
        real(dp), allocatable :: mx(:, :), mz(:, :)  !! moments of sigma_x and sigma_z at t(:, c)
    end type cluster_tree_t

    !> The tractions on every element as quadratics in t = (s - x(e-1)) / h_e in [0, 1]:
    !! sigma_j(s) = c(1, j, e) + t (c(2, j, e) + t c(3, j, e)), j = 1 (sigma_x), 2 (sigma_z);
    !! evaluated at each line point without the bases (the P1, P2 and S2 fields are
    !! polynomials of degree <= 2 on an element).
    type :: traction_poly_t
        real(dp), allocatable :: c(:, :, :)
    end type traction_poly_t

    !> Kernel points of one evaluation point, and the weights that go with each:
    !! u += F_11 ax + F_12 az + P_11 cx + P_12 cz, w += F_21 ax + ... (c: log weight).
    type :: point_list_t
        integer :: n = 0
        real(dp), allocatable :: s(:), ax(:), az(:), cx(:), cz(:), x_rep(:)
        logical, allocatable :: with_log(:)
        real(dp), allocatable :: f(:, :, :), p(:, :, :)
    end type point_list_t

contains

    module subroutine displacement_split_kernel(kernel, bx, bz, rx, rz, x_eval, u, w, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: rx(:)
        real(dp), intent(in) :: rz(:)
        real(dp), intent(in) :: x_eval(:)
        real(dp), intent(out) :: u(:)
        real(dp), intent(out) :: w(:)
        type(error_t), allocatable, intent(out) :: err
        type(gauss_tables_t) :: tab
        type(line_rule_t) :: line
        type(cluster_tree_t) :: tree
        type(traction_poly_t) :: sig
        type(point_list_t) :: list
        real(dp) :: lambda(n_cheb), cosines(n_cheb)
        integer, allocatable :: stack(:)
        integer :: i
        character(len=60) :: where

        call check_bases(bx, bz, err)
        if (allocated(err)) return
        if (size(rx) /= bx%n_dof .or. size(rz) /= bz%n_dof .or. size(u) /= size(x_eval) &
            .or. size(w) /= size(x_eval)) then
            call new_error(err, EXIT_INTERNAL, 'surface displacement: array sizes do not match')
            return
        end if
        call new_gauss_tables(tab, lazy=.true.)
        call chebyshev_points(cosines, lambda)
        sig = traction_polynomials(bx, bz, rx, rz)
        call build_tree(bx, tree)
        call fill_moments(tab, bx, sig, cosines, lambda, tree)
        allocate (stack(tree%n))
        points: do i = 1, size(x_eval)
            list%n = 0
            call gather_points(kernel, tab, bx, sig, tree, x_eval(i), stack, line, list)
            call sum_point(kernel, list, x_eval(i), u(i), w(i), err)
            if (allocated(err)) then
                write (where, '("surface displacement at point ",i0)') i
                call add_context(err, trim(where))
                return
            end if
        end do points
    end subroutine displacement_split_kernel

    !> Chebyshev points of the first kind cos((2k - 1) pi / (2 n)) on [-1, 1] and their
    !! barycentric weights (-1)^(k+1) sin((2k - 1) pi / (2 n)) (the same on every interval).
    pure subroutine chebyshev_points(cosines, lambda)
        real(dp), intent(out) :: cosines(:), lambda(:)
        real(dp) :: theta
        integer :: k, n
        n = size(cosines)
        nodes: do k = 1, n
            theta = real(2*k - 1, dp)*acos(-1.0_dp)/real(2*n, dp)
            cosines(k) = cos(theta)
            lambda(k) = real(1 - 2*mod(k + 1, 2), dp)*sin(theta)
        end do nodes
    end subroutine chebyshev_points

    !> l_k(s) at the points t(k) with barycentric weights lambda(k) (second barycentric form).
    pure subroutine lagrange_values(t, lambda, s, ell)
        real(dp), intent(in) :: t(:), lambda(:), s
        real(dp), intent(out) :: ell(:)
        integer :: k
        nodes: do k = 1, size(t)
            if (s == t(k)) then
                ell = 0.0_dp
                ell(k) = 1.0_dp
                return
            end if
            ell(k) = lambda(k)/(s - t(k))
        end do nodes
        ell = ell/sum(ell)
    end subroutine lagrange_values

    ! ---------------------------------------------------------------- the cluster tree

    !> Clusters by halving the element range until at most leaf_max elements remain.
    pure subroutine build_tree(basis, tree)
        type(basis_t), intent(in) :: basis
        type(cluster_tree_t), intent(out) :: tree
        integer :: c, cap, mid
        cap = max(1, 2*basis%ne)
        allocate (tree%first(cap), tree%last(cap), tree%child(2, cap), tree%lo(cap), tree%hi(cap))
        tree%n = 1
        tree%first(1) = 1
        tree%last(1) = basis%ne
        c = 0
        ! breadth first: children are numbered after their parent
        clusters: do while (c < tree%n)
            c = c + 1
            tree%lo(c) = basis%x(tree%first(c) - 1)
            tree%hi(c) = basis%x(tree%last(c))
            tree%child(:, c) = 0
            if (tree%last(c) - tree%first(c) + 1 <= leaf_max) cycle clusters
            mid = (tree%first(c) + tree%last(c))/2
            tree%child(:, c) = [tree%n + 1, tree%n + 2]
            tree%first(tree%n + 1:tree%n + 2) = [tree%first(c), mid + 1]
            tree%last(tree%n + 1:tree%n + 2) = [mid, tree%last(c)]
            tree%n = tree%n + 2
        end do clusters
    end subroutine build_tree

    !> Chebyshev points and moments M_k = int l_k sigma ds of every cluster that is not a leaf:
    !! children first (clusters are numbered parents before children), a leaf child's elements
    !! by a Gauss rule exact for l_k sigma, another child's moments through l_k of the parent at
    !! the child's points.
    pure subroutine fill_moments(tab, basis, sig, cosines, lambda, tree)
        type(gauss_tables_t), intent(inout) :: tab
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        real(dp), intent(in) :: cosines(:), lambda(:)
        type(cluster_tree_t), intent(inout) :: tree
        real(dp) :: ell(n_cheb)
        integer :: c, j, k, ch
        allocate (tree%t(n_cheb, tree%n), tree%mx(n_cheb, tree%n), tree%mz(n_cheb, tree%n))
        nodes: do c = 1, tree%n
            tree%t(:, c) = 0.5_dp*(tree%lo(c) + tree%hi(c)) + 0.5_dp*(tree%hi(c) - tree%lo(c))*cosines
        end do nodes
        tree%mx = 0.0_dp
        tree%mz = 0.0_dp
        upwards: do c = tree%n, 1, -1
            if (tree%child(1, c) == 0) cycle upwards
            children: do j = 1, 2
                ch = tree%child(j, c)
                if (tree%child(1, ch) == 0) then
                    call add_element_moments(tab, basis, sig, tree%first(ch), tree%last(ch), &
                                             tree%t(:, c), lambda, tree%mx(:, c), tree%mz(:, c))
                else
                    child_points: do k = 1, n_cheb
                        call lagrange_values(tree%t(:, c), lambda, tree%t(k, ch), ell)
                        tree%mx(:, c) = tree%mx(:, c) + ell*tree%mx(k, ch)
                        tree%mz(:, c) = tree%mz(:, c) + ell*tree%mz(k, ch)
                    end do child_points
                end if
            end do children
        end do upwards
    end subroutine fill_moments

    !> Add int l_k sigma ds over the elements first..last to the moments (mx, mz), l_k the
    !! Lagrange polynomials at t: Gauss rule of n_cheb/2 + 1 points per element, exact for the
    !! degree n_cheb + 1 of l_k sigma.
    pure subroutine add_element_moments(tab, basis, sig, first, last, t, lambda, mx, mz)
        type(gauss_tables_t), intent(inout) :: tab
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        integer, intent(in) :: first, last
        real(dp), intent(in) :: t(:), lambda(:)
        real(dp), intent(inout) :: mx(:), mz(:)
        integer, parameter :: n = n_cheb/2 + 1
        real(dp) :: ell(n_cheb), h, sx(n), sz(n)
        integer :: e, i
        call need_order(tab, n)
        elements: do e = first, last
            h = basis%x(e) - basis%x(e - 1)
            call tractions_at(sig, e, tab%v(1:n, n), sx, sz)
            nodes: do i = 1, n
                call lagrange_values(t, lambda, basis%x(e - 1) + h*tab%v(i, n), ell)
                mx = mx + ell*(h*tab%w(i, n)*sx(i))
                mz = mz + ell*(h*tab%w(i, n)*sz(i))
            end do nodes
        end do elements
    end subroutine add_element_moments

    !> The quadratics of traction_poly_t from the values at t = 0, 1/2, 1 of every element.
    pure function traction_polynomials(bx, bz, rx, rz) result(sig)
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: rx(:), rz(:)
        type(traction_poly_t) :: sig
        integer :: idx(max_local), e, k
        real(dp) :: val(max_local), der(max_local), x_out, y(3, 2)
        allocate (sig%c(3, 2, bx%ne))
        elements: do e = 1, bx%ne
            ends: do k = 1, 3
                ! (eval_basis directly: the parent's private basis_at may be inlined away)
                call eval_basis(bx, e, real(k - 2, dp), idx, val, der, x_out)
                y(k, 1) = sum(val(1:bx%n_local)*rx(idx(1:bx%n_local)))
                call eval_basis(bz, e, real(k - 2, dp), idx, val, der, x_out)
                y(k, 2) = sum(val(1:bz%n_local)*rz(idx(1:bz%n_local)))
            end do ends
            sig%c(1, :, e) = y(1, :)
            sig%c(2, :, e) = 4.0_dp*y(2, :) - 3.0_dp*y(1, :) - y(3, :)
            sig%c(3, :, e) = 2.0_dp*(y(1, :) + y(3, :)) - 4.0_dp*y(2, :)
        end do elements
    end function traction_polynomials

    !> sigma_j at the local coordinates t of element e (traction_poly_t).
    pure subroutine tractions_at(sig, e, t, sx, sz)
        type(traction_poly_t), intent(in) :: sig
        integer, intent(in) :: e
        real(dp), intent(in) :: t(:)
        real(dp), intent(out) :: sx(:), sz(:)
        sx = sig%c(1, 1, e) + t*(sig%c(2, 1, e) + t*sig%c(3, 1, e))
        sz = sig%c(1, 2, e) + t*(sig%c(2, 2, e) + t*sig%c(3, 2, e))
    end subroutine tractions_at

    ! ---------------------------------------------------------------- one evaluation point

    !> The kernel points of x0: from the root down, a cluster far enough from x0 (module header)
    !! as its Chebyshev points and moments, the elements of a leaf that is not by the line
    !! rule of the reference.
    pure subroutine gather_points(kernel, tab, basis, sig, tree, x0, stack, line, list)
        class(split_kernel_t), intent(in) :: kernel
        type(gauss_tables_t), intent(inout) :: tab
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        type(cluster_tree_t), intent(in) :: tree
        real(dp), intent(in) :: x0
        integer, intent(inout) :: stack(:)
        type(line_rule_t), intent(inout) :: line
        type(point_list_t), intent(inout) :: list
        real(dp) :: gap, u0
        integer :: top, c, e, n0, n1
        u0 = kernel%log_length(x0)
        top = 1
        stack(1) = 1
        clusters: do while (top > 0)
            c = stack(top)
            top = top - 1
            gap = max(tree%lo(c) - x0, x0 - tree%hi(c), 0.0_dp)
            if (tree%child(1, c) /= 0) then
                if (gap >= far_ratio*(tree%hi(c) - tree%lo(c))) then
                    call make_room(list, n_cheb, n0, n1)
                    list%s(n0:n1) = tree%t(:, c)
                    list%ax(n0:n1) = tree%mx(:, c)
                    list%az(n0:n1) = tree%mz(:, c)
                    list%cx(n0:n1) = 0.0_dp
                    list%cz(n0:n1) = 0.0_dp
                    list%with_log(n0:n1) = .false.
                else
                    stack(top + 1:top + 2) = tree%child(:, c)
                    top = top + 2
                end if
                cycle clusters
            end if
            elements: do e = tree%first(c), tree%last(c)
                call build_line_rule(tab, basis%x(e - 1), basis%x(e), x0, u0, line)
                call make_room(list, line%n, n0, n1)
                list%s(n0:n1) = line%s(1:line%n)
                ! sigma at t = (s - x(e-1))/h; cx, cz are scratch for it here
                list%cx(n0:n1) = (line%s(1:line%n) - basis%x(e - 1))/(basis%x(e) - basis%x(e - 1))
                call tractions_at(sig, e, list%cx(n0:n1), list%ax(n0:n1), list%az(n0:n1))
                list%cx(n0:n1) = line%wc(1:line%n)*list%ax(n0:n1)
                list%cz(n0:n1) = line%wc(1:line%n)*list%az(n0:n1)
                list%ax(n0:n1) = line%w(1:line%n)*list%ax(n0:n1)
                list%az(n0:n1) = line%w(1:line%n)*list%az(n0:n1)
                list%with_log(n0:n1) = line%wc(1:line%n) /= 0.0_dp
            end do elements
        end do clusters
    end subroutine gather_points

    !> Append n points to the list: they go to n0..n1 (filled by the caller).
    pure subroutine make_room(list, n, n0, n1)
        type(point_list_t), intent(inout) :: list
        integer, intent(in) :: n
        integer, intent(out) :: n0, n1
        if (.not. allocated(list%s)) then
            call resize(list, max(1024, n))
        else if (list%n + n > size(list%s)) then
            call resize(list, max(2*size(list%s), list%n + n))
        end if
        n0 = list%n + 1
        n1 = list%n + n
        list%n = n1
    end subroutine make_room

    !> Make room for cap points, keeping the points listed.
    pure subroutine resize(list, cap)
        type(point_list_t), intent(inout) :: list
        integer, intent(in) :: cap
        type(point_list_t) :: bigger
        integer :: n
        n = list%n
        allocate (bigger%s(cap), bigger%ax(cap), bigger%az(cap), bigger%cx(cap), bigger%cz(cap), &
                  bigger%x_rep(cap), bigger%with_log(cap), bigger%f(2, 2, cap), bigger%p(2, 2, cap))
        if (n > 0) then
            bigger%s(1:n) = list%s(1:n)
            bigger%ax(1:n) = list%ax(1:n)
            bigger%az(1:n) = list%az(1:n)
            bigger%cx(1:n) = list%cx(1:n)
            bigger%cz(1:n) = list%cz(1:n)
            bigger%with_log(1:n) = list%with_log(1:n)
        end if
        bigger%n = n
        call move_alloc(bigger%s, list%s)
        call move_alloc(bigger%ax, list%ax)
        call move_alloc(bigger%az, list%az)
        call move_alloc(bigger%cx, list%cx)
        call move_alloc(bigger%cz, list%cz)
        call move_alloc(bigger%x_rep, list%x_rep)
        call move_alloc(bigger%with_log, list%with_log)
        call move_alloc(bigger%f, list%f)
        call move_alloc(bigger%p, list%p)
    end subroutine resize

    !> The kernel at all points of the list in one call, and the weighted sums u and w.
    subroutine sum_point(kernel, list, x0, u, w, err)
        class(split_kernel_t), intent(in) :: kernel
        type(point_list_t), intent(inout) :: list
        real(dp), intent(in) :: x0
        real(dp), intent(out) :: u, w
        type(error_t), allocatable, intent(out) :: err
        integer :: k, n
        u = 0.0_dp
        w = 0.0_dp
        n = list%n
        if (n == 0) return
        list%x_rep(1:n) = x0
        call kernel%values(list%x_rep(1:n), list%s(1:n), list%with_log(1:n), list%f(:, :, 1:n), &
                           list%p(:, :, 1:n), err)
        if (allocated(err)) return
        points: do k = 1, n
            u = u + list%f(1, 1, k)*list%ax(k) + list%f(1, 2, k)*list%az(k)
            w = w + list%f(2, 1, k)*list%ax(k) + list%f(2, 2, k)*list%az(k)
            if (list%with_log(k)) then
                u = u + list%p(1, 1, k)*list%cx(k) + list%p(1, 2, k)*list%cz(k)
                w = w + list%p(2, 1, k)*list%cx(k) + list%p(2, 2, k)*list%cz(k)
            end if
        end do points
    end subroutine sum_point
end submodule station_displacement
