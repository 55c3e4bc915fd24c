!> The report's words on how a case was solved and how far its numbers can be trusted:
!! the simplifications of the solve (model_reduction), the error estimate's method
!! (error_estimate) and the adaptation's cycles (adaptive_solve). The solver and quality
!! modules decide; the wording of what they decided lives here, with the other outputs.
module method_notes
    use kinds, only: dp
    use model, only: model_t
    use discretization, only: discretization_t
    use model_reduction, only: reduction_t, plan_reduction, is_active
    use adaptive_solve, only: adaptation_t
    use error_estimate, only: min_estimate_elements
    implicit none
    private

    public :: simplification_text, error_method_text, adaptation_lines, no_estimate_reason

contains

    !> 'simplifications used: ..., saved N% of the unknowns' (or 'none'), and the settled
    !! lift-off tractions decoupled in the Newton factorisations (schur_solver), when the
    !! solution's decoupled (N, of M kept unknowns) says so.
    pure function simplification_text(m, d, decoupled) result(text)
        type(model_t), intent(in) :: m                  !! the model
        type(discretization_t), intent(in) :: d         !! the discretisation
        integer, intent(in), optional :: decoupled(2)   !! solution_t%decoupled
        character(len=:), allocatable :: text
        type(reduction_t) :: red
        character(len=120) :: saved
        red = plan_reduction(m, d)
        text = 'simplifications used: '
        saved = ''
        if (present(decoupled)) then
            if (decoupled(1) > 0) write (saved, '(a,i0,a,i0,a)') &
                'settled lift-off tractions decoupled in the factorisation (', decoupled(1), &
                ' of ', decoupled(2), ' kept unknowns)'
        end if
        if (.not. is_active(red)) then
            if (len_trim(saved) > 0) then
                text = text//trim(saved)//', the answer that of the full model'
            else
                text = text//'none (full model)'
            end if
            return
        end if
        if (len_trim(saved) > 0) text = text//trim(saved)//', '
        saved = ''

        if (red%frictionless .and. red%mean_shear) then
            text = text//'sigma_x reduced to its mean, 0 (f = 0, frictionless), '
        else if (red%frictionless) then
            text = text//'no sigma_x unknowns (f = 0, frictionless), '
        end if
        if (red%half) text = text//'half beam (symmetric geometry and vertical loads), '
        write (saved, '(a,f0.1,a,i0,a,i0,a)') 'saved ', &
            100.0_dp*real(red%n_full - red%n_reduced, dp)/real(red%n_full, dp), &
            '% of the unknowns (', red%n_reduced, ' of ', red%n_full, ' solved)'
        text = text//trim(saved)
    end function simplification_text

    !> One line for reports: how the estimate was obtained (adapted: on an adapted mesh).
    pure function error_method_text(adapted) result(text)
        logical, intent(in), optional :: adapted   !! the estimate is on an adapted mesh
        character(len=:), allocatable :: text
        if (present(adapted)) then
            if (adapted) then
                text = 'estimated error: the adapted mesh (N_e elements) coarsened twice by '// &
                    'removing every other node, keeping the ends, the load positions and the '// &
                    'snapped contact and slip boundaries (N2, N4 elements, r = N_e/N2); E = '// &
                    '1.25 |Q(N2) - Q(N_e)| / (r^p - 1) with the observed order p, or (p*) '// &
                    '3 max(|Q(N2) - Q(N_e)|, |Q(N4) - Q(N2)|/r)/(r - 1) where convergence is '// &
                    'not yet regular; contact extent at least the distance of its node from '// &
                    'the located boundary. Measured with ADAPT to tol 1e-3: 0.5 to 5 times '// &
                    'the true error for 62 % of 534 results, 11 % below 0.2 times (doc/'// &
                    'OUTPUT.md): an indication, not a bound'
                return
            end if
        end if
        text = 'estimated error: the case re-solved on its mesh with every element cut '// &
               'in two (Q_f) and with every other node removed (Q_c); E = max(1.25 |Q - Q_f| '// &
               '2^p/(2^p - 1), |Q_c - Q|/4) with the order p observed from the three, in [1, '// &
               '2] and at most the formal order (1 on a uniform mesh with an edge in contact), '// &
               'p* where p = 1 is assumed; contact extent at least half the element beyond it '// &
               '(at an end of the base, the end element); an extreme between two stations adds '// &
               'the excess of the parabola through its station and their neighbours, an '// &
               'extreme moment that is not established at least |M_opposite| + E_opposite, the '// &
               'settlement at a load inside an element its continuation from the nearer node; '// &
               'where N_e/4 shows the meshes short of the asymptotic range, E >= |Q_c - Q|; '// &
               'where a concentrated load lies inside the base or the mesh has more than 128 '// &
               'elements, E >= half the change to the meshes of N_e - 1 and N_e + 1 elements '// &
               '(same grading, the loads on nodes alike); on a mesh of at most 128 elements, E '// &
               '>= the change to the mesh cut in two twice (4 N_e); E >= 1e-6 |Q| (the digits '// &
               'the solution holds). Where the refined case does not fit in memory: the coarse '// &
               'meshes N_e/2, N_e/4 with Roache''s GCI. Measured: 0.5 to 5 times the true '// &
               'error for 93.4 % of 11335 results, none below 0.2 times (doc/OUTPUT.md)'
    end function error_method_text

    !> Why a case has no error estimate (report and HTML record): its mesh is too coarse
    !! (error_estimate, min_estimate_elements), a coarse or refined solve failed, or the run
    !! has --no-estimates.
    pure function no_estimate_reason() result(text)
        character(len=:), allocatable :: text
        character(len=8) :: n
        write (n, '(i0)') min_estimate_elements
        text = 'it needs N_e >= '//trim(n)//' (on coarser meshes the estimates were measured '// &
               'down to 0.03 of the error) and coarse and refined solves that converge, and is '// &
               'not made with --no-estimates'
    end function no_estimate_reason

    !> The report's lines on the adaptation.
    pure function adaptation_lines(info) result(lines)
        type(adaptation_t), intent(in) :: info   !! the adaptation's cycles and outcome
        character(len=400), allocatable :: lines(:)
        character(len=400) :: buf
        integer :: k
        allocate (lines(0))
        if (.not. info%adapted) return
        write (buf, '(a,es9.2,a,i0,a,i0,a,i0)') 'mesh adapted (ADAPT tol ', info%tol, &
            ', max_elements ', info%max_ne, '): ', info%cycles, ' cycles, final N_e = ', info%ne
        lines = [character(len=400) :: lines, buf]
        if (info%estimate >= 0.0_dp) then
            write (buf, '(a,es9.2,a)') 'largest estimated relative error ', info%estimate, &
                ' ('//info%worst//')'
        else
            buf = 'no error estimate on the final mesh (a coarsened mesh could not be solved)'
        end if
        lines = [character(len=400) :: lines, buf]
        if (info%reached) then
            lines = [character(len=400) :: lines, 'tolerance reached']
        else
            lines = [character(len=400) :: lines, 'TOLERANCE NOT REACHED: '//info%note]
        end if
        do k = 1, size(info%history_ne)
            if (info%history_estimate(k) >= 0.0_dp) then
                write (buf, '(a,i3,a,i6,a,es9.2)') 'cycle ', k, ': N_e = ', info%history_ne(k), &
                    ', estimate ', info%history_estimate(k)
            else
                write (buf, '(a,i3,a,i6,a)') 'cycle ', k, ': N_e = ', info%history_ne(k), &
                    ', not estimated (indicators from the previous cycle)'
            end if
            lines = [character(len=400) :: lines, buf]
        end do
    end function adaptation_lines
end module method_notes
