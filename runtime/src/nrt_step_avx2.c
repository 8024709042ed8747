/* nrt_step_avx2.c - the node sums of nrt_step with AVX2 gathers on x86-64 hosts: the same exact sums, eight connections per instruction. */
#include "nrt_internal.h"

/*
 * One more implementation of nrt_step's node loop (nrt_step.c), used when
 * the processor has AVX2. A node's sum is an exact integer (Q27 products
 * below 2^30, summed in 64 bits), so summing eight products at a time in
 * 32-bit lanes (each product fits) and widening them to 64 bits before
 * adding gives the same sum as the scalar loop. tests/duelsim/test_golden.c
 * checks both against the same recorded hashes.
 *
 * The activations are gathered 32 bits at a time from two bytes before each
 * source (AVX2 has no 16-bit gather): the upper half is the activation. The
 * two bytes before act[0] are the last entry of end[], before act[1] the last
 * activation of act[0], as nrt_load lays the buffer out; a network laid out
 * otherwise takes the scalar path.
 */

#if NRT_HAVE_AVX2
#include <immintrin.h>

#define NRT_AVX2 __attribute__((target("avx2")))

NRT_AVX2 static void nrt_nodes_gather(const nrt_net *net, const nrt_q15 *prev, nrt_q15 *next)
{
    const nrt_w12 *w = net->weight;
    const uint16_t *src = net->src, *end = net->end;
    const int *base = (const int *)(const void *)prev;
    const __m256i two = _mm256_set1_epi32(2);
    uint32_t j, non_in = (uint32_t)net->n_nodes - net->n_inputs;
    size_t k = 0;

    for (j = 0; j < non_in; j++) {
        size_t e = end[j];
        __m256i acc = _mm256_setzero_si256();
        __m128i half;
        int64_t sum;
        for (; k + 8u <= e; k += 8u) {
            __m256i at = _mm256_cvtepu16_epi32(_mm_loadu_si128((const __m128i *)(const void *)(src + k)));
            /* byte offset 2 src - 2: the activation is the upper half */
            __m256i a = _mm256_srai_epi32(
                _mm256_i32gather_epi32(base, _mm256_sub_epi32(_mm256_add_epi32(at, at), two), 1), 16);
            __m256i p = _mm256_mullo_epi32(
                a, _mm256_cvtepi16_epi32(_mm_loadu_si128((const __m128i *)(const void *)(w + k))));
            acc = _mm256_add_epi64(acc, _mm256_cvtepi32_epi64(_mm256_castsi256_si128(p)));
            acc = _mm256_add_epi64(acc, _mm256_cvtepi32_epi64(_mm256_extracti128_si256(p, 1)));
        }
        if (k + 4u <= e) {
            __m128i at = _mm_cvtepu16_epi32(_mm_loadl_epi64((const __m128i *)(const void *)(src + k)));
            __m128i a = _mm_srai_epi32(
                _mm_i32gather_epi32(base, _mm_sub_epi32(_mm_add_epi32(at, at), _mm256_castsi256_si128(two)), 1), 16);
            __m128i p = _mm_mullo_epi32(a, _mm_cvtepi16_epi32(_mm_loadl_epi64((const __m128i *)(const void *)(w + k))));
            acc = _mm256_add_epi64(acc, _mm256_cvtepi32_epi64(p));
            k += 4u;
        }
        half = _mm_add_epi64(_mm256_castsi256_si128(acc), _mm256_extracti128_si256(acc, 1));
        sum = _mm_cvtsi128_si64(half) + _mm_extract_epi64(half, 1);
        sum = nrt_tail(sum, w, src, prev, k, e);
        k = e;
        next[j] = nrt_sig_eval(sum);
    }
}

int nrt_nodes_avx2(const nrt_net *net, const nrt_q15 *prev, nrt_q15 *next)
{
    uint32_t non_in = (uint32_t)net->n_nodes - net->n_inputs;
    if (!__builtin_cpu_supports("avx2"))
        return -1;
    /* the layout the two bytes before each activation array rely on */
    if ((const void *)net->act[0] != (const void *)(net->end + non_in) || net->act[1] != net->act[0] + net->n_nodes)
        return -1;
    nrt_nodes_gather(net, prev, next);
    return 0;
}

#else
/* no AVX2 path in this build: an empty unit is not ISO C */
typedef int nrt_step_avx2_unused;
#endif
