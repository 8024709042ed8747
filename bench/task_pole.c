/* task_pole.c - double pole balancing with velocities (Markov) and without (non-Markov, damping fitness). */
#include <math.h>

#include "bench.h"
#include "cartpole.h"
#include "neat_phenotype.h"

/* Network inputs, scaled as in the C++ release; input 0 is the bias. */
static void pole_inputs(const cartpole *c, int markov, nrt_q15 *in)
{
    in[0] = NRT_ONE;
    if (markov) {
        in[1] = neat_q15(c->s[0] / 4.8);
        in[2] = neat_q15(c->s[1] / 2.0);
        in[3] = neat_q15(c->s[2] / 0.52);
        in[4] = neat_q15(c->s[3] / 2.0);
        in[5] = neat_q15(c->s[4] / 0.52);
        in[6] = neat_q15(c->s[5] / 2.0);
    } else {
        in[1] = neat_q15(c->s[0] / 4.8);
        in[2] = neat_q15(c->s[2] / 0.52);
        in[3] = neat_q15(c->s[4] / 0.52);
    }
}

/* One network action: output in (0, 1) -> force in (-10, 10) N. */
static void pole_step(neat_phenotype *ph, cartpole *c, int markov)
{
    nrt_q15 in[7], out[1];
    pole_inputs(c, markov, in);
    nrt_step(&ph->net, in, out);
    cartpole_act(c, (neat_from_q15(out[0]) - 0.5) * 20.0);
}

/* Steps balanced from state c (network reset first), at most max_steps. */
static uint32_t pole_balance(neat_phenotype *ph, cartpole *c, int markov, uint32_t max_steps)
{
    uint32_t t;
    nrt_reset(&ph->net);
    for (t = 0; t < max_steps; t++) {
        pole_step(ph, c, markov);
        if (cartpole_failed(c))
            return t;
    }
    return max_steps;
}

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
        pole_step(ph, &c, 0);
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
                    if (pole_balance(ph, &c, 0, steps) >= steps - 1)
                        ok++;
                }
    return ok;
}

static void pole_record(bench_result *res, const neat_genome *g, uint64_t evals, uint32_t gen)
{
    res->solved = 1;
    res->evaluations = evals;
    res->generations = gen + 1;
    res->hidden_nodes = neat_genome_hidden_count(g);
    res->connections = neat_genome_enabled_count(g);
}

int task_pole_run(const bench_cfg *cfg, uint64_t seed, int markov, bench_result *res)
{
    neat_pop *pop = NULL;
    neat_phenotype ph;
    uint32_t gen, i, n;
    uint64_t evals = 0;
    int err;

    res->solved = 0;
    neat_phenotype_init(&ph);
    err = neat_pop_create(&pop, &cfg->neat, NULL, seed, NULL);
    for (gen = 0; !err && gen < cfg->max_generations; gen++) {
        uint32_t best = 0;
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
                cartpole c;
                cartpole_init(&c);
                f = pole_balance(&ph, &c, 1, cfg->balance_steps);
                if (f >= cfg->balance_steps)
                    pole_record(res, g, evals, gen);
            } else {
                f = pole_damping_fitness(&ph, cfg->damping_steps);
            }
            if (f > best_f) {
                best_f = f;
                best = i;
            }
            err = neat_pop_set_fitness(pop, i, f);
        }
        if (!markov && !err) {
            /* the generation's champion: long test, then generalisation */
            const neat_genome *g = neat_pop_genome(pop, best);
            cartpole c;
            cartpole_init(&c);
            err = neat_phenotype_load(&ph, g, &cfg->neat);
            if (!err && pole_balance(&ph, &c, 0, cfg->balance_steps) >= cfg->balance_steps) {
                uint32_t gz = pole_generalization(&ph, 1000);
                if (gz >= cfg->generalization_min) {
                    pole_record(res, g, evals, gen);
                    res->generalization = gz;
                }
            }
        }
        if (res->solved || err)
            break;
        if (cfg->max_evaluations && evals >= cfg->max_evaluations)
            break;
        err = neat_pop_epoch(pop);
    }
    if (!res->solved) {
        res->evaluations = evals;
        res->generations = gen;
    }
    neat_phenotype_free(&ph);
    neat_pop_free(pop);
    res->error = err;
    return err;
}
