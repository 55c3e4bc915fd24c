!> The checks every solution of the contact problem must pass, whatever the method: loads
!! that no unilateral frictional support can carry are refused before solving; the answer is
!! measured against the complete problem (4.2 with tau0 = f max(sigma_z, 0) of the final
!! state), not against the method's own stopping rule, and against statics (reactions = loads).
module solution_checks
    use kinds, only: dp
    use errors, only: error_t, new_error, EXIT_ANALYSIS
    use model, only: model_t, MODEL_BEAM, LOAD_MOMENT, LOAD_PATCH, total_vertical_load
    use discretization, only: discretization_t
    use contact_system, only: solution_t, system_t, complete_residual, jacobian_diagonal, &
                              a0_times, equilibrium_residual
    implicit none
    private

    public :: check_load_admissible, final_checks, applied_moment

    !> What require_checks accepts: equilibrium (4.2a residual, reactions) to this fraction of
    !! the load, the interface law to this fraction of max |r| (reports print 6 digits).
    real(dp), parameter, public :: check_limit = 1.0e-5_dp

contains

    !> Loads that no unilateral frictional support can carry (SPEC §4): EXIT_ANALYSIS.
    subroutine check_load_admissible(m, err)
        type(model_t), intent(in) :: m                   !! the model
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        real(dp) :: v, h_total, arm
        character(len=240) :: text
        v = total_vertical_load(m%loads)
        if (.not. v > 0.0_dp) then
            write (text, '(a,es12.4,a)') 'no equilibrium: the net vertical load (', v, &
                ') is not downward and the soil takes no tension (uplift)'
            call new_error(err, EXIT_ANALYSIS, trim(text))
            return
        end if
        h_total = sum(m%loads%fx)
        if (abs(h_total) > m%interface%f*v) then
            write (text, &
                '(a,es12.4,a,es12.4,a)') 'no equilibrium: sliding - the horizontal load H =', &
                h_total, ' exceeds the friction capacity f*V =', m%interface%f*v, &
                ' (utilisation H/(fV) > 1)'
            call new_error(err, EXIT_ANALYSIS, trim(text))
            return
        end if
        if (m%structure%kind == MODEL_BEAM) then
            arm = applied_moment(m)/v
            if (abs(arm) >= 0.5_dp*m%structure%length) then
                write (text, '(a,es12.4,a,es12.4,a)') 'no equilibrium: overturning - the load '// &
                    'resultant acts at x =', arm, ', outside the base (|x| < ', &
                    0.5_dp*m%structure%length, ')'
                call new_error(err, EXIT_ANALYSIS, trim(text))
            end if
        end if
    end subroutine check_load_admissible

    !> Moment of the loads about the mid-plane at x = 0, work-conjugate to a rigid rotation
    !! (w = x, psi = 1): sum F_z x + M + h F_x (horizontal loads act on the top face and their
    !! reaction on the bottom face).
    pure real(dp) function applied_moment(m)
        type(model_t), intent(in) :: m   !! the model (its loads and thickness)
        integer :: i
        applied_moment = 0.0_dp
        do i = 1, size(m%loads)
            associate (ld => m%loads(i))
                if (ld%kind == LOAD_MOMENT) then
                    applied_moment = applied_moment + ld%fz
                else if (ld%kind == LOAD_PATCH) then
                    applied_moment = applied_moment + ld%fz*0.5_dp*(ld%x1 + ld%x2) &
                        + m%structure%h*ld%fx
                else
                    applied_moment = applied_moment + ld%fz*ld%x1 + m%structure%h*ld%fx
                end if
            end associate
        end do
    end function applied_moment

    !> Residuals of both equations of the complete problem (tau0 = f max(sigma_z, 0) from the
    !! final state, whatever the method), equilibrium, admissibility. 4.2a is evaluated in
    !! double-double for the solution as held, z + z_lo (equilibrium_residual).
    subroutine final_checks(m, d, sys, sol, err)
        type(model_t), intent(in) :: m                   !! the model
        type(discretization_t), intent(in) :: d          !! the discretisation
        type(system_t), intent(in) :: sys                !! the assembled system (A0, q)
        type(solution_t), intent(inout) :: sol           !! the solution, updated
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        real(dp), allocatable :: res(:), v_only(:), mv(:), z_lo(:)
        integer :: p
        allocate (res(d%n), z_lo(d%n))
        z_lo = 0.0_dp
        if (allocated(sol%z_lo)) z_lo = sol%z_lo
        call complete_residual(d, sys, sys%law, sol%pts, sol%z, res)
        res(1:d%nv) = equilibrium_residual(d, sys, sol%z, z_lo)
        sol%residual(1) = maxval(abs(res(1:d%nv)))/max(maxval(abs(sys%q)), tiny(1.0_dp))
        v_only = [sol%z(1:d%nv), spread(0.0_dp, 1, d%nr)]
        mv = a0_times(sys, 0.0_dp*v_only, v_only)       ! M v in the traction rows
        sol%residual(2) = maxval(abs(res(d%nv + 1:))) &
                          /max(maxval(abs(mv(d%nv + 1:))), tiny(1.0_dp))
        sol%law_residual = traction_residual(d, sys, sol, res)
        sol%reaction = 0.0_dp
        do p = 1, sol%pts%n
            sol%reaction(1) = sol%reaction(1) + sol%pts%wt(p)*sol%sigma(2, p)
            sol%reaction(2) = sol%reaction(2) + sol%pts%wt(p)*sol%sigma(1, p)
            sol%reaction(3) = sol%reaction(3) + sol%pts%wt(p)*sol%sigma(2, p)*sol%pts%x(p)
        end do
        sol%applied(1) = total_vertical_load(m%loads)
        sol%applied(2) = sum(m%loads%fx)
        if (m%structure%kind == MODEL_BEAM) then
            sol%applied(3) = applied_moment(m)
            ! reaction moment about the mid-plane: int sigma_z x - (h/2) int sigma_x
            sol%reaction(3) = sol%reaction(3) - 0.5_dp*m%structure%h*sol%reaction(2)
            sol%applied(3) = sol%applied(3) - 0.5_dp*m%structure%h*sol%applied(2)
        else
            ! radial shear is self-equilibrated by symmetry: no horizontal or moment balance
            sol%reaction(2:3) = 0.0_dp
            sol%applied(2:3) = 0.0_dp
        end if
        sol%admissibility = maxval(abs(sol%sigma(1, :)) - m%interface%f*max(sol%sigma(2, :), &
            0.0_dp))
        sol%min_sigma_z = minval(sol%sigma(2, :))
        if (.not. all(sol%z == sol%z)) then
            call new_error(err, EXIT_ANALYSIS, 'the solution contains NaN')
            return
        end if
        call require_checks(m, sol, err)
    end subroutine final_checks

    !> The 4.2b residual of the complete problem as a traction error: max over the traction
    !! equations of |F_i / J_ii| (the Jacobi correction, J the generalised Jacobian at the
    !! final state), relative to max |r|. Scale-free: the slip and penalty rows, whose entries
    !! carry 1/eps_bar and 1/eta_bar, are measured in tractions like the others.
    real(dp) function traction_residual(d, sys, sol, res) result(err_r)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(in) :: sol
        real(dp), intent(in) :: res(:)
        real(dp), allocatable :: dg(:)
        integer :: i
        dg = jacobian_diagonal(d, sys, sys%law, sol%pts, sol%sigma)
        err_r = 0.0_dp
        do i = d%nv + 1, d%n
            if (dg(i) /= 0.0_dp) err_r = max(err_r, abs(res(i)/dg(i)))
        end do
        err_r = err_r/max(maxval(abs(sol%z(d%nv + 1:))), tiny(1.0_dp))
    end function traction_residual

    !> Every method's answer is checked against the complete problem, not its own stopping
    !! rule. The interface law (4.2b) is tested as a traction error (traction_residual): the
    !! plain residual of 4.2b carries the slip stiffness 1/eps_bar and the penalty 1/eta_bar, so
    !! round-off and the two-loop's lagged threshold inflate it without meaning. A solution
    !! that fails its equilibrium is no result either: the linear solves have lost their
    !! accuracy (ill-conditioning: a very stiff structure on a very fine mesh, say).
    subroutine require_checks(m, sol, err)
        type(model_t), intent(in) :: m
        type(solution_t), intent(in) :: sol
        type(error_t), allocatable, intent(out) :: err
        real(dp), parameter :: limit = check_limit
        real(dp) :: scale(3), equilibrium
        character(len=300) :: text
        scale = total_vertical_load(m%loads)*[1.0_dp, 1.0_dp, m%structure%length]
        equilibrium = maxval(abs(sol%reaction - sol%applied)/scale)
        if (.not. sol%law_residual <= limit) then
            write (text, '(a,a,a,es9.2,a)') 'the ', trim(sol%method), ' solution fails the '// &
                'interface law of the complete problem (4.2b with tau0 = f max(sigma_z, 0): '// &
                'traction residual ', sol%law_residual, ' of max |r|): no solution'
            call new_error(err, EXIT_ANALYSIS, trim(text))
            return
        end if
        if (sol%residual(1) <= limit .and. equilibrium <= limit) return
        write (text, '(a,es9.2,a,es9.2,a)') 'the solution fails its equilibrium check '// &
            '(relative residual of 4.2a ', sol%residual(1), &
            '; reaction error ', equilibrium, ' of the load): the system is too '// &
            'ill-conditioned to trust (very stiff structure or very fine mesh?)'
        call new_error(err, EXIT_ANALYSIS, trim(text))
    end subroutine require_checks
end module solution_checks
