/* task_pole.c - double pole balancing with velocities (Markov) and without (non-Markov, damping fitness). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "bench_eval.h"

/* Gruau's damping fitness: 0.1 f1 + 0.9 f2, f1 = steps / window,
 * f2 = 0.75 / sum over the last 100 steps of |x| + |x'| + |th1| + |th1'|
 * (f2 only when more than 100 steps were balanced). */
static double pole_damping_fitness(neat_phenotype *ph, uint32_t window)
{
    /* 101 slots: a failing step's own value must not overwrite the first of
     * the 100 before it */
    double jiggle[101], sum = 0.0;
    cartpole c;
    uint32_t t, balanced = window, k;
    cartpole_init(&c);
    nrt_reset(&ph->net);
    for (t = 0; t < window; t++) {
        bench_pole_step(ph, &c, 0);
        jiggle[t % 101] = fabs(c.s[0]) + fabs(c.s[1]) + fabs(c.s[2]) + fabs(c.s[3]);
        if (cartpole_failed(&c)) {
            balanced = t;
            break;
        }
    }
    if (balanced <= 100)
        return 0.1 * balanced / (double)window;
    /* the 100 steps before the end: steps balanced-100 .. balanced-1 */
    for (k = 1; k <= 100; k++)
        sum += jiggle[(balanced - k) % 101];
    return 0.1 * balanced / (double)window + 0.9 * 0.75 / sum;
}

/* The 625 starts of the generalisation test: x, x', th1, th1' over 5 values
 * each (the C++ release's grid), th2 = th2' = 0, 1000 steps each. */
static uint32_t pole_generalization(neat_phenotype *ph, uint32_t steps)
{
    static const double v[5] = {0.05, 0.25, 0.5, 0.75, 0.95};
    uint32_t a, b, cc, d, ok = 0;
    for (a = 0; a < 5; a++)
        for (b = 0; b < 5; b++)
            for (cc = 0; cc < 5; cc++)
                for (d = 0; d < 5; d++) {
                    cartpole c;
                    cartpole_init(&c);
                    c.s[0] = v[a] * 4.32 - 2.16;
                    c.s[1] = v[b] * 2.70 - 1.35;
                    c.s[2] = v[cc] * 0.12566304 - 0.06283152;
                    c.s[3] = v[d] * 0.30019504 - 0.15009752;
                    if (bench_pole_balance(ph, &c, 0, steps) >= steps - 1)
                        ok++;
                }
    return ok;
}

/* Networks already put to the champion tests, by their blob's CRC-32: each
 * generation tests the fittest genome not tested before, so a run whose best
 * genome passes the damping test but not the others moves on to the next
 * candidates (the C++ release likewise tests a different species'
 * champion each generation). */
typedef struct pole_tested {
    uint32_t *crc;
    size_t n, cap;
} pole_tested;

static int pole_was_tested(pole_tested *t, uint32_t crc)
{
    size_t i;
    for (i = 0; i < t->n; i++)
        if (t->crc[i] == crc)
            return 1;
    if (t->n == t->cap) {
        size_t ncap = t->cap ? 2 * t->cap : 64;
        uint32_t *nc = (uint32_t *)realloc(t->crc, ncap * sizeof(uint32_t));
        if (nc == NULL)
            return 0; /* cannot remember: test it again, which is only slower */
        t->crc = nc;
        t->cap = ncap;
    }
    t->crc[t->n++] = crc;
    return 0;
}

/* The fittest genome (lowest index on ties) not put to the tests before,
 * loaded into ph; -1 when every genome has been. skip[] is scratch. */
static int pole_next_candidate(const neat_pop *pop, const neat_params *p, neat_phenotype *ph, pole_tested *t,
                               uint8_t *skip, int *err)
{
    uint32_t i, n = neat_pop_size(pop);
    for (i = 0; i < n; i++)
        skip[i] = 0;
    for (;;) {
        int best = -1;
        for (i = 0; i < n; i++)
            if (!skip[i] && (best < 0 || neat_pop_genome(pop, i)->fitness > neat_pop_genome(pop, (uint32_t)best)->fitness))
                best = (int)i;
        if (best < 0)
            return -1;
        skip[best] = 1;
        *err = neat_phenotype_load(ph, neat_pop_genome(pop, (uint32_t)best), p);
        if (*err)
            return -1;
        if (!pole_was_tested(t, nrt_crc32(0, ph->blob, ph->blob_len)))
            return best;
    }
}

int task_pole_run(const bench_cfg *cfg, uint64_t seed, int markov, bench_result *res)
{
    neat_pop *pop = NULL;
    neat_phenotype ph;
    uint32_t gen, i, n;
    uint64_t evals = 0;
    int err;

    pole_tested tested = {NULL, 0, 0};
    uint8_t *skip = (uint8_t *)malloc(cfg->neat.pop_size);

    res->solved = 0;
    neat_phenotype_init(&ph, NULL);
    err = skip == NULL ? NEAT_E_NOMEM : neat_pop_create(&pop, &cfg->neat, NULL, seed, NULL);
    for (gen = 0; !err && gen < cfg->max_generations; gen++) {
        double best_f = -1.0;
        n = neat_pop_size(pop);
        for (i = 0; i < n && !err && !res->solved; i++) {
            const neat_genome *g = neat_pop_genome(pop, i);
            double f;
            err = neat_phenotype_load(&ph, g, &cfg->neat);
            if (err)
                break;
            evals++;
            if (markov) {
                f = bench_pole_markov(&ph, cfg->balance_steps);
                if (f >= cfg->balance_steps)
                    bench_solved(res, g, evals, gen);
            } else {
                f = pole_damping_fitness(&ph, cfg->damping_steps);
            }
            if (f > best_f)
                best_f = f;
            err = neat_pop_set_fitness(pop, i, f);
        }
        if (!markov && !err) {
            /* this generation's candidate: long test, then generalisation */
            int cand = pole_next_candidate(pop, &cfg->neat, &ph, &tested, skip, &err);
            const neat_genome *g = cand >= 0 ? neat_pop_genome(pop, (uint32_t)cand) : NULL;
            uint32_t steps = 0, gz = 0;
            cartpole c;
            cartpole_init(&c);
            if (g != NULL)
                steps = bench_pole_balance(&ph, &c, 0, cfg->balance_steps);
            if (g != NULL && steps >= cfg->balance_steps) {
                gz = pole_generalization(&ph, 1000);
                if (gz >= cfg->generalization_min) {
                    bench_solved(res, g, evals, gen);
                    res->generalization = gz;
                }
            }
            if (cfg->verbose)
                fprintf(stderr, "  seed %llu generation %u: best damping fitness %.4f, champion balanced %u steps, "
                        "generalised %u/625, %u species\n", (unsigned long long)seed, gen, best_f, steps, gz,
                        neat_pop_species_count(pop));
        } else if (cfg->verbose && !err) {
            fprintf(stderr, "  seed %llu generation %u: best fitness %.4f, %u species\n", (unsigned long long)seed,
                    gen, best_f, neat_pop_species_count(pop));
        }
        if (res->solved || err)
            break;
        if (cfg->max_evaluations && evals >= cfg->max_evaluations)
            break;
        err = neat_pop_epoch(pop);
    }
    neat_phenotype_free(&ph);
    neat_pop_free(pop);
    free(tested.crc);
    free(skip);
    return bench_finish(res, evals, gen, err);
}
