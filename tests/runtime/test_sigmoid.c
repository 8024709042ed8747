/* test_sigmoid.c - the runtime's fixed-point sigmoid: table entries, symmetry, monotonicity, error bound, saturation. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "nrt.h"

#define SIG_STEP_SHIFT 21                  /* one table step (1/64) of a Q27 sum */
#define SIG_ONE_Q27 ((int64_t)1 << 27)    /* x = 1.0 */
#define SIG_TABLE_LAST 192                 /* the table covers x = 0 .. 192/64 = 3 */

/* xorshift64 (Marsaglia): the test's own reproducible pseudo-random source. */
static uint64_t sig_xorshift(uint64_t *s)
{
    uint64_t x = *s;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    *s = x;
    return x;
}

static double sig_exact(int64_t sum)
{
    double x = (double)sum / (double)SIG_ONE_Q27;
    return 1.0 / (1.0 + exp(-4.9 * x));
}

/* At every table point the result is the rounded exact value (clamped to Q1.15's 32767). */
static void test_table_points_exact(void **state)
{
    int i;
    (void)state;
    for (i = 0; i < SIG_TABLE_LAST; i++) {
        long want = lround(32768.0 / (1.0 + exp(-4.9 * (double)i / 64.0)));
        if (want > 32767)
            want = 32767;
        assert_int_equal(nrt_sigmoid((int64_t)i << SIG_STEP_SHIFT), want);
    }
}

/* sigmoid(-x) = 1 - sigmoid(x) exactly, wherever the positive side is not clamped. */
static void test_symmetry(void **state)
{
    int64_t x;
    (void)state;
    for (x = 1; x < ((int64_t)SIG_TABLE_LAST + 8) << SIG_STEP_SHIFT; x += 997) {
        int32_t pos = nrt_sigmoid(x), neg = nrt_sigmoid(-x);
        if (pos < 32767)
            assert_int_equal(neg, 32768 - pos);
        else
            assert_true(neg == 0 || neg == 1); /* 32768 clamped to 32767 */
    }
    assert_int_equal(nrt_sigmoid(0), 16384);
}

/* Non-decreasing over a dense sweep of [-4, 4], and exhaustively around every table point. */
static void test_monotonic(void **state)
{
    int64_t x, lo = -4 * SIG_ONE_Q27, hi = 4 * SIG_ONE_Q27;
    int32_t prev = nrt_sigmoid(lo);
    int i;
    (void)state;
    for (x = lo; x <= hi; x += 61) {
        int32_t y = nrt_sigmoid(x);
        assert_true(y >= prev);
        prev = y;
    }
    for (i = -SIG_TABLE_LAST - 1; i <= SIG_TABLE_LAST + 1; i++) {
        int64_t c = (int64_t)i * ((int64_t)1 << SIG_STEP_SHIFT); /* i may be negative: no shift */
        prev = nrt_sigmoid(c - 4096);
        for (x = c - 4096; x <= c + 4096; x++) {
            int32_t y = nrt_sigmoid(x);
            assert_true(y >= prev);
            prev = y;
        }
    }
}

/* Max absolute error against double precision below 1.2e-4 over 2^21+1 evenly
 * spaced and 2^20 pseudo-random x in [-4, 4]; the measured figures are printed. */
static void test_error_bound(void **state)
{
    const int64_t lo = -4 * SIG_ONE_Q27, span = 8 * SIG_ONE_Q27;
    const int64_t step = span >> 21;
    uint64_t rng = 0x9E3779B97F4A7C15u;
    double max_err = 0.0, sum_err = 0.0, worst_x = 0.0;
    long n = 0, k;
    (void)state;
    for (k = 0; k <= (1L << 21) + (1L << 20); k++) {
        int64_t sum;
        double err;
        if (k <= 1L << 21)
            sum = lo + (int64_t)k * step; /* evenly spaced, exact in double */
        else
            sum = lo + (int64_t)(sig_xorshift(&rng) % (uint64_t)(span + 1));
        err = fabs((double)nrt_sigmoid(sum) / 32768.0 - sig_exact(sum));
        sum_err += err;
        n++;
        if (err > max_err) {
            max_err = err;
            worst_x = (double)sum / (double)SIG_ONE_Q27;
        }
    }
    printf("nrt_sigmoid vs double 1/(1+exp(-4.9x)), %ld points in [-4, 4]: max error %.3e (at x = %.6f), "
           "mean error %.3e\n",
           n, max_err, worst_x, sum_err / (double)n);
    assert_true(n >= 1000000);
    assert_true(max_err < 1.2e-4);
}

/* Sums far beyond the table saturate at 32767 and 0. */
static void test_saturation(void **state)
{
    static const int64_t big[] = {(int64_t)SIG_TABLE_LAST << SIG_STEP_SHIFT,
                                  ((int64_t)SIG_TABLE_LAST << SIG_STEP_SHIFT) + 1,
                                  4 * SIG_ONE_Q27,
                                  (int64_t)1 << 40,
                                  /* 65535 connections of weight -8 from activation -1: the largest sum a blob allows */
                                  (int64_t)65535 * 32768 * 32768,
                                  INT64_MAX / 2};
    size_t i;
    (void)state;
    for (i = 0; i < sizeof big / sizeof big[0]; i++) {
        assert_int_equal(nrt_sigmoid(big[i]), 32767);
        assert_int_equal(nrt_sigmoid(-big[i]), 0);
    }
    assert_int_equal(nrt_sigmoid(INT64_MAX), 32767);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table_points_exact),
        cmocka_unit_test(test_symmetry),
        cmocka_unit_test(test_monotonic),
        cmocka_unit_test(test_error_bound),
        cmocka_unit_test(test_saturation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
