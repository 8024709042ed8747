/* duel_ctrl.c - champion blob and genome files read whole, and a controller from the command line: a blob or genome file (validated by the runtime) or builtin:NAME. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "duel_ctrl.h"
#include "neat_coev.h"
#include "duel_config.h"
#include "duel_files.h"
#include "duel_runtag.h"
#include "duel_text.h"
#include "duel_world_cfg.h"

#define DUEL_BLOB_MAX (NRT_HEADER_SIZE + NRT_CONN_SIZE * 65535u)

int duel_ctrl_run_of(const char *path, char *run, size_t cap)
{
    const char *slash = strrchr(path, '/'), *p;
    char ini[4300];
    size_t n;
    if (slash == NULL)
        return 0;
    /* RUN/champions/NAME: the directory before "champions" */
    for (p = slash; p > path && p[-1] != '/'; p--)
        ;
    if ((size_t)(slash - p) != 9 || strncmp(p, "champions", 9) != 0)
        return 0;
    n = (size_t)(p - path);
    if (n == 0) {
        snprintf(run, cap, ".");
    } else {
        if (n >= cap)
            return 0;
        memcpy(run, path, n - 1u);
        run[n - 1u] = '\0';
        if (run[0] == '\0')
            snprintf(run, cap, "/");
    }
    snprintf(ini, sizeof ini, "%s/config.ini", run);
    return access(ini, F_OK) == 0;
}

int duel_run_net_step(const char *run)
{
    char ini[4300], err[4400];
    duel_config cfg;
    snprintf(ini, sizeof ini, "%s/config.ini", run);
    duel_config_default(&cfg);
    if (duel_config_read(&cfg, ini, err, sizeof err) != 0)
        return NEAT_STEP_SYNC;
    return cfg.neat.net_step;
}

/* The origin of a file already read (buf, len: a blob or a genome file, not
 * yet checked), with the genome parsed into g when it is one (g NULL: not
 * kept). 0, or -1 with the line in err. */
static int duel_origin_of_bytes(const char *path, const uint8_t *buf, size_t len, duel_origin *o, neat_genome *g,
                                uint32_t *ni, uint32_t *no, int want_world, char *err, size_t err_len)
{
    char run[4200];
    int in_run = duel_ctrl_run_of(path, run, sizeof run);
    memset(o, 0, sizeof *o);
    o->net_step = NEAT_STEP_SYNC;
    if (duel_is_genome_file(buf, len)) {
        neat_genome_origin go;
        neat_genome tmp;
        neat_genome *gp = g != NULL ? g : &tmp;
        if (duel_genome_parse_origin(path, buf, len, gp, ni, no, &go, err, err_len) != 0)
            return -1;
        if (g == NULL)
            neat_genome_free(&tmp, NULL);
        o->genome = 1;
        if (go.version >= 2) {
            o->net_step = go.net_step;
            o->step_from = DUEL_ORIGIN_FILE;
            /* the run's tag: the world's rules first (another program's tag names no world) */
            if (duel_tag_world(go.tag, go.tag_len, &o->world, NULL) == 0)
                o->world_from = DUEL_ORIGIN_FILE;
        }
    } else if (len >= 6 && memcmp(buf, "NRTB", 4) == 0) {
        /* a blob says its step by its version (docs/formats.md): 2 propagate */
        o->net_step = buf[4] == NRT_FORMAT_VERSION_PROPAGATE && buf[5] == 0 ? NEAT_STEP_PROPAGATE : NEAT_STEP_SYNC;
        o->step_from = DUEL_ORIGIN_FILE;
    }
    if (in_run && o->step_from == DUEL_ORIGIN_NONE) {
        o->net_step = duel_run_net_step(run);
        o->step_from = DUEL_ORIGIN_RUN;
    }
    if (in_run && want_world && o->world_from == DUEL_ORIGIN_NONE) {
        char why[2000];
        if (duel_run_world_msg(run, &o->world, why, sizeof why) != 0) {
            snprintf(err, err_len, "%s: the world of its run cannot be read: %s", path, why);
            return -1;
        }
        o->world_from = DUEL_ORIGIN_RUN;
    }
    return 0;
}

int duel_ctrl_origin(const char *spec, duel_origin *o)
{
    uint8_t *buf = NULL;
    size_t len = 0;
    char err[4400];
    int r;
    memset(o, 0, sizeof *o);
    if (strncmp(spec, "builtin:", 8) == 0) {
        o->builtin = 1;
        return 0;
    }
    if (duel_file_read(spec, DUEL_GENOME_MAX, &buf, &len) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot %s: %s\n", duel_esc(spec), errno == ENOENT ? "open" : "read",
                errno == EFBIG ? "larger than 64 MB" : duel_file_strerror(errno));
        return -1;
    }
    r = duel_origin_of_bytes(spec, buf, len, o, NULL, NULL, NULL, 1, err, sizeof err);
    free(buf);
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
    return r;
}

const char *duel_step_name(int net_step)
{
    return net_step == NEAT_STEP_PROPAGATE ? "propagate" : "sync";
}

const char *duel_origin_step_text(const duel_origin *o)
{
    if (o->builtin)
        return "builtin";
    return duel_step_name(o->net_step);
}

/* duel_read_blob_msg, the world of a file in a run looked up only when want_world: the message in err (the
 * path escaped already; a loader's message as it gave it: print it through duel_esc_msg) */
static int duel_read_blob_in(const char *path, uint8_t **blob, size_t *len, duel_origin *origin, int want_world,
                             char *err, size_t cap)
{
    duel_origin own;
    duel_origin *o = origin != NULL ? origin : &own;
    char esc[1100];
    int r = duel_file_read(path, DUEL_GENOME_MAX, blob, len);
    if (r == 0 && duel_is_genome_file(*blob, *len)) {
        /* a genome file: its network's blob, as evolution would encode it, in the step it was evolved with */
        neat_genome g;
        uint32_t ni, no;
        uint8_t *file = *blob;
        *blob = NULL;
        r = duel_origin_of_bytes(path, file, *len, o, &g, &ni, &no, want_world, err, cap);
        free(file);
        if (r != 0) {
            *len = 0;
            return -1;
        }
        r = duel_genome_blob(&g, ni, no, o->net_step, blob, len);
        neat_genome_free(&g, NULL);
        if (r != 0) {
            snprintf(err, cap, "%s: the genome has no blob: %s", duel_text_escape(path, esc, sizeof esc),
                     neat_strerror(r));
            return -1;
        }
        return 0;
    }
    if (r == 0 && *len > DUEL_BLOB_MAX) {
        free(*blob);
        r = -2;
        errno = EFBIG;
    }
    if (r == 0) {
        if (duel_origin_of_bytes(path, *blob, *len, o, NULL, NULL, NULL, want_world, err, cap) == 0)
            return 0;
        free(*blob);
        *blob = NULL;
        *len = 0;
        return -1;
    }
    *blob = NULL;
    *len = 0;
    duel_text_escape(path, esc, sizeof esc);
    if (r == -1)
        snprintf(err, cap, "%s: cannot open: %s", esc, strerror(errno));
    else if (errno == EFBIG)
        snprintf(err, cap, "%s: larger than any champion blob (%lu bytes at most)", esc, (unsigned long)DUEL_BLOB_MAX);
    else
        snprintf(err, cap, "%s: cannot read: %s", esc, strerror(errno));
    return -1;
}

int duel_read_blob_msg(const char *path, uint8_t **blob, size_t *len, duel_origin *origin, char *err, size_t cap)
{
    return duel_read_blob_in(path, blob, len, origin, origin != NULL, err, cap);
}

/* The commands' reading: the message printed. */
static int duel_read_blob_print(const char *path, uint8_t **blob, size_t *len, duel_origin *origin, int want_world)
{
    char err[4600];
    if (duel_read_blob_in(path, blob, len, origin, want_world, err, sizeof err) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
    return -1;
}

int duel_cli_read_blob_origin(const char *path, uint8_t **blob, size_t *len, duel_origin *origin)
{
    return duel_read_blob_print(path, blob, len, origin, origin != NULL);
}

int duel_cli_read_blob(const char *path, uint8_t **blob, size_t *len)
{
    return duel_read_blob_print(path, blob, len, NULL, 0);
}

static int duel_ctrl_open_in(duel_cli_ctrl *c, const char *spec, int want_world);

int duel_cli_ctrl_open(duel_cli_ctrl *c, const char *spec)
{
    return duel_ctrl_open_in(c, spec, 1);
}

int duel_cli_ctrl_open_run_champion(duel_cli_ctrl *c, const char *spec)
{
    return duel_ctrl_open_in(c, spec, 0);
}

int duel_ctrl_open_msg(duel_cli_ctrl *c, const char *spec, int want_world, char *msg, size_t cap)
{
    size_t size, need;
    char esc[1100];
    int err;

    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", spec);
    duel_text_escape(spec, esc, sizeof esc);
    if (strncmp(spec, "builtin:", 8) == 0) {
        int b = duel_builtin_parse(spec + 8);
        if (b < 0) {
            snprintf(msg, cap, "%s: unknown builtin (idle, spinner, forager, hunter, forager-hunter)", esc);
            return -1;
        }
        c->ctrl.builtin = b;
        c->origin.builtin = 1;
        return 0;
    }
    if (duel_read_blob_in(spec, &c->blob, &size, &c->origin, want_world, msg, cap) != 0)
        return -1;
    c->blob_len = size;
    err = nrt_mem_required(c->blob, size, &need);
    if (!err) {
        c->mem = malloc(need);
        err = c->mem == NULL ? NRT_E_NOMEM : nrt_load(&c->net, c->blob, size, c->mem, need);
    }
    if (err) {
        snprintf(msg, cap, "%s: not a valid champion blob: %s", esc, nrt_strerror(err));
        duel_cli_ctrl_close(c);
        return -1;
    }
    if (c->net.n_inputs != DUEL_N_INPUTS || c->net.n_outputs != DUEL_N_OUTPUTS) {
        snprintf(msg, cap, "%s: a network with %u inputs and %u outputs, not the duel's %d and %d", esc,
                 (unsigned)c->net.n_inputs, (unsigned)c->net.n_outputs, DUEL_N_INPUTS, DUEL_N_OUTPUTS);
        duel_cli_ctrl_close(c);
        return -1;
    }
    c->ctrl.net = &c->net;
    return 0;
}

static int duel_ctrl_open_in(duel_cli_ctrl *c, const char *spec, int want_world)
{
    char msg[4600];
    if (duel_ctrl_open_msg(c, spec, want_world, msg, sizeof msg) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return -1;
}

void duel_cli_ctrl_close(duel_cli_ctrl *c)
{
    free(c->blob);
    free(c->mem);
    c->blob = NULL;
    c->mem = NULL;
    c->ctrl.net = NULL;
}

void duel_fixed_run_refused_msg(const char *prefix, const char *path, char *msg, size_t cap)
{
    char esc[1100];
    snprintf(msg, cap, "%s%s: the checkpoint of a run against fixed opponents (one population, no dominance "
                       "tournament): compare, ladder and experiment measure coevolution runs; play its champions "
                       "instead (champions/gen-G.blob)", prefix, duel_text_escape(path, esc, sizeof esc));
}

void duel_fixed_run_refused(const char *prefix, const char *path)
{
    char msg[1600];
    duel_fixed_run_refused_msg(prefix, path, msg, sizeof msg);
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
}

int duel_run_is_fixed(const char *dir)
{
    char path[4200];
    uint8_t head[8];
    FILE *f;
    int yes;
    if ((size_t)snprintf(path, sizeof path, "%s/checkpoint.bin", dir) >= sizeof path ||
        (f = duel_fopen_regular(path)) == NULL)
        return 0;
    yes = fread(head, 1, 8, f) == 8 && neat_checkpoint_kind(head, 8) == NEAT_CKPT_POP;
    fclose(f);
    return yes;
}

int duel_any_ckpt_load_msg(const char *prefix, const char *path, neat_coev **coev, neat_pop **pop, uint32_t *format,
                           char *msg, size_t cap)
{
    uint8_t *buf;
    size_t len, off = 0;
    uint32_t v = 0;
    char esc[1100];
    int err, kind;
    if (coev != NULL)
        *coev = NULL;
    if (pop != NULL)
        *pop = NULL;
    msg[0] = '\0';
    duel_text_escape(path, esc, sizeof esc);
    if (duel_file_read(path, DUEL_CKPT_MAX, &buf, &len) != 0) {
        if (errno == ENOENT)
            return 1;
        snprintf(msg, cap, "%s%s: cannot read: %s", prefix, esc,
                 errno == EFBIG ? "larger than 1 GB" : duel_file_strerror(errno));
        return -1;
    }
    kind = neat_checkpoint_kind(buf, len);
    if (len >= 12)
        v = (uint32_t)buf[8] | (uint32_t)buf[9] << 8 | (uint32_t)buf[10] << 16 | (uint32_t)buf[11] << 24;
    if (format != NULL)
        *format = v;
    /* the kind by its magic: a population's is a run against fixed opponents'; a kind not wanted is not loaded */
    if ((kind == NEAT_CKPT_POP && pop == NULL) || (kind != NEAT_CKPT_POP && coev == NULL)) {
        free(buf);
        return -2;
    }
    err = kind == NEAT_CKPT_POP ? neat_pop_load(pop, buf, len, NULL, &off) : neat_coev_load(coev, buf, len, NULL, &off);
    if (err == NEAT_E_FORMAT && off == 8 && len >= 12 && kind == NEAT_CKPT_COEV)
        snprintf(msg, cap, "%s%s: offset 8: checkpoint format %lu, but this duel_evolve reads format %d "
                           "(docs/formats.md)", prefix, esc, (unsigned long)v, NEAT_COEV_CHECKPOINT_VERSION);
    else if (err)
        snprintf(msg, cap, "%s%s: offset %zu: %s", prefix, esc, off, neat_strerror(err));
    free(buf);
    return err ? -1 : 0;
}

int duel_ckpt_load_msg(const char *prefix, const char *path, neat_coev **out, char *msg, size_t cap)
{
    int r = duel_any_ckpt_load_msg(prefix, path, out, NULL, NULL, msg, cap);
    if (r == -2) {
        duel_fixed_run_refused_msg(prefix, path, msg, cap);
        return -1;
    }
    return r;
}

int duel_ckpt_load(const char *prefix, const char *path, neat_coev **out)
{
    char msg[4600];
    int r = duel_ckpt_load_msg(prefix, path, out, msg, sizeof msg);
    if (r < 0)
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return r;
}

int duel_ckpt_world_msg(const struct neat_coev *c, const char *path, duel_rules *r, char *msg, size_t cap)
{
    size_t len = 0, off = 0;
    const uint8_t *tag = neat_coev_game(c, &len);
    char esc[1100];
    /* the rules' bytes come first; what follows is the run's own (docs/tools.md, "The run directory"); no tag:
     * world v1 */
    if (duel_tag_world(tag, len, r, &off) < 0) {
        snprintf(msg, cap, "%s: its world's rules (the game tag) are damaged at byte %zu of %zu",
                 duel_text_escape(path, esc, sizeof esc), off, len);
        return -1;
    }
    return 0;
}

int duel_ckpt_world(const struct neat_coev *c, const char *path, duel_rules *r)
{
    char msg[1400];
    if (duel_ckpt_world_msg(c, path, r, msg, sizeof msg) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return -1;
}

int duel_run_world_msg(const char *dir, duel_rules *r, char *msg, size_t cap)
{
    char path[4200], esc[1100];
    neat_coev *c;
    neat_pop *pop;
    int e;
    if ((size_t)snprintf(path, sizeof path, "%s/checkpoint.bin", dir) >= sizeof path) {
        snprintf(msg, cap, "%s: the path is too long", duel_text_escape(dir, esc, sizeof esc));
        return -1;
    }
    /* a run against fixed opponents checkpoints one population: its tag the same */
    e = duel_any_ckpt_load_msg("", path, &c, &pop, NULL, msg, cap);
    if (e < 0)
        return -1;
    if (e == 0 && pop != NULL) {
        size_t tlen = 0;
        const uint8_t *tag = neat_pop_game(pop, &tlen);
        e = duel_tag_world(tag, tlen, r, NULL); /* such a run's tag always names its world */
        neat_pop_free(pop);
        if (e != 0) {
            snprintf(msg, cap, "%s: its world's rules (the game tag) are missing or damaged",
                     duel_text_escape(path, esc, sizeof esc));
            return -1;
        }
        return 0;
    }
    if (e == 0) {
        e = duel_ckpt_world_msg(c, path, r, msg, cap);
        neat_coev_free(c);
        return e;
    }
    snprintf(path, sizeof path, "%s/config.ini", dir);
    if (access(path, F_OK) != 0) {
        *r = *duel_rules_v1();
        return 0;
    }
    return duel_world_of_run_msg(r, dir, msg, cap);
}

int duel_run_world(const char *dir, duel_rules *r)
{
    char msg[4600];
    if (duel_run_world_msg(dir, r, msg, sizeof msg) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return -1;
}

int duel_ctrl_world(const char *const *specs, int n, duel_rules *r, int *found)
{
    char first[4200], a[40], b[40];
    duel_origin o;
    int i;
    *found = 0;
    for (i = 0; i < n; i++) {
        if (duel_ctrl_origin(specs[i], &o) != 0)
            return -1;
        if (o.world_from == DUEL_ORIGIN_NONE)
            continue;
        if (*found && !duel_rules_equal(&o.world, r)) {
            fprintf(stderr, "duel_evolve: %s is of world %s, %s of world %s: give --world to play them in one\n",
                    duel_esc(first), duel_world_label(r, a, sizeof a), duel_esc(specs[i]), duel_world_label(&o.world, b, sizeof b));
            return -1;
        }
        if (!*found)
            snprintf(first, sizeof first, "%s", specs[i]);
        *r = o.world;
        *found = 1;
    }
    return 0;
}
