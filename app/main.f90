!> fricon [options] [DECK...]: solves each deck (without a deck, the embedded default raft).
!! Exit status: the worst of the decks: 0 solved, 1 input or file error, 2 analysis failed,
!! 3 internal error.
program fricon
    use iso_fortran_env, only: error_unit, output_unit
    use iso_c_binding, only: c_int
    use errors, only: error_t, EXIT_OK, EXIT_INPUT
    use gsl_wrappers, only: gsl_start
    use deck_reader, only: deck_t, read_deck, parse_deck, default_deck_lines, case_count
    use analysis_driver, only: run_analysis, run_options_t
    use output_paths, only: stderr_is_terminal, check_decks_apart, remove_stale_outputs
    use temporary_cleanup, only: install_cleanup
    implicit none
    interface
        ! void exit(int status);  (the C library: ends without the runtime's "STOP n" line)
        subroutine c_exit(status) bind(c, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
    end interface
    character(len=*), parameter :: version = '0.2.0'   !! as in fpm.toml
    type(run_options_t) :: options
    character(len=1024), allocatable :: decks(:)
    character(len=1024) :: out_dir
    integer :: status, k, deck_status
    logical :: quiet, progress_forced

    ! SIGTERM and SIGINT remove the temporary files of the case being written
    if (.not. install_cleanup()) write (error_unit, '(a)') 'fricon: warning: no signal '// &
        'handler: a SIGTERM or SIGINT may leave NAME.tmp files (the next run removes them)'
    call read_arguments(decks, out_dir, options, quiet, progress_forced)
    options%progress = progress_forced .or. (.not. quiet .and. stderr_is_terminal())
    call gsl_start()
    status = EXIT_OK
    if (size(decks) == 0) then
        call run_default(trim(out_dir), options, status)
    else
        call check_distinct_outputs(decks, out_dir)
        do k = 1, size(decks)
            call run_deck(trim(decks(k)), trim(out_dir), options, deck_status)
            if (size(decks) > 1) write (output_unit, '(a,i0,a)') 'fricon: '//trim(decks(k))// &
                ': exit status ', deck_status, ' ('//trim(outcome(deck_status))//')'
            status = max(status, deck_status)
        end do
    end if
    call finish(status)

contains

    !> Options and deck names from the command line; --help and --version end the run.
    subroutine read_arguments(decks, out_dir, options, quiet, progress_forced)
        character(len=1024), allocatable, intent(out) :: decks(:)
        character(len=1024), intent(out) :: out_dir
        type(run_options_t), intent(inout) :: options
        logical, intent(out) :: quiet, progress_forced
        character(len=1024) :: arg
        integer :: i, k, n, ios
        allocate (decks(0))
        out_dir = ''
        quiet = .false.
        progress_forced = .false.
        n = command_argument_count()
        i = 0
        arguments: do while (i < n)
            i = i + 1
            call get_command_argument(i, arg)
            select case (trim(arg))
            case ('-h', '--help')
                call print_usage(output_unit)
                call finish(EXIT_OK)
            case ('-V', '-v', '--version')
                write (output_unit, '(a)') 'fricon '//version
                call finish(EXIT_OK)
            case ('-o', '--output')
                if (i == n) call usage_error('option '//trim(arg)//' needs a folder')
                i = i + 1
                call get_command_argument(i, out_dir)
            case ('--no-figures')
                options%figures = .false.
            case ('--no-estimates')
                options%estimates = .false.
            case ('--full-model')
                options%full_model = .true.
            case ('-j', '--jobs')
                if (i == n) call usage_error('option '//trim(arg)//' needs a number of cases')
                i = i + 1
                call get_command_argument(i, arg)
                read (arg, *, iostat=ios) options%threads
                if (ios /= 0 .or. options%threads < 1) call usage_error('--jobs needs a whole '// &
                    'number >= 1, got '//trim(arg))
            case ('--shard')
                if (i == n) call usage_error('option --shard needs I/N')
                i = i + 1
                call get_command_argument(i, arg)
                call read_shard(trim(arg), options)
            case ('-q', '--quiet')
                quiet = .true.
            case ('--progress')
                progress_forced = .true.
            case ('--')
                ! (a separate index: an implied-do may not use its own variable in its limits)
                decks = [character(len=1024) :: decks, (next_argument(k), k=i + 1, n)]
                exit arguments
            case default
                if (arg(1:1) == '-') call usage_error('unknown option '//trim(arg))
                decks = [character(len=1024) :: decks, arg]
            end select
        end do arguments
    end subroutine read_arguments

    !> --shard I/N: this run solves cases I, I+N, I+2N, ... of each sweep (1 <= I <= N).
    subroutine read_shard(text, options)
        character(len=*), intent(in) :: text
        type(run_options_t), intent(inout) :: options
        integer :: slash, ios1, ios2
        slash = index(text, '/')
        ios1 = 1
        ios2 = 1
        if (slash > 1) then
            read (text(1:slash - 1), *, iostat=ios1) options%shard_index
            read (text(slash + 1:), *, iostat=ios2) options%shard_count
        end if
        if (ios1 /= 0 .or. ios2 /= 0) call usage_error('--shard needs I/N such as 3/8, got '//text)
        if (options%shard_count < 1 .or. options%shard_index < 1 .or. &
            options%shard_index > options%shard_count) &
            call usage_error('--shard I/N needs 1 <= I <= N, got '//text)
    end subroutine read_shard

    function next_argument(i) result(arg)
        integer, intent(in) :: i
        character(len=1024) :: arg
        call get_command_argument(i, arg)
    end function next_argument

    subroutine print_usage(unit)
        integer, intent(in) :: unit
        write (unit, '(a)') 'usage: fricon [options] [DECK...]'
        write (unit, '(a)') ''
        write (unit, '(a)') 'Solves each card-image DECK: a beam or circular raft on an elastic '// &
            'half-space with'
        write (unit, '(a)') 'lift-off and friction. Without a DECK, solves the built-in default '// &
            'raft (input/default.dat).'
        write (unit, '(a)') ''
        write (unit, '(a)') 'options:'
        write (unit, '(a)') '  -o, --output DIR  write the outputs under DIR (default: output/ '// &
            'in the current folder,'
        write (unit, '(a)') '                    output/SUB for a deck in input/SUB/)'
        write (unit, '(a)') '      --no-figures  write each figure script (.gp) but do not run '// &
            'gnuplot'
        write (unit, '(a)') '      --no-estimates  no error estimates (they re-solve each case on '// &
            'N_e/2 and N_e/4)'
        write (unit, '(a)') '      --full-model  no simplifications (half beam, no sigma_x at f = 0, '// &
            'settled lift-off'
        write (unit, '(a)') '                    decoupled in the factorisation): the full model'
        write (unit, '(a)') '  -j, --jobs N      solve N cases of a sweep at once (default: all cores)'
        write (unit, '(a)') '      --shard I/N   solve cases I, I+N, I+2N, ... of each sweep only '// &
            '(a job array:'
        write (unit, '(a)') '                    scripts/merge_shards.sh joins the shard summaries)'
        write (unit, '(a)') '  -q, --quiet       no progress on standard error'
        write (unit, '(a)') '      --progress    progress even when standard error is not a '// &
            'terminal'
        write (unit, '(a)') '  -h, --help        this text'
        write (unit, '(a)') '  -V, --version     the version'
        write (unit, '(a)') ''
        write (unit, '(a)') 'Each case writes CASE.txt (report), .dat, .csv, .json, .gp and .png; '// &
            'README.md and'
        write (unit, '(a)') 'doc/OUTPUT.md describe the decks and the outputs.'
        write (unit, '(a)') 'Exit status: the worst of the decks: 0 solved, 1 input or file '// &
            'error, 2 analysis failed, 3 internal error.'
    end subroutine print_usage

    subroutine usage_error(text)
        character(len=*), intent(in) :: text
        write (error_unit, '(a)') 'ERROR: '//text//' (fricon --help lists the options)'
        call finish(EXIT_INPUT)
    end subroutine usage_error

    !> Decks of one call that would write the same file, or overwrite one another, are refused
    !! before anything is solved (output_paths::check_decks_apart); a deck that cannot be
    !! read writes nothing and is left to its own error.
    subroutine check_distinct_outputs(decks, out_dir)
        character(len=*), intent(in) :: decks(:), out_dir
        character(len=1024) :: dirs(size(decks)), stems(size(decks))
        integer :: counts(size(decks)), k
        type(deck_t) :: deck
        type(error_t), allocatable :: err
        if (size(decks) < 2) return
        do k = 1, size(decks)
            dirs(k) = output_directory(trim(decks(k)), trim(out_dir))
            counts(k) = 0
            stems(k) = ''
            call read_deck(trim(decks(k)), deck, err)
            if (allocated(err)) then
                deallocate (err)
                cycle
            end if
            counts(k) = case_count(deck)
            stems(k) = deck%stem
        end do
        call check_decks_apart(decks, dirs, stems, counts, err)
        if (allocated(err)) call usage_error(err%message)
    end subroutine check_distinct_outputs

    subroutine run_default(out_dir, options, status)
        character(len=*), intent(in) :: out_dir
        type(run_options_t), intent(in) :: options
        integer, intent(out) :: status
        type(deck_t) :: deck
        type(error_t), allocatable :: err
        character(len=80), allocatable :: lines(:)
        call default_deck_lines(lines)
        call parse_deck('input/default.dat', lines, deck, err)
        if (allocated(err)) then
            write (error_unit, '(a)') 'ERROR: '//err%message
            status = err%code
            return
        end if
        call run_analysis(deck, output_directory('', out_dir), output_unit, error_unit, status, &
                          options)
    end subroutine run_default

    subroutine run_deck(path, out_dir, options, status)
        character(len=*), intent(in) :: path, out_dir
        type(run_options_t), intent(in) :: options
        integer, intent(out) :: status
        type(deck_t) :: deck
        type(error_t), allocatable :: err
        call read_deck(path, deck, err)
        if (allocated(err)) then
            write (error_unit, '(a)') 'ERROR: '//err%message
            status = err%code
            ! no output, and none of an earlier run of this deck left to be taken for its result
            call remove_stale_outputs(output_directory(path, out_dir), deck%stem, 0, path)
            return
        end if
        call run_analysis(deck, output_directory(path, out_dir), output_unit, error_unit, &
                          status, options)
    end subroutine run_deck

    !> The -o folder if given; else output/, or output/SUB for a deck under input/SUB/ (e.g.
    !! input/paper/ -> output/paper/), relative to the current folder.
    function output_directory(deck_path, given) result(dir)
        character(len=*), intent(in) :: deck_path, given
        character(len=:), allocatable :: dir
        integer :: i, j
        if (len_trim(given) > 0) then
            dir = trim(given)
            return
        end if
        dir = 'output'
        i = index(deck_path, 'input/', back=.true.)
        j = index(deck_path, '/', back=.true.)
        if (i == 0 .or. j <= i + 5) return
        if (i > 1) then
            if (deck_path(i - 1:i - 1) /= '/') return
        end if
        dir = 'output/'//deck_path(i + 6:j - 1)
    end function output_directory

    pure function outcome(code) result(text)
        integer, intent(in) :: code
        character(len=24) :: text
        select case (code)
        case (0)
            text = 'solved'
        case (1)
            text = 'input or file error'
        case (2)
            text = 'analysis failed'
        case default
            text = 'internal error'
        end select
    end function outcome

    !> Flush and end with the exit status, without the runtime's "STOP n" line on standard
    !! error (a Fortran STOP with a code prints one).
    subroutine finish(code)
        integer, intent(in) :: code
        flush (output_unit)
        flush (error_unit)
        call c_exit(int(code, c_int))
    end subroutine finish
end program fricon
