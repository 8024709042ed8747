/* duel_exp_report.c - an experiment's report from its files alone: Table 1 with Mann-Whitney p-values, per-run rows, the ladder per method, the data of Figures 7, 11 and 12-15, then the plots. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "duel_ctrl.h"
#include "duel_dominance.h"
#include "duel_exp.h"
#include "duel_files.h"
#include "duel_generations.h"
#include "duel_perf.h"
#include "duel_stats.h"
#include "duel_world_cfg.h"
#include "duel_text.h"

#ifndef DUEL_PLOT_SCRIPT
#define DUEL_PLOT_SCRIPT "plot_experiment.py"
#endif
#ifndef DUEL_PYTHON
#define DUEL_PYTHON "python3"
#endif

#define DUEL_REP_MAX_FIELDS 64

/* Table 1's columns: the statistic of each run that a method's mean, sd and p-value are taken of. */
enum { COL_LEVELS, COL_TOPGEN, COL_PERF_HI, COL_GEN_HI, COL_PERF_CO, COL_GEN_CO, N_COLS };
static const char *const col_key[N_COLS] = {"levels", "top_generation", "highest_performance",
                                            "highest_equivalent_generation", "contiguous_performance",
                                            "contiguous_equivalent_generation"};

typedef struct rep_run {
    uint32_t method, k, seed, generations;
    char dir[300];
    duel_dominance_row *rows;
    uint32_t n_levels;
    duel_dominance_score *scores;
    double col[N_COLS];
    uint32_t ladder[DUEL_N_BUILTINS + 1][2]; /* the top dominant's wins and losses; [DUEL_N_BUILTINS]: total */
    double seconds;
    duel_rules world; /* the run's own (its checkpoint's tag) */
    int net_step;     /* its config.ini's */
} rep_run;

typedef struct rep_method {
    uint32_t first, n;    /* its runs: runs[first .. first + n) */
    double mean[N_COLS], sd[N_COLS];
    duel_test test[N_COLS]; /* against the reference method */
    uint32_t typical;     /* index into runs */
    duel_perf perf;       /* its runs against the reference rankings */
} rep_method;

typedef struct rep {
    const duel_plan *p;
    const char *dir;
    rep_run *runs;
    uint32_t n_runs;
    rep_method m[DUEL_PLAN_MAX_METHODS];
    duel_test wil_conns, wil_hidden;
    duel_rules world;     /* every run's: a report of runs of several worlds is refused */
    char world_label[40];
    double first_conns, final_conns, first_hidden, final_hidden;
    uint32_t games; /* games per comparison of the reference runs' dominance tournaments */
} rep;

/* Splits a CSV line (no quoting: the tools write none) into at most max fields, in place. */
static uint32_t rep_split(char *line, char **f, uint32_t max)
{
    uint32_t n = 0;
    char *p = line;
    while (n < max) {
        f[n++] = p;
        p = strchr(p, ',');
        if (p == NULL)
            break;
        *p++ = '\0';
    }
    return n;
}

/* The file's lines (newline-terminated ones) one by one: fn(ud, line number, line) on a writable copy. */
typedef int (*rep_line_fn)(void *ud, uint32_t line, char *text);
static int rep_lines(const char *path, rep_line_fn fn, void *ud)
{
    uint8_t *data;
    size_t len, i, start = 0;
    uint32_t line = 0;
    if (duel_file_read(path, 256u << 20, &data, &len) != 0)
        return -1;
    for (i = 0; i < len; i++)
        if (data[i] == '\n') {
            data[i] = '\0';
            if (fn(ud, ++line, (char *)data + start) != 0) {
                free(data);
                return -2;
            }
            start = i + 1;
        }
    free(data);
    return 0;
}

/* ---- what each run left */

typedef struct rep_ladder_ctx {
    rep_run *r;
    const char *path;
    int ok;
    uint32_t fields; /* the header's */
} rep_ladder_ctx;

static int rep_ladder_line(void *ud, uint32_t line, char *text)
{
    rep_ladder_ctx *c = (rep_ladder_ctx *)ud;
    char *f[DUEL_REP_MAX_FIELDS];
    uint32_t n = rep_split(text, f, DUEL_REP_MAX_FIELDS), b;
    /* ladder.csv ends with world and step since issue 49; a run's older ladder.csv (2 fields fewer) still reads */
    if (line == 1)
        c->fields = n;
    if (line == 1) {
        if ((n != 7 + 2 * DUEL_N_BUILTINS && n != 9 + 2 * DUEL_N_BUILTINS) || strcmp(f[0], "level") != 0) {
            fprintf(stderr, "duel_evolve: experiment: %s:1: not the ladder.csv of this version (delete it: the "
                            "experiment writes it again)\n", duel_esc(c->path));
            return -1;
        }
        for (b = 0; b < DUEL_N_BUILTINS; b++)
            if (strncmp(f[5 + 2 * b], duel_builtin_name((int)b), strlen(duel_builtin_name((int)b))) != 0) {
                fprintf(stderr, "duel_evolve: experiment: %s:1: built-in strategy %s expected in column %u\n",
                        duel_esc(c->path), duel_builtin_name((int)b), 6 + 2 * b);
                return -1;
            }
        return 0;
    }
    if (n != c->fields) {
        fprintf(stderr, "duel_evolve: experiment: %s:%u: %u fields, expected %u\n", duel_esc(c->path), line, n, c->fields);
        return -1;
    }
    /* the last row is the top dominant's */
    for (b = 0; b <= DUEL_N_BUILTINS; b++) {
        c->r->ladder[b][0] = (uint32_t)strtoul(f[5 + 2 * b], NULL, 10);
        c->r->ladder[b][1] = (uint32_t)strtoul(f[6 + 2 * b], NULL, 10);
    }
    c->ok = (uint32_t)strtoul(f[0], NULL, 10) == c->r->n_levels;
    return 0;
}

static int rep_read_run(rep *R, rep_run *r)
{
    char err[4400], path[400];
    rep_ladder_ctx lc;
    int e;
    if (duel_dominance_read_scores(r->dir, &r->rows, &r->n_levels, &r->scores, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s/%s\n", duel_esc(R->dir), duel_esc_msg(err));
        return 2;
    }
    if (r->n_levels == 0) {
        fprintf(stderr, "duel_evolve: experiment: %s/%s/dominance.csv: no dominance level\n", duel_esc(R->dir), r->dir);
        return 2;
    }
    /* the world and step the run was made with: the report names them, and refuses runs of several worlds */
    if (duel_run_world(r->dir, &r->world) != 0)
        return 2;
    r->net_step = duel_run_net_step(r->dir);
    snprintf(path, sizeof path, "%s/ladder.csv", r->dir);
    lc.r = r;
    lc.path = path;
    lc.ok = 0;
    lc.fields = 0; /* set by the header line, which rep_lines reads first */
    e = rep_lines(path, rep_ladder_line, &lc);
    if (e == -1)
        fprintf(stderr, "duel_evolve: experiment: %s/%s: %s (continue the experiment to play its ladder)\n", duel_esc(R->dir),
                duel_esc(path), strerror(errno));
    else if (e == 0 && !lc.ok)
        fprintf(stderr, "duel_evolve: experiment: %s/%s: its last row is not the run's level %u (delete it: the "
                        "experiment writes it again)\n", duel_esc(R->dir), duel_esc(path), r->n_levels);
    if (e != 0 || !lc.ok)
        return 2;
    {
        duel_gen_row *g;
        size_t n, k;
        if (duel_generations_read(r->dir, &g, &n, err, sizeof err) != 0) {
            fprintf(stderr, "duel_evolve: experiment: %s/%s: " DUEL_GENERATIONS_LOST_ADVICE "\n", duel_esc(R->dir), duel_esc_msg(err));
            return 2;
        }
        for (k = 0; k < n; k++)
            r->seconds += g[k].pop == 'A' ? g[k].seconds : 0.0;
        free(g);
    }
    r->col[COL_LEVELS] = r->n_levels;
    r->col[COL_TOPGEN] = r->rows[r->n_levels - 1].generation;
    return 0;
}

/* ---- the numbers */

static double rep_round6(double x)
{
    return floor(x * 1e6 + 0.5) / 1e6;
}

static int rep_measure(rep *R)
{
    const duel_plan *p = R->p;
    const duel_plan_method *ref = &p->m[p->ref];
    const char **against = (const char **)calloc(ref->runs, sizeof *against);
    uint32_t i, k, c;
    int rc = 0;
    if (against == NULL)
        return 1;
    for (k = 0; k < ref->runs; k++)
        against[k] = R->runs[R->m[p->ref].first + k].dir;
    for (i = 0; i < p->n_methods && rc == 0; i++) {
        rep_method *m = &R->m[i];
        const char **cand = (const char **)calloc(m->n, sizeof *cand);
        duel_perf_opts o;
        if (cand == NULL) {
            rc = 1;
            break;
        }
        for (k = 0; k < m->n; k++)
            cand[k] = R->runs[m->first + k].dir;
        memset(&o, 0, sizeof o);
        o.mode = DUEL_PERF_CACHE_ONLY;
        o.no_checkpoint = 1; /* the report needs the rankings and the caches, not the populations */
        o.prefix = "experiment: report: ";
        rc = duel_perf_measure(&m->perf, cand, m->n, against, ref->runs, &o);
        free(cand);
        for (k = 0; rc == 0 && k < m->n; k++) {
            rep_run *r = &R->runs[m->first + k];
            /* to the 6 decimals runs.csv prints: equal means of different fractions (10/11 as 5/11 + 5/11 or as
             * 20/22) can differ in their last bit, and the tests must see them as the tie they are; anyone who
             * recomputes a p-value from runs.csv then gets the same one */
            r->col[COL_PERF_HI] = rep_round6(m->perf.perf_hi[k]);
            r->col[COL_PERF_CO] = rep_round6(m->perf.perf_co[k]);
            r->col[COL_GEN_HI] = rep_round6(m->perf.gen_hi[k]);
            r->col[COL_GEN_CO] = rep_round6(m->perf.gen_co[k]);
        }
    }
    free(against);
    if (rc != 0)
        return rc;
    /* means, sds, and each method against the reference */
    for (i = 0; i < p->n_methods; i++) {
        rep_method *m = &R->m[i];
        for (c = 0; c < N_COLS; c++) {
            double *v = (double *)malloc(m->n * sizeof *v), *w = (double *)malloc(R->m[p->ref].n * sizeof *w);
            if (v == NULL || w == NULL) {
                free(v);
                free(w);
                return 1;
            }
            for (k = 0; k < m->n; k++)
                v[k] = R->runs[m->first + k].col[c];
            for (k = 0; k < R->m[p->ref].n; k++)
                w[k] = R->runs[R->m[p->ref].first + k].col[c];
            m->mean[c] = duel_stats_mean(v, m->n);
            m->sd[c] = duel_stats_sd(v, m->n);
            if (i != p->ref && duel_stats_mwu(w, R->m[p->ref].n, v, m->n, &m->test[c]) != 0) {
                free(v);
                free(w);
                return 1;
            }
            free(v);
            free(w);
        }
        /* the typical run: the median performance ("highest" reading; the lower one of an even count) */
        {
            uint32_t best = m->first, j;
            for (k = 0; k < m->n; k++) {
                uint32_t below = 0, same_before = 0;
                double x = R->runs[m->first + k].col[COL_PERF_HI];
                for (j = 0; j < m->n; j++) {
                    double y = R->runs[m->first + j].col[COL_PERF_HI];
                    below += y < x;
                    same_before += y == x && j < k;
                }
                if (below + same_before == (m->n - 1) / 2)
                    best = m->first + k;
            }
            m->typical = best;
        }
    }
    /* Figure 7's test: the first against the final dominant of each reference run */
    {
        const rep_method *m = &R->m[p->ref];
        double *dc = (double *)malloc(m->n * sizeof *dc), *dh = (double *)malloc(m->n * sizeof *dh);
        if (dc == NULL || dh == NULL) {
            free(dc);
            free(dh);
            return 1;
        }
        for (k = 0; k < m->n; k++) {
            const rep_run *r = &R->runs[m->first + k];
            R->first_conns += r->rows[0].conns / (double)m->n;
            R->final_conns += r->rows[r->n_levels - 1].conns / (double)m->n;
            R->first_hidden += r->rows[0].hidden / (double)m->n;
            R->final_hidden += r->rows[r->n_levels - 1].hidden / (double)m->n;
            dc[k] = (double)r->rows[r->n_levels - 1].conns - (double)r->rows[0].conns;
            dh[k] = (double)r->rows[r->n_levels - 1].hidden - (double)r->rows[0].hidden;
        }
        rc = duel_stats_wilcoxon(dc, m->n, &R->wil_conns) != 0 || duel_stats_wilcoxon(dh, m->n, &R->wil_hidden) != 0;
        free(dc);
        free(dh);
    }
    return rc;
}

/* ---- the files */

static void rep_p(FILE *f, const duel_test *t)
{
    fprintf(f, "%.6g", t->p);
}

static void rep_write_table_csv(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    uint32_t i, c;
    fprintf(f, "method,runs");
    for (c = 0; c < N_COLS; c++)
        fprintf(f, ",%s_mean,%s_sd", col_key[c], col_key[c]);
    for (c = 0; c < N_COLS; c++)
        fprintf(f, ",%s_p", col_key[c]);
    fprintf(f, ",world,step\n");
    for (i = 0; i < R->p->n_methods; i++) {
        const rep_method *m = &R->m[i];
        fprintf(f, "%s,%u", R->p->m[i].name, m->n);
        for (c = 0; c < N_COLS; c++)
            fprintf(f, ",%.6f,%.6f", m->mean[c], m->sd[c]);
        for (c = 0; c < N_COLS; c++) {
            fputc(',', f);
            if (i != R->p->ref)
                rep_p(f, &m->test[c]);
        }
        fprintf(f, ",%s,%s\n", R->world_label, duel_step_name(R->runs[m->first].net_step));
    }
}

static void rep_write_runs_csv(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    uint32_t k, c, b;
    fprintf(f, "method,run,seed,generations,top_hidden,top_connections");
    for (c = 0; c < N_COLS; c++)
        fprintf(f, ",%s", col_key[c]);
    for (b = 0; b < DUEL_N_BUILTINS; b++)
        fprintf(f, ",%s_wins,%s_losses", duel_builtin_name((int)b), duel_builtin_name((int)b));
    fprintf(f, ",ladder_wins,ladder_losses,world,step\n");
    for (k = 0; k < R->n_runs; k++) {
        const rep_run *r = &R->runs[k];
        fprintf(f, "%s,%s,%u,%u,%u,%u,%u,%u,%.6f,%.6f,%.6f,%.6f", R->p->m[r->method].name, r->dir + 5, r->seed,
                r->generations, r->rows[r->n_levels - 1].hidden, r->rows[r->n_levels - 1].conns, r->n_levels,
                r->rows[r->n_levels - 1].generation, r->col[COL_PERF_HI], r->col[COL_GEN_HI], r->col[COL_PERF_CO],
                r->col[COL_GEN_CO]);
        for (b = 0; b <= DUEL_N_BUILTINS; b++)
            fprintf(f, ",%u,%u", r->ladder[b][0], r->ladder[b][1]);
        fprintf(f, ",%s,%s\n", R->world_label, duel_step_name(r->net_step));
    }
}

static void rep_write_timing_csv(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    uint32_t k;
    fprintf(f, "method,run,generations,seconds\n");
    for (k = 0; k < R->n_runs; k++)
        fprintf(f, "%s,%s,%u,%.3f\n", R->p->m[R->runs[k].method].name, R->runs[k].dir + 5, R->runs[k].generations,
                R->runs[k].seconds);
}

/* the summed ladder of a method's top dominants */
static void rep_method_ladder(const rep *R, uint32_t i, uint32_t out[DUEL_N_BUILTINS + 1][2])
{
    uint32_t k, b;
    memset(out, 0, sizeof(uint32_t) * 2 * (DUEL_N_BUILTINS + 1));
    for (k = 0; k < R->m[i].n; k++)
        for (b = 0; b <= DUEL_N_BUILTINS; b++) {
            out[b][0] += R->runs[R->m[i].first + k].ladder[b][0];
            out[b][1] += R->runs[R->m[i].first + k].ladder[b][1];
        }
}

static void rep_write_ladder_csv(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    uint32_t i, b, l[DUEL_N_BUILTINS + 1][2];
    fprintf(f, "method,runs,opponent,games,wins,losses,world,step\n");
    for (i = 0; i < R->p->n_methods; i++) {
        rep_method_ladder(R, i, l);
        for (b = 0; b <= DUEL_N_BUILTINS; b++)
            fprintf(f, "%s,%u,%s,%u,%u,%u,%s,%s\n", R->p->m[i].name, R->m[i].n,
                    b < DUEL_N_BUILTINS ? duel_builtin_name((int)b) : "all", R->m[i].n * 2u * DUEL_CONFIGS *
                    (b < DUEL_N_BUILTINS ? 1u : (uint32_t)DUEL_N_BUILTINS), l[b][0], l[b][1], R->world_label,
                    duel_step_name(R->runs[R->m[i].first].net_step));
    }
}

static void rep_md_ms(FILE *f, double mean, double sd, int pct, int prec)
{
    if (pct)
        fprintf(f, " %.1f %% (%.1f) |", 100.0 * mean, 100.0 * sd);
    else
        fprintf(f, " %.*f (%.*f) |", prec, mean, prec, sd);
}

static void rep_write_md(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    const duel_plan *p = R->p;
    uint32_t i, c, k, b, l[DUEL_N_BUILTINS + 1][2];
    int exact = 1;
    fprintf(f, "## Table 1: the methods against the %s dominance rankings\n\n", p->reference);
    fprintf(f, "Mean (standard deviation) over each method's runs. *Highest*: the highest level of a ranking the "
               "run's top dominant defeats; *contiguous*: the highest level L such that it defeats every level up to "
               "L. Performance: that level over the ranking's levels; equivalent generation: that level's generation. "
               "Each run is measured against every %s run but itself, %u games a level, in world %s (identity "
               "%016llx).", p->reference, 2u * DUEL_CONFIGS, R->world_label, (unsigned long long)duel_rules_id(&R->world));
    for (i = 0; i < p->n_methods && R->runs[R->m[i].first].net_step == R->runs[0].net_step; i++)
        ;
    if (i == p->n_methods) {
        fprintf(f, " Every network steps %s.\n\n", duel_step_name(R->runs[0].net_step));
    } else {
        fprintf(f, " Network step:");
        for (i = 0; i < p->n_methods; i++)
            fprintf(f, "%s %s %s", i ? "," : "", p->m[i].name, duel_step_name(R->runs[R->m[i].first].net_step));
        fprintf(f, ".\n\n");
    }
    fprintf(f, "| method | runs | dominance levels | generation of the highest dominant | performance (highest) | "
               "equivalent generation (highest) | performance (contiguous) | equivalent generation (contiguous) |\n");
    fprintf(f, "|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < p->n_methods; i++) {
        const rep_method *m = &R->m[i];
        fprintf(f, "| %s | %u |", p->m[i].name, m->n);
        for (c = 0; c < N_COLS; c++)
            rep_md_ms(f, m->mean[c], m->sd[c], c == COL_PERF_HI || c == COL_PERF_CO, 1);
        fprintf(f, "\n");
    }
    for (i = 0; i < p->n_methods; i++)
        for (c = 0; c < N_COLS && i != p->ref; c++)
            exact &= R->m[i].test[c].exact;
    fprintf(f, "\nTwo-sided Mann-Whitney U p-values, %s against each method (%s):\n\n", p->reference,
            exact ? "exact, ties by mid-ranks" : "exact up to 64 runs in all, else the normal approximation");
    fprintf(f, "| method | dominance levels | generation of the highest dominant | performance (highest) | "
               "equivalent generation (highest) | performance (contiguous) | equivalent generation (contiguous) |\n");
    fprintf(f, "|---|---:|---:|---:|---:|---:|---:|\n");
    for (i = 0; i < p->n_methods; i++) {
        if (i == p->ref)
            continue;
        fprintf(f, "| %s |", p->m[i].name);
        for (c = 0; c < N_COLS; c++)
            fprintf(f, " %.3g |", R->m[i].test[c].p);
        fprintf(f, "\n");
    }
    fprintf(f, "\n## Every run\n\n| method | run | seed | levels | top generation | hidden | connections | "
               "performance (highest) | equivalent generation (highest) | performance (contiguous) | equivalent "
               "generation (contiguous) |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (k = 0; k < R->n_runs; k++) {
        const rep_run *r = &R->runs[k];
        fprintf(f, "| %s | %s | %u | %u | %u | %u | %u | %.1f %% | %.1f | %.1f %% | %.1f |\n", p->m[r->method].name,
                r->dir + 5, r->seed, r->n_levels, r->rows[r->n_levels - 1].generation,
                r->rows[r->n_levels - 1].hidden, r->rows[r->n_levels - 1].conns, 100.0 * r->col[COL_PERF_HI],
                r->col[COL_GEN_HI], 100.0 * r->col[COL_PERF_CO], r->col[COL_GEN_CO]);
    }
    fprintf(f, "\n## The top dominants against the built-in strategies\n\nEach run's top dominant plays %u games "
               "against each built-in strategy (`duel_evolve ladder`); wins:losses summed over a method's runs "
               "(draws and timeouts are neither).\n\n| method | runs |", 2u * DUEL_CONFIGS);
    for (b = 0; b < DUEL_N_BUILTINS; b++)
        fprintf(f, " %s |", duel_builtin_name((int)b));
    fprintf(f, " all |\n|---|---:|");
    for (b = 0; b <= DUEL_N_BUILTINS; b++)
        fprintf(f, "---:|");
    fprintf(f, "\n");
    for (i = 0; i < p->n_methods; i++) {
        rep_method_ladder(R, i, l);
        fprintf(f, "| %s | %u |", p->m[i].name, R->m[i].n);
        for (b = 0; b <= DUEL_N_BUILTINS; b++)
            fprintf(f, " %u:%u |", l[b][0], l[b][1]);
        fprintf(f, "\n");
    }
    fprintf(f, "\n## Complexification (Figure 7)\n\nThe %s runs' first and final dominants: %.1f to %.1f connections "
               "(two-sided Wilcoxon signed-rank p = %.3g, %s), %.1f to %.1f hidden nodes (p = %.3g).\n",
            p->reference, R->first_conns, R->final_conns, R->wil_conns.p, R->wil_conns.exact ? "exact" : "normal",
            R->first_hidden, R->final_hidden, R->wil_hidden.p);
}

static void rep_json_test(FILE *f, const char *name, const rep_method *m, uint32_t c, int with_p)
{
    fprintf(f, "\"%s\": {\"mean\": %.6f, \"sd\": %.6f", name, m->mean[c], m->sd[c]);
    if (with_p)
        fprintf(f, ", \"p\": %.6g, \"u\": %.1f, \"exact\": %s", m->test[c].p, m->test[c].statistic,
                m->test[c].exact ? "true" : "false");
    fprintf(f, "}");
}

static void rep_write_json(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    const duel_plan *p = R->p;
    uint32_t i, k, b, l[DUEL_N_BUILTINS + 1][2];
    fprintf(f, "{\n  \"reference\": \"%s\",\n  \"games_per_comparison\": %d,\n  \"world\": \"%s\",\n  "
               "\"world_id\": \"%016llx\",\n  \"methods\": [\n", p->reference, 2 * DUEL_CONFIGS, R->world_label,
            (unsigned long long)duel_rules_id(&R->world));
    for (i = 0; i < p->n_methods; i++) {
        const rep_method *m = &R->m[i];
        int t = i != p->ref;
        fprintf(f, "    {\"name\": \"%s\", \"preset\": \"%s\", \"runs\": %u, \"random_fitness\": %s, \"step\": \"%s\", ",
                p->m[i].name, p->m[i].preset, m->n, p->m[i].cfg.coev.random_fitness ? "true" : "false",
                duel_step_name(R->runs[m->first].net_step));
        rep_json_test(f, "levels", m, COL_LEVELS, t);
        fprintf(f, ", ");
        rep_json_test(f, "top_generation", m, COL_TOPGEN, t);
        fprintf(f, ",\n     \"highest\": {");
        rep_json_test(f, "performance", m, COL_PERF_HI, t);
        fprintf(f, ", ");
        rep_json_test(f, "equivalent_generation", m, COL_GEN_HI, t);
        fprintf(f, "},\n     \"contiguous\": {");
        rep_json_test(f, "performance", m, COL_PERF_CO, t);
        fprintf(f, ", ");
        rep_json_test(f, "equivalent_generation", m, COL_GEN_CO, t);
        fprintf(f, "},\n     \"ladder\": {");
        rep_method_ladder(R, i, l);
        for (b = 0; b <= DUEL_N_BUILTINS; b++)
            fprintf(f, "%s\"%s\": {\"wins\": %u, \"losses\": %u}", b ? ", " : "",
                    b < DUEL_N_BUILTINS ? duel_builtin_name((int)b) : "all", l[b][0], l[b][1]);
        fprintf(f, "},\n     \"typical_run\": \"%s\",\n     \"per_run\": [\n", R->runs[m->typical].dir + 5);
        for (k = 0; k < m->n; k++) {
            const rep_run *r = &R->runs[m->first + k];
            fprintf(f, "       {\"run\": \"%s\", \"seed\": %u, \"levels\": %u, \"top_generation\": %u, \"hidden\": %u, "
                       "\"connections\": %u, \"highest\": {\"performance\": %.6f, \"equivalent_generation\": %.3f}, "
                       "\"contiguous\": {\"performance\": %.6f, \"equivalent_generation\": %.3f}}%s\n",
                    r->dir + 5, r->seed, r->n_levels, r->rows[r->n_levels - 1].generation,
                    r->rows[r->n_levels - 1].hidden, r->rows[r->n_levels - 1].conns, r->col[COL_PERF_HI],
                    r->col[COL_GEN_HI], r->col[COL_PERF_CO], r->col[COL_GEN_CO], k + 1 < m->n ? "," : "");
        }
        fprintf(f, "     ]}%s\n", i + 1 < p->n_methods ? "," : "");
    }
    fprintf(f, "  ],\n  \"complexification\": {\"runs\": %u, \"connections\": {\"first_mean\": %.4f, \"final_mean\": "
               "%.4f, \"w_plus\": %.1f, \"p\": %.6g, \"exact\": %s}, \"hidden\": {\"first_mean\": %.4f, "
               "\"final_mean\": %.4f, \"w_plus\": %.1f, \"p\": %.6g, \"exact\": %s}}\n}\n",
            R->m[p->ref].n, R->first_conns, R->final_conns, R->wil_conns.statistic, R->wil_conns.p,
            R->wil_conns.exact ? "true" : "false", R->first_hidden, R->final_hidden, R->wil_hidden.statistic,
            R->wil_hidden.p, R->wil_hidden.exact ? "true" : "false");
}

/* Figure 7: the current dominant's size, averaged over the reference runs, at every generation where one of them
 * gains a level. */
static void rep_write_fig7(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    const rep_method *m = &R->m[R->p->ref];
    uint32_t g, k, gmax = R->p->m[R->p->ref].cfg.generations;
    fprintf(f, "generation,runs,new_levels,mean_connections,mean_hidden\n");
    for (g = 0; g < gmax; g++) {
        uint32_t n = 0, gained = 0;
        double conns = 0.0, hidden = 0.0;
        for (k = 0; k < m->n; k++) {
            const rep_run *r = &R->runs[m->first + k];
            uint32_t l, at = UINT32_MAX;
            for (l = 0; l < r->n_levels && r->rows[l].generation <= g; l++)
                at = l;
            gained += at != UINT32_MAX && r->rows[at].generation == g;
            if (at != UINT32_MAX) {
                n++;
                conns += r->rows[at].conns;
                hidden += r->rows[at].hidden;
            }
        }
        if (gained > 0)
            fprintf(f, "%u,%u,%u,%.4f,%.4f\n", g, n, gained, conns / n, hidden / n);
    }
}

/* The runs' strength.csv (a plan with strength_every): every row of every run that has one, after its method and
 * run, into report/strength.csv; the file's header checked against the one duel_evolve writes. */
typedef struct rep_strength {
    FILE *f;
    const rep *R;
    const rep_run *r;
    const char *path;
    int bad, any;
    int champion; /* the file being read ends each row with its champion column */
} rep_strength;

static int rep_strength_line(void *ud, uint32_t line, char *text)
{
    rep_strength *x = (rep_strength *)ud;
    char want[600];
    size_t at;
    int k;
    if (line == 1) {
        at = (size_t)snprintf(want, sizeof want, "generation");
        for (k = 0; k < DUEL_N_BUILTINS; k++) {
            const char *n = duel_builtin_name(k);
            at += (size_t)snprintf(want + at, sizeof want - at, ",%s_wins,%s_losses,%s_draws,%s_timeouts", n, n, n, n);
        }
        /* since issue 49 a run's strength.csv ends with the champion measured; the report keeps the columns before */
        x->champion = strncmp(text, want, strlen(want)) == 0 && strcmp(text + strlen(want), ",champion") == 0;
        if (strcmp(text, want) != 0 && !x->champion) {
            fprintf(stderr, "duel_evolve: experiment: %s:1: not a strength.csv of this version\n", x->path);
            x->bad = 1;
            return -1;
        }
        if (!x->any)
            fprintf(x->f, "method,run,%s\n", want);
        x->any = 1;
        return 0;
    }
    if (x->champion) {
        char *comma = strrchr(text, ',');
        if (comma != NULL)
            *comma = '\0';
    }
    fprintf(x->f, "%s,%u,%s\n", x->R->p->m[x->r->method].name, x->r->k, text);
    return 0;
}

static void rep_write_strength(FILE *f, const void *ctx)
{
    rep_strength *x = (rep_strength *)(uintptr_t)ctx;
    uint32_t k;
    x->f = f;
    for (k = 0; k < x->R->n_runs && !x->bad; k++) {
        char path[600];
        x->r = &x->R->runs[k];
        snprintf(path, sizeof path, "%s/strength.csv", x->r->dir);
        x->path = path;
        if (access(path, F_OK) == 0 && rep_lines(path, rep_strength_line, x) != 0 && !x->bad) {
            fprintf(stderr, "duel_evolve: experiment: %s: cannot read: %s\n", duel_esc(path), strerror(errno));
            x->bad = 1;
        }
    }
}

/* Figure 7's dashed lines: the smallest and largest networks of the random-fitness runs' populations. */
typedef struct rep_rand {
    double *sum;   /* [gmax][5]: runs, min conns, max conns, min hidden, max hidden */
    double *cur;   /* [gmax][4] of the run being read: both populations */
    uint32_t gmax;
} rep_rand;

typedef struct rep_fig7r {
    const rep *R;
    rep_rand rr;
} rep_fig7r;

static void rep_write_fig7_random(FILE *f, const void *ctx)
{
    const rep_fig7r *x = (const rep_fig7r *)ctx;
    uint32_t g;
    fprintf(f, "generation,runs,min_connections,max_connections,min_hidden,max_hidden\n");
    for (g = 0; g < x->rr.gmax; g++) {
        const double *s = x->rr.sum + 5 * (size_t)g;
        if (s[0] > 0)
            fprintf(f, "%u,%.0f,%.4f,%.4f,%.4f,%.4f\n", g, s[0], s[1] / s[0], s[2] / s[0], s[3] / s[0], s[4] / s[0]);
    }
}

static int rep_fig7_random(const rep *R, const char *path)
{
    rep_fig7r x;
    uint32_t i, k, g;
    int rc;
    x.R = R;
    x.rr.gmax = 0;
    for (i = 0; i < R->p->n_methods; i++)
        if (R->p->m[i].cfg.coev.random_fitness && R->p->m[i].cfg.generations > x.rr.gmax)
            x.rr.gmax = R->p->m[i].cfg.generations;
    x.rr.sum = (double *)calloc(5 * (size_t)x.rr.gmax + 1, sizeof(double));
    x.rr.cur = (double *)calloc(4 * (size_t)x.rr.gmax + 1, sizeof(double));
    if (x.rr.sum == NULL || x.rr.cur == NULL) {
        free(x.rr.sum);
        free(x.rr.cur);
        return 1;
    }
    for (i = 0; i < R->p->n_methods; i++) {
        if (!R->p->m[i].cfg.coev.random_fitness)
            continue;
        for (k = 0; k < R->m[i].n; k++) {
            duel_gen_row *rows;
            size_t n, j;
            char err[4400];
            for (g = 0; g < 4 * x.rr.gmax; g++)
                x.rr.cur[g] = g % 2 == 0 ? -1.0 : 0.0;
            if (duel_generations_read(R->runs[R->m[i].first + k].dir, &rows, &n, err, sizeof err) != 0) {
                fprintf(stderr, "duel_evolve: experiment: %s: " DUEL_GENERATIONS_LOST_ADVICE "\n", duel_esc_msg(err));
                free(x.rr.sum);
                free(x.rr.cur);
                return 1;
            }
            for (j = 0; j < n; j++) {
                /* both populations' smallest and largest of the generation */
                double *c;
                if (rows[j].generation >= x.rr.gmax)
                    continue;
                c = x.rr.cur + 4 * (size_t)rows[j].generation;
                if (c[0] < 0 || rows[j].min_conns < c[0])
                    c[0] = rows[j].min_conns;
                if (rows[j].max_conns > c[1])
                    c[1] = rows[j].max_conns;
                if (c[2] < 0 || rows[j].min_hidden < c[2])
                    c[2] = rows[j].min_hidden;
                if (rows[j].max_hidden > c[3])
                    c[3] = rows[j].max_hidden;
            }
            free(rows);
            for (g = 0; g < x.rr.gmax; g++) {
                const double *c = x.rr.cur + 4 * (size_t)g;
                double *s = x.rr.sum + 5 * (size_t)g;
                if (c[0] < 0)
                    continue;
                s[0] += 1;
                s[1] += c[0];
                s[2] += c[1];
                s[3] += c[2];
                s[4] += c[3];
            }
        }
    }
    rc = duel_file_write_with(path, rep_write_fig7_random, &x);
    free(x.rr.sum);
    free(x.rr.cur);
    return rc;
}

static void rep_write_fig7_test(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    fprintf(f, "measure,runs,first_mean,final_mean,w_plus,nonzero_differences,p,exact\n");
    fprintf(f, "connections,%u,%.4f,%.4f,%.1f,%zu,%.6g,%d\n", R->m[R->p->ref].n, R->first_conns, R->final_conns,
            R->wil_conns.statistic, R->wil_conns.n, R->wil_conns.p, R->wil_conns.exact);
    fprintf(f, "hidden,%u,%.4f,%.4f,%.1f,%zu,%.6g,%d\n", R->m[R->p->ref].n, R->first_hidden, R->final_hidden,
            R->wil_hidden.statistic, R->wil_hidden.n, R->wil_hidden.p, R->wil_hidden.exact);
}

/* Figure 11: the extra games a dominant won against each level below it in its dominance tournament, by the
 * difference in level, over every reference run. */
static void rep_write_fig11(FILE *f, const void *ctx)
{
    const rep *R = (const rep *)ctx;
    const rep_method *m = &R->m[R->p->ref];
    uint32_t d, k, l, dmax = 0;
    for (k = 0; k < m->n; k++)
        if (R->runs[m->first + k].n_levels > dmax)
            dmax = R->runs[m->first + k].n_levels;
    fprintf(f, "level_difference,comparisons,games,mean_extra_wins,sd_extra_wins\n");
    for (d = 1; d < dmax; d++) {
        double s = 0.0, s2 = 0.0;
        uint32_t n = 0;
        for (k = 0; k < m->n; k++) {
            const rep_run *r = &R->runs[m->first + k];
            for (l = d; l < r->n_levels; l++) {
                /* level l + 1 against level l + 1 - d: its score d - 1 (against the level just below first) */
                const duel_dominance_score *sc = &r->scores[r->rows[l].scores + (d - 1)];
                double x = (double)sc->wins - (double)sc->losses;
                s += x;
                s2 += x * x;
                n++;
            }
        }
        {
            double mean = s / n, var = n > 1 ? (s2 - n * mean * mean) / (n - 1) : 0.0;
            fprintf(f, "%u,%u,%u,%.4f,%.4f\n", d, n, R->games, mean, var > 0 ? sqrt(var) : 0.0);
        }
    }
}

typedef struct rep_levels_ctx {
    const rep *R;
    uint32_t method;
} rep_levels_ctx;

/* Figures 12-15: the typical reference run's levels beside the typical run of a method, and where the method's
 * best stands in the reference ranking. */
static void rep_write_levels(FILE *f, const void *ctx)
{
    const rep_levels_ctx *c = (const rep_levels_ctx *)ctx;
    const rep *R = c->R;
    const rep_method *m = &R->m[c->method];
    const rep_run *ref = &R->runs[R->m[R->p->ref].typical], *run = &R->runs[m->typical];
    const rep_run *both[2];
    uint32_t s, l, k;
    both[0] = ref;
    both[1] = run;
    fprintf(f, "series,run,level,generation,hidden,connections\n");
    for (s = 0; s < 2; s++)
        for (l = 0; l < both[s]->n_levels; l++)
            fprintf(f, "%s,%s,%u,%u,%u,%u\n", s == 0 ? "reference" : "method", both[s]->dir + 5, l + 1,
                    both[s]->rows[l].generation, both[s]->rows[l].hidden, both[s]->rows[l].conns);
    /* the arrow: the method run's top dominant, and the level of the reference run it equals ("highest") */
    for (k = 0; k < m->perf.n_pairs; k++) {
        const duel_perf_pair *pp = &m->perf.pairs[k];
        if (strcmp(m->perf.runs[pp->cand].dir, run->dir) != 0 || strcmp(m->perf.runs[pp->rank].dir, ref->dir) != 0)
            continue;
        fprintf(f, "arrow_from,%s,%u,%u,%u,%u\n", run->dir + 5, run->n_levels, run->rows[run->n_levels - 1].generation,
                run->rows[run->n_levels - 1].hidden, run->rows[run->n_levels - 1].conns);
        if (pp->highest > 0)
            fprintf(f, "arrow_to,%s,%u,%u,%u,%u\n", ref->dir + 5, pp->highest, ref->rows[pp->highest - 1].generation,
                    ref->rows[pp->highest - 1].hidden, ref->rows[pp->highest - 1].conns);
        else
            fprintf(f, "arrow_to,%s,0,0,0,0\n", ref->dir + 5);
    }
}

/* python3 plot_experiment.py report: the pictures. 0, or 1 after one line. */
static int rep_plot(const char *dir)
{
    const char *py = getenv("DUEL_PYTHON"), *script = getenv("DUEL_PLOT_SCRIPT");
    pid_t pid;
    int status;
    if (py == NULL || *py == '\0')
        py = DUEL_PYTHON;
    if (script == NULL || *script == '\0')
        script = DUEL_PLOT_SCRIPT;
    fflush(NULL);
    pid = fork();
    if (pid == 0) {
        execlp(py, py, script, "report", (char *)NULL);
        fprintf(stderr, "duel_evolve: experiment: cannot run %s: %s\n", py, strerror(errno));
        _exit(127);
    }
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "duel_evolve: experiment: the figures were not drawn (%s %s report failed); the tables and "
                        "the figures' data are in %s/report; draw them again with duel_evolve experiment report %s\n",
                py, script, duel_esc(dir), duel_esc(dir));
        return 1;
    }
    return 0;
}

int duel_exp_report_here(const duel_plan *p, const char *dir)
{
    rep R;
    uint32_t i, k;
    int rc = 0;
    memset(&R, 0, sizeof R);
    R.p = p;
    R.dir = dir;
    R.games = 2u * p->m[p->ref].cfg.coev.compare_configs;
    for (i = 0; i < p->n_methods; i++)
        R.n_runs += p->m[i].runs;
    R.runs = (rep_run *)calloc(R.n_runs, sizeof *R.runs);
    if (R.runs == NULL) {
        fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        return 1;
    }
    for (i = 0, R.n_runs = 0; i < p->n_methods && rc == 0; i++) {
        R.m[i].first = R.n_runs;
        R.m[i].n = p->m[i].runs;
        for (k = 1; k <= p->m[i].runs && rc == 0; k++) {
            rep_run *r = &R.runs[R.n_runs++];
            r->method = i;
            r->k = k;
            r->seed = p->seed + (k - 1);
            r->generations = p->m[i].cfg.generations;
            duel_exp_run_dir(r->dir, sizeof r->dir, p, i, k);
            rc = rep_read_run(&R, r);
        }
    }
    /* one world for every run, or no report (the plan says one; a directory put together by hand may not) */
    for (k = 1; rc == 0 && k < R.n_runs; k++)
        if (!duel_rules_equal(&R.runs[k].world, &R.runs[0].world)) {
            char a[40], b[40];
            fprintf(stderr, "duel_evolve: experiment: %s: runs of several worlds: %s is of world %s, %s of world %s; "
                            "a report compares runs of one world\n", duel_esc(dir), R.runs[0].dir,
                    duel_world_label(&R.runs[0].world, a, sizeof a), R.runs[k].dir,
                    duel_world_label(&R.runs[k].world, b, sizeof b));
            rc = 2;
        }
    if (rc == 0) {
        R.world = R.runs[0].world;
        duel_world_label(&R.world, R.world_label, sizeof R.world_label);
        rc = rep_measure(&R);
        if (rc == 1)
            fprintf(stderr, "duel_evolve: experiment: report: out of memory\n");
    }
    if (rc == 0 && duel_mkdir("report") != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s/report: cannot create: %s\n", duel_esc(dir), strerror(errno));
        rc = 1;
    }
    if (rc == 0) {
        rc |= duel_file_write_with("report/table1.csv", rep_write_table_csv, &R);
        rc |= duel_file_write_with("report/table1.md", rep_write_md, &R);
        rc |= duel_file_write_with("report/table1.json", rep_write_json, &R);
        rc |= duel_file_write_with("report/runs.csv", rep_write_runs_csv, &R);
        rc |= duel_file_write_with("report/ladder.csv", rep_write_ladder_csv, &R);
        rc |= duel_file_write_with("report/timing.csv", rep_write_timing_csv, &R);
        rc |= duel_file_write_with("report/fig7-complexity.csv", rep_write_fig7, &R);
        rc |= rep_fig7_random(&R, "report/fig7-random.csv");
        rc |= duel_file_write_with("report/fig7-test.csv", rep_write_fig7_test, &R);
        rc |= duel_file_write_with("report/fig11-levels.csv", rep_write_fig11, &R);
        {
            /* the strength series, when the plan asked for it (strength_every): drawn beside Figure 7 */
            rep_strength x;
            memset(&x, 0, sizeof x);
            x.R = &R;
            rc |= duel_file_write_with("report/strength.csv", rep_write_strength, &x);
            if (!x.any && !x.bad)
                unlink("report/strength.csv");
            rc |= x.bad;
        }
        for (i = 0; i < p->n_methods; i++) {
            rep_levels_ctx c;
            char path[200];
            if (i == p->ref)
                continue;
            c.R = &R;
            c.method = i;
            snprintf(path, sizeof path, "report/levels-%s.csv", p->m[i].name);
            rc |= duel_file_write_with(path, rep_write_levels, &c);
        }
        rc = rc ? 1 : 0;
        if (rc == 0)
            rc = rep_plot(dir);
        if (rc == 0)
            fprintf(stderr, "experiment: the report is in %s/report (table1.md, figures *.png and *.svg)\n", duel_esc(dir));
    }
    for (i = 0; i < p->n_methods; i++)
        duel_perf_free(&R.m[i].perf);
    for (k = 0; k < R.n_runs; k++) {
        free(R.runs[k].rows);
        free(R.runs[k].scores);
    }
    free(R.runs);
    return rc;
}

int duel_exp_report(const duel_plan *p, const char *dir)
{
    int rc = duel_exp_enter(p, dir, 0);
    if (rc != 0)
        return rc;
    return duel_exp_report_here(p, dir);
}
