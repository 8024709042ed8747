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
#include "duel_text.h"

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

/* 1 when the file at dir/name starts with mark. */
static int duel_starts_with(const char *dir, const char *name, const char *mark)
{
    char path[PATH_MAX + 64], head[64];
    size_t k = strlen(mark);
    FILE *f;
    int yes;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if ((f = duel_fopen_regular(path)) == NULL)
        return 0;
    yes = fread(head, 1, k, f) == k && memcmp(head, mark, k) == 0;
    fclose(f);
    return yes;
}

/* What the (resolved) directory dir is: 1 a run directory (a checkpoint.bin, or a config.ini a run wrote), 2 an
 * experiment directory (a plan.ini an experiment wrote), 0 neither. */
static int duel_dir_role(const char *dir)
{
    char path[PATH_MAX + 64];
    struct stat st;
    snprintf(path, sizeof path, "%s/checkpoint.bin", dir);
    if (lstat(path, &st) == 0 || duel_starts_with(dir, "config.ini", DUEL_RUN_CONFIG_MARK))
        return 1;
    return duel_starts_with(dir, "plan.ini", DUEL_EXP_PLAN_MARK) ? 2 : 0;
}

/* 1 for the name of a champion file (a blob or genome, or a temporary of one); a picture drawn beside it is not. */
static int duel_is_champion_name(const char *name)
{
    size_t n = strlen(name);
    if (n > 4 && strcmp(name + n - 4, ".tmp") == 0)
        n -= 4;
    return (n >= 5 && strncmp(name + n - 5, ".blob", 5) == 0) || (n >= 7 && strncmp(name + n - 7, ".genome", 7) == 0);
}

/* The run or experiment directory whose own file the resolved path rout is (its records, checkpoint,
 * configuration, log, champions, opponents, games or ladder; an experiment's plan, configurations and report),
 * copied to dir; 0 when it is none. A compare cache is not one: compare checks its own. */
static int duel_protected(const char *rout, char dir[PATH_MAX + 1])
{
    size_t n = strlen(rout);
    int depth;
    memcpy(dir, rout, n + 1);
    for (depth = 1; depth <= 2; depth++) {
        char *slash = strrchr(dir, '/');
        const char *rest;
        int role;
        if (slash == NULL || slash == dir)
            return 0;
        *slash = '\0';
        rest = rout + (slash - dir) + 1;
        role = duel_dir_role(dir);
        if (role == 1) {
            if (depth == 2)
                return (strncmp(rest, "champions/", 10) == 0 && duel_is_champion_name(rest + 10)) ||
                       strncmp(rest, "opponents/", 10) == 0 || strncmp(rest, "games/", 6) == 0;
            return duel_is_run_file(rest) && strcmp(rest, "compare-cache.csv") != 0 &&
                   strcmp(rest, "compare-cache.csv.tmp") != 0;
        }
        if (role == 2) {
            if (depth == 2)
                return strncmp(rest, "configs/", 8) == 0 || strncmp(rest, "report/", 7) == 0;
            return strcmp(rest, "plan.ini") == 0 || strcmp(rest, ".lock") == 0 || strcmp(rest, "plan.ini.tmp") == 0;
        }
    }
    return 0;
}

/* Whether the directory that would hold path exists (a missing one is reported up front, not after the work). */
static int duel_parent_ok(const char *cmd, const char *opt, const char *path, char *msg, size_t cap)
{
    char dir[PATH_MAX + 1];
    const char *slash = strrchr(path, '/');
    struct stat st;
    char ep[1100], ed[1100];
    if (slash == NULL)
        return 0;
    duel_text_escape(path, ep, sizeof ep);
    if (strlen(path) >= sizeof dir) {
        snprintf(msg, cap, "%s: %s %s: name too long", cmd, opt, ep);
        return 2;
    }
    snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        snprintf(msg, cap, "%s: %s %s: cannot write: %s %s", cmd, opt, ep, duel_text_escape(dir, ed, sizeof ed),
                stat(dir, &st) != 0 ? "does not exist" : "is not a directory");
        return 2;
    }
    return 0;
}

int duel_out_is_duel_lcm(const uint8_t *head, size_t len, const char *path)
{
    (void)path;
    /* sync word, event number (8), time (8), channel length (4), data length (4), channel */
    return len >= 33 && head[0] == 0xED && head[1] == 0xA1 && head[2] == 0xDA && head[3] == 0x01 &&
           memcmp(head + 28, "DUEL_", 5) == 0;
}

static int duel_out_check(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                          const char *const *inputs, size_t n_inputs, int own, char *msg, size_t cap)
{
    char rout[PATH_MAX + 1], rin[PATH_MAX + 1], rdir[PATH_MAX + 1];
    uint8_t head[DUEL_OUT_HEAD];
    struct stat st, si;
    size_t i, got = 0;
    ssize_t r;
    int fd, resolved;
    char ep[1100], ei[1100], ed[1100];
    duel_text_escape(path, ep, sizeof ep); /* every name in a message one line, whatever bytes it holds */
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        snprintf(msg, cap, "%s: %s %s is a directory: name a file", cmd, opt, ep);
        return 2;
    }
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return 0; /* a pipe or device: written in place (/dev/null twice is fine) */
    if (!own && duel_parent_ok(cmd, opt, path, msg, cap) != 0)
        return 2; /* (a command's own file is in the run it reads, which it checks first) */
    resolved = duel_resolve(path, rout) == 0;
    for (i = 0; i < n_inputs; i++) {
        if (inputs[i] == NULL)
            continue;
        if (duel_same_path(path, inputs[i])) {
            snprintf(msg, cap, "%s: %s %s is also one of its inputs or outputs (%s): refusing to write over it", cmd,
                    opt, ep, duel_text_escape(inputs[i], ei, sizeof ei));
            return 2;
        }
        if (resolved && stat(inputs[i], &si) == 0 && S_ISDIR(si.st_mode) && realpath(inputs[i], rin) != NULL &&
            duel_in_run(rout, rin)) {
            snprintf(msg, cap, "%s: %s %s is a file of the run %s it reads: refusing to write over it",
                    cmd, opt, ep, duel_text_escape(inputs[i], ei, sizeof ei));
            return 2;
        }
    }
    /* a run's or an experiment's own file is never an output: --force does not lift this */
    if (resolved && !own && duel_protected(rout, rdir)) {
        snprintf(msg, cap, "%s: %s %s is a file of the %s directory %s: refusing to write there "
                        "(choose a path outside it)", cmd, opt, ep, duel_dir_role(rdir) == 2 ? "experiment" : "run",
                duel_text_escape(rdir, ed, sizeof ed));
        return 2;
    }
    if (stat(path, &st) != 0 || st.st_size == 0 || force)
        return 0; /* missing (created), empty (nothing to lose), or --force */
    fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(msg, cap, "%s: %s %s: cannot read it to see what it is: %s", cmd, opt, ep,
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
    snprintf(msg, cap, "%s: %s %s exists and is not %s: refusing to replace it (--force replaces it)", cmd,
            opt, ep, kind->name);
    return 2;
}

int duel_out_allowed_msg(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                         const char *const *inputs, size_t n_inputs, char *msg, size_t cap)
{
    return duel_out_check(cmd, opt, path, kind, force, inputs, n_inputs, 0, msg, cap);
}

int duel_out_own_allowed_msg(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind,
                             int force, const char *const *inputs, size_t n_inputs, char *msg, size_t cap)
{
    return duel_out_check(cmd, opt, path, kind, force, inputs, n_inputs, 1, msg, cap);
}

/* The commands' checks: the message printed. */
static int duel_out_print(int r, const char *msg)
{
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return r;
}

int duel_out_allowed(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                     const char *const *inputs, size_t n_inputs)
{
    char msg[4600];
    return duel_out_print(duel_out_check(cmd, opt, path, kind, force, inputs, n_inputs, 0, msg, sizeof msg), msg);
}

int duel_out_own_allowed(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                         const char *const *inputs, size_t n_inputs)
{
    char msg[4600];
    return duel_out_print(duel_out_check(cmd, opt, path, kind, force, inputs, n_inputs, 1, msg, sizeof msg), msg);
}
