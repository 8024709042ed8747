/* nrt_sigmoid.c - the fixed-point sigmoid 1/(1+exp(-4.9x)): a half table with linear interpolation. */
#include "nrt.h"

/* NRT_SIG_TABLE[i] = round(32768 / (1 + exp(-4.9 * i / 64))), i = 0..192,
 * i.e. x from 0 to 3 in steps of 1/64 (tests/runtime/test_sigmoid.c
 * recomputes every entry). Only x >= 0 is stored: sigmoid(-x) = 1 - sigmoid(x).
 * Beyond x = 3 the true value is within 2^-21 of 1, below half a Q1.15 step. */
static const uint16_t nrt_sig_table[193] = {
    16384, 17011, 17636, 18257, 18873, 19482, 20082, 20672, 21250, 21816, 22367, 22902,
    23422, 23925, 24411, 24878, 25328, 25759, 26171, 26566, 26941, 27299, 27639, 27962,
    28267, 28556, 28830, 29087, 29330, 29559, 29774, 29975, 30165, 30343, 30509, 30665,
    30811, 30947, 31074, 31193, 31304, 31407, 31504, 31594, 31677, 31755, 31828, 31895,
    31958, 32016, 32070, 32121, 32168, 32211, 32252, 32289, 32324, 32356, 32386, 32414,
    32440, 32464, 32486, 32507, 32526, 32544, 32560, 32575, 32589, 32602, 32615, 32626,
    32636, 32646, 32655, 32663, 32671, 32678, 32685, 32691, 32696, 32702, 32707, 32711,
    32715, 32719, 32723, 32726, 32729, 32732, 32735, 32737, 32739, 32742, 32743, 32745,
    32747, 32749, 32750, 32751, 32753, 32754, 32755, 32756, 32757, 32757, 32758, 32759,
    32760, 32760, 32761, 32761, 32762, 32762, 32763, 32763, 32763, 32764, 32764, 32764,
    32765, 32765, 32765, 32765, 32766, 32766, 32766, 32766, 32766, 32766, 32766, 32767,
    32767, 32767, 32767, 32767, 32767, 32767, 32767, 32767, 32767, 32767, 32767, 32767,
    32767, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768,
    32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768,
    32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768,
    32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768, 32768,
    32768,
};

#define NRT_SIG_SHIFT 21   /* sum is Q27; 2^27 / 64 = 2^21 per table step */
#define NRT_SIG_LIMIT ((int64_t)192 << NRT_SIG_SHIFT)

/* Q1.15 sigmoid of a non-negative Q27 argument, in [16384, 32768]. */
static int32_t nrt_sig_pos(int64_t x)
{
    uint32_t i;
    int32_t lo, hi, frac;
    if (x >= NRT_SIG_LIMIT)
        return 32768;
    i = (uint32_t)(x >> NRT_SIG_SHIFT);
    /* 16 bits of the position between entries i and i+1 */
    frac = (int32_t)((x >> (NRT_SIG_SHIFT - 16)) & 0xFFFF);
    lo = nrt_sig_table[i];
    hi = nrt_sig_table[i + 1];
    return lo + (((hi - lo) * frac) >> 16);
}

nrt_q15 nrt_sigmoid(int64_t sum)
{
    int32_t y;
    if (sum >= 0) {
        y = nrt_sig_pos(sum);
        if (y > 32767)
            y = 32767;
    } else {
        /* clamp before negating: -INT64_MIN would overflow (a valid network's
         * sum stays below 2^47 in magnitude, but callers may pass anything) */
        if (sum < -NRT_SIG_LIMIT)
            sum = -NRT_SIG_LIMIT;
        y = 32768 - nrt_sig_pos(-sum);
    }
    return (nrt_q15)y;
}
