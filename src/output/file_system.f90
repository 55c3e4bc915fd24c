!> Files and folders without a shell: create a folder with its parents (mkdir -p), check that
!! files can be created in it, list the names in one that have a given prefix and suffix, read
!! a file's size, last byte and number of names, rename and delete a file. POSIX
!! opendir/closedir, rename and unlink through bind(c) interfaces; mkdir, readdir, stat, lstat
!! and access through the C shim file_system_shim.c (their C types, mode_t, struct dirent
!! and struct stat, differ between systems).
module file_system
    use iso_c_binding, only: c_char, c_int, c_long, c_ptr, c_null_char, c_associated
    implicit none
    private

    integer, parameter :: name_max = 256   !! room for an entry's name and its NUL (NAME_MAX 255)

    interface
        ! int fricon_make_folder(const char *path);   (file_system_shim.c)
        function c_make_folder(path) bind(c, name='fricon_make_folder') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: code
        end function c_make_folder
        ! int fricon_writable_folder(const char *path, char *why, int capacity);   (shim)
        function c_writable_folder(path, why, capacity) bind(c, name='fricon_writable_folder') &
            result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            character(kind=c_char), intent(out) :: why(*)
            integer(c_int), value :: capacity
            integer(c_int) :: code
        end function c_writable_folder
        ! long fricon_size_and_last_byte(const char *path, int *last);   (file_system_shim.c)
        function c_size_and_last_byte(path, last) bind(c, name='fricon_size_and_last_byte') &
            result(size)
            import :: c_char, c_int, c_long
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), intent(out) :: last
            integer(c_long) :: size
        end function c_size_and_last_byte
        ! int fricon_may_write(const char *path);   (file_system_shim.c)
        function c_may_write(path) bind(c, name='fricon_may_write') result(yes)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: yes
        end function c_may_write
        ! long fricon_file_links(const char *path);   (file_system_shim.c)
        function c_file_links(path) bind(c, name='fricon_file_links') result(links)
            import :: c_char, c_long
            character(kind=c_char), intent(in) :: path(*)
            integer(c_long) :: links
        end function c_file_links
        ! DIR *opendir(const char *name);
        function c_opendir(path) bind(c, name='opendir') result(folder)
            import :: c_char, c_ptr
            character(kind=c_char), intent(in) :: path(*)
            type(c_ptr) :: folder
        end function c_opendir
        ! int fricon_next_entry(DIR *folder, char *name, int capacity);   (file_system_shim.c)
        function c_next_entry(folder, name, capacity) bind(c, name='fricon_next_entry') &
            result(length)
            import :: c_ptr, c_char, c_int
            type(c_ptr), value :: folder
            character(kind=c_char), intent(out) :: name(*)
            integer(c_int), value :: capacity
            integer(c_int) :: length
        end function c_next_entry
        ! int rename(const char *oldpath, const char *newpath);
        function c_rename(oldpath, newpath) bind(c, name='rename') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: oldpath(*), newpath(*)
            integer(c_int) :: code
        end function c_rename
        ! int unlink(const char *pathname);   (a file only: it fails on a folder)
        function c_unlink(path) bind(c, name='unlink') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: code
        end function c_unlink
        ! int closedir(DIR *dirp);
        function c_closedir(folder) bind(c, name='closedir') result(code)
            import :: c_ptr, c_int
            type(c_ptr), value :: folder
            integer(c_int) :: code
        end function c_closedir
    end interface

    public :: make_folder, writable_folder, folder_entries, size_and_last_byte, file_links, &
              may_write, move_file, delete_file

contains

    !> Create the folder `path` and any missing parents (as mkdir -p). Success when it is a
    !! folder afterwards (made now or before); else `made` is false (the caller's write
    !! into it says why).
    subroutine make_folder(path, made)
        character(len=*), intent(in) :: path   !! the folder, with its parents
        logical, intent(out) :: made           !! it is a folder afterwards
        integer :: k
        integer(c_int) :: code
        ! each parent first: those that exist answer at once; a failure shows at the last
        parents: do k = 2, len(path)
            if (path(k:k) /= '/' .or. path(k - 1:k - 1) == '/') cycle parents
            code = c_make_folder(path(1:k - 1)//c_null_char)
        end do parents
        code = c_make_folder(path//c_null_char)
        made = code == 0
    end subroutine make_folder

    !> Whether files can be created in the folder `path` (it is a folder, and access(2) grants
    !! writing and searching; a read-only file system is refused too); when not, `why` holds
    !! the system's reason (e.g. 'Permission denied', 'Not a directory').
    subroutine writable_folder(path, writable, why)
        character(len=*), intent(in) :: path                 !! the folder
        logical, intent(out) :: writable                     !! files can be created in it
        character(len=:), allocatable, intent(out) :: why    !! the reason when not
        character(kind=c_char) :: buffer(name_max)
        integer :: n
        buffer = c_null_char
        writable = c_writable_folder(path//c_null_char, buffer, int(name_max, c_int)) == 0
        n = 0
        do while (n < name_max)
            if (buffer(n + 1) == c_null_char) exit
            n = n + 1
        end do
        why = chars_text(buffer, int(n, c_int))
    end subroutine writable_folder

    !> The size in bytes of the file at `path` (-1 when it cannot be opened or read) and its
    !! last byte (-1 when the file is empty or unreadable): one open, fstat, pread and close.
    subroutine size_and_last_byte(path, size_bytes, last)
        character(len=*), intent(in) :: path       !! the file
        integer, intent(out) :: size_bytes         !! its size [bytes], or -1
        integer, intent(out) :: last               !! its last byte (0..255), or -1
        integer(c_int) :: byte
        size_bytes = int(c_size_and_last_byte(path//c_null_char, byte))
        last = int(byte)
    end subroutine size_and_last_byte

    !> Whether this process may write the file at `path` (access(2)). Not Fortran's INQUIRE
    !! (WRITE=): gfortran's INQUIRE by file name waits for every open unit's lock, so a thread
    !! writing a case's files waited for another thread's gnuplot to answer, and a sweep's
    !! figures no longer used the second core.
    logical function may_write(path)
        character(len=*), intent(in) :: path   !! the file
        may_write = c_may_write(path//c_null_char) == 1
    end function may_write

    !> The number of names (hard links) of the regular file at `path`; -1 when there is no
    !! regular file there (nothing, a folder, a symbolic link).
    integer function file_links(path)
        character(len=*), intent(in) :: path   !! the file
        file_links = int(c_file_links(path//c_null_char))
    end function file_links

    !> The names in folder `dir` that start with `prefix` and end with `suffix`, read in one
    !! pass over the folder; `listed` is false when the folder cannot be read (it does not
    !! exist, or is no folder), and then names is empty.
    subroutine folder_entries(dir, prefix, suffix, names, listed)
        !> the folder; the start and the end of the names wanted
        character(len=*), intent(in) :: dir, prefix, suffix
        character(len=:), allocatable, intent(out) :: names(:)   !! the names found
        logical, intent(out) :: listed                           !! the folder could be read
        character(len=name_max), allocatable :: found(:)
        character(kind=c_char) :: buffer(name_max)
        type(c_ptr) :: folder
        integer(c_int) :: length, code
        integer :: n, m, width
        allocate (found(0))
        n = 0
        width = 1
        folder = c_opendir(dir//c_null_char)
        listed = c_associated(folder)
        if (listed) then
            entries: do
                length = c_next_entry(folder, buffer, int(name_max, c_int))
                if (length == -1) exit entries
                if (length < len(prefix) + len(suffix)) cycle entries   ! (-2: too long)
                if (.not. starts_with(buffer, prefix)) cycle entries
                if (n == size(found)) call grow(found)
                m = int(length)
                found(n + 1) = chars_text(buffer, length)
                if (found(n + 1)(m - len(suffix) + 1:m) /= suffix) cycle entries
                n = n + 1
                width = max(width, m)
            end do entries
            code = c_closedir(folder)
        end if
        allocate (character(len=width) :: names(n))
        names = found(1:n)
    end subroutine folder_entries

    !> Rename `from` to `to` (rename(2): atomic, replaces a file at `to`, never moves into a
    !! folder of that name); moved says whether it was done.
    subroutine move_file(from, to, moved)
        character(len=*), intent(in) :: from, to   !! the file and its new path
        logical, intent(out) :: moved              !! the rename was done
        moved = c_rename(from//c_null_char, to//c_null_char) == 0
    end subroutine move_file

    !> Delete the file at path, if there is one (unlink(2): never a folder).
    subroutine delete_file(path)
        character(len=*), intent(in) :: path   !! the file (nothing happens if there is none)
        integer(c_int) :: code
        code = c_unlink(path//c_null_char)
    end subroutine delete_file

    !> The first len(prefix) characters of buffer are prefix.
    pure logical function starts_with(buffer, prefix)
        character(kind=c_char), intent(in) :: buffer(:)
        character(len=*), intent(in) :: prefix
        integer :: i
        starts_with = .false.
        do i = 1, len(prefix)
            if (buffer(i) /= prefix(i:i)) return
        end do
        starts_with = .true.
    end function starts_with

    !> The first n characters of a C character array as a Fortran string.
    pure function chars_text(buffer, n) result(text)
        character(kind=c_char), intent(in) :: buffer(:)
        integer(c_int), intent(in) :: n
        character(len=n) :: text
        integer :: i
        do i = 1, n
            text(i:i) = buffer(i)
        end do
    end function chars_text

    !> Twice the room (at least 16), the names kept.
    pure subroutine grow(names)
        character(len=name_max), allocatable, intent(inout) :: names(:)
        character(len=name_max), allocatable :: larger(:)
        allocate (larger(max(16, 2*size(names))))
        larger(1:size(names)) = names
        call move_alloc(larger, names)
    end subroutine grow
end module file_system
