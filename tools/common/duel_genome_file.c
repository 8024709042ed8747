/* duel_genome_file.c - champion genome files as the tools read, check and write them (every error one line naming the file and the byte), and a genome as a blob. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel_files.h"
#include "duel_genome_file.h"
#include "duel_text.h"

int duel_genome_read(const char *path, neat_genome *g, uint32_t *n_inputs, uint32_t *n_outputs)
{
    uint8_t *buf = NULL;
    size_t len = 0;
    char err[4400];
    int r = duel_file_read(path, DUEL_GENOME_MAX, &buf, &len);
    neat_genome_init(g);
    if (r != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot %s: %s\n", duel_esc(path), r == -1 ? "open" : "read",
                errno == EFBIG ? "larger than 64 MB" : duel_file_strerror(errno));
        return -1;
    }
    r = duel_genome_parse(path, buf, len, g, n_inputs, n_outputs, err, sizeof err);
    free(buf);
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
    return r;
}

int duel_genome_parse(const char *path, const uint8_t *buf, size_t len, neat_genome *g, uint32_t *n_inputs,
                      uint32_t *n_outputs, char *err, size_t err_len)
{
    return duel_genome_parse_origin(path, buf, len, g, n_inputs, n_outputs, NULL, err, err_len);
}

int duel_genome_parse_origin(const char *path, const uint8_t *buf, size_t len, neat_genome *g, uint32_t *n_inputs,
                             uint32_t *n_outputs, neat_genome_origin *origin, char *err, size_t err_len)
{
    size_t off = 0;
    char esc[1100]; /* its own buffer: a parse may run off the main thread (duel_esc's are the main thread's) */
    int e = neat_genome_load_origin(g, n_inputs, n_outputs, origin, buf, len, NULL, &off);
    if (e == NEAT_E_NOMEM)
        snprintf(err, err_len, "%s: cannot load the genome: %s", duel_text_escape(path, esc, sizeof esc),
                 neat_strerror(e));
    else if (e)
        snprintf(err, err_len, "%s: not a valid genome file: %s at byte %lu", duel_text_escape(path, esc, sizeof esc),
                 neat_strerror(e), (unsigned long)off);
    return e ? -1 : 0;
}

int duel_is_genome_file(const uint8_t *buf, size_t len)
{
    return len >= 8 && memcmp(buf, NEAT_GENOME_FILE_MAGIC, 8) == 0;
}

int duel_genome_write_msg(const char *path, const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs,
                          const neat_genome_origin *origin, char *msg, size_t cap)
{
    uint8_t *buf = NULL;
    size_t len = 0;
    char esc[1100];
    int err = neat_genome_save_origin(g, n_inputs, n_outputs, origin, &buf, &len, NULL), r;
    if (err) {
        snprintf(msg, cap, "%s: cannot encode the genome: %s", duel_text_escape(path, esc, sizeof esc),
                 neat_strerror(err));
        return -1;
    }
    r = duel_file_replace(path, buf, len);
    if (r != 0)
        snprintf(msg, cap, "%s: cannot write: %s", duel_text_escape(path, esc, sizeof esc), strerror(errno));
    free(buf);
    return r;
}

int duel_genome_write(const char *path, const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs,
                      const neat_genome_origin *origin)
{
    char msg[1400];
    int r = duel_genome_write_msg(path, g, n_inputs, n_outputs, origin, msg, sizeof msg);
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return r;
}

int duel_genome_blob(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, int net_step, uint8_t **blob,
                     size_t *len)
{
    int e;
    *len = neat_blob_size(g);
    *blob = (uint8_t *)malloc(*len);
    e = *blob == NULL ? NEAT_E_NOMEM : neat_blob_write_step(g, n_inputs, n_outputs, net_step, *blob, *len, len);
    if (e != NEAT_OK) {
        free(*blob);
        *blob = NULL;
        *len = 0;
    }
    return e;
}
