/* duel_exec.c - PATH lookup and running an external program (ffmpeg, dot) with its stderr captured, for the render commands. */
#define _GNU_SOURCE /* prctl(PR_SET_PDEATHSIG): a child dies with its parent (Linux) */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "duel_exec.h"

extern char **environ;

int duel_exec_find(const char *name, char *buf, size_t len)
{
    const char *path = getenv("PATH"), *p, *end;
    struct stat st;
    if (path == NULL)
        path = "/usr/local/bin:/usr/bin:/bin";
    for (p = path;; p = end + 1) {
        size_t n;
        int w;
        end = strchr(p, ':');
        if (end == NULL)
            end = p + strlen(p);
        n = (size_t)(end - p);
        w = n == 0 ? snprintf(buf, len, "./%s", name) : snprintf(buf, len, "%.*s/%s", (int)n, p, name);
        if (w >= 0 && (size_t)w < len && stat(buf, &st) == 0 && S_ISREG(st.st_mode) && access(buf, X_OK) == 0)
            return 0;
        if (*end == '\0')
            break;
    }
    if (len > 0)
        buf[0] = '\0';
    return -1;
}

/* Keeps the last non-empty line of the text read so far: line is the one
 * being read (cur bytes), msg the last complete one. */
static void duel_exec_keep(char *line, size_t *cur, size_t cap, const char *data, size_t n, char *msg, size_t msg_len)
{
    size_t i;
    for (i = 0; i < n; i++) {
        char c = data[i];
        if (c == '\n' || c == '\r') {
            if (*cur > 0) {
                line[*cur] = '\0';
                snprintf(msg, msg_len, "%s", line);
                *cur = 0;
            }
        } else if (*cur + 1 < cap) {
            line[(*cur)++] = (unsigned char)c < 0x20 ? ' ' : c;
        }
    }
}

int duel_exec_run(const char *path, char *const argv[], char *msg, size_t msg_len)
{
    char line[512], data[512];
    size_t cur = 0;
    int pipefd[2], status, errpipe[2], child_err = 0;
    pid_t pid, parent = getpid();
    ssize_t got;

    if (msg_len > 0)
        msg[0] = '\0';
    if (pipe(pipefd) != 0) {
        snprintf(msg, msg_len, "cannot create a pipe: %s", strerror(errno));
        return -1;
    }
    /* errpipe: close-on-exec, so it reads EOF once the program runs, or the exec's errno */
    if (pipe(errpipe) != 0 || fcntl(errpipe[1], F_SETFD, FD_CLOEXEC) != 0) {
        snprintf(msg, msg_len, "cannot create a pipe: %s", strerror(errno));
        close(pipefd[0]);
        close(pipefd[1]);
        return -1;
    }
    pid = fork();
    if (pid < 0) {
        snprintf(msg, msg_len, "cannot run %s: %s", path, strerror(errno));
        close(pipefd[0]);
        close(pipefd[1]);
        close(errpipe[0]);
        close(errpipe[1]);
        return -1;
    }
    if (pid == 0) {
        /* the program dies with us: a killed duel_evolve leaves no ffmpeg behind (and if we died
         * before the request took effect, there is no parent to wait for) */
        int in = open("/dev/null", O_RDONLY), out = open("/dev/null", O_WRONLY), e;
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent || in < 0 || out < 0 ||
            dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(pipefd[1], 2) < 0)
            _exit(127);
        /* a source that already was 0, 1 or 2 (the parent started with it closed) stays open */
        if (in > 2)
            close(in);
        if (out > 2)
            close(out);
        if (pipefd[0] > 2)
            close(pipefd[0]);
        if (pipefd[1] > 2)
            close(pipefd[1]);
        close(errpipe[0]);
        execve(path, argv, environ);
        e = errno;
        if (write(errpipe[1], &e, sizeof e) < 0)
            _exit(127);
        _exit(127);
    }
    close(pipefd[1]);
    close(errpipe[1]);
    while ((got = read(errpipe[0], &child_err, sizeof child_err)) < 0 && errno == EINTR)
        ;
    close(errpipe[0]);
    if (got == (ssize_t)sizeof child_err) {
        close(pipefd[0]);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            ;
        snprintf(msg, msg_len, "cannot run %s: %s", path, strerror(child_err));
        return -1;
    }
    for (;;) {
        got = read(pipefd[0], data, sizeof data);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            break;
        duel_exec_keep(line, &cur, sizeof line, data, (size_t)got, msg, msg_len);
    }
    duel_exec_keep(line, &cur, sizeof line, "\n", 1, msg, msg_len);
    close(pipefd[0]);
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) {
            snprintf(msg, msg_len, "cannot wait for %s: %s", path, strerror(errno));
            return -1;
        }
    if (WIFEXITED(status))
        return WEXITSTATUS(status);
    snprintf(msg, msg_len, "%s killed by signal %d", path, WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    return -1;
}
