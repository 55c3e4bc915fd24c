!> Output files are written completely or not at all: write to NAME.tmp, then rename it to
!! NAME (POSIX rename(2) is atomic within a file system). An earlier NAME that is fricon's
!! output and has no other name becomes NAME.tmp and is overwritten in place, then cut at the
!! end of the new text: rewriting a deck's outputs allocates and frees no inode and no data
!! block (on ext4 a new file and the unlinked old one cost about 0.1 ms a file, more when many
!! files were deleted recently). Meanwhile NAME is absent, never partial. Otherwise a new
!! NAME.tmp is written and an earlier NAME (fricon's) removed just before the rename. Against
!! a crash of the program (kill -9, a full disk, a signal), not a power failure: nothing is
!! fsync'ed.
module atomic_files
    use iso_c_binding, only: c_int, c_char, c_null_char
    use errors, only: error_t, new_error, EXIT_INPUT
    use output_paths, only: looks_like_output
    use file_system, only: size_and_last_byte, file_links, may_write, move_file
    use temporary_cleanup, only: register_temporary, release_temporary
    implicit none
    private
    public :: open_temporary, commit_file, discard_file

    interface
        ! int rename(const char *oldpath, const char *newpath);
        function c_rename(oldpath, newpath) bind(c, name='rename')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: oldpath(*), newpath(*)
            integer(c_int) :: c_rename
        end function c_rename
        ! int unlink(const char *pathname);   (a file only: it fails on a folder)
        function c_unlink(path) bind(c, name='unlink')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: c_unlink
        end function c_unlink
        ! int remove(const char *pathname);
        function c_remove(path) bind(c, name='remove')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: c_remove
        end function c_remove
    end interface

contains

    !> Open `path`.tmp for writing; the unit is returned.
    subroutine open_temporary(path, unit, err)
        character(len=*), intent(in) :: path             !! the final file (written as path.tmp)
        integer, intent(out) :: unit                     !! the open temporary file
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        integer :: ios
        character(len=256) :: msg
        integer :: size_bytes, last
        logical :: moved
        call size_and_last_byte(path//'.tmp', size_bytes, last)   ! -1: none (or no file)
        if (size_bytes >= 0) then
            if (.not. looks_like_output(path//'.tmp')) then
                ! a file of the user's named like a temporary output: not replaced
                call new_error(err, EXIT_INPUT, 'not written: '//path//'.tmp exists and is '// &
                               'not a fricon output; fricon does not overwrite it: rename it '// &
                               'or write elsewhere (-o DIR)')
                return
            end if
        end if
        ! removed by the signal handler if SIGTERM or SIGINT ends the program before commit
        call register_temporary(path//'.tmp')
        ios = 1
        if (reusable(path)) then
            ! overwritten from its start, without truncation (commit_file cuts it)
            open (newunit=unit, file=path//'.tmp', status='old', action='write', &
                  iostat=ios, iomsg=msg)
            ! (not expected after reusable's checks) the earlier output gets its name back
            if (ios /= 0) call move_file(path//'.tmp', path, moved)
        end if
        if (ios /= 0) open (newunit=unit, file=path//'.tmp', status='replace', action='write', &
                            iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call release_temporary(path//'.tmp')
            call new_error(err, EXIT_INPUT, 'cannot write '//path//'.tmp: '//trim(msg))
        end if
    end subroutine open_temporary

    !> An earlier output at `path` (fricon's, by looks_like_output) whose file has no other
    !! name and may be written, moved to `path`.tmp to be rewritten; false (nothing moved)
    !! otherwise. A file with
    !! two names (a hard link kept as a copy) is not rewritten: its other name keeps the
    !! earlier results.
    logical function reusable(path)
        character(len=*), intent(in) :: path
        reusable = .false.
        if (file_links(path) /= 1) return
        ! a file the user made read-only is replaced by a new one, as before
        if (.not. may_write(path)) return
        if (.not. looks_like_output(path)) return
        call move_file(path, path//'.tmp', reusable)
    end function reusable

    !> Close the unit and move `path`.tmp to `path`; if that fails, the temporary file is
    !! removed (no NAME.tmp is left) and the error says why it may have failed.
    subroutine commit_file(path, unit, err)
        character(len=*), intent(in) :: path             !! the final file
        integer, intent(in) :: unit                      !! the open temporary file (open_temporary)
        type(error_t), allocatable, intent(out) :: err   !! allocated on failure
        call move_into_place(path, unit, err)
        call release_temporary(path//'.tmp')
    end subroutine commit_file

    !> commit_file without the signal handler's registration.
    subroutine move_into_place(path, unit, err)
        character(len=*), intent(in) :: path
        integer, intent(in) :: unit
        type(error_t), allocatable, intent(out) :: err
        integer :: ios, written
        character(len=256) :: msg
        msg = ''
        ! the file ends where the text ends (a reused earlier output may be longer): ENDFILE
        ! writes out gfortran's buffer and truncates the file there. A file that a full disk
        ! cut short is thereby filled up to its length with zero bytes: its last byte is then
        ! no line end (complete)
        endfile (unit, iostat=ios, iomsg=msg)
        if (ios /= 0) then
            close (unit, iostat=ios)
            ios = c_remove(path//'.tmp'//c_null_char)
            call new_error(err, EXIT_INPUT, 'cannot write '//path//': '//trim(msg))
            return
        end if
        ! the bytes written, counted by gfortran with what its buffer still holds (-1: unknown)
        inquire (unit=unit, size=written, iostat=ios)
        if (ios /= 0) written = -1
        close (unit, iostat=ios, iomsg=msg)
        if (ios /= 0) then
            ios = c_remove(path//'.tmp'//c_null_char)
            call new_error(err, EXIT_INPUT, 'cannot write '//path//': '//trim(msg))
            return
        end if
        if (.not. complete(path//'.tmp', written)) then
            ! a full disk: gfortran's buffered writes and close report nothing, and the file
            ! is cut at a block boundary (which may fall at a line end) or empty
            ios = c_remove(path//'.tmp'//c_null_char)
            call new_error(err, EXIT_INPUT, 'cannot write '//path//': the file came out '// &
                           'incomplete (is the disk full?)')
            return
        end if
        if (existing_foreign(path)) then
            ! a deck, or any file of the user's, given an output's name: never replaced
            ios = c_remove(path//'.tmp'//c_null_char)
            call new_error(err, EXIT_INPUT, 'not written: '//path//' exists and is not a '// &
                           'fricon output (a deck?); fricon does not overwrite it: rename it '// &
                           'or write elsewhere (-o DIR)')
            return
        end if
        ! the previous file of this name goes first: on ext4 a rename that replaces a file
        ! writes the new file's data out at once (auto_da_alloc, about 80 us a file on the
        ! benchmark machine), a rename to a free name does not. In between the name is absent,
        ! never partial; a folder of that name is not unlinked and makes the rename fail.
        ios = c_unlink(path//c_null_char)
        if (c_rename(path//'.tmp'//c_null_char, path//c_null_char) /= 0) then
            ios = c_remove(path//'.tmp'//c_null_char)
            call new_error(err, EXIT_INPUT, 'cannot write '//path//': it cannot replace what '// &
                           'is there (a folder of that name, or a file or folder without write '// &
                           'permission)')
        end if
    end subroutine move_into_place

    !> A text file written completely: as long as what was written to it (when known), not
    !! empty, and its last byte the end of a line (every file fricon writes through here ends
    !! its last line).
    logical function complete(path, written)
        character(len=*), intent(in) :: path
        integer, intent(in) :: written          !! bytes written; < 0: not known
        integer :: size_bytes, last
        call size_and_last_byte(path, size_bytes, last)
        complete = size_bytes > 0 .and. (written < 0 .or. size_bytes == written) .and. &
                   last == 10
    end function complete

    !> A regular file is at path and does not look like fricon's output (a folder is left to
    !! rename's own error).
    logical function existing_foreign(path)
        character(len=*), intent(in) :: path
        integer :: size_bytes, last
        ! one open tells a readable file (a folder, an unreadable or absent path: size -1)
        call size_and_last_byte(path, size_bytes, last)
        existing_foreign = .false.
        if (size_bytes < 0) return
        existing_foreign = .not. looks_like_output(path)
    end function existing_foreign

    !> Close and delete a temporary file (after a failure).
    subroutine discard_file(unit)
        integer, intent(in) :: unit   !! the open temporary file
        integer :: ios
        character(len=4096) :: name
        name = ''
        inquire (unit=unit, name=name, iostat=ios)
        close (unit, status='delete', iostat=ios)
        if (len_trim(name) > 0) call release_temporary(trim(name))
    end subroutine discard_file
end module atomic_files
