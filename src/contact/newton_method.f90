!> Globalised semismooth (generalised) Newton method on the complete discrete problem (paper
!! 4.2 with tau0 = f max(sigma_z, 0) inside the equations, SPEC §4; F and its generalised
!! Jacobian in contact_system). The friction threshold and the contact sets are solved together:
!! on the slipping points in compression the Jacobian holds the non-symmetric block
!! d tau0/d sigma_z (LU then; LDL^T where the Jacobian is symmetric).
!!
!! Globalisation:
!! - start: the solution for the sets predicted by the nested coarser mesh (contact_solver),
!!   else the adhesive (bonded, bilateral) solution A0 z = [q; 0], the paper's start;
!! - merit: the Jacobi correction |F_i / J_ii| of every equation (J at the point where F is
!!   evaluated) relative to max |v| or max |r| at the start of the stage, in the 2-norm: the
!!   penalty and slip rows, whose entries carry 1/eta_bar and 1/eps_bar, count in tractions;
!! - watchdog: full steps while they lower the best merit, or for up to `watchdog` steps without
!!   descent; then the exact line search from the best point along its direction. F is
!!   piecewise linear along a Newton ray (kinks where a point crosses sigma_z = 0 or
!!   |sigma_x| = f sigma_z), so the merit is minimised exactly piece by piece; a kink, where
!!   the weights jump and round-off decides the crossing point's set, counts with the larger
!!   of the merits on its two sides. A step to a set pattern met in the last 16 iterates (a
!!   cycle) is replaced by the better of the exact line search along it (its merit on a kink:
!!   the larger side's) and the single-flip step (Murty's fallback for block pivoting: the
!!   solution for the pattern with only the ray's first crossing point changed, one more
!!   linear solve); a full step that keeps the set pattern is always taken (it solves F = 0);
!! - continuation where the plain iteration stalls (25 steps, the watchdog runs out once - its
!!   line search from the best point does not halve the best merit -, or a damped step no
!!   longer moves), from the same start: eps_bar scaled by 10^s from
!!   max(10^3 eps_bar, 1e-3) (at most 0.5) down to the deck's, eta_bar by 10^min(s, 3), each
!!   stage started from the previous solution, one decade per stage (doubled, up to 4, after
!!   a stage of at most 3 steps while s > 3: eps_bar = 1e-12 spans 9 decades). A failed stage
!!   is retried from the last converged one with half the decrement; a failed first stage
!!   from two decades more regularisation; the case ends with status 2 when the decrement falls
!!   below 1/8 decade or the first stage fails at eps_bar = 0.5.
!! A stage has converged when the merit is at round-off, or when a full step leaves the sets
!! it was computed with unchanged (F is then linear between the iterates and the step solves
!! F = 0 up to the accuracy of the solve) and the residual of 4.2a is below 1e-12 of the load
!! or no longer halves (further exact steps after an inaccurate solve). The converged solution is
!! then held in double-double and refined with 4.2a in double-double (refine_equilibrium: thin,
!! stiff structures on fine meshes, whose v' in double cannot meet 4.2a to 1e-8).
module newton_method
    use kinds, only: dp
    use double_double, only: two_sum
    use errors, only: error_t, new_error, EXIT_ANALYSIS
    use model, only: model_t, interface_t
    use discretization, only: discretization_t
    use linear_solve, only: solve_equilibrated
    use schur_solver, only: schur_t, schur_factor_t, new_schur, schur_prepare, schur_solve, &
                            schur_factorise
    use contact_system, only: solution_t, system_t, law_t, iteration_record_t, new_law, &
                              contact_points_t, &
                              point_tractions, complete_residual, complete_jacobian, &
                              jacobian_diagonal, relative_change, linear_part, &
                              set_terms_t, set_terms, jacobian_with_terms, &
                              equilibrium_residual
    use interface_law, only: friction_threshold, in_tension, is_slipping
    use sorting, only: sort_ascending
    implicit none
    private

    public :: solve_newton

    integer, parameter :: plain_limit = 25          !! Newton steps before continuation
    real(dp), parameter :: armijo = 1.0e-4_dp       !! sufficient decrease of the merit
    real(dp), parameter :: round_off = 1.0e3_dp*epsilon(1.0_dp)  !! merit of a solution
    real(dp), parameter :: refine_tol = 1.0e-12_dp  !! refine an exact step while 4.2a's
                                                    !! residual is above this (of max |q|)
    integer, parameter :: watchdog = 5             !! full steps allowed without descent
    real(dp), parameter :: stall_increment = 1.0e-12_dp  !! a damped step this small: stalled
    integer, parameter :: memory = 16               !! set patterns kept for cycle detection
    real(dp), parameter :: top_level = 3.0_dp       !! continuation starts at 10^3 eps, eta
    real(dp), parameter :: min_decrement = 0.125_dp !! smallest continuation step (decades)
    real(dp), parameter :: max_decrement = 4.0_dp   !! largest continuation step (decades)
    integer, parameter :: quick_stage = 3           !! a stage this short doubles the step

    !> The linear solver of the Newton steps and what it carries from step to step: the
    !! Schur complement onto the tractions (fixed for the case), its factorisation (updated
    !! or renewed across steps) and the tension set of the contact points at the previous
    !! step (settled_lift_off: tractions in tension at two successive steps may be decoupled
    !! in the factorisation).
    type :: step_solver_t
        type(schur_t) :: sc
        type(schur_factor_t) :: fac
        logical, allocatable :: tension_before(:)
    end type step_solver_t

    !> Merit bookkeeping of one Newton stage.
    type :: newton_state_t
        real(dp), allocatable :: res(:)      !! F at the current iterate
        real(dp) :: phi = 0.0_dp             !! merit there
        real(dp) :: block_scale(2) = 1.0_dp  !! max |v|, max |r| at the start of the stage
        real(dp) :: phi_best = 0.0_dp        !! lowest merit reached with sufficient decrease
        real(dp), allocatable :: z_best(:)   !! where
        real(dp), allocatable :: dz_best(:)  !! the Newton direction computed there
        integer :: relaxed = 0               !! full steps taken since, without descent
        real(dp) :: phi_now = 0.0_dp         !! merit at the current iterate
        integer, allocatable :: seen(:, :)   !! set patterns of the last iterates (ring)
        integer :: n_seen = 0                !! iterates recorded in seen
        logical :: exhausted = .false.       !! the watchdog has run out at least once
    end type newton_state_t

contains

    !> Solve the complete problem from the predicted or adhesive start; continuation if the
    !! plain method stalls. Fails with EXIT_ANALYSIS when neither converges.
    subroutine solve_newton(m, d, sys, sol, err, sigma_start)
        type(model_t), intent(in) :: m                          !! the model
        type(discretization_t), intent(in) :: d                 !! the discretisation
        type(system_t), intent(in) :: sys                       !! the assembled system (A0, q)
        type(solution_t), intent(inout) :: sol                  !! the solution, updated
        type(error_t), allocatable, intent(out) :: err          !! allocated on failure
        real(dp), allocatable, intent(in) :: sigma_start(:, :)  !! tractions at the contact
                                            !! points predicting the sets (else: adhesive)
        real(dp), allocatable :: z_start(:)
        type(step_solver_t) :: ls
        type(set_terms_t) :: st
        logical, allocatable :: settled(:)
        logical :: converged
        sol%method = 'NEWTON'
        call new_schur(d, sys, ls%sc)
        ls%sc%decouple = m%solver%simplify
        if (allocated(sigma_start)) then
            call set_terms(sys, sys%law, sol%pts, sigma_start, st)
            call log_note(sol, 'start: sets of the nested coarser mesh')
            ! the coarser mesh's converged sets count as the step before the start
            ls%tension_before = in_tension(sigma_start(2, :))
            settled = settled_lift_off(sol%pts, sigma_start, d%n, ls)
        else
            allocate (st%first(sol%pts%n + 1), st%row(0), st%col(0), st%val(0))
            st%first = 1
            allocate (settled(d%n), source=.false.)
        end if
        call solve_for_sets(d, sys, ls, st, settled, sol, err)
        if (allocated(err)) return
        z_start = sol%z
        call newton_stage(d, sys, ls, sys%law, 1, min(plain_limit, m%solver%max_inner), &
                          .false., sol, converged, err)
        if (allocated(err)) return
        if (.not. converged) then
            call log_note(sol, 'plain Newton stalled: continuation')
            sol%z = z_start
            call continuation(m, d, sys, ls, sol, err)
            if (allocated(err)) return
        end if
        call refine_equilibrium(d, sys, ls, sol, err)
    end subroutine solve_newton

    !> Iterative refinement of the converged solution in double-double, z + z_lo, where its
    !! 4.2a residual (in double-double: equilibrium_residual) is above refine_from of
    !! the load: the residual solved with the Newton matrix of the final sets and the
    !! correction added to the held sum, while 4.2a is above refine_tol and halves (at most
    !! max_refine steps). A thin, stiff structure needs it: no double v' meets 4.2a better
    !! than about eps |K| |v'| (4e-8 of the load at rho 1e6, zeta 1e-3, N_e 160, plate), one
    !! step brings it to 1e-15. Ordinary cases end at their own double floor, far below
    !! refine_from (input/plate_nondim.dat: 8e-14 to 1.2e-11 at N_e 20 to 1000): one
    !! residual, no solve.
    subroutine refine_equilibrium(d, sys, ls, sol, err)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: max_refine = 3
        !> two decades below the 1e-8 of the load to which the tests hold equilibrium
        real(dp), parameter :: refine_from = 1.0e-10_dp
        real(dp), allocatable :: res(:), dz(:), z_before(:, :)
        real(dp), allocatable :: sum_hi(:), sum_lo(:)
        real(dp) :: load, equilibrium, previous
        integer :: step
        allocate (res(d%n), sum_hi(d%n), sum_lo(d%n))
        sol%z_lo = spread(0.0_dp, 1, d%n)
        load = max(maxval(abs(sys%q)), tiny(1.0_dp))
        previous = huge(1.0_dp)
        ! max_refine solves; the pass after the last only judges (and may undo) its step
        steps: do step = 1, max_refine + 1
            call complete_residual(d, sys, sys%law, sol%pts, sol%z, res)
            res(1:d%nv) = equilibrium_residual(d, sys, sol%z, sol%z_lo)
            equilibrium = maxval(abs(res(1:d%nv)))/load
            if (equilibrium > previous) then
                ! round-off of the solve: keep the better held solution
                sol%z = z_before(:, 1)
                sol%z_lo = z_before(:, 2)
            end if
            if (equilibrium <= merge(refine_from, refine_tol, step == 1) .or. &
                equilibrium > 0.5_dp*previous .or. step > max_refine) exit steps
            previous = equilibrium
            call newton_direction(d, sys, ls, sys%law, sol, res, dz, err)
            if (allocated(err)) return
            z_before = reshape([sol%z, sol%z_lo], [d%n, 2])
            ! (z + z_lo) + dz in double-double: z + dz exactly as sum + its error, the old
            ! z_lo added to the error, renormalised so that |z_lo| <= ulp(z)/2
            call two_sum(sol%z, dz, sum_hi, sum_lo)
            sum_lo = sum_lo + sol%z_lo
            call two_sum(sum_hi, sum_lo, sol%z, sol%z_lo)
        end do steps
    end subroutine refine_equilibrium

    !> The start: the solution for the set terms st, J_st z = [q; 0] (F is linear on each set
    !! pattern and F(0) = -[q; 0], so one solve gives it). No set terms: bonded bilateral
    !! contact A0 z = [q; 0], the paper's adhesive start.
    subroutine solve_for_sets(d, sys, ls, st, settled, sol, err)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(set_terms_t), intent(in) :: st
        logical, intent(in) :: settled(:)   !! settled lift-off tractions (settled_lift_off)
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: a(:, :), rhs(:)
        logical :: factorised
        allocate (rhs(d%n))
        rhs = 0.0_dp
        rhs(1:d%nv) = sys%q
        rhs(d%fixed) = 0.0_dp
        factorised = .true.
        if (ls%sc%ready) then
            call schur_step(sys, ls, st, settled, rhs, sol%z, sol, factorised, err)
        else
            call jacobian_with_terms(d, sys, st, a)
            call solve_equilibrated(a, rhs, sol%z, st%symmetric, err)
        end if
        if (allocated(err)) return
        sol%n_solves = sol%n_solves + 1
        if (factorised) sol%n_factorisations = sol%n_factorisations + 1
    end subroutine solve_for_sets

    !> Stages from eps_bar = max(10^3 eps_bar, 1e-3) down to the deck's (stage_law) from
    !! sol%z, the decrement doubled after a quick stage; a stage that fails is retried from
    !! the last converged one with half the decrement, a first stage that fails from a
    !! regularisation two decades larger (up to eps_bar = 0.5).
    subroutine continuation(m, d, sys, ls, sol, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: z_good(:)
        real(dp) :: level, good_level, step
        integer :: stage, solves_before
        logical :: converged
        character(len=200) :: text
        level = max(top_level, log10(1.0e-3_dp/m%interface%eps_bar))
        good_level = huge(1.0_dp)
        step = 1.0_dp
        z_good = sol%z
        stage = 1
        stages: do
            stage = stage + 1
            solves_before = sol%n_solves
            call newton_stage(d, sys, ls, stage_law(m%interface, sys, level), stage, &
                m%solver%max_inner, &
                              .true., sol, converged, err)
            if (allocated(err)) return
            if (converged) then
                if (level <= 0.0_dp) return
                good_level = level
                z_good = sol%z
                if (sol%n_solves - solves_before <= quick_stage .and. level > top_level) &
                    step = min(2.0_dp*step, max_decrement)
                level = max(level - step, 0.0_dp)
            else if (good_level == huge(1.0_dp)) then
                if (m%interface%eps_bar*10.0_dp**level >= 0.5_dp) exit stages
                level = level + 2.0_dp
                sol%z = z_good
            else
                step = 0.5_dp*step
                if (step < min_decrement) exit stages
                sol%z = z_good
                level = max(good_level - step, 0.0_dp)
            end if
        end do stages
        write (text, '(a,f6.3,a,i0,a)') 'the contact problem did not converge: Newton stalled '// &
            'at eps_bar, eta_bar x 10^', level, ' of the continuation after ', sol%n_solves, &
            ' linear solves (no solution found)'
        call new_error(err, EXIT_ANALYSIS, trim(text))
    end subroutine continuation

    !> The deck's law with eps_bar scaled by 10^level (at most 0.5) and eta_bar by
    !! 10^min(level, top_level).
    pure function stage_law(interface, sys, level) result(law)
        type(interface_t), intent(in) :: interface   !! the interface part of the model
        type(system_t), intent(in) :: sys
        real(dp), intent(in) :: level
        type(law_t) :: law
        law = new_law(interface, sys%c, min(interface%eps_bar*10.0_dp**level, 0.5_dp), &
                      interface%eta_bar*10.0_dp**min(level, top_level))
    end function stage_law

    !> Newton iterations for one law from sol%z; converged tells whether it stopped on a
    !! convergence test (else it stalled or reached max_iter). Watchdog: full steps are taken
    !! even when they raise the merit, up to `watchdog` in a row; if none of them has lowered
    !! the merit below the best point's, the iteration returns to that point and takes the
    !! exact line-search step along the direction computed there (so the merit decreases at
    !! least every watchdog + 1 steps, and a cycle of set patterns cannot repeat).
    subroutine newton_stage(d, sys, ls, law, stage, max_iter, patient, sol, converged, &
                            err)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(law_t), intent(in) :: law
        integer, intent(in) :: stage, max_iter
        logical, intent(in) :: patient     !! else give up when the watchdog first runs out
        type(solution_t), intent(inout) :: sol
        logical, intent(out) :: converged
        type(error_t), allocatable, intent(out) :: err
        type(newton_state_t) :: s
        real(dp), allocatable :: dz(:), z_old(:), z_exact(:)
        integer, allocatable :: code(:), new_code(:)
        real(dp) :: t, incr, phi_exact, equilibrium
        integer :: iter
        logical :: exact, flipped
        phi_exact = huge(1.0_dp)
        call start_state(d, sys, law, sol, s)
        code = set_pattern(law, point_tractions(sol%pts, sol%z))
        converged = s%phi <= round_off .and. maxval(abs(s%res(1:d%nv))) &
                    <= refine_tol*maxval(abs(sys%q))
        iterations: do iter = 1, max_iter
            if (converged) exit iterations
            call newton_direction(d, sys, ls, law, sol, s%res, dz, err)
            if (allocated(err)) return
            if (s%relaxed == 0) s%dz_best = dz
            z_old = sol%z
            call take_step(d, sys, ls, law, sol, s, dz, t, flipped, err)
            if (allocated(err)) return
            incr = relative_change(d, sol%z, z_old)
            new_code = set_pattern(law, point_tractions(sol%pts, sol%z))
            if (t <= 0.0_dp .or. (t < 1.0_dp .and. incr <= stall_increment)) then
                ! no descent, or a step that no longer moves: stalled at a kink
                call log_step(sol, stage, iter, law, new_code, code, incr, -1.0_dp, t)
                exit iterations
            end if
            call log_step(sol, stage, iter, law, new_code, code, incr, s%phi, t, flipped)
            ! a single-flip step solved another pattern than code's: not exact by its sets
            exact = t == 1.0_dp .and. s%relaxed == 0 .and. .not. flipped .and. &
                    (all(new_code == code) .or. incr <= round_off)
            ! an exact step solves F = 0 up to the accuracy of the solve: with the merit at
            ! round-off it is the answer (4.2a of a stiff structure is refined afterwards in
            ! double-double: refine_equilibrium); otherwise (an inaccurate solve) further
            ! steps, while 4.2a's residual is above refine_tol and halves
            equilibrium = maxval(abs(s%res(1:d%nv)))/max(maxval(abs(sys%q)), tiny(1.0_dp))
            converged = s%phi <= round_off .or. (exact .and. (equilibrium <= refine_tol .or. &
                                                              equilibrium > 0.5_dp*phi_exact))
            exact = exact .or. s%phi <= round_off
            if (converged .and. equilibrium > phi_exact) then
                ! the refinement has reached round-off and made it worse: keep the better
                ! exact step (the state is recomputed from z by the caller)
                sol%z = z_exact
            else if (exact) then
                phi_exact = equilibrium
                z_exact = sol%z
            end if
            code = new_code
            if (.not. (converged .or. patient) .and. s%exhausted) exit iterations
        end do iterations
        sol%n_outer = stage
    end subroutine newton_stage

    !> Merit bookkeeping at the start of a stage.
    subroutine start_state(d, sys, law, sol, s)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(law_t), intent(in) :: law
        type(solution_t), intent(in) :: sol
        type(newton_state_t), intent(out) :: s
        allocate (s%res(d%n))
        s%block_scale = [max(maxval(abs(sol%z(1:d%nv))), tiny(1.0_dp)), &
                         max(maxval(abs(sol%z(d%nv + 1:))), tiny(1.0_dp))]
        call complete_residual(d, sys, law, sol%pts, sol%z, s%res)
        s%phi = merit(d, sys, law, sol%pts, s, sol%z, s%res)
        s%phi_best = s%phi
        s%z_best = sol%z
        s%relaxed = 0
        s%phi_now = s%phi
        allocate (s%seen(sol%pts%n, memory))
        s%n_seen = 1
        s%seen(:, 1) = set_pattern(law, point_tractions(sol%pts, sol%z))
    end subroutine start_state

    !> The generalised Newton direction J dz = -F at sol%z (one linear solve): by the Schur
    !! complement onto the tractions (schur_solver) when it is ready, else dense.
    subroutine newton_direction(d, sys, ls, law, sol, res, dz, err)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(law_t), intent(in) :: law
        type(solution_t), intent(inout) :: sol
        real(dp), intent(in) :: res(:)
        real(dp), allocatable, intent(out) :: dz(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: a(:, :)
        type(set_terms_t) :: st
        logical :: symmetric, factorised
        allocate (dz(d%n))
        factorised = .true.
        if (ls%sc%ready) then
            call set_terms(sys, law, sol%pts, point_tractions(sol%pts, sol%z), st)
            call schur_step(sys, ls, st, &
                            settled_lift_off(sol%pts, point_tractions(sol%pts, sol%z), d%n, ls), &
                            -res, dz, sol, factorised, err)
        else
            call complete_jacobian(d, sys, law, sol%pts, point_tractions(sol%pts, sol%z), a, &
                                   symmetric)
            call solve_equilibrated(a, -res, dz, symmetric, err)
        end if
        if (allocated(err)) return
        if (factorised) sol%n_factorisations = sol%n_factorisations + 1
        sol%n_solves = sol%n_solves + 1
        sol%n_inner = sol%n_inner + 1
    end subroutine newton_direction

    !> The traction unknowns (global numbers) of settled lift-off: every contact point where
    !! the function is nonzero is in the tension set at the tractions sigma and was at the
    !! previous step (recorded in ls%tension_before, which this updates).
    function settled_lift_off(pts, sigma, n, ls) result(settled)
        type(contact_points_t), intent(in) :: pts
        real(dp), intent(in) :: sigma(:, :)
        integer, intent(in) :: n
        type(step_solver_t), intent(inout) :: ls
        logical :: settled(n)
        logical :: tension(pts%n), supported(n)
        integer :: p, k, l
        tension = in_tension(sigma(2, :))
        settled = .false.
        if (allocated(ls%tension_before)) then
            settled = .true.
            supported = .false.
            points: do p = 1, pts%n
                do k = 1, 2
                    do l = 1, pts%nl(k)
                        if (pts%val(l, k, p) == 0.0_dp) cycle
                        associate (j => pts%idx(l, k, p))
                            supported(j) = .true.
                            settled(j) = settled(j) .and. tension(p) .and. ls%tension_before(p)
                        end associate
                    end do
                end do
            end do points
            settled = settled .and. supported
        end if
        ls%tension_before = tension
    end function settled_lift_off

    !> J x = b by the Schur complement: the kept block updated or factorised (schur_prepare,
    !! the settled lift-off tractions decoupled where that pays), factorised afresh and in
    !! full when a low-rank update or the decoupling left the refined solve inaccurate.
    !! Counts the steps solved with decoupling in sol (solution_t%decoupled: the most).
    subroutine schur_step(sys, ls, st, settled, b, x, sol, factorised, err)
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(set_terms_t), intent(in) :: st
        logical, intent(in) :: settled(:)     !! global unknowns (settled_lift_off)
        real(dp), intent(in) :: b(:)
        real(dp), intent(out) :: x(:)
        type(solution_t), intent(inout) :: sol
        logical, intent(out) :: factorised
        type(error_t), allocatable, intent(out) :: err
        logical :: accurate
        associate (sc => ls%sc, fac => ls%fac)
            call schur_prepare(sc, st, fac, factorised, err, settled)
            if (.not. allocated(err)) call schur_solve(sys, sc, st, fac, b, x, err, accurate)
            if (allocated(err)) return
            if (.not. accurate) then
                call schur_factorise(sc, st, fac, err)
                factorised = .true.
                if (.not. allocated(err)) call schur_solve(sys, sc, st, fac, b, x, err)
                if (allocated(err)) return
            end if
            if (fac%n_decoupled == 0) return
            sol%n_decoupled_steps = sol%n_decoupled_steps + 1
            if (fac%n_decoupled > sol%decoupled(1)) sol%decoupled = [fac%n_decoupled, sc%nk]
        end associate
    end subroutine schur_step

    !> The full step when it keeps the set pattern (it then solves F = 0), when it lowers the
    !! best merit, or while the watchdog allows, unless its
    !! set pattern was met before in this stage (a cycle): then the better of the exact line
    !! search along the step (half the step if that finds no descent) and the single-flip
    !! step (single_flip_step). When the watchdog has run out: the exact line search from the
    !! best point along its direction. t = 0: no descent there.
    subroutine take_step(d, sys, ls, law, sol, s, dz, t, flipped, err)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(law_t), intent(in) :: law
        type(solution_t), intent(inout) :: sol
        type(newton_state_t), intent(inout) :: s
        real(dp), intent(in) :: dz(:)
        real(dp), intent(out) :: t
        logical, intent(out) :: flipped    !! the single-flip step was taken
        type(error_t), allocatable, intent(out) :: err
        integer, allocatable :: code(:)
        real(dp), allocatable :: z_flip(:), res_flip(:)
        real(dp) :: phi_flip, phi_line
        logical :: descent, cycled, searched, evaluated
        integer :: k
        t = 1.0_dp
        flipped = .false.
        call complete_residual(d, sys, law, sol%pts, sol%z + dz, s%res)
        s%phi = merit(d, sys, law, sol%pts, s, sol%z + dz, s%res)
        code = set_pattern(law, point_tractions(sol%pts, sol%z + dz))
        descent = s%phi <= (1.0_dp - armijo)*s%phi_best
        cycled = .false.
        do k = 1, min(s%n_seen, size(s%seen, 2))
            cycled = cycled .or. all(s%seen(:, k) == code)
        end do
        searched = .false.
        evaluated = .false.     ! s%res, s%phi already at the new sol%z
        if (all(code == s%seen(:, modulo(s%n_seen - 1, size(s%seen, 2)) + 1))) then
            ! the full step keeps the sets its Jacobian was built with: it solves F = 0
            sol%z = sol%z + dz
            s%relaxed = 0
        else if (cycled) then
            call single_flip_step(d, sys, ls, law, sol, dz, z_flip)
            call line_search(d, sys, law, sol%pts, s, sol%z, dz, s%phi_now, t, phi_line)
            if (t <= 0.0_dp) then
                t = 0.5_dp
                phi_line = 0.0_dp   ! the half step counts with its merit alone
            end if
            sol%z = sol%z + t*dz
            s%relaxed = s%relaxed + 1
            if (allocated(z_flip)) then
                allocate (res_flip(d%n))
                call complete_residual(d, sys, law, sol%pts, z_flip, res_flip)
                phi_flip = merit(d, sys, law, sol%pts, s, z_flip, res_flip)
                call complete_residual(d, sys, law, sol%pts, sol%z, s%res)
                s%phi = merit(d, sys, law, sol%pts, s, sol%z, s%res)
                evaluated = .true.
                ! on a kink the line search's merit counts, not the side round-off chose
                if (phi_flip < max(s%phi, phi_line)) then
                    sol%z = z_flip
                    s%res = res_flip
                    s%phi = phi_flip
                    t = 1.0_dp
                    flipped = .true.
                end if
            end if
        else if (descent .or. s%relaxed < watchdog) then
            sol%z = sol%z + dz
            s%relaxed = s%relaxed + 1
        else
            call line_search(d, sys, law, sol%pts, s, s%z_best, s%dz_best, s%phi_best, t)
            sol%z = s%z_best + t*s%dz_best
            searched = .true.
        end if
        if ((t < 1.0_dp .or. searched) .and. .not. evaluated) then
            call complete_residual(d, sys, law, sol%pts, sol%z, s%res)
            s%phi = merit(d, sys, law, sol%pts, s, sol%z, s%res)
        end if
        ! the watchdog has run out unless its line search at least halved the best merit
        if (searched .and. s%phi > 0.5_dp*s%phi_best) s%exhausted = .true.
        s%phi_now = s%phi
        s%n_seen = s%n_seen + 1
        s%seen(:, modulo(s%n_seen - 1, size(s%seen, 2)) + 1) = &
            set_pattern(law, point_tractions(sol%pts, sol%z))
        if (s%phi <= (1.0_dp - armijo)*s%phi_best .or. searched) then
            s%phi_best = s%phi
            s%z_best = sol%z
            s%relaxed = 0
        end if
    end subroutine take_step

    !> Murty's single-pivot fallback for block pivoting that cycles (a point at a kink flipping
    !! back and forth with its neighbours, each full step changing several sets at once, e.g.
    !! paper case fig07_s2#3 near the beam's lifted end): the solution for the set pattern of
    !! the ray's first piece past its first kink, the current pattern with only the points
    !! that cross first changed (F is linear on a pattern: one linear solve). Not allocated
    !! when the ray has no kink or the solve fails (a fallback, not a step the case needs:
    !! the factorisation is then dropped, the next step factorises afresh).
    subroutine single_flip_step(d, sys, ls, law, sol, dz, z_flip)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(step_solver_t), intent(inout) :: ls
        type(law_t), intent(in) :: law
        type(solution_t), intent(inout) :: sol
        real(dp), intent(in) :: dz(:)
        real(dp), allocatable, intent(out) :: z_flip(:)
        real(dp), allocatable :: knots(:), z_held(:)
        type(set_terms_t) :: st
        type(error_t), allocatable :: err
        type(schur_factor_t) :: fresh
        logical, allocatable :: settled(:)
        integer :: k
        knots = ray_kinks(law, point_tractions(sol%pts, sol%z), point_tractions(sol%pts, dz))
        if (size(knots) <= 2) return
        ! points that cross together (a symmetric structure) share a kink: the piece past
        ! it ends at the next distinct one
        k = 3
        do while (knots(k) <= knots(2) .and. k < size(knots))
            k = k + 1
        end do
        call set_terms(sys, law, sol%pts, &
                       point_tractions(sol%pts, sol%z + 0.5_dp*(knots(2) + knots(k))*dz), st)
        allocate (settled(d%n), source=.false.)
        z_held = sol%z
        call solve_for_sets(d, sys, ls, st, settled, sol, err)
        if (allocated(err)) then
            ls%fac = fresh
        else
            call move_alloc(sol%z, z_flip)
        end if
        sol%z = z_held
    end subroutine single_flip_step

    !> Set pattern of the complete problem at the tractions sigma: 1 for tension (penalty),
    !! plus +-2 for slipping with that sign (interface_law decides both, independently). On
    !! the tension set tau0 = 0, so the slip term is linear in sigma_x whatever its sign and
    !! the Jacobian does not depend on it: a tensile slipping point is 3 for either sign (else
    !! a sign change there, e.g. where sigma_x ~ 0 in a lifted-off zone, would count as a set
    !! change: a cycle, or a step that solves F = 0 not recognised as exact).
    pure function set_pattern(law, sigma) result(code)
        type(law_t), intent(in) :: law
        real(dp), intent(in) :: sigma(:, :)
        integer :: code(size(sigma, 2))
        code = merge(1, 0, in_tension(sigma(2, :)))
        where (is_slipping(sigma(1, :), friction_threshold(law%f, sigma(2, :)))) &
            code = code + merge(2, -2, sigma(1, :) >= 0.0_dp .or. code == 1)
    end function set_pattern

    !> Step length t on the ray z + t dz: the exact minimiser of the merit over (0, 1] (on each
    !! piece between kinks F is affine and the weights constant, so the merit squared is
    !! quadratic there); 0 if no point of the ray is better than z. The merit jumps at a kink
    !! (a point's weights change with its set), and on a kink the point's set is decided by
    !! the last bit of its traction: a kink counts with the larger of its two one-sided
    !! merits, and a piece's minimum at its end is that kink's (phi_t: the merit counted at
    !! t, independent of rounding).
    subroutine line_search(d, sys, law, pts, s, z, dz, phi0, t, phi_t)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(law_t), intent(in) :: law
        type(contact_points_t), intent(in) :: pts
        type(newton_state_t), intent(in) :: s
        real(dp), intent(in) :: z(:), dz(:)   !! the ray
        real(dp), intent(in) :: phi0          !! merit at z
        real(dp), intent(out) :: t
        real(dp), intent(out), optional :: phi_t   !! the merit counted at t (phi0 if t = 0)
        real(dp), allocatable :: lin0(:), lin1(:), f_a(:), f_b(:), knots(:), wgt(:)
        real(dp) :: best, phi_cand, frac, t_mid, end_before
        integer :: k
        lin0 = linear_part(d, sys, z)
        lin0(1:d%nv) = lin0(1:d%nv) - sys%q
        lin1 = linear_part(d, sys, dz)
        allocate (f_a(d%n), f_b(d%n))
        knots = distinct(ray_kinks(law, point_tractions(pts, z), point_tractions(pts, dz)))
        best = phi0
        t = 0.0_dp
        end_before = 0.0_dp
        call complete_residual(d, sys, law, pts, z, f_a, lin0)
        segments: do k = 2, size(knots)
            call complete_residual(d, sys, law, pts, z + knots(k)*dz, f_b, &
                                   lin0 + knots(k)*lin1)
            t_mid = 0.5_dp*(knots(k - 1) + knots(k))
            wgt = merit_weights(d, sys, law, pts, s, z + t_mid*dz)
            ! the kink at knots(k - 1): the larger of the merits on its two sides
            if (k > 2) call keep_better(max(end_before, norm2(wgt*f_a)), knots(k - 1), best, t)
            call segment_minimum(wgt, f_a, f_b, frac, phi_cand)
            if (frac > 0.0_dp .and. frac < 1.0_dp) &
                call keep_better(phi_cand, knots(k - 1) + frac*(knots(k) - knots(k - 1)), &
                                 best, t)
            end_before = norm2(wgt*f_b)
            f_a = f_b
        end do segments
        call keep_better(end_before, 1.0_dp, best, t)    ! the full step
        if (present(phi_t)) phi_t = best
    end subroutine line_search

    !> A candidate step t_cand with merit phi_cand replaces (best, t) if it is lower.
    pure subroutine keep_better(phi_cand, t_cand, best, t)
        real(dp), intent(in) :: phi_cand, t_cand
        real(dp), intent(inout) :: best, t
        if (phi_cand >= best) return
        best = phi_cand
        t = t_cand
    end subroutine keep_better

    !> The sorted values x without repeats (points crossing the ray together share a kink).
    pure function distinct(x) result(y)
        real(dp), intent(in) :: x(:)    !! sorted ascending
        real(dp), allocatable :: y(:)
        logical :: first(size(x))
        integer :: i
        first = .true.
        do i = 2, size(x)
            first(i) = x(i) > x(i - 1)
        end do
        y = pack(x, first)
    end function distinct

    !> The merit: the Jacobi correction |F_i / J_ii| (J the generalised Jacobian at z) of
    !! every equation, relative to the block scale of its unknowns, in the 2-norm. Tension
    !! and slip rows are thus measured in tractions like the others, not multiplied by
    !! 1/eta_bar or 1/eps_bar (which makes a fixed row scaling useless as a merit here).
    real(dp) function merit(d, sys, law, pts, s, z, res)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(law_t), intent(in) :: law
        type(contact_points_t), intent(in) :: pts
        type(newton_state_t), intent(in) :: s
        real(dp), intent(in) :: z(:), res(:)
        merit = norm2(merit_weights(d, sys, law, pts, s, z)*res)
    end function merit

    !> 1 / (|J_ii| block scale) at z.
    function merit_weights(d, sys, law, pts, s, z) result(wgt)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(law_t), intent(in) :: law
        type(contact_points_t), intent(in) :: pts
        type(newton_state_t), intent(in) :: s
        real(dp), intent(in) :: z(:)
        real(dp), allocatable :: wgt(:)
        wgt = abs(jacobian_diagonal(d, sys, law, pts, point_tractions(pts, z)))
        where (wgt == 0.0_dp) wgt = 1.0_dp
        wgt(1:d%nv) = 1.0_dp/(wgt(1:d%nv)*s%block_scale(1))
        wgt(d%nv + 1:) = 1.0_dp/(wgt(d%nv + 1:)*s%block_scale(2))
    end function merit_weights

    !> 0, the kinks of F on the ray z + t dz inside (0, 1) in ascending order, and 1: where a
    !! point's sigma_z or |sigma_x| - f sigma_z changes sign (tractions are linear in t).
    pure function ray_kinks(law, sig0, dsig) result(knots)
        type(law_t), intent(in) :: law
        real(dp), intent(in) :: sig0(:, :)   !! tractions at t = 0
        real(dp), intent(in) :: dsig(:, :)   !! their change per unit t
        real(dp), allocatable :: knots(:)
        real(dp) :: cand(3), num(3), den(3)
        integer :: p, j, n
        allocate (knots(3*size(sig0, 2) + 2))
        n = 1
        knots(1) = 0.0_dp
        points: do p = 1, size(sig0, 2)
            num = [sig0(2, p), sig0(1, p) - law%f*sig0(2, p), sig0(1, p) + law%f*sig0(2, p)]
            den = [dsig(2, p), dsig(1, p) - law%f*dsig(2, p), dsig(1, p) + law%f*dsig(2, p)]
            kinds_of_kink: do j = 1, merge(3, 1, law%f > 0.0_dp)
                if (den(j) == 0.0_dp) cycle kinds_of_kink
                cand(j) = -num(j)/den(j)
                if (cand(j) > 0.0_dp .and. cand(j) < 1.0_dp) then
                    n = n + 1
                    knots(n) = cand(j)
                end if
            end do kinds_of_kink
        end do points
        n = n + 1
        knots(n) = 1.0_dp
        knots = knots(1:n)
        call sort_ascending(knots)
    end function ray_kinks

    !> Minimum of || D (f_a + s (f_b - f_a)) || over s in [0, 1] (F is affine between kinks).
    pure subroutine segment_minimum(wgt, f_a, f_b, s, phi)
        real(dp), intent(in) :: wgt(:)      !! merit weights on the segment
        real(dp), intent(in) :: f_a(:), f_b(:)
        real(dp), intent(out) :: s      !! position of the minimum in the segment
        real(dp), intent(out) :: phi    !! the minimum
        real(dp), allocatable :: a(:), b(:)
        real(dp) :: bb
        a = wgt*f_a
        b = wgt*(f_b - f_a)
        bb = dot_product(b, b)
        s = 1.0_dp
        if (bb > 0.0_dp) s = min(1.0_dp, max(0.0_dp, -dot_product(a, b)/bb))
        phi = norm2(a + s*b)
    end subroutine segment_minimum

    !> One line of the log for a Newton step (residual < 0: the step was rejected).
    subroutine log_step(sol, stage, iter, law, new_code, code, incr, residual, t, flipped)
        type(solution_t), intent(inout) :: sol
        integer, intent(in) :: stage, iter
        type(law_t), intent(in) :: law
        integer, intent(in) :: new_code(:), code(:)
        real(dp), intent(in) :: incr, residual, t
        logical, intent(in), optional :: flipped   !! a single-flip step (take_step)
        type(iteration_record_t) :: rec
        logical :: flip
        rec%outer = stage
        rec%inner = iter
        rec%n_tension = count(modulo(new_code, 2) == 1)
        rec%n_slip = count(abs(new_code - modulo(new_code, 2)) == 2)
        rec%n_changed = count(new_code /= code)
        rec%increment = incr
        rec%residual = residual
        flip = .false.
        if (present(flipped)) flip = flipped
        if (residual < 0.0_dp) then
            write (rec%note, '(a,es8.1)') 'stalled: no descent, eps_bar ', law%eps
        else if (flip) then
            rec%note = 'single-flip step (a cycle of sets)'
        else if (t < 1.0_dp) then
            write (rec%note, '(a,es10.3)') 'damped step x', t
        else if (stage > 1) then
            write (rec%note, '(a,es8.1)') 'Newton, eps_bar ', law%eps
        end if
        sol%history = [sol%history, rec]
        if (sol%progress_unit >= 0) then
            write (sol%progress_unit, '(a,i0,a,i0,a,es9.2,a,i0,a)') 'fricon:   Newton stage ', &
                stage, ', step ', iter, ': residual ', residual, ', ', rec%n_changed, &
                ' points changed state'
            flush (sol%progress_unit)
        end if
    end subroutine log_step

    subroutine log_note(sol, note)
        type(solution_t), intent(inout) :: sol
        character(len=*), intent(in) :: note
        type(iteration_record_t) :: rec
        rec%note = note
        sol%history = [sol%history, rec]
    end subroutine log_note
end module newton_method
