!> fricon: `fricon [DECK]`. Without a deck, solves the embedded default raft (input/default.dat).
!! Exit status: 0 solved, 1 input or file error, 2 analysis failed, 3 internal error.
program fricon
    use iso_fortran_env, only: error_unit, output_unit
    use errors, only: error_t, EXIT_OK
    use gsl_wrappers, only: gsl_start
    use deck_reader, only: deck_t, read_deck, parse_deck, default_deck_lines
    use analysis_driver, only: run_analysis
    implicit none
    type(deck_t) :: deck
    type(error_t), allocatable :: err
    character(len=80), allocatable :: lines(:)
    character(len=1024) :: path
    integer :: status

    call gsl_start()
    if (command_argument_count() >= 1) then
        call get_command_argument(1, path)
        call read_deck(trim(path), deck, err)
    else
        call default_deck_lines(lines)
        call parse_deck('input/default.dat', lines, deck, err)
    end if
    if (allocated(err)) then
        write (error_unit, '(a)') 'ERROR: '//err%message
        call finish(err%code)
    end if
    call run_analysis(deck, 'output', output_unit, error_unit, status)
    call finish(status)

contains

    !> Fortran 2008 allows only constant stop codes, hence the select.
    subroutine finish(code)
        integer, intent(in) :: code
        flush (output_unit)
        select case (code)
        case (EXIT_OK)
            stop
        case (1)
            stop 1
        case (2)
            stop 2
        case default
            stop 3
        end select
    end subroutine finish
end program fricon
