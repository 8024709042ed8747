/* test_match.c - duelsim's games and comparisons: builtins, traces, tallies, determinism, mirror symmetry, errors. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "duel.h"
#include "neat.h"

/* Under -DNEAT_SANITIZE=ON every game here stops at the first sensing of a
 * robot facing west or south: duel_sense.c duel_wall_distance left-shifts a
 * negative value (undefined behaviour), see test_sense.c test_wall. */

/* node ids of the duel genomes: bias 0, sensors 1..12 (input i is node i), outputs l, r, f */
#define TM_L 13u
#define TM_R 14u
#define TM_F 15u

typedef struct tm_net {
    uint8_t blob[1024];
    size_t len;
    uint64_t mem[512];
    nrt_net net;
} tm_net;

typedef struct tm_link {
    uint32_t in, out;
    double w;
} tm_link;

/* A network from a list of connections: n_in sensors (+ bias), n_out outputs, no hidden nodes; step: enum neat_net_step. */
static void tm_build_step(tm_net *t, uint32_t n_in, uint32_t n_out, const tm_link *links, size_t n_links, int step)
{
    neat_genome g;
    size_t need = 0;
    uint32_t i;
    neat_genome_init(&g);
    for (i = 0; i <= n_in + n_out; i++) {
        int type = i == 0 ? NEAT_NODE_BIAS : i <= n_in ? NEAT_NODE_INPUT : NEAT_NODE_OUTPUT;
        assert_int_equal(neat_genome_add_node(&g, i, type, NULL), NEAT_OK);
    }
    for (i = 0; i < n_links; i++)
        assert_int_equal(neat_genome_add_conn(&g, links[i].in, links[i].out, links[i].w, i, 1, NULL), NEAT_OK);
    assert_int_equal(neat_blob_write_step(&g, n_in, n_out, step, t->blob, sizeof t->blob, &t->len), NEAT_OK);
    assert_int_equal(nrt_mem_required(t->blob, t->len, &need), NRT_OK);
    assert_true(need <= sizeof t->mem);
    assert_int_equal(nrt_load(&t->net, t->blob, t->len, t->mem, sizeof t->mem), NRT_OK);
    neat_genome_free(&g, NULL);
}

static void tm_build(tm_net *t, uint32_t n_in, uint32_t n_out, const tm_link *links, size_t n_links)
{
    tm_build_step(t, n_in, n_out, links, n_links, NEAT_STEP_SYNC);
}

/* Goes straight, speed from the bias and the sensors that are their own
 * mirror image (ahead, energy, wall); l = r from the bias alone. */
static const tm_link tm_straight[] = {
    {0, TM_L, 0.3}, {0, TM_R, 0.3}, {0, TM_F, 0.4}, {1, TM_F, 1.5}, {6, TM_F, -0.7}, {11, TM_F, 0.5}, {12, TM_F, -1.2},
};

/* Mirror-symmetric but turning: l reads the left sectors 1 (food) and 1
 * (robot), r the mirror-image right sectors 4; the same bias, wall and
 * self-connection weights on both; f as above, plus a self-connection. Sectors 2 and 3 are left out: an object
 * straight behind is on boundary 2, which the spec gives to sector 3 on
 * either side, so those inputs are not mirror images of each other. */
static const tm_link tm_turner[] = {
    {0, TM_L, -0.4}, {2, TM_L, 2.5}, {7, TM_L, 1.0}, {12, TM_L, 0.8},
    {0, TM_R, -0.4}, {5, TM_R, 2.5}, {10, TM_R, 1.0}, {12, TM_R, 0.8},
    {0, TM_F, 0.3},  {1, TM_F, 1.5}, {6, TM_F, -0.7}, {11, TM_F, 0.5}, {12, TM_F, -1.2},
    {TM_L, TM_L, 0.6}, {TM_R, TM_R, 0.6}, {TM_F, TM_F, -0.5}, /* recurrent: state that a reset must clear */
};

static duel_controller tm_builtin(int b)
{
    duel_controller c;
    c.net = NULL;
    c.builtin = b;
    return c;
}

static duel_controller tm_netc(tm_net *t)
{
    duel_controller c;
    c.net = &t->net;
    c.builtin = 0;
    return c;
}

/* ---- traces ---- */
#define TM_MAX_TRACE (DUEL_MAX_STEPS + 2)
typedef struct tm_trace {
    uint32_t n;
    uint32_t t[TM_MAX_TRACE];
    duel_robot robot[TM_MAX_TRACE][2];
    uint32_t food_mask[TM_MAX_TRACE];
    nrt_q15 in[TM_MAX_TRACE][2][DUEL_N_INPUTS];
    nrt_q15 out[TM_MAX_TRACE][2][DUEL_N_OUTPUTS];
    int outcome[TM_MAX_TRACE];
    uint64_t hash;
} tm_trace;

static void tm_hash(uint64_t *h, int64_t v)
{
    *h = (*h ^ (uint64_t)v) * 0x100000001B3ull;
}

static void tm_record(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                      const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    tm_trace *tr = ud;
    uint32_t i = tr->n < TM_MAX_TRACE ? tr->n : TM_MAX_TRACE - 1;
    int side, k;
    tr->t[i] = w->t;
    memcpy(tr->robot[i], w->robot, sizeof w->robot);
    tr->food_mask[i] = w->food_mask;
    memcpy(tr->in[i], in, sizeof tr->in[i]);
    memcpy(tr->out[i], out, sizeof tr->out[i]);
    tr->outcome[i] = ev->outcome;
    for (side = 0; side < 2; side++) {
        tm_hash(&tr->hash, w->robot[side].x);
        tm_hash(&tr->hash, w->robot[side].y);
        tm_hash(&tr->hash, w->robot[side].heading);
        tm_hash(&tr->hash, w->robot[side].energy);
        tm_hash(&tr->hash, w->robot[side].eaten);
        tm_hash(&tr->hash, ev->eaten_by[side]);
        for (k = 0; k < DUEL_N_INPUTS; k++)
            tm_hash(&tr->hash, in[side][k]);
        for (k = 0; k < DUEL_N_OUTPUTS; k++)
            tm_hash(&tr->hash, out[side][k]);
    }
    tm_hash(&tr->hash, w->food_mask);
    tm_hash(&tr->hash, ev->outcome);
    tr->n++;
}

/* two results field by field (the struct has padding) */
static void tm_same_result(const duel_result *a, const duel_result *b)
{
    assert_int_equal(a->outcome, b->outcome);
    assert_int_equal(a->steps, b->steps);
    assert_int_equal(a->energy[0], b->energy[0]);
    assert_int_equal(a->energy[1], b->energy[1]);
    assert_int_equal(a->eaten[0], b->eaten[0]);
    assert_int_equal(a->eaten[1], b->eaten[1]);
}

static tm_trace *tm_trace_new(void)
{
    tm_trace *tr = test_calloc(1, sizeof *tr);
    assert_non_null(tr);
    tr->hash = 0xCBF29CE484222325ull;
    return tr;
}

/* ---- games with builtins ---- */

/* idle vs idle: nobody moves, the game times out after 750 steps with the energies untouched */
static void test_idle_vs_idle(void **state)
{
    duel_controller a = tm_builtin(DUEL_IDLE), b = tm_builtin(DUEL_IDLE);
    duel_result r;
    (void)state;
    memset(&r, 0xFF, sizeof r);
    assert_int_equal(duel_play(&a, &b, DUEL_TRAINING, &r, NULL, NULL), DUEL_OK);
    assert_int_equal(r.outcome, DUEL_TIMEOUT);
    assert_int_equal(r.steps, 750);
    assert_int_equal(r.energy[0], 1200 * 65536);
    assert_int_equal(r.energy[1], 1200 * 65536);
    assert_int_equal(r.eaten[0], 0);
    assert_int_equal(r.eaten[1], 0);
}

/* the spinner turns in place at the full rate: 750 |theta| paid, nothing eaten */
static void test_spinner_pays(void **state)
{
    duel_controller a = tm_builtin(DUEL_SPINNER), b = tm_builtin(DUEL_IDLE);
    duel_result r;
    double paid;
    (void)state;
    assert_int_equal(duel_play(&a, &b, DUEL_TRAINING, &r, NULL, NULL), DUEL_OK);
    assert_int_equal(r.outcome, DUEL_TIMEOUT);
    paid = 1200.0 - r.energy[DUEL_WEST] / 65536.0;
    /* 750 * 0.24 * 32767 / 32768 = 179.9945 */
    assert_true(fabs(paid - 750 * 0.24 * 32767.0 / 32768.0) < 750.0 / 65536.0);
    assert_int_equal(r.energy[DUEL_EAST], 1200 * 65536);
    assert_int_equal(r.eaten[DUEL_WEST], 0);
}

/* the forager eats training food; energy = 1200 + 200 per item - what it spent */
static void test_forager_eats(void **state)
{
    duel_controller a = tm_builtin(DUEL_FORAGER), b = tm_builtin(DUEL_IDLE);
    duel_result r;
    (void)state;
    assert_int_equal(duel_play(&a, &b, DUEL_TRAINING, &r, NULL, NULL), DUEL_OK);
    printf("forager (west) vs idle: outcome %d after %u steps, ate %u, energy %.3f\n", r.outcome, (unsigned)r.steps,
           (unsigned)r.eaten[DUEL_WEST], r.energy[DUEL_WEST] / 65536.0);
    assert_true(r.eaten[DUEL_WEST] >= 3);
    assert_true(r.energy[DUEL_WEST] > 1200 * 65536);
    assert_int_equal(r.eaten[DUEL_EAST], 0);
    /* from the east side too */
    assert_int_equal(duel_play(&b, &a, DUEL_TRAINING, &r, NULL, NULL), DUEL_OK);
    assert_true(r.eaten[DUEL_EAST] >= 3);
}

/* the trace is called once per step, before.t = 0, 1, 2, ..., with the state before the move */
static void test_trace_once_per_step(void **state)
{
    duel_controller a = tm_builtin(DUEL_FORAGER_HUNTER), b = tm_builtin(DUEL_HUNTER);
    duel_result r, r2;
    tm_trace *tr = tm_trace_new();
    uint32_t i;
    (void)state;
    assert_int_equal(duel_play(&a, &b, 17, &r, tm_record, tr), DUEL_OK);
    assert_int_equal(tr->n, r.steps);
    assert_int_equal(r.outcome, DUEL_WEST_WINS); /* a collision before the time out */
    assert_true(r.steps >= 1 && r.steps < 750);
    for (i = 0; i < tr->n; i++) {
        assert_int_equal(tr->t[i], i);
        /* only the last step ends the game */
        assert_int_equal(tr->outcome[i], i + 1 == tr->n ? r.outcome : DUEL_RUNNING);
    }
    /* step 0 shows the start */
    assert_int_equal(tr->robot[0][DUEL_WEST].x, 100 * 65536);
    assert_int_equal(tr->robot[0][DUEL_EAST].x, 500 * 65536);
    assert_int_equal(tr->robot[0][DUEL_WEST].energy, 1200 * 65536);
    assert_int_equal(tr->food_mask[0], 0x7FFu);
    /* the inputs recorded are those of the state recorded */
    for (i = 0; i < tr->n; i += 37) {
        duel_world w;
        nrt_q15 in[DUEL_N_INPUTS];
        int side;
        assert_int_equal(duel_world_init(&w, 17), DUEL_OK);
        memcpy(w.robot, tr->robot[i], sizeof w.robot);
        w.food_mask = tr->food_mask[i];
        w.t = i;
        for (side = 0; side < 2; side++) {
            duel_sense(&w, side, in);
            assert_memory_equal(in, tr->in[i][side], sizeof in);
        }
    }
    /* the trace does not change the game */
    assert_int_equal(duel_play(&a, &b, 17, &r2, NULL, NULL), DUEL_OK);
    tm_same_result(&r, &r2);
    test_free(tr);
}

/* ---- comparisons ---- */

/* 288 games counted once each; compare(a, b) is compare(b, a) with the wins swapped */
static void test_compare_tally(void **state)
{
    static const int pairs[][2] = {
        {DUEL_FORAGER, DUEL_FORAGER_HUNTER}, {DUEL_FORAGER_HUNTER, DUEL_HUNTER}, {DUEL_FORAGER, DUEL_FORAGER}};
    size_t p;
    (void)state;
    for (p = 0; p < sizeof pairs / sizeof pairs[0]; p++) {
        duel_controller a = tm_builtin(pairs[p][0]), b = tm_builtin(pairs[p][1]);
        duel_tally ab, ba;
        assert_int_equal(duel_compare(&a, &b, &ab), DUEL_OK);
        assert_int_equal(duel_compare(&b, &a, &ba), DUEL_OK);
        printf("%s vs %s: %u wins, %u wins, %u draws, %u timeouts\n", duel_builtin_name(pairs[p][0]),
               duel_builtin_name(pairs[p][1]), (unsigned)ab.wins_a, (unsigned)ab.wins_b, (unsigned)ab.draws,
               (unsigned)ab.timeouts);
        assert_int_equal(ab.wins_a + ab.wins_b + ab.draws + ab.timeouts, 288);
        assert_int_equal(ab.wins_a, ba.wins_b);
        assert_int_equal(ab.wins_b, ba.wins_a);
        assert_int_equal(ab.draws, ba.draws);
        assert_int_equal(ab.timeouts, ba.timeouts);
        assert_true(ab.wins_a + ab.wins_b > 0); /* decisive games happen */
    }
}

/* the tally counts from each side: game by game, against duel_play */
static void test_compare_counts_games(void **state)
{
    duel_controller a = tm_builtin(DUEL_FORAGER), b = tm_builtin(DUEL_FORAGER_HUNTER);
    duel_tally tally, want = {0, 0, 0, 0};
    int k, side;
    (void)state;
    for (k = 0; k < DUEL_CONFIGS; k++)
        for (side = 0; side < 2; side++) {
            duel_result r;
            int a_west = side == 0;
            assert_int_equal(duel_play(a_west ? &a : &b, a_west ? &b : &a, k, &r, NULL, NULL), DUEL_OK);
            if (r.outcome == DUEL_DRAW)
                want.draws++;
            else if (r.outcome == DUEL_TIMEOUT)
                want.timeouts++;
            else if ((r.outcome == DUEL_WEST_WINS) == a_west)
                want.wins_a++;
            else
                want.wins_b++;
        }
    assert_int_equal(duel_compare(&a, &b, &tally), DUEL_OK);
    assert_memory_equal(&tally, &want, sizeof tally);
}

/* idle against idle: 288 timeouts */
static void test_compare_idle(void **state)
{
    duel_controller a = tm_builtin(DUEL_IDLE), b = tm_builtin(DUEL_IDLE);
    duel_tally t;
    (void)state;
    assert_int_equal(duel_compare(&a, &b, &t), DUEL_OK);
    assert_int_equal(t.timeouts, 288);
    assert_int_equal(t.wins_a + t.wins_b + t.draws, 0);
    assert_int_equal(duel_compare(&a, &b, NULL), DUEL_E_ARG);
}

/* ---- determinism and symmetry ---- */

/* the same game twice (networks reset in between) gives the same trace, bit for bit */
static void test_deterministic(void **state)
{
    tm_net *n1 = test_malloc(sizeof *n1), *n2 = test_malloc(sizeof *n2);
    tm_trace *t1 = tm_trace_new(), *t2 = tm_trace_new();
    duel_controller a, b;
    duel_result r1, r2;
    duel_tally c1, c2;
    (void)state;
    tm_build(n1, 12, 3, tm_turner, sizeof tm_turner / sizeof tm_turner[0]);
    tm_build(n2, 12, 3, tm_straight, sizeof tm_straight / sizeof tm_straight[0]);
    a = tm_netc(n1);
    b = tm_netc(n2);
    assert_int_equal(duel_play(&a, &b, 50, &r1, tm_record, t1), DUEL_OK);
    assert_int_equal(duel_play(&a, &b, 50, &r2, tm_record, t2), DUEL_OK);
    tm_same_result(&r1, &r2);
    assert_int_equal(t1->n, t2->n);
    assert_true(t1->hash == t2->hash);
    assert_memory_equal(t1->in, t2->in, sizeof t1->in);
    b = tm_builtin(DUEL_FORAGER_HUNTER);
    assert_int_equal(duel_compare(&a, &b, &c1), DUEL_OK);
    assert_int_equal(duel_compare(&a, &b, &c2), DUEL_OK);
    assert_memory_equal(&c1, &c2, sizeof c1);
    test_free(t1);
    test_free(t2);
    test_free(n1);
    test_free(n2);
}

/* Networks without hidden nodes, whose only cycles are self-connections,
 * act the same in both step modes (an output reads the inputs of now and
 * its own last value either way). The propagate ones, which duel_play
 * cannot give to the dense step (nrt_dense_make refuses them), play step
 * for step the games of the sync ones, which take the dense step where
 * there is one: the fallback to nrt_step runs the blob's mode. */
static void test_propagate_nets_play(void **state)
{
    tm_net *s1 = test_malloc(sizeof *s1), *s2 = test_malloc(sizeof *s2);
    tm_net *p1 = test_malloc(sizeof *p1), *p2 = test_malloc(sizeof *p2);
    tm_trace *ts = tm_trace_new(), *tp = tm_trace_new();
    duel_controller a, b, c, d;
    duel_result rs, rp;
    duel_tally cs, cp;
    (void)state;
    tm_build(s1, 12, 3, tm_turner, sizeof tm_turner / sizeof tm_turner[0]);
    tm_build(s2, 12, 3, tm_straight, sizeof tm_straight / sizeof tm_straight[0]);
    tm_build_step(p1, 12, 3, tm_turner, sizeof tm_turner / sizeof tm_turner[0], NEAT_STEP_PROPAGATE);
    tm_build_step(p2, 12, 3, tm_straight, sizeof tm_straight / sizeof tm_straight[0], NEAT_STEP_PROPAGATE);
    assert_int_equal(p1->net.step, NRT_STEP_PROPAGATE);
    a = tm_netc(s1);
    b = tm_netc(s2);
    c = tm_netc(p1);
    d = tm_netc(p2);
    assert_int_equal(duel_play(&a, &b, 50, &rs, tm_record, ts), DUEL_OK);
    assert_int_equal(duel_play(&c, &d, 50, &rp, tm_record, tp), DUEL_OK);
    tm_same_result(&rs, &rp);
    assert_int_equal(ts->n, tp->n);
    assert_true(ts->hash == tp->hash);
    assert_memory_equal(ts->out, tp->out, sizeof ts->out);
    b = tm_builtin(DUEL_FORAGER_HUNTER);
    assert_int_equal(duel_compare(&a, &b, &cs), DUEL_OK);
    assert_int_equal(duel_compare(&c, &b, &cp), DUEL_OK);
    assert_memory_equal(&cs, &cp, sizeof cs);
    test_free(ts);
    test_free(tp);
    test_free(s1);
    test_free(s2);
    test_free(p1);
    test_free(p2);
}

/* Every step of a game between two copies of one mirror-symmetric network
 * on mirror-symmetric food is a mirror image: x_west = 600 - x_east,
 * y equal, heading_west = pi - heading_east, energies and meals equal,
 * inputs mirrored (1 <-> 4, 2 <-> 3 in each rangefinder group), l and r swapped. */
static void tm_check_mirror(const tm_trace *tr)
{
    static const int mirror[DUEL_N_INPUTS] = {0, 1, 5, 4, 3, 2, 6, 10, 9, 8, 7, 11, 12};
    uint32_t i;
    int k;
    for (i = 0; i < tr->n; i++) {
        const duel_robot *w = &tr->robot[i][DUEL_WEST], *e = &tr->robot[i][DUEL_EAST];
        int axis;
        if (w->x != 600 * 65536 - e->x || w->y != e->y || w->heading != DUEL_HALF_TURN - e->heading ||
            w->energy != e->energy || w->eaten != e->eaten)
            fail_msg("step %u: west (%d, %d, %u, %d), east (%d, %d, %u, %d)", (unsigned)i, w->x, w->y,
                     (unsigned)w->heading, w->energy, e->x, e->y, (unsigned)e->heading, e->energy);
        /* Straight behind is exactly on boundary 2 when the heading is a
         * multiple of 45 degrees, and the spec gives it to sector 3 on
         * either side: the rear sectors (inputs 3, 4, 8, 9) are then not
         * mirror images (at the start both robots have food and the other
         * robot straight behind). Otherwise they must be. */
        axis = e->heading % 0x20000000u == 0;
        for (k = 0; k < DUEL_N_INPUTS; k++)
            if (axis && (k == 3 || k == 4 || k == 8 || k == 9))
                continue;
            else if (tr->in[i][DUEL_WEST][k] != tr->in[i][DUEL_EAST][mirror[k]])
                fail_msg("step %u: west in[%d] = %d, east in[%d] = %d", (unsigned)i, k, tr->in[i][DUEL_WEST][k],
                         mirror[k], tr->in[i][DUEL_EAST][mirror[k]]);
        assert_int_equal(tr->out[i][DUEL_WEST][0], tr->out[i][DUEL_EAST][1]);
        assert_int_equal(tr->out[i][DUEL_WEST][1], tr->out[i][DUEL_EAST][0]);
        assert_int_equal(tr->out[i][DUEL_WEST][2], tr->out[i][DUEL_EAST][2]);
    }
}

/* a straight-driving symmetric network on both sides of the training food */
static void test_mirror_straight(void **state)
{
    tm_net *n1 = test_malloc(sizeof *n1), *n2 = test_malloc(sizeof *n2);
    tm_trace *tr = tm_trace_new();
    duel_controller a, b;
    duel_result r;
    (void)state;
    tm_build(n1, 12, 3, tm_straight, sizeof tm_straight / sizeof tm_straight[0]);
    tm_build(n2, 12, 3, tm_straight, sizeof tm_straight / sizeof tm_straight[0]);
    a = tm_netc(n1);
    b = tm_netc(n2);
    assert_int_equal(duel_play(&a, &b, DUEL_TRAINING, &r, tm_record, tr), DUEL_OK);
    tm_check_mirror(tr);
    assert_int_equal(r.outcome, DUEL_TIMEOUT);
    assert_int_equal(r.energy[0], r.energy[1]);
    /* it did move, toward the west wall */
    assert_true(tr->robot[tr->n - 1][DUEL_WEST].x < 50 * 65536);
    test_free(tr);
    test_free(n1);
    test_free(n2);
}

/* a turning mirror-symmetric network on symmetric configurations (K = 13 j:
 * the same candidate on both halves) */
static void test_mirror_turning(void **state)
{
    tm_net *n1 = test_malloc(sizeof *n1), *n2 = test_malloc(sizeof *n2);
    tm_trace *tr = tm_trace_new();
    duel_controller a, b;
    int j, turned = 0, ate = 0;
    (void)state;
    tm_build(n1, 12, 3, tm_turner, sizeof tm_turner / sizeof tm_turner[0]);
    tm_build(n2, 12, 3, tm_turner, sizeof tm_turner / sizeof tm_turner[0]);
    a = tm_netc(n1);
    b = tm_netc(n2);
    for (j = 0; j < 12; j++) {
        duel_result r;
        uint32_t i;
        memset(tr, 0, sizeof *tr);
        assert_int_equal(duel_play(&a, &b, 13 * j, &r, tm_record, tr), DUEL_OK);
        tm_check_mirror(tr);
        assert_true(r.outcome == DUEL_TIMEOUT || r.outcome == DUEL_DRAW);
        assert_int_equal(r.energy[0], r.energy[1]);
        for (i = 0; i < tr->n; i++)
            if (tr->robot[i][DUEL_EAST].heading % 0x40000000u != 0)
                turned = 1;
        ate += r.eaten[0];
    }
    /* the games were not trivial: the robots turned and ate */
    assert_true(turned);
    assert_true(ate > 0);
    printf("mirror-symmetric turner: %d items eaten per side over 12 symmetric configurations\n", ate);
    test_free(tr);
    test_free(n1);
    test_free(n2);
}

/* ---- bad controllers and arguments ---- */

/* one nrt_net cannot drive both robots */
static void test_same_net_refused(void **state)
{
    tm_net *n = test_malloc(sizeof *n);
    duel_controller a, b;
    duel_result r;
    (void)state;
    tm_build(n, 12, 3, tm_straight, sizeof tm_straight / sizeof tm_straight[0]);
    a = tm_netc(n);
    b = tm_netc(n);
    assert_int_equal(duel_play(&a, &b, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_ARG);
    assert_int_equal(duel_play(&a, &a, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_ARG);
    test_free(n);
}

/* networks without 13 inputs and 3 outputs: DUEL_E_NET, on either side */
static void test_wrong_shape_refused(void **state)
{
    static const tm_link few_in[] = {{0, 12, 1.0}};  /* 11 sensors: outputs are 12..14 */
    static const tm_link many_in[] = {{0, 14, 1.0}}; /* 13 sensors */
    static const tm_link two_out[] = {{0, 13, 1.0}}; /* 12 sensors, 2 outputs */
    tm_net *n = test_malloc(sizeof *n);
    duel_controller c, idle = tm_builtin(DUEL_IDLE);
    duel_result r;
    (void)state;
    tm_build(n, 11, 3, few_in, 1);
    c = tm_netc(n);
    assert_int_equal(duel_play(&c, &idle, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_NET);
    assert_int_equal(duel_play(&idle, &c, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_NET);
    assert_int_equal(duel_compare(&c, &idle, &(duel_tally){0, 0, 0, 0}), DUEL_E_NET);
    tm_build(n, 13, 3, many_in, 1);
    assert_int_equal(duel_play(&c, &idle, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_NET);
    tm_build(n, 12, 2, two_out, 1);
    assert_int_equal(duel_play(&idle, &c, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_NET);
    test_free(n);
}

/* NULL arguments and a bad food configuration: DUEL_E_ARG */
static void test_play_bad_args(void **state)
{
    duel_controller a = tm_builtin(DUEL_IDLE), b = tm_builtin(DUEL_FORAGER);
    duel_result r;
    (void)state;
    assert_int_equal(duel_play(&a, &b, DUEL_TRAINING, NULL, NULL, NULL), DUEL_E_ARG);
    assert_int_equal(duel_play(NULL, &b, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_ARG);
    assert_int_equal(duel_play(&a, NULL, DUEL_TRAINING, &r, NULL, NULL), DUEL_E_ARG);
    assert_int_equal(duel_play(&a, &b, 144, &r, NULL, NULL), DUEL_E_ARG);
    assert_int_equal(duel_play(&a, &b, -2, &r, NULL, NULL), DUEL_E_ARG);
    assert_int_equal(duel_play(&a, &b, 143, &r, NULL, NULL), DUEL_OK);
    /* a builtin index out of range is refused (with DUEL_E_NET today; duel.h
     * lists bad builtins under DUEL_E_ARG only for names) */
    a.builtin = DUEL_N_BUILTINS;
    assert_true(duel_play(&a, &b, DUEL_TRAINING, &r, NULL, NULL) < 0);
    a.builtin = -1;
    assert_true(duel_play(&b, &a, DUEL_TRAINING, &r, NULL, NULL) < 0);
}

/* builtin names: each parses to its index and back; anything else is DUEL_E_ARG */
static void test_builtin_names(void **state)
{
    static const char *const names[DUEL_N_BUILTINS] = {"idle", "spinner", "forager", "hunter", "forager-hunter"};
    static const char *const bad[] = {"",        "Forager", "forage",       "foragerr",
                                      "forager-", "hunter ", "builtin:idle", "none"};
    int i;
    size_t k;
    (void)state;
    assert_int_equal(duel_builtin_parse("idle"), DUEL_IDLE);
    assert_int_equal(duel_builtin_parse("spinner"), DUEL_SPINNER);
    assert_int_equal(duel_builtin_parse("forager"), DUEL_FORAGER);
    assert_int_equal(duel_builtin_parse("hunter"), DUEL_HUNTER);
    assert_int_equal(duel_builtin_parse("forager-hunter"), DUEL_FORAGER_HUNTER);
    for (i = 0; i < DUEL_N_BUILTINS; i++) {
        assert_string_equal(duel_builtin_name(i), names[i]);
        assert_int_equal(duel_builtin_parse(duel_builtin_name(i)), i);
    }
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++)
        assert_int_equal(duel_builtin_parse(bad[k]), DUEL_E_ARG);
    assert_int_equal(duel_builtin_parse(NULL), DUEL_E_ARG);
    assert_null(duel_builtin_name(-1));
    assert_null(duel_builtin_name(DUEL_N_BUILTINS));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_idle_vs_idle),
        cmocka_unit_test(test_spinner_pays),
        cmocka_unit_test(test_forager_eats),
        cmocka_unit_test(test_trace_once_per_step),
        cmocka_unit_test(test_compare_tally),
        cmocka_unit_test(test_compare_counts_games),
        cmocka_unit_test(test_compare_idle),
        cmocka_unit_test(test_deterministic),
        cmocka_unit_test(test_propagate_nets_play),
        cmocka_unit_test(test_mirror_straight),
        cmocka_unit_test(test_mirror_turning),
        cmocka_unit_test(test_same_net_refused),
        cmocka_unit_test(test_wrong_shape_refused),
        cmocka_unit_test(test_play_bad_args),
        cmocka_unit_test(test_builtin_names),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
