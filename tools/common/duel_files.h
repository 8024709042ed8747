/* duel_files.h - every file the tools write goes through here: temporary file, fsync, rename, directory sync; whole-file reads, durable appends, CSV truncation. */
#ifndef DUEL_FILES_H
#define DUEL_FILES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Every output file is written as PATH.tmp, synced, renamed over PATH, and
 * its directory synced: a reader sees the old file or the new one, never a
 * mix, a failure leaves PATH as it was, and a PATH reported written survives
 * a power cut. A PATH.tmp left by a killed writer is ours: the next write of
 * PATH takes it over. */

/* Writes data to path that way. 0; -1 (errno set) when path.tmp cannot be
 * created, -2 when writing, renaming or syncing failed. */
int duel_file_replace(const char *path, const void *data, size_t len);

/* A file written as a stream (a trace, a log), put in place only by
 * duel_out_commit. */
typedef struct duel_out {
    FILE *f;     /* write here */
    int direct;  /* 1: written in place (see duel_out_target), no temporary */
    char path[4096], tmp[4104];
} duel_out;
/* Opens path.tmp (or path itself, see duel_out_target). 0, or -1 (errno
 * set; ENAMETOOLONG for a path too long, EISDIR for a directory). */
int duel_out_open(duel_out *o, const char *path);
/* Flushes, syncs and closes the stream, renames it over path and syncs the
 * directory. 0, or -1 (errno set; the temporary is gone, path unchanged). */
int duel_out_commit(duel_out *o);
/* Closes the stream and removes the temporary: path is as it was. */
void duel_out_abort(duel_out *o);

/* Where an output named path is written: a symbolic link is followed (the
 * link stays, its target is replaced; a dangling one is written through); an
 * existing path that is not a regular file (a terminal, a pipe such as
 * /dev/stdout, a device) is written in place (*direct = 1): there is nothing
 * to rename over. 0 with the file in target, or -1 (errno set; EISDIR for a
 * directory). */
int duel_out_target(const char *path, char *target, size_t cap, int *direct);
/* Creates the temporary file tmp afresh: a stale one (a killed writer's) is
 * removed first, and a symbolic link there is never followed. A descriptor
 * open for writing, or -1 (errno set). */
int duel_tmp_create(const char *tmp);
/* fsync of the file at path (one another program wrote). 0 or -1. */
int duel_file_sync(const char *path);

/* Renames tmp over path and syncs path's directory. 0, or -1 (errno set; tmp
 * removed when the rename failed). */
int duel_file_commit(const char *tmp, const char *path);
/* fsync of the directory that holds path. 0 or -1 (errno set). */
int duel_dir_sync(const char *path);

/* errno of a read refused because the path is not a regular file (a FIFO,
 * a device, a socket): no reader waits on a pipe or reads an endless device. */
#define DUEL_ENOTREG ENOSTR

/* The whole file, at most max bytes, in a malloc'd buffer. 0; -1 when it
 * cannot be opened (errno set; ENOENT when missing); -2 when it cannot be
 * read (errno set; EFBIG when it is larger than max, EISDIR for a
 * directory, DUEL_ENOTREG for anything else not a regular file). */
int duel_file_read(const char *path, size_t max, uint8_t **data, size_t *len);
/* fopen(path, "rb") of a regular file only (never waiting on a FIFO), or
 * NULL with errno (EISDIR, DUEL_ENOTREG, or open's). */
FILE *duel_fopen_regular(const char *path);
/* strerror, with "not a regular file" for DUEL_ENOTREG and "too large" for EFBIG. */
const char *duel_file_strerror(int err);

/* Appends text and flushes it to the disk (and the directory, when this
 * created the file). 0 or -1. */
int duel_file_append(const char *path, const char *text);

/* The most a run directory's CSV record is read to (a 500-generation run's
 * generations.csv is about 100 KB): a link to an endless file is refused. */
#define DUEL_CSV_MAX_FILE ((size_t)256 << 20)

/* Keeps the header and the complete rows whose first field (a generation
 * number) is below generation; drops the rest, including a torn last row.
 * A missing file is fine. 0 or -1. */
int duel_csv_keep_before(const char *path, uint32_t generation);

/* What a record's reader names before anything else, rather than reporting it as a lost or malformed row: the
 * first line (1-based) of text that ends in CRLF (*what "crlf": a copy converted by a tool that writes Windows
 * line ends), or the first row that repeats the one before it byte for byte (*what "dup": a row written twice).
 * 0 when there is neither. */
uint32_t duel_csv_odd_line(const char *text, size_t len, const char **what);

/* The text write(f, ctx) prints, put in place by duel_file_replace. Returns
 * 0, 2 (cannot create: a bad path) or 1 (the write failed), with one line on
 * stderr. */
typedef void (*duel_write_fn)(FILE *f, const void *ctx);
int duel_file_write_with(const char *path, duel_write_fn write, const void *ctx);
/* The same, printing nothing: the status with the line in msg (the path escaped). */
int duel_file_write_with_msg(const char *path, duel_write_fn write, const void *ctx, char *msg, size_t cap);
/* The same, for a writer that can fail (out of memory): when *failed is set after write(f, ctx) returns, nothing is
 * put in place and the status is 1 ("out of memory"). */
int duel_file_write_checked_msg(const char *path, duel_write_fn write, const void *ctx, const int *failed, char *msg,
                                size_t cap);

/* A working directory's lock: the directory itself and DIR/.lock, both
 * flock'ed (the kernel drops them when the process ends, even by kill -9).
 * The directory's lock keeps a second writer out even when .lock is deleted;
 * where a file system cannot lock a directory, .lock alone does. */
typedef struct duel_lock {
    int dir_fd, file_fd;
} duel_lock;
/* Takes DIR's lock. 0, or -1 with errno EWOULDBLOCK when another process
 * holds it, ELOOP when .lock is a symbolic link (never followed). */
int duel_dir_lock(const char *dir, duel_lock *lk);
/* 1 while DIR/.lock is still the file lk locked (not deleted or replaced). */
int duel_dir_lock_held(const duel_lock *lk, const char *dir);
/* Gives the lock back (nothing when not held). */
void duel_dir_unlock(duel_lock *lk);

/* mkdir -p: the parents too, and an existing directory is fine. 0 or -1. */
int duel_mkdir(const char *path);

#endif /* DUEL_FILES_H */
