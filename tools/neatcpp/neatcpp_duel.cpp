// neatcpp_duel.cpp - duel_evolve whose coevolution runs with [run] reproduction = neat-cpp-1.2.1 reproduce by NEAT C++ 1.2.1's own code.
//
// Everything but reproduction is the project's: the coevolution protocol (libneat's neat_coev: opponents, 24
// games a host, a win a point, the hall of fame, the dominance tournament), world v1, the runtime every network
// runs on, the run directory and every command that reads it. Only the step from one generation's genomes and
// their wins to the next generation's genomes and species is the release's: its Population::epoch and all under
// it, on populations of NEAT::Organism kept beside libneat's, converted to libneat genomes after every epoch
// (neatcpp_genome.cpp), and handed to the coevolution through neat_pop_replace (docs/neat-cpp.md, "The release
// on the duel").
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <iostream>
#include <streambuf>
#include <vector>

#include "genome.h"
#include "neat.h"
#include "organism.h"
#include "population.h"
#include "species.h"
extern "C" {
#include "duel_cli.h"
#include "duel_engine.h"
}
#include "neatcpp_genome.h"
#include "neatcpp_random.h"

namespace {

// the release narrates every epoch on std::cout; duel_evolve's own output goes through stdio
class null_buf : public std::streambuf {
  protected:
    int overflow(int c) { return c; }
};

struct release_run {
    NEAT::Population *pop[2];
    double threshold[2];   // the dynamic compatibility threshold of each population (below)
    neat_params p;
    uint64_t seed;
};

release_run run_state;

// The release's globals from the run's [neat] values: the same numbers drive libneat's runs, so the two
// reproductions differ in their rules alone. The release has no mode: a fixed topology is no structural
// mutation. Its trait mutations (traits do nothing here), toggling and re-enabling are off, as in params256.ne.
int set_release_params(const neat_params *p)
{
    if (p->mode == NEAT_MODE_SIMPLIFY) {
        fprintf(stderr, "neatcpp_duel: mode = simplify: NEAT C++ 1.2.1 has no simplifying mutation\n");
        return -1;
    }
    // what the release has fixed in its code: another value would be silently not what ran
    if (p->elitism_min_size != 5 || p->weight_max != 8.0 || p->weight_init_range != 1.0 || p->cull_every != 30 ||
        p->cull_age != 20 || p->normalize_by_size != 0) {
        fprintf(stderr, "neatcpp_duel: NEAT C++ 1.2.1 fixes elitism_min_size 5, weight_max 8, weight_init_range 1, "
                        "cull_every 30, cull_age 20 and normalize_by_size false in its code: this run sets another\n");
        return -1;
    }
    NEAT::trait_param_mut_prob = 0.0;
    NEAT::trait_mutation_power = 0.0;
    NEAT::linktrait_mut_sig = 0.0;
    NEAT::nodetrait_mut_sig = 0.0;
    NEAT::weight_mut_power = p->weight_perturb_power;
    NEAT::recur_prob = 0.0; // read by the release, used nowhere
    NEAT::disjoint_coeff = p->c2;
    NEAT::excess_coeff = p->c1;
    NEAT::mutdiff_coeff = p->c3;
    NEAT::compat_threshold = p->delta_t;
    NEAT::age_significance = 1.0;
    NEAT::survival_thresh = p->survival_fraction;
    NEAT::mutate_only_prob = p->mutate_only_prob;
    NEAT::mutate_random_trait_prob = 0.0;
    NEAT::mutate_link_trait_prob = 0.0;
    NEAT::mutate_node_trait_prob = 0.0;
    NEAT::mutate_link_weights_prob = p->weight_mut_prob;
    NEAT::mutate_toggle_enable_prob = 0.0;
    NEAT::mutate_gene_reenable_prob = 0.0;
    NEAT::mutate_add_node_prob = p->mode == NEAT_MODE_FIXED ? 0.0 : p->add_node_prob;
    NEAT::mutate_add_link_prob = p->mode == NEAT_MODE_FIXED ? 0.0 : p->add_conn_prob;
    NEAT::interspecies_mate_rate = p->interspecies_prob;
    NEAT::mate_multipoint_prob = 1.0 - p->mate_avg_prob;
    NEAT::mate_multipoint_avg_prob = p->mate_avg_prob;
    NEAT::mate_singlepoint_prob = 0.0;
    NEAT::mate_only_prob = p->mate_only_prob;
    NEAT::recur_only_prob = p->allow_recurrent ? p->recur_only_prob : 0.0;
    NEAT::pop_size = (int)p->pop_size;
    NEAT::dropoff_age = (int)p->dropoff_age;
    NEAT::newlink_tries = (int)p->add_conn_tries;
    NEAT::print_every = 1000000;
    NEAT::babies_stolen = 0;
    NEAT::num_runs = 1;
    return 0;
}

// The paper's dynamic threshold (Appendix A), which the release has commented out (Population::epoch): moved by
// delta_t_step toward target_species after every speciation, as libneat moves it.
void move_threshold(uint32_t which)
{
    const neat_params *p = &run_state.p;
    size_t n = run_state.pop[which]->species.size();
    double *t = &run_state.threshold[which];
    if (p->target_species == 0)
        return;
    if (n > p->target_species)
        *t += p->delta_t_step;
    else if (n < p->target_species)
        *t -= p->delta_t_step;
    if (*t < p->delta_t_min)
        *t = p->delta_t_min;
}

// The release population's organisms, in its order, as libneat genomes with their species' ids; used: the
// threshold they were speciated with.
int install(uint32_t which, neat_pop *pop, int evaluated, double used)
{
    NEAT::Population *rp = run_state.pop[which];
    size_t n = rp->organisms.size(), i;
    std::vector<neat_genome> gs(n);
    std::vector<uint32_t> labels(n);
    uint32_t dropped = 0;
    int err = NEAT_OK;
    if (n != neat_pop_size(pop)) {
        fprintf(stderr, "neatcpp_duel: NEAT C++ 1.2.1's population has %zu organisms, not %u\n", n, neat_pop_size(pop));
        return NEAT_E_STATE;
    }
    for (i = 0; i < n; i++)
        neat_genome_init(&gs[i]);
    for (i = 0; i < n && !err; i++) {
        err = neatcpp_genome_convert_ids(rp->organisms[i]->gnome, &gs[i], &dropped);
        labels[i] = (uint32_t)rp->organisms[i]->species->id;
    }
    if (!err && dropped > 0)
        // seen never so far: said, since such a network is not quite the release's
        fprintf(stderr, "neatcpp_duel: population %u, generation %u: %u repeated genes or nodes of NEAT C++ 1.2.1's "
                        "genomes left out (docs/neat-cpp.md)\n", which, neat_pop_generation(pop), dropped);
    if (!err)
        err = neat_pop_replace(pop, gs.data(), labels.data(), (uint32_t)n, evaluated, used);
    for (i = 0; i < n; i++)
        neat_genome_free(&gs[i], NULL);
    if (err)
        fprintf(stderr, "neatcpp_duel: NEAT C++ 1.2.1's generation as libneat's: %s\n", neat_strerror(err));
    return err;
}

// A run begins: the release's parameters and random state (neatcpp_random.h), seeded from the run's seed.
int begin(void *ud, const duel_config *cfg)
{
    uint64_t key = 0x6e656174u; // "neat": the release's stream
    (void)ud;
    run_state.pop[0] = run_state.pop[1] = NULL;
    run_state.p = cfg->neat;
    run_state.seed = cfg->seed;
    if (set_release_params(&cfg->neat) != 0)
        return -1;
    neatcpp_reset_random((uint32_t)neat_seed_derive(cfg->seed, &key, 1));
    return 0;
}

int reproduce(void *ud, uint32_t which, neat_pop *pop, int evaluated)
{
    null_buf sink;
    std::streambuf *was = std::cout.rdbuf(&sink);
    int err = NEAT_OK;
    (void)ud;
    if (!evaluated) {
        // the start: the coevolution's start topology, each organism its own weights (the release's spawn)
        NEAT::Genome *start = neatcpp_genome_from_libneat(neat_pop_genome(pop, 0));
        delete run_state.pop[which];
        run_state.threshold[which] = run_state.p.delta_t;
        NEAT::compat_threshold = run_state.threshold[which];
        run_state.pop[which] = new NEAT::Population(start, (int)neat_pop_size(pop));
        delete start;
    } else {
        NEAT::Population *rp = run_state.pop[which];
        uint32_t i, n = neat_pop_size(pop);
        if (rp == NULL || rp->organisms.size() != n) {
            std::cout.rdbuf(was);
            fprintf(stderr, "neatcpp_duel: no NEAT C++ 1.2.1 population %u to reproduce (a resumed run?)\n", which);
            return NEAT_E_STATE;
        }
        double total = 0.0;
        for (i = 0; i < n; i++) {
            rp->organisms[i]->fitness = neat_pop_genome(pop, i)->fitness; // wins out of the host's games
            total += rp->organisms[i]->fitness;
        }
        if (total == 0.0)
            // not one win: the release's shares would divide by a mean of 0 (undefined behaviour in
            // Population::epoch); equal fitness instead, as libneat gives every species an equal share then
            for (i = 0; i < n; i++)
                rp->organisms[i]->fitness = 1.0;
        for (std::vector<NEAT::Species *>::iterator s = rp->species.begin(); s != rp->species.end(); ++s) {
            (*s)->compute_average_fitness(); // as experiments.cpp's epochs do before Population::epoch
            (*s)->compute_max_fitness();
        }
        NEAT::compat_threshold = run_state.threshold[which];
        rp->epoch((int)neat_pop_generation(pop) + 1); // the release counts generations from 1 (its cull: % 30)
    }
    {
        double used = run_state.threshold[which];
        move_threshold(which);
        std::cout.rdbuf(was);
        err = install(which, pop, evaluated, used);
    }
    return err;
}

} // namespace

int main(int argc, char **argv)
{
    duel_reproducer r;
    r.which = DUEL_REPRODUCE_NEAT_CPP;
    r.begin = begin;
    r.reproduce = reproduce;
    r.ud = NULL;
    duel_engine_set_reproducer(&r);
    return duel_evolve_main(argc, argv);
}
