!> Where a run writes, checked before anything is solved: the output folder must be writable,
!! and no output file may be the deck itself (decks and data files may share the extension
!! .dat). POSIX calls (realpath, isatty) through thin bind(c) interfaces.
module output_paths
    use iso_c_binding, only: c_char, c_int, c_ptr, c_null_char, c_associated
    use errors, only: error_t, new_error, EXIT_INPUT
    implicit none
    private

    integer, parameter :: path_max = 4096

    !> The extensions fricon writes (a case: NAME.ext; a sweep also STEM_summary.csv and
    !! STEM_sweep.gp, .png).
    character(len=*), parameter :: output_extensions(6) = ['.txt ', '.dat ', '.csv ', &
                                                           '.json', '.gp  ', '.png ']

    interface
        ! char *realpath(const char *path, char *resolved_path);
        function c_realpath(path, resolved) bind(c, name='realpath') result(p)
            import :: c_char, c_ptr
            character(kind=c_char), intent(in) :: path(*)
            character(kind=c_char), intent(out) :: resolved(*)
            type(c_ptr) :: p
        end function c_realpath
        ! int isatty(int fd);
        function c_isatty(fd) bind(c, name='isatty') result(yes)
            import :: c_int
            integer(c_int), value :: fd
            integer(c_int) :: yes
        end function c_isatty
    end interface

    public :: prepare_output_dir, check_deck_not_overwritten, stderr_is_terminal

contains

    !> Create the folder (and its parents) and prove it writable with a probe file; an error
    !! (exit status 1) names the folder and the reason.
    subroutine prepare_output_dir(dir, err)
        character(len=*), intent(in) :: dir
        type(error_t), allocatable, intent(out) :: err
        integer :: u, ios, exit_status, cmd_status
        character(len=256) :: msg
        if (scan(dir, '''"`$\') > 0) then
            call new_error(err, EXIT_INPUT, 'output folder '''//dir//''': quotes, backquotes, '// &
                           '$ and \ are not allowed in its name')
            return
        end if
        call execute_command_line("mkdir -p -- '"//dir//"' 2>/dev/null", exitstat=exit_status, &
                                  cmdstat=cmd_status)
        open (newunit=u, file=dir//'/.fricon_write_probe', status='replace', action='write', &
              iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call new_error(err, EXIT_INPUT, 'cannot write to the output folder '//dir//': '// &
                           trim(msg)//' (is it a file, or read-only?)')
            return
        end if
        close (u, status='delete', iostat=ios)
    end subroutine prepare_output_dir

    !> Refuse (exit status 1) when an output of the deck would be the deck itself: the deck
    !! lies in the output folder and is named STEM.ext with an extension fricon writes.
    subroutine check_deck_not_overwritten(deck_path, dir, stem, err)
        character(len=*), intent(in) :: deck_path, dir, stem
        type(error_t), allocatable, intent(out) :: err
        character(len=:), allocatable :: deck_real, dir_real
        integer :: k
        deck_real = real_path(deck_path)
        dir_real = real_path(dir)
        if (len(deck_real) == 0 .or. len(dir_real) == 0) return
        do k = 1, size(output_extensions)
            if (deck_real == dir_real//'/'//stem//trim(output_extensions(k))) then
                call new_error(err, EXIT_INPUT, 'the deck '//deck_path//' lies in the output '// &
                    'folder '//dir//' and would be overwritten by its own '// &
                    trim(output_extensions(k))//' output: give another folder (-o DIR) or '// &
                    'rename the deck (decks are not overwritten)')
                return
            end if
        end do
    end subroutine check_deck_not_overwritten

    !> The canonical absolute path of an existing file or folder; '' if it cannot be resolved.
    function real_path(path) result(resolved)
        character(len=*), intent(in) :: path
        character(len=:), allocatable :: resolved
        character(kind=c_char) :: buffer(path_max)
        integer :: n
        buffer = c_null_char
        resolved = ''
        if (.not. c_associated(c_realpath(path//c_null_char, buffer))) return
        n = 0
        do while (n < path_max)
            if (buffer(n + 1) == c_null_char) exit
            n = n + 1
        end do
        resolved = repeat(' ', n)
        do n = 1, len(resolved)
            resolved(n:n) = buffer(n)
        end do
    end function real_path

    !> Standard error (file descriptor 2) is a terminal: progress is shown by default.
    logical function stderr_is_terminal()
        stderr_is_terminal = c_isatty(2_c_int) == 1
    end function stderr_is_terminal
end module output_paths
