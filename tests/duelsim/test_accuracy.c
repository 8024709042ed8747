/* test_accuracy.c - the fixed-point sensors and motion against a double-precision reading of the spec, over 10^6 random scenes. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "duel.h"
#include "duel_internal.h"

#define ACC_SCENES 1000000
static const double acc_pi = 3.14159265358979323846;

static uint64_t acc_state = 0x9E3779B97F4A7C15ull;

static uint64_t acc_next(void)
{
    acc_state ^= acc_state << 13;
    acc_state ^= acc_state >> 7;
    acc_state ^= acc_state << 17;
    return acc_state;
}

static double acc_uniform(double lo, double hi)
{
    return lo + (hi - lo) * (double)(acc_next() >> 11) * (1.0 / 9007199254740992.0);
}

static double acc_heading(duel_angle a)
{
    return (double)a * (2.0 * acc_pi / 4294967296.0);
}

/* One robot, one food item, the other robot far in a corner: the food
 * rangefinders against the spec in double precision (sector
 * floor((b + 36) / 72) mod 5 of the bearing b, reading 1 - d / 850). */
static void test_food_rangefinders_match_spec(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    uint32_t n, wrong_sector = 0, near_boundary = 0;
    double max_err = 0.0, sum_err = 0.0, max_boundary_gap = 0.0;
    (void)state;
    for (n = 0; n < ACC_SCENES; n++) {
        double rx = acc_uniform(10, 590), ry = acc_uniform(10, 590), fx, fy, d, b, h, gap, want, got;
        int k, sector;
        duel_world_init(&w, DUEL_TRAINING);
        w.robot[0].x = (int32_t)floor(rx * DUEL_ONE);
        w.robot[0].y = (int32_t)floor(ry * DUEL_ONE);
        w.robot[0].heading = (duel_angle)(acc_next() >> 32);
        w.robot[1].x = DUEL_FIX(590);
        w.robot[1].y = DUEL_FIX(590);
        do {
            fx = acc_uniform(0, 600);
            fy = acc_uniform(0, 600);
        } while (hypot(fx - rx, fy - ry) < 1.0);
        w.food_x[0] = (int32_t)floor(fx * DUEL_ONE);
        w.food_y[0] = (int32_t)floor(fy * DUEL_ONE);
        w.food_mask = 1u;
        duel_sense(&w, DUEL_WEST, in);
        /* the double-precision spec from the same (fixed-point) positions */
        rx = w.robot[0].x / 65536.0;
        ry = w.robot[0].y / 65536.0;
        fx = w.food_x[0] / 65536.0;
        fy = w.food_y[0] / 65536.0;
        h = acc_heading(w.robot[0].heading);
        d = hypot(fx - rx, fy - ry);
        b = fmod(atan2(fy - ry, fx - rx) - h + 4.0 * acc_pi, 2.0 * acc_pi) * 180.0 / acc_pi;
        sector = (int)floor((b + 36.0) / 72.0) % 5;
        gap = fabs(fmod(b + 36.0, 72.0));
        if (gap > 36.0)
            gap = 72.0 - gap;
        for (k = 0; k < 5; k++)
            if (in[1 + k] != 0 && k != sector) {
                /* only a bearing within a hair of a boundary may fall on the other side */
                wrong_sector++;
                if (gap > max_boundary_gap)
                    max_boundary_gap = gap;
            }
        if (gap < 1e-4)
            near_boundary++;
        want = 1.0 - d / 850.0;
        got = 0.0;
        for (k = 0; k < 5; k++)
            if (in[1 + k] != 0)
                got = in[1 + k] / 32768.0;
        if (fabs(got - want) > max_err)
            max_err = fabs(got - want);
        sum_err += fabs(got - want);
    }
    printf("food rangefinders, %d scenes: %u outside the spec's sector (largest distance from a boundary %.3g degrees), "
           "reading error max %.3g mean %.3g\n",
           ACC_SCENES, wrong_sector, max_boundary_gap, max_err, sum_err / ACC_SCENES);
    /* measured 2026-11-25: no bearing outside its sector, reading error 1.53e-5 (half a Q15 step) */
    assert_true(max_boundary_gap < 1e-5); /* degrees */
    assert_true(max_err < 1.0 / 32768.0);
}

/* The wall sensor against max(0, 1 - d / 200) with d along the heading. */
static void test_wall_sensor_matches_spec(void **state)
{
    duel_world w;
    nrt_q15 in[DUEL_N_INPUTS];
    uint32_t n;
    double max_err = 0.0;
    (void)state;
    for (n = 0; n < ACC_SCENES; n++) {
        double x, y, h, c, s, t = 1e30, want;
        duel_world_init(&w, DUEL_TRAINING);
        w.robot[0].x = (int32_t)(acc_next() % (uint64_t)(DUEL_FIX(580))) + DUEL_FIX(10);
        w.robot[0].y = (int32_t)(acc_next() % (uint64_t)(DUEL_FIX(580))) + DUEL_FIX(10);
        w.robot[0].heading = (duel_angle)(acc_next() >> 32);
        duel_sense(&w, DUEL_WEST, in);
        x = w.robot[0].x / 65536.0;
        y = w.robot[0].y / 65536.0;
        h = acc_heading(w.robot[0].heading);
        c = cos(h);
        s = sin(h);
        if (c > 1e-12)
            t = (600.0 - x) / c;
        else if (c < -1e-12)
            t = -x / c;
        if (s > 1e-12 && (600.0 - y) / s < t)
            t = (600.0 - y) / s;
        else if (s < -1e-12 && -y / s < t)
            t = -y / s;
        want = t >= 200.0 ? 0.0 : 1.0 - t / 200.0;
        if (fabs(in[12] / 32768.0 - want) > max_err)
            max_err = fabs(in[12] / 32768.0 - want);
    }
    printf("wall sensor, %d scenes: error max %.3g\n", ACC_SCENES, max_err);
    assert_true(max_err < 1.0 / 32768.0); /* measured 1.55e-5 */
}

/* One step of motion against Appendix B in double precision. */
static void test_motion_matches_spec(void **state)
{
    duel_world w;
    nrt_q15 out[2][DUEL_N_OUTPUTS];
    uint32_t n;
    double max_pos = 0.0, max_head = 0.0, max_energy = 0.0;
    (void)state;
    for (n = 0; n < ACC_SCENES; n++) {
        double x, y, h, e, l, r, f, th, nx, ny, dh;
        int i;
        duel_world_init(&w, DUEL_TRAINING);
        w.robot[0].x = DUEL_FIX(100) + (int32_t)(acc_next() % (uint64_t)DUEL_FIX(400));
        w.robot[0].y = DUEL_FIX(100) + (int32_t)(acc_next() % (uint64_t)DUEL_FIX(400));
        w.robot[0].heading = (duel_angle)(acc_next() >> 32);
        w.robot[1].x = DUEL_FIX(10);
        w.robot[1].y = DUEL_FIX(10);
        w.food_mask = 0;
        for (i = 0; i < 3; i++) {
            out[0][i] = (nrt_q15)(acc_next() % 32768u);
            out[1][i] = 0;
        }
        x = w.robot[0].x / 65536.0;
        y = w.robot[0].y / 65536.0;
        h = acc_heading(w.robot[0].heading);
        e = w.robot[0].energy / 65536.0;
        l = out[0][0] / 32768.0;
        r = out[0][1] / 32768.0;
        f = out[0][2] / 32768.0;
        th = 0.24 * (l - r);
        nx = x + 1.33 * f * cos(h + th / 2.0);
        ny = y + 1.33 * f * sin(h + th / 2.0);
        duel_world_step(&w, out[0], out[1], NULL);
        if (fabs(w.robot[0].x / 65536.0 - nx) > max_pos)
            max_pos = fabs(w.robot[0].x / 65536.0 - nx);
        if (fabs(w.robot[0].y / 65536.0 - ny) > max_pos)
            max_pos = fabs(w.robot[0].y / 65536.0 - ny);
        dh = fabs(fmod(acc_heading(w.robot[0].heading) - (h + th) + 5.0 * acc_pi, 2.0 * acc_pi) - acc_pi);
        if (dh > max_head)
            max_head = dh;
        if (fabs(w.robot[0].energy / 65536.0 - (e - fabs(th) - 1.33 * f)) > max_energy)
            max_energy = fabs(w.robot[0].energy / 65536.0 - (e - fabs(th) - 1.33 * f));
    }
    printf("motion, %d steps: position error max %.3g, heading error max %.3g rad, energy error max %.3g\n",
           ACC_SCENES, max_pos, max_head, max_energy);
    /* measured: 1.52e-5 (a Q16.16 rounding), 1.66e-9 rad, 1.5e-5 */
    assert_true(max_pos < 2.0 / 65536.0);
    assert_true(max_head < 1e-8);
    assert_true(max_energy < 2.0 / 65536.0);
}

/* duel_isqrt32 is the exact floor: every value below 2^21, 10^7 random ones, the edges. */
static void test_isqrt32_exact(void **state)
{
    static const uint32_t edges[] = {0xFFFFFFFFu, 0xFFFE0001u, 0xFFFE0000u, 1u << 30, (1u << 30) - 1u, 1u << 31,
                                     65535u * 65535u, 65536u * 65535u, 3u, 4u};
    uint32_t i, bad = 0;
    (void)state;
    for (i = 0; i < (1u << 21); i++) {
        uint64_t r = duel_isqrt32(i);
        bad += r * r > i || (r + 1) * (r + 1) <= i;
    }
    for (i = 0; i < 10000000u; i++) {
        uint32_t v = (uint32_t)(acc_next() >> 32);
        uint64_t r = duel_isqrt32(v);
        bad += r * r > v || (r + 1) * (r + 1) <= v;
    }
    for (i = 0; i < sizeof edges / sizeof edges[0]; i++) {
        uint64_t r = duel_isqrt32(edges[i]);
        bad += r * r > edges[i] || (r + 1) * (r + 1) <= edges[i];
    }
    assert_int_equal(bad, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_food_rangefinders_match_spec),
        cmocka_unit_test(test_wall_sensor_matches_spec),
        cmocka_unit_test(test_motion_matches_spec),
        cmocka_unit_test(test_isqrt32_exact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
