!> The command line of fricon: `fricon [options] [DECK...]` read into a command_t. Reading
!! never ends the run: a usage error comes back as an error_t, --help and --version as flags
!! that the program acts on.
module command_line
    use errors, only: error_t, new_error, EXIT_INPUT
    use analysis_driver, only: run_options_t
    use run_identity, only: program_version
    implicit none
    private

    character(len=*), parameter, public :: version = program_version   !! as in fpm.toml

    !> What the command line asks for.
    type, public :: command_t
        character(len=1024), allocatable :: decks(:)  !! deck paths, in order (none: default)
        character(len=1024) :: out_dir = ''           !! -o DIR ('': output/ by deck folder)
        type(run_options_t) :: options                !! how the run behaves
        logical :: quiet = .false.                    !! -q: no progress
        logical :: progress_forced = .false.          !! --progress: progress even if piped
        logical :: help = .false.                     !! -h: print usage_lines and stop
        logical :: show_version = .false.             !! -V: print the version and stop
        logical :: merge = .false.                    !! --merge: the arguments are shard
                                                      !! summaries to merge, not decks
    end type command_t

    public :: read_command_line, usage_lines

contains

    !> Options and deck names from the command line; stops reading at --help or --version.
    subroutine read_command_line(cmd, err)
        type(command_t), intent(out) :: cmd               !! what was asked
        type(error_t), allocatable, intent(out) :: err    !! a usage error (EXIT_INPUT)
        character(len=1024) :: arg
        integer :: i, k, n
        allocate (cmd%decks(0))
        n = command_argument_count()
        i = 0
        arguments: do while (i < n)
            i = i + 1
            call get_command_argument(i, arg)
            select case (trim(arg))
            case ('-h', '--help')
                cmd%help = .true.
                return
            case ('-V', '-v', '--version')
                cmd%show_version = .true.
                return
            case ('-o', '--output', '-j', '--jobs', '--shard')
                if (i == n) then
                    call new_error(err, EXIT_INPUT, 'option '//trim(arg)//' needs '// &
                                   trim(value_name(trim(arg))))
                    return
                end if
                i = i + 1
                call read_option_value(trim(arg), next_argument(i), cmd, err)
                if (allocated(err)) return
            case ('--no-figures')
                cmd%options%figures = .false.
            case ('--no-html')
                cmd%options%record = .false.
            case ('--no-estimates')
                cmd%options%estimates = .false.
            case ('--full-model')
                cmd%options%full_model = .true.
            case ('--merge')
                cmd%merge = .true.
            case ('-q', '--quiet')
                cmd%quiet = .true.
            case ('--progress')
                cmd%progress_forced = .true.
            case ('--')
                ! (a separate index: an implied-do may not use its own variable in its limits)
                cmd%decks = [character(len=1024) :: cmd%decks, (next_argument(k), k=i + 1, n)]
                exit arguments
            case default
                if (arg(1:1) == '-') then
                    call new_error(err, EXIT_INPUT, 'unknown option '//trim(arg))
                    return
                end if
                cmd%decks = [character(len=1024) :: cmd%decks, arg]
            end select
        end do arguments
    end subroutine read_command_line

    !> What an option that takes a value needs, for the message when it is missing.
    pure function value_name(option) result(text)
        character(len=*), intent(in) :: option   !! -o, -j, --shard or a long form
        character(len=:), allocatable :: text
        select case (option)
        case ('-o', '--output')
            text = 'a folder'
        case ('-j', '--jobs')
            text = 'a number of cases'
        case default
            text = 'I/N'
        end select
    end function value_name

    !> The value of -o, -j or --shard.
    subroutine read_option_value(option, value, cmd, err)
        character(len=*), intent(in) :: option            !! the option
        character(len=*), intent(in) :: value             !! the argument after it
        type(command_t), intent(inout) :: cmd             !! gets the value
        type(error_t), allocatable, intent(out) :: err    !! a value that does not fit
        integer :: ios
        select case (option)
        case ('-o', '--output')
            cmd%out_dir = value
        case ('-j', '--jobs')
            read (value, *, iostat=ios) cmd%options%threads
            if (ios /= 0 .or. cmd%options%threads < 1) call new_error(err, EXIT_INPUT, &
                '--jobs needs a whole number >= 1, got '//trim(value))
        case default
            call read_shard(trim(value), cmd%options, err)
        end select
    end subroutine read_option_value

    !> --shard I/N: this run solves cases I, I+N, I+2N, ... of each sweep (1 <= I <= N).
    subroutine read_shard(text, options, err)
        character(len=*), intent(in) :: text              !! I/N
        type(run_options_t), intent(inout) :: options     !! gets shard_index, shard_count
        type(error_t), allocatable, intent(out) :: err    !! not of the form I/N
        integer :: slash, ios1, ios2
        slash = index(text, '/')
        ios1 = 1
        ios2 = 1
        if (slash > 1) then
            read (text(1:slash - 1), *, iostat=ios1) options%shard_index
            read (text(slash + 1:), *, iostat=ios2) options%shard_count
        end if
        if (ios1 /= 0 .or. ios2 /= 0) then
            call new_error(err, EXIT_INPUT, '--shard needs I/N such as 3/8, got '//text)
        else if (options%shard_count < 1 .or. options%shard_index < 1 .or. &
                 options%shard_index > options%shard_count) then
            call new_error(err, EXIT_INPUT, '--shard I/N needs 1 <= I <= N, got '//text)
        end if
    end subroutine read_shard

    function next_argument(i) result(arg)
        integer, intent(in) :: i   !! argument number
        character(len=1024) :: arg
        call get_command_argument(i, arg)
    end function next_argument

    !> The text of --help.
    pure function usage_lines() result(lines)
        character(len=120), allocatable :: lines(:)
        lines = [character(len=120) :: &
            'usage: fricon [options] [DECK...]', &
            '       fricon --merge [-o DIR] [--no-figures] SHARD...', &
            '', &
            'Solves each card-image DECK: a beam or circular raft on an elastic half-space with', &
            'lift-off and friction. Without a DECK, solves the built-in default raft '// &
            '(input/default.dat).', &
            '', &
            'options:', &
            '  -o, --output DIR  write the outputs under DIR (default: output/ in the current '// &
            'folder,', &
            '                    output/SUB for a deck in input/SUB/)', &
            '      --no-figures  write each figure script (.gp) but do not run gnuplot', &
            '      --no-html     no calculation record (CASE.html) per case', &
            '      --no-estimates  no error estimates (they re-solve each case on 2 N_e, '// &
                'N_e/2, N_e/4,', &
            '                    4 N_e where N_e <= 128, N_e +- 1 where N_e > 128 or a '// &
                'concentrated', &
            '                    load lies inside the base)', &
            '      --full-model  no simplifications (half beam, no sigma_x at f = 0, settled '// &
            'lift-off', &
            '                    decoupled in the factorisation): the full model', &
            '  -j, --jobs N      solve N cases of a sweep at once (default: all cores)', &
            '      --shard I/N   solve cases I, I+N, I+2N, ... of each sweep only (a job array:', &
            '                    fricon --merge joins the shard summaries)', &
            '      --merge SHARD...  join the shard summaries STEM_summary.shard-I-of-N.csv of', &
            '                    a sweep into STEM_summary.csv and its response figure, and a', &
            '                    deck with load combinations into STEM_envelope.* too (in -o', &
            '                    DIR or the first shard''s folder); every shard, no case twice', &
            '  -q, --quiet       no progress on standard error', &
            '      --progress    progress even when standard error is not a terminal', &
            '  -h, --help        this text', &
            '  -V, --version     the version', &
            '', &
            'Each case writes CASE.txt (report), .dat, .csv, .json, .gp, .png and .html (the', &
            'printable calculation record); README.md and doc/OUTPUT.md describe the decks and', &
            'the outputs.', &
            'Exit status: the worst of the decks: 0 solved, 1 input or file error, 2 analysis '// &
            'failed, 3 internal error.']
    end function usage_lines
end module command_line
