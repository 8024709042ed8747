/* duel_exec.c - PATH lookup and running an external program (ffmpeg, dot) with its stderr captured, for the render commands. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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
    posix_spawn_file_actions_t fa;
    char line[512], data[512];
    size_t cur = 0;
    int pipefd[2], status, err;
    pid_t pid;
    ssize_t got;

    if (msg_len > 0)
        msg[0] = '\0';
    if (pipe(pipefd) != 0) {
        snprintf(msg, msg_len, "cannot create a pipe: %s", strerror(errno));
        return -1;
    }
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, pipefd[1], 2);
    posix_spawn_file_actions_addclose(&fa, pipefd[0]);
    posix_spawn_file_actions_addclose(&fa, pipefd[1]);
    err = posix_spawn(&pid, path, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    close(pipefd[1]);
    if (err) {
        close(pipefd[0]);
        snprintf(msg, msg_len, "cannot run %s: %s", path, strerror(err));
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
