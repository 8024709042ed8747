/* neat_params.c - the parameter defaults (the paper's Appendix A) and their range checks. */
#include <math.h>

#include "nrt.h"
#include "neat_internal.h"

neat_params neat_params_default(void)
{
    neat_params p;
    /* Appendix A of Stanley & Miikkulainen (2004) unless marked; the others
     * are documented with their source in docs/parameters.md. */
    p.pop_size = 256;
    p.n_inputs = 12;            /* the duel's sensors; bias is input 0 */
    p.n_outputs = 3;
    p.mode = NEAT_MODE_COMPLEXIFY;
    p.c1 = 1.0;
    p.c2 = 1.0;
    p.c3 = 2.0;
    p.normalize_by_size = 0;
    p.delta_t = 3.0;
    p.delta_t_step = 0.3;
    p.delta_t_min = 0.3;        /* chosen: a threshold must stay positive */
    p.target_species = 10;
    p.survival_fraction = 0.2;  /* C++ release, pole2_markov.ne */
    p.elitism_min_size = 5;
    p.stagnation_rule = NEAT_STAGNATION_OLDEST_WORST;
    p.dropoff_age = 30;
    p.stagnation_factor = 0.0;
    p.pop_stagnation = 35;      /* C++ release: dropoff_age + 5 */
    p.mutate_only_prob = 0.25;
    p.mate_only_prob = 0.2;     /* C++ release */
    p.interspecies_prob = 0.05;
    p.mate_avg_prob = 0.4;
    p.disable_prob = 0.75;
    p.excess_equal_prob = 0.5;  /* "from both parents randomly" */
    p.weight_mut_prob = 0.8;
    p.weight_perturb_prob = 0.9;
    p.weight_perturb_power = 2.5; /* C++ release, pole2_markov.ne */
    p.weight_init_range = 1.0;  /* C++ release: new links uniform in [-1, 1] */
    p.weight_replace_range = 2.5; /* C++ release: a replaced weight is uniform in +-power */
    p.weight_max = 8.0;         /* C++ release cap; also the blob's Q3.12 range */
    p.add_conn_prob = 0.1;
    p.add_node_prob = 0.01;
    p.add_conn_tries = 20;      /* C++ release newlink_tries */
    p.allow_recurrent = 1;
    p.max_nodes = NRT_MAX_NODES;
    p.net_step = NEAT_STEP_SYNC; /* chosen: the paper-era NEAT's step (docs/parameters.md) */
    /* the paper's text where the release differs (neat_params_neat_cpp) */
    p.profile = NEAT_PROFILE_DEFAULT;
    p.equal_fitness_rule = NEAT_EQUAL_RANDOM;
    p.reenable_rule = NEAT_REENABLE_PAPER;
    p.add_conn_rule = NEAT_ADD_CONN_ANY;
    p.recur_only_prob = 0.0;
    p.species_rep = NEAT_REP_RANDOM;
    p.weight_mut_rule = NEAT_WEIGHTS_UNIFORM;
    p.elitism_rule = NEAT_ELITE_BY_SIZE;
    p.interspecies_rule = NEAT_INTER_UNIFORM;
    p.identical_rule = NEAT_IDENTICAL_SAME;
    p.offspring_rounding = NEAT_ROUND_REMAINDER;
    p.speciate_rule = NEAT_SPECIATE_AFTER;
    p.cull_every = 30;          /* C++ release (Population::epoch): only under NEAT_STAGNATION_CPP */
    p.cull_age = 20;
    p.pop_stagnation_rule = NEAT_POPSTAG_TWO_BEST;
    return p;
}

int neat_params_set_profile(neat_params *p, int profile)
{
    neat_params d = neat_params_default();
    int cpp = profile == NEAT_PROFILE_NEAT_CPP;
    if (p == NULL || (profile != NEAT_PROFILE_DEFAULT && !cpp))
        return NEAT_E_ARG;
    p->profile = profile;
    p->equal_fitness_rule = cpp ? NEAT_EQUAL_SMALLER : d.equal_fitness_rule;
    p->reenable_rule = cpp ? NEAT_REENABLE_CPP : d.reenable_rule;
    p->add_conn_rule = cpp ? NEAT_ADD_CONN_CPP : d.add_conn_rule;
    p->recur_only_prob = cpp ? 0.2 : d.recur_only_prob;       /* params256.ne */
    p->species_rep = cpp ? NEAT_REP_CHAMPION : d.species_rep;
    p->weight_mut_rule = cpp ? NEAT_WEIGHTS_CPP : d.weight_mut_rule;
    p->elitism_rule = cpp ? NEAT_ELITE_BY_OFFSPRING : d.elitism_rule;
    p->interspecies_rule = cpp ? NEAT_INTER_CPP : d.interspecies_rule;
    p->identical_rule = cpp ? NEAT_IDENTICAL_EQUAL : d.identical_rule;
    p->offspring_rounding = cpp ? NEAT_ROUND_SKIM : d.offspring_rounding;
    p->speciate_rule = cpp ? NEAT_SPECIATE_INTERLEAVED : d.speciate_rule;
    p->stagnation_rule = cpp ? NEAT_STAGNATION_CPP : d.stagnation_rule;
    p->dropoff_age = cpp ? 1000 : d.dropoff_age;               /* params256.ne */
    p->cull_every = d.cull_every;
    p->cull_age = d.cull_age;
    p->pop_stagnation_rule = cpp ? NEAT_POPSTAG_DELTA : d.pop_stagnation_rule;
    p->pop_stagnation = cpp ? 0 : d.pop_stagnation;            /* the release's 1005: beyond any run */
    return NEAT_OK;
}

int neat_params_uses_neat_cpp(const neat_params *p)
{
    neat_params d = neat_params_default();
    return p->profile != d.profile || p->equal_fitness_rule != d.equal_fitness_rule ||
           p->reenable_rule != d.reenable_rule || p->add_conn_rule != d.add_conn_rule ||
           p->recur_only_prob != d.recur_only_prob || p->species_rep != d.species_rep ||
           p->weight_mut_rule != d.weight_mut_rule || p->elitism_rule != d.elitism_rule ||
           p->interspecies_rule != d.interspecies_rule || p->identical_rule != d.identical_rule ||
           p->offspring_rounding != d.offspring_rounding || p->speciate_rule != d.speciate_rule ||
           p->cull_every != d.cull_every || p->cull_age != d.cull_age ||
           p->pop_stagnation_rule != d.pop_stagnation_rule || p->stagnation_rule == NEAT_STAGNATION_CPP;
}

neat_params neat_params_neat_cpp(void)
{
    neat_params p = neat_params_default();
    (void)neat_params_set_profile(&p, NEAT_PROFILE_NEAT_CPP);
    return p;
}

static int neat_prob_ok(double x)
{
    return x >= 0.0 && x <= 1.0;
}

/* the release's switches: 0 (this library's rule) or 1 (the release's) */
static int neat_switch_ok(int x)
{
    return x == 0 || x == 1;
}

/* Upper bounds of the parameters that have no natural one, so that a value
 * read from a file can neither overflow arithmetic nor stall an epoch (the
 * same ranges as the tools' INI keys, tools/common/neat_config.c). */
#define NEAT_PARAM_BIG 1e9          /* c1..c3, delta_t and its step and floor */
#define NEAT_PARAM_MAX_POP 1000000u /* pop_size, target_species, elitism_min_size */
#define NEAT_PARAM_MAX_AGE 1000000000u /* dropoff_age, pop_stagnation (generations) */
#define NEAT_PARAM_MAX_TRIES 1000u     /* add_conn_tries: each try costs a look through a genome (C++ uses 20) */

int neat_params_check(const neat_params *p, const char **field)
{
    const char *bad = NULL;
    if (p == NULL)
        return NEAT_E_ARG;
    if (p->pop_size < 2 || p->pop_size > NEAT_PARAM_MAX_POP)
        bad = "pop_size";
    else if (p->n_outputs < 1 || p->n_inputs >= NRT_MAX_NODES || p->n_outputs >= NRT_MAX_NODES ||
             p->n_inputs + p->n_outputs + 1 > NRT_MAX_NODES) /* each bounded first: the sum cannot wrap */
        bad = "n_inputs/n_outputs";
    else if (p->mode < NEAT_MODE_COMPLEXIFY || p->mode > NEAT_MODE_SIMPLIFY)
        bad = "mode";
    else if (!(p->c1 >= 0 && p->c1 <= NEAT_PARAM_BIG) || !(p->c2 >= 0 && p->c2 <= NEAT_PARAM_BIG) ||
             !(p->c3 >= 0 && p->c3 <= NEAT_PARAM_BIG))
        bad = "c1/c2/c3";
    else if (p->normalize_by_size != 0 && p->normalize_by_size != 1)
        bad = "normalize_by_size";
    else if (!(p->delta_t > 0 && p->delta_t <= NEAT_PARAM_BIG))
        bad = "delta_t";
    else if (!(p->delta_t_step >= 0 && p->delta_t_step <= NEAT_PARAM_BIG))
        bad = "delta_t_step";
    else if (!(p->delta_t_min > 0 && p->delta_t_min <= NEAT_PARAM_BIG))
        bad = "delta_t_min";
    else if (p->target_species > NEAT_PARAM_MAX_POP)
        bad = "target_species";
    else if (p->elitism_min_size > NEAT_PARAM_MAX_POP)
        bad = "elitism_min_size";
    else if (p->dropoff_age > NEAT_PARAM_MAX_AGE)
        bad = "dropoff_age";
    else if (p->pop_stagnation > NEAT_PARAM_MAX_AGE)
        bad = "pop_stagnation";
    else if (!(p->survival_fraction > 0) || p->survival_fraction > 1)
        bad = "survival_fraction";
    else if (p->stagnation_rule < NEAT_STAGNATION_OLDEST_WORST || p->stagnation_rule > NEAT_STAGNATION_CPP)
        bad = "stagnation_rule";
    else if (!neat_prob_ok(p->stagnation_factor))
        bad = "stagnation_factor";
    else if (!neat_prob_ok(p->mutate_only_prob))
        bad = "mutate_only_prob";
    else if (!neat_prob_ok(p->mate_only_prob))
        bad = "mate_only_prob";
    else if (!neat_prob_ok(p->interspecies_prob))
        bad = "interspecies_prob";
    else if (!neat_prob_ok(p->mate_avg_prob))
        bad = "mate_avg_prob";
    else if (!neat_prob_ok(p->disable_prob))
        bad = "disable_prob";
    else if (!neat_prob_ok(p->excess_equal_prob))
        bad = "excess_equal_prob";
    else if (!neat_prob_ok(p->weight_mut_prob))
        bad = "weight_mut_prob";
    else if (!neat_prob_ok(p->weight_perturb_prob))
        bad = "weight_perturb_prob";
    else if (!(p->weight_perturb_power >= 0 && p->weight_perturb_power <= 1000))
        bad = "weight_perturb_power";
    else if (!(p->weight_max > 0) || p->weight_max > 8.0)
        bad = "weight_max";
    else if (!(p->weight_init_range >= 0) || p->weight_init_range > p->weight_max)
        bad = "weight_init_range";
    else if (!(p->weight_replace_range >= 0) || p->weight_replace_range > p->weight_max)
        bad = "weight_replace_range";
    else if (!neat_prob_ok(p->add_conn_prob))
        bad = "add_conn_prob";
    else if (!neat_prob_ok(p->add_node_prob))
        bad = "add_node_prob";
    else if (p->add_node_prob + p->add_conn_prob > 1.0)
        bad = "add_node_prob + add_conn_prob"; /* one draw picks at most one of them: their sum is at most 1 */
    else if (p->add_conn_tries > NEAT_PARAM_MAX_TRIES)
        bad = "add_conn_tries";
    else if (p->allow_recurrent != 0 && p->allow_recurrent != 1)
        bad = "allow_recurrent";
    else if (p->max_nodes < p->n_inputs + p->n_outputs + 1 || p->max_nodes > NRT_MAX_NODES)
        bad = "max_nodes";
    else if (p->net_step != NEAT_STEP_SYNC && p->net_step != NEAT_STEP_PROPAGATE)
        bad = "net_step";
    else if (p->profile != NEAT_PROFILE_DEFAULT && p->profile != NEAT_PROFILE_NEAT_CPP)
        bad = "profile";
    else if (!neat_switch_ok(p->equal_fitness_rule))
        bad = "equal_fitness_rule";
    else if (!neat_switch_ok(p->reenable_rule))
        bad = "reenable_rule";
    else if (!neat_switch_ok(p->add_conn_rule))
        bad = "add_conn_rule";
    else if (!neat_prob_ok(p->recur_only_prob))
        bad = "recur_only_prob";
    else if (!neat_switch_ok(p->species_rep))
        bad = "species_rep";
    else if (!neat_switch_ok(p->weight_mut_rule))
        bad = "weight_mut_rule";
    else if (!neat_switch_ok(p->elitism_rule))
        bad = "elitism_rule";
    else if (!neat_switch_ok(p->interspecies_rule))
        bad = "interspecies_rule";
    else if (!neat_switch_ok(p->identical_rule))
        bad = "identical_rule";
    else if (!neat_switch_ok(p->offspring_rounding))
        bad = "offspring_rounding";
    else if (!neat_switch_ok(p->speciate_rule))
        bad = "speciate_rule";
    else if (p->cull_every > NEAT_PARAM_MAX_AGE)
        bad = "cull_every";
    else if (p->cull_age > NEAT_PARAM_MAX_AGE)
        bad = "cull_age";
    else if (!neat_switch_ok(p->pop_stagnation_rule))
        bad = "pop_stagnation_rule";
    if (field != NULL)
        *field = bad;
    return bad == NULL ? NEAT_OK : NEAT_E_PARAM;
}

const char *neat_strerror(int err)
{
    switch (err) {
    case NEAT_OK: return "ok";
    case NEAT_E_ARG: return "invalid argument";
    case NEAT_E_NOMEM: return "out of memory";
    case NEAT_E_PARAM: return "parameter out of range";
    case NEAT_E_FITNESS: return "fitness missing, negative, NaN or infinite";
    case NEAT_E_TOOBIG: return "network too large for the blob format";
    case NEAT_E_FORMAT: return "malformed file (magic, version, size or value)";
    case NEAT_E_CRC: return "checksum mismatch";
    case NEAT_E_TRUNCATED: return "truncated";
    case NEAT_E_STATE: return "call out of order";
    case NEAT_E_COUNTERS: return "a counter (node ids, innovation numbers, species ids or generations) reached its "
                                 "limit of 2^31 - 1: the run cannot go on";
    default: return "unknown error";
    }
}
