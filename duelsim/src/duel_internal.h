/* duel_internal.h - helpers the duelsim modules share: symmetric rounding and squared distances. */
#ifndef DUEL_INTERNAL_H
#define DUEL_INTERNAL_H

#include "duel.h"

/* x / 2^shift rounded to nearest, halves away from zero: the same for x and
 * -x, so mirror-image games stay mirror images */
static inline int64_t duel_round_shift(int64_t x, int shift)
{
    int64_t half = (int64_t)1 << (shift - 1);
    return x >= 0 ? (x + half) >> shift : -((-x + half) >> shift);
}

/* squared distance between two Q16.16 points, Q32 */
static inline int64_t duel_dist2(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    int64_t dx = (int64_t)ax - bx, dy = (int64_t)ay - by;
    return dx * dx + dy * dy;
}

/* duel_sqrt_est[j] = ceil(sqrt((64 + j) 2^24)), j = 0..192 (duel_trig.c) */
extern const uint32_t duel_sqrt_est[193];

/* floor(sqrt(x)) in 32-bit arithmetic: inline, because every rangefinder
 * reading takes one. */
/* Leading zero count of a non-zero 32-bit value, rounded down to even: the
 * compiler's builtin where the processor has the instruction (elsewhere the
 * builtin would call a libgcc helper), a binary search otherwise;
 * both give the same number, so the square root below is the same
 * everywhere. */
static inline unsigned duel_even_clz(uint32_t y)
{
#if (defined(__GNUC__) || defined(__clang__)) && \
    (defined(__x86_64__) || defined(__i386__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ))
    return (unsigned)__builtin_clz(y) & ~1u;
#else
    unsigned sh = 0;
    if (y < (1u << 16)) {
        y <<= 16;
        sh += 16;
    }
    if (y < (1u << 24)) {
        y <<= 8;
        sh += 8;
    }
    if (y < (1u << 28)) {
        y <<= 4;
        sh += 4;
    }
    if (y < (1u << 30))
        sh += 2;
    return sh;
#endif
}

static inline uint32_t duel_isqrt32(uint32_t x)
{
    /* Normalise to [2^30, 2^32) by an even shift, interpolate the table
     * (sqrt is smooth: the estimate is within 0.01 % of the root), then one
     * step of Newton's iteration: floor((r + floor(x / r)) / 2) is never
     * below floor(sqrt(x)) for any r > 0 (the arithmetic-geometric mean
     * inequality), and from so close it lands on the floor or one above,
     * which the final check corrects. */
    uint32_t y, i, frac, lo, hi, r;
    unsigned sh;
    if (x < 2)
        return x;
    sh = duel_even_clz(x);
    y = x << sh;
    i = (y >> 24) - 64;
    frac = (y >> 16) & 0xFFu;
    lo = duel_sqrt_est[i];
    hi = duel_sqrt_est[i + 1];
    /* sqrt(y) lies between lo and hi: interpolate by the next byte of y and
     * undo half the shift; lo >= 2^15 and sh <= 30 keep r >= 1 */
    r = ((lo << 8) + (hi - lo) * frac) >> (8 + sh / 2);
    r = (r + x / r) >> 1;
    if ((uint64_t)r * r > x)
        r--;
    return r;
}

#endif /* DUEL_INTERNAL_H */
