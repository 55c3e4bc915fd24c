!> Contact solver against closed forms and physical laws (doc/SPEC.md §4).
module test_contact_solver
    use kinds, only: dp, pi
    use harness, only: unittest_t, new_unittest, error_t, check, check_close
    use errors, only: EXIT_ANALYSIS, EXIT_INPUT
    use model, only: model_t, load_t, MODEL_BEAM, MODEL_PLATE, LOAD_POINT, LOAD_PATCH, &
                     complete_model, relative_stiffness, METHOD_NEWTON, METHOD_TWOLOOP
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact, STATE_LIFTOFF
    use station_results, only: station_table_t, tabulate, contact_extent
    use resource_limits, only: check_memory, case_memory, case_unknowns
    use model, only: METHOD_NEWTON, METHOD_TWOLOOP
    use station_columns, only: Q_GAP
    use shape_functions, only: INTERP_P1, INTERP_P2, INTERP_S2
    use station_test_support, only: nd, nd_all
    use contact_test_support, only: nondim_plate, nondim_beam, run
    implicit none
    private
    public :: collect_contact_solver

contains

    subroutine collect_contact_solver(tests)
        type(unittest_t), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('rigid_punch_frictionless', test_rigid_punch), &
                 new_unittest('equilibrium_beam_and_plate', test_equilibrium), &
                 new_unittest('frictionless_has_no_shear', test_frictionless_shear), &
                 new_unittest('bonded_punch_mossakovskii', test_bonded_punch), &
                 new_unittest('bonded_equals_frictionless_nu_half', test_bonded_nu_half), &
                 new_unittest('flexible_plate_lifts_off', test_lift_off), &
                 new_unittest('friction_admissible_everywhere', test_admissibility), &
                 new_unittest('table1_eps_trend', test_table1_trend), &
                 new_unittest('beam_sliding_status_2', test_sliding), &
                 new_unittest('uplift_status_2', test_uplift), &
                 new_unittest('no_convergence_status_2', test_no_convergence), &
                 new_unittest('soft_beam_hard_case', test_soft_beam), &
                 new_unittest('ill_conditioned_refused', test_ill_conditioned), &
                 new_unittest('iteration_cap_allocates_nothing', test_iteration_cap), &
                 new_unittest('memory_beyond_machine_refused', test_memory_limit)]
    end subroutine collect_contact_solver

    !> Rigid frictionless punch (Boussinesq 1885; Johnson 1985 §3.8): w = F(1-nu_f^2)/(2 E_f a),
    !! i.e. W(0) = rho/4, and Sigma_z = 1/(2 sqrt(1 - t^2)).
    subroutine test_rigid_punch(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        integer :: i
        real(dp) :: t
        m = nondim_plate(1.0e3_dp, 0.1_dp, 0.1_dp, 0.0_dp, 40)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        call check_close(err, nd(m, tab, 'W', 1), relative_stiffness(m%structure, &
            m%ground)/4.0_dp, &
                         1.0e-2_dp, 0.0_dp, 'rigid punch W(0)')
        if (allocated(err)) return
        do i = 1, tab%n
            t = nd(m, tab, 't', i)
            if (t > 0.7_dp) exit
            call check_close(err, nd(m, tab, 'Sigma_z', i), 0.5_dp/sqrt(1.0_dp - t*t), &
                             3.0e-2_dp, 0.0_dp, 'rigid punch Sigma_z')
            if (allocated(err)) return
        end do
    end subroutine test_rigid_punch

    !> Total reaction = load (to 1e-8 of F) for a beam with H, a moment-producing offset and a
    !! plate with a patch.
    subroutine test_equilibrium(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        integer :: k
        m = nondim_beam(0.01_dp, 0.1_dp, 0.05_dp, 0.6_dp, 0.2_dp, 30)
        m%loads(1)%x1 = 0.1_dp
        call run(m, sol, tab, err)
        if (allocated(err)) return
        do k = 1, 3
            call check(err, abs(sol%reaction(k) - sol%applied(k)) <= 1.0e-8_dp, &
                       'beam equilibrium component violated')
            if (allocated(err)) return
        end do
        m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 30)
        m%loads = [load_t(kind=LOAD_PATCH, fz=1.0_dp, x1=0.0_dp, x2=0.3_dp)]
        call run(m, sol, tab, err)
        if (allocated(err)) return
        call check(err, abs(sol%reaction(1) - 1.0_dp) <= 1.0e-8_dp .and. &
                   abs(sol%reaction(2)) <= 1.0e-8_dp, 'plate equilibrium violated')
    end subroutine test_equilibrium

    !> f = 0: the regularised law leaves |Sigma_x| of order eps_bar (Coulomb: exactly 0).
    subroutine test_frictionless_shear(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        m = nondim_plate(0.05_dp, 0.1_dp, 0.1_dp, 0.0_dp, 30)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        call check(err, maxval(abs(nd_all(m, tab, 'Sigma_x'))) <= 1.0e-4_dp, &
                   'f = 0 but Sigma_x is not ~ 0')
    end subroutine test_frictionless_shear

    !> Bonded rigid punch (Mossakovskii 1954; Spence 1968): F/delta = 4 G_f a ln(3-4nu_f)/(1-2nu_f),
    !! W(0) = rho/(4 c), c = (1-nu_f) ln(3-4nu_f)/(1-2nu_f) = 1.07495 for nu_f = 0.1.
    subroutine test_bonded_punch(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        real(dp) :: c, w_bonded, w_free
        m = nondim_plate(1.0e3_dp, 0.1_dp, 0.1_dp, 1.0e3_dp, 40)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        w_bonded = nd(m, tab, 'W', 1)
        c = 0.9_dp*log(3.0_dp - 0.4_dp)/0.8_dp
        call check_close(err, w_bonded, relative_stiffness(m%structure, m%ground)/(4.0_dp*c), &
            2.0e-2_dp, 0.0_dp, &
                         'bonded punch W(0)')
        if (allocated(err)) return
        w_free = relative_stiffness(m%structure, m%ground)/4.0_dp
        call check(err, w_bonded < w_free, 'bonded punch is not stiffer than the frictionless one')
    end subroutine test_bonded_punch

    !> nu_f = 0.5: no normal/tangential coupling, so a rigid bonded punch settles as a smooth one.
    subroutine test_bonded_nu_half(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        real(dp) :: w_bonded, w_free
        m = nondim_plate(1.0e4_dp, 0.1_dp, 0.5_dp, 1.0e3_dp, 30)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        w_bonded = nd(m, tab, 'W', 1)
        m = nondim_plate(1.0e4_dp, 0.1_dp, 0.5_dp, 0.0_dp, 30)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        w_free = nd(m, tab, 'W', 1)
        call check_close(err, w_bonded, w_free, 1.0e-3_dp, 0.0_dp, 'nu_f = 0.5 bonded vs smooth')
    end subroutine test_bonded_nu_half

    !> A flexible plate under a central load lifts off at the rim; a stiff one stays in contact.
    !! Complementarity: sigma_z * gap ~ 0 (penalty, O(eta_bar)).
    subroutine test_lift_off(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        m = nondim_plate(1.0e-3_dp, 0.05_dp, 0.1_dp, 0.5_dp, 40)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        call check(err, contact_extent(tab, &
            m%structure%length) < 0.9_dp .and. tab%state(tab%n) == STATE_LIFTOFF, &
                   'flexible plate did not lift off')
        if (allocated(err)) return
        ! penalty: sigma_z = -(eta_bar/c) gap in the lift-off zone, so sigma_z * gap = O(eta_bar)
        call check(err, tab%complementarity <= 1.0e3_dp*m%interface%eta_bar, &
            'complementarity violated')
        if (allocated(err)) return
        call check(err, all(tab%val(Q_GAP, :) > 0.0_dp .or. tab%state /= STATE_LIFTOFF), &
                   'lift-off station without a positive gap')
        if (allocated(err)) return
        m = nondim_plate(10.0_dp, 0.1_dp, 0.1_dp, 0.5_dp, 40)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        call check(err, all(tab%state(1:tab%n - 1) /= STATE_LIFTOFF), 'stiff plate lifted off')
    end subroutine test_lift_off

    !> |Sigma_x| <= f Sigma_z + O(eps_bar) at every Gauss point (SPEC §4).
    subroutine test_admissibility(err)
        type(error_t), allocatable, intent(out) :: err
        call require_admissible(nondim_plate(0.01_dp, 0.2_dp, 0.1_dp, 0.2_dp, 30), 'plate', err)
        if (allocated(err)) return
        call require_admissible(nondim_beam(0.0025_dp, 0.1_dp, 0.005_dp, 0.6_dp, 0.1_dp, 20), &
                                'beam', err)
    end subroutine test_admissibility

    !> m solves, and |Sigma_x| <= f Sigma_z + 1e3 eps_bar at every Gauss point.
    subroutine require_admissible(m, what, err)
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: what
        type(error_t), allocatable, intent(out) :: err
        type(solution_t) :: sol
        type(station_table_t) :: tab
        call run(m, sol, tab, err)
        if (allocated(err)) return
        call check(err, sol%admissibility*nd(m, tab, 'Sigma_z', &
            0) <= 1.0e3_dp*m%interface%eps_bar, &
                   what//': |Sigma_x| exceeds f Sigma_z beyond the regularisation')
    end subroutine require_admissible

    !> Paper Table 1 trend (beam, rho = 0.0025, f = 0.6, N_e = 20, central load with H/V = 0.1,
    !! b/l = 0.005, zeta = 0.1): W and Sigma_z at eps_bar = 1e-4 and 1e-7 agree to 1e-4; 1e-1
    !! differs. Sigma_x agrees only to ~2e-3 with the SPEC reading of the law (the slip branch
    !! stiffness is eps_bar/c): the regularisation error is linear in eps_bar, which is asserted
    !! instead: the change from 1e-7 to 1e-8 is (1e-7 - 1e-8)/(1e-4 - 1e-7) = 9e-4 of the change
    !! from 1e-4 to 1e-7 (asserted below 2e-3).
    subroutine test_table1_trend(err)
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: val(3, 4), eps(4), ratio
        integer :: k, mid
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        eps = [1.0e-1_dp, 1.0e-4_dp, 1.0e-7_dp, 1.0e-8_dp]
        do k = 1, 4
            m = nondim_beam(0.0025_dp, 0.1_dp, 0.005_dp, 0.6_dp, 0.1_dp, 20)
            m%interface%eps_bar = eps(k)
            call run(m, sol, tab, err)
            if (allocated(err)) return
            mid = (tab%n + 1)/2
            val(:, k) = [nd(m, tab, 'W', mid), nd(m, tab, 'Sigma_x', mid), &
                         nd(m, tab, 'Sigma_z', mid)]
        end do
        do k = 1, 3, 2
            call check_close(err, val(k, 2), val(k, 3), 1.0e-4_dp, 0.0_dp, 'eps 1e-4 vs 1e-7')
            if (allocated(err)) return
        end do
        ratio = abs(val(2, 3) - val(2, 4))/abs(val(2, 2) - val(2, 3))
        call check(err, ratio < 2.0e-3_dp, 'Sigma_x does not converge linearly in eps_bar')
        if (allocated(err)) return
        call check(err, abs(val(2, 1) - val(2, 3)) > 1.0e-2_dp*abs(val(2, 3)), &
                   'eps 1e-1 should differ from 1e-7')
    end subroutine test_table1_trend

    !> H > f V: no equilibrium, status 2 with a sliding message.
    subroutine test_sliding(err)
        type(error_t), allocatable, intent(out) :: err
        call expect_status_2(nondim_beam(0.01_dp, 0.1_dp, 0.05_dp, 0.3_dp, 0.31_dp, 20), &
                             'sliding', 'H > f V was solved', &
                             'H > f V: expected status 2 and a sliding message', err)
    end subroutine test_sliding

    !> m must end with status 2 (EXIT_ANALYSIS) and a message that contains word.
    subroutine expect_status_2(m, word, if_solved, if_other, err)
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: word
        character(len=*), intent(in) :: if_solved      !! the message if m solves
        character(len=*), intent(in) :: if_other       !! the message if m fails otherwise
        type(error_t), allocatable, intent(out) :: err
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(error_t), allocatable :: run_err
        call run(m, sol, tab, run_err)
        call check(err, allocated(run_err), if_solved)
        if (allocated(err)) return
        call check(err, run_err%code == EXIT_ANALYSIS .and. &
                   index(run_err%message, word) > 0, if_other)
    end subroutine expect_status_2

    !> An upward net load has no equilibrium on a tensionless soil: status 2.
    subroutine test_uplift(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 10)
        m%loads(1)%fz = -1.0_dp
        call expect_status_2(m, 'uplift', 'uplift was solved', 'uplift: expected status 2', err)
    end subroutine test_uplift

    !> An iteration limit too small to converge: status 2 naming the loop, never a result.
    !! Two-loop method with two outer iterations; Newton with one step per stage (the case
    !! needs several: its contact zone and slip zone are far from the adhesive start's).
    subroutine test_no_convergence(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        m = nondim_plate(1.0e-3_dp, 0.05_dp, 0.1_dp, 0.5_dp, 20)
        m%solver%method = METHOD_TWOLOOP
        m%solver%max_outer = 2
        call expect_status_2(m, 'did not converge', 'two outer iterations should not suffice', &
                             'expected status 2', err)
        if (allocated(err)) return
        m%solver%method = METHOD_NEWTON
        m%solver%max_outer = 100
        m%solver%max_inner = 1
        call expect_status_2(m, 'did not converge', &
                             'one Newton step per stage should not suffice', &
                             'Newton: expected status 2', err)
    end subroutine test_no_convergence

    !> rho = 1e-5, zeta = 0.2: the plain fixed point does not settle (the paper's known hard
    !! case); the line-search fallback must reach a state that satisfies the checks.
    subroutine test_soft_beam(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        m = nondim_beam(1.0e-5_dp, 0.2_dp, 0.05_dp, 0.6_dp, 0.1_dp, 60)
        call run(m, sol, tab, err)
        if (allocated(err)) return
        call check(err, maxval(abs(sol%reaction - sol%applied)) <= 1.0e-8_dp .and. &
                   sol%residual(2) <= 1.0e-8_dp .and. &
                   sol%admissibility*nd(m, tab, 'Sigma_z', 0) <= 1.0e3_dp*m%interface%eps_bar, &
                   'soft beam: equilibrium, interface residual or admissibility violated')
    end subroutine test_soft_beam

    !> rho = 1e4 on a 150-element EDGES mesh: the linear solves lose all accuracy (found by the
    !! convergence study: a solver without the accuracy guard ends "solved" with every point
    !! lifted off and a reaction of -1e-4 F). It must end with status 2, never with a result
    !! that fails equilibrium.
    subroutine test_ill_conditioned(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(error_t), allocatable :: run_err
        m = nondim_plate(1.0e4_dp, 0.1_dp, 0.1_dp, 1.0e3_dp, 150)
        m%mesh%grading = 'EDGES'
        call run(m, sol, tab, run_err)
        if (.not. allocated(run_err)) then
            ! solved after all: then it must satisfy its checks
            call check(err, abs(sol%reaction(1) - 1.0_dp) <= 1.0e-6_dp, &
                       'ill-conditioned case returned a result that fails equilibrium')
            return
        end if
        call check(err, run_err%code == EXIT_ANALYSIS, 'expected status 2')
    end subroutine test_ill_conditioned
    !> Limits refused, not crashed into: SOLVER max inner = 1e9 (a method that kept every set
    !! pattern would allocate 320 GB). Both methods must solve with such a cap: nothing is
    !! allocated in proportion to it.
    subroutine test_iteration_cap(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(solution_t) :: sol
        type(station_table_t) :: tab
        integer :: k
        do k = 1, 2
            m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 20)
            m%solver%max_inner = 1000000000
            m%solver%method = merge(METHOD_NEWTON, METHOD_TWOLOOP, k == 1)
            call run(m, sol, tab, err)
            if (allocated(err)) return
        end do
    end subroutine test_iteration_cap

    !> A case that does not fit is refused with its need and the limit: N_e = 40000 on a
    !! plate gives n = 200005 unknowns, nr = 80002 of them tractions, about 21 nr^2 bytes =
    !! 134 GB (Newton) > 0.8 x 16 GB; N_e = 20 fits. A P1 plate of N_e = 10000 (nr = 20002)
    !! fits a machine with 24 GB available: the measured peaks (doc/CHOICES.md, "Memory
    !! model") grow like 17 to 19.5 bytes per nr^2, i.e. 6.8 to 7.8 GB. The estimate is at
    !! least, and at most 1.5 times, the peak resident size measured with GNU time for each
    !! kind and interpolation of that table (P1, P2 tractions, S2; beam and plate; the
    !! two-loop method).
    subroutine test_memory_limit(err)
        type(error_t), allocatable, intent(out) :: err
        type(model_t) :: m
        type(error_t), allocatable :: refusal
        m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 40000)
        call check(err, case_unknowns(m) == 200005, 'unknowns of a P1 plate: 5 (N_e + 1)')
        if (allocated(err)) return
        call check_memory(m, 1, 16.0e9_dp, refusal)
        call check(err, allocated(refusal), 'a 134 GB case was not refused')
        if (allocated(err)) return
        call check(err, refusal%code == EXIT_INPUT .and. index(refusal%message, 'GB') > 0 .and. &
                   index(refusal%message, '12.8 GB usable') > 0, 'refusal lacks need or limit: '// &
                   refusal%message)
        if (allocated(err)) return
        m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 20)
        call check_memory(m, 1, 16.0e9_dp, refusal)
        call check(err, .not. allocated(refusal), 'a small case was refused')
        if (allocated(err)) return
        m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.5_dp, 10000)
        call check_memory(m, 1, 24.0e9_dp, refusal)
        call check(err, .not. allocated(refusal), 'a P1 plate of N_e 10000 (about 7 GB) was '// &
                   'refused with 24 GB available')
        if (allocated(err)) return
        call check_measured_peaks(err)
    end subroutine test_memory_limit

    !> The estimate against the measured peaks (scripts/memory_table.sh and doc/CHOICES.md:
    !! peak resident size in MiB, NONDIM rho 0.01, zeta 0.1, f 0.6, UNIFORM): it must cover
    !! each and exceed none by more than half.
    subroutine check_measured_peaks(err)
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: n_rows = 9
        ! kind (1 plate, 2 beam), N_e, interpolation of displacements and tractions, method
        ! (1 Newton, 2 two-loop), peak [MiB]
        integer, parameter :: kinds(n_rows) = [1, 1, 1, 1, 2, 2, 2, 2, 1]
        integer, parameter :: nes(n_rows) = [1000, 3000, 1000, 1000, 1000, 3000, 1000, 1000, &
                                             500]
        integer, parameter :: disp(n_rows) = [INTERP_P1, INTERP_P1, INTERP_P1, INTERP_S2, &
            INTERP_P1, INTERP_P1, INTERP_P1, INTERP_S2, INTERP_P1]
        integer, parameter :: trac(n_rows) = [INTERP_P1, INTERP_P1, INTERP_P2, INTERP_S2, &
            INTERP_P1, INTERP_P1, INTERP_P2, INTERP_S2, INTERP_P1]
        integer, parameter :: methods(n_rows) = [1, 1, 1, 1, 1, 1, 1, 1, 2]
        real(dp), parameter :: peak_mib(n_rows) = [82.4_dp, 591.4_dp, 274.7_dp, 85.5_dp, &
            85.2_dp, 601.5_dp, 302.7_dp, 87.0_dp, 114.0_dp]
        type(model_t) :: m
        real(dp) :: ratio
        character(len=80) :: what
        integer :: k
        rows: do k = 1, n_rows
            if (kinds(k) == 1) then
                m = nondim_plate(0.01_dp, 0.1_dp, 0.1_dp, 0.6_dp, nes(k))
            else
                m = nondim_beam(0.01_dp, 0.1_dp, 0.1_dp, 0.6_dp, 0.1_dp, nes(k))
            end if
            m%mesh%interp(1:3) = disp(k)
            m%mesh%interp(4:5) = trac(k)
            m%solver%method = merge(METHOD_NEWTON, METHOD_TWOLOOP, methods(k) == 1)
            ratio = case_memory(m)/(peak_mib(k)*1048576.0_dp)
            write (what, '(a,i0,a,f5.2)') 'row ', k, ' of the memory table: estimate/peak = ', &
                ratio
            call check(err, ratio >= 1.0_dp .and. ratio <= 1.5_dp, trim(what))
            if (allocated(err)) return
        end do rows
    end subroutine check_measured_peaks
end module test_contact_solver
