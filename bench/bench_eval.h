/* bench_eval.h - the benchmark tasks' per-network evaluators, shared by neat_bench and the NEAT C++ harness. */
#ifndef BENCH_EVAL_H
#define BENCH_EVAL_H

#include <stdint.h>

#include "cartpole.h"
#include "neat_phenotype.h"

/* The C++ harness (tools/neatcpp) links these C symbols */
#ifdef __cplusplus
extern "C" {
#endif

/* XOR on the four patterns, each from a reset network settled to a fixed
 * point: *fitness = (4 - error)^2. Returns 1 if every output rounds right
 * (>= 0.5 for 1), else 0. */
int bench_xor_eval(neat_phenotype *ph, double *fitness);

/* One network action on the double-pole cart: inputs from c (bias, then the
 * Markov task's 6 state variables or the non-Markov task's 3, scaled as in
 * the C++ release), one nrt_step, output in (0, 1) -> force in (-10, 10) N. */
void bench_pole_step(neat_phenotype *ph, cartpole *c, int markov);
/* Steps balanced from state c (the network reset first), at most max_steps. */
uint32_t bench_pole_balance(neat_phenotype *ph, cartpole *c, int markov, uint32_t max_steps);
/* The Markov task's fitness: steps balanced from the standard start
 * (cartpole_init), at most max_steps; max_steps means solved. */
uint32_t bench_pole_markov(neat_phenotype *ph, uint32_t max_steps);

#ifdef __cplusplus
}
#endif

#endif /* BENCH_EVAL_H */
