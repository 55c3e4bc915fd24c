!> Unilateral contact with regularised Coulomb friction: one case solved by the method the deck
!! selects (SOLVER f7): the semismooth Newton method on the complete problem (newton_method,
!! the default) or the paper's two-loop iteration (§3–4, below), and the checks every answer
!! must pass against the complete problem.
!!
!! The job is split by module: contact_system (the discrete problem 4.2: points, matrices,
!! residual and Jacobian of the complete problem), interface_law (stick / slip / lift-off at a
!! point), newton_method and two_loop_method (the iterations), solution_checks (refusals and
!! the checks of every answer). This module only dispatches; every method solves in the
!! rigid coordinates of rigid_body (stiff structures), the answer is returned absolute.
module contact_solver
    use errors, only: error_t
    use model, only: model_t, METHOD_TWOLOOP
    use discretization, only: discretization_t
    use contact_system, only: contact_points_t, iteration_record_t, solution_t, system_t, &
                              build_system, contact_points, point_tractions, &
                              use_rigid_coordinates
    use rigid_body, only: to_absolute
    use newton_method, only: solve_newton
    use two_loop_method, only: solve_two_loop
    use solution_checks, only: check_load_admissible, final_checks
    use model_reduction, only: reduction_t, plan_reduction, is_active, reduced_discretization, &
                               reduced_system, reduced_points, expand
    use interface_law, only: STATE_LIFTOFF, STATE_STICK, STATE_SLIP, contact_state, &
                             friction_threshold, in_tension, is_slipping
    implicit none
    private

    public :: STATE_LIFTOFF, STATE_STICK, STATE_SLIP
    public :: contact_points_t, iteration_record_t, solution_t
    public :: solve_contact, check_load_admissible, contact_points

contains

    !> Solve one case. Fails with EXIT_ANALYSIS when there is no equilibrium or no convergence.
    subroutine solve_contact(m, d, sol, err, progress_unit)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(out) :: sol
        type(error_t), allocatable, intent(out) :: err
        integer, intent(in), optional :: progress_unit   !! a unit for one line per Newton step
        type(system_t) :: sys

        allocate (sol%history(0))
        if (present(progress_unit)) sol%progress_unit = progress_unit
        call check_load_admissible(m, err)
        if (allocated(err)) return
        sol%pts = contact_points(m, d)
        call build_system(m, d, sol%pts, sys, err)
        if (allocated(err)) return
        allocate (sol%z(d%n), sol%state(sol%pts%n), sol%sigma(2, sol%pts%n))
        allocate (sol%slip(sol%pts%n), sol%tension(sol%pts%n))
        if (is_active(plan_reduction(m, d))) then
            call solve_reduced(m, d, sys, sol, err)
            return
        end if
        call use_rigid_coordinates(sys)
        if (m%method == METHOD_TWOLOOP) then
            call solve_two_loop(m, d, sys, sol, err)
        else
            call solve_newton(m, d, sys, sol, err)
            if (.not. allocated(err)) call classify_complete(m, sol)
        end if
        if (.not. allocated(err)) call final_checks(m, d, sys, sol, err)
        sol%z = to_absolute(sys%rigid, sol%z)
    end subroutine solve_contact

    !> Newton on the reduced problem of model_reduction, checked against the reduced complete
    !! problem (the model solved: for f = 0 Coulomb's sigma_x = 0, which the full model's
    !! regularised law would judge at its stick kink), then expanded to the full numbering
    !! (the contact points, and so the tractions and sets there, are the full model's).
    subroutine solve_reduced(m, d, sys, sol, err)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        type(reduction_t) :: red
        type(discretization_t) :: dr
        type(system_t) :: sr
        type(contact_points_t) :: pts
        red = plan_reduction(m, d)
        dr = reduced_discretization(d, red)
        sr = reduced_system(sys, d, dr, red)
        call use_rigid_coordinates(sr)
        pts = sol%pts
        sol%pts = reduced_points(pts, red)
        deallocate (sol%z)
        allocate (sol%z(dr%n))
        call solve_newton(m, dr, sr, sol, err)
        if (.not. allocated(err)) then
            call classify_complete(m, sol)
            call final_checks(m, dr, sr, sol, err)
        end if
        sol%z = expand(red, to_absolute(sr%rigid, sol%z))
        sol%pts = pts
    end subroutine solve_reduced

    !> Tractions, threshold tau0 = f max(sigma_z, 0), sets and states of the complete problem.
    subroutine classify_complete(m, sol)
        type(model_t), intent(in) :: m
        type(solution_t), intent(inout) :: sol
        sol%sigma = point_tractions(sol%pts, sol%z)
        sol%tau0 = friction_threshold(m%f, sol%sigma(2, :))
        sol%state = contact_state(sol%sigma(1, :), sol%sigma(2, :), sol%tau0)
        sol%slip = is_slipping(sol%sigma(1, :), sol%tau0)
        sol%tension = in_tension(sol%sigma(2, :))
    end subroutine classify_complete

end module contact_solver

