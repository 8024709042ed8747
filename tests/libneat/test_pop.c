/* test_pop.c - the population interface: fitness errors, the three modes over many generations, determinism, collapse. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat_internal.h"

static neat_params small_params(uint32_t pop_size)
{
    neat_params p = neat_params_default();
    p.pop_size = pop_size;
    p.n_inputs = 2;
    p.n_outputs = 1;
    return p;
}

/* a toy fitness depending on weights and structure, in [0, 2) */
static double toy_fitness(const neat_genome *g)
{
    double s = 0.0;
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].enabled)
            s += g->conns[i].weight * (double)(1 + i % 3);
    return 1.0 / (1.0 + fabs(s - 1.5)) + 0.01 * neat_genome_hidden_count(g);
}

static void evaluate_all(neat_pop *pop)
{
    uint32_t i;
    for (i = 0; i < neat_pop_size(pop); i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, toy_fitness(neat_pop_genome(pop, i))), NEAT_OK);
}

static void run_generations(neat_pop *pop, uint32_t n)
{
    uint32_t g;
    for (g = 0; g < n; g++) {
        evaluate_all(pop);
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    }
}

/* the checkpoint bytes: the whole state, to compare two populations */
static void save(const neat_pop *pop, uint8_t **buf, size_t *len)
{
    assert_int_equal(neat_pop_save(pop, buf, len), NEAT_OK);
}

static void assert_species_cover_pop(const neat_pop *pop)
{
    uint32_t k, total = 0;
    neat_species_info info;
    assert_true(neat_pop_species_count(pop) >= 1);
    for (k = 0; k < neat_pop_species_count(pop); k++) {
        assert_int_equal(neat_pop_species(pop, k, &info), NEAT_OK);
        assert_true(info.size >= 1);
        total += info.size;
    }
    assert_int_equal(total, neat_pop_size(pop));
}

/* ---- fitness errors ---- */

static void test_epoch_rejects_missing_fitness(void **state)
{
    neat_params p = small_params(20);
    neat_pop *pop = NULL;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 1, NULL), NEAT_OK);
    /* none given: genome 0 named */
    assert_int_equal(neat_pop_epoch(pop), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_error_index(pop), 0);
    /* all but 13 */
    for (i = 0; i < 20; i++)
        if (i != 13)
            assert_int_equal(neat_pop_set_fitness(pop, i, 1.0), NEAT_OK);
    assert_int_equal(neat_pop_epoch(pop), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_error_index(pop), 13);
    assert_int_equal(neat_pop_generation(pop), 0);
    assert_null(neat_pop_best_ever(pop));
    /* given at last: the epoch goes through */
    assert_int_equal(neat_pop_set_fitness(pop, 13, 1.0), NEAT_OK);
    assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    assert_int_equal(neat_pop_generation(pop), 1);
    neat_pop_free(pop);
}

static void test_set_fitness_rejects_bad_values(void **state)
{
    const double bad[] = {NAN, INFINITY, -INFINITY, -1.0, -1e-300};
    neat_params p = small_params(20);
    neat_pop *pop = NULL;
    size_t k;
    (void)state;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 1, NULL), NEAT_OK);
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        uint32_t idx = (uint32_t)(3 + 2 * k);
        assert_int_equal(neat_pop_set_fitness(pop, idx, bad[k]), NEAT_E_FITNESS);
        assert_int_equal(neat_pop_error_index(pop), idx);
    }
    /* zero and the largest finite value are fine; an index out of range is an argument error */
    assert_int_equal(neat_pop_set_fitness(pop, 0, 0.0), NEAT_OK);
    assert_int_equal(neat_pop_set_fitness(pop, 1, 1.7976931348623157e308), NEAT_OK);
    assert_int_equal(neat_pop_set_fitness(pop, 20, 1.0), NEAT_E_ARG);
    neat_pop_free(pop);
}

static void test_rejected_fitness_counts_as_missing(void **state)
{
    /* a good value then a bad one for the same genome: the epoch refuses it */
    neat_params p = small_params(10);
    neat_pop *pop = NULL;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 1, NULL), NEAT_OK);
    for (i = 0; i < 10; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, 1.0), NEAT_OK);
    assert_int_equal(neat_pop_set_fitness(pop, 6, NAN), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_epoch(pop), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_error_index(pop), 6);
    neat_pop_free(pop);
}

static void test_failed_epoch_leaves_population_unchanged(void **state)
{
    neat_params p = small_params(30);
    neat_pop *pop = NULL;
    uint8_t *b1, *b2;
    size_t l1, l2;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 3, NULL), NEAT_OK);
    run_generations(pop, 3);
    for (i = 0; i < 30; i++)
        if (i != 29)
            assert_int_equal(neat_pop_set_fitness(pop, i, toy_fitness(neat_pop_genome(pop, i))), NEAT_OK);
    save(pop, &b1, &l1);
    assert_int_equal(neat_pop_epoch(pop), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_error_index(pop), 29);
    save(pop, &b2, &l2);
    assert_int_equal(l1, l2);
    assert_memory_equal(b1, b2, l1);
    assert_int_equal(neat_pop_generation(pop), 3);
    neat_pop_buf_free(pop, b1, l1);
    neat_pop_buf_free(pop, b2, l2);
    neat_pop_free(pop);
}

static void test_population_usable_after_error(void **state)
{
    neat_params p = small_params(30);
    neat_pop *pop = NULL;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 4, NULL), NEAT_OK);
    assert_int_equal(neat_pop_epoch(pop), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_set_fitness(pop, 5, -2.0), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_set_fitness(pop, 8, INFINITY), NEAT_E_FITNESS);
    for (i = 0; i < 30; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, toy_fitness(neat_pop_genome(pop, i))), NEAT_OK);
    assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    assert_int_equal(neat_pop_generation(pop), 1);
    assert_non_null(neat_pop_best_ever(pop));
    /* new generation: fitness needed again */
    assert_int_equal(neat_pop_epoch(pop), NEAT_E_FITNESS);
    run_generations(pop, 5);
    assert_int_equal(neat_pop_generation(pop), 6);
    assert_species_cover_pop(pop);
    neat_pop_free(pop);
}

static void test_best_genomes(void **state)
{
    neat_params p = small_params(20);
    neat_pop *pop = NULL;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 8, NULL), NEAT_OK);
    assert_null(neat_pop_last_best(pop));
    assert_null(neat_pop_best_ever(pop));
    /* generation 0: best 5.0 at 7 and 12: the lowest index */
    for (i = 0; i < 20; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, (i == 7 || i == 12) ? 5.0 : 1.0), NEAT_OK);
    assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    assert_true(neat_pop_best_ever(pop)->fitness == 5.0);
    assert_true(neat_pop_last_best(pop)->fitness == 5.0);
    /* generation 1: worse; best ever stays */
    for (i = 0; i < 20; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, i == 3 ? 2.0 : 0.5), NEAT_OK);
    assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    assert_true(neat_pop_best_ever(pop)->fitness == 5.0);
    assert_true(neat_pop_last_best(pop)->fitness == 2.0);
    neat_pop_free(pop);
}

/* ---- modes ---- */

static void test_fixed_mode_keeps_structure(void **state)
{
    neat_params p = small_params(50);
    neat_pop *pop = NULL;
    uint32_t g, i, k;
    (void)state;
    p.mode = NEAT_MODE_FIXED;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 10, NULL), NEAT_OK);
    for (g = 0; g < 30; g++) {
        evaluate_all(pop);
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
        for (i = 0; i < 50; i++) {
            const neat_genome *x = neat_pop_genome(pop, i);
            assert_int_equal(x->n_nodes, 4);
            assert_int_equal(x->n_conns, 3);
            for (k = 0; k < 3; k++)
                assert_int_equal(x->conns[k].innov, k);
        }
        assert_int_equal(neat_pop_innovations(pop), 3);
        assert_species_cover_pop(pop);
    }
    neat_pop_free(pop);
}

static void test_simplify_mode_only_removes(void **state)
{
    neat_params p = small_params(50);
    neat_pop *pop = NULL;
    neat_genome start;
    neat_start st;
    uint32_t g, i, k, total0 = 0, total = 0, innov0;
    (void)state;
    p.mode = NEAT_MODE_SIMPLIFY;
    p.add_conn_prob = 0.3; /* removal chance: add_node_prob + add_conn_prob */
    assert_int_equal(neat_genome_recurrent_hidden(&start, 2, 1, 3, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    st.genome = &start;
    st.keep_weights = 0;
    assert_int_equal(neat_pop_create(&pop, &p, &st, 11, NULL), NEAT_OK);
    innov0 = neat_pop_innovations(pop);
    assert_int_equal(innov0, start.n_conns);
    for (i = 0; i < 50; i++)
        total0 += neat_pop_genome(pop, i)->n_conns;
    for (g = 0; g < 30; g++) {
        evaluate_all(pop);
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
        assert_int_equal(neat_pop_innovations(pop), innov0);
        for (i = 0; i < 50; i++) {
            const neat_genome *x = neat_pop_genome(pop, i);
            assert_true(x->n_conns <= start.n_conns);
            assert_true(x->n_nodes <= start.n_nodes);
            /* every gene is one of the start's, same link; every node too */
            for (k = 0; k < x->n_conns; k++) {
                const neat_conn *c = &x->conns[k];
                assert_true(c->innov < innov0);
                assert_int_equal(c->in, start.conns[c->innov].in);
                assert_int_equal(c->out, start.conns[c->innov].out);
            }
            for (k = 0; k < x->n_nodes; k++)
                assert_non_null(neat_genome_find_node(&start, x->nodes[k].id));
        }
    }
    for (i = 0; i < 50; i++)
        total += neat_pop_genome(pop, i)->n_conns;
    /* and connections were really removed */
    assert_true(total < total0);
    neat_genome_free(&start, NULL);
    neat_pop_free(pop);
}

static void test_complexify_mode_grows(void **state)
{
    neat_params p = small_params(50);
    neat_pop *pop = NULL;
    uint32_t g, i, max_hidden = 0, max_conns = 0;
    (void)state;
    p.add_node_prob = 0.03;
    p.add_conn_prob = 0.2;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 12, NULL), NEAT_OK);
    for (g = 0; g < 30; g++) {
        evaluate_all(pop);
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
        for (i = 0; i < 50; i++) {
            const neat_genome *x = neat_pop_genome(pop, i);
            assert_true(neat_genome_io_ok(x, 2, 1));
            if (neat_genome_hidden_count(x) > max_hidden)
                max_hidden = neat_genome_hidden_count(x);
            if (x->n_conns > max_conns)
                max_conns = x->n_conns;
        }
        assert_species_cover_pop(pop);
    }
    assert_true(max_hidden > 0);
    assert_true(max_conns > 3);
    assert_true(neat_pop_innovations(pop) > 3);
    neat_pop_free(pop);
}

/* ---- determinism ---- */

static void champion_blob(uint64_t seed, uint8_t *blob, size_t cap, size_t *len)
{
    neat_params p = small_params(60);
    neat_pop *pop = NULL;
    p.add_node_prob = 0.03;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, seed, NULL), NEAT_OK);
    run_generations(pop, 20);
    assert_non_null(neat_pop_best_ever(pop));
    assert_int_equal(neat_blob_write(neat_pop_best_ever(pop), 2, 1, blob, cap, len), NEAT_OK);
    neat_pop_free(pop);
}

static void test_same_seed_same_champion(void **state)
{
    uint8_t a[4096], b[4096];
    size_t la, lb;
    (void)state;
    champion_blob(77, a, sizeof a, &la);
    champion_blob(77, b, sizeof b, &lb);
    assert_int_equal(la, lb);
    assert_memory_equal(a, b, la);
}

static void test_different_seed_different_champion(void **state)
{
    uint8_t a[4096], b[4096];
    size_t la, lb;
    (void)state;
    champion_blob(77, a, sizeof a, &la);
    champion_blob(78, b, sizeof b, &lb);
    assert_true(la != lb || memcmp(a, b, la) != 0);
}

static void test_evaluation_order_irrelevant(void **state)
{
    /* fitness given in reverse order: the same run */
    neat_params p = small_params(40);
    neat_pop *a = NULL, *b = NULL;
    uint8_t *ba, *bb;
    size_t la, lb;
    uint32_t g, i;
    (void)state;
    assert_int_equal(neat_pop_create(&a, &p, NULL, 5, NULL), NEAT_OK);
    assert_int_equal(neat_pop_create(&b, &p, NULL, 5, NULL), NEAT_OK);
    for (g = 0; g < 10; g++) {
        evaluate_all(a);
        for (i = 40; i-- > 0;)
            assert_int_equal(neat_pop_set_fitness(b, i, toy_fitness(neat_pop_genome(b, i))), NEAT_OK);
        assert_int_equal(neat_pop_epoch(a), NEAT_OK);
        assert_int_equal(neat_pop_epoch(b), NEAT_OK);
    }
    save(a, &ba, &la);
    save(b, &bb, &lb);
    assert_int_equal(la, lb);
    assert_memory_equal(ba, bb, la);
    neat_pop_buf_free(a, ba, la);
    neat_pop_buf_free(b, bb, lb);
    neat_pop_free(a);
    neat_pop_free(b);
}

/* ---- degenerate runs ---- */

static void test_constant_zero_fitness_collapse(void **state)
{
    /* no fitness signal at all, species cut early and often */
    neat_params p = small_params(40);
    neat_pop *pop = NULL;
    uint32_t g, i;
    (void)state;
    p.dropoff_age = 5;
    p.pop_stagnation = 3;
    p.add_node_prob = 0.05;
    p.add_conn_prob = 0.2;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 13, NULL), NEAT_OK);
    for (g = 0; g < 60; g++) {
        for (i = 0; i < 40; i++)
            assert_int_equal(neat_pop_set_fitness(pop, i, 0.0), NEAT_OK);
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
        assert_species_cover_pop(pop);
        for (i = 0; i < 40; i++)
            assert_true(neat_genome_io_ok(neat_pop_genome(pop, i), 2, 1));
        assert_true(neat_pop_delta_t(pop) >= p.delta_t_min);
    }
    assert_int_equal(neat_pop_generation(pop), 60);
    assert_true(neat_pop_best_ever(pop)->fitness == 0.0);
    neat_pop_free(pop);
}

static void test_many_species_stagnating(void **state)
{
    /* a tiny threshold makes many small species, then a constant fitness
     * makes all of them stagnate together */
    neat_params p = small_params(40);
    neat_pop *pop = NULL;
    uint32_t g, i;
    (void)state;
    p.delta_t = 0.3;
    p.delta_t_min = 0.05;
    p.target_species = 30;
    p.dropoff_age = 5;
    p.pop_stagnation = 3;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 14, NULL), NEAT_OK);
    assert_true(neat_pop_species_count(pop) > 5);
    for (g = 0; g < 60; g++) {
        for (i = 0; i < 40; i++)
            assert_int_equal(neat_pop_set_fitness(pop, i, g < 5 ? (double)(i % 7) : 1.0), NEAT_OK);
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
        assert_species_cover_pop(pop);
    }
    neat_pop_free(pop);
}

static void test_create_rejects_bad_arguments(void **state)
{
    neat_params p = small_params(20);
    neat_pop *pop = (neat_pop *)&p; /* must be cleared on failure */
    neat_genome g;
    neat_start st;
    (void)state;
    assert_int_equal(neat_pop_create(NULL, &p, NULL, 1, NULL), NEAT_E_ARG);
    assert_int_equal(neat_pop_create(&pop, NULL, NULL, 1, NULL), NEAT_E_ARG);
    p.pop_size = 1;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 1, NULL), NEAT_E_PARAM);
    assert_null(pop);
    /* a start genome with too few nodes for n_inputs / n_outputs */
    p.pop_size = 20;
    assert_int_equal(neat_genome_minimal(&g, 1, 1, NULL), NEAT_OK);
    st.genome = &g;
    st.keep_weights = 1;
    assert_int_equal(neat_pop_create(&pop, &p, &st, 1, NULL), NEAT_E_ARG);
    assert_null(pop);
    neat_genome_free(&g, NULL);
}

static void test_create_rejects_start_with_wrong_layout(void **state)
{
    /* enough nodes, wrong roles: 1 input and 2 outputs given for 2 inputs
     * and 1 output (node 2 is an output where an input belongs). Accepted,
     * every genome would fail neat_blob_write and every checkpoint would
     * fail neat_pop_load's layout check.
     * neat_pop_create checks the start's whole layout (neat_genome_io_ok),
     * not only its node count. */
    neat_params p = small_params(20);
    neat_pop *pop = NULL;
    neat_genome g;
    neat_start st;
    int err, created;
    (void)state;
    assert_int_equal(neat_genome_minimal(&g, 1, 2, NULL), NEAT_OK);
    st.genome = &g;
    st.keep_weights = 0;
    err = neat_pop_create(&pop, &p, &st, 1, NULL);
    created = pop != NULL;
    neat_pop_free(pop);
    neat_genome_free(&g, NULL);
    assert_int_equal(err, NEAT_E_ARG);
    assert_false(created);
}

static void test_start_genome_keep_weights(void **state)
{
    neat_params p = small_params(10);
    neat_pop *pop = NULL;
    neat_genome g;
    neat_start st;
    uint32_t i, k;
    (void)state;
    assert_int_equal(neat_genome_recurrent_hidden(&g, 2, 1, 2, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    for (k = 0; k < g.n_conns; k++)
        g.conns[k].weight = 0.125 * k - 1.0;
    st.genome = &g;
    st.keep_weights = 1;
    assert_int_equal(neat_pop_create(&pop, &p, &st, 1, NULL), NEAT_OK);
    for (i = 0; i < 10; i++)
        for (k = 0; k < g.n_conns; k++)
            assert_true(neat_pop_genome(pop, i)->conns[k].weight == g.conns[k].weight);
    /* the population's counters continue after the start's markings */
    assert_int_equal(neat_pop_innovations(pop), g.n_conns);
    assert_int_equal(pop->iv.next_node, g.n_nodes);
    neat_pop_free(pop);
    neat_genome_free(&g, NULL);
}

/* counters near 2^31 - 1 (a start genome's markings): the epoch that would pass the limit says so with its own code,
 * NEAT_E_COUNTERS, not a blob-format error, and leaves the population as it was */
static void test_counters_at_their_limit(void **state)
{
    neat_params p = small_params(10);
    neat_pop *pop = NULL;
    neat_genome g;
    neat_start st;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_genome_recurrent_hidden(&g, 2, 1, 2, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    g.conns[g.n_conns - 1].innov = 0x7ffffff0u;
    st.genome = &g;
    st.keep_weights = 0;
    assert_int_equal(neat_pop_create(&pop, &p, &st, 1, NULL), NEAT_OK);
    for (i = 0; i < 10; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, 1.0 + i), NEAT_OK);
    assert_int_equal(neat_pop_epoch(pop), NEAT_E_COUNTERS);
    assert_int_equal(neat_pop_generation(pop), 0);
    assert_non_null(strstr(neat_strerror(NEAT_E_COUNTERS), "2^31 - 1"));
    neat_pop_free(pop);
    neat_genome_free(&g, NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_epoch_rejects_missing_fitness),
        cmocka_unit_test(test_set_fitness_rejects_bad_values),
        cmocka_unit_test(test_rejected_fitness_counts_as_missing),
        cmocka_unit_test(test_failed_epoch_leaves_population_unchanged),
        cmocka_unit_test(test_population_usable_after_error),
        cmocka_unit_test(test_best_genomes),
        cmocka_unit_test(test_fixed_mode_keeps_structure),
        cmocka_unit_test(test_simplify_mode_only_removes),
        cmocka_unit_test(test_complexify_mode_grows),
        cmocka_unit_test(test_same_seed_same_champion),
        cmocka_unit_test(test_different_seed_different_champion),
        cmocka_unit_test(test_evaluation_order_irrelevant),
        cmocka_unit_test(test_constant_zero_fitness_collapse),
        cmocka_unit_test(test_many_species_stagnating),
        cmocka_unit_test(test_create_rejects_bad_arguments),
        cmocka_unit_test(test_create_rejects_start_with_wrong_layout),
        cmocka_unit_test(test_start_genome_keep_weights),
        cmocka_unit_test(test_counters_at_their_limit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
