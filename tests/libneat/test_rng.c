/* test_rng.c - libneat's PRNG (xoshiro256** seeded by splitmix64) and neat_seed_derive. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "neat.h"

static void test_same_seed_same_sequence(void **state)
{
    neat_rng a, b;
    int i;
    (void)state;
    neat_rng_seed(&a, 12345);
    neat_rng_seed(&b, 12345);
    for (i = 0; i < 1000; i++)
        assert_true(neat_rng_next(&a) == neat_rng_next(&b));
}

static void test_different_seeds_differ(void **state)
{
    static const uint64_t seeds[] = {0, 1, 2, 42, 43, 0xFFFFFFFFFFFFFFFFull};
    const size_t n = sizeof seeds / sizeof seeds[0];
    uint64_t first[6][4];
    size_t i, j;
    int k, same;
    (void)state;
    for (i = 0; i < n; i++) {
        neat_rng r;
        neat_rng_seed(&r, seeds[i]);
        for (k = 0; k < 4; k++)
            first[i][k] = neat_rng_next(&r);
    }
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++) {
            same = 0;
            for (k = 0; k < 4; k++)
                same += first[i][k] == first[j][k];
            assert_int_equal(same, 0);
        }
}

static void test_seed_zero_is_not_stuck(void **state)
{
    /* xoshiro's all-zero state would output zeros forever: splitmix seeding avoids it */
    neat_rng r;
    int i, zeros = 0;
    (void)state;
    neat_rng_seed(&r, 0);
    for (i = 0; i < 64; i++)
        zeros += neat_rng_next(&r) == 0;
    assert_int_equal(zeros, 0);
}

static void test_golden_values_seed_42(void **state)
{
    /* pinned from the implementation and checked against the reference
     * xoshiro256** / splitmix64 algorithms: any change to the PRNG (and so
     * to every recorded run) breaks this */
    neat_rng r;
    (void)state;
    neat_rng_seed(&r, 42);
    assert_true(neat_rng_next(&r) == 0x15780B2E0C2EC716ull);
    assert_true(neat_rng_next(&r) == 0x6104D9866D113A7Eull);
    assert_true(neat_rng_next(&r) == 0xAE17533239E499A1ull);
}

static void test_uniform_in_unit_interval(void **state)
{
    neat_rng r;
    double u, min = 1.0, max = 0.0, sum = 0.0;
    int i, n = 100000;
    (void)state;
    neat_rng_seed(&r, 7);
    for (i = 0; i < n; i++) {
        u = neat_rng_uniform(&r);
        assert_true(u >= 0.0);
        assert_true(u < 1.0);
        if (u < min)
            min = u;
        if (u > max)
            max = u;
        sum += u;
    }
    /* it spans the interval and is centred */
    assert_true(min < 0.001);
    assert_true(max > 0.999);
    assert_true(sum / n > 0.49 && sum / n < 0.51);
}

static void test_uniform_is_top_53_bits(void **state)
{
    /* uniform = (next >> 11) * 2^-53: the largest value is 1 - 2^-53 < 1 */
    neat_rng a, b;
    int i;
    (void)state;
    neat_rng_seed(&a, 11);
    neat_rng_seed(&b, 11);
    for (i = 0; i < 1000; i++)
        assert_true(neat_rng_uniform(&a) == (double)(neat_rng_next(&b) >> 11) / 9007199254740992.0);
    assert_true((double)(UINT64_MAX >> 11) / 9007199254740992.0 < 1.0);
}

static void test_below_in_range(void **state)
{
    static const uint32_t ns[] = {1, 2, 3, 5, 7, 10, 255, 256, 1000, 65537, 0x80000001u, 0xFFFFFFFFu};
    neat_rng r;
    size_t k;
    int i;
    (void)state;
    neat_rng_seed(&r, 99);
    for (k = 0; k < sizeof ns / sizeof ns[0]; k++)
        for (i = 0; i < 10000; i++)
            assert_true(neat_rng_below(&r, ns[k]) < ns[k]);
}

static void test_below_one_is_zero(void **state)
{
    neat_rng r;
    int i;
    (void)state;
    neat_rng_seed(&r, 3);
    for (i = 0; i < 100; i++)
        assert_int_equal(neat_rng_below(&r, 1), 0);
}

/* chi-square statistic of draws of neat_rng_below(n) */
static double chi_square_below(uint64_t seed, uint32_t n, int draws)
{
    uint32_t counts[64] = {0}, k;
    neat_rng r;
    double expect = (double)draws / n, chi = 0.0;
    int i;
    neat_rng_seed(&r, seed);
    for (i = 0; i < draws; i++)
        counts[neat_rng_below(&r, n)]++;
    for (k = 0; k < n; k++)
        chi += (counts[k] - expect) * (counts[k] - expect) / expect;
    return chi;
}

/* multiplicative inverse of an odd number modulo 2^64 (Newton) */
static uint64_t inverse_odd(uint64_t a)
{
    uint64_t x = a;
    int i;
    for (i = 0; i < 6; i++)
        x *= 2 - a * x;
    return x;
}

static void test_below_rejects_top_partial_block(void **state)
{
    /* xoshiro256**'s next output depends on s[1] only (r = rotl(5 s1, 7) * 9),
     * so a state whose next output is the first value of the partial top
     * block can be built: neat_rng_below must skip it and use the draw after */
    const uint32_t n = 0x80000001u;
    const uint64_t limit = UINT64_MAX - (UINT64_MAX % n);
    uint64_t t, r1, r2;
    neat_rng r, copy;
    (void)state;
    assert_true(limit % n == 0 && limit < UINT64_MAX);
    t = limit * inverse_odd(9);
    t = (t >> 7) | (t << 57);
    r.s[0] = 0x0123456789ABCDEFull;
    r.s[1] = t * inverse_odd(5);
    r.s[2] = 0x0F1E2D3C4B5A6978ull;
    r.s[3] = 0x1111111111111111ull;
    copy = r;
    r1 = neat_rng_next(&copy);
    r2 = neat_rng_next(&copy);
    assert_true(r1 == limit);
    assert_true(r2 < limit);
    assert_true(r1 % n != r2 % n);
    assert_int_equal(neat_rng_below(&r, n), (uint32_t)(r2 % n));
    /* it consumed exactly two draws */
    assert_true(r.s[0] == copy.s[0] && r.s[1] == copy.s[1] && r.s[2] == copy.s[2] && r.s[3] == copy.s[3]);
}

static void test_below_roughly_uniform(void **state)
{
    /* chi-square over 10^5 draws; the bounds are far beyond the 99.99%
     * quantiles (dof 2: 18.4, dof 6: 27.9, dof 9: 33.7, dof 36: 73.4) so
     * only a real bias fails */
    (void)state;
    assert_true(chi_square_below(1, 3, 100000) < 25.0);
    assert_true(chi_square_below(2, 7, 100000) < 35.0);
    assert_true(chi_square_below(3, 10, 100000) < 45.0);
    assert_true(chi_square_below(4, 37, 100000) < 90.0);
}

static void test_below_every_value_reached(void **state)
{
    uint32_t seen[10] = {0}, k;
    neat_rng r;
    int i;
    (void)state;
    neat_rng_seed(&r, 5);
    for (i = 0; i < 1000; i++)
        seen[neat_rng_below(&r, 10)]++;
    for (k = 0; k < 10; k++)
        assert_true(seen[k] > 0);
}

static void test_seed_derive_deterministic(void **state)
{
    const uint64_t keys[4] = {17, 3, 0, 1};
    (void)state;
    assert_true(neat_seed_derive(42, keys, 4) == neat_seed_derive(42, keys, 4));
    assert_true(neat_seed_derive(0, NULL, 0) == neat_seed_derive(0, NULL, 0));
}

static void test_seed_derive_sensitive_to_base(void **state)
{
    const uint64_t keys[3] = {1, 2, 3};
    (void)state;
    assert_true(neat_seed_derive(42, keys, 3) != neat_seed_derive(43, keys, 3));
    assert_true(neat_seed_derive(0, keys, 3) != neat_seed_derive(1, keys, 3));
}

static void test_seed_derive_sensitive_to_every_key(void **state)
{
    const uint64_t base[4] = {10, 20, 30, 40};
    uint64_t keys[4], ref = neat_seed_derive(7, base, 4);
    static const uint64_t deltas[] = {1, 2, 0x100, 0x8000000000000000ull};
    size_t i, d;
    (void)state;
    for (i = 0; i < 4; i++)
        for (d = 0; d < sizeof deltas / sizeof deltas[0]; d++) {
            keys[0] = base[0];
            keys[1] = base[1];
            keys[2] = base[2];
            keys[3] = base[3];
            keys[i] ^= deltas[d];
            assert_true(neat_seed_derive(7, keys, 4) != ref);
        }
}

static void test_seed_derive_sensitive_to_key_order(void **state)
{
    const uint64_t ab[2] = {5, 9}, ba[2] = {9, 5};
    const uint64_t abc[3] = {1, 2, 3}, acb[3] = {1, 3, 2}, cba[3] = {3, 2, 1};
    /* equal keys swapped are the same tuple; a zero key moved is not */
    const uint64_t z0[2] = {0, 4}, z1[2] = {4, 0};
    (void)state;
    assert_true(neat_seed_derive(1, ab, 2) != neat_seed_derive(1, ba, 2));
    assert_true(neat_seed_derive(1, abc, 3) != neat_seed_derive(1, acb, 3));
    assert_true(neat_seed_derive(1, abc, 3) != neat_seed_derive(1, cba, 3));
    assert_true(neat_seed_derive(1, z0, 2) != neat_seed_derive(1, z1, 2));
}

static void test_seed_derive_sensitive_to_key_count(void **state)
{
    const uint64_t keys[3] = {0, 0, 0};
    (void)state;
    /* (g) and (g, 0) are different games */
    assert_true(neat_seed_derive(1, keys, 0) != neat_seed_derive(1, keys, 1));
    assert_true(neat_seed_derive(1, keys, 1) != neat_seed_derive(1, keys, 2));
    assert_true(neat_seed_derive(1, keys, 2) != neat_seed_derive(1, keys, 3));
}

static void test_seed_derive_spreads(void **state)
{
    /* neighbouring tuples give unrelated seeds: no collisions over a grid,
     * and each output bit is set about half the time */
    enum { G = 40, H = 40 };
    static uint64_t out[G * H];
    uint64_t keys[2];
    uint32_t ones[64] = {0};
    int i, j, b;
    (void)state;
    for (i = 0; i < G; i++)
        for (j = 0; j < H; j++) {
            keys[0] = (uint64_t)i;
            keys[1] = (uint64_t)j;
            out[i * H + j] = neat_seed_derive(2024, keys, 2);
        }
    for (i = 0; i < G * H; i++) {
        for (j = i + 1; j < G * H; j++)
            assert_true(out[i] != out[j]);
        for (b = 0; b < 64; b++)
            ones[b] += (uint32_t)((out[i] >> b) & 1u);
    }
    for (b = 0; b < 64; b++)
        assert_true(ones[b] > G * H * 4 / 10 && ones[b] < G * H * 6 / 10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_seed_same_sequence),
        cmocka_unit_test(test_different_seeds_differ),
        cmocka_unit_test(test_seed_zero_is_not_stuck),
        cmocka_unit_test(test_golden_values_seed_42),
        cmocka_unit_test(test_uniform_in_unit_interval),
        cmocka_unit_test(test_uniform_is_top_53_bits),
        cmocka_unit_test(test_below_in_range),
        cmocka_unit_test(test_below_one_is_zero),
        cmocka_unit_test(test_below_rejects_top_partial_block),
        cmocka_unit_test(test_below_roughly_uniform),
        cmocka_unit_test(test_below_every_value_reached),
        cmocka_unit_test(test_seed_derive_deterministic),
        cmocka_unit_test(test_seed_derive_sensitive_to_base),
        cmocka_unit_test(test_seed_derive_sensitive_to_every_key),
        cmocka_unit_test(test_seed_derive_sensitive_to_key_order),
        cmocka_unit_test(test_seed_derive_sensitive_to_key_count),
        cmocka_unit_test(test_seed_derive_spreads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
