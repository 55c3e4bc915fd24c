/* The POSIX calls of file_system.f90 whose C types Fortran cannot spell portably: mkdir's
 * mode_t, and readdir's struct dirent (its layout differs between systems). */
#include <dirent.h>
#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

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
