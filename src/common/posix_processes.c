/* Worker processes for hsri2d's studies (report C.8, `--jobs N`), called
 * from Fortran through the module posix_processes
 * (src/common/posix_processes.f90): start a copy of the program with its
 * own arguments, wait for the copies, and tell a terminal (progress is
 * shown only there). Standard Fortran has none of these.
 *
 * Every function returns 0 on success or an errno value; none prints or
 * exits. */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

/* Start the program `path` with the n_args arguments packed one after
 * another in args, each ended by a NUL byte (argv[0] included); *pid is
 * the new process. Its standard streams are this process's. */
int hsri2d_spawn(const char *path, const char *args, int n_args, long *pid)
{
    char **argv;
    const char *p = args;
    pid_t child;
    int i, e;
    argv = calloc((size_t)n_args + 1, sizeof *argv);
    if (argv == NULL) return ENOMEM;
    for (i = 0; i < n_args; i++) {
        argv[i] = (char *)p;
        p += strlen(p) + 1;
    }
    argv[n_args] = NULL;
    e = posix_spawn(&child, path, NULL, NULL, argv, environ);
    free(argv);
    if (e != 0) return e;
    *pid = (long)child;
    return 0;
}

/* Wait for process pid, blocking unless nohang; *done = 1 once it has
 * ended, with *status its exit status (128 + the signal that killed it). */
int hsri2d_wait(long pid, int nohang, int *done, int *status)
{
    int st = 0;
    pid_t r;
    *done = 0;
    *status = 0;
    do {
        r = waitpid((pid_t)pid, &st, nohang ? WNOHANG : 0);
    } while (r < 0 && errno == EINTR);
    if (r < 0) return errno;
    if (r == 0) return 0;
    *done = 1;
    if (WIFEXITED(st)) *status = WEXITSTATUS(st);
    else if (WIFSIGNALED(st)) *status = 128 + WTERMSIG(st);
    return 0;
}

/* 1 when descriptor fd is a terminal. */
int hsri2d_is_terminal(int fd)
{
    return isatty(fd) ? 1 : 0;
}

/* Sleep for ms milliseconds (a worker's progress is polled). */
void hsri2d_sleep_ms(int ms)
{
    struct timespec ts;
    ts.tv_sec = ms / 1000;
    ts.tv_nsec = (long)(ms % 1000) * 1000000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}
