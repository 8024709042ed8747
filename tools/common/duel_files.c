/* duel_files.c - every file the tools write goes through here: temporary file, fsync, rename, directory sync; whole-file reads, durable appends, CSV truncation. */
#define _XOPEN_SOURCE 700 /* POSIX 2008 with realpath */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "duel_files.h"
#include "duel_text.h"

static int duel_write_all(int fd, const void *data, size_t len)
{
    const char *p = (const char *)data;
    while (len > 0) {
        ssize_t w = write(fd, p, len);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        p += w;
        len -= (size_t)w;
    }
    return 0;
}

/* path's directory: "." for a bare name. */
static void duel_dir_of(const char *path, char *dir, size_t cap)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL)
        snprintf(dir, cap, ".");
    else if (slash == path)
        snprintf(dir, cap, "/");
    else
        snprintf(dir, cap, "%.*s", (int)(slash - path), path);
}

/* fsync of what path names, opened read-only with flags added. 0 or -1 (errno set). */
static int duel_fsync_path(const char *path, int flags)
{
    int fd = open(path, O_RDONLY | flags), r, e;
    if (fd < 0)
        return -1;
    r = fsync(fd);
    e = errno;
    close(fd);
    errno = e;
    return r;
}

int duel_dir_sync(const char *path)
{
    char dir[4200];
    duel_dir_of(path, dir, sizeof dir);
    return duel_fsync_path(dir, O_DIRECTORY);
}

int duel_file_commit(const char *tmp, const char *path)
{
    int e;
    if (rename(tmp, path) != 0) {
        e = errno;
        unlink(tmp);
        errno = e;
        return -1;
    }
    return duel_dir_sync(path);
}

static int duel_tmp_name(char *tmp, size_t cap, const char *path)
{
    if (snprintf(tmp, cap, "%s.tmp", path) >= (int)cap) {
        errno = ENAMETOOLONG;
        return -1;
    }
    return 0;
}

int duel_out_target(const char *path, char *target, size_t cap, int *direct)
{
    struct stat st;
    *direct = 0;
    if (strlen(path) >= cap) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(target, path);
    if (lstat(path, &st) != 0)
        return errno == ENOENT ? 0 : -1; /* a new file */
    if (S_ISLNK(st.st_mode)) {
        /* the link stays; what it points to is replaced (a dangling one: written through, creating it) */
        char *real = realpath(path, NULL);
        if (real == NULL) {
            *direct = 1;
            return 0;
        }
        if (strlen(real) >= cap || stat(real, &st) != 0) {
            free(real);
            errno = ENAMETOOLONG;
            return -1;
        }
        strcpy(target, real);
        free(real);
    }
    if (S_ISDIR(st.st_mode)) {
        errno = EISDIR;
        return -1;
    }
    /* a terminal, a pipe (/dev/stdout), a device: there is nothing to rename over */
    *direct = !S_ISREG(st.st_mode);
    return 0;
}

int duel_tmp_create(const char *tmp)
{
    /* a stale temporary of ours (a killed writer) is taken over; a symbolic link planted there is removed,
     * never followed */
    if (unlink(tmp) != 0 && errno != ENOENT)
        return -1;
    return open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644);
}

int duel_file_sync(const char *path)
{
    return duel_fsync_path(path, 0);
}

int duel_file_replace(const char *path, const void *data, size_t len)
{
    char target[4096], tmp[4200];
    int fd, e, direct;
    if (duel_out_target(path, target, sizeof target, &direct) != 0)
        return -1;
    if (direct) {
        fd = open(target, O_WRONLY | O_TRUNC);
        if (fd < 0)
            return -1;
        if (duel_write_all(fd, data, len) != 0) {
            e = errno;
            close(fd);
            errno = e;
            return -2;
        }
        return close(fd) == 0 ? 0 : -2;
    }
    if (duel_tmp_name(tmp, sizeof tmp, target) != 0)
        return -1;
    fd = duel_tmp_create(tmp);
    if (fd < 0)
        return -1;
    if (duel_write_all(fd, data, len) != 0 || fsync(fd) != 0) {
        e = errno;
        close(fd);
        unlink(tmp);
        errno = e;
        return -2;
    }
    if (close(fd) != 0) {
        e = errno;
        unlink(tmp);
        errno = e;
        return -2;
    }
    return duel_file_commit(tmp, target) == 0 ? 0 : -2;
}

int duel_out_open(duel_out *o, const char *path)
{
    int fd;
    memset(o, 0, sizeof *o);
    if (duel_out_target(path, o->path, sizeof o->path, &o->direct) != 0)
        return -1;
    if (o->direct) {
        o->f = fopen(o->path, "wb");
        return o->f != NULL ? 0 : -1;
    }
    if (duel_tmp_name(o->tmp, sizeof o->tmp, o->path) != 0)
        return -1;
    fd = duel_tmp_create(o->tmp);
    if (fd < 0)
        return -1;
    o->f = fdopen(fd, "wb");
    if (o->f == NULL) {
        int e = errno;
        close(fd);
        unlink(o->tmp);
        errno = e;
        return -1;
    }
    return 0;
}

int duel_out_commit(duel_out *o)
{
    int bad, e;
    if (o->f == NULL) {
        errno = EBADF;
        return -1;
    }
    bad = fflush(o->f) != 0 || ferror(o->f) || (!o->direct && fsync(fileno(o->f)) != 0);
    e = errno;
    if (fclose(o->f) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    o->f = NULL;
    if (bad) {
        if (!o->direct)
            unlink(o->tmp);
        errno = e ? e : EIO;
        return -1;
    }
    return o->direct ? 0 : duel_file_commit(o->tmp, o->path);
}

void duel_out_abort(duel_out *o)
{
    if (o->f != NULL)
        fclose(o->f);
    o->f = NULL;
    if (!o->direct)
        unlink(o->tmp);
}

int duel_file_read(const char *path, size_t max, uint8_t **data, size_t *len)
{
    /* O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC), e = 0;
    struct stat st;
    uint8_t *buf = NULL;
    size_t n = 0, cap = 0;
    if (fd < 0)
        return -1;
    if (fstat(fd, &st) != 0)
        e = errno;
    else if (S_ISDIR(st.st_mode))
        e = EISDIR;
    else if (!S_ISREG(st.st_mode))
        e = DUEL_ENOTREG; /* a FIFO, a device (/dev/zero is endless), a socket */
    else if ((uint64_t)st.st_size > (uint64_t)max)
        e = EFBIG;
    if (e) {
        close(fd);
        errno = e;
        return -2;
    }
    for (;;) {
        ssize_t got;
        if (n == cap) {
            uint8_t *nb;
            cap = cap ? cap * 2 : 65536;
            nb = (uint8_t *)realloc(buf, cap);
            if (nb == NULL) {
                e = ENOMEM;
                break;
            }
            buf = nb;
        }
        got = read(fd, buf + n, cap - n);
        if (got < 0) {
            if (errno == EINTR)
                continue;
            e = errno == EAGAIN ? EIO : errno;
            break;
        }
        n += (size_t)got;
        if (n > max) {
            e = EFBIG; /* a file still growing: found out after at most max + 64 KiB */
            break;
        }
        if (got == 0)
            break;
    }
    close(fd);
    if (e) {
        free(buf);
        errno = e;
        return -2;
    }
    *data = buf;
    *len = n;
    return 0;
}

FILE *duel_fopen_regular(const char *path)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC), e = 0;
    struct stat st;
    FILE *f;
    if (fd < 0)
        return NULL;
    if (fstat(fd, &st) != 0)
        e = errno;
    else if (S_ISDIR(st.st_mode))
        e = EISDIR;
    else if (!S_ISREG(st.st_mode))
        e = DUEL_ENOTREG;
    else if (fcntl(fd, F_SETFL, O_RDONLY) != 0) /* blocking reads from here on, as from fopen */
        e = errno;
    if (e == 0 && (f = fdopen(fd, "rb")) != NULL)
        return f;
    e = e ? e : errno;
    close(fd);
    errno = e;
    return NULL;
}

const char *duel_file_strerror(int err)
{
    if (err == DUEL_ENOTREG)
        return "not a regular file";
    if (err == EFBIG)
        return "too large";
    return strerror(err);
}

int duel_file_append(const char *path, const char *text)
{
    struct stat st;
    int fd = open(path, O_WRONLY | O_CREAT | O_APPEND, 0644), e, created;
    if (fd < 0)
        return -1;
    /* empty before this write: just created (or left empty by a failed one), so its name needs the sync too */
    created = fstat(fd, &st) != 0 || st.st_size == 0;
    if (duel_write_all(fd, text, strlen(text)) != 0 || fsync(fd) != 0) {
        e = errno;
        close(fd);
        errno = e;
        return -1;
    }
    if (close(fd) != 0)
        return -1;
    /* a new file's name is in its directory only once the directory is synced */
    return created ? duel_dir_sync(path) : 0;
}

int duel_csv_keep_before(const char *path, uint32_t generation)
{
    uint8_t *data;
    size_t len, at = 0, keep = 0;
    int first = 1, r;
    if (duel_file_read(path, DUEL_CSV_MAX_FILE, &data, &len) != 0)
        return errno == ENOENT ? 0 : -1;
    while (at < len) {
        const uint8_t *nl = (const uint8_t *)memchr(data + at, '\n', len - at);
        size_t end;
        if (nl == NULL)
            break; /* a torn last row */
        end = (size_t)(nl - data) + 1;
        if (!first) {
            char *stop;
            unsigned long g = strtoul((const char *)data + at, &stop, 10);
            if (stop == (const char *)data + at || *stop != ',' || g >= generation)
                break;
        }
        first = 0;
        keep = end;
        at = end;
    }
    r = keep == len ? 0 : duel_file_replace(path, data, keep);
    free(data);
    return r;
}

int duel_mkdir(const char *path)
{
    char buf[4200], *p;
    struct stat st;
    if (strlen(path) >= sizeof buf) {
        errno = ENAMETOOLONG;
        return -1;
    }
    strcpy(buf, path);
    /* the parents first, like mkdir -p */
    for (p = buf + 1; *p; p++) {
        if (*p != '/')
            continue;
        *p = '\0';
        if (mkdir(buf, 0755) != 0 && errno != EEXIST)
            return -1;
        *p = '/';
    }
    if (mkdir(buf, 0755) == 0)
        return 0;
    if (errno == EEXIST && stat(buf, &st) == 0 && S_ISDIR(st.st_mode))
        return 0;
    if (errno == EEXIST)
        errno = ENOTDIR;
    return -1;
}

int duel_file_write_checked_msg(const char *path, duel_write_fn write, const void *ctx, const int *failed, char *msg,
                                size_t cap)
{
    char *text = NULL, esc[1100];
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    int r;
    duel_text_escape(path, esc, sizeof esc);
    if (mem == NULL) {
        snprintf(msg, cap, "%s: out of memory", esc);
        return 1;
    }
    write(mem, ctx);
    /* a writer that could not finish (out of memory) says so in *failed: nothing is put in place then */
    if (fclose(mem) != 0 || (failed != NULL && *failed)) {
        snprintf(msg, cap, "%s: out of memory", esc);
        free(text);
        return 1;
    }
    r = duel_file_replace(path, text, len);
    free(text);
    if (r == 0)
        return 0;
    snprintf(msg, cap, "%s: %s: %s", esc, r == -1 ? "cannot write" : "write failed", strerror(errno));
    return r == -1 ? 2 : 1;
}

int duel_file_write_with_msg(const char *path, duel_write_fn write, const void *ctx, char *msg, size_t cap)
{
    return duel_file_write_checked_msg(path, write, ctx, NULL, msg, cap);
}

int duel_file_write_with(const char *path, duel_write_fn write, const void *ctx)
{
    char msg[1400];
    int r = duel_file_write_with_msg(path, write, ctx, msg, sizeof msg);
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return r;
}

int duel_dir_lock(const char *dir, duel_lock *lk)
{
    char path[4200];
    struct stat a, b;
    int tries;
    lk->dir_fd = lk->file_fd = -1;
    if ((size_t)snprintf(path, sizeof path, "%s/.lock", dir) >= sizeof path) {
        errno = ENAMETOOLONG;
        return -1;
    }
    /* the directory itself: deleting or replacing .lock cannot let a second writer in */
    lk->dir_fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (lk->dir_fd < 0)
        return -1;
    if (flock(lk->dir_fd, LOCK_EX | LOCK_NB) != 0) {
        int e = errno;
        if (e == EWOULDBLOCK) {
            duel_dir_unlock(lk);
            errno = e;
            return -1;
        }
        /* a file system that cannot lock a directory (NFS emulates flock with write locks): .lock alone */
        close(lk->dir_fd);
        lk->dir_fd = -1;
    }
    for (tries = 0; tries < 8; tries++) {
        /* O_NOFOLLOW: a .lock that is a symbolic link is refused, its target never created */
        lk->file_fd = open(path, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (lk->file_fd < 0 || flock(lk->file_fd, LOCK_EX | LOCK_NB) != 0) {
            int e = errno;
            duel_dir_unlock(lk);
            errno = e;
            return -1;
        }
        /* still the file named .lock (not one deleted or replaced while we waited for it)? */
        if (fstat(lk->file_fd, &a) == 0 && lstat(path, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino)
            return 0; /* held until duel_dir_unlock or the process ends, however it ends */
        close(lk->file_fd);
        lk->file_fd = -1;
    }
    duel_dir_unlock(lk);
    errno = EWOULDBLOCK;
    return -1;
}

int duel_dir_lock_held(const duel_lock *lk, const char *dir)
{
    char path[4200];
    struct stat a, b;
    if (lk->file_fd < 0)
        return 0;
    snprintf(path, sizeof path, "%s/.lock", dir);
    return fstat(lk->file_fd, &a) == 0 && lstat(path, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

void duel_dir_unlock(duel_lock *lk)
{
    if (lk->file_fd >= 0)
        close(lk->file_fd);
    if (lk->dir_fd >= 0)
        close(lk->dir_fd);
    lk->dir_fd = lk->file_fd = -1;
}

uint32_t duel_csv_odd_line(const char *text, size_t len, const char **what)
{
    const char *p = text, *end = text + len, *prev = NULL, *nl;
    size_t prev_len = 0;
    uint32_t line = 0;
    while (p < end && (nl = (const char *)memchr(p, '\n', (size_t)(end - p))) != NULL) {
        size_t n = (size_t)(nl - p);
        line++;
        if (n > 0 && p[n - 1] == '\r') {
            *what = "crlf";
            return line;
        }
        if (prev != NULL && line > 2 && n == prev_len && n > 0 && memcmp(p, prev, n) == 0) {
            *what = "dup";
            return line;
        }
        prev = p;
        prev_len = n;
        p = nl + 1;
    }
    return 0;
}
