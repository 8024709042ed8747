/* task_xor.c - XOR (NEAT paper, 2002): fitness (4 - error)^2, solved when all four outputs round right. */
#include <math.h>

#include "bench.h"
#include "neat_phenotype.h"

/* Fitness of one network, and whether it solves XOR. */
static int xor_eval(neat_phenotype *ph, double *fitness)
{
    static const int pat[4][3] = {{0, 0, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 0}};
    double err = 0.0;
    int k, correct = 1;
    for (k = 0; k < 4; k++) {
        nrt_q15 in[3], out[1];
        double o;
        in[0] = NRT_ONE;
        in[1] = pat[k][0] ? NRT_ONE : 0;
        in[2] = pat[k][1] ? NRT_ONE : 0;
        nrt_reset(&ph->net);
        /* feed-forward: propagate until nothing changes (depth <= nodes) */
        (void)nrt_settle(&ph->net, in, out, ph->net.n_nodes + 1);
        o = neat_from_q15(out[0]);
        err += fabs(o - pat[k][2]);
        if ((o >= 0.5) != (pat[k][2] == 1))
            correct = 0;
    }
    *fitness = (4.0 - err) * (4.0 - err);
    return correct;
}

int task_xor_run(const bench_cfg *cfg, uint64_t seed, bench_result *res)
{
    neat_pop *pop = NULL;
    neat_phenotype ph;
    uint32_t gen, i, n;
    uint64_t evals = 0;
    int err;

    res->solved = 0;
    neat_phenotype_init(&ph, NULL);
    err = neat_pop_create(&pop, &cfg->neat, NULL, seed, NULL);
    for (gen = 0; !err && gen < cfg->max_generations; gen++) {
        n = neat_pop_size(pop);
        for (i = 0; i < n && !err && !res->solved; i++) {
            const neat_genome *g = neat_pop_genome(pop, i);
            double f;
            int solved;
            err = neat_phenotype_load(&ph, g, &cfg->neat);
            if (err)
                break;
            solved = xor_eval(&ph, &f);
            evals++;
            err = neat_pop_set_fitness(pop, i, f);
            if (solved && !res->solved)
                bench_solved(res, g, evals, gen);
        }
        if (res->solved || err)
            break;
        if (cfg->max_evaluations && evals >= cfg->max_evaluations)
            break;
        err = neat_pop_epoch(pop);
    }
    neat_phenotype_free(&ph);
    neat_pop_free(pop);
    return bench_finish(res, evals, gen, err);
}
