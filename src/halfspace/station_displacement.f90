!> Surface displacements at many points (the report stations) under a traction field:
!! u_i(x0) = int K_ij(x0, s) sigma_j(s) ds over the mesh, for every x0 in x_eval.
!!
!! The reference (`displacement_split_kernel_reference`) builds a line rule for every (point,
!! element) pair and calls the kernel once per pair: O(points x elements) rules, calls and
!! kernel values (about 4 200 values per point at N_e = 1000, 540 at N_e = 100). Here the
!! elements are grouped in a binary tree of clusters (contiguous elements, halved by count down
!! to leaves of at most leaf_max elements) and, at each point x0, from the root down:
!!  * a cluster [lo, hi] (not a leaf) whose gap to x0 is at least far_ratio times its length is
!!    integrated as one piece: K(x0, s) is interpolated at the m Chebyshev points t_i of the
!!    cluster, so that
!!        int K(x0, s) sigma(s) ds ~= sum_i K(x0, t_i) W_i,   W_i = int l_i(s) sigma(s) ds,
!!    l_i the Lagrange polynomials. The weights W_i do not depend on x0: they come from the
!!    cluster's Chebyshev moments mu_q = int T_q sigma ds (q < n_cheb), computed once per
!!    traction field, exactly: on the elements of a leaf by a Gauss rule exact for the
!!    polynomial T_q sigma (the tractions are polynomials on each element but not across
!!    elements, which is why the kernel, not the integrand, is interpolated), and up the tree
!!    through the child's weights of order n_cheb (T_q of the parent is a polynomial of degree
!!    < n_cheb on the child). The order m <= n_cheb is the least of `orders` with
!!    rho^(-m) <= 1e-16 (cheb_digits), rho = c + sqrt(c^2 - 1), c = 1 + 2 gap/length, the
!!    Bernstein ellipse of the cluster through x0: the kernel is analytic in s inside it (the
!!    log point and the jump of the kernels are at x0; the strip kernels' other singular
!!    points x0 +- i b/2 and the ring kernels' circle |s| = x0 lie outside it), and Chebyshev
!!    interpolation converges like rho^(-m). Gap = length/2: m = 28; gap = 5 lengths: m = 12;
!!  * the elements of a leaf get the reference's line rule (`build_line_rule`: the log-weighted
!!    piece at x0, graded Gauss pieces), point for point, or, where that rule is a single
!!    Gauss piece, that piece directly: next to x0 nothing changes.
!! All kernel values of one point go to the kernel in two calls, the points with a log weight
!! (next to x0) and the others (the ring kernels run their AGM on vectors of 32 points and form
!! the log coefficients only in the first). About 250 kernel values per point at N_e = 100 and
!! 400 at N_e = 1000 (O(log N_e) clusters per point). The results differ from the reference's
!! by the rounding of its sums: with both sums accumulated in quadruple precision they agree to
!! 1.6e-15 of the largest |u| and 7e-16 of the largest |w| (example decks, N_e 20 to 1000), the
!! same with cheb_digits = 17; in double precision, to 1e-14, the reference's own rounding
!! (doc/METHOD.md).
submodule(singular_quadrature) station_displacement
    use kinds, only: pi
    use chebyshev_tables, only: n_cheb, orders, n_orders, chebyshev_t, new_chebyshev, &
                                chebyshev_values, order_for
    implicit none

    real(dp), parameter :: far_ratio = 0.5_dp   !! gap / length from which a cluster is one piece
    integer, parameter :: leaf_max = 3          !! elements of a leaf cluster, at most (a cluster
                                                !! of 4 elements at gap = length/2 needs 31 GL
                                                !! points element by element, > n_cheb)
    integer, parameter :: n_weights = sum(orders)

    !> Binary tree of clusters of contiguous elements; cluster 1 is the whole mesh.
    type :: cluster_tree_t
        integer :: n = 0                          !! clusters
        integer, allocatable :: first(:), last(:) !! elements first..last
        integer, allocatable :: child(:, :)       !! child(1:2, c); 0: a leaf (<= leaf_max)
        real(dp), allocatable :: lo(:), hi(:)     !! extent [x(first - 1), x(last)]
        !> Chebyshev moments mux(q + 1, c) = int T_q(xi) sigma_x ds, xi in [-1, 1] across c
        !! (muz: sigma_z), q < n_cheb; not for leaves
        real(dp), allocatable :: mux(:, :), muz(:, :)
        !> wx(slot_start(k) + i - 1, c) = int l_i sigma_x ds (wz: sigma_z), l_i the Lagrange
        !! polynomials of orders(k) on cluster c; made when first used (ready)
        real(dp), allocatable :: wx(:, :), wz(:, :)
        logical, allocatable :: ready(:, :)
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
        type(chebyshev_t) :: cheb
        type(cluster_tree_t) :: tree
        type(traction_poly_t) :: sig
        type(point_list_t) :: plain, logs
        integer, allocatable :: stack(:)
        real(dp), allocatable :: x0(:)
        real(dp) :: u_log, w_log
        integer :: i
        character(len=60) :: where

        call check_displacement_arguments(bx, bz, size(rx), size(rz), size(x_eval), size(u), &
                                          size(w), err)
        if (allocated(err)) return
        call shared_gauss_tables(tab)
        call new_chebyshev(cheb)
        sig = traction_polynomials(bx, bz, rx, rz)
        call build_tree(bx, tree)
        call fill_moments(tab, bx, sig, cheb, tree)
        allocate (stack(tree%n))
        x0 = snapped_to_nodes(bx%x, x_eval)
        points: do i = 1, size(x_eval)
            plain%n = 0
            logs%n = 0
            call gather_points(kernel, tab, bx, sig, cheb, tree, x0(i), stack, line, plain, &
                               logs)
            call sum_list(kernel, plain, .false., x0(i), u(i), w(i), err)
            if (.not. allocated(err)) call sum_list(kernel, logs, .true., x0(i), u_log, &
                                                          w_log, err)
            if (allocated(err)) then
                write (where, '("surface displacement at point ",i0)') i
                call add_context(err, trim(where))
                return
            end if
            u(i) = u(i) + u_log
            w(i) = w(i) + w_log
        end do points
    end subroutine displacement_split_kernel

    ! ---------------------------------------------------------------- interpolation

    !> Range of the weights of orders(k) in wx(:, c) and wz(:, c).
    pure integer function slot_start(k) result(i0)
        integer, intent(in) :: k
        i0 = sum(orders(1:k - 1)) + 1
    end function slot_start

    !> The lowest order that is accurate for a far cluster at gap / length = ratio (>= far_ratio,
    !! where the highest order always is: its least ratio is 0.4996).
    pure integer function order_index(cheb, ratio) result(k)
        type(chebyshev_t), intent(in) :: cheb
        real(dp), intent(in) :: ratio
        k = order_for(cheb, ratio)
        if (k == 0) k = n_orders
    end function order_index

    !> Weights of orders(k) on cluster c from its Chebyshev moments: int l_i sigma =
    !! (2/m) sum'_{q<m} T_q(x_i) mu_q (new_chebyshev), exact as m <= n_cheb.
    pure subroutine order_weights(cheb, k, c, tree)
        type(chebyshev_t), intent(in) :: cheb
        integer, intent(in) :: k, c
        type(cluster_tree_t), intent(inout) :: tree
        integer :: i0, m
        i0 = slot_start(k)
        m = orders(k)
        tree%wx(i0:i0 + m - 1, c) = matmul(cheb%to_weights(1:m, 1:m, k), tree%mux(1:m, c))
        tree%wz(i0:i0 + m - 1, c) = matmul(cheb%to_weights(1:m, 1:m, k), tree%muz(1:m, c))
        tree%ready(k, c) = .true.
    end subroutine order_weights

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

    !> Chebyshev moments of every cluster that is not a leaf, children first (clusters are
    !! numbered parents before children): a leaf child's elements by a Gauss rule exact for
    !! T_q sigma; another child's through its Lagrange weights of order n_cheb, T_q of the parent
    !! being a polynomial of degree < n_cheb on the child: int T_q sigma = sum_j T_q(t_j) W_j.
    pure subroutine fill_moments(tab, basis, sig, cheb, tree)
        type(gauss_tables_t), intent(in) :: tab
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        type(chebyshev_t), intent(in) :: cheb
        type(cluster_tree_t), intent(inout) :: tree
        real(dp) :: t_q(n_cheb, n_cheb), t_child(n_cheb), mid, scale
        integer :: c, j, ch, i0
        allocate (tree%mux(n_cheb, tree%n), tree%muz(n_cheb, tree%n), &
                  tree%wx(n_weights, tree%n), tree%wz(n_weights, tree%n), &
                  tree%ready(n_orders, tree%n))
        tree%ready = .false.
        i0 = slot_start(n_orders)
        upwards: do c = tree%n, 1, -1
            if (tree%child(1, c) == 0) cycle upwards
            tree%mux(:, c) = 0.0_dp
            tree%muz(:, c) = 0.0_dp
            mid = 0.5_dp*(tree%lo(c) + tree%hi(c))
            scale = 2.0_dp/(tree%hi(c) - tree%lo(c))
            children: do j = 1, 2
                ch = tree%child(j, c)
                if (tree%child(1, ch) == 0) then
                    call add_element_moments(tab, basis, sig, tree%first(ch), tree%last(ch), mid, &
                                             scale, tree%mux(:, c), tree%muz(:, c))
                    cycle children
                end if
                if (.not. tree%ready(n_orders, ch)) call order_weights(cheb, n_orders, ch, tree)
                t_child = cluster_points(cheb, n_orders, tree, ch)
                call chebyshev_values(scale*(t_child - mid), t_q)
                tree%mux(:, c) = tree%mux(:, c) + &
                                 matmul(tree%wx(i0:i0 + n_cheb - 1, ch), t_q)
                tree%muz(:, c) = tree%muz(:, c) + &
                                 matmul(tree%wz(i0:i0 + n_cheb - 1, ch), t_q)
            end do children
        end do upwards
    end subroutine fill_moments

    !> The points of orders(k) on cluster c.
    pure function cluster_points(cheb, k, tree, c) result(t)
        type(chebyshev_t), intent(in) :: cheb
        integer, intent(in) :: k, c
        type(cluster_tree_t), intent(in) :: tree
        real(dp) :: t(orders(k))
        t = 0.5_dp*(tree%lo(c) + tree%hi(c)) + 0.5_dp*(tree%hi(c) - tree%lo(c))* &
            cheb%cosines(1:orders(k), k)
    end function cluster_points

    !> Add int T_q(xi) sigma ds over the elements first..last to the moments (mux, muz),
    !! xi = scale (s - mid): Gauss rule of n_cheb/2 + 1 points per element, exact for the
    !! degree n_cheb + 1 of T_q sigma.
    pure subroutine add_element_moments(tab, basis, sig, first, last, mid, scale, mux, muz)
        type(gauss_tables_t), intent(in) :: tab
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        integer, intent(in) :: first, last
        real(dp), intent(in) :: mid, scale
        real(dp), intent(inout) :: mux(:), muz(:)
        integer, parameter :: n = n_cheb/2 + 1
        real(dp) :: t_q(n, n_cheb), h, sx(n), sz(n)
        integer :: e
        elements: do e = first, last
            h = basis%x(e) - basis%x(e - 1)
            call tractions_at(sig, e, tab%v(1:n, n), sx, sz)
            call chebyshev_values(scale*(basis%x(e - 1) + h*tab%v(1:n, n) - mid), t_q)
            mux = mux + matmul(h*tab%w(1:n, n)*sx, t_q)
            muz = muz + matmul(h*tab%w(1:n, n)*sz, t_q)
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
            samples: do k = 1, 3
                ! (eval_basis directly: the parent's private basis_at may be inlined away)
                call eval_basis(bx, e, real(k - 2, dp), idx, val, der, x_out)
                y(k, 1) = sum(val(1:bx%n_local)*rx(idx(1:bx%n_local)))
                call eval_basis(bz, e, real(k - 2, dp), idx, val, der, x_out)
                y(k, 2) = sum(val(1:bz%n_local)*rz(idx(1:bz%n_local)))
            end do samples
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

    !> The kernel points of x0, from the root down: a cluster far enough from x0 (module header)
    !! as the points of its order and their weights (in plain); the elements of a leaf that is
    !! not by the line rule of the reference (points with a log weight in logs, the others in
    !! plain: the ring kernels then form P on whole vectors, and only where needed).
    pure subroutine gather_points(kernel, tab, basis, sig, cheb, tree, x0, stack, line, plain, &
                                  logs)
        class(split_kernel_t), intent(in) :: kernel
        type(gauss_tables_t), intent(in) :: tab
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        type(chebyshev_t), intent(in) :: cheb
        type(cluster_tree_t), intent(inout) :: tree
        real(dp), intent(in) :: x0
        integer, intent(inout) :: stack(:)
        type(line_rule_t), intent(inout) :: line
        type(point_list_t), intent(inout) :: plain, logs
        real(dp) :: gap, len, u0
        integer :: top, c, e, k, i0, n0, n1, n
        u0 = kernel%log_length(x0)
        top = 1
        stack(1) = 1
        clusters: do while (top > 0)
            c = stack(top)
            top = top - 1
            if (tree%child(1, c) == 0) then
                elements: do e = tree%first(c), tree%last(c)
                    n = one_piece_order(basis%x(e - 1), basis%x(e), x0)
                    if (n > 0) then
                        call add_gauss_points(tab, basis, sig, e, n, plain)
                    else
                        call build_line_rule(tab, basis%x(e - 1), basis%x(e), x0, u0, line)
                        call add_line_points(basis, sig, e, line, plain, logs)
                    end if
                end do elements
                cycle clusters
            end if
            gap = max(tree%lo(c) - x0, x0 - tree%hi(c), 0.0_dp)
            len = tree%hi(c) - tree%lo(c)
            if (gap < far_ratio*len) then
                stack(top + 1:top + 2) = tree%child(:, c)
                top = top + 2
                cycle clusters
            end if
            k = order_index(cheb, gap/len)
            if (.not. tree%ready(k, c)) call order_weights(cheb, k, c, tree)
            i0 = slot_start(k)
            call make_room(plain, orders(k), n0, n1)
            plain%s(n0:n1) = cluster_points(cheb, k, tree, c)
            plain%ax(n0:n1) = tree%wx(i0:i0 + orders(k) - 1, c)
            plain%az(n0:n1) = tree%wz(i0:i0 + orders(k) - 1, c)
        end do clusters
    end subroutine gather_points

    !> The GL order of the element [a, b] if the reference's line rule for x0 is one GL piece
    !! (x0 outside, the far end at most 2.5 times as far as the near one: `add_ray`), else 0.
    pure integer function one_piece_order(a, b, x0) result(n)
        real(dp), intent(in) :: a, b, x0
        real(dp) :: near, far
        n = 0
        if (x0 <= a) then
            near = a - x0
            far = b - x0
        else if (x0 >= b) then
            near = x0 - b
            far = x0 - a
        else
            return
        end if
        if (near <= 8.0_dp*epsilon(1.0_dp)*max(abs(x0), far) .or. far > 2.5_dp*near) return
        n = points_for_ratio(near/(far - near))
    end function one_piece_order

    !> The n-point GL rule on element e, sigma times its weights, to plain.
    pure subroutine add_gauss_points(tab, basis, sig, e, n, plain)
        type(gauss_tables_t), intent(in) :: tab
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        integer, intent(in) :: e, n
        type(point_list_t), intent(inout) :: plain
        real(dp) :: h
        integer :: n0, n1
        call make_room(plain, n, n0, n1)
        h = basis%x(e) - basis%x(e - 1)
        plain%s(n0:n1) = basis%x(e - 1) + h*tab%v(1:n, n)
        call tractions_at(sig, e, tab%v(1:n, n), plain%ax(n0:n1), plain%az(n0:n1))
        plain%ax(n0:n1) = h*tab%w(1:n, n)*plain%ax(n0:n1)
        plain%az(n0:n1) = h*tab%w(1:n, n)*plain%az(n0:n1)
    end subroutine add_gauss_points

    !> The points of an element's line rule with sigma times their weights: those with a log
    !! weight to logs, the others to plain.
    pure subroutine add_line_points(basis, sig, e, line, plain, logs)
        type(basis_t), intent(in) :: basis
        type(traction_poly_t), intent(in) :: sig
        integer, intent(in) :: e
        type(line_rule_t), intent(in) :: line
        type(point_list_t), intent(inout) :: plain, logs
        real(dp) :: t, sx, sz, inv_h, c(3, 2)
        integer :: k, n
        call reserve(plain, line%n)
        call reserve(logs, line%n)
        inv_h = 1.0_dp/(basis%x(e) - basis%x(e - 1))
        c = sig%c(:, :, e)
        points: do k = 1, line%n
            t = (line%s(k) - basis%x(e - 1))*inv_h
            sx = c(1, 1) + t*(c(2, 1) + t*c(3, 1))
            sz = c(1, 2) + t*(c(2, 2) + t*c(3, 2))
            if (line%wc(k) == 0.0_dp) then
                n = plain%n + 1
                plain%n = n
                plain%s(n) = line%s(k)
                plain%ax(n) = line%w(k)*sx
                plain%az(n) = line%w(k)*sz
            else
                n = logs%n + 1
                logs%n = n
                logs%s(n) = line%s(k)
                logs%ax(n) = line%w(k)*sx
                logs%az(n) = line%w(k)*sz
                logs%cx(n) = line%wc(k)*sx
                logs%cz(n) = line%wc(k)*sz
            end if
        end do points
    end subroutine add_line_points

    !> Room for n more points in the list.
    pure subroutine reserve(list, n)
        type(point_list_t), intent(inout) :: list
        integer, intent(in) :: n
        if (.not. allocated(list%s)) then
            call resize(list, max(1024, n))
        else if (list%n + n > size(list%s)) then
            call resize(list, max(2*size(list%s), list%n + n))
        end if
    end subroutine reserve

    !> Append n points to the list: they go to n0..n1 (filled by the caller).
    pure subroutine make_room(list, n, n0, n1)
        type(point_list_t), intent(inout) :: list
        integer, intent(in) :: n
        integer, intent(out) :: n0, n1
        call reserve(list, n)
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
                  bigger%x_rep(cap), bigger%with_log(cap), bigger%f(2, 2, cap), &
                  bigger%p(2, 2, cap))
        if (n > 0) then
            bigger%s(1:n) = list%s(1:n)
            bigger%ax(1:n) = list%ax(1:n)
            bigger%az(1:n) = list%az(1:n)
            bigger%cx(1:n) = list%cx(1:n)
            bigger%cz(1:n) = list%cz(1:n)
        end if
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

    !> The kernel at all points of a list in one call (P only for logs, where every point has
    !! a log weight; plain has none), and the weighted sums u and w.
    subroutine sum_list(kernel, list, with_log, x0, u, w, err)
        class(split_kernel_t), intent(in) :: kernel
        type(point_list_t), intent(inout) :: list
        logical, intent(in) :: with_log
        real(dp), intent(in) :: x0
        real(dp), intent(out) :: u, w
        type(error_t), allocatable, intent(out) :: err
        integer :: k, n
        u = 0.0_dp
        w = 0.0_dp
        n = list%n
        if (n == 0) return
        list%x_rep(1:n) = x0
        list%with_log(1:n) = with_log
        call kernel%values(list%x_rep(1:n), list%s(1:n), list%with_log(1:n), &
                           list%f(:, :, 1:n), list%p(:, :, 1:n), err)
        if (allocated(err)) return
        points: do k = 1, n
            u = u + list%f(1, 1, k)*list%ax(k) + list%f(1, 2, k)*list%az(k)
            w = w + list%f(2, 1, k)*list%ax(k) + list%f(2, 2, k)*list%az(k)
        end do points
        if (.not. with_log) return
        log_terms: do k = 1, n
            u = u + list%p(1, 1, k)*list%cx(k) + list%p(1, 2, k)*list%cz(k)
            w = w + list%p(2, 1, k)*list%cx(k) + list%p(2, 2, k)*list%cz(k)
        end do log_terms
    end subroutine sum_list
end submodule station_displacement
