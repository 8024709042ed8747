/* task_xor.c - XOR (NEAT paper, 2002): fitness (4 - error)^2, solved when all four outputs round right. */
#include "bench.h"
#include "bench_eval.h"

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
            solved = bench_xor_eval(&ph, &f);
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
