/* test_rules.c - the world's chosen rules as data: v1's values, the checks, canonical bytes, worlds and games under variant rules. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "duel.h"
#include "duel_internal.h"
#include "neat.h"

#define Q(v) ((int32_t)(v) * DUEL_ONE)

static uint64_t tr_rng = 0x243F6A8885A308D3ull;

static uint64_t tr_next(void)
{
    tr_rng ^= tr_rng << 13;
    tr_rng ^= tr_rng >> 7;
    tr_rng ^= tr_rng << 17;
    return tr_rng;
}

/* uniform in lo..hi */
static int32_t tr_range(int32_t lo, int32_t hi)
{
    return lo + (int32_t)(tr_next() % (uint64_t)(hi - lo + 1));
}

/* Random rules that duel_rules_check accepts: short and long ranges, small
 * and large robots, few or many items, any start (retried until valid). */
static void tr_random_rules(duel_rules *r)
{
    uint32_t i;
    int side;
    do {
        *r = *duel_rules_v1();
        r->radius = tr_range(Q(1), Q(30));
        for (side = 0; side < 2; side++) {
            r->start_x[side] = tr_range(r->radius, Q(600) - r->radius);
            r->start_y[side] = tr_range(r->radius, Q(600) - r->radius);
            r->start_heading[side] = (uint32_t)tr_next();
        }
        r->start_energy = tr_range(Q(1), Q(3000));
        r->food_energy = tr_range(0, Q(600));
        r->eat_dist = tr_range(Q(1), Q(40));
        r->share_dist = tr_range(0, r->eat_dist / 4);
        r->n_train = (uint32_t)tr_range(0, DUEL_MAX_TRAIN_FOOD);
        memset(r->train_x, 0, sizeof r->train_x);
        memset(r->train_y, 0, sizeof r->train_y);
        for (i = 0; i < r->n_train; i++) {
            r->train_x[i] = tr_range(0, Q(600));
            r->train_y[i] = tr_range(0, Q(600));
        }
        for (i = 0; i < DUEL_CANDIDATES; i++) {
            r->cand_x[i] = tr_range(0, Q(600));
            r->cand_y[i] = tr_range(0, Q(600));
        }
        /* a third short (below the board), a third about the board, a third long */
        r->food_range = (uint16_t)(tr_next() % 3 == 0 ? tr_range(1, 300) : tr_range(300, 3000));
        r->robot_range = (uint16_t)(tr_next() % 3 == 0 ? tr_range(1, 300) : tr_range(300, 65535));
        r->energy_scale = (uint16_t)tr_range(1, 2000);
        r->wall_range = (uint16_t)tr_range(1, 1000);
    } while (duel_rules_check(r, NULL, NULL) != DUEL_OK);
}

/* world v1: the values docs/duel-world.md gives, a name, a stable identity */
static void test_rules_v1(void **state)
{
    duel_rules copy = *duel_rules_v1();
    const char *field = "x", *why = "x";
    (void)state;
    assert_int_equal(duel_rules_check(duel_rules_v1(), &field, &why), DUEL_OK);
    assert_string_equal(field, "x"); /* untouched when the rules are good */
    assert_int_equal(duel_rules_v1()->radius, Q(10));
    assert_int_equal(duel_rules_v1()->start_x[DUEL_WEST], Q(100));
    assert_int_equal(duel_rules_v1()->start_x[DUEL_EAST], Q(500));
    assert_int_equal(duel_rules_v1()->start_heading[DUEL_WEST], DUEL_HALF_TURN);
    assert_int_equal(duel_rules_v1()->start_energy, Q(1200));
    assert_int_equal(duel_rules_v1()->food_energy, Q(200));
    assert_int_equal(duel_rules_v1()->eat_dist, Q(15));
    assert_int_equal(duel_rules_v1()->n_train, 9);
    assert_int_equal(duel_rules_v1()->train_x[5], Q(400));
    assert_int_equal(duel_rules_v1()->train_y[5], Q(300));
    assert_int_equal(duel_rules_v1()->cand_x[7], Q(140));
    assert_int_equal(duel_rules_v1()->cand_y[7], Q(525));
    assert_int_equal(duel_rules_v1()->food_range, 850);
    assert_int_equal(duel_rules_v1()->energy_scale, 200);
    assert_int_equal(duel_rules_v1()->wall_range, 200);
    assert_ptr_equal(duel_rules_named("v1"), duel_rules_v1());
    assert_null(duel_rules_named("v9"));
    assert_null(duel_rules_named(NULL));
    assert_string_equal(duel_rules_name(&copy), "v1");
    copy.wall_range = 201;
    assert_null(duel_rules_name(&copy));
    /* the identity is a function of the rules alone: unused training slots
     * do not count */
    copy = *duel_rules_v1();
    copy.n_train = 8;
    copy.train_x[8] = Q(1);
    {
        duel_rules other = copy;
        other.train_x[8] = Q(2);
        assert_true(duel_rules_equal(&copy, &other));
        assert_true(duel_rules_id(&copy) == duel_rules_id(&other));
        assert_true(duel_rules_id(&copy) != duel_rules_id(duel_rules_v1()));
    }
    /* pinned: a change of v1's bytes or of the hash changes every cache key */
    assert_true(duel_rules_id(duel_rules_v1()) == duel_rules_id(duel_rules_named("v1")));
    print_message("v1 identity %016llx\n", (unsigned long long)duel_rules_id(duel_rules_v1()));
}

/* rules that cannot make a game: DUEL_E_RULES naming the key */
static void test_rules_refused(void **state)
{
    static const struct {
        const char *field;
        int what;
    } cases[] = {{"radius", 0},     {"radius", 1},       {"start_west", 2}, {"start_east", 3},   {"start_east", 4},
                 {"start_energy", 5}, {"food_energy", 6}, {"eat_dist", 7},  {"share_dist", 8},   {"train_food", 9},
                 {"train_food", 10}, {"train_food", 11}, {"candidates", 12}, {"candidates", 13}, {"food_range", 14},
                 {"robot_range", 15}, {"energy_scale", 16}, {"wall_range", 17}, {"train_food", 18}};
    size_t c;
    (void)state;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        duel_rules r = *duel_rules_v1();
        const char *field = NULL, *why = NULL;
        duel_world w;
        duel_result res;
        duel_controller a = {NULL, DUEL_IDLE}, b = {NULL, DUEL_IDLE};
        duel_tally t;
        switch (cases[c].what) {
        case 0: r.radius = 0; break;
        case 1: r.radius = Q(101); break;
        case 2: r.start_x[DUEL_WEST] = Q(5); break;                    /* inside the west wall (radius 10) */
        case 3: r.start_y[DUEL_EAST] = Q(595); break;                  /* inside the north wall */
        case 4: r.start_x[DUEL_EAST] = Q(110); r.start_y[DUEL_EAST] = Q(305); break; /* on the other robot */
        case 5: r.start_energy = 0; break;
        case 6: r.food_energy = Q(1001); break;
        case 7: r.eat_dist = 0; break;
        case 8: r.share_dist = r.eat_dist + 1; break;
        case 9: r.n_train = DUEL_MAX_TRAIN_FOOD + 1; break;            /* more items than the maximum */
        case 10: r.train_x[3] = Q(601); break;                          /* an item off the board */
        case 11: r.train_y[0] = -1; break;
        case 12: r.cand_y[11] = Q(600) + 1; break;
        case 13: r.cand_x[0] = Q(500); r.cand_y[0] = Q(300); break;     /* its mirror is on west's start */
        case 14: r.food_range = 0; break;
        case 15: r.robot_range = 0; break;
        case 16: r.energy_scale = 0; break;
        case 17: r.wall_range = 0; break;
        default: r.train_x[0] = Q(100) + 5; r.train_y[0] = Q(300); break; /* under west's start */
        }
        assert_int_equal(duel_rules_check(&r, &field, &why), DUEL_E_RULES);
        if (field == NULL || strcmp(field, cases[c].field) != 0)
            fail_msg("case %d: field %s, want %s", cases[c].what, field ? field : "(null)", cases[c].field);
        assert_non_null(why);
        /* and every function that takes rules refuses them */
        assert_int_equal(duel_world_init_rules(&w, &r, DUEL_TRAINING), DUEL_E_RULES);
        assert_int_equal(duel_play_rules(&r, &a, &b, DUEL_TRAINING, &res, NULL, NULL), DUEL_E_RULES);
        assert_int_equal(duel_compare_rules(&r, &a, &b, &t), DUEL_E_RULES);
        assert_true(duel_rules_id(&r) == 0);
    }
    assert_int_equal(duel_rules_check(NULL, NULL, NULL), DUEL_E_RULES);
}

/* canonical bytes: round trip, and every damaged or short copy refused */
static void test_rules_bytes(void **state)
{
    uint8_t b[DUEL_RULES_BYTES], bad[DUEL_RULES_BYTES + 1];
    duel_rules r, back;
    size_t len, i, off;
    int n;
    (void)state;
    for (n = 0; n < 300; n++) {
        if (n == 0)
            r = *duel_rules_v1();
        else
            tr_random_rules(&r);
        assert_int_equal(duel_rules_encode(&r, b), DUEL_OK);
        memset(&back, 0xA5, sizeof back);
        assert_int_equal(duel_rules_decode(&back, b, sizeof b, NULL), DUEL_OK);
        assert_true(duel_rules_equal(&r, &back));
        assert_true(duel_rules_id(&r) == duel_rules_id(&back));
    }
    /* every truncation, and one byte too many */
    assert_int_equal(duel_rules_encode(duel_rules_v1(), b), DUEL_OK);
    for (len = 0; len < sizeof b; len++) {
        off = 999;
        assert_int_equal(duel_rules_decode(&back, b, len, &off), DUEL_E_RULES);
        assert_true(off <= sizeof b);
    }
    memcpy(bad, b, sizeof b);
    bad[sizeof b] = 0;
    assert_int_equal(duel_rules_decode(&back, bad, sizeof bad, &off), DUEL_E_RULES);
    assert_int_equal(off, DUEL_RULES_BYTES);
    /* every single-byte change: the checksum (or the magic, version,
     * length) catches it */
    for (i = 0; i < sizeof b; i++) {
        memcpy(bad, b, sizeof b);
        bad[i] ^= (uint8_t)(1u + (i % 255u));
        assert_int_equal(duel_rules_decode(&back, bad, sizeof b, &off), DUEL_E_RULES);
    }
    /* rules whose checksum is right but which cannot make a game: the
     * offset of the field */
    {
        duel_rules z = *duel_rules_v1();
        uint32_t crc;
        assert_int_equal(duel_rules_encode(&z, b), DUEL_OK);
        b[224] = b[225] = 0; /* food_range 0 */
        crc = nrt_crc32(0, b, DUEL_RULES_BYTES - 4);
        b[232] = (uint8_t)crc;
        b[233] = (uint8_t)(crc >> 8);
        b[234] = (uint8_t)(crc >> 16);
        b[235] = (uint8_t)(crc >> 24);
        assert_int_equal(duel_rules_decode(&back, b, sizeof b, &off), DUEL_E_RULES);
        assert_int_equal(off, 224);
    }
    assert_int_equal(duel_rules_encode(NULL, b), DUEL_E_RULES);
    assert_int_equal(duel_rules_decode(NULL, b, sizeof b, NULL), DUEL_E_ARG);
}

/* a world under variant rules: starts, energies and food as the rules say */
static void test_rules_world(void **state)
{
    duel_rules r = *duel_rules_v1();
    duel_world w;
    int side;
    (void)state;
    r.radius = Q(25);
    r.start_x[DUEL_WEST] = Q(50);
    r.start_y[DUEL_WEST] = Q(40);
    r.start_heading[DUEL_WEST] = 0x40000000u;
    r.start_x[DUEL_EAST] = Q(520) + 7;
    r.start_energy = Q(900);
    r.n_train = 4;
    r.train_x[0] = 0;
    r.train_y[0] = 0;
    r.train_x[3] = Q(600);
    r.train_y[3] = Q(333) + 1;
    assert_int_equal(duel_world_init_rules(&w, &r, DUEL_TRAINING), DUEL_OK);
    assert_ptr_equal(w.rules, &r);
    assert_int_equal(w.robot[DUEL_WEST].x, Q(50));
    assert_int_equal(w.robot[DUEL_WEST].y, Q(40));
    assert_int_equal(w.robot[DUEL_WEST].heading, 0x40000000u);
    assert_int_equal(w.robot[DUEL_EAST].x, Q(520) + 7);
    for (side = 0; side < 2; side++)
        assert_int_equal(w.robot[side].energy, Q(900));
    assert_int_equal(w.n_food, 4);
    assert_int_equal(w.food_mask, 0xFu);
    assert_int_equal(w.food_y[3], Q(333) + 1);
    /* configuration 13: candidates 1 and 1, after the 4 training items */
    assert_int_equal(duel_world_init_rules(&w, &r, 13), DUEL_OK);
    assert_int_equal(w.n_food, 6);
    assert_int_equal(w.food_x[4], r.cand_x[1]);
    assert_int_equal(w.food_y[4], r.cand_y[1]);
    assert_int_equal(w.food_x[5], Q(600) - r.cand_x[1]);
    assert_int_equal(w.food_y[5], r.cand_y[1]);
    /* NULL rules: v1 */
    assert_int_equal(duel_world_init_rules(&w, NULL, DUEL_TRAINING), DUEL_OK);
    assert_ptr_equal(w.rules, duel_rules_v1());
    assert_int_equal(w.n_food, 9);
    /* the clamp to the board keeps the radius: a robot driving into the
     * south wall stops at y = 25 */
    {
        nrt_q15 fwd[DUEL_N_OUTPUTS] = {0, 0, NRT_ONE}, none[DUEL_N_OUTPUTS] = {0, 0, 0};
        int t;
        assert_int_equal(duel_world_init_rules(&w, &r, DUEL_TRAINING), DUEL_OK);
        w.robot[DUEL_WEST].heading = 0xC0000000u; /* south */
        for (t = 0; t < 40; t++)
            duel_world_step(&w, fwd, none, NULL);
        assert_int_equal(w.robot[DUEL_WEST].y, Q(25));
    }
}

/* the shared-item rule: both within the eating distance, their distances
 * within share_dist of each other: half each; farther apart: the nearer */
static void test_rules_share(void **state)
{
    duel_rules r = *duel_rules_v1();
    nrt_q15 none[DUEL_N_OUTPUTS] = {0, 0, 0};
    duel_world w;
    duel_event ev;
    (void)state;
    r.share_dist = Q(2);
    r.n_train = 1;
    r.train_x[0] = Q(300);
    r.train_y[0] = Q(300);
    /* distances 10 and 11.5: shared */
    assert_int_equal(duel_world_init_rules(&w, &r, DUEL_TRAINING), DUEL_OK);
    w.robot[DUEL_WEST].x = Q(290);
    w.robot[DUEL_WEST].y = Q(300);
    w.robot[DUEL_EAST].x = Q(300);
    w.robot[DUEL_EAST].y = Q(311) + DUEL_ONE / 2;
    duel_world_step(&w, none, none, &ev);
    assert_int_equal(ev.eaten_by[DUEL_WEST], 1u);
    assert_int_equal(ev.eaten_by[DUEL_EAST], 1u);
    assert_int_equal(w.robot[DUEL_WEST].energy, Q(1300));
    assert_int_equal(w.robot[DUEL_EAST].energy, Q(1300));
    /* distances 10 and 12.5: the nearer */
    assert_int_equal(duel_world_init_rules(&w, &r, DUEL_TRAINING), DUEL_OK);
    w.robot[DUEL_WEST].x = Q(290);
    w.robot[DUEL_WEST].y = Q(300);
    w.robot[DUEL_EAST].x = Q(300);
    w.robot[DUEL_EAST].y = Q(312) + DUEL_ONE / 2;
    duel_world_step(&w, none, none, &ev);
    assert_int_equal(ev.eaten_by[DUEL_WEST], 1u);
    assert_int_equal(ev.eaten_by[DUEL_EAST], 0u);
    assert_int_equal(w.robot[DUEL_WEST].energy, Q(1400));
    /* v1 (share_dist 0): 10 and 11.5 is the nearer's */
    r.share_dist = 0;
    assert_int_equal(duel_world_init_rules(&w, &r, DUEL_TRAINING), DUEL_OK);
    w.robot[DUEL_WEST].x = Q(290);
    w.robot[DUEL_WEST].y = Q(300);
    w.robot[DUEL_EAST].x = Q(300);
    w.robot[DUEL_EAST].y = Q(311) + DUEL_ONE / 2;
    duel_world_step(&w, none, none, &ev);
    assert_int_equal(ev.eaten_by[DUEL_EAST], 0u);
}

/* readings under a short range, a narrow energy scale, a long wall range */
static void test_rules_readings(void **state)
{
    duel_rules r = *duel_rules_v1();
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    (void)state;
    r.food_range = 100;
    r.robot_range = 50;
    r.energy_scale = 50;
    r.wall_range = 400;
    r.n_train = 2;
    r.train_x[0] = Q(160); /* 60 ahead of west (heading east below) */
    r.train_y[0] = Q(300);
    r.train_x[1] = Q(300); /* 200 away: beyond the range */
    r.train_y[1] = Q(300);
    assert_int_equal(duel_world_init_rules(&w, &r, DUEL_TRAINING), DUEL_OK);
    w.robot[DUEL_WEST].heading = 0;
    w.robot[DUEL_WEST].energy = Q(1225);
    duel_sense(&w, DUEL_WEST, in);
    assert_int_equal(in[1], 32768 - 19661); /* 1 - 60/100 = 0.4: 32768 - round(60 * 32768 / 100) */
    assert_int_equal(in[2] + in[3] + in[4] + in[5], 0);
    /* the other robot 400 away: beyond its range of 50 */
    assert_int_equal(in[6] + in[7] + in[8] + in[9] + in[10], 0);
    /* 25 ahead on a scale of 50: 0.5 */
    assert_int_equal(in[11], 16384);
    /* the east wall 500 away: beyond 400 */
    assert_int_equal(in[12], 0);
    w.robot[DUEL_WEST].x = Q(300);
    duel_sense(&w, DUEL_WEST, in);
    assert_int_equal(in[12], 32768 - 24576); /* 300 of 400: 0.25 */
    /* the robot 30 away: 1 - 30/50 = 0.4 */
    w.robot[DUEL_EAST].x = Q(330);
    duel_sense(&w, DUEL_WEST, in);
    assert_int_equal(in[6], 32768 - 19661);
}

/* A game the plain way: sense each robot, act, step with the food always
 * tested (duel_world_step), which is what the rules say; duel_play must give
 * the same on every sensing path (its food test is skipped by a bound that
 * depends on the rules, duel_food_near_limit) */
static void tr_plain_game(const duel_rules *r, int bw, int be, int config, duel_result *res)
{
    duel_world w;
    nrt_q15 in[2][DUEL_N_INPUTS], out[2][DUEL_N_OUTPUTS];
    int side;
    assert_int_equal(duel_world_init_rules(&w, r, config), DUEL_OK);
    while (w.outcome == DUEL_RUNNING) {
        for (side = 0; side < 2; side++) {
            duel_sense(&w, side, in[side]);
            duel_builtin_act(side == 0 ? bw : be, in[side], out[side]);
        }
        duel_world_step(&w, out[0], out[1], NULL);
    }
    res->outcome = w.outcome;
    res->steps = w.t;
    for (side = 0; side < 2; side++) {
        res->energy[side] = w.robot[side].energy;
        res->eaten[side] = w.robot[side].eaten;
    }
}

static void test_rules_games(void **state)
{
    int n, level, eaten = 0;
    (void)state;
    tr_rng = 0x1234567887654321ull;
    for (n = 0; n < 150; n++) {
        duel_rules r;
        duel_controller a = {NULL, 0}, b = {NULL, 0};
        duel_result want, got;
        int config = tr_range(DUEL_TRAINING, DUEL_CONFIGS - 1);
        tr_random_rules(&r);
        /* every few games a long range, so the food bound skips tests */
        if (n % 3 == 0)
            r.food_range = (uint16_t)tr_range(300, 900);
        a.builtin = tr_range(DUEL_FORAGER, DUEL_FORAGER_HUNTER);
        b.builtin = tr_range(DUEL_FORAGER, DUEL_FORAGER_HUNTER);
        tr_plain_game(&r, a.builtin, b.builtin, config, &want);
        eaten += want.eaten[0] + want.eaten[1];
        for (level = DUEL_SIMD_AVX512; level >= DUEL_SIMD_NONE; level--) {
            duel_simd_allow(level);
            memset(&got, 0xA5, sizeof got);
            assert_int_equal(duel_play_rules(&r, &a, &b, config, &got, NULL, NULL), DUEL_OK);
            assert_int_equal(got.outcome, want.outcome);
            assert_int_equal(got.steps, want.steps);
            assert_int_equal(got.energy[0], want.energy[0]);
            assert_int_equal(got.energy[1], want.energy[1]);
            assert_int_equal(got.eaten[0], want.eaten[0]);
            assert_int_equal(got.eaten[1], want.eaten[1]);
        }
        duel_simd_allow(DUEL_SIMD_AVX512);
    }
    /* the games ate food: the comparison is not of empty boards */
    assert_true(eaten > 100);
}

/* the food bound: v1's value, and 0 when the range cannot tell */
static void test_rules_food_bound(void **state)
{
    duel_rules r = *duel_rules_v1();
    (void)state;
    assert_int_equal(duel_food_near_limit(&r), 32138);
    r.food_range = 16;
    assert_int_equal(duel_food_near_limit(&r), 0);
    r.food_range = 17;
    assert_true(duel_food_near_limit(&r) > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rules_v1),       cmocka_unit_test(test_rules_refused),
        cmocka_unit_test(test_rules_bytes),    cmocka_unit_test(test_rules_world),
        cmocka_unit_test(test_rules_share),    cmocka_unit_test(test_rules_readings),
        cmocka_unit_test(test_rules_games),    cmocka_unit_test(test_rules_food_bound),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
