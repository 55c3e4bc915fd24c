!> The discrete contact problem (paper 4.2, SPEC §4) as data: the interface Gauss points, the
!! set-independent matrix, and the residual and generalised Jacobian of the complete problem.
!!
!! z = [v; r] (displacement, then traction coefficients). The complete problem is
!!   F(z) = A0 z - [q; 0] + N(r) = 0,
!!   N_x = - c (eps - eps0) S0 r_x - c kappa sum_p w_p g(p) (|sigma_x| - tau0)^+ sign(sigma_x)
!!   N_z = - (c/eta_bar) sum_p w_p h(p) min(sigma_z, 0),       tau0 = f max(sigma_z, 0)
!! with A0 = [K M^T; M -(T + c eps0 S0)] assembled once (eps0 the deck's eps_bar), kappa =
!! (1 - eps^2)/eps, g / h the sigma_x / sigma_z basis functions at Gauss point p and w_p its
!! weight (times 2 pi r for the plate). The law at a point is that of `interface_law`; a
!! regularisation other than the deck's (law_t) serves the continuation of the Newton method.
!! Constrained unknowns (d%fixed) have the equation z_i = 0.
module contact_system
    use iso_fortran_env, only: int64
    use kinds, only: dp, pi
    use double_double, only: two_sum
    use errors, only: error_t, add_context
    use quadrature, only: gauss_legendre
    use shape_functions, only: eval_basis, max_local, basis_t, INTERP_P2, INTERP_S2
    use model, only: interface_t, structure_t, model_t, MODEL_BEAM, FIELD_U, FIELD_W, FIELD_PSI, &
        FIELD_SX, FIELD_SZ, &
                     friction_compliance
    use discretization, only: discretization_t
    use mindlin_structure, only: section_of, stiffness_entries, assemble_loads, &
                                 coupling_entries
    use flexibility_cache, only: flexibility_cache_t, flexibility_of
    use nested_spaces, only: restricted_tractions
    use interface_law, only: friction_threshold, slip_excess, tensile_part, threshold_slope, &
                             is_slipping, in_tension
    use rigid_body, only: rigid_t, new_rigid, to_rigid_coordinates
    use sparse_matrix, only: columns_t, triplets_t, compressed, transposed, triplets_of, &
                             columns_times, columns_times_double_double, dense_column, &
                             scatter_column, &
                             pack_lower, packed_times, packed_column, packed_entry, &
                             packed_position
    implicit none
    private

    !> Gauss points of the interface where the sets are decided (paper 4.6–4.7), with the
    !! traction basis there.
    type, public :: contact_points_t
        integer :: n = 0
        integer, allocatable :: elem(:)
        real(dp), allocatable :: xi(:), x(:)
        real(dp), allocatable :: wt(:)       !! Gauss weight * Jacobian (* 2 pi r for the plate)
        integer :: nl(2) = 0                 !! basis functions per point: sigma_x, sigma_z
        integer, allocatable :: idx(:, :, :) !! (max_local, 2, n): global unknowns (x, z field)
        real(dp), allocatable :: val(:, :, :)  !! (max_local, 2, n): basis values
    end type contact_points_t

    !> One line of the solver log.
    type, public :: iteration_record_t
        integer :: outer = 0, inner = 0
        integer :: n_slip = 0, n_tension = 0, n_changed = 0
        real(dp) :: increment = 0.0_dp       !! relative change of the solution
        real(dp) :: residual = -1.0_dp       !! relative residual of (4.2)
        character(len=40) :: note = ''
    end type iteration_record_t

    !> The solution of the case on a nested coarser mesh (the Newton start, contact_solver):
    !! kept so that the error estimate need not solve that mesh again.
    type, public :: coarse_solution_t
        real(dp), allocatable :: x(:)        !! the mesh nodes x(0:ne)
        real(dp), allocatable :: z(:)        !! [v; r], physical units
        real(dp) :: admissibility = 0.0_dp   !! as in solution_t
        real(dp) :: reaction(3) = 0.0_dp
        real(dp) :: applied(3) = 0.0_dp
        integer :: n_solves = 0
    end type coarse_solution_t

    !> The converged state of one case and how it was reached.
    type, public :: solution_t
        real(dp), allocatable :: z(:)        !! [v; r], physical units
        real(dp), allocatable :: z_lo(:)     !! z + z_lo: the solution held in double-double
                                             !! by the Newton method's final refinement, in
                                             !! the solver's (rigid) coordinates; none after
                                             !! z is mapped back to absolute ones
        real(dp), allocatable :: tau0(:)     !! friction threshold at the contact points
        integer, allocatable :: state(:)     !! STATE_* at the contact points (reported)
        logical, allocatable :: slip(:)      !! slip set (paper 4.6a/4.7a): |sigma_x| > tau0
        logical, allocatable :: tension(:)   !! tension set (paper 4.6b/4.7b): sigma_z <= 0
        real(dp), allocatable :: sigma(:, :) !! (sigma_x, sigma_z) at the contact points
        type(contact_points_t) :: pts
        type(iteration_record_t), allocatable :: history(:)
        character(len=8) :: method = ''      !! NEWTON or TWOLOOP
        integer :: n_outer = 0, n_inner = 0
        integer :: n_solves = 0              !! linear solves of the case
        integer :: n_nested_solves = 0       !! linear solves on the nested coarser meshes
                                             !! that gave the Newton start (contact_solver)
        type(coarse_solution_t), allocatable :: coarse(:)  !! the nested coarser meshes'
                                             !! solutions, finest first (none: not nested)
        real(dp) :: seconds(5) = 0.0_dp      !! wall time [s] of: T (assembled, or given, and
                                             !! its restriction to the nested mesh); the rest
                                             !! of the system (K, M, B0, loads); the nested start;
                                             !! the iterations; the final checks
        integer :: progress_unit = -1        !! >= 0: each Newton step also reported there
                                             !! (the caller's progress for a big case)
        integer :: n_factorisations = 0      !! matrix factorisations among them (Newton: the
                                             !! others reuse one by a low-rank update)
        integer :: n_decoupled_steps = 0     !! Newton steps whose factorisation decoupled the
                                             !! settled lift-off tractions (schur_solver)
        integer :: decoupled(2) = 0          !! the most decoupled in one step, of the kept
                                             !! unknowns then
        real(dp) :: residual(2) = 0.0_dp     !! relative residuals of equations 4.2a, 4.2b
        real(dp) :: law_residual = 0.0_dp    !! 4.2b of the complete problem as a traction error
        real(dp) :: reaction(3) = 0.0_dp     !! int sigma_z, int sigma_x, moment (beam)
        real(dp) :: applied(3) = 0.0_dp      !! the same of the loads
        real(dp) :: admissibility = 0.0_dp   !! max(|sigma_x| - f sigma_z) over contact points
        real(dp) :: min_sigma_z = 0.0_dp     !! most tensile sigma_z (penalty, O(eta_bar))
    end type solution_t

    !> Regularisation of the interface law: the deck's, or a stage of a continuation.
    type, public :: law_t
        real(dp) :: f = 0.0_dp               !! friction coefficient
        real(dp) :: eps = 1.0e-6_dp          !! eps_bar
        real(dp) :: slip = 0.0_dp            !! c kappa = c (1 - eps^2)/eps
        real(dp) :: penalty = 0.0_dp         !! c / eta_bar
    end type law_t

    !> The set-independent data of one case. The base matrix A0 = [K M^T; M B0] is held by
    !! blocks (sparse_matrix): K and M by their nonzeros, B0 = -(T + c eps0 S0) (symmetric,
    !! dense) by its lower triangle; a dense A0 is formed only for the methods that need one
    !! (a0_dense: the two-loop method, the dense fallback of the Newton method).
    type, public :: system_t
        type(columns_t) :: k                 !! K (nv x nv)
        type(columns_t) :: mm                !! M (nr x nv)
        type(columns_t) :: mt                !! M^T (nv x nr)
        real(dp), allocatable :: b0(:)       !! B0 (nr x nr), packed lower triangle
        real(dp), allocatable :: q(:)        !! structural loads
        real(dp), allocatable :: row_scale(:)  !! 1/sqrt|diag a0|: fixed scaling of the residual
        real(dp) :: c = 0.0_dp, kappa = 0.0_dp, penalty = 0.0_dp
        type(law_t) :: law                   !! the deck's law
        type(rigid_t) :: rigid               !! the structure's rigid-body modes (K R = 0)
        logical :: rigid_coordinates = .false.  !! K, M, q (and the solvers' z) in rigid
                                                !! coordinates (rigid_body), else absolute
        integer :: nv = 0                    !! displacement unknowns
        integer :: nr = 0                    !! traction unknowns
        real(dp) :: t_seconds = 0.0_dp       !! wall time of T: its assembly (or none when
                                             !! given), and its restriction to a nested mesh [s]
    end type system_t

    public :: build_system, add_point_mass, contact_points, new_law, relative_change
    public :: point_tractions, complete_residual, complete_jacobian, scaled_norm
    public :: jacobian_with_terms
    public :: jacobian_diagonal, linear_part, set_terms, a0_times, set_base_matrix, &
              a0_lower_column
    public :: equilibrium_residual
    public :: use_rigid_coordinates, a0_column, a0_dense, a0_diagonal, diagonal_scaling

    !> Set-dependent entries of the Jacobian (global unknown numbers).
    type, public :: set_terms_t
        integer :: n = 0                     !! entries in use
        integer, allocatable :: first(:)     !! contact point p has entries first(p):first(p+1)-1
        integer, allocatable :: row(:), col(:)
        real(dp), allocatable :: val(:)
        logical :: symmetric = .true.        !! no d tau0/d sigma_z block
    end type set_terms_t

contains

    !> K, M, T, S0 and q assembled once per case into the base matrix.
    subroutine build_system(m, d, pts, sys, err, t_given, nested, t_nested, cache)
        type(model_t), intent(in) :: m                           !! the model
        type(discretization_t), intent(in) :: d                  !! the discretisation
        type(contact_points_t), intent(in) :: pts                !! the contact points
        type(system_t), intent(out) :: sys                       !! the assembled system (A0, q)
        type(error_t), allocatable, intent(out) :: err           !! allocated on failure
        !> T of d, restricted from a finer mesh (nested_spaces): moved in, not assembled
        real(dp), allocatable, intent(inout), optional :: t_given(:, :)
        type(discretization_t), intent(in), optional :: nested   !! a mesh nested in d, and
        !> its T (P^T T P). inout, not out (doc/CHOICES.md, "intent(inout) of t_nested")
        real(dp), allocatable, intent(inout), optional :: t_nested(:, :)
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        real(dp), allocatable :: t_mat(:, :), b0(:)
        integer :: i
        integer(int64) :: t0, t1, rate
        call system_clock(t0, rate)
        if (present(t_given)) then
            call move_alloc(t_given, t_mat)
        else
            call flexibility_of(m, d, t_mat, err, cache)    ! assembled, or a cached copy
        end if
        if (.not. allocated(err) .and. present(nested) .and. present(t_nested)) &
            call restricted_tractions(t_mat, d, nested, t_nested, err)
        call system_clock(t1)
        sys%t_seconds = real(t1 - t0, dp)/real(rate, dp)
        if (allocated(err)) then
            call add_context(err, 'assembling the half-space flexibility T')
            return
        end if
        allocate (sys%q(d%nv))
        call assemble_loads(m, d, sys%q, err)
        if (allocated(err)) return
        sys%c = friction_compliance(m%structure, m%ground)
        sys%law = new_law(m%interface, sys%c, m%interface%eps_bar, m%interface%eta_bar)
        sys%rigid = rigid_modes(m%structure, d)
        sys%kappa = (1.0_dp - m%interface%eps_bar**2)/m%interface%eps_bar
        sys%penalty = sys%law%penalty
        ! B0 = -(T + c eps S0): S0 the stick branch of the law, everywhere
        t_mat = -t_mat
        do i = 1, pts%n
            call add_point_mass(pts, i, 1, -sys%c*m%interface%eps_bar, t_mat, d%nv)
        end do
        call pack_lower(t_mat, b0)
        deallocate (t_mat)
        call set_base_matrix(sys, d%nv, stiffness_entries(section_of(m%structure), d), &
                             coupling_entries(m%structure, d), b0)
        sys%row_scale = diagonal_scaling(a0_diagonal(sys))
    end subroutine build_system

    !> The base matrix from the entries of K and M and the packed B0 (moved in).
    subroutine set_base_matrix(sys, nv, k, mm, b0)
        type(system_t), intent(inout) :: sys            !! the assembled system, changed in place
        integer, intent(in) :: nv                       !! displacement unknowns
        type(triplets_t), intent(in) :: k, mm           !! the entries of K and of M
        real(dp), allocatable, intent(inout) :: b0(:)   !! B0, packed lower triangle (moved in)
        sys%nv = nv
        sys%nr = mm%nrow
        sys%k = compressed(k)
        sys%mm = compressed(mm)
        sys%mt = transposed(sys%mm)
        if (allocated(b0)) call move_alloc(b0, sys%b0)
    end subroutine set_base_matrix

    !> 1/sqrt|a_ii| (1 where a_ii = 0): the fixed row scaling of the residual.
    pure function diagonal_scaling(dg) result(scale)
        real(dp), intent(in) :: dg(:)   !! the diagonal of A0
        real(dp) :: scale(size(dg))
        scale = 1.0_dp
        where (dg /= 0.0_dp) scale = 1.0_dp/sqrt(abs(dg))
    end function diagonal_scaling

    !> The rigid-body modes of the structure: the translation of w (plate), and for the beam
    !! also the translation of u_s and the rotation psi = 1, w = x.
    pure function rigid_modes(structure, d) result(rb)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d
        type(rigid_t) :: rb
        integer :: w_range(2), u_range(2), psi_range(2)
        w_range = [d%offset(FIELD_W) + 1, d%offset(FIELD_W) + d%basis(FIELD_W)%n_dof]
        if (structure%kind /= MODEL_BEAM) then
            rb = new_rigid(d%nv, reshape(w_range, [2, 1]), [0, 0])
            return
        end if
        u_range = [d%offset(FIELD_U) + 1, d%offset(FIELD_U) + d%basis(FIELD_U)%n_dof]
        psi_range = [d%offset(FIELD_PSI) + 1, d%offset(FIELD_PSI) + d%basis(FIELD_PSI)%n_dof]
        rb = new_rigid(d%nv, reshape([w_range, u_range], [2, 2]), psi_range, &
                       linear_coefficients(d%basis(FIELD_W)))
    end function rigid_modes

    !> Change A0 and q to rigid coordinates (rigid_body; once, before a method solves): the
    !! methods then solve for z in rigid coordinates, which to_absolute maps back. The row
    !! scaling stays that of the absolute coordinates.
    subroutine use_rigid_coordinates(sys)
        type(system_t), intent(inout) :: sys   !! the assembled system, changed in place
        type(triplets_t) :: k, mm
        real(dp), allocatable :: no_b0(:)
        if (sys%rigid_coordinates) return
        k = triplets_of(sys%k, 0)
        mm = triplets_of(sys%mm, sys%rigid%np*sys%nr)
        call to_rigid_coordinates(sys%rigid, k, mm, sys%q)
        call set_base_matrix(sys, sys%nv, k, mm, no_b0)
        sys%rigid_coordinates = .true.
    end subroutine use_rigid_coordinates

    !> A0 times x_top in the displacement rows and times x_bottom in the traction rows.
    pure function a0_times(sys, x_top, x_bottom) result(y)
        type(system_t), intent(in) :: sys   !! the assembled system (A0, q)
        !> the displacement and the traction part of x
        real(dp), intent(in) :: x_top(:), x_bottom(:)
        real(dp) :: y(size(x_top))
        associate (nv => sys%nv)
            y(1:nv) = columns_times(sys%k, x_top(1:nv)) + columns_times(sys%mt, x_top(nv + 1:))
            y(nv + 1:) = columns_times(sys%mm, x_bottom(1:nv)) &
                         + packed_times(sys%b0, x_bottom(nv + 1:))
        end associate
    end function a0_times

    !> Column j of A0.
    pure function a0_column(sys, j) result(col)
        type(system_t), intent(in) :: sys   !! the assembled system (A0, q)
        integer, intent(in) :: j            !! the column
        real(dp) :: col(sys%nv + sys%nr)
        associate (nv => sys%nv)
            if (j <= nv) then
                col(1:nv) = dense_column(sys%k, j)
                col(nv + 1:) = dense_column(sys%mm, j)
            else
                col(1:nv) = dense_column(sys%mt, j - nv)
                col(nv + 1:) = packed_column(sys%b0, sys%nr, j - nv)
            end if
        end associate
    end function a0_column

    !> Column j of A0 without the part of B0 above the diagonal (those rows are 0), written
    !! into col, which is zero on entry; the same call with clear makes it zero again. The
    !! Schur set-up reads every column of A0 once or twice: writing only the nonzeros, not n
    !! rows per column (an O(n^2) memset, a tenth of the plate's solve at N_e = 1000), is why
    !! col is the caller's. The upper part of a packed column is a strided gather, which cost
    !! more than the Schur complement's other set-up work at N_e = 1000
    !! (output/bench/linalg_before_after.md): the rows below j are what is read.
    pure subroutine a0_lower_column(sys, j, col, clear)
        type(system_t), intent(in) :: sys   !! the assembled system (A0, q)
        integer, intent(in) :: j            !! the column
        real(dp), intent(inout) :: col(:)   !! (nv + nr), zero on entry
        logical, intent(in) :: clear        !! zero the column's entries instead of writing them
        associate (nv => sys%nv)
            if (j <= nv) then
                call scatter_column(sys%k, j, col(1:nv), clear)
                call scatter_column(sys%mm, j, col(nv + 1:), clear)
            else
                call scatter_column(sys%mt, j - nv, col(1:nv), clear)
                if (clear) then
                    col(j:) = 0.0_dp
                else
                    col(j:) = sys%b0(packed_position(sys%nr, j - nv, j - nv): &
                                     packed_position(sys%nr, sys%nr, j - nv))
                end if
            end if
        end associate
    end subroutine a0_lower_column


    !> A0 as a dense array (n^2 numbers: only for the methods that factorise it whole).
    pure function a0_dense(sys) result(a)
        type(system_t), intent(in) :: sys   !! the assembled system (A0, q)
        real(dp), allocatable :: a(:, :)
        integer :: j
        allocate (a(sys%nv + sys%nr, sys%nv + sys%nr))
        do j = 1, size(a, 2)
            a(:, j) = a0_column(sys, j)
        end do
    end function a0_dense

    !> The diagonal of A0.
    pure function a0_diagonal(sys) result(dg)
        type(system_t), intent(in) :: sys   !! the assembled system (A0, q)
        real(dp) :: dg(sys%nv + sys%nr)
        integer :: j
        do j = 1, sys%nv
            dg(j) = sum(sys%k%val(sys%k%ptr(j):sys%k%ptr(j + 1) - 1), &
                        mask=sys%k%row(sys%k%ptr(j):sys%k%ptr(j + 1) - 1) == j)
        end do
        do j = 1, sys%nr
            dg(sys%nv + j) = packed_entry(sys%b0, sys%nr, j, j)
        end do
    end function a0_diagonal

    !> The law with regularisation eps_bar = eps, penalty parameter eta_bar = eta.
    pure function new_law(interface, c, eps, eta) result(law)
        type(interface_t), intent(in) :: interface   !! the interface part of the model
        real(dp), intent(in) :: c      !! friction compliance (model.f90)
        real(dp), intent(in) :: eps    !! eps_bar of the friction law
        real(dp), intent(in) :: eta    !! eta_bar of the penalty
        type(law_t) :: law
        law%f = interface%f
        law%eps = eps
        law%slip = c*(1.0_dp - eps**2)/eps
        law%penalty = c/eta
    end function new_law

    !> a(i,j) += factor * wt g_i g_j at contact point p for traction field k (1: x, 2: z);
    !! a holds the unknowns from shift + 1 on (default 0: all of them).
    pure subroutine add_point_mass(pts, p, k, factor, a, shift)
        type(contact_points_t), intent(in) :: pts   !! the contact points
        integer, intent(in) :: p, k                 !! contact point, traction field (1: x, 2: z)
        real(dp), intent(in) :: factor              !! the factor of wt g_i g_j
        real(dp), intent(inout) :: a(:, :)          !! the matrix added to
        integer, intent(in), optional :: shift      !! a(1, 1) is unknown shift + 1
        integer :: i, j, s
        s = 0
        if (present(shift)) s = shift
        associate (idx => pts%idx(:, k, p) - s, val => pts%val(:, k, p))
            do j = 1, pts%nl(k)
                do i = 1, pts%nl(k)
                    a(idx(i), idx(j)) = a(idx(i), idx(j)) + factor*pts%wt(p)*val(i)*val(j)
                end do
            end do
        end associate
    end subroutine add_point_mass

    !> Gauss points per element: (highest traction degree + 1), exact for the masses.
    pure function contact_points(structure, d) result(pts)
        type(structure_t), intent(in) :: structure   !! the structure part of the model
        type(discretization_t), intent(in) :: d      !! the discretisation
        type(contact_points_t) :: pts
        real(dp), allocatable :: xg(:), wg(:)
        integer :: ng, e, g, p
        real(dp) :: h
        ng = max(d%basis(FIELD_SX)%degree, d%basis(FIELD_SZ)%degree) + 1
        allocate (xg(ng), wg(ng))
        call gauss_legendre(ng, xg, wg)
        pts%n = ng*d%msh%ne
        allocate (pts%elem(pts%n), pts%xi(pts%n), pts%x(pts%n), pts%wt(pts%n))
        p = 0
        elements: do e = 1, d%msh%ne
            h = d%msh%x(e) - d%msh%x(e - 1)
            gauss_points: do g = 1, ng
                p = p + 1
                pts%elem(p) = e
                pts%xi(p) = xg(g)
                pts%x(p) = d%msh%x(e - 1) + 0.5_dp*(xg(g) + 1.0_dp)*h
                pts%wt(p) = 0.5_dp*wg(g)*h
                if (structure%kind /= MODEL_BEAM) pts%wt(p) = pts%wt(p)*2.0_dp*pi*pts%x(p)
            end do gauss_points
        end do elements
        call tabulate_basis(d, pts)
    end function contact_points

    !> The traction basis at every contact point, with global unknown numbers.
    pure subroutine tabulate_basis(d, pts)
        type(discretization_t), intent(in) :: d
        type(contact_points_t), intent(inout) :: pts
        integer, parameter :: fields(2) = [FIELD_SX, FIELD_SZ]
        integer :: p, k, idx(max_local)
        real(dp) :: val(max_local), der(max_local), x
        allocate (pts%idx(max_local, 2, pts%n), pts%val(max_local, 2, pts%n))
        pts%idx = 1
        pts%val = 0.0_dp
        do k = 1, 2
            pts%nl(k) = d%basis(fields(k))%n_local
            points: do p = 1, pts%n
                call eval_basis(d%basis(fields(k)), pts%elem(p), pts%xi(p), idx, val, der, x)
                pts%idx(1:pts%nl(k), k, p) = idx(1:pts%nl(k)) + d%offset(fields(k))
                pts%val(1:pts%nl(k), k, p) = val(1:pts%nl(k))
            end do points
        end do
    end subroutine tabulate_basis

    !> (sigma_x, sigma_z) at every contact point for the unknowns z = [v; r].
    pure function point_tractions(pts, z) result(sigma)
        type(contact_points_t), intent(in) :: pts   !! the contact points
        real(dp), intent(in) :: z(:)                !! the unknowns [v; r]
        real(dp) :: sigma(2, pts%n)
        integer :: p, k, i
        ! scalar loops: z(idx(...)) as an array section makes a temporary per point
        do p = 1, pts%n
            do k = 1, 2
                sigma(k, p) = 0.0_dp
                do i = 1, pts%nl(k)
                    sigma(k, p) = sigma(k, p) + pts%val(i, k, p)*z(pts%idx(i, k, p))
                end do
            end do
        end do
    end function point_tractions

    !> res += the interface terms N(r) of the complete problem for the tractions sigma.
    pure subroutine add_interface_terms(sys, law, pts, sigma, res)
        type(system_t), intent(in) :: sys
        type(law_t), intent(in) :: law
        type(contact_points_t), intent(in) :: pts
        real(dp), intent(in) :: sigma(:, :)
        real(dp), intent(inout) :: res(:)
        real(dp) :: f(2), tau0
        integer :: p, k, i
        points: do p = 1, pts%n
            tau0 = friction_threshold(law%f, sigma(2, p))
            f(1) = -sys%c*(law%eps - sys%law%eps)*sigma(1, p) &
                   - law%slip*slip_excess(sigma(1, p), tau0)
            f(2) = -law%penalty*tensile_part(sigma(2, p))
            ! scalar loops, as in point_tractions
            do k = 1, 2
                do i = 1, pts%nl(k)
                    res(pts%idx(i, k, p)) = res(pts%idx(i, k, p)) + f(k)*pts%wt(p)*pts%val(i, k, p)
                end do
            end do
        end do points
    end subroutine add_interface_terms

    !> F(z) of the complete problem for the law `law`; lin = A0 z - [q; 0] may be passed
    !! when known (the line search evaluates F along a ray from its affine part).
    pure subroutine complete_residual(d, sys, law, pts, z, res, lin)
        type(discretization_t), intent(in) :: d     !! the discretisation
        type(system_t), intent(in) :: sys           !! the assembled system (A0, q)
        type(law_t), intent(in) :: law              !! the interface law of this stage
        type(contact_points_t), intent(in) :: pts   !! the contact points
        real(dp), intent(in) :: z(:)                !! the unknowns [v; r]
        real(dp), intent(out) :: res(:)             !! F(z)
        real(dp), intent(in), optional :: lin(:)    !! A0 z - [q; 0], when known
        if (present(lin)) then
            res = lin
        else
            res = linear_part(d, sys, z)
            res(1:d%nv) = res(1:d%nv) - sys%q
        end if
        call add_interface_terms(sys, law, pts, point_tractions(pts, z), res)
        res(d%fixed) = z(d%fixed)
    end subroutine complete_residual

    !> The displacement rows of F (4.2a, the structure's equilibrium K v + M^T r - q) at
    !! z + z_lo, K (v + v_lo) summed in double-double (module double_double). In rigid
    !! coordinates K holds the shear stiffness kGh/h_e of the section while the flexural part
    !! v' has w' - psi nearly cancelling: for a thin, stiff structure eps |K| |v'| reaches
    !! 1e-7 of the load (rho 1e6, zeta 1e-3, N_e 400), and the residual of the exactly solved
    !! v' rounded to double is that large too (doc/METHOD.md, double-double refinement).
    !! M^T r is summed in double: its round-off, eps |M^T| |r|, is that of the load itself.
    pure function equilibrium_residual(d, sys, z, z_lo) result(res)
        type(discretization_t), intent(in) :: d   !! the discretisation
        type(system_t), intent(in) :: sys       !! the assembled system (A0, q)
        real(dp), intent(in) :: z(:), z_lo(:)   !! [v; r] = z + z_lo
        real(dp) :: res(d%nv)
        real(dp) :: kv(d%nv), kv_lo(d%nv), rest(d%nv), s(d%nv), s_err(d%nv)
        integer :: i
        associate (nv => d%nv)
            call columns_times_double_double(sys%k, z(1:nv), z_lo(1:nv), kv, kv_lo)
            rest = columns_times(sys%mt, z(nv + 1:)) - sys%q
            call two_sum(kv, rest, s, s_err)
            res = s + (s_err + kv_lo)
        end associate
        do i = 1, size(d%fixed)
            if (d%fixed(i) <= d%nv) res(d%fixed(i)) = z(d%fixed(i))
        end do
    end function equilibrium_residual

    !> The generalised Jacobian of F at the tractions sigma (sets decided there by
    !! interface_law): A0 plus the set-dependent entries of set_terms, fixed unknowns with
    !! identity rows and columns. symmetric is false when the d tau0/d sigma_z block is present.
    pure subroutine complete_jacobian(d, sys, law, pts, sigma, a, symmetric)
        type(discretization_t), intent(in) :: d         !! the discretisation
        type(system_t), intent(in) :: sys               !! the assembled system (A0, q)
        type(law_t), intent(in) :: law                  !! the interface law of this stage
        type(contact_points_t), intent(in) :: pts       !! the contact points
        real(dp), intent(in) :: sigma(:, :)             !! (sigma_x, sigma_z) at the contact points
        real(dp), allocatable, intent(out) :: a(:, :)   !! the Jacobian (n x n)
        logical, intent(out) :: symmetric               !! no d tau0/d sigma_z block
        type(set_terms_t) :: st
        call set_terms(sys, law, pts, sigma, st)
        symmetric = st%symmetric
        call jacobian_with_terms(d, sys, st, a)
    end subroutine complete_jacobian

    !> A0 plus the set terms st (duplicates add), fixed unknowns with identity rows and
    !! columns: the dense Jacobian.
    pure subroutine jacobian_with_terms(d, sys, st, a)
        type(discretization_t), intent(in) :: d         !! the discretisation
        type(system_t), intent(in) :: sys               !! the assembled system (A0, q)
        type(set_terms_t), intent(in) :: st             !! the set-dependent entries of the Jacobian
        real(dp), allocatable, intent(out) :: a(:, :)   !! the Jacobian (n x n)
        integer :: i
        a = a0_dense(sys)
        entries: do i = 1, st%n
            a(st%row(i), st%col(i)) = a(st%row(i), st%col(i)) + st%val(i)
        end do entries
        do i = 1, size(d%fixed)
            a(d%fixed(i), :) = 0.0_dp
            a(:, d%fixed(i)) = 0.0_dp
            a(d%fixed(i), d%fixed(i)) = 1.0_dp
        end do
    end subroutine jacobian_with_terms

    !> The set-dependent entries of the Jacobian at the tractions sigma, as (row, col, value)
    !! triplets on the traction unknowns (duplicates add): the eps_bar of a continuation stage
    !! where it differs from the deck's, the penalty on the tension set, the slip terms and
    !! d tau0/d sigma_z on the slip set. All live on the interface's Gauss points.
    pure subroutine set_terms(sys, law, pts, sigma, st)
        type(system_t), intent(in) :: sys           !! the assembled system (A0, q)
        type(law_t), intent(in) :: law              !! the interface law of this stage
        type(contact_points_t), intent(in) :: pts   !! the contact points
        real(dp), intent(in) :: sigma(:, :)         !! (sigma_x, sigma_z) at the contact points
        type(set_terms_t), intent(out) :: st        !! the set-dependent entries
        real(dp) :: tau0, coupling
        integer :: p, nx, nz
        nx = pts%nl(1)
        nz = pts%nl(2)
        allocate (st%row(pts%n*(2*nx*nx + nz*nz + nx*nz)))
        allocate (st%col(size(st%row)), st%val(size(st%row)))
        allocate (st%first(pts%n + 1))
        st%n = 0
        st%symmetric = .true.
        points: do p = 1, pts%n
            st%first(p) = st%n + 1
            if (law%eps /= sys%law%eps) &
                call add_point_entries(pts, p, 1, 1, -sys%c*(law%eps - sys%law%eps), st)
            if (in_tension(sigma(2, p))) call add_point_entries(pts, p, 2, 2, -law%penalty, st)
            tau0 = friction_threshold(law%f, sigma(2, p))
            if (.not. is_slipping(sigma(1, p), tau0)) cycle points
            call add_point_entries(pts, p, 1, 1, -law%slip, st)
            coupling = law%slip*sign(1.0_dp, sigma(1, p))*threshold_slope(law%f, sigma(2, p))
            if (coupling == 0.0_dp) cycle points
            st%symmetric = .false.
            call add_point_entries(pts, p, 1, 2, coupling, st)
        end do points
        st%first(pts%n + 1) = st%n + 1
    end subroutine set_terms

    !> Triplets factor * wt g_i h_j at contact point p, g of traction field kr (1: x, 2: z)
    !! in the rows, h of field kc in the columns.
    pure subroutine add_point_entries(pts, p, kr, kc, factor, st)
        type(contact_points_t), intent(in) :: pts
        integer, intent(in) :: p, kr, kc
        real(dp), intent(in) :: factor
        type(set_terms_t), intent(inout) :: st
        integer :: i, j
        columns: do j = 1, pts%nl(kc)
            rows: do i = 1, pts%nl(kr)
                st%n = st%n + 1
                st%row(st%n) = pts%idx(i, kr, p)
                st%col(st%n) = pts%idx(j, kc, p)
                st%val(st%n) = factor*pts%wt(p)*pts%val(i, kr, p)*pts%val(j, kc, p)
            end do rows
        end do columns
    end subroutine add_point_entries

    !> A0 z (in rigid coordinates K acts on the flexural part only: see rigid_body).
    pure function linear_part(d, sys, z) result(lin)
        type(discretization_t), intent(in) :: d   !! the discretisation
        type(system_t), intent(in) :: sys         !! the assembled system (A0, q)
        real(dp), intent(in) :: z(:)              !! the unknowns [v; r]
        real(dp) :: lin(d%n)
        lin = a0_times(sys, z, z)
    end function linear_part

    !> Coefficients of the function x in a basis (it reproduces linear functions): nodal values
    !! for P1 and P2, Greville abscissae (t(i+1) + t(i+2))/2 for the quadratic B-splines.
    pure function linear_coefficients(basis) result(c)
        type(basis_t), intent(in) :: basis
        real(dp), allocatable :: c(:)
        integer :: i, e
        allocate (c(basis%n_dof))
        select case (basis%family)
        case (INTERP_P2)
            do e = 1, basis%ne
                c(2*e - 1) = basis%x(e - 1)
                c(2*e) = 0.5_dp*(basis%x(e - 1) + basis%x(e))
            end do
            c(basis%n_dof) = basis%x(basis%ne)
        case (INTERP_S2)
            do i = 1, basis%n_dof
                c(i) = 0.5_dp*(basis%knots(i + 1) + basis%knots(i + 2))
            end do
        case default
            c = basis%x(0:basis%ne)
        end select
    end function linear_coefficients

    !> The diagonal of complete_jacobian at the tractions sigma (the off-diagonal
    !! d tau0/d sigma_z block does not touch it).
    pure function jacobian_diagonal(d, sys, law, pts, sigma) result(dg)
        type(discretization_t), intent(in) :: d     !! the discretisation
        type(system_t), intent(in) :: sys           !! the assembled system (A0, q)
        type(law_t), intent(in) :: law              !! the interface law of this stage
        type(contact_points_t), intent(in) :: pts   !! the contact points
        real(dp), intent(in) :: sigma(:, :)         !! (sigma_x, sigma_z) at the contact points
        real(dp) :: dg(d%n)
        real(dp) :: fx, fz
        integer :: i, p
        dg = a0_diagonal(sys)
        points: do p = 1, pts%n
            fx = -sys%c*(law%eps - sys%law%eps)
            if (is_slipping(sigma(1, p), friction_threshold(law%f, sigma(2, p)))) &
                fx = fx - law%slip
            fz = 0.0_dp
            if (in_tension(sigma(2, p))) fz = -law%penalty
            associate (ix => pts%idx(1:pts%nl(1), 1, p), iz => pts%idx(1:pts%nl(2), 2, p))
                dg(ix) = dg(ix) + fx*pts%wt(p)*pts%val(1:pts%nl(1), 1, p)**2
                dg(iz) = dg(iz) + fz*pts%wt(p)*pts%val(1:pts%nl(2), 2, p)**2
            end associate
        end do points
        if (sys%rigid_coordinates) then
            ! the compatibility rows of the rigid modes have diagonal 0: theirs is taken from
            ! the Schur complement onto the mode amplitudes, (MR)^T D^-1 (MR), so that their
            ! Jacobi correction is a displacement like the others'
            do i = 1, sys%rigid%np
                associate (mr => dense_column(sys%mm, sys%rigid%pinned(i)), &
                           dr => dg(d%nv + 1:))
                    dg(sys%rigid%pinned(i)) = sum(mr**2/abs(dr), mask=dr /= 0.0_dp)
                end associate
            end do
        end if
        dg(d%fixed) = 1.0_dp
    end function jacobian_diagonal

    !> || row_scale * res ||_2: the merit norm (fixed scaling from the diagonal of A0).
    pure real(dp) function scaled_norm(sys, res)
        type(system_t), intent(in) :: sys   !! the assembled system (A0, q)
        real(dp), intent(in) :: res(:)      !! a residual F(z)
        scaled_norm = norm2(sys%row_scale*res)
    end function scaled_norm

    !> max over displacement and traction blocks of |dz|_inf / |z|_inf.
    pure real(dp) function relative_change(d, z_new, z_old) result(incr)
        type(discretization_t), intent(in) :: d      !! the discretisation
        real(dp), intent(in) :: z_new(:), z_old(:)   !! the new and the previous unknowns [v; r]
        incr = max(maxval(abs(z_new(1:d%nv) - z_old(1:d%nv))) &
                   /max(maxval(abs(z_new(1:d%nv))), tiny(1.0_dp)), &
                   maxval(abs(z_new(d%nv + 1:) - z_old(d%nv + 1:))) &
                   /max(maxval(abs(z_new(d%nv + 1:))), tiny(1.0_dp)))
    end function relative_change
end module contact_system
