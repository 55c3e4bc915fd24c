!> Unilateral contact with regularised Coulomb friction: the paper's two-loop iteration (§3–4).
!!
!! Discrete system (paper 4.2, SPEC §4), z = [v; r]:
!!   K v + M^T r = q
!!   M v - (T + c eps S0 + c kappa Gbar + (c/eta_bar) G) r = - c kappa b
!! with kappa = (1 - eps^2)/eps (eps = eps_bar), c the friction compliance (model.f90),
!! Gbar / G the Gauss-point masses of the slipping / tensile points, and
!! b_a = sum over slipping points of w tau0 sign(sigma_x) g_a (paper 4.5a, with the threshold and
!! the sign taken at the Gauss point rather than through nodal coefficients: identical where the
!! sign does not change inside an element, and exact at the points that decide the sets).
!! Inner loop: sets (slip, sign, tension) from the previous iterate, starting from adhesive
!! contact; stops when the sets repeat or the solution changes by less than tol_inner; a set
!! pattern that recurs (a cycle) is broken by halving the step. Outer loop: tau0 <- f max(sigma_z,
!! 0) at the Gauss points (paper 3.6), under-relaxed when the increments stop shrinking.
module contact_solver
    use kinds, only: dp, pi
    use errors, only: error_t, new_error, add_context, EXIT_ANALYSIS
    use quadrature, only: gauss_legendre
    use shape_functions, only: eval_basis, max_local
    use model, only: model_t, MODEL_BEAM, LOAD_MOMENT, LOAD_PATCH, FIELD_SX, FIELD_SZ, &
                     friction_compliance, total_vertical_load
    use discretization, only: discretization_t
    use mindlin_structure, only: section_of, assemble_stiffness, assemble_loads, &
                                 assemble_coupling, traction_at
    use halfspace_operator, only: assemble_flexibility
    use linear_solve, only: solve_symmetric
    use interface_law, only: STATE_LIFTOFF, STATE_STICK, STATE_SLIP, contact_state, &
                             friction_threshold, in_tension, is_slipping
    implicit none
    private

    public :: STATE_LIFTOFF, STATE_STICK, STATE_SLIP

    !> Gauss points of the interface where the sets are decided (paper 4.6–4.7).
    type, public :: contact_points_t
        integer :: n = 0
        integer, allocatable :: elem(:)
        real(dp), allocatable :: xi(:), x(:)
        real(dp), allocatable :: wt(:)       !! Gauss weight * Jacobian (* 2 pi r for the plate)
    end type contact_points_t

    !> One line of the solver log.
    type, public :: iteration_record_t
        integer :: outer = 0, inner = 0
        integer :: n_slip = 0, n_tension = 0, n_changed = 0
        real(dp) :: increment = 0.0_dp       !! relative change of the solution
        real(dp) :: residual = -1.0_dp       !! relative residual of (4.2), sets of the iterate
        character(len=40) :: note = ''
    end type iteration_record_t

    !> The converged state of one case and how it was reached.
    type, public :: solution_t
        real(dp), allocatable :: z(:)        !! [v; r], physical units
        real(dp), allocatable :: tau0(:)     !! friction threshold at the contact points
        integer, allocatable :: state(:)     !! STATE_* at the contact points (reported)
        logical, allocatable :: slip(:)      !! slip set (paper 4.6a/4.7a): |sigma_x| > tau0
        logical, allocatable :: tension(:)   !! tension set (paper 4.6b/4.7b): sigma_z <= 0
        real(dp), allocatable :: sigma(:, :) !! (sigma_x, sigma_z) at the contact points
        type(contact_points_t) :: pts
        type(iteration_record_t), allocatable :: history(:)
        integer :: n_outer = 0, n_inner = 0
        integer :: n_solves = 0              !! linear solves (factorisations) of the case
        real(dp) :: residual(2) = 0.0_dp     !! relative residuals of equations 4.2a, 4.2b
        real(dp) :: reaction(3) = 0.0_dp     !! int sigma_z, int sigma_x, moment (beam)
        real(dp) :: applied(3) = 0.0_dp      !! the same of the loads
        real(dp) :: admissibility = 0.0_dp   !! max(|sigma_x| - f sigma_z) over contact points
        real(dp) :: complementarity = 0.0_dp !! max |Sigma_z gap| at lift-off stations (report)
        real(dp) :: compatibility = 0.0_dp   !! max |gap|/max|w| at contact stations (report)
        real(dp) :: min_sigma_z = 0.0_dp     !! most tensile sigma_z (penalty, O(eta_bar))
    end type solution_t

    !> Work data of the iteration.
    type :: system_t
        real(dp), allocatable :: a0(:, :)    !! matrix without the set-dependent terms
        real(dp), allocatable :: q(:)        !! structural loads
        real(dp), allocatable :: row_scale(:)  !! 1/sqrt|diag a0|: fixed scaling of the residual
        real(dp) :: c = 0.0_dp, kappa = 0.0_dp, penalty = 0.0_dp
    end type system_t

    public :: solve_contact, check_load_admissible, contact_points

contains

    !> Solve one case. Fails with EXIT_ANALYSIS when there is no equilibrium or no convergence.
    subroutine solve_contact(m, d, sol, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(out) :: sol
        type(error_t), allocatable, intent(out) :: err
        type(system_t) :: sys

        allocate (sol%history(0))
        call check_load_admissible(m, err)
        if (allocated(err)) return
        sol%pts = contact_points(m, d)
        call build_system(m, d, sol%pts, sys, err)
        if (allocated(err)) return
        allocate (sol%z(d%n), sol%state(sol%pts%n), sol%sigma(2, sol%pts%n))
        allocate (sol%slip(sol%pts%n), sol%tension(sol%pts%n))
        call friction_loop(m, d, sys, sol, err)
        if (allocated(err)) return
        call final_checks(m, d, sys, sol, err)
    end subroutine solve_contact

    !> Loads that no unilateral frictional support can carry (SPEC §4): EXIT_ANALYSIS.
    subroutine check_load_admissible(m, err)
        type(model_t), intent(in) :: m
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: v, h_total, arm
        character(len=240) :: text
        v = total_vertical_load(m)
        if (.not. v > 0.0_dp) then
            write (text, '(a,es12.4,a)') 'no equilibrium: the net vertical load (', v, &
                ') is not downward and the soil takes no tension (uplift)'
            call new_error(err, EXIT_ANALYSIS, trim(text))
            return
        end if
        h_total = sum(m%loads%fx)
        if (abs(h_total) > m%f*v) then
            write (text, '(a,es12.4,a,es12.4,a)') 'no equilibrium: sliding - the horizontal load H =', &
                h_total, ' exceeds the friction capacity f*V =', m%f*v, &
                ' (utilisation H/(fV) > 1)'
            call new_error(err, EXIT_ANALYSIS, trim(text))
            return
        end if
        if (m%kind == MODEL_BEAM) then
            arm = applied_moment(m)/v
            if (abs(arm) >= 0.5_dp*m%length) then
                write (text, '(a,es12.4,a,es12.4,a)') 'no equilibrium: overturning - the load '// &
                    'resultant acts at x =', arm, ', outside the base (|x| < ', &
                    0.5_dp*m%length, ')'
                call new_error(err, EXIT_ANALYSIS, trim(text))
            end if
        end if
    end subroutine check_load_admissible

    !> Moment of the loads about the mid-plane at x = 0, work-conjugate to a rigid rotation
    !! (w = x, psi = 1): sum F_z x + M + h F_x (horizontal loads act on the top face and their
    !! reaction on the bottom face).
    pure real(dp) function applied_moment(m)
        type(model_t), intent(in) :: m
        integer :: i
        applied_moment = 0.0_dp
        do i = 1, size(m%loads)
            associate (ld => m%loads(i))
                if (ld%kind == LOAD_MOMENT) then
                    applied_moment = applied_moment + ld%fz
                else if (ld%kind == LOAD_PATCH) then
                    applied_moment = applied_moment + ld%fz*0.5_dp*(ld%x1 + ld%x2) + m%h*ld%fx
                else
                    applied_moment = applied_moment + ld%fz*ld%x1 + m%h*ld%fx
                end if
            end associate
        end do
    end function applied_moment

    !> K, M, T, S0 and q assembled once per case into the base matrix.
    subroutine build_system(m, d, pts, sys, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(contact_points_t), intent(in) :: pts
        type(system_t), intent(out) :: sys
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: t_mat(:, :), mm(:, :)
        integer :: nv, n, i
        nv = d%nv
        n = d%n
        allocate (sys%a0(n, n), sys%q(nv), mm(d%nr, nv))
        sys%a0 = 0.0_dp
        call assemble_stiffness(section_of(m), d, sys%a0(1:nv, 1:nv))
        call assemble_coupling(m, d, mm)
        sys%a0(nv + 1:n, 1:nv) = mm
        sys%a0(1:nv, nv + 1:n) = transpose(mm)
        call assemble_flexibility(m, d, t_mat, err)
        if (allocated(err)) then
            call add_context(err, 'assembling the half-space flexibility T')
            return
        end if
        sys%a0(nv + 1:n, nv + 1:n) = -t_mat
        call assemble_loads(m, d, sys%q, err)
        if (allocated(err)) return
        sys%c = friction_compliance(m)
        sys%kappa = (1.0_dp - m%eps_bar**2)/m%eps_bar
        sys%penalty = sys%c/m%eta_bar
        ! - c eps S0 on the sigma_x block: the stick branch of the law, everywhere
        do i = 1, pts%n
            call add_point_mass(d, pts, i, FIELD_SX, -sys%c*m%eps_bar, sys%a0)
        end do
        allocate (sys%row_scale(n))
        do i = 1, n
            sys%row_scale(i) = 1.0_dp
            if (sys%a0(i, i) /= 0.0_dp) sys%row_scale(i) = 1.0_dp/sqrt(abs(sys%a0(i, i)))
        end do
    end subroutine build_system

    !> a(i,j) += factor * wt g_i g_j at contact point p for the traction field.
    pure subroutine add_point_mass(d, pts, p, field, factor, a)
        type(discretization_t), intent(in) :: d
        type(contact_points_t), intent(in) :: pts
        integer, intent(in) :: p, field
        real(dp), intent(in) :: factor
        real(dp), intent(inout) :: a(:, :)
        integer :: idx(max_local), i, j, nl
        real(dp) :: val(max_local), der(max_local), x
        call eval_basis(d%basis(field), pts%elem(p), pts%xi(p), idx, val, der, x)
        nl = d%basis(field)%n_local
        idx(1:nl) = idx(1:nl) + d%offset(field)
        do j = 1, nl
            do i = 1, nl
                a(idx(i), idx(j)) = a(idx(i), idx(j)) + factor*pts%wt(p)*val(i)*val(j)
            end do
        end do
    end subroutine add_point_mass

    !> Gauss points per element: (highest traction degree + 1), exact for the masses.
    pure function contact_points(m, d) result(pts)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
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
        do e = 1, d%msh%ne
            h = d%msh%x(e) - d%msh%x(e - 1)
            do g = 1, ng
                p = p + 1
                pts%elem(p) = e
                pts%xi(p) = xg(g)
                pts%x(p) = d%msh%x(e - 1) + 0.5_dp*(xg(g) + 1.0_dp)*h
                pts%wt(p) = 0.5_dp*wg(g)*h
                if (m%kind /= MODEL_BEAM) pts%wt(p) = pts%wt(p)*2.0_dp*pi*pts%x(p)
            end do
        end do
    end function contact_points

    !> Outer loop: fixed point of tau0 -> f max(sigma_z, 0) (paper 3.6).
    subroutine friction_loop(m, d, sys, sol, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: z_prev(:), tau_new(:), sigma_prev(:, :)
        integer, allocatable :: state_prev(:)
        logical, allocatable :: slip_prev(:), tension_prev(:)
        real(dp) :: incr, incr_prev, omega
        integer :: outer
        character(len=200) :: text

        allocate (sol%tau0(sol%pts%n), tau_new(sol%pts%n), z_prev(d%n))
        sol%tau0 = start_threshold(m)
        sol%state = STATE_STICK      ! adhesive contact
        sol%slip = .false.
        sol%tension = .false.
        sol%sigma = 0.0_dp
        sol%z = 0.0_dp
        omega = 1.0_dp
        incr = huge(1.0_dp)
        incr_prev = huge(1.0_dp)
        outer_loop: do outer = 1, m%max_outer
            z_prev = sol%z
            state_prev = sol%state
            slip_prev = sol%slip
            tension_prev = sol%tension
            sigma_prev = sol%sigma
            call penalty_loop(m, d, sys, outer, .false., sol, err)
            if (allocated(err)) then
                if (index(err%message, 'did not converge') > 0) then
                    ! the plain fixed point failed: restart this inner loop with backtracking
                    call log_note(sol, outer, 'inner loop restarted with line search')
                    sol%z = z_prev
                    sol%state = state_prev
                    sol%slip = slip_prev
                    sol%tension = tension_prev
                    sol%sigma = sigma_prev
                    call penalty_loop(m, d, sys, outer, .true., sol, err)
                end if
            end if
            if (allocated(err)) return
            sol%n_outer = outer
            tau_new = friction_threshold(m%f, sol%sigma(2, :))
            if (outer > 1) then
                incr = relative_change(d, sol%z, z_prev)
                call log_outer(sol, outer, incr, omega)
                if (incr <= m%tol_outer) return
                ! under-relax while the increments grow, relax back while they shrink fast
                if (incr >= incr_prev) then
                    omega = max(0.0625_dp, 0.5_dp*omega)
                else if (incr < 0.5_dp*incr_prev) then
                    omega = min(1.0_dp, 2.0_dp*omega)
                end if
                incr_prev = incr
            end if
            sol%tau0 = sol%tau0 + omega*(tau_new - sol%tau0)
            ! Sets re-decided with the new tau0. Keeping the last solve's sets halves the solves
            ! but, on fig07_ref_005, ends at a different state (max |Sigma_x| 1.449 vs 1.386),
            ! both passing every check: the fixed point is not unique there (open question).
            call classify(d, sol)
        end do outer_loop
        write (text, '(a,i0,a,es10.3,a,es10.3)') 'friction (outer) loop did not converge in ', &
            m%max_outer, ' iterations: last relative change ', incr, ' > tol ', m%tol_outer
        call new_error(err, EXIT_ANALYSIS, trim(text))
    end subroutine friction_loop

    !> Initial threshold: SOLVER tau0 start (nondimensional Sigma) or f * mean pressure.
    pure real(dp) function start_threshold(m) result(tau)
        type(model_t), intent(in) :: m
        real(dp) :: mean_pressure
        if (m%kind == MODEL_BEAM) then
            mean_pressure = total_vertical_load(m)/m%length
        else
            mean_pressure = total_vertical_load(m)/(pi*m%length**2)
        end if
        if (m%tau0_start >= 0.0_dp) then
            tau = m%tau0_start*mean_pressure
        else
            tau = m%f*mean_pressure
        end if
    end function start_threshold

    !> Inner loop for fixed tau0: sets (slip, sign, tension) from the previous iterate. Each
    !! solve is a generalised Newton step for the piecewise-linear equations (4.2). Plain mode:
    !! full steps as in the paper, a step halved when its set pattern was met before (a cycle).
    !! Searching mode (the fallback): every step halved until it lowers the scaled residual
    !! (backtracking). Converged only on a full step.
    subroutine penalty_loop(m, d, sys, outer, searching, sol, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        integer, intent(in) :: outer
        logical, intent(in) :: searching   !! backtracking on every step (else: halve on cycles)
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        integer, allocatable :: code(:), new_code(:), seen(:, :)
        real(dp), allocatable :: z_new(:), z_base(:)
        real(dp) :: incr, merit_base, lambda
        integer :: inner, n_changed
        logical :: cycled
        character(len=200) :: text

        allocate (z_new(d%n), seen(sol%pts%n, m%max_inner))
        n_changed = 0
        inner_loop: do inner = 1, m%max_inner
            code = set_code(sol)
            seen(:, inner) = code
            merit_base = huge(1.0_dp)
            if (searching .and. inner > 1) merit_base = merit(d, sys, sol)
            call solve_with_sets(d, sys, sol, z_new, err)
            if (allocated(err)) return
            z_base = sol%z
            if (inner > 1 .and. relative_change(d, z_new, z_base) <= m%tol_inner) then
                ! the Newton point of the current sets is the current iterate (within tol):
                ! any set still changing sits exactly at its threshold
                sol%z = z_new
                call classify(d, sol)
                call log_inner(d, sys, sol, outer, inner, 0, relative_change(d, z_new, z_base), 1.0_dp)
                sol%n_inner = sol%n_inner + 1
                return
            end if
            call line_search(d, sys, z_base, z_new - z_base, merit_base, code, sol, lambda)
            incr = relative_change(d, sol%z, z_base)
            new_code = set_code(sol)
            n_changed = count(new_code /= code)
            cycled = .not. searching .and. n_changed > 0 .and. &
                     any(all(seen(:, 1:inner) == spread(new_code, 2, inner), dim=1))
            if (cycled) then
                ! the plain fixed point met a set pattern again: take half the step
                lambda = 0.5_dp
                sol%z = z_base + lambda*(z_new - z_base)
                call classify(d, sol)
            end if
            call log_inner(d, sys, sol, outer, inner, n_changed, incr, lambda)
            sol%n_inner = sol%n_inner + 1
            if (lambda == 1.0_dp .and. (n_changed == 0 .or. incr <= m%tol_inner)) return
        end do inner_loop
        write (text, '(a,i0,a,i0,a,i0,a)') 'contact (inner) loop did not converge in ', &
            m%max_inner, ' iterations at outer iteration ', outer, ' (', n_changed, &
            ' Gauss points still change state)'
        call new_error(err, EXIT_ANALYSIS, trim(text))
    end subroutine penalty_loop

    !> z = z_base + lambda step with lambda = 1, 1/2, ... 1/64: the full step when it keeps the
    !! sets it was computed with (it then solves its own system exactly), else the first that
    !! lowers the residual (Armijo, 1e-4), else the last. Leaves sol classified at that point.
    subroutine line_search(d, sys, z_base, step, merit_base, code, sol, lambda)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        real(dp), intent(in) :: z_base(:), step(:), merit_base
        integer, intent(in) :: code(:)
        type(solution_t), intent(inout) :: sol
        real(dp), intent(out) :: lambda
        integer :: halving
        lambda = 1.0_dp
        halvings: do halving = 0, 6
            sol%z = z_base + lambda*step
            call classify(d, sol)
            if (merit_base == huge(1.0_dp)) exit halvings
            if (halving == 0 .and. all(set_code(sol) == code)) exit halvings
            if (merit(d, sys, sol) <= (1.0_dp - 1.0e-4_dp*lambda)*merit_base) exit halvings
            if (halving < 6) lambda = 0.5_dp*lambda
        end do halvings
    end subroutine line_search

    !> Scaled residual norm of (4.2) at sol%z with the sets of sol (fixed row scaling).
    real(dp) function merit(d, sys, sol)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(in) :: sol
        real(dp), allocatable :: a(:, :), rhs(:), res(:)
        integer :: i
        call system_for_sets(d, sys, sol, a, rhs)
        res = matmul(a, sol%z) - rhs
        do i = 1, d%n
            res(i) = res(i)*sys%row_scale(i)*min(1.0_dp, abs(sys%a0(i, i)/a(i, i)))**0.5_dp
        end do
        merit = norm2(res)
    end function merit

    !> Integer pattern of the two independent sets: 1 for tension, plus +-2 for slipping with
    !! that sign (so -2..3).
    pure function set_code(sol) result(code)
        type(solution_t), intent(in) :: sol
        integer :: code(size(sol%state))
        code = merge(1, 0, sol%tension)
        where (sol%slip) code = code + merge(2, -2, sol%sigma(1, :) >= 0.0_dp)
    end function set_code

    !> Tractions at the contact points, the two independent sets (paper 4.6a/4.7a slip with the
    !! current tau0, 4.6b/4.7b tension) and the reported state, for the current z and tau0.
    subroutine classify(d, sol)
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(inout) :: sol
        integer :: p
        do p = 1, sol%pts%n
            sol%sigma(:, p) = traction_at(d, sol%z(d%nv + 1:), sol%pts%elem(p), sol%pts%xi(p))
        end do
        sol%state = contact_state(sol%sigma(1, :), sol%sigma(2, :), sol%tau0)
        sol%slip = is_slipping(sol%sigma(1, :), sol%tau0)
        sol%tension = in_tension(sol%sigma(2, :))
    end subroutine classify

    !> Assemble the set-dependent terms, equilibrate, solve.
    subroutine solve_with_sets(d, sys, sol, z, err)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(inout) :: sol
        real(dp), intent(out) :: z(:)
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: a(:, :), rhs(:), s(:), y(:)
        integer :: i
        call system_for_sets(d, sys, sol, a, rhs)
        allocate (s(d%n), y(d%n))
        do i = 1, d%n
            s(i) = 1.0_dp
            if (a(i, i) /= 0.0_dp) s(i) = 1.0_dp/sqrt(abs(a(i, i)))
        end do
        do i = 1, d%n
            a(:, i) = a(:, i)*s*s(i)
        end do
        rhs = rhs*s
        call solve_symmetric(a, rhs, y, err)
        if (allocated(err)) return
        z = s*y
        sol%n_solves = sol%n_solves + 1
    end subroutine solve_with_sets

    !> Matrix and right-hand side of (4.2) for the sets held in sol, constraints applied.
    subroutine system_for_sets(d, sys, sol, a, rhs)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(in) :: sol
        real(dp), allocatable, intent(out) :: a(:, :), rhs(:)
        integer :: p, i, nl, idx(max_local)
        real(dp) :: val(max_local), der(max_local), x, sgn
        a = sys%a0
        allocate (rhs(d%n))
        rhs = 0.0_dp
        rhs(1:d%nv) = sys%q
        points: do p = 1, sol%pts%n
            if (sol%tension(p)) call add_point_mass(d, sol%pts, p, FIELD_SZ, -sys%penalty, a)
            if (.not. sol%slip(p)) cycle points
            call add_point_mass(d, sol%pts, p, FIELD_SX, -sys%c*sys%kappa, a)
            call eval_basis(d%basis(FIELD_SX), sol%pts%elem(p), sol%pts%xi(p), idx, val, der, x)
            nl = d%basis(FIELD_SX)%n_local
            sgn = sign(1.0_dp, sol%sigma(1, p))
            idx(1:nl) = idx(1:nl) + d%offset(FIELD_SX)
            rhs(idx(1:nl)) = rhs(idx(1:nl)) &
                             - sys%c*sys%kappa*sol%pts%wt(p)*sol%tau0(p)*sgn*val(1:nl)
        end do points
        do i = 1, size(d%fixed)
            a(d%fixed(i), :) = 0.0_dp
            a(:, d%fixed(i)) = 0.0_dp
            a(d%fixed(i), d%fixed(i)) = 1.0_dp
            rhs(d%fixed(i)) = 0.0_dp
        end do
    end subroutine system_for_sets

    !> max over displacement and traction blocks of |dz|_inf / |z|_inf.
    pure real(dp) function relative_change(d, z_new, z_old) result(incr)
        type(discretization_t), intent(in) :: d
        real(dp), intent(in) :: z_new(:), z_old(:)
        incr = max(maxval(abs(z_new(1:d%nv) - z_old(1:d%nv))) &
                   /max(maxval(abs(z_new(1:d%nv))), tiny(1.0_dp)), &
                   maxval(abs(z_new(d%nv + 1:) - z_old(d%nv + 1:))) &
                   /max(maxval(abs(z_new(d%nv + 1:))), tiny(1.0_dp)))
    end function relative_change

    subroutine log_inner(d, sys, sol, outer, inner, n_changed, incr, lambda)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(inout) :: sol
        integer, intent(in) :: outer, inner, n_changed
        real(dp), intent(in) :: incr, lambda
        type(iteration_record_t) :: rec
        rec%outer = outer
        rec%inner = inner
        rec%n_slip = count(sol%slip)
        rec%n_tension = count(sol%tension)
        rec%n_changed = n_changed
        rec%increment = incr
        rec%residual = merit(d, sys, sol)/max(norm2(sys%row_scale(1:d%nv)*sys%q), tiny(1.0_dp))
        if (lambda < 1.0_dp) write (rec%note, '(a,f9.6)') 'damped step x', lambda
        sol%history = [sol%history, rec]
    end subroutine log_inner

    subroutine log_note(sol, outer, note)
        type(solution_t), intent(inout) :: sol
        integer, intent(in) :: outer
        character(len=*), intent(in) :: note
        type(iteration_record_t) :: rec
        rec%outer = outer
        rec%note = note
        sol%history = [sol%history, rec]
    end subroutine log_note

    subroutine log_outer(sol, outer, incr, omega)
        type(solution_t), intent(inout) :: sol
        integer, intent(in) :: outer
        real(dp), intent(in) :: incr, omega
        type(iteration_record_t) :: rec
        rec%outer = outer
        rec%inner = 0
        rec%n_slip = count(sol%slip)
        rec%n_tension = count(sol%tension)
        rec%increment = incr
        write (rec%note, '(a,f6.4)') 'outer: tau0 update, relaxation ', omega
        sol%history = [sol%history, rec]
    end subroutine log_outer

    !> Residuals of both equations with the sets of the final state, equilibrium, admissibility.
    subroutine final_checks(m, d, sys, sol, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable :: a(:, :), rhs(:), res(:)
        integer :: p
        call system_for_sets(d, sys, sol, a, rhs)
        res = matmul(a, sol%z) - rhs
        sol%residual(1) = maxval(abs(res(1:d%nv)))/max(maxval(abs(sys%q)), tiny(1.0_dp))
        sol%residual(2) = maxval(abs(res(d%nv + 1:))) &
                          /max(maxval(abs(matmul(a(d%nv + 1:, 1:d%nv), sol%z(1:d%nv)))), &
                               tiny(1.0_dp))
        sol%reaction = 0.0_dp
        do p = 1, sol%pts%n
            sol%reaction(1) = sol%reaction(1) + sol%pts%wt(p)*sol%sigma(2, p)
            sol%reaction(2) = sol%reaction(2) + sol%pts%wt(p)*sol%sigma(1, p)
            sol%reaction(3) = sol%reaction(3) + sol%pts%wt(p)*sol%sigma(2, p)*sol%pts%x(p)
        end do
        sol%applied(1) = total_vertical_load(m)
        sol%applied(2) = sum(m%loads%fx)
        if (m%kind == MODEL_BEAM) then
            sol%applied(3) = applied_moment(m)
            ! reaction moment about the mid-plane: int sigma_z x - (h/2) int sigma_x
            sol%reaction(3) = sol%reaction(3) - 0.5_dp*m%h*sol%reaction(2)
            sol%applied(3) = sol%applied(3) - 0.5_dp*m%h*sol%applied(2)
        else
            ! radial shear is self-equilibrated by symmetry: no horizontal or moment balance
            sol%reaction(2:3) = 0.0_dp
            sol%applied(2:3) = 0.0_dp
        end if
        sol%admissibility = maxval(abs(sol%sigma(1, :)) - m%f*max(sol%sigma(2, :), 0.0_dp))
        sol%min_sigma_z = minval(sol%sigma(2, :))
        if (.not. all(sol%z == sol%z)) then
            call new_error(err, EXIT_ANALYSIS, 'the solution contains NaN')
            return
        end if
        call require_checks(m, sol, err)
    end subroutine final_checks

    !> A solution that fails its own equilibrium is no result: the linear solves have lost their
    !! accuracy (ill-conditioning: a very stiff structure on a very fine mesh, say). The
    !! interface-law residual is reported, not tested: with sets re-decided at the final state
    !! it is dominated by points exactly at their threshold times the slip stiffness 1/eps_bar.
    subroutine require_checks(m, sol, err)
        type(model_t), intent(in) :: m
        type(solution_t), intent(in) :: sol
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: limit = 1.0e-5_dp   !! of the load (reports print 6 digits)
        real(dp) :: scale(3), equilibrium
        character(len=300) :: text
        scale = total_vertical_load(m)*[1.0_dp, 1.0_dp, m%length]
        equilibrium = maxval(abs(sol%reaction - sol%applied)/scale)
        if (sol%residual(1) <= limit .and. equilibrium <= limit) return
        write (text, '(a,es9.2,a,es9.2,a)') 'the solution fails its equilibrium check '// &
            '(relative residual of 4.2a ', sol%residual(1), &
            '; reaction error ', equilibrium, ' of the load): the system is too '// &
            'ill-conditioned to trust (very stiff structure or very fine mesh?)'
        call new_error(err, EXIT_ANALYSIS, trim(text))
    end subroutine require_checks
end module contact_solver
