/* Temporary output files removed when the program is ended by SIGTERM or SIGINT.
 *
 * A fixed table of path slots (no allocation, no locks): fricon_register_temporary copies
 * a NAME.tmp path into a free slot before the file is created, fricon_release_temporary
 * frees the slot once the file is renamed or removed. The handler only reads the slots that
 * are ready and calls unlink(2), then restores the default action and re-raises the signal
 * (both async-signal-safe: POSIX.1-2008, signal-safety(7)), so the process still ends "killed
 * by SIGTERM" (exit status 143 in a shell) or SIGINT (130). A slot's state goes
 * free -> filling -> ready -> free with atomic operations, so concurrent registration from
 * OpenMP threads and a handler running on any thread see either no path or a whole one. A
 * path longer than the slot, or more temporary files than slots at once, is not registered
 * (it would only be left behind, as without this module); fricon writes one case's files
 * at a time, so a few slots per thread suffice. */
#include <signal.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define SLOTS 64
#define PATH_BYTES 4096

enum { FREE = 0, FILLING = 1, READY = 2 };

static volatile int state[SLOTS];
static char paths[SLOTS][PATH_BYTES];
/* set by the handler before anything else: no thread registers (and so creates) a temporary
 * file after it */
static volatile int terminating;
/* the program's child processes (its gnuplots, which write NAME.png.tmp): killed first */
#define CHILDREN 64
static volatile int children[CHILDREN];

static void unlink_ready(void)
{
    int k;
    for (k = 0; k < SLOTS; k++) {
        if (__atomic_load_n(&state[k], __ATOMIC_ACQUIRE) == READY)
            unlink(paths[k]);
    }
}

/* Another thread may have registered a path just before the flag was set and create its file
 * just after the first sweep (seen: 1 of 20 rounds of scripts/signal_test.sh left a .tmp),
 * so the handler sweeps again 50 ms later (nanosleep is async-signal-safe); a thread that
 * comes to register after the flag waits in pause() until the re-raised signal ends the
 * process, and creates nothing. */
static void remove_temporaries(int sig)
{
    const struct timespec grace = {0, 50000000L};
    int k, pid;
    __atomic_store_n(&terminating, 1, __ATOMIC_SEQ_CST);
    for (k = 0; k < CHILDREN; k++) {
        pid = __atomic_load_n(&children[k], __ATOMIC_ACQUIRE);
        if (pid > 0) kill((pid_t)pid, SIGKILL);
    }
    unlink_ready();
    nanosleep(&grace, NULL);
    unlink_ready();
    signal(sig, SIG_DFL);
    raise(sig);
}

/* Install the handler for SIGTERM, and for SIGINT unless it is ignored (a background job of
 * a shell without job control, or nohup: the caller chose to ignore it). 0 on success. */
int fricon_install_cleanup(void)
{
    struct sigaction action, previous;
    memset(&action, 0, sizeof action);
    action.sa_handler = remove_temporaries;
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGTERM);
    sigaddset(&action.sa_mask, SIGINT);
    if (sigaction(SIGTERM, &action, NULL) != 0) return -1;
    if (sigaction(SIGINT, NULL, &previous) != 0) return -1;
    if (previous.sa_handler == SIG_IGN) return 0;
    return sigaction(SIGINT, &action, NULL);
}

/* Register path (length bytes, not NUL-terminated) as a temporary file. */
void fricon_register_temporary(const char *path, int length)
{
    int k, expected;
    if (length <= 0 || length >= PATH_BYTES) return;
    while (__atomic_load_n(&terminating, __ATOMIC_SEQ_CST))
        pause();
    for (k = 0; k < SLOTS; k++) {
        expected = FREE;
        if (__atomic_compare_exchange_n(&state[k], &expected, FILLING, 0, __ATOMIC_ACQ_REL,
                                        __ATOMIC_RELAXED)) {
            memcpy(paths[k], path, (size_t)length);
            paths[k][length] = '\0';
            __atomic_store_n(&state[k], READY, __ATOMIC_RELEASE);
            return;
        }
    }
}

/* Forget path (renamed or removed by the program). */
void fricon_release_temporary(const char *path, int length)
{
    int k;
    if (length <= 0 || length >= PATH_BYTES) return;
    for (k = 0; k < SLOTS; k++) {
        if (__atomic_load_n(&state[k], __ATOMIC_ACQUIRE) != READY) continue;
        if (strncmp(paths[k], path, (size_t)length) == 0 && paths[k][length] == '\0') {
            __atomic_store_n(&state[k], FREE, __ATOMIC_RELEASE);
            return;
        }
    }
}

/* Register a child process (a gnuplot that writes temporary figures): killed by the handler
 * before it removes the temporary files, so that it cannot write one after them. fricon runs
 * one gnuplot per thread; a child beyond the table's 64 is not registered (it is then only
 * covered by the handler's second sweep). */
void fricon_register_child(int pid)
{
    int k, expected;
    for (k = 0; k < CHILDREN; k++) {
        expected = 0;
        if (__atomic_compare_exchange_n(&children[k], &expected, pid, 0, __ATOMIC_ACQ_REL,
                                        __ATOMIC_RELAXED))
            return;
    }
}

/* Forget a child process (it was waited for). */
void fricon_release_child(int pid)
{
    int k, expected;
    for (k = 0; k < CHILDREN; k++) {
        expected = pid;
        if (__atomic_compare_exchange_n(&children[k], &expected, 0, 0, __ATOMIC_ACQ_REL,
                                        __ATOMIC_RELAXED))
            return;
    }
}
