/* gnuplot as a child process that draws one figure after another (figure_renderer.f90):
 * started without a shell, its standard input and output on one end of a socket pair (a
 * socket, so that writing to a gnuplot that has died fails with EPIPE instead of killing
 * fricon with SIGPIPE: send(..., MSG_NOSIGNAL)). Safe to call from several threads at once,
 * each with its own gnuplot. */
#define _GNU_SOURCE
#include <errno.h>
#include <stdlib.h>
#include <spawn.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;
/* temporary_cleanup.c: a signal that ends fricon kills its gnuplots before it removes the
 * temporary figures */
void fricon_register_child(int pid);
void fricon_release_child(int pid);

/* Start gnuplot; *channel receives our end of its standard input and output. The process id,
 * or minus errno (-ENOENT: no gnuplot on the PATH). */
int fricon_gnuplot_start(int *channel)
{
    int ends[2], status;
    pid_t pid;
    char *argv[] = {"gnuplot", NULL};
    posix_spawn_file_actions_t actions;
    /* both ends close on exec: no other child (another thread's gnuplot) inherits them */
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return -errno;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, ends[1], 0);
    posix_spawn_file_actions_adddup2(&actions, ends[1], 1);
    status = posix_spawnp(&pid, "gnuplot", &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(ends[1]);
    if (status != 0) {
        close(ends[0]);
        return -status;
    }
    *channel = ends[0];
    fricon_register_child((int)pid);
    return (int)pid;
}

/* Send the commands (text ending with a line that prints `marker` and gnuplot's error number
 * GPVAL_ERRNO to its standard output) and wait for that line: 0 when gnuplot reports no
 * error, 1 when it reports one, 2 when it is gone (the channel failed or closed first). */
int fricon_gnuplot_draw(int channel, const char *commands, const char *marker)
{
    char window[4096];
    size_t held = 0, sent = 0, total = strlen(commands), n_marker = strlen(marker);
    while (sent < total) {
        ssize_t n = send(channel, commands + sent, total - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return 2;
        sent += (size_t)n;
    }
    for (;;) {
        char *line;
        ssize_t n = recv(channel, window + held, sizeof(window) - 1 - held, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return 2;
        held += (size_t)n;
        window[held] = '\0';
        line = strstr(window, marker);
        if (line != NULL && strchr(line + n_marker, '\n') != NULL) {
            long code = strtol(line + n_marker, NULL, 10);
            return code == 0 ? 0 : 1;
        }
        if (held > sizeof(window) / 2) {
            /* keep the tail, where a marker may have begun */
            memmove(window, window + held - n_marker, n_marker);
            held = n_marker;
        }
    }
}

/* Close our end (gnuplot reads the end of its input and exits) and wait for the process. */
void fricon_gnuplot_stop(int pid, int channel)
{
    int status;
    close(channel);
    while (waitpid((pid_t)pid, &status, 0) < 0 && errno == EINTR) {
    }
    fricon_release_child(pid);
}
