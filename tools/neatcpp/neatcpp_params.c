/* neatcpp_params.c - a .ne file of the NEAT C++ release read by position, and the libneat parameters it maps to. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "neatcpp_params.h"

static const char *const neatcpp_ne_names[NE_COUNT] = {
    "trait_param_mut_prob", "trait_mutation_power", "linktrait_mut_sig", "nodetrait_mut_sig",
    "weight_mut_power", "recur_prob", "disjoint_coeff", "excess_coeff", "mutdiff_coeff",
    "compat_threshold", "age_significance", "survival_thresh", "mutate_only_prob",
    "mutate_random_trait_prob", "mutate_link_trait_prob", "mutate_node_trait_prob",
    "mutate_link_weights_prob", "mutate_toggle_enable_prob", "mutate_gene_reenable_prob",
    "mutate_add_node_prob", "mutate_add_link_prob", "interspecies_mate_rate", "mate_multipoint_prob",
    "mate_multipoint_avg_prob", "mate_singlepoint_prob", "mate_only_prob", "recur_only_prob",
    "pop_size", "dropoff_age", "newlink_tries", "print_every", "babies_stolen", "num_runs"};

const char *neatcpp_ne_name(int k)
{
    return k >= 0 && k < NE_COUNT ? neatcpp_ne_names[k] : "?";
}

int neatcpp_ne_read(const char *path, neatcpp_ne *ne, char *err, size_t err_len)
{
    FILE *f = fopen(path, "r");
    char name[128], value[128];
    int k;
    if (f == NULL) {
        snprintf(err, err_len, "%s: %s", path, strerror(errno));
        return -1;
    }
    for (k = 0; k < NE_COUNT; k++) {
        char *end;
        double v;
        /* whitespace-separated words, as the release's operator>> reads them */
        if (fscanf(f, "%127s %127s", name, value) != 2) {
            snprintf(err, err_len, "%s: %d values, the release reads %d (the last: %s)", path, k, NE_COUNT,
                     neatcpp_ne_names[NE_COUNT - 1]);
            fclose(f);
            return -1;
        }
        errno = 0;
        v = strtod(value, &end);
        if (*end != '\0' || errno || !isfinite(v)) {
            snprintf(err, err_len, "%s: value %d (%s, named %s in the file): '%s' is not a number", path, k + 1,
                     neatcpp_ne_names[k], name, value);
            fclose(f);
            return -1;
        }
        if (k >= NE_POP_SIZE && (v != floor(v) || v < 0 || v > 1e9)) {
            snprintf(err, err_len, "%s: value %d (%s): '%s' must be a whole number", path, k + 1,
                     neatcpp_ne_names[k], value);
            fclose(f);
            return -1;
        }
        ne->v[k] = v;
    }
    fclose(f);
    return 0;
}

/* Where the release reads each value is named in brackets (src/FILE.cpp). */
neat_params neatcpp_params_from_ne(const neatcpp_ne *ne, uint32_t n_inputs, uint32_t n_outputs)
{
    neat_params p = neat_params_default();
    const double *v = ne->v;
    double avg_single = v[NE_MATE_MULTIPOINT_AVG_PROB] + v[NE_MATE_SINGLEPOINT_PROB];

    /* [experiments.cpp: new Population(start_genome, NEAT::pop_size)] */
    p.pop_size = (uint32_t)v[NE_POP_SIZE];
    /* the start genome's sensors (less the bias) and outputs */
    p.n_inputs = n_inputs;
    p.n_outputs = n_outputs;
    p.mode = NEAT_MODE_COMPLEXIFY;
    /* [genome.cpp Genome::compatibility: disjoint_coeff * disjoint + excess_coeff * excess
     * + mutdiff_coeff * mean |mutation_num difference| of matching genes, nothing divided by
     * the genome size]; libneat's c1 weighs excess genes, c2 disjoint ones */
    p.c1 = v[NE_EXCESS_COEFF];
    p.c2 = v[NE_DISJOINT_COEFF];
    p.c3 = v[NE_MUTDIFF_COEFF];
    p.normalize_by_size = 0;
    /* [population.cpp Population::speciate: compatibility < compat_threshold]; the
     * threshold is fixed (the adjustment in Population::epoch is commented out) */
    p.delta_t = v[NE_COMPAT_THRESHOLD];
    p.target_species = 0;
    /* [species.cpp Species::adjust_fitness: floor(survival_thresh * size + 1) parents] */
    p.survival_fraction = v[NE_SURVIVAL_THRESH];
    /* [species.cpp Species::adjust_fitness: fitness * 0.01 once a species has gone
     * dropoff_age - 1 generations without improving (age - age_of_last_improvement + 1
     * >= dropoff_age), the best species included; see docs/neat-cpp.md] */
    p.stagnation_rule = NEAT_STAGNATION_IMPROVEMENT;
    p.dropoff_age = (uint32_t)v[NE_DROPOFF_AGE];
    p.stagnation_factor = 0.01;
    /* [population.cpp Population::epoch: highest_last_changed >= dropoff_age + 5 -> the
     * two best species get all the offspring] */
    p.pop_stagnation = (uint32_t)v[NE_DROPOFF_AGE] + 5;
    /* [species.cpp Species::reproduce] */
    p.mutate_only_prob = v[NE_MUTATE_ONLY_PROB];
    p.mate_only_prob = v[NE_MATE_ONLY_PROB];
    p.interspecies_prob = v[NE_INTERSPECIES_MATE_RATE];
    /* [species.cpp Species::reproduce: multipoint with mate_multipoint_prob, else
     * averaging with avg / (avg + singlepoint), else singlepoint, which libneat has not:
     * its crossovers are multipoint (averaging or not)] */
    p.mate_avg_prob = avg_single > 0 ? (1.0 - v[NE_MATE_MULTIPOINT_PROB]) * v[NE_MATE_MULTIPOINT_AVG_PROB] / avg_single
                                     : 0.0;
    /* [species.cpp Species::reproduce: mutate_link_weights(weight_mut_power, 1.0, GAUSSIAN)
     * with mutate_link_weights_prob: perturbation and replacement both uniform in
     * +-weight_mut_power (genome.cpp); caps at +-8] */
    p.weight_mut_prob = v[NE_MUTATE_LINK_WEIGHTS_PROB];
    p.weight_perturb_power = v[NE_WEIGHT_MUT_POWER];
    p.weight_replace_range = v[NE_WEIGHT_MUT_POWER];
    p.weight_max = 8.0;
    /* [population.cpp Population::spawn: COLDGAUSSIAN power 1.0, and genome.cpp
     * mutate_add_link: new weights uniform in +-1] */
    p.weight_init_range = 1.0;
    /* [species.cpp Species::reproduce: add node, else add link, else the weights] */
    p.add_node_prob = v[NE_MUTATE_ADD_NODE_PROB];
    p.add_conn_prob = v[NE_MUTATE_ADD_LINK_PROB];
    /* [genome.cpp Genome::mutate_add_link(..., newlink_tries)] */
    p.add_conn_tries = (uint32_t)v[NE_NEWLINK_TRIES];
    /* [genome.cpp Genome::mutate_add_link: recurrent links only with recur_only_prob;
     * recur_prob is read but used nowhere (its line is commented out)] */
    p.allow_recurrent = v[NE_RECUR_PROB] > 0 || v[NE_RECUR_ONLY_PROB] > 0;
    /* the same, for add_conn_rule = neat-cpp (libneat's own rule ignores it) */
    p.recur_only_prob = v[NE_RECUR_ONLY_PROB];
    return p;
}
