/* test_trig.c - duelsim's fixed-point cos/sin (table, error against double, symmetries) and integer square root. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "duel.h"

/*
 * Error of the Q30 products the simulator builds on these values
 * (duel_world.c, duel_sense.c):
 *  - cos/sin are Q2.30 with an absolute error below TT_MAX_ERR (measured
 *    below: linear interpolation on 1024 steps per quarter turn, bound
 *    h^2 / 8 = 2.9e-7 for h = pi / 2048, plus half a Q30 step, 4.7e-10).
 *  - A move is round(dist * c / 2^30) with dist <= 1.33 units = 87160 Q16.16
 *    units: the trigonometric error adds at most 87160 * 3e-7 = 0.026 Q16.16
 *    units (4e-7 board units) to the half unit of the final rounding, so one
 *    coordinate of one move is within 0.53 Q16.16 units (8.1e-6 board units)
 *    of the real-valued move in the direction the simulator computes.
 *  - A rangefinder sector test is the exact sign of a cross product of an
 *    integer Q16.16 vector and a Q30 boundary vector (no rounding): the
 *    boundary's direction is off by at most ~3e-7 rad from (2k+1) 36 degrees
 *    plus the binary angle's own rounding (pi 2^-32 rad).
 */

#define TT_PI 3.14159265358979323846264338327950288L
#define TT_Q30 1073741824.0
/* Measured (x86-64, printed by test_error_bound): max 2.949e-7, mean 1.248e-7.
 * Analytic bound: h^2 / 8 = 2.9413e-7 (h = pi / 2048) for the linear
 * interpolation, plus two Q30 roundings (table entry, interpolation) of
 * 4.66e-10 each: 2.951e-7. The bounds sit just above. */
#define TT_MAX_ERR 2.96e-7
#define TT_MEAN_ERR 1.26e-7

/* xorshift64 (Marsaglia): the test's own reproducible pseudo-random source */
static uint64_t tt_next(uint64_t *s)
{
    uint64_t x = *s;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    *s = x;
    return x;
}

typedef struct tt_err {
    double max, sum;
    uint64_t n;
    duel_angle worst;
} tt_err;

static void tt_measure(tt_err *e, duel_angle a)
{
    int32_t c, s;
    /* the exact real angle of the binary angle, in long double */
    long double rad = (long double)a * (2.0L * TT_PI / 4294967296.0L);
    double ec, es;
    duel_cossin(a, &c, &s);
    ec = fabs((double)((long double)c / TT_Q30 - cosl(rad)));
    es = fabs((double)((long double)s / TT_Q30 - sinl(rad)));
    if (ec > e->max) {
        e->max = ec;
        e->worst = a;
    }
    if (es > e->max) {
        e->max = es;
        e->worst = a;
    }
    e->sum += ec + es;
    e->n += 2;
}

/* (a) the quarter-wave table: binary angle i 2^20 is table entry i, exactly
 * round(2^30 sin(i pi / 2048)), and its cosine is entry 1024 - i */
static void test_table_entries(void **state)
{
    int32_t table[1025];
    uint32_t i;
    (void)state;
    for (i = 0; i <= 1024; i++) {
        int32_t c, s;
        long double want = floorl(1073741824.0L * sinl((long double)i * TT_PI / 2048.0L) + 0.5L);
        duel_cossin((duel_angle)(i << 20), &c, &s);
        assert_int_equal(s, (int32_t)want);
        table[i] = s;
    }
    for (i = 0; i <= 1024; i++) {
        int32_t c, s;
        duel_cossin((duel_angle)(i << 20), &c, &s);
        assert_int_equal(c, table[1024 - i]);
    }
    assert_int_equal(table[0], 0);
    assert_int_equal(table[1024], 1 << 30);
}

static void tt_report(const char *what, const tt_err *e)
{
    printf("duel_cossin, %s: %llu values, max abs error %.4e (binary angle %lu), mean %.4e\n", what,
           (unsigned long long)e->n, e->max, (unsigned long)e->worst, e->sum / (double)e->n);
}

/* (b) absolute error against long double cos/sin, as a fraction of 1.0 */
static void test_error_bound(void **state)
{
    tt_err grid = {0.0, 0.0, 0, 0}, rnd = {0.0, 0.0, 0, 0};
    uint64_t seed = 0x9E3779B97F4A7C15ull;
    uint32_t i;
    (void)state;
    for (i = 0; i < (1u << 20); i++) /* evenly spaced, 2^12 apart: 256 points in every table interval */
        tt_measure(&grid, (duel_angle)(i << 12));
    for (i = 0; i < 1000000u; i++)
        tt_measure(&rnd, (duel_angle)(tt_next(&seed) >> 32));
    tt_report("2^20 evenly spaced angles", &grid);
    tt_report("10^6 xorshift64 angles", &rnd);
    assert_true(grid.max < TT_MAX_ERR);
    assert_true(rnd.max < TT_MAX_ERR);
    assert_true(grid.sum / (double)grid.n < TT_MEAN_ERR);
    assert_true(rnd.sum / (double)rnd.n < TT_MEAN_ERR);
    /* and not vacuously: the interpolation error really is there */
    assert_true(grid.max > 2.9e-7);
}

/* (c) the symmetries of the real functions hold exactly */
static void test_exact_symmetries(void **state)
{
    uint64_t seed = 0xD1B54A32D192ED03ull;
    uint32_t i;
    (void)state;
    for (i = 0; i < 1000000u; i++) {
        duel_angle a = (duel_angle)(tt_next(&seed) >> 32);
        int32_t c, s, c2, s2;
        if (i < 8) /* the quadrant edges and their neighbours */
            a = (duel_angle)((i / 2) * 0x40000000u + (i % 2));
        duel_cossin(a, &c, &s);
        duel_cossin((duel_angle)(0u - a), &c2, &s2);
        assert_int_equal(c2, c);
        assert_int_equal(s2, -s);
        duel_cossin((duel_angle)(DUEL_HALF_TURN - a), &c2, &s2);
        assert_int_equal(c2, -c);
        assert_int_equal(s2, s);
        duel_cossin((duel_angle)(a + 0x40000000u), &c2, &s2);
        assert_int_equal(c2, -s);
        assert_int_equal(s2, c);
        duel_cossin((duel_angle)(a + DUEL_HALF_TURN), &c2, &s2);
        assert_int_equal(c2, -c);
        assert_int_equal(s2, -s);
    }
}

/* the axes are exact: (1, 0), (0, 1), (-1, 0), (0, -1) in Q30 */
static void test_axes_exact(void **state)
{
    static const int32_t want[4][2] = {{1 << 30, 0}, {0, 1 << 30}, {-(1 << 30), 0}, {0, -(1 << 30)}};
    uint32_t q;
    (void)state;
    for (q = 0; q < 4; q++) {
        int32_t c, s;
        duel_cossin((duel_angle)(q << 30), &c, &s);
        assert_int_equal(c, want[q][0]);
        assert_int_equal(s, want[q][1]);
    }
}

/* r = isqrt(x) is floor(sqrt(x)): r^2 <= x < (r + 1)^2, in 64-bit integers */
static void tt_check_isqrt(uint64_t x)
{
    uint64_t r = duel_isqrt64(x);
    assert_true(r <= 0xFFFFFFFFull);
    assert_true(r * r <= x);
    /* (r + 1)^2 = 2^64 when r = 2^32 - 1: above every uint64 */
    if (r < 0xFFFFFFFFull)
        assert_true((r + 1) * (r + 1) > x);
}

/* (d) edge cases by value */
static void test_isqrt_edges(void **state)
{
    static const struct {
        uint64_t x;
        uint32_t r;
    } cases[] = {
        {0, 0},
        {1, 1},
        {2, 1},
        {3, 1},
        {4, 2},
        {0xFFFFFFFFull, 65535},
        {1ull << 62, 1u << 31},
        {0x3FFFFFFF00000001ull, 0x7FFFFFFFu},             /* (2^31 - 1)^2 */
        {0x3FFFFFFF00000000ull, 0x7FFFFFFEu},             /* (2^31 - 1)^2 - 1 */
        {(1ull << 62) - 1, 0x7FFFFFFFu},                  /* (2^31)^2 - 1 */
        {0xFFFFFFFE00000001ull, 0xFFFFFFFFu},             /* (2^32 - 1)^2 */
        {0xFFFFFFFFFFFFFFFFull, 0xFFFFFFFFu},
        {(uint64_t)600 * 65536 * 600 * 65536 * 2, 55609140u}, /* the board's diagonal, Q32 */
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        assert_int_equal(duel_isqrt64(cases[i].x), cases[i].r);
        tt_check_isqrt(cases[i].x);
    }
}

/* (d) pseudo-random values of every magnitude, and squares and their neighbours */
static void test_isqrt_random(void **state)
{
    uint64_t seed = 0x2545F4914F6CDD1Dull, n = 0;
    uint32_t i;
    (void)state;
    for (i = 0; i < 1000000u; i++) {
        uint64_t v = tt_next(&seed);
        uint64_t x = v >> (tt_next(&seed) & 63); /* every bit length */
        uint64_t r = (uint32_t)tt_next(&seed), sq = r * r;
        tt_check_isqrt(x);
        tt_check_isqrt(sq);
        assert_int_equal(duel_isqrt64(sq), r);
        if (sq > 0) {
            tt_check_isqrt(sq - 1);
            assert_int_equal(duel_isqrt64(sq - 1), r - 1);
        }
        tt_check_isqrt(sq + 1);
        n += 4;
    }
    printf("duel_isqrt64: %llu values checked\n", (unsigned long long)n);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table_entries),
        cmocka_unit_test(test_error_bound),
        cmocka_unit_test(test_exact_symmetries),
        cmocka_unit_test(test_axes_exact),
        cmocka_unit_test(test_isqrt_edges),
        cmocka_unit_test(test_isqrt_random),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
