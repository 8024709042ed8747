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

/* floor(sqrt(x)) in 32-bit arithmetic (duel_trig.c) */
uint32_t duel_isqrt32(uint32_t x);

#endif /* DUEL_INTERNAL_H */
