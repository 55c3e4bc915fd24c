!> The layer above the case pipeline that goes back to the solver: one case brought to the
!! quality its deck asks for, by one of two policies, then its error estimated.
!!
!!  * ADAPT card: adaptive refinement to a tolerance (adaptive_solve); the estimates are
!!    those of the final cycle.
!!  * otherwise the MESH card's mesh, refined by doubling while friction is not resolved
!!    pointwise (admissible_refinement); then the estimate from the same case on its mesh
!!    with every element cut in two and with every other node removed (error_estimate),
!!    unless estimates are switched off.
!!
!! Every refined or coarsened solve is a new case of the one pipeline (solved_case); the
!! deck's model is never changed.
module case_quality
    use kinds, only: dp
    use errors, only: error_t
    use model, only: model_t, MODEL_PLATE, FIELD_W, FIELD_PSI
    use shape_functions, only: INTERP_P1
    use discretization, only: discretization_t, new_discretization, loads_on_nodes
    use contact_solver, only: solution_t
    use solved_case, only: case_t, solve_case, finish_case, failed_case
    use flexibility_cache, only: flexibility_cache_t
    use plausibility, only: warning_length, settlement_warnings, tension_warnings
    use error_estimate, only: estimate_errors
    use adaptive_solve, only: adaptation_t, solve_adaptive
    use admissible_refinement, only: refine_until_admissible, require_admissible
    implicit none
    private

    public :: solve_to_quality, adapt_interpolation_warnings

contains

    !> Solve m to the quality its deck asks for (module header). On failure c holds what
    !! there is of the failed case (its discretisation, the solver's history) for the report.
    subroutine solve_to_quality(m, estimates, progress_unit, c, adaptation, warnings, err, &
                                cache)
        type(model_t), intent(in) :: m                  !! the deck's model
        logical, intent(in) :: estimates                !! estimate errors (two more solves)
        integer, intent(in) :: progress_unit            !! >= 0: each Newton step there
        type(case_t), intent(out) :: c                  !! the case solved
        type(adaptation_t), intent(out) :: adaptation   !! what ADAPT did (adapted false else)
        character(len=warning_length), allocatable, intent(out) :: warnings(:)  !! on results
        type(error_t), allocatable, intent(out) :: err  !! no result (status in err%code)
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        allocate (warnings(0))
        if (m%mesh%adapt_tol > 0.0_dp) then
            call adapt(m, c, adaptation, err, cache)
        else
            call solve_case(m, c, err, progress_unit, cache)
            if (.not. allocated(err)) call refine_until_admissible(c, progress_unit, &
                                                                   warnings, err, cache)
        end if
        if (.not. allocated(err)) call require_admissible(c%summary, err)
        if (allocated(err)) return
        warnings = [character(len=warning_length) :: warnings, &
                    settlement_warnings(c%model, c%summary%w_max%value), &
                    tension_warnings(c%model, c%summary%n_tension_flags, &
                                     c%summary%n_tension_lifted, c%stations%n, &
                                     c%stations%most_tensile, c%stations%tension_tol)]
        if (adaptation%adapted) then
            warnings = [character(len=warning_length) :: warnings, &
                        adapt_interpolation_warnings(m)]
            call take_adapted_estimates(adaptation, c, warnings)
            return
        end if
        if (.not. loads_on_nodes(m%loads, c%d%msh)) &
            warnings = [character(len=warning_length) :: warnings, &
                        'a POINT, RING or MOMENT load lies between two nodes of '// &
                        'the mesh: results near it converge at first order only '// &
                        '(so do their error estimates); MESH grading LOADS puts '// &
                        'a node at every load']
        if (estimates) call estimate_errors(c%model, c%d, c%entries, c%sol%coarse, &
                                            c%summary%edge_in_contact, cache, c%sol, &
                                            c%design)
    end subroutine solve_to_quality

    !> Warning for an ADAPT deck that keeps P1 deflection or rotation on a plate: its centre
    !! pressure converges at first order on any mesh (error_estimate, formal_order), so the
    !! adaptation refines far. Measured on the work-precision plate
    !! (output/bench/adapt_pays.md): P1-ADAPT took 0.189 s to tol 1e-3 and 2.36 s to 1e-4,
    !! ADAPT with S2 w and psi (its default when the MESH card gives no interpolation) 0.0132
    !! and 0.229 s. On the beam P1-ADAPT was the faster of the two: no warning there.
    pure function adapt_interpolation_warnings(m) result(w)
        type(model_t), intent(in) :: m         !! the model (an ADAPT deck)
        character(len=warning_length), allocatable :: w(:)
        allocate (w(0))
        if (.not. m%mesh%adapt_tol > 0.0_dp) return
        if (m%structure%kind /= MODEL_PLATE) return
        if (m%mesh%interp(FIELD_W) /= INTERP_P1 .and. m%mesh%interp(FIELD_PSI) /= INTERP_P1) &
            return
        w = [character(len=warning_length) :: 'ADAPT with P1 w or psi on a plate: its '// &
             'centre pressure converges at first order on any mesh; S2 w and psi (ADAPT''s '// &
             'default) reached the same tol 10 to 14 times sooner (output/bench/adapt_pays.md)']
    end function adapt_interpolation_warnings

    !> The ADAPT policy: adaptive refinement from the MESH card's mesh, then the case's
    !! results on the final mesh.
    subroutine adapt(m, c, adaptation, err, cache)
        type(model_t), intent(in) :: m                  !! the deck's model
        type(case_t), intent(out) :: c                  !! the case on the adapted mesh
        type(adaptation_t), intent(out) :: adaptation   !! the cycles
        type(error_t), allocatable, intent(out) :: err  !! the first mesh failed
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(discretization_t) :: d
        type(solution_t) :: sol
        call new_discretization(m, d, err)
        if (.not. allocated(err)) call solve_adaptive(m, d, sol, adaptation, err, cache)
        if (allocated(err)) then
            c = failed_case(m, d, sol)
            return
        end if
        call finish_case(m, d, sol, c, err)
    end subroutine adapt

    !> The estimates of the adaptation's final cycle (the same mesh and solution as the
    !! entries) and, when the tolerance was not reached, a warning that says so.
    subroutine take_adapted_estimates(a, c, warnings)
        type(adaptation_t), intent(in) :: a             !! what ADAPT did
        type(case_t), intent(inout) :: c                !! its entries get the estimates
        character(len=warning_length), allocatable, intent(inout) :: warnings(:)  !! appended
        character(len=warning_length) :: text
        integer :: i, k
        do i = 1, size(c%entries)
            do k = 1, size(a%entries)
                if (a%entries(k)%key /= c%entries(i)%key) cycle
                c%entries(i)%has_error = a%entries(k)%has_error
                c%entries(i)%error = a%entries(k)%error
                c%entries(i)%order = a%entries(k)%order
            end do
        end do
        if (a%reached) return
        ! the reason (a failed refined solve quotes its message) goes in the report's
        ! adaptation lines; the warning stays within one warning line
        if (a%estimate >= 0.0_dp) then
            write (text, '(a,es9.2,a,es9.2,a,i0,a)') 'ADAPT tolerance ', a%tol, &
                ' not reached: largest estimated relative error ', a%estimate, &
                ' ('//a%worst//') at N_e = ', a%ne, '; see the report, section 2'
        else
            write (text, '(a,es9.2,a,i0,a)') 'ADAPT tolerance ', a%tol, &
                ' not reached: no error estimate at N_e = ', a%ne, '; see the report, section 2'
        end if
        warnings = [character(len=warning_length) :: warnings, text]
    end subroutine take_adapted_estimates
end module case_quality
