!> Runs a whole deck: validates every case first, then solves each case on its own (a failed
!! case does not stop the others) and writes its report, data, gnuplot script and PNG.
module analysis_driver
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use errors, only: error_t, new_error, add_context, EXIT_OK, EXIT_INPUT, EXIT_ANALYSIS
    use model, only: model_t, MODEL_BEAM, relative_stiffness, METHOD_TWOLOOP
    use deck_reader, only: deck_t, case_count, case_model
    use discretization, only: discretization_t, new_discretization, loads_on_nodes
    use contact_solver, only: solution_t, solve_contact
    use station_results, only: station_table_t, tabulate, tabulate_design, contact_extent
    use design_summary, only: summary_t, summarise
    use summary_table, only: entry_t, summary_entries, entry_keys
    use report_writer, only: write_data_file, write_physical_csv, write_summary_json, &
                             write_plot_script, write_sweep_script, write_report, shell_safe
    use atomic_files, only: open_temporary, commit_file
    use temporary_cleanup, only: register_temporary, release_temporary
    use plausibility, only: warning_length, input_warnings, settlement_warnings, &
                            tension_warnings
    use error_estimate, only: estimate_errors
    use adaptive_solve, only: adaptation_t, solve_adaptive
    use output_paths, only: prepare_output_dir, check_deck_not_overwritten, case_name, &
                            case_number, remove_stale_outputs, remove_output, canonical_path, &
                            remove_shard_summaries, remove_sweep_outputs
    use blas_threads, only: set_blas_threads, blas_thread_count
    use flexibility_cache, only: enable_flexibility_cache
    use resource_limits, only: check_memory, memory_available, case_memory, time_needed, &
                               case_unknowns
    implicit none
    private

    !> Key results of one case, for the console and the sweep summary.
    type, public :: case_result_t
        character(len=:), allocatable :: name, label, message
        integer :: status = EXIT_OK
        real(dp) :: rho = 0.0_dp
        real(dp) :: mean_pressure = 0.0_dp         !! V / contact area [F/L^2] (figures)
        integer :: n_outer = 0, n_inner = 0
        integer :: elements = 0                    !! N_e of the mesh solved (refined, adapted)
        type(entry_t), allocatable :: entries(:)   !! key results (summary_table); solved only
        type(adaptation_t) :: adaptation           !! what ADAPT did (adapted false without it)
        character(len=warning_length), allocatable :: warnings(:)  !! plausibility (deck, result)
    end type case_result_t

    !> How a run behaves (command-line options).
    type, public :: run_options_t
        logical :: figures = .true.     !! run gnuplot (the .gp is always written)
        logical :: progress = .false.   !! progress on the error unit: case i of n, time left
        integer :: threads = 0          !! cases solved at once (0: all cores)
        logical :: estimates = .true.   !! error estimates (two coarser solves per case)
        logical :: full_model = .false. !! no simplifications (model_reduction)
        integer :: shard_index = 1      !! solve cases shard_index, +shard_count, ... only
        integer :: shard_count = 1
    end type run_options_t

    public :: run_analysis, solve_case

contains

    !> Solve every case of the deck (or, with a shard, every n-th); `status` is the worst exit
    !! status of all cases. Every case is validated, the output folder proved writable and the
    !! deck checked against being overwritten before anything is solved. The cases of a sweep
    !! run in parallel (OpenMP, one case per thread, each with single-threaded BLAS); a case's
    !! result does not depend on the thread that solved it, and the console lines, files and
    !! summary rows come in case order.
    subroutine run_analysis(deck, out_dir, log_unit, err_unit, status, options)
        type(deck_t), intent(in) :: deck
        character(len=*), intent(in) :: out_dir    !! e.g. 'output'
        integer, intent(in) :: log_unit            !! where each case's outcome is written
        integer, intent(in) :: err_unit            !! errors, warnings and progress
        integer, intent(out) :: status
        type(run_options_t), intent(in), optional :: options
        type(run_options_t) :: opt
        integer(int64) :: clock_start
        type(model_t), allocatable :: cases(:)
        character(len=200), allocatable :: labels(:)
        type(case_result_t), allocatable :: results(:)
        logical, allocatable :: selected(:)
        type(error_t), allocatable :: err
        integer :: i, n, done, threads, blas_before, big_case_unit
        character(len=:), allocatable :: label

        n = case_count(deck)
        allocate (cases(n), labels(n), results(n))
        status = EXIT_OK
        validate: do i = 1, n
            call case_model(deck, i, cases(i), label, err)
            labels(i) = 'case '//case_number(i, n)//' of '//case_number(n, n)
            if (len(label) > 0) labels(i) = trim(labels(i))//': '//label
            if (allocated(err)) then
                write (err_unit, '(a)') 'ERROR: '//err%message
                status = EXIT_INPUT
                deallocate (err)
            end if
        end do validate
        if (status /= EXIT_OK) then
            ! exit 1 writes no output, and leaves none of an earlier run of this deck
            if (deck%from_file) call remove_stale_outputs(out_dir, deck%stem, 0, deck%path)
            return
        end if
        if (present(options)) opt = options
        if (opt%full_model) cases(:)%simplify = .false.
        call prepare_output_dir(out_dir, err)
        if (.not. allocated(err)) call check_deck_not_overwritten(deck%path, out_dir, deck%stem, &
                                                                  n, err)
        if (allocated(err)) then
            write (err_unit, '(a)') 'ERROR: '//err%message
            status = err%code
            return
        end if
        selected = [(mod(i - 1, opt%shard_count) == opt%shard_index - 1, i=1, n)]
        threads = thread_count(opt%threads, count(selected))
        call fit_memory(cases, selected, threads, err)
        if (allocated(err)) then
            write (err_unit, '(a)') 'ERROR: '//deck%path//': '//err%message
            ! (a machine too small now is no fault of the deck: earlier results, and those of
            ! the other shards of a job array, stay)
            status = err%code
            return
        end if
        ! a single case that takes a while: its size first, then each Newton step
        big_case_unit = -1
        if (opt%progress .and. n == 1) then
            call announce_size(err_unit, deck%stem, cases(1))
            if (time_needed(case_unknowns(cases(1))) >= 2.0_dp) big_case_unit = err_unit
        end if
        ! every case uses single-threaded BLAS, a single case too: the summation order, and so
        ! every digit, is then the same in serial, parallel and sharded runs and on any number
        ! of cores (a single plate case printed other last digits on two BLAS threads); on two
        ! cores OpenBLAS's threads saved 4 to 10 % at N_e = 1000 only, and nothing measurable
        ! below (output/bench/blas_threads.md)
        blas_before = blas_thread_count()
        call set_blas_threads(1)
        ! a sweep's cases on one mesh share T (flexibility_cache); one case holds no extra copy
        call enable_flexibility_cache(count(selected) > 1)
        call system_clock(clock_start)
        done = 0
        !$omp parallel do schedule(dynamic, 1) num_threads(threads) default(shared) private(i)
        cases_loop: do i = 1, n
            if (.not. selected(i)) cycle cases_loop
            call solve_case(deck, cases(i), trim(labels(i)), out_dir, case_name(deck%stem, i, n), &
                            opt%figures, opt%estimates, big_case_unit, results(i))
            !$omp critical (fricon_progress)
            done = done + 1
            if (opt%progress) call report_progress(err_unit, done, count(selected), &
                                                   results(i)%name, clock_start)
            !$omp end critical (fricon_progress)
        end do cases_loop
        !$omp end parallel do
        call enable_flexibility_cache(.false.)
        call set_blas_threads(blas_before)
        do i = 1, n
            if (selected(i)) call report_case(log_unit, err_unit, deck%path, out_dir, results(i), &
                                              status)
        end do
        if (n > 1) call write_sweep_outputs(out_dir, deck%stem, cases, results, selected, opt, err)
        if (allocated(err)) then
            write (err_unit, '(a)') 'ERROR: '//err%message
            status = max(status, err%code)
        end if
        ! what an earlier run of this deck wrote and this one did not (a longer sweep, a sweep
        ! where there is now one case, or one case where there is now a sweep)
        if (deck%from_file) call remove_stale_outputs(out_dir, deck%stem, n, deck%path)
    end subroutine run_analysis

    !> Refuse (exit status 1) a case that alone needs more memory than the machine has; solve
    !! fewer cases at once when the memory does not hold `threads` of the largest.
    subroutine fit_memory(cases, selected, threads, err)
        type(model_t), intent(in) :: cases(:)
        logical, intent(in) :: selected(:)
        integer, intent(inout) :: threads
        type(error_t), allocatable, intent(out) :: err
        real(dp) :: available, largest
        integer :: i
        available = memory_available()
        largest = 0.0_dp
        do i = 1, size(cases)
            if (.not. selected(i)) cycle
            call check_memory(cases(i), 1, available, err)
            if (allocated(err)) then
                call add_context(err, 'case '//case_number(i, size(cases)))
                return
            end if
            largest = max(largest, case_memory(cases(i)))
        end do
        threads = max(1, min(threads, int(0.8_dp*available/max(largest, 1.0_dp))))
    end subroutine fit_memory

    !> A case large enough to take a while: its size and rough time and memory on stderr.
    subroutine announce_size(unit, name, m)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: name
        type(model_t), intent(in) :: m
        integer :: n
        n = case_unknowns(m)
        if (time_needed(n) < 2.0_dp) return
        write (unit, '(a,i0,a,f0.1,a)') 'fricon: '//name//': ', n, ' unknowns, about '// &
            seconds(time_needed(n))//' and ', &
            case_memory(m)/1.0e9_dp, ' GB (rough estimates)'
        flush (unit)
    end subroutine announce_size

    !> Threads for the case loop: the --jobs option, else OpenMP's default (all cores), never
    !! more than the cases.
    integer function thread_count(jobs, n_cases) result(threads)
        !$ use omp_lib, only: omp_get_max_threads
        integer, intent(in) :: jobs, n_cases
        threads = 1
        !$ threads = omp_get_max_threads()
        if (jobs > 0) threads = jobs
        threads = max(1, min(threads, n_cases))
    end function thread_count

    !> The console line (or error) and the warnings of one case; status: the worst so far.
    subroutine report_case(log_unit, err_unit, deck_path, out_dir, r, status)
        integer, intent(in) :: log_unit, err_unit
        character(len=*), intent(in) :: deck_path, out_dir
        type(case_result_t), intent(in) :: r
        integer, intent(inout) :: status
        integer :: k
        if (r%status == EXIT_OK) then
            write (log_unit, '(a)') r%name//': solved  '//console_summary(r%entries)// &
                '  -> '//out_dir//'/'//r%name//'.txt'
        else
            write (err_unit, '(a)') 'ERROR: '//r%name//' ('//deck_path//'): '//r%message
        end if
        if (len(r%message) > 0 .and. r%status == EXIT_OK) &
            write (err_unit, '(a)') 'WARNING: '//r%name//': '//r%message
        do k = 1, size(r%warnings)
            write (err_unit, '(a)') 'WARNING: '//r%name//' ('//deck_path//'): '//trim(r%warnings(k))
        end do
        status = max(status, r%status)
    end subroutine report_case

    !> A sweep's summary CSV and overlay figure; a shard writes STEM_summary.shard-I-of-N.csv
    !! with its own rows (scripts/merge_shards.sh joins the shards into STEM_summary.csv).
    subroutine write_sweep_outputs(out_dir, stem, cases, results, selected, opt, err)
        character(len=*), intent(in) :: out_dir, stem
        type(model_t), intent(in) :: cases(:)
        type(case_result_t), intent(in) :: results(:)
        logical, intent(in) :: selected(:)
        type(run_options_t), intent(in) :: opt
        type(error_t), allocatable, intent(out) :: err
        character(len=40) :: shard
        integer :: n_unwritten
        shard = ''
        if (opt%shard_count > 1) write (shard, '(a,i0,a,i0)') '.shard-', opt%shard_index, &
            '-of-', opt%shard_count
        n_unwritten = count(selected .and. results%status == EXIT_INPUT)
        if (n_unwritten > 0) then
            ! a case could not write its files (a full disk): a summary would cover part of
            ! the sweep, and one of an earlier run would not match it
            call remove_sweep_outputs(out_dir, stem, trim(shard))
            write (shard, '(i0)') n_unwritten
            call new_error(err, EXIT_INPUT, 'no sweep summary written: '//trim(shard)// &
                           ' case(s) could not write their files')
            return
        end if
        if (opt%shard_count > 1) then
            ! the summaries of an earlier split into another number of shards are stale
            call remove_shard_summaries(out_dir, stem, opt%shard_count)
            call write_summary_csv(out_dir//'/'//stem//'_summary'//trim(shard)//'.csv', cases(1), &
                                   pack(results, selected), err)
        else
            call remove_shard_summaries(out_dir, stem, 0)
            call write_summary_csv(out_dir//'/'//stem//'_summary.csv', cases(1), results, err)
            if (.not. allocated(err)) call write_sweep_plot(out_dir, stem, cases, results, &
                                                            opt%figures, err)
            if (allocated(err)) then
                ! no summary or overlay of an earlier run beside this run's cases
                call remove_output(out_dir//'/'//stem//'_summary.csv')
                call remove_output(out_dir//'/'//stem//'_sweep.gp')
                call remove_output(out_dir//'/'//stem//'_sweep.png')
            end if
        end if
    end subroutine write_sweep_outputs

    !> Standard-error progress: cases done of n, the elapsed time and an estimate of the time
    !! left (the mean time per case so far).
    subroutine report_progress(unit, done, n, name, clock_start)
        integer, intent(in) :: unit, done, n
        character(len=*), intent(in) :: name
        integer(int64), intent(in) :: clock_start
        integer(int64) :: now, rate
        real(dp) :: elapsed
        character(len=80) :: eta
        call system_clock(now, rate)
        elapsed = real(now - clock_start, dp)/real(rate, dp)
        eta = ''
        if (done < n) eta = ', about '//seconds(elapsed/real(done, dp)*real(n - done, dp))//' left'
        write (unit, '(a,i0,a,i0,a)') 'fricon: ', done, ' of ', n, ' done ('//name//'), '// &
            seconds(elapsed)//' elapsed'//trim(eta)
        flush (unit)
    end subroutine report_progress

    pure function seconds(t) result(text)
        real(dp), intent(in) :: t
        character(len=:), allocatable :: text
        character(len=16) :: buf
        write (buf, '(f12.1)') t
        text = trim(adjustl(buf))//' s'
    end function seconds

    !> One case: solve, tabulate, summarise, estimate the error (all in parallel with other
    !! cases of a sweep), then write the report, data files, JSON summary, gnuplot script and
    !! PNG. The writing runs one case at a time (a critical section): it is cheap, and it keeps
    !! the library's formatted-output and character temporaries out of any race. A failed case
    !! writes its report (ANALYSIS FAILED) and its JSON only, and removes the data files and
    !! figure of an earlier run of the same case.
    subroutine solve_case(deck, m, label, out_dir, name, figures, estimates, progress_unit, &
                          result)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(inout) :: m
        character(len=*), intent(in) :: label, out_dir, name
        logical, intent(in) :: figures            !! run gnuplot on the written .gp
        logical, intent(in) :: estimates          !! estimate the error (two coarser solves)
        integer, intent(in) :: progress_unit      !! >= 0: report each Newton step there
        type(case_result_t), intent(out) :: result
        type(discretization_t) :: d
        type(solution_t) :: sol
        type(station_table_t) :: tab
        type(summary_t) :: s
        type(error_t), allocatable :: err
        real(dp) :: extent

        result%name = name
        result%label = label
        result%message = ''
        result%rho = relative_stiffness(m)
        result%warnings = input_warnings(m)
        call solve_on_mesh(m, progress_unit, d, sol, tab, s, extent, result, err)
        if (.not. allocated(err) .and. m%adapt_tol <= 0.0_dp) &
            call refine_until_admissible(m, progress_unit, d, sol, tab, s, extent, result, err)
        if (.not. allocated(err)) call require_admissible(s, err)
        result%elements = m%ne
        if (result%adaptation%adapted) result%elements = result%adaptation%ne
        if (allocated(err)) then
            result%status = err%code
            result%message = err%message
            allocate (result%entries(0))
        else
            result%warnings = [character(len=warning_length) :: result%warnings, &
                               settlement_warnings(m, s%w_max%value), tension_warnings(m, &
                               s%n_tension_flags, s%n_tension_lifted, tab%n, tab%most_tensile, &
                               tab%tension_tol)]
            if (m%adapt_tol <= 0.0_dp .and. .not. loads_on_nodes(m, d%msh)) &
                result%warnings = [character(len=warning_length) :: result%warnings, &
                                   'a POINT, RING or MOMENT load lies between two nodes of '// &
                                   'the mesh: results near it converge at first order only '// &
                                   '(so do their error estimates); MESH grading LOADS puts '// &
                                   'a node at every load']
            result%entries = summary_entries(m, s, extent)
            if (result%adaptation%adapted) then
                call take_adapted_estimates(result)
            else if (estimates) then
                call estimate_errors(m, d, result%entries, sol%coarse, s%edge_in_contact)
            end if
            result%mean_pressure = s%mean_pressure
        end if
        !$omp critical (fricon_output)
        call write_case_files(deck, m, d, sol, tab, s, out_dir//'/'//name, figures, result)
        !$omp end critical (fricon_output)
    end subroutine solve_case

    !> Discretise m, solve (ADAPT: adaptively), tabulate at the stations and summarise (from
    !! the design table: every node, patch edge and load position; tabulate_design).
    subroutine solve_on_mesh(m, progress_unit, d, sol, tab, s, extent, result, err)
        type(model_t), intent(in) :: m
        integer, intent(in) :: progress_unit
        type(discretization_t), intent(out) :: d
        type(solution_t), intent(out) :: sol
        type(station_table_t), intent(out) :: tab
        type(summary_t), intent(out) :: s
        real(dp), intent(out) :: extent            !! contact extent t (contact_extent)
        type(case_result_t), intent(inout) :: result
        type(error_t), allocatable, intent(out) :: err
        type(station_table_t) :: design
        extent = -1.0_dp
        call new_discretization(m, d, err)
        if (.not. allocated(err)) then
            if (m%adapt_tol > 0.0_dp) then
                call solve_adaptive(m, d, sol, result%adaptation, err)
            else if (progress_unit >= 0) then
                call solve_contact(m, d, sol, err, progress_unit)
            else
                call solve_contact(m, d, sol, err)
            end if
        end if
        result%n_outer = sol%n_outer
        result%n_inner = sol%n_inner
        if (.not. allocated(err)) call tabulate(m, d, sol, tab, err)
        if (.not. allocated(err)) call tabulate_design(m, d, sol, tab, design, err)
        if (allocated(err)) return
        s = summarise(m, sol, design)
        extent = contact_extent(design, m%length)
    end subroutine solve_on_mesh

    !> A case solved with the law of the complete problem (its residual checks passed) whose
    !! friction admissibility check still fails is a mesh too coarse for the slip: the law
    !! holds in the Galerkin sense, over each traction function, not at every Gauss point
    !! (doc/CHOICES.md, "Very soft beams"). It is solved again with twice the elements of the
    !! same MESH family, up to max_doublings times and max_auto_elements, and the report says
    !! so; require_admissible then judges the last mesh. The results are the refined mesh's.
    subroutine refine_until_admissible(m, progress_unit, d, sol, tab, s, extent, result, err)
        type(model_t), intent(inout) :: m
        integer, intent(in) :: progress_unit
        type(discretization_t), intent(inout) :: d
        type(solution_t), intent(inout) :: sol
        type(station_table_t), intent(inout) :: tab
        type(summary_t), intent(inout) :: s
        real(dp), intent(inout) :: extent
        type(case_result_t), intent(inout) :: result
        type(error_t), allocatable, intent(out) :: err
        integer, parameter :: max_doublings = 3
        integer, parameter :: max_auto_elements = 1000   !! as ADAPT's default max_elements
        character(len=warning_length) :: text
        character(len=120) :: where
        real(dp) :: excess, allowance
        integer :: ne_deck, k
        ne_deck = m%ne
        excess = s%admissibility
        allowance = s%admissibility_tol
        doublings: do k = 1, max_doublings
            if (s%admissibility <= s%admissibility_tol .or. 2*m%ne > max_auto_elements) &
                exit doublings
            if (.not. finer_fits(m)) exit doublings
            m%ne = 2*m%ne
            call solve_on_mesh(m, progress_unit, d, sol, tab, s, extent, result, err)
            if (allocated(err)) exit doublings
        end do doublings
        if (m%ne == ne_deck) return
        write (where, '(a,i0,a,i0,a,i0)') 'friction not resolved pointwise on N_e = ', &
            ne_deck, ', mesh refined to N_e = ', m%ne
        if (allocated(err)) then
            call add_context(err, trim(where))
            return
        end if
        if (s%admissibility > s%admissibility_tol) then
            call require_admissible(s, err)
            call add_context(err, trim(where))
            return
        end if
        write (text, '(a,i0,a,i0,a,es8.2,a,es8.2,a,i0,a)') 'mesh refined from N_e = ', &
            ne_deck, ' to ', m%ne, ': friction not resolved pointwise on the deck''s mesh '// &
            '(max(|Sigma_x| - f Sigma_z) ', excess, ' > allowed ', allowance, &
            '); results are for N_e = ', m%ne, ' (doc/CHOICES.md)'
        result%warnings = [character(len=warning_length) :: result%warnings, text]
    end subroutine refine_until_admissible

    !> Whether the case on twice its elements fits in the memory available now (the check
    !! before solving sized it on the deck's mesh; the other cases of a sweep running at the
    !! same time have taken theirs already).
    logical function finer_fits(m)
        type(model_t), intent(in) :: m
        type(model_t) :: finer
        type(error_t), allocatable :: err
        finer = m
        finer%ne = 2*m%ne
        call check_memory(finer, 1, memory_available(), err)
        finer_fits = .not. allocated(err)
    end function finer_fits

    !> The estimates of the adaptation's final cycle (the same mesh and solution as the
    !! entries) and, when the tolerance was not reached, a warning that says so.
    subroutine take_adapted_estimates(r)
        type(case_result_t), intent(inout) :: r
        character(len=warning_length) :: text
        integer :: i, k
        associate (a => r%adaptation)
            do i = 1, size(r%entries)
                do k = 1, size(a%entries)
                    if (a%entries(k)%key /= r%entries(i)%key) cycle
                    r%entries(i)%has_error = a%entries(k)%has_error
                    r%entries(i)%error = a%entries(k)%error
                    r%entries(i)%order = a%entries(k)%order
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
            r%warnings = [character(len=warning_length) :: r%warnings, text]
        end associate
    end subroutine take_adapted_estimates

    !> The files of one solved or failed case (see solve_case).
    subroutine write_case_files(deck, m, d, sol, tab, s, base, figures, result)
        type(deck_t), intent(in) :: deck
        type(model_t), intent(in) :: m
        type(discretization_t), intent(in) :: d
        type(solution_t), intent(in) :: sol
        type(station_table_t), intent(in) :: tab
        type(summary_t), intent(in) :: s
        character(len=*), intent(in) :: base
        logical, intent(in) :: figures
        type(case_result_t), intent(inout) :: result
        type(error_t), allocatable :: err, err_report
        character(len=:), allocatable :: note
        call remove_temporaries(base)
        if (result%status /= EXIT_OK) then
            call remove_stale(base)
            call write_report(base//'.txt', deck%path, deck%lines, result%label, m, d, sol, tab, &
                              result%entries, s, result%message, &
                              report_notes(result%warnings, ''), err_report, result%adaptation)
            if (.not. allocated(err_report)) call write_summary_json(base//'.json', result%name, &
                deck%path, m, result%status, result%message, result%entries, s, sol, tab, &
                err_report, result%adaptation, result%warnings, deck_file_of(deck))
            if (allocated(err_report)) then
                ! the failure's own report cannot be written: that is what the user must hear
                call remove_case_files(base)
                result%status = err_report%code
                result%message = trim(result%message)//'; and its report: '//err_report%message
            end if
            return
        end if
        call write_data_file(base//'.dat', m, tab, err)
        if (.not. allocated(err) .and. .not. m%nondim) call write_physical_csv(base//'.csv', m, &
                                                                               tab, err)
        if (.not. allocated(err)) call write_summary_json(base//'.json', result%name, deck%path, &
                                                          m, EXIT_OK, '', result%entries, s, &
                                                          sol, tab, err, result%adaptation, &
                                                          result%warnings, deck_file_of(deck))
        ! no figure or CSV of an earlier run beside results that have none
        if (.not. allocated(err) .and. .not. figures) call remove_output(base//'.png')
        if (.not. allocated(err) .and. m%nondim) call remove_output(base//'.csv')
        if (.not. allocated(err)) call write_plot_script(base//'.gp', result%name, m, &
                                                         result%label, s, err)
        if (allocated(err)) then
            ! no partial set of a case's files is left (README: exit 1 writes no output)
            call remove_case_files(base)
            result%status = err%code
            result%message = err%message
            return
        end if
        note = ''
        if (figures) call render_png(base, note)
        result%message = note
        call write_report(base//'.txt', deck%path, deck%lines, result%label, m, d, sol, tab, &
                          result%entries, s, '', report_notes(result%warnings, note), err, &
                          result%adaptation)
        if (allocated(err)) then
            call remove_case_files(base)
            result%status = err%code
            result%message = err%message
        end if
    end subroutine write_case_files

    !> A case whose tractions break the friction law beyond what the regularisation allows is
    !! no result (status 2), whatever the solver's own stopping rule said.
    subroutine require_admissible(s, err)
        type(summary_t), intent(in) :: s
        type(error_t), allocatable, intent(out) :: err
        character(len=400) :: text
        if (s%admissibility <= s%admissibility_tol) return
        ! the solver holds the law in the Galerkin sense (its residual is checked before); a
        ! pointwise excess beyond the allowance is then a mesh too coarse for the slip
        ! (doc/CHOICES.md, very soft beams at eps_bar = 1e-12)
        write (text, '(a,es10.3,a,es10.3,a)') 'the friction admissibility check failed: max(|Sigma_x| '// &
            '- f Sigma_z) = ', s%admissibility, ' exceeds the ', s%admissibility_tol, &
            ' the regularised law allows at the largest slip: the law holds on average over '// &
            'each traction function but is not resolved pointwise on this mesh: refine it'
        call new_error(err, EXIT_ANALYSIS, trim(text))
    end subroutine require_admissible

    !> The report's closing lines: each warning, then the note (if any).
    pure function report_notes(warnings, note) result(lines)
        character(len=*), intent(in) :: warnings(:), note
        character(len=warning_length + 10), allocatable :: lines(:)
        integer :: k
        allocate (lines(size(warnings) + merge(1, 0, len_trim(note) > 0)))
        do k = 1, size(warnings)
            lines(k) = 'WARNING: '//warnings(k)
        end do
        if (len_trim(note) > 0) lines(size(lines)) = 'NOTE: '//note
    end function report_notes

    !> Results of an earlier run of the same case that a failed run must not leave beside its
    !! ANALYSIS FAILED report.
    subroutine remove_stale(base)
        character(len=*), intent(in) :: base
        character(len=*), parameter :: ext(5) = ['.dat', '.csv', '.gp ', '.png', '.txt']
        call remove_files(base, ext)
    end subroutine remove_stale

    !> The deck's canonical path for the JSON summaries ('' for the built-in default, which is
    !! no file: outputs of a deck that happens to lie at input/default.dat are not its own).
    function deck_file_of(deck) result(path)
        type(deck_t), intent(in) :: deck
        character(len=:), allocatable :: path
        path = ''
        if (deck%from_file) path = canonical_path(deck%path)
    end function deck_file_of

    !> Every file of a case (a write that failed leaves none of the others).
    subroutine remove_case_files(base)
        character(len=*), intent(in) :: base
        call remove_stale(base)
        call remove_files(base, ['.json'])
        call remove_temporaries(base)
    end subroutine remove_case_files

    !> The temporary files of this case's outputs that a killed earlier run may have left
    !! (NAME.ext.tmp): removed before the case writes, so none is ever taken for a result.
    subroutine remove_temporaries(base)
        character(len=*), intent(in) :: base
        character(len=*), parameter :: ext(6) = ['.dat.tmp ', '.csv.tmp ', '.gp.tmp  ', &
                                                 '.png.tmp ', '.txt.tmp ', '.json.tmp']
        call remove_files(base, ext)
    end subroutine remove_temporaries

    !> base.ext for each ext, where it looks like fricon's output (never a deck given such a
    !! name: output_paths::remove_output).
    subroutine remove_files(base, ext)
        character(len=*), intent(in) :: base
        character(len=*), intent(in) :: ext(:)
        integer :: k
        do k = 1, size(ext)
            call remove_output(base//trim(ext(k)))
        end do
    end subroutine remove_files

    !> x with four significant digits: fixed notation from 1e-3 to 1e5, else E notation.
    pure function four_digits(x) result(text)
        real(dp), intent(in) :: x
        character(len=24) :: text
        integer :: decimals
        if (x == 0.0_dp) then
            text = '0'
        else if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e5_dp) then
            decimals = max(0, 3 - floor(log10(abs(x))))
            write (text, '(f0.'//achar(iachar('0') + min(decimals, 9))//')') x
            if (text(1:1) == '.') text = '0'//text
            if (text(1:2) == '-.') text = '-0'//text(2:)
        else
            write (text, '(es10.3)') x
            text = adjustl(text)
        end if
    end function four_digits

    !> The console line: key results with their units.
    pure function console_summary(e) result(text)
        type(entry_t), intent(in) :: e(:)
        character(len=:), allocatable :: text
        character(len=*), parameter :: keys(4) = [character(len=24) :: 'settlement_max', &
                                                   'differential_settlement', 'pressure_mean', &
                                                   'contact_extent_t']
        character(len=*), parameter :: names(4) = [character(len=12) :: 'w_max', 'w_diff', &
                                                    'p_mean', 'extent t']
        character(len=24) :: buf
        integer :: i, k
        text = ''
        do k = 1, size(keys)
            do i = 1, size(e)
                if (trim(e(i)%key) /= trim(keys(k))) cycle
                buf = four_digits(e(i)%value)
                text = text//trim(names(k))//' = '//trim(adjustl(buf))
                if (len_trim(e(i)%unit) > 0) text = text//' '//trim(e(i)%unit)
                if (k < size(keys)) text = text//',  '
            end do
        end do
    end function console_summary

    !> gnuplot runs the figure script base.gp and renders the PNG to a temporary name, moved
    !! into place on success; `note` says why a figure was not drawn.
    subroutine render_png(base, note)
        character(len=*), intent(in) :: base
        character(len=:), allocatable, intent(out) :: note
        integer :: exit_status, cmd_status
        note = ''
        if (index(base, "'") > 0 .or. index(base, '"') > 0) then
            note = 'figure not rendered: the output path contains a quote'
            call remove_output(base//'.png')
            return
        end if
        call execute_command_line('command -v gnuplot > /dev/null 2>&1', exitstat=exit_status, &
                                  cmdstat=cmd_status)
        if (cmd_status /= 0 .or. exit_status /= 0) then
            note = 'figure '//base//'.png not drawn: gnuplot is not installed (the script '// &
                   base//'.gp is written; scripts/setup.sh installs gnuplot)'
            call remove_output(base//'.png')      ! not an earlier run's figure beside it
            return
        end if
        call register_temporary(base//'.png.tmp')
        call execute_command_line("gnuplot -e ""png_override='"//base//".png.tmp'"" '"//base// &
            ".gp' && tail -c 12 '"//base//".png.tmp' | grep -qa IEND && mv -fT '"//base// &
            ".png.tmp' '"//base//".png'", exitstat=exit_status, cmdstat=cmd_status)
        if (cmd_status /= 0 .or. exit_status /= 0) then
            ! (a PNG ends with its IEND chunk: gnuplot exits 0 on a full disk with the file
            ! cut; mv -T: a folder named like the figure is not a place to move it into)
            note = 'figure '//base//'.png not drawn: gnuplot failed on '//base//'.gp, the '// &
                   'figure came out incomplete (disk full?), or '//base//'.png cannot be replaced'
            call remove_output(base//'.png')
            call execute_command_line("rm -f '"//base//".png.tmp'")
        end if
        call release_temporary(base//'.png.tmp')
    end subroutine render_png

    !> output/STEM_sweep.gp and .png: the solved cases overlaid (report_writer
    !! write_sweep_script: the first solved case's settings, the case files, the legend labels
    !! of the swept values and each case's mean contact pressure for the clip rule).
    subroutine write_sweep_plot(out_dir, stem, cases, results, figures, err)
        character(len=*), intent(in) :: out_dir, stem
        type(model_t), intent(in) :: cases(:)
        type(case_result_t), intent(in) :: results(:)
        logical, intent(in) :: figures
        type(error_t), allocatable, intent(out) :: err
        character(len=200), allocatable :: names(:), labels(:)
        real(dp), allocatable :: means(:)
        character(len=:), allocatable :: note
        integer :: i, first
        allocate (names(0), labels(0), means(0))
        first = 0
        do i = 1, size(results)
            if (results(i)%status /= EXIT_OK) cycle
            if (first == 0) first = i
            names = [character(len=200) :: names, results(i)%name]
            labels = [character(len=200) :: labels, one_word(results(i)%label)]
            means = [means, results(i)%mean_pressure]
        end do
        if (first == 0 .or. .not. figures) call remove_output(out_dir//'/'//stem//'_sweep.png')
        if (first == 0) then
            ! no solved case: an earlier overlay would show curves of files that are gone
            call remove_output(out_dir//'/'//stem//'_sweep.gp')
            return
        end if
        call write_sweep_script(out_dir//'/'//stem//'_sweep.gp', stem, cases(first), names, &
                                labels, means, err)
        if (allocated(err)) return
        if (figures) call render_png(out_dir//'/'//stem//'_sweep', note)
    end subroutine write_sweep_plot

    !> A sweep label as one quoted gnuplot word (for word() and the legend):
    !! 'case 002 of 006: RHO=0.01 F=0.5' -> 'RHO=0.01 F=0.5' in single quotes.
    pure function one_word(label) result(word)
        character(len=*), intent(in) :: label
        character(len=:), allocatable :: word
        integer :: i
        word = trim(adjustl(label(index(label, ':') + 1:)))
        do i = 1, len(word)
            if (index('"''`$\', word(i:i)) > 0) word(i:i) = ' '
        end do
        word = trim(adjustl(word))
        if (len(word) == 0) word = 'case'
        word = "'"//word//"'"
    end function one_word

    !> output/STEM_summary.csv: one row per case, with the key results of summary_table
    !! (display units, named in the header); a failed case has empty result fields.
    subroutine write_summary_csv(path, m, results, err)
        character(len=*), intent(in) :: path
        type(model_t), intent(in) :: m
        type(case_result_t), intent(in) :: results(:)
        type(error_t), allocatable, intent(out) :: err
        character(len=32), allocatable :: keys(:)
        integer :: u, i, k
        keys = entry_keys(m)
        call open_temporary(path, u, err)
        if (allocated(err)) return
        write (u, '(a)', advance='no') 'case,parameters,status,rho,outer_iterations,elements'
        do k = 1, size(keys)
            write (u, '(a)', advance='no') ','//trim(keys(k))//unit_suffix(results, k)
        end do
        write (u, '(a)') ',message'
        do i = 1, size(results)
            associate (r => results(i))
                write (u, '(a,",",a,",",i0,",",es15.7,",",i0,",",i0)', advance='no') r%name, &
                    '"'//r%label//'"', r%status, r%rho, r%n_outer, r%elements
                do k = 1, size(keys)
                    if (r%status /= EXIT_OK .or. .not. allocated(r%entries)) then
                        write (u, '(a)', advance='no') ','
                    else if (.not. r%entries(k)%defined) then
                        write (u, '(a)', advance='no') ','
                    else if (r%entries(k)%integer_valued) then
                        write (u, '(",",i0)', advance='no') nint(r%entries(k)%value)
                    else
                        write (u, '(",",es15.7)', advance='no') r%entries(k)%value
                    end if
                end do
                write (u, '(a)') ',"'//r%message//'"'
            end associate
        end do
        call commit_file(path, u, err)
    end subroutine write_summary_csv

    !> ' [unit]' of key k from the first solved case ('' if none or a pure number).
    pure function unit_suffix(results, k) result(text)
        type(case_result_t), intent(in) :: results(:)
        integer, intent(in) :: k
        character(len=:), allocatable :: text
        integer :: i
        text = ''
        do i = 1, size(results)
            if (.not. allocated(results(i)%entries)) cycle
            if (size(results(i)%entries) < k) cycle      ! a failed case has no results
            if (len_trim(results(i)%entries(k)%unit) > 0) &
                text = ' ['//trim(results(i)%entries(k)%unit)//']'
            return
        end do
    end function unit_suffix
end module analysis_driver
