/* duel_compare.c - `duel_evolve compare RUN... --against RUN...`: the paper's performance measure, each run's highest dominant against the dominance rankings of other runs, in both readings. */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "duel_cli.h"
#include "duel_json.h"
#include "duel_cmp_cache.h"
#include "duel_config.h"
#include "duel_ctrl.h"
#include "duel_files.h"
#include "duel_outputs.h"
#include "duel_perf.h"
#include "duel_text.h"
#include "duel_world_cfg.h"

#define DUEL_CMP_USAGE "usage: duel_evolve compare RUN... --against RUN... [--threads T] [--json FILE] [--csv FILE] [--cache FILE] [--force]"

static void duel_cmp_print(const duel_perf *m)
{
    duel_cmp_stats h = duel_cmp_stat(m->perf_hi, m->n_cand), c = duel_cmp_stat(m->perf_co, m->n_cand),
                   gh = duel_cmp_stat(m->gen_hi, m->n_cand), gc = duel_cmp_stat(m->gen_co, m->n_cand);
    size_t w = 14;
    uint32_t i;
    char wl[40];
    for (i = 0; i < m->n_cand; i++)
        if (strlen(m->runs[i].dir) > w)
            w = strlen(m->runs[i].dir);
    printf("%u run%s against the dominance rankings of %u run%s (never its own): %u pairs, %zu comparisons of %d "
           "games (%zu played, %zu from the cache), world %s\n",
           m->n_cand, m->n_cand == 1 ? "" : "s", m->n_rank, m->n_rank == 1 ? "" : "s", m->n_pairs, m->played + m->cached,
           2 * DUEL_CONFIGS, m->played, m->cached, duel_world_label(&m->world, wl, sizeof wl));
    printf("%-*s  %6s %6s   %-24s   %-24s\n", (int)w, "", "top", "top", "highest level defeated",
           "every level up to");
    printf("%-*s  %6s %6s   %11s %12s   %11s %12s\n", (int)w, "run", "level", "gen", "performance", "equiv. gen",
           "performance", "equiv. gen");
    for (i = 0; i < m->n_cand; i++) {
        const duel_perf_run *r = &m->runs[i];
        printf("%-*s  %6u %6u   %9.1f %% %12.1f   %9.1f %% %12.1f\n", (int)w, r->dir, r->n_levels,
               r->levels[r->n_levels - 1].generation, 100.0 * m->perf_hi[i], m->gen_hi[i], 100.0 * m->perf_co[i],
               m->gen_co[i]);
    }
    printf("%-*s  %13s   %9.1f %% %12.1f   %9.1f %% %12.1f\n", (int)w, "mean", "", 100.0 * h.mean, gh.mean,
           100.0 * c.mean, gc.mean);
    printf("%-*s  %13s   %9.1f %% %12.1f   %9.1f %% %12.1f\n", (int)w, "sd (over runs)", "", 100.0 * h.sd, gh.sd,
           100.0 * c.sd, gc.sd);
}

int duel_cmd_compare(int argc, char **argv)
{
    duel_perf m;
    duel_perf_opts o;
    const char *json = NULL, *csv = NULL, *cache_path = NULL, **cand = NULL, **against = NULL;
    uint32_t threads = 0, n_against = 0, n_cand = 0, i;
    int in_against = 0, rc = 2, force = 0;

    memset(&m, 0, sizeof m);
    cand = (const char **)calloc((size_t)argc + 1, sizeof *cand);
    against = (const char **)calloc((size_t)argc + 1, sizeof *against);
    if (cand == NULL || against == NULL) {
        fprintf(stderr, "duel_evolve: compare: out of memory\n");
        goto out;
    }
    for (i = 0; i < (uint32_t)argc; i++) {
        const char *a = argv[i], *v = i + 1 < (uint32_t)argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--against") == 0) {
            in_against = 1;
        } else if (strcmp(a, "--force") == 0) {
            force = 1;
        } else if (strcmp(a, "--threads") == 0 || strcmp(a, "--json") == 0 || strcmp(a, "--csv") == 0 ||
                   strcmp(a, "--cache") == 0) {
            if (v == NULL) {
                fprintf(stderr, "duel_evolve: compare: %s needs a value\n", a);
                goto out;
            }
            i++;
            if (strcmp(a, "--threads") == 0) {
                char *end;
                unsigned long t;
                errno = 0;
                t = strtoul(v, &end, 10);
                if (*v < '0' || *v > '9' || *end != '\0' || errno || t > 256) {
                    fprintf(stderr, "duel_evolve: compare: --threads takes 0 (every core) to 256, not '%s'\n", duel_esc(v));
                    goto out;
                }
                threads = (uint32_t)t;
            } else if (strcmp(a, "--json") == 0) {
                json = v;
            } else if (strcmp(a, "--csv") == 0) {
                csv = v;
            } else {
                cache_path = v;
            }
        } else if (a[0] == '-') {
            fprintf(stderr, "duel_evolve: compare: unknown option '%s' (%s)\n", duel_esc(a), DUEL_CMP_USAGE);
            goto out;
        } else if (in_against) {
            against[n_against++] = a;
        } else {
            cand[n_cand++] = a;
        }
    }
    /* before any game: outputs that would replace an input or a file that is not this command's are refused */
    {
        const char **in = (const char **)calloc((size_t)n_cand + n_against + 3, sizeof *in);
        uint32_t n_in = 0;
        int bad;
        if (in == NULL) {
            fprintf(stderr, "duel_evolve: compare: out of memory\n");
            goto out;
        }
        for (i = 0; i < n_cand; i++)
            in[n_in++] = cand[i];
        for (i = 0; i < n_against; i++)
            in[n_in++] = against[i];
        in[n_in] = json;
        in[n_in + 1] = cache_path;
        bad = csv != NULL && duel_out_allowed("compare", "--csv", csv, &duel_perf_csv_kind, force, in, n_in + 2) != 0;
        in[n_in] = csv;
        bad = bad || (json != NULL && duel_out_allowed("compare", "--json", json, &duel_perf_json_kind, force, in, n_in + 2) != 0);
        in[n_in + 1] = json;
        bad = bad || (cache_path != NULL &&
                      duel_out_allowed("compare", "--cache", cache_path, &duel_perf_cache_kind, force, in, n_in + 2) != 0);
        free(in);
        if (bad)
            goto out;
    }
    memset(&o, 0, sizeof o);
    o.force = force;
    o.threads = threads;
    o.cache_path = cache_path;
    o.mode = DUEL_PERF_PLAY;
    o.prefix = "compare: ";
    o.progress = isatty(STDERR_FILENO);
    rc = duel_perf_measure(&m, cand, n_cand, against, n_against, &o);
    if (rc != 0)
        goto out;
    rc = 0;
    if (csv != NULL && duel_file_write_with(csv, duel_perf_write_csv, &m) != 0)
        rc = 1;
    if (json != NULL && duel_file_write_with(json, duel_perf_write_json, &m) != 0)
        rc = 1;
    duel_cmp_print(&m);
out:
    duel_perf_free(&m);
    free(cand);
    free(against);
    return rc;
}
