/* test_coev_start.c - coevolution from a start topology (fixed, simplifying), the random-fitness control, the population's size range and threshold in the report, and the rule coevolution refuses. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat_coev.h"

/* A game decided by the genomes' summed weights, the side, and the seed
 * when near equal: enough for selection to have something to act on. */
static double strength(const neat_genome *g)
{
    double s = 0.0;
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].enabled)
            s += g->conns[i].weight;
    return s;
}

static int play(void *ud, neat_game *games, size_t n)
{
    size_t k;
    uint32_t *calls = (uint32_t *)ud;
    if (calls != NULL)
        ++*calls;
    for (k = 0; k < n; k++) {
        double d = strength(games[k].a) - strength(games[k].b) + (games[k].a_first ? 0.1 : -0.1);
        games[k].result = (int8_t)(d > 0.3 ? 1 : d < -0.3 ? -1 : (int)(games[k].seed % 3u) - 1);
    }
    return 0;
}

static neat_params small_params(int mode)
{
    neat_params p = neat_params_default();
    p.pop_size = 16;
    p.n_inputs = 3;
    p.n_outputs = 2;
    p.mode = mode;
    p.add_node_prob = 0.2;
    p.add_conn_prob = 0.4;
    p.target_species = 4;
    p.pop_stagnation = 0;
    return p;
}

static neat_coev_params small_cp(void)
{
    neat_coev_params cp = neat_coev_params_default();
    cp.compare_configs = 2;
    return cp;
}

/* the largest innovation number in use anywhere in population i */
static uint32_t max_innov(const neat_coev *c, uint32_t which)
{
    const neat_pop *pop = neat_coev_pop(c, which);
    uint32_t i, k, m = 0;
    for (i = 0; i < neat_pop_size(pop); i++) {
        const neat_genome *g = neat_pop_genome(pop, i);
        for (k = 0; k < g->n_conns; k++)
            if (g->conns[k].innov > m)
                m = g->conns[k].innov;
    }
    return m;
}

static void test_hidden_start_counts(void **state)
{
    /* the paper's figures for the duel's 12 inputs and 3 outputs */
    static const uint32_t h[4] = {5, 10, 12, 1};
    static const int direct[4] = {NEAT_DIRECT_INPUTS, NEAT_DIRECT_BIAS, NEAT_DIRECT_BIAS, NEAT_DIRECT_INPUTS};
    static const uint32_t conns[4] = {144, 263, 339, 56};
    neat_genome g;
    uint32_t k;
    (void)state;
    for (k = 0; k < 4; k++) {
        assert_int_equal(neat_genome_recurrent_hidden(&g, 12, 3, h[k], direct[k], NULL), NEAT_OK);
        assert_int_equal(neat_genome_enabled_count(&g), conns[k]);
        assert_int_equal(neat_genome_hidden_count(&g), h[k]);
        assert_int_equal(g.n_conns, h[k] * h[k] + 16u * h[k] + (direct[k] == NEAT_DIRECT_BIAS ? 3u : 39u));
        neat_genome_free(&g, NULL);
    }
    assert_int_equal(neat_genome_recurrent_hidden(&g, 12, 3, 2, 7, NULL), NEAT_E_ARG);
}

static void test_blob_roundtrip(void **state)
{
    /* genome -> blob -> genome -> blob gives the same bytes, and the genome
     * has the blob's network with innovations 0.. in blob order */
    neat_genome g, back;
    uint8_t b1[4096], b2[4096];
    size_t l1, l2, k;
    neat_rng rng;
    (void)state;
    neat_rng_seed(&rng, 5);
    assert_int_equal(neat_genome_recurrent_hidden(&g, 4, 2, 3, NEAT_DIRECT_BIAS, NULL), NEAT_OK);
    for (k = 0; k < g.n_conns; k++)
        g.conns[k].weight = 8.0 * neat_rng_uniform(&rng) - 4.0;
    g.conns[3].enabled = 0;
    assert_int_equal(neat_blob_write(&g, 4, 2, b1, sizeof b1, &l1), NEAT_OK);
    assert_int_equal(neat_genome_from_blob(&back, b1, l1, NULL), NEAT_OK);
    assert_int_equal(back.n_nodes, g.n_nodes);
    assert_int_equal(back.n_conns, g.n_conns - 1);
    assert_int_equal(neat_genome_hidden_count(&back), 3);
    for (k = 0; k < back.n_conns; k++)
        assert_int_equal(back.conns[k].innov, k);
    assert_int_equal(neat_blob_write(&back, 4, 2, b2, sizeof b2, &l2), NEAT_OK);
    assert_int_equal(l1, l2);
    assert_memory_equal(b1, b2, l1);
    neat_genome_free(&back, NULL);
    /* not a blob */
    b1[l1 - 1] ^= 1u;
    assert_int_equal(neat_genome_from_blob(&back, b1, l1, NULL), NEAT_E_FORMAT);
    assert_int_equal(neat_genome_from_blob(&back, b1, 10, NULL), NEAT_E_FORMAT);
    neat_genome_free(&g, NULL);
}

/* fixed mode from a hidden-layer start: generation 0 is the start's
 * structure everywhere, and no generation ever changes it */
static void test_fixed_from_start(void **state)
{
    neat_params p = small_params(NEAT_MODE_FIXED);
    neat_coev_params cp = small_cp();
    neat_genome start;
    neat_start st;
    neat_coev *c = NULL, *back = NULL;
    neat_coev_report r;
    uint8_t *buf;
    size_t len;
    uint32_t g, i, w;
    (void)state;
    assert_int_equal(neat_genome_recurrent_hidden(&start, 3, 2, 2, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    st.genome = &start;
    st.keep_weights = 0;
    assert_int_equal(neat_coev_create(&c, &p, &cp, &st, 9, NULL), NEAT_OK);
    assert_int_equal(neat_coev_start(c)->n_conns, start.n_conns);
    for (g = 0; g < 12; g++) {
        for (w = 0; w < 2; w++)
            for (i = 0; i < p.pop_size; i++) {
                const neat_genome *x = neat_pop_genome(neat_coev_pop(c, w), i);
                assert_int_equal(x->n_nodes, start.n_nodes);
                assert_int_equal(x->n_conns, start.n_conns);
                assert_int_equal(neat_genome_enabled_count(x), start.n_conns);
            }
        assert_int_equal(neat_coev_step(c, play, NULL, &r), NEAT_OK);
        for (w = 0; w < 2; w++) {
            assert_int_equal(r.pop[w].min_conns, start.n_conns);
            assert_int_equal(r.pop[w].max_conns, start.n_conns);
            assert_int_equal(r.pop[w].min_hidden, 2);
            assert_int_equal(r.pop[w].max_hidden, 2);
        }
    }
    /* the checkpoint carries the start */
    assert_int_equal(neat_coev_save(c, &buf, &len), NEAT_OK);
    assert_int_equal(neat_coev_load(&back, buf, len, NULL, NULL), NEAT_OK);
    assert_int_equal(neat_coev_start(back)->n_conns, start.n_conns);
    assert_int_equal(neat_coev_start(back)->n_nodes, start.n_nodes);
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(back);
    neat_coev_free(c);
    neat_genome_free(&start, NULL);
}

/* simplify mode: connections only go, nodes left unconnected go with
 * them, and no innovation number is ever created */
static void test_simplify_from_start(void **state)
{
    neat_params p = small_params(NEAT_MODE_SIMPLIFY);
    neat_coev_params cp = small_cp();
    neat_genome start;
    neat_start st;
    neat_coev *c = NULL;
    neat_coev_report r;
    uint32_t g, w, top, first_max[2] = {0, 0};
    (void)state;
    assert_int_equal(neat_genome_recurrent_hidden(&start, 3, 2, 3, NEAT_DIRECT_BIAS, NULL), NEAT_OK);
    top = start.conns[start.n_conns - 1].innov;
    st.genome = &start;
    st.keep_weights = 0;
    assert_int_equal(neat_coev_create(&c, &p, &cp, &st, 4, NULL), NEAT_OK);
    for (g = 0; g < 30; g++) {
        assert_int_equal(neat_coev_step(c, play, NULL, &r), NEAT_OK);
        for (w = 0; w < 2; w++) {
            assert_true(r.pop[w].max_conns <= start.n_conns);
            assert_true(r.pop[w].max_hidden <= 3);
            assert_true(max_innov(c, w) <= top);
            assert_true(neat_pop_innovations(neat_coev_pop(c, w)) == top + 1u);
            if (g == 0)
                first_max[w] = r.pop[w].max_conns;
        }
    }
    /* and it did simplify */
    assert_true(r.pop[0].min_conns < first_max[0] || r.pop[1].min_conns < first_max[1]);
    neat_coev_free(c);
    neat_genome_free(&start, NULL);
}

static int play_forbidden(void *ud, neat_game *games, size_t n)
{
    (void)ud;
    (void)games;
    (void)n;
    fail_msg("random fitness must not play the games");
    return -1;
}

/* random fitness: every game a coin from its seed; nothing is played, the
 * run is deterministic, wins are about half, and evolution goes on */
static void test_random_fitness(void **state)
{
    neat_params p = small_params(NEAT_MODE_COMPLEXIFY);
    neat_coev_params cp = small_cp();
    neat_coev *c1 = NULL, *c2 = NULL;
    neat_coev_report r1, r2;
    uint8_t *b1, *b2;
    size_t l1, l2;
    uint32_t g, w;
    double mean = 0;
    (void)state;
    cp.random_fitness = 1;
    assert_int_equal(neat_coev_create(&c1, &p, &cp, NULL, 21, NULL), NEAT_OK);
    assert_int_equal(neat_coev_create(&c2, &p, &cp, NULL, 21, NULL), NEAT_OK);
    for (g = 0; g < 20; g++) {
        assert_int_equal(neat_coev_step(c1, play_forbidden, NULL, &r1), NEAT_OK);
        assert_int_equal(neat_coev_step(c2, play_forbidden, NULL, &r2), NEAT_OK);
        for (w = 0; w < 2; w++) {
            assert_true(r1.pop[w].mean_fitness == r2.pop[w].mean_fitness);
            mean += r1.pop[w].mean_fitness / (double)(r1.pop[w].games / p.pop_size) / 40.0;
        }
        assert_int_equal(r1.champion_wins[0] + r1.champion_wins[1], 2u * cp.compare_configs);
    }
    assert_true(mean > 0.4 && mean < 0.6);
    assert_true(r1.pop[0].max_conns > r1.pop[0].min_conns || r1.pop[1].max_conns > r1.pop[1].min_conns);
    assert_int_equal(neat_coev_save(c1, &b1, &l1), NEAT_OK);
    assert_int_equal(neat_coev_save(c2, &b2, &l2), NEAT_OK);
    assert_int_equal(l1, l2);
    assert_memory_equal(b1, b2, l1);
    neat_coev_buf_free(c1, b1, l1);
    neat_coev_buf_free(c2, b2, l2);
    /* and a checkpoint keeps the switch */
    assert_int_equal(neat_coev_save(c1, &b1, &l1), NEAT_OK);
    neat_coev_free(c2);
    assert_int_equal(neat_coev_load(&c2, b1, l1, NULL, NULL), NEAT_OK);
    assert_int_equal(neat_coev_get_params(c2)->random_fitness, 1);
    neat_coev_buf_free(c1, b1, l1);
    neat_coev_free(c1);
    neat_coev_free(c2);
    cp.random_fitness = 2;
    assert_int_equal(neat_coev_create(&c1, &p, &cp, NULL, 21, NULL), NEAT_E_PARAM);
}

/* the report's sizes are those of the generation that played */
static void test_report_sizes(void **state)
{
    neat_params p = small_params(NEAT_MODE_COMPLEXIFY);
    neat_coev_params cp = small_cp();
    neat_coev *c = NULL;
    neat_coev_report r;
    uint32_t g, w, i, lo[2][4], hi[2][4];
    int grew = 0;
    (void)state;
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 3, NULL), NEAT_OK);
    for (g = 0; g < 25; g++) {
        for (w = 0; w < 2; w++) {
            const neat_pop *pop = neat_coev_pop(c, w);
            lo[w][0] = lo[w][1] = UINT32_MAX;
            hi[w][0] = hi[w][1] = 0;
            for (i = 0; i < p.pop_size; i++) {
                const neat_genome *x = neat_pop_genome(pop, i);
                uint32_t h = neat_genome_hidden_count(x), e = neat_genome_enabled_count(x);
                lo[w][0] = h < lo[w][0] ? h : lo[w][0];
                hi[w][0] = h > hi[w][0] ? h : hi[w][0];
                lo[w][1] = e < lo[w][1] ? e : lo[w][1];
                hi[w][1] = e > hi[w][1] ? e : hi[w][1];
            }
        }
        assert_int_equal(neat_coev_step(c, play, NULL, &r), NEAT_OK);
        for (w = 0; w < 2; w++) {
            assert_int_equal(r.pop[w].min_hidden, lo[w][0]);
            assert_int_equal(r.pop[w].max_hidden, hi[w][0]);
            assert_int_equal(r.pop[w].min_conns, lo[w][1]);
            assert_int_equal(r.pop[w].max_conns, hi[w][1]);
            assert_true(r.pop[w].min_conns <= r.pop[w].mean_conns && r.pop[w].mean_conns <= r.pop[w].max_conns);
            grew |= hi[w][0] > 0;
        }
    }
    assert_true(grew);
    neat_coev_free(c);
}

/* the threshold a generation reports is the one it was speciated with:
 * generation 0 with delta_t itself, each later one with the previous moved
 * by one step toward the target */
static void test_report_delta_t(void **state)
{
    neat_params p = small_params(NEAT_MODE_COMPLEXIFY);
    neat_coev_params cp = small_cp();
    neat_coev *c = NULL;
    neat_coev_report r, prev;
    uint32_t g, w;
    (void)state;
    p.delta_t = 1.0;
    p.delta_t_step = 0.25;
    p.delta_t_min = 0.25;
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 8, NULL), NEAT_OK);
    for (g = 0; g < 15; g++) {
        assert_int_equal(neat_coev_step(c, play, NULL, &r), NEAT_OK);
        for (w = 0; w < 2; w++) {
            if (g == 0) {
                assert_true(r.pop[w].delta_t == 1.0);
            } else {
                double want = prev.pop[w].delta_t;
                if (prev.pop[w].species > p.target_species)
                    want += p.delta_t_step;
                else if (prev.pop[w].species < p.target_species)
                    want -= p.delta_t_step;
                if (want < p.delta_t_min)
                    want = p.delta_t_min;
                assert_true(r.pop[w].delta_t == want);
            }
        }
        prev = r;
    }
    neat_coev_free(c);
}

/* pop_stagnation needs an absolute fitness: coevolution refuses it */
static void test_pop_stagnation_refused(void **state)
{
    neat_params p = small_params(NEAT_MODE_COMPLEXIFY);
    neat_coev_params cp = small_cp();
    neat_coev *c = NULL;
    (void)state;
    p.pop_stagnation = 35;
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 1, NULL), NEAT_E_PARAM);
    assert_null(c);
    p.pop_stagnation = 0;
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 1, NULL), NEAT_OK);
    p.pop_stagnation = 35;
    assert_int_equal(neat_coev_set_params(c, &p, &cp), NEAT_E_PARAM);
    p.pop_stagnation = 0;
    assert_int_equal(neat_coev_set_params(c, &p, &cp), NEAT_OK);
    neat_coev_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hidden_start_counts),
        cmocka_unit_test(test_blob_roundtrip),
        cmocka_unit_test(test_fixed_from_start),
        cmocka_unit_test(test_simplify_from_start),
        cmocka_unit_test(test_random_fitness),
        cmocka_unit_test(test_report_sizes),
        cmocka_unit_test(test_report_delta_t),
        cmocka_unit_test(test_pop_stagnation_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
