/* test_sense.c - duelsim's 13 sensors on hand-placed scenes: sectors, boundaries, ranges, energy, wall, bias. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "duel.h"

#define TS_PI 3.14159265358979323846
#define TS_NEAR(got, want, tol)                                                                                     \
    do {                                                                                                            \
        long ts_g_ = (long)(got), ts_w_ = (long)(want);                                                             \
        if (ts_g_ - ts_w_ > (long)(tol) || ts_w_ - ts_g_ > (long)(tol))                                             \
            fail_msg("%s = %ld, want %ld +- %ld", #got, ts_g_, ts_w_, (long)(tol));                                 \
    } while (0)

static int32_t ts_q16(double v)
{
    return (int32_t)floor(v * 65536.0 + 0.5);
}

static duel_angle ts_deg(double deg)
{
    double u = fmod(deg / 360.0, 1.0);
    if (u < 0)
        u += 1.0;
    return (duel_angle)(uint64_t)floor(u * 4294967296.0 + 0.5);
}

static double ts_rad(duel_angle a)
{
    return (double)a * (2.0 * TS_PI / 4294967296.0);
}

/* A training world with no food left, the robot `side` at (x, y) heading h,
 * the other robot in the far corner. */
static void ts_world(duel_world *w, int side, double x, double y, duel_angle h)
{
    assert_int_equal(duel_world_init(w, DUEL_TRAINING), DUEL_OK);
    w->food_mask = 0;
    w->robot[side].x = ts_q16(x);
    w->robot[side].y = ts_q16(y);
    w->robot[side].heading = h;
    w->robot[side ^ 1].x = ts_q16(x < 300 ? 590 : 10);
    w->robot[side ^ 1].y = ts_q16(y < 300 ? 590 : 10);
}

/* item i placed at bearing `deg` (counter-clockwise from r's heading), distance d */
static void ts_food_at(duel_world *w, uint32_t i, const duel_robot *r, double deg, double d)
{
    double a = ts_rad(r->heading) + deg * TS_PI / 180.0;
    w->food_x[i] = r->x + ts_q16(d * cos(a));
    w->food_y[i] = r->y + ts_q16(d * sin(a));
    w->food_mask |= 1u << i;
}

/* 1 - d / 850 in Q15 (1.0 = 32768, saturated at 32767) for the real
 * distance between r and the Q16.16 point (x, y) */
static long ts_range(const duel_robot *r, int32_t x, int32_t y)
{
    double dx = ((double)x - r->x) / 65536.0, dy = ((double)y - r->y) / 65536.0;
    double v = floor(32768.0 * (1.0 - sqrt(dx * dx + dy * dy) / 850.0) + 0.5);
    return v > 32767 ? 32767 : (v < 0 ? 0 : (long)v);
}

/* only in[first + k] of in[first..first+4] is non-zero, and it reads want +- 1 */
static void ts_only(const nrt_q15 in[DUEL_N_INPUTS], int first, int k, long want)
{
    int j;
    for (j = 0; j < 5; j++)
        if (j != k && in[first + j] != 0)
            fail_msg("in[%d] = %d, want 0 (object in sector %d)", first + j, in[first + j], k);
    TS_NEAR(in[first + k], want, 1);
}

/* a food item anywhere inside sector k (centre and edges +-30 degrees) is read by in[1 + k] alone, as 1 - d / 850 */
static void test_food_sectors(void **state)
{
    static const double offs[] = {-30.0, -17.0, 0.0, 12.5, 30.0};
    static const double dists[] = {25.0, 100.0, 280.0};
    static const duel_angle headings[] = {0u, 0x40000000u, 0x80000000u, 0x9ABCDEF0u, 0x12345678u};
    size_t h, o, di;
    int k;
    (void)state;
    for (h = 0; h < sizeof headings / sizeof headings[0]; h++)
        for (k = 0; k < 5; k++)
            for (o = 0; o < sizeof offs / sizeof offs[0]; o++)
                for (di = 0; di < sizeof dists / sizeof dists[0]; di++) {
                    duel_world w;
                    nrt_q15 in[DUEL_N_INPUTS];
                    ts_world(&w, DUEL_WEST, 300, 300, headings[h]);
                    ts_food_at(&w, 4, &w.robot[0], 72.0 * k + offs[o], dists[di]);
                    duel_sense(&w, DUEL_WEST, in);
                    ts_only(in, 1, k, ts_range(&w.robot[0], w.food_x[4], w.food_y[4]));
                    /* the value against the real-valued rule with the intended distance */
                    TS_NEAR(in[1 + k], floor(32768.0 * (1.0 - dists[di] / 850.0) + 0.5), 1);
                }
}

/* The sector of the single item on the board, from the food rangefinders
 * (-1: none reads). */
static int ts_food_sector(const duel_world *w, int side)
{
    nrt_q15 in[DUEL_N_INPUTS];
    int k, found = -1;
    duel_sense(w, side, in);
    for (k = 0; k < 5; k++)
        if (in[1 + k] != 0) {
            if (found >= 0)
                fail_msg("one item read by sectors %d and %d", found, k);
            found = k;
        }
    return found;
}

/* A bearing exactly on a boundary belongs to the sector counter-clockwise
 * of it. Boundaries lie at 36, 108, 180, 252 and 324 degrees from a binary
 * heading; only the one straight behind (180) can carry an object exactly,
 * and only for headings on multiples of 45 degrees, where the fixed-point
 * heading and boundary vectors are exactly (+-1, 0), (0, +-1) or (c, c):
 * there, straight behind is sector 3, one Q16.16 unit clockwise is sector 2. */
static void test_on_boundary_behind(void **state)
{
    int e;
    (void)state;
    for (e = 0; e < 8; e++) {
        /* the direction straight behind, as integer steps */
        static const int32_t back[8][2] = {{-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}};
        duel_world w;
        nrt_q15 in[DUEL_N_INPUTS];
        int32_t m = back[e][0] != 0 && back[e][1] != 0 ? ts_q16(70) : ts_q16(100);
        int32_t vx = back[e][0] * m, vy = back[e][1] * m;
        /* clockwise of v by one unit per non-zero axis: (vy, -vx) direction */
        int32_t ox = (vy > 0) - (vy < 0), oy = (vx < 0) - (vx > 0);
        ts_world(&w, DUEL_WEST, 300, 300, (duel_angle)e * 0x20000000u);
        w.food_mask = 1;
        w.food_x[0] = w.robot[0].x + vx;
        w.food_y[0] = w.robot[0].y + vy;
        duel_sense(&w, DUEL_WEST, in);
        ts_only(in, 1, 3, ts_range(&w.robot[0], w.food_x[0], w.food_y[0]));
        /* one unit clockwise: sector 2; counter-clockwise: still sector 3 */
        w.food_x[0] = w.robot[0].x + vx + ox;
        w.food_y[0] = w.robot[0].y + vy + oy;
        assert_int_equal(ts_food_sector(&w, DUEL_WEST), 2);
        w.food_x[0] = w.robot[0].x + vx - ox;
        w.food_y[0] = w.robot[0].y + vy - oy;
        assert_int_equal(ts_food_sector(&w, DUEL_WEST), 3);
        /* the robot rangefinders follow the same rule */
        w.food_mask = 0;
        w.robot[1].x = w.robot[0].x + vx;
        w.robot[1].y = w.robot[0].y + vy;
        duel_sense(&w, DUEL_WEST, in);
        ts_only(in, 6, 3, ts_range(&w.robot[0], w.robot[1].x, w.robot[1].y));
    }
}

/* Every boundary lies where the spec puts it, (2k + 1) 36 degrees from the
 * heading, within the fixed-point error, with no gap and no overlap: along
 * a line crossing boundary k at 100 units, in exact integer steps of about
 * 3 Q16.16 units, the sector is k up to one point and k + 1 from there on,
 * and the switch is within 3 steps (9 units, 1.4e-4 board units) of the
 * real boundary. */
static void test_boundaries_where_spec_says(void **state)
{
    uint32_t seed = 0x1234567u, n;
    int worst = 0;
    (void)state;
    for (n = 0; n < 400; n++) {
        int k;
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        for (k = 0; k < 5; k++) {
            duel_world w;
            double u, bx, by;
            int32_t sx, sy;
            int j, sw = 99, prev = -1;
            ts_world(&w, DUEL_WEST, 300, 300, (duel_angle)seed);
            u = ts_rad(w.robot[0].heading) + (2 * k + 1) * 36.0 * TS_PI / 180.0;
            bx = 100.0 * cos(u);
            by = 100.0 * sin(u);
            /* an exact integer step, counter-clockwise across the boundary */
            sx = (int32_t)floor(-3.0 * sin(u) + 0.5);
            sy = (int32_t)floor(3.0 * cos(u) + 0.5);
            w.food_mask = 1;
            for (j = -12; j <= 12; j++) {
                int sec;
                w.food_x[0] = w.robot[0].x + ts_q16(bx) + j * sx;
                w.food_y[0] = w.robot[0].y + ts_q16(by) + j * sy;
                sec = ts_food_sector(&w, DUEL_WEST);
                if (sec != k && sec != (k + 1) % 5)
                    fail_msg("heading %u boundary %d step %d: sector %d", (unsigned)seed, k, j, sec);
                if (prev == (k + 1) % 5 && sec == k)
                    fail_msg("heading %u boundary %d: back to sector %d at step %d", (unsigned)seed, k, k, j);
                if (prev == k && sec == (k + 1) % 5)
                    sw = j;
                prev = sec;
            }
            if (sw == 99 || sw < -3 || sw > 4)
                fail_msg("heading %u boundary %d: switch at step %d", (unsigned)seed, k, sw);
            if (abs(sw) > worst)
                worst = abs(sw);
        }
    }
    printf("sector boundaries: switch at most %d steps of 3 units from the real boundary\n", worst);
}

/* The mirror image of a scene (x -> 600 - x, heading -> pi - heading) is
 * sensed as the mirror image: left and right sectors swap (1 <-> 4, 2 <-> 3),
 * everything else is equal (objects off the boundaries) */
static void test_mirror_image_inputs(void **state)
{
    static const int mirror[DUEL_N_INPUTS] = {0, 1, 5, 4, 3, 2, 6, 10, 9, 8, 7, 11, 12};
    uint32_t seed = 0xCAFEF00Du, n;
    (void)state;
    for (n = 0; n < 20000; n++) {
        duel_world w, m;
        nrt_q15 in[DUEL_N_INPUTS], in_m[DUEL_N_INPUTS];
        int i, side;
        assert_int_equal(duel_world_init(&w, (int)(n % 145) - 1), DUEL_OK);
        for (i = 0; i < 2 + DUEL_MAX_FOOD; i++) {
            int32_t x, y;
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            x = ts_q16(10) + (int32_t)(seed % (uint32_t)ts_q16(580));
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            y = ts_q16(10) + (int32_t)(seed % (uint32_t)ts_q16(580));
            if (i < 2) {
                w.robot[i].x = x;
                w.robot[i].y = y;
                seed ^= seed << 13;
                seed ^= seed >> 17;
                seed ^= seed << 5;
                w.robot[i].heading = seed;
                w.robot[i].energy = ts_q16(1000) + (int32_t)(seed % (uint32_t)ts_q16(400));
            } else if (n % 3 != 0) { /* every third scene keeps the spec's food */
                w.food_x[i - 2] = x;
                w.food_y[i - 2] = y;
            }
        }
        w.food_mask &= (uint32_t)(n * 2654435761u);
        m = w;
        for (i = 0; i < 2; i++) {
            m.robot[i].x = ts_q16(600) - w.robot[i].x;
            m.robot[i].heading = DUEL_HALF_TURN - w.robot[i].heading;
        }
        for (i = 0; i < DUEL_MAX_FOOD; i++)
            m.food_x[i] = ts_q16(600) - w.food_x[i];
        for (side = 0; side < 2; side++) {
            duel_sense(&w, side, in);
            duel_sense(&m, side, in_m);
            for (i = 0; i < DUEL_N_INPUTS; i++)
                if (in_m[mirror[i]] != in[i])
                    fail_msg("scene %u side %d: in[%d] = %d, mirror in[%d] = %d", (unsigned)n, side, i, in[i],
                             mirror[i], in_m[mirror[i]]);
        }
    }
}

/* across the board's diagonal (834 units) the reading is small but positive */
static void test_long_range(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    (void)state;
    ts_world(&w, DUEL_WEST, 10, 10, 0x20000000u); /* facing north-east */
    w.food_x[0] = ts_q16(600);
    w.food_y[0] = ts_q16(600);
    w.food_mask = 1;
    w.robot[1].x = ts_q16(590);
    w.robot[1].y = ts_q16(589);
    duel_sense(&w, DUEL_WEST, in);
    /* 32768 (1 - 834.386 / 850) = 601.9; 32768 (1 - 819.54 / 850) = 1174.3 */
    ts_only(in, 1, 0, 602);
    ts_only(in, 6, 0, ts_range(&w.robot[0], w.robot[1].x, w.robot[1].y));
    assert_true(in[1] > 0 && in[1] < 700);
    assert_true(in[6] > 1000 && in[6] < 1300);
}

/* no object anywhere: every rangefinder reads 0 */
static void test_nothing_reads_zero(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    int k;
    (void)state;
    ts_world(&w, DUEL_WEST, 300, 300, 0x12345678u);
    /* the other robot exactly on top: the zero vector has no sector */
    w.robot[1].x = w.robot[0].x;
    w.robot[1].y = w.robot[0].y;
    duel_sense(&w, DUEL_WEST, in);
    for (k = 1; k <= 10; k++)
        assert_int_equal(in[k], 0);
}

/* two items in one sector: the nearer one is read, whatever the order of the items */
static void test_nearest_wins(void **state)
{
    int order;
    (void)state;
    for (order = 0; order < 2; order++) {
        duel_world w;
        nrt_q15 in[DUEL_N_INPUTS];
        uint32_t near_i = order ? 2u : 7u, far_i = order ? 7u : 2u;
        ts_world(&w, DUEL_WEST, 300, 300, 0x30000000u);
        ts_food_at(&w, far_i, &w.robot[0], 72.0 + 25.0, 120.0);
        ts_food_at(&w, near_i, &w.robot[0], 72.0 - 20.0, 60.0);
        duel_sense(&w, DUEL_WEST, in);
        ts_only(in, 1, 1, ts_range(&w.robot[0], w.food_x[near_i], w.food_y[near_i]));
        TS_NEAR(in[2], floor(32768.0 * (1.0 - 60.0 / 850.0) + 0.5), 1);
    }
}

/* an eaten item (its bit cleared) is not seen, even when nearer */
/* an item exactly at the robot's centre has no bearing: it gives no reading
 * and hides nothing (a farther item ahead is still read); at one unit away it
 * reads, nearly 1 */
static void test_item_at_centre(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    int k;
    (void)state;
    ts_world(&w, 0, 300, 300, ts_deg(10));
    w.food_x[0] = w.robot[0].x;
    w.food_y[0] = w.robot[0].y;
    w.food_mask = 1u;
    duel_sense(&w, 0, in);
    for (k = 1; k <= 5; k++)
        assert_int_equal(in[k], 0);
    ts_food_at(&w, 1, &w.robot[0], 0, 100);
    duel_sense(&w, 0, in);
    ts_only(in, 1, 0, ts_range(&w.robot[0], w.food_x[1], w.food_y[1]));
    w.food_x[0] = w.robot[0].x + 1;
    duel_sense(&w, 0, in);
    ts_only(in, 1, 0, 32767);
}

static void test_eaten_food_unseen(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    (void)state;
    ts_world(&w, DUEL_WEST, 300, 300, 0);
    ts_food_at(&w, 0, &w.robot[0], 0.0, 50.0);
    ts_food_at(&w, 1, &w.robot[0], 10.0, 150.0);
    w.food_mask &= ~1u;
    duel_sense(&w, DUEL_WEST, in);
    ts_only(in, 1, 0, ts_range(&w.robot[0], w.food_x[1], w.food_y[1]));
    w.food_mask &= ~2u;
    duel_sense(&w, DUEL_WEST, in);
    assert_int_equal(in[1], 0);
}

/* the training layout seen from the west start: nearest items per sector */
static void test_training_start(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    (void)state;
    assert_int_equal(duel_world_init(&w, DUEL_TRAINING), DUEL_OK);
    duel_sense(&w, DUEL_WEST, in);
    /* west at (100, 300) facing west: (200, 200) at bearing 135 (sector 2),
     * (200, 400) at 225 and (200, 300) straight behind on boundary 2, both sector 3 */
    assert_int_equal(in[1], 0);
    assert_int_equal(in[2], 0);
    TS_NEAR(in[3], floor(32768.0 * (1.0 - sqrt(20000.0) / 850.0) + 0.5), 1);
    TS_NEAR(in[4], floor(32768.0 * (1.0 - 100.0 / 850.0) + 0.5), 1);
    assert_int_equal(in[5], 0);
    /* the east robot straight behind, 400 away: sector 3 */
    ts_only(in, 6, 3, (long)floor(32768.0 * (1.0 - 400.0 / 850.0) + 0.5));
}

/* the other robot is read by in[6 + k] for its sector k; food rangefinders do not see it */
static void test_robot_sectors(void **state)
{
    static const double offs[] = {-30.0, 0.0, 30.0};
    size_t o;
    int k, side;
    (void)state;
    for (side = 0; side < 2; side++)
        for (k = 0; k < 5; k++)
            for (o = 0; o < sizeof offs / sizeof offs[0]; o++) {
                duel_world w;
                nrt_q15 in[DUEL_N_INPUTS];
                duel_robot *me, *other;
                double a;
                int j;
                ts_world(&w, side, 250, 320, 0x5555AAAAu);
                me = &w.robot[side];
                other = &w.robot[side ^ 1];
                a = ts_rad(me->heading) + (72.0 * k + offs[o]) * TS_PI / 180.0;
                other->x = me->x + ts_q16(150.0 * cos(a));
                other->y = me->y + ts_q16(150.0 * sin(a));
                duel_sense(&w, side, in);
                ts_only(in, 6, k, ts_range(me, other->x, other->y));
                TS_NEAR(in[6 + k], floor(32768.0 * (1.0 - 150.0 / 850.0) + 0.5), 1);
                for (j = 1; j <= 5; j++)
                    assert_int_equal(in[j], 0);
            }
}

/* food does not show on the robot rangefinders */
static void test_food_not_a_robot(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    int k;
    (void)state;
    ts_world(&w, DUEL_WEST, 300, 300, 0);
    w.robot[1].x = w.robot[0].x; /* the other robot gives no reading: zero vector */
    w.robot[1].y = w.robot[0].y;
    for (k = 0; k < 5; k++)
        ts_food_at(&w, (uint32_t)k, &w.robot[0], 72.0 * k, 40.0 + 10.0 * k);
    duel_sense(&w, DUEL_WEST, in);
    for (k = 0; k < 5; k++) {
        assert_true(in[1 + k] > 0);
        assert_int_equal(in[6 + k], 0);
    }
}

/* in[11] = clamp((E_self - E_other) / 200, -1, 1): values, clamping at +-32767, exact opposites */
static void test_energy_difference(void **state)
{
    static const struct {
        double diff;
        long want;
    } cases[] = {
        {0.0, 0},      {100.0, 16384}, {50.0, 8192},   {-50.0, -8192}, {199.0, 32604},
        {200.0, 32767}, {300.0, 32767}, {-200.0, -32767}, {-1000.0, -32767}, {1.0, 164},
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        duel_world w;
        nrt_q15 in_w[DUEL_N_INPUTS], in_e[DUEL_N_INPUTS];
        ts_world(&w, DUEL_WEST, 300, 300, 0);
        w.robot[0].energy = ts_q16(1200.0 + cases[i].diff);
        w.robot[1].energy = ts_q16(1200.0);
        duel_sense(&w, DUEL_WEST, in_w);
        duel_sense(&w, DUEL_EAST, in_e);
        TS_NEAR(in_w[11], cases[i].want, 0);
        TS_NEAR(in_e[11], -cases[i].want, 0);
    }
}

/* for pseudo-random energies the two robots read exact opposites, within 1 LSB of the real value */
static void test_energy_opposites(void **state)
{
    uint32_t s = 0x6D2B79F5u, i;
    (void)state;
    for (i = 0; i < 100000u; i++) {
        duel_world w;
        nrt_q15 in_w[DUEL_N_INPUTS], in_e[DUEL_N_INPUTS];
        double want;
        ts_world(&w, DUEL_WEST, 300, 300, 0);
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        w.robot[0].energy = (int32_t)(s % (3400u * 65536u));
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        w.robot[1].energy = i % 7 == 0 ? w.robot[0].energy + (int32_t)(s % 801u) - 400 /* near 0 */
                                       : (int32_t)(s % (3400u * 65536u));
        duel_sense(&w, DUEL_WEST, in_w);
        duel_sense(&w, DUEL_EAST, in_e);
        assert_int_equal(in_w[11], -in_e[11]);
        want = ((double)w.robot[0].energy - w.robot[1].energy) / 65536.0 / 200.0 * 32768.0;
        want = want > 32767 ? 32767 : (want < -32767 ? -32767 : want);
        assert_true(fabs(in_w[11] - want) <= 0.5 + 1e-9);
    }
}

/* in[12] = max(0, 1 - d / 200), d along the heading to the first edge,
 * including headings with cos < 0 or sin < 0 (the sanitizer build checks
 * that no negative value is shifted on the way). */
static void test_wall(void **state)
{
    static const struct {
        double x, y, deg, d; /* d: distance to the first edge hit, -1: 200 or more */
    } cases[] = {
        {500, 300, 0, 100},      /* east at x = 500: 0.5 */
        {300, 300, 0, -1},       /* east at x = 300: 300 away */
        {400, 300, 0, 200},      /* exactly 200: 0 */
        {100, 300, 180, 100},    /* west */
        {300, 550, 90, 50},      /* north */
        {300, 20, 270, 20},      /* south */
        {590, 300, 0, 10},       /* against the east wall */
        {550, 580, 45, 20 * 1.4142135623730951},  /* into the north-east corner: y = 600 first */
        {580, 500, 45, 20 * 1.4142135623730951},  /* the same corner: x = 600 first */
        {30, 590, 135, 10 * 1.4142135623730951},  /* into the north-west corner: y = 600 first */
        {20, 40, 225, 20 * 1.4142135623730951},   /* into the south-west corner: x = 0 first */
        {300, 300, 30, -1},      /* 300 / cos 30 to the east edge */
        {450, 100, -30, 173.20508075688772}, /* 150 / cos 30 to x = 600 before 200 to y = 0 */
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        duel_world w;
        nrt_q15 in[DUEL_N_INPUTS];
        long want = cases[i].d < 0 ? 0 : (long)floor(32768.0 * (1.0 - cases[i].d / 200.0) + 0.5);
        if (want > 32767)
            want = 32767;
        if (want < 0)
            want = 0;
        ts_world(&w, DUEL_EAST, cases[i].x, cases[i].y, ts_deg(cases[i].deg));
        duel_sense(&w, DUEL_EAST, in);
        TS_NEAR(in[12], want, 1);
    }
}

/* in[0], the bias, is NRT_ONE for both robots in any state */
static void test_bias(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    int side;
    (void)state;
    assert_int_equal(duel_world_init(&w, 77), DUEL_OK);
    for (side = 0; side < 2; side++) {
        duel_sense(&w, side, in);
        assert_int_equal(in[0], NRT_ONE);
    }
    ts_world(&w, DUEL_WEST, 10, 590, 0xDEADBEEFu);
    duel_sense(&w, DUEL_WEST, in);
    assert_int_equal(in[0], NRT_ONE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_food_sectors),
        cmocka_unit_test(test_on_boundary_behind),
        cmocka_unit_test(test_boundaries_where_spec_says),
        cmocka_unit_test(test_mirror_image_inputs),
        cmocka_unit_test(test_long_range),
        cmocka_unit_test(test_nothing_reads_zero),
        cmocka_unit_test(test_nearest_wins),
        cmocka_unit_test(test_eaten_food_unseen),
        cmocka_unit_test(test_item_at_centre),
        cmocka_unit_test(test_training_start),
        cmocka_unit_test(test_robot_sectors),
        cmocka_unit_test(test_food_not_a_robot),
        cmocka_unit_test(test_energy_difference),
        cmocka_unit_test(test_energy_opposites),
        cmocka_unit_test(test_wall),
        cmocka_unit_test(test_bias),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
