/* bench_nets.c - random test networks of an exact connection count, shared by the benchmarks. */
#include "bench_nets.h"

static double bench_weight(neat_rng *rng)
{
    return (2.0 * neat_rng_uniform(rng) - 1.0) * 2.0;
}

int bench_random_net(neat_genome *g, uint32_t n_in, uint32_t n_out, uint32_t n_hidden, uint32_t n_conns,
                     int minimal_first, neat_rng *rng)
{
    uint32_t i, innov = 0, first_out = n_in + 1, nodes = n_in + 1 + n_out + n_hidden;
    int err = 0;
    if (minimal_first) {
        err = neat_genome_minimal(g, n_in, n_out, NULL);
        for (i = 0; !err && i < g->n_conns; i++)
            g->conns[i].weight = bench_weight(rng);
        innov = g->n_conns;
    } else {
        neat_genome_init(g);
        for (i = 0; i < first_out + n_out && !err; i++)
            err = neat_genome_add_node(g, i, i == 0 ? NEAT_NODE_BIAS : i <= n_in ? NEAT_NODE_INPUT : NEAT_NODE_OUTPUT,
                                       NULL);
    }
    for (i = 0; !err && i < n_hidden; i++)
        err = neat_genome_add_node(g, first_out + n_out + i, NEAT_NODE_HIDDEN, NULL);
    while (!err && g->n_conns < n_conns) {
        uint32_t s = neat_rng_below(rng, nodes), d = first_out + neat_rng_below(rng, nodes - first_out);
        uint32_t k, dup = 0;
        for (k = 0; k < g->n_conns; k++)
            dup |= g->conns[k].in == s && g->conns[k].out == d;
        if (!dup)
            err = neat_genome_add_conn(g, s, d, bench_weight(rng), innov++, 1, NULL);
    }
    return err;
}
