/* duel_files.h - the file operations a run directory needs: atomic replacement, whole-file reads, CSV rows kept up to a generation. */
#ifndef DUEL_FILES_H
#define DUEL_FILES_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Writes data to path through path.tmp, fsync and rename: a reader sees the
 * old file or the new one, never a mix (a path.tmp left by a killed writer
 * is taken over by the next write of path). 0; -1 (errno set) when path.tmp
 * cannot be created, -2 when writing or renaming it failed. */
int duel_file_replace(const char *path, const void *data, size_t len);

/* The whole file, at most max bytes, in a malloc'd buffer. 0; -1 when it
 * cannot be opened (errno set; ENOENT when missing); -2 when it cannot be
 * read (errno set; EFBIG when it is larger than max). */
int duel_file_read(const char *path, size_t max, uint8_t **data, size_t *len);

/* Appends text and flushes it to the disk. 0 or -1. */
int duel_file_append(const char *path, const char *text);

/* Keeps the header and the complete rows whose first field (a generation
 * number) is below generation; drops the rest, including a torn last row.
 * A missing file is fine. 0 or -1. */
int duel_csv_keep_before(const char *path, uint32_t generation);

/* The text write(f, ctx) prints, put in place by duel_file_replace. Returns
 * 0, 2 (cannot create: a bad path) or 1 (the write failed), with one line on
 * stderr. */
typedef void (*duel_write_fn)(FILE *f, const void *ctx);
int duel_file_write_with(const char *path, duel_write_fn write, const void *ctx);

/* Takes DIR/.lock exclusively for the rest of the process (the kernel drops
 * it when the process ends, even by kill -9). The descriptor, or -1 with
 * errno EWOULDBLOCK when another process holds it. */
int duel_dir_lock(const char *dir);

/* mkdir -p: the parents too, and an existing directory is fine. 0 or -1. */
int duel_mkdir(const char *path);

#endif /* DUEL_FILES_H */
