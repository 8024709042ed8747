/* duel_outputs.c - whether a command may write an output where it was told to: never over one of its inputs, and over an existing file only when that file is recognisably this command's output of this kind (or --force). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "duel_files.h"
#include "duel_outputs.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

int duel_is_run_file(const char *name)
{
    static const char *const names[] = {"config.ini", "generations.csv", "dominance.csv", "strength.csv",
                                        "checkpoint.bin", "ladder.csv", "compare-cache.csv", "log.txt",
                                        "champions", "games", "opponents", ".lock", "compare-cache.csv.lock"};
    size_t i, n = strlen(name);
    for (i = 0; i < sizeof names / sizeof names[0]; i++) {
        size_t k = strlen(names[i]);
        /* NAME, or NAME.tmp left by a killed writer */
        if (strcmp(name, names[i]) == 0 ||
            (n == k + 4 && strncmp(name, names[i], k) == 0 && strcmp(name + k, ".tmp") == 0))
            return 1;
    }
    return 0;
}

/* path resolved: realpath of the whole when it exists, else of its directory
 * followed by its last name. 0, or -1 (the directory does not resolve). */
static int duel_resolve(const char *path, char out[PATH_MAX + 1])
{
    char dir[PATH_MAX + 1], rdir[PATH_MAX + 1];
    const char *slash, *base;
    if (realpath(path, out) != NULL)
        return 0;
    if (strlen(path) >= sizeof dir)
        return -1;
    slash = strrchr(path, '/');
    if (slash == NULL) {
        snprintf(dir, sizeof dir, ".");
        base = path;
    } else {
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
        base = slash + 1;
    }
    if (realpath(dir, rdir) == NULL || strlen(rdir) + 1 + strlen(base) > PATH_MAX)
        return -1;
    {
        size_t n = strlen(rdir);
        memcpy(out, rdir, n);
        if (strcmp(rdir, "/") != 0)
            out[n++] = '/';
        memcpy(out + n, base, strlen(base) + 1); /* fits: checked above */
    }
    return 0;
}

int duel_same_path(const char *a, const char *b)
{
    struct stat sa, sb;
    char ra[PATH_MAX + 1], rb[PATH_MAX + 1];
    if (stat(a, &sa) == 0 && stat(b, &sb) == 0)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    return duel_resolve(a, ra) == 0 && duel_resolve(b, rb) == 0 && strcmp(ra, rb) == 0;
}

/* 1 when out (resolved) is a file the run directory dir (resolved) reads as
 * its own: its records and champions, not the outputs other commands keep
 * there (ladder.csv, compare-cache.csv). */
static int duel_in_run(const char *rout, const char *rdir)
{
    size_t n = strlen(rdir);
    const char *rest;
    if (strncmp(rout, rdir, n) != 0 || rout[n] != '/')
        return 0;
    rest = rout + n + 1;
    if (strncmp(rest, "champions/", 10) == 0 || strncmp(rest, "opponents/", 10) == 0 ||
        strncmp(rest, "games/", 6) == 0)
        return 1;
    return strchr(rest, '/') == NULL && duel_is_run_file(rest) && strcmp(rest, "ladder.csv") != 0 &&
           strcmp(rest, "compare-cache.csv") != 0;
}

int duel_out_is_duel_lcm(const uint8_t *head, size_t len, const char *path)
{
    (void)path;
    /* sync word, event number (8), time (8), channel length (4), data length (4), channel */
    return len >= 33 && head[0] == 0xED && head[1] == 0xA1 && head[2] == 0xDA && head[3] == 0x01 &&
           memcmp(head + 28, "DUEL_", 5) == 0;
}

int duel_out_allowed(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                     const char *const *inputs, size_t n_inputs)
{
    char rout[PATH_MAX + 1], rin[PATH_MAX + 1];
    uint8_t head[DUEL_OUT_HEAD];
    struct stat st, si;
    size_t i, got = 0;
    ssize_t r;
    int fd, resolved = duel_resolve(path, rout) == 0;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return 0; /* a pipe or device (written in place: /dev/null twice is fine), a directory (the writer says so) */
    for (i = 0; i < n_inputs; i++) {
        if (inputs[i] == NULL)
            continue;
        if (duel_same_path(path, inputs[i])) {
            fprintf(stderr, "duel_evolve: %s: %s %s is also one of its inputs or outputs (%s): refusing to write over it\n", cmd,
                    opt, path, inputs[i]);
            return 2;
        }
        if (resolved && stat(inputs[i], &si) == 0 && S_ISDIR(si.st_mode) && realpath(inputs[i], rin) != NULL &&
            duel_in_run(rout, rin)) {
            fprintf(stderr, "duel_evolve: %s: %s %s is a file of the run %s it reads: refusing to write over it\n",
                    cmd, opt, path, inputs[i]);
            return 2;
        }
    }
    if (stat(path, &st) != 0 || st.st_size == 0 || force)
        return 0; /* missing (created), empty (nothing to lose), or --force */
    fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        fprintf(stderr, "duel_evolve: %s: %s %s: cannot read it to see what it is: %s\n", cmd, opt, path,
                strerror(errno));
        return 2;
    }
    while (got < sizeof head && (r = read(fd, head + got, sizeof head - got)) != 0) {
        if (r < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        got += (size_t)r;
    }
    close(fd);
    if ((kind->prefix != NULL && got >= strlen(kind->prefix) && memcmp(head, kind->prefix, strlen(kind->prefix)) == 0) ||
        (kind->ours != NULL && kind->ours(head, got, path)))
        return 0;
    fprintf(stderr, "duel_evolve: %s: %s %s exists and is not %s: refusing to replace it (--force replaces it)\n", cmd,
            opt, path, kind->name);
    return 2;
}
