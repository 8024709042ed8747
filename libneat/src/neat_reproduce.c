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

/* NEAT_STAGNATION_CPP: a species' fitness factor, as NEAT C++'s
 * Species::adjust_fitness: 0.01 when culled, or when its best has not
 * risen for dropoff_age - 1 generations (the release's age - age of last
 * improvement + 1 >= dropoff_age, counted before this generation's best is
 * looked at), else 1. */
static double neat_cpp_factor(const neat_pop *pop, const neat_species *s)
{
    return s->culled || s->cull_now || (uint64_t)s->since_improved + 2 >= pop->p.dropoff_age ? 0.01 : 1.0;
}

/* NEAT C++'s cull "for competitive coevolution" (Population::epoch): every
 * cull_every-th generation (the release counts them from 1) the last
 * species, in the order they were founded, that is at least cull_age
 * generations old (the release's ages start at 1), or the oldest species
 * if none is. The release picks it from a list sorted on a key that is 0
 * for every species at that point, which std::sort leaves in founding
 * order while there are at most 16 species; beyond that it permutes them,
 * which this does not copy. */
static void neat_cpp_cull(neat_pop *pop)
{
    uint32_t k;
    if (pop->p.cull_every == 0 || pop->n_species == 0 || (pop->generation + 1u) % pop->p.cull_every != 0)
        return;
    for (k = pop->n_species - 1; k > 0 && (uint64_t)pop->species[k].age + 1 < pop->p.cull_age; k--)
        ;
    pop->species[k].cull_now = 1; /* culled for good when the epoch commits (a refused epoch changes nothing) */
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
    if (pop->p.pop_stagnation_rule == NEAT_POPSTAG_TWO_BEST && pop->p.pop_stagnation > 0 &&
        *since_pop >= pop->p.pop_stagnation && pop->n_species > 2) {
        for (k = 0; k < pop->n_species; k++)
            pop->species[k].eligible = k == top0 || k == top1;
        *since_pop = 0;
        return;
    }
    if (pop->p.stagnation_rule == NEAT_STAGNATION_CPP)
        return; /* its penalties are in the shares (neat_apportion) */
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

/* NEAT_ROUND_SKIM, as NEAT C++'s Population::epoch and
 * Species::count_offspring: each genome is due its shared fitness over the
 * population's mean; the whole parts count, the fractions are carried from
 * genome to genome (species in founding order, members best first) and
 * each time they pass 1 the whole of them counts; a shortfall goes to the
 * species due the most (the last one on a tie), and should that not be
 * enough, every offspring goes to that species. scale: the power of two
 * the shares were scaled by. */
static uint32_t neat_skim(neat_pop *pop, double total, double scale)
{
    uint32_t k, i, n = pop->p.pop_size, given = 0, best = 0, most = 0;
    double mean = total / (double)n, skim = 0.0;
    for (k = 0; k < pop->n_species; k++) {
        neat_species *s = &pop->species[k];
        double factor = s->factor; /* every penalty its share got (neat_apportion) */
        s->offspring = 0;
        if (!s->eligible)
            continue;
        for (i = 0; i < s->n_members; i++) {
            double due = pop->genomes[s->members[i]].fitness * factor / (double)s->n_members * scale / mean;
            double whole = floor(due);
            s->offspring += (uint32_t)whole;
            skim += due - whole;
            if (skim > 1.0) {
                whole = floor(skim);
                s->offspring += (uint32_t)whole;
                skim -= whole;
            }
        }
        given += s->offspring;
    }
    if (given < n) {
        for (k = 0; k < pop->n_species; k++)
            if (pop->species[k].offspring >= most) {
                most = pop->species[k].offspring;
                best = k;
            }
        pop->species[best].offspring++;
        if (++given < n) {
            for (k = 0; k < pop->n_species; k++)
                pop->species[k].offspring = 0;
            pop->species[best].offspring = n;
            given = n;
        }
    }
    return given;
}

/* NEAT_POPSTAG_DELTA, as NEAT C++'s "delta coding": the best species (by
 * its champion; the older on a tie) gets half the offspring, the second
 * the rest, all as copies of their champions (neat_breed_super), and both
 * count as improved; with one species it gets them all (the release gives
 * it only the second half, and its population shrinks). */
static void neat_delta_coding(neat_pop *pop)
{
    uint32_t k, top0 = 0, top1 = UINT32_MAX, n = pop->p.pop_size;
    for (k = 1; k < pop->n_species; k++) {
        if (neat_champ_fitness(pop, k) > neat_champ_fitness(pop, top0)) {
            top1 = top0;
            top0 = k;
        } else if (top1 == UINT32_MAX || neat_champ_fitness(pop, k) > neat_champ_fitness(pop, top1)) {
            top1 = k;
        }
    }
    for (k = 0; k < pop->n_species; k++) {
        neat_species *s = &pop->species[k];
        s->offspring = k == top0 ? (top1 == UINT32_MAX ? n : n / 2) : (k == top1 ? n - n / 2 : 0);
        s->super = k == top0 || k == top1;
        if (s->super)
            s->next_since = 0;
    }
}

void neat_apportion(neat_pop *pop, uint32_t *since_pop)
{
    uint32_t k, given = 0, n_elig = 0, n = pop->p.pop_size;
    double total = 0.0, scale = 1.0;
    int cpp = pop->p.stagnation_rule == NEAT_STAGNATION_CPP;

    for (k = 0; k < pop->n_species; k++)
        pop->species[k].cull_now = 0;
    if (cpp)
        neat_cpp_cull(pop);
    for (k = 0; k < pop->n_species; k++) {
        pop->species[k].adj_sum = neat_shared_sum(pop, &pop->species[k]);
        pop->species[k].factor = pop->species[k].adj_sum; /* the raw sum, for the factor below */
        if (cpp)
            pop->species[k].adj_sum *= neat_cpp_factor(pop, &pop->species[k]);
        pop->species[k].super = 0;
    }
    neat_mark_eligible(pop, since_pop);
    /* each species' penalties as one factor (the release's rule, or the improvement rule's
     * stagnation_factor), for the per-genome shares of NEAT_ROUND_SKIM */
    for (k = 0; k < pop->n_species; k++) {
        neat_species *s = &pop->species[k];
        s->factor = s->factor > 0 ? s->adj_sum / s->factor : 1.0;
    }
    /* scaled by a power of two (exact) so the largest share is below 1:
     * n * share cannot overflow, whatever the magnitude of the fitness */
    {
        double top = 0.0;
        int e = 0;
        for (k = 0; k < pop->n_species; k++)
            if (pop->species[k].eligible && pop->species[k].adj_sum > top)
                top = pop->species[k].adj_sum;
        (void)frexp(top, &e);
        scale = ldexp(1.0, -e);
        for (k = 0; k < pop->n_species; k++)
            pop->species[k].adj_sum = ldexp(pop->species[k].adj_sum, -e);
    }
    for (k = 0; k < pop->n_species; k++)
        if (pop->species[k].eligible) {
            total += pop->species[k].adj_sum;
            n_elig++;
        }
    if (pop->p.offspring_rounding == NEAT_ROUND_SKIM && total > 0) {
        given = neat_skim(pop, total, scale);
    } else {
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
    }
    while (given > n) { /* floating rounding can only overshoot by a unit or so */
        for (k = pop->n_species; k-- > 0;)
            if (pop->species[k].offspring > 0 && given > n) {
                pop->species[k].offspring--;
                given--;
            }
    }
    if (pop->p.pop_stagnation_rule == NEAT_POPSTAG_DELTA && pop->p.pop_stagnation > 0 &&
        *since_pop >= pop->p.pop_stagnation && pop->n_species > 0) {
        neat_delta_coding(pop);
        *since_pop = 0;
    }
}

/* Where a species' parents come from this generation: its best `parents`
 * members and (NEAT_SPECIATE_INTERLEAVED) the children of earlier species
 * already placed in it, next[extra[0..n_extra-1]], as NEAT C++'s
 * Species::reproduce picks its parents from a list holding both; and the
 * species in order of their champions' fitness (for NEAT_INTER_CPP). */
typedef struct neat_pool {
    const neat_genome *next;
    const uint32_t *extra;
    uint32_t parents, n_extra;
    const uint32_t *by_champ;
} neat_pool;

static const neat_genome *neat_pool_pick(neat_pop *pop, const neat_species *s, const neat_pool *pool)
{
    uint32_t r = neat_rng_below_inl(&pop->rng, pool->parents + pool->n_extra);
    return r < pool->parents ? &pop->genomes[s->members[r]] : &pool->next[pool->extra[r - pool->parents]];
}

/* NEAT C++'s interspecies mate: up to 5 draws of a species from the
 * fitness order, at |N(0,1)| / 4 of the way down (a negative draw is the
 * best), until one is not k; its champion, or k's own if all 5 were k. */
static const neat_genome *neat_inter_cpp(neat_pop *pop, uint32_t k, const neat_pool *pool)
{
    uint32_t t, k2 = k, ns = pop->n_species;
    for (t = 0; t < 5 && k2 == k; t++) {
        double x = neat_rng_gauss(&pop->rng) / 4.0, at;
        if (x > 1.0)
            x = 1.0;
        at = floor(x * (double)(ns - 1) + 0.5);
        k2 = pool->by_champ[at > 0 ? (uint32_t)at : 0];
    }
    return &pop->genomes[pop->species[k2].members[0]];
}

/* crossover children are mutated unless mate_only_prob spares them, and
 * always when the parents are the same genome (NEAT_IDENTICAL_EQUAL: or
 * genetically identical, NEAT C++'s compatibility 0) */
static int neat_identical(const neat_params *p, const neat_genome *mom, const neat_genome *dad)
{
    return dad == mom || (p->identical_rule == NEAT_IDENTICAL_EQUAL && neat_genome_distance(mom, dad, p) == 0.0);
}

static int neat_breed_one(neat_pop *pop, uint32_t k, const neat_pool *pool, neat_genome *child)
{
    neat_species *s = &pop->species[k];
    const neat_params *p = &pop->p;
    const neat_genome *mom = neat_pool_pick(pop, s, pool);
    const neat_genome *dad;
    int err, avg;

    if (pool->parents + pool->n_extra == 1 || neat_rng_uniform_inl(&pop->rng) < p->mutate_only_prob) {
        err = neat_genome_copy(child, mom, &pop->a);
        child->has_fitness = 0;
        return err ? err : neat_mutate(child, p, &pop->rng, &pop->iv, &pop->a);
    }
    if (p->interspecies_rule == NEAT_INTER_CPP) {
        dad = neat_rng_uniform_inl(&pop->rng) < p->interspecies_prob ? neat_inter_cpp(pop, k, pool)
                                                                    : neat_pool_pick(pop, s, pool);
    } else if (pop->n_species > 1 && neat_rng_uniform_inl(&pop->rng) < p->interspecies_prob) {
        /* another species' champion */
        uint32_t k2 = neat_rng_below_inl(&pop->rng, pop->n_species - 1);
        if (k2 >= k)
            k2++;
        dad = &pop->genomes[pop->species[k2].members[0]];
    } else {
        dad = neat_pool_pick(pop, s, pool);
    }
    avg = neat_rng_uniform_inl(&pop->rng) < p->mate_avg_prob;
    err = neat_crossover(child, mom, dad, avg, p, &pop->rng, &pop->a);
    if (!err && (neat_identical(p, mom, dad) || !(neat_rng_uniform_inl(&pop->rng) < p->mate_only_prob)))
        err = neat_mutate(child, p, &pop->rng, &pop->iv, &pop->a);
    return err;
}

/* NEAT_POPSTAG_DELTA's offspring (NEAT C++'s "super champion" offspring):
 * copies of the champion, each but the last mutated, 80 % in its weights
 * (every time when add_conn_prob is 0) and otherwise by a new connection. */
static int neat_breed_super(neat_pop *pop, const neat_species *s, int last, neat_genome *child)
{
    const neat_params *p = &pop->p;
    int err = neat_genome_copy(child, &pop->genomes[s->members[0]], &pop->a);
    child->has_fitness = 0;
    if (err || last)
        return err;
    if (neat_rng_uniform_inl(&pop->rng) < 0.8 || p->add_conn_prob == 0.0 || p->mode != NEAT_MODE_COMPLEXIFY)
        return neat_mutate_weights(child, p, &pop->rng);
    return neat_mutate_add_conn(child, p, &pop->rng, &pop->iv, &pop->a);
}

int neat_reproduce(neat_pop *pop, neat_genome *next, neat_spec_plan *plan)
{
    uint32_t k, o, i, idx = 0, *extra = NULL, *by_champ = NULL;
    size_t extra_bytes = (size_t)pop->p.pop_size * sizeof(uint32_t);
    size_t champ_bytes = (size_t)pop->n_species * sizeof(uint32_t);
    neat_pool pool;
    int err = NEAT_OK;

    pool.next = next;
    pool.n_extra = 0;
    if (plan != NULL) {
        extra = (uint32_t *)neat_mem_realloc(&pop->a, NULL, 0, extra_bytes);
        if (extra == NULL)
            return NEAT_E_NOMEM;
    }
    pool.extra = extra;
    if (pop->p.interspecies_rule == NEAT_INTER_CPP && pop->n_species > 0) {
        /* the species by their champions' fitness, best first (the older on a tie) */
        by_champ = (uint32_t *)neat_mem_realloc(&pop->a, NULL, 0, champ_bytes);
        if (by_champ == NULL) {
            neat_mem_free(&pop->a, extra, extra_bytes);
            return NEAT_E_NOMEM;
        }
        for (k = 0; k < pop->n_species; k++) {
            uint32_t j = k;
            for (; j > 0 && neat_champ_fitness(pop, k) > neat_champ_fitness(pop, by_champ[j - 1]); j--)
                by_champ[j] = by_champ[j - 1];
            by_champ[j] = k;
        }
    }
    pool.by_champ = by_champ;
    for (k = 0; k < pop->n_species && !err; k++) {
        neat_species *s = &pop->species[k];
        /* survivors: as the C++ release, floor(fraction * size + 1) */
        uint32_t parents = (uint32_t)floor(pop->p.survival_fraction * s->n_members + 1.0);
        int elite;
        if (parents > s->n_members)
            parents = s->n_members;
        pool.parents = parents;
        if (plan != NULL) {
            /* the children of earlier species that joined this one, in birth order */
            pool.n_extra = 0;
            for (i = 0; i < idx; i++)
                if (plan->slot[i] == k)
                    extra[pool.n_extra++] = i;
        }
        if (pop->p.elitism_rule == NEAT_ELITE_BY_OFFSPRING)
            elite = s->offspring > pop->p.elitism_min_size;
        else
            elite = s->offspring > 0 && s->n_members > pop->p.elitism_min_size;
        for (o = 0; o < s->offspring && !err; o++) {
            if (s->super) {
                err = neat_breed_super(pop, s, o + 1 == s->offspring, &next[idx]);
            } else if (o == 0 && elite) {
                err = neat_genome_copy(&next[idx], &pop->genomes[s->members[0]], &pop->a);
                next[idx].has_fitness = 0;
            } else {
                err = neat_breed_one(pop, k, &pool, &next[idx]);
            }
            if (!err && plan != NULL) {
                /* unevaluated: as a later species' parent it counts fitness 0, as in the release
                 * (a copy would otherwise carry its parent's) */
                next[idx].fitness = 0.0;
                neat_speciate_place(pop, next, plan, idx);
            }
            idx++;
        }
    }
    neat_mem_free(&pop->a, extra, extra_bytes);
    neat_mem_free(&pop->a, by_champ, champ_bytes);
    return err;
}
