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

/* World v1's rules (duel_rules.c; duel_rules_v1() outside the library) */
extern const duel_rules duel_v1_rules;

/* The world's rules: NULL (a world made by hand) is v1. */
static inline const duel_rules *duel_rules_of(const duel_world *w)
{
    return w->rules != NULL ? w->rules : &duel_v1_rules;
}

/* duel_world_init_rules without the check: rules already checked. */
int duel_world_start(duel_world *w, const duel_rules *r, int food_config);

/* duel_world_step, the food tested only when food_near: 0 promises that no
 * item can be within the eating distance after this move (duel_play knows
 * it from the food readings, duel_food_near). w->rules must be set (every
 * world duel_world_start made). */
int duel_world_step_food(duel_world *w, const nrt_q15 out_west[DUEL_N_OUTPUTS],
                         const nrt_q15 out_east[DUEL_N_OUTPUTS], duel_event *ev, int food_near);

/* The food reading below which no item can be within the eating distance
 * after the robot's next move. A food reading v < T is 32768 - (n + 1) / 2
 * with n = floor(d / food_range) (d in Q16.16) at least 65537 - 2T, or 0 for
 * an item out of range (n >= 65536); either way d >= (65537 - 2T) range.
 * A move is at most 1.33 units (87160 in Q16.16, and one more for the
 * rounding of each axis; the clamp to the board only shortens it), so T is
 * the largest with (65537 - 2T) range >= eat_dist + 87162: every item then
 * stays at or beyond the eating distance. 0 (every step tests the food)
 * when the range is too short for the readings to tell. World v1: 32138.
 * An item at the robot's very centre gives no reading, but cannot be there:
 * it would have been within the eating distance after the previous move and
 * eaten then (or that move's readings were not all below T), and no item
 * is within it of a start position (duel_rules_check). */
static inline nrt_q15 duel_food_near_limit(const duel_rules *r)
{
    /* 32-bit: eat_dist is at most 150 units (duel_rules_check) */
    uint32_t need = (uint32_t)r->eat_dist + 87162u, n = (need + r->food_range - 1u) / r->food_range;
    return (nrt_q15)(n < 65536u ? (65537u - n) / 2u : 0u);
}

/* Whether a robot whose food readings (inputs 1-5) these are may be within
 * the eating distance of an item after its next move (limit:
 * duel_food_near_limit). */
static inline int duel_food_near(const nrt_q15 in[DUEL_N_INPUTS], nrt_q15 limit)
{
    return in[1] >= limit || in[2] >= limit || in[3] >= limit || in[4] >= limit || in[5] >= limit;
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
    /* the readings' division by the range, floor(r / range) = r * mul >>
     * shift, per lane: [0] four food lanes, [1] food, food, robot, robot */
    int64_t mul[2][4], shift[2][4];
#endif
} duel_lanes;

/* A game's lanes, at its start, for its rules: the processor's features
 * read once per game, not per step, and the readings' divisors (the
 * firmware has no use for them) */
void duel_lanes_init(duel_lanes *lanes, const duel_rules *r);

/* Both robots' inputs, exactly as duel_sense gives them, with AVX2: 0, or
 * -1 when this build or processor has no AVX2 path (then duel_sense twice).
 * lanes starts from duel_lanes_init, at the start of a game. */
int duel_sense_both(const duel_world *w, duel_lanes *lanes, nrt_q15 west[DUEL_N_INPUTS],
                    nrt_q15 east[DUEL_N_INPUTS]);

#endif /* DUEL_INTERNAL_H */
