/* neat_bench.c - the NEAT paper's benchmarks (XOR, double pole with and without velocities) and the activation speed. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include "duel_cores.h"
#include "neat_config.h"
#include "nrt.h"

/* ---- runs in parallel: each run's seed comes from its index, so results do not depend on threads ---- */
typedef struct bench_job {
    const bench_cfg *cfg;
    const char *task;
    bench_result *res;
    uint32_t next;
    int quiet;
    pthread_mutex_t lock;
} bench_job;

static void *bench_worker(void *arg)
{
    bench_job *job = (bench_job *)arg;
    for (;;) {
        uint32_t r;
        uint64_t key, seed;
        bench_result *res;
        pthread_mutex_lock(&job->lock);
        r = job->next++;
        pthread_mutex_unlock(&job->lock);
        if (r >= job->cfg->runs)
            return NULL;
        key = r;
        seed = neat_seed_derive(job->cfg->seed, &key, 1);
        res = &job->res[r];
        memset(res, 0, sizeof *res);
        if (strcmp(job->task, "xor") == 0)
            task_xor_run(job->cfg, seed, res);
        else
            task_pole_run(job->cfg, seed, strcmp(job->task, "pole") == 0, res);
        if (!job->quiet) {
            pthread_mutex_lock(&job->lock);
            if (res->error)
                fprintf(stderr, "run %u: error: %s\n", r, res->error < -90 ? nrt_strerror(res->error + 100)
                                                                           : neat_strerror(res->error));
            else if (res->solved)
                fprintf(stderr, "run %u: solved after %llu evaluations (generation %u), %u hidden nodes, %u connections\n",
                        r, (unsigned long long)res->evaluations, res->generations, res->hidden_nodes, res->connections);
            else
                fprintf(stderr, "run %u: FAILED after %llu evaluations (%u generations)\n", r,
                        (unsigned long long)res->evaluations, res->generations);
            pthread_mutex_unlock(&job->lock);
        }
    }
}

static int bench_cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int bench_evolve(const char *task, bench_cfg *cfg, int quiet)
{
    bench_job job;
    pthread_t *th;
    uint32_t t, r, solved = 0, errors = 0, n_threads = cfg->threads;
    uint64_t *ev;
    double t0 = bench_now(), secs, sum_ev = 0, sum_hid = 0, sum_conn = 0, sum_gen = 0, median = 0;

    if (n_threads == 0)
        n_threads = duel_cores();
    if (n_threads > cfg->runs)
        n_threads = cfg->runs;
    memset(&job, 0, sizeof job);
    job.cfg = cfg;
    job.task = task;
    job.quiet = quiet;
    job.res = (bench_result *)calloc(cfg->runs, sizeof(bench_result));
    th = (pthread_t *)calloc(n_threads, sizeof(pthread_t));
    ev = (uint64_t *)calloc(cfg->runs, sizeof(uint64_t));
    if (job.res == NULL || th == NULL || ev == NULL) {
        fprintf(stderr, "neat_bench: out of memory\n");
        return 1;
    }
    pthread_mutex_init(&job.lock, NULL);
    for (t = 0; t < n_threads; t++)
        pthread_create(&th[t], NULL, bench_worker, &job);
    for (t = 0; t < n_threads; t++)
        pthread_join(th[t], NULL);
    pthread_mutex_destroy(&job.lock);
    secs = bench_now() - t0;

    for (r = 0; r < cfg->runs; r++) {
        bench_result *x = &job.res[r];
        errors += x->error != 0;
        if (!x->solved)
            continue;
        ev[solved++] = x->evaluations;
        sum_ev += (double)x->evaluations;
        sum_hid += x->hidden_nodes;
        sum_conn += x->connections;
        sum_gen += x->generations;
    }
    if (solved) {
        qsort(ev, solved, sizeof ev[0], bench_cmp_u64);
        median = solved % 2 ? (double)ev[solved / 2] : 0.5 * (double)(ev[solved / 2 - 1] + ev[solved / 2]);
    }
    /* a sync run's lines are what they were before the modes (scripts parse them) */
    const char *mode = cfg->neat.net_step == NEAT_STEP_PROPAGATE ? " (propagate)" : "";
    printf("task %s%s: %u runs, %u failures (%u errors), seed %llu, %u threads, %.1f s\n", task, mode, cfg->runs,
           cfg->runs - solved, errors, (unsigned long long)cfg->seed, n_threads, secs);
    if (solved)
        printf("solved runs: mean %.1f evaluations, median %.1f, mean %.2f hidden nodes, %.2f connections, %.1f generations\n",
               sum_ev / solved, median, sum_hid / solved, sum_conn / solved, sum_gen / solved);
    printf("{\"task\":\"%s\",\"runs\":%u,\"failures\":%u,\"errors\":%u,\"mean_evaluations\":%.1f,"
           "\"median_evaluations\":%.1f,\"mean_hidden_nodes\":%.3f,\"mean_connections\":%.3f,"
           "\"mean_generations\":%.2f,\"seed\":%llu,\"threads\":%u,\"seconds\":%.2f%s}\n",
           task, cfg->runs, cfg->runs - solved, errors, solved ? sum_ev / solved : 0.0, median,
           solved ? sum_hid / solved : 0.0, solved ? sum_conn / solved : 0.0, solved ? sum_gen / solved : 0.0,
           (unsigned long long)cfg->seed, n_threads, secs, *mode ? ",\"net_step\":\"propagate\"" : "");
    free(job.res);
    free(th);
    free(ev);
    return errors ? 1 : 0;
}

static void bench_usage(FILE *f)
{
    fprintf(f, "usage: neat_bench --version | --help\n"
               "       neat_bench xor|pole|pole-nv|activation [--runs N] [--seed S] [--threads T]\n"
               "                  [--config FILE.ini] [--dump-config] [--quiet] [--verbose]\n"
               "       neat_bench activation [--count-steps N --connections 40|200]\n"
               "       (any task) [--net-step sync|propagate|both]\n"
               "Runs NEAT on a benchmark of the NEAT paper (Stanley & Miikkulainen 2002); the last line\n"
               "of stdout is a JSON summary. Defaults: bench/<task>.ini, compiled in.\n"
               "  xor, pole, pole-nv        XOR; double pole balancing with and without velocities (docs/parameters.md)\n"
               "  activation                network steps per second of 40- and 200-connection networks\n"
               "  --runs N                  independent runs (default: the task's ini)\n"
               "  --seed S                  the base seed; run k's is derived from (S, k) (default 1)\n"
               "  --threads T               threads (default 0: every core); results do not depend on it\n"
               "  --config FILE.ini         the task's parameters from FILE.ini instead of bench/<task>.ini\n"
               "  --dump-config             print the parameters the runs would use, run nothing\n"
               "  --quiet                   only the JSON summary\n"
               "  --verbose                 one line per generation on stderr\n"
               "  --count-steps N           activation: step one network N times (for instruction counts)\n"
               "  --connections 40|200      activation: which network --count-steps steps\n"
               "  --net-step MODE           how networks step: sync, propagate, or both (sync's report, then\n"
               "                            propagate's); default: the task's ini (net_step; sync)\n");
}

static int bench_parse_u64(const char *opt, const char *s, uint64_t max, uint64_t *out)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (s[0] == '\0' || s[0] == '-' || *end != '\0' || errno || v > max) {
        fprintf(stderr, "neat_bench: bad value '%s' for %s\n", s, opt);
        return -1;
    }
    *out = v;
    return 0;
}

static int bench_main(int argc, char **argv)
{
    bench_cfg cfg;
    const char *task, *config = NULL;
    char path[1024];
    uint64_t runs = 0, threads = 0, seed = 1, count_steps = 0, count_conns = 40;
    int i, have_seed = 0, have_runs = 0, have_threads = 0, quiet = 0, dump = 0, verbose = 0, net_step = -1;

    if (argc >= 2 && strcmp(argv[1], "--version") == 0) {
        printf("neat_bench %s (libneat %d.%d)\n", NEAT_DUEL_VERSION_STRING, NEAT_VERSION_MAJOR, NEAT_VERSION_MINOR);
        return 0;
    }
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        bench_usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    for (i = 2; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            bench_usage(stdout);
            return 0;
        }
    task = argv[1];
    if (strcmp(task, "xor") && strcmp(task, "pole") && strcmp(task, "pole-nv") && strcmp(task, "activation")) {
        fprintf(stderr, "neat_bench: unknown task '%s' (xor, pole, pole-nv or activation)\n", task);
        return 2;
    }
    for (i = 2; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--quiet") == 0) {
            quiet = 1;
            continue;
        }
        if (strcmp(a, "--verbose") == 0) {
            verbose = 1;
            continue;
        }
        if (strcmp(a, "--dump-config") == 0) {
            dump = 1;
            continue;
        }
        if (i + 1 >= argc) {
            int takes = strcmp(a, "--runs") == 0 || strcmp(a, "--seed") == 0 || strcmp(a, "--threads") == 0 ||
                        strcmp(a, "--config") == 0 || strcmp(a, "--count-steps") == 0 ||
                        strcmp(a, "--connections") == 0 || strcmp(a, "--net-step") == 0;
            fprintf(stderr, takes ? "neat_bench: %s needs a value\n" : "neat_bench: unknown option '%s'\n", a);
            return 2;
        }
        if (strcmp(a, "--runs") == 0) {
            if (bench_parse_u64(a, argv[++i], 100000, &runs) || runs == 0)
                return 2;
            have_runs = 1;
        } else if (strcmp(a, "--seed") == 0) {
            if (bench_parse_u64(a, argv[++i], UINT64_MAX, &seed))
                return 2;
            have_seed = 1;
        } else if (strcmp(a, "--threads") == 0) {
            if (bench_parse_u64(a, argv[++i], 1024, &threads))
                return 2;
            have_threads = 1;
        } else if (strcmp(a, "--count-steps") == 0) {
            if (bench_parse_u64(a, argv[++i], UINT64_MAX, &count_steps))
                return 2;
        } else if (strcmp(a, "--connections") == 0) {
            if (bench_parse_u64(a, argv[++i], 200, &count_conns) || (count_conns != 40 && count_conns != 200)) {
                fprintf(stderr, "neat_bench: --connections must be 40 or 200\n");
                return 2;
            }
        } else if (strcmp(a, "--net-step") == 0) {
            const char *v = argv[++i];
            net_step = strcmp(v, "sync") == 0        ? NEAT_STEP_SYNC
                       : strcmp(v, "propagate") == 0 ? NEAT_STEP_PROPAGATE
                       : strcmp(v, "both") == 0      ? BENCH_STEP_BOTH
                                                     : -2;
            if (net_step == -2) {
                fprintf(stderr, "neat_bench: --net-step must be sync, propagate or both, not '%s'\n", v);
                return 2;
            }
        } else if (strcmp(a, "--config") == 0) {
            config = argv[++i];
        } else {
            fprintf(stderr, "neat_bench: unknown option '%s'\n", a);
            return 2;
        }
    }
    if (strcmp(task, "activation") == 0) {
        if (count_steps > 0) {
            if (net_step == BENCH_STEP_BOTH) {
                fprintf(stderr, "neat_bench: --count-steps steps one network: --net-step sync or propagate\n");
                return 2;
            }
            return bench_activation_count(seed, (uint32_t)count_conns, count_steps, net_step < 0 ? 0 : net_step);
        }
        return bench_activation(seed, 0.5, net_step < 0 ? NEAT_STEP_SYNC : net_step);
    }

    memset(&cfg, 0, sizeof cfg);
    cfg.neat = neat_params_default();
    cfg.runs = 10;
    cfg.max_generations = 100;
    cfg.balance_steps = 100000;
    cfg.damping_steps = 1000;
    cfg.generalization_min = 200;
    if (config == NULL) {
        /* the defaults are compiled in: an installed neat_bench reads no source tree */
        const char *text = bench_default_ini(task);
        char err[600];
        snprintf(path, sizeof path, "bench/%s.ini (built in)", task);
        if (text == NULL || bench_config_load_text(&cfg, path, text, strlen(text), err, sizeof err) != 0) {
            fprintf(stderr, "neat_bench: %s\n", text == NULL ? "no built-in parameters for this task" : err);
            return 2;
        }
    } else if (bench_config_load(&cfg, config) != 0) {
        return 2;
    }
    if (have_runs)
        cfg.runs = (uint32_t)runs;
    if (have_threads)
        cfg.threads = (uint32_t)threads;
    cfg.seed = have_seed ? seed : 1;
    cfg.verbose = verbose;
    if (net_step == NEAT_STEP_SYNC || net_step == NEAT_STEP_PROPAGATE)
        cfg.neat.net_step = net_step;
    if (dump) {
        printf("[bench]\n");
        bench_config_dump(stdout, &cfg);
        printf("\n[neat]\n");
        neat_config_dump(stdout, &cfg.neat);
        return 0;
    }
    if (net_step == BENCH_STEP_BOTH) {
        int rc;
        cfg.neat.net_step = NEAT_STEP_SYNC;
        rc = bench_evolve(task, &cfg, quiet);
        cfg.neat.net_step = NEAT_STEP_PROPAGATE;
        return bench_evolve(task, &cfg, quiet) ? 1 : rc;
    }
    return bench_evolve(task, &cfg, quiet);
}

int main(int argc, char **argv)
{
    int rc = bench_main(argc, argv);
    /* the JSON summary must have reached standard output (a full disk, a closed pipe: a failure) */
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "neat_bench: cannot write standard output: %s\n", strerror(errno));
        return rc != 0 ? rc : 1;
    }
    return rc;
}
