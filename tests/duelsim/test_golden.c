/* test_golden.c - results pinned to the bit: sensing, network steps and whole games against hashes recorded from the reference code. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "duel.h"
#include "duel_internal.h"

/*
 * Every speed-up of the simulator or the runtime must leave every game as it
 * was. These hashes were recorded from the code before issue 16's work (commit
 * 3cfa6ff) and are checked at -O0, -O2 and -O3 (tests/CMakeLists.txt builds
 * this file three times, each against its own copy of duelsim and the
 * runtime compiled at that level) and in the sanitizer build. A change that
 * alters results on purpose (a new spec version) records new hashes; the
 * failure message prints them.
 *
 * The inputs are made here, from a fixed xorshift generator, as raw blobs and
 * raw world states, so nothing outside duelsim and the runtime can move them.
 *
 * Where the processor has AVX2, the games are played on every sensing path
 * it has (AVX2, and AVX2 with AVX-512VL's masks where it has those too:
 * duel_sense_avx2.c) and on the scalar one, against the same hashes, and
 * every random state is also sensed by duel_sense_both on each vector path,
 * which must give duel_sense's inputs exactly.
 */

static uint64_t tg_rng = 0x9E3779B97F4A7C15ull;

static uint32_t tg_next(void)
{
    tg_rng ^= tg_rng << 13;
    tg_rng ^= tg_rng >> 7;
    tg_rng ^= tg_rng << 17;
    return (uint32_t)(tg_rng >> 32);
}

/* uniform in [lo, hi] */
static int32_t tg_range(int32_t lo, int32_t hi)
{
    return lo + (int32_t)(tg_next() % (uint32_t)(hi - lo + 1));
}

static void tg_hash(uint64_t *h, int64_t v)
{
    *h = (*h ^ (uint64_t)v) * 0x100000001B3ull;
}

#define TG_HASH0 0xCBF29CE484222325ull

static void tg_check(const char *what, uint64_t got, uint64_t want)
{
    if (got != want)
        print_error("%s: hash 0x%016llxull, recorded 0x%016llxull: results changed\n", what,
                    (unsigned long long)got, (unsigned long long)want);
    assert_true(got == want);
}

/* ---- networks as raw blobs (docs/formats.md) ---- */

#define TG_MAX_CONNS 1200

typedef struct tg_net {
    uint8_t blob[NRT_HEADER_SIZE + NRT_CONN_SIZE * TG_MAX_CONNS];
    size_t len;
    uint64_t mem[(4 * TG_MAX_CONNS + 6 * NRT_MAX_NODES + 16) / 8 + 1];
    nrt_net net;
} tg_net;

static void tg_put16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static void tg_put32(uint8_t *p, uint32_t v)
{
    tg_put16(p, v & 0xFFFFu);
    tg_put16(p + 2, v >> 16);
}

/* A weight: mostly what evolution makes (|w| up to about 3), some saturated
 * ones at the Q3.12 limits. */
static int32_t tg_weight(int saturate)
{
    if (saturate && tg_next() % 4 == 0)
        return tg_next() % 2 ? NRT_WEIGHT_MAX : NRT_WEIGHT_MIN;
    return tg_range(-12000, 12000);
}

/* n_in inputs (bias included), n_out outputs, n_hid hidden; every output
 * reads every input (the minimal duel topology) when dense, then random
 * connections (recurrent, self and hidden ones included) up to n_conns. */
static void tg_make(tg_net *t, uint32_t n_in, uint32_t n_out, uint32_t n_hid, uint32_t n_conns, int dense,
                    int saturate)
{
    static uint8_t conn[TG_MAX_CONNS][2];
    uint32_t nodes = n_in + n_out + n_hid, k = 0, i, j, dst;
    size_t need = 0;
    uint8_t *p;
    assert_true(n_conns <= TG_MAX_CONNS && nodes <= NRT_MAX_NODES);
    if (dense)
        for (j = 0; j < n_out; j++)
            for (i = 0; i < n_in && k < n_conns; i++, k++) {
                conn[k][0] = (uint8_t)i;
                conn[k][1] = (uint8_t)(n_in + j);
            }
    for (; k < n_conns; k++) {
        conn[k][0] = (uint8_t)(tg_next() % nodes);
        conn[k][1] = (uint8_t)(n_in + tg_next() % (nodes - n_in));
    }
    memset(t->blob, 0, sizeof t->blob);
    p = t->blob;
    p[0] = NRT_MAGIC0;
    p[1] = NRT_MAGIC1;
    p[2] = NRT_MAGIC2;
    p[3] = NRT_MAGIC3;
    tg_put16(p + NRT_OFF_VERSION, NRT_FORMAT_VERSION);
    tg_put16(p + NRT_OFF_HEADER_SIZE, NRT_HEADER_SIZE);
    tg_put16(p + NRT_OFF_INPUTS, n_in);
    tg_put16(p + NRT_OFF_OUTPUTS, n_out);
    tg_put16(p + NRT_OFF_HIDDEN, n_hid);
    tg_put16(p + NRT_OFF_CONNS, n_conns);
    tg_put32(p + NRT_OFF_TOTAL_SIZE, NRT_HEADER_SIZE + NRT_CONN_SIZE * n_conns);
    p[NRT_OFF_WEIGHT_BITS] = NRT_WEIGHT_FRAC_BITS;
    p[NRT_OFF_ACTIVATION] = NRT_ACT_SIGMOID49;
    /* sorted by target, as the format requires */
    p += NRT_HEADER_SIZE;
    for (dst = n_in; dst < nodes; dst++)
        for (k = 0; k < n_conns; k++)
            if (conn[k][1] == dst) {
                p[0] = conn[k][0];
                p[1] = conn[k][1];
                tg_put16(p + 2, (uint32_t)tg_weight(saturate) & 0xFFFFu);
                p += NRT_CONN_SIZE;
            }
    t->len = NRT_HEADER_SIZE + NRT_CONN_SIZE * n_conns;
    tg_put32(t->blob + NRT_OFF_CRC,
             nrt_crc32(nrt_crc32(0, t->blob, NRT_OFF_CRC), t->blob + NRT_HEADER_SIZE, NRT_CONN_SIZE * n_conns));
    assert_int_equal(nrt_mem_required(t->blob, t->len, &need), NRT_OK);
    assert_true(need <= sizeof t->mem);
    assert_int_equal(nrt_load(&t->net, t->blob, t->len, t->mem, sizeof t->mem), NRT_OK);
}

/* the duel networks of the game test: the shapes evolution and the presets give */
#define TG_NETS 7
static tg_net tg_nets[TG_NETS];

static void tg_make_duel_nets(void)
{
    tg_rng = 0x0123456789ABCDEFull;
    tg_make(&tg_nets[0], DUEL_N_INPUTS, DUEL_N_OUTPUTS, 0, 39, 1, 0);   /* minimal */
    tg_make(&tg_nets[1], DUEL_N_INPUTS, DUEL_N_OUTPUTS, 0, 39, 1, 0);
    tg_make(&tg_nets[2], DUEL_N_INPUTS, DUEL_N_OUTPUTS, 3, 60, 1, 0);   /* a few hidden nodes */
    tg_make(&tg_nets[3], DUEL_N_INPUTS, DUEL_N_OUTPUTS, 20, 202, 1, 0); /* the paper's champion's size */
    tg_make(&tg_nets[4], DUEL_N_INPUTS, DUEL_N_OUTPUTS, 10, 263, 1, 1); /* fixed-10's size, saturating */
    tg_make(&tg_nets[5], DUEL_N_INPUTS, DUEL_N_OUTPUTS, 5, 41, 0, 1);   /* sparse */
    tg_make(&tg_nets[6], DUEL_N_INPUTS, DUEL_N_OUTPUTS, 120, 1100, 0, 0);
}

/* ---- sensing ---- */

/* a coordinate: anywhere on the board, often on its edge */
static int32_t tg_coord(void)
{
    switch (tg_next() % 8) {
    case 0: return DUEL_FIX(DUEL_RADIUS);
    case 1: return DUEL_FIX(DUEL_BOARD - DUEL_RADIUS);
    default: return tg_range(DUEL_FIX(DUEL_RADIUS), DUEL_FIX(DUEL_BOARD - DUEL_RADIUS));
    }
}

/* a heading: anywhere, often on or next to a sector boundary or an axis */
static duel_angle tg_heading(void)
{
    static const uint32_t tenth = 429496730u; /* 2^32 / 10: 36 degrees */
    switch (tg_next() % 4) {
    case 0: return (duel_angle)(tenth * (tg_next() % 10) + (uint32_t)tg_range(-3, 3));
    case 1: return (duel_angle)((tg_next() % 4) << 30) + (uint32_t)tg_range(-3, 3);
    default: return (duel_angle)tg_next();
    }
}

/* the best vector path here (enum duel_simd), read once */
static int tg_simd_best(void)
{
    static int best = -1;
    if (best < 0) {
        duel_simd_allow(DUEL_SIMD_AVX512);
        best = duel_simd_active();
    }
    return best;
}

static const char *const tg_simd_name[] = {"scalar", "AVX2", "AVX-512VL"};

/* The vector path (enum duel_simd) on which duel_sense_both, with its food
 * lanes made afresh, gives other inputs than duel_sense on both sides of w,
 * or 0: each one this processor has */
static int tg_paths_differ(const duel_world *w)
{
    nrt_q15 scalar[2][DUEL_N_INPUTS], both[2][DUEL_N_INPUTS];
    duel_lanes lanes;
    int side, level, differ = 0;
    for (side = 0; side < 2; side++)
        duel_sense(w, side, scalar[side]);
    for (level = DUEL_SIMD_AVX2; level <= tg_simd_best() && !differ; level++) {
        duel_simd_allow(level);
        assert_int_equal(duel_simd_active(), level);
        duel_lanes_init(&lanes, duel_rules_of(w));
        assert_int_equal(duel_sense_both(w, &lanes, both[0], both[1]), 0);
        if (memcmp(both, scalar, sizeof both) != 0)
            differ = level;
    }
    duel_simd_allow(DUEL_SIMD_AVX512);
    return differ;
}

/* 200,000 readings of random states: robots anywhere (on food, on each
 * other, at the walls), any heading, any energies, any food left */
static void test_golden_sensing(void **state)
{
    uint64_t h = TG_HASH0;
    int n, side, k, simd_states = 0;
    (void)state;
    tg_rng = 0xFEEDFACECAFEBEEFull;
    for (n = 0; n < 100000; n++) {
        duel_world w;
        nrt_q15 in[DUEL_N_INPUTS];
        assert_int_equal(duel_world_init(&w, tg_range(DUEL_TRAINING, DUEL_CONFIGS - 1)), DUEL_OK);
        for (side = 0; side < 2; side++) {
            duel_robot *r = &w.robot[side];
            r->x = tg_coord();
            r->y = tg_coord();
            r->heading = tg_heading();
            r->energy = tg_range(-DUEL_FIX(200), DUEL_FIX(3000));
        }
        switch (tg_next() % 8) {
        case 0: /* on a food item */
            k = (int)(tg_next() % w.n_food);
            w.robot[0].x = w.food_x[k] + tg_range(-2, 2);
            w.robot[0].y = w.food_y[k] + tg_range(-2, 2);
            break;
        case 1: /* on the other robot, or nearly */
            w.robot[1].x = w.robot[0].x + tg_range(-1, 1);
            w.robot[1].y = w.robot[0].y + tg_range(-1, 1);
            break;
        case 2: /* equal energies */
            w.robot[1].energy = w.robot[0].energy;
            break;
        default: break;
        }
        w.food_mask = tg_next() % 4 == 0 ? tg_next() & ((1u << w.n_food) - 1u) : (1u << w.n_food) - 1u;
        for (side = 0; side < 2; side++) {
            duel_sense(&w, side, in);
            for (k = 0; k < DUEL_N_INPUTS; k++)
                tg_hash(&h, in[k]);
        }
        if (tg_simd_best() != DUEL_SIMD_NONE) {
            int differ = tg_paths_differ(&w);
            if (differ) {
                print_error("state %d: the %s sensing differs from duel_sense\n", n, tg_simd_name[differ]);
                fail();
            }
            simd_states++;
        }
    }
    print_message("sensing: %d states, %d of them also through the vector paths up to %s\n", n, simd_states,
                  tg_simd_name[tg_simd_best()]);
    tg_check("sensing", h, 0xbb2c7fb9fb6477e0ull);
}

/* The AVX2 readings at every place a reading changes: the other robot at
 * d = 850 (2m - 1) Q16.16 units (d2 = (2m - 1)^2 722500, where round(d /
 * 1700) steps from m - 1 to m) and one unit nearer and farther, along an
 * axis and along a diagonal, for every m the board allows; then food on a
 * sector boundary's line. */
static void test_golden_simd_thresholds(void **state)
{
    int m, off, diag, side, checked = 0;
    (void)state;
    if (tg_simd_best() == DUEL_SIMD_NONE) {
        print_message("no AVX2 here: nothing to compare\n");
        return;
    }
    for (diag = 0; diag < 2; diag++)
        for (m = 1; m < 23000; m++)
            for (off = -1; off <= 1; off++) {
                duel_world w;
                int64_t d = (int64_t)850 * (2 * m - 1) + off;
                /* on the diagonal the offset is d / sqrt(2) on each axis, rounded down */
                int64_t dx = diag ? d * 46341 / 65536 : d, dy = diag ? dx : 0;
                if (DUEL_FIX(DUEL_RADIUS) + dx > DUEL_FIX(DUEL_BOARD - DUEL_RADIUS))
                    continue;
                assert_int_equal(duel_world_init(&w, DUEL_TRAINING), DUEL_OK);
                w.robot[0].x = DUEL_FIX(DUEL_RADIUS);
                w.robot[0].y = DUEL_FIX(DUEL_RADIUS);
                w.robot[1].x = (int32_t)(DUEL_FIX(DUEL_RADIUS) + dx);
                w.robot[1].y = (int32_t)(DUEL_FIX(DUEL_RADIUS) + dy);
                w.robot[0].heading = (duel_angle)(m * 2654435761u);
                w.robot[1].heading = (duel_angle)(m * 40503u);
                if (tg_paths_differ(&w)) {
                    print_error("d = %lld (m = %d, diagonal %d): the %s sensing differs\n", (long long)d, m, diag,
                                tg_simd_name[tg_paths_differ(&w)]);
                    fail();
                }
                checked++;
            }
    /* food exactly on boundary 2's line (behind and ahead): robots on a
     * row or a column of the training food, heading along it */
    for (side = 0; side < 4; side++)
        for (m = 0; m < 3; m++)
            for (off = 10; off <= 590; off += 5) {
                duel_world w;
                assert_int_equal(duel_world_init(&w, DUEL_TRAINING), DUEL_OK);
                w.robot[0].x = side % 2 == 0 ? DUEL_FIX(off) : DUEL_FIX(200 + 100 * m);
                w.robot[0].y = side % 2 == 0 ? DUEL_FIX(200 + 100 * m) : DUEL_FIX(off);
                w.robot[0].heading = (duel_angle)side << 30;
                w.robot[1].x = DUEL_FIX(590 - off);
                w.robot[1].y = w.robot[0].y;
                w.robot[1].heading = (duel_angle)(side ^ 2) << 30;
                if (tg_paths_differ(&w)) {
                    print_error("heading %d, row %d, at %d: the %s sensing differs\n", side, m, off,
                                tg_simd_name[tg_paths_differ(&w)]);
                    fail();
                }
                checked++;
            }
    print_message("%d states at the readings' steps and on sector boundaries: every vector path up to %s = scalar\n",
                  checked, tg_simd_name[tg_simd_best()]);
}

/* ---- network steps ---- */

static nrt_q15 tg_input(void)
{
    switch (tg_next() % 8) {
    case 0: return (nrt_q15)(tg_next() % 2 ? 32767 : -32768);
    case 1: return 0;
    default: return (nrt_q15)tg_range(-32768, 32767);
    }
}

/* networks of every size a blob allows (up to 256 nodes, 1,200 connections
 * here), stepped on random inputs: every activation after every step */
static void test_golden_steps(void **state)
{
    static tg_net t;
    uint64_t h = TG_HASH0;
    int n, s;
    uint32_t i;
    (void)state;
    tg_rng = 0x5DEECE66DA3B1F27ull;
    for (n = 0; n < 120; n++) {
        uint32_t n_in = (uint32_t)tg_range(1, 24), n_out = (uint32_t)tg_range(1, 6);
        uint32_t n_hid = (uint32_t)tg_range(0, (int32_t)(NRT_MAX_NODES - n_in - n_out) / (n % 10 == 0 ? 1 : 8));
        uint32_t n_conns = (uint32_t)tg_range(0, n % 10 == 0 ? TG_MAX_CONNS : 300);
        nrt_q15 in[24], out[6];
        tg_make(&t, n_in, n_out, n_hid, n_conns, n % 3 == 0, n % 2 == 0);
        for (s = 0; s < 60; s++) {
            for (i = 0; i < n_in; i++)
                in[i] = tg_input();
            if (s % 7 == 3) {
                /* the inputs written in place (the duel's way) */
                memcpy(nrt_inputs(&t.net), in, 2u * n_in);
                nrt_step(&t.net, nrt_inputs(&t.net), out);
            } else {
                nrt_step(&t.net, in, s % 5 == 4 ? NULL : out);
            }
            for (i = 0; i < t.net.n_nodes; i++)
                tg_hash(&h, nrt_inputs(&t.net)[i]);
            for (i = 0; i < n_out; i++)
                tg_hash(&h, nrt_outputs(&t.net)[i]);
        }
        tg_hash(&h, nrt_settle(&t.net, in, out, 30));
        for (i = 0; i < n_out; i++)
            tg_hash(&h, out[i]);
    }
    tg_check("network steps", h, 0xad3a0cc06e767afbull);
}

/* ---- whole games ---- */

static void tg_trace(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                     const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    uint64_t *h = ud;
    int side, k;
    tg_hash(h, w->t);
    for (side = 0; side < 2; side++) {
        tg_hash(h, w->robot[side].x);
        tg_hash(h, w->robot[side].y);
        tg_hash(h, w->robot[side].heading);
        tg_hash(h, w->robot[side].energy);
        tg_hash(h, w->robot[side].eaten);
        tg_hash(h, ev->eaten_by[side]);
        for (k = 0; k < DUEL_N_INPUTS; k++)
            tg_hash(h, in[side][k]);
        for (k = 0; k < DUEL_N_OUTPUTS; k++)
            tg_hash(h, out[side][k]);
    }
    tg_hash(h, w->food_mask);
    tg_hash(h, ev->outcome);
}

static void tg_result(uint64_t *h, const duel_result *r)
{
    tg_hash(h, r->outcome);
    tg_hash(h, r->steps);
    tg_hash(h, r->energy[0]);
    tg_hash(h, r->energy[1]);
    tg_hash(h, r->eaten[0]);
    tg_hash(h, r->eaten[1]);
}

/* controller i: the builtins, then the networks */
static duel_controller tg_controller(int i)
{
    duel_controller c;
    c.net = i < DUEL_N_BUILTINS ? NULL : &tg_nets[i - DUEL_N_BUILTINS].net;
    c.builtin = i < DUEL_N_BUILTINS ? i : 0;
    return c;
}

/* every pair of 12 controllers (5 builtins, 7 networks; a network also
 * against its twin) on 13 food configurations, each side: 1,898 games,
 * every step traced; then two whole 288-game comparisons and 21 more
 * games, untraced, the way evolution plays */
static void tg_games(void)
{
    static tg_net twin;
    uint64_t traced = TG_HASH0, untraced = TG_HASH0;
    int i, j, k, side, n = DUEL_N_BUILTINS + TG_NETS;
    duel_tally tally;
    tg_make_duel_nets();
    for (i = 0; i < n; i++)
        for (j = i; j < n; j++) {
            duel_controller a = tg_controller(i), b = tg_controller(j);
            if (i == j) {
                if (a.net == NULL)
                    continue;
                /* a network against itself: its twin, loaded from the same blob */
                assert_int_equal(nrt_load(&twin.net, tg_nets[j - DUEL_N_BUILTINS].blob,
                                          tg_nets[j - DUEL_N_BUILTINS].len, twin.mem, sizeof twin.mem),
                                 NRT_OK);
                b.net = &twin.net;
            }
            for (k = -1; k < 12; k++)
                for (side = 0; side < 2; side++) {
                    duel_result r;
                    int config = k < 0 ? DUEL_TRAINING : k * 12 + (k * 5) % 12;
                    int err = side == 0 ? duel_play(&a, &b, config, &r, tg_trace, &traced)
                                        : duel_play(&b, &a, config, &r, tg_trace, &traced);
                    assert_int_equal(err, DUEL_OK);
                    tg_result(&traced, &r);
                }
        }
    tg_check("traced games", traced, 0x1e7b72fcc3ebd1ceull);
    for (i = 0; i < 2; i++) {
        duel_controller a = tg_controller(DUEL_N_BUILTINS + 2 * i), b = tg_controller(DUEL_N_BUILTINS + 3 + i);
        assert_int_equal(duel_compare(&a, &b, &tally), DUEL_OK);
        tg_hash(&untraced, tally.wins_a);
        tg_hash(&untraced, tally.wins_b);
        tg_hash(&untraced, tally.draws);
        tg_hash(&untraced, tally.timeouts);
    }
    for (k = 0; k < DUEL_CONFIGS; k += 7) {
        duel_controller a = tg_controller(DUEL_N_BUILTINS), b = tg_controller(DUEL_FORAGER_HUNTER);
        duel_result r;
        assert_int_equal(duel_play(&a, &b, k, &r, NULL, NULL), DUEL_OK);
        tg_result(&untraced, &r);
    }
    tg_check("untraced games", untraced, 0xf065414941a055caull);
}

/* The states of the seven networks (and a twin), for comparing what two
 * ways of playing leave in them */
typedef struct tg_states {
    nrt_q15 act[TG_NETS + 1][NRT_MAX_NODES];
    uint16_t cur[TG_NETS + 1];
} tg_states;

static void tg_save_states(tg_states *st, const nrt_net *twin)
{
    int i;
    memset(st, 0, sizeof *st);
    for (i = 0; i <= TG_NETS; i++) {
        const nrt_net *n = i < TG_NETS ? &tg_nets[i].net : twin;
        st->cur[i] = n->cur;
        memcpy(st->act[i], n->act[n->cur], 2u * n->n_nodes);
    }
}

/* duel_play2 against two calls of duel_play for pairs of games: a host
 * against two opponents (on either side), the same two controllers on both
 * sides, two games sharing nothing, builtins, and the networks too large for
 * a dense form (played one after the other); the results and the networks'
 * states after each pair must be the same. Then the errors. */
static void tg_pairs(void)
{
    static tg_net twin;
    static tg_states seq, two;
    int n = DUEL_N_BUILTINS + TG_NETS, i, pairs = 0;
    tg_make_duel_nets();
    assert_int_equal(nrt_load(&twin.net, tg_nets[0].blob, tg_nets[0].len, twin.mem, sizeof twin.mem), NRT_OK);
    tg_rng = 0x5EED5EED5EED5EEDull;
    for (i = 0; i < 400; i++) {
        duel_controller c[4], spare, *west[2], *east[2];
        duel_result r_seq[2], r_two[2];
        int config[2], k, pick[4];
        for (k = 0; k < 4; k++) {
            pick[k] = (int)(tg_next() % (uint64_t)n);
            c[k] = tg_controller(pick[k]);
        }
        spare.net = &twin.net;
        spare.builtin = 0;
        switch (i % 4) {
        case 0: /* a host (c0) against two opponents */
            west[0] = &c[0];
            east[0] = &c[1];
            west[1] = (i & 4) ? &c[0] : &c[2];
            east[1] = (i & 4) ? &c[2] : &c[0];
            break;
        case 1: /* the same two on both sides */
            west[0] = east[1] = &c[0];
            east[0] = west[1] = &c[1];
            break;
        case 2: /* nothing shared (or, by the draw, something) */
            west[0] = &c[0];
            east[0] = &c[1];
            west[1] = &c[2];
            east[1] = &c[3];
            break;
        default: /* the same game twice */
            west[0] = west[1] = &c[0];
            east[0] = east[1] = &c[1];
            break;
        }
        /* one game's two controllers may not share a network: then the
         * east one is the twin of network 0 */
        for (k = 0; k < 2; k++)
            if (west[k]->net != NULL && west[k]->net == east[k]->net)
                east[k] = &spare;
        for (k = 0; k < 2; k++)
            config[k] = (int)(tg_next() % (DUEL_CONFIGS + 1)) - 1;
        for (k = 0; k < 2; k++)
            assert_int_equal(duel_play(west[k], east[k], config[k], &r_seq[k], NULL, NULL), DUEL_OK);
        tg_save_states(&seq, &twin.net);
        assert_int_equal(duel_play2(west, east, config, r_two), DUEL_OK);
        tg_save_states(&two, &twin.net);
        for (k = 0; k < 2; k++) {
            assert_int_equal(r_two[k].outcome, r_seq[k].outcome);
            assert_int_equal(r_two[k].steps, r_seq[k].steps);
            assert_memory_equal(r_two[k].energy, r_seq[k].energy, sizeof r_seq[k].energy);
            assert_memory_equal(r_two[k].eaten, r_seq[k].eaten, sizeof r_seq[k].eaten);
        }
        assert_memory_equal(&two, &seq, sizeof seq);
        pairs++;
    }
    print_message("%d pairs of games: duel_play2 = duel_play twice\n", pairs);
    {
        duel_controller a = tg_controller(DUEL_N_BUILTINS), b = tg_controller(DUEL_N_BUILTINS + 1);
        duel_controller *west[2] = {&a, &a}, *east[2] = {&b, &a};
        int config[2] = {0, 0};
        duel_result r[2];
        /* game 1's two controllers share one network */
        assert_int_equal(duel_play2(west, east, config, r), DUEL_E_ARG);
        assert_int_equal(duel_play2(NULL, east, config, r), DUEL_E_ARG);
        east[1] = &b;
        config[1] = DUEL_CONFIGS;
        assert_int_equal(duel_play2(west, east, config, r), DUEL_E_ARG);
    }
}

static void test_golden_pairs(void **state)
{
    int level;
    (void)state;
    for (level = tg_simd_best(); level >= DUEL_SIMD_NONE; level--) {
        duel_simd_allow(level);
        print_message("pairs with the %s sensing\n", tg_simd_name[level]);
        tg_pairs();
    }
    duel_simd_allow(DUEL_SIMD_AVX512);
}

static void test_golden_games(void **state)
{
    int level;
    (void)state;
    /* the best path first, then each lower one down to the scalar sensing */
    for (level = tg_simd_best(); level >= DUEL_SIMD_NONE; level--) {
        duel_simd_allow(level);
        assert_int_equal(duel_simd_active(), level);
        print_message("games with the %s sensing\n", tg_simd_name[level]);
        tg_games();
    }
    duel_simd_allow(DUEL_SIMD_AVX512);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_golden_sensing),
        cmocka_unit_test(test_golden_simd_thresholds),
        cmocka_unit_test(test_golden_steps),
        cmocka_unit_test(test_golden_games),
        cmocka_unit_test(test_golden_pairs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
