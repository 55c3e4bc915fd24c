!> Temporary output files (NAME.tmp) are removed when the program is ended by SIGTERM or
!! SIGINT: a thin interface to temporary_cleanup.c, whose signal handler unlinks the
!! registered paths and re-raises the signal (async-signal-safe; the C file says how).
!! `install_cleanup` once at start-up; `register_temporary` before a temporary file is
!! created, `release_temporary` once it is renamed or removed. SIGKILL cannot be caught: its
!! .tmp files are removed by the next run of the deck (output_paths).
module temporary_cleanup
    use iso_c_binding, only: c_int, c_char
    implicit none
    private
    public :: install_cleanup, register_temporary, release_temporary

    interface
        ! int fricon_install_cleanup(void);
        function c_install_cleanup() bind(c, name='fricon_install_cleanup')
            import :: c_int
            integer(c_int) :: c_install_cleanup
        end function c_install_cleanup
        ! void fricon_register_temporary(const char *path, int length);
        subroutine c_register_temporary(path, length) bind(c, name='fricon_register_temporary')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), value :: length
        end subroutine c_register_temporary
        ! void fricon_release_temporary(const char *path, int length);
        subroutine c_release_temporary(path, length) bind(c, name='fricon_release_temporary')
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), value :: length
        end subroutine c_release_temporary
    end interface

contains

    !> Install the handler (SIGTERM; SIGINT unless ignored); .false. if it could not be.
    logical function install_cleanup()
        install_cleanup = c_install_cleanup() == 0_c_int
    end function install_cleanup

    !> path (a NAME.tmp about to be created) is removed if a signal ends the program.
    subroutine register_temporary(path)
        character(len=*), intent(in) :: path   !! a NAME.tmp about to be created
        call c_register_temporary(path, int(len(path), c_int))
    end subroutine register_temporary

    !> path is no longer a temporary file of the program (renamed or removed).
    subroutine release_temporary(path)
        character(len=*), intent(in) :: path   !! the NAME.tmp renamed or removed
        call c_release_temporary(path, int(len(path), c_int))
    end subroutine release_temporary
end module temporary_cleanup
