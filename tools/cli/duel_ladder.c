/* duel_ladder.c - `duel_evolve ladder DIR`: every dominant strategy of a run (or some of them) against the built-in strategies (or some), into ladder.csv, a table or JSON. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_text.h"
#include "duel_files.h"
#include "duel_json.h"
#include "duel_outputs.h"
#include "duel_levels.h"
#include "duel_pairs.h"
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
        static const duel_out_kind kind = {"a ladder CSV", "level,generation,population,hidden,connections,", NULL};
        char path[4200];
        const char *in[1];
        in[0] = o->dir;
        snprintf(path, sizeof path, "%s/ladder.csv", o->dir);
        if (o->csv != NULL ? duel_out_allowed("ladder", "--csv", o->csv, &kind, o->force, in, 1) != 0
                           : duel_out_own_allowed("ladder", "its", path, &kind, o->force, in, 1) != 0)
            return -1;
    }
    return 0;
}

/* The CSV: level, generation, population, hidden, connections, NAME_wins, NAME_losses per strategy, totals,
 * then the world the games were played in and the dominant's network step (issue 49: a file that leaves its run
 * still says what it was measured in). */
static void duel_ladder_csv(FILE *f, const duel_ladder_opts *o, const duel_level *lv, uint32_t first, uint32_t end,
                            const duel_pair *pairs)
{
    uint32_t k, b;
    char w[40];
    duel_world_label(&o->world, w, sizeof w);
    fprintf(f, "level,generation,population,hidden,connections");
    for (b = 0; b < o->n_against; b++)
        fprintf(f, ",%s_wins,%s_losses", duel_builtin_name(o->against[b]), duel_builtin_name(o->against[b]));
    fprintf(f, ",total_wins,total_losses,world,step\n");
    for (k = first; k < end; k++) {
        uint32_t tw = 0, tl = 0;
        fprintf(f, "%u,%u,%s,%u,%u", lv[k].level, lv[k].generation, lv[k].pop, lv[k].hidden, lv[k].conns);
        for (b = 0; b < o->n_against; b++) {
            const duel_tally *t = &pairs[(k - first) * o->n_against + b].tally;
            fprintf(f, ",%u,%u", t->wins_a, t->wins_b);
            tw += t->wins_a;
            tl += t->wins_b;
        }
        fprintf(f, ",%u,%u,%s,%s\n", tw, tl, w, duel_origin_step_text(&lv[k].ctrl.origin));
    }
}

static void duel_ladder_table(const duel_ladder_opts *o, const duel_level *lv, uint32_t first, uint32_t end,
                              const duel_pair *pairs)
{
    uint32_t k, b;
    printf("%-5s %-5s %-3s %-6s %-5s", "level", "gen", "pop", "hidden", "conns");
    for (b = 0; b < o->n_against; b++)
        printf(" %15s", duel_builtin_name(o->against[b]));
    printf(" %11s\n", "total");
    for (k = first; k < end; k++) {
        uint32_t tw = 0, tl = 0;
        printf("%-5u %-5u %-3s %-6u %-5u", lv[k].level, lv[k].generation, lv[k].pop, lv[k].hidden, lv[k].conns);
        for (b = 0; b < o->n_against; b++) {
            const duel_tally *t = &pairs[(k - first) * o->n_against + b].tally;
            printf(" %7u:%-7u", t->wins_a, t->wins_b);
            tw += t->wins_a;
            tl += t->wins_b;
        }
        printf(" %5u:%-5u\n", tw, tl);
    }
    {
        char w[40];
        printf("wins:losses of %u games against each built-in strategy (draws and timeouts are neither), world %s, "
               "network step %s\n", 2u * DUEL_CONFIGS, duel_world_label(&o->world, w, sizeof w),
               end > first ? duel_origin_step_text(&lv[first].ctrl.origin) : "none");
    }
}

/* docs/tools.md, "ladder --json" */
static void duel_ladder_json(const duel_ladder_opts *o, const duel_level *lv, uint32_t first, uint32_t end,
                             const duel_pair *pairs)
{
    uint32_t k, b;
    char w[40];
    printf("{\"run\":");
    duel_json_str(stdout, o->dir);
    printf(",\"world\":\"%s\",\"world_id\":\"%016llx\",\"step\":\"%s\",\"games\":%u,\"against\":[",
           duel_world_label(&o->world, w, sizeof w), (unsigned long long)duel_rules_id(&o->world),
           end > first ? duel_origin_step_text(&lv[first].ctrl.origin) : "none", 2u * DUEL_CONFIGS);
    for (b = 0; b < o->n_against; b++)
        printf("%s\"%s\"", b ? "," : "", duel_builtin_name(o->against[b]));
    printf("],\"levels\":[");
    for (k = first; k < end; k++) {
        uint32_t tw = 0, tl = 0;
        printf("%s{\"level\":%u,\"generation\":%u,\"population\":\"%s\",\"hidden\":%u,\"connections\":%u,"
               "\"results\":{", k > first ? "," : "", lv[k].level, lv[k].generation, lv[k].pop, lv[k].hidden,
               lv[k].conns);
        for (b = 0; b < o->n_against; b++) {
            const duel_tally *t = &pairs[(k - first) * o->n_against + b].tally;
            printf("%s\"%s\":{\"wins\":%u,\"losses\":%u,\"draws\":%u,\"timeouts\":%u}", b ? "," : "",
                   duel_builtin_name(o->against[b]), t->wins_a, t->wins_b, t->draws, t->timeouts);
            tw += t->wins_a;
            tl += t->wins_b;
        }
        printf("},\"total_wins\":%u,\"total_losses\":%u}", tw, tl);
    }
    printf("]}\n");
}

int duel_cmd_ladder(int argc, char **argv)
{
    duel_ladder_opts o;
    duel_level *levels;
    duel_cli_ctrl builtins[DUEL_N_BUILTINS];
    duel_pair *pairs;
    uint32_t n, k, first, end, b;
    char path[4200], *text = NULL;
    size_t len = 0;
    FILE *mem;
    int err;

    if (duel_ladder_parse(argc, argv, &o) != 0)
        return 2;
    if (duel_levels_read(o.dir, &levels, &n) != 0)
        return 2;
    /* --top: the highest dominant alone (what an experiment's report needs); --levels: a range */
    first = o.top ? n - 1 : (o.lo ? o.lo - 1 : 0);
    end = o.lo ? o.hi : n;
    if (o.lo && o.hi > n) {
        fprintf(stderr, "duel_evolve: ladder: %s has %u dominance level%s, not %u\n", o.dir, n, n == 1 ? "" : "s",
                o.hi);
        duel_levels_free(levels, n);
        return 2;
    }
    /* one comparison per (level, strategy) */
    memset(builtins, 0, sizeof builtins);
    for (b = 0; b < o.n_against; b++)
        builtins[b].ctrl.builtin = o.against[b];
    pairs = (duel_pair *)calloc((size_t)(end - first) * o.n_against, sizeof *pairs);
    if (pairs == NULL) {
        fprintf(stderr, "duel_evolve: ladder: out of memory\n");
        duel_levels_free(levels, n);
        return 1;
    }
    for (k = 0; k < (end - first) * o.n_against; k++) {
        pairs[k].a = &levels[first + k / o.n_against].ctrl;
        pairs[k].b = &builtins[k % o.n_against];
    }
    err = duel_pairs_play(&o.world, pairs, (size_t)(end - first) * o.n_against, 0, NULL, NULL);
    mem = err ? NULL : open_memstream(&text, &len);
    if (mem == NULL) {
        fprintf(stderr, "duel_evolve: ladder: %s\n", err ? "a comparison failed" : "out of memory");
        free(pairs);
        duel_levels_free(levels, n);
        return 1;
    }
    duel_ladder_csv(mem, &o, levels, first, end, pairs);
    fclose(mem);
    if (o.json)
        duel_ladder_json(&o, levels, first, end, pairs);
    else
        duel_ladder_table(&o, levels, first, end, pairs);
    free(pairs);
    duel_levels_free(levels, n);
    /* DIR/ladder.csv holds the whole ladder (or --top's row, as an experiment keeps it): a part of it only
     * where --csv says */
    k = 0;
    if (o.csv != NULL || !o.subset) {
        if (o.csv != NULL)
            snprintf(path, sizeof path, "%s", o.csv);
        else
            snprintf(path, sizeof path, "%s/ladder.csv", o.dir);
        k = duel_file_replace(path, text, len) != 0;
        if (k)
            fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    }
    free(text);
    return k ? 1 : 0;
}
