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
!!
!! Nested start (Newton): a mesh of more than nested_from elements is first solved on its
!! nested coarser mesh (every other node, the ends and the load positions kept: mesh_refinement),
!! itself solved the same way, with its T restricted from the fine one (nested_spaces: the
!! same Galerkin matrix to round-off, without the kernel integrals); the coarse tractions at
!! the fine contact points predict the sets, and the Newton method starts from the solution
!! for those sets. The lift-off and
!! stick/slip boundaries then start within an element or two of their place, where the
!! adhesive start leaves them to move one front of Gauss points per step: on fine meshes of
!! soft structures that front moved by a few points per step and the merit stalled (a plate,
!! rho 1e-6, disk load: solved at N_e = 20, status 2 at N_e = 200 to 2000 before).
module contact_solver
    use errors, only: error_t
    use flexibility_cache, only: flexibility_cache_t
    use model, only: interface_t, model_t, METHOD_TWOLOOP
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use applied_loads, only: load_positions
    use discretization, only: discretization_t, discretise_mesh, &
                              locate_element
    use mesh, only: mesh_t
    use mesh_refinement, only: coarsened, pinned_nodes, same_nodes
    use mindlin_structure, only: traction_at
    use contact_system, only: contact_points_t, iteration_record_t, solution_t, system_t, &
                              coarse_solution_t, &
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
    public :: contact_points_t, iteration_record_t, solution_t, coarse_solution_t
    public :: solve_contact, check_load_admissible, contact_points, nested_prediction
    public :: nested_discretisation
    public :: classify_complete

    integer, parameter :: nested_from = 48   !! larger meshes start from the nested coarser one

contains

    !> Solve one case. Fails with EXIT_ANALYSIS when there is no equilibrium or no convergence.
    recursive subroutine solve_contact(m, d, sol, err, progress_unit, t_given, cache, start)
        type(model_t), intent(in) :: m                   !! the model
        type(discretization_t), intent(in) :: d          !! the discretisation
        type(solution_t), intent(out) :: sol             !! the solution
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        integer, intent(in), optional :: progress_unit   !! a unit for one line per Newton step
        !> T of d when it is known (the restriction of a finer mesh's): moved in
        real(dp), allocatable, intent(inout), optional :: t_given(:, :)
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        !> a solution known on a coarser mesh of the same base (a case's own, d being its
        !! mesh with every element cut in two; an adaptation's previous cycle): where d gets
        !! a nested start, it is predicted from this solution instead of solving the nested
        !! coarser mesh
        type(coarse_solution_t), intent(in), optional :: start
        type(system_t) :: sys
        type(discretization_t) :: dc, ds
        real(dp), allocatable :: sigma_start(:, :), t_c(:, :)
        real(dp) :: t0
        logical :: nest, known

        allocate (sol%history(0))
        if (present(progress_unit)) sol%progress_unit = progress_unit
        call check_load_admissible(m, err)
        if (allocated(err)) return
        sol%pts = contact_points(m%structure, d)
        nest = nested_discretisation(m, d, dc)
        known = nest .and. present(start)
        t0 = wall_seconds()
        if (nest .and. .not. known) then
            call build_system(m, d, sol%pts, sys, err, t_given, dc, t_c, cache=cache)
        else
            call build_system(m, d, sol%pts, sys, err, t_given, cache=cache)
        end if
        sol%seconds(1) = sys%t_seconds
        sol%seconds(2) = wall_seconds() - t0 - sys%t_seconds
        if (allocated(err)) return
        t0 = wall_seconds()
        if (known) then
            sol%coarse = [start]
            ds = dc
            if (.not. same_nodes(start%x, dc%msh%x)) call discretise_nodes(m, start%x, ds)
            call predicted_tractions(ds, start%z, sol%pts, sigma_start)
        else if (nest) then
            call nested_prediction(m, dc, t_c, sol, sigma_start)
        end if
        sol%seconds(3) = wall_seconds() - t0
        allocate (sol%z(d%n), sol%state(sol%pts%n), sol%sigma(2, sol%pts%n))
        allocate (sol%slip(sol%pts%n), sol%tension(sol%pts%n))
        t0 = wall_seconds()
        if (is_active(plan_reduction(m, d))) then
            call solve_reduced(m, d, sys, sol, err, sigma_start, t0)
            return
        end if
        call use_rigid_coordinates(sys)
        if (m%solver%method == METHOD_TWOLOOP) then
            call solve_two_loop(m, d, sys, sol, err)
        else
            call solve_newton(m, d, sys, sol, err, sigma_start)
            if (.not. allocated(err)) call classify_complete(m%interface, sol)
        end if
        sol%seconds(4) = wall_seconds() - t0
        t0 = wall_seconds()
        if (.not. allocated(err)) call final_checks(m, d, sys, sol, err)
        call absolute_answer(sys, sol)
        sol%seconds(5) = wall_seconds() - t0
    end subroutine solve_contact

    !> Newton on the reduced problem of model_reduction, checked against the reduced complete
    !! problem (the model solved: for f = 0 Coulomb's sigma_x = 0, which the full model's
    !! regularised law would judge at its stick kink), then expanded to the full numbering
    !! (the contact points, and so the tractions and sets there, are the full model's).
    subroutine solve_reduced(m, d, sys, sol, err, sigma_start, t0)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(inout) :: sol
        type(error_t), allocatable, intent(out) :: err
        real(dp), allocatable, intent(in) :: sigma_start(:, :)   !! nested_prediction's
        real(dp), intent(in) :: t0           !! wall_seconds() when the iterations began
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
        call solve_newton(m, dr, sr, sol, err, sigma_start)
        sol%seconds(4) = wall_seconds() - t0
        if (.not. allocated(err)) then
            call classify_complete(m%interface, sol)
            call final_checks(m, dr, sr, sol, err)
        end if
        call absolute_answer(sr, sol)
        sol%z = expand(red, sol%z)
        sol%seconds(5) = wall_seconds() - t0 - sol%seconds(4)
        sol%pts = pts
    end subroutine solve_reduced

    !> z mapped from the solver's rigid coordinates to absolute ones, in double: the low
    !! part of a held solution (z_lo, newton_method) is below the rounding of the absolute
    !! displacements and is dropped with the coordinates it belongs to.
    pure subroutine absolute_answer(sys, sol)
        type(system_t), intent(in) :: sys
        type(solution_t), intent(inout) :: sol
        sol%z = to_absolute(sys%rigid, sol%z)
        if (allocated(sol%z_lo)) deallocate (sol%z_lo)
    end subroutine absolute_answer

    !> The nested coarser mesh of d (every other node, the ends and the load positions kept),
    !! discretised as d: true for the Newton method on more than nested_from elements.
    function nested_discretisation(m, d, dc) result(nest)
        type(model_t), intent(in) :: m              !! the model
        type(discretization_t), intent(in) :: d     !! the discretisation
        type(discretization_t), intent(out) :: dc   !! the nested coarser mesh, discretised as d
        logical :: nest
        type(mesh_t) :: coarse
        logical, allocatable :: pinned_c(:)
        nest = .false.
        if (m%solver%method == METHOD_TWOLOOP .or. d%msh%ne <= nested_from) return
        call coarsened(d%msh, pinned_nodes(d%msh, load_positions(m%loads)), coarse, pinned_c)
        if (coarse%ne >= d%msh%ne) return
        call discretise_mesh(m, coarse, dc)
        nest = .true.
    end function nested_discretisation

    !> The tractions at the contact points of sol predicted by the solution on the nested
    !! coarser mesh dc, whose T (t_c, the Galerkin restriction of the fine one) is moved in
    !! (sigma not allocated when the coarse case could not be solved: the Newton method then
    !! starts from the adhesive solution). Its linear solves are counted in
    !! sol%n_nested_solves.
    recursive subroutine nested_prediction(m, dc, t_c, sol, sigma)
        type(model_t), intent(in) :: m             !! the model
        type(discretization_t), intent(in) :: dc   !! the nested coarser discretisation
        !> its T (restricted from the fine one), moved in
        real(dp), allocatable, intent(inout) :: t_c(:, :)
        type(solution_t), intent(inout) :: sol     !! the solution, updated
        !> (sigma_x, sigma_z) at sol's contact points
        real(dp), allocatable, intent(out) :: sigma(:, :)
        type(solution_t) :: sol_c
        type(error_t), allocatable :: err_c
        call solve_contact(m, dc, sol_c, err_c, t_given=t_c)
        sol%n_nested_solves = sol_c%n_solves + sol_c%n_nested_solves
        if (allocated(err_c)) return
        if (.not. allocated(sol_c%coarse)) allocate (sol_c%coarse(0))
        sol%coarse = [coarse_solution_t(x=dc%msh%x, z=sol_c%z, admissibility=sol_c%admissibility, &
                                        reaction=sol_c%reaction, applied=sol_c%applied, &
                                        n_solves=sol_c%n_solves), sol_c%coarse]
        call predicted_tractions(dc, sol_c%z, sol%pts, sigma)
    end subroutine nested_prediction

    !> The model discretised on the mesh whose nodes are x (x(1) the first).
    subroutine discretise_nodes(m, x, d)
        type(model_t), intent(in) :: m              !! the model
        real(dp), intent(in) :: x(:)                !! the nodes [L]
        type(discretization_t), intent(out) :: d    !! the discretisation
        type(mesh_t) :: msh
        msh%ne = size(x) - 1
        allocate (msh%x(0:msh%ne))
        msh%x(:) = x
        call discretise_mesh(m, msh, d)
    end subroutine discretise_nodes

    !> The tractions (sigma_x, sigma_z) of the solution z on the coarser discretisation dc
    !! at the contact points pts of a finer mesh.
    pure subroutine predicted_tractions(dc, z, pts, sigma)
        type(discretization_t), intent(in) :: dc          !! the coarser discretisation
        real(dp), intent(in) :: z(:)                      !! its solution [v; r]
        type(contact_points_t), intent(in) :: pts         !! the finer mesh's contact points
        real(dp), allocatable, intent(out) :: sigma(:, :) !! (2, pts%n) the tractions there
        integer :: p, e
        real(dp) :: xi
        allocate (sigma(2, pts%n))
        do p = 1, pts%n
            call locate_element(dc%msh, pts%x(p), e, xi)
            sigma(:, p) = traction_at(dc, z(dc%nv + 1:), e, xi)
        end do
    end subroutine predicted_tractions

    !> Tractions, threshold tau0 = f max(sigma_z, 0), sets and states of the complete problem.
    subroutine classify_complete(interface, sol)
        type(interface_t), intent(in) :: interface   !! the interface part of the model
        type(solution_t), intent(inout) :: sol       !! the solution, updated
        sol%sigma = point_tractions(sol%pts, sol%z)
        sol%tau0 = friction_threshold(interface%f, sol%sigma(2, :))
        sol%state = contact_state(sol%sigma(1, :), sol%sigma(2, :), sol%tau0)
        sol%slip = is_slipping(sol%sigma(1, :), sol%tau0)
        sol%tension = in_tension(sol%sigma(2, :))
    end subroutine classify_complete

    !> Wall-clock seconds (for the phase times of solution_t).
    real(dp) function wall_seconds()
        integer(int64) :: count, rate
        call system_clock(count, rate)
        wall_seconds = real(count, dp)/real(rate, dp)
    end function wall_seconds

end module contact_solver

