/* duel_ctrl.h - a controller named on the command line (a champion blob or genome file, or builtin:NAME), and blob and genome files read whole. */
#ifndef DUEL_CTRL_H
#define DUEL_CTRL_H

#include <stddef.h>
#include <stdint.h>

#include "duel.h"
#include "neat.h"

/* A controller named on the command line: a blob or genome file, or builtin:NAME. */
typedef struct duel_cli_ctrl {
    duel_controller ctrl;
    nrt_net net;
    void *mem;
    uint8_t *blob;
    size_t blob_len;
    char name[256];
} duel_cli_ctrl;

/* A genome file (neat_genome_save: magic NEATGENM) read into g (the caller
 * frees it) with its shape; on error prints one line naming the file, the
 * problem and its byte offset, and returns -1 (g empty). */
int duel_genome_read(const char *path, neat_genome *g, uint32_t *n_inputs, uint32_t *n_outputs);
/* The same from len bytes already read from path (freed when free_buf). */
int duel_genome_parse(const char *path, uint8_t *buf, size_t len, neat_genome *g, uint32_t *n_inputs,
                      uint32_t *n_outputs, int free_buf);
/* Whether buf starts as a genome file does. */
int duel_is_genome_file(const uint8_t *buf, size_t len);
/* g as a genome file at path, written atomically (temporary file, rename);
 * on error prints one line and returns -1. */
int duel_genome_write(const char *path, const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs);

/* Reads the whole file at path into a malloc'd *blob (the caller frees it)
 * of *len bytes, not validated (a genome file gives its network's blob); on
 * error prints one line naming the file and the problem to stderr and
 * returns -1 (*blob NULL). */
int duel_cli_read_blob(const char *path, uint8_t **blob, size_t *len);

/* Loads spec into c; on error prints one line naming the problem to stderr
 * and returns -1. */
int duel_cli_ctrl_open(duel_cli_ctrl *c, const char *spec);

/* Coevolution checkpoints are a few MB at the paper's scale; a larger file than this is refused. */
#define DUEL_CKPT_MAX ((size_t)1 << 30)

struct neat_coev;
/* The coevolution checkpoint at path, read and loaded into *out. 0; 1 when
 * the file does not exist (nothing printed); -1 after one line on stderr,
 * "duel_evolve: PREFIXPATH: ...": unreadable, larger than DUEL_CKPT_MAX, or
 * refused at an offset (naming both format versions when it is a format
 * this build does not read). */
int duel_ckpt_load(const char *prefix, const char *path, struct neat_coev **out);
void duel_cli_ctrl_close(duel_cli_ctrl *c);

#endif /* DUEL_CTRL_H */
