/* bench_result.c - recording how a benchmark run ended, the same way for every task. */
#include "bench.h"

void bench_solved(bench_result *res, const neat_genome *g, uint64_t evals, uint32_t gen)
{
    res->solved = 1;
    res->evaluations = evals;
    res->generations = gen + 1;
    res->hidden_nodes = neat_genome_hidden_count(g);
    res->connections = neat_genome_enabled_count(g);
}

int bench_finish(bench_result *res, uint64_t evals, uint32_t generations, int err)
{
    if (!res->solved) {
        res->evaluations = evals;
        res->generations = generations;
    }
    res->error = err;
    return err;
}
