!> bench_linalg: time per phase of the default (Newton) solve of one deck at several N_e
!! (doc/METHOD.md, Solution methods). Not a test: it measures.
!!
!!     OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
!!         fpm run --profile release --example bench_linalg -- \
!!         input/plate_nondim.dat 20 100 320 1000
!!
!! Phases (processor time, least of repeated runs for small cases): assembly of T; of K and M;
!! build_system (T, K, M and the base matrix); the whole solve_contact (build included), so
!! iterations = solve - build; the linear solves it counts; one dense factorisation (LDL^T or
!! LU of the complete n x n Jacobian, the path before the Schur complement) of the final system; the
!! set-up of the Schur complement onto the tractions (schur_solver: banded Cholesky of K_ii, S0) and
!! one factorisation of the final system's Schur complement (the path of every Newton step).
program bench_linalg
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t
    use discretization, only: discretization_t, new_discretization
    use deck_reader, only: deck_t, read_deck, case_model
    use contact_solver, only: solution_t, solve_contact
    use contact_system, only: system_t, contact_points_t, build_system, contact_points, &
                              complete_jacobian, point_tractions, set_terms_t, set_terms
    use schur_solver, only: schur_t, schur_factor_t, new_schur, schur_factorise
    use mindlin_structure, only: section_of, assemble_stiffness, assemble_coupling
    use halfspace_operator, only: assemble_flexibility
    use linear_solve, only: solve_equilibrated
    implicit none

    type(deck_t) :: deck
    type(model_t) :: m0, m
    type(error_t), allocatable :: err
    character(len=:), allocatable :: label
    character(len=512) :: path
    character(len=32) :: arg
    integer :: i, ne

    call start_program()
    call get_command_argument(1, path)
    call read_deck(trim(path), deck, err)
    if (allocated(err)) error stop 'cannot read the deck'
    call case_model(deck, 1, m0, label, err)
    if (allocated(err)) error stop 'cannot build the case'
    write (*, '(a)') '# deck: '//trim(path)
    write (*, '(a)') '|   N_e |     n |  nr | T s | K,M s | build s | solve_contact s | '// &
        'iterations s | solves | factorisations | dense final factorisation s | '// &
        'iterations / dense | '// &
        'Schur setup s (K_ii band, S0) | Schur final factorisation s | iterations / Schur |'
    write (*, '(a)') '|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|'
    do i = 2, command_argument_count()
        call get_command_argument(i, arg)
        read (arg, *) ne
        m = m0
        m%mesh%ne = ne
        call bench_one(m)
    end do

contains

    !> Processor time of the process (the machine is shared: wall time would also measure the
    !! other jobs); run with OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1.
    real(dp) function now()
        call cpu_time(now)
    end function now

    subroutine bench_one(m)
        type(model_t), intent(in) :: m
        type(discretization_t) :: d
        type(contact_points_t) :: pts
        type(system_t) :: sys
        type(solution_t) :: sol
        type(error_t), allocatable :: err
        real(dp), allocatable :: t_mat(:, :), k(:, :), mm(:, :), a(:, :), b(:), x(:)
        real(dp) :: t0, t_t, t_km, t_build, t_solve, t_fact, t_setup, t_schur
        type(schur_t) :: sc
        type(schur_factor_t) :: fac
        type(set_terms_t) :: st
        integer :: rep, n_rep
        logical :: symmetric
        call new_discretization(m, d, err)
        if (allocated(err)) error stop 'discretisation failed'
        n_rep = max(1, min(20, 4000/(m%mesh%ne*m%mesh%ne/100 + 1)))
        if (m%mesh%ne >= 320) n_rep = 1
        t_t = huge(1.0_dp); t_km = t_t; t_build = t_t; t_solve = t_t; t_fact = t_t
        t_setup = t_t; t_schur = t_t
        repeats: do rep = 1, n_rep
            t0 = now()
            call assemble_flexibility(m, d, t_mat, err)
            t_t = min(t_t, now() - t0)
            t0 = now()
            allocate (k(d%nv, d%nv), mm(d%nr, d%nv))
            call assemble_stiffness(section_of(m%structure), d, k)
            call assemble_coupling(m, d, mm)
            t_km = min(t_km, now() - t0)
            deallocate (k, mm, t_mat)
            t0 = now()
            pts = contact_points(m%structure, d)
            call build_system(m, d, pts, sys, err)
            t_build = min(t_build, now() - t0)
            t0 = now()
            call solve_contact(m, d, sol, err)
            t_solve = min(t_solve, now() - t0)
            if (allocated(err)) then
                write (*, '(a)') 'status 2: '//err%message
                return
            end if
            t0 = now()
            call complete_jacobian(d, sys, sys%law, pts, point_tractions(pts, sol%z), a, &
                                   symmetric)
            allocate (b(d%n), x(d%n))
            b = 1.0_dp
            call solve_equilibrated(a, b, x, symmetric, err)
            t_fact = min(t_fact, now() - t0)
            deallocate (a, b, x)
            t0 = now()
            call new_schur(d, sys, sc)
            t_setup = min(t_setup, now() - t0)
            if (.not. sc%ready) error stop 'the Schur complement is not ready'
            t0 = now()
            call set_terms(sys, sys%law, pts, point_tractions(pts, sol%z), st)
            call schur_factorise(sc, st, fac, err)
            t_schur = min(t_schur, now() - t0)
        end do repeats
        write (*, '(a,i6,a,i6,a,i5,a,f9.4,a,f9.4,a,f9.4,a,f9.4,a,f9.4,a,i4,a,i4,a,f9.4,a,f6.1,'// &
               'a,f9.4,a,f9.4,a,f6.1,a)') &
            '|', m%mesh%ne, '|', d%n, '|', d%nr, '|', t_t, '|', t_km, '|', t_build, '|', t_solve, &
            '|', t_solve - t_build, '|', sol%n_solves, '|', sol%n_factorisations, '|', &
            t_fact, '|', &
            (t_solve - t_build)/t_fact, '|', t_setup, '|', t_schur, '|', &
            (t_solve - t_build)/t_schur, '|'
    end subroutine bench_one
end program bench_linalg
