/* nrt_dense.c - nrt_step as a dense matrix-vector product with AVX2 on x86-64 hosts (nrt_dense.h). */
#include <string.h>

#include "nrt_dense.h"
#include "nrt_internal.h"

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__) && !defined(NRT_NO_AVX2)
#include <immintrin.h>

#define NRT_AVX2 __attribute__((target("avx2")))

int nrt_dense_make(nrt_dense *d, const nrt_net *net)
{
    uint32_t rows, blocks, j, k = 0, cols, tiles = 0, groups;
    /* a propagate network's step is not one matrix-vector product: its
     * callers keep nrt_step, which executes the blob's mode */
    if (d == NULL || net == NULL || net->order != NULL || net->n_nodes > NRT_DENSE_MAX_NODES ||
        net->n_nodes <= net->n_inputs || !__builtin_cpu_supports("avx2"))
        return NRT_E_ARG;
    rows = (uint32_t)net->n_nodes - net->n_inputs;
    blocks = ((uint32_t)net->n_nodes + 15u) / 16u;
    cols = 16u * blocks;
    groups = (rows + 7u) / 8u;
    /* the tiles that hold a connection (end[] runs from connection 0 up) */
    memset(d->tiles, 0, sizeof d->tiles);
    for (j = 0; j < rows; j++)
        for (; k < net->end[j]; k++)
            d->tiles[j / 8u] |= (uint8_t)(1u << (net->src[k] / 16u));
    for (j = 0; j < groups; j++)
        tiles += (uint32_t)__builtin_popcount(d->tiles[j]);
    /* Worth it? The list costs about 10 instructions a connection and 12 a
     * node (bench/duel_instructions.sh); the matrix about 5 per row of a
     * tile it does not skip and 5 per row for the sums and sigmoids. A
     * network of at most NRT_DENSE_FEW rows takes every tile. */
    if (rows <= NRT_DENSE_FEW)
        tiles = blocks;
    if (8u * (5u * tiles + 5u * groups) >= 10u * net->n_conns + 12u * rows)
        return NRT_E_ARG;
    /* whole groups of eight rows, the ones past the last all zero */
    memset(d->w, 0, sizeof d->w[0] * 8u * groups * cols);
    d->narrow = (uint8_t)((1u << groups) - 1u);
    for (j = 0, k = 0; j < rows; j++) {
        uint32_t l1 = 0; /* at most 64 * 32767 */
        for (; k < net->end[j]; k++) {
            nrt_w12 *cell = &d->w[j * cols + net->src[k]];
            /* two connections between the same nodes: the list's sum has
             * both products, a cell holds one weight */
            if (*cell != 0)
                return NRT_E_ARG;
            *cell = net->weight[k];
            l1 += (uint32_t)(net->weight[k] < 0 ? -net->weight[k] : net->weight[k]);
        }
        /* |sum| <= l1 * 32768 < 2^31: every partial sum fits 32 bits */
        if (l1 > NRT_DENSE_NARROW_L1)
            d->narrow &= (uint8_t)~(1u << (j / 8u));
    }
    d->rows = (uint16_t)rows;
    d->blocks = (uint16_t)blocks;
    d->n_inputs = net->n_inputs;
    d->n_nodes = net->n_nodes;
    /* the padding is zero, and only ever meets zero weights */
    memset(d->act, 0, sizeof d->act);
    memcpy(d->act[0], net->act[0], 2u * net->n_nodes);
    memcpy(d->act[1], net->act[1], 2u * net->n_nodes);
    d->cur = (uint8_t)net->cur;
    return NRT_OK;
}

void nrt_dense_save(const nrt_dense *d, nrt_net *net)
{
    memcpy(net->act[0], d->act[0], 2u * d->n_nodes);
    memcpy(net->act[1], d->act[1], 2u * d->n_nodes);
    net->cur = d->cur;
}

/* A row's sum in two parts, lanes of 32 bits: NRT_DENSE_MADD is one
 * block's vpmaddwd, lane m = w_i a_i + w_(i+1) a_(i+1); NRT_DENSE_ADD adds
 * one block of the row (16 cells), hi += m >> 16 and sm += m (wrapping);
 * NRT_DENSE_ROW sums a whole row. Two products of at most 2^30 - 2^15 each
 * (|w| <= 32767, |a| <= 32768) keep m below 2^31, exact in 32 bits, and
 * m = hi * 2^16 + lo with 0 <= lo < 2^16: hi is the sum's high part, exact
 * (|hi| <= 2^15 a lane), and sm the whole sum modulo 2^32, whose low part
 * (the sum of the los, below 2^21 for a row) is then sm - hi * 2^16, exact
 * too. One add fewer per block than summing the los themselves. */
#define NRT_DENSE_MADD(cells, vb) _mm256_madd_epi16(_mm256_loadu_si256((const __m256i *)(const void *)(cells)), (vb))
#define NRT_DENSE_ADD(cells, vb, hi, sm)                                                                            \
    do {                                                                                                            \
        __m256i m_ = NRT_DENSE_MADD(cells, vb);                                                                     \
        hi = _mm256_add_epi32(hi, _mm256_srai_epi32(m_, 16));                                                       \
        sm = _mm256_add_epi32(sm, m_);                                                                              \
    } while (0)
#define NRT_DENSE_ROW(row, v, blocks, hi, sm)                                                                      \
    do {                                                                                                            \
        uint32_t b_;                                                                                                \
        hi = sm = _mm256_setzero_si256();                                                                           \
        for (b_ = 0; b_ < (blocks); b_++) {                                                                         \
            NRT_DENSE_ADD((row) + 16u * b_, (v)[b_], hi, sm);                                                       \
        }                                                                                                           \
    } while (0)

/* A step's activations a, padded to whole blocks, into v: blocks a
 * constant where it is inlined, so that these are plain vector loads */
NRT_AVX2 static inline __attribute__((always_inline)) void nrt_dense_load(const nrt_q15 *a, __m256i *v, uint32_t blocks)
{
    uint32_t b;
    for (b = 0; b < blocks; b++)
        v[b] = _mm256_loadu_si256((const __m256i *)(const void *)(a + 16u * b));
}

/* The eight lanes of each of x[0..7] added up: lane r of the result is the
 * sum of x[r]. */
NRT_AVX2 static inline __m256i nrt_dense_sum8(const __m256i x[8])
{
    __m256i u0 = _mm256_hadd_epi32(_mm256_hadd_epi32(x[0], x[1]), _mm256_hadd_epi32(x[2], x[3]));
    __m256i u1 = _mm256_hadd_epi32(_mm256_hadd_epi32(x[4], x[5]), _mm256_hadd_epi32(x[6], x[7]));
    return _mm256_add_epi32(_mm256_permute2x128_si256(u0, u1, 0x20), _mm256_permute2x128_si256(u0, u1, 0x31));
}

/* Table entries i and i + 1 as one 32-bit word (i in the low half: x86 is little endian),
 * for eight indices i <= NRT_SIG_ENTRIES - 2. By scalar loads: vpgatherdd was a fifth of
 * the step's time here (perf; it is microcoded on processors with the
 * gather data sampling mitigation). */
NRT_AVX2 static inline __m256i nrt_dense_entries8(__m256i i)
{
    uint32_t idx[8], e[8];
    int r;
    _mm256_storeu_si256((__m256i *)(void *)idx, i);
    for (r = 0; r < 8; r++)
        memcpy(&e[r], nrt_sig_table + idx[r], sizeof e[r]);
    return _mm256_setr_epi32((int32_t)e[0], (int32_t)e[1], (int32_t)e[2], (int32_t)e[3], (int32_t)e[4], (int32_t)e[5],
                             (int32_t)e[6], (int32_t)e[7]);
}

/* nrt_sig_eval of eight sums given as their high parts and the sums
 * modulo 2^32 (NRT_DENSE_ADD: sum = hi * 2^16 + lo, |hi| <= 2^20, 0 <= lo
 * < 2^21, sm = sum mod 2^32), as eight Q1.15 values in the low 128 bits.
 * hi clamped to +-2^14 (h) keeps every sum below 2^31 in magnitude: h *
 * 2^16 + lo = sm + (h - hi) * 2^16 modulo 2^32, the sum itself where |sum|
 * < 2^30 - 2^21 (there h = hi) and of the right sign with |sum| beyond
 * NRT_SIG_LIMIT (2^28.2) elsewhere, which saturates the same. The table
 * lookup is nrt_sig_eval's integer arithmetic, in 32-bit lanes: t1 - t0
 * (the table rises: at most 627) and frac are below 2^16. */
NRT_AVX2 static inline __m128i nrt_dense_sig8(__m256i hi, __m256i sm)
{
    const __m256i limit = _mm256_set1_epi32((int32_t)NRT_SIG_LIMIT), top = _mm256_set1_epi32(32768);
    __m256i h = _mm256_max_epi32(_mm256_min_epi32(hi, _mm256_set1_epi32(1 << 14)), _mm256_set1_epi32(-(1 << 14)));
    __m256i sum = _mm256_add_epi32(sm, _mm256_slli_epi32(_mm256_sub_epi32(h, hi), 16));
    __m256i x = _mm256_min_epi32(_mm256_abs_epi32(sum), limit);
    __m256i sat = _mm256_cmpeq_epi32(x, limit);
    __m256i i = _mm256_min_epi32(_mm256_srli_epi32(x, NRT_SIG_SHIFT), _mm256_set1_epi32(NRT_SIG_ENTRIES - 2));
    __m256i frac = _mm256_and_si256(_mm256_srli_epi32(x, NRT_SIG_SHIFT - 16), _mm256_set1_epi32(0xFFFF));
    __m256i pair = nrt_dense_entries8(i);
    __m256i t0 = _mm256_and_si256(pair, _mm256_set1_epi32(0xFFFF)), t1 = _mm256_srli_epi32(pair, 16);
    /* (t1 - t0) frac >> 16, both factors in the low halves of the lanes
     * (the high halves 0): the unsigned high multiply of 16-bit lanes is
     * that floor exactly, and 0 in the high halves. 5 cycles of latency
     * where vpmulld and a shift took 11 on Intel's cores, on the chain
     * each step waits for (2-3 % more game-steps/s in duel_bench) */
    __m256i y = _mm256_add_epi32(t0, _mm256_mulhi_epu16(_mm256_sub_epi32(t1, t0), frac));
    __m256i neg = _mm256_cmpgt_epi32(_mm256_setzero_si256(), sum), out;
    y = _mm256_blendv_epi8(y, top, sat);
    out = _mm256_blendv_epi8(_mm256_min_epi32(y, _mm256_set1_epi32(32767)), _mm256_sub_epi32(top, y), neg);
    return _mm256_castsi256_si128(_mm256_permute4x64_epi64(_mm256_packs_epi32(out, out), 0x08));
}

/* The sums of a network of at most NRT_DENSE_FEW rows (nrt_dense.h), for
 * the activations in v, in one reduction: lanes 0-3 the rows' his, 4-7
 * their sums modulo 2^32 (rows past the last zero). More rows share a
 * reduction four at a time, or eight in a narrow group (nrt_dense_rows);
 * either way eight sigmoids at once. */
NRT_AVX2 static inline __attribute__((always_inline)) __m256i nrt_dense_few(const nrt_dense *d, const __m256i *v,
                                                                           uint32_t blocks)
{
    __m256i x[8];
    const nrt_w12 *row = d->w;
    uint32_t r;
    /* x[r]: row r's hi, x[4 + r] its sm; the rows past the last are in the
     * matrix (a whole group of eight), all zero, and sum to zero: cheaper
     * to add up than to branch around */
    for (r = 0; r < NRT_DENSE_FEW; r++, row += 16u * blocks)
        NRT_DENSE_ROW(row, v, blocks, x[r], x[4 + r]);
    return nrt_dense_sum8(x);
}

/* The rows' new activations into next[]: a[] holds the step's activations
 * padded to whole blocks (zeros at first, then whatever the group stores
 * below left there: the padding columns' weights are 0 in every row, so
 * their values never count); the matrix has whole groups of eight rows,
 * those past d->rows all zero. The stores write whole groups (of four or
 * eight): the values past the last row land in that padding, beyond the
 * last node. */
NRT_AVX2 static inline __attribute__((always_inline)) void nrt_dense_rows(const nrt_dense *d, const nrt_q15 *a,
                                                                          nrt_q15 *next, uint32_t blocks)
{
    __m256i v[NRT_DENSE_MAX_NODES / 16], x[8], s[2];
    const nrt_w12 *row = d->w;
    uint32_t b, j, q, r, rows = d->rows;
    nrt_dense_load(a, v, blocks);
    if (rows <= NRT_DENSE_FEW) {
        s[0] = nrt_dense_few(d, v, blocks);
        _mm_storel_epi64((__m128i *)(void *)next, nrt_dense_sig8(s[0], _mm256_permute4x64_epi64(s[0], 0x4E)));
        return;
    }
    for (j = 0; j < rows; j += 8u, row += 8u * 16u * blocks) {
        /* tile by tile, skipping those without a connection: their
         * products are all 0, so every sum is the same; four rows at a
         * time, so that their eight sums and a block of activations stay
         * in registers (eight rows' sixteen spilled), one reduction each */
        uint32_t tiles = d->tiles[j / 8u];
        if (d->narrow & (1u << (j / 8u))) {
            /* every sum fits 32 bits (nrt_dense_make): the products added
             * up directly, eight rows to a reduction, the high parts 0 */
            for (r = 0; r < 8u; r++)
                x[r] = _mm256_setzero_si256();
            for (b = 0; b < blocks; b++)
                if (tiles & (1u << b))
                    for (r = 0; r < 8u; r++)
                        x[r] = _mm256_add_epi32(x[r], NRT_DENSE_MADD(row + 16u * (blocks * r + b), v[b]));
            _mm_storeu_si128((__m128i *)(void *)(next + j), nrt_dense_sig8(_mm256_setzero_si256(), nrt_dense_sum8(x)));
            continue;
        }
        for (q = 0; q < 2u; q++) {
            for (r = 0; r < 4u; r++)
                x[r] = x[4 + r] = _mm256_setzero_si256();
            for (b = 0; b < blocks; b++)
                if (tiles & (1u << b))
                    for (r = 0; r < 4u; r++)
                        NRT_DENSE_ADD(row + 16u * (blocks * (4u * q + r) + b), v[b], x[r], x[4 + r]);
            s[q] = nrt_dense_sum8(x);
        }
        /* the eight rows' his, then their sums */
        _mm_storeu_si128((__m128i *)(void *)(next + j), nrt_dense_sig8(_mm256_permute2x128_si256(s[0], s[1], 0x20),
                                                                       _mm256_permute2x128_si256(s[0], s[1], 0x31)));
    }
}

NRT_AVX2 void nrt_dense_step(nrt_dense *d)
{
    const nrt_q15 *a = d->act[d->cur];
    nrt_q15 *next = d->act[d->cur ^ 1u] + d->n_inputs;
    /* a constant block count for each, so that the compiler unrolls */
    switch (d->blocks) {
    case 1:
        nrt_dense_rows(d, a, next, 1);
        break;
    case 2:
        nrt_dense_rows(d, a, next, 2);
        break;
    case 3:
        nrt_dense_rows(d, a, next, 3);
        break;
    default:
        nrt_dense_rows(d, a, next, 4);
        break;
    }
    d->cur ^= 1u;
}

/* nrt_dense_few for d's current activations, blocks a constant */
NRT_AVX2 static inline __attribute__((always_inline)) __m256i nrt_dense_few_at(const nrt_dense *d, uint32_t blocks)
{
    __m256i v[NRT_DENSE_MAX_NODES / 16];
    nrt_dense_load(d->act[d->cur], v, blocks);
    return nrt_dense_few(d, v, blocks);
}

/* nrt_dense_few_at with d's block count, a constant in each case (with a
 * variable count GCC made the loads one call of memcpy into the stack, a
 * fortieth of a generation's time) */
NRT_AVX2 static inline __attribute__((always_inline)) __m256i nrt_dense_few_sums(const nrt_dense *d)
{
    switch (d->blocks) {
    case 1: return nrt_dense_few_at(d, 1);
    case 2: return nrt_dense_few_at(d, 2);
    case 3: return nrt_dense_few_at(d, 3);
    default: return nrt_dense_few_at(d, 4);
    }
}

NRT_AVX2 void nrt_dense_step2(nrt_dense *d0, nrt_dense *d1)
{
    __m256i s0, s1;
    __m128i out;
    if (d0->rows > NRT_DENSE_FEW || d1->rows > NRT_DENSE_FEW) {
        nrt_dense_step(d0);
        nrt_dense_step(d1);
        return;
    }
    /* both small: one sigmoid of eight for the two networks' rows, d0's
     * his and los in lanes 0-3, d1's in 4-7 */
    s0 = nrt_dense_few_sums(d0);
    s1 = nrt_dense_few_sums(d1);
    out = nrt_dense_sig8(_mm256_permute2x128_si256(s0, s1, 0x20), _mm256_permute2x128_si256(s0, s1, 0x31));
    _mm_storel_epi64((__m128i *)(void *)(d0->act[d0->cur ^ 1u] + d0->n_inputs), out);
    _mm_storel_epi64((__m128i *)(void *)(d1->act[d1->cur ^ 1u] + d1->n_inputs), _mm_unpackhi_epi64(out, out));
    d0->cur ^= 1u;
    d1->cur ^= 1u;
}

#else /* no dense step on this processor or compiler */

int nrt_dense_make(nrt_dense *d, const nrt_net *net)
{
    (void)d;
    (void)net;
    return NRT_E_ARG;
}

void nrt_dense_step(nrt_dense *d)
{
    (void)d;
}

void nrt_dense_step2(nrt_dense *d0, nrt_dense *d1)
{
    (void)d0;
    (void)d1;
}

void nrt_dense_save(const nrt_dense *d, nrt_net *net)
{
    (void)d;
    (void)net;
}

#endif
