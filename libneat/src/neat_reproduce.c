/* neat_reproduce.c - explicit fitness sharing, exact offspring apportionment, stagnation, and breeding the next generation. */
#include <math.h>

#include "neat_internal.h"

/* Sum of the members' adjusted fitness f / size (explicit fitness sharing,
 * the paper's eq. 2 with sh = 1 inside the species), i.e. the mean. */
static double neat_shared_sum(const neat_pop *pop, const neat_species *s)
{
    uint32_t i;
    double sum = 0.0;
    for (i = 0; i < s->n_members; i++)
        sum += pop->genomes[s->members[i]].fitness / (double)s->n_members;
    return sum;
}

static double neat_champ_fitness(const neat_pop *pop, uint32_t k)
{
    return pop->genomes[pop->species[k].members[0]].fitness;
}

/* Which species may breed this generation (docs/parameters.md, "Stagnation"). */
static void neat_mark_eligible(neat_pop *pop, uint32_t *since_pop)
{
    uint32_t k, n_ok = 0, worst = UINT32_MAX, top0 = UINT32_MAX, top1 = UINT32_MAX;

    for (k = 0; k < pop->n_species; k++) {
        pop->species[k].eligible = 1;
        if (top0 == UINT32_MAX || neat_champ_fitness(pop, k) > neat_champ_fitness(pop, top0)) {
            top1 = top0;
            top0 = k;
        } else if (top1 == UINT32_MAX || neat_champ_fitness(pop, k) > neat_champ_fitness(pop, top1)) {
            top1 = k;
        }
    }
    /* The whole population stagnant: only the two best species breed (the
     * C++ release's rule), then the counter starts again. The species rules
     * below do not apply then: they could bar the second of the two (an old
     * worst species), leaving every offspring to one. */
    if (pop->p.pop_stagnation > 0 && *since_pop >= pop->p.pop_stagnation && pop->n_species > 2) {
        for (k = 0; k < pop->n_species; k++)
            pop->species[k].eligible = k == top0 || k == top1;
        *since_pop = 0;
        return;
    }
    if (pop->p.stagnation_rule == NEAT_STAGNATION_IMPROVEMENT) {
        /* 2002 paper: a species not improved for dropoff_age generations
         * stops breeding (or, factor > 0, breeds at that fraction, as the
         * C++ release); the species holding the best genome never does. */
        for (k = 0; k < pop->n_species; k++)
            if (pop->species[k].eligible && k != top0 && pop->species[k].next_since >= pop->p.dropoff_age) {
                if (pop->p.stagnation_factor > 0)
                    pop->species[k].adj_sum *= pop->p.stagnation_factor;
                else
                    pop->species[k].eligible = 0;
            }
        return;
    }
    /* Appendix A: the lowest performing species older than dropoff_age gets
     * no offspring, unless it holds the generation's best or is the last. */
    for (k = 0; k < pop->n_species; k++) {
        if (!pop->species[k].eligible)
            continue;
        n_ok++;
        if (pop->species[k].age > pop->p.dropoff_age && k != top0 &&
            (worst == UINT32_MAX || pop->species[k].adj_sum <= pop->species[worst].adj_sum))
            worst = k;
    }
    if (worst != UINT32_MAX && n_ok > 1)
        pop->species[worst].eligible = 0;
}

void neat_apportion(neat_pop *pop, uint32_t *since_pop)
{
    uint32_t k, given = 0, n_elig = 0, n = pop->p.pop_size;
    double total = 0.0;

    for (k = 0; k < pop->n_species; k++)
        pop->species[k].adj_sum = neat_shared_sum(pop, &pop->species[k]);
    neat_mark_eligible(pop, since_pop);
    /* scaled by a power of two (exact) so the largest share is below 1:
     * n * share cannot overflow, whatever the magnitude of the fitness */
    {
        double top = 0.0;
        int e = 0;
        for (k = 0; k < pop->n_species; k++)
            if (pop->species[k].eligible && pop->species[k].adj_sum > top)
                top = pop->species[k].adj_sum;
        (void)frexp(top, &e);
        for (k = 0; k < pop->n_species; k++)
            pop->species[k].adj_sum = ldexp(pop->species[k].adj_sum, -e);
    }
    for (k = 0; k < pop->n_species; k++)
        if (pop->species[k].eligible) {
            total += pop->species[k].adj_sum;
            n_elig++;
        }
    /* Largest remainder (Hamilton): the floors of the quotas, then one more
     * to the largest fractional parts (ties to the older species), so the
     * counts always sum to the population size. All fitness zero: equal. */
    for (k = 0; k < pop->n_species; k++) {
        neat_species *s = &pop->species[k];
        double q = 0.0;
        if (s->eligible)
            q = total > 0 ? (double)n * s->adj_sum / total : (double)n / (double)n_elig;
        s->offspring = (uint32_t)floor(q);
        if (s->offspring > n)
            s->offspring = n;
        s->remainder = s->eligible ? q - floor(q) : -1.0;
        given += s->offspring;
    }
    while (given < n) {
        uint32_t best = UINT32_MAX;
        for (k = 0; k < pop->n_species; k++)
            if (pop->species[k].remainder >= 0 &&
                (best == UINT32_MAX || pop->species[k].remainder > pop->species[best].remainder))
                best = k;
        if (best == UINT32_MAX) {
            /* rounding gave fewer than n - given remainders: next round */
            for (k = 0; k < pop->n_species; k++)
                if (pop->species[k].eligible)
                    pop->species[k].remainder = 0.0;
            continue;
        }
        pop->species[best].offspring++;
        pop->species[best].remainder = -1.0;
        given++;
    }
    while (given > n) { /* floating rounding can only overshoot by a unit or so */
        for (k = pop->n_species; k-- > 0;)
            if (pop->species[k].offspring > 0 && given > n) {
                pop->species[k].offspring--;
                given--;
            }
    }
}

static int neat_breed_one(neat_pop *pop, uint32_t k, uint32_t parents, neat_genome *child)
{
    neat_species *s = &pop->species[k];
    const neat_params *p = &pop->p;
    const neat_genome *mom = &pop->genomes[s->members[neat_rng_below_inl(&pop->rng, parents)]];
    const neat_genome *dad;
    int err, avg;

    if (parents == 1 || neat_rng_uniform_inl(&pop->rng) < p->mutate_only_prob) {
        err = neat_genome_copy(child, mom, &pop->a);
        child->has_fitness = 0;
        return err ? err : neat_mutate(child, p, &pop->rng, &pop->iv, &pop->a);
    }
    if (pop->n_species > 1 && neat_rng_uniform_inl(&pop->rng) < p->interspecies_prob) {
        /* another species' champion */
        uint32_t k2 = neat_rng_below_inl(&pop->rng, pop->n_species - 1);
        if (k2 >= k)
            k2++;
        dad = &pop->genomes[pop->species[k2].members[0]];
    } else {
        dad = &pop->genomes[s->members[neat_rng_below_inl(&pop->rng, parents)]];
    }
    avg = neat_rng_uniform_inl(&pop->rng) < p->mate_avg_prob;
    err = neat_crossover(child, mom, dad, avg, p, &pop->rng, &pop->a);
    if (!err && (dad == mom || !(neat_rng_uniform_inl(&pop->rng) < p->mate_only_prob)))
        err = neat_mutate(child, p, &pop->rng, &pop->iv, &pop->a);
    return err;
}

int neat_reproduce(neat_pop *pop, neat_genome *next)
{
    uint32_t k, o, idx = 0;
    int err = NEAT_OK;
    for (k = 0; k < pop->n_species && !err; k++) {
        neat_species *s = &pop->species[k];
        /* survivors: as the C++ release, floor(fraction * size + 1) */
        uint32_t parents = (uint32_t)floor(pop->p.survival_fraction * s->n_members + 1.0);
        if (parents > s->n_members)
            parents = s->n_members;
        o = 0;
        if (s->offspring > 0 && s->n_members > pop->p.elitism_min_size) {
            err = neat_genome_copy(&next[idx], &pop->genomes[s->members[0]], &pop->a);
            next[idx].has_fitness = 0;
            idx++;
            o++;
        }
        for (; o < s->offspring && !err; o++)
            err = neat_breed_one(pop, k, parents, &next[idx++]);
    }
    return err;
}
