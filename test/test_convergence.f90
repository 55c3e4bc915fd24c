!> Convergence under mesh refinement, with observed orders (doc/CHOICES.md, Convergence orders).
!!
!! Three NONDIM plates (a = 1, F = 1, nu = 0.3, nu_f = 0.1, zeta = 0.1); the measured quantity is
!! the centre settlement W(0) = D w(0)/(F a^2), its relative error e = W_h(0)/W(0) - 1 against a
!! closed form, and the observed order between N_e and 2 N_e is log2(|e_N| / |e_2N|). Each test
!! prints its table (it appears in the `fpm test` log).
!!
!! 1. Frictionless rigid punch (rho = 1e4, f = 0, central POINT load): W(0) = rho/4, i.e.
!!    w = F (1 - nu_f^2)/(2 E_f a) (Boussinesq 1885; Johnson 1985 ch. 3).
!! 2. Bonded rigid punch (rho = 1e4, f = 1e3: stick everywhere, no lift-off): W(0) = rho/(4 c),
!!    c = (1 - nu_f) ln(3 - 4 nu_f)/(1 - 2 nu_f) (Mossakovskii 1954; Spence 1968).
!! 3. Bonded plate with no bending stiffness (rho = 1e-12, f = 1e3, eps_bar = 1e-10) under a
!!    uniform load over the whole disk (PATCH 0..a): the plate passes the load on unchanged, the
!!    contact pressure is uniform (smooth) and W(0) = rho/pi, i.e. the centre settlement
!!    w(0) = 2 (1 - nu_f^2) q a/E_f of a uniformly loaded circle (Johnson 1985 ch. 3).
!!
!! Theory used for the assertions.
!!  * Rigid punch, frictionless or bonded. For a rigid punch (constant displacement) W(0) is the
!!    compliance of the half-space, the minimum of the complementary energy <sigma, T sigma> over
!!    tractions with resultant F. The traction space of the mixed method is a Galerkin subspace,
!!    so W_h(0) >= W(0) and W_h(0) - W(0) = ||sigma - sigma_h||_T^2 (energy norm, H^(-1/2)):
!!    the error is positive and converges like the square of the traction error. The exact
!!    pressure has the inverse-square-root edge singularity, sigma ~ d^(-1/2) at distance d from
!!    the rim (bonded: d^(-1/2) cos(epsilon ln d + phi), epsilon = ln(3 - 4 nu_f)/(2 pi), the same
!!    real exponent). Scaling the element at the rim, of size h_e, to unit size shows that its
!!    share of ||sigma - sigma_h||_T^2 is C_p h_e whatever the polynomial degree p of the
!!    traction (d^(-1/2) is not in any polynomial space), while the smooth interior contributes
!!    O(h^(2p+3)). Hence e ~ C_p h_e: the observed order is log2(h_e(N)/h_e(2N)) for every family,
!!    i.e. 1 on UNIFORM meshes (h_e = a/N) for P1, P2 and S2 alike, whatever their degree.
!!    On EDGES meshes (ratio 1.1 between neighbours, towards the rim) h_e = 0.1 a/(1.1^N - 1)
!!    for N_e <= 61: it shrinks faster than 1/N, so the order in N grows with N (1.3, 1.65, 2.5
!!    from N_e = 4 to 32); it is asserted against log2(h_e(N)/h_e(2N)) taken from the mesh. A
!!    radical grading r_i = a (1 - (1 - i/N)^3), built in this test (not a deck option), has
!!    h_e = a N^(-3) and order 3 for every family.
!!  * Smooth case (3). With (practically) no plate stiffness and the same interpolation for all
!!    five fields, discrete equilibrium M^T r = q reproduces the uniform load exactly, and the
!!    compatibility M v = T r makes w_h the (weighted) L2 projection of the exact surface
!!    settlement w_f(r) = (4 (1 - nu_f^2) q a/(pi E_f)) E(r/a), which is smooth at the axis (its
!!    (a - r) ln(a - r) term at the rim pollutes the axis only exponentially weakly). The L2
!!    projection onto degree-p piecewise polynomials is L-infinity stable on quasi-uniform
!!    meshes, so |W_h(0) - W(0)| = O(h^(p+1)): order 2 for P1, at least 3 for P2 and S2 (the
!!    value at the axis node superconverges to order 4 for P2 and S2 in practice; 3 is what is
!!    asserted). This is the only smooth case available: a disk in full contact under a plate
!!    of finite stiffness always has the d^(-1/2) rim singularity, and a contact that ends by
!!    lift-off has a sqrt(d) pressure at a free boundary.
!!
!! Margins. Asserted: observed >= 0.8 x theory on every pair (pre-asymptotic effects on the
!! coarse meshes and the floors below), and for the punches also observed <= 1.25 x theory (the
!! singular rate is sharp: a faster rate would mean the test no longer sees the singularity).
!! Floors that limit the meshes:
!!  * rigid punches, rho = 1e4: the plate's own deflection under the point load and the punch
!!    pressure adds O(1) to W(0) (0.031 in fricon, independent of rho to leading order), i.e.
!!    ~1.2e-5 relative, below 10 % of every asserted error. N_e <= 64 (UNIFORM), <= 32
!!    (EDGES), <= 8 (radical) for the asserted orders: limits against the round-off of
!!    solvers in absolute displacements, about rho (a/h_e) zeta^-2 eps; the solvers work in
!!    rigid coordinates, src/contact/rigid_body.f90 (doc/CHOICES.md, Convergence orders).
!!  * bonded punch: the bonded solution's pressure changes sign within ~1e-4 a of the rim (the
!!    oscillation of cos(epsilon ln d)); a mesh that resolves this (EDGES from N_e = 64) asks the
!!    unilateral solver for tension there (no convergence, status 2), so EDGES stops at 32.
!!  * smooth case: eps_bar = 1e-10 and the O(rho) membrane restraint leave W(0) within ~1e-9 of
!!    rho/pi, which P2 and S2 reach at N_e = 64: their orders are asserted up to N_e = 32.
module test_convergence
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, error_t, check
    use model, only: model_t, load_t, LOAD_POINT, LOAD_PATCH, FIELD_U, FIELD_PSI, FIELD_SX, &
                     FIELD_SZ, relative_stiffness
    use shape_functions, only: new_basis, interp_name, INTERP_P1, INTERP_P2, INTERP_S2
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: STATE_STICK
    use station_test_support, only: nd, nd_all
    use solved_case, only: case_t, solve_on
    use contact_test_support, only: nondim_plate
    implicit none
    private
    public :: collect_convergence

    integer, parameter :: MESH_UNIFORM = 1, MESH_EDGES = 2, MESH_RADICAL = 3
    character(len=8), parameter :: mesh_word(3) = [character(len=8) :: 'UNIFORM', 'EDGES', &
                                                   'RADICAL3']
    integer, parameter :: families(3) = [INTERP_P1, INTERP_P2, INTERP_S2]
    real(dp), parameter :: rho_rigid = 1.0e4_dp   !! rigid punch: plate/soil stiffness ratio
    real(dp), parameter :: f_bonded = 1.0e3_dp    !! friction coefficient that bonds (stick)
    real(dp), parameter :: low_margin = 0.8_dp    !! observed order >= 0.8 x theory
    real(dp), parameter :: high_margin = 1.25_dp  !! observed order <= 1.25 x theory (punches)

    !> One problem: the model (mesh fields left to the series) and the closed-form W(0).
    type :: problem_t
        type(model_t) :: m
        real(dp) :: w_exact = 0.0_dp            !! closed-form W(0), nondimensional
        logical :: matching = .false.           !! displacements interpolated like the tractions
        logical :: want_stick = .false.         !! every station must be in stick (bonded)
    end type problem_t

    !> Relative errors of W(0) on a sequence of meshes N_e = 4, 8, 16, ...
    type :: series_t
        integer :: n = 0                        !! number of meshes
        integer, allocatable :: ne(:)           !! N_e
        real(dp), allocatable :: error(:)       !! W_h(0)/W(0) - 1, signed
        real(dp), allocatable :: h_edge(:)      !! size of the element at the rim [a]
    end type series_t

contains

    subroutine collect_convergence(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('rigid_punch_frictionless_orders', test_rigid_punch), &
                 new_unittest('bonded_punch_orders', test_bonded_punch), &
                 new_unittest('smooth_bonded_plate_orders', test_smooth_plate)]
    end subroutine collect_convergence

    !> Test 1: frictionless rigid punch, W(0) = rho/4 (Boussinesq). Orders as in the header:
    !! log2(h_e(N)/h_e(2N)) for all three traction families (displacements P1: a rigid plate's
    !! constant displacement is exact in every family).
    subroutine test_rigid_punch(err)
        type(error_t), allocatable, intent(out) :: err
        type(problem_t) :: prob
        prob%m = nondim_plate(rho_rigid, 0.1_dp, 0.1_dp, 0.0_dp, loads=[load_t(kind=LOAD_POINT, &
                                                                       fz=1.0_dp)])
        prob%w_exact = relative_stiffness(prob%m%structure, prob%m%ground)/4.0_dp
        call punch_orders(prob, 'frictionless rigid punch, rho = 1e4: W(0) against rho/4 '// &
                          '(Boussinesq)', .true., err)
    end subroutine test_rigid_punch

    !> Test 2: bonded rigid punch (f = 1e3: every station in stick, no lift-off, no slip),
    !! W(0) = rho/(4 c), c = (1 - nu_f) ln(3 - 4 nu_f)/(1 - 2 nu_f) = 1.07495 for nu_f = 0.1
    !! (Mossakovskii). Same theory as the frictionless punch (edge exponent -1/2).
    subroutine test_bonded_punch(err)
        type(error_t), allocatable, intent(out) :: err
        type(problem_t) :: prob
        real(dp) :: c, nu_f
        prob%m = nondim_plate(rho_rigid, 0.1_dp, 0.1_dp, f_bonded, loads=[load_t(kind=LOAD_POINT, &
                                                                         fz=1.0_dp)])
        nu_f = prob%m%ground%nu_f
        c = (1.0_dp - nu_f)*log(3.0_dp - 4.0_dp*nu_f)/(1.0_dp - 2.0_dp*nu_f)
        prob%w_exact = relative_stiffness(prob%m%structure, prob%m%ground)/(4.0_dp*c)
        prob%want_stick = .true.
        call punch_orders(prob, 'bonded rigid punch, rho = 1e4, f = 1e3: W(0) against '// &
                          'rho/(4c) (Mossakovskii)', .false., err)
    end subroutine test_bonded_punch

    !> Orders of a rigid punch on UNIFORM (N_e 4..64), EDGES (4..32) and, when `radical`, the
    !! radical grading (4, 8), for tractions P1, P2, S2. Asserts e > 0 (Galerkin compliance),
    !! 0.8 <= observed/theory <= 1.25 with theory = log2(h_e(N)/h_e(2N)), and EDGES below
    !! UNIFORM at every N_e (smaller rim element).
    subroutine punch_orders(prob, title, radical, err)
        type(problem_t), intent(inout) :: prob
        character(len=*), intent(in) :: title
        logical, intent(in) :: radical
        type(error_t), allocatable, intent(out) :: err
        type(series_t) :: s(3, 3)                    ! (family, mesh)
        integer :: fam, mesh, n_mesh(3), k
        n_mesh = [5, 4, 2]
        if (.not. radical) n_mesh(MESH_RADICAL) = 0
        solve_meshes: do mesh = MESH_UNIFORM, MESH_RADICAL
            solve_families: do fam = 1, 3
                call run_series(prob, families(fam), mesh, n_mesh(mesh), s(fam, mesh), err)
                if (allocated(err)) return
            end do solve_families
        end do solve_meshes
        call print_table(title, 'log2 h_e ratio', s, n_mesh, .true.)
        check_meshes: do mesh = MESH_UNIFORM, MESH_RADICAL
            check_families: do fam = 1, 3
                if (n_mesh(mesh) == 0) cycle check_meshes
                call check(err, all(s(fam, mesh)%error > 0.0_dp), trim(mesh_word(mesh))//' '// &
                           interp_name(families(fam))//': W_h(0) below the closed form '// &
                           '(a Galerkin compliance is an upper bound)')
                if (allocated(err)) return
                call check_singular_orders(s(fam, mesh), trim(mesh_word(mesh))//' '// &
                                           interp_name(families(fam)), err)
                if (allocated(err)) return
            end do check_families
        end do check_meshes
        edges_families: do fam = 1, 3
            edges_levels: do k = 1, n_mesh(MESH_EDGES)
                call check(err, s(fam, MESH_EDGES)%error(k) < s(fam, MESH_UNIFORM)%error(k), &
                           'EDGES '//interp_name(families(fam))//' is not more accurate '// &
                           'than UNIFORM at the same N_e')
                if (allocated(err)) return
            end do edges_levels
        end do edges_families
    end subroutine punch_orders

    !> 0.8 <= observed / log2(h_e(N)/h_e(2N)) <= 1.25 on every pair of the series.
    subroutine check_singular_orders(s, what, err)
        type(series_t), intent(in) :: s
        character(len=*), intent(in) :: what
        type(error_t), allocatable, intent(out) :: err
        character(len=160) :: text
        real(dp) :: observed, theory
        integer :: k
        pairs: do k = 1, s%n - 1
            observed = observed_order(s, k)
            theory = edge_order(s, k)
            write (text, '(a,": observed order ",f6.3," between N_e = ",i0," and ",i0, &
                   &", theory (e ~ h_e) ",f6.3)') what, observed, s%ne(k), s%ne(k + 1), theory
            call check(err, observed >= low_margin*theory .and. &
                       observed <= high_margin*theory, trim(text))
            if (allocated(err)) return
        end do pairs
    end subroutine check_singular_orders

    !> Test 3: the smooth case. Bonded plate with no bending stiffness (rho = 1e-12) under a
    !! uniform load over the whole disk; all five fields in the same family; UNIFORM N_e 4..64.
    !! W(0) = rho/pi (uniformly loaded circle). Asserts: every station in stick, Sigma_z = 1
    !! (the load passes unchanged) and orders >= 0.8 (p + 1): P1 2, P2 and S2 3 (header).
    subroutine test_smooth_plate(err)
        type(error_t), allocatable, intent(out) :: err
        type(problem_t) :: prob
        type(series_t) :: s(3, 3)
        integer :: fam, k, n_mesh(3), last_pair
        real(dp) :: theory, observed
        character(len=160) :: text
        prob%m = nondim_plate(1.0e-12_dp, 0.1_dp, 0.1_dp, f_bonded, &
                              loads=[load_t(kind=LOAD_PATCH, fz=1.0_dp, x1=0.0_dp, x2=1.0_dp)])
        prob%m%interface%eps_bar = 1.0e-10_dp
        prob%w_exact = relative_stiffness(prob%m%structure, prob%m%ground)/pi
        prob%matching = .true.
        prob%want_stick = .true.
        n_mesh = [5, 0, 0]
        solve_families: do fam = 1, 3
            call run_series(prob, families(fam), MESH_UNIFORM, n_mesh(1), s(fam, 1), err)
            if (allocated(err)) return
        end do solve_families
        call print_table('bonded plate without bending stiffness (rho = 1e-12), uniform '// &
                         'load: W(0) against rho/pi', 'P1 2, P2 >= 3, S2 >= 3', &
                         s, n_mesh, .false.)
        check_families: do fam = 1, 3
            theory = merge(2.0_dp, 3.0_dp, families(fam) == INTERP_P1)
            ! P2 and S2 reach the ~1e-9 floor (header) at N_e = 64: their last pair is not asserted
            last_pair = merge(4, 3, families(fam) == INTERP_P1)
            pairs: do k = 1, last_pair
                observed = observed_order(s(fam, 1), k)
                write (text, '(a,": observed order ",f6.3," between N_e = ",i0," and ",i0, &
                       &", theory ",f4.1)') 'smooth '//interp_name(families(fam)), observed, &
                    s(fam, 1)%ne(k), s(fam, 1)%ne(k + 1), theory
                call check(err, observed >= low_margin*theory, trim(text))
                if (allocated(err)) return
            end do pairs
        end do check_families
    end subroutine test_smooth_plate

    !> Solve the problem on N_e = 4, 8, ... (n_levels meshes) of one kind, tractions (and, when
    !! prob%matching, displacements) in `family`.
    subroutine run_series(prob, family, mesh, n_levels, s, err)
        type(problem_t), intent(in) :: prob
        integer, intent(in) :: family, mesh, n_levels
        type(series_t), intent(out) :: s
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        real(dp) :: w0
        integer :: k
        s%n = n_levels
        allocate (s%ne(n_levels), s%error(n_levels), s%h_edge(n_levels))
        levels: do k = 1, n_levels
            m = prob%m
            m%mesh%ne = 4*2**(k - 1)
            m%mesh%grading = merge('EDGES  ', 'UNIFORM', mesh == MESH_EDGES)
            m%mesh%interp(FIELD_SX:FIELD_SZ) = family
            if (prob%matching) m%mesh%interp(FIELD_U:FIELD_PSI) = family
            call solve_w0(m, mesh == MESH_RADICAL, prob%want_stick, w0, s%h_edge(k), err)
            if (allocated(err)) return
            s%ne(k) = m%mesh%ne
            s%error(k) = w0/prob%w_exact - 1.0_dp
        end do levels
    end subroutine run_series

    !> W(0) of one case; the size of the rim element; when want_stick, fails unless every station
    !! is in stick and, for a uniform load on a plate without stiffness, Sigma_z = 1 there.
    subroutine solve_w0(m, radical, want_stick, w0, h_edge, err)
        type(model_t), intent(in) :: m
        logical, intent(in) :: radical         !! replace the nodes by r_i = a (1 - (1 - i/N)^3)
        logical, intent(in) :: want_stick
        real(dp), intent(out) :: w0            !! W(0), nondimensional
        real(dp), intent(out) :: h_edge        !! rim element [a]
        type(error_t), allocatable, intent(out) :: err
        type(discretization_t) :: d
        type(case_t) :: c
        character(len=120) :: text
        integer :: i, field
        call new_discretization(m, d, err)
        if (allocated(err)) return
        if (radical) then
            ! same number of elements, so the numbering of new_discretization still holds
            radical_nodes: do i = 0, m%mesh%ne
                d%msh%x(i) = m%structure%length*(1.0_dp - (1.0_dp - real(i, dp)/real(m%mesh%ne, &
                    dp))**3)
            end do radical_nodes
            rebuild_bases: do field = FIELD_U, FIELD_SZ
                call new_basis(d%basis(field), d%msh, m%mesh%interp(field))
            end do rebuild_bases
        end if
        call solve_on(m, d, c, err)
        if (allocated(err)) return
        w0 = nd(m, c%stations, 'W', 1)
        h_edge = (d%msh%x(m%mesh%ne) - d%msh%x(m%mesh%ne - 1))/m%structure%length
        write (text, '(a,i0,a)') 'N_e = ', m%mesh%ne, ': '
        ! a spurious "converged" state (all points in tension) misses equilibrium by ~F; the
        ! round-off of the stiff punch (rho = 1e4) leaves up to ~1e-6 F (N_e = 64)
        call check(err, abs(c%sol%reaction(1) - c%sol%applied(1)) <= 1.0e-4_dp*c%sol%applied(1), &
                   trim(text)//'vertical equilibrium violated')
        if (allocated(err)) return
        if (.not. want_stick) return
        call check(err, all(c%stations%state == STATE_STICK), trim(text)//'bonded case has a '// &
                   'station in lift-off or slip')
        if (allocated(err)) return
        if (m%groups%rho >= 1.0e-6_dp) return
        ! no plate stiffness: M^T r = q with matching spaces reproduces the uniform load. The
        ! residual stiffness (rho = 1e-12) leaves a rim singularity of tiny amplitude whose value
        ! at the rim node grows as the rim element shrinks (~3e-7 at N_e = 64); 1e-5 allows for
        ! it and still fails on any real departure from the uniform load
        call check(err, maxval(abs(nd_all(m, c%stations, 'Sigma_z') - 1.0_dp)) <= 1.0e-5_dp, &
                   trim(text)//'uniform load not passed on as Sigma_z = 1')
    end subroutine solve_w0

    !> log2(|e_k| / |e_k+1|).
    pure real(dp) function observed_order(s, k)
        type(series_t), intent(in) :: s
        integer, intent(in) :: k
        observed_order = log(abs(s%error(k))/max(abs(s%error(k + 1)), tiny(1.0_dp)))/log(2.0_dp)
    end function observed_order

    !> log2(h_e(k) / h_e(k+1)): the order of e ~ h_e (header).
    pure real(dp) function edge_order(s, k)
        type(series_t), intent(in) :: s
        integer, intent(in) :: k
        edge_order = log(s%h_edge(k)/s%h_edge(k + 1))/log(2.0_dp)
    end function edge_order

    !> Table: per mesh and N_e, the rim element, the errors and observed orders of P1, P2, S2,
    !! and (singular cases) the theoretical order log2(h_e(N)/h_e(2N)).
    subroutine print_table(title, theory_note, s, n_mesh, singular)
        character(len=*), intent(in) :: title, theory_note
        type(series_t), intent(in) :: s(3, 3)
        integer, intent(in) :: n_mesh(3)
        logical, intent(in) :: singular
        integer :: mesh, k, fam
        character(len=8) :: order_text(3), theory_text
        write (*, '(a)') 'convergence: '//title
        write (*, '(a)') '  mesh      N_e   h_edge      P1 error  order    P2 error  order'// &
            '    S2 error  order  theory ('//theory_note//')'
        table_meshes: do mesh = MESH_UNIFORM, MESH_RADICAL
            table_rows: do k = 1, n_mesh(mesh)
                order_text = ''
                theory_text = ''
                if (k > 1) then
                    row_orders: do fam = 1, 3
                        write (order_text(fam), '(f6.2)') observed_order(s(fam, mesh), k - 1)
                    end do row_orders
                    if (singular) write (theory_text, '(f6.2)') edge_order(s(1, mesh), k - 1)
                end if
                write (*, '(2x,a8,i5,es10.2,3(es12.3,a7),1x,a)') mesh_word(mesh), &
                    s(1, mesh)%ne(k), s(1, mesh)%h_edge(k), &
                    (s(fam, mesh)%error(k), order_text(fam)(1:7), fam = 1, 3), trim(theory_text)
            end do table_rows
        end do table_meshes
        flush (6)
    end subroutine print_table
end module test_convergence
