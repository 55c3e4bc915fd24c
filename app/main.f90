!> fricon: `fricon [DECK]`. Without a deck, solves the embedded default raft (input/default.dat).
!! Exit status: 0 solved, 1 input or file error, 2 analysis failed, 3 internal error.
program fricon
    use iso_fortran_env, only: error_unit, output_unit
    use iso_c_binding, only: c_int
    use errors, only: error_t, EXIT_OK
    use gsl_wrappers, only: gsl_start
    use deck_reader, only: deck_t, read_deck, parse_deck, default_deck_lines
    use analysis_driver, only: run_analysis
    implicit none
    interface
        ! void exit(int status);  (the C library: ends without the runtime's "STOP n" line)
        subroutine c_exit(status) bind(c, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
    end interface
    type(deck_t) :: deck
    type(error_t), allocatable :: err
    character(len=80), allocatable :: lines(:)
    character(len=1024) :: path
    integer :: status

    path = ''
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
    call run_analysis(deck, output_directory(trim(path)), output_unit, error_unit, status)
    call finish(status)

contains

    !> output/, or output/SUB/ for a deck under input/SUB/ (e.g. input/paper/ -> output/paper/).
    function output_directory(deck_path) result(dir)
        character(len=*), intent(in) :: deck_path
        character(len=:), allocatable :: dir
        integer :: i, j
        dir = 'output'
        i = index(deck_path, 'input/', back=.true.)
        j = index(deck_path, '/', back=.true.)
        if (i == 0 .or. j <= i + 5) return
        if (i > 1) then
            if (deck_path(i - 1:i - 1) /= '/') return
        end if
        dir = 'output/'//deck_path(i + 6:j - 1)
    end function output_directory

    !> Flush and end with the exit status, without the runtime's "STOP n" line on standard
    !! error (a Fortran STOP with a code prints one).
    subroutine finish(code)
        integer, intent(in) :: code
        flush (output_unit)
        flush (error_unit)
        call c_exit(int(code, c_int))
    end subroutine finish
end program fricon
