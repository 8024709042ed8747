/* test_species.c - speciation: first compatible species, new species for far genomes, dynamic threshold, dead species. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "neat_internal.h"

#define assert_near(a, b, eps)                                                                                        \
    do {                                                                                                              \
        double got_ = (a), want_ = (b);                                                                               \
        if (!(fabs(got_ - want_) <= (eps)))                                                                           \
            fail_msg("%s = %.17g, expected %.17g", #a, got_, want_);                                                  \
    } while (0)

/* n genomes of 1 input, 1 output: two genes each, so with c3 = 2 and equal
 * weights w on both genes, delta(a, b) = 2 |w_a - w_b| */
static neat_pop *make_pop(uint32_t n, double delta_t, uint32_t target)
{
    neat_params p = neat_params_default();
    neat_pop *pop = NULL;
    p.pop_size = n;
    p.n_inputs = 1;
    p.n_outputs = 1;
    p.delta_t = delta_t;
    p.target_species = target;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 1, NULL), NEAT_OK);
    return pop;
}

static void set_weight(neat_pop *pop, uint32_t i, double w)
{
    uint32_t k;
    for (k = 0; k < pop->genomes[i].n_conns; k++)
        pop->genomes[i].conns[k].weight = w;
}

/* forget every species (as before the first generation) */
static void clear_species(neat_pop *pop)
{
    uint32_t k;
    for (k = 0; k < pop->n_species; k++)
        neat_species_free(&pop->species[k], &pop->a);
    pop->n_species = 0;
}

static void speciate_weights(neat_pop *pop, const double *w)
{
    uint32_t i;
    for (i = 0; i < pop->p.pop_size; i++)
        set_weight(pop, i, w[i]);
    assert_int_equal(neat_speciate(pop), NEAT_OK);
}

static void assert_members(const neat_pop *pop, uint32_t k, const uint32_t *want, uint32_t n)
{
    uint32_t i;
    assert_true(k < pop->n_species);
    assert_int_equal(pop->species[k].n_members, n);
    for (i = 0; i < n; i++) {
        assert_int_equal(pop->species[k].members[i], want[i]);
        assert_int_equal(pop->genomes[want[i]].species, pop->species[k].id);
    }
}

/* weights 0, 0.1, 0.8, 0.45, 0.85, 3.0 under delta_t 1:
 *   g0 founds A; g1 is 0.2 from A; g2 is 1.6 from A: founds B;
 *   g3 is 0.9 from A (and 0.7 from B): joins A, the first compatible;
 *   g4 is 1.7 from A, 0.1 from B: joins B; g5 is far from both: founds C */
static const double layout6[6] = {0.0, 0.1, 0.8, 0.45, 0.85, 3.0};

static void test_first_compatible_species(void **state)
{
    static const uint32_t a[] = {0, 1, 3}, b[] = {2, 4}, c[] = {5};
    neat_pop *pop = make_pop(6, 1.0, 0);
    (void)state;
    clear_species(pop);
    speciate_weights(pop, layout6);
    assert_int_equal(pop->n_species, 3);
    assert_members(pop, 0, a, 3);
    assert_members(pop, 1, b, 2);
    assert_members(pop, 2, c, 1);
    /* new species get fresh, increasing ids */
    assert_true(pop->species[0].id < pop->species[1].id);
    assert_true(pop->species[1].id < pop->species[2].id);
    assert_int_equal(neat_pop_species_count(pop), 3);
    neat_pop_free(pop);
}

static void test_founder_is_representative(void **state)
{
    neat_pop *pop = make_pop(6, 1.0, 0);
    (void)state;
    clear_species(pop);
    speciate_weights(pop, layout6);
    assert_true(pop->species[0].rep.conns[0].weight == 0.0);
    assert_true(pop->species[1].rep.conns[0].weight == 0.8);
    assert_true(pop->species[2].rep.conns[0].weight == 3.0);
    /* a copy, not the genome itself */
    assert_true(pop->species[0].rep.conns != pop->genomes[0].conns);
    neat_pop_free(pop);
}

static void test_far_genome_founds_new_species(void **state)
{
    static const double w[5] = {0.2, 0.2, 0.2, 5.0, 0.2};
    static const uint32_t near[] = {0, 1, 2, 4}, far[] = {3};
    neat_pop *pop = make_pop(5, 1.0, 0);
    (void)state;
    clear_species(pop);
    speciate_weights(pop, w);
    assert_int_equal(pop->n_species, 2);
    assert_members(pop, 0, near, 4);
    assert_members(pop, 1, far, 1);
    neat_pop_free(pop);
}

static void test_existing_species_checked_oldest_first(void **state)
{
    /* next generation, every genome at 0.4: 0.8 from A's representative
     * and 0.8 from B's, both compatible: all join A, the older */
    static const double w1[6] = {0.4, 0.4, 0.4, 0.4, 0.4, 0.4};
    static const uint32_t all[] = {0, 1, 2, 3, 4, 5};
    neat_pop *pop = make_pop(6, 1.0, 0);
    uint32_t id_a;
    (void)state;
    clear_species(pop);
    speciate_weights(pop, layout6);
    id_a = pop->species[0].id;
    speciate_weights(pop, w1);
    assert_int_equal(pop->n_species, 1);
    assert_int_equal(pop->species[0].id, id_a);
    assert_members(pop, 0, all, 6);
    neat_pop_free(pop);
}

static void test_empty_species_removed(void **state)
{
    /* next generation all near B's representative (0.8): A and C die out,
     * B survives with its id, age and representative */
    static const double w1[6] = {0.85, 0.9, 0.75, 0.8, 0.7, 0.82};
    neat_pop *pop = make_pop(6, 1.0, 0);
    uint32_t id_b, i;
    (void)state;
    clear_species(pop);
    speciate_weights(pop, layout6);
    id_b = pop->species[1].id;
    pop->species[1].age = 7;
    speciate_weights(pop, w1);
    assert_int_equal(pop->n_species, 1);
    assert_int_equal(pop->species[0].id, id_b);
    assert_int_equal(pop->species[0].age, 7);
    assert_int_equal(pop->species[0].n_members, 6);
    for (i = 0; i < 6; i++)
        assert_int_equal(pop->genomes[i].species, id_b);
    /* a new far genome next time founds a new species with a new id */
    set_weight(pop, 5, -4.0);
    assert_int_equal(neat_speciate(pop), NEAT_OK);
    assert_int_equal(pop->n_species, 2);
    assert_true(pop->species[1].id > id_b);
    neat_pop_free(pop);
}

static void test_middle_species_removed_keeps_order(void **state)
{
    static const double w1[6] = {0.0, 3.0, 0.1, 3.1, 0.2, 2.9};
    neat_pop *pop = make_pop(6, 1.0, 0);
    uint32_t id_a, id_c;
    (void)state;
    clear_species(pop);
    speciate_weights(pop, layout6);
    id_a = pop->species[0].id;
    id_c = pop->species[2].id;
    speciate_weights(pop, w1);
    assert_int_equal(pop->n_species, 2);
    assert_int_equal(pop->species[0].id, id_a);
    assert_int_equal(pop->species[1].id, id_c);
    assert_int_equal(pop->species[0].n_members, 3);
    assert_int_equal(pop->species[1].n_members, 3);
    neat_pop_free(pop);
}

static void test_speciation_invariants_random(void **state)
{
    /* random weights, several thresholds: every genome in exactly one
     * species, closer than delta_t to its representative, and not
     * compatible with any species before its own */
    static const double thresholds[] = {0.3, 1.0, 2.0, 3.0};
    uint32_t t, seed, i, k, m;
    (void)state;
    for (t = 0; t < 4; t++)
        for (seed = 0; seed < 5; seed++) {
            neat_pop *pop = make_pop(60, thresholds[t], 0);
            neat_rng rng;
            uint8_t seen[60] = {0};
            neat_rng_seed(&rng, seed);
            for (i = 0; i < 60; i++)
                neat_genome_randomize(&pop->genomes[i], &rng, 2.0);
            assert_int_equal(neat_speciate(pop), NEAT_OK);
            for (k = 0; k < pop->n_species; k++) {
                const neat_species *s = &pop->species[k];
                assert_true(s->n_members > 0);
                for (m = 0; m < s->n_members; m++) {
                    uint32_t j, g = s->members[m];
                    assert_true(g < 60);
                    assert_int_equal(seen[g], 0);
                    seen[g] = 1;
                    assert_int_equal(pop->genomes[g].species, s->id);
                    assert_true(neat_genome_distance(&pop->genomes[g], &s->rep, &pop->p) < pop->delta_t);
                    for (j = 0; j < k; j++)
                        assert_true(neat_genome_distance(&pop->genomes[g], &pop->species[j].rep, &pop->p) >=
                                    pop->delta_t);
                }
            }
            for (i = 0; i < 60; i++)
                assert_int_equal(seen[i], 1);
            assert_true(pop->n_species >= 1);
            neat_pop_free(pop);
        }
}

static void test_delta_t_up_when_too_many(void **state)
{
    neat_pop *pop = make_pop(6, 1.0, 2);
    (void)state;
    clear_species(pop);
    pop->delta_t = 1.0;
    speciate_weights(pop, layout6);
    /* assigned with the old threshold, then moved: 3 > 2 */
    assert_int_equal(pop->n_species, 3);
    assert_near(neat_pop_next_delta_t(pop), 1.3, 1e-12);
    neat_pop_free(pop);
}

static void test_delta_t_down_when_too_few(void **state)
{
    neat_pop *pop = make_pop(6, 1.0, 5);
    (void)state;
    clear_species(pop);
    pop->delta_t = 1.0;
    speciate_weights(pop, layout6);
    assert_int_equal(pop->n_species, 3);
    assert_near(neat_pop_next_delta_t(pop), 0.7, 1e-12);
    neat_pop_free(pop);
}

static void test_delta_t_kept_at_target(void **state)
{
    neat_pop *pop = make_pop(6, 1.0, 3);
    (void)state;
    clear_species(pop);
    pop->delta_t = 1.0;
    speciate_weights(pop, layout6);
    assert_int_equal(pop->n_species, 3);
    assert_true(neat_pop_next_delta_t(pop) == 1.0);
    neat_pop_free(pop);
}

static void test_delta_t_fixed_without_target(void **state)
{
    neat_pop *pop = make_pop(6, 1.0, 0);
    (void)state;
    clear_species(pop);
    pop->delta_t = 1.0;
    speciate_weights(pop, layout6);
    assert_true(neat_pop_next_delta_t(pop) == 1.0);
    neat_pop_free(pop);
}

static void test_delta_t_step_and_floor(void **state)
{
    /* one species, target 10: down by delta_t_step each generation, never
     * below delta_t_min */
    static const double same[6] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    neat_pop *pop = make_pop(6, 3.0, 10);
    int g;
    (void)state;
    pop->p.delta_t_step = 0.3;
    pop->p.delta_t_min = 0.5;
    pop->delta_t = 3.0;
    clear_species(pop);
    for (g = 1; g <= 8; g++) {
        speciate_weights(pop, same);
        assert_int_equal(pop->n_species, 1);
        assert_near(neat_pop_next_delta_t(pop), 3.0 - 0.3 * g, 1e-9);
    }
    for (g = 0; g < 5; g++) {
        speciate_weights(pop, same);
        assert_true(neat_pop_next_delta_t(pop) == 0.5);
    }
    neat_pop_free(pop);
}

static void test_delta_t_floor_on_single_step(void **state)
{
    neat_pop *pop = make_pop(6, 1.0, 5);
    (void)state;
    pop->p.delta_t_min = 0.9;
    clear_species(pop);
    pop->delta_t = 1.0;
    speciate_weights(pop, layout6);
    assert_true(neat_pop_next_delta_t(pop) == 0.9);
    neat_pop_free(pop);
}

/* what neat_pop_epoch does with the statistics neat_species_rank computes */
static void rank_and_commit(neat_pop *pop)
{
    uint32_t k;
    neat_species_rank(pop);
    for (k = 0; k < pop->n_species; k++) {
        pop->species[k].best_fitness = pop->species[k].next_best;
        pop->species[k].since_improved = pop->species[k].next_since;
    }
}

static void test_rank_best_first(void **state)
{
    static const double fit[6] = {1.0, 4.0, 2.0, 4.0, 0.0, 9.0};
    neat_pop *pop = make_pop(6, 1.0, 0);
    uint32_t i;
    (void)state;
    clear_species(pop);
    speciate_weights(pop, layout6);
    for (i = 0; i < 6; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, fit[i]), NEAT_OK);
    neat_species_rank(pop);
    /* A = {0, 1, 3}: 1 and 3 tie at 4 (lower index first), then 0 */
    assert_int_equal(pop->species[0].members[0], 1);
    assert_int_equal(pop->species[0].members[1], 3);
    assert_int_equal(pop->species[0].members[2], 0);
    /* B = {2, 4} */
    assert_int_equal(pop->species[1].members[0], 2);
    assert_int_equal(pop->species[1].members[1], 4);
    /* the statistics wait in next_best until the epoch commits */
    assert_true(pop->species[0].next_best == 4.0);
    assert_true(pop->species[2].next_best == 9.0);
    neat_pop_free(pop);
}

static void test_rank_counts_stagnation(void **state)
{
    neat_pop *pop = make_pop(6, 1.0, 0);
    neat_species_info info;
    uint32_t i;
    (void)state;
    clear_species(pop);
    speciate_weights(pop, layout6);
    for (i = 0; i < 6; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, 1.0), NEAT_OK);
    rank_and_commit(pop);
    pop->species[0].age = 1;
    /* no better: since_improved counts up */
    rank_and_commit(pop);
    rank_and_commit(pop);
    assert_int_equal(neat_pop_species(pop, 0, &info), NEAT_OK);
    assert_int_equal(info.since_improved, 2);
    assert_true(info.best_fitness == 1.0);
    assert_int_equal(info.size, 3);
    /* better: back to 0, new best */
    assert_int_equal(neat_pop_set_fitness(pop, 3, 1.5), NEAT_OK);
    rank_and_commit(pop);
    assert_int_equal(neat_pop_species(pop, 0, &info), NEAT_OK);
    assert_int_equal(info.since_improved, 0);
    assert_true(info.best_fitness == 1.5);
    assert_int_equal(neat_pop_species(pop, 3, &info), NEAT_E_ARG);
    neat_pop_free(pop);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_compatible_species),
        cmocka_unit_test(test_founder_is_representative),
        cmocka_unit_test(test_far_genome_founds_new_species),
        cmocka_unit_test(test_existing_species_checked_oldest_first),
        cmocka_unit_test(test_empty_species_removed),
        cmocka_unit_test(test_middle_species_removed_keeps_order),
        cmocka_unit_test(test_speciation_invariants_random),
        cmocka_unit_test(test_delta_t_up_when_too_many),
        cmocka_unit_test(test_delta_t_down_when_too_few),
        cmocka_unit_test(test_delta_t_kept_at_target),
        cmocka_unit_test(test_delta_t_fixed_without_target),
        cmocka_unit_test(test_delta_t_step_and_floor),
        cmocka_unit_test(test_delta_t_floor_on_single_step),
        cmocka_unit_test(test_rank_best_first),
        cmocka_unit_test(test_rank_counts_stagnation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
