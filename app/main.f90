!> fricon [options] [DECK...]: solves each deck (without a deck, the embedded default raft).
!! Exit status: the worst of the decks: 0 solved, 1 input or file error, 2 analysis failed,
!! 3 internal error. The program only reads its command line, runs the decks and ends with
!! their status; everything else lives in src/ (doc/ARCHITECTURE.md).
program fricon
    use iso_fortran_env, only: error_unit, output_unit
    use iso_c_binding, only: c_int
    use errors, only: error_t, EXIT_OK
    use start_up, only: start_program
    use command_line, only: command_t, read_command_line, usage_lines, version
    use deck_runs, only: run_decks
    use shard_merge, only: run_merge
    use output_paths, only: stderr_is_terminal
    use temporary_cleanup, only: install_cleanup
    implicit none
    interface
        ! void exit(int status);  (the C library: ends without the runtime's "STOP n" line)
        subroutine c_exit(status) bind(c, name='exit')
            import :: c_int
            integer(c_int), value :: status
        end subroutine c_exit
    end interface
    type(command_t) :: cmd
    type(error_t), allocatable :: err
    integer :: status, k
    character(len=120), allocatable :: lines(:)

    ! SIGTERM and SIGINT remove the temporary files of the case being written
    if (.not. install_cleanup()) write (error_unit, '(a)') 'fricon: warning: no signal '// &
        'handler: a SIGTERM or SIGINT may leave NAME.tmp files (the next run removes them)'
    call read_command_line(cmd, err)
    if (allocated(err)) then
        write (error_unit, '(a)') 'ERROR: '//err%message//' (fricon --help lists the options)'
        call finish(err%code)
    else if (cmd%help) then
        lines = usage_lines()
        write (output_unit, '(a)') (trim(lines(k)), k=1, size(lines))
        call finish(EXIT_OK)
    else if (cmd%show_version) then
        write (output_unit, '(a)') 'fricon '//version
        call finish(EXIT_OK)
    end if
    cmd%options%progress = cmd%progress_forced .or. (.not. cmd%quiet .and. stderr_is_terminal())
    call start_program()
    if (cmd%merge) then
        call run_merge(cmd%decks, trim(cmd%out_dir), cmd%options%figures, cmd%quiet, status)
        call finish(status)
    end if
    call run_decks(cmd%decks, trim(cmd%out_dir), cmd%options, status)
    call finish(status)

contains

    !> Flush and end with the exit status, without the runtime's "STOP n" line on standard
    !! error (a Fortran STOP with a code prints one).
    subroutine finish(code)
        integer, intent(in) :: code   !! exit status
        flush (output_unit)
        flush (error_unit)
        call c_exit(int(code, c_int))
    end subroutine finish
end program fricon
