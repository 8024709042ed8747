/* test_dense.c - the dense AVX2 step (nrt_dense.h) against nrt_step: the same activations on random networks, and what it refuses. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "nrt.h"
#include "nrt_dense.h"

#define TD_MAX_CONNS (NRT_DENSE_MAX_NODES * NRT_DENSE_MAX_NODES)

/* A network built in place (nrt_net's fields are public): what nrt_load
 * would give for the same connections. */
typedef struct td_net {
    nrt_net net;
    nrt_w12 weight[TD_MAX_CONNS];
    uint16_t src[TD_MAX_CONNS], end[NRT_DENSE_MAX_NODES];
    nrt_q15 act[2][NRT_DENSE_MAX_NODES + 1];
} td_net;

static uint32_t td_next(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return *s;
}

/* Weights and inputs at the extremes a quarter of the time: the sums reach
 * the saturation of the sigmoid, and the exact pair bound (2^31 - 2^16). */
static int16_t td_value(uint32_t *s, int lowest)
{
    uint32_t r = td_next(s);
    switch (r & 7u) {
    case 0:
        return 32767;
    case 1:
        return (int16_t)lowest;
    default:
        return (int16_t)(int32_t)((r >> 8) % 65535u) - 32767;
    }
}

/* Every node sees each earlier node and itself with probability density /
 * 8 (recurrent links too, as nrt_step allows: any non-input target). */
static void td_make(td_net *t, uint32_t n_in, uint32_t n_out, uint32_t n_hid, uint32_t density, uint32_t *seed)
{
    uint32_t n = n_in + n_out + n_hid, j, i, k = 0;
    memset(t, 0, sizeof *t);
    for (j = 0; j < n - n_in; j++) {
        for (i = 0; i < n; i++)
            if ((td_next(seed) & 7u) < density) {
                t->src[k] = (uint16_t)i;
                t->weight[k] = td_value(seed, -32767);
                k++;
            }
        t->end[j] = (uint16_t)k;
    }
    t->net.n_inputs = (uint16_t)n_in;
    t->net.n_outputs = (uint16_t)n_out;
    t->net.n_hidden = (uint16_t)n_hid;
    t->net.n_nodes = (uint16_t)n;
    t->net.n_conns = (uint16_t)k;
    t->net.weight = t->weight;
    t->net.src = t->src;
    t->net.end = t->end;
    t->net.act[0] = t->act[0];
    t->net.act[1] = t->act[1];
}

/* b: a copy of a, its net pointing at b's own arrays */
static void td_copy(td_net *b, const td_net *a)
{
    memcpy(b, a, sizeof *a);
    b->net.weight = b->weight;
    b->net.src = b->src;
    b->net.end = b->end;
    b->net.act[0] = b->act[0];
    b->net.act[1] = b->act[1];
}

/* Keeps only the connections inside a random choice of 8-row by 16-column
 * tiles (rows 8g..8g+7 keep the source blocks of a random mask each), as a
 * NEAT network's hidden rows see few of the columns: the dense step skips
 * the empty tiles. */
static void td_thin(td_net *t, uint32_t *seed)
{
    uint32_t j, k = 0, kept = 0, mask = 0;
    for (j = 0; j < (uint32_t)t->net.n_nodes - t->net.n_inputs; j++) {
        if (j % 8u == 0)
            mask = td_next(seed) & 15u;
        for (; k < t->end[j]; k++)
            if (mask & (1u << (t->src[k] / 16u))) {
                t->src[kept] = t->src[k];
                t->weight[kept++] = t->weight[k];
            }
        t->end[j] = (uint16_t)kept;
    }
    t->net.n_conns = (uint16_t)kept;
}

/* Every weight divided by div: small weights, as evolved networks have,
 * make rows whose sums fit 32 bits (nrt_dense.narrow) even with many
 * connections. */
static void td_shrink(td_net *t, int div)
{
    uint32_t k;
    for (k = 0; k < t->net.n_conns; k++)
        t->weight[k] = (nrt_w12)(t->weight[k] / div);
}

/* Of d's groups of eight rows: how many have sums that fit 32 bits. */
static uint32_t td_narrow(const nrt_dense *d)
{
    return (uint32_t)__builtin_popcount(d->narrow);
}

/* Whether d skips a tile (a group of rows without a connection from some block). */
static int td_skips(const nrt_dense *d)
{
    uint32_t g;
    for (g = 0; g < (d->rows + 7u) / 8u; g++)
        if ((uint32_t)__builtin_popcount(d->tiles[g]) < d->blocks)
            return 1;
    return 0;
}

static int td_available(void)
{
    static nrt_dense d;
    td_net *t = test_malloc(sizeof *t);
    uint32_t seed = 1;
    int ok;
    td_make(t, 13, 3, 0, 8, &seed);
    ok = nrt_dense_make(&d, &t->net) == NRT_OK;
    test_free(t);
    return ok;
}

/* 400 random networks of 2-64 nodes (every eighth of at most NRT_DENSE_FEW
 * rows), half of them thinned to a few tiles (td_thin), half with weights
 * a sixteenth of the range (td_shrink), 12 steps each with new random
 * inputs: after every step all activations of both copies are equal. */
static void test_dense_matches_step(void **state)
{
    static nrt_dense d;
    td_net *a = test_malloc(sizeof *a), *b = test_malloc(sizeof *b);
    uint32_t seed = 0x2545F491u, trial, made = 0, big = 0, skips = 0, narrow = 0, wide = 0;
    (void)state;
    if (!td_available()) {
        test_free(a);
        test_free(b);
        skip();
    }
    for (trial = 0; trial < 400; trial++) {
        uint32_t n_in = 1 + td_next(&seed) % 20, n_out = 1 + td_next(&seed) % 6;
        uint32_t room = NRT_DENSE_MAX_NODES - n_in - n_out, n_hid = td_next(&seed) % (room + 1);
        uint32_t density = 3 + td_next(&seed) % 6, s1 = seed, step, i;
        if (trial % 8u == 7u) { /* at most NRT_DENSE_FEW rows: the one-reduction sums */
            n_out = 1 + td_next(&seed) % NRT_DENSE_FEW;
            n_hid = td_next(&seed) % (NRT_DENSE_FEW + 1 - n_out);
            s1 = seed;
        }
        td_make(a, n_in, n_out, n_hid, density, &s1);
        seed = s1;
        if (trial % 2u)
            td_thin(a, &seed);
        if (trial % 4u < 2u)
            td_shrink(a, 16);
        td_copy(b, a);
        if (nrt_dense_make(&d, &b->net) != NRT_OK)
            continue;
        made++;
        big += b->net.n_nodes - b->net.n_inputs > 4;
        skips += b->net.n_nodes - b->net.n_inputs > 4 && td_skips(&d);
        if (d.rows > NRT_DENSE_FEW) {
            narrow += td_narrow(&d);
            wide += (d.rows + 7u) / 8u - td_narrow(&d);
        }
        for (step = 0; step < 12; step++) {
            nrt_q15 *ia = nrt_inputs(&a->net), *ib = nrt_dense_inputs(&d);
            for (i = 0; i < n_in; i++)
                ia[i] = ib[i] = td_value(&seed, -32768);
            nrt_step(&a->net, ia, NULL);
            nrt_dense_step(&d);
            assert_memory_equal(nrt_outputs(&a->net), nrt_dense_outputs(&d), 2u * n_out);
            nrt_dense_save(&d, &b->net);
            assert_int_equal(a->net.cur, b->net.cur);
            assert_memory_equal(a->net.act[a->net.cur], b->net.act[b->net.cur], 2u * a->net.n_nodes);
        }
    }
    /* the comparison covered both ways of taking the sigmoid */
    assert_true(made >= 300);
    assert_true(big >= 200 && made - big >= 20);
    /* and the step skipping tiles, and groups of rows summed both ways */
    assert_true(skips >= 100);
    assert_true(narrow >= 100 && wide >= 100);
    test_free(a);
    test_free(b);
}

/* nrt_dense_step2 on 300 random pairs, most of them small enough (at most
 * four rows each) to share the sigmoid pass, the rest mixed: after every
 * step both networks' activations are nrt_step's. */
static void test_dense_pair_matches_step(void **state)
{
    static nrt_dense d[2];
    td_net *a[2], *b[2];
    uint32_t seed = 0x9E3779B9u, trial, made = 0, shared = 0, k;
    (void)state;
    for (k = 0; k < 2; k++) {
        a[k] = test_malloc(sizeof *a[k]);
        b[k] = test_malloc(sizeof *b[k]);
    }
    if (!td_available()) {
        for (k = 0; k < 2; k++) {
            test_free(a[k]);
            test_free(b[k]);
        }
        skip();
    }
    for (trial = 0; trial < 300; trial++) {
        int ok = 1;
        uint32_t step, i;
        for (k = 0; k < 2; k++) {
            uint32_t n_in = 1 + td_next(&seed) % 20, n_out = 1 + td_next(&seed) % 4;
            uint32_t room = trial % 4 == 3 ? NRT_DENSE_MAX_NODES - n_in - n_out : 4 - n_out;
            uint32_t n_hid = td_next(&seed) % (room + 1), density = 3 + td_next(&seed) % 6, s1 = seed, s2 = seed;
            td_make(a[k], n_in, n_out, n_hid, density, &s1);
            td_make(b[k], n_in, n_out, n_hid, density, &s2);
            seed = s1;
            ok = ok && nrt_dense_make(&d[k], &b[k]->net) == NRT_OK;
        }
        if (!ok)
            continue;
        made++;
        shared += d[0].rows <= 4 && d[1].rows <= 4;
        for (step = 0; step < 12; step++) {
            for (k = 0; k < 2; k++) {
                nrt_q15 *ia = nrt_inputs(&a[k]->net), *ib = nrt_dense_inputs(&d[k]);
                for (i = 0; i < a[k]->net.n_inputs; i++)
                    ia[i] = ib[i] = td_value(&seed, -32768);
                nrt_step(&a[k]->net, ia, NULL);
            }
            nrt_dense_step2(&d[0], &d[1]);
            for (k = 0; k < 2; k++) {
                assert_memory_equal(nrt_outputs(&a[k]->net), nrt_dense_outputs(&d[k]), 2u * a[k]->net.n_outputs);
                nrt_dense_save(&d[k], &b[k]->net);
                assert_int_equal(a[k]->net.cur, b[k]->net.cur);
                assert_memory_equal(a[k]->net.act[a[k]->net.cur], b[k]->net.act[b[k]->net.cur],
                                    2u * a[k]->net.n_nodes);
            }
        }
    }
    /* both ways: the shared pass, and a pair with a larger network */
    assert_true(made >= 150);
    assert_true(shared >= 100 && made - shared >= 20);
    for (k = 0; k < 2; k++) {
        test_free(a[k]);
        test_free(b[k]);
    }
}

/* Three steps of a and of d (made from its copy b) with every input x:
 * after each the activations of both are equal. */
static void td_steps_constant(td_net *a, td_net *b, nrt_dense *d, nrt_q15 x)
{
    uint32_t i, j;
    for (j = 0; j < 3; j++) {
        nrt_q15 *ia = nrt_inputs(&a->net), *ib = nrt_dense_inputs(d);
        for (i = 0; i < a->net.n_inputs; i++)
            ia[i] = ib[i] = x;
        nrt_step(&a->net, ia, NULL);
        nrt_dense_step(d);
        nrt_dense_save(d, &b->net);
        assert_memory_equal(a->net.act[a->net.cur], b->net.act[b->net.cur], 2u * a->net.n_nodes);
    }
}

/* The largest sums there are: every weight 32767 or -32767 from every node,
 * every activation -32768 or 32767, in one 64-node network. */
static void test_dense_extremes(void **state)
{
    static nrt_dense d;
    td_net *a = test_malloc(sizeof *a), *b = test_malloc(sizeof *b);
    uint32_t sign, j;
    (void)state;
    if (!td_available()) {
        test_free(a);
        test_free(b);
        skip();
    }
    for (sign = 0; sign < 4; sign++) {
        uint32_t seed = 7;
        td_make(a, 16, 8, 40, 8, &seed);
        for (j = 0; j < a->net.n_conns; j++)
            a->weight[j] = (sign & 1u) ? -32767 : 32767;
        td_copy(b, a);
        assert_int_equal(nrt_dense_make(&d, &b->net), NRT_OK);
        td_steps_constant(a, b, &d, (sign & 2u) ? -32768 : 32767);
    }
    test_free(a);
    test_free(b);
}

/* Rows at the bound of nrt_dense.narrow: weights of absolute sum 65535
 * (the sums fit 32 bits, added up directly) and 65536 (not), every input
 * -32768 or 32767, every sign: the sums reach -+(2^31 - 2^15) and 2^31. */
static void test_dense_narrow_bound(void **state)
{
    static nrt_dense d;
    td_net *a = test_malloc(sizeof *a), *b = test_malloc(sizeof *b);
    uint32_t last, sign, i, j, k;
    (void)state;
    if (!td_available()) {
        test_free(a);
        test_free(b);
        skip();
    }
    for (last = 1; last <= 2; last++)
        for (sign = 0; sign < 4; sign++) {
            uint32_t seed = 9;
            td_make(a, 16, 8, 0, 0, &seed);
            for (j = 0, k = 0; j < 8; j++) {
                for (i = 0; i < 16; i++, k++) {
                    nrt_w12 w = (nrt_w12)(i < 2 ? 32767 : (i == 2 ? (int)last : 0));
                    a->src[k] = (uint16_t)i;
                    a->weight[k] = (sign & 1u) && j % 2u == 0 ? (nrt_w12)-w : w;
                }
                a->end[j] = (uint16_t)k;
            }
            a->net.n_conns = (uint16_t)k;
            td_copy(b, a);
            assert_int_equal(nrt_dense_make(&d, &b->net), NRT_OK);
            assert_int_equal(td_narrow(&d), last == 1);
            td_steps_constant(a, b, &d, (sign & 2u) ? -32768 : 32767);
        }
    test_free(a);
    test_free(b);
}

/* One input (of 8) into 8 outputs (the eight-row sigmoid, with either sum) or 3 (the scalar one)
 * with weights spread over the whole range: every input value from -32768
 * to 32767 puts the sums on every segment of the sigmoid's table, its last
 * entries and its saturation included. */
static void test_dense_sigmoid_sweep(void **state)
{
    static const nrt_w12 w[8] = {32767, -32767, 4096, -4096, 517, -1, 24000, -9000};
    static nrt_dense d;
    td_net *a = test_malloc(sizeof *a), *b = test_malloc(sizeof *b);
    uint32_t n_out, j;
    int32_t x;
    (void)state;
    if (!td_available()) {
        test_free(a);
        test_free(b);
        skip();
    }
    for (n_out = 3; n_out <= 16; n_out += 5) {
        uint32_t seed = 5;
        uint32_t k = 0, i;
        /* inputs 1-7 with weight 0: connections enough for the dense form;
         * for 13 (8 outputs again) inputs 1 and 2 (always 0) with weight
         * 32767, so that the rows' sums may exceed 32 bits (nrt_dense.narrow
         * clear: the other sum) */
        uint32_t n = n_out == 13 ? 8 : n_out;
        td_make(a, 8, n, 0, 0, &seed);
        for (j = 0; j < n; j++) {
            for (i = 0; i < 8; i++, k++) {
                a->src[k] = (uint16_t)i;
                a->weight[k] = i == 0 ? w[j] : (n_out == 13 && i <= 2 ? 32767 : 0);
            }
            a->end[j] = (uint16_t)k;
        }
        a->net.n_conns = (uint16_t)k;
        td_copy(b, a);
        assert_int_equal(nrt_dense_make(&d, &b->net), NRT_OK);
        if (n == 8)
            assert_int_equal(td_narrow(&d), n_out == 8);
        for (x = -32768; x <= 32767; x++) {
            nrt_inputs(&a->net)[0] = nrt_dense_inputs(&d)[0] = (nrt_q15)x;
            nrt_step(&a->net, nrt_inputs(&a->net), NULL);
            nrt_dense_step(&d);
            assert_memory_equal(nrt_outputs(&a->net), nrt_dense_outputs(&d), 2u * n);
        }
    }
    test_free(a);
    test_free(b);
}

/* Too many nodes, two connections between the same nodes, a sparse network
 * the list steps faster, NULL: refused. */
static void test_dense_refuses(void **state)
{
    static nrt_dense d;
    td_net *t = test_malloc(sizeof *t);
    uint32_t seed = 3;
    (void)state;
    if (!td_available()) {
        test_free(t);
        skip();
    }
    assert_int_equal(nrt_dense_make(NULL, &t->net), NRT_E_ARG);
    assert_int_equal(nrt_dense_make(&d, NULL), NRT_E_ARG);
    td_make(t, 13, 3, 0, 8, &seed);
    t->src[1] = t->src[0];
    assert_int_equal(nrt_dense_make(&d, &t->net), NRT_E_ARG);
    td_make(t, 13, 3, 0, 8, &seed);
    t->net.n_nodes = NRT_DENSE_MAX_NODES + 1;
    assert_int_equal(nrt_dense_make(&d, &t->net), NRT_E_ARG);
    /* a propagate network (an evaluation order): not one matrix product */
    td_make(t, 13, 3, 0, 8, &seed);
    assert_int_equal(nrt_dense_make(&d, &t->net), NRT_OK);
    {
        uint8_t order[3] = {13, 14, 15};
        t->net.order = order;
        t->net.step = NRT_STEP_PROPAGATE;
        assert_int_equal(nrt_dense_make(&d, &t->net), NRT_E_ARG);
        t->net.order = NULL;
        t->net.step = NRT_STEP_SYNC;
    }
    /* 51 rows, where the first of each eight has one connection in each
     * block of 16 columns: every tile of the matrix to multiply for 28
     * connections, which the list steps faster */
    td_make(t, 13, 3, 48, 0, &seed);
    {
        uint32_t j, b, k = 0;
        for (j = 0; j < 51; j++) {
            for (b = 0; j % 8u == 0 && b < 4; b++) {
                t->src[k] = (uint16_t)(16u * b + j / 8u);
                t->weight[k++] = 1000;
            }
            t->end[j] = (uint16_t)k;
        }
        t->net.n_conns = (uint16_t)k;
    }
    assert_int_equal(nrt_dense_make(&d, &t->net), NRT_E_ARG);
    test_free(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dense_matches_step),
        cmocka_unit_test(test_dense_pair_matches_step),
        cmocka_unit_test(test_dense_extremes),
        cmocka_unit_test(test_dense_narrow_bound),
        cmocka_unit_test(test_dense_sigmoid_sweep),
        cmocka_unit_test(test_dense_refuses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
