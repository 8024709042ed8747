/* duel_export_c.h - a champion blob (validated by the runtime) or a world's rules as C source a firmware links: duel_evolve export and the Python package's deploy. */
#ifndef DUEL_EXPORT_C_H
#define DUEL_EXPORT_C_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "duel.h"
#include "duel_ctrl.h"
#include "duel_outputs.h"
#include "nrt.h"

#define DUEL_EXPORT_NAME_MAX 63 /* longest array name; NAME_len adds 4 */
#define DUEL_EXPORT_PER_LINE 12 /* bytes per line of the initialiser */

/* A validated blob and what the comment says about it (path: the file it came from, named in the comment). */
typedef struct duel_export {
    const char *path;
    const char *name;
    uint8_t *blob;
    size_t len;
    size_t mem_required;
    nrt_net net;
    const char *header;  /* --header FILE.h: the file the .c includes, or NULL */
    duel_origin origin;  /* the world and step it was made with, as far as known */
} duel_export;

/* A world's rules and the array's name (export --world). */
typedef struct duel_export_world {
    const char *name;
    duel_rules r;
    uint8_t b[DUEL_RULES_BYTES];
} duel_export_world;

/* NAME is a C identifier of at most DUEL_EXPORT_NAME_MAX characters and not a keyword (NAME_len then is one too). */
int duel_export_name_ok(const char *s);
/* The blob or genome file at path read and validated as a firmware will (nrt_load); or the blob bytes given (path
 * the name the comment gives). 0, or -1 with the line in msg; x->blob malloc'd (free it). */
int duel_export_open_msg(duel_export *x, const char *path, char *msg, size_t cap);
int duel_export_from_bytes(duel_export *x, const char *path, const uint8_t *blob, size_t len, char *msg, size_t cap);
/* duel_file_write_with's writers: the C file and the header of a duel_export, the C file and the raw bytes of a
 * duel_export_world. */
void duel_export_write_cb(FILE *f, const void *ctx);
void duel_export_write_header_cb(FILE *f, const void *ctx);
void duel_export_world_write(FILE *f, const char *name, const duel_rules *r, const uint8_t *b);
void duel_export_world_cb(FILE *f, const void *ctx);
void duel_export_raw_cb(FILE *f, const void *ctx);
/* What export's outputs are (duel_outputs.h): a C file from export, a world's raw bytes. */
extern const duel_out_kind duel_export_c_kind, duel_export_raw_kind;

#endif /* DUEL_EXPORT_C_H */
