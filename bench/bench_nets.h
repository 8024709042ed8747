/* bench_nets.h - random test networks of an exact connection count, shared by the benchmarks. */
#ifndef BENCH_NETS_H
#define BENCH_NETS_H

#include "neat.h"

/* n_in sensors (plus the bias), n_out outputs, n_hidden hidden nodes and
 * exactly n_conns distinct connections with weights uniform in [-2, 2]:
 * first every bias/input -> output connection if minimal_first, then random
 * (possibly recurrent or self) ones. The same draws give the same network. */
int bench_random_net(neat_genome *g, uint32_t n_in, uint32_t n_out, uint32_t n_hidden, uint32_t n_conns,
                     int minimal_first, neat_rng *rng);

#endif /* BENCH_NETS_H */
