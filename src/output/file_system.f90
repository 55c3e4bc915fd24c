!> Files and folders without a shell: create a folder with its parents (mkdir -p), list the
!! names in one that have a given prefix and suffix, rename and delete a file. POSIX
!! opendir/closedir, rename and remove through bind(c) interfaces; mkdir and readdir through
!! the small C shim file_system_shim.c (their C types, mode_t and struct dirent, differ
!! between systems).
module file_system
    use iso_c_binding, only: c_char, c_int, c_ptr, c_null_char, c_associated
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
        ! int remove(const char *pathname);
        function c_remove(path) bind(c, name='remove') result(code)
            import :: c_char, c_int
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int) :: code
        end function c_remove
        ! int closedir(DIR *dirp);
        function c_closedir(folder) bind(c, name='closedir') result(code)
            import :: c_ptr, c_int
            type(c_ptr), value :: folder
            integer(c_int) :: code
        end function c_closedir
    end interface

    public :: make_folder, folder_entries, move_file, delete_file

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

    !> Delete the file at path, if there is one.
    subroutine delete_file(path)
        character(len=*), intent(in) :: path   !! the file (nothing happens if there is none)
        integer(c_int) :: code
        code = c_remove(path//c_null_char)
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
