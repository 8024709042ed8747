/* test_reproduce.c - offspring apportionment (exact sums, fitness sharing), stagnation rules, elitism. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "neat_internal.h"

static neat_pop *make_pop(uint32_t n)
{
    neat_params p = neat_params_default();
    neat_pop *pop = NULL;
    p.pop_size = n;
    p.n_inputs = 1;
    p.n_outputs = 1;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 1, NULL), NEAT_OK);
    return pop;
}

/* replaces the species by n_species species of the given sizes, members in
 * index order (sizes sum to the population size) */
static void set_layout(neat_pop *pop, const uint32_t *sizes, uint32_t n_species)
{
    uint32_t k, i, idx = 0;
    for (k = 0; k < pop->n_species; k++)
        neat_species_free(&pop->species[k], &pop->a);
    pop->n_species = 0;
    assert_int_equal(neat_mem_reserve(&pop->a, (void **)&pop->species, &pop->cap_species, n_species,
                                      sizeof(neat_species)),
                     NEAT_OK);
    for (k = 0; k < n_species; k++) {
        neat_species *s = &pop->species[k];
        memset(s, 0, sizeof *s);
        s->id = 100 + k;
        assert_int_equal(neat_mem_reserve(&pop->a, (void **)&s->members, &s->cap_members, sizes[k], sizeof(uint32_t)),
                         NEAT_OK);
        for (i = 0; i < sizes[k]; i++) {
            pop->genomes[idx].species = s->id;
            s->members[s->n_members++] = idx++;
        }
        pop->n_species++;
    }
    assert_int_equal(idx, pop->p.pop_size);
}

static void set_fitness(neat_pop *pop, uint32_t i, double f)
{
    assert_int_equal(neat_pop_set_fitness(pop, i, f), NEAT_OK);
}

/* every member of species k the same fitness f */
static void set_species_fitness(neat_pop *pop, uint32_t k, double f)
{
    uint32_t m;
    for (m = 0; m < pop->species[k].n_members; m++)
        set_fitness(pop, pop->species[k].members[m], f);
}

static uint32_t offspring_sum(const neat_pop *pop)
{
    uint32_t k, sum = 0;
    for (k = 0; k < pop->n_species; k++)
        sum += pop->species[k].offspring;
    return sum;
}

/* ---- apportionment ---- */

static void test_apportion_sums_to_pop_size_property(void **state)
{
    /* 2000 random cases: population size, species layout, fitness shape,
     * ages and stagnation counters; the counts always sum to pop_size,
     * non-breeding species get none, and the breeding ones are within one
     * of their exact quota (Hamilton) */
    neat_rng rng;
    uint32_t c, n_cases = 2000;
    (void)state;
    neat_rng_seed(&rng, 2024);
    for (c = 0; c < n_cases; c++) {
        uint32_t n = 2 + neat_rng_below(&rng, 199), kind = c % 6, n_species, k, i, left, n_elig = 0;
        uint32_t sizes[16];
        double total = 0.0;
        neat_pop *pop = make_pop(n);
        /* layout: 1 .. min(n, 16) species (one species in every sixth
         * case), one member each, the rest spread at random or, in a third
         * of the cases, all into one species */
        n_species = kind == 5 ? 1 : 1 + neat_rng_below(&rng, n < 16 ? n : 16);
        for (k = 0; k < n_species; k++)
            sizes[k] = 1;
        left = n - n_species;
        if (neat_rng_below(&rng, 3) == 0)
            sizes[neat_rng_below(&rng, n_species)] += left;
        else
            for (i = 0; i < left; i++)
                sizes[neat_rng_below(&rng, n_species)]++;
        set_layout(pop, sizes, n_species);
        for (i = 0; i < n; i++) {
            double f;
            switch (kind) {
            case 0: f = 0.0; break;                                      /* all zero */
            case 1: f = 10.0 * neat_rng_uniform(&rng); break;            /* uniform */
            case 2: f = neat_rng_below(&rng, 2) ? 0.0 : neat_rng_uniform(&rng); break; /* half zero */
            case 3: f = pow(10.0, 12.0 * neat_rng_uniform(&rng) - 6.0); break; /* 1e-6 .. 1e6 */
            case 4: f = (double)neat_rng_below(&rng, 3); break;          /* many ties */
            default: f = neat_rng_uniform(&rng); break;
            }
            set_fitness(pop, i, f);
        }
        neat_species_rank(pop);
        for (k = 0; k < n_species; k++)
            pop->species[k].age = neat_rng_below(&rng, 40);
        for (k = 0; k < n_species; k++)
            pop->species[k].next_since = neat_rng_below(&rng, 40);
        pop->p.dropoff_age = neat_rng_below(&rng, 40);
        pop->p.stagnation_rule = (int)neat_rng_below(&rng, 2);
        pop->p.stagnation_factor = neat_rng_below(&rng, 2) ? 0.0 : neat_rng_uniform(&rng);
        pop->p.pop_stagnation = neat_rng_below(&rng, 4);
        pop->since_pop_improved = neat_rng_below(&rng, 5);
        neat_apportion(pop, &pop->since_pop_improved);
        assert_int_equal(offspring_sum(pop), n);
        for (k = 0; k < n_species; k++) {
            assert_true(pop->species[k].offspring <= n);
            if (!pop->species[k].eligible)
                assert_int_equal(pop->species[k].offspring, 0);
            else {
                n_elig++;
                total += pop->species[k].adj_sum;
            }
        }
        assert_true(n_elig >= 1);
        for (k = 0; k < n_species; k++) {
            double q;
            if (!pop->species[k].eligible)
                continue;
            q = total > 0 ? (double)n * pop->species[k].adj_sum / total : (double)n / n_elig;
            if (!(fabs(pop->species[k].offspring - q) < 1.0 + 1e-9))
                fail_msg("case %u: species %u got %u, quota %.6f", c, k, pop->species[k].offspring, q);
        }
        neat_pop_free(pop);
    }
}

static void test_apportion_proportional_to_mean_fitness(void **state)
{
    static const uint32_t sizes[2] = {50, 50};
    neat_pop *pop = make_pop(100);
    (void)state;
    set_layout(pop, sizes, 2);
    set_species_fitness(pop, 0, 3.0);
    set_species_fitness(pop, 1, 1.0);
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 75);
    assert_int_equal(pop->species[1].offspring, 25);
    neat_pop_free(pop);
}

static void test_apportion_shares_fitness_by_size(void **state)
{
    /* explicit fitness sharing: a big species of equally fit genomes gets
     * no more than a small one */
    static const uint32_t sizes[2] = {20, 80};
    neat_pop *pop = make_pop(100);
    (void)state;
    set_layout(pop, sizes, 2);
    set_species_fitness(pop, 0, 2.0);
    set_species_fitness(pop, 1, 2.0);
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 50);
    assert_int_equal(pop->species[1].offspring, 50);
    neat_pop_free(pop);
}

static void test_apportion_largest_remainder(void **state)
{
    /* quotas 10 * 1/3 and 10 * 2/3: 3.33 and 6.67 -> 3 and 7 */
    static const uint32_t sizes[2] = {5, 5};
    neat_pop *pop = make_pop(10);
    (void)state;
    set_layout(pop, sizes, 2);
    set_species_fitness(pop, 0, 1.0);
    set_species_fitness(pop, 1, 2.0);
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 3);
    assert_int_equal(pop->species[1].offspring, 7);
    neat_pop_free(pop);
}

static void test_apportion_all_zero_fitness_equal(void **state)
{
    static const uint32_t sizes[3] = {1, 5, 6};
    neat_pop *pop = make_pop(12);
    uint32_t k;
    (void)state;
    set_layout(pop, sizes, 3);
    for (k = 0; k < 3; k++)
        set_species_fitness(pop, k, 0.0);
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    for (k = 0; k < 3; k++)
        assert_int_equal(pop->species[k].offspring, 4);
    neat_pop_free(pop);
}

static void test_apportion_one_species_gets_all(void **state)
{
    static const uint32_t sizes[1] = {17};
    neat_pop *pop = make_pop(17);
    (void)state;
    set_layout(pop, sizes, 1);
    set_species_fitness(pop, 0, 0.5);
    neat_species_rank(pop);
    pop->species[0].age = 1000; /* old and the lowest: still the last */
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 17);
    neat_pop_free(pop);
}

static void test_apportion_huge_fitness_still_proportional(void **state)
{
    /* fitness values anywhere in the finite range are legal; the quota
     * n * adj / total must not overflow to infinity. Species A (mean 1e306)
     * should get essentially all 200 offspring, B (mean 1e300) none.
     * (n * adj_sum would overflow for adj_sum > DBL_MAX / n, so
     * neat_apportion scales the shares by a power of two first.) */
    static const uint32_t sizes[2] = {100, 100};
    neat_pop *pop = make_pop(200);
    uint32_t sum, a;
    (void)state;
    set_layout(pop, sizes, 2);
    set_species_fitness(pop, 0, 1e306);
    set_species_fitness(pop, 1, 1e300);
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    sum = offspring_sum(pop);
    a = pop->species[0].offspring;
    neat_pop_free(pop);
    assert_int_equal(sum, 200);
    if (a < 199)
        fail_msg("species A (mean 1e306) got %u of 200 offspring, B (mean 1e300) %u", a, 200 - a);
}

/* ---- stagnation ---- */

/* three species of 10, all older than dropoff_age (30): means A 3, B 1, C 2 */
static neat_pop *three_old_species(void)
{
    static const uint32_t sizes[3] = {10, 10, 10};
    neat_pop *pop = make_pop(30);
    uint32_t k;
    set_layout(pop, sizes, 3);
    set_species_fitness(pop, 0, 3.0);
    set_species_fitness(pop, 1, 1.0);
    set_species_fitness(pop, 2, 2.0);
    for (k = 0; k < 3; k++)
        pop->species[k].age = 31;
    pop->p.dropoff_age = 30;
    pop->p.pop_stagnation = 0;
    return pop;
}

static void test_dropoff_lowest_old_species_cut(void **state)
{
    neat_pop *pop = three_old_species();
    (void)state;
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[1].offspring, 0);
    assert_int_equal(pop->species[1].eligible, 0);
    assert_true(pop->species[0].offspring > 0);
    assert_true(pop->species[2].offspring > 0);
    /* the others share by mean: 30 * 3/5 and 30 * 2/5 */
    assert_int_equal(pop->species[0].offspring, 18);
    assert_int_equal(pop->species[2].offspring, 12);
    neat_pop_free(pop);
}

static void test_dropoff_spares_young_species(void **state)
{
    /* B is exactly dropoff_age old: not "older than", so it breeds, and C
     * (the lowest of the old ones) is cut instead */
    neat_pop *pop = three_old_species();
    (void)state;
    pop->species[1].age = 30;
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_true(pop->species[1].offspring > 0);
    assert_int_equal(pop->species[2].offspring, 0);
    assert_int_equal(offspring_sum(pop), 30);
    neat_pop_free(pop);
}

static void test_dropoff_spares_species_with_best_genome(void **state)
{
    /* B's mean is the lowest (0.5) but it holds the best genome (5): it
     * breeds; C is the lowest of the rest and is cut */
    neat_pop *pop = three_old_species();
    (void)state;
    set_species_fitness(pop, 1, 0.0);
    set_fitness(pop, pop->species[1].members[3], 5.0);
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_true(pop->species[1].offspring > 0);
    assert_int_equal(pop->species[2].offspring, 0);
    assert_int_equal(offspring_sum(pop), 30);
    neat_pop_free(pop);
}

static void test_dropoff_two_old_species_lower_cut(void **state)
{
    /* two old species: the lower (B) is cut, A has every offspring */
    static const uint32_t sizes[2] = {10, 20};
    neat_pop *pop = make_pop(30);
    (void)state;
    set_layout(pop, sizes, 2);
    set_species_fitness(pop, 0, 4.0);
    set_species_fitness(pop, 1, 1.0);
    pop->species[0].age = 100;
    pop->species[1].age = 100;
    pop->p.dropoff_age = 30;
    pop->p.pop_stagnation = 0;
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 30);
    assert_int_equal(pop->species[1].offspring, 0);
    neat_pop_free(pop);
}

static void test_dropoff_one_old_species_breeds(void **state)
{
    /* the last breeding species is never cut, however old and poor */
    static const uint32_t sizes[1] = {30};
    neat_pop *pop = make_pop(30);
    (void)state;
    set_layout(pop, sizes, 1);
    set_species_fitness(pop, 0, 1.0);
    pop->species[0].age = 100;
    pop->p.dropoff_age = 30;
    neat_species_rank(pop);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 30);
    neat_pop_free(pop);
}

static void test_improvement_rule_cuts_stagnant_species(void **state)
{
    /* NEAT_STAGNATION_IMPROVEMENT, factor 0: a species not improved for
     * dropoff_age generations stops breeding, unless it holds the best */
    neat_pop *pop = three_old_species();
    (void)state;
    pop->p.stagnation_rule = NEAT_STAGNATION_IMPROVEMENT;
    pop->p.stagnation_factor = 0.0;
    pop->p.dropoff_age = 10;
    neat_species_rank(pop);
    pop->species[0].next_since = 50; /* holds the best (3) */
    pop->species[1].next_since = 9;  /* one short */
    pop->species[2].next_since = 10;
    neat_apportion(pop, &pop->since_pop_improved);
    assert_true(pop->species[0].offspring > 0);
    assert_true(pop->species[1].offspring > 0);
    assert_int_equal(pop->species[2].offspring, 0);
    /* A and B share by mean: 30 * 3/4 and 30 * 1/4 */
    assert_int_equal(pop->species[0].offspring, 23);
    assert_int_equal(pop->species[1].offspring, 7);
    neat_pop_free(pop);
}

static void test_improvement_rule_factor_scales_share(void **state)
{
    /* factor 0.5: C's (mean 2, stagnant) share counts as 1: 3 : 1 : 1 */
    neat_pop *pop = three_old_species();
    (void)state;
    set_species_fitness(pop, 1, 1.0);
    set_species_fitness(pop, 2, 2.0);
    pop->p.stagnation_rule = NEAT_STAGNATION_IMPROVEMENT;
    pop->p.stagnation_factor = 0.5;
    pop->p.dropoff_age = 10;
    neat_species_rank(pop);
    pop->species[2].next_since = 10;
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 18);
    assert_int_equal(pop->species[1].offspring, 6);
    assert_int_equal(pop->species[2].offspring, 6);
    neat_pop_free(pop);
}

/* four young species of 10 with champions (and means) c[0..3] */
static neat_pop *four_species(const double *c, uint32_t since, uint32_t stagnation)
{
    static const uint32_t sizes[4] = {10, 10, 10, 10};
    neat_pop *pop = make_pop(40);
    uint32_t k;
    set_layout(pop, sizes, 4);
    for (k = 0; k < 4; k++)
        set_species_fitness(pop, k, c[k]);
    pop->p.pop_stagnation = stagnation;
    pop->since_pop_improved = since;
    neat_species_rank(pop);
    return pop;
}

static void test_pop_stagnation_two_best_breed(void **state)
{
    static const double c1[4] = {4.0, 3.0, 2.0, 1.0}, c2[4] = {2.0, 1.0, 4.0, 3.0};
    neat_pop *pop;
    (void)state;
    pop = four_species(c1, 5, 5);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring + pop->species[1].offspring, 40);
    assert_int_equal(pop->species[2].offspring, 0);
    assert_int_equal(pop->species[3].offspring, 0);
    assert_int_equal(pop->species[0].offspring, 23); /* 40 * 4/7 = 22.86 */
    /* the counter starts again */
    assert_int_equal(pop->since_pop_improved, 0);
    neat_pop_free(pop);
    /* best two found wherever they are in the list */
    pop = four_species(c2, 9, 5);
    neat_apportion(pop, &pop->since_pop_improved);
    assert_int_equal(pop->species[0].offspring, 0);
    assert_int_equal(pop->species[1].offspring, 0);
    assert_int_equal(pop->species[2].offspring + pop->species[3].offspring, 40);
    assert_true(pop->species[3].offspring > 0);
    neat_pop_free(pop);
}

/* The two best breed even when every species is old or stagnant: the
 * species rules must not then bar the second of them (with only two
 * eligible, the oldest-worst rule used to take the second away, and the
 * improvement rule any but the best). */
static void test_pop_stagnation_old_species(void **state)
{
    static const double c[4] = {4.0, 3.0, 2.0, 1.0};
    neat_pop *pop;
    uint32_t k, rule;
    (void)state;
    for (rule = 0; rule < 2; rule++) {
        pop = four_species(c, 5, 5);
        pop->p.stagnation_rule = rule == 0 ? NEAT_STAGNATION_OLDEST_WORST : NEAT_STAGNATION_IMPROVEMENT;
        pop->p.dropoff_age = 30;
        for (k = 0; k < 4; k++) {
            pop->species[k].age = 31 + k;
            pop->species[k].next_since = 40;
        }
        neat_apportion(pop, &pop->since_pop_improved);
        assert_true(pop->species[0].offspring > 0);
        assert_true(pop->species[1].offspring > 0);
        assert_int_equal(pop->species[0].offspring + pop->species[1].offspring, 40);
        neat_pop_free(pop);
    }
}

static void test_pop_stagnation_not_yet(void **state)
{
    static const double c[4] = {4.0, 3.0, 2.0, 1.0};
    neat_pop *pop;
    uint32_t k;
    (void)state;
    /* one generation short */
    pop = four_species(c, 4, 5);
    neat_apportion(pop, &pop->since_pop_improved);
    for (k = 0; k < 4; k++)
        assert_true(pop->species[k].offspring > 0);
    assert_int_equal(pop->since_pop_improved, 4);
    neat_pop_free(pop);
    /* 0 disables the rule */
    pop = four_species(c, 1000, 0);
    neat_apportion(pop, &pop->since_pop_improved);
    for (k = 0; k < 4; k++)
        assert_true(pop->species[k].offspring > 0);
    neat_pop_free(pop);
}

/* ---- elitism ---- */

static int genome_equal(const neat_genome *a, const neat_genome *b)
{
    uint32_t i;
    if (a->n_nodes != b->n_nodes || a->n_conns != b->n_conns)
        return 0;
    for (i = 0; i < a->n_nodes; i++)
        if (a->nodes[i].id != b->nodes[i].id || a->nodes[i].type != b->nodes[i].type)
            return 0;
    for (i = 0; i < a->n_conns; i++)
        if (a->conns[i].in != b->conns[i].in || a->conns[i].out != b->conns[i].out ||
            a->conns[i].innov != b->conns[i].innov || a->conns[i].enabled != b->conns[i].enabled ||
            memcmp(&a->conns[i].weight, &b->conns[i].weight, sizeof(double)) != 0)
            return 0;
    return 1;
}

/* a toy fitness in [1, 2): prefers weights summing to 1 */
static double toy_fitness(const neat_genome *g)
{
    double s = 0.0;
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].enabled)
            s += g->conns[i].weight;
    return 1.0 + 1.0 / (1.0 + fabs(s - 1.0));
}

static void test_elitism_champions_copied_unchanged(void **state)
{
    neat_params p = neat_params_default();
    neat_pop *pop = NULL;
    neat_genome champs[64];
    uint32_t gen, i, k, n_champs, checked = 0;
    (void)state;
    p.pop_size = 100;
    p.n_inputs = 2;
    p.n_outputs = 1;
    p.dropoff_age = 1000; /* no species cut: every one breeds */
    p.pop_stagnation = 0;
    p.add_node_prob = 0.05;
    p.add_conn_prob = 0.2;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 99, NULL), NEAT_OK);
    for (gen = 0; gen < 8; gen++) {
        for (i = 0; i < p.pop_size; i++)
            assert_int_equal(neat_pop_set_fitness(pop, i, toy_fitness(neat_pop_genome(pop, i))), NEAT_OK);
        /* the champion of each species of more than elitism_min_size:
         * highest fitness, lowest index on ties */
        n_champs = 0;
        for (k = 0; k < pop->n_species; k++) {
            const neat_species *s = &pop->species[k];
            uint32_t m, best;
            if (s->n_members <= p.elitism_min_size)
                continue;
            best = s->members[0];
            for (m = 1; m < s->n_members; m++) {
                uint32_t x = s->members[m];
                double fx = pop->genomes[x].fitness, fb = pop->genomes[best].fitness;
                if (fx > fb || (fx == fb && x < best))
                    best = x;
            }
            assert_true(n_champs < 64);
            neat_genome_init(&champs[n_champs]);
            assert_int_equal(neat_genome_copy(&champs[n_champs], &pop->genomes[best], NULL), NEAT_OK);
            n_champs++;
        }
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
        for (k = 0; k < n_champs; k++) {
            int found = 0;
            for (i = 0; i < p.pop_size && !found; i++)
                found = genome_equal(&champs[k], neat_pop_genome(pop, i));
            if (!found)
                fail_msg("generation %u: champion %u not copied", gen, k);
            checked++;
            neat_genome_free(&champs[k], NULL);
        }
    }
    /* the test saw real champions */
    assert_true(checked >= 8);
    neat_pop_free(pop);
}

/* one species of n genomes, fitness 1 + i, every offspring mutate-only with
 * all weights mutated: only an elite copy can survive unchanged. Returns how
 * many of the new genomes equal an old one (and which old one in *which). */
static uint32_t unchanged_after_epoch(uint32_t n, uint32_t *which)
{
    neat_params p = neat_params_default();
    neat_pop *pop = NULL;
    neat_genome before[8];
    uint32_t i, j, same = 0;
    p.pop_size = n;
    p.n_inputs = 2;
    p.n_outputs = 1;
    p.delta_t = 100.0;
    p.target_species = 0;
    p.mutate_only_prob = 1.0;
    p.weight_mut_prob = 1.0;
    p.add_conn_prob = 0.0;
    p.add_node_prob = 0.0;
    assert_true(n <= 8);
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 5, NULL), NEAT_OK);
    assert_int_equal(neat_pop_species_count(pop), 1);
    for (i = 0; i < n; i++) {
        neat_genome_init(&before[i]);
        assert_int_equal(neat_genome_copy(&before[i], neat_pop_genome(pop, i), NULL), NEAT_OK);
        assert_int_equal(neat_pop_set_fitness(pop, i, 1.0 + i), NEAT_OK);
    }
    assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++)
            if (genome_equal(&before[j], neat_pop_genome(pop, i))) {
                same++;
                *which = j;
            }
    for (i = 0; i < n; i++)
        neat_genome_free(&before[i], NULL);
    neat_pop_free(pop);
    return same;
}

static void test_elitism_needs_more_than_min_size(void **state)
{
    /* 5 members (elitism_min_size): no elite, every genome changes */
    uint32_t which = 99;
    (void)state;
    assert_int_equal(unchanged_after_epoch(5, &which), 0);
}

static void test_elitism_six_members_keeps_champion(void **state)
{
    /* 6 members: exactly the champion (index 5, fitness 6) survives */
    uint32_t which = 99;
    (void)state;
    assert_int_equal(unchanged_after_epoch(6, &which), 1);
    assert_int_equal(which, 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_apportion_sums_to_pop_size_property),
        cmocka_unit_test(test_apportion_proportional_to_mean_fitness),
        cmocka_unit_test(test_apportion_shares_fitness_by_size),
        cmocka_unit_test(test_apportion_largest_remainder),
        cmocka_unit_test(test_apportion_all_zero_fitness_equal),
        cmocka_unit_test(test_apportion_one_species_gets_all),
        cmocka_unit_test(test_apportion_huge_fitness_still_proportional),
        cmocka_unit_test(test_dropoff_lowest_old_species_cut),
        cmocka_unit_test(test_dropoff_spares_young_species),
        cmocka_unit_test(test_dropoff_spares_species_with_best_genome),
        cmocka_unit_test(test_dropoff_two_old_species_lower_cut),
        cmocka_unit_test(test_dropoff_one_old_species_breeds),
        cmocka_unit_test(test_improvement_rule_cuts_stagnant_species),
        cmocka_unit_test(test_improvement_rule_factor_scales_share),
        cmocka_unit_test(test_pop_stagnation_two_best_breed),
        cmocka_unit_test(test_pop_stagnation_not_yet),
        cmocka_unit_test(test_pop_stagnation_old_species),
        cmocka_unit_test(test_elitism_champions_copied_unchanged),
        cmocka_unit_test(test_elitism_needs_more_than_min_size),
        cmocka_unit_test(test_elitism_six_members_keeps_champion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
