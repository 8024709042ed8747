/* test_genome.c - genomes: start topologies, sorted node and connection genes, deep copy, compatibility distance. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "neat_internal.h"

/* cmocka 1.1 compares floats only */
#define assert_near(a, b, eps)                                                                                        \
    do {                                                                                                              \
        double got_ = (a), want_ = (b);                                                                               \
        if (!(fabs(got_ - want_) <= (eps)))                                                                           \
            fail_msg("%s = %.17g, expected %.17g", #a, got_, want_);                                                  \
    } while (0)

/* bias 0, inputs 1..n_in, outputs next, then hidden ids given */
static void build_nodes(neat_genome *g, uint32_t n_in, uint32_t n_out, const uint32_t *hidden, uint32_t n_hid)
{
    uint32_t i;
    neat_genome_init(g);
    assert_int_equal(neat_genome_add_node(g, 0, NEAT_NODE_BIAS, NULL), NEAT_OK);
    for (i = 1; i <= n_in; i++)
        assert_int_equal(neat_genome_add_node(g, i, NEAT_NODE_INPUT, NULL), NEAT_OK);
    for (i = 0; i < n_out; i++)
        assert_int_equal(neat_genome_add_node(g, n_in + 1 + i, NEAT_NODE_OUTPUT, NULL), NEAT_OK);
    for (i = 0; i < n_hid; i++)
        assert_int_equal(neat_genome_add_node(g, hidden[i], NEAT_NODE_HIDDEN, NULL), NEAT_OK);
}

static void test_minimal_layout(void **state)
{
    neat_genome g;
    uint32_t i, o, s, k = 0;
    (void)state;
    assert_int_equal(neat_genome_minimal(&g, 3, 2, NULL), NEAT_OK);
    assert_int_equal(g.n_nodes, 1 + 3 + 2);
    assert_int_equal(g.nodes[0].id, 0);
    assert_int_equal(g.nodes[0].type, NEAT_NODE_BIAS);
    for (i = 1; i <= 3; i++) {
        assert_int_equal(g.nodes[i].id, i);
        assert_int_equal(g.nodes[i].type, NEAT_NODE_INPUT);
    }
    for (i = 4; i <= 5; i++) {
        assert_int_equal(g.nodes[i].id, i);
        assert_int_equal(g.nodes[i].type, NEAT_NODE_OUTPUT);
    }
    assert_int_equal(neat_genome_hidden_count(&g), 0);
    assert_true(neat_genome_io_ok(&g, 3, 2));
    /* (n_in + 1) * n_out connections, innovations 0.. in order, all enabled */
    assert_int_equal(g.n_conns, (3 + 1) * 2);
    assert_int_equal(neat_genome_enabled_count(&g), 8);
    for (o = 0; o < 2; o++)
        for (s = 0; s <= 3; s++) {
            assert_int_equal(g.conns[k].innov, k);
            assert_int_equal(g.conns[k].in, s);
            assert_int_equal(g.conns[k].out, 4 + o);
            assert_int_equal(g.conns[k].enabled, 1);
            k++;
        }
    /* every source reaches every output exactly once */
    for (o = 4; o <= 5; o++)
        for (s = 0; s <= 3; s++)
            assert_true(neat_genome_has_link(&g, s, o));
    assert_false(neat_genome_has_link(&g, 4, 5));
    neat_genome_free(&g, NULL);
    assert_null(g.nodes);
    assert_null(g.conns);
}

static void test_minimal_one_input_one_output(void **state)
{
    neat_genome g;
    (void)state;
    assert_int_equal(neat_genome_minimal(&g, 1, 1, NULL), NEAT_OK);
    assert_int_equal(g.n_nodes, 3);
    assert_int_equal(g.n_conns, 2);
    assert_int_equal(g.conns[0].in, 0);
    assert_int_equal(g.conns[1].in, 1);
    assert_int_equal(g.conns[0].out, 2);
    assert_int_equal(g.conns[1].out, 2);
    neat_genome_free(&g, NULL);
}

static void test_recurrent_hidden_counts(void **state)
{
    static const uint32_t cases[][3] = {{3, 2, 4}, {1, 1, 1}, {12, 3, 5}, {2, 1, 0}};
    size_t c;
    (void)state;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        uint32_t n_in = cases[c][0], n_out = cases[c][1], H = cases[c][2], i, h, k, selfs = 0;
        uint32_t first_hid = n_in + n_out + 1;
        neat_genome g;
        assert_int_equal(neat_genome_recurrent_hidden(&g, n_in, n_out, H, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
        assert_int_equal(g.n_nodes, n_in + 1 + n_out + H);
        assert_int_equal(neat_genome_hidden_count(&g), H);
        assert_true(neat_genome_io_ok(&g, n_in, n_out));
        assert_int_equal(g.n_conns, (n_in + 1) * H + H * H + H * n_out + (n_in + 1) * n_out);
        assert_int_equal(neat_genome_enabled_count(&g), g.n_conns);
        for (i = 0; i < g.n_conns; i++) {
            assert_int_equal(g.conns[i].innov, i);
            selfs += g.conns[i].in == g.conns[i].out;
        }
        /* every hidden node has its self connection, every hidden pair both ways */
        assert_int_equal(selfs, H);
        for (h = 0; h < H; h++) {
            for (k = 0; k < H; k++)
                assert_true(neat_genome_has_link(&g, first_hid + h, first_hid + k));
            for (i = 0; i <= n_in; i++)
                assert_true(neat_genome_has_link(&g, i, first_hid + h));
            for (i = 0; i < n_out; i++)
                assert_true(neat_genome_has_link(&g, first_hid + h, n_in + 1 + i));
        }
        for (i = 0; i <= n_in; i++)
            for (k = 0; k < n_out; k++)
                assert_true(neat_genome_has_link(&g, i, n_in + 1 + k));
        /* nothing leaves an output */
        for (i = 0; i < g.n_conns; i++)
            assert_true(g.conns[i].in <= n_in || g.conns[i].in >= first_hid);
        neat_genome_free(&g, NULL);
    }
}

static void test_add_node_keeps_ids_sorted(void **state)
{
    static const uint32_t ids[] = {9, 3, 7, 20, 0, 5, 4, 100, 1};
    neat_genome g;
    uint32_t i;
    (void)state;
    neat_genome_init(&g);
    for (i = 0; i < sizeof ids / sizeof ids[0]; i++)
        assert_int_equal(neat_genome_add_node(&g, ids[i], ids[i] == 0 ? NEAT_NODE_BIAS : NEAT_NODE_HIDDEN, NULL),
                         NEAT_OK);
    assert_int_equal(g.n_nodes, 9);
    for (i = 1; i < g.n_nodes; i++)
        assert_true(g.nodes[i - 1].id < g.nodes[i].id);
    /* the type travels with its id */
    assert_int_equal(neat_genome_find_node(&g, 0)->type, NEAT_NODE_BIAS);
    assert_int_equal(neat_genome_find_node(&g, 100)->type, NEAT_NODE_HIDDEN);
    assert_non_null(neat_genome_find_node(&g, 7));
    assert_null(neat_genome_find_node(&g, 8));
    assert_null(neat_genome_find_node(&g, 101));
    neat_genome_free(&g, NULL);
}

static void test_add_node_rejects_duplicate(void **state)
{
    neat_genome g;
    (void)state;
    neat_genome_init(&g);
    assert_int_equal(neat_genome_add_node(&g, 5, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(&g, 2, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(&g, 5, NEAT_NODE_HIDDEN, NULL), NEAT_E_ARG);
    assert_int_equal(neat_genome_add_node(&g, 2, NEAT_NODE_OUTPUT, NULL), NEAT_E_ARG);
    assert_int_equal(g.n_nodes, 2);
    neat_genome_free(&g, NULL);
}

static void test_add_node_rejects_bad_type(void **state)
{
    neat_genome g;
    (void)state;
    neat_genome_init(&g);
    assert_int_equal(neat_genome_add_node(&g, 1, -1, NULL), NEAT_E_ARG);
    assert_int_equal(neat_genome_add_node(&g, 1, NEAT_NODE_HIDDEN + 1, NULL), NEAT_E_ARG);
    assert_int_equal(g.n_nodes, 0);
    neat_genome_free(&g, NULL);
}

static void test_add_conn_keeps_innovation_order(void **state)
{
    static const uint32_t innovs[] = {10, 2, 7, 30, 0, 11, 8};
    neat_genome g;
    uint32_t i;
    (void)state;
    build_nodes(&g, 2, 1, NULL, 0);
    for (i = 0; i < sizeof innovs / sizeof innovs[0]; i++)
        assert_int_equal(neat_genome_add_conn(&g, i % 3, 3, 0.1 * i, innovs[i], 1, NULL), NEAT_OK);
    assert_int_equal(g.n_conns, 7);
    for (i = 1; i < g.n_conns; i++)
        assert_true(g.conns[i - 1].innov < g.conns[i].innov);
    /* the gene's other fields moved with its innovation */
    for (i = 0; i < g.n_conns; i++) {
        uint32_t k;
        for (k = 0; innovs[k] != g.conns[i].innov; k++)
            ;
        assert_int_equal(g.conns[i].in, k % 3);
        assert_true(g.conns[i].weight == 0.1 * k);
    }
    neat_genome_free(&g, NULL);
}

static void test_add_conn_stores_fields(void **state)
{
    neat_genome g;
    (void)state;
    build_nodes(&g, 2, 1, NULL, 0);
    assert_int_equal(neat_genome_add_conn(&g, 2, 3, -1.25, 4, 0, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_conn(&g, 1, 3, 0.5, 5, 7, NULL), NEAT_OK);
    assert_int_equal(g.conns[0].in, 2);
    assert_int_equal(g.conns[0].out, 3);
    assert_true(g.conns[0].weight == -1.25);
    assert_int_equal(g.conns[0].innov, 4);
    assert_int_equal(g.conns[0].enabled, 0);
    assert_int_equal(g.conns[1].enabled, 1); /* any non-zero is enabled, stored as 1 */
    assert_int_equal(neat_genome_enabled_count(&g), 1);
    neat_genome_free(&g, NULL);
}

static void test_add_conn_rejects_duplicate_innovation(void **state)
{
    neat_genome g;
    (void)state;
    build_nodes(&g, 2, 1, NULL, 0);
    assert_int_equal(neat_genome_add_conn(&g, 0, 3, 0.0, 3, 1, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_conn(&g, 1, 3, 0.0, 8, 1, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_conn(&g, 2, 3, 0.0, 3, 1, NULL), NEAT_E_ARG); /* in the middle */
    assert_int_equal(neat_genome_add_conn(&g, 2, 3, 0.0, 8, 1, NULL), NEAT_E_ARG); /* the last */
    assert_int_equal(g.n_conns, 2);
    assert_int_equal(g.conns[0].in, 0);
    assert_int_equal(g.conns[1].in, 1);
    neat_genome_free(&g, NULL);
}

static void test_add_conn_rejects_into_bias_or_input(void **state)
{
    neat_genome g;
    (void)state;
    build_nodes(&g, 2, 1, NULL, 0);
    assert_int_equal(neat_genome_add_conn(&g, 3, 0, 0.0, 0, 1, NULL), NEAT_E_ARG);
    assert_int_equal(neat_genome_add_conn(&g, 3, 1, 0.0, 1, 1, NULL), NEAT_E_ARG);
    assert_int_equal(neat_genome_add_conn(&g, 1, 2, 0.0, 2, 1, NULL), NEAT_E_ARG);
    assert_int_equal(g.n_conns, 0);
    /* out of an output (recurrent) is allowed, and into itself */
    assert_int_equal(neat_genome_add_conn(&g, 3, 3, 0.0, 3, 1, NULL), NEAT_OK);
    neat_genome_free(&g, NULL);
}

static void test_add_conn_rejects_missing_node(void **state)
{
    neat_genome g;
    (void)state;
    build_nodes(&g, 2, 1, NULL, 0);
    assert_int_equal(neat_genome_add_conn(&g, 9, 3, 0.0, 0, 1, NULL), NEAT_E_ARG);
    assert_int_equal(neat_genome_add_conn(&g, 1, 9, 0.0, 1, 1, NULL), NEAT_E_ARG);
    assert_int_equal(g.n_conns, 0);
    neat_genome_free(&g, NULL);
}

static void test_copy_is_deep(void **state)
{
    neat_genome a, b;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_genome_recurrent_hidden(&a, 2, 1, 2, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    for (i = 0; i < a.n_conns; i++)
        a.conns[i].weight = 0.25 * i;
    a.fitness = 3.5;
    a.has_fitness = 1;
    a.species = 4;
    neat_genome_init(&b);
    assert_int_equal(neat_genome_copy(&b, &a, NULL), NEAT_OK);
    assert_int_equal(b.n_nodes, a.n_nodes);
    assert_int_equal(b.n_conns, a.n_conns);
    assert_true(b.nodes != a.nodes);
    assert_true(b.conns != a.conns);
    assert_true(b.fitness == 3.5);
    assert_int_equal(b.has_fitness, 1);
    assert_int_equal(b.species, 4);
    for (i = 0; i < a.n_conns; i++) {
        assert_int_equal(b.conns[i].innov, a.conns[i].innov);
        assert_int_equal(b.conns[i].in, a.conns[i].in);
        assert_int_equal(b.conns[i].out, a.conns[i].out);
        assert_true(b.conns[i].weight == a.conns[i].weight);
    }
    /* changing the copy leaves the original alone, and back */
    b.conns[0].weight = 99.0;
    b.nodes[0].type = NEAT_NODE_HIDDEN;
    assert_true(a.conns[0].weight == 0.0);
    assert_int_equal(a.nodes[0].type, NEAT_NODE_BIAS);
    assert_int_equal(neat_genome_add_node(&b, 50, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    assert_int_equal(a.n_nodes, 6);
    neat_genome_free(&a, NULL);
    /* the copy survives the original's free */
    assert_int_equal(b.conns[1].innov, 1);
    neat_genome_free(&b, NULL);
}

static void test_copy_into_larger_genome_shrinks_counts(void **state)
{
    neat_genome big, small;
    (void)state;
    assert_int_equal(neat_genome_recurrent_hidden(&big, 3, 2, 3, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    assert_int_equal(neat_genome_minimal(&small, 1, 1, NULL), NEAT_OK);
    assert_int_equal(neat_genome_copy(&big, &small, NULL), NEAT_OK);
    assert_int_equal(big.n_nodes, 3);
    assert_int_equal(big.n_conns, 2);
    assert_true(neat_genome_io_ok(&big, 1, 1));
    neat_genome_free(&big, NULL);
    neat_genome_free(&small, NULL);
}

/* ---- compatibility distance ---- */

static neat_params dist_params(double c1, double c2, double c3, int normalize)
{
    neat_params p = neat_params_default();
    p.c1 = c1;
    p.c2 = c2;
    p.c3 = c3;
    p.normalize_by_size = normalize;
    return p;
}

/* genes (innov, weight) all 1 -> 4 or through hidden 5 / 6: links are irrelevant to delta */
static void build_genes(neat_genome *g, const uint32_t *innov, const double *w, uint32_t n)
{
    static const uint32_t hid[2] = {5, 6};
    uint32_t i;
    build_nodes(g, 3, 1, hid, 2);
    for (i = 0; i < n; i++)
        assert_int_equal(neat_genome_add_conn(g, i % 4, 4 + i % 3, w[i], innov[i], 1, NULL), NEAT_OK);
}

static void test_distance_identical_is_zero(void **state)
{
    const uint32_t in[4] = {0, 1, 4, 9};
    const double w[4] = {0.5, -1.0, 2.0, 0.0};
    neat_genome a, b;
    neat_params p = dist_params(1, 1, 2, 0);
    (void)state;
    build_genes(&a, in, w, 4);
    build_genes(&b, in, w, 4);
    assert_true(neat_genome_distance(&a, &b, &p) == 0.0);
    assert_true(neat_genome_distance(&a, &a, &p) == 0.0);
    p.normalize_by_size = 1;
    assert_true(neat_genome_distance(&a, &b, &p) == 0.0);
    neat_genome_free(&a, NULL);
    neat_genome_free(&b, NULL);
}

static void test_distance_only_excess(void **state)
{
    /* a: 0 1 ; b: 0 1 2 3, same weights -> E = 2, D = 0, W = 0 */
    const uint32_t ia[2] = {0, 1}, ib[4] = {0, 1, 2, 3};
    const double wa[2] = {0.5, 0.5}, wb[4] = {0.5, 0.5, 1.0, -3.0};
    neat_genome a, b;
    neat_params p = dist_params(1, 1, 2, 0);
    (void)state;
    build_genes(&a, ia, wa, 2);
    build_genes(&b, ib, wb, 4);
    assert_near(neat_genome_distance(&a, &b, &p), 2.0, 1e-12);
    assert_near(neat_genome_distance(&b, &a, &p), 2.0, 1e-12);
    /* they count with c1, not c2 */
    p = dist_params(3, 100, 2, 0);
    assert_near(neat_genome_distance(&a, &b, &p), 6.0, 1e-12);
    /* N = 4 genes of the larger */
    p = dist_params(1, 1, 2, 1);
    assert_near(neat_genome_distance(&a, &b, &p), 0.5, 1e-12);
    neat_genome_free(&a, NULL);
    neat_genome_free(&b, NULL);
}

static void test_distance_disjoint_excess_weights(void **state)
{
    /*   innov:  0     1     2     3     4     5     6
     *   a:     0.5   0.2    -   -1.0    -    0.3   0.1
     *   b:     0.0    -    0.7   1.0   0.4    -     -
     * matching 0, 3: W = (|0.5 - 0| + |-1 - 1|) / 2 = 1.25
     * a's 1 (< b's last 4) and b's 2, 4 (< a's last 6): D = 3
     * a's 5, 6 (> 4): E = 2 */
    const uint32_t ia[5] = {0, 1, 3, 5, 6}, ib[4] = {0, 2, 3, 4};
    const double wa[5] = {0.5, 0.2, -1.0, 0.3, 0.1}, wb[4] = {0.0, 0.7, 1.0, 0.4};
    neat_genome a, b;
    neat_params p;
    (void)state;
    build_genes(&a, ia, wa, 5);
    build_genes(&b, ib, wb, 4);
    /* c1 = 1, c2 = 1, c3 = 2, N = 1: 2 + 3 + 2.5 */
    p = dist_params(1, 1, 2, 0);
    assert_near(neat_genome_distance(&a, &b, &p), 7.5, 1e-12);
    assert_near(neat_genome_distance(&b, &a, &p), 7.5, 1e-12);
    /* normalize_by_size: N = 5 (a is larger): 2/5 + 3/5 + 2.5 */
    p.normalize_by_size = 1;
    assert_near(neat_genome_distance(&a, &b, &p), 3.5, 1e-12);
    assert_near(neat_genome_distance(&b, &a, &p), 3.5, 1e-12);
    /* coefficients separate E, D and W: 2*2 + 0.5*3 + 1*1.25 */
    p = dist_params(2, 0.5, 1, 0);
    assert_near(neat_genome_distance(&a, &b, &p), 6.75, 1e-12);
    p = dist_params(0, 0, 1, 0);
    assert_near(neat_genome_distance(&a, &b, &p), 1.25, 1e-12);
    neat_genome_free(&a, NULL);
    neat_genome_free(&b, NULL);
}

static void test_distance_disjoint_only(void **state)
{
    /* same last innovation, interleaved middles: a: 0 1 5 ; b: 0 2 3 5 -> D = 3, E = 0 */
    const uint32_t ia[3] = {0, 1, 5}, ib[4] = {0, 2, 3, 5};
    const double wa[3] = {1.0, 0.0, 1.0}, wb[4] = {0.0, 0.0, 0.0, 1.0};
    neat_genome a, b;
    neat_params p = dist_params(100, 1, 2, 0);
    (void)state;
    build_genes(&a, ia, wa, 3);
    build_genes(&b, ib, wb, 4);
    /* W = (1 + 0) / 2 = 0.5 -> 3 + 1 */
    assert_near(neat_genome_distance(&a, &b, &p), 4.0, 1e-12);
    neat_genome_free(&a, NULL);
    neat_genome_free(&b, NULL);
}

static void test_distance_against_empty_genome(void **state)
{
    /* no matching genes: W = 0; everything of the other genome is excess */
    const uint32_t ia[3] = {2, 4, 6};
    const double wa[3] = {5.0, 5.0, 5.0};
    neat_genome a, e;
    neat_params p = dist_params(1, 10, 2, 0);
    (void)state;
    build_genes(&a, ia, wa, 3);
    build_nodes(&e, 3, 1, NULL, 0);
    assert_near(neat_genome_distance(&a, &e, &p), 3.0, 1e-12);
    assert_near(neat_genome_distance(&e, &a, &p), 3.0, 1e-12);
    assert_true(neat_genome_distance(&e, &e, &p) == 0.0);
    p.normalize_by_size = 1;
    assert_near(neat_genome_distance(&a, &e, &p), 1.0, 1e-12);
    assert_true(neat_genome_distance(&e, &e, &p) == 0.0);
    neat_genome_free(&a, NULL);
    neat_genome_free(&e, NULL);
}

static void test_distance_counts_disabled_genes(void **state)
{
    /* a disabled gene is still a gene for delta (it is part of the history) */
    const uint32_t in[2] = {0, 1};
    const double w[2] = {0.0, 0.0};
    neat_genome a, b;
    neat_params p = dist_params(1, 1, 2, 0);
    (void)state;
    build_genes(&a, in, w, 2);
    build_genes(&b, in, w, 1);
    a.conns[1].enabled = 0;
    assert_near(neat_genome_distance(&a, &b, &p), 1.0, 1e-12);
    neat_genome_free(&a, NULL);
    neat_genome_free(&b, NULL);
}

/* neat_genome_compatible (speciation's question, which may stop counting
 * early) answers exactly distance < delta_t: random genome pairs,
 * coefficients (zeros too), both normalisations, thresholds at, just
 * around, below and above each distance, and NaN and infinity. */
static void test_compatible_is_distance_below_threshold(void **state)
{
    neat_rng rng;
    int trial;
    (void)state;
    neat_rng_seed(&rng, 41);
    for (trial = 0; trial < 3000; trial++) {
        uint32_t ia[30], ib[30], na = 0, nb = 0, k, t;
        double wa[30], wb[30];
        neat_genome a, b;
        neat_params p = dist_params(neat_rng_below(&rng, 4) == 0 ? 0.0 : 3.0 * neat_rng_uniform(&rng),
                                    neat_rng_below(&rng, 4) == 0 ? 0.0 : 3.0 * neat_rng_uniform(&rng),
                                    neat_rng_below(&rng, 4) == 0 ? 0.0 : 3.0 * neat_rng_uniform(&rng),
                                    (int)neat_rng_below(&rng, 2));
        double d, th[9];
        for (k = 0; k < 30; k++) {
            if (neat_rng_below(&rng, 3) != 0) {
                ia[na] = k;
                wa[na++] = 6.0 * neat_rng_uniform(&rng) - 3.0;
            }
            if (neat_rng_below(&rng, 3) != 0) {
                ib[nb] = k;
                wb[nb++] = 6.0 * neat_rng_uniform(&rng) - 3.0;
            }
        }
        na -= neat_rng_below(&rng, na + 1) / 2; /* some shorter, so excess genes too */
        build_genes(&a, ia, wa, na);
        build_genes(&b, ib, wb, nb);
        d = neat_genome_distance(&a, &b, &p);
        th[0] = d;
        th[1] = nextafter(d, HUGE_VAL);
        th[2] = nextafter(d, -HUGE_VAL);
        th[3] = d * neat_rng_uniform(&rng);
        th[4] = d + 1.0;
        th[5] = NAN;
        th[6] = HUGE_VAL;
        th[7] = 0.5 * neat_rng_uniform(&rng);
        th[8] = 3.0 * neat_rng_uniform(&rng);
        for (t = 0; t < 9; t++) {
            if (neat_genome_compatible(&a, &b, &p, th[t]) != (d < th[t]))
                fail_msg("trial %d threshold %u: distance %.17g, threshold %.17g", trial, t, d, th[t]);
            if (neat_genome_compatible(&b, &a, &p, th[t]) != (neat_genome_distance(&b, &a, &p) < th[t]))
                fail_msg("trial %d threshold %u, swapped", trial, t);
        }
        neat_genome_free(&a, NULL);
        neat_genome_free(&b, NULL);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_minimal_layout),
        cmocka_unit_test(test_minimal_one_input_one_output),
        cmocka_unit_test(test_recurrent_hidden_counts),
        cmocka_unit_test(test_add_node_keeps_ids_sorted),
        cmocka_unit_test(test_add_node_rejects_duplicate),
        cmocka_unit_test(test_add_node_rejects_bad_type),
        cmocka_unit_test(test_add_conn_keeps_innovation_order),
        cmocka_unit_test(test_add_conn_stores_fields),
        cmocka_unit_test(test_add_conn_rejects_duplicate_innovation),
        cmocka_unit_test(test_add_conn_rejects_into_bias_or_input),
        cmocka_unit_test(test_add_conn_rejects_missing_node),
        cmocka_unit_test(test_copy_is_deep),
        cmocka_unit_test(test_copy_into_larger_genome_shrinks_counts),
        cmocka_unit_test(test_distance_identical_is_zero),
        cmocka_unit_test(test_distance_only_excess),
        cmocka_unit_test(test_distance_disjoint_excess_weights),
        cmocka_unit_test(test_distance_disjoint_only),
        cmocka_unit_test(test_distance_against_empty_genome),
        cmocka_unit_test(test_distance_counts_disabled_genes),
        cmocka_unit_test(test_compatible_is_distance_below_threshold),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
