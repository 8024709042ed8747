/* duel_perf.c - the paper's performance measure: candidates' highest dominants against other runs' dominance rankings, every comparison cached, and compare's CSV and JSON (for compare, experiment and runs.compare). */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "duel_cmp_cache.h"
#include "duel_config.h"
#include "duel_ctrl.h"
#include "duel_files.h"
#include "duel_json.h"
#include "duel_outputs.h"
#include "duel_generations.h"
#include "duel_pairs.h"
#include "duel_perf.h"
#include "duel_world_cfg.h"
#include "neat_coev.h"
#include "duel_text.h"

/* Where duel_perf_measure's lines go: stderr ("duel_evolve: LINE"), or the caller's buffer (duel_perf_opts.msg,
 * the last line kept). Process-wide for the call: one measure at a time in a process (the commands, an
 * experiment, the Python package's lock). */
static char *duel_perf_sink;
static size_t duel_perf_sink_cap;

static void duel_perf_say(const char *fmt, ...)
{
    char line[8400];
    va_list ap;
    va_start(ap, fmt);
    duel_text_vline(line, sizeof line, fmt, ap);
    va_end(ap);
    if (duel_perf_sink != NULL)
        snprintf(duel_perf_sink, duel_perf_sink_cap, "%s", line);
    else
        fprintf(stderr, "duel_evolve: %s\n", line);
}

/* DIR is a run that has played every generation of its config.ini, and its
 * dominance.csv holds the levels its checkpoint does. */
/* The generations generations.csv records in full (both populations' rows), or UINT32_MAX after one line
 * when it cannot be read or is damaged. */
static uint32_t duel_perf_csv_generations(const char *dir, const char *pre)
{
    duel_gen_row *rows;
    size_t n;
    char err[4400];
    uint32_t done;
    if (duel_generations_read(dir, &rows, &n, err, sizeof err) != 0) {
        duel_perf_say("%s%s: " DUEL_GENERATIONS_LOST_ADVICE "\n", pre, duel_esc_msg(err));
        return UINT32_MAX;
    }
    done = duel_generations_done(rows, n);
    free(rows);
    return done;
}

static int duel_perf_open_in(duel_perf_run *r, const char *dir, const char *pre, int ckpt)
{
    char path[4200], err[4400];
    duel_config cfg;
    struct stat st;
    neat_coev *c;
    uint32_t gen, k;
    int e;

    memset(r, 0, sizeof *r);
    r->dir = dir;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        duel_perf_say("%s%s: not a run directory (%s)\n", pre, duel_esc(dir),
                stat(dir, &st) != 0 ? strerror(errno) : "not a directory");
        return -1;
    }
    if (realpath(dir, r->real) == NULL) {
        duel_perf_say("%s%s: %s\n", pre, duel_esc(dir), strerror(errno));
        return -1;
    }
    duel_config_default(&cfg);
    snprintf(path, sizeof path, "%s/config.ini", dir);
    if (duel_config_load(&cfg, path, err, sizeof err) != 0) {
        duel_perf_say("%s%s\n", pre, duel_esc_msg(err));
        return -1;
    }
    r->net_step = cfg.neat.net_step;
    if (ckpt) {
        snprintf(path, sizeof path, "%s/checkpoint.bin", dir);
        e = duel_ckpt_load(pre, path, &c);
        if (e > 0)
            duel_perf_say("%s%s: missing: not a run directory, or one that never finished a "
                            "generation\n", pre, duel_esc(path));
        if (e != 0)
            return -1;
        gen = neat_coev_generation(c);
        e = duel_ckpt_world(c, path, &r->world);
        neat_coev_free(c);
        if (e != 0)
            return -1;
    } else {
        gen = duel_perf_csv_generations(dir, pre);
        if (gen == UINT32_MAX)
            return -1;
        r->world = cfg.world;
    }
    if (gen < cfg.generations) {
        duel_perf_say("%s%s: not a finished run (%u of %u generations): resume it first\n", pre, duel_esc(dir),
                gen, cfg.generations);
        return -1;
    }
    /* the levels as the checkpoint holds them (duel_levels_check: their number, each row and blob) */
    if (duel_levels_read(dir, &r->levels, &r->n_levels) != 0)
        return -1;
    r->hash = (uint64_t *)malloc(r->n_levels * sizeof *r->hash);
    if (r->hash == NULL) {
        duel_perf_say("%sout of memory\n", pre);
        return -1;
    }
    for (k = 0; k < r->n_levels; k++)
        r->hash[k] = duel_blob_hash(r->levels[k].ctrl.blob, r->levels[k].ctrl.blob_len);
    r->top_hash = r->hash[r->n_levels - 1];
    return 0;
}

static void duel_perf_close(duel_perf_run *r)
{
    duel_levels_free(r->levels, r->n_levels);
    free(r->hash);
    memset(r, 0, sizeof *r);
}

/* duel_perf_open_in, leaving nothing allocated when it fails */
static int duel_perf_open(duel_perf_run *r, const char *dir, const char *pre, int ckpt)
{
    if (duel_perf_open_in(r, dir, pre, ckpt) == 0)
        return 0;
    duel_perf_close(r);
    return -1;
}

/* Both readings: the highest level defeated, and the highest L such that
 * every level 1..L is defeated ("defeat": more wins of the 288). */
static void duel_perf_readings(duel_perf_pair *p, uint32_t n)
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

double duel_perf_level_share(const duel_perf *m, const duel_perf_pair *p, uint32_t level)
{
    return (double)level / (double)m->runs[p->rank].n_levels;
}

double duel_perf_gen(const duel_perf *m, const duel_perf_pair *p, uint32_t level)
{
    return level == 0 ? 0.0 : (double)m->runs[p->rank].levels[level - 1].generation;
}

/* The progress line over the chunks: where this chunk starts, of how many in all. */
typedef struct duel_perf_chunk {
    const char *pre;
    size_t base, total;
} duel_perf_chunk;

static void duel_perf_chunk_progress(void *ud, size_t done, size_t n)
{
    const duel_perf_chunk *ch = (const duel_perf_chunk *)ud;
    size_t all = ch->base + done;
    (void)n;
    fprintf(stderr, "\r%s%zu/%zu comparisons played%s", ch->pre, all, ch->total, all == ch->total ? "\n" : "");
}

#define DUEL_PERF_OOM(m_)                                                                                             \
    do {                                                                                                              \
        duel_perf_say("%sout of memory\n", pre);                                                       \
        rc = 1;                                                                                                       \
        goto out;                                                                                                     \
    } while (0)

/* Every candidate opened, then the rankings not among them; the pairs. 0 or 2/1 after one line. */
static int duel_perf_open_all(duel_perf *m, const char *const *cand, uint32_t n_cand, const char *const *against,
                              uint32_t n_against, const char *pre, int ckpt)
{
    uint32_t i, j, k;
    int rc = 2;
    if (n_cand == 0 || n_against == 0) {
        duel_perf_say("%s%s\n", pre,
                n_cand == 0 ? "which runs? (no candidate run before --against)" : "an empty ranking: --against names no run");
        return 2;
    }
    if ((uint64_t)n_cand + n_against > DUEL_PERF_MAX_RUNS) {
        duel_perf_say("%s%u runs, at most %d\n", pre, n_cand + n_against, DUEL_PERF_MAX_RUNS);
        return 2;
    }
    m->n_cand = n_cand;
    m->runs = (duel_perf_run *)calloc((size_t)n_cand + n_against, sizeof *m->runs);
    m->rank = (uint32_t *)calloc(n_against, sizeof *m->rank);
    if (m->runs == NULL || m->rank == NULL)
        DUEL_PERF_OOM(m);
    for (i = 0; i < n_cand; i++) {
        if (duel_perf_open(&m->runs[m->n_runs], cand[i], pre, ckpt) != 0)
            goto out;
        m->n_runs++;
        for (j = 0; j < i; j++)
            if (strcmp(m->runs[j].real, m->runs[i].real) == 0) {
                duel_perf_say("%s%s is given twice as a candidate\n", pre, duel_esc(cand[i]));
                goto out;
            }
    }
    for (i = 0; i < n_against; i++) {
        duel_perf_run r;
        if (duel_perf_open(&r, against[i], pre, ckpt) != 0)
            goto out;
        for (j = 0; j < m->n_runs && strcmp(m->runs[j].real, r.real) != 0; j++)
            ;
        for (k = 0; k < m->n_rank; k++)
            if (m->rank[k] == j) {
                duel_perf_say("%s%s is given twice after --against\n", pre, duel_esc(against[i]));
                duel_perf_close(&r);
                goto out;
            }
        if (j == m->n_runs)
            m->runs[m->n_runs++] = r;
        else
            duel_perf_close(&r); /* a candidate too: already open */
        m->rank[m->n_rank++] = j;
    }

    /* one world: a comparison means something only between strategies of the same game */
    for (i = 1; i < m->n_runs; i++)
        if (!duel_rules_equal(&m->runs[i].world, &m->runs[0].world)) {
            char a[40], b[40];
            duel_perf_say("%s%s was made in world %s, %s in world %s: runs of different worlds are "
                            "not compared\n", pre, duel_esc(m->runs[0].dir), duel_world_label(&m->runs[0].world, a, sizeof a),
                    duel_esc(m->runs[i].dir), duel_world_label(&m->runs[i].world, b, sizeof b));
            goto out;
        }
    m->world = m->runs[0].world;

    /* the pairs: every candidate against every ranking but its own */
    m->pairs = (duel_perf_pair *)calloc((size_t)m->n_cand * m->n_rank, sizeof *m->pairs);
    m->perf_hi = (double *)calloc(m->n_cand, sizeof(double));
    m->perf_co = (double *)calloc(m->n_cand, sizeof(double));
    m->gen_hi = (double *)calloc(m->n_cand, sizeof(double));
    m->gen_co = (double *)calloc(m->n_cand, sizeof(double));
    m->pair_hi = (double *)calloc((size_t)m->n_cand * m->n_rank + 1, sizeof(double));
    m->pair_co = (double *)calloc((size_t)m->n_cand * m->n_rank + 1, sizeof(double));
    if (m->pairs == NULL || m->perf_hi == NULL || m->perf_co == NULL || m->gen_hi == NULL || m->gen_co == NULL ||
        m->pair_hi == NULL || m->pair_co == NULL)
        DUEL_PERF_OOM(m);
    for (i = 0; i < m->n_cand; i++) {
        uint32_t mine = 0;
        for (k = 0; k < m->n_rank; k++) {
            duel_perf_pair *p = &m->pairs[m->n_pairs];
            if (m->rank[k] == i)
                continue;
            p->cand = i;
            p->rank = m->rank[k];
            p->t = (duel_tally *)calloc(m->runs[p->rank].n_levels, sizeof *p->t);
            if (p->t == NULL)
                DUEL_PERF_OOM(m);
            m->n_pairs++;
            mine++;
        }
        if (mine == 0) {
            duel_perf_say("%s%s: an empty ranking: --against names no run but itself\n", pre,
                    duel_esc(m->runs[i].dir));
            goto out;
        }
    }
    rc = 0;
out:
    return rc;
}

/* Saves the n caches that changed; the first failure is said once (*failed), and changes no result. */
static void duel_perf_save(duel_cmp_cache *c, uint32_t n, const char *pre, int *failed)
{
    uint32_t i;
    for (i = 0; i < n; i++)
        if (duel_cmp_cache_save(&c[i]) != 0 && !*failed) {
            *failed = 1;
            duel_perf_say("%s%s: cannot write the cache (%s); the results are not affected\n", pre,
                    duel_esc(c[i].path), strerror(errno));
        }
}

/* A cache opened; a file that is not one starts afresh (and is replaced) only with --force. 0 or -1. */
static int duel_perf_cache_open(duel_cmp_cache *c, const char *path, const duel_perf_opts *o, char *err,
                                size_t err_len)
{
    int r = duel_cmp_cache_open(c, path, err, err_len);
    if (r == -2 && o->force) {
        memset(c, 0, sizeof *c);
        snprintf(c->path, sizeof c->path, "%s", path);
        c->dirty = 1;
        return 0;
    }
    return r == 0 ? 0 : -1;
}

static int duel_perf_measure_in(duel_perf *m, const char *const *cand, uint32_t n_cand, const char *const *against,
                                uint32_t n_against, const duel_perf_opts *o);

int duel_perf_measure(duel_perf *m, const char *const *cand, uint32_t n_cand, const char *const *against,
                      uint32_t n_against, const duel_perf_opts *o)
{
    int rc;
    duel_perf_sink = o->msg;
    duel_perf_sink_cap = o->msg_cap;
    if (o->msg != NULL && o->msg_cap > 0)
        o->msg[0] = '\0';
    rc = duel_perf_measure_in(m, cand, n_cand, against, n_against, o);
    duel_perf_sink = NULL;
    return rc;
}

static int duel_perf_measure_in(duel_perf *m, const char *const *cand, uint32_t n_cand, const char *const *against,
                                uint32_t n_against, const duel_perf_opts *o)
{
    duel_cmp_cache *caches = NULL, shared;
    duel_pair *jobs = NULL;
    uint32_t *slot = NULL;
    uint64_t *job_key = NULL;         /* the cache key of each job: (candidate's top, ranking level) */
    duel_cmp_cache **job_cache = NULL; /* and the cache it goes into */
    int save_failed = 0;
    uint32_t i, k, l, n_jobs = 0;
    uint64_t world = 0;
    size_t total = 0, at = 0;
    const char *pre = o->prefix ? o->prefix : "";
    char err[4400];
    int rc;

    memset(m, 0, sizeof *m);
    memset(&shared, 0, sizeof shared);
    rc = duel_perf_open_all(m, cand, n_cand, against, n_against, pre, !o->no_checkpoint);
    if (rc != 0)
        goto out;
    world = duel_rules_id(&m->world);
    rc = 2;

    /* the caches: one per candidate run (RUN/compare-cache.csv), or one for all */
    caches = (duel_cmp_cache *)calloc(m->n_cand, sizeof *caches);
    if (caches == NULL)
        DUEL_PERF_OOM(m);
    if (o->cache_path != NULL && duel_perf_cache_open(&shared, o->cache_path, o, err, sizeof err) != 0) {
        duel_perf_say("%s%s\n", pre, duel_esc_msg(err));
        goto out;
    }
    for (i = 0; i < m->n_cand && o->cache_path == NULL; i++) {
        char path[4200];
        snprintf(path, sizeof path, "%s/compare-cache.csv", m->runs[i].dir);
        if (duel_perf_cache_open(&caches[i], path, o, err, sizeof err) != 0) {
            duel_perf_say("%s%s\n", pre, duel_esc_msg(err));
            goto out;
        }
    }

    /* what the caches do not hold: one job per (pair, level), found again through slot */
    for (k = 0; k < m->n_pairs; k++)
        total += m->runs[m->pairs[k].rank].n_levels;
    jobs = (duel_pair *)calloc(total + 1, sizeof *jobs);
    job_key = (uint64_t *)calloc(2 * (total + 1), sizeof *job_key);
    slot = (uint32_t *)calloc(total + 1, sizeof *slot);
    job_cache = (duel_cmp_cache **)calloc(total + 1, sizeof *job_cache);
    if (jobs == NULL || slot == NULL || job_cache == NULL || job_key == NULL)
        DUEL_PERF_OOM(m);
    for (k = 0; k < m->n_pairs; k++) {
        duel_perf_pair *p = &m->pairs[k];
        duel_perf_run *c = &m->runs[p->cand], *r = &m->runs[p->rank];
        duel_cmp_cache *cc = o->cache_path ? &shared : &caches[p->cand];
        for (l = 0; l < r->n_levels; l++, at++) {
            const duel_tally *t = duel_cmp_cache_find(cc, world, c->top_hash, r->hash[l]);
            if (t != NULL) {
                p->t[l] = *t;
                slot[at] = UINT32_MAX;
                m->cached++;
            } else {
                jobs[n_jobs].a = &c->levels[c->n_levels - 1].ctrl;
                jobs[n_jobs].b = &r->levels[l].ctrl;
                job_key[2 * n_jobs] = c->top_hash;
                job_key[2 * n_jobs + 1] = r->hash[l];
                job_cache[n_jobs] = cc;
                slot[at] = n_jobs++;
            }
        }
    }
    if (n_jobs > 0 && o->mode == DUEL_PERF_CACHE_ONLY) {
        duel_perf_say("%s%u comparisons are not in the caches (the first: %s against %s): they would "
                        "have to be played\n", pre, n_jobs, duel_esc(jobs[0].a->name), duel_esc(jobs[0].b->name));
        goto out;
    }
    /* played a chunk at a time, each chunk's results saved in the caches at once: a compare killed midway keeps
     * what it played (a chunk is long enough for the threads to stay busy: its last comparisons are its only
     * idle time) */
    {
        duel_perf_chunk ch;
        size_t from, chunk = n_jobs / 16 > 32 ? n_jobs / 16 : 32;
        ch.pre = pre;
        ch.total = n_jobs;
        for (from = 0; from < n_jobs; from += chunk) {
            size_t n = n_jobs - from < chunk ? n_jobs - from : chunk, j;
            ch.base = from;
            if (duel_pairs_play(&m->world, jobs + from, n, o->threads, o->progress ? duel_perf_chunk_progress : NULL,
                                &ch) != 0) {
                duel_perf_say("%sa comparison failed (out of memory)\n", pre);
                rc = 1;
                goto out;
            }
            for (j = from; j < from + n; j++)
                if (duel_cmp_cache_add(job_cache[j], world, job_key[2 * j], job_key[2 * j + 1], &jobs[j].tally) != 0)
                    DUEL_PERF_OOM(m);
            duel_perf_save(o->cache_path ? &shared : caches, o->cache_path ? 1u : m->n_cand, pre, &save_failed);
        }
    }
    /* and once more: a cache that changed without a game (a format-1 file, written back in format 2) */
    duel_perf_save(o->cache_path ? &shared : caches, o->cache_path ? 1u : m->n_cand, pre, &save_failed);
    m->played = n_jobs;
    /* into the pairs */
    for (k = 0, at = 0; k < m->n_pairs; k++) {
        duel_perf_pair *p = &m->pairs[k];
        duel_perf_run *r = &m->runs[p->rank];
        for (l = 0; l < r->n_levels; l++, at++)
            if (slot[at] != UINT32_MAX)
                p->t[l] = jobs[slot[at]].tally;
        duel_perf_readings(p, r->n_levels);
    }

    /* per candidate: the means over its rankings */
    for (i = 0, k = 0; i < m->n_cand; i++) {
        uint32_t n = 0;
        for (; k < m->n_pairs && m->pairs[k].cand == i; k++, n++) {
            const duel_perf_pair *p = &m->pairs[k];
            m->pair_hi[k] = duel_perf_level_share(m, p, p->highest);
            m->pair_co[k] = duel_perf_level_share(m, p, p->contiguous);
            m->perf_hi[i] += m->pair_hi[k];
            m->perf_co[i] += m->pair_co[k];
            m->gen_hi[i] += duel_perf_gen(m, p, p->highest);
            m->gen_co[i] += duel_perf_gen(m, p, p->contiguous);
        }
        m->perf_hi[i] /= n;
        m->perf_co[i] /= n;
        m->gen_hi[i] /= n;
        m->gen_co[i] /= n;
    }
    rc = 0;
out:
    free(jobs);
    free(slot);
    free(job_cache);
    free(job_key);
    for (i = 0; caches != NULL && i < m->n_cand; i++)
        duel_cmp_cache_free(&caches[i]);
    free(caches);
    duel_cmp_cache_free(&shared);
    return rc;
}

void duel_perf_free(duel_perf *m)
{
    uint32_t i, k;
    free(m->pair_hi);
    free(m->pair_co);
    for (k = 0; m->pairs != NULL && k < m->n_pairs; k++)
        free(m->pairs[k].t);
    free(m->pairs);
    for (i = 0; m->runs != NULL && i < m->n_runs; i++)
        duel_perf_close(&m->runs[i]);
    free(m->runs);
    free(m->rank);
    free(m->perf_hi);
    free(m->perf_co);
    free(m->gen_hi);
    free(m->gen_co);
    memset(m, 0, sizeof *m);
}

const duel_out_kind duel_perf_csv_kind = {"a compare CSV", "candidate,candidate_level,", NULL};
const duel_out_kind duel_perf_json_kind = {"a compare JSON file", "{\n  \"games_per_comparison\"", NULL};
const duel_out_kind duel_perf_cache_kind = {"a compare cache", NULL, duel_cmp_cache_is};


/* mean and sample standard deviation (0 for one value) */
duel_cmp_stats duel_cmp_stat(const double *v, size_t n)
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

void duel_perf_write_csv(FILE *f, const void *ctx)
{
    const duel_perf *m = (const duel_perf *)ctx;
    uint32_t k, l;
    char w[40];
    duel_world_label(&m->world, w, sizeof w);
    fprintf(f, "candidate,candidate_level,candidate_generation,ranking,ranking_levels,highest_level,"
               "highest_generation,highest_performance,contiguous_level,contiguous_generation,contiguous_performance,"
               "wins,world,candidate_step,ranking_step\n");
    for (k = 0; k < m->n_pairs; k++) {
        const duel_perf_pair *p = &m->pairs[k];
        const duel_perf_run *c = &m->runs[p->cand], *r = &m->runs[p->rank];
        duel_csv_field(f, c->dir);
        fprintf(f, ",%u,%u,", c->n_levels, c->levels[c->n_levels - 1].generation);
        duel_csv_field(f, r->dir);
        fprintf(f, ",%u,%u,%.0f,%.6f,%u,%.0f,%.6f,", r->n_levels, p->highest,
                duel_perf_gen(m, p, p->highest), duel_perf_level_share(m, p, p->highest), p->contiguous,
                duel_perf_gen(m, p, p->contiguous), duel_perf_level_share(m, p, p->contiguous));
        for (l = 0; l < r->n_levels; l++)
            fprintf(f, "%s%u:%u", l ? " " : "", p->t[l].wins_a, p->t[l].wins_b);
        fprintf(f, ",%s,%s,%s\n", w, duel_step_name(c->net_step), duel_step_name(r->net_step));
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

void duel_perf_write_json(FILE *f, const void *ctx)
{
    const duel_perf *m = (const duel_perf *)ctx;
    uint32_t i, k, l, at = 0;
    char w[40];
    fprintf(f, "{\n  \"games_per_comparison\": %d,\n  \"world\": \"%s\",\n  \"world_id\": \"%016llx\",\n  \"runs\": %u,\n  "
               "\"summary\": {", 2 * DUEL_CONFIGS, duel_world_label(&m->world, w, sizeof w),
            (unsigned long long)duel_rules_id(&m->world), m->n_cand);
    duel_cmp_json_stats(f, "highest", m->perf_hi, m->gen_hi, m->n_cand, m->pair_hi, m->n_pairs);
    fprintf(f, ", ");
    duel_cmp_json_stats(f, "contiguous", m->perf_co, m->gen_co, m->n_cand, m->pair_co, m->n_pairs);
    fprintf(f, "},\n  \"candidates\": [\n");
    for (i = 0; i < m->n_cand; i++) {
        const duel_perf_run *c = &m->runs[i];
        fprintf(f, "    {\"run\": ");
        duel_json_str(f, c->dir);
        fprintf(f, ", \"levels\": %u, \"generation\": %u, \"hidden\": %u, \"connections\": %u, "
                   "\"highest\": {\"performance\": %.6f, \"equivalent_generation\": %.3f}, "
                   "\"contiguous\": {\"performance\": %.6f, \"equivalent_generation\": %.3f}, \"step\": \"%s\", "
                   "\"rankings\": [\n",
                c->n_levels, c->levels[c->n_levels - 1].generation, c->levels[c->n_levels - 1].hidden,
                c->levels[c->n_levels - 1].conns, m->perf_hi[i], m->gen_hi[i], m->perf_co[i], m->gen_co[i],
                duel_step_name(c->net_step));
        for (k = 0; at < m->n_pairs && m->pairs[at].cand == i; at++, k++) {
            const duel_perf_pair *p = &m->pairs[at];
            const duel_perf_run *r = &m->runs[p->rank];
            fprintf(f, "%s      {\"run\": ", k ? ",\n" : "");
            duel_json_str(f, r->dir);
            fprintf(f, ", \"levels\": %u, \"highest_level\": %u, \"highest_generation\": %.0f, "
                       "\"contiguous_level\": %u, \"contiguous_generation\": %.0f, \"wins\": [",
                    r->n_levels, p->highest, duel_perf_gen(m, p, p->highest), p->contiguous,
                    duel_perf_gen(m, p, p->contiguous));
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

