!> The refinement policy of friction: a case solved with the law of the complete problem
!! (its residual checks passed) whose friction admissibility check still fails is a mesh too
!! coarse for the slip. The law holds in the Galerkin sense, over each traction function,
!! not at every Gauss point (doc/CHOICES.md, "Very soft beams"). The case is solved again,
!! as a new case, on twice the elements of the same MESH family, up to max_doublings times
!! and max_auto_elements; require_admissible then judges the last mesh.
module admissible_refinement
    use kinds, only: dp
    use errors, only: error_t, new_error, add_context, EXIT_ANALYSIS
    use model, only: model_t
    use solved_case, only: case_t, solve_case
    use flexibility_cache, only: flexibility_cache_t
    use design_summary, only: summary_t
    use plausibility, only: warning_length
    use resource_limits, only: check_memory, memory_available
    implicit none
    private

    integer, parameter :: max_doublings = 3
    integer, parameter :: max_auto_elements = 1000   !! as ADAPT's default max_elements

    public :: refine_until_admissible, require_admissible

contains

    !> c (in: solved on the deck's mesh; out: on the mesh that resolves the friction, or the
    !! failed finer case); a warning says so when the mesh was refined.
    subroutine refine_until_admissible(c, progress_unit, warnings, err, cache)
        type(case_t), intent(inout) :: c                  !! the case, solved
        integer, intent(in) :: progress_unit              !! >= 0: each Newton step there
        character(len=warning_length), allocatable, intent(inout) :: warnings(:)  !! appended
        type(error_t), allocatable, intent(out) :: err    !! a finer solve failed, or no mesh
                                                          !! resolved the friction
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(model_t) :: finer
        type(case_t) :: next
        character(len=warning_length) :: text
        character(len=120) :: where
        real(dp) :: excess, allowance
        integer :: ne_deck, k
        ne_deck = c%model%mesh%ne
        excess = c%summary%admissibility
        allowance = c%summary%admissibility_tol
        doublings: do k = 1, max_doublings
            if (c%summary%admissibility <= c%summary%admissibility_tol .or. &
                2*c%model%mesh%ne > max_auto_elements) exit doublings
            finer = c%model
            finer%mesh%ne = 2*c%model%mesh%ne
            if (.not. fits(finer)) exit doublings
            call solve_case(finer, next, err, progress_unit, cache)
            c = next
            if (allocated(err)) exit doublings
        end do doublings
        if (c%model%mesh%ne == ne_deck) return
        write (where, '(a,i0,a,i0,a,i0)') 'friction not resolved pointwise on N_e = ', &
            ne_deck, ', mesh refined to N_e = ', c%model%mesh%ne
        if (allocated(err)) then
            call add_context(err, trim(where))
            return
        end if
        if (c%summary%admissibility > c%summary%admissibility_tol) then
            call require_admissible(c%summary, err)
            call add_context(err, trim(where))
            return
        end if
        write (text, '(a,i0,a,i0,a,es8.2,a,es8.2,a,i0,a)') 'mesh refined from N_e = ', &
            ne_deck, ' to ', c%model%mesh%ne, ': friction not resolved pointwise on the '// &
            'deck''s mesh (max(|Sigma_x| - f Sigma_z) ', excess, ' > allowed ', allowance, &
            '); results are for N_e = ', c%model%mesh%ne, ' (doc/CHOICES.md)'
        warnings = [character(len=warning_length) :: warnings, text]
    end subroutine refine_until_admissible

    !> Whether the finer case fits in the memory available now (the check before solving
    !! sized it on the deck's mesh; the other cases of a sweep running at the same time have
    !! taken theirs already).
    logical function fits(finer)
        type(model_t), intent(in) :: finer   !! the case on its finer mesh
        type(error_t), allocatable :: err
        call check_memory(finer, 1, memory_available(), err)
        fits = .not. allocated(err)
    end function fits

    !> A case whose tractions break the friction law beyond what the regularisation allows is
    !! no result (status 2), whatever the solver's own stopping rule said.
    subroutine require_admissible(s, err)
        type(summary_t), intent(in) :: s                  !! the case's design summary
        type(error_t), allocatable, intent(out) :: err    !! the check failed
        character(len=400) :: text
        if (s%admissibility <= s%admissibility_tol) return
        ! the solver holds the law in the Galerkin sense (its residual is checked before); a
        ! pointwise excess beyond the allowance is then a mesh too coarse for the slip
        ! (doc/CHOICES.md, very soft beams at eps_bar = 1e-12)
        write (text, &
            '(a,es10.3,a,es10.3,a)') 'the friction admissibility check failed: max(|Sigma_x| '// &
            '- f Sigma_z) = ', s%admissibility, ' exceeds the ', s%admissibility_tol, &
            ' the regularised law allows at the largest slip: the law holds on average over '// &
            'each traction function but is not resolved pointwise on this mesh: refine it'
        call new_error(err, EXIT_ANALYSIS, trim(text))
    end subroutine require_admissible
end module admissible_refinement
