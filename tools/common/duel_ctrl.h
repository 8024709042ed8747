/* duel_ctrl.h - a controller named on the command line (a champion blob or genome file, or builtin:NAME), and blob and genome files read whole. */
#ifndef DUEL_CTRL_H
#define DUEL_CTRL_H

#include <stddef.h>
#include <stdint.h>

#include "duel.h"
#include "duel_genome_file.h"

/* Where a controller's world or step comes from. */
enum { DUEL_ORIGIN_NONE = 0, DUEL_ORIGIN_FILE = 1, DUEL_ORIGIN_RUN = 2 };

/* Where a champion file was made, as far as the file says or its place tells
 * (docs/formats.md): a genome file of version 2 records its step and its
 * run's tag (the world first); a blob records its step (its version) but no
 * world; a file in a run's champions/ has its run's world and step. */
typedef struct duel_origin {
    int builtin;     /* builtin:NAME: no network, no world of its own */
    int genome;      /* a genome file (else a blob) */
    int world_from;  /* DUEL_ORIGIN_*: NONE, the file records no world and lies in no run */
    duel_rules world;
    int step_from;   /* DUEL_ORIGIN_*: NONE, a genome file of version 1 outside a run (played as sync) */
    int net_step;    /* the step it is played with */
} duel_origin;

/* The origin of spec (a file, or builtin:NAME). 0, or -1 after one line naming the file. */
int duel_ctrl_origin(const char *spec, duel_origin *o);
/* The step mode of the run in dir (its config.ini's net_step); sync when it cannot be read. */
int duel_run_net_step(const char *dir);
/* "sync" or "propagate"; a controller's "builtin" when it is one. */
const char *duel_step_name(int net_step);
const char *duel_origin_step_text(const duel_origin *o);

/* A controller named on the command line: a blob or genome file, or builtin:NAME. */
typedef struct duel_cli_ctrl {
    duel_controller ctrl;
    nrt_net net;
    void *mem;
    uint8_t *blob;
    size_t blob_len;
    char name[256];
    duel_origin origin; /* where it was made (duel_ctrl_origin) */
} duel_cli_ctrl;

/* Whether path names a file in a run's champions/ (RUN/champions/NAME with
 * RUN/config.ini): 1 and RUN in run, else 0. */
int duel_ctrl_run_of(const char *path, char *run, size_t cap);

/* The world the controllers were made in (each spec whose origin has a world
 * counts: a genome file that records it, or a file in a run's champions/):
 * *found 1 and their world in *r; *found 0 when none says; -1 after one line
 * when two worlds differ or a file cannot be read. */
int duel_ctrl_world(const char *const *specs, int n, duel_rules *r, int *found);

/* Reads the whole file at path into a malloc'd *blob (the caller frees it)
 * of *len bytes, not validated (a genome file gives its network's blob, in
 * the step mode it records, else that of the run it lies in, else sync); on
 * error prints one line naming the file and the problem to stderr and
 * returns -1 (*blob NULL). */
int duel_cli_read_blob(const char *path, uint8_t **blob, size_t *len);
/* The same, with the file's origin in *origin (NULL: not wanted). */
int duel_cli_read_blob_origin(const char *path, uint8_t **blob, size_t *len, duel_origin *origin);
/* The same, printing nothing (for the run engine, which may run in a thread): -1 with the line in err, without
 * "duel_evolve: " (paths escaped already; give it through duel_esc_msg or duel_text_escape_msg). */
int duel_read_blob_msg(const char *path, uint8_t **blob, size_t *len, duel_origin *origin, char *err, size_t cap);

/* Loads spec into c; on error prints one line naming the problem to stderr
 * and returns -1. */
int duel_cli_ctrl_open(duel_cli_ctrl *c, const char *spec);
/* The same for a champion of a run whose world the caller knows (a run's own levels): its origin's world is not
 * looked up (world_from stays NONE), which would read the run's checkpoint for every champion. */
int duel_cli_ctrl_open_run_champion(duel_cli_ctrl *c, const char *spec);
/* Either, printing nothing (want_world 1: duel_cli_ctrl_open's): -1 with the line in msg (as duel_read_blob_msg's). */
int duel_ctrl_open_msg(duel_cli_ctrl *c, const char *spec, int want_world, char *msg, size_t cap);

/* Coevolution checkpoints are a few MB at the paper's scale; a larger file than this is refused. */
#define DUEL_CKPT_MAX ((size_t)1 << 30)

struct neat_coev;
/* The coevolution checkpoint at path, read and loaded into *out. 0; 1 when
 * the file does not exist (nothing printed); -1 after one line on stderr,
 * "duel_evolve: PREFIXPATH: ...": unreadable, larger than DUEL_CKPT_MAX, or
 * refused at an offset (naming both format versions when it is a format
 * this build does not read). */
int duel_ckpt_load(const char *prefix, const char *path, struct neat_coev **out);
/* The same, printing nothing: -1 with the line in msg (as duel_read_blob_msg's). */
int duel_ckpt_load_msg(const char *prefix, const char *path, struct neat_coev **out, char *msg, size_t cap);
/* Either checkpoint at path, by its magic: a coevolution's into *coev or a population's (a run against fixed
 * opponents) into *pop, the other NULL; *format (NULL: not wanted) the file's format word (bytes 8-11). 0; 1 when
 * the file does not exist; -2 when it is of the kind whose pointer is NULL (not loaded, nothing in msg); -1 with
 * the line in msg, "PREFIXPATH: ..." (the one loader of both kinds). */
int duel_any_ckpt_load_msg(const char *prefix, const char *path, struct neat_coev **coev, struct neat_pop **pop,
                           uint32_t *format, char *msg, size_t cap);
/* 1 when dir's checkpoint.bin is a run's against fixed opponents (a population's, "NEATCKPT"). */
int duel_run_is_fixed(const char *dir);
/* The one line that refuses such a run's checkpoint (at path) where a coevolution's is needed. */
void duel_fixed_run_refused(const char *prefix, const char *path);
void duel_fixed_run_refused_msg(const char *prefix, const char *path, char *msg, size_t cap);
void duel_cli_ctrl_close(duel_cli_ctrl *c);

/* The world a coevolution checkpoint (read from path) was made in: its game
 * tag's first DUEL_RULES_BYTES, or world v1 when it has none (a run from
 * before the rules were data, checkpoint version 2). 0, or -1 after one
 * line on stderr. */
int duel_ckpt_world(const struct neat_coev *c, const char *path, duel_rules *r);
int duel_ckpt_world_msg(const struct neat_coev *c, const char *path, duel_rules *r, char *msg, size_t cap);

/* The world of the run in dir: its checkpoint's (duel_ckpt_world), else,
 * before its first checkpoint, its config.ini's [world], else v1. 0, or -1
 * after one line on stderr (a damaged checkpoint or config.ini). */
int duel_run_world(const char *dir, duel_rules *r);
/* The same two, printing nothing: -1 with the line in msg (as duel_read_blob_msg's). */
int duel_run_world_msg(const char *dir, duel_rules *r, char *msg, size_t cap);

#endif /* DUEL_CTRL_H */
