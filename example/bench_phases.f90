!> bench_phases: processor time of each phase of one case, from the deck to the written
!! report, at several N_e, with the fitted exponent p of time ~ N_e^p per phase (the
!! requirement: "a time breakdown by phase for N_e = 20, 100, 1000 with the fitted exponent of each
!! phase"). Not a test: it measures.
!!
!!     OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 fpm run --profile release \
!!         --example bench_phases [-- OUTDIR [N_e ...]]
!!
!! (default OUTDIR output/bench, N_e 20 50 100 200 500 1000). Cases: input/plate_nondim.dat
!! (frictional plate with lift-off) and input/beam_nondim.dat (frictional beam, H = 0.1 V),
!! N_e changed. Writes OUTDIR/phases_run.md (machine, load, tables; also echoed to standard
!! output), OUTDIR/phases.dat, OUTDIR/phases.gp and OUTDIR/phases.png.
!!
!! The solve is taken apart exactly as contact_solver::solve_contact does it for these cases
!! (Newton, no model reduction: the program stops otherwise), calling the same public
!! procedures in the same order, so that each phase is timed directly rather than inferred;
!! the whole solve_contact is also timed in the same repetition and its answer compared with
!! the replica's. No source under src/ is instrumented.
program bench_phases
    use deck_fields, only: int_text
    use iso_fortran_env, only: output_unit, compiler_version, compiler_options
    use kinds, only: dp
    use errors, only: error_t
    use start_up, only: start_program
    use model, only: model_t, METHOD_NEWTON
    use deck_reader, only: deck_t, read_deck, case_model
    use discretization, only: discretization_t, new_discretization
    use contact_solver, only: solution_t, solve_contact, check_load_admissible, nested_prediction, &
                              classify_complete, nested_discretisation
    use contact_system, only: system_t, build_system, contact_points, point_tractions, &
                              use_rigid_coordinates, set_terms_t, set_terms
    use rigid_body, only: to_absolute
    use newton_method, only: solve_newton
    use solution_checks, only: final_checks
    use model_reduction, only: plan_reduction, is_active
    use schur_solver, only: schur_t, schur_factor_t, new_schur, schur_factorise
    use mindlin_structure, only: section_of, stiffness_entries, coupling_entries
    use sparse_matrix, only: columns_t, compressed
    use halfspace_operator, only: assemble_flexibility
    use station_results, only: station_table_t, tabulate, tabulate_design, contact_extent
    use design_summary, only: summary_t, summarise
    use summary_table, only: entry_t, summary_entries
    use error_estimate, only: estimate_errors
    use solved_case, only: case_t, finish_case
    use case_files, only: case_result_t, write_case_files
    implicit none

    integer, parameter :: n_phase = 10
    integer, parameter :: P_DISC = 1, P_T = 2, P_KM = 3, P_SETUP = 4, P_NEWTON = 5, &
                          P_CHECKS = 6, P_TAB = 7, P_SUMMARY = 8, P_ESTIMATE = 9, P_WRITE = 10
    character(len=*), parameter :: phase_name(n_phase) = [character(len=30) :: &
        'discretisation', 'T assembly', 'K, M assembly', 'rest of system set-up (*)', &
        'Newton iterations', 'final checks', 'tabulation (stations)', 'design summary', &
        'error estimate', 'report writing']
    !> The exponent the algorithm should show for P1 fields (n ~ 5 N_e unknowns); the reasons
    !! are in the notes of phases_run.md (notes_lines).
    character(len=*), parameter :: expected(n_phase) = [character(len=14) :: '1', '2', &
        '1, then 2', '2', '2, then 3', '2', '1', '1', 'as tabulation', '1']
    !> Extra timings, each a separate call (not part of the phases' sum).
    integer, parameter :: n_info = 4
    integer, parameter :: I_BUILD = 1, I_SCHUR_SETUP = 2, I_SCHUR_FACT = 3, I_WHOLE = 4
    real(dp), parameter :: fit_floor = 1.0e-3_dp   !! s: phases faster than this are not fitted
    character(len=*), parameter :: decks(2) = [character(len=24) :: 'input/plate_nondim.dat', &
                                               'input/beam_nondim.dat']
    character(len=*), parameter :: case_title(2) = [character(len=80) :: &
        'PLATE: rho 0.01, zeta 0.1, f 0.5, central point load', &
        'BEAM: rho 0.0025, zeta 0.1, f 0.6, central point load, H = 0.1 V']

    !> The measurements of one case at each mesh.
    type :: case_times_t
        integer, allocatable :: ne(:), n(:), nr(:), solves(:), factorisations(:), reps(:)
        real(dp), allocatable :: t(:, :)       !! (n_phase, mesh): least over repetitions, s
        real(dp), allocatable :: info(:, :)    !! (n_info, mesh): least over repetitions, s
        real(dp), allocatable :: z_diff(:)     !! max |z replica - z solve_contact| / max |z|
    end type case_times_t

    character(len=256) :: out_dir
    integer, allocatable :: ne_list(:)
    type(case_times_t) :: res(2)
    character(len=64) :: load_start, load_end, start_time
    integer :: k, u

    call start_program()
    call read_arguments(out_dir, ne_list)
    call execute_command_line('mkdir -p '//trim(out_dir)//'/phases_tmp')
    start_time = time_stamp()
    load_start = load_average()
    do k = 1, 2
        call measure_case(trim(decks(k)), ne_list, trim(out_dir)//'/phases_tmp', res(k))
    end do
    load_end = load_average()
    call execute_command_line('rm -rf '//trim(out_dir)//'/phases_tmp')
    open (newunit=u, file=trim(out_dir)//'/phases_run.md', status='replace', action='write')
    call write_header(u, start_time, load_start, load_end)
    do k = 1, 2
        call write_case_tables(u, k, res(k))
    end do
    call write_notes(u)
    close (u)
    call write_figure(trim(out_dir), res)

contains

    !> OUTDIR and the meshes from the command line (defaults: output/bench; 20 ... 1000).
    subroutine read_arguments(out_dir, ne_list)
        character(len=*), intent(out) :: out_dir
        integer, allocatable, intent(out) :: ne_list(:)
        character(len=32) :: arg
        integer :: i
        out_dir = 'output/bench'
        if (command_argument_count() >= 1) call get_command_argument(1, out_dir)
        if (command_argument_count() < 2) then
            ne_list = [20, 50, 100, 200, 500, 1000]
            return
        end if
        allocate (ne_list(command_argument_count() - 1))
        do i = 2, command_argument_count()
            call get_command_argument(i, arg)
            read (arg, *) ne_list(i - 1)
        end do
    end subroutine read_arguments

    !> Processor time of the process: the machine is shared, and wall time would also count
    !! the other jobs (run with OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1).
    real(dp) function now()
        call cpu_time(now)
    end function now

    !> Repetitions at one mesh: at least 5 (the least is kept: the machine is shared), more
    !! while cheap, so that the millisecond phases of the small meshes are not a few noisy
    !! samples. About 75 s in all for the default meshes.
    pure integer function repetitions(ne)
        integer, intent(in) :: ne
        repetitions = max(5, min(20, 20000/(ne*ne/10 + 1)))
    end function repetitions

    !> Every mesh of one deck.
    subroutine measure_case(path, ne_list, tmp_dir, r)
        character(len=*), intent(in) :: path, tmp_dir
        integer, intent(in) :: ne_list(:)
        type(case_times_t), intent(out) :: r
        type(deck_t) :: deck
        type(model_t) :: m0, m
        type(error_t), allocatable :: err
        character(len=:), allocatable :: label
        integer :: i, nm
        call read_deck(path, deck, err)
        if (allocated(err)) error stop 'bench_phases: cannot read the deck'
        call case_model(deck, 1, m0, label, err)
        if (allocated(err)) error stop 'bench_phases: cannot build the case'
        nm = size(ne_list)
        r%ne = ne_list
        allocate (r%n(nm), r%nr(nm), r%solves(nm), r%factorisations(nm), r%reps(nm))
        allocate (r%t(n_phase, nm), r%info(n_info, nm), r%z_diff(nm))
        do i = 1, nm
            m = m0
            m%mesh%ne = ne_list(i)
            call measure_mesh(deck, m, label, tmp_dir, r, i)
            write (output_unit, '(a,i5,a,f8.3,a)') '# '//path//' N_e', m%mesh%ne, ': total', &
                sum(r%t(:, i)), ' s (least of repetitions)'
            flush (output_unit)
        end do
    end subroutine measure_case

    !> The least time of each phase over the repetitions at one mesh. The rest of the system
    !! set-up is build_system + use_rigid_coordinates less the separately timed T and K, M
    !! (the only phase obtained by a difference: build_system assembles T, K and M inside).
    subroutine measure_mesh(deck, m, label, tmp_dir, r, i)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: label, tmp_dir
        type(case_times_t), intent(inout) :: r
        integer, intent(in) :: i
        real(dp) :: t(n_phase), info(n_info)
        integer :: rep
        r%t(:, i) = huge(1.0_dp)
        r%info(:, i) = huge(1.0_dp)
        r%z_diff(i) = 0.0_dp
        r%reps(i) = repetitions(m%mesh%ne)
        do rep = 1, r%reps(i)
            call run_once(deck, m, label, tmp_dir, t, info, r, i)
            r%t(:, i) = min(r%t(:, i), t)
            r%info(:, i) = min(r%info(:, i), info)
        end do
        r%t(P_SETUP, i) = r%info(I_BUILD, i) - r%t(P_T, i) - r%t(P_KM, i)
    end subroutine measure_mesh

    !> One pass from the mesh to the written files, each phase timed; the counts and the
    !! comparison with solve_contact go into r at mesh i.
    subroutine run_once(deck, m, label, tmp_dir, t, info, r, i)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(in) :: m
        character(len=*), intent(in) :: label, tmp_dir
        real(dp), intent(out) :: t(n_phase), info(n_info)
        type(case_times_t), intent(inout) :: r
        integer, intent(in) :: i
        type(discretization_t) :: d
        type(system_t) :: sys
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(summary_t) :: s
        type(entry_t), allocatable :: e(:)
        real(dp) :: t0
        t0 = now()
        call discretise(m, d, sol)
        t(P_DISC) = now() - t0
        call time_assembly(m, d, t(P_T), t(P_KM))
        call time_solve(m, d, sys, sol, info(I_BUILD), t(P_NEWTON), t(P_CHECKS))
        call time_schur(d, sys, sol, info(I_SCHUR_SETUP), info(I_SCHUR_FACT))
        call time_results(m, d, sol, tab, s, e, t(P_TAB), t(P_SUMMARY), t(P_ESTIMATE))
        call write_files(deck, m, d, sol, e, label, tmp_dir, t(P_WRITE))
        call time_whole(m, d, sol, info(I_WHOLE), r%z_diff(i))
        r%n(i) = d%n
        r%nr(i) = d%nr
        r%solves(i) = sol%n_solves
        r%factorisations(i) = sol%n_factorisations
    end subroutine run_once

    !> Mesh, bases, numbering and the interface's Gauss points (and solve_contact's load
    !! admissibility check, O(loads)).
    subroutine discretise(m, d, sol)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(out) :: d
        type(solution_t), intent(out) :: sol
        type(error_t), allocatable :: err
        call new_discretization(m, d, err)
        if (allocated(err)) error stop 'bench_phases: discretisation failed'
        call check_load_admissible(m, err)
        if (allocated(err)) error stop 'bench_phases: the load is not admissible'
        sol%pts = contact_points(m%structure, d)
    end subroutine discretise

    !> T, and K with M, as build_system assembles them (K and M by their nonzeros: element
    !! triplets compressed into columns), each timed on its own with its allocation.
    subroutine time_assembly(m, d, t_t, t_km)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        real(dp), intent(out) :: t_t, t_km
        real(dp), allocatable :: t_mat(:, :)
        type(columns_t) :: k, mm
        type(error_t), allocatable :: err
        real(dp) :: t0
        t0 = now()
        call assemble_flexibility(m, d, t_mat, err)
        t_t = now() - t0
        if (allocated(err)) error stop 'bench_phases: T assembly failed'
        t0 = now()
        k = compressed(stiffness_entries(section_of(m%structure), d))
        mm = compressed(coupling_entries(m%structure, d))
        t_km = now() - t0
        if (k%ncol /= d%nv .or. mm%nrow /= d%nr) error stop 'bench_phases: K or M misshapen'
    end subroutine time_assembly

    !> contact_solver::solve_contact for a Newton case without model reduction, in its
    !! order: the system (build_system: T, K, M, packed B0, loads; then the
    !! change to rigid coordinates), the Newton iterations (nested_prediction: the solves on
    !! the nested coarser meshes, then solve_newton: Schur set-up, the start, the steps with their
    !! factorisations, updates, line searches and residuals, a continuation if it stalls), and the
    !! final checks (the complete problem's sets, residuals, equilibrium, admissibility; back to
    !! absolute coordinates).
    subroutine time_solve(m, d, sys, sol, t_build, t_newton, t_checks)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(system_t), intent(out) :: sys
        type(solution_t), intent(inout) :: sol
        real(dp), intent(out) :: t_build, t_newton, t_checks
        type(error_t), allocatable :: err
        real(dp), allocatable :: sigma_start(:, :), t_c(:, :)
        type(discretization_t) :: dc
        logical :: nest
        real(dp) :: t0
        if (m%solver%method /= METHOD_NEWTON .or. is_active(plan_reduction(m, d))) &
            error stop 'bench_phases: the replica covers Newton without model reduction only'
        t0 = now()
        allocate (sol%history(0))
        nest = nested_discretisation(m, d, dc)
        if (nest) then
            call build_system(m, d, sol%pts, sys, err, nested=dc, t_nested=t_c)
        else
            call build_system(m, d, sol%pts, sys, err)
        end if
        if (allocated(err)) error stop 'bench_phases: build_system failed'
        allocate (sol%z(d%n), sol%state(sol%pts%n), sol%sigma(2, sol%pts%n))
        allocate (sol%slip(sol%pts%n), sol%tension(sol%pts%n))
        call use_rigid_coordinates(sys)
        t_build = now() - t0
        t0 = now()
        if (nest) call nested_prediction(m, dc, t_c, sol, sigma_start)
        call solve_newton(m, d, sys, sol, err, sigma_start)
        t_newton = now() - t0
        if (allocated(err)) error stop 'bench_phases: the Newton solve failed'
        t0 = now()
        call classify_complete(m%interface, sol)
        call final_checks(m, d, sys, sol, err)
        sol%z = to_absolute(sys%rigid, sol%z)
        t_checks = now() - t0
        if (allocated(err)) error stop 'bench_phases: the final checks failed'
    end subroutine time_solve

    !> Two parts of the Newton iterations timed again on their own (they are inside
    !! solve_newton, which has no hook): the Schur set-up (banded Cholesky of K_ii, S0 on the
    !! kept unknowns) and one factorisation of the kept block at the final sets.
    subroutine time_schur(d, sys, sol, t_setup, t_fact)
        type(discretization_t), intent(in) :: d
        type(system_t), intent(in) :: sys
        type(solution_t), intent(in) :: sol
        real(dp), intent(out) :: t_setup, t_fact
        type(schur_t) :: sc
        type(schur_factor_t) :: fac
        type(set_terms_t) :: st
        type(error_t), allocatable :: err
        real(dp) :: t0
        t0 = now()
        call new_schur(d, sys, sc)
        t_setup = now() - t0
        if (.not. sc%ready) error stop 'bench_phases: the Schur complement is not ready'
        t0 = now()
        call set_terms(sys, sys%law, sol%pts, point_tractions(sol%pts, sol%z), st)
        call schur_factorise(sc, st, fac, err)
        t_fact = now() - t0
        if (allocated(err)) error stop 'bench_phases: Schur factorisation failed'
    end subroutine time_schur

    !> As the pipeline (solved_case::finish_case) and the quality layer
    !! (case_quality::solve_to_quality): the station and design tables, the design summary
    !! with its key results, and their error estimates (the case re-solved on N_e/2 and N_e/4).
    subroutine time_results(m, d, sol, tab, s, e, t_tab, t_summary, t_estimate)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(out) :: tab
        type(summary_t), intent(out) :: s
        type(entry_t), allocatable, intent(out) :: e(:)
        real(dp), intent(out) :: t_tab, t_summary, t_estimate
        type(error_t), allocatable :: err
        type(station_table_t) :: design
        real(dp) :: t0
        t0 = now()
        call tabulate(m, d, sol, tab, err)
        if (.not. allocated(err)) call tabulate_design(m, d, sol, tab, design, err)
        t_tab = now() - t0
        if (allocated(err)) error stop 'bench_phases: tabulate failed'
        t0 = now()
        s = summarise(m, sol, design)
        e = summary_entries(m, s, contact_extent(design, m%structure%length))
        t_summary = now() - t0
        t0 = now()
        call estimate_errors(m, d, e, sol%coarse, s%edge_in_contact, solution=sol)
        t_estimate = now() - t0
    end subroutine time_results

    !> The files of a solved case as the program writes them (case_files::write_case_files),
    !! into tmp_dir: the report, the data file (the CSV for physical decks), the JSON summary
    !! and the gnuplot script. Not the PNG: gnuplot is a child process, outside this
    !! process's time. The case's tables are made again outside the timed phase.
    subroutine write_files(deck, m, d, sol, e, label, tmp_dir, t_write)
        type(deck_t), intent(in) :: deck               !! the deck (echoed in the report)
        type(model_t), intent(in) :: m                 !! the case's model
        type(discretization_t), intent(in) :: d        !! its discretisation
        type(solution_t), intent(in) :: sol            !! its solution
        type(entry_t), intent(in) :: e(:)              !! key results with their estimates
        character(len=*), intent(in) :: label          !! the case's label
        character(len=*), intent(in) :: tmp_dir        !! where the files go
        real(dp), intent(out) :: t_write               !! time of the writing [s]
        type(case_t) :: c
        type(case_result_t) :: result
        type(error_t), allocatable :: err
        real(dp) :: t0
        call finish_case(m, d, sol, c, err)
        if (allocated(err)) error stop 'bench_phases: the case could not be tabulated'
        c%entries = e
        result%name = 'case'
        result%label = label
        result%message = ''
        result%entries = e
        allocate (result%warnings(0))
        t0 = now()
        call write_case_files(deck, c, tmp_dir//'/case', .false., result)
        t_write = now() - t0
        if (result%status /= 0) error stop 'bench_phases: writing the report failed'
    end subroutine write_files

    !> The whole solve_contact, for comparison with the sum of the replica's phases, and the
    !! largest difference of its answer from the replica's (relative to max |z|).
    subroutine time_whole(m, d, sol, t_whole, z_diff)
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        real(dp), intent(out) :: t_whole
        real(dp), intent(inout) :: z_diff
        type(solution_t) :: whole
        type(error_t), allocatable :: err
        real(dp) :: t0
        t0 = now()
        call solve_contact(m, d, whole, err)
        t_whole = now() - t0
        if (allocated(err)) error stop 'bench_phases: solve_contact failed'
        z_diff = max(z_diff, maxval(abs(whole%z - sol%z))/maxval(abs(sol%z)))
    end subroutine time_whole

    !> Least-squares slope of log t against log N_e over the meshes where t > fit_floor;
    !! used(i) says which; p is NaN (printed '-') with fewer than two such meshes.
    pure subroutine fit_exponent(ne, t, p, used)
        integer, intent(in) :: ne(:)
        real(dp), intent(in) :: t(:)
        real(dp), intent(out) :: p
        logical, intent(out) :: used(:)
        real(dp) :: x(size(ne)), y(size(ne)), xm, ym
        integer :: k
        used = t > fit_floor
        k = count(used)
        p = ieee_nan()
        if (k < 2) return
        x = log(real(ne, dp))
        y = log(max(t, tiny(1.0_dp)))
        xm = sum(x, mask=used)/k
        ym = sum(y, mask=used)/k
        p = sum((x - xm)*(y - ym), mask=used)/sum((x - xm)**2, mask=used)
    end subroutine fit_exponent

    !> The slope between the two largest meshes (both above fit_floor), else NaN.
    pure real(dp) function last_slope(ne, t) result(p)
        integer, intent(in) :: ne(:)
        real(dp), intent(in) :: t(:)
        integer :: k
        k = size(ne)
        p = ieee_nan()
        if (k < 2) return
        if (t(k - 1) <= fit_floor .or. t(k) <= fit_floor) return
        p = log(t(k)/t(k - 1))/log(real(ne(k), dp)/real(ne(k - 1), dp))
    end function last_slope

    !> The least-squares slope over every mesh, sub-millisecond ones included (timer-level
    !! noise and fixed overheads there: for the phases too fast for the fit).
    pure real(dp) function slope_all(ne, t) result(p)
        integer, intent(in) :: ne(:)
        real(dp), intent(in) :: t(:)
        real(dp) :: x(size(ne)), y(size(ne))
        p = ieee_nan()
        if (size(ne) < 2 .or. any(t <= 0.0_dp)) return
        x = log(real(ne, dp))
        y = log(t)
        p = sum((x - sum(x)/size(x))*(y - sum(y)/size(y)))/sum((x - sum(x)/size(x))**2)
    end function slope_all

    pure real(dp) function ieee_nan()
        use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
        ieee_nan = ieee_value(1.0_dp, ieee_quiet_nan)
    end function ieee_nan

    !> Title, machine, compiler, load, and how the numbers were obtained.
    subroutine write_header(u, start_time, load_start, load_end)
        integer, intent(in) :: u
        character(len=*), intent(in) :: start_time, load_start, load_end
        call put(u, '# Time per phase against N_e (bench_phases)')
        call put(u, '')
        call put(u, 'Run started '//trim(start_time)//'. Machine: '//cpu_model()// &
                 '; logical CPUs (/proc/cpuinfo): '//int_text(cpu_count())//'.')
        call put(u, 'Load average (/proc/loadavg: 1, 5, 15 min) before: '//trim(load_start)// &
                 '; after: '//trim(load_end)//'.')
        call put(u, 'Compiler: '//compiler_version()//'; options: '//compiler_options())
        call put(u, '')
        call put(u, 'Times: processor seconds of the process (cpu_time: user + system time, '// &
                 'page faults included), the least over the '// &
                 'repetitions (column reps), shown in ms. Threads: run with '// &
                 'OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1.')
        call put(u, 'Exponent p of time ~ N_e^p: least squares on log t against log N_e over '// &
                 'the meshes where the phase took more than 1 ms (listed); local p: the '// &
                 'slope between the two largest meshes; p, all meshes: the fit over every mesh '// &
                 '(for the phases below 1 ms: fixed overheads and timer-level noise there).')
    end subroutine write_header

    !> The phase table and the table of counts and cross-checks of one case.
    subroutine write_case_tables(u, k, r)
        integer, intent(in) :: u, k
        type(case_times_t), intent(in) :: r
        integer :: ip, nm
        nm = size(r%ne)
        call put(u, '')
        call put(u, '## '//trim(case_title(k))//' ('//trim(decks(k))//', N_e changed)')
        call put(u, '')
        call put(u, '| phase |'//join_ne(r%ne, &
            ' ms |')//' fitted p | fitted on N_e | local p | '// &
                 'p, all meshes | expected p | share at N_e = '//int_text(r%ne(nm))//' |')
        call put(u, '|---|'//repeat('---:|', nm)//'---:|---|---:|---:|---|---:|')
        do ip = 1, n_phase
            call put(u, phase_row(phase_name(ip), r%t(ip, :), r%ne, expected(ip), &
                                  r%t(ip, nm)/sum(r%t(:, nm))))
        end do
        call put(u, phase_row('**total**', sum(r%t, dim=1), r%ne, '', 1.0_dp))
        call put(u, '')
        call put(u, '| N_e | n | nr | reps | linear solves | factorisations | '// &
                 'Schur set-up ms | one Schur factorisation ms | whole solve_contact ms | '// &
                 'replica (set-up to checks) ms | max rel. diff. of z | '// &
                 'solve / one linear solve | '// &
                 'solve / one factorisation |')
        call put(u, '|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
        do ip = 1, nm
            call put(u, count_row(r, ip))
        end do
        call write_targets(u, r)
    end subroutine write_case_tables

    !> The solver's performance targets at each mesh, as read in doc/CHOICES.md ("The solver's
    !! performance targets"): T under 10 % of the case (item 3); the solve without T at most 3 times
    !! one linear solve of the final system from scratch (Schur set-up + factorisation; item 2); the
    !! whole solve_contact under 5 ms at N_e = 20 and under 2 s at N_e = 1000 (item 2).
    subroutine write_targets(u, r)
        integer, intent(in) :: u
        type(case_times_t), intent(in) :: r
        character(len=:), allocatable :: share_row, ratio_row, time_row
        character(len=16) :: buf
        real(dp) :: share, ratio
        integer :: i
        share_row = '| T share of the case < 10 % (item 3) |'
        ratio_row = '| solve / one linear solve <= 3 (item 2) |'
        time_row = '| whole solve_contact < 5 ms (N_e 20), < 2 s (N_e 1000) (item 2) |'
        do i = 1, size(r%ne)
            share = r%t(P_T, i)/sum(r%t(:, i))
            write (buf, '(f5.1," %")') 100.0_dp*share
            share_row = share_row//' '//trim(adjustl(buf))//' '//verdict(share < 0.1_dp)//' |'
            ratio = solve_ratio(r, i)
            write (buf, '(f5.1)') ratio
            ratio_row = ratio_row//' '//trim(adjustl(buf))//' '//verdict(ratio <= 3.0_dp)//' |'
            select case (r%ne(i))
            case (20)
                time_row = time_row//' '//ms(r%info(I_WHOLE, i))//' ms '// &
                           verdict(r%info(I_WHOLE, i) < 5.0e-3_dp)//' |'
            case (1000)
                time_row = time_row//' '//ms(r%info(I_WHOLE, i))//' ms '// &
                           verdict(r%info(I_WHOLE, i) < 2.0_dp)//' |'
            case default
                time_row = time_row//' - |'
            end select
        end do
        call put(u, '')
        call put(u, '| target |'//join_ne(r%ne, ' |'))
        call put(u, '|---|'//repeat('---:|', size(r%ne)))
        call put(u, share_row)
        call put(u, ratio_row)
        call put(u, time_row)
    end subroutine write_targets

    !> The target "total solve time against one factorisation of the final system" at mesh i:
    !! the solve is the case less the discretisation and T (item 3 times T on its own); one
    !! linear solve of the final system from scratch is the Schur set-up plus one factorisation.
    pure real(dp) function solve_ratio(r, i)
        type(case_times_t), intent(in) :: r
        integer, intent(in) :: i
        solve_ratio = sum(r%t(P_KM:P_CHECKS, i))/ &
                      (r%info(I_SCHUR_SETUP, i) + r%info(I_SCHUR_FACT, i))
    end function solve_ratio

    !> 'met' or 'NOT met'.
    pure function verdict(met) result(text)
        logical, intent(in) :: met
        character(len=:), allocatable :: text
        text = merge('met    ', 'NOT met', met)
        text = trim(text)
    end function verdict

    !> '| name | t1 | t2 | ... | p | N_e used | local p | expected | share |'
    function phase_row(name, t, ne, expect, share) result(line)
        character(len=*), intent(in) :: name, expect
        real(dp), intent(in) :: t(:), share
        integer, intent(in) :: ne(:)
        character(len=:), allocatable :: line
        logical :: used(size(ne))
        real(dp) :: p
        integer :: i
        character(len=16) :: buf
        call fit_exponent(ne, t, p, used)
        line = '| '//trim(name)//' |'
        do i = 1, size(t)
            line = line//' '//ms(t(i))//' |'
        end do
        line = line//' '//exponent_text(p)//' | '//used_list(ne, used)//' | '// &
               exponent_text(last_slope(ne, t))//' | '//exponent_text(slope_all(ne, t))// &
               ' | '//trim(expect)//' |'
        write (buf, '(f6.1,a)') 100.0_dp*share, ' %'
        line = line//' '//trim(adjustl(buf))//' |'
    end function phase_row

    !> Unknowns, repetitions, solver counts, the Schur parts and the cross-check at mesh i.
    function count_row(r, i) result(line)
        type(case_times_t), intent(in) :: r
        integer, intent(in) :: i
        character(len=:), allocatable :: line
        character(len=16) :: buf, ratios
        real(dp) :: replica
        replica = sum(r%t(P_DISC:P_CHECKS, i))
        write (buf, '(es9.1)') r%z_diff(i)
        write (ratios, '(f5.1," | ",f5.1)') solve_ratio(r, i), &
            sum(r%t(P_KM:P_CHECKS, i))/r%info(I_SCHUR_FACT, i)
        line = '| '//int_text(r%ne(i))//' | '//int_text(r%n(i))//' | '//int_text(r%nr(i))//' | '// &
               int_text(r%reps(i))//' | '//int_text(r%solves(i))//' | '// &
                   int_text(r%factorisations(i))// &
               ' | '//ms(r%info(I_SCHUR_SETUP, i))//' | '//ms(r%info(I_SCHUR_FACT, i))//' | '// &
               ms(r%info(I_WHOLE, i))//' | '//ms(replica)//' | '//trim(adjustl(buf))//' | '// &
               trim(ratios)//' |'
    end function count_row

    !> What each phase includes and why the expected exponent is what it is.
    subroutine write_notes(u)
        integer, intent(in) :: u
        integer :: i
        character(len=*), parameter :: lines(*) = [character(len=100) :: &
            '', &
            'Phases (the solve replicates contact_solver::solve_contact call by call):', &
            '', &
            '- discretisation: new_discretization (mesh, bases, numbering), the load', &
            '  admissibility check, contact_points (Gauss points of the interface). Expected 1.', &
            '- T assembly: assemble_flexibility, the dense nr x nr half-space flexibility;', &
            '  nr^2/2 pairs of element integrals of the kernels (plate, N_e >= 128: far', &
            '  clusters of element pairs as interpolated blocks). Expected 2 (the dense T).', &
            '- K, M assembly: stiffness_entries and coupling_entries (element triplets),', &
            '  compressed into sparse columns as build_system does. Expected 1.', &
            '- rest of system set-up (*): build_system + use_rigid_coordinates, less the T and', &
            '  K, M times measured on their own (build_system assembles T, K and M inside it);', &
            '  the stick terms on T, the packing of B0 = -(T + c eps S0) into its lower', &
            '  triangle, M^T, loads, the row scaling, the rigid-coordinate change of K and M;', &
            '  N_e > 48: the restriction P^T T P of T to the nested coarser mesh', &
            '  (nested_spaces).', &
            '  Expected 2 (the packing of the dense block, the restriction).', &
            '- Newton iterations: nested_prediction (N_e > 48: the case on the nested coarser', &
            '  mesh, recursively, its T restricted, not assembled, for the start) and', &
            '  solve_newton. The Schur set-up (banded Cholesky of K_ii,', &
            '  O(N_e); S0 = J_kk - C^T K_ii^-1 C: nk band solves, O(N_e^2)), the adhesive start,', &
            '  each step: set terms, a dense LDL^T/LU of the nk x nk kept block (nk ~ 2 N_e,', &
            '  O(N_e^3)) or a Woodbury update, solves and refinement with the dense T block', &
            '  (O(N_e^2)), line search residuals (O(N_e^2)). Expected 2 at small N_e, 3 in the', &
            '  limit (3 or 4 factorisations of nk^3/3 flops each); the step count grows slowly.', &
            '- final checks: the sets of the complete problem, the residuals of 4.2a/b (products', &
            '  with the packed B0 block), equilibrium, admissibility, to_absolute. Expected 2.', &
            '- tabulation (stations): station_results::tabulate at the N_e + 1 node stations;', &
            '  the half-space surface displacement at each station: the near elements by their', &
            '  line rules, far clusters of elements by Chebyshev interpolation (a cluster tree).', &
            '  Expected about 1 (N_e log N_e).', &
            '- design summary: summarise, summary_entries, contact_extent: O(stations). '// &
                'Expected 1.', &
            '- error estimate: error_estimate::estimate_errors, the case discretised, solved and', &
            '  tabulated on N_e/2 and N_e/4; above N_e = 48 the solves are those of the nested', &
            '  start, reused, and only the tabulations remain. Expected: as the tabulation.', &
            '- report writing: the report, data file, JSON summary and gnuplot script of', &
            '  analysis_driver::write_case_files written to a temporary folder (NONDIM decks: no', &
            '  CSV). Without the PNG: gnuplot runs as a child process, not in this process''s', &
            '  time. O(stations). Expected 1.', &
            '', &
            '(*) the only phase obtained by a difference (least build time less least T and K, M', &
            'times): noisy where T dominates it. The second table times, as separate calls that', &
            'are not in the sum, the Schur set-up and one Schur factorisation of the final sets', &
            '(both inside the Newton iterations), and the whole solve_contact; the replica '// &
                'column', &
            'is the sum of the phases discretisation to final checks; max rel. diff. of z: the', &
            'replica''s answer against solve_contact''s. solve / one linear solve: the phases', &
            'K, M assembly to final checks (the case''s solve without T, which item 3 times)', &
            'over the Schur set-up plus one Schur factorisation (what one linear solve of the', &
            'final system costs from scratch); solve / one factorisation: the same over the', &
            'factorisation alone.']
        do i = 1, size(lines)
            call put(u, trim(lines(i)))
        end do
    end subroutine write_notes

    !> OUTDIR/phases.dat (one index block per case: N_e, each phase, total, in s; '?' where a
    !! phase took no measurable time or, the difference, came out negative), phases.gp, and
    !! phases.png drawn by gnuplot.
    subroutine write_figure(out_dir, r)
        character(len=*), intent(in) :: out_dir
        type(case_times_t), intent(in) :: r(2)
        integer :: u, k, i, k2
        open (newunit=u, file=out_dir//'/phases.dat', status='replace', action='write')
        do k = 1, 2
            write (u, '(a)') '# '//trim(case_title(k))//': N_e, then s per phase '// &
                '(discretisation, T, K M, rest of set-up, Newton, checks, tabulation, '// &
                'summary, estimate, writing), total'
            do i = 1, size(r(k)%ne)
                write (u, '(i6,*(1x,a))') r(k)%ne(i), (dat_value(r(k)%t(:, i), k2), &
                    k2=1, n_phase), dat_value([sum(r(k)%t(:, i))], 1)
            end do
            write (u, '(/)')
        end do
        close (u)
        call write_gp(out_dir, maxval(r(1)%ne))
        call execute_command_line('gnuplot '//out_dir//'/phases.gp')
    end subroutine write_figure

    !> One value of phases.dat: seconds, or '?' (gnuplot's missing value) when not positive.
    function dat_value(t, k) result(text)
        real(dp), intent(in) :: t(:)
        integer, intent(in) :: k
        character(len=:), allocatable :: text
        character(len=16) :: buf
        text = '?'
        if (t(k) <= 0.0_dp) return
        write (buf, '(es11.4)') t(k)
        text = trim(adjustl(buf))
    end function dat_value

    !> Two panels (plate, beam) of log time against log N_e, one line per phase and the total,
    !! the 1 ms floor of the fits dashed; one legend at the right, outside both panels.
    subroutine write_gp(out_dir, ne_max)
        character(len=*), intent(in) :: out_dir
        integer, intent(in) :: ne_max
        character(len=*), parameter :: colour(n_phase) = [character(len=7) :: '#1f77b4', &
            '#ff7f0e', '#2ca02c', '#d62728', '#9467bd', '#8c564b', '#e377c2', '#7f7f7f', &
            '#bcbd22', '#17becf']
        character(len=*), parameter :: margins(2) = [character(len=80) :: &
            'set lmargin at screen 0.06; set rmargin at screen 0.39', &
            'set lmargin at screen 0.45; set rmargin at screen 0.78']
        integer :: u, k, ip
        open (newunit=u, file=out_dir//'/phases.gp', status='replace', action='write')
        write (u, '(a)') '# bench_phases: run from the project folder: gnuplot '//out_dir// &
            '/phases.gp'
        write (u, '(a)') "set terminal pngcairo size 1500,620 font 'Sans,11' noenhanced"
        write (u, '(a)') "set output '"//out_dir//"/phases.png'"
        write (u, '(a)') "set datafile missing '?'"
        write (u, '(a)') "set multiplot title 'fricon: processor time per phase against "// &
            "N_e (P1, least of repetitions, 1 thread)' font 'Sans,14'"
        write (u, '(a)') 'set logscale xy; set grid; set format y "%.0e"'
        write (u, '(a)') 'set xrange [15:'//int_text(nint(1.3*ne_max))//']; set yrange [1e-6:30]'
        write (u, '(a)') "set xtics (20, 50, 100, 200, 500, 1000, 2000)"
        write (u, '(a)') "set xlabel 'N_e (elements; n = 5 N_e + 5 unknowns)'"
        write (u, '(a)') "set ylabel 'processor time [s]'"
        write (u, '(a)') 'set tmargin at screen 0.88; set bmargin at screen 0.12'
        do k = 1, 2
            write (u, '(a)') trim(margins(k))
            if (k == 1) write (u, '(a)') 'unset key'
            if (k == 2) write (u, '(a)') "set key at screen 0.80, 0.88 left top box opaque "// &
                "title 'phase'"
            write (u, '(a)') "set title '"//trim(case_title(k))//"'"
            write (u, '(a)', advance='no') 'plot '
            do ip = 1, n_phase
                write (u, '(a)', advance='no') "'"//out_dir//"/phases.dat' index "// &
                    int_text(k - 1)//' using 1:'//int_text(ip + 1)//" with linespoints lw 2 pt "// &
                    int_text(ip + 3)//" lc rgb '"//colour(ip)//"' title '"// &
                    trim(phase_name(ip))//"', "
            end do
            write (u, '(a)') "'"//out_dir//"/phases.dat' index "//int_text(k - 1)//' using 1:'// &
                int_text(n_phase + 2)// &
                    " with linespoints lw 3 pt 7 lc rgb 'black' title 'total', "// &
                "1e-3 with lines dt 2 lc rgb 'gray40' title '1 ms (fit floor)'"
        end do
        write (u, '(a)') 'unset multiplot'
        close (u)
    end subroutine write_gp

    !> A time in ms, about three significant digits.
    function ms(t) result(text)
        real(dp), intent(in) :: t
        character(len=:), allocatable :: text
        character(len=16) :: buf
        real(dp) :: x
        x = 1000.0_dp*t
        if (x >= 100.0_dp) then
            write (buf, '(f10.0)') x
            buf = buf(1:len_trim(buf) - 1)     ! no trailing point
        else if (x >= 10.0_dp) then
            write (buf, '(f10.1)') x
        else if (x >= 1.0_dp) then
            write (buf, '(f10.2)') x
        else
            write (buf, '(f10.3)') x
        end if
        text = trim(adjustl(buf))
    end function ms

    function exponent_text(p) result(text)
        real(dp), intent(in) :: p
        character(len=:), allocatable :: text
        character(len=16) :: buf
        text = '-'
        if (p /= p) return
        write (buf, '(f6.2)') p
        text = trim(adjustl(buf))
    end function exponent_text

    !> The meshes a fit used, e.g. '100-1000' when they are consecutive, else a list.
    function used_list(ne, used) result(text)
        integer, intent(in) :: ne(:)
        logical, intent(in) :: used(:)
        character(len=:), allocatable :: text
        integer :: i, first, last
        text = '-'
        if (count(used) < 2) return
        first = findloc(used, .true., dim=1)
        last = findloc(used, .true., dim=1, back=.true.)
        if (all(used(first:last))) then
            text = int_text(ne(first))//'-'//int_text(ne(last))
            return
        end if
        text = ''
        do i = 1, size(ne)
            if (used(i)) text = text//','//int_text(ne(i))
        end do
        text = text(2:)
    end function used_list

    function join_ne(ne, suffix) result(text)
        integer, intent(in) :: ne(:)
        character(len=*), intent(in) :: suffix
        character(len=:), allocatable :: text
        integer :: i
        text = ''
        do i = 1, size(ne)
            text = text//' N_e '//int_text(ne(i))//suffix
        end do
    end function join_ne


    !> A line to the file and to standard output.
    subroutine put(u, line)
        integer, intent(in) :: u
        character(len=*), intent(in) :: line
        write (u, '(a)') line
        write (output_unit, '(a)') line
    end subroutine put

    function time_stamp() result(text)
        character(len=64) :: text
        character(len=8) :: date
        character(len=10) :: time
        character(len=5) :: zone
        call date_and_time(date, time, zone)
        text = date(1:4)//'-'//date(5:6)//'-'//date(7:8)//' '//time(1:2)//':'//time(3:4)// &
               ':'//time(5:6)//' '//zone
    end function time_stamp

    !> The first line of /proc/loadavg (Linux), or 'unknown'.
    function load_average() result(text)
        character(len=64) :: text
        integer :: u, ios
        text = 'unknown'
        open (newunit=u, file='/proc/loadavg', status='old', action='read', iostat=ios)
        if (ios /= 0) return
        read (u, '(a)', iostat=ios) text
        close (u)
        if (ios /= 0) text = 'unknown'
    end function load_average

    !> The 'model name' of /proc/cpuinfo, or 'unknown'.
    function cpu_model() result(text)
        character(len=:), allocatable :: text
        character(len=256) :: line
        integer :: u, ios
        text = 'unknown'
        open (newunit=u, file='/proc/cpuinfo', status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'model name') == 1) then
                text = trim(adjustl(line(index(line, ':') + 1:)))
                exit
            end if
        end do
        close (u)
    end function cpu_model

    !> The 'processor' entries of /proc/cpuinfo (0 if it cannot be read).
    integer function cpu_count() result(n)
        character(len=256) :: line
        integer :: u, ios
        n = 0
        open (newunit=u, file='/proc/cpuinfo', status='old', action='read', iostat=ios)
        if (ios /= 0) return
        do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit
            if (index(line, 'processor') == 1) n = n + 1
        end do
        close (u)
    end function cpu_count
end program bench_phases
