/* test_crossover.c - crossover lined up by innovation number: the paper's Figure 4, gene by gene. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "neat_internal.h"

/* Figure 4 of Stanley & Miikkulainen (2004). Node ids as in the figure:
 * inputs 1, 2, 3, output 4, hidden 5 (and 6 in parent 2); libneat adds
 * the bias 0, which has no genes here. */
typedef struct fig_gene {
    uint32_t innov, in, out;
    int enabled;
} fig_gene;

static const fig_gene parent1_genes[] = {
    {1, 1, 4, 1}, {2, 2, 4, 0}, {3, 3, 4, 1}, {4, 2, 5, 1}, {5, 5, 4, 1}, {8, 1, 5, 1},
};
static const fig_gene parent2_genes[] = {
    {1, 1, 4, 1}, {2, 2, 4, 0}, {3, 3, 4, 1}, {4, 2, 5, 1}, {5, 5, 4, 0},
    {6, 5, 6, 1}, {7, 6, 4, 1}, {9, 3, 5, 1}, {10, 1, 6, 1},
};
/* the offspring of the figure: every gene, 2 and 5 disabled */
static const fig_gene offspring_genes[] = {
    {1, 1, 4, 1}, {2, 2, 4, 0}, {3, 3, 4, 1}, {4, 2, 5, 1}, {5, 5, 4, 0},
    {6, 5, 6, 1}, {7, 6, 4, 1}, {8, 1, 5, 1}, {9, 3, 5, 1}, {10, 1, 6, 1},
};
#define N_OF(a) (sizeof(a) / sizeof((a)[0]))

/* weights tell the parents apart: parent 1 gene i has +i/8, parent 2 -i/16 */
static double p1_weight(uint32_t innov)
{
    return innov / 8.0;
}

static double p2_weight(uint32_t innov)
{
    return -(innov / 16.0);
}

static void build_parent(neat_genome *g, const fig_gene *genes, size_t n, int with_node6, double (*w)(uint32_t),
                         double fitness)
{
    uint32_t i;
    size_t k;
    neat_genome_init(g);
    assert_int_equal(neat_genome_add_node(g, 0, NEAT_NODE_BIAS, NULL), NEAT_OK);
    for (i = 1; i <= 3; i++)
        assert_int_equal(neat_genome_add_node(g, i, NEAT_NODE_INPUT, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 4, NEAT_NODE_OUTPUT, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 5, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    if (with_node6)
        assert_int_equal(neat_genome_add_node(g, 6, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    for (k = 0; k < n; k++)
        assert_int_equal(neat_genome_add_conn(g, genes[k].in, genes[k].out, w(genes[k].innov), genes[k].innov,
                                              genes[k].enabled, NULL),
                         NEAT_OK);
    assert_true(neat_genome_io_ok(g, 3, 1));
    g->fitness = fitness;
    g->has_fitness = 1;
}

static void build_parents(neat_genome *p1, neat_genome *p2, double f1, double f2)
{
    build_parent(p1, parent1_genes, N_OF(parent1_genes), 0, p1_weight, f1);
    build_parent(p2, parent2_genes, N_OF(parent2_genes), 1, p2_weight, f2);
}

static neat_params fig_params(double excess_equal_prob, double disable_prob)
{
    neat_params p = neat_params_default();
    p.n_inputs = 3;
    p.n_outputs = 1;
    p.excess_equal_prob = excess_equal_prob;
    p.disable_prob = disable_prob;
    return p;
}

static int in_parent(const fig_gene *genes, size_t n, uint32_t innov)
{
    size_t k;
    for (k = 0; k < n; k++)
        if (genes[k].innov == innov)
            return 1;
    return 0;
}

/* child has exactly the genes want[] (innovation order, endpoints,
 * enabled flags) and the nodes they need */
static void assert_genes(const neat_genome *c, const fig_gene *want, size_t n)
{
    uint32_t i;
    assert_int_equal(c->n_conns, n);
    for (i = 0; i < c->n_conns; i++) {
        assert_int_equal(c->conns[i].innov, want[i].innov);
        assert_int_equal(c->conns[i].in, want[i].in);
        assert_int_equal(c->conns[i].out, want[i].out);
        assert_int_equal(c->conns[i].enabled, want[i].enabled);
    }
    assert_true(neat_genome_io_ok(c, 3, 1));
    for (i = 0; i < c->n_conns; i++) {
        assert_non_null(neat_genome_find_node(c, c->conns[i].in));
        assert_non_null(neat_genome_find_node(c, c->conns[i].out));
    }
    assert_int_equal(c->has_fitness, 0);
}

static void test_figure4_offspring_genes(void **state)
{
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 1.0);
    neat_rng rng;
    uint32_t seed, i, from1 = 0, from2 = 0;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    for (seed = 0; seed < 64; seed++) {
        neat_rng_seed(&rng, seed);
        /* either parent as mom */
        if (seed % 2 == 0)
            assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
        else
            assert_int_equal(neat_crossover(&child, &p2, &p1, 0, &p, &rng, NULL), NEAT_OK);
        assert_genes(&child, offspring_genes, N_OF(offspring_genes));
        /* nodes: bias, 1..3, 4, 5, 6 */
        assert_int_equal(child.n_nodes, 7);
        assert_int_equal(neat_genome_find_node(&child, 5)->type, NEAT_NODE_HIDDEN);
        assert_int_equal(neat_genome_find_node(&child, 6)->type, NEAT_NODE_HIDDEN);
        for (i = 0; i < child.n_conns; i++) {
            uint32_t in1, in2, v = child.conns[i].innov;
            double w = child.conns[i].weight;
            in1 = (uint32_t)in_parent(parent1_genes, N_OF(parent1_genes), v);
            in2 = (uint32_t)in_parent(parent2_genes, N_OF(parent2_genes), v);
            if (in1 && in2) {
                /* matching: one parent's weight, chosen at random */
                assert_true(w == p1_weight(v) || w == p2_weight(v));
                from1 += w == p1_weight(v);
                from2 += w == p2_weight(v);
            } else {
                /* disjoint / excess: its owner's weight */
                assert_true(w == (in1 ? p1_weight(v) : p2_weight(v)));
            }
        }
    }
    /* both parents contributed matching weights */
    assert_true(from1 > 50);
    assert_true(from2 > 50);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_figure4_average_weights(void **state)
{
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 1.0);
    neat_rng rng;
    uint32_t i;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 3);
    assert_int_equal(neat_crossover(&child, &p1, &p2, 1, &p, &rng, NULL), NEAT_OK);
    assert_genes(&child, offspring_genes, N_OF(offspring_genes));
    for (i = 0; i < child.n_conns; i++) {
        uint32_t v = child.conns[i].innov;
        double w = child.conns[i].weight;
        if (v <= 5)
            assert_true(w == 0.5 * (p1_weight(v) + p2_weight(v)));
        else if (v == 8)
            assert_true(w == p1_weight(v));
        else
            assert_true(w == p2_weight(v));
    }
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_fitter_parent1_gives_its_disjoint_and_excess(void **state)
{
    /* parent 1 fitter: 1..5 matching, 8 its disjoint; 6, 7, 9, 10 dropped */
    static const fig_gene want[] = {
        {1, 1, 4, 1}, {2, 2, 4, 0}, {3, 3, 4, 1}, {4, 2, 5, 1}, {5, 5, 4, 0}, {8, 1, 5, 1},
    };
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 1.0);
    neat_rng rng;
    uint64_t seed;
    (void)state;
    build_parents(&p1, &p2, 2.0, 1.0);
    neat_genome_init(&child);
    for (seed = 0; seed < 16; seed++) {
        neat_rng_seed(&rng, seed);
        assert_int_equal(neat_crossover(&child, seed % 2 ? &p2 : &p1, seed % 2 ? &p1 : &p2, 0, &p, &rng, NULL),
                         NEAT_OK);
        assert_genes(&child, want, N_OF(want));
        /* node 6 was only used by parent 2's dropped genes */
        assert_int_equal(child.n_nodes, 6);
        assert_null(neat_genome_find_node(&child, 6));
    }
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_fitter_parent2_gives_its_disjoint_and_excess(void **state)
{
    static const fig_gene want[] = {
        {1, 1, 4, 1}, {2, 2, 4, 0}, {3, 3, 4, 1}, {4, 2, 5, 1}, {5, 5, 4, 0},
        {6, 5, 6, 1}, {7, 6, 4, 1}, {9, 3, 5, 1}, {10, 1, 6, 1},
    };
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 1.0);
    neat_rng rng;
    uint64_t seed;
    (void)state;
    build_parents(&p1, &p2, 0.5, 3.0);
    neat_genome_init(&child);
    for (seed = 0; seed < 16; seed++) {
        neat_rng_seed(&rng, seed);
        assert_int_equal(neat_crossover(&child, seed % 2 ? &p2 : &p1, seed % 2 ? &p1 : &p2, 0, &p, &rng, NULL),
                         NEAT_OK);
        assert_genes(&child, want, N_OF(want));
        assert_int_equal(child.n_nodes, 7);
    }
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_equal_fitness_no_excess_keeps_matching_only(void **state)
{
    static const fig_gene want[] = {{1, 1, 4, 1}, {2, 2, 4, 0}, {3, 3, 4, 1}, {4, 2, 5, 1}, {5, 5, 4, 0}};
    neat_genome p1, p2, child;
    neat_params p = fig_params(0.0, 1.0);
    neat_rng rng;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 1);
    assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
    assert_genes(&child, want, N_OF(want));
    assert_int_equal(child.n_nodes, 6);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_equal_fitness_excess_kept_at_rate(void **state)
{
    /* excess_equal_prob 0.5: each of 6, 7, 8, 9, 10 in about half the children */
    neat_genome p1, p2, child;
    neat_params p = fig_params(0.5, 1.0);
    neat_rng rng;
    uint32_t kept[11] = {0}, i, t, n = 2000;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 17);
    for (t = 0; t < n; t++) {
        assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
        for (i = 0; i < child.n_conns; i++)
            kept[child.conns[i].innov]++;
        /* whatever was dropped, the child is consistent */
        assert_true(neat_genome_io_ok(&child, 3, 1));
        for (i = 0; i < child.n_conns; i++)
            assert_non_null(neat_genome_find_node(&child, child.conns[i].out));
    }
    for (i = 1; i <= 5; i++)
        assert_int_equal(kept[i], n);
    for (i = 6; i <= 10; i++)
        assert_true(kept[i] > n * 45 / 100 && kept[i] < n * 55 / 100);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_disable_prob_zero_reenables(void **state)
{
    /* disabled in either parent is only a chance of staying disabled: with
     * 0.0, gene 5 (disabled in parent 2) and gene 2 (in both) come back */
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 0.0);
    neat_rng rng;
    uint32_t i;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 2);
    assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
    assert_int_equal(child.n_conns, 10);
    for (i = 0; i < child.n_conns; i++)
        assert_int_equal(child.conns[i].enabled, 1);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_disable_prob_rate(void **state)
{
    /* the paper's 75%: gene 5 stays disabled in about three children of four */
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 0.75);
    neat_rng rng;
    uint32_t t, off = 0, n = 2000;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 23);
    for (t = 0; t < n; t++) {
        assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
        assert_int_equal(child.conns[4].innov, 5);
        off += child.conns[4].enabled == 0;
        /* genes enabled in both parents are always enabled */
        assert_int_equal(child.conns[0].enabled, 1);
        assert_int_equal(child.conns[3].enabled, 1);
    }
    assert_true(off > n * 70 / 100 && off < n * 80 / 100);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_self_crossover_is_a_copy(void **state)
{
    neat_genome p1, p2, child;
    neat_params p = fig_params(0.5, 1.0);
    neat_rng rng;
    uint32_t i;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 4);
    assert_int_equal(neat_crossover(&child, &p2, &p2, 0, &p, &rng, NULL), NEAT_OK);
    assert_genes(&child, parent2_genes, N_OF(parent2_genes));
    for (i = 0; i < child.n_conns; i++)
        assert_true(child.conns[i].weight == p2.conns[i].weight);
    assert_int_equal(child.n_nodes, p2.n_nodes);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_same_link_twice_inherited_once(void **state)
{
    /* 3 -> 5 arose twice (innovation 9 in parent 2, 12 in parent 1, in
     * different generations): the child keeps one gene per link */
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 1.0);
    neat_rng rng;
    uint32_t i, links = 0;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    assert_int_equal(neat_genome_add_conn(&p1, 3, 5, 0.3, 12, 1, NULL), NEAT_OK);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 5);
    assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
    for (i = 0; i < child.n_conns; i++)
        links += child.conns[i].in == 3 && child.conns[i].out == 5;
    assert_int_equal(links, 1);
    assert_int_equal(child.n_conns, 10);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_union_over_max_nodes_gives_fitter_parent(void **state)
{
    /* the union needs 7 nodes; with max_nodes 6 the child is the fitter
     * parent (mom at equal fitness) */
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 1.0);
    neat_rng rng;
    uint32_t i;
    (void)state;
    p.max_nodes = 6;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    neat_rng_seed(&rng, 6);
    assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
    assert_genes(&child, parent1_genes, N_OF(parent1_genes));
    for (i = 0; i < child.n_conns; i++)
        assert_true(child.conns[i].weight == p1.conns[i].weight);
    assert_true(child.n_nodes <= p.max_nodes);
    assert_true(child.fitness == 0.0);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

static void test_child_buffer_reused(void **state)
{
    /* a child genome that held a bigger genome is overwritten, not appended to */
    neat_genome p1, p2, child;
    neat_params p = fig_params(1.0, 1.0);
    neat_rng rng;
    (void)state;
    build_parents(&p1, &p2, 1.0, 1.0);
    neat_genome_init(&child);
    assert_int_equal(neat_genome_recurrent_hidden(&child, 3, 1, 10, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    child.fitness = 9.0;
    child.has_fitness = 1;
    neat_rng_seed(&rng, 7);
    assert_int_equal(neat_crossover(&child, &p1, &p2, 0, &p, &rng, NULL), NEAT_OK);
    assert_genes(&child, offspring_genes, N_OF(offspring_genes));
    assert_int_equal(child.n_nodes, 7);
    assert_true(child.fitness == 0.0);
    neat_genome_free(&child, NULL);
    neat_genome_free(&p1, NULL);
    neat_genome_free(&p2, NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_figure4_offspring_genes),
        cmocka_unit_test(test_figure4_average_weights),
        cmocka_unit_test(test_fitter_parent1_gives_its_disjoint_and_excess),
        cmocka_unit_test(test_fitter_parent2_gives_its_disjoint_and_excess),
        cmocka_unit_test(test_equal_fitness_no_excess_keeps_matching_only),
        cmocka_unit_test(test_equal_fitness_excess_kept_at_rate),
        cmocka_unit_test(test_disable_prob_zero_reenables),
        cmocka_unit_test(test_disable_prob_rate),
        cmocka_unit_test(test_self_crossover_is_a_copy),
        cmocka_unit_test(test_same_link_twice_inherited_once),
        cmocka_unit_test(test_union_over_max_nodes_gives_fitter_parent),
        cmocka_unit_test(test_child_buffer_reused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
