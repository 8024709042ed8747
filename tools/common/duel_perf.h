/* duel_perf.h - the paper's performance measure: each candidate run's highest dominant against every level of other runs' dominance rankings, 288 games a level, cached, in both readings. */
#ifndef DUEL_PERF_H
#define DUEL_PERF_H

#include <limits.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "duel.h"
#include "duel_levels.h"
#include "duel_outputs.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif
#define DUEL_PERF_MAX_RUNS 4096

/* A finished run: its dominance ranking with every dominant's blob. */
typedef struct duel_perf_run {
    const char *dir;        /* as given */
    duel_rules world;       /* the rules it was made in (its checkpoint's, else its config.ini's) */
    int net_step;           /* its networks' step (config.ini's net_step) */
    char real[PATH_MAX];    /* realpath: a run is never ranked against itself */
    duel_level *levels;
    uint32_t n_levels;
    uint64_t top_hash;      /* the highest dominant's blob */
    uint64_t *hash;         /* [n_levels] */
} duel_perf_run;

/* One candidate against one ranking: the result of each comparison and the two readings. */
typedef struct duel_perf_pair {
    uint32_t cand, rank;          /* indices into duel_perf.runs */
    duel_tally *t;                /* [levels of the ranking] */
    uint32_t highest, contiguous; /* levels (0: none defeated) */
} duel_perf_pair;

typedef struct duel_perf {
    duel_perf_run *runs;    /* candidates first, then the rankings not among them */
    uint32_t n_runs, n_cand;
    uint32_t *rank;         /* [n_rank] indices into runs */
    uint32_t n_rank;
    duel_perf_pair *pairs;  /* [n_pairs], candidate-major, rankings in the order given */
    uint32_t n_pairs;
    double *pair_hi, *pair_co; /* [n_pairs] each pair's performance, both readings */
    /* per candidate, means over its rankings */
    double *perf_hi, *perf_co, *gen_hi, *gen_co;
    size_t played, cached;  /* comparisons played now, and found in the caches */
    duel_rules world;       /* every run's: runs of different worlds are not compared */
} duel_perf;

/* What duel_perf_measure does with a comparison no cache holds. */
enum duel_perf_mode {
    DUEL_PERF_PLAY = 0,      /* play it and keep it in the cache */
    DUEL_PERF_CACHE_ONLY = 1 /* refuse: nothing may be played */
};

typedef struct duel_perf_opts {
    uint32_t threads;        /* 0: every core */
    const char *cache_path;  /* NULL: each candidate's RUN/compare-cache.csv */
    int mode;                /* enum duel_perf_mode */
    const char *prefix;      /* error lines: "duel_evolve: PREFIX..." ("compare: ") */
    int progress;            /* 1: a progress line on stderr */
    int force;               /* 1: a cache file that is not one is replaced (--force); 0: refused */
    int no_checkpoint;       /* 1: a run is finished when generations.csv records every generation (a report of
                              * runs kept without their checkpoints); 0: its checkpoint says so */
    char *msg;               /* NULL: lines on stderr; else nothing printed, the last line here (without
                              * "duel_evolve: ") */
    size_t msg_cap;
} duel_perf_opts;

/* Opens every candidate and every ranking (each a finished run), pairs every
 * candidate with every ranking but its own, and fills m, playing in the
 * runs' world. 0; 2 after one line on stderr (bad input: not a finished
 * run, a run named twice, runs of different worlds, an empty ranking, a
 * damaged cache, or in DUEL_PERF_CACHE_ONLY a comparison that is not cached); 1 after one line (out of memory, a comparison failed).
 * duel_perf_free(m) in every case. */
int duel_perf_measure(duel_perf *m, const char *const *cand, uint32_t n_cand, const char *const *against,
                      uint32_t n_against, const duel_perf_opts *o);
void duel_perf_free(duel_perf *m);

/* compare's outputs of a measure m (ctx: const duel_perf *, for duel_file_write_with): --csv, a row per
 * (candidate, ranking) pair, and --json, the summary and every pair (docs/tools.md, "compare"). */
void duel_perf_write_csv(FILE *f, const void *ctx);
void duel_perf_write_json(FILE *f, const void *ctx);
/* What each of compare's files is, for the output checks (duel_outputs.h). */
extern const duel_out_kind duel_perf_csv_kind, duel_perf_json_kind, duel_perf_cache_kind;
/* mean and sample standard deviation (0 for one value) */
typedef struct duel_cmp_stats {
    double mean, sd;
} duel_cmp_stats;
duel_cmp_stats duel_cmp_stat(const double *v, size_t n);

/* The generation of level (1-based) of pair p's ranking; 0.0 for level 0 (nothing defeated: as if it equalled
 * generation 0). */
double duel_perf_gen(const duel_perf *m, const duel_perf_pair *p, uint32_t level);
/* level / levels of pair p's ranking. */
double duel_perf_level_share(const duel_perf *m, const duel_perf_pair *p, uint32_t level);

#endif /* DUEL_PERF_H */
