!> Quadrature of the half-space surface kernels (logarithmic singularity, step discontinuity)
!! in 1-D Galerkin double integrals and in displacement (collocation) integrals, to full double
!! precision; and the Galerkin assembly / displacement evaluation shared by the BEAM and PLATE
!! operators.
!!
!! A kernel is handed over in split form (kernel reference §A.3, §B.3, §C.1): its value F and
!! the coefficient P of its logarithmic singularity,
!!     F(x, xi) = P(x, xi) ln|x - xi| + Q(x, xi),      P, Q analytic next to x = xi,
!! plus at most a jump across x = xi (coupling kernels A2/A4, B11, C2/C3). Every rule built here
!! is a list of points with two weights (w, wc) such that
!!     integral of F  ~=  sum_i ( w_i F_i + wc_i P_i ),
!! with wc_i = 0 away from the singularity, so that P is only evaluated next to it.
!!
!! Building blocks:
!!  * Gauss–Legendre (GL) pieces graded geometrically away from the singular point, each piece
!!    no longer than its distance from the singular point; the number of points follows from the
!!    Bernstein-ellipse parameter rho of that ratio (error ~ rho^(-2n), target 1e-17).
!!  * a product-integration rule on the GL nodes of [0,1] for ln(v) A(v): A is interpolated in
!!    shifted Legendre polynomials and integrated exactly with the moments
!!    int_0^1 P_j(2v-1) ln v dv = -1 (j = 0), (-1)^(j+1)/(j(j+1)) (j >= 1); exact for degree < n,
!!    spectrally convergent for analytic A.
!!  * element pairs that touch or nearly touch: relative coordinates u = x - xi (the square is cut
!!    along its diagonal and at the kinks of the inner range, so step kernels are integrated
!!    exactly too), product-log rule in u next to u = 0, inner GL in x;
!!  * the element at the origin of a kernel homogeneous of degree 0 about x = 0 (axisymmetric ring
!!    kernels, G(r, s) = F(s/r), nothing analytic at the corner (0,0)): ratio coordinates
!!    xi = x t and x = xi t on the two triangles, polynomial in the outer variable, product-log
!!    rule in t next to t = 1;
!!  * well separated pairs: tensor GL with the number of points set by distance/size.
!! The displacements at many points (`displacement_split_kernel`, the report stations) are in
!! the submodule station_displacement (file station_displacement.f90): far clusters of elements
!! by interpolating the kernel, the elements next to each point by `build_line_rule`;
!! `displacement_split_kernel_reference` (the line rule for every point and element) is kept
!! as the reference of its tests.
module singular_quadrature
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use sorting, only: sort_ascending
    use errors, only: error_t, new_error, add_context, EXIT_INTERNAL
    use quadrature, only: gauss_legendre
    use gauss_rule_tables, only: packed_nodes, packed_weights, packed_log_weights
    use shape_functions, only: basis_t, eval_basis, max_local
    implicit none
    private

    public :: split_kernel_t, gauss_tables_t, point_rule_t, line_rule_t
    public :: shared_gauss_tables, build_pair_rule, build_line_rule
    public :: assemble_split_kernel_reference, displacement_split_kernel
    public :: displacement_split_kernel_reference
    public :: check_bases, near_ratio, n_max, n_log, points_for_ratio, new_gauss_tables
    ! public because the submodule calls them: gfortran 12 does not emit a private module
    ! procedure that only a submodule (or an inlined call) uses, and the link fails
    public :: check_displacement_arguments, snapped_to_nodes

    integer, parameter :: n_max = 32        !! largest GL rule tabulated
    real(dp), parameter :: snap_ulps = 1024.0_dp  !! snapped_to_nodes: a point this close to a
                                                  !! node (in units of eps |x|) is the node
    integer, parameter :: n_log = 24        !! points of the product-log rule, at most
    integer, parameter :: n_log_min = 12    !! ... at least (log_points)
    real(dp), parameter :: log_digits = 20.0_dp  !! log10(1/error) of log_points (rho^-n)
    integer, parameter :: n_inner = 12      !! inner GL points of the pair rules
    real(dp), parameter :: target_digits = 8.5_dp  !! log10(1/error) per direction, error rho^-2n
    real(dp), parameter :: near_ratio = 0.5_dp     !! gap/size below which the pair rule is used

    !> A 2x2 surface kernel in split form. Index 1 = tangential (sigma_x, u), 2 = normal
    !! (sigma_z, w): f(i, j) = displacement i due to a unit traction j.
    type, abstract :: split_kernel_t
        logical :: homogeneous = .false.   !! homogeneous of degree 0 about x = 0 (ring kernels)
        logical :: translation_invariant = .false.  !! depends on x - xi only (strip kernels)
        !> The coupling kernels are constants for x < xi: F_12 = coupling(1), F_21 =
        !! coupling(2) there (the rings: steps at r = s). The far pairs of the fast assembly
        !! all have x < xi, so it integrates them in closed form and `grid_values` need fill
        !! only f(:, :, 1, 1) and f(:, :, 2, 2).
        logical :: constant_coupling = .false.
        real(dp) :: coupling(2) = 0.0_dp
        !> Measure of the field integral, linear: W(x) = measure(0) + measure(1) x (1 for the
        !! beam, 2 pi x for the plate), so that it can be formed on vectors.
        real(dp) :: measure(0:1) = [1.0_dp, 0.0_dp]
    contains
        procedure(kernel_values_i), deferred :: values
        procedure :: grid_values => split_grid_values
        procedure :: field_weight => split_field_weight
        procedure(log_length_i), deferred :: log_length
    end type split_kernel_t

    abstract interface
        !> F and P of the four kernels at the points (x(k), xi(k)); P only where with_log(k).
        subroutine kernel_values_i(self, x, xi, with_log, f, p, err)
            import :: split_kernel_t, dp, error_t
            class(split_kernel_t), intent(in) :: self
            real(dp), intent(in) :: x(:)           !! field points
            real(dp), intent(in) :: xi(:)          !! source points
            logical, intent(in) :: with_log(:)     !! P wanted at this point
            real(dp), intent(out) :: f(:, :, :)    !! f(i, j, k) kernel values
            real(dp), intent(out) :: p(:, :, :)    !! p(i, j, k) coefficient of ln|x - xi|
            type(error_t), allocatable, intent(out) :: err
        end subroutine kernel_values_i

        !> Longest distance from a singular point at x_sing over which the split (P, Q) stays
        !! analytic; 0 when the kernel is regular there.
        pure real(dp) function log_length_i(self, x_sing)
            import :: split_kernel_t, dp
            class(split_kernel_t), intent(in) :: self
            real(dp), intent(in) :: x_sing
        end function log_length_i
    end interface

    !> GL rules on [0, 1] for n = 1..n_max and the product-log weights of the rules of
    !! n <= n_log points.
    type :: gauss_tables_t
        real(dp) :: v(n_max, n_max) = 0.0_dp   !! v(i, n): node i of the n-point rule
        real(dp) :: w(n_max, n_max) = 0.0_dp   !! w(i, n): its weight
        real(dp) :: wq(n_log, n_log) = 0.0_dp  !! wq(i, n) = wl_i - w_i ln v_i (add_log_piece),
                                               !! int_0^1 A(v) ln v dv ~= sum wl_i A(v(i, n));
                                               !! tabulated: a log piece costs no logarithms
    end type gauss_tables_t

    !> Points of a double integral over (x, xi) with weights for F (w) and for P (wc).
    type :: point_rule_t
        integer :: n = 0
        real(dp), allocatable :: x(:), xi(:), w(:), wc(:)
    end type point_rule_t

    !> Points of a single integral over s with weights for F (w) and for P (wc); d = s - x0,
    !! the signed offset from the singular point, exact (s itself is rounded).
    type :: line_rule_t
        integer :: n = 0
        real(dp), allocatable :: s(:), w(:), wc(:), d(:)
    end type line_rule_t

    interface
        !> Surface displacements u (tangential) and w (normal) at the points x_eval produced by
        !! the tractions sigma_x = sum rx_b g_b, sigma_z = sum rz_b g_b:
        !! u_i(x) = int K_ij(x, s) sigma_j ds (submodule station_displacement).
        module subroutine displacement_split_kernel(kernel, bx, bz, rx, rz, x_eval, u, w, err)
            class(split_kernel_t), intent(in) :: kernel      !! the surface kernel in split form
            type(basis_t), intent(in) :: bx, bz   !! the bases of sigma_x and sigma_z
            real(dp), intent(in) :: rx(:)         !! sigma_x coefficients (bx)
            real(dp), intent(in) :: rz(:)         !! sigma_z coefficients (bz)
            real(dp), intent(in) :: x_eval(:)     !! evaluation points
            real(dp), intent(out) :: u(:)         !! tangential displacement
            real(dp), intent(out) :: w(:)         !! normal displacement (down positive)
            type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        end subroutine displacement_split_kernel
    end interface

contains

    !> Tabulate GL rules on [0, 1] and the product-log weights (see module header); the
    !! program takes its copies from shared_gauss_tables.
    pure subroutine new_gauss_tables(tab)
        type(gauss_tables_t), intent(out) :: tab   !! the rules, computed
        integer :: n
        rules: do n = 1, n_max
            call tabulate_order(tab, n)
        end do rules
    end subroutine new_gauss_tables

    !> A copy of all GL rules and product-log weights, unpacked from the constants of
    !! gauss_rule_tables: the numbers new_gauss_tables computes (station_displacement/
    !! embedded_gauss_tables_match), embedded because computing them took 0.2 ms a small case.
    pure subroutine shared_gauss_tables(tab)
        type(gauss_tables_t), intent(out) :: tab   !! the rules
        integer :: n, first
        rules: do n = 1, n_max
            first = n*(n - 1)/2
            tab%v(1:n, n) = packed_nodes(first + 1:first + n)
            tab%w(1:n, n) = packed_weights(first + 1:first + n)
            if (n <= n_log) tab%wq(1:n, n) = packed_log_weights(first + 1:first + n)
        end do rules
    end subroutine shared_gauss_tables

    !> Tabulate the n-point rule (and, for n <= n_log, its product-log weights).
    pure subroutine tabulate_order(tab, n)
        type(gauss_tables_t), intent(inout) :: tab
        integer, intent(in) :: n
        real(dp) :: xi(n_max), wt(n_max), leg(0:n_log - 1), mom(0:n_log - 1), wl
        integer :: i, j
        call gauss_legendre(n, xi(1:n), wt(1:n))
        tab%v(1:n, n) = 0.5_dp*(xi(1:n) + 1.0_dp)
        tab%w(1:n, n) = 0.5_dp*wt(1:n)
        if (n > n_log) return
        ! wl_i = w_i sum_j (2j + 1) P_j(v_i) int_0^1 P_j ln v dv (interpolatory: exact for A of
        ! degree < n), int_0^1 P_j(2v - 1) ln v dv = -1 (j = 0), (-1)^(j+1)/(j (j + 1))
        mom(0) = -1.0_dp
        moments: do j = 1, n - 1
            mom(j) = real((-1)**(j + 1), dp)/real(j*(j + 1), dp)
        end do moments
        nodes: do i = 1, n
            call shifted_legendre(n - 1, tab%v(i, n), leg(0:n - 1))
            wl = 0.0_dp
            do j = 0, n - 1
                wl = wl + real(2*j + 1, dp)*leg(j)*mom(j)
            end do
            tab%wq(i, n) = wl*tab%w(i, n) - tab%w(i, n)*log(tab%v(i, n))
        end do nodes
    end subroutine tabulate_order

    !> P_j(2v - 1), j = 0..n, by the three-term recurrence.
    pure subroutine shifted_legendre(n, v, leg)
        integer, intent(in) :: n
        real(dp), intent(in) :: v
        real(dp), intent(out) :: leg(0:n)
        real(dp) :: y
        integer :: j
        y = 2.0_dp*v - 1.0_dp
        leg(0) = 1.0_dp
        if (n >= 1) leg(1) = y
        recurrence: do j = 2, n
            leg(j) = (real(2*j - 1, dp)*y*leg(j - 1) - real(j - 1, dp)*leg(j - 2))/real(j, dp)
        end do recurrence
    end subroutine shifted_legendre

    !> GL points for a piece whose distance from the nearest singularity is `ratio` times its
    !! length: rho = 1 + 2 ratio + sqrt((1 + 2 ratio)^2 - 1), n = target_digits / log10(rho).
    pure integer function points_for_ratio(ratio) result(n)
        real(dp), intent(in) :: ratio   !! distance / length of the piece
        real(dp) :: c, rho
        c = 1.0_dp + 2.0_dp*max(ratio, 0.0_dp)
        rho = c + sqrt(c*c - 1.0_dp)
        if (rho <= 1.0_dp + 1.0e-3_dp) then
            n = n_max
        else
            n = min(n_max, max(4, ceiling(target_digits/log10(rho))))
        end if
    end function points_for_ratio

    !> Points of the product-log rule of a log piece [0, len] whose split (P, Q) is analytic
    !! within u0 >= len of the singular point (log_length): the rule is interpolatory in P,
    !! error about rho^-n with rho the Bernstein ellipse of [0, len] through u = -u0. The
    !! rings' nearest singularity is at 2 u0 (a larger rho); the strip's at i u0, where rho is
    !! up to a fifth smaller for the pieces that get fewer than n_log points (u0/len > 1.2),
    !! within the margin of log_digits. n_log points for a piece of the whole length u0 (the
    !! rule of before), fewer for the short pieces of small elements away from the axis.
    !! log_digits and the floor n_log_min cover the growth of P's coefficients with the pole
    !! order of the across integrals (module galerkin_assembly) and were set by comparing T
    !! with the n_log rule everywhere (output/bench/assembly_before_after.md, sixth step: at
    !! most 4.3e-16 of the largest entry, plate and beam).
    pure integer function log_points(ratio) result(n)
        real(dp), intent(in) :: ratio          !! u0 / len >= 1
        real(dp) :: c, rho
        c = 1.0_dp + 2.0_dp*ratio
        rho = c + sqrt(c*c - 1.0_dp)
        n = min(n_log, max(n_log_min, ceiling(log_digits/log10(rho))))
    end function log_points

    !> Measure of the field integral W(x) (split_kernel_t%measure).
    pure real(dp) function split_field_weight(self, x)
        class(split_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x
        split_field_weight = self%measure(0) + self%measure(1)*x
    end function split_field_weight

    !> Kernel values F (no log split) on the grid of field points x(k) and source points s(l)
    !! of a well separated element pair (no x(k) = s(l)): f(k, l, i, j) = F_ij(x(k), s(l)).
    !! This default calls `values` once per source point; a kernel overrides it where a grid
    !! can be evaluated faster (the ring kernels: on vectors of field points; with
    !! constant_coupling only the diagonal components f(:, :, i, i)).
    subroutine split_grid_values(self, x, s, f, err)
        class(split_kernel_t), intent(in) :: self
        real(dp), intent(in) :: x(:)               !! field points
        real(dp), intent(in) :: s(:)               !! source points
        real(dp), intent(out) :: f(:, :, :, :)     !! f(k, l, i, j)
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: part = 32            ! fixed size: no heap arrays per call
        real(dp) :: f_point(2, 2, part), p_point(2, 2, part), s_rep(part)
        logical :: with_log(part)
        integer :: l, i, j, k0, n
        with_log = .false.
        sources: do l = 1, size(s)
            s_rep = s(l)
            parts: do k0 = 1, size(x), part
                n = min(size(x) - k0 + 1, part)
                call self%values(x(k0:k0 + n - 1), s_rep(1:n), with_log(1:n), &
                                 f_point(:, :, 1:n), p_point(:, :, 1:n), err)
                if (allocated(err)) return
                components: do j = 1, 2
                    do i = 1, 2
                        f(k0:k0 + n - 1, l, i, j) = f_point(i, j, 1:n)
                    end do
                end do components
            end do parts
        end do sources
    end subroutine split_grid_values

    ! ---------------------------------------------------------------- one-dimensional rules

    !> Rule for int_a^b F(s) ds with F = P ln|s - x0| + Q: log pieces of length <= u0 next to
    !! x0 (u0 <= 0: F regular at x0), GL pieces graded geometrically away from x0 elsewhere,
    !! each with the points its distance from x0 asks, or from x_pole if that is nearer (a
    !! pole of F outside [a, b]).
    pure subroutine build_line_rule(tab, a, b, x0, u0, line, x_pole)
        type(gauss_tables_t), intent(in) :: tab    !! the GL rules and product-log weights
        real(dp), intent(in) :: a, b          !! interval, a < b
        real(dp), intent(in) :: x0            !! singular point (anywhere)
        real(dp), intent(in) :: u0            !! longest log piece
        type(line_rule_t), intent(inout) :: line   !! the rule, filled
        real(dp), intent(in), optional :: x_pole  !! another singular point, outside [a, b]
        real(dp) :: pole
        pole = huge(1.0_dp)
        if (present(x_pole)) pole = x_pole
        line%n = 0
        if (x0 <= a) then
            call add_ray(tab, x0, 1.0_dp, a - x0, b - x0, u0, line, pole - x0)
        else if (x0 >= b) then
            call add_ray(tab, x0, -1.0_dp, x0 - b, x0 - a, u0, line, x0 - pole)
        else
            call add_ray(tab, x0, -1.0_dp, 0.0_dp, x0 - a, u0, line, x0 - pole)
            call add_ray(tab, x0, 1.0_dp, 0.0_dp, b - x0, u0, line, pole - x0)
        end if
    end subroutine build_line_rule

    !> Append the rule for s = x0 + dir u, u in [d_start, d_end], singular at u = 0 and, if
    !! given, at u = u_pole (outside the ray).
    pure subroutine add_ray(tab, x0, dir, d_start, d_end, u0, line, u_pole)
        type(gauss_tables_t), intent(in) :: tab
        real(dp), intent(in) :: x0, dir, d_start, d_end, u0
        type(line_rule_t), intent(inout) :: line
        real(dp), intent(in), optional :: u_pole
        real(dp) :: lo, hi, pole, ratio
        if (.not. d_end > d_start) return
        ! a ray shorter than the rounding of x0 holds no point distinct from x0; its share of
        ! the integral, O(d_end ln d_end), is below the rounding of the result
        if (d_end <= 8.0_dp*epsilon(1.0_dp)*abs(x0)) return
        ! a pole on the other side of x0 is farther than x0 from every piece
        pole = huge(1.0_dp)
        if (present(u_pole)) then
            if (u_pole > 0.0_dp) pole = u_pole
        end if
        lo = d_start
        if (lo <= 8.0_dp*epsilon(1.0_dp)*max(abs(x0), d_end)) then
            ! the piece touches the singular point (up to rounding of the node coordinates)
            if (u0 <= 0.0_dp) then
                ! ratio min(1, (pole - d_end)/d_end), without dividing huge(1.0) by d_end < 1
                ratio = 1.0_dp
                if (pole - d_end < d_end) ratio = (pole - d_end)/d_end
                call add_gauss_piece(tab, x0, dir, 0.0_dp, d_end, points_for_ratio(ratio), line)
                return
            end if
            hi = min(u0, d_end)
            call add_log_piece(tab, x0, dir, hi, u0, line)
            lo = hi
        end if
        geometric: do while (lo < d_end)
            hi = 2.0_dp*lo
            if (d_end <= 2.5_dp*lo) hi = d_end
            call add_gauss_piece(tab, x0, dir, lo, hi, &
                                 points_for_ratio(min(lo, pole - hi)/(hi - lo)), line)
            lo = hi
        end do geometric
    end subroutine add_ray

    !> Product-log piece u in [0, len]:
    !! int_0^len (P ln u + Q) du = sum len w_i F_i + len (wl_i - w_i ln v_i) P_i (tab%wq), n
    !! points from the distance u0 over which the split is analytic (log_points).
    pure subroutine add_log_piece(tab, x0, dir, len, u0, line)
        type(gauss_tables_t), intent(in) :: tab
        real(dp), intent(in) :: x0, dir, len, u0
        type(line_rule_t), intent(inout) :: line
        integer :: i, n
        n = log_points(u0/len)
        nodes: do i = 1, n
            call push_line(line, x0, dir*len*tab%v(i, n), len*tab%w(i, n), len*tab%wq(i, n))
        end do nodes
    end subroutine add_log_piece

    !> Plain n-point GL piece u in [lo, hi].
    pure subroutine add_gauss_piece(tab, x0, dir, lo, hi, n, line)
        type(gauss_tables_t), intent(in) :: tab
        real(dp), intent(in) :: x0, dir, lo, hi
        integer, intent(in) :: n
        type(line_rule_t), intent(inout) :: line
        integer :: i
        nodes: do i = 1, n
            call push_line(line, x0, dir*(lo + (hi - lo)*tab%v(i, n)), (hi - lo)*tab%w(i, n), &
                           0.0_dp)
        end do nodes
    end subroutine add_gauss_piece

    pure subroutine push_line(line, x0, offset, w, wc)
        type(line_rule_t), intent(inout) :: line
        real(dp), intent(in) :: x0, offset, w, wc
        call room_for_one(line%n, 256, line%s, line%w, line%wc, line%d)
        line%n = line%n + 1
        line%s(line%n) = x0 + offset
        line%d(line%n) = offset
        line%w(line%n) = w
        line%wc(line%n) = wc
    end subroutine push_line

    !> Room for one more entry in four parallel vectors holding n: first `initial` entries,
    !! then twice as many whenever they are full.
    pure subroutine room_for_one(n, initial, v1, v2, v3, v4)
        integer, intent(in) :: n                 !! entries held
        integer, intent(in) :: initial           !! first capacity
        real(dp), allocatable, intent(inout) :: v1(:), v2(:), v3(:), v4(:)
        integer :: cap
        if (.not. allocated(v1)) then
            allocate (v1(initial), v2(initial), v3(initial), v4(initial))
        else if (n == size(v1)) then
            cap = 2*size(v1)
            call grow_vector(v1, cap)
            call grow_vector(v2, cap)
            call grow_vector(v3, cap)
            call grow_vector(v4, cap)
        end if
    end subroutine room_for_one

    !> Enlarge an array to `cap` entries, keeping its contents.
    pure subroutine grow_vector(v, cap)
        real(dp), allocatable, intent(inout) :: v(:)
        integer, intent(in) :: cap
        real(dp), allocatable :: tmp(:)
        allocate (tmp(cap))
        tmp(1:size(v)) = v
        call move_alloc(tmp, v)
    end subroutine grow_vector

    pure subroutine push_point(rule, x, xi, w, wc)
        type(point_rule_t), intent(inout) :: rule
        real(dp), intent(in) :: x, xi, w, wc
        call room_for_one(rule%n, 1024, rule%x, rule%xi, rule%w, rule%wc)
        rule%n = rule%n + 1
        rule%x(rule%n) = x
        rule%xi(rule%n) = xi
        rule%w(rule%n) = w
        rule%wc(rule%n) = wc
    end subroutine push_point

    ! ---------------------------------------------------------------- element-pair rules

    !> Rule for int_{a1}^{b1} int_{a2}^{b2} F(x, xi) dxi dx (x field, xi source).
    !! u0: longest log piece next to the diagonal; ratio_rule: use ratio coordinates (coincident
    !! elements at the origin of a kernel homogeneous of degree 0).
    pure subroutine build_pair_rule(tab, a1, b1, a2, b2, u0, ratio_rule, rule, line)
        type(gauss_tables_t), intent(in) :: tab     !! the GL rules and product-log weights
        real(dp), intent(in) :: a1, b1          !! field element
        real(dp), intent(in) :: a2, b2          !! source element
        real(dp), intent(in) :: u0              !! longest log piece
        logical, intent(in) :: ratio_rule       !! ratio coordinates (see module header)
        type(point_rule_t), intent(inout) :: rule   !! the rule, filled
        type(line_rule_t), intent(inout) :: line   !! work space
        real(dp) :: gap
        rule%n = 0
        gap = max(a2 - b1, a1 - b2)
        if (gap >= near_ratio*max(b1 - a1, b2 - a2)) then
            call add_tensor(tab, a1, b1, a2, b2, points_for_ratio(gap/(b1 - a1)), &
                            points_for_ratio(gap/(b2 - a2)), rule)
        else if (ratio_rule) then
            call add_ratio(tab, b1, rule, line)
        else
            call add_relative(tab, a1, b1, a2, b2, u0, rule, line)
        end if
    end subroutine build_pair_rule

    pure subroutine add_tensor(tab, a1, b1, a2, b2, n1, n2, rule)
        type(gauss_tables_t), intent(in) :: tab
        real(dp), intent(in) :: a1, b1, a2, b2
        integer, intent(in) :: n1, n2
        type(point_rule_t), intent(inout) :: rule
        integer :: i, j
        field: do i = 1, n1
            source: do j = 1, n2
                call push_point(rule, a1 + (b1 - a1)*tab%v(i, n1), a2 + (b2 - a2)*tab%v(j, n2), &
                                (b1 - a1)*tab%w(i, n1)*(b2 - a2)*tab%w(j, n2), 0.0_dp)
            end do source
        end do field
    end subroutine add_tensor

    !> Relative coordinates u = x - xi over pieces of u between the kinks of the inner range
    !! x in [max(a1, a2 + u), min(b1, b2 + u)] and the diagonal u = 0.
    pure subroutine add_relative(tab, a1, b1, a2, b2, u0, rule, line)
        type(gauss_tables_t), intent(in) :: tab
        real(dp), intent(in) :: a1, b1, a2, b2, u0
        type(point_rule_t), intent(inout) :: rule
        type(line_rule_t), intent(inout) :: line
        real(dp) :: cuts(5), tiny_len, lo, hi, x_lo, x_hi, len, x
        integer :: n_cut, i, k, j
        tiny_len = 1.0e-14_dp*((b1 - a1) + (b2 - a2))
        cuts = [a1 - b2, a1 - a2, b1 - b2, 0.0_dp, b1 - a2]
        call sort_ascending(cuts)
        n_cut = 5
        pieces: do i = 1, n_cut - 1
            lo = max(cuts(i), a1 - b2)
            hi = min(cuts(i + 1), b1 - a2)
            if (hi - lo <= tiny_len) cycle pieces
            line%n = 0
            if (lo >= 0.0_dp) then
                call add_ray(tab, 0.0_dp, 1.0_dp, lo, hi, u0, line)
            else
                call add_ray(tab, 0.0_dp, -1.0_dp, -hi, -lo, u0, line)
            end if
            u_nodes: do k = 1, line%n
                x_lo = max(a1, a2 + line%s(k))
                x_hi = min(b1, b2 + line%s(k))
                len = x_hi - x_lo
                if (len <= 0.0_dp) cycle u_nodes
                x_nodes: do j = 1, n_inner
                    x = x_lo + len*tab%v(j, n_inner)
                    call push_point(rule, x, x - line%s(k), line%w(k)*len*tab%w(j, n_inner), &
                                    line%wc(k)*len*tab%w(j, n_inner))
                end do x_nodes
            end do u_nodes
        end do pieces
    end subroutine add_relative

    !> Ratio coordinates on [0, h]^2: xi = x t (xi < x) and x = xi t (x < xi), t in [0, 1],
    !! ln|x - xi| = ln(outer) + ln(1 - t); product-log rule next to t = 1.
    pure subroutine add_ratio(tab, h, rule, line)
        type(gauss_tables_t), intent(in) :: tab
        real(dp), intent(in) :: h
        type(point_rule_t), intent(inout) :: rule
        type(line_rule_t), intent(inout) :: line
        real(dp) :: outer, w_outer
        integer :: i, k
        call build_line_rule(tab, 0.0_dp, 1.0_dp, 1.0_dp, 0.5_dp, line)
        outer_nodes: do i = 1, n_inner
            outer = h*tab%v(i, n_inner)
            w_outer = h*tab%w(i, n_inner)*outer
            t_nodes: do k = 1, line%n
                call push_point(rule, outer, outer*line%s(k), w_outer*line%w(k), &
                                w_outer*line%wc(k))
                call push_point(rule, outer*line%s(k), outer, w_outer*line%w(k), &
                                w_outer*line%wc(k))
            end do t_nodes
        end do outer_nodes
    end subroutine add_ratio

    ! ---------------------------------------------------------------- assembly and evaluation

    !> Check that the two bases live on the same mesh.
    pure subroutine check_bases(bx, bz, err)
        type(basis_t), intent(in) :: bx, bz              !! the bases of sigma_x and sigma_z
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        if (.not. (allocated(bx%x) .and. allocated(bz%x))) then
            call new_error(err, EXIT_INTERNAL, 'traction bases are not built')
        else if (bx%ne < 1 .or. bx%ne /= bz%ne) then
            call new_error(err, EXIT_INTERNAL, 'traction bases have different meshes')
        else if (any(bx%x /= bz%x)) then
            call new_error(err, EXIT_INTERNAL, 'traction bases have different meshes')
        else if (bx%n_local > max_local .or. bz%n_local > max_local) then
            call new_error(err, EXIT_INTERNAL, 'traction basis with too many local functions')
        end if
    end subroutine check_bases

    !> The evaluation points, each within snap_ulps of a node moved onto it. On a ray that
    !! short the log rule's points round to the point itself, where the split kernel is
    !! singular: a station at a load position a few ulps off its LOADS node stopped the plate
    !! (elliptic integral at m1 = 0) and gave Inf for the beam. The move, 1e-13 of the
    !! coordinate, is below the precision of any input position.
    pure function snapped_to_nodes(nodes, x_eval) result(x)
        real(dp), intent(in) :: nodes(0:)      !! mesh nodes, increasing
        real(dp), intent(in) :: x_eval(:)      !! evaluation points
        real(dp) :: x(size(x_eval))
        integer :: i, lo, hi, mid, ne
        real(dp) :: tol
        x = x_eval
        ne = ubound(nodes, 1)
        tol = snap_ulps*epsilon(1.0_dp)*max(abs(nodes(0)), abs(nodes(ne)), nodes(ne) - nodes(0))
        points: do i = 1, size(x)
            ! the last node at or left of x(i) (bisection), then the nearer of it and the next
            lo = 0
            hi = ne
            bisection: do while (hi - lo > 1)
                mid = (lo + hi)/2
                if (nodes(mid) <= x(i)) then
                    lo = mid
                else
                    hi = mid
                end if
            end do bisection
            if (abs(nodes(lo) - x(i)) <= tol) then
                x(i) = nodes(lo)
            else if (abs(nodes(hi) - x(i)) <= tol) then
                x(i) = nodes(hi)
            end if
        end do points
    end function snapped_to_nodes

    !> The bases of a surface-displacement call agree, and its arrays have their sizes
    !! (coefficients of each basis; u and w one per evaluation point).
    pure subroutine check_displacement_arguments(bx, bz, nrx, nrz, n_eval, nu, nw, err)
        type(basis_t), intent(in) :: bx, bz               !! the bases of sigma_x and sigma_z
        integer, intent(in) :: nrx, nrz, n_eval, nu, nw   !! the sizes of rx, rz, x_eval, u and w
        type(error_t), allocatable, intent(out) :: err    !! allocated on failure
        call check_bases(bx, bz, err)
        if (allocated(err)) return
        if (nrx /= bx%n_dof .or. nrz /= bz%n_dof .or. nu /= n_eval .or. nw /= n_eval) &
            call new_error(err, EXIT_INTERNAL, 'surface displacement: array sizes do not match')
    end subroutine check_displacement_arguments

    !> T_ab = int int g_a(x) W(x) K(x, xi) g_b(xi) dxi dx, blocks [T_xx T_xz; T_zx T_zz] with all
    !! bx coefficients first. Both triangles are integrated (no symmetrisation). Reference
    !! assembly: a rule built point by point for every element pair (graded pieces, GL orders
    !! for 1e-17 per direction); `galerkin_assembly` is the fast one used by the program.
    subroutine assemble_split_kernel_reference(kernel, bx, bz, t_mat, err, n_kernel)
        class(split_kernel_t), intent(in) :: kernel         !! the surface kernel in split form
        type(basis_t), intent(in) :: bx            !! basis of sigma_x
        type(basis_t), intent(in) :: bz            !! basis of sigma_z
        real(dp), allocatable, intent(out) :: t_mat(:, :)   !! T (nr x nr)
        type(error_t), allocatable, intent(out) :: err      !! allocated on failure
        integer(int64), intent(out), optional :: n_kernel   !! kernel evaluations (point pairs)
        type(gauss_tables_t) :: tab
        type(point_rule_t) :: rule
        type(line_rule_t) :: line
        real(dp), allocatable :: f(:, :, :), p(:, :, :)
        real(dp) :: a1, b1, a2, b2
        integer :: e1, e2, nx, nz
        character(len=60) :: where

        if (present(n_kernel)) n_kernel = 0_int64
        call check_bases(bx, bz, err)
        if (allocated(err)) return
        nx = bx%n_dof
        nz = bz%n_dof
        allocate (t_mat(nx + nz, nx + nz), source=0.0_dp)
        call new_gauss_tables(tab)
        field_elements: do e1 = 1, bx%ne
            a1 = bx%x(e1 - 1)
            b1 = bx%x(e1)
            source_elements: do e2 = 1, bx%ne
                a2 = bx%x(e2 - 1)
                b2 = bx%x(e2)
                call build_pair_rule(tab, a1, b1, a2, b2, kernel%log_length(max(a1, a2)), &
                                     kernel%homogeneous .and. e1 == e2 .and. &
                                     .not. kernel%log_length(a1) > 0.0_dp, rule, line)
                call grow(f, p, rule%n)
                if (present(n_kernel)) n_kernel = n_kernel + int(rule%n, int64)
                call kernel%values(rule%x(1:rule%n), rule%xi(1:rule%n), &
                                   rule%wc(1:rule%n) /= 0.0_dp, f, p, err)
                if (allocated(err)) then
                    write (where, '("half-space operator, elements ",i0," and ",i0)') e1, e2
                    call add_context(err, trim(where))
                    return
                end if
                call add_pair(kernel, bx, bz, e1, e2, rule, f, p, t_mat)
            end do source_elements
        end do field_elements
    end subroutine assemble_split_kernel_reference

    !> Make sure the kernel work arrays hold n points.
    pure subroutine grow(f, p, n)
        real(dp), allocatable, intent(inout) :: f(:, :, :), p(:, :, :)
        integer, intent(in) :: n
        if (allocated(f)) then
            if (size(f, 3) >= n) return
            deallocate (f, p)
        end if
        allocate (f(2, 2, max(n, 256)), p(2, 2, max(n, 256)))
    end subroutine grow

    !> Add the contribution of one element pair.
    pure subroutine add_pair(kernel, bx, bz, e1, e2, rule, f, p, t_mat)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e1, e2
        type(point_rule_t), intent(in) :: rule
        real(dp), intent(in) :: f(:, :, :), p(:, :, :)
        real(dp), intent(inout) :: t_mat(:, :)
        integer :: idx_f(max_local, 2), idx_s(max_local, 2), nl(2), off(2), k, i, j, a, b
        real(dp) :: val_f(max_local, 2), val_s(max_local, 2), c(2, 2), wx
        nl = [bx%n_local, bz%n_local]
        off = [0, bx%n_dof]
        points: do k = 1, rule%n
            ! tensor rules repeat the field point: evaluate its functions once
            if (k == 1 .or. rule%x(k) /= rule%x(max(k - 1, 1))) then
                call basis_at(bx, e1, rule%x(k), idx_f(:, 1), val_f(:, 1))
                call basis_at(bz, e1, rule%x(k), idx_f(:, 2), val_f(:, 2))
                wx = kernel%field_weight(rule%x(k))
            end if
            call basis_at(bx, e2, rule%xi(k), idx_s(:, 1), val_s(:, 1))
            call basis_at(bz, e2, rule%xi(k), idx_s(:, 2), val_s(:, 2))
            c = wx*(rule%w(k)*f(:, :, k))
            if (rule%wc(k) /= 0.0_dp) c = c + wx*rule%wc(k)*p(:, :, k)
            blocks_i: do i = 1, 2
                blocks_j: do j = 1, 2
                    rows: do a = 1, nl(i)
                        cols: do b = 1, nl(j)
                            t_mat(off(i) + idx_f(a, i), off(j) + idx_s(b, j)) = &
                                t_mat(off(i) + idx_f(a, i), off(j) + idx_s(b, j)) + &
                                val_f(a, i)*c(i, j)*val_s(b, j)
                        end do cols
                    end do rows
                end do blocks_j
            end do blocks_i
        end do points
    end subroutine add_pair

    !> Basis functions of element e at the physical point x.
    pure subroutine basis_at(basis, e, x, idx, val)
        type(basis_t), intent(in) :: basis
        integer, intent(in) :: e
        real(dp), intent(in) :: x
        integer, intent(out) :: idx(max_local)
        real(dp), intent(out) :: val(max_local)
        real(dp) :: der(max_local), x_out, xi
        xi = (2.0_dp*x - (basis%x(e - 1) + basis%x(e)))/(basis%x(e) - basis%x(e - 1))
        call eval_basis(basis, e, xi, idx, val, der, x_out)
    end subroutine basis_at

    !> Surface displacements u (tangential) and w (normal) at the points x_eval produced by the
    !! tractions sigma_x = sum rx_b g_b, sigma_z = sum rz_b g_b: u_i(x) = int K_ij(x, s) sigma_j ds.
    !! Reference evaluation: the line rule of `build_line_rule` for every (point, element) pair,
    !! the kernel called once per pair; `displacement_split_kernel` (submodule
    !! station_displacement) is the fast one used by the program, checked against this one.
    subroutine displacement_split_kernel_reference(kernel, bx, bz, rx, rz, x_eval, u, w, err)
        class(split_kernel_t), intent(in) :: kernel      !! the surface kernel in split form
        type(basis_t), intent(in) :: bx, bz   !! the bases of sigma_x and sigma_z
        real(dp), intent(in) :: rx(:)         !! sigma_x coefficients (bx)
        real(dp), intent(in) :: rz(:)         !! sigma_z coefficients (bz)
        real(dp), intent(in) :: x_eval(:)     !! evaluation points
        real(dp), intent(out) :: u(:)         !! tangential displacement
        real(dp), intent(out) :: w(:)         !! normal displacement (down positive)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        type(gauss_tables_t) :: tab
        type(line_rule_t) :: line
        real(dp), allocatable :: f(:, :, :), p(:, :, :), x_rep(:), x0(:)
        integer :: i, e
        character(len=60) :: where

        call check_displacement_arguments(bx, bz, size(rx), size(rz), size(x_eval), size(u), &
                                          size(w), err)
        if (allocated(err)) return
        call new_gauss_tables(tab)
        u = 0.0_dp
        w = 0.0_dp
        x0 = snapped_to_nodes(bx%x, x_eval)
        points: do i = 1, size(x_eval)
            elements: do e = 1, bx%ne
                call build_line_rule(tab, bx%x(e - 1), bx%x(e), x0(i), &
                                     kernel%log_length(x0(i)), line)
                call grow(f, p, line%n)
                if (allocated(x_rep)) deallocate (x_rep)
                allocate (x_rep(line%n), source=x0(i))
                call kernel%values(x_rep, line%s(1:line%n), line%wc(1:line%n) /= 0.0_dp, f, p, err)
                if (allocated(err)) then
                    write (where, '("surface displacement at point ",i0)') i
                    call add_context(err, trim(where))
                    return
                end if
                call add_line(bx, bz, rx, rz, e, line, f, p, u(i), w(i))
            end do elements
        end do points
    end subroutine displacement_split_kernel_reference

    !> Add one element's contribution to the displacements at one point.
    pure subroutine add_line(bx, bz, rx, rz, e, line, f, p, u, w)
        type(basis_t), intent(in) :: bx, bz
        real(dp), intent(in) :: rx(:), rz(:)
        integer, intent(in) :: e
        type(line_rule_t), intent(in) :: line
        real(dp), intent(in) :: f(:, :, :), p(:, :, :)
        real(dp), intent(inout) :: u, w
        integer :: idx(max_local), k
        real(dp) :: val(max_local), sig_x, sig_z, c(2, 2)
        points: do k = 1, line%n
            call basis_at(bx, e, line%s(k), idx, val)
            sig_x = sum(val(1:bx%n_local)*rx(idx(1:bx%n_local)))
            call basis_at(bz, e, line%s(k), idx, val)
            sig_z = sum(val(1:bz%n_local)*rz(idx(1:bz%n_local)))
            c = line%w(k)*f(:, :, k)
            if (line%wc(k) /= 0.0_dp) c = c + line%wc(k)*p(:, :, k)
            u = u + c(1, 1)*sig_x + c(1, 2)*sig_z
            w = w + c(2, 1)*sig_x + c(2, 2)*sig_z
        end do points
    end subroutine add_line
end module singular_quadrature
