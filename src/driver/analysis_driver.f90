!> Runs a whole deck: validates every case first, then solves each case on its own (a failed
!! case does not stop the others) and writes its report, data, gnuplot script and PNG.
module analysis_driver
    use iso_fortran_env, only: int64
    use kinds, only: dp
    use errors, only: error_t, add_context, EXIT_OK, EXIT_INPUT
    use model, only: model_t, relative_stiffness, METHOD_TWOLOOP
    use deck_reader, only: deck_t, case_count, case_model, combination_names
    use plausibility, only: warning_length, input_warnings
    use solved_case, only: case_t
    use case_quality, only: solve_to_quality
    use design_checks, only: evaluate_design_checks
    use case_files, only: case_result_t, write_case_files
    use figure_renderer, only: renderer_t, stop_renderer
    use sweep_files, only: write_sweep_outputs
    use design_envelope, only: design_values
    use combination_runs, only: write_run_envelope
    use console, only: report_case, report_progress, seconds
    use output_paths, only: prepare_output_dir, check_deck_not_overwritten, case_name, &
                            case_number, remove_stale_outputs
    use blas_threads, only: set_blas_threads, blas_thread_count
    use flexibility_cache, only: flexibility_cache_t, new_flexibility_cache
    use resource_limits, only: check_memory, memory_available, case_memory, time_needed, &
                               case_unknowns
    implicit none
    private

    !> How a run behaves (command-line options).
    type, public :: run_options_t
        logical :: figures = .true.     !! run gnuplot (the .gp is always written)
        logical :: record = .true.      !! write each case's HTML record (--no-html: not)
        logical :: progress = .false.   !! progress on the error unit: case i of n, time left
        integer :: threads = 0          !! cases solved at once (0: all cores)
        logical :: estimates = .true.   !! error estimates (two coarser solves per case)
        logical :: full_model = .false. !! no simplifications (model_reduction)
        integer :: shard_index = 1      !! solve cases shard_index, +shard_count, ... only
        integer :: shard_count = 1
    end type run_options_t

    public :: case_result_t
    public :: run_analysis, run_case

contains

    !> Solve every case of the deck (or, with a shard, every n-th); `status` is the worst exit
    !! status of all cases. Every case is validated, the output folder proved writable and the
    !! deck checked against being overwritten before anything is solved. The cases of a sweep
    !! run in parallel (OpenMP, one case per thread, each with single-threaded BLAS); a case's
    !! result does not depend on the thread that solved it, and the console lines, files and
    !! summary rows come in case order.
    subroutine run_analysis(deck, out_dir, log_unit, err_unit, status, options)
        !$ use omp_lib, only: omp_get_thread_num
        type(deck_t), intent(in) :: deck           !! the read deck: its cases and sweeps
        character(len=*), intent(in) :: out_dir    !! e.g. 'output'
        integer, intent(in) :: log_unit            !! where each case's outcome is written
        integer, intent(in) :: err_unit            !! errors, warnings and progress
        integer, intent(out) :: status             !! the worst exit status of the cases
        !> threads, shard, estimates, figures (defaults: run_options_t)
        type(run_options_t), intent(in), optional :: options
        type(run_options_t) :: opt
        integer(int64) :: clock_start
        type(model_t), allocatable :: cases(:)
        character(len=200), allocatable :: labels(:)
        !> the cases' file name stems, made before the parallel loop: case_name's result has a
        !! deferred length, which gfortran keeps in a static variable of the caller
        !! (scripts/check_thread_safety.py)
        character(len=:), allocatable :: names(:)
        type(case_result_t), allocatable :: results(:)
        logical, allocatable :: selected(:)
        type(error_t), allocatable :: err
        type(flexibility_cache_t) :: cache
        type(renderer_t), allocatable :: renderers(:)   !! one gnuplot per thread
        integer :: i, n, done, threads, blas_before, big_case_unit, thread
        character(len=10), allocatable :: tags(:)

        n = case_count(deck)
        tags = combination_names(deck)
        allocate (results(n))
        call case_models(deck, err_unit, cases, labels, status)
        if (status /= EXIT_OK) then
            ! exit 1 writes no output, and leaves none of an earlier run of this deck
            if (deck%from_file) call remove_stale_outputs(out_dir, deck%stem, 0, deck%path)
            return
        end if
        if (present(options)) opt = options
        if (opt%full_model) cases(:)%solver%simplify = .false.
        call prepare_output_dir(out_dir, err)
        if (.not. allocated(err)) call check_deck_not_overwritten(deck%path, out_dir, deck%stem, &
                                                                  n, err, tags)
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
        cache = new_flexibility_cache(count(selected) > 1)
        call system_clock(clock_start)
        done = 0
        allocate (renderers(threads))
        ! (a stem, a case number and a combination name of at most 10 characters)
        allocate (character(len=len(deck%stem) + 32) :: names(n))
        do i = 1, n
            names(i) = case_name(deck%stem, i, n, tags)
        end do
        !$omp parallel do schedule(dynamic, 1) num_threads(threads) default(shared) &
        !$omp private(i, thread)
        cases_loop: do i = 1, n
            if (.not. selected(i)) cycle cases_loop
            thread = 1
            !$ thread = omp_get_thread_num() + 1
            call run_case(deck, cases(i), trim(labels(i)), out_dir, &
                            trim(names(i)), &
                            opt%figures, opt%estimates, big_case_unit, results(i), cache, &
                            renderers(thread), opt%record)
            !$omp critical (fricon_progress)
            done = done + 1
            if (opt%progress) call report_progress(err_unit, done, count(selected), &
                                                   results(i)%name, clock_start)
            !$omp end critical (fricon_progress)
        end do cases_loop
        !$omp end parallel do
        do thread = 1, threads
            call stop_renderer(renderers(thread))
        end do
        call set_blas_threads(blas_before)
        do i = 1, n
            if (selected(i)) call report_case(log_unit, err_unit, deck%path, out_dir, results(i), &
                                              status)
        end do
        if (n > 1) call write_sweep_outputs(out_dir, deck%stem, cases, results, selected, &
                                            opt%figures, opt%shard_index, opt%shard_count, err)
        if (allocated(err)) then
            write (err_unit, '(a)') 'ERROR: '//err%message
            status = max(status, err%code)
        end if
        if (size(tags) > 0) call write_run_envelope(deck, out_dir, results, opt%shard_count, &
                                                    log_unit, err_unit, status)
        ! what an earlier run of this deck wrote and this one did not (a longer sweep, a sweep
        ! where there is now one case, or one case where there is now a sweep)
        if (deck%from_file) call remove_stale_outputs(out_dir, deck%stem, n, deck%path, tags)
    end subroutine run_analysis

    !> The model and the label of every case of the deck; every input error of every case is
    !! written (status EXIT_INPUT), so that all are reported before anything is solved.
    subroutine case_models(deck, err_unit, cases, labels, status)
        type(deck_t), intent(in) :: deck                          !! the read deck
        integer, intent(in) :: err_unit                           !! where errors are written
        type(model_t), allocatable, intent(out) :: cases(:)       !! one model per case
        character(len=200), allocatable, intent(out) :: labels(:) !! 'case i of n: values'
        integer, intent(out) :: status                            !! EXIT_OK or EXIT_INPUT
        type(error_t), allocatable :: err
        character(len=:), allocatable :: label
        integer :: i, n
        n = case_count(deck)
        allocate (cases(n), labels(n))
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
    end subroutine case_models

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

    !> One case: brought to the quality its deck asks for (case_quality: solve, refine or
    !! adapt, estimate), in parallel with the other cases of a sweep, then its files written
    !! (case_files: the writing one case at a time, the figure drawn by the thread's own
    !! gnuplot in parallel).
    subroutine run_case(deck, m, label, out_dir, name, figures, estimates, progress_unit, &
                        result, cache, renderer, record)
        type(deck_t), intent(in) :: deck             !! the deck (echoed in the report)
        type(model_t), intent(in) :: m               !! the case's model
        character(len=*), intent(in) :: label        !! 'case i of n: swept values'
        character(len=*), intent(in) :: out_dir      !! output folder
        character(len=*), intent(in) :: name         !! the case's file name stem
        logical, intent(in) :: figures               !! run gnuplot on the written .gp
        logical, intent(in) :: estimates             !! estimate the error (two coarser solves)
        integer, intent(in) :: progress_unit         !! >= 0: report each Newton step there
        type(case_result_t), intent(out) :: result   !! status, key results, warnings
        type(flexibility_cache_t), intent(inout), optional :: cache  !! the run's cache of T
        type(renderer_t), intent(inout), optional :: renderer  !! the thread's gnuplot
        logical, intent(in), optional :: record      !! write the HTML record (default yes)
        type(case_t) :: c
        character(len=warning_length), allocatable :: warnings(:)
        type(error_t), allocatable :: err
        result%name = name
        result%label = label
        result%message = ''
        result%rho = relative_stiffness(m%structure, m%ground)
        call solve_to_quality(m, estimates, progress_unit, c, result%adaptation, warnings, err, &
                              cache)
        result%warnings = [character(len=warning_length) :: input_warnings(m), warnings]
        result%n_outer = c%sol%n_outer
        result%n_inner = c%sol%n_inner
        result%elements = c%model%mesh%ne
        if (result%adaptation%adapted) result%elements = result%adaptation%ne
        if (allocated(err)) then
            result%status = err%code
            result%message = err%message
            allocate (result%entries(0))
        else
            result%entries = c%entries
            result%values = design_values(c)
            result%checks = evaluate_design_checks(c%model, c%summary)
            result%mean_pressure = c%summary%mean_pressure
        end if
        call write_case_files(deck, c, out_dir//'/'//name, figures, result, renderer, record)
    end subroutine run_case

end module analysis_driver
