/* nrt_internal.h - what the runtime's files share: the sigmoid table and its inline evaluation, the products of a node's sum. */
#ifndef NRT_INTERNAL_H
#define NRT_INTERNAL_H

#include "nrt.h"

/* NRT_SIG_TABLE[i] = round(32768 / (1 + exp(-4.9 * i / 64))), i = 0..192:
 * x from 0 to 3 in steps of 1/64 (tests/runtime/test_sigmoid.c recomputes
 * every entry). Only x >= 0 is stored: sigmoid(-x) = 1 - sigmoid(x). */
extern const uint16_t nrt_sig_table[193];

#define NRT_SIG_SHIFT 21 /* sums are Q27; 2^27 / 64 = 2^21 per table step */
#define NRT_SIG_LIMIT ((int64_t)192 << NRT_SIG_SHIFT)

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

/* Connections k and k + 1 of a node: their products w * a as one 64-bit
 * term. On a 64-bit processor each product is widened (a 64-bit multiply
 * costs what a 32-bit one does); elsewhere the pair is summed in 32 bits
 * first, which cannot overflow: |w| <= 32767 (the loader refuses -32768)
 * and |a| <= 32768 keep each product at most 2^30 - 2^15, so one widening
 * (on Armv6-M a sign extension and a 64-bit add) serves two connections.
 * Either way the sum of the node is the same exact integer. */
#if UINTPTR_MAX > 0xFFFFFFFFu
#define NRT_PAIR(w, src, a, k) \
    ((int64_t)(w)[k] * (a)[(src)[k]] + (int64_t)(w)[(k) + 1u] * (a)[(src)[(k) + 1u]])
#else
#define NRT_PAIR(w, src, a, k) \
    ((int64_t)((int32_t)(w)[k] * (a)[(src)[k]] + (int32_t)(w)[(k) + 1u] * (a)[(src)[(k) + 1u]]))
#endif

/* sum plus the products of the last 0-3 connections k..e-1 of a node */
static inline int64_t nrt_tail(int64_t sum, const nrt_w12 *w, const uint16_t *src, const nrt_q15 *prev, size_t k,
                               size_t e)
{
    switch (e - k) {
    case 3:
        sum += NRT_PAIR(w, src, prev, k);
        k += 2u;
        /* fall through */
    case 1:
        sum += (int32_t)w[k] * prev[src[k]];
        break;
    case 2:
        sum += NRT_PAIR(w, src, prev, k);
        break;
    default:
        break;
    }
    return sum;
}

/* ---- nrt_step_avx2.c: the node sums with AVX2 gathers on x86-64 ---- */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__) && !defined(NRT_NO_AVX2)
#define NRT_HAVE_AVX2 1
/* nrt_step's node activations (next from prev) eight connections a round:
 * 0, or -1 when the processor has no AVX2 or the network's arrays are not
 * laid out as nrt_load lays them (then nrt_step computes them itself). */
int nrt_nodes_avx2(const nrt_net *net, const nrt_q15 *prev, nrt_q15 *next);
#else
#define NRT_HAVE_AVX2 0
#endif

#endif /* NRT_INTERNAL_H */
