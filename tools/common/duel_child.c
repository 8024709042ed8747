/* duel_child.c - duel_evolve started again as a child process that dies with its parent and plays alone (an experiment's runs and ladders). */
#define _GNU_SOURCE /* prctl's PR_SET_PDEATHSIG, and the POSIX calls */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "duel_child.h"

int duel_child_self(char *out, size_t cap)
{
    ssize_t n = readlink("/proc/self/exe", out, cap - 1);
    if (n <= 0 || (size_t)n >= cap - 1)
        return -1;
    out[n] = '\0';
    return 0;
}

pid_t duel_child_spawn(const char *self, char *const *args, int quiet_out)
{
    pid_t parent = getpid(), pid = fork();
    if (pid != 0)
        return pid;
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    if (getppid() != parent)
        _exit(127);
    if (quiet_out) {
        int fd = open("/dev/null", O_WRONLY);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            close(fd);
        }
    }
    setenv("DUEL_MPI", "0", 1); /* a child of an MPI rank plays alone */
    execv(self, args);
    fprintf(stderr, "duel_evolve: cannot start %s: %s\n", self, strerror(errno));
    _exit(127);
}
