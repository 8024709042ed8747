/* nrt_internal.h - the sigmoid table and its inline evaluation, shared by nrt_sigmoid.c and nrt_step.c. */
#ifndef NRT_INTERNAL_H
#define NRT_INTERNAL_H

#include "nrt.h"

/* NRT_SIG_TABLE[i] = round(32768 / (1 + exp(-4.9 * i / 64))), i = 0..145:
 * x from 0 to 145/64 in steps of 1/64 (tests/runtime/test_sigmoid.c
 * recomputes every entry), where the entries reach 32768. Only x >= 0 is
 * stored: sigmoid(-x) = 1 - sigmoid(x). */
#define NRT_SIG_ENTRIES 146
extern const uint16_t nrt_sig_table[NRT_SIG_ENTRIES];

#define NRT_SIG_SHIFT 21 /* sums are Q27; 2^27 / 64 = 2^21 per table step */
/* from here on the value is 32768 (table entry 145 and every later one) */
#define NRT_SIG_LIMIT ((int64_t)(NRT_SIG_ENTRIES - 1) << NRT_SIG_SHIFT)

/* Q1.15 sigmoid of a Q27 sum: inline, because nrt_step calls it once per node. */
static inline nrt_q15 nrt_sig_eval(int64_t sum)
{
    int64_t x = sum >= 0 ? sum : (sum < -NRT_SIG_LIMIT ? NRT_SIG_LIMIT : -sum);
    int32_t y;
    if (x >= NRT_SIG_LIMIT) {
        y = 32768;
    } else {
        uint32_t i = (uint32_t)(x >> NRT_SIG_SHIFT);
        /* 16 bits of the position between entries i and i + 1 */
        int32_t frac = (int32_t)((x >> (NRT_SIG_SHIFT - 16)) & 0xFFFF);
        int32_t lo = nrt_sig_table[i], hi = nrt_sig_table[i + 1];
        y = lo + (((hi - lo) * frac) >> 16);
    }
    /* y is sigmoid(|x|) in [16384, 32768]; the negative half mirrors it */
    if (sum < 0)
        return (nrt_q15)(32768 - y);
    return (nrt_q15)(y > 32767 ? 32767 : y);
}

#endif /* NRT_INTERNAL_H */
