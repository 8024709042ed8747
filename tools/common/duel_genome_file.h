/* duel_genome_file.h - champion genome files (neat_genome_save's format) as the tools read, check and write them. */
#ifndef DUEL_GENOME_FILE_H
#define DUEL_GENOME_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "neat.h"

/* A genome file (neat_genome_save) holds 21 bytes a connection gene: far
 * more than a blob could, but not without bound. */
#define DUEL_GENOME_MAX ((size_t)64 << 20)

/* A genome file (neat_genome_save: magic NEAT_GENOME_FILE_MAGIC) read into
 * g (the caller frees it) with its shape; on error prints one line naming
 * the file, the problem and its byte offset, and returns -1 (g empty). */
int duel_genome_read(const char *path, neat_genome *g, uint32_t *n_inputs, uint32_t *n_outputs);
/* The same from len bytes already read from path: 0, or -1 with the line
 * (without "duel_evolve: ") in err. */
int duel_genome_parse(const char *path, const uint8_t *buf, size_t len, neat_genome *g, uint32_t *n_inputs,
                      uint32_t *n_outputs, char *err, size_t err_len);
/* Whether buf starts as a genome file does. */
int duel_is_genome_file(const uint8_t *buf, size_t len);
/* The same, also giving the file's origin (neat_genome_origin; its tag
 * points into buf, so it is only given when origin is not NULL and the
 * caller keeps buf: NULL leaves it unread). */
int duel_genome_parse_origin(const char *path, const uint8_t *buf, size_t len, neat_genome *g, uint32_t *n_inputs,
                             uint32_t *n_outputs, neat_genome_origin *origin, char *err, size_t err_len);
/* g as a genome file at path, written atomically (temporary file, rename),
 * with its origin (a run's champions: the run's step and game tag, so that the
 * file still says where it was made once copied out; NULL: a version-1 file
 * that says nothing); on error prints one line and returns -1. */
int duel_genome_write(const char *path, const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs,
                      const neat_genome_origin *origin);
/* The same, printing nothing: -1 with the line in msg (the path escaped already). */
int duel_genome_write_msg(const char *path, const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs,
                          const neat_genome_origin *origin, char *msg, size_t cap);
/* g's network as a blob in step mode net_step (neat_blob_write_step), in a malloc'd *blob of *len bytes (the caller
 * frees it). NEAT_OK, or a NEAT_E_ code (*blob NULL). */
int duel_genome_blob(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, int net_step, uint8_t **blob,
                     size_t *len);

#endif /* DUEL_GENOME_FILE_H */
