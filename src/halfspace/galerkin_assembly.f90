!> Galerkin assembly of the half-space flexibility T at the cost of its kernel evaluations.
!!
!! T_ab = int int g_a(x) W(x) K(x, xi) g_b(xi) dxi dx (W = 1 beam, 2 pi x plate), blocks
!! [T_xx T_xz; T_zx T_zz] with all bx coefficients first; K a kernel in split form
!! (`singular_quadrature`: value F and coefficient P of ln|x - xi|, steps at x = xi). Every
!! element pair is integrated with fixed-order rules and ONE kernel evaluation per point pair,
!! shared by all local basis products of the pair:
!!  * well separated pairs (gap >= near_ratio times the longer element): tensor Gauss–Legendre,
!!    n points per direction from the Bernstein-ellipse parameter of gap/size and the degree of
!!    the polynomial factor (`far_points`, 1e-16 per direction), contracted as
!!    L = B_f diag(w_f W) K diag(w_s) B_s^T;
!!  * touching and nearly touching pairs, kernels that depend on one variable v only (strip:
!!    v = x - xi; rings, homogeneous of degree 0: v = x/xi, ln|x - xi| = ln xi + ln|v - 1|):
!!    the logarithm is integrated analytically by the product-log rule of `singular_quadrature`
!!    (Legendre moments of ln, i.e. a log-weighted rule, the remainder P, Q analytic), pieces cut
!!    at the kinks of the range across v and at the steps, the kernel evaluated once per node of
!!    v, and the integral across v of the basis products done exactly (polynomial, 4-point GL);
!!    All positions there are offsets from the singular point and from the element starts,
!!    formed from differences of node coordinates (1 - t or x - a rounded from absolute
!!    positions would cost eps |x|/h, 1e-13 at N_e = 1000);
!!  * other kernels: the two-dimensional pair rules of `singular_quadrature`.
!! A translation-invariant kernel on a (piecewise) uniform mesh repeats the pair integrals of
!! the translated pair (`translates`): O(N_e) pairs are integrated, the rest copied.
!! Only pairs e2 >= e1 are integrated; the pair (e2, e1) is the transpose by reciprocity
!! (W(x) K_ij(x, xi) = W(xi) K_ji(xi, x): r G_ij(r, s) = s G_ji(s, r) for the rings, k_ij(X) =
!! k_ji(-X) for the strip); a self pair is one triangle plus its transpose, so T is exactly
!! symmetric. `assemble_split_kernel_reference` (adaptive pair rules, both triangles) is kept as
!! the reference of the tests.
module galerkin_assembly
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use sorting, only: sort_ascending
    use errors, only: error_t, add_context
    use shape_functions, only: basis_t, eval_basis, max_local
    use singular_quadrature, only: split_kernel_t, gauss_tables_t, point_rule_t, line_rule_t, &
                                   new_gauss_tables, need_order, build_pair_rule, build_line_rule, &
                                   check_bases, near_ratio, n_max
    implicit none
    private

    public :: assemble_split_kernel

    integer, parameter :: n_loc = 2*max_local    !! local functions of one element, both fields
    real(dp), parameter :: far_digits = 16.5_dp  !! see far_points
    integer, parameter :: n_across = 4   !! GL points across the reduced variable: exact for the
                                         !! basis products (degree <= 6 with the ring measure)

    !> Local numbering of one element pair: rows (field element) and columns (source element),
    !! first the bx functions then the bz functions.
    type :: pair_map_t
        integer :: nf = 0                         !! local rows
        integer :: ns = 0                         !! local columns
        integer :: comp_f(n_loc) = 0              !! 1 = bx (tangential), 2 = bz (normal)
        integer :: comp_s(n_loc) = 0
        integer :: row(n_loc) = 0                 !! global row of each local row
        integer :: col(n_loc) = 0                 !! global column of each local column
    end type pair_map_t

    !> Values of the local functions of every element at the nodes of one GL rule.
    type :: order_table_t
        logical :: ready = .false.
        real(dp), allocatable :: b(:, :, :)        !! b(r, i, e): function r of e at node i
    end type order_table_t

    !> Work arrays reused over the element pairs.
    type :: work_t
        type(gauss_tables_t) :: tab
        type(point_rule_t) :: rule
        type(line_rule_t) :: line
        real(dp), allocatable :: x(:), xi(:)       !! point pairs
        real(dp), allocatable :: w(:), wc(:)       !! weights of F and of its log coefficient P
        real(dp), allocatable :: dv(:)             !! reduced nodes: offsets v - v_sing (exact)
        logical, allocatable :: with_log(:)
        real(dp), allocatable :: f(:, :, :), p(:, :, :)
        integer(int64) :: n_kernel = 0_int64       !! kernel evaluations so far
        integer, allocatable :: n_fun(:)           !! functions nonzero on element e
        integer, allocatable :: comp(:, :)         !! their field (1 = bx, 2 = bz)
        integer, allocatable :: glob(:, :)         !! their global number in T
        type(order_table_t) :: by_order(n_max)     !! basis values at the GL nodes, by order
        real(dp), allocatable :: poly(:, :, :)     !! poly(:, r, e): g_r = c1 + c2 xi + c3 xi^2
    end type work_t

contains

    !> T (module header); n_kernel returns the number of kernel evaluations (point pairs).
    subroutine assemble_split_kernel(kernel, bx, bz, t_mat, err, n_kernel)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx            !! basis of sigma_x
        type(basis_t), intent(in) :: bz            !! basis of sigma_z, same mesh
        real(dp), allocatable, intent(out) :: t_mat(:, :)
        type(error_t), allocatable, intent(out) :: err
        integer(int64), intent(out), optional :: n_kernel
        type(work_t) :: work
        type(pair_map_t) :: map
        real(dp), allocatable :: column_loc(:, :, :, :)
        logical, allocatable :: shift_ok(:)
        integer :: e1, e2, now
        character(len=60) :: where
        call check_bases(bx, bz, err)
        if (allocated(err)) return
        allocate (t_mat(bx%n_dof + bz%n_dof, bx%n_dof + bz%n_dof), source=0.0_dp)
        call new_gauss_tables(work%tab, lazy=.true.)
        call need_order(work%tab, n_across)
        call reserve(work, 1024)
        call number_elements(bx, bz, work)
        call translates(kernel, bx, work%poly, shift_ok)
        allocate (column_loc(n_loc, n_loc, bx%ne, 0:1))
        ! columns outer: the pair (e1, e2) adds to columns of e2 only, rows in order
        source_elements: do e2 = 1, bx%ne
            now = mod(e2, 2)
            field_elements: do e1 = 1, e2
                call new_pair_map(work, e1, e2, map)
                if (repeats_pair(bx, shift_ok, e1, e2)) then
                    ! translate of the pair (e1 - 1, e2 - 1), integrated in the last column
                    column_loc(:, :, e1, now) = column_loc(:, :, e1 - 1, 1 - now)
                else
                    call pair_integrals(kernel, bx, bz, e1, e2, map, work, &
                                        column_loc(:, :, e1, now), err)
                    if (allocated(err)) then
                        write (where, '("half-space operator, elements ",i0," and ",i0)') e1, e2
                        call add_context(err, trim(where))
                        return
                    end if
                end if
                call scatter(map, e1 == e2, column_loc(:, :, e1, now), t_mat)
            end do field_elements
        end do source_elements
        call add_transpose(t_mat)
        if (present(n_kernel)) n_kernel = work%n_kernel
    end subroutine assemble_split_kernel

    !> shift_ok(e): for a translation-invariant kernel, element e is element e - 1 moved by its
    !! length: the same length and the same local functions (polynomial coefficients), both up
    !! to the rounding of the node coordinates. Then a pair (e1, e2) with shift_ok(e1),
    !! shift_ok(e2) and h(e1 - 1) = h(e2 - 1) repeats the pair (e1 - 1, e2 - 1): uniform and
    !! piecewise uniform meshes integrate O(N_e) pairs instead of O(N_e^2).
    pure subroutine translates(kernel, bx, poly, shift_ok)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        real(dp), intent(in) :: poly(:, :, :)      !! work%poly
        logical, allocatable, intent(out) :: shift_ok(:)
        integer :: e
        allocate (shift_ok(bx%ne), source=.false.)
        if (.not. kernel%translation_invariant) return
        elements: do e = 2, bx%ne
            shift_ok(e) = same_length(bx, e, e - 1) .and. &
                          all(abs(poly(:, :, e) - poly(:, :, e - 1)) <= 64.0_dp*epsilon(1.0_dp))
        end do elements
    end subroutine translates

    !> The pair (e1, e2) is the pair (e1 - 1, e2 - 1) moved along (see translates).
    pure logical function repeats_pair(bx, shift_ok, e1, e2)
        type(basis_t), intent(in) :: bx
        logical, intent(in) :: shift_ok(:)
        integer, intent(in) :: e1, e2
        repeats_pair = .false.
        if (e1 < 2) return
        if (.not. (shift_ok(e1) .and. shift_ok(e2))) return
        repeats_pair = same_length(bx, e1 - 1, e2 - 1)
    end function repeats_pair

    !> Elements e and f have the same length up to the rounding of the node coordinates.
    pure logical function same_length(bx, e, f)
        type(basis_t), intent(in) :: bx
        integer, intent(in) :: e, f
        same_length = abs((bx%x(e) - bx%x(e - 1)) - (bx%x(f) - bx%x(f - 1))) <= &
                      8.0_dp*epsilon(1.0_dp)*max(abs(bx%x(0)), abs(bx%x(bx%ne)))
    end function same_length

    !> Local and global numbering of the functions of elements e1 (rows) and e2 (columns).
    pure subroutine new_pair_map(work, e1, e2, map)
        type(work_t), intent(in) :: work
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(out) :: map
        map%nf = work%n_fun(e1)
        map%comp_f = work%comp(:, e1)
        map%row = work%glob(:, e1)
        map%ns = work%n_fun(e2)
        map%comp_s = work%comp(:, e2)
        map%col = work%glob(:, e2)
    end subroutine new_pair_map

    !> Numbering of the functions of every element (element_numbers), once.
    pure subroutine number_elements(bx, bz, work)
        type(basis_t), intent(in) :: bx, bz
        type(work_t), intent(inout) :: work
        integer :: e
        allocate (work%n_fun(bx%ne), work%comp(n_loc, bx%ne), work%glob(n_loc, bx%ne))
        allocate (work%poly(3, n_loc, bx%ne))
        work%comp = 0
        work%glob = 0
        elements: do e = 1, bx%ne
            call element_numbers(bx, bz, e, work%n_fun(e), work%comp(:, e), work%glob(:, e))
            call element_polynomials(bx, bz, e, work%poly(:, :, e))
        end do elements
    end subroutine number_elements

    !> The local functions of element e as quadratics in the local coordinate xi, c1 + c2 xi +
    !! c3 xi^2 (exact: degree <= 2 on an element), from their values at both ends and their slope
    !! at the left end. Only the element ends are evaluated: the shape functions place an
    !! interior point at the physical x = a + (1 + xi) h/2, rounded by eps |x|, i.e. by
    !! eps |x|/h of the element (1e-13 at N_e = 1000), and S2 is evaluated from that x.
    pure subroutine element_polynomials(bx, bz, e, poly)
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e
        real(dp), intent(out) :: poly(3, n_loc)
        real(dp) :: left(n_loc), right(n_loc), slope(n_loc), unused(n_loc), half_h
        call end_values(bx, bz, e, -1.0_dp, left, slope)
        call end_values(bx, bz, e, 1.0_dp, right, unused)
        half_h = 0.5_dp*(bx%x(e) - bx%x(e - 1))
        slope = slope*half_h                                  ! d/dxi at xi = -1: c2 - 2 c3
        poly(2, :) = 0.5_dp*(right - left)
        poly(3, :) = 0.5_dp*(poly(2, :) - slope)
        poly(1, :) = left + poly(2, :) - poly(3, :)
    end subroutine element_polynomials

    !> Values and x-derivatives of the bx then bz functions of element e at xi = +-1.
    pure subroutine end_values(bx, bz, e, xi, val, der)
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e
        real(dp), intent(in) :: xi
        real(dp), intent(out) :: val(n_loc), der(n_loc)
        integer :: idx(max_local)
        real(dp) :: v(max_local), d(max_local), x_out
        val = 0.0_dp
        der = 0.0_dp
        call eval_basis(bx, e, xi, idx, v, d, x_out)
        val(1:bx%n_local) = v(1:bx%n_local)
        der(1:bx%n_local) = d(1:bx%n_local)
        call eval_basis(bz, e, xi, idx, v, d, x_out)
        val(bx%n_local + 1:bx%n_local + bz%n_local) = v(1:bz%n_local)
        der(bx%n_local + 1:bx%n_local + bz%n_local) = d(1:bz%n_local)
    end subroutine end_values

    !> Tabulate the local functions of every element at the nodes of the n-point GL rule.
    pure subroutine tabulate_order(bx, bz, n, work)
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: n
        type(work_t), intent(inout) :: work
        real(dp) :: xi(n)
        integer :: e, i
        xi = 2.0_dp*work%tab%v(1:n, n) - 1.0_dp
        allocate (work%by_order(n)%b(n_loc, n, bx%ne))
        elements: do e = 1, bx%ne
            nodes: do i = 1, n
                work%by_order(n)%b(:, i, e) = work%poly(1, :, e) + xi(i)*(work%poly(2, :, e) + &
                                                                          xi(i)*work%poly(3, :, e))
            end do nodes
        end do elements
        work%by_order(n)%ready = .true.
    end subroutine tabulate_order

    !> Functions nonzero on element e: count, field (1 = bx, 2 = bz) and global number.
    pure subroutine element_numbers(bx, bz, e, n, comp, glob)
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e
        integer, intent(out) :: n, comp(n_loc), glob(n_loc)
        integer :: idx(max_local)
        real(dp) :: val(max_local), der(max_local), x_out
        call eval_basis(bx, e, 0.0_dp, idx, val, der, x_out)
        comp(1:bx%n_local) = 1
        glob(1:bx%n_local) = idx(1:bx%n_local)
        call eval_basis(bz, e, 0.0_dp, idx, val, der, x_out)
        n = bx%n_local + bz%n_local
        comp(bx%n_local + 1:n) = 2
        glob(bx%n_local + 1:n) = bx%n_dof + idx(1:bz%n_local)
    end subroutine element_numbers

    !> The kernel depends on one combination of (x, xi) only (reduced_pair applies).
    pure logical function reducible(kernel)
        class(split_kernel_t), intent(in) :: kernel
        reducible = kernel%homogeneous .or. kernel%translation_invariant
    end function reducible

    !> GL points per direction for a well separated pair: the error of n-point GL on
    !! poly_p(x) k(x), k singular at distance `ratio` element lengths from the element, is about
    !! rho^(p - 2n), rho = c + sqrt(c^2 - 1), c = 1 + 2 ratio (Bernstein ellipse through the
    !! singularity; the polynomial of degree p grows like rho^p on it). n = (far_digits/log10 rho
    !! + p)/2 rounded up keeps it below 1e-16 of int |poly_p k| for k = 1/d, ln d and for the
    !! worst (Legendre) polynomial of degree p <= 3, as measured with 40-digit arithmetic at
    !! ratios 2 to 3000.
    pure integer function far_points(ratio, p) result(n)
        real(dp), intent(in) :: ratio      !! gap / element length, >= near_ratio
        integer, intent(in) :: p           !! polynomial degree of the non-kernel factor
        real(dp) :: c, rho
        c = 1.0_dp + 2.0_dp*ratio
        rho = c + sqrt(c*c - 1.0_dp)
        n = min(n_max, max(2, ceiling(0.5_dp*(far_digits/log10(rho) + real(p, dp)))))
    end function far_points

    !> Degree of the polynomial factor on the field side: the basis, times x for the ring
    !! measure 2 pi x (homogeneous kernels are the ring kernels) where that factor grows on the
    !! Bernstein ellipse: 2 pi x = W0 (1 + eps xi), eps = h/(a + b), is at most 2 W0 on the
    !! ellipse rho when eps rho <= 1 (elements away from the axis), a factor 2 in the error.
    pure integer function field_degree(kernel, bx, bz, e, ratio) result(p)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e                !! field element
        real(dp), intent(in) :: ratio           !! gap / its length
        real(dp) :: c
        p = max(bx%degree, bz%degree)
        if (.not. kernel%homogeneous) return
        c = 1.0_dp + 2.0_dp*ratio
        if ((bx%x(e) - bx%x(e - 1))*(c + sqrt(c*c - 1.0_dp)) > bx%x(e) + bx%x(e - 1)) p = p + 1
    end function field_degree

    !> Make the work arrays hold n point pairs.
    pure subroutine reserve(work, n)
        type(work_t), intent(inout) :: work
        integer, intent(in) :: n
        integer :: cap
        if (allocated(work%x)) then
            if (size(work%x) >= n) return
            deallocate (work%x, work%xi, work%w, work%wc, work%dv, work%with_log, work%f, work%p)
        end if
        cap = max(n, 1024)
        allocate (work%x(cap), work%xi(cap), work%w(cap), work%wc(cap), work%dv(cap), &
                  work%with_log(cap), work%f(2, 2, cap), work%p(2, 2, cap))
    end subroutine reserve

    !> loc(r, c) = int int g_r(x) W(x) K_{comp_f(r), comp_s(c)}(x, xi) g_c(xi) over e1 x e2.
    subroutine pair_integrals(kernel, bx, bz, e1, e2, map, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(in) :: map
        type(work_t), intent(inout) :: work
        real(dp), intent(out) :: loc(n_loc, n_loc)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: a1, b1, a2, b2, gap
        a1 = bx%x(e1 - 1)
        b1 = bx%x(e1)
        a2 = bx%x(e2 - 1)
        b2 = bx%x(e2)
        gap = max(a2 - b1, a1 - b2)
        if (gap >= near_ratio*max(b1 - a1, b2 - a2)) then
            call tensor_pair(kernel, bx, bz, e1, e2, a1, b1, a2, b2, &
                             far_points(gap/(b1 - a1), &
                                        field_degree(kernel, bx, bz, e1, gap/(b1 - a1))), &
                             far_points(gap/(b2 - a2), max(bx%degree, bz%degree)), &
                             map, work, loc, err)
        else if (reducible(kernel)) then
            call reduced_pair(kernel, bx, bz, e1, e2, map, work, loc, err)
        else
            call build_pair_rule(work%tab, a1, b1, a2, b2, kernel%log_length(max(a1, a2)), &
                                 kernel%homogeneous .and. e1 == e2 .and. &
                                 .not. kernel%log_length(a1) > 0.0_dp, work%rule, work%line)
            call rule_pair(kernel, bx, bz, e1, e2, map, work, loc, err)
        end if
    end subroutine pair_integrals

    !> Tensor GL rule n1 x n2 on a well separated pair: one kernel evaluation per point pair,
    !! contracted with all basis products, loc = B_f diag(w_f W) K diag(w_s) B_s^T.
    subroutine tensor_pair(kernel, bx, bz, e1, e2, a1, b1, a2, b2, n1, n2, map, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e1, e2, n1, n2
        real(dp), intent(in) :: a1, b1, a2, b2
        type(pair_map_t), intent(in) :: map
        type(work_t), intent(inout) :: work
        real(dp), intent(out) :: loc(n_loc, n_loc)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: xf(n1), xs(n2), bf(n_loc, n1), bs(n_loc, n2), tmp(2, n2)
        integer :: i, j, k, r, c
        call need_order(work%tab, n1)
        call need_order(work%tab, n2)
        if (.not. work%by_order(n1)%ready) call tabulate_order(bx, bz, n1, work)
        if (.not. work%by_order(n2)%ready) call tabulate_order(bx, bz, n2, work)
        xf = a1 + (b1 - a1)*work%tab%v(1:n1, n1)
        xs = a2 + (b2 - a2)*work%tab%v(1:n2, n2)
        field_weights: do i = 1, n1
            bf(:, i) = work%by_order(n1)%b(:, i, e1)* &
                       ((b1 - a1)*work%tab%w(i, n1)*kernel%field_weight(xf(i)))
        end do field_weights
        source_weights: do j = 1, n2
            bs(:, j) = work%by_order(n2)%b(:, j, e2)*((b2 - a2)*work%tab%w(j, n2))
        end do source_weights
        call reserve(work, n1*n2)
        field_points: do i = 1, n1
            work%x((i - 1)*n2 + 1:i*n2) = xf(i)
            work%xi((i - 1)*n2 + 1:i*n2) = xs
        end do field_points
        work%with_log(1:n1*n2) = .false.
        call kernel%values(work%x(1:n1*n2), work%xi(1:n1*n2), work%with_log(1:n1*n2), &
                           work%f(:, :, 1:n1*n2), work%p(:, :, 1:n1*n2), err)
        if (allocated(err)) return
        work%n_kernel = work%n_kernel + int(n1*n2, int64)
        loc = 0.0_dp
        rows: do r = 1, map%nf
            source_points: do j = 1, n2
                contract_field: do c = 1, 2
                    tmp(c, j) = 0.0_dp
                    do i = 1, n1
                        k = (i - 1)*n2 + j
                        tmp(c, j) = tmp(c, j) + bf(r, i)*work%f(map%comp_f(r), c, k)
                    end do
                end do contract_field
            end do source_points
            columns: do c = 1, map%ns
                loc(r, c) = dot_product(tmp(map%comp_s(c), 1:n2), bs(c, 1:n2))
            end do columns
        end do rows
    end subroutine tensor_pair

    !> b(r, i) = g_r(x_i) w_i (times W(x_i) on the field side) for the local functions of e;
    !! the functions are evaluated at the local coordinates loc_xi (exact for the GL nodes of
    !! tensor rules: a node x = a + h v rounds by eps |x|, i.e. by eps |x|/h of the element).
    pure subroutine weighted_basis(kernel, bx, bz, e, x, loc_xi, w, field, b)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e
        real(dp), intent(in) :: x(:)           !! points on element e
        real(dp), intent(in) :: loc_xi(:)      !! their local coordinates in [-1, 1]
        real(dp), intent(in) :: w(:)           !! their weights
        logical, intent(in) :: field           !! include the field measure W(x)
        real(dp), intent(out) :: b(:, :)       !! b(r, i), r over the bx then the bz functions
        integer :: idx(max_local), i
        real(dp) :: val(max_local), der(max_local), wi, x_out
        points: do i = 1, size(x)
            wi = w(i)
            if (field) wi = wi*kernel%field_weight(x(i))
            call eval_basis(bx, e, loc_xi(i), idx, val, der, x_out)
            b(1:bx%n_local, i) = val(1:bx%n_local)*wi
            call eval_basis(bz, e, loc_xi(i), idx, val, der, x_out)
            b(bx%n_local + 1:bx%n_local + bz%n_local, i) = val(1:bz%n_local)*wi
        end do points
    end subroutine weighted_basis

    !> Local coordinate of x on element e.
    pure real(dp) function local_coordinate(basis, e, x) result(xi)
        type(basis_t), intent(in) :: basis
        integer, intent(in) :: e
        real(dp), intent(in) :: x
        xi = (2.0_dp*x - (basis%x(e - 1) + basis%x(e)))/(basis%x(e) - basis%x(e - 1))
    end function local_coordinate

    !> Touching pair of a kernel that depends on one combination v of (x, xi) only: v = x - xi
    !! (translation invariant, strip) or v = x/xi (homogeneous of degree 0, rings; then
    !! ln|x - xi| = ln xi + ln|v - 1|). Product-log rule in v cut at the kinks of the range
    !! across it, ONE kernel evaluation per node of v, and the integral across v of the basis
    !! products exact by n_across GL points. A self pair integrates the triangle x < xi and
    !! adds the transpose (the other triangle, by reciprocity).
    subroutine reduced_pair(kernel, bx, bz, e1, e2, map, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(in) :: map
        type(work_t), intent(inout) :: work
        real(dp), intent(out) :: loc(n_loc, n_loc)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: cuts(5), u0, c(2, 2)
        integer :: n, k
        call reduced_cuts(kernel, bx, e1, e2, cuts, u0)
        call reduced_nodes(work, cuts, u0, n)
        if (kernel%homogeneous) then
            ! G(t xi, xi) = G(t, 1) = G(S t, S) with S = 1/|t - 1|: S t - S = +-1 exactly, so
            ! ln|r - s| keeps full relative precision next to t = 1 (1 - t itself rounds)
            work%xi(1:n) = 1.0_dp/abs(work%dv(1:n))
            work%x(1:n) = work%xi(1:n) + sign(1.0_dp, work%dv(1:n))
        else
            work%x(1:n) = work%dv(1:n)              ! k(x - xi) = k(u)
            work%xi(1:n) = 0.0_dp
        end if
        call kernel%values(work%x(1:n), work%xi(1:n), work%with_log(1:n), work%f(:, :, 1:n), &
                           work%p(:, :, 1:n), err)
        if (allocated(err)) return
        work%n_kernel = work%n_kernel + int(n, int64)
        loc = 0.0_dp
        v_nodes: do k = 1, n
            c = work%w(k)*work%f(:, :, k)
            if (work%with_log(k)) c = c + work%wc(k)*work%p(:, :, k)
            call add_across(kernel, bx, e1, e2, map, work%poly, work%tab, work%dv(k), c, loc)
        end do v_nodes
        if (e1 == e2) loc = loc + transpose(loc)
    end subroutine reduced_pair

    !> Range of v, its kinks and the log length, all as OFFSETS from the singular point (v - 1
    !! for v = x/xi, v - 0 for v = x - xi), formed from differences of node coordinates so that
    !! the range of an element pair keeps full relative precision; over e1 x e2 (e2 > e1) or
    !! over the triangle x < xi of a self pair; sorted, and clipped to [cuts(1), cuts(5)].
    pure subroutine reduced_cuts(kernel, bx, e1, e2, cuts, u0)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        integer, intent(in) :: e1, e2
        real(dp), intent(out) :: cuts(5), u0
        real(dp) :: a1, b1, a2, b2
        integer :: i
        a1 = bx%x(e1 - 1)
        b1 = bx%x(e1)
        a2 = bx%x(e2 - 1)
        b2 = bx%x(e2)
        if (kernel%homogeneous) then
            u0 = kernel%log_length(1.0_dp)
            if (e1 == e2) then
                cuts = [-(b1 - a1)/b1, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
            else
                cuts = [(a1 - b2)/b2, (a1 - a2)/a2, (b1 - b2)/b2, 0.0_dp, (b1 - a2)/a2]
            end if
        else
            u0 = kernel%log_length(max(a1, a2))
            if (e1 == e2) then
                cuts = [a1 - b1, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp]
            else
                cuts = [a1 - b2, a1 - a2, b1 - b2, 0.0_dp, b1 - a2]
            end if
        end if
        call sort_ascending(cuts)
        clip: do i = 2, 4
            cuts(i) = min(max(cuts(i), cuts(1)), cuts(5))
        end do clip
    end subroutine reduced_cuts

    !> Offsets of the nodes of v from the singular point (work%dv) with weights work%w,
    !! work%wc, and with_log, piece by piece.
    pure subroutine reduced_nodes(work, cuts, u0, n)
        type(work_t), intent(inout) :: work
        real(dp), intent(in) :: cuts(5), u0
        integer, intent(out) :: n
        type(line_rule_t) :: piece
        real(dp) :: tiny_len
        integer :: i, m
        tiny_len = 1.0e-14_dp*(cuts(5) - cuts(1))
        n = 0
        pieces: do i = 1, 4
            if (cuts(i + 1) - cuts(i) <= tiny_len) cycle pieces
            call build_line_rule(work%tab, cuts(i), cuts(i + 1), 0.0_dp, u0, piece)
            m = piece%n
            call reserve(work, n + m)
            work%w(n + 1:n + m) = piece%w(1:m)
            work%wc(n + 1:n + m) = piece%wc(1:m)
            work%dv(n + 1:n + m) = piece%d(1:m)
            n = n + m
        end do pieces
        work%with_log(1:n) = work%wc(1:n) /= 0.0_dp
    end subroutine reduced_nodes

    !> Add c(i, j) times the integral of the basis products across the reduced variable at one
    !! node, given as its offset d from the singular point; all positions as offsets from the
    !! element starts (full relative precision): translation, u = d, x - a1 in
    !! [max(0, a2 - a1 + u), min(h1, b2 - a1 + u)], xi - a2 = (x - a1) - (a2 - a1) - u;
    !! homogeneous, t = 1 + d, xi - a2 in [max(0, (a1 - a2 - a2 d)/t), min(h2, (b1 - a2 -
    !! a2 d)/t)], x - a1 = (a2 - a1) + a2 d + t (xi - a2), dx = xi dt.
    pure subroutine add_across(kernel, bx, e1, e2, map, poly, tab, d, c, loc)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx            !! (mesh)
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(in) :: map
        real(dp), intent(in) :: poly(:, :, :)      !! work%poly
        type(gauss_tables_t), intent(in) :: tab
        real(dp), intent(in) :: d, c(2, 2)
        real(dp), intent(inout) :: loc(n_loc, n_loc)
        real(dp) :: a1, a2, h1, h2, t, lo, hi, len, y, off1, off2, wj, l1, l2
        real(dp) :: bf(n_loc), bs(n_loc), cb(n_loc, n_loc)
        integer :: j, col
        a1 = bx%x(e1 - 1)
        a2 = bx%x(e2 - 1)
        h1 = bx%x(e1) - a1
        h2 = bx%x(e2) - a2
        t = 1.0_dp + d
        if (kernel%homogeneous) then
            lo = max(0.0_dp, ((a1 - a2) - a2*d)/t)
            hi = min(h2, ((bx%x(e1) - a2) - a2*d)/t)
        else
            lo = max(0.0_dp, (a2 - a1) + d)
            hi = min(h1, (bx%x(e2) - a1) + d)
        end if
        len = hi - lo
        if (len <= 0.0_dp) return
        couplings: do col = 1, map%ns
            cb(1:map%nf, col) = c(map%comp_f(1:map%nf), map%comp_s(col))
        end do couplings
        across: do j = 1, n_across
            y = lo + len*tab%v(j, n_across)
            if (kernel%homogeneous) then
                off2 = y
                off1 = (a2 - a1) + a2*d + t*y
                wj = len*tab%w(j, n_across)*(a2 + y)*kernel%field_weight(a1 + off1)
            else
                off1 = y
                off2 = y - (a2 - a1) - d
                wj = len*tab%w(j, n_across)*kernel%field_weight(a1 + off1)
            end if
            l1 = 2.0_dp*off1/h1 - 1.0_dp
            l2 = 2.0_dp*off2/h2 - 1.0_dp
            bf(1:map%nf) = wj*(poly(1, 1:map%nf, e1) + l1*(poly(2, 1:map%nf, e1) + &
                                                           l1*poly(3, 1:map%nf, e1)))
            bs(1:map%ns) = poly(1, 1:map%ns, e2) + l2*(poly(2, 1:map%ns, e2) + &
                                                       l2*poly(3, 1:map%ns, e2))
            columns: do col = 1, map%ns
                loc(1:map%nf, col) = loc(1:map%nf, col) + bf(1:map%nf)*cb(1:map%nf, col)*bs(col)
            end do columns
        end do across
    end subroutine add_across

    !> A general point rule (work%rule) on a touching pair: one kernel evaluation per point,
    !! F with weight w and the log coefficient P with weight wc, added to every basis product.
    subroutine rule_pair(kernel, bx, bz, e1, e2, map, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(in) :: map
        type(work_t), intent(inout) :: work
        real(dp), intent(out) :: loc(n_loc, n_loc)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: bf(n_loc, 1), bs(n_loc, 1), c(2, 2)
        integer :: k, n, r, col
        n = work%rule%n
        call reserve(work, n)
        work%with_log(1:n) = work%rule%wc(1:n) /= 0.0_dp
        call kernel%values(work%rule%x(1:n), work%rule%xi(1:n), work%with_log(1:n), &
                           work%f(:, :, 1:n), work%p(:, :, 1:n), err)
        if (allocated(err)) return
        work%n_kernel = work%n_kernel + int(n, int64)
        loc = 0.0_dp
        points: do k = 1, n
            call weighted_basis(kernel, bx, bz, e1, work%rule%x(k:k), &
                                [local_coordinate(bx, e1, work%rule%x(k))], [1.0_dp], .true., bf)
            call weighted_basis(kernel, bx, bz, e2, work%rule%xi(k:k), &
                                [local_coordinate(bx, e2, work%rule%xi(k))], [1.0_dp], .false., bs)
            c = work%rule%w(k)*work%f(:, :, k)
            if (work%with_log(k)) c = c + work%rule%wc(k)*work%p(:, :, k)
            columns: do col = 1, map%ns
                rows: do r = 1, map%nf
                    loc(r, col) = loc(r, col) + bf(r, 1)*c(map%comp_f(r), map%comp_s(col))* &
                                  bs(col, 1)
                end do rows
            end do columns
        end do points
    end subroutine rule_pair

    !> Accumulate A with T = A + A^T (add_transpose at the end): a pair e1 < e2 adds loc at
    !! (rows, columns), its mirror (e2, e1) being the transpose by reciprocity; a self pair adds
    !! half of its symmetric part (its rule is symmetric only up to rounding).
    pure subroutine scatter(map, self_pair, loc, t_mat)
        type(pair_map_t), intent(in) :: map
        logical, intent(in) :: self_pair
        real(dp), intent(in) :: loc(n_loc, n_loc)
        real(dp), intent(inout) :: t_mat(:, :)
        integer :: r, c
        if (self_pair) then
            self_columns: do c = 1, map%ns
                self_rows: do r = 1, map%nf
                    t_mat(map%row(r), map%col(c)) = t_mat(map%row(r), map%col(c)) + &
                                                    0.25_dp*(loc(r, c) + loc(c, r))
                end do self_rows
            end do self_columns
            return
        end if
        columns: do c = 1, map%ns
            rows: do r = 1, map%nf
                t_mat(map%row(r), map%col(c)) = t_mat(map%row(r), map%col(c)) + loc(r, c)
            end do rows
        end do columns
    end subroutine scatter

    !> A <- A + A^T in place, in square tiles (both halves of a tile pair stay in cache).
    pure subroutine add_transpose(a)
        real(dp), intent(inout) :: a(:, :)
        integer, parameter :: tile = 64
        integer :: n, ib, jb, i, j
        real(dp) :: total
        n = size(a, 1)
        tile_columns: do jb = 1, n, tile
            tile_rows: do ib = 1, jb, tile
                columns: do j = jb, min(jb + tile - 1, n)
                    rows: do i = ib, min(ib + tile - 1, j)
                        total = a(i, j) + a(j, i)
                        a(i, j) = total
                        a(j, i) = total
                    end do rows
                end do columns
            end do tile_rows
        end do tile_columns
    end subroutine add_transpose
end module galerkin_assembly
