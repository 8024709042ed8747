/* fault_shim.c - LD_PRELOAD shim for the fault tests: the Nth write, fsync or rename on a file fails, as on a full or failing disk. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/*
 * Environment:
 *   NEAT_FAULT_AT=N      the Nth counted call fails (1 = the first); unset or 0: none fails
 *   NEAT_FAULT_OPS=LIST  which calls count: any of write, fsync, rename (default all three)
 *   NEAT_FAULT_COUNT=F   at exit, the number of counted calls is written to F
 *   NEAT_FAULT_TRACE=F   each counted call appended to F as a line: "write file", "fsync file", "fsync dir",
 *                        "rename TO" (durability checks: a rename followed by a directory sync)
 * Only calls on regular files and directories count (not the terminal or a
 * pipe). A failing write or fsync sets ENOSPC or EIO, a failing rename EIO.
 */

static unsigned long fault_calls;

static int fault_counts(const char *op)
{
    const char *ops = getenv("NEAT_FAULT_OPS");
    return ops == NULL || strstr(ops, op) != NULL;
}

/* 1 when this call is the one to fail. */
static int fault_now(const char *op)
{
    const char *at = getenv("NEAT_FAULT_AT");
    unsigned long n;
    if (!fault_counts(op))
        return 0;
    n = __atomic_add_fetch(&fault_calls, 1, __ATOMIC_SEQ_CST);
    return at != NULL && strtoul(at, NULL, 10) == n;
}

static int fault_file(int fd)
{
    struct stat st;
    return fstat(fd, &st) == 0 && (S_ISREG(st.st_mode) || S_ISDIR(st.st_mode));
}

static void fault_trace(const char *op, const char *what)
{
    const char *path = getenv("NEAT_FAULT_TRACE");
    FILE *f;
    if (path == NULL || !fault_counts(op) || (f = fopen(path, "a")) == NULL)
        return;
    fprintf(f, "%s %s\n", op, what);
    fclose(f);
}

static const char *fault_kind(int fd)
{
    struct stat st;
    return fstat(fd, &st) == 0 && S_ISDIR(st.st_mode) ? "dir" : "file";
}

ssize_t write(int fd, const void *buf, size_t n)
{
    static ssize_t (*real)(int, const void *, size_t);
    if (real == NULL)
        *(void **)&real = dlsym(RTLD_NEXT, "write");
    if (!fault_file(fd))
        return real(fd, buf, n);
    fault_trace("write", "file");
    if (fault_now("write")) {
        errno = ENOSPC;
        return -1;
    }
    return real(fd, buf, n);
}

int fsync(int fd)
{
    static int (*real)(int);
    if (real == NULL)
        *(void **)&real = dlsym(RTLD_NEXT, "fsync");
    if (!fault_file(fd))
        return real(fd);
    fault_trace("fsync", fault_kind(fd));
    if (fault_now("fsync")) {
        errno = EIO;
        return -1;
    }
    return real(fd);
}

int rename(const char *from, const char *to)
{
    static int (*real)(const char *, const char *);
    if (real == NULL)
        *(void **)&real = dlsym(RTLD_NEXT, "rename");
    fault_trace("rename", to);
    if (fault_now("rename")) {
        errno = EIO;
        return -1;
    }
    return real(from, to);
}

__attribute__((destructor)) static void fault_report(void)
{
    const char *path = getenv("NEAT_FAULT_COUNT");
    FILE *f;
    if (path == NULL || (f = fopen(path, "w")) == NULL)
        return;
    fprintf(f, "%lu\n", fault_calls);
    fclose(f);
}
