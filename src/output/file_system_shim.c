/* The POSIX calls of file_system.f90 whose C types Fortran cannot spell portably: mkdir's
 * mode_t, readdir's struct dirent and stat's struct stat (their layouts differ between
 * systems). */
#include <dirent.h>
#include <fcntl.h>
#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* mkdir(path, 0777) (less the umask): 0 when made, or when a folder is there already;
 * else errno (a file of that name: EEXIST). */
int fricon_make_folder(const char *path)
{
    struct stat st;
    if (mkdir(path, 0777) == 0) return 0;
    if (errno == EEXIST && stat(path, &st) == 0 && S_ISDIR(st.st_mode)) return 0;
    return errno;
}

/* The name of the next entry of an opendir() stream copied into name (capacity bytes, NUL
 * terminated): its length; -1 at the end of the folder; -2 when it does not fit. */
int fricon_next_entry(DIR *folder, char *name, int capacity)
{
    struct dirent *entry = readdir(folder);
    size_t n;
    if (entry == NULL) return -1;
    n = strlen(entry->d_name);
    if (n >= (size_t)capacity) return -2;
    memcpy(name, entry->d_name, n + 1);
    return (int)n;
}

/* 0 when path is a folder this process may create files in (access(2) with W_OK | X_OK, which
 * also answers EROFS for a read-only file system); else errno (ENOTDIR when it is no folder),
 * and the system's text for it copied into why (capacity bytes, NUL terminated). One stat and
 * one access: no probe file is created and unlinked (an inode made and freed on every run). */
int fricon_writable_folder(const char *path, char *why, int capacity)
{
    struct stat st;
    int code = 0;
    if (stat(path, &st) != 0) code = errno;
    else if (!S_ISDIR(st.st_mode)) code = ENOTDIR;
    else if (access(path, W_OK | X_OK) != 0) code = errno;
    if (code != 0 && capacity > 0) {
        strncpy(why, strerror(code), (size_t)capacity - 1);
        why[capacity - 1] = '\0';
    }
    return code;
}

/* The size of the file at path in bytes and its last byte (-1 when it is empty), read with
 * one open, fstat, pread and close; -1 when it cannot be opened or read. */
long fricon_size_and_last_byte(const char *path, int *last)
{
    struct stat st;
    unsigned char byte;
    long size = -1;
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    *last = -1;
    if (fd < 0) return -1;
    if (fstat(fd, &st) == 0) {
        size = (long)st.st_size;
        if (size > 0) {
            if (pread(fd, &byte, 1, (off_t)(size - 1)) == 1) *last = byte;
            else size = -1;
        }
    }
    close(fd);
    return size;
}

/* The number of names (hard links) of the regular file at path; -1 when there is none there,
 * or it is no regular file (lstat: a symbolic link counts as no regular file). */
long fricon_file_links(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode)) return -1;
    return (long)st.st_nlink;
}

/* 1 when this process may write the file at path (access(2), W_OK), else 0. */
int fricon_may_write(const char *path)
{
    return access(path, W_OK) == 0;
}
