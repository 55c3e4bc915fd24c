!> One call of fricon over its decks: each deck read and run in turn (without a deck, the
!! embedded default raft), into output/ or output/SUB for a deck in input/SUB/, after a check
!! that the decks of one call cannot write the same file or overwrite one another.
module deck_runs
    use iso_fortran_env, only: error_unit, output_unit
    use errors, only: error_t, EXIT_OK, EXIT_INPUT
    use deck_reader, only: deck_t, read_deck, parse_deck, default_deck_lines, case_count, &
                           combination_names
    use analysis_driver, only: run_analysis, run_options_t
    use output_paths, only: check_decks_apart, remove_stale_outputs
    implicit none
    private

    public :: run_decks

contains

    !> Run every deck (none: the default raft); status: the worst exit status of the decks.
    subroutine run_decks(decks, out_dir, options, status)
        character(len=*), intent(in) :: decks(:)          !! deck paths, in order
        character(len=*), intent(in) :: out_dir           !! -o DIR, or '' (by deck folder)
        type(run_options_t), intent(in) :: options        !! how the run behaves
        integer, intent(out) :: status                    !! 0 solved, 1 input, 2 analysis, 3
        type(error_t), allocatable :: err
        integer :: k, deck_status
        status = EXIT_OK
        if (size(decks) == 0) then
            call run_default(out_dir, options, status)
            return
        end if
        call check_distinct_outputs(decks, out_dir, err)
        if (allocated(err)) then
            write (error_unit, '(a)') 'ERROR: '//err%message//' (fricon --help lists the options)'
            status = EXIT_INPUT
            return
        end if
        do k = 1, size(decks)
            call run_deck(trim(decks(k)), out_dir, options, deck_status)
            if (size(decks) > 1) write (output_unit, '(a,i0,a)') 'fricon: '//trim(decks(k))// &
                ': exit status ', deck_status, ' ('//trim(outcome(deck_status))//')'
            status = max(status, deck_status)
        end do
    end subroutine run_decks

    !> Decks of one call that would write the same file, or overwrite one another, are refused
    !! before anything is solved (output_paths::check_decks_apart); a deck that cannot be
    !! read writes nothing and is left to its own error.
    subroutine check_distinct_outputs(decks, out_dir, err)
        character(len=*), intent(in) :: decks(:)          !! deck paths
        character(len=*), intent(in) :: out_dir           !! -o DIR, or ''
        type(error_t), allocatable, intent(out) :: err    !! two decks' outputs collide
        character(len=1024) :: dirs(size(decks)), stems(size(decks))
        integer :: counts(size(decks)), tag_counts(size(decks)), k
        character(len=10), allocatable :: tags(:, :), names(:)
        type(deck_t) :: deck
        if (size(decks) < 2) return
        allocate (tags(0, size(decks)))
        tag_counts = 0
        do k = 1, size(decks)
            dirs(k) = output_directory(trim(decks(k)), out_dir)
            counts(k) = 0
            stems(k) = ''
            call read_deck(trim(decks(k)), deck, err)
            if (allocated(err)) then
                deallocate (err)
                cycle
            end if
            counts(k) = case_count(deck)
            stems(k) = deck%stem
            names = combination_names(deck)
            tag_counts(k) = size(names)
            if (size(names) > size(tags, 1)) tags = widened(tags, size(names))
            tags(1:size(names), k) = names
        end do
        call check_decks_apart(decks, dirs, stems, counts, err, tags, tag_counts)
    end subroutine check_distinct_outputs

    !> The table of combination names with n rows (the new rows blank).
    pure function widened(tags, n) result(wider)
        character(len=10), intent(in) :: tags(:, :)
        integer, intent(in) :: n
        character(len=10), allocatable :: wider(:, :)
        allocate (wider(n, size(tags, 2)))
        wider = ''
        wider(1:size(tags, 1), :) = tags
    end function widened

    !> The built-in default raft (input/default.dat's text), into output/ or -o DIR.
    subroutine run_default(out_dir, options, status)
        character(len=*), intent(in) :: out_dir           !! -o DIR, or ''
        type(run_options_t), intent(in) :: options        !! how the run behaves
        integer, intent(out) :: status                    !! its exit status
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

    !> One deck file.
    subroutine run_deck(path, out_dir, options, status)
        character(len=*), intent(in) :: path              !! the deck
        character(len=*), intent(in) :: out_dir           !! -o DIR, or ''
        type(run_options_t), intent(in) :: options        !! how the run behaves
        integer, intent(out) :: status                    !! its exit status
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
        character(len=*), intent(in) :: deck_path         !! the deck ('' for the default)
        character(len=*), intent(in) :: given             !! -o DIR, or ''
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

    !> The words for an exit status.
    pure function outcome(code) result(text)
        integer, intent(in) :: code   !! exit status
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
end module deck_runs
