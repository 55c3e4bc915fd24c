!> Galerkin assembly of the half-space flexibility T at the cost of its kernel evaluations.
!!
!! T_ab = int int g_a(x) W(x) K(x, xi) g_b(xi) dxi dx (W = 1 beam, 2 pi x plate), blocks
!! [T_xx T_xz; T_zx T_zz] with all bx coefficients first; K a kernel in split form
!! (`singular_quadrature`: value F and coefficient P of ln|x - xi|, steps at x = xi). Every
!! element pair is integrated with fixed-order rules and ONE kernel evaluation per point pair,
!! shared by all local basis products of the pair:
!!  * well separated pairs (gap >= near_ratio times the longer element): tensor Gauss–Legendre,
!!    n points per direction from the Bernstein-ellipse parameter of gap/size and the degree of
!!    the polynomial factor (`far_points`, 1e-13 per direction: T to round-off of its largest
!!    entry), contracted as L = B_f diag(w_f W) K diag(w_s) B_s^T. The far pairs of one source
!!    element that share its order are done together (`far_batch`): the kernel on the grid of
!!    all their field nodes x the source nodes in one call (`grid_values`, vectorised for the
!!    rings), then K diag(w_s) B_s^T for all field nodes at once, then B_f per pair. Coupling
!!    kernels that are constant on x < xi (the rings' steps; every far pair has x < xi) are not
!!    on the grid: their entries are the constant times the element moments of the functions;
!!  * touching and nearly touching pairs, kernels that depend on one variable v only (strip:
!!    v = x - xi; rings, homogeneous of degree 0: v = x/xi, ln|x - xi| = ln xi + ln|v - 1|):
!!    the logarithm is integrated analytically by the product-log rule of `singular_quadrature`
!!    (Legendre moments of ln, i.e. a log-weighted rule, the remainder P, Q analytic), pieces cut
!!    at the kinks of the range across v and at the steps, the kernel evaluated once per node of
!!    v, and the integral across v of the basis products done exactly (polynomial, GL of
!!    `across_points`), up to 64 nodes at once in vector loops (`add_across`); GL pieces of v
!!    graded by their distance to v = 1 and to the pole of the range across v at v = 0.
!!    All positions there are offsets from the singular point and from the element starts,
!!    formed from differences of node coordinates (1 - t or x - a rounded from absolute
!!    positions would cost eps |x|/h, 1e-13 at N_e = 1000);
!!  * other kernels: the two-dimensional pair rules of `singular_quadrature`.
!! Interpolated blocks (ring kernels, N_e >= min_blocks; doc/METHOD.md, Assembly of the
!! half-space flexibility T): the elements are
!! grouped in a binary tree of clusters (contiguous elements halved by count down to leaf_max)
!! and a pair of clusters X left of Y with gap >= block_ratio times the longer, whose
!! interpolation needs fewer than block_cost kernel values per element pair, is one block: the
!! kernel interpolated in both variables at the Chebyshev points of X and Y (orders 12 to 28
!! per direction from gap / length, for rho^-p <= 1e-16 as in station_displacement; the
!! Bernstein ellipse of either cluster stays clear of the circle |x| = xi of the other's
!! points), K(x, xi) ~ sum_ab l_a(x) K(x_a, xi_b) l_b(xi), so that its part of T is
!! Mx K My^T for the diagonal components (BLAS dgemm), Mx(f, a) = int g_f W l_a over the part of
!! the support of f in X, My(f, b) = int g_f l_b over the part in Y (from the Chebyshev moments
!! of the cluster, exact GL), and the constant coupling components F_ij (int g W)(int g). The
!! element pairs of a block are skipped by the column pass, so every pair is added once; the
!! blocks are added one after the other after the column pass (T the same on any number of
!! threads). The kernel values fall by 3 to 9 times at N_e 200 to 1000; T
!! moves by 1e-15 to 3.2e-15 of its largest entry (pairwise = .true.: no blocks, the assembly
!! of fc09087, output/bench/assembly_before_after.md). Below min_blocks elements the blocks
!! do not pay (most pairs are near or nearly near). The blocks start at N_e = 50, with leaves
!! of up to 6 elements and up to 24 kernel values per element pair (doc/METHOD.md, "T share"
!! step; doc/CHOICES.md, Assembly of T), and the Chebyshev moments of a leaf form T_q at
!! its GL nodes once per element and a function repeating another (bx and bz of one family)
!! once (`leaf_moments`): T 10 to 25 % faster at N_e = 50 to 128 (1.8e-15 of its largest
!! entry from the pairwise T), 5 % at 200, the same at 500 and 1000 (the same blocks there).
!! A translation-invariant kernel on a (piecewise) uniform mesh repeats the pair integrals of
!! the translated pair (`translates`): O(N_e) pairs are integrated, the rest copied, column
!! after column. Otherwise the columns (source elements) are integrated in parallel (OpenMP,
!! one work per thread), in colours of columns that share no function (`column_stride`), each
!! column added to T by the thread that integrated it: T does not depend on the number of
!! threads, bit for bit. No reuse by homogeneity: a pair integral scales by lambda^3 with both
!! elements, but on a uniform mesh no two element pairs are similar.
!! Only pairs e2 >= e1 are integrated; the pair (e2, e1) is the transpose by reciprocity
!! (W(x) K_ij(x, xi) = W(xi) K_ji(xi, x): r G_ij(r, s) = s G_ji(s, r) for the rings, k_ij(X) =
!! k_ji(-X) for the strip); a self pair is one triangle plus its transpose, so T is exactly
!! symmetric. `assemble_split_kernel_reference` (adaptive pair rules, both triangles) is kept as
!! the reference of the tests.
module galerkin_assembly
    use iso_fortran_env, only: int64
    !$ use omp_lib, only: omp_get_max_threads, omp_get_thread_num, omp_in_parallel
    use kinds, only: dp, pi
    use lapack_interfaces, only: dgemm
    use blas_threads, only: blas_thread_count, set_blas_threads
    use chebyshev_tables, only: n_cheb, orders, n_orders, chebyshev_t, new_chebyshev, order_for
    use sorting, only: sort_ascending
    use errors, only: error_t, add_context
    use shape_functions, only: basis_t, eval_basis, max_local
    use singular_quadrature, only: split_kernel_t, gauss_tables_t, point_rule_t, line_rule_t, &
                                   shared_gauss_tables, build_pair_rule, build_line_rule, &
                                   check_bases, near_ratio, n_max
    implicit none
    private

    public :: assemble_split_kernel

    integer, parameter :: n_loc = 2*max_local    !! local functions of one element, both fields
    real(dp), parameter :: default_far_digits = 13.0_dp  !! see far_points
    integer, parameter :: max_across = 4 !! GL points across the reduced variable, at most
                                         !! (across_points)
    integer, parameter :: max_degree = 3 !! polynomial degree of a far integrand's factor, at most
    integer, parameter :: max_batch = 256  !! field nodes of one far batch (>= n_max)
    integer, parameter :: batch_rows = max_batch + 8  !! leading dimension of the batch arrays
                                         !! g and y: off the 4 kB multiples, so that their
                                         !! columns do not fall on one cache set (a precaution:
                                         !! no difference measured)
    integer, parameter :: part = 64      !! nodes of v added together (add_across)
    integer, parameter :: min_parallel = 100 !! fewer elements: one thread (below about 3 ms
                                             !! a thread start-up, or a colour's barrier
                                             !! waiting for a preempted thread on a busy
                                             !! machine, costs more than the second core saves)
    integer, parameter :: max_threads = 8    !! each thread keeps its own GL tables (about 12 MB
                                             !! at N_e = 1000) and column storage (0.6 MB)
    ! interpolated blocks (add_blocks)
    integer, parameter :: min_blocks = 50        !! fewer elements: no blocks (at N_e = 40
                                                 !! and 48 they cost more than they saved;
                                                 !! from 50 to 128 they pay, 10 to 25 %)
    real(dp), parameter :: block_ratio = 1.0_dp  !! gap / longer cluster length, at least
    real(dp), parameter :: block_cost = 24.0_dp  !! kernel values per element pair, at most
    integer, parameter :: leaf_max = 6           !! elements of a leaf cluster, at most
    integer, parameter :: moment_points = 16     !! GL points per element of the moments

    !> Local numbering of one element pair: rows (field element) and columns (source element),
    !! first the bx functions then the bz functions (the global numbers: work%glob).
    type :: pair_map_t
        integer :: nf = 0                         !! local rows
        integer :: ns = 0                         !! local columns
        integer :: comp_f(n_loc) = 0              !! 1 = bx (tangential), 2 = bz (normal)
        integer :: comp_s(n_loc) = 0
    end type pair_map_t

    !> Work arrays reused over the element pairs; one per thread.
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
        real(dp), allocatable :: poly(:, :, :)     !! poly(:, r, e): g_r = c1 + c2 xi + c3 xi^2
        integer, allocatable :: same(:, :)         !! same(r, e): the first local function of e
                                                   !! equal to g_r (bx and bz of one family)
        real(dp) :: far_limit(2:n_max, 0:max_degree) = 0.0_dp  !! see far_points
        real(dp), allocatable :: raise_ratio(:)    !! see field_degree
        real(dp), allocatable :: moment(:, :, :)   !! moment(r, 1, e) = int g_r W dx,
                                                   !! moment(r, 2, e) = int g_r dx on e
                                                   !! (constant coupling, contract_fields)
        integer :: n_across = max_across           !! see across_points
        integer, allocatable :: far(:, :)          !! (e1, n1, n2) of the far pairs of a column
        integer, allocatable :: by_n2(:, :)        !! the same (e1, n1), sorted by n2
        real(dp), allocatable :: gx(:)             !! field nodes of a far batch
        real(dp), allocatable :: gbf(:, :)         !! gbf(k, r): the weighted functions of the
                                                   !! field element of node k (element_nodes)
        real(dp) :: sx(n_max) = 0.0_dp             !! source nodes of a far batch
        real(dp) :: sbs(n_max, n_loc) = 0.0_dp     !! the weighted source functions there
        real(dp), allocatable :: g(:, :, :, :)     !! kernel on the batch grid, g(k, l, i, j)
        real(dp), allocatable :: y(:, :, :)        !! y(k, i, c) = sum_l g(k, l, i, .) bs(c, l)
        type(error_t), allocatable :: err          !! failure of this thread's last column
    end type work_t

    !> Moments of the functions of one cluster against its Lagrange polynomials of one order:
    !! field(row, a, i) with the field measure, source(row, a, i) without; i the field.
    type :: moments_t
        real(dp), allocatable :: field(:, :, :), source(:, :, :)
    end type moments_t

    !> Chebyshev moments of the functions of one cluster (cluster_tree_t).
    type :: chebyshev_moments_t
        real(dp), allocatable :: a(:, :, :)
    end type chebyshev_moments_t

    !> The functions of one field with support in a cluster (global numbers).
    type :: cluster_rows_t
        integer :: n = 0
        integer, allocatable :: glob(:)
    end type cluster_rows_t

    !> Binary tree of clusters of contiguous elements (cluster 1: the mesh) and the admissible
    !! blocks (cx, cy, order index of cx, order index of cy).
    type :: cluster_tree_t
        integer :: n = 0
        integer, allocatable :: first(:), last(:), child(:, :)
        integer, allocatable :: parent(:)          !! 0 for the root
        integer, allocatable :: leaf_of(:)         !! leaf_of(e): the leaf holding element e
        real(dp), allocatable :: lo(:), hi(:)
        integer :: n_blocks = 0
        integer, allocatable :: blocks(:, :)
        !> The blocks whose cy is cluster c: by_cy(cy_start(c):cy_start(c + 1) - 1)
        integer, allocatable :: by_cy(:), cy_start(:)
        type(moments_t), allocatable :: side(:, :)        !! side(k, c): orders(k) on c
        type(cluster_rows_t), allocatable :: rows(:, :)   !! rows(i, c)
        !> Chebyshev moments of the functions of cluster c: a(row, q + 1, i) = int g W T_q
        !! (field) and int g T_q (source), q < n_cheb
        type(chebyshev_moments_t), allocatable :: cheb_field(:), cheb_source(:)
        !> Fields whose moments are stored (the last index of cheb_field%a, side%field, ...):
        !! 1 when the bz functions repeat the bx functions on every element (P1/P1, P2/P2,
        !! S2/S2: the moments of the two fields are the same numbers, formed and kept once),
        !! else 2; field i is stored at min(i, n_stored)
        integer :: n_stored = 2
    end type cluster_tree_t

contains

    !> T (module header); n_kernel returns the number of kernel evaluations (point pairs).
    subroutine assemble_split_kernel(kernel, bx, bz, t_mat, err, n_kernel, far_digits, pairwise)
        class(split_kernel_t), intent(in) :: kernel         !! the surface kernel in split form
        type(basis_t), intent(in) :: bx            !! basis of sigma_x
        type(basis_t), intent(in) :: bz            !! basis of sigma_z, same mesh
        real(dp), allocatable, intent(out) :: t_mat(:, :)   !! T (nr x nr)
        type(error_t), allocatable, intent(out) :: err      !! allocated on failure
        integer(int64), intent(out), optional :: n_kernel   !! kernel evaluations (point pairs)
        real(dp), intent(in), optional :: far_digits  !! accuracy studies only: digits of the
                                                      !! far rules (far_points) instead of
                                                      !! default_far_digits
        logical, intent(in), optional :: pairwise     !! all far pairs pair by pair (the
                                                      !! assembly before add_blocks; tests)
        type(work_t) :: work
        type(chebyshev_t) :: cheb
        type(cluster_tree_t) :: tree
        logical, allocatable :: skip(:, :)         !! skip(e1, thread): the pair (e1, e2) of the
                                                   !! thread's column e2 is in a block
        logical :: use_blocks
        type(work_t), allocatable :: works(:)
        real(dp), allocatable :: column_loc(:, :, :, :, :)
        logical, allocatable :: shift_ok(:)
        logical :: in_order
        integer :: e2, n_threads, thread, n_colours, colour, first, last, step
        call check_bases(bx, bz, err)
        if (allocated(err)) return
        allocate (t_mat(bx%n_dof + bz%n_dof, bx%n_dof + bz%n_dof), source=0.0_dp)
        call shared_gauss_tables(work%tab)
        call new_work(kernel, bx, bz, work, far_digits)
        call translates(kernel, bx, work%poly, shift_ok)
        ! translated pairs are copied from the previous column: one thread does the columns in
        ! order then (O(N_e) pair integrals); no nested teams (the cases of a sweep already run
        ! in parallel)
        in_order = any(shift_ok)
        use_blocks = kernel%homogeneous .and. kernel%constant_coupling .and. .not. in_order &
                     .and. bx%ne >= min_blocks
        if (present(pairwise)) use_blocks = use_blocks .and. .not. pairwise
        if (use_blocks) then
            call new_chebyshev(cheb)
            call new_blocks(bx, cheb, tree)
        end if
        n_threads = 1
        !$ if (.not. in_order .and. .not. omp_in_parallel() .and. bx%ne >= min_parallel) &
        !$     n_threads = min(omp_get_max_threads(), max_threads)
        allocate (works(n_threads))
        works(:) = work
        each_thread: do thread = 1, n_threads
            call new_batch_arrays(bx, works(thread))
        end do each_thread
        n_colours = 1
        if (.not. in_order) n_colours = column_stride(work)
        allocate (column_loc(n_loc, n_loc, bx%ne, 0:1, n_threads))
        allocate (skip(bx%ne, n_threads), source=.false.)
        ! columns outer: the pair (e1, e2) adds to the columns of e2's functions only, and the
        ! columns e2 of one colour (e2 mod n_colours) share no function, so they are added to T
        ! in parallel without races; every entry receives its terms in the same order (colour
        ! by colour, rows in order) on any number of threads. Costly (long) columns first,
        ! except for the translated pairs (one colour, one thread, in order).
        colours: do colour = 1, n_colours
            first = 1
            last = bx%ne
            step = 1
            if (.not. in_order) then
                first = bx%ne - modulo(bx%ne - colour, n_colours)
                last = 1
                step = -n_colours
            end if
            !$omp parallel do num_threads(n_threads) schedule(dynamic, 1) default(shared) &
            !$omp private(thread)
            source_elements: do e2 = first, last, step
                thread = 1
                !$ thread = omp_get_thread_num() + 1
                if (use_blocks) call blocked_rows(tree, e2, skip(:, thread))
                call integrate_column(kernel, bx, bz, e2, shift_ok, skip(:, thread), &
                                      works(thread), column_loc(:, :, :, :, thread))
                call add_column(e2, skip(:, thread), works(thread), &
                                column_loc(:, :, :, mod(e2, 2), thread), t_mat)
            end do source_elements
            !$omp end parallel do
        end do colours
        threads: do thread = 1, n_threads
            if (.not. allocated(works(thread)%err)) cycle threads
            call move_alloc(works(thread)%err, err)
            return
        end do threads
        if (use_blocks) then
            call add_blocks_on_one_thread(kernel, bx, cheb, tree, works(1), t_mat, err)
            if (allocated(err)) return
        end if
        call add_transpose(t_mat)
        if (present(n_kernel)) n_kernel = sum(works%n_kernel)
    end subroutine assemble_split_kernel

    !> add_blocks with dgemm on one BLAS thread: OpenBLAS's threaded kernels sum in an order
    !! that depends on the thread count, and T must not depend on it (T changed with
    !! OPENBLAS_NUM_THREADS otherwise). The program's driver runs every case's BLAS on one
    !! thread already; this guard is for direct callers (tests, examples), which call it
    !! outside any parallel region, so the count is never touched concurrently.
    subroutine add_blocks_on_one_thread(kernel, bx, cheb, tree, work, t_mat, err)
        class(split_kernel_t), intent(in) :: kernel       !! the half-space kernel
        type(basis_t), intent(in) :: bx                   !! basis of sigma_x
        type(chebyshev_t), intent(in) :: cheb             !! the interpolation rule
        type(cluster_tree_t), intent(inout) :: tree       !! the blocks
        type(work_t), intent(inout) :: work               !! one thread's work
        real(dp), intent(inout) :: t_mat(:, :)            !! T, blocks added
        type(error_t), allocatable, intent(out) :: err    !! an interpolated block failed
        integer :: blas_count
        blas_count = blas_thread_count()
        if (blas_count > 1) call set_blas_threads(1)
        call add_blocks(kernel, bx, cheb, tree, work, t_mat, err)
        if (blas_count > 1) call set_blas_threads(blas_count)
        if (allocated(err)) call add_context(err, 'half-space operator, interpolated blocks')
    end subroutine add_blocks_on_one_thread

    !> Work of one thread (its GL tables already copied: shared_gauss_tables): the numbering and
    !! polynomials of every element, the far-rule limits and the element moments.
    pure subroutine new_work(kernel, bx, bz, work, far_digits)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        type(work_t), intent(inout) :: work
        real(dp), intent(in), optional :: far_digits
        real(dp) :: q, digits
        integer :: e
        work%n_across = across_points(kernel, bx, bz)
        call number_elements(bx, bz, work)
        digits = default_far_digits
        if (present(far_digits)) digits = far_digits
        call far_limits(digits, work%far_limit)
        if (kernel%constant_coupling) call element_moments(kernel, bx, work)
        allocate (work%raise_ratio(bx%ne), source=huge(1.0_dp))
        if (kernel%homogeneous) then
            elements: do e = 1, bx%ne
                q = (bx%x(e) + bx%x(e - 1))/(bx%x(e) - bx%x(e - 1))
                work%raise_ratio(e) = 0.5_dp*(0.5_dp*(q + 1.0_dp/q) - 1.0_dp)
            end do elements
        end if
    end subroutine new_work

    !> work%moment: the integrals of the local functions of every element, with and without
    !! the field measure W, by 3-point GL (exact: g_r W has degree <= 3).
    pure subroutine element_moments(kernel, bx, work)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        type(work_t), intent(inout) :: work
        integer, parameter :: n = 3
        real(dp) :: h, xi, x, b(n_loc)
        integer :: e, i
        allocate (work%moment(n_loc, 2, bx%ne), source=0.0_dp)
        elements: do e = 1, bx%ne
            h = bx%x(e) - bx%x(e - 1)
            nodes: do i = 1, n
                xi = 2.0_dp*work%tab%v(i, n) - 1.0_dp
                x = bx%x(e - 1) + h*work%tab%v(i, n)
                b = work%poly(1, :, e) + xi*(work%poly(2, :, e) + xi*work%poly(3, :, e))
                b = b*(h*work%tab%w(i, n))
                work%moment(:, 1, e) = work%moment(:, 1, e) + b*kernel%field_weight(x)
                work%moment(:, 2, e) = work%moment(:, 2, e) + b
            end do nodes
        end do elements
    end subroutine element_moments

    !> The far-batch and point-pair arrays of one thread's work (not in the work copied to
    !! every thread: about 100 kB that every assembly would copy).
    pure subroutine new_batch_arrays(bx, work)
        type(basis_t), intent(in) :: bx
        type(work_t), intent(inout) :: work
        call reserve(work, 256)
        allocate (work%far(3, bx%ne), work%by_n2(2, bx%ne), work%gx(max_batch), &
                  work%gbf(batch_rows, n_loc), work%g(batch_rows, 4, 2, 2), &
                  work%y(batch_rows, 2, n_loc))
    end subroutine new_batch_arrays

    !> The least stride s such that elements e and e + s have no function in common, for
    !! every e (the supports are consecutive elements: P1, P2 2, S2 3).
    pure integer function column_stride(work) result(stride)
        type(work_t), intent(in) :: work
        integer :: e, f, i
        stride = 1
        elements: do e = 1, size(work%n_fun)
            later: do f = e + stride, size(work%n_fun)
                shares: do i = 1, work%n_fun(f)
                    if (any(work%glob(1:work%n_fun(e), e) == work%glob(i, f))) exit shares
                end do shares
                if (i > work%n_fun(f)) exit later
                stride = f - e + 1
            end do later
        end do elements
    end function column_stride

    !> The pairs (e1, e2), e1 = 1..e2, of source element e2 into loc(:, :, e1, mod(e2, 2)):
    !! translated pairs copied from the previous column (loc(:, :, :, mod(e2 - 1, 2)), filled
    !! by the same work: one thread), near pairs one by one, far pairs in batches
    !! (far_pairs). A failure is left in work%err (the threads share no error variable), and
    !! the thread does nothing more.
    subroutine integrate_column(kernel, bx, bz, e2, shift_ok, skip, work, loc)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e2
        logical, intent(in) :: shift_ok(:)         !! see translates
        logical, intent(in) :: skip(:)             !! skip(e1): the pair is in an interpolated
                                                   !! block (add_blocks)
        type(work_t), intent(inout) :: work
        real(dp), contiguous, intent(inout) :: loc(:, :, :, 0:)  !! loc(r, c, e1, parity of e2)
        type(error_t), allocatable :: err
        type(pair_map_t) :: map
        real(dp) :: gap, h1, h2
        integer :: e1, now, n_far
        character(len=60) :: where
        if (allocated(work%err)) return
        now = mod(e2, 2)
        n_far = 0
        h2 = bx%x(e2) - bx%x(e2 - 1)
        field_elements: do e1 = 1, e2
            if (skip(e1)) cycle field_elements
            if (repeats_pair(bx, shift_ok, e1, e2)) then
                loc(:, :, e1, now) = loc(:, :, e1 - 1, 1 - now)
                cycle field_elements
            end if
            h1 = bx%x(e1) - bx%x(e1 - 1)
            gap = max(bx%x(e2 - 1) - bx%x(e1), bx%x(e1 - 1) - bx%x(e2))
            if (gap >= near_ratio*max(h1, h2)) then
                n_far = n_far + 1
                work%far(:, n_far) = [e1, &
                    far_points(work%far_limit(:, field_degree(work, bx, bz, e1, gap/h1)), &
                               gap/h1), &
                    far_points(work%far_limit(:, max(bx%degree, bz%degree)), gap/h2)]
                cycle field_elements
            end if
            call new_pair_map(work, e1, e2, map)
            call near_pair(kernel, bx, bz, e1, e2, map, work, loc(:, :, e1, now), err)
            if (allocated(err)) then
                write (where, '("half-space operator, elements ",i0," and ",i0)') e1, e2
                call add_context(err, trim(where))
                call move_alloc(err, work%err)
                return
            end if
        end do field_elements
        call far_pairs(kernel, bx, e2, n_far, work, loc(:, :, :, now), err)
        if (allocated(err)) then
            write (where, '("half-space operator, far pairs of element ",i0)') e2
            call add_context(err, trim(where))
            call move_alloc(err, work%err)
        end if
    end subroutine integrate_column

    !> Add the pairs of column e2 (loc(:, :, e1), e1 <= e2) to T, unless this thread failed.
    pure subroutine add_column(e2, skip, work, loc, t_mat)
        integer, intent(in) :: e2
        logical, intent(in) :: skip(:)             !! see integrate_column
        type(work_t), intent(in) :: work
        real(dp), contiguous, intent(in) :: loc(:, :, :)
        real(dp), intent(inout) :: t_mat(:, :)
        integer :: e1
        if (allocated(work%err)) return
        field_elements: do e1 = 1, e2
            if (skip(e1)) cycle field_elements
            call scatter(work%glob(1:work%n_fun(e1), e1), work%glob(1:work%n_fun(e2), e2), &
                         e1 == e2, loc(:, :, e1), t_mat)
        end do field_elements
    end subroutine add_column

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

    !> Local numbering of the functions of elements e1 (rows) and e2 (columns).
    pure subroutine new_pair_map(work, e1, e2, map)
        type(work_t), intent(in) :: work
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(out) :: map
        map%nf = work%n_fun(e1)
        map%comp_f = work%comp(:, e1)
        map%ns = work%n_fun(e2)
        map%comp_s = work%comp(:, e2)
    end subroutine new_pair_map

    !> Numbering of the functions of every element (element_numbers), once.
    pure subroutine number_elements(bx, bz, work)
        type(basis_t), intent(in) :: bx, bz
        type(work_t), intent(inout) :: work
        integer :: e, r, q
        allocate (work%n_fun(bx%ne), work%comp(n_loc, bx%ne), work%glob(n_loc, bx%ne))
        allocate (work%poly(3, n_loc, bx%ne), work%same(n_loc, bx%ne))
        work%comp = 0
        work%glob = 0
        elements: do e = 1, bx%ne
            call element_numbers(bx, bz, e, work%n_fun(e), work%comp(:, e), work%glob(:, e))
            call element_polynomials(bx, bz, e, work%poly(:, :, e))
            functions: do r = 1, n_loc
                work%same(r, e) = r
                earlier: do q = 1, r - 1
                    if (all(work%poly(:, q, e) == work%poly(:, r, e))) then
                        work%same(r, e) = q
                        exit earlier
                    end if
                end do earlier
            end do functions
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

    !> Nodes x(i) of the n-point GL rule on element e and its local functions there, weighted
    !! for the field side (bf = g_r h w_i W(x_i)) and for the source side (bs = g_r h w_i).
    !! Formed where they are used (a far batch, a leaf's moments), not tabulated for every
    !! order and element: a few multiplications per node against the tens of kernel
    !! evaluations each node serves, and tables of every order on every element (0.6 MB at
    !! N_e = 100, 12 MB at 1000) are fresh pages at every assembly of a case.
    pure subroutine element_nodes(kernel, bx, work, n, e, x, bf, bs)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        type(work_t), intent(in) :: work           !! GL tables, polynomials
        integer, intent(in) :: n, e
        real(dp), intent(out) :: x(:)              !! x(i), i <= n
        real(dp), intent(out), optional :: bf(:, :)  !! bf(i, r), r <= n_fun(e)
        real(dp), intent(out), optional :: bs(:, :)  !! bs(i, r)
        real(dp) :: xi, b, h, w, wf
        integer :: i, r
        h = bx%x(e) - bx%x(e - 1)
        nodes: do i = 1, n
            xi = 2.0_dp*work%tab%v(i, n) - 1.0_dp
            x(i) = bx%x(e - 1) + h*work%tab%v(i, n)
            w = h*work%tab%w(i, n)
            if (present(bf)) wf = w*kernel%field_weight(x(i))
            functions: do r = 1, work%n_fun(e)
                b = work%poly(1, r, e) + xi*(work%poly(2, r, e) + xi*work%poly(3, r, e))
                if (present(bs)) bs(i, r) = b*w
                if (present(bf)) bf(i, r) = b*wf
            end do functions
        end do nodes
    end subroutine element_nodes

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

    !> GL points across the reduced variable that integrate the basis products exactly: a
    !! product of a field and a source function has degree 2 max_degree in the offset across v,
    !! times x W(x) for the rings (W = 2 pi x, and dx = xi dt): 2 more; n points are exact to
    !! degree 2 n - 1 (4 for P2/S2 on the rings, 3 for P1; 2 and 3 for the strip).
    pure integer function across_points(kernel, bx, bz) result(n)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer :: degree
        degree = 2*max(bx%degree, bz%degree)
        if (kernel%homogeneous) degree = degree + 2
        n = min(max_across, degree/2 + 1)
    end function across_points

    !> The kernel depends on one combination of (x, xi) only (reduced_pair applies).
    pure logical function reducible(kernel)
        class(split_kernel_t), intent(in) :: kernel
        reducible = kernel%homogeneous .or. kernel%translation_invariant
    end function reducible

    !> GL points per direction for a well separated pair: the error of n-point GL on
    !! poly_p(x) k(x), k singular at distance `ratio` element lengths from the element, is about
    !! rho^(p - 2n), rho = c + sqrt(c^2 - 1), c = 1 + 2 ratio (Bernstein ellipse through the
    !! singularity; the polynomial of degree p grows like rho^p on it). n = (far_digits/log10 rho
    !! + p)/2 rounded up keeps it below 10^-far_digits of int |poly_p k| for k = 1/d, ln d and
    !! for the worst (Legendre) polynomial of degree p <= 3, as measured with 40-digit
    !! arithmetic at ratios 2 to 3000. The contract of T is its entries to about 1e-14 of the
    !! LARGEST entry, and the kernels here are logarithmic (milder than 1/d, for which the
    !! estimate was made): far_digits = 13 (doc/CHOICES.md, Assembly of T) moves T by at most
    !! 1.0e-15 of its largest entry against rules of 20 digits (1.4e-15 for the beam), the
    !! round-off level of the assembly (3e-16 to 7e-16 with 15 digits), for 20 % fewer kernel
    !! evaluations; an entry far below the largest may move by more relative to itself
    !! (5e-14 on uniform P1 meshes, 6e-12 for the small entries of EDGES P2/S2). 12 digits give
    !! 8e-15 of the largest (example accuracy_far_rules; output/bench/assembly_before_after.md).
    !! The least n >= 2 (at most n_max) whose limit (far_limits) the ratio reaches.
    pure integer function far_points(limit, ratio) result(n)
        real(dp), intent(in) :: limit(2:n_max)  !! work%far_limit(:, p), p the polynomial degree
        real(dp), intent(in) :: ratio           !! gap / element length, >= near_ratio
        n = 2
        fewest: do while (n < n_max)
            if (ratio >= limit(n)) exit fewest
            n = n + 1
        end do fewest
    end function far_points

    !> limit(n, p): the least gap/size ratio at which n points suffice for degree p in
    !! far_points: n >= (far_digits/log10 rho + p)/2 is rho >= rho_n = 10^(far_digits/(2n - p)),
    !! i.e. ratio >= (c_n - 1)/2, c_n = (rho_n + 1/rho_n)/2. Tabulated once, so that a pair
    !! costs comparisons instead of a logarithm.
    pure subroutine far_limits(far_digits, limit)
        real(dp), intent(in) :: far_digits
        real(dp), intent(out) :: limit(2:n_max, 0:max_degree)
        real(dp) :: rho
        integer :: n, p
        degrees: do p = 0, max_degree
            orders: do n = 2, n_max
                rho = 10.0_dp**(far_digits/real(2*n - p, dp))
                limit(n, p) = 0.5_dp*(0.5_dp*(rho + 1.0_dp/rho) - 1.0_dp)
            end do orders
        end do degrees
    end subroutine far_limits

    !> Degree of the polynomial factor on the field side: the basis, times x for the ring
    !! measure 2 pi x (homogeneous kernels are the ring kernels) where that factor grows on the
    !! Bernstein ellipse: 2 pi x = W0 (1 + eps xi), eps = h/(a + b), is at most 2 W0 on the
    !! ellipse rho when eps rho <= 1 (elements away from the axis), a factor 2 in the error.
    !! With q = (a + b)/h >= 1, rho > q is ratio > ((q + 1/q)/2 - 1)/2 = work%raise_ratio(e)
    !! (new_work; huge for the other kernels).
    pure integer function field_degree(work, bx, bz, e, ratio) result(p)
        type(work_t), intent(in) :: work
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e                !! field element
        real(dp), intent(in) :: ratio           !! gap / its length
        p = max(bx%degree, bz%degree)
        if (ratio > work%raise_ratio(e)) p = p + 1
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

    !> loc(r, c) = int int g_r(x) W(x) K_{comp_f(r), comp_s(c)}(x, xi) g_c(xi) over e1 x e2,
    !! a touching or nearly touching pair.
    subroutine near_pair(kernel, bx, bz, e1, e2, map, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx, bz
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(in) :: map
        type(work_t), intent(inout) :: work
        real(dp), intent(out) :: loc(n_loc, n_loc)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: a1, a2
        if (reducible(kernel)) then
            call reduced_pair(kernel, bx, e1, e2, map, work, loc, err)
        else
            a1 = bx%x(e1 - 1)
            a2 = bx%x(e2 - 1)
            call build_pair_rule(work%tab, a1, bx%x(e1), a2, bx%x(e2), &
                                 kernel%log_length(max(a1, a2)), &
                                 kernel%homogeneous .and. e1 == e2 .and. &
                                 .not. kernel%log_length(a1) > 0.0_dp, work%rule, work%line)
            call rule_pair(kernel, bx, bz, e1, e2, map, work, loc, err)
        end if
    end subroutine near_pair

    !> The far pairs of column e2, work%far(:, 1:n_far), sorted by the source order n2 (a
    !! counting sort: pairs of one n2 share the source nodes) and done in batches of at most
    !! max_batch field nodes (far_batch).
    subroutine far_pairs(kernel, bx, e2, n_far, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        integer, intent(in) :: e2, n_far
        type(work_t), intent(inout) :: work
        real(dp), contiguous, intent(inout) :: loc(:, :, :)    !! loc(r, c, e1)
        type(error_t), allocatable, intent(out) :: err
        integer :: n_with(n_max), first(n_max + 1), next(n_max), q, n2, start, points
        n_with = 0
        count_orders: do q = 1, n_far
            n_with(work%far(3, q)) = n_with(work%far(3, q)) + 1
        end do count_orders
        first(1) = 1
        offsets: do n2 = 1, n_max
            first(n2 + 1) = first(n2) + n_with(n2)
        end do offsets
        next = first(1:n_max)
        sort: do q = 1, n_far
            n2 = work%far(3, q)
            work%by_n2(:, next(n2)) = work%far(1:2, q)
            next(n2) = next(n2) + 1
        end do sort
        orders: do n2 = 2, n_max
            start = first(n2)
            points = 0
            pairs: do q = first(n2), first(n2 + 1) - 1
                if (points + work%by_n2(2, q) > max_batch) then
                    call far_batch(kernel, bx, e2, n2, start, q - 1, work, loc, err)
                    if (allocated(err)) return
                    start = q
                    points = 0
                end if
                points = points + work%by_n2(2, q)
            end do pairs
            if (points == 0) cycle orders
            call far_batch(kernel, bx, e2, n2, start, first(n2 + 1) - 1, work, loc, err)
            if (allocated(err)) return
        end do orders
    end subroutine far_pairs

    !> The far pairs (e1, e2) of source order n2 listed in work%by_n2(:, first:last): the kernel
    !! on the grid of all their field nodes x the source nodes in one call, y = K diag(w_s)
    !! B_s^T for all field nodes at once, then loc(:, :, e1) = B_f diag(w_f W) y per pair (the
    !! tensor GL rule of far_points, contracted in this order). With constant coupling kernels
    !! (rings: x < xi in every far pair) only the diagonal components are on the grid.
    subroutine far_batch(kernel, bx, e2, n2, first, last, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        integer, intent(in) :: e2, n2, first, last
        type(work_t), intent(inout) :: work
        real(dp), contiguous, intent(inout) :: loc(:, :, :)    !! loc(r, c, e1)
        type(error_t), allocatable, intent(out) :: err
        integer :: q, n1, k0
        call element_nodes(kernel, bx, work, n2, e2, work%sx, bs=work%sbs)
        k0 = 0
        field_nodes: do q = first, last
            n1 = work%by_n2(2, q)
            call element_nodes(kernel, bx, work, n1, work%by_n2(1, q), work%gx(k0 + 1:k0 + n1), &
                               bf=work%gbf(k0 + 1:k0 + n1, :))
            k0 = k0 + n1
        end do field_nodes
        if (size(work%g, 2) < n2) then
            ! as large as needed only: below the allocator's mmap threshold it is reused
            ! without fresh pages (page faults) at every assembly
            deallocate (work%g)
            allocate (work%g(batch_rows, n2, 2, 2))
        end if
        call kernel%grid_values(work%gx(1:k0), work%sx(1:n2), &
                                work%g(1:k0, 1:n2, :, :), err)
        if (allocated(err)) return
        work%n_kernel = work%n_kernel + int(k0*n2, int64)
        call contract_sources(kernel, e2, n2, k0, work)
        call contract_fields(kernel, e2, first, last, work, loc)
    end subroutine far_batch

    !> y(k, i, c) = sum_l g(k, l, i, comp(c)) bs(l, c) for the k0 field nodes of a far batch and
    !! the functions c of source element e2; with constant coupling only i = comp(c) (the
    !! coupling rows are closed, contract_fields).
    pure subroutine contract_sources(kernel, e2, n2, k0, work)
        class(split_kernel_t), intent(in) :: kernel
        integer, intent(in) :: e2, n2, k0
        type(work_t), intent(inout) :: work
        integer :: c, l, i, j
        source_functions: do c = 1, work%n_fun(e2)
            j = work%comp(c, e2)
            components: do i = 1, 2
                if (kernel%constant_coupling .and. i /= j) cycle components
                work%y(1:k0, i, c) = work%g(1:k0, 1, i, j)*work%sbs(1, c)
                source_nodes: do l = 2, n2
                    work%y(1:k0, i, c) = work%y(1:k0, i, c) + work%g(1:k0, l, i, j)*work%sbs(l, c)
                end do source_nodes
            end do components
        end do source_functions
    end subroutine contract_sources

    !> loc(r, c, e1) = sum_k bf(k, r, e1) y(k, comp(r), c) for the far pairs of a batch; with
    !! constant coupling F_ij (i /= j) the integral of a coupling entry is
    !! F_ij (int g_r W dx) (int g_c dxi) (work%moment).
    pure subroutine contract_fields(kernel, e2, first, last, work, loc)
        class(split_kernel_t), intent(in) :: kernel
        integer, intent(in) :: e2, first, last
        type(work_t), intent(in) :: work
        real(dp), contiguous, intent(inout) :: loc(:, :, :)    !! loc(r, c, e1)
        real(dp) :: total
        integer :: q, e1, n1, k0, c, r, i, j, k
        k0 = 0
        pairs: do q = first, last
            e1 = work%by_n2(1, q)
            n1 = work%by_n2(2, q)
            associate (bf => work%gbf, y => work%y)
                columns: do c = 1, work%n_fun(e2)
                    j = work%comp(c, e2)
                    rows: do r = 1, work%n_fun(e1)
                        i = work%comp(r, e1)
                        if (kernel%constant_coupling .and. i /= j) then
                            loc(r, c, e1) = kernel%coupling(i)*work%moment(r, 1, e1)* &
                                            work%moment(c, 2, e2)
                            cycle rows
                        end if
                        total = 0.0_dp
                        nodes: do k = 1, n1
                            total = total + bf(k0 + k, r)*y(k0 + k, i, c)
                        end do nodes
                        loc(r, c, e1) = total
                    end do rows
                end do columns
            end associate
            k0 = k0 + n1
        end do pairs
    end subroutine contract_fields

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
    !! products exact by work%n_across GL points. A self pair integrates the triangle x < xi
    !! and adds the transpose (the other triangle, by reciprocity).
    subroutine reduced_pair(kernel, bx, e1, e2, map, work, loc, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(in) :: map
        type(work_t), intent(inout) :: work
        real(dp), intent(out) :: loc(n_loc, n_loc)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: cuts(5), u0, pole
        integer :: n, k0
        call reduced_cuts(kernel, bx, e1, e2, cuts, u0, pole)
        call reduced_nodes(work, cuts, u0, pole, n)
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
        parts: do k0 = 1, n, part
            call add_across(kernel, bx, e1, e2, map, work, k0, min(part, n - k0 + 1), loc)
        end do parts
        if (e1 == e2) loc = loc + transpose(loc)
    end subroutine reduced_pair

    !> Range of v, its kinks and the log length, all as OFFSETS from the singular point (v - 1
    !! for v = x/xi, v - 0 for v = x - xi), formed from differences of node coordinates so that
    !! the range of an element pair keeps full relative precision; over e1 x e2 (e2 > e1) or
    !! over the triangle x < xi of a self pair; sorted, and clipped to [cuts(1), cuts(5)]. The
    !! range across v = x/xi has a pole at v = 0 (offset -1: xi in [a1/v, b1/v]).
    pure subroutine reduced_cuts(kernel, bx, e1, e2, cuts, u0, pole)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        integer, intent(in) :: e1, e2
        real(dp), intent(out) :: cuts(5), u0
        real(dp), intent(out) :: pole          !! offset of the pole, -huge if none
        real(dp) :: a1, b1, a2, b2
        integer :: i
        a1 = bx%x(e1 - 1)
        b1 = bx%x(e1)
        a2 = bx%x(e2 - 1)
        b2 = bx%x(e2)
        pole = -huge(1.0_dp)
        if (kernel%homogeneous) then
            pole = -1.0_dp
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
    !! work%wc, and with_log, piece by piece; a piece's points also from its distance to the
    !! pole of the range across v, except for a piece that starts at the pole: it starts at
    !! the axis (a1 = 0), where the branch b1/v - a2 of the range is not taken (that range
    !! is [a2, b2] for v <= b1/b2) and the branch a1/v - a2 is negative.
    pure subroutine reduced_nodes(work, cuts, u0, pole, n)
        type(work_t), intent(inout) :: work
        real(dp), intent(in) :: cuts(5), u0, pole
        integer, intent(out) :: n
        real(dp) :: tiny_len
        integer :: i, m
        tiny_len = 1.0e-14_dp*(cuts(5) - cuts(1))
        n = 0
        pieces: do i = 1, 4
            if (cuts(i + 1) - cuts(i) <= tiny_len) cycle pieces
            ! work%line: its arrays are kept from pair to pair (no allocation per piece)
            call build_line_rule(work%tab, cuts(i), cuts(i + 1), 0.0_dp, u0, work%line, &
                                 merge(pole, -huge(1.0_dp), cuts(i) > pole))
            m = work%line%n
            call reserve(work, n + m)
            work%w(n + 1:n + m) = work%line%w(1:m)
            work%wc(n + 1:n + m) = work%line%wc(1:m)
            work%dv(n + 1:n + m) = work%line%d(1:m)
            n = n + m
        end do pieces
        work%with_log(1:n) = work%wc(1:n) /= 0.0_dp
    end subroutine reduced_nodes

    !> Add the nodes k0 .. k0 + m - 1 of v (work%dv, at most `part`), each its weighted kernel
    !! w F + wc P times the integral of the basis products across v, the nodes together in
    !! vector loops. All positions are offsets from the element starts (full relative
    !! precision), the node given as its offset d from the singular point: translation, u = d,
    !! x - a1 in [max(0, a2 - a1 + u), min(h1, b2 - a1 + u)], xi - a2 = (x - a1) - (a2 - a1) - u;
    !! homogeneous, t = 1 + d, xi - a2 in [max(0, (a1 - a2 - a2 d)/t), min(h2, (b1 - a2 -
    !! a2 d)/t)], x - a1 = (a2 - a1) + a2 d + t (xi - a2), dx = xi dt.
    pure subroutine add_across(kernel, bx, e1, e2, map, work, k0, m, loc)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx            !! (mesh)
        integer, intent(in) :: e1, e2
        type(pair_map_t), intent(in) :: map
        type(work_t), intent(in) :: work           !! nodes, weights, kernel values, poly, tab
        integer, intent(in) :: k0, m
        real(dp), intent(inout) :: loc(n_loc, n_loc)
        ! fixed size: automatic arrays would be allocated on the heap at every call
        real(dp), dimension(part) :: d, t, inv_t, lo, len, y, off1, off2, wj, l1, l2
        real(dp) :: c(part, 2, 2), bf(part, max_across, n_loc), bs(part, max_across, n_loc)
        real(dp) :: prod(part, n_loc, n_loc)
        real(dp) :: a1, a2, h1, h2, to_l1, to_l2
        integer :: i, j, k, r, col, n_across
        n_across = work%n_across
        a1 = bx%x(e1 - 1)
        a2 = bx%x(e2 - 1)
        h1 = bx%x(e1) - a1
        h2 = bx%x(e2) - a2
        d(1:m) = work%dv(k0:k0 + m - 1)
        t(1:m) = 1.0_dp + d(1:m)
        if (kernel%homogeneous) then
            inv_t(1:m) = 1.0_dp/t(1:m)
            lo(1:m) = max(0.0_dp, ((a1 - a2) - a2*d(1:m))*inv_t(1:m))
            len(1:m) = min(h2, ((bx%x(e1) - a2) - a2*d(1:m))*inv_t(1:m)) - lo(1:m)
        else
            lo(1:m) = max(0.0_dp, (a2 - a1) + d(1:m))
            len(1:m) = min(h1, (bx%x(e2) - a1) + d(1:m)) - lo(1:m)
        end if
        ! the weighted kernel, none where the range across v is empty (ends of the range)
        components: do j = 1, 2
            do i = 1, 2
                nodes: do k = 1, m
                    c(k, i, j) = work%w(k0 + k - 1)*work%f(i, j, k0 + k - 1)
                    if (work%with_log(k0 + k - 1)) c(k, i, j) = c(k, i, j) + &
                        work%wc(k0 + k - 1)*work%p(i, j, k0 + k - 1)
                    if (.not. len(k) > 0.0_dp) c(k, i, j) = 0.0_dp
                end do nodes
            end do
        end do components
        len(1:m) = max(len(1:m), 0.0_dp)
        to_l1 = 2.0_dp/h1
        to_l2 = 2.0_dp/h2
        across: do j = 1, n_across
            y(1:m) = lo(1:m) + len(1:m)*work%tab%v(j, n_across)
            if (kernel%homogeneous) then
                off2(1:m) = y(1:m)
                off1(1:m) = (a2 - a1) + a2*d(1:m) + t(1:m)*y(1:m)
                wj(1:m) = len(1:m)*work%tab%w(j, n_across)*(a2 + y(1:m))
            else
                off1(1:m) = y(1:m)
                off2(1:m) = y(1:m) - (a2 - a1) - d(1:m)
                wj(1:m) = len(1:m)*work%tab%w(j, n_across)
            end if
            wj(1:m) = wj(1:m)*(kernel%measure(0) + kernel%measure(1)*(a1 + off1(1:m)))
            l1(1:m) = to_l1*off1(1:m) - 1.0_dp
            l2(1:m) = to_l2*off2(1:m) - 1.0_dp
            ! a function that repeats an earlier one (bx and bz of one family) is not formed again
            field_functions: do r = 1, map%nf
                if (work%same(r, e1) /= r) cycle field_functions
                bf(1:m, j, r) = wj(1:m)*(work%poly(1, r, e1) + l1(1:m)*(work%poly(2, r, e1) + &
                                                              l1(1:m)*work%poly(3, r, e1)))
            end do field_functions
            source_functions: do col = 1, map%ns
                if (work%same(col, e2) /= col) cycle source_functions
                bs(1:m, j, col) = work%poly(1, col, e2) + l2(1:m)*(work%poly(2, col, e2) + &
                                                          l2(1:m)*work%poly(3, col, e2))
            end do source_functions
        end do across
        ! the across integral of each product of distinct functions
        product_columns: do col = 1, map%ns
            if (work%same(col, e2) /= col) cycle product_columns
            product_rows: do r = 1, map%nf
                if (work%same(r, e1) /= r) cycle product_rows
                prod(1:m, r, col) = bf(1:m, 1, r)*bs(1:m, 1, col)
                sum_across: do j = 2, n_across
                    prod(1:m, r, col) = prod(1:m, r, col) + bf(1:m, j, r)*bs(1:m, j, col)
                end do sum_across
            end do product_rows
        end do product_columns
        ! loc += the weighted kernel (comp_f, comp_s) times the across integral of each product
        columns: do col = 1, map%ns
            rows: do r = 1, map%nf
                loc(r, col) = loc(r, col) + &
                              dot_product4(c(1:m, map%comp_f(r), map%comp_s(col)), &
                                           prod(1:m, work%same(r, e1), work%same(col, e2)))
            end do rows
        end do columns
    end subroutine add_across

    !> sum(a*b) in four interleaved partial sums: four independent additions in flight instead
    !! of one chain (a plain sum of products is not reordered, hence not vectorised, by the
    !! compiler); the order is fixed, so the result is the same on every run and thread.
    pure real(dp) function dot_product4(a, b) result(total)
        real(dp), intent(in) :: a(:), b(:)
        real(dp) :: part4(4)
        integer :: k, n4
        n4 = 4*(size(a)/4)
        part4 = 0.0_dp
        quads: do k = 1, n4, 4
            part4 = part4 + a(k:k + 3)*b(k:k + 3)
        end do quads
        total = (part4(1) + part4(3)) + (part4(2) + part4(4))
        rest: do k = n4 + 1, size(a)
            total = total + a(k)*b(k)
        end do rest
    end function dot_product4

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
    pure subroutine scatter(row, col, self_pair, loc, t_mat)
        integer, intent(in) :: row(:)              !! global rows of the field element's functions
        integer, intent(in) :: col(:)              !! global columns of the source element's
        logical, intent(in) :: self_pair
        real(dp), intent(in) :: loc(n_loc, n_loc)
        real(dp), intent(inout) :: t_mat(:, :)
        integer :: r, c
        if (self_pair) then
            self_columns: do c = 1, size(col)
                self_rows: do r = 1, size(row)
                    t_mat(row(r), col(c)) = t_mat(row(r), col(c)) + &
                                            0.25_dp*(loc(r, c) + loc(c, r))
                end do self_rows
            end do self_columns
            return
        end if
        columns: do c = 1, size(col)
            rows: do r = 1, size(row)
                t_mat(row(r), col(c)) = t_mat(row(r), col(c)) + loc(r, c)
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

    ! ---------------------------------------------------------------- interpolated blocks

    !> The cluster tree (contiguous elements halved by count down to leaf_max) and the
    !! admissible blocks (cx left of cy, gap >= block_ratio times the longer, and fewer kernel
    !! values than block_cost per element pair), listed by cy (blocked_rows).
    subroutine new_blocks(bx, cheb, tree)
        type(basis_t), intent(in) :: bx
        type(chebyshev_t), intent(in) :: cheb
        type(cluster_tree_t), intent(out) :: tree
        integer, allocatable :: next(:)
        integer :: c, n, mid, b
        allocate (tree%first(2*bx%ne), tree%last(2*bx%ne), tree%child(2, 2*bx%ne), &
                  tree%lo(2*bx%ne), tree%hi(2*bx%ne), tree%parent(2*bx%ne), tree%leaf_of(bx%ne))
        tree%n = 1
        tree%first(1) = 1
        tree%last(1) = bx%ne
        tree%parent(1) = 0
        c = 0
        grow: do while (c < tree%n)
            c = c + 1
            tree%lo(c) = bx%x(tree%first(c) - 1)
            tree%hi(c) = bx%x(tree%last(c))
            tree%child(:, c) = 0
            n = tree%last(c) - tree%first(c) + 1
            if (n <= leaf_max) then
                tree%leaf_of(tree%first(c):tree%last(c)) = c
                cycle grow
            end if
            mid = tree%first(c) + n/2 - 1
            tree%child(:, c) = [tree%n + 1, tree%n + 2]
            tree%parent(tree%n + 1:tree%n + 2) = c
            tree%first(tree%n + 1:tree%n + 2) = [tree%first(c), mid + 1]
            tree%last(tree%n + 1:tree%n + 2) = [mid, tree%last(c)]
            tree%n = tree%n + 2
        end do grow
        allocate (tree%blocks(4, 4*bx%ne))
        tree%n_blocks = 0
        call split_pair(1, 1)
        ! the blocks by cy (a counting sort)
        allocate (tree%cy_start(tree%n + 1), source=0)
        allocate (tree%by_cy(tree%n_blocks))
        count_cy: do b = 1, tree%n_blocks
            tree%cy_start(tree%blocks(2, b) + 1) = tree%cy_start(tree%blocks(2, b) + 1) + 1
        end do count_cy
        tree%cy_start(1) = 1
        offsets: do c = 1, tree%n
            tree%cy_start(c + 1) = tree%cy_start(c + 1) + tree%cy_start(c)
        end do offsets
        next = tree%cy_start(1:tree%n)
        place: do b = 1, tree%n_blocks
            c = tree%blocks(2, b)
            tree%by_cy(next(c)) = b
            next(c) = next(c) + 1
        end do place
    contains
        recursive subroutine split_pair(cx, cy)
            integer, intent(in) :: cx, cy
            real(dp) :: gap, len_x, len_y
            integer :: kx, ky, nx, ny, px, py
            if (cx == cy) then
                if (tree%child(1, cx) == 0) return
                call split_pair(tree%child(1, cx), tree%child(1, cx))
                call split_pair(tree%child(1, cx), tree%child(2, cx))
                call split_pair(tree%child(2, cx), tree%child(2, cx))
                return
            end if
            gap = tree%lo(cy) - tree%hi(cx)
            len_x = tree%hi(cx) - tree%lo(cx)
            len_y = tree%hi(cy) - tree%lo(cy)
            nx = tree%last(cx) - tree%first(cx) + 1
            ny = tree%last(cy) - tree%first(cy) + 1
            if (gap >= block_ratio*max(len_x, len_y)) then
                kx = order_for(cheb, gap/len_x)
                ky = order_for(cheb, gap/len_y)
                if (kx > 0 .and. ky > 0) then
                    px = orders(kx)
                    py = orders(ky)
                    if (real(px*py, dp) <= block_cost*real(nx*ny, dp)) then
                        if (tree%n_blocks == size(tree%blocks, 2)) call grow_blocks()
                        tree%n_blocks = tree%n_blocks + 1
                        tree%blocks(:, tree%n_blocks) = [cx, cy, kx, ky]
                        return
                    end if
                end if
            end if
            if (tree%child(1, cx) == 0 .and. tree%child(1, cy) == 0) return
            if (tree%child(1, cy) == 0 .or. (tree%child(1, cx) /= 0 .and. nx >= ny)) then
                call split_pair(tree%child(1, cx), cy)
                call split_pair(tree%child(2, cx), cy)
            else
                call split_pair(cx, tree%child(1, cy))
                call split_pair(cx, tree%child(2, cy))
            end if
        end subroutine split_pair

        subroutine grow_blocks()
            integer, allocatable :: more(:, :)
            allocate (more(4, 2*size(tree%blocks, 2)))
            more(:, 1:tree%n_blocks) = tree%blocks(:, 1:tree%n_blocks)
            call move_alloc(more, tree%blocks)
        end subroutine grow_blocks
    end subroutine new_blocks

    !> skip(e1) = the pair (e1, e2) is in a block: the blocks whose cy holds e2 are those of
    !! the ancestors of e2's leaf (each element pair is in at most one block).
    pure subroutine blocked_rows(tree, e2, skip)
        type(cluster_tree_t), intent(in) :: tree
        integer, intent(in) :: e2
        logical, intent(out) :: skip(:)
        integer :: c, q, cx
        skip = .false.
        c = tree%leaf_of(e2)
        ancestors: do while (c /= 0)
            blocks_of_c: do q = tree%cy_start(c), tree%cy_start(c + 1) - 1
                cx = tree%blocks(1, tree%by_cy(q))
                skip(tree%first(cx):tree%last(cx)) = .true.
            end do blocks_of_c
            c = tree%parent(c)
        end do ancestors
    end subroutine blocked_rows

    !> The moments of the functions of cluster c against its Lagrange polynomials of
    !! orders(k), with the field measure W (field side) and without (source side), over the
    !! part of their support in c: m(row, a) = int g W l_a, from the Chebyshev moments
    !! (chebyshev_moments) through l_a = (2/m) sum'_{q<m} T_q(t_a) T_q.
    subroutine cluster_moments(kernel, bx, cheb, tree, c, k, field, work, mark)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        type(chebyshev_t), intent(in) :: cheb
        type(cluster_tree_t), intent(inout) :: tree
        integer, intent(in) :: c, k
        logical, intent(in) :: field               !! the field side (c is the X of a block),
                                                   !! else the source side (the Y): only the
                                                   !! moments a block uses are formed
        type(work_t), intent(inout) :: work
        integer, intent(inout) :: mark(:)          !! zero on entry and exit
        integer :: p, i, n_rows
        if (field .and. allocated(tree%side(k, c)%field)) return
        if (.not. field .and. allocated(tree%side(k, c)%source)) return
        p = orders(k)
        call chebyshev_moments(kernel, bx, tree, c, work, mark)
        n_rows = size(tree%cheb_field(c)%a, 1)
        ! m(row, a) = sum_q mu(row, q) to_weights(a, q)
        if (field) then
            allocate (tree%side(k, c)%field(n_rows, p, tree%n_stored))
            field_moments: do i = 1, tree%n_stored
                call dgemm('N', 'T', n_rows, p, p, 1.0_dp, tree%cheb_field(c)%a(1, 1, i), &
                           n_rows, cheb%to_weights(1, 1, k), n_cheb, 0.0_dp, &
                           tree%side(k, c)%field(1, 1, i), n_rows)
            end do field_moments
        else
            allocate (tree%side(k, c)%source(n_rows, p, tree%n_stored))
            source_moments: do i = 1, tree%n_stored
                call dgemm('N', 'T', n_rows, p, p, 1.0_dp, tree%cheb_source(c)%a(1, 1, i), &
                           n_rows, cheb%to_weights(1, 1, k), n_cheb, 0.0_dp, &
                           tree%side(k, c)%source(1, 1, i), n_rows)
            end do source_moments
        end if
    end subroutine cluster_moments

    !> The functions of field i (1 = bx, 2 = bz) with support in cluster c (tree%rows: their
    !! global numbers, in order of first appearance) and their Chebyshev moments over the part
    !! of their support in c, int g W T_q and int g T_q (q < n_cheb, T_q across c): on a leaf
    !! by the moment_points GL rule on every element (exact: degree <= 2 + 1 + 27), on a parent
    !! from its children's, T_q of the parent being a polynomial of degree q on a child
    !! (chebyshev_transfer; exact, BLAS products).
    recursive subroutine chebyshev_moments(kernel, bx, tree, c, work, mark)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        type(cluster_tree_t), intent(inout) :: tree
        integer, intent(in) :: c
        type(work_t), intent(inout) :: work
        integer, intent(inout) :: mark(:)          !! zero on entry and exit
        real(dp) :: pf(n_loc, n_cheb, leaf_max), ps(n_loc, n_cheb, leaf_max)
        real(dp) :: s_mat(n_cheb, n_cheb, 2)
        real(dp), allocatable :: tmp(:, :)
        integer :: e, r, i, n, q, row, g, lo_r(2), hi_r(2), n_rows, j, ch, n_ch
        if (allocated(tree%cheb_field(c)%a)) return
        if (tree%child(1, c) /= 0) then
            call chebyshev_moments(kernel, bx, tree, tree%child(1, c), work, mark)
            call chebyshev_moments(kernel, bx, tree, tree%child(2, c), work, mark)
            call chebyshev_transfer(tree, c, tree%child(1, c), s_mat(:, :, 1))
            call chebyshev_transfer(tree, c, tree%child(2, c), s_mat(:, :, 2))
        end if
        lo_r = [1, bx%n_local + 1]
        hi_r = [bx%n_local, work%n_fun(1)]
        components: do i = 1, 2
            allocate (tree%rows(i, c)%glob(work%n_fun(1)*(tree%last(c) - tree%first(c) + 1)))
            n = 0
            cluster_elements: do e = tree%first(c), tree%last(c)
                local_functions: do r = lo_r(i), hi_r(i)
                    g = work%glob(r, e)
                    if (mark(g) /= 0) cycle local_functions
                    n = n + 1
                    mark(g) = n
                    tree%rows(i, c)%glob(n) = g
                end do local_functions
            end do cluster_elements
            tree%rows(i, c)%n = n
            mark(tree%rows(i, c)%glob(1:n)) = 0
        end do components
        n_rows = maxval(tree%rows(:, c)%n)
        allocate (tree%cheb_field(c)%a(n_rows, n_cheb, tree%n_stored), &
                  tree%cheb_source(c)%a(n_rows, n_cheb, tree%n_stored), source=0.0_dp)
        if (tree%child(1, c) == 0) call leaf_moments(kernel, bx, tree, c, work, pf, ps)
        fields: do i = 1, tree%n_stored
            n = tree%rows(i, c)%n
            mark(tree%rows(i, c)%glob(1:n)) = [(q, q=1, n)]
            if (tree%child(1, c) /= 0) then
                children: do j = 1, 2
                    ch = tree%child(j, c)
                    n_ch = tree%rows(i, ch)%n
                    allocate (tmp(n_ch, n_cheb))
                    call dgemm('N', 'N', n_ch, n_cheb, n_cheb, 1.0_dp, &
                               tree%cheb_field(ch)%a(1, 1, i), size(tree%cheb_field(ch)%a, 1), &
                               s_mat(1, 1, j), n_cheb, 0.0_dp, tmp, n_ch)
                    do r = 1, n_ch
                        row = mark(tree%rows(i, ch)%glob(r))
                        tree%cheb_field(c)%a(row, :, i) = tree%cheb_field(c)%a(row, :, i) + &
                                                          tmp(r, :)
                    end do
                    call dgemm('N', 'N', n_ch, n_cheb, n_cheb, 1.0_dp, &
                               tree%cheb_source(ch)%a(1, 1, i), &
                               size(tree%cheb_source(ch)%a, 1), s_mat(1, 1, j), n_cheb, 0.0_dp, &
                               tmp, n_ch)
                    do r = 1, n_ch
                        row = mark(tree%rows(i, ch)%glob(r))
                        tree%cheb_source(c)%a(row, :, i) = tree%cheb_source(c)%a(row, :, i) + &
                                                           tmp(r, :)
                    end do
                    deallocate (tmp)
                end do children
                mark(tree%rows(i, c)%glob(1:n)) = 0
                cycle fields
            end if
            elements: do e = tree%first(c), tree%last(c)
                associate (mf => tree%cheb_field(c)%a, ms => tree%cheb_source(c)%a, &
                           k => e - tree%first(c) + 1)
                    do r = lo_r(i), hi_r(i)
                        row = mark(work%glob(r, e))
                        mf(row, :, i) = mf(row, :, i) + pf(r, :, k)
                        ms(row, :, i) = ms(row, :, i) + ps(r, :, k)
                    end do
                end associate
            end do elements
            mark(tree%rows(i, c)%glob(1:n)) = 0
        end do fields
    end subroutine chebyshev_moments

    !> The Chebyshev moments over each element of leaf cluster c of its local functions,
    !! pf(r, q + 1, k) = int g_r W T_q and ps(r, q + 1, k) = int g_r T_q on the k-th element of
    !! the leaf (moment_points GL, exact: see chebyshev_moments); T_q at the nodes once per
    !! element, a function that repeats an earlier one (bx and bz of one family) copied.
    subroutine leaf_moments(kernel, bx, tree, c, work, pf, ps)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        type(cluster_tree_t), intent(in) :: tree
        integer, intent(in) :: c
        type(work_t), intent(inout) :: work
        real(dp), intent(out) :: pf(:, :, :), ps(:, :, :)   !! (n_loc, n_cheb, leaf_max)
        integer, parameter :: np = moment_points
        real(dp) :: x(np), bf(np, n_loc), bs(np, n_loc), t(np), tq(np, n_cheb), scale, mid
        integer :: e, r, q, k
        scale = 2.0_dp/(tree%hi(c) - tree%lo(c))
        mid = 0.5_dp*(tree%lo(c) + tree%hi(c))
        elements: do e = tree%first(c), tree%last(c)
            k = e - tree%first(c) + 1
            call element_nodes(kernel, bx, work, np, e, x, bf, bs)
            t = scale*(x - mid)
            tq(:, 1) = 1.0_dp
            tq(:, 2) = t
            do q = 3, n_cheb
                tq(:, q) = 2.0_dp*t*tq(:, q - 1) - tq(:, q - 2)
            end do
            functions: do r = 1, work%n_fun(e)
                if (work%same(r, e) /= r) then
                    pf(r, :, k) = pf(work%same(r, e), :, k)
                    ps(r, :, k) = ps(work%same(r, e), :, k)
                    cycle functions
                end if
                pf(r:r, :, k) = matmul(transpose(bf(:, r:r)), tq)
                ps(r:r, :, k) = matmul(transpose(bs(:, r:r)), tq)
            end do functions
        end do elements
    end subroutine leaf_moments

    !> s(k + 1, q + 1): the coefficient of T_k of child ch in T_q of its parent c (q, k <
    !! n_cheb), t_parent = alpha t_child + beta: by T_(q+1) = 2 (alpha t + beta) T_q - T_(q-1)
    !! on the coefficients, t T_0 = T_1, t T_k = (T_(k+1) + T_(k-1))/2.
    pure subroutine chebyshev_transfer(tree, c, ch, s)
        type(cluster_tree_t), intent(in) :: tree
        integer, intent(in) :: c, ch
        real(dp), intent(out) :: s(n_cheb, n_cheb)
        real(dp) :: alpha, beta, tc(n_cheb + 1)
        integer :: q, k
        alpha = (tree%hi(ch) - tree%lo(ch))/(tree%hi(c) - tree%lo(c))
        beta = ((tree%hi(ch) + tree%lo(ch)) - (tree%hi(c) + tree%lo(c)))/(tree%hi(c) - tree%lo(c))
        s = 0.0_dp
        s(1, 1) = 1.0_dp
        s(1, 2) = beta
        s(2, 2) = alpha
        degrees: do q = 2, n_cheb - 1
            ! tc = t * (column q of s) in the child's basis
            tc = 0.0_dp
            tc(2) = s(1, q)
            times_t: do k = 2, q
                tc(k + 1) = tc(k + 1) + 0.5_dp*s(k, q)
                tc(k - 1) = tc(k - 1) + 0.5_dp*s(k, q)
            end do times_t
            s(:, q + 1) = 2.0_dp*(alpha*tc(1:n_cheb) + beta*s(:, q)) - s(:, q - 1)
        end do degrees
    end subroutine chebyshev_transfer

    !> The bz functions repeat the bx functions on every element (work%same): the two fields'
    !! moments are the same numbers (cluster_tree_t%n_stored).
    pure logical function repeated_fields(bx, work)
        type(basis_t), intent(in) :: bx
        type(work_t), intent(in) :: work
        integer :: e, r
        repeated_fields = .false.
        elements: do e = 1, size(work%n_fun)
            if (work%n_fun(e) /= 2*bx%n_local) return
            functions: do r = 1, bx%n_local
                if (work%same(bx%n_local + r, e) /= r) return
            end do functions
        end do elements
        repeated_fields = .true.
    end function repeated_fields

    !> Add the admissible blocks to T (A of T = A + A^T), one after the other: the kernel at
    !! the px x py Chebyshev points of the two clusters, and the block of each diagonal
    !! component Mx K My^T by two products (BLAS); the constant coupling components in
    !! closed form element pair by element pair (as contract_fields).
    subroutine add_blocks(kernel, bx, cheb, tree, work, t_mat, err)
        class(split_kernel_t), intent(in) :: kernel
        type(basis_t), intent(in) :: bx
        type(chebyshev_t), intent(in) :: cheb
        type(cluster_tree_t), intent(inout) :: tree
        type(work_t), intent(inout) :: work
        real(dp), intent(inout) :: t_mat(:, :)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: g(n_cheb, n_cheb, 2, 2), gx(n_cheb), gy(n_cheb)
        real(dp), allocatable :: cy_mat(:, :), l_mat(:, :)
        integer, allocatable :: mark(:)
        integer :: b, cx, cy, kx, ky, px, py, i, nx, ny, jj, j
        allocate (mark(size(t_mat, 1)), source=0)
        allocate (tree%side(n_orders, tree%n), tree%rows(2, tree%n), tree%cheb_field(tree%n), &
                  tree%cheb_source(tree%n))
        allocate (cy_mat(n_cheb, 64), l_mat(64, 64))
        tree%n_stored = 2
        if (repeated_fields(bx, work)) tree%n_stored = 1
        blocks: do b = 1, tree%n_blocks
            cx = tree%blocks(1, b)
            cy = tree%blocks(2, b)
            kx = tree%blocks(3, b)
            ky = tree%blocks(4, b)
            px = orders(kx)
            py = orders(ky)
            call cluster_moments(kernel, bx, cheb, tree, cx, kx, .true., work, mark)
            call cluster_moments(kernel, bx, cheb, tree, cy, ky, .false., work, mark)
            gx(1:px) = 0.5_dp*(tree%lo(cx) + tree%hi(cx)) + &
                       0.5_dp*(tree%hi(cx) - tree%lo(cx))*cheb%cosines(1:px, kx)
            gy(1:py) = 0.5_dp*(tree%lo(cy) + tree%hi(cy)) + &
                       0.5_dp*(tree%hi(cy) - tree%lo(cy))*cheb%cosines(1:py, ky)
            call kernel%grid_values(gx(1:px), gy(1:py), g(1:px, 1:py, :, :), err)
            if (allocated(err)) return
            work%n_kernel = work%n_kernel + int(px*py, int64)
            components: do i = 1, 2
                nx = tree%rows(i, cx)%n
                ny = tree%rows(i, cy)%n
                if (size(cy_mat, 2) < ny) then
                    deallocate (cy_mat)
                    allocate (cy_mat(n_cheb, 2*ny))
                end if
                if (size(l_mat, 1) < nx .or. size(l_mat, 2) < ny) then
                    deallocate (l_mat)
                    allocate (l_mat(2*nx, 2*ny))
                end if
                ! K My^T (px x ny), then Mx (K My^T) (nx x ny)
                call dgemm('N', 'T', px, ny, py, 1.0_dp, g(1, 1, i, i), n_cheb, &
                           tree%side(ky, cy)%source(1, 1, min(i, tree%n_stored)), &
                           size(tree%side(ky, cy)%source, 1), 0.0_dp, cy_mat, size(cy_mat, 1))
                call dgemm('N', 'N', nx, ny, px, 1.0_dp, &
                           tree%side(kx, cx)%field(1, 1, min(i, tree%n_stored)), &
                           size(tree%side(kx, cx)%field, 1), cy_mat, size(cy_mat, 1), 0.0_dp, &
                           l_mat, size(l_mat, 1))
                associate (rows => tree%rows(i, cx)%glob, cols => tree%rows(i, cy)%glob)
                    columns: do jj = 1, ny
                        t_mat(rows(1:nx), cols(jj)) = t_mat(rows(1:nx), cols(jj)) + &
                                                      l_mat(1:nx, jj)
                    end do columns
                end associate
            end do components
            if (.not. kernel%constant_coupling) cycle blocks
            ! the coupling F_ij (i /= j) is constant: its block is F_ij (int g_r W) (int g_c),
            ! the moments q = 0 over the parts of the supports in cx and cy
            couplings: do i = 1, 2
                j = 3 - i
                if (kernel%coupling(i) == 0.0_dp) cycle couplings
                nx = tree%rows(i, cx)%n
                ny = tree%rows(j, cy)%n
                associate (rows => tree%rows(i, cx)%glob, cols => tree%rows(j, cy)%glob, &
                           mx => tree%cheb_field(cx)%a(:, 1, min(i, tree%n_stored)), &
                           my => tree%cheb_source(cy)%a(:, 1, min(j, tree%n_stored)))
                    coupling_columns: do jj = 1, ny
                        t_mat(rows(1:nx), cols(jj)) = t_mat(rows(1:nx), cols(jj)) + &
                            (kernel%coupling(i)*mx(1:nx))*my(jj)
                    end do coupling_columns
                end associate
            end do couplings
        end do blocks
    end subroutine add_blocks
end module galerkin_assembly
