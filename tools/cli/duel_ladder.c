/* duel_ladder.c - `duel_evolve ladder DIR`: every dominant strategy of a run (or some of them) against the built-in strategies (or some), into ladder.csv, a table or JSON. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_text.h"
#include "duel_files.h"
#include "duel_ladder_games.h"
#include "duel_outputs.h"
#include "duel_world_cfg.h"

#define DUEL_LADDER_USAGE                                                                                          \
    "usage: duel_evolve ladder DIR [--top | --levels L1-L2] [--against NAME,...] [--world NAME|FILE] [--csv FILE] " \
    "[--force] [--json]"

/* What to play and where the results go. */
typedef struct duel_ladder_opts {
    const char *dir, *csv, *world_arg;
    duel_rules world;                /* the run's, or --world's */
    int top, json, subset, force;
    uint32_t lo, hi;                 /* levels lo..hi (1-based, inclusive); 0, 0: all */
    int against[DUEL_N_BUILTINS];    /* the built-in strategies, in the order given */
    uint32_t n_against;
} duel_ladder_opts;

/* "L" or "L1-L2" */
static int duel_ladder_levels(const char *v, uint32_t *lo, uint32_t *hi)
{
    char *end;
    unsigned long a, b;
    errno = 0;
    a = strtoul(v, &end, 10);
    b = a;
    if (*end == '-') {
        const char *w = end + 1;
        if (*w < '0' || *w > '9')
            return -1;
        b = strtoul(w, &end, 10);
    }
    if (*v < '0' || *v > '9' || *end != '\0' || errno || a < 1 || b < a || b > 1000000)
        return -1;
    *lo = (uint32_t)a;
    *hi = (uint32_t)b;
    return 0;
}

/* "idle,forager": each name once */
static int duel_ladder_against(const char *v, duel_ladder_opts *o)
{
    char buf[256], *tok, *save = NULL;
    uint32_t k;
    if (strlen(v) >= sizeof buf)
        return -1;
    strcpy(buf, v);
    o->n_against = 0;
    for (tok = strtok_r(buf, ",", &save); tok != NULL; tok = strtok_r(NULL, ",", &save)) {
        int b = duel_builtin_parse(tok);
        if (b < 0)
            return -1;
        for (k = 0; k < o->n_against; k++)
            if (o->against[k] == b)
                return -1;
        o->against[o->n_against++] = b;
    }
    return o->n_against > 0 ? 0 : -1;
}

static int duel_ladder_parse(int argc, char **argv, duel_ladder_opts *o)
{
    int i, b;
    memset(o, 0, sizeof *o);
    for (b = 0; b < DUEL_N_BUILTINS; b++)
        o->against[b] = b;
    o->n_against = DUEL_N_BUILTINS;
    for (i = 0; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--top") == 0) {
            o->top = 1;
        } else if (strcmp(a, "--json") == 0) {
            o->json = 1;
        } else if (strcmp(a, "--force") == 0) {
            o->force = 1;
        } else if (strcmp(a, "--levels") == 0 || strcmp(a, "--against") == 0 || strcmp(a, "--csv") == 0 ||
                   strcmp(a, "--world") == 0) {
            if (v == NULL) {
                fprintf(stderr, "duel_evolve: ladder: %s needs a value\n", a);
                return -1;
            }
            i++;
            if (strcmp(a, "--csv") == 0) {
                o->csv = v;
            } else if (strcmp(a, "--world") == 0) {
                o->world_arg = v;
                o->subset = 1; /* another world's ladder is not the run's ladder.csv */
            } else if (strcmp(a, "--levels") == 0) {
                if (duel_ladder_levels(v, &o->lo, &o->hi) != 0) {
                    fprintf(stderr, "duel_evolve: ladder: --levels takes L or L1-L2 (levels from 1), not '%s'\n", duel_esc(v));
                    return -1;
                }
                o->subset = 1;
            } else {
                if (duel_ladder_against(v, o) != 0) {
                    fprintf(stderr, "duel_evolve: ladder: --against takes built-in strategies separated by commas, "
                                    "each once (idle, spinner, forager, hunter, forager-hunter), not '%s'\n", duel_esc(v));
                    return -1;
                }
                o->subset |= o->n_against != DUEL_N_BUILTINS;
                for (b = 0; b < (int)o->n_against; b++)
                    o->subset |= o->against[b] != b; /* another order is another table */
            }
        } else if (a[0] != '-' && o->dir == NULL) {
            o->dir = a;
        } else {
            fprintf(stderr, "duel_evolve: ladder: unknown option '%s' (%s)\n", duel_esc(a), DUEL_LADDER_USAGE);
            return -1;
        }
    }
    if (o->dir == NULL) {
        fprintf(stderr, "%s\n", DUEL_LADDER_USAGE);
        return -1;
    }
    if (o->top && o->lo != 0) {
        fprintf(stderr, "duel_evolve: ladder: --top and --levels name the levels twice: give one\n");
        return -1;
    }
    /* the games are the run's own unless --world says otherwise */
    if (o->world_arg != NULL ? duel_world_arg(&o->world, o->world_arg) : duel_run_world(o->dir, &o->world))
        return -1;
    /* before any game: an output that is not a ladder is refused now, not after the work */
    if (o->csv != NULL || !o->subset) {
        const duel_out_kind *kind = &duel_ladder_csv_kind;
        char path[4200];
        const char *in[1];
        in[0] = o->dir;
        snprintf(path, sizeof path, "%s/ladder.csv", o->dir);
        if (o->csv != NULL ? duel_out_allowed("ladder", "--csv", o->csv, kind, o->force, in, 1) != 0
                           : duel_out_own_allowed("ladder", "its", path, kind, o->force, in, 1) != 0)
            return -1;
    }
    return 0;
}

int duel_cmd_ladder(int argc, char **argv)
{
    duel_ladder_opts o;
    duel_ladder L;
    char path[4200], msg[4600], *text = NULL;
    size_t len = 0;
    FILE *mem;
    int e;

    if (duel_ladder_parse(argc, argv, &o) != 0)
        return 2;
    e = duel_ladder_play(&L, o.dir, &o.world, o.top, o.lo, o.hi, o.against, o.n_against, 0, msg, sizeof msg);
    mem = e ? NULL : open_memstream(&text, &len);
    if (mem == NULL) {
        fprintf(stderr, "duel_evolve: %s\n", e ? duel_esc_msg(msg) : "ladder: out of memory");
        duel_ladder_free(&L);
        return e ? e : 1;
    }
    duel_ladder_write_csv(mem, &L);
    fclose(mem);
    if (o.json)
        duel_ladder_write_json(stdout, &L);
    else
        duel_ladder_write_table(stdout, &L);
    duel_ladder_free(&L);
    /* DIR/ladder.csv holds the whole ladder (or --top's row, as an experiment keeps it): a part of it only
     * where --csv says */
    e = 0;
    if (o.csv != NULL || !o.subset) {
        if (o.csv != NULL)
            snprintf(path, sizeof path, "%s", o.csv);
        else
            snprintf(path, sizeof path, "%s/ladder.csv", o.dir);
        e = duel_file_replace(path, text, len) != 0;
        if (e)
            fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    }
    free(text);
    return e ? 1 : 0;
}
