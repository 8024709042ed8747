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
#include "duel_cmp_cache.h"
#include "duel_config.h"
#include "duel_ctrl.h"
#include "duel_files.h"
#include "duel_levels.h"
#include "duel_pairs.h"
#include "neat_coev.h"

#define DUEL_CMP_MAX_RUNS 4096

/* A finished run: its dominance ranking with every dominant's blob. */
typedef struct duel_cmp_run {
    const char *dir;        /* as given */
    char real[PATH_MAX];    /* realpath: a run is never ranked against itself */
    duel_level *levels;
    uint32_t n_levels;
    uint64_t top_hash;      /* the highest dominant's blob */
    uint64_t *hash;         /* [n_levels] */
} duel_cmp_run;

/* One candidate against one ranking: the wins of each comparison and the two readings. */
typedef struct duel_cmp_pair {
    uint32_t cand, rank;
    duel_tally *t;          /* [levels of the ranking] */
    uint32_t highest, contiguous; /* levels (0: none defeated) */
} duel_cmp_pair;

typedef struct duel_cmp_stats {
    double mean, sd;
} duel_cmp_stats;

#define DUEL_CMP_USAGE "usage: duel_evolve compare RUN... --against RUN... [--threads T] [--json FILE] [--csv FILE] [--cache FILE]"

/* DIR is a run that has played every generation of its config.ini, and its
 * dominance.csv holds the levels its checkpoint does. */
static int duel_cmp_open_in(duel_cmp_run *r, const char *dir)
{
    char path[4200], err[4400];
    duel_config cfg;
    struct stat st;
    neat_coev *c;
    uint32_t gen, doms, k;
    int e;

    memset(r, 0, sizeof *r);
    r->dir = dir;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "duel_evolve: compare: %s: not a run directory (%s)\n", dir,
                stat(dir, &st) != 0 ? strerror(errno) : "not a directory");
        return -1;
    }
    if (realpath(dir, r->real) == NULL) {
        fprintf(stderr, "duel_evolve: compare: %s: %s\n", dir, strerror(errno));
        return -1;
    }
    duel_config_default(&cfg);
    snprintf(path, sizeof path, "%s/config.ini", dir);
    if (duel_config_load(&cfg, path, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: compare: %s\n", err);
        return -1;
    }
    snprintf(path, sizeof path, "%s/checkpoint.bin", dir);
    e = duel_ckpt_load("compare: ", path, &c);
    if (e > 0)
        fprintf(stderr, "duel_evolve: compare: %s: missing: not a run directory, or one that never finished a "
                        "generation\n", path);
    if (e != 0)
        return -1;
    gen = neat_coev_generation(c);
    doms = neat_coev_dominant_count(c);
    neat_coev_free(c);
    if (gen < cfg.generations) {
        fprintf(stderr, "duel_evolve: compare: %s: not a finished run (%u of %u generations): resume it first\n", dir,
                gen, cfg.generations);
        return -1;
    }
    if (duel_levels_read(dir, &r->levels, &r->n_levels) != 0)
        return -1;
    if (r->n_levels != doms) {
        fprintf(stderr, "duel_evolve: compare: %s/dominance.csv: %u levels, but the checkpoint has %u: resume the run "
                        "to repair it\n", dir, r->n_levels, doms);
        return -1;
    }
    r->hash = (uint64_t *)malloc(r->n_levels * sizeof *r->hash);
    if (r->hash == NULL) {
        fprintf(stderr, "duel_evolve: compare: out of memory\n");
        return -1;
    }
    for (k = 0; k < r->n_levels; k++)
        r->hash[k] = duel_blob_hash(r->levels[k].ctrl.blob, r->levels[k].ctrl.blob_len);
    r->top_hash = r->hash[r->n_levels - 1];
    return 0;
}

static void duel_cmp_close(duel_cmp_run *r)
{
    duel_levels_free(r->levels, r->n_levels);
    free(r->hash);
    memset(r, 0, sizeof *r);
}

/* duel_cmp_open_in, leaving nothing allocated when it fails */
static int duel_cmp_open(duel_cmp_run *r, const char *dir)
{
    if (duel_cmp_open_in(r, dir) == 0)
        return 0;
    duel_cmp_close(r);
    return -1;
}

/* Both readings: the highest level defeated, and the highest L such that
 * every level 1..L is defeated ("defeat": more wins of the 288). */
static void duel_cmp_readings(duel_cmp_pair *p, uint32_t n)
{
    uint32_t k;
    int gap = 0;
    p->highest = p->contiguous = 0;
    for (k = 0; k < n; k++) {
        int won = p->t[k].wins_a > p->t[k].wins_b;
        if (won)
            p->highest = k + 1;
        if (!won)
            gap = 1;
        if (won && !gap)
            p->contiguous = k + 1;
    }
}

/* mean and sample standard deviation (0 for one value) */
static duel_cmp_stats duel_cmp_stat(const double *v, size_t n)
{
    duel_cmp_stats s = {0.0, 0.0};
    size_t k;
    for (k = 0; k < n; k++)
        s.mean += v[k] / (double)n;
    for (k = 0; n > 1 && k < n; k++)
        s.sd += (v[k] - s.mean) * (v[k] - s.mean) / (double)(n - 1);
    s.sd = sqrt(s.sd);
    return s;
}

static void duel_json_str(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char ch = (unsigned char)*s;
        if (ch == '"' || ch == '\\')
            fprintf(f, "\\%c", ch);
        else if (ch < 0x20)
            fprintf(f, "\\u%04x", ch);
        else
            fputc(ch, f);
    }
    fputc('"', f);
}

static void duel_cmp_progress(void *ud, size_t done, size_t n)
{
    (void)ud;
    fprintf(stderr, "\rcompare: %zu/%zu comparisons played%s", done, n, done == n ? "\n" : "");
}

typedef struct duel_cmp {
    duel_cmp_run *runs;     /* candidates first, then the rankings not among them */
    uint32_t n_runs, n_cand;
    uint32_t *rank;         /* [n_rank] indices into runs */
    uint32_t n_rank;
    duel_cmp_pair *pairs;   /* [n_pairs], candidate-major */
    uint32_t n_pairs;
    double *pair_hi, *pair_co; /* [n_pairs] each pair's performance, both readings */
    /* per candidate, means over its rankings */
    double *perf_hi, *perf_co, *gen_hi, *gen_co;
} duel_cmp;

static double duel_cmp_perf(const duel_cmp *m, const duel_cmp_pair *p, uint32_t level)
{
    return (double)level / (double)m->runs[p->rank].n_levels;
}

static double duel_cmp_gen(const duel_cmp *m, const duel_cmp_pair *p, uint32_t level)
{
    /* nothing defeated: as if it equalled generation 0 */
    return level == 0 ? 0.0 : (double)m->runs[p->rank].levels[level - 1].generation;
}

static void duel_cmp_write_csv(FILE *f, const void *ctx)
{
    const duel_cmp *m = (const duel_cmp *)ctx;
    uint32_t k, l;
    fprintf(f, "candidate,candidate_level,candidate_generation,ranking,ranking_levels,highest_level,"
               "highest_generation,highest_performance,contiguous_level,contiguous_generation,contiguous_performance,"
               "wins\n");
    for (k = 0; k < m->n_pairs; k++) {
        const duel_cmp_pair *p = &m->pairs[k];
        const duel_cmp_run *c = &m->runs[p->cand], *r = &m->runs[p->rank];
        fprintf(f, "%s,%u,%u,%s,%u,%u,%.0f,%.6f,%u,%.0f,%.6f,", c->dir, c->n_levels,
                c->levels[c->n_levels - 1].generation, r->dir, r->n_levels, p->highest,
                duel_cmp_gen(m, p, p->highest), duel_cmp_perf(m, p, p->highest), p->contiguous,
                duel_cmp_gen(m, p, p->contiguous), duel_cmp_perf(m, p, p->contiguous));
        for (l = 0; l < r->n_levels; l++)
            fprintf(f, "%s%u:%u", l ? " " : "", p->t[l].wins_a, p->t[l].wins_b);
        fputc('\n', f);
    }
}

static void duel_cmp_json_stats(FILE *f, const char *name, const double *perf, const double *gen, uint32_t n,
                                const double *pair_perf, uint32_t n_pairs)
{
    duel_cmp_stats sp = duel_cmp_stat(perf, n), sg = duel_cmp_stat(gen, n), pp = duel_cmp_stat(pair_perf, n_pairs);
    fprintf(f, "\"%s\": {\"performance_mean\": %.6f, \"performance_sd\": %.6f, \"equivalent_generation_mean\": %.3f, "
               "\"equivalent_generation_sd\": %.3f, \"pairs_performance_mean\": %.6f, \"pairs_performance_sd\": %.6f}",
            name, sp.mean, sp.sd, sg.mean, sg.sd, pp.mean, pp.sd);
}

static void duel_cmp_write_json(FILE *f, const void *ctx)
{
    const duel_cmp *m = (const duel_cmp *)ctx;
    uint32_t i, k, l, at = 0;
    fprintf(f, "{\n  \"games_per_comparison\": %d,\n  \"runs\": %u,\n  \"summary\": {", 2 * DUEL_CONFIGS, m->n_cand);
    duel_cmp_json_stats(f, "highest", m->perf_hi, m->gen_hi, m->n_cand, m->pair_hi, m->n_pairs);
    fprintf(f, ", ");
    duel_cmp_json_stats(f, "contiguous", m->perf_co, m->gen_co, m->n_cand, m->pair_co, m->n_pairs);
    fprintf(f, "},\n  \"candidates\": [\n");
    for (i = 0; i < m->n_cand; i++) {
        const duel_cmp_run *c = &m->runs[i];
        fprintf(f, "    {\"run\": ");
        duel_json_str(f, c->dir);
        fprintf(f, ", \"levels\": %u, \"generation\": %u, \"hidden\": %u, \"connections\": %u, "
                   "\"highest\": {\"performance\": %.6f, \"equivalent_generation\": %.3f}, "
                   "\"contiguous\": {\"performance\": %.6f, \"equivalent_generation\": %.3f}, \"rankings\": [\n",
                c->n_levels, c->levels[c->n_levels - 1].generation, c->levels[c->n_levels - 1].hidden,
                c->levels[c->n_levels - 1].conns, m->perf_hi[i], m->gen_hi[i], m->perf_co[i], m->gen_co[i]);
        for (k = 0; at < m->n_pairs && m->pairs[at].cand == i; at++, k++) {
            const duel_cmp_pair *p = &m->pairs[at];
            const duel_cmp_run *r = &m->runs[p->rank];
            fprintf(f, "%s      {\"run\": ", k ? ",\n" : "");
            duel_json_str(f, r->dir);
            fprintf(f, ", \"levels\": %u, \"highest_level\": %u, \"highest_generation\": %.0f, "
                       "\"contiguous_level\": %u, \"contiguous_generation\": %.0f, \"wins\": [",
                    r->n_levels, p->highest, duel_cmp_gen(m, p, p->highest), p->contiguous,
                    duel_cmp_gen(m, p, p->contiguous));
            for (l = 0; l < r->n_levels; l++)
                fprintf(f, "%s%u", l ? ", " : "", p->t[l].wins_a);
            fprintf(f, "], \"losses\": [");
            for (l = 0; l < r->n_levels; l++)
                fprintf(f, "%s%u", l ? ", " : "", p->t[l].wins_b);
            fprintf(f, "]}");
        }
        fprintf(f, "\n    ]}%s\n", i + 1 < m->n_cand ? "," : "");
    }
    fprintf(f, "  ]\n}\n");
}

static void duel_cmp_print(const duel_cmp *m, size_t played, size_t cached)
{
    duel_cmp_stats h = duel_cmp_stat(m->perf_hi, m->n_cand), c = duel_cmp_stat(m->perf_co, m->n_cand),
                   gh = duel_cmp_stat(m->gen_hi, m->n_cand), gc = duel_cmp_stat(m->gen_co, m->n_cand);
    size_t w = 14;
    uint32_t i;
    for (i = 0; i < m->n_cand; i++)
        if (strlen(m->runs[i].dir) > w)
            w = strlen(m->runs[i].dir);
    printf("%u run%s against the dominance rankings of %u run%s (never its own): %u pairs, %zu comparisons of %d "
           "games (%zu played, %zu from the cache)\n",
           m->n_cand, m->n_cand == 1 ? "" : "s", m->n_rank, m->n_rank == 1 ? "" : "s", m->n_pairs, played + cached,
           2 * DUEL_CONFIGS, played, cached);
    printf("%-*s  %6s %6s   %-24s   %-24s\n", (int)w, "", "top", "top", "highest level defeated",
           "every level up to");
    printf("%-*s  %6s %6s   %11s %12s   %11s %12s\n", (int)w, "run", "level", "gen", "performance", "equiv. gen",
           "performance", "equiv. gen");
    for (i = 0; i < m->n_cand; i++) {
        const duel_cmp_run *r = &m->runs[i];
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
    duel_cmp m;
    duel_cmp_cache *caches = NULL, shared;
    duel_pair *jobs = NULL;
    uint32_t *slot = NULL;
    const char *json = NULL, *csv = NULL, *cache_path = NULL, **cand = NULL, **against = NULL;
    uint32_t threads = 0, n_against = 0, i, j, k, l, n_jobs = 0;
    size_t cached = 0;
    int in_against = 0, rc = 2;
    char err[4400];

    memset(&m, 0, sizeof m);
    memset(&shared, 0, sizeof shared);
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
                    fprintf(stderr, "duel_evolve: compare: --threads takes 0 (every core) to 256, not '%s'\n", v);
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
            fprintf(stderr, "duel_evolve: compare: unknown option '%s' (%s)\n", a, DUEL_CMP_USAGE);
            goto out;
        } else if (in_against) {
            against[n_against++] = a;
        } else {
            cand[m.n_cand++] = a;
        }
    }
    if (m.n_cand == 0 || n_against == 0) {
        fprintf(stderr, "duel_evolve: compare: %s\n",
                m.n_cand == 0 ? "which runs? (no candidate run before --against)"
                              : "an empty ranking: --against names no run");
        goto out;
    }
    if (m.n_cand + n_against > DUEL_CMP_MAX_RUNS) {
        fprintf(stderr, "duel_evolve: compare: %u runs, at most %d\n", m.n_cand + n_against, DUEL_CMP_MAX_RUNS);
        goto out;
    }

    /* every run opened once: the candidates, then the rankings not among them */
    m.runs = (duel_cmp_run *)calloc((size_t)m.n_cand + n_against, sizeof *m.runs);
    m.rank = (uint32_t *)calloc(n_against, sizeof *m.rank);
    if (m.runs == NULL || m.rank == NULL) {
        fprintf(stderr, "duel_evolve: compare: out of memory\n");
        goto out;
    }
    for (i = 0; i < m.n_cand; i++) {
        if (duel_cmp_open(&m.runs[m.n_runs], cand[i]) != 0)
            goto out;
        m.n_runs++;
        for (j = 0; j < i; j++)
            if (strcmp(m.runs[j].real, m.runs[i].real) == 0) {
                fprintf(stderr, "duel_evolve: compare: %s is given twice as a candidate\n", cand[i]);
                goto out;
            }
    }
    for (i = 0; i < n_against; i++) {
        duel_cmp_run r;
        if (duel_cmp_open(&r, against[i]) != 0)
            goto out;
        for (j = 0; j < m.n_runs && strcmp(m.runs[j].real, r.real) != 0; j++)
            ;
        for (k = 0; k < m.n_rank; k++)
            if (m.rank[k] == j) {
                fprintf(stderr, "duel_evolve: compare: %s is given twice after --against\n", against[i]);
                duel_cmp_close(&r);
                goto out;
            }
        if (j == m.n_runs)
            m.runs[m.n_runs++] = r;
        else
            duel_cmp_close(&r); /* a candidate too: already open */
        m.rank[m.n_rank++] = j;
    }

    /* the pairs: every candidate against every ranking but its own */
    m.pairs = (duel_cmp_pair *)calloc((size_t)m.n_cand * m.n_rank, sizeof *m.pairs);
    m.perf_hi = (double *)calloc(m.n_cand, sizeof(double));
    m.perf_co = (double *)calloc(m.n_cand, sizeof(double));
    m.gen_hi = (double *)calloc(m.n_cand, sizeof(double));
    m.gen_co = (double *)calloc(m.n_cand, sizeof(double));
    m.pair_hi = (double *)calloc((size_t)m.n_cand * m.n_rank + 1, sizeof(double));
    m.pair_co = (double *)calloc((size_t)m.n_cand * m.n_rank + 1, sizeof(double));
    if (m.pairs == NULL || m.perf_hi == NULL || m.perf_co == NULL || m.gen_hi == NULL || m.gen_co == NULL ||
        m.pair_hi == NULL || m.pair_co == NULL) {
        fprintf(stderr, "duel_evolve: compare: out of memory\n");
        goto out;
    }
    for (i = 0; i < m.n_cand; i++) {
        uint32_t mine = 0;
        for (k = 0; k < m.n_rank; k++) {
            duel_cmp_pair *p = &m.pairs[m.n_pairs];
            if (m.rank[k] == i)
                continue;
            p->cand = i;
            p->rank = m.rank[k];
            p->t = (duel_tally *)calloc(m.runs[p->rank].n_levels, sizeof *p->t);
            if (p->t == NULL) {
                fprintf(stderr, "duel_evolve: compare: out of memory\n");
                goto out;
            }
            m.n_pairs++;
            mine++;
        }
        if (mine == 0) {
            fprintf(stderr, "duel_evolve: compare: %s: an empty ranking: --against names no run but itself\n",
                    m.runs[i].dir);
            goto out;
        }
    }

    /* the caches: one per candidate run (RUN/compare-cache.csv), or --cache for all */
    caches = (duel_cmp_cache *)calloc(m.n_cand, sizeof *caches);
    if (caches == NULL) {
        fprintf(stderr, "duel_evolve: compare: out of memory\n");
        goto out;
    }
    if (cache_path != NULL && duel_cmp_cache_open(&shared, cache_path, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: compare: %s\n", err);
        goto out;
    }
    for (i = 0; i < m.n_cand && cache_path == NULL; i++) {
        char path[4200];
        snprintf(path, sizeof path, "%s/compare-cache.csv", m.runs[i].dir);
        if (duel_cmp_cache_open(&caches[i], path, err, sizeof err) != 0) {
            fprintf(stderr, "duel_evolve: compare: %s\n", err);
            goto out;
        }
    }

    /* what the caches do not hold: one job per (pair, level), found again through slot */
    {
        size_t total = 0, at = 0;
        for (k = 0; k < m.n_pairs; k++)
            total += m.runs[m.pairs[k].rank].n_levels;
        jobs = (duel_pair *)calloc(total + 1, sizeof *jobs);
        slot = (uint32_t *)calloc(total + 1, sizeof *slot);
        if (jobs == NULL || slot == NULL) {
            fprintf(stderr, "duel_evolve: compare: out of memory\n");
            goto out;
        }
        for (k = 0; k < m.n_pairs; k++) {
            duel_cmp_pair *p = &m.pairs[k];
            duel_cmp_run *c = &m.runs[p->cand], *r = &m.runs[p->rank];
            duel_cmp_cache *cc = cache_path ? &shared : &caches[p->cand];
            for (l = 0; l < r->n_levels; l++, at++) {
                const duel_tally *t = duel_cmp_cache_find(cc, c->top_hash, r->hash[l]);
                if (t != NULL) {
                    p->t[l] = *t;
                    slot[at] = UINT32_MAX;
                    cached++;
                } else {
                    jobs[n_jobs].a = &c->levels[c->n_levels - 1].ctrl;
                    jobs[n_jobs].b = &r->levels[l].ctrl;
                    slot[at] = n_jobs++;
                }
            }
        }
        if (n_jobs > 0 &&
            duel_pairs_play(jobs, n_jobs, threads, isatty(STDERR_FILENO) ? duel_cmp_progress : NULL, NULL) != 0) {
            fprintf(stderr, "duel_evolve: compare: a comparison failed (out of memory)\n");
            rc = 1;
            goto out;
        }
        /* into the pairs and the caches, which are saved at once */
        for (k = 0, at = 0; k < m.n_pairs; k++) {
            duel_cmp_pair *p = &m.pairs[k];
            duel_cmp_run *c = &m.runs[p->cand], *r = &m.runs[p->rank];
            duel_cmp_cache *cc = cache_path ? &shared : &caches[p->cand];
            for (l = 0; l < r->n_levels; l++, at++) {
                if (slot[at] == UINT32_MAX)
                    continue;
                p->t[l] = jobs[slot[at]].tally;
                if (duel_cmp_cache_add(cc, c->top_hash, r->hash[l], &p->t[l]) != 0) {
                    fprintf(stderr, "duel_evolve: compare: out of memory\n");
                    rc = 1;
                    goto out;
                }
            }
            duel_cmp_readings(p, r->n_levels);
        }
    }
    for (i = 0; i < (cache_path ? 1u : m.n_cand); i++) {
        duel_cmp_cache *cc = cache_path ? &shared : &caches[i];
        if (duel_cmp_cache_save(cc) != 0)
            fprintf(stderr, "duel_evolve: compare: %s: cannot write the cache (%s); the results are not affected\n",
                    cc->path, strerror(errno));
    }

    /* per candidate: the means over its rankings */
    for (i = 0, k = 0; i < m.n_cand; i++) {
        uint32_t n = 0;
        for (; k < m.n_pairs && m.pairs[k].cand == i; k++, n++) {
            const duel_cmp_pair *p = &m.pairs[k];
            m.pair_hi[k] = duel_cmp_perf(&m, p, p->highest);
            m.pair_co[k] = duel_cmp_perf(&m, p, p->contiguous);
            m.perf_hi[i] += m.pair_hi[k];
            m.perf_co[i] += m.pair_co[k];
            m.gen_hi[i] += duel_cmp_gen(&m, p, p->highest);
            m.gen_co[i] += duel_cmp_gen(&m, p, p->contiguous);
        }
        m.perf_hi[i] /= n;
        m.perf_co[i] /= n;
        m.gen_hi[i] /= n;
        m.gen_co[i] /= n;
    }
    rc = 0;
    if (csv != NULL && duel_file_write_with(csv, duel_cmp_write_csv, &m) != 0)
        rc = 1;
    if (json != NULL && duel_file_write_with(json, duel_cmp_write_json, &m) != 0)
        rc = 1;
    duel_cmp_print(&m, n_jobs, cached);
out:
    free(jobs);
    free(slot);
    free(m.pair_hi);
    free(m.pair_co);
    for (k = 0; k < m.n_pairs; k++)
        free(m.pairs[k].t);
    free(m.pairs);
    for (i = 0; i < m.n_runs; i++)
        duel_cmp_close(&m.runs[i]);
    free(m.runs);
    free(m.rank);
    free(m.perf_hi);
    free(m.perf_co);
    free(m.gen_hi);
    free(m.gen_co);
    for (i = 0; caches != NULL && i < m.n_cand; i++)
        duel_cmp_cache_free(&caches[i]);
    free(caches);
    duel_cmp_cache_free(&shared);
    free(cand);
    free(against);
    return rc;
}
