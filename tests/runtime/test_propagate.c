/* test_propagate.c - the propagate step mode: its evaluation order, both modes against a double-precision reference, its blobs refused when bad. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat.h"
#include "nrt.h"

#define PG_W12(w) ((int32_t)floor((w) * 4096.0 + 0.5))
#define PG_MAX 64
#define PG_CONNS 320

typedef struct pg_rt {
    uint8_t blob[4096];
    size_t len;
    uint64_t mem[1024];
    nrt_net net;
} pg_rt;

/* xorshift32 (Marsaglia): the test's own reproducible pseudo-random source. */
static uint32_t pg_rand(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *s = x;
    return x;
}

/* Nodes with the genome's ids = runtime indices: bias 0, inputs, outputs, hidden. */
static void pg_nodes(neat_genome *g, uint32_t n_in, uint32_t n_out, uint32_t n_hid)
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

static void pg_conn(neat_genome *g, uint32_t in, uint32_t out, double w)
{
    assert_int_equal(neat_genome_add_conn(g, in, out, w, g->n_conns, 1, NULL), NEAT_OK);
}

/* Genome -> blob of the given mode -> loaded net (the genome is kept). */
static void pg_load(pg_rt *rt, const neat_genome *g, uint32_t n_in, uint32_t n_out, int step)
{
    size_t need = 0;
    assert_int_equal(neat_blob_write_step(g, n_in, n_out, step, rt->blob, sizeof rt->blob, &rt->len), NEAT_OK);
    assert_int_equal(nrt_mem_required(rt->blob, rt->len, &need), NRT_OK);
    assert_true(need <= sizeof rt->mem);
    assert_int_equal(nrt_load(&rt->net, rt->blob, rt->len, rt->mem, sizeof rt->mem), NRT_OK);
    assert_int_equal(rt->net.step, step == NEAT_STEP_PROPAGATE ? NRT_STEP_PROPAGATE : NRT_STEP_SYNC);
}

/* ---- the reference: doubles, the definitions of docs/runtime.md written out again ---- */
typedef struct pg_ref {
    uint32_t n_in, n_nodes, n_conns; /* n_in counts the bias */
    uint32_t src[PG_CONNS], dst[PG_CONNS];
    double w[PG_CONNS];
    double act[PG_MAX];
    uint32_t order[PG_MAX]; /* propagate: the non-input nodes in evaluation order */
} pg_ref;

/* The order rule, from the connection list: repeatedly the lowest-index
 * unplaced node whose every source other than itself is an input or placed;
 * if there is none, the lowest-index unplaced node. */
static void pg_ref_order(pg_ref *r)
{
    uint8_t placed[PG_MAX];
    uint32_t p, t, k, non_in = r->n_nodes - r->n_in;
    memset(placed, 0, sizeof placed);
    for (t = 0; t < r->n_in; t++)
        placed[t] = 1;
    for (p = 0; p < non_in; p++) {
        uint32_t pick = PG_MAX;
        for (t = r->n_in; t < r->n_nodes && pick == PG_MAX; t++) {
            int ready = !placed[t];
            for (k = 0; k < r->n_conns && ready; k++)
                if (r->dst[k] == t && r->src[k] != t && !placed[r->src[k]])
                    ready = 0;
            if (ready)
                pick = t;
        }
        for (t = r->n_in; t < r->n_nodes && pick == PG_MAX; t++)
            if (!placed[t])
                pick = t;
        r->order[p] = pick;
        placed[pick] = 1;
    }
}

static void pg_ref_init(pg_ref *r, const neat_genome *g, uint32_t n_in)
{
    uint32_t k;
    memset(r, 0, sizeof *r);
    assert_true(g->n_nodes <= PG_MAX && g->n_conns <= PG_CONNS);
    r->n_in = n_in + 1;
    r->n_nodes = g->n_nodes;
    for (k = 0; k < g->n_conns; k++) {
        if (!g->conns[k].enabled)
            continue;
        r->src[r->n_conns] = g->conns[k].in;
        r->dst[r->n_conns] = g->conns[k].out;
        r->w[r->n_conns] = (double)PG_W12(g->conns[k].weight) / 4096.0;
        r->n_conns++;
    }
    pg_ref_order(r);
}

static double pg_sig(double x)
{
    return 1.0 / (1.0 + exp(-4.9 * x));
}

/* sync: every node from the previous step's values; propagate: the nodes
 * one at a time in order, each from the values as they are now */
static void pg_ref_step(pg_ref *r, const nrt_q15 *in, int propagate)
{
    double sum[PG_MAX];
    uint32_t j, k, p;
    for (j = 0; j < r->n_in; j++)
        r->act[j] = (double)in[j] / 32768.0;
    if (!propagate) {
        memset(sum, 0, sizeof sum);
        for (k = 0; k < r->n_conns; k++)
            sum[r->dst[k]] += r->w[k] * r->act[r->src[k]];
        for (j = r->n_in; j < r->n_nodes; j++)
            r->act[j] = pg_sig(sum[j]);
        return;
    }
    for (p = 0; p < r->n_nodes - r->n_in; p++) {
        double s = 0.0;
        j = r->order[p];
        for (k = 0; k < r->n_conns; k++)
            if (r->dst[k] == j)
                s += r->w[k] * r->act[r->src[k]];
        r->act[j] = pg_sig(s);
    }
}

/* ---- the evaluation order on hand-built networks ---- */

/* Loads g as propagate and checks net.order against want. */
static void pg_expect_order(neat_genome *g, uint32_t n_in, uint32_t n_out, const uint8_t *want, uint32_t n)
{
    static pg_rt rt;
    pg_ref ref;
    uint32_t p;
    pg_load(&rt, g, n_in, n_out, NEAT_STEP_PROPAGATE);
    assert_int_equal((uint32_t)rt.net.n_nodes - rt.net.n_inputs, n);
    pg_ref_init(&ref, g, n_in);
    for (p = 0; p < n; p++) {
        if (rt.net.order[p] != want[p])
            fail_msg("position %u: node %u, expected %u", (unsigned)p, (unsigned)rt.net.order[p], (unsigned)want[p]);
        assert_int_equal(ref.order[p], want[p]); /* the reference's rule agrees */
    }
    neat_genome_free(g, NULL);
}

/* A chain whose hidden ids run against the signal: inputs first, each node
 * once its source is placed (nodes: bias 0, input 1, output 2, hidden 3, 4). */
static void test_order_chain_against_ids(void **state)
{
    static const uint8_t want[] = {4, 3, 2};
    neat_genome g;
    (void)state;
    pg_nodes(&g, 1, 1, 2);
    pg_conn(&g, 1, 4, 1.0);
    pg_conn(&g, 4, 3, 1.0);
    pg_conn(&g, 3, 2, 1.0);
    pg_expect_order(&g, 1, 1, want, 3);
}

/* Placing a higher node can make a lower one ready: the search starts again
 * from the lowest (2 <- 4, 3 <- 1, 4 <- 1: 3, then 4, then 2). */
static void test_order_lowest_ready_first(void **state)
{
    static const uint8_t want[] = {3, 4, 2};
    neat_genome g;
    (void)state;
    pg_nodes(&g, 1, 1, 2);
    pg_conn(&g, 4, 2, 1.0);
    pg_conn(&g, 1, 3, 1.0);
    pg_conn(&g, 1, 4, 1.0);
    pg_expect_order(&g, 1, 1, want, 3);
}

/* A cycle 2 <-> 3 with a self-connection on 2: nothing is ready, so the
 * lowest unplaced (2) goes first, then 3 is ready; then 4, fed by the cycle. */
static void test_order_cycle_lowest_first(void **state)
{
    static const uint8_t want[] = {2, 3, 4};
    neat_genome g;
    (void)state;
    pg_nodes(&g, 1, 1, 2);
    pg_conn(&g, 1, 3, 1.0);
    pg_conn(&g, 2, 2, 0.5);
    pg_conn(&g, 3, 2, 1.0);
    pg_conn(&g, 2, 3, 1.0);
    pg_conn(&g, 3, 4, 1.0);
    pg_expect_order(&g, 1, 1, want, 3);
}

/* A self-connection alone does not hold a node back; a node without
 * connections is ready at once; only enabled connections count (with
 * 4 <- 3 enabled, 3 and 4 would be a cycle and go 3, 4). */
static void test_order_self_and_unconnected(void **state)
{
    static const uint8_t want[] = {2, 4, 3};
    neat_genome g;
    (void)state;
    pg_nodes(&g, 1, 2, 1);
    pg_conn(&g, 2, 2, 1.0);
    pg_conn(&g, 1, 2, 1.0);
    pg_conn(&g, 4, 3, 1.0); /* 3 waits for 4 */
    pg_conn(&g, 3, 4, 1.0);
    g.conns[3].enabled = 0; /* disabled: not a connection of the network, 4 has none */
    pg_expect_order(&g, 1, 2, want, 3);
}

/* ---- steps ---- */

/* A chain input -> h1 -> ... -> hD -> output: propagate gives the final
 * output on the first step, sync only after D + 1 steps (before, two inputs
 * give the same output: the input has not arrived); settle: 2 steps (the
 * second finds nothing changed) against D + 2. */
static void test_deep_chain_one_step(void **state)
{
    enum { D = 12 };
    static pg_rt sa, sb, pa, pb;
    neat_genome g;
    nrt_q15 in_a[2] = {NRT_ONE, 20000}, in_b[2] = {NRT_ONE, -20000}, oa, ob, fa, fb;
    uint32_t i;
    int s;
    (void)state;
    pg_nodes(&g, 1, 1, D);
    pg_conn(&g, 1, 3, 1.5);
    for (i = 3; i < 2 + D; i++)
        pg_conn(&g, i, i + 1, i % 2 ? -1.25 : 1.75);
    pg_conn(&g, 2 + D, 2, 2.0);
    pg_load(&sa, &g, 1, 1, NEAT_STEP_SYNC);
    pg_load(&sb, &g, 1, 1, NEAT_STEP_SYNC);
    pg_load(&pa, &g, 1, 1, NEAT_STEP_PROPAGATE);
    pg_load(&pb, &g, 1, 1, NEAT_STEP_PROPAGATE);
    nrt_step(&pa.net, in_a, &fa);
    nrt_step(&pb.net, in_b, &fb);
    assert_true(fa != fb); /* the input reached the output in one step */
    for (s = 1; s <= D + 1; s++) {
        nrt_step(&sa.net, in_a, &oa);
        nrt_step(&sb.net, in_b, &ob);
        if (s <= D) {
            assert_int_equal(oa, ob); /* not there yet */
        } else {
            assert_int_equal(oa, fa); /* the same fixed-point arithmetic, D steps later */
            assert_int_equal(ob, fb);
        }
        nrt_step(&pa.net, in_a, &oa);
        assert_int_equal(oa, fa); /* settled from the first step */
    }
    nrt_reset(&pa.net);
    nrt_reset(&sa.net);
    assert_int_equal(nrt_settle(&pa.net, in_a, &oa, 50), 2);
    assert_int_equal(oa, fa);
    assert_int_equal(nrt_settle(&sa.net, in_a, &ob, 50), D + 2);
    assert_int_equal(ob, fa);
    nrt_reset(&pa.net);
    assert_int_equal(nrt_settle(&pa.net, in_a, &oa, 1), -1); /* after a reset one step changes everything */
    neat_genome_free(&g, NULL);
}

/* Many random networks with cycles and self-connections, both modes,
 * against the double-precision reference, compared at every step. The
 * bound: each sigmoid errs by at most 1.2e-4 and weights are the same
 * quantised values, so differences come only from rounding, and a network
 * whose gain (4.9/4 x the sum of |w| into a node, here at most 1.225 x 8 x
 * 0.3) is near 1 carries them on without growing them much; 1e-3 leaves
 * room for long in-step chains of propagate. */
static void test_random_both_modes_match_reference(void **state)
{
    enum { NETS = 60, STEPS = 150, IN = 4, OUT = 3, MAXHID = 20 };
    static pg_rt rt;
    uint32_t seed = 0x5EED1234u, n;
    double max_err[2] = {0.0, 0.0};
    int mode;
    (void)state;
    for (n = 0; n < NETS; n++) {
        neat_genome g;
        pg_ref ref;
        uint32_t hid = pg_rand(&seed) % (MAXHID + 1), nodes = IN + 1 + OUT + hid, conns, i, selfs = 0;
        static uint8_t used[PG_MAX][PG_MAX];
        pg_nodes(&g, IN, OUT, hid);
        memset(used, 0, sizeof used);
        conns = nodes * 3;
        while (g.n_conns < conns) {
            uint32_t s = pg_rand(&seed) % nodes;
            uint32_t d = IN + 1 + pg_rand(&seed) % (nodes - IN - 1);
            double w = ((double)(pg_rand(&seed) % 2000001u) / 1000000.0 - 1.0) * 0.3;
            if (used[s][d])
                continue;
            used[s][d] = 1;
            selfs += s == d;
            pg_conn(&g, s, d, w);
        }
        for (mode = 0; mode < 2; mode++) {
            int t;
            nrt_q15 in[IN + 1], out[OUT];
            uint32_t run = seed;
            pg_ref_init(&ref, &g, IN);
            pg_load(&rt, &g, IN, OUT, mode ? NEAT_STEP_PROPAGATE : NEAT_STEP_SYNC);
            for (i = 0; mode && i < nodes - IN - 1u; i++)
                assert_int_equal(rt.net.order[i], ref.order[i]);
            for (t = 0; t < STEPS; t++) {
                uint32_t j;
                in[0] = NRT_ONE;
                for (i = 1; i <= IN; i++)
                    in[i] = (nrt_q15)((int32_t)(pg_rand(&run) % 65536u) - 32768);
                nrt_step(&rt.net, in, out);
                pg_ref_step(&ref, in, mode);
                /* every node, not only the outputs: the state is where a wrong order shows first */
                for (j = IN + 1; j < nodes; j++) {
                    const nrt_q15 *a = rt.net.act[rt.net.cur];
                    double err = fabs((double)a[j] / 32768.0 - ref.act[j]);
                    if (err > max_err[mode])
                        max_err[mode] = err;
                    if (err > 1e-3)
                        fail_msg("net %u (%u hidden, %u self-loops) %s step %d node %u: %.3e apart", (unsigned)n,
                                 (unsigned)hid, (unsigned)selfs, mode ? "propagate" : "sync", t, (unsigned)j, err);
                }
                for (j = 0; j < OUT; j++)
                    assert_int_equal(out[j], rt.net.act[rt.net.cur][IN + 1 + j]);
            }
        }
        neat_genome_free(&g, NULL);
    }
    printf("%d random recurrent networks x %d steps: max |runtime - double| sync %.3e, propagate %.3e\n", NETS, STEPS,
           max_err[0], max_err[1]);
}

/* The same network in the two modes differs where the order matters: a
 * hidden node feeding an output gives the output its new value in
 * propagate, the previous step's in sync. */
static void test_modes_differ(void **state)
{
    static pg_rt a, b;
    neat_genome g;
    nrt_q15 in[2] = {NRT_ONE, 30000}, oa, ob;
    (void)state;
    pg_nodes(&g, 1, 1, 1);
    pg_conn(&g, 1, 3, 2.0);
    pg_conn(&g, 3, 2, 2.0);
    pg_load(&a, &g, 1, 1, NEAT_STEP_SYNC);
    pg_load(&b, &g, 1, 1, NEAT_STEP_PROPAGATE);
    nrt_step(&a.net, in, &oa);
    nrt_step(&b.net, in, &ob);
    assert_int_equal(oa, 16384);
    assert_true(ob > 30000);
    neat_genome_free(&g, NULL);
}

/* ---- blobs and memory ---- */

/* A recurrent sample with a self-connection, as a propagate blob. */
static void pg_sample(pg_rt *rt)
{
    neat_genome g;
    uint32_t i;
    assert_int_equal(neat_genome_recurrent_hidden(&g, 3, 2, 2, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    for (i = 0; i < g.n_conns; i++)
        g.conns[i].weight = ((double)((i * 7u) % 13u) - 6.0) * 0.625;
    g.conns[5].enabled = 0;
    assert_int_equal(neat_blob_write_step(&g, 3, 2, NEAT_STEP_PROPAGATE, rt->blob, sizeof rt->blob, &rt->len),
                     NEAT_OK);
    neat_genome_free(&g, NULL);
}

/* The bytes: the sync blob's with the version 2, the step byte 1 and the CRC. */
static void test_blob_bytes(void **state)
{
    static pg_rt p, s;
    neat_genome g;
    size_t i;
    (void)state;
    pg_sample(&p);
    assert_int_equal(neat_genome_recurrent_hidden(&g, 3, 2, 2, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    for (i = 0; i < g.n_conns; i++)
        g.conns[i].weight = ((double)((i * 7u) % 13u) - 6.0) * 0.625;
    g.conns[5].enabled = 0;
    assert_int_equal(neat_blob_write(&g, 3, 2, s.blob, sizeof s.blob, &s.len), NEAT_OK);
    neat_genome_free(&g, NULL);
    assert_int_equal(p.len, s.len);
    assert_int_equal(p.blob[NRT_OFF_VERSION], NRT_FORMAT_VERSION_PROPAGATE);
    assert_int_equal(s.blob[NRT_OFF_VERSION], NRT_FORMAT_VERSION);
    assert_int_equal(p.blob[NRT_OFF_STEP], NRT_STEP_PROPAGATE);
    for (i = 0; i < p.len; i++)
        if (i != NRT_OFF_VERSION && i != NRT_OFF_STEP && (i < NRT_OFF_CRC || i >= NRT_HEADER_SIZE))
            assert_int_equal(p.blob[i], s.blob[i]);
}

/* Every truncation of a propagate blob: NRT_E_TRUNCATED; every single-byte
 * change (each offset, each other value): refused (the version and step
 * byte each way, the rest by the CRC or the field checks). */
static void test_bad_blobs_refused(void **state)
{
    static pg_rt s;
    static uint8_t t[4096];
    static uint64_t mem[1024];
    size_t len, off;
    int v;
    (void)state;
    pg_sample(&s);
    for (len = 0; len < s.len; len++) {
        uint8_t *p = (uint8_t *)malloc(len + 1);
        nrt_net net;
        assert_non_null(p);
        memcpy(p, s.blob, len);
        assert_int_equal(nrt_load(&net, p, len, mem, sizeof mem), NRT_E_TRUNCATED);
        free(p);
    }
    for (off = 0; off < s.len; off++)
        for (v = 0; v < 256; v++) {
            nrt_net net;
            int err;
            if (v == s.blob[off])
                continue;
            memcpy(t, s.blob, s.len);
            t[off] = (uint8_t)v;
            err = nrt_load(&net, t, s.len, mem, sizeof mem);
            if (err == NRT_OK)
                fail_msg("byte %u set to %d accepted", (unsigned)off, v);
            assert_null(net.order);
        }
}

/* Rewrites the CRC after an edit, so that the check under test fires. */
static void pg_fix_crc(uint8_t *b, size_t len)
{
    uint32_t crc = nrt_crc32(0, b, NRT_OFF_CRC);
    crc = nrt_crc32(crc, b + NRT_HEADER_SIZE, len - NRT_HEADER_SIZE);
    b[NRT_OFF_CRC] = (uint8_t)crc;
    b[NRT_OFF_CRC + 1] = (uint8_t)(crc >> 8);
    b[NRT_OFF_CRC + 2] = (uint8_t)(crc >> 16);
    b[NRT_OFF_CRC + 3] = (uint8_t)(crc >> 24);
}

/* With a valid CRC: version 1 with the step byte set, version 2 with it
 * clear or naming an unknown mode, a reserved byte after it: NRT_E_HEADER. */
static void test_step_byte_rules(void **state)
{
    static pg_rt s;
    static uint64_t mem[1024];
    nrt_net net;
    int off;
    (void)state;
    pg_sample(&s);
    s.blob[NRT_OFF_VERSION] = NRT_FORMAT_VERSION;
    pg_fix_crc(s.blob, s.len);
    assert_int_equal(nrt_load(&net, s.blob, s.len, mem, sizeof mem), NRT_E_HEADER);
    s.blob[NRT_OFF_VERSION] = NRT_FORMAT_VERSION_PROPAGATE;
    s.blob[NRT_OFF_STEP] = NRT_STEP_SYNC;
    pg_fix_crc(s.blob, s.len);
    assert_int_equal(nrt_load(&net, s.blob, s.len, mem, sizeof mem), NRT_E_HEADER);
    s.blob[NRT_OFF_STEP] = 2;
    pg_fix_crc(s.blob, s.len);
    assert_int_equal(nrt_load(&net, s.blob, s.len, mem, sizeof mem), NRT_E_HEADER);
    for (off = NRT_OFF_STEP + 1; off < NRT_OFF_CRC; off++) {
        pg_sample(&s);
        s.blob[off] = 1;
        pg_fix_crc(s.blob, s.len);
        assert_int_equal(nrt_load(&net, s.blob, s.len, mem, sizeof mem), NRT_E_HEADER);
    }
    pg_sample(&s);
    assert_int_equal(nrt_load(&net, s.blob, s.len, mem, sizeof mem), NRT_OK);
}

/* nrt_mem_required: the sync figure plus a byte per non-input node; one
 * byte short is refused; exactly that much at an odd address loads and
 * steps without touching the byte after it. */
static void test_memory(void **state)
{
    static pg_rt s;
    static uint64_t mem[1024];
    uint8_t *buf = (uint8_t *)mem + 1;
    size_t need = 0, blob_size = 0;
    nrt_net net;
    nrt_q15 in[4] = {NRT_ONE, 1000, -2000, 3000}, out[2];
    (void)state;
    pg_sample(&s);
    assert_int_equal(nrt_inspect(s.blob, s.len, &blob_size, &need), NRT_OK);
    assert_int_equal(blob_size, s.len);
    /* 8 nodes (4 inputs), 23 connections: 4 x 23 + 2 x 4 + 4 x 8 + 1, + 4 */
    assert_int_equal(need, 4u * 23u + 2u * 4u + 4u * 8u + 1u + 4u);
    memset(mem, 0xA5, sizeof mem);
    assert_int_equal(nrt_load(&net, s.blob, s.len, buf, need - 1), NRT_E_NOMEM);
    assert_int_equal(nrt_load(&net, s.blob, s.len, buf, need), NRT_OK);
    assert_true(net.order >= buf && net.order + 4 <= buf + need);
    nrt_step(&net, in, out);
    nrt_step(&net, in, out);
    assert_int_equal(buf[need], 0xA5);
}

/* The blob's network read back as a genome: the same connections whatever
 * the mode, and the mode reported; rewritten, the same bytes. */
static void test_genome_from_propagate_blob(void **state)
{
    static pg_rt s;
    uint8_t again[4096];
    size_t len = 0;
    neat_genome g;
    int step = -1;
    (void)state;
    pg_sample(&s);
    assert_int_equal(neat_genome_from_blob_step(&g, s.blob, s.len, NULL, &step), NEAT_OK);
    assert_int_equal(step, NEAT_STEP_PROPAGATE);
    assert_int_equal(neat_blob_write_step(&g, 3, 2, NEAT_STEP_PROPAGATE, again, sizeof again, &len), NEAT_OK);
    assert_int_equal(len, s.len);
    assert_memory_equal(again, s.blob, len);
    /* the same network as a sync blob says sync, and gives the same genome's blob */
    assert_int_equal(neat_blob_write(&g, 3, 2, again, sizeof again, &len), NEAT_OK);
    neat_genome_free(&g, NULL);
    assert_int_equal(neat_genome_from_blob_step(&g, again, len, NULL, &step), NEAT_OK);
    assert_int_equal(step, NEAT_STEP_SYNC);
    neat_genome_free(&g, NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_order_chain_against_ids),
        cmocka_unit_test(test_order_lowest_ready_first),
        cmocka_unit_test(test_order_cycle_lowest_first),
        cmocka_unit_test(test_order_self_and_unconnected),
        cmocka_unit_test(test_deep_chain_one_step),
        cmocka_unit_test(test_random_both_modes_match_reference),
        cmocka_unit_test(test_modes_differ),
        cmocka_unit_test(test_blob_bytes),
        cmocka_unit_test(test_bad_blobs_refused),
        cmocka_unit_test(test_step_byte_rules),
        cmocka_unit_test(test_memory),
        cmocka_unit_test(test_genome_from_propagate_blob),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
