/* test_step.c - the runtime's synchronous fixed-point step, reset and settle on hand-built genomes. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "neat.h"
#include "nrt.h"

/* Q3.12 weight as the blob writer rounds it. */
#define ST_W12(w) ((int32_t)floor((w) * 4096.0 + 0.5))

typedef struct st_rt {
    uint8_t blob[4096];
    size_t len;
    uint64_t mem[1024];
    nrt_net net;
} st_rt;

/* Nodes with the genome's ids: bias 0, inputs 1..n_in, outputs next, hidden after. */
static void st_nodes(neat_genome *g, uint32_t n_in, uint32_t n_out, uint32_t n_hid)
{
    uint32_t i, n = n_in + 1 + n_out + n_hid;
    neat_genome_init(g);
    for (i = 0; i < n; i++) {
        int type = i == 0 ? NEAT_NODE_BIAS
                   : i <= n_in ? NEAT_NODE_INPUT
                   : i <= n_in + n_out ? NEAT_NODE_OUTPUT : NEAT_NODE_HIDDEN;
        assert_int_equal(neat_genome_add_node(g, i, type, NULL), NEAT_OK);
    }
}

static void st_conn(neat_genome *g, uint32_t in, uint32_t out, double w)
{
    assert_int_equal(neat_genome_add_conn(g, in, out, w, g->n_conns, 1, NULL), NEAT_OK);
}

/* Genome -> blob -> loaded net; frees the genome. */
static void st_load(st_rt *rt, neat_genome *g, uint32_t n_in, uint32_t n_out)
{
    size_t need = 0;
    assert_int_equal(neat_blob_write(g, n_in, n_out, rt->blob, sizeof rt->blob, &rt->len), NEAT_OK);
    assert_int_equal(nrt_mem_required(rt->blob, rt->len, &need), NRT_OK);
    assert_true(need <= sizeof rt->mem);
    assert_int_equal(nrt_load(&rt->net, rt->blob, rt->len, rt->mem, sizeof rt->mem), NRT_OK);
    neat_genome_free(g, NULL);
}

static double st_sig(double x)
{
    return 1.0 / (1.0 + exp(-4.9 * x));
}

/* xorshift32 (Marsaglia): the test's own reproducible pseudo-random source. */
static uint32_t st_xorshift(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *s = x;
    return x;
}

/* A double-precision network with the runtime's synchronous rule: every
 * non-input node's new value from the previous step's values, inputs given now. */
#define ST_REF_MAX 64
#define ST_REF_CONNS 256
typedef struct st_ref {
    uint32_t n_in, n_nodes, n_conns; /* n_in counts the bias */
    uint32_t src[ST_REF_CONNS], dst[ST_REF_CONNS];
    double w[ST_REF_CONNS];
    double act[ST_REF_MAX];
} st_ref;

/* The reference of a genome whose nodes are ids 0..n-1 in runtime order, with its weights quantised to Q3.12. */
static void st_ref_init(st_ref *r, const neat_genome *g, uint32_t n_in)
{
    uint32_t k;
    memset(r, 0, sizeof *r);
    assert_true(g->n_nodes <= ST_REF_MAX && g->n_conns <= ST_REF_CONNS);
    r->n_in = n_in + 1;
    r->n_nodes = g->n_nodes;
    for (k = 0; k < g->n_conns; k++) {
        if (!g->conns[k].enabled)
            continue;
        r->src[r->n_conns] = g->conns[k].in;
        r->dst[r->n_conns] = g->conns[k].out;
        r->w[r->n_conns] = (double)ST_W12(g->conns[k].weight) / 4096.0;
        r->n_conns++;
    }
}

static void st_ref_step(st_ref *r, const nrt_q15 *in)
{
    double sum[ST_REF_MAX];
    uint32_t j, k;
    for (j = 0; j < r->n_in; j++)
        r->act[j] = (double)in[j] / 32768.0;
    memset(sum, 0, sizeof sum);
    for (k = 0; k < r->n_conns; k++)
        sum[r->dst[k]] += r->w[k] * r->act[r->src[k]];
    for (j = r->n_in; j < r->n_nodes; j++)
        r->act[j] = st_sig(sum[j]);
}

/* input -> hidden -> output: the input reaches the output on the second step, not the first. */
static void test_chain_needs_two_steps(void **state)
{
    static st_rt rt;
    neat_genome g;
    nrt_q15 in[2] = {NRT_ONE, 20000}, out[1];
    int32_t h;
    (void)state;
    st_nodes(&g, 1, 1, 1); /* bias 0, input 1, output 2, hidden 3 */
    st_conn(&g, 1, 3, 2.0);
    st_conn(&g, 3, 2, 3.0);
    st_load(&rt, &g, 1, 1);
    nrt_step(&rt.net, in, out);
    assert_int_equal(out[0], 16384); /* the hidden node's activation was still 0 */
    h = nrt_sigmoid((int64_t)ST_W12(2.0) * in[1]);
    nrt_step(&rt.net, in, out);
    assert_int_equal(out[0], nrt_sigmoid((int64_t)ST_W12(3.0) * h));
    assert_true(out[0] > 16384 + 8000);
    nrt_step(&rt.net, in, out);
    assert_int_equal(out[0], nrt_sigmoid((int64_t)ST_W12(3.0) * h)); /* steady */
}

/* A latch (hidden node with a strong self connection) built for the memory tests:
 * bias 0, input 1, output 2, hidden 3. */
static void st_latch(neat_genome *g)
{
    st_nodes(g, 1, 1, 1);
    st_conn(g, 0, 3, -3.0);
    st_conn(g, 1, 3, 6.0);
    st_conn(g, 3, 3, 6.0);
    st_conn(g, 3, 2, 1.0);
    st_conn(g, 0, 2, -0.5);
}

/* A self-recurrent node remembers a one-step pulse; outputs match the double-precision reference within 3e-4. */
static void test_self_recurrent_memory(void **state)
{
    static st_rt rt;
    neat_genome g;
    st_ref ref;
    nrt_q15 in[2], out[1];
    double before = 0.0, max_err = 0.0;
    int t;
    (void)state;
    st_latch(&g);
    st_ref_init(&ref, &g, 1);
    st_load(&rt, &g, 1, 1);
    in[0] = NRT_ONE;
    for (t = 0; t < 40; t++) {
        double err;
        in[1] = t == 10 ? NRT_ONE : 0; /* a pulse at step 10 only */
        nrt_step(&rt.net, in, out);
        st_ref_step(&ref, in);
        err = fabs((double)out[0] / 32768.0 - ref.act[2]);
        if (err > max_err)
            max_err = err;
        if (t == 9)
            before = (double)out[0] / 32768.0;
        if (t >= 12) /* the pulse is gone but the hidden node still holds it */
            assert_true((double)out[0] / 32768.0 > before + 0.2);
    }
    assert_true(before < 0.2);
    printf("latch: max |runtime - double| = %.3e over 40 steps\n", max_err);
    assert_true(max_err < 3e-4);
}

/* A leaky self-recurrent node (mid-range, not saturated) tracks the double reference within 3e-4.
 * The loop gains stay below 1 so rounding errors decay instead of adding up. */
static void test_self_recurrent_matches_reference(void **state)
{
    static st_rt rt;
    neat_genome g;
    st_ref ref;
    nrt_q15 in[2], out[1];
    double max_err = 0.0;
    uint32_t seed = 12345u;
    int t;
    (void)state;
    st_nodes(&g, 1, 1, 1);
    st_conn(&g, 0, 3, -0.4);
    st_conn(&g, 1, 3, 0.7);
    st_conn(&g, 3, 3, 0.6);
    st_conn(&g, 3, 2, 0.6);
    st_conn(&g, 2, 2, -0.3); /* the output is recurrent too */
    st_conn(&g, 0, 2, -0.3);
    st_ref_init(&ref, &g, 1);
    st_load(&rt, &g, 1, 1);
    in[0] = NRT_ONE;
    for (t = 0; t < 100; t++) {
        double err;
        in[1] = (nrt_q15)((int32_t)(st_xorshift(&seed) % 65536u) - 32768);
        nrt_step(&rt.net, in, out);
        st_ref_step(&ref, in);
        err = fabs((double)out[0] / 32768.0 - ref.act[2]);
        if (err > max_err)
            max_err = err;
    }
    printf("leaky recurrent node: max |runtime - double| = %.3e over 100 steps\n", max_err);
    assert_true(max_err < 3e-4);
}

/* After nrt_reset the same inputs give the same output sequence again. */
static void test_reset_restores_initial_behaviour(void **state)
{
    static st_rt rt;
    neat_genome g;
    nrt_q15 in[4], first[30][2], out[2];
    uint32_t i, seed;
    int t, pass;
    (void)state;
    assert_int_equal(neat_genome_recurrent_hidden(&g, 3, 2, 3, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    for (i = 0; i < g.n_conns; i++)
        g.conns[i].weight = ((double)((i * 5u) % 11u) - 5.0) * 0.45;
    st_load(&rt, &g, 3, 2);
    for (pass = 0; pass < 2; pass++) {
        if (pass == 1)
            nrt_reset(&rt.net);
        seed = 777u;
        for (t = 0; t < 30; t++) {
            in[0] = NRT_ONE;
            for (i = 1; i < 4; i++)
                in[i] = (nrt_q15)((int32_t)(st_xorshift(&seed) % 65536u) - 32768);
            nrt_step(&rt.net, in, out);
            if (pass == 0) {
                memcpy(first[t], out, sizeof out);
            } else {
                assert_int_equal(out[0], first[t][0]);
                assert_int_equal(out[1], first[t][1]);
            }
        }
    }
    /* and the state really was changed before the reset */
    assert_true(first[0][0] != first[29][0] || first[0][1] != first[29][1]);
}

/* nrt_reset zeroes every hidden and output activation. */
static void test_reset_zeroes_activations(void **state)
{
    static st_rt rt;
    neat_genome g;
    nrt_q15 in[2] = {NRT_ONE, NRT_ONE}, out[1];
    uint32_t j;
    (void)state;
    st_latch(&g);
    st_load(&rt, &g, 1, 1);
    nrt_step(&rt.net, in, out);
    nrt_step(&rt.net, in, out);
    nrt_reset(&rt.net);
    for (j = 0; j < rt.net.n_nodes; j++) {
        assert_int_equal(rt.net.act[0][j], 0);
        assert_int_equal(rt.net.act[1][j], 0);
    }
}

/* XOR: bias 0, inputs 1, 2, output 3, hidden 4 (OR-like) and 5 (AND-like); depth 2. */
static void st_xor(st_rt *rt)
{
    neat_genome g;
    st_nodes(&g, 2, 1, 2);
    st_conn(&g, 1, 4, 2.0);
    st_conn(&g, 2, 4, 2.0);
    st_conn(&g, 0, 4, -1.0);
    st_conn(&g, 1, 5, 2.0);
    st_conn(&g, 2, 5, 2.0);
    st_conn(&g, 0, 5, -3.0);
    st_conn(&g, 4, 3, 4.0);
    st_conn(&g, 5, 3, -4.0);
    st_conn(&g, 0, 3, -2.0);
    st_load(rt, &g, 2, 1);
}

/* nrt_settle on a feed-forward XOR: at most depth + 1 (<= nodes) steps, right answers, with and without reset. */
static void test_settle_xor(void **state)
{
    static st_rt rt;
    int p, s, reset;
    (void)state;
    st_xor(&rt);
    for (reset = 1; reset >= 0; reset--) {
        for (p = 0; p < 4; p++) {
            nrt_q15 in[3], out[1];
            int a = p & 1, b = p >> 1;
            in[0] = NRT_ONE;
            in[1] = a ? NRT_ONE : 0;
            in[2] = b ? NRT_ONE : 0;
            if (reset)
                nrt_reset(&rt.net);
            s = nrt_settle(&rt.net, in, out, 10);
            assert_true(s >= 1 && s <= 3);
            assert_true(s <= rt.net.n_nodes);
            if (a != b)
                assert_true(out[0] >= 16384);
            else
                assert_true(out[0] < 16384);
        }
    }
}

/* nrt_settle returns -1 when max_steps is smaller than the network's depth needs; outputs hold the last step. */
static void test_settle_too_few_steps(void **state)
{
    static st_rt rt;
    nrt_q15 in[3] = {NRT_ONE, NRT_ONE, 0}, out[1];
    (void)state;
    st_xor(&rt);
    assert_int_equal(nrt_settle(&rt.net, in, out, 1), -1);
    /* one step: the hidden nodes were still 0, so the output saw only the bias */
    assert_int_equal(out[0], nrt_sigmoid((int64_t)ST_W12(-2.0) * NRT_ONE));
    nrt_reset(&rt.net);
    assert_int_equal(nrt_settle(&rt.net, in, out, 2), -1);
    assert_true(out[0] >= 16384); /* the second step already gives the answer, but it was a change */
    nrt_reset(&rt.net);
    assert_int_equal(nrt_settle(&rt.net, in, out, 0), -1);
    assert_int_equal(nrt_settle(&rt.net, in, out, 3), 3);
}

/* Nodes without incoming connections output sigmoid(0) = 16384 after one step, and neighbours still compute right. */
static void test_unconnected_node(void **state)
{
    static st_rt rt;
    neat_genome g;
    nrt_q15 in[3] = {NRT_ONE, 12000, -7000}, out[3];
    int32_t want_mid;
    (void)state;
    /* bias 0, inputs 1-2, outputs 3 (none), 4 (from input 1 and hidden 6), 5 (none), hidden 6 (none), 7 (from input 2) */
    st_nodes(&g, 2, 3, 2);
    st_conn(&g, 1, 4, 1.5);
    st_conn(&g, 6, 4, -2.0);
    st_conn(&g, 2, 7, 1.0);
    st_load(&rt, &g, 2, 3);
    assert_int_equal(rt.net.act[rt.net.cur][3], 0);
    nrt_step(&rt.net, in, out);
    assert_int_equal(out[0], 16384);
    assert_int_equal(out[2], 16384);
    assert_int_equal(out[1], nrt_sigmoid((int64_t)ST_W12(1.5) * in[1])); /* hidden 6 was still 0 */
    nrt_step(&rt.net, in, out);
    assert_int_equal(out[0], 16384);
    assert_int_equal(out[2], 16384);
    want_mid = nrt_sigmoid((int64_t)ST_W12(1.5) * in[1] + (int64_t)ST_W12(-2.0) * 16384);
    assert_int_equal(out[1], want_mid);
}

/* A random 200-connection recurrent network over 200 steps stays within 2e-3 of the double reference.
 * Weights in [-0.75, 0.75]: with much larger ones the network is chaotic and
 * any rounding difference, fixed point or not, grows without bound. */
static void test_random_recurrent_matches_reference(void **state)
{
    enum { IN = 4, OUT = 3, HID = 13, NODES = IN + 1 + OUT + HID, CONNS = 200, STEPS = 200 };
    static st_rt rt;
    neat_genome g;
    st_ref ref;
    uint8_t used[NODES][NODES];
    nrt_q15 in[IN + 1], out[OUT];
    uint32_t seed = 0xC0FFEEu, i;
    double max_err = 0.0, sum_err = 0.0;
    int t;
    (void)state;
    st_nodes(&g, IN, OUT, HID);
    memset(used, 0, sizeof used);
    while (g.n_conns < CONNS) {
        uint32_t s = st_xorshift(&seed) % NODES;
        uint32_t d = IN + 1 + st_xorshift(&seed) % (NODES - IN - 1);
        double w = ((double)(st_xorshift(&seed) % 2000001u) / 1000000.0 - 1.0) * 0.75; /* [-0.75, 0.75] */
        if (used[s][d])
            continue;
        used[s][d] = 1;
        st_conn(&g, s, d, w);
    }
    st_ref_init(&ref, &g, IN);
    st_load(&rt, &g, IN, OUT);
    assert_int_equal(rt.net.n_conns, CONNS);
    for (t = 0; t < STEPS; t++) {
        in[0] = NRT_ONE;
        for (i = 1; i <= IN; i++)
            in[i] = (nrt_q15)((int32_t)(st_xorshift(&seed) % 65536u) - 32768);
        nrt_step(&rt.net, in, out);
        st_ref_step(&ref, in);
        for (i = 0; i < OUT; i++) {
            double err = fabs((double)out[i] / 32768.0 - ref.act[IN + 1 + i]);
            sum_err += err;
            if (err > max_err)
                max_err = err;
        }
    }
    printf("random 200-connection network: max |runtime - double| = %.3e, mean %.3e over %d steps\n", max_err,
           sum_err / (STEPS * OUT), STEPS);
    assert_true(max_err < 2e-3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_needs_two_steps),
        cmocka_unit_test(test_self_recurrent_memory),
        cmocka_unit_test(test_self_recurrent_matches_reference),
        cmocka_unit_test(test_reset_restores_initial_behaviour),
        cmocka_unit_test(test_reset_zeroes_activations),
        cmocka_unit_test(test_settle_xor),
        cmocka_unit_test(test_settle_too_few_steps),
        cmocka_unit_test(test_unconnected_node),
        cmocka_unit_test(test_random_recurrent_matches_reference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
