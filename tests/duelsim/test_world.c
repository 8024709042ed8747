/* test_world.c - duelsim's world and step: start, food layouts, motion, energy, walls, eating, collision, timeout. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "duel.h"

#define TW_PI 3.14159265358979323846
#define TW_TURN_RAD (2.0 * TW_PI / 4294967296.0) /* radians per binary-angle unit */

#define TW_NEAR(got, want, tol)                                                                                     \
    do {                                                                                                            \
        double tw_g_ = (double)(got), tw_w_ = (double)(want);                                                       \
        if (fabs(tw_g_ - tw_w_) > (double)(tol))                                                                    \
            fail_msg("%s = %.9g, want %.9g +- %g", #got, tw_g_, tw_w_, (double)(tol));                              \
    } while (0)

static const nrt_q15 tw_idle[DUEL_N_OUTPUTS] = {0, 0, 0};

static int32_t tw_q16(double v)
{
    return (int32_t)floor(v * 65536.0 + 0.5);
}

/* the signed difference of two binary angles, in radians */
static double tw_turned(duel_angle from, duel_angle to)
{
    return (double)(int32_t)(to - from) * TW_TURN_RAD;
}

/* A training world without food, the robots at (wx, wy) and (ex, ey). */
static void tw_world(duel_world *w, double wx, double wy, double ex, double ey)
{
    assert_int_equal(duel_world_init(w, DUEL_TRAINING), DUEL_OK);
    w->food_mask = 0;
    w->robot[DUEL_WEST].x = tw_q16(wx);
    w->robot[DUEL_WEST].y = tw_q16(wy);
    w->robot[DUEL_EAST].x = tw_q16(ex);
    w->robot[DUEL_EAST].y = tw_q16(ey);
}

/* the spec's start: positions, headings, energies, clock, outcome */
static void test_init_start(void **state)
{
    duel_world w;
    int side;
    (void)state;
    memset(&w, 0xA5, sizeof w);
    assert_int_equal(duel_world_init(&w, DUEL_TRAINING), DUEL_OK);
    assert_int_equal(w.robot[DUEL_WEST].x, 100 * 65536);
    assert_int_equal(w.robot[DUEL_WEST].y, 300 * 65536);
    assert_int_equal(w.robot[DUEL_WEST].heading, 0x80000000u);
    assert_int_equal(w.robot[DUEL_EAST].x, 500 * 65536);
    assert_int_equal(w.robot[DUEL_EAST].y, 300 * 65536);
    assert_int_equal(w.robot[DUEL_EAST].heading, 0u);
    for (side = 0; side < 2; side++) {
        assert_int_equal(w.robot[side].energy, 1200 * 65536);
        assert_int_equal(w.robot[side].eaten, 0);
    }
    assert_int_equal(w.t, 0);
    assert_int_equal(w.outcome, DUEL_RUNNING);
}

/* training food: 9 items, item i at (200 + 100 (i mod 3), 200 + 100 (i div 3)) */
static void test_init_training_food(void **state)
{
    static const int xy[9][2] = {{200, 200}, {300, 200}, {400, 200}, {200, 300}, {300, 300},
                                 {400, 300}, {200, 400}, {300, 400}, {400, 400}};
    duel_world w;
    int i;
    (void)state;
    assert_int_equal(duel_world_init(&w, DUEL_TRAINING), DUEL_OK);
    assert_int_equal(w.n_food, 9);
    assert_int_equal(w.food_mask, 0x1FFu);
    for (i = 0; i < 9; i++) {
        assert_int_equal(w.food_x[i], xy[i][0] * 65536);
        assert_int_equal(w.food_y[i], xy[i][1] * 65536);
    }
}

/* configuration K: the training items, item 9 at P[K div 12], item 10 at the mirror of P[K mod 12] */
static void test_init_config_food(void **state)
{
    static const struct {
        int k;
        int x9, y9, x10, y10;
    } cases[] = {
        {0, 60, 75, 540, 75},      /* P[0] and mirror P[0] */
        {13, 60, 225, 540, 225},   /* P[1], mirror P[1] */
        {29, 60, 375, 460, 225},   /* P[2], mirror P[5] */
        {70, 140, 225, 380, 375},  /* P[5], mirror P[10] */
        {143, 220, 525, 380, 525}, /* P[11], mirror P[11] */
    };
    static const int px[3] = {60, 140, 220}, py[4] = {75, 225, 375, 525};
    duel_world w;
    size_t c;
    int k, i;
    (void)state;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        assert_int_equal(duel_world_init(&w, cases[c].k), DUEL_OK);
        assert_int_equal(w.n_food, 11);
        assert_int_equal(w.food_mask, 0x7FFu);
        assert_int_equal(w.food_x[9], cases[c].x9 * 65536);
        assert_int_equal(w.food_y[9], cases[c].y9 * 65536);
        assert_int_equal(w.food_x[10], cases[c].x10 * 65536);
        assert_int_equal(w.food_y[10], cases[c].y10 * 65536);
    }
    /* every configuration, by the spec's formula, training items unchanged */
    for (k = 0; k < DUEL_CONFIGS; k++) {
        int jw = k / 12, je = k % 12;
        assert_int_equal(duel_world_init(&w, k), DUEL_OK);
        for (i = 0; i < 9; i++) {
            assert_int_equal(w.food_x[i], (200 + 100 * (i % 3)) * 65536);
            assert_int_equal(w.food_y[i], (200 + 100 * (i / 3)) * 65536);
        }
        assert_int_equal(w.food_x[9], px[jw / 4] * 65536);
        assert_int_equal(w.food_y[9], py[jw % 4] * 65536);
        assert_int_equal(w.food_x[10], (600 - px[je / 4]) * 65536);
        assert_int_equal(w.food_y[10], py[je % 4] * 65536);
        assert_true(w.food_x[9] < 300 * 65536 && w.food_x[10] > 300 * 65536);
    }
}

/* food configurations outside DUEL_TRAINING..143, and no world: DUEL_E_ARG */
static void test_init_bad_config(void **state)
{
    static const int bad[] = {-2, -100, 144, 145, 1000};
    duel_world w;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++)
        assert_int_equal(duel_world_init(&w, bad[i]), DUEL_E_ARG);
    assert_int_equal(duel_world_init(NULL, DUEL_TRAINING), DUEL_E_ARG);
    assert_int_equal(duel_world_init(NULL, 0), DUEL_E_ARG);
}

/* f = 1 (NRT_ONE), no turn: 1.33 units along the heading, 1.33 energy */
static void test_forward(void **state)
{
    static const duel_angle headings[] = {0u, 0x80000000u, 0x40000000u, 0x2AAAAAABu /* 60 deg */, 0xE0000000u};
    const nrt_q15 fwd[DUEL_N_OUTPUTS] = {0, 0, NRT_ONE};
    const double step = 1.33 * 32767.0 / 32768.0; /* board units */
    size_t i;
    (void)state;
    for (i = 0; i < sizeof headings / sizeof headings[0]; i++) {
        duel_world w;
        duel_robot before;
        tw_world(&w, 150, 300, 450, 300);
        w.robot[DUEL_EAST].heading = headings[i];
        before = w.robot[DUEL_EAST];
        assert_int_equal(duel_world_step(&w, tw_idle, fwd, NULL), DUEL_RUNNING);
        TW_NEAR(w.robot[DUEL_EAST].x - before.x, step * cos(headings[i] * TW_TURN_RAD) * 65536.0, 2);
        TW_NEAR(w.robot[DUEL_EAST].y - before.y, step * sin(headings[i] * TW_TURN_RAD) * 65536.0, 2);
        assert_int_equal(w.robot[DUEL_EAST].heading, headings[i]);
        TW_NEAR(before.energy - w.robot[DUEL_EAST].energy, step * 65536.0, 2);
        /* the idle robot neither moved nor paid */
        assert_int_equal(w.robot[DUEL_WEST].x, tw_q16(150));
        assert_int_equal(w.robot[DUEL_WEST].energy, tw_q16(1200));
        assert_int_equal(w.t, 1);
    }
    {
        /* along an axis the move is exact: round(1.33 * 32767 / 32768 * 65536) = 87160 */
        duel_world w;
        tw_world(&w, 150, 300, 450, 300);
        duel_world_step(&w, fwd, fwd, NULL);
        assert_int_equal(w.robot[DUEL_EAST].x, tw_q16(450) + 87160);
        assert_int_equal(w.robot[DUEL_WEST].x, tw_q16(150) - 87160);
        assert_int_equal(w.robot[DUEL_EAST].y, tw_q16(300));
        assert_int_equal(w.robot[DUEL_WEST].y, tw_q16(300));
    }
}

/* l = 1, r = 0, f = 0: a turn of 0.24 * 32767 / 32768 rad in place (within
 * 1e-8 rad: two rounded half turns are 1.5e-9), paid |theta| */
static void test_pure_turn(void **state)
{
    const nrt_q15 left[DUEL_N_OUTPUTS] = {NRT_ONE, 0, 0}, right[DUEL_N_OUTPUTS] = {0, NRT_ONE, 0};
    const nrt_q15 both[DUEL_N_OUTPUTS] = {NRT_ONE, NRT_ONE, 0};
    const double theta = 0.24 * 32767.0 / 32768.0;
    duel_world w;
    duel_robot before;
    (void)state;
    tw_world(&w, 150, 300, 450, 300);
    w.robot[DUEL_WEST].heading = 0xFFFFFF00u; /* crosses 0: wraps modulo 2^32 */
    before = w.robot[DUEL_WEST];
    duel_world_step(&w, left, right, NULL);
    TW_NEAR(tw_turned(before.heading, w.robot[DUEL_WEST].heading), theta, 1e-8);
    TW_NEAR(tw_turned(0u, w.robot[DUEL_EAST].heading), -theta, 1e-8);
    /* left and right are exact opposites */
    assert_int_equal((int32_t)(w.robot[DUEL_WEST].heading - before.heading), -(int32_t)w.robot[DUEL_EAST].heading);
    /* in place */
    assert_int_equal(w.robot[DUEL_WEST].x, before.x);
    assert_int_equal(w.robot[DUEL_WEST].y, before.y);
    assert_int_equal(w.robot[DUEL_EAST].x, tw_q16(450));
    /* energy: |theta| */
    TW_NEAR(before.energy - w.robot[DUEL_WEST].energy, theta * 65536.0, 1);
    assert_int_equal(w.robot[DUEL_WEST].energy, w.robot[DUEL_EAST].energy);
    /* l = r = 1: no turn and no turning cost */
    before = w.robot[DUEL_WEST];
    duel_world_step(&w, both, tw_idle, NULL);
    assert_int_equal(w.robot[DUEL_WEST].heading, before.heading);
    assert_int_equal(w.robot[DUEL_WEST].energy, before.energy);
}

/* every output value moves, turns and charges within the last place's
 * rounding of the real rule: forward 1.33 f = 2.66 f Q16.16 units
 * (+-0.5), theta = 0.24 d / 32768 rad (+-1.5 binary-angle units: two
 * rounded half turns), cost within 0.5 Q16.16 units of each term */
static void test_motion_rounding(void **state)
{
    const double half_units = 0.12 / 32768.0 / TW_TURN_RAD; /* binary-angle units of theta / 2 per unit of d */
    double worst_move = 0, worst_turn = 0;
    int32_t v;
    (void)state;
    for (v = 0; v <= 32767; v++) {
        nrt_q15 fwd[DUEL_N_OUTPUTS] = {0, 0, 0}, turn[DUEL_N_OUTPUTS] = {0, 0, 0};
        duel_world w;
        double e;
        fwd[2] = (nrt_q15)v;
        turn[v % 2] = (nrt_q15)v; /* left for even values, right for odd */
        tw_world(&w, 150, 300, 450, 300);
        w.robot[DUEL_WEST].heading = 0;
        duel_world_step(&w, fwd, turn, NULL);
        e = fabs((w.robot[DUEL_WEST].x - tw_q16(150)) - 2.66 * v);
        worst_move = e > worst_move ? e : worst_move;
        TW_NEAR(w.robot[DUEL_WEST].x - tw_q16(150), 2.66 * v, 0.5 + 1e-9);
        TW_NEAR(tw_q16(1200) - w.robot[DUEL_WEST].energy, 2.66 * v, 0.5 + 1e-9);
        e = fabs((double)(int32_t)w.robot[DUEL_EAST].heading - (v % 2 ? -2.0 : 2.0) * half_units * v);
        worst_turn = e > worst_turn ? e : worst_turn;
        TW_NEAR((int32_t)w.robot[DUEL_EAST].heading, (v % 2 ? -2.0 : 2.0) * half_units * v, 1.5);
        TW_NEAR(tw_q16(1200) - w.robot[DUEL_EAST].energy, 0.48 * v, 0.5 + 1e-9);
        assert_int_equal(w.robot[DUEL_EAST].x, tw_q16(450));
    }
    printf("motion rounding: forward within %.3f Q16.16 units, turn within %.3f binary-angle units\n", worst_move,
           worst_turn);
}

/* The double-precision reference of one step's motion (Appendix B): turn
 * theta / 2, move 1.33 f, turn theta / 2; x, y in board units. */
static void tw_ref_move(double *x, double *y, double *h, int l, int r, int f)
{
    double theta = 0.24 * (l - r) / 32768.0;
    *h += theta / 2;
    *x += 1.33 * f / 32768.0 * cos(*h);
    *y += 1.33 * f / 32768.0 * sin(*h);
    *h += theta / 2;
}

/* half turn, move, half turn: the move is along heading + theta / 2, not
 * along the old or the new heading */
static void test_half_turn_order(void **state)
{
    static const nrt_q15 outs[][DUEL_N_OUTPUTS] = {
        {20000, 0, NRT_ONE}, {0, 32767, 32767}, {32767, 1000, 16000}, {123, 30000, 30000},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof outs / sizeof outs[0]; i++) {
        duel_world w;
        duel_angle h_bin = 0x0C49BA5Eu; /* about 0.3 rad */
        double h0 = h_bin * TW_TURN_RAD, h = h0, x = 450, y = 300, f = 1.33 * outs[i][2] / 32768.0, theta;
        tw_world(&w, 150, 300, 450, 300);
        w.robot[DUEL_EAST].heading = h_bin;
        duel_world_step(&w, tw_idle, outs[i], NULL);
        tw_ref_move(&x, &y, &h, outs[i][0], outs[i][1], outs[i][2]);
        theta = h - h0;
        TW_NEAR(w.robot[DUEL_EAST].x, x * 65536.0, 2);
        TW_NEAR(w.robot[DUEL_EAST].y, y * 65536.0, 2);
        TW_NEAR(tw_turned(h_bin, w.robot[DUEL_EAST].heading), theta, 1e-8);
        /* the test tells the orders apart: a move along the new heading or
         * along the old one lands far more than 2 Q16.16 units away */
        assert_true(fabs(450 + f * cos(h0 + theta) - x) * 65536.0 > 100 ||
                    fabs(300 + f * sin(h0 + theta) - y) * 65536.0 > 100);
        assert_true(fabs(450 + f * cos(h0) - x) * 65536.0 > 100 || fabs(300 + f * sin(h0) - y) * 65536.0 > 100);
    }
}

/* energy over many steps of varied outputs against the double-precision rule,
 * |theta| + 1.33 f per step: within one Q16.16 unit per step */
static void test_energy_accounting(void **state)
{
    duel_world w;
    double spent[2] = {0, 0};
    uint32_t s = 0x9E3779B9u, t;
    int side;
    (void)state;
    tw_world(&w, 100, 300, 500, 300);
    for (t = 0; t < 740; t++) {
        nrt_q15 out[2][DUEL_N_OUTPUTS];
        for (side = 0; side < 2; side++) {
            int o;
            for (o = 0; o < 3; o++) {
                s ^= s << 13;
                s ^= s >> 17;
                s ^= s << 5;
                out[side][o] = (nrt_q15)(s % 32768u);
            }
            if (t % 50 == 0) { /* the extremes too */
                out[side][0] = NRT_ONE;
                out[side][1] = 0;
                out[side][2] = NRT_ONE;
            }
            spent[side] += 0.24 * fabs((double)out[side][0] - out[side][1]) / 32768.0 + 1.33 * out[side][2] / 32768.0;
        }
        assert_int_equal(duel_world_step(&w, out[0], out[1], NULL), DUEL_RUNNING);
        /* keep them apart: positions do not enter the energy */
        w.robot[DUEL_WEST].x = tw_q16(100);
        w.robot[DUEL_WEST].y = tw_q16(300);
        w.robot[DUEL_EAST].x = tw_q16(500);
        w.robot[DUEL_EAST].y = tw_q16(300);
    }
    for (side = 0; side < 2; side++) {
        double got = 1200.0 - w.robot[side].energy / 65536.0;
        printf("side %d: spent %.6f in 740 steps, double %.6f, difference %.2e\n", side, got, spent[side],
               got - spent[side]);
        TW_NEAR(got * 65536.0, spent[side] * 65536.0, 740);
        assert_true(spent[side] > 300); /* really spent */
    }
}

/* driving into the west wall stops at x = 10 exactly, and the robot slides along y */
static void test_wall_clip(void **state)
{
    const nrt_q15 fwd[DUEL_N_OUTPUTS] = {0, 0, NRT_ONE};
    const double step = 1.33 * 32767.0 / 32768.0;
    duel_world w;
    int i;
    (void)state;
    tw_world(&w, 11, 300, 500, 300);
    w.robot[DUEL_WEST].heading = 0x80000000u; /* due west */
    duel_world_step(&w, fwd, tw_idle, NULL);
    assert_int_equal(w.robot[DUEL_WEST].x, 10 * 65536);
    assert_int_equal(w.robot[DUEL_WEST].y, 300 * 65536);
    /* the full 1.33 is paid even though only 1 unit was moved */
    TW_NEAR(1200 * 65536 - w.robot[DUEL_WEST].energy, step * 65536.0, 2);
    /* 30 degrees north of west: x stays 10, y grows by 1.33 sin 150 deg each step */
    w.robot[DUEL_WEST].heading = 0x80000000u - 0x15555555u;
    for (i = 0; i < 20; i++) {
        int32_t y0 = w.robot[DUEL_WEST].y;
        duel_world_step(&w, fwd, tw_idle, NULL);
        assert_int_equal(w.robot[DUEL_WEST].x, 10 * 65536);
        TW_NEAR(w.robot[DUEL_WEST].y - y0, step * 0.5 * 65536.0, 1);
    }
    /* into the north-east corner: both coordinates clamp to 590 */
    tw_world(&w, 100, 300, 589.5, 589.9);
    w.robot[DUEL_EAST].heading = 0x20000000u;
    for (i = 0; i < 3; i++) {
        duel_world_step(&w, tw_idle, fwd, NULL);
        assert_int_equal(w.robot[DUEL_EAST].x, 590 * 65536);
        assert_int_equal(w.robot[DUEL_EAST].y, 590 * 65536);
    }
    /* south wall */
    tw_world(&w, 100, 10.5, 500, 300);
    w.robot[DUEL_WEST].heading = 0xC0000000u;
    duel_world_step(&w, fwd, tw_idle, NULL);
    assert_int_equal(w.robot[DUEL_WEST].y, 10 * 65536);
    assert_int_equal(w.robot[DUEL_WEST].x, 100 * 65536);
}

/* a robot closer than 15 to an item eats it: +200, the bit clears, the event and count record it */
static void test_eat(void **state)
{
    duel_world w;
    duel_event ev;
    (void)state;
    tw_world(&w, 286, 300, 500, 300); /* 14 from item 4 at (300, 300) */
    w.food_mask = 1u << 4 | 1u << 8;
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, &ev), DUEL_RUNNING);
    assert_int_equal(w.robot[DUEL_WEST].energy, 1400 * 65536);
    assert_int_equal(w.robot[DUEL_EAST].energy, 1200 * 65536);
    assert_int_equal(w.food_mask, 1u << 8);
    assert_int_equal(ev.eaten_by[DUEL_WEST], 1u << 4);
    assert_int_equal(ev.eaten_by[DUEL_EAST], 0);
    assert_int_equal(w.robot[DUEL_WEST].eaten, 1);
    assert_int_equal(w.robot[DUEL_EAST].eaten, 0);
    /* gone: no second helping */
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, &ev), DUEL_RUNNING);
    assert_int_equal(w.robot[DUEL_WEST].energy, 1400 * 65536);
    assert_int_equal(ev.eaten_by[DUEL_WEST], 0);
    assert_int_equal(w.robot[DUEL_WEST].eaten, 1);
}

/* eating uses the position after this step's move */
static void test_eat_after_move(void **state)
{
    const nrt_q15 fwd[DUEL_N_OUTPUTS] = {0, 0, NRT_ONE};
    duel_world w;
    (void)state;
    tw_world(&w, 285, 300, 500, 300); /* exactly 15: not yet */
    w.food_mask = 1u << 4;
    w.robot[DUEL_WEST].heading = 0;
    duel_world_step(&w, fwd, tw_idle, NULL);
    assert_int_equal(w.food_mask, 0);
    assert_int_equal(w.robot[DUEL_WEST].energy, 1400 * 65536 - 87160);
}

/* exactly 15 away (on an axis and as a 9-12-15 triangle) does not eat; one Q16.16 unit closer does */
static void test_eat_distance_15(void **state)
{
    static const double pos[][2] = {{285, 300}, {315, 300}, {300, 285}, {291, 312}, {312, 309}};
    duel_world w;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof pos / sizeof pos[0]; i++) {
        tw_world(&w, pos[i][0], pos[i][1], 500, 500);
        w.food_mask = 1u << 4;
        duel_world_step(&w, tw_idle, tw_idle, NULL);
        assert_int_equal(w.food_mask, 1u << 4);
        assert_int_equal(w.robot[DUEL_WEST].energy, 1200 * 65536);
    }
    tw_world(&w, 285, 300, 500, 500);
    w.robot[DUEL_WEST].x += 1;
    w.food_mask = 1u << 4;
    duel_world_step(&w, tw_idle, tw_idle, NULL);
    assert_int_equal(w.food_mask, 0);
    assert_int_equal(w.robot[DUEL_WEST].energy, 1400 * 65536);
}

/* both robots within 15 of one item: the nearer eats all of it */
static void test_eat_nearer_wins(void **state)
{
    duel_world w;
    duel_event ev;
    (void)state;
    tw_world(&w, 288, 300, 310, 300); /* 12 and 10 from (300, 300), 22 apart */
    w.food_mask = 1u << 4;
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, &ev), DUEL_RUNNING);
    assert_int_equal(w.robot[DUEL_WEST].energy, 1200 * 65536);
    assert_int_equal(w.robot[DUEL_EAST].energy, 1400 * 65536);
    assert_int_equal(ev.eaten_by[DUEL_WEST], 0);
    assert_int_equal(ev.eaten_by[DUEL_EAST], 1u << 4);
    assert_int_equal(w.food_mask, 0);
    /* and the other way round */
    tw_world(&w, 291, 300, 313, 300); /* 9 and 13 */
    w.food_mask = 1u << 4;
    duel_world_step(&w, tw_idle, tw_idle, &ev);
    assert_int_equal(w.robot[DUEL_WEST].energy, 1400 * 65536);
    assert_int_equal(w.robot[DUEL_EAST].energy, 1200 * 65536);
    assert_int_equal(w.robot[DUEL_EAST].eaten, 0);
}

/* an exact tie shares the item: +100 each, both count it */
static void test_eat_tie_shares(void **state)
{
    static const double pos[][4] = {
        {289, 300, 311, 300}, /* mirror images, 11 each */
        {287, 300, 305, 312}, /* 13 each (a 5-12-13 triangle), 21.6 apart */
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof pos / sizeof pos[0]; i++) {
        duel_world w;
        duel_event ev;
        tw_world(&w, pos[i][0], pos[i][1], pos[i][2], pos[i][3]);
        w.food_mask = 1u << 4;
        assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, &ev), DUEL_RUNNING);
        assert_int_equal(w.robot[DUEL_WEST].energy, 1300 * 65536);
        assert_int_equal(w.robot[DUEL_EAST].energy, 1300 * 65536);
        assert_int_equal(ev.eaten_by[DUEL_WEST], 1u << 4);
        assert_int_equal(ev.eaten_by[DUEL_EAST], 1u << 4);
        assert_int_equal(w.robot[DUEL_WEST].eaten, 1);
        assert_int_equal(w.robot[DUEL_EAST].eaten, 1);
        assert_int_equal(w.food_mask, 0);
    }
}

/* closer than 20 ends the game: more energy wins, equal is a draw */
static void test_collision_outcomes(void **state)
{
    static const struct {
        double ew, ee;
        int outcome;
    } cases[] = {
        {1200.5, 1200, DUEL_WEST_WINS},
        {1200, 1200 + 1.0 / 65536, DUEL_EAST_WINS},
        {1200, 1200, DUEL_DRAW},
        {10, 3000, DUEL_EAST_WINS},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        duel_world w;
        duel_event ev;
        tw_world(&w, 300, 300, 319, 300);
        w.robot[DUEL_WEST].energy = tw_q16(cases[i].ew);
        w.robot[DUEL_EAST].energy = tw_q16(cases[i].ee);
        assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, &ev), cases[i].outcome);
        assert_int_equal(w.outcome, cases[i].outcome);
        assert_int_equal(ev.outcome, cases[i].outcome);
        assert_int_equal(w.t, 1);
    }
}

/* exactly 20 apart (on an axis and as a 12-16-20 triangle) is no collision; one Q16.16 unit closer is */
static void test_collision_distance_20(void **state)
{
    duel_world w;
    (void)state;
    tw_world(&w, 300, 300, 320, 300);
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, NULL), DUEL_RUNNING);
    tw_world(&w, 300, 300, 312, 316);
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, NULL), DUEL_RUNNING);
    tw_world(&w, 300, 300, 320, 300);
    w.robot[DUEL_EAST].x -= 1;
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, NULL), DUEL_DRAW);
}

/* the collision compares energies after this step's payments and meals */
static void test_collision_after_move_and_food(void **state)
{
    const nrt_q15 fwd[DUEL_N_OUTPUTS] = {0, 0, NRT_ONE};
    duel_world w;
    (void)state;
    /* equal energies; west drives into east and pays for it: east wins */
    tw_world(&w, 300, 300, 321, 300);
    w.robot[DUEL_WEST].heading = 0;
    assert_int_equal(duel_world_step(&w, fwd, tw_idle, NULL), DUEL_EAST_WINS);
    /* west 100 behind but eats an item in the colliding step: west wins */
    tw_world(&w, 300, 300, 319, 300);
    w.robot[DUEL_WEST].energy = tw_q16(1100);
    w.food_x[0] = tw_q16(290);
    w.food_y[0] = tw_q16(300);
    w.food_mask = 1;
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, NULL), DUEL_WEST_WINS);
    assert_int_equal(w.robot[DUEL_WEST].energy, 1300 * 65536);
}

/* step 750 ends the game with DUEL_TIMEOUT, not before */
static void test_timeout(void **state)
{
    duel_world w;
    duel_event ev;
    uint32_t t;
    (void)state;
    assert_int_equal(duel_world_init(&w, DUEL_TRAINING), DUEL_OK);
    for (t = 0; t < 749; t++)
        assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, &ev), DUEL_RUNNING);
    assert_int_equal(w.t, 749);
    assert_int_equal(ev.outcome, DUEL_RUNNING);
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, &ev), DUEL_TIMEOUT);
    assert_int_equal(w.t, 750);
    assert_int_equal(w.outcome, DUEL_TIMEOUT);
    assert_int_equal(ev.outcome, DUEL_TIMEOUT);
}

/* a collision in step 750 is a collision (rule 5 before rule 6) */
static void test_collision_beats_timeout(void **state)
{
    duel_world w;
    (void)state;
    tw_world(&w, 300, 300, 310, 300);
    w.t = 749;
    w.robot[DUEL_EAST].energy = tw_q16(1201);
    assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, NULL), DUEL_EAST_WINS);
    assert_int_equal(w.t, 750);
}

/* stepping a finished world changes nothing and reports its outcome again */
static void test_finished_world_frozen(void **state)
{
    const nrt_q15 busy[DUEL_N_OUTPUTS] = {NRT_ONE, 0, NRT_ONE};
    duel_world w, before;
    duel_event ev;
    int i;
    (void)state;
    for (i = 0; i < 2; i++) {
        memset(&w, 0, sizeof w);
        if (i == 0) {
            tw_world(&w, 300, 300, 310, 300); /* collision */
            w.food_x[0] = tw_q16(305);
            w.food_y[0] = tw_q16(300);
            assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, NULL), DUEL_DRAW);
            w.food_mask = 1; /* an item in reach: still not eaten */
        } else {
            assert_int_equal(duel_world_init(&w, 5), DUEL_OK);
            w.t = 749;
            assert_int_equal(duel_world_step(&w, tw_idle, tw_idle, NULL), DUEL_TIMEOUT);
        }
        memcpy(&before, &w, sizeof w);
        memset(&ev, 0xFF, sizeof ev);
        assert_int_equal(duel_world_step(&w, busy, busy, &ev), before.outcome);
        assert_memory_equal(&w, &before, sizeof w);
        assert_int_equal(ev.outcome, before.outcome);
        assert_int_equal(ev.eaten_by[0], 0);
        assert_int_equal(ev.eaten_by[1], 0);
        assert_int_equal(duel_world_step(&w, busy, busy, NULL), before.outcome);
        assert_memory_equal(&w, &before, sizeof w);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_init_start),
        cmocka_unit_test(test_init_training_food),
        cmocka_unit_test(test_init_config_food),
        cmocka_unit_test(test_init_bad_config),
        cmocka_unit_test(test_forward),
        cmocka_unit_test(test_pure_turn),
        cmocka_unit_test(test_motion_rounding),
        cmocka_unit_test(test_half_turn_order),
        cmocka_unit_test(test_energy_accounting),
        cmocka_unit_test(test_wall_clip),
        cmocka_unit_test(test_eat),
        cmocka_unit_test(test_eat_after_move),
        cmocka_unit_test(test_eat_distance_15),
        cmocka_unit_test(test_eat_nearer_wins),
        cmocka_unit_test(test_eat_tie_shares),
        cmocka_unit_test(test_collision_outcomes),
        cmocka_unit_test(test_collision_distance_20),
        cmocka_unit_test(test_collision_after_move_and_food),
        cmocka_unit_test(test_timeout),
        cmocka_unit_test(test_collision_beats_timeout),
        cmocka_unit_test(test_finished_world_frozen),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
