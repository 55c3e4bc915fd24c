!> The globalised semismooth Newton method (doc/METHOD.md, Solution methods): the practical cases
!! the two-loop iteration failed, a hard-case grid, and agreement with the two-loop method.
!!
!! Every case must end solved with its checks inside tolerance. The expected values are not
!! fricon output; each comes from statics or from the interface law itself:
!! - equilibrium: the reactions int sigma_z, int sigma_x and their moment equal the applied
!!   loads (statics of the free structure), to 1e-8 of the vertical load V (of V l for moments);
!! - the complete problem (4.2 with tau0 = f max(sigma_z, 0) of the final state): its 4.2b
!!   residual as a traction error below 1e-8 of max |r| (a solution satisfies it exactly; 1e-8
!!   leaves room for round-off only);
!! - complementarity, at the Gauss points where the discrete problem imposes it: the penalty
!!   makes sigma_z = -(eta_bar/c) gap on lifted-off points, so no sigma_z may be more tensile
!!   than (eta_bar/c) max |gap| (factor 10 for the weak enforcement). (At the stations, P1
!!   tractions extrapolated to an end node can be tensile by O(h), which is discretisation.)
!! - friction admissibility: the regularised law gives |sigma_x| - f sigma_z =
!!   eps_bar/(1 - eps_bar^2) slip/c on slipping points, O(eps_bar) times a slip that soft
!!   structures make large: below 10 times that for the largest slip (factor 10 for the
!!   weak enforcement), and never below 1e3 eps_bar max(1, max Sigma_z), the bound of
!!   contact_solver's admissibility and soft-beam tests.
module test_newton
    use kinds, only: dp
    use double_double, only: two_sum, two_product
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_ANALYSIS
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_PATCH, &
                     total_vertical_load, friction_compliance, METHOD_NEWTON, METHOD_TWOLOOP, &
                     FIELD_U, FIELD_SZ
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t
    use station_results, only: station_table_t
    use solved_case, only: case_t, solve_case
    use station_columns, only: Q_GAP, Q_SLIP, Q_W, Q_X
    use station_test_support, only: nd, nd_all
    use deck_reader, only: deck_t, read_deck, case_model
    use shape_functions, only: INTERP_P2, INTERP_S2
    use contact_system, only: system_t, set_terms_t, build_system, complete_jacobian, &
                              point_tractions, set_terms, use_rigid_coordinates
    use schur_solver, only: schur_t, schur_factor_t, new_schur, schur_prepare, schur_solve
    use linear_solve, only: solve_equilibrated
    use band_solve, only: band_cholesky_solve, band_cholesky_solve_rows
    use lapack_interfaces, only: dpbtrf, dpbtrs
    use contact_test_support, only: nondim_plate, nondim_beam, run
    implicit none
    private
    public :: collect_newton

contains

    !> The error-free transformations of the double-double refinement, on numbers whose exact
    !! sums and products are known in closed form: (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60, whose
    !! double is 1 + 2^-29 and error 2^-60; 1 + 2^-60 rounds to 1 with error 2^-60; and
    !! (2^-60 + 1) - 1 recovered exactly from the pair. binary128 (exact for these) was the
    !! arithmetic before.
    subroutine test_double_double(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: a, p, e, s, t
        a = 1.0_dp + 2.0_dp**(-30)
        call two_product(a, a, p, e)
        call check(err, p == 1.0_dp + 2.0_dp**(-29) .and. e == 2.0_dp**(-60), &
                   'two_product((1 + 2^-30)^2) is not 1 + 2^-29 with error 2^-60')
        if (allocated(err)) return
        call two_sum(1.0_dp, 2.0_dp**(-60), s, e)
        call check(err, s == 1.0_dp .and. e == 2.0_dp**(-60), &
                   'two_sum(1, 2^-60) is not 1 with error 2^-60')
        if (allocated(err)) return
        call two_sum(2.0_dp**(-60), 1.0_dp, s, e)
        call two_sum(s, -1.0_dp, t, p)
        call check(err, t + (p + e) == 2.0_dp**(-60), &
                   '(2^-60 + 1) - 1 in double-double is not 2^-60')
    end subroutine test_double_double

    subroutine collect_newton(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('beam_horizontal_load_03', test_beam_horizontal), &
                 new_unittest('wide_beam', test_wide_beam), &
                 new_unittest('beam_physical_edges_meshes', test_beam_physical_edges), &
                 new_unittest('plate_p2_meshes', test_plate_p2), &
                 new_unittest('soft_plate_meshes', test_soft_plate_meshes), &
                 new_unittest('s2_beam_point_load_c0', test_s2_point_load), &
                 new_unittest('hard_case_grid', test_hard_grid), &
                 new_unittest('stiff_structures', test_stiff_structures), &
                 new_unittest('stiff_structures_fine_mesh', test_stiff_fine_mesh), &
                 new_unittest('newton_agrees_with_two_loop', test_agreement), &
                 new_unittest('fig07_ref_case5_one_state', test_fig07_case5), &
                 new_unittest('set_cycle_broken_by_single_flip', test_single_flip), &
                 new_unittest('set_cycle_broken_whatever_the_rounding', test_flip_rounding), &
                 new_unittest('schur_solve_matches_dense', test_schur_matches_dense), &
                 new_unittest('band_solve_matches_lapack', test_band_solve), &
                 new_unittest('double_double_exact', test_double_double)]
    end subroutine collect_newton

    !> Solve m and assert the four checks of the module header; what names the case.
    subroutine require_solved(m, what, err, sol_out, tab_out)
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: what
        type(error_t), allocatable, intent(out) :: err
        type(solution_t), intent(out), optional :: sol_out
        type(station_table_t), intent(out), optional :: tab_out
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(error_t), allocatable :: run_err
        real(dp) :: v, scale(3), p_max, gap, slip_law, eq_tol
        call run(m, sol, tab, run_err)
        if (allocated(run_err)) then
            call check(err, .false., what//': not solved: '//run_err%message)
            return
        end if
        eq_tol = 1.0e-8_dp
        v = total_vertical_load(m%loads)
        scale = v*[1.0_dp, 1.0_dp, m%structure%length]
        call check(err, all(abs(sol%reaction - sol%applied) <= eq_tol*scale), &
                   what//': reactions do not balance the loads')
        if (allocated(err)) return
        call check(err, sol%law_residual <= 1.0e-8_dp, &
                   what//': residual of the complete problem (4.2b) too large')
        if (allocated(err)) return
        ! scale of a gap: the settlements (a tensile Gauss point may sit where every station
        ! is still in contact, whose reported gap is 0)
        gap = max(maxval(abs(tab%val(Q_GAP, :))), maxval(abs(tab%val(Q_W, :))))
        call check(err, &
            -sol%min_sigma_z <= 10.0_dp*m%interface%eta_bar/friction_compliance(m%structure, &
                m%ground)*gap, &
                   what//': complementarity violated (tension beyond the penalty law)')
        if (allocated(err)) return
        p_max = maxval(nd_all(m, tab, 'Sigma_z^h'))
        slip_law = m%interface%eps_bar/(1.0_dp - m%interface%eps_bar**2) &
            *maxval(abs(tab%val(Q_SLIP, :))) &
                   /friction_compliance(m%structure, m%ground)*nd(m, tab, 'Sigma_z', 0)
        call check(err, sol%admissibility*nd(m, tab, 'Sigma_z', &
            0) <= max(1.0e3_dp*m%interface%eps_bar &
                   *max(1.0_dp, p_max), 10.0_dp*slip_law), what//': friction not admissible')
        if (present(sol_out)) sol_out = sol
        if (present(tab_out)) tab_out = tab
    end subroutine require_solved

    !> A practical case the two-loop iteration failed: a beam with H = 0.3 V and f = 0.6
    !! (utilisation H/(fV) = 0.5).
    subroutine test_beam_horizontal(err)
        type(error_t), allocatable, intent(out) :: err
        call require_solved(nondim_beam(0.01_dp, 0.1_dp, 0.05_dp, 0.6_dp, 0.3_dp, 40), &
                            'beam H = 0.3 V, f = 0.6', err)
    end subroutine test_beam_horizontal

    !> A practical case the two-loop iteration failed: a wide beam, b/l = 1.
    subroutine test_wide_beam(err)
        type(error_t), allocatable, intent(out) :: err
        call require_solved(nondim_beam(0.01_dp, 0.1_dp, 1.0_dp, 0.6_dp, 0.1_dp, 40), &
                            'wide beam b/l = 1', err)
    end subroutine test_wide_beam

    !> A practical case the two-loop iteration failed: input/beam_physical.dat with its MESH
    !! card set to EDGES and 60, 80, 100, 120 elements (refining must never turn a solved case into
    !! a failure).
    subroutine test_beam_physical_edges(err)
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: meshes(4) = [60, 80, 100, 120]
        type(deck_t) :: deck
        type(model_t) :: m
        character(len=:), allocatable :: label
        character(len=40) :: what
        integer :: k
        call read_deck('input/beam_physical.dat', deck, err)
        if (allocated(err)) return
        call case_model(deck, 1, m, label, err)
        if (allocated(err)) return
        m%mesh%grading = 'EDGES'
        meshes_loop: do k = 1, size(meshes)
            m%mesh%ne = meshes(k)
            write (what, '(a,i0)') 'beam_physical.dat EDGES N_e = ', meshes(k)
            call require_solved(m, trim(what), err)
            if (allocated(err)) return
        end do meshes_loop
    end subroutine test_beam_physical_edges

    !> A practical case the two-loop iteration failed: P2 meshes (every field P2) at N_e = 20 and 80
    !! on a plate with rho = 0.001, zeta = 0.1, f = 0.6.
    subroutine test_plate_p2(err)
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: meshes(2) = [20, 80]
        type(model_t) :: m
        character(len=40) :: what
        integer :: k
        meshes_loop: do k = 1, size(meshes)
            m = nondim_plate(1.0e-3_dp, 0.1_dp, 0.1_dp, 0.6_dp, meshes(k))
            m%mesh%interp = INTERP_P2
            write (what, '(a,i0)') 'P2 plate N_e = ', meshes(k)
            call require_solved(m, trim(what), err)
            if (allocated(err)) return
        end do meshes_loop
    end subroutine test_plate_p2

    !> A very soft plate (rho = 1e-6, zeta = 0.1) under a disk load r <= 0.1 a, frictionless
    !! and with f = 0.6, on N_e = 20, 100 and 200: found by the extended atlas (its N_e axis),
    !! it solved at N_e = 20 and ended with status 2 from N_e = 200 up with f = 0.6 (from
    !! N_e = 1000 up frictionless, too big for the suite; the adhesive start
    !! left the lift-off front to move a few Gauss points per Newton step; the nested start
    !! of contact_solver cures it). Refining must never turn a solved case into a failure.
    subroutine test_soft_plate_meshes(err)
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: meshes(3) = [20, 100, 200]
        real(dp), parameter :: fs(2) = [0.0_dp, 0.6_dp]
        type(model_t) :: m
        character(len=48) :: what
        integer :: k, i
        frictions: do i = 1, size(fs)
            meshes_loop: do k = 1, size(meshes)
                m = nondim_plate(1.0e-6_dp, 0.1_dp, 0.1_dp, fs(i), meshes(k), &
                                 [load_t(kind=LOAD_PATCH, fz=1.0_dp, x1=0.0_dp, x2=0.1_dp)])
                write (what, '(a,f3.1,a,i0)') 'soft plate, disk load, f ', fs(i), &
                    ', N_e = ', meshes(k)
                call require_solved(m, trim(what), err)
                if (allocated(err)) return
            end do meshes_loop
        end do frictions
    end subroutine test_soft_plate_meshes

    !> S2 displacements under a point load (doc/CHOICES.md, S2 displacements at concentrated
    !! loads): the slope of w jumps there by
    !! F/(k G A), which C1 splines cannot follow; shape_functions makes the S2 displacement
    !! bases C0 at a node where a concentrated load acts. Beam rho = 0.001, zeta = 0.1,
    !! b/l = 0.05, f = 0.6, V = 1 with H = 0.1 V at the centre (the work-precision beam): W(0)
    !! of S2 on N_e = 40 against an independent reference, P1 on N_e = 640 (a different
    !! interpolation; its own error is about 2e-7 relative, the change from 640 to 1280
    !! elements). Measured: 3.9e-5 with the C0 knot, 1.3e-2 without (first order: 2.8e-2 at
    !! N_e = 20, 1.6e-3 at 320); asserted: 2e-4.
    subroutine test_s2_point_load(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        real(dp) :: w_s2, w_ref
        m = nondim_beam(1.0e-3_dp, 0.1_dp, 0.05_dp, 0.6_dp, 0.1_dp, 640)
        call centre_settlement(m, w_ref, err)
        if (allocated(err)) return
        m = nondim_beam(1.0e-3_dp, 0.1_dp, 0.05_dp, 0.6_dp, 0.1_dp, 40)
        m%mesh%interp(FIELD_U:FIELD_SZ) = INTERP_S2
        call centre_settlement(m, w_s2, err)
        if (allocated(err)) return
        call check(err, abs(w_s2/w_ref - 1.0_dp) <= 2.0e-4_dp, &
                   'S2 beam, point load, N_e = 40: W(0) not within 2e-4 of P1 on N_e = 640')
    end subroutine test_s2_point_load

    !> The settlement at the station nearest x = 0 of the solved case m.
    subroutine centre_settlement(m, w0, err)
        type(model_t), intent(in) :: m
        real(dp), intent(out) :: w0
        type(error_t), allocatable, intent(out) :: err
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(error_t), allocatable :: run_err
        w0 = 0.0_dp
        call run(m, sol, tab, run_err)
        if (allocated(run_err)) then
            call check(err, .false., 'not solved: '//run_err%message)
            return
        end if
        w0 = tab%val(Q_W, minloc(abs(tab%val(Q_X, :)), dim=1))
    end subroutine centre_settlement

    !> Hard-case grid: beam and plate, rho 1e-6, 1e-2, 1e4, 1e6; zeta 0.001, 0.1, 0.5; f 0,
    !! 0.6, 2 (beam: H = f V/4, utilisation 0.25; b/l = 0.05); N_e 20 and 40 alternating.
    !! The stiff corners (rho >= 1e4 with zeta = 0.001) are solved in rigid coordinates
    !! (doc/CHOICES.md, Stiff thin structures); test_stiff_structures asserts their 4.2a residual as
    !! well.
    subroutine test_hard_grid(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: rhos(4) = [1.0e-6_dp, 1.0e-2_dp, 1.0e4_dp, 1.0e6_dp]
        real(dp), parameter :: zetas(3) = [1.0e-3_dp, 0.1_dp, 0.5_dp]
        real(dp), parameter :: fs(3) = [0.0_dp, 0.6_dp, 2.0_dp]
        type(model_t) :: m
        character(len=80) :: what
        integer :: kind, i, j, k, ne, n_case
        n_case = 0
        kinds_loop: do kind = MODEL_BEAM, MODEL_PLATE
            rho_loop: do i = 1, size(rhos)
                zeta_loop: do j = 1, size(zetas)
                    f_loop: do k = 1, size(fs)
                        n_case = n_case + 1
                        ne = merge(20, 40, mod(n_case, 2) == 0)
                        if (kind == MODEL_BEAM) then
                            m = nondim_beam(rhos(i), zetas(j), 0.05_dp, fs(k), 0.25_dp*fs(k), ne)
                        else
                            m = nondim_plate(rhos(i), zetas(j), 0.1_dp, fs(k), ne)
                        end if
                        write (what, '(a,3(a,es8.1),a,i0)') merge('beam ', 'plate', &
                            kind == MODEL_BEAM), ' rho', rhos(i), ' zeta', zetas(j), ' f', &
                            fs(k), ' N_e ', ne
                        call require_solved(m, trim(what), err)
                        if (allocated(err)) return
                    end do f_loop
                end do zeta_loop
            end do rho_loop
        end do kinds_loop
    end subroutine test_hard_grid

    !> Stiff structures, rho up to 1e6 with zeta down to 0.001 (a structure
    !! 1e6 times stiffer than the soil in bending and far stiffer still in shear), plate and
    !! beam, both methods, P1 and S2: solved with the checks of require_solved (reactions =
    !! loads to 1e-8) and, for the Newton method, the residual of 4.2a (the structure's
    !! equilibrium) below 1e-8 of the load. Before rigid coordinates the 4.2a residual was
    !! 4e-2 (plate) and the reactions missed the load by 1e-2 (beam): K times a large rigid
    !! settlement left round-off of eps |K| |v|. (The two-loop method ends on its last dense
    !! solve, without the Newton method's refining steps: 1.5e-8 on the rho = 1e6 plate.)
    subroutine test_stiff_structures(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: rhos(2) = [1.0e4_dp, 1.0e6_dp], zetas(2) = [1.0e-3_dp, 1.0e-2_dp]
        type(model_t) :: m
        type(solution_t) :: sol
        character(len=80) :: what
        integer :: kind, i, j, method
        kinds_loop: do kind = MODEL_BEAM, MODEL_PLATE
            do i = 1, size(rhos)
                do j = 1, size(zetas)
                    do method = METHOD_NEWTON, METHOD_TWOLOOP
                        if (kind == MODEL_BEAM) then
                            m = nondim_beam(rhos(i), zetas(j), 0.05_dp, 0.6_dp, 0.1_dp, 40)
                        else
                            m = nondim_plate(rhos(i), zetas(j), 0.1_dp, 0.6_dp, 40)
                        end if
                        m%solver%method = method
                        if (i == j) m%mesh%interp(FIELD_U:FIELD_SZ) = INTERP_S2
                        write (what, '(a,2(a,es8.1),a,i0)') merge('beam ', 'plate', &
                            kind == MODEL_BEAM), ' rho', rhos(i), ' zeta', zetas(j), &
                            ' method ', method
                        call require_solved(m, trim(what), err, sol)
                        if (allocated(err)) return
                        if (method == METHOD_NEWTON) &
                            call check(err, sol%residual(1) <= 1.0e-8_dp, trim(what)// &
                                       ': residual of 4.2a above 1e-8 of the load')
                        if (allocated(err)) return
                    end do
                end do
            end do
        end do kinds_loop
    end subroutine test_stiff_structures

    !> Stiff structures on a finer mesh: rho 1e6, zeta 1e-3, f 0.6, N_e 160. No double v'
    !! meets 4.2a there better than about eps |K| |v'|, which grows like N_e (doc/METHOD.md):
    !! a Newton method that holds its answer in double only (commit e7d0b97) leaves 4.2a
    !! residuals of 4.4e-8 (plate P1), 1.7e-7 (plate P2) and 2.0e-9 (beam P1) of the load; with
    !! the answer in double-double it must be below 1e-8 (the discrete equations themselves), with
    !! the statics, complementarity and friction checks of require_solved. (How far the answer moved
    !! against e7d0b97 is measured in doc/METHOD.md, not pinned here: a test's expected values do
    !! not come from the program's own output.)
    subroutine test_stiff_fine_mesh(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: cases(3)
        character(len=*), parameter :: names(3) = [character(len=8) :: 'plate P1', &
                                                  'plate P2', 'beam P1']
        type(solution_t) :: sol
        integer :: k
        cases(1) = nondim_plate(1.0e6_dp, 1.0e-3_dp, 0.1_dp, 0.6_dp, 160)
        cases(2) = cases(1)
        cases(2)%mesh%interp(FIELD_U:FIELD_SZ) = INTERP_P2
        cases(3) = nondim_beam(1.0e6_dp, 1.0e-3_dp, 0.05_dp, 0.6_dp, 0.1_dp, 160)
        cases_loop: do k = 1, size(cases)
            call require_solved(cases(k), names(k)//' N_e 160', err, sol)
            if (allocated(err)) return
            call check(err, sol%residual(1) <= 1.0e-8_dp, names(k)// &
                       ': residual of 4.2a above 1e-8 of the load')
            if (allocated(err)) return
        end do cases_loop
    end subroutine test_stiff_fine_mesh

    !> Newton and the paper's two-loop iteration solve the same equations: where both
    !! converge they agree to 1e-8 (max-norm of each block of z = [v; r], relative). The
    !! two-loop runs with tol outer = tol inner = 1e-13 so that its own stopping error is far
    !! below 1e-8.
    subroutine test_agreement(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: cases(3)
        type(solution_t) :: newton
        integer :: k
        cases(1) = nondim_plate(1.0e-3_dp, 0.1_dp, 0.1_dp, 0.6_dp, 20)
        cases(2) = nondim_beam(0.01_dp, 0.1_dp, 0.05_dp, 0.6_dp, 0.3_dp, 40)
        cases(3) = nondim_beam(1.0e-5_dp, 0.2_dp, 0.05_dp, 0.6_dp, 0.1_dp, 30)
        cases_loop: do k = 1, size(cases)
            cases(k)%solver%method = METHOD_NEWTON
            call require_solved(cases(k), 'agreement case, Newton', err, newton)
            if (allocated(err)) return
            call require_two_loop_agrees(cases(k), newton, 'agreement case', err)
            if (allocated(err)) return
        end do cases_loop
    end subroutine test_agreement

    !> The paper's two-loop iteration on m (tol outer = tol inner = 1e-13, so that its own
    !! stopping error is far below 1e-8) solves and agrees with the Newton solution to 1e-8
    !! (max-norm of each block of z = [v; r], relative).
    subroutine require_two_loop_agrees(m, newton, what, err)
        type(model_t), intent(in) :: m
        type(solution_t), intent(in) :: newton
        character(len=*), intent(in) :: what
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: mt
        type(solution_t) :: two_loop
        type(discretization_t) :: d
        real(dp) :: diff(2)
        mt = m
        mt%solver%method = METHOD_TWOLOOP
        mt%solver%tol_outer = 1.0e-13_dp
        mt%solver%tol_inner = 1.0e-13_dp
        mt%solver%max_outer = 1000
        call require_solved(mt, what//', two-loop', err, two_loop)
        if (allocated(err)) return
        call new_discretization(mt, d, err)
        if (allocated(err)) return
        associate (zn => newton%z, zt => two_loop%z, nv => d%nv)
            diff = [maxval(abs(zn(1:nv) - zt(1:nv)))/maxval(abs(zt(1:nv))), &
                    maxval(abs(zn(nv + 1:) - zt(nv + 1:)))/maxval(abs(zt(nv + 1:)))]
        end associate
        call check_close(err, maxval(diff), 0.0_dp, 0.0_dp, 1.0e-8_dp, &
                         what//': Newton and two-loop, relative difference of [v; r]')
    end subroutine require_two_loop_agrees

    !> input/paper/fig07_ref.dat case 5: the "second converged state" with
    !! max |Sigma_x| = 1.449 fails the complete problem (4.2b residual 7e2); every method the
    !! reviewers of the solver tried independently (two-loop from 7 starts, Newton with and without
    !! continuation, a smoothing Newton without active sets) reaches max |Sigma_x| = 1.386299
    !! to 6e-11. The Newton method must reach it too, with the checks of require_solved.
    subroutine test_fig07_case5(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(station_table_t) :: tab
        character(len=:), allocatable :: label
        call read_deck('input/paper/fig07_ref.dat', deck, err)
        if (allocated(err)) return
        call case_model(deck, 5, m, label, err)
        if (allocated(err)) return
        m%solver%method = METHOD_NEWTON
        call require_solved(m, 'fig07_ref case 5', err, tab_out=tab)
        if (allocated(err)) return
        call check_close(err, maxval(abs(nd_all(m, tab, 'Sigma_x^h'))), 1.386299_dp, &
                         1.0e-6_dp, 0.0_dp, 'fig07_ref case 5: max |Sigma_x|')
    end subroutine test_fig07_case5

    !> input/paper/fig07_s2.dat case 3 (beam, rho 0.0025, S2 tractions, N_e 20): the full
    !! Newton steps cycle near the lifted end, three points at sigma_z ~ 0 flipping between
    !! tension and slip together; the plain iteration stalled and the continuation restarted
    !! (29 to 32 linear solves, by rounding). The single-flip step (newton_method) must break
    !! the cycle within the plain stage (stage 1, no continuation), to a solution that passes
    !! require_solved's checks and agrees with the paper's two-loop iteration (an independent
    !! method on the same equations, run to 1e-13) to 1e-8.
    subroutine test_single_flip(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m
        type(solution_t) :: newton
        character(len=:), allocatable :: label
        call read_deck('input/paper/fig07_s2.dat', deck, err)
        if (allocated(err)) return
        call case_model(deck, 3, m, label, err)
        if (allocated(err)) return
        m%solver%method = METHOD_NEWTON
        call require_solved(m, 'fig07_s2 case 3, Newton', err, newton)
        if (allocated(err)) return
        call check(err, newton%n_outer == 1, 'fig07_s2 case 3: the plain Newton stage '// &
                   'must converge (the cycle broken without continuation)')
        if (allocated(err)) return
        call require_two_loop_agrees(m, newton, 'fig07_s2 case 3', err)
    end subroutine test_single_flip

    !> The cycle of test_single_flip must be broken within the plain stage whatever the last
    !! bits of the arithmetic: a load changed by k units of round-off (F (1 + k eps),
    !! k = -20..20, a change of at most 4.4e-15 that no result may notice) changes the
    !! rounding of every step as another BLAS kernel does (OpenBLAS's Haswell and generic
    !! kernels give this case different last bits). On the cycle's Newton ray the merit is
    !! lowest at a kink, where a point's set, and so the merit, is decided by the last bit
    !! of its traction: the iteration must not hang on which side round-off puts it.
    subroutine test_flip_rounding(err)
        type(error_t), allocatable, intent(out) :: err
        type(deck_t) :: deck
        type(model_t) :: m, changed
        type(solution_t) :: sol
        type(station_table_t) :: tab
        character(len=:), allocatable :: label
        character(len=12) :: k_text
        integer :: k
        call read_deck('input/paper/fig07_s2.dat', deck, err)
        if (allocated(err)) return
        call case_model(deck, 3, m, label, err)
        if (allocated(err)) return
        m%solver%method = METHOD_NEWTON
        loads: do k = -20, 20
            changed = m
            changed%loads(1)%fz = m%loads(1)%fz*(1.0_dp + real(k, dp)*epsilon(1.0_dp))
            call run(changed, sol, tab, err)
            write (k_text, '(i0)') k
            if (allocated(err)) then
                err%message = 'fig07_s2 case 3, load x (1 + '//trim(k_text)//' eps): '// &
                              err%message
                return
            end if
            call check(err, sol%n_outer == 1, 'fig07_s2 case 3, load x (1 + '// &
                       trim(k_text)//' eps): the plain Newton stage must converge')
            if (allocated(err)) return
        end do loads
    end subroutine test_flip_rounding

    !> A Newton step by the Schur complement onto the tractions (fresh, then
    !! by a low-rank update after two contact points change state) solves J x = b as the dense
    !! LDL^T / LU of the complete Jacobian does, to 1e-9 of max |x| (both are backward stable;
    !! the margin is round-off times the condition number of these small systems).
    subroutine test_schur_matches_dense(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: cases(2)
        integer :: k
        cases = [nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 20), &
                 nondim_beam(0.01_dp, 0.1_dp, 0.05_dp, 0.6_dp, 0.1_dp, 20)]
        do k = 1, size(cases)
            call compare_schur_dense(cases(k), err)
            if (allocated(err)) return
        end do
    end subroutine test_schur_matches_dense

    subroutine compare_schur_dense(m, err)
        type(model_t), intent(in) :: m
        type(error_t), allocatable, intent(out) :: err
        type(case_t) :: c
        type(system_t) :: sys
        type(schur_t) :: sc
        type(schur_factor_t) :: fac
        type(set_terms_t) :: st
        real(dp), allocatable :: sigma(:, :), b(:)
        integer :: i, flipped
        logical :: factorised
        call solve_case(m, c, err)
        if (.not. allocated(err)) call build_system(m, c%d, c%sol%pts, sys, err)
        if (allocated(err)) return
        call use_rigid_coordinates(sys)      ! as the solvers use it
        call new_schur(c%d, sys, sc)
        call check(err, sc%ready, 'the Schur complement is not ready')
        if (allocated(err)) return
        b = [(sin(real(i, dp)), i=1, c%d%n)]
        sigma = point_tractions(c%sol%pts, c%sol%z)
        call set_terms(sys, sys%law, c%sol%pts, sigma, st)
        call schur_prepare(sc, st, fac, factorised, err)
        if (allocated(err)) return
        call check(err, factorised, 'first Schur step not factorised')
        if (.not. allocated(err)) call compare_one(c%d, sys, sc, fac, c%sol, sigma, b, err)
        if (allocated(err)) return
        ! two points in compression lift off: a low-rank change of the set terms
        flipped = 0
        points: do i = 1, size(sigma, 2)
            if (sigma(2, i) <= 0.0_dp) cycle points
            sigma(2, i) = -sigma(2, i)
            flipped = flipped + 1
            if (flipped == 2) exit points
        end do points
        call set_terms(sys, sys%law, c%sol%pts, sigma, st)
        call schur_prepare(sc, st, fac, factorised, err)
        if (allocated(err)) return
        call check(err, .not. factorised .and. fac%nu > 0, 'two changed points: no update')
        if (.not. allocated(err)) call compare_one(c%d, sys, sc, fac, c%sol, sigma, b, err)
    end subroutine compare_schur_dense

    subroutine compare_one(d, sys, sc, fac, sol, sigma, b, err)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(schur_t), intent(in) :: sc
        type(schur_factor_t), intent(in) :: fac
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: sigma(:, :), b(:)
        type(error_t), allocatable, intent(out) :: err
        type(set_terms_t) :: st
        real(dp), allocatable :: a(:, :), x_dense(:), x_schur(:)
        logical :: symmetric
        allocate (x_dense(d%n), x_schur(d%n))
        call complete_jacobian(d, sys, sys%law, sol%pts, sigma, a, symmetric)
        call solve_equilibrated(a, b, x_dense, symmetric, err)
        if (allocated(err)) return
        call set_terms(sys, sys%law, sol%pts, sigma, st)
        call schur_solve(sys, sc, st, fac, b, x_schur, err)
        if (allocated(err)) return
        call check_close(err, maxval(abs(x_schur - x_dense))/maxval(abs(x_dense)), 0.0_dp, &
                         0.0_dp, 1.0e-9_dp, 'Schur vs dense solve, relative difference')
    end subroutine compare_one

    !> band_solve (the Schur complement's K_ii solves, one and many right-hand sides) against
    !! LAPACK's dpbtrs with the same
    !! dpbtrf factor, and against the matrix itself (the residual K x - b), on a symmetric
    !! positive definite band matrix (n = 40, kd = 4: diagonal 10, off-diagonals from a fixed
    !! sine pattern of size at most 1, so K is diagonally dominant) with three right-hand
    !! sides, one of them zero but for its last entry (the substitution's far end).
    subroutine test_band_solve(err)
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: n = 40, kd = 4, nrhs = 3
        real(dp) :: band(kd + 1, n), factor(kd + 1, n), b(n, nrhs), x(n, nrhs), x_ref(n, nrhs)
        real(dp) :: r(n), xt(nrhs, n)
        integer :: i, j, c, info
        do j = 1, n
            band(1, j) = 10.0_dp
            do i = 2, kd + 1
                band(i, j) = sin(real(7*j + 3*i, dp))
            end do
        end do
        do c = 1, nrhs
            do i = 1, n
                b(i, c) = cos(real(i*c, dp))
            end do
        end do
        b(1:n - 1, 3) = 0.0_dp
        factor = band
        call dpbtrf('L', n, kd, factor, kd + 1, info)
        call check(err, info == 0, 'dpbtrf failed on a diagonally dominant band')
        if (allocated(err)) return
        x = b
        call band_cholesky_solve(factor, kd, x)
        x_ref = b
        call dpbtrs('L', n, kd, nrhs, factor, kd + 1, x_ref, n, info)
        call check(err, info == 0 .and. maxval(abs(x - x_ref)) <= 1.0e-14_dp*maxval(abs(x_ref)), &
                   'band_cholesky_solve differs from dpbtrs')
        if (allocated(err)) return
        xt = transpose(b)
        call band_cholesky_solve_rows(factor, kd, xt)
        call check(err, maxval(abs(transpose(xt) - x_ref)) <= 1.0e-14_dp*maxval(abs(x_ref)), &
                   'band_cholesky_solve_rows differs from dpbtrs')
        if (allocated(err)) return
        ! the third alone: its forward substitution starts at its only nonzero, row n
        xt(1:1, :) = transpose(b(:, 3:3))
        call band_cholesky_solve_rows(factor, kd, xt(1:1, :))
        call check(err, maxval(abs(xt(1, :) - x_ref(:, 3))) <= 1.0e-14_dp*maxval(abs(x_ref(:, &
            3))), &
                   'band_cholesky_solve_rows from its first nonzero row differs from dpbtrs')
        if (allocated(err)) return
        do c = 1, nrhs
            r = -b(:, c)
            do j = 1, n          ! r += K x from the lower band and its mirror
                do i = j, min(n, j + kd)
                    r(i) = r(i) + band(1 + i - j, j)*x(j, c)
                    if (i /= j) r(j) = r(j) + band(1 + i - j, j)*x(i, c)
                end do
            end do
            call check(err, maxval(abs(r)) <= 1.0e-14_dp*maxval(abs(b(:, c))), &
                       'band_cholesky_solve: residual K x - b too large')
            if (allocated(err)) return
        end do
    end subroutine test_band_solve
end module test_newton
