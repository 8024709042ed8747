/* bench.h - what the neat_bench tasks share: their configuration and the result of one run. */
#ifndef BENCH_H
#define BENCH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "neat.h"

typedef struct bench_cfg {
    neat_params neat;           /* [neat] section */
    uint32_t runs;              /* [bench] runs */
    uint64_t seed;              /* [bench] seed: run r uses neat_seed_derive(seed, r) */
    uint32_t max_generations;   /* a run that has not solved by then fails */
    uint32_t max_evaluations;   /* ... or has evaluated this many genomes (0: no limit) */
    uint32_t threads;           /* runs in parallel (0: every core) */
    /* pole tasks */
    uint32_t balance_steps;     /* 100000: a Markov solution / the non-Markov long test */
    uint32_t damping_steps;     /* 1000: non-Markov fitness window */
    uint32_t generalization_min;/* 200 of the 625 starts */
    int verbose;                /* one line per generation on stderr */
} bench_cfg;

/* bench_config.c: FILE (or text named name) over cfg, its [bench] and [neat]
 * keys; 0, or -1 with one line on stderr (load) or in err (load_text). */
int bench_config_load(bench_cfg *cfg, const char *path);
int bench_config_load_text(bench_cfg *cfg, const char *name, const char *text, size_t len, char *err, size_t err_len);
/* The text of bench/TASK.ini as it was when neat_bench was built (bench_defaults.c, generated), or NULL
 * for a task without one. */
const char *bench_default_ini(const char *task);
/* The [bench] keys as "key = value" lines. */
void bench_config_dump(FILE *out, const bench_cfg *cfg);

typedef struct bench_result {
    int solved;
    uint64_t evaluations;   /* genomes evaluated up to and including the solution */
    uint32_t generations;
    uint32_t hidden_nodes;  /* of the solution */
    uint32_t connections;   /* enabled, of the solution */
    uint32_t generalization;/* pole-nv: starts the solution balanced */
    int error;              /* a libneat or runtime error stopped the run */
} bench_result;

/* A run solved by g after evals evaluations, in generation gen (from 0). */
void bench_solved(bench_result *res, const neat_genome *g, uint64_t evals, uint32_t gen);
/* The end of a run: an unsolved run records what it spent. Returns err. */
int bench_finish(bench_result *res, uint64_t evals, uint32_t generations, int err);

/* One evolutionary run each; return 0 or an error code. */
int task_xor_run(const bench_cfg *cfg, uint64_t seed, bench_result *res);
int task_pole_run(const bench_cfg *cfg, uint64_t seed, int markov, bench_result *res);
/* --net-step both: each figure for NEAT_STEP_SYNC, then NEAT_STEP_PROPAGATE */
#define BENCH_STEP_BOTH 2
/* the activation micro-benchmark in net_step (enum neat_net_step or
 * BENCH_STEP_BOTH): prints its figures, returns 0 */
int bench_activation(uint64_t seed, double min_seconds, int net_step);
/* exactly `steps` steps of the 40- or 200-connection network, for callgrind */
int bench_activation_count(uint64_t seed, uint32_t conns, uint64_t steps, int net_step);

#endif /* BENCH_H */
