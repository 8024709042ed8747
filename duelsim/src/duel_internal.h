/* duel_internal.h - helpers the duelsim modules share: symmetric rounding and squared distances. */
#ifndef DUEL_INTERNAL_H
#define DUEL_INTERNAL_H

#include "duel.h"

/* The rounding below shifts negative values right: that is implementation
 * defined in C99, arithmetic (floor) on every compiler this builds with; a
 * compiler that did otherwise stops the build here. */
typedef char duel_arithmetic_shift_check[(-9 >> 1) == -5 ? 1 : -1];

/* x / 2^shift rounded to nearest, halves away from zero: the same for x and
 * -x, so mirror-image games stay mirror images. Without a branch: for x < 0,
 * -floor((-x + h) / 2h) = floor((x + h - 1) / 2h) (h = 2^(shift-1)), so
 * both signs are one add and one floor shift. */
static inline int64_t duel_round_shift(int64_t x, int shift)
{
    int64_t half = (int64_t)1 << (shift - 1);
    return (x + half - (x < 0)) >> shift;
}

/* squared distance between two Q16.16 points, Q32 */
static inline int64_t duel_dist2(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    int64_t dx = (int64_t)ax - bx, dy = (int64_t)ay - by;
    return dx * dx + dy * dy;
}

/* duel_sin_q[i] = round(2^30 sin(i pi / 2048)), i = 0..1024, and entry 1025
 * = entry 1024 (duel_trig.c) */
extern const int32_t duel_sin_q[1026];

#define DUEL_QUARTER 0x40000000u

/* sin of p in [0, pi/2] (p a binary angle below 2^30, or exactly 2^30), Q30:
 * linear interpolation between table entries on 20 fraction bits.
 * Inline, except at -Os (the firmware): there the compiler keeps it out of
 * line in every module that takes a cos or sin, so it is defined once, in
 * duel_trig.c (DUEL_TRIG_C), which saves 136 bytes on Cortex-M0+ and no
 * instruction. */
#ifdef __OPTIMIZE_SIZE__
int32_t duel_sin_quarter(uint32_t p);
#define DUEL_SIN_LINKAGE
#else
#define DUEL_SIN_LINKAGE static inline
#endif
#if !defined(__OPTIMIZE_SIZE__) || defined(DUEL_TRIG_C)
DUEL_SIN_LINKAGE int32_t duel_sin_quarter(uint32_t p)
{
    uint32_t i = p >> 20, frac = p & 0xFFFFFu;
    int64_t lo, hi;
    lo = duel_sin_q[i];
    hi = duel_sin_q[i + 1];
    /* rounding to nearest; hi >= lo, so the product is non-negative */
    return (int32_t)(lo + (((hi - lo) * (int64_t)frac + (1 << 19)) >> 20));
}
#endif

/* duel_cossin (duel.h), inline: sensing and motion take one each per robot
 * and step. */
static inline void duel_cossin_q30(duel_angle a, int32_t *c, int32_t *s)
{
    /* fold into the first quadrant: every other quadrant is a sign change
     * and/or sin <-> cos swap of the same two values, so the symmetries of
     * the real functions hold exactly */
    uint32_t q = a >> 30, p = a & (DUEL_QUARTER - 1u);
    int32_t sp = duel_sin_quarter(p), cp = duel_sin_quarter(DUEL_QUARTER - p);
    switch (q) {
    case 0: *c = cp; *s = sp; break;
    case 1: *c = -sp; *s = cp; break;
    case 2: *c = -cp; *s = -sp; break;
    default: *c = sp; *s = -cp; break;
    }
}

/* duel_sqrt_est[j] = ceil(sqrt((64 + j) 2^24)) - 2^15, j = 0..192 (duel_trig.c) */
extern const uint16_t duel_sqrt_est[193];

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

/* Index of the lowest set bit of a non-zero mask: the processor's instruction
 * where it has one (the same condition as duel_even_clz), else a de Bruijn
 * multiply; both give the same index. */
#if (defined(__GNUC__) || defined(__clang__)) && \
    (defined(__x86_64__) || defined(__i386__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ))
#define DUEL_HAVE_CTZ 1
#else
#define DUEL_HAVE_CTZ 0
/* duel_debruijn[(m * 0x077CB531) >> 27] = k for m = 2^k (duel_trig.c: one table for every module) */
extern const uint8_t duel_debruijn[32];
#endif
static inline unsigned duel_lowest_bit(uint32_t m)
{
#if DUEL_HAVE_CTZ
    return (unsigned)__builtin_ctz(m);
#else
    return duel_debruijn[((m & (0u - m)) * 0x077CB531u) >> 27];
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
    /* sqrt(y) lies between lo and hi (both less 2^15, which the 2^23 adds
     * back): interpolate by the next byte of y and undo half the shift;
     * lo + 2^15 >= 2^15 and sh <= 30 keep r >= 1 */
    r = ((lo << 8) + (1u << 23) + (hi - lo) * frac) >> (8 + sh / 2);
    r = (r + x / r) >> 1;
    if ((uint64_t)r * r > x)
        r--;
    return r;
}

/* duel_world_step, the food tested only when food_near: 0 promises that no
 * item can be within the eating distance after this move (duel_play knows
 * it from the food readings, duel_food_near). */
int duel_world_step_food(duel_world *w, const nrt_q15 out_west[DUEL_N_OUTPUTS],
                         const nrt_q15 out_east[DUEL_N_OUTPUTS], duel_event *ev, int food_near);

/* Whether a robot whose food readings (inputs 1-5) these are may be within
 * the eating distance of an item after its next move. A reading r < 32113 is
 * round(d / 1700) >= 656 in Q16.16, so d >= 655.5 * 1700 / 65536 > 17.003
 * units; a move is at most 1.33 units (the clamp to the board only shortens
 * it), so every item stays beyond 15.67, above the eating distance of 15. An
 * item at the robot's very centre gives no reading, but cannot be there: it
 * would have been within 15 after the previous move and eaten then (or that
 * move's readings were not all below 32113), and no item is at a start
 * position. */
static inline int duel_food_near(const nrt_q15 in[DUEL_N_INPUTS])
{
    return in[1] >= 32113 || in[2] >= 32113 || in[3] >= 32113 || in[4] >= 32113 || in[5] >= 32113;
}

/* A function kept out of its caller: its locals then take no room in the
 * caller's frame (duel_play's traced step, which the firmware never runs). */
#if defined(__GNUC__) || defined(__clang__)
#define DUEL_NOINLINE __attribute__((noinline))
#else
#define DUEL_NOINLINE
#endif

/* ---- the AVX2 sensing (duel_sense_avx2.c) ---- */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__) && !defined(DUEL_NO_AVX2)
#define DUEL_HAVE_AVX2 1
#else
#define DUEL_HAVE_AVX2 0
#endif

/* The food still on the board in the lanes duel_sense_both reads: item
 * pairs (i, j) as (x_i, x_i, x_j, x_j), the same for y. The food does not
 * move, so duel_play keeps one per game; it remakes itself when the food
 * mask it was made for changes (an item eaten). */
typedef struct duel_lanes {
    uint32_t mask;  /* the food_mask it holds, or ~0: not made yet */
    uint32_t pairs;
    int level;      /* the sensing path (enum duel_simd), read once per game */
#if DUEL_HAVE_AVX2
    int64_t x[(DUEL_MAX_FOOD + 1) / 2][4], y[(DUEL_MAX_FOOD + 1) / 2][4];
#endif
} duel_lanes;

/* A game's lanes, at its start: the processor's features read once per
 * game, not per step (inline: the firmware has no use for it) */
static inline void duel_lanes_init(duel_lanes *lanes)
{
    lanes->mask = ~0u;
    lanes->level = duel_simd_active();
}

/* Both robots' inputs, exactly as duel_sense gives them, with AVX2: 0, or
 * -1 when this build or processor has no AVX2 path (then duel_sense twice).
 * lanes starts from duel_lanes_init, at the start of a game. */
int duel_sense_both(const duel_world *w, duel_lanes *lanes, nrt_q15 west[DUEL_N_INPUTS],
                    nrt_q15 east[DUEL_N_INPUTS]);

#endif /* DUEL_INTERNAL_H */
