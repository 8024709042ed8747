/* test_stats.c - the experiment's statistics: exact Mann-Whitney U and Wilcoxon signed-rank p-values against cases counted by hand (every split, every sign pattern), ties, and the normal approximation. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "duel_stats.h"

static void test_mean_sd(void **state)
{
    const double v[] = {2, 4, 4, 4, 5, 5, 7, 9};
    (void)state;
    assert_float_equal(duel_stats_mean(v, 8), 5.0, 1e-12);
    assert_float_equal(duel_stats_sd(v, 8), 2.1380899352993950, 1e-12); /* sqrt(32 / 7) */
    assert_float_equal(duel_stats_sd(v, 1), 0.0, 0.0);
}

/* x = {1,2,3}, y = {4,5,6}: of the C(6,3) = 20 splits, only x itself and y give a rank sum as far from the
 * mean (6 and 15 against 10.5): p = 2/20. */
static void test_mwu_separated(void **state)
{
    const double x[] = {1, 2, 3}, y[] = {4, 5, 6};
    duel_test t;
    (void)state;
    assert_int_equal(duel_stats_mwu(x, 3, y, 3, &t), 0);
    assert_true(t.exact);
    assert_float_equal(t.statistic, 0.0, 0.0);
    assert_float_equal(t.p, 0.1, 1e-12);
    assert_int_equal(duel_stats_mwu(y, 3, x, 3, &t), 0);
    assert_float_equal(t.statistic, 9.0, 0.0);
    assert_float_equal(t.p, 0.1, 1e-12);
}

/* 5 against 3, separated: 2 of the C(8,5) = 56 splits: p = 1/28, the smallest p these sizes allow. */
static void test_mwu_five_three(void **state)
{
    const double x[] = {1, 2, 3, 4, 5}, y[] = {6, 7, 8};
    duel_test t;
    (void)state;
    assert_int_equal(duel_stats_mwu(x, 5, y, 3, &t), 0);
    assert_float_equal(t.p, 1.0 / 28.0, 1e-12);
}

/* Ties: x = {0.5, 0.6, 0.6, 0.9}, y = {0.6, 0.7, 0.95, 0.95, 1.0}; mid-ranks 1, 3, 3, 5 | 3, 6, 7.5, 7.5, 9;
 * U = 3; 14 of the C(9,4) = 126 splits give a rank sum at least as far from 20 as 12: p = 1/9. */
static void test_mwu_ties(void **state)
{
    const double x[] = {0.5, 0.6, 0.6, 0.9}, y[] = {0.6, 0.7, 0.95, 0.95, 1.0};
    duel_test t;
    (void)state;
    assert_int_equal(duel_stats_mwu(x, 4, y, 5, &t), 0);
    assert_true(t.exact);
    assert_float_equal(t.statistic, 3.0, 0.0);
    assert_float_equal(t.p, 1.0 / 9.0, 1e-12);
}

/* Everything tied: no evidence at all. */
static void test_mwu_all_equal(void **state)
{
    const double x[] = {0.5, 0.5}, y[] = {0.5, 0.5, 0.5};
    duel_test t;
    (void)state;
    assert_int_equal(duel_stats_mwu(x, 2, y, 3, &t), 0);
    assert_float_equal(t.p, 1.0, 1e-12);
    assert_int_equal(duel_stats_mwu(x, 0, y, 3, &t), -1);
}

/* Beyond DUEL_STATS_EXACT_MAX: the normal approximation with continuity and tie corrections (the values scipy
 * 1.10's mannwhitneyu(method='asymptotic') gives for the same samples). */
static void test_mwu_normal(void **state)
{
    double x[40], y[35], a[72], b[63];
    static const double pa[8] = {1, 2, 2, 3, 3, 3, 4, 5}, pb[7] = {2, 3, 4, 4, 5, 5, 6};
    duel_test t;
    int k;
    (void)state;
    for (k = 0; k < 40; k++)
        x[k] = k;
    for (k = 0; k < 35; k++)
        y[k] = k + 7.5;
    assert_int_equal(duel_stats_mwu(x, 40, y, 35, &t), 0);
    assert_false(t.exact);
    assert_float_equal(t.p, 0.06855970814103057, 1e-9);
    for (k = 0; k < 72; k++)
        a[k] = pa[k % 8];
    for (k = 0; k < 63; k++)
        b[k] = pb[k % 7];
    assert_int_equal(duel_stats_mwu(a, 72, b, 63, &t), 0);
    assert_float_equal(t.p, 1.1945398713949186e-07, 1e-9);
}

/* Signed ranks: all six differences positive: 2 of the 2^6 sign patterns are as extreme: p = 1/32. */
static void test_wilcoxon(void **state)
{
    const double d1[] = {1, 2, 3, 4, 5, 6};
    /* {-1, 2, -3, 4, 5, 6, 7, 0, 2}: the zero dropped; |d| mid-ranks 1, 2.5, 4, 5, 6, 7, 8, 2.5; W+ = 31 of 36;
     * 20 of the 256 patterns are at least 13 from 18: p = 5/64 */
    const double d2[] = {-1, 2, -3, 4, 5, 6, 7, 0, 2};
    const double d0[] = {0, 0};
    duel_test t;
    (void)state;
    assert_int_equal(duel_stats_wilcoxon(d1, 6, &t), 0);
    assert_true(t.exact);
    assert_float_equal(t.statistic, 21.0, 0.0);
    assert_float_equal(t.p, 1.0 / 32.0, 1e-12);
    assert_int_equal(duel_stats_wilcoxon(d2, 9, &t), 0);
    assert_int_equal((int)t.n, 8);
    assert_float_equal(t.statistic, 31.0, 0.0);
    assert_float_equal(t.p, 5.0 / 64.0, 1e-12);
    assert_int_equal(duel_stats_wilcoxon(d0, 2, &t), 0);
    assert_float_equal(t.p, 1.0, 0.0);
}

/* 70 differences with ties: the normal approximation (scipy 1.10's wilcoxon(mode='approx', correction=True)). */
static void test_wilcoxon_normal(void **state)
{
    double d[70];
    duel_test t;
    int k;
    (void)state;
    for (k = 0; k < 70; k++)
        d[k] = (double)((k * 37) % 23) - 9.5;
    assert_int_equal(duel_stats_wilcoxon(d, 70, &t), 0);
    assert_false(t.exact);
    assert_float_equal(t.p, 0.11717458504893317, 1e-9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mean_sd),       cmocka_unit_test(test_mwu_separated), cmocka_unit_test(test_mwu_five_three),
        cmocka_unit_test(test_mwu_ties),      cmocka_unit_test(test_mwu_all_equal), cmocka_unit_test(test_mwu_normal),
        cmocka_unit_test(test_wilcoxon),      cmocka_unit_test(test_wilcoxon_normal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
