/* neatcpp_params.h - the NEAT C++ release's parameter file (.ne) read by position, and its mapping to neat_params. */
#ifndef NEATCPP_PARAMS_H
#define NEATCPP_PARAMS_H

#include <stddef.h>
#include <stdint.h>

#include "neat.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The release's NEAT::load_neat_params reads 33 "name value" pairs by
 * position and ignores the names (test.ne spells weight_mut_power
 * "weigh_mut_power"); these are its globals' names, in its order. */
enum {
    NE_TRAIT_PARAM_MUT_PROB, NE_TRAIT_MUTATION_POWER, NE_LINKTRAIT_MUT_SIG, NE_NODETRAIT_MUT_SIG,
    NE_WEIGHT_MUT_POWER, NE_RECUR_PROB, NE_DISJOINT_COEFF, NE_EXCESS_COEFF, NE_MUTDIFF_COEFF,
    NE_COMPAT_THRESHOLD, NE_AGE_SIGNIFICANCE, NE_SURVIVAL_THRESH, NE_MUTATE_ONLY_PROB,
    NE_MUTATE_RANDOM_TRAIT_PROB, NE_MUTATE_LINK_TRAIT_PROB, NE_MUTATE_NODE_TRAIT_PROB,
    NE_MUTATE_LINK_WEIGHTS_PROB, NE_MUTATE_TOGGLE_ENABLE_PROB, NE_MUTATE_GENE_REENABLE_PROB,
    NE_MUTATE_ADD_NODE_PROB, NE_MUTATE_ADD_LINK_PROB, NE_INTERSPECIES_MATE_RATE, NE_MATE_MULTIPOINT_PROB,
    NE_MATE_MULTIPOINT_AVG_PROB, NE_MATE_SINGLEPOINT_PROB, NE_MATE_ONLY_PROB, NE_RECUR_ONLY_PROB,
    NE_POP_SIZE, NE_DROPOFF_AGE, NE_NEWLINK_TRIES, NE_PRINT_EVERY, NE_BABIES_STOLEN, NE_NUM_RUNS,
    NE_COUNT
};

typedef struct neatcpp_ne {
    double v[NE_COUNT]; /* the values, by the enum above */
} neatcpp_ne;

/* The release's name of value k (its global's name, not the file's). */
const char *neatcpp_ne_name(int k);
/* Reads path as the release does (positional pairs), stricter: every value
 * must be a number, the integer ones integers. 0, or -1 with err. */
int neatcpp_ne_read(const char *path, neatcpp_ne *ne, char *err, size_t err_len);
/* libneat's parameters for the same run (docs/neat-cpp.md has the table):
 * neat_params_default() with every value the release has a counterpart
 * for replaced. n_inputs and n_outputs come from the start genome. */
neat_params neatcpp_params_from_ne(const neatcpp_ne *ne, uint32_t n_inputs, uint32_t n_outputs);

#ifdef __cplusplus
}
#endif

#endif /* NEATCPP_PARAMS_H */
