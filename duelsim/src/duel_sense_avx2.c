/* duel_sense_avx2.c - both robots' sensors at once with AVX2 (and AVX-512VL's masks where present) on x86-64: the readings of duel_sense, four cross products per instruction. */
#include "duel_sensors.h"

/*
 * The same step as duel_sense (duel_sense.c), one more implementation of it:
 * duel_play senses both robots of its game here when the processor has AVX2,
 * and with duel_sense twice otherwise. The arithmetic is the scalar path's,
 * in 64-bit lanes: every product is a signed 32 x 32 -> 64 multiply
 * (vpmuldq) of values that fit 32 bits (offsets below 2^26, Q30 boundaries
 * at most 2^30 + 1), so each cross product and squared distance is the same
 * exact integer, and each comparison the same. tests/duelsim/test_golden.c
 * checks both paths against the same recorded hashes and against each other.
 *
 * Lanes: (west, item i), (east, item i), (west, item j), (east, item j): two
 * food items per round for both robots (duel_lanes, made once per game and
 * again when an item is eaten). An odd item count repeats the last item,
 * which cannot change a minimum.
 *
 * Where the processor also has AVX-512 (F, VL and DQ), the food scan's loop
 * is duel_scan_pair_vl: the same lanes and products in the same 256-bit
 * registers, with the comparisons into mask registers and each sector's
 * minimum one masked unsigned vpminuq instead of a compare, an and and a
 * blend (on Intel's cores the compares and blends crowd one port: 17 % and
 * 9 % more game-steps a second with 39 and 202 connections on a Xeon,
 * docs/duelsim.md). Everything else is the AVX2 code; test_golden runs both
 * against the scalar path.
 */

static int duel_simd_cap = DUEL_SIMD_AVX512;

void duel_simd_allow(int level)
{
    duel_simd_cap = level < DUEL_SIMD_NONE ? DUEL_SIMD_NONE : level;
}

#if DUEL_HAVE_AVX2
#include <immintrin.h>

int duel_simd_active(void)
{
    if (duel_simd_cap == DUEL_SIMD_NONE || !__builtin_cpu_supports("avx2"))
        return DUEL_SIMD_NONE;
    if (duel_simd_cap >= DUEL_SIMD_AVX512 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512dq"))
        return DUEL_SIMD_AVX512;
    return DUEL_SIMD_AVX2;
}

/* floor(r / range) = r * mul >> shift for every r below 2^26 (a distance
 * on the board in Q16.16): shift = 26 + ceil(log2 range), mul =
 * ceil(2^shift / range) = (2^shift + e) / range with 0 <= e < range, so
 * r * mul / 2^shift = r / range + r e / (range 2^shift), and r e < 2^26
 * 2^ceil(log2 range) = 2^shift keeps the excess below 1 / range: it never
 * reaches the next multiple. mul <= 2^27 + 1: a 32 x 32-bit product. */
static void duel_divisor(uint32_t range, int64_t *mul, int64_t *shift)
{
    int s = 26;
    while ((1u << (s - 26)) < range)
        s++;
    *shift = s;
    *mul = (int64_t)((((uint64_t)1 << s) + range - 1u) / range);
}

void duel_lanes_init(duel_lanes *lanes, const duel_rules *r)
{
    int64_t fm, fs, rm, rs;
    int k;
    lanes->mask = ~0u;
    lanes->level = duel_simd_active();
    duel_divisor(r->food_range, &fm, &fs);
    duel_divisor(r->robot_range, &rm, &rs);
    for (k = 0; k < 4; k++) {
        lanes->mul[0][k] = fm;
        lanes->shift[0][k] = fs;
        lanes->mul[1][k] = k < 2 ? fm : rm;
        lanes->shift[1][k] = k < 2 ? fs : rs;
    }
}

#define DUEL_AVX2 __attribute__((target("avx2")))
/* Every helper below is inlined into the two sensing functions at the end
 * (the AVX2 one and the AVX-512VL one, whose target includes AVX2's): so
 * the boundaries stay in registers, and there is no call per step. */
#define DUEL_INLINE static inline __attribute__((always_inline))

/* (west value, east value) in both halves */
DUEL_AVX2 DUEL_INLINE __m256i duel_lanes_of(int64_t west, int64_t east)
{
    return _mm256_set_epi64x(east, west, east, west);
}

/* x / 2^30 rounded as duel_round_shift does, right for results that fit 32
 * bits (the boundaries: at most 2^30 + 1), sign-extended from those */
DUEL_AVX2 DUEL_INLINE __m256i duel_round30(__m256i x)
{
    const __m256i half = _mm256_set1_epi64x((int64_t)1 << 29);
    __m256i neg = _mm256_cmpgt_epi64(_mm256_setzero_si256(), x);
    /* the low 32 bits of a logical and of an arithmetic shift agree */
    __m256i q = _mm256_srli_epi64(_mm256_add_epi64(_mm256_add_epi64(x, half), neg), 30);
    return _mm256_cvtepi32_epi64(
        _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(q, _mm256_set_epi32(7, 5, 3, 1, 6, 4, 2, 0))));
}

/* Both robots' frames (duel_frame_of) as their boundaries in lanes (west,
 * east, west, east): the eight products of each robot four at a time; the
 * headings' cos and sin into c[2], s[2]. */
DUEL_AVX2 DUEL_INLINE void duel_frames_of(const duel_world *w, int32_t c[2], int32_t s[2], __m256i bx[5], __m256i by[5])
{
    __m256i vc, vs, kc, ks, cc, ss, cs, sc, lo_x, lo_y, hi_x, hi_y;
    duel_cossin_q30(w->robot[DUEL_WEST].heading, &c[0], &s[0]);
    duel_cossin_q30(w->robot[DUEL_EAST].heading, &c[1], &s[1]);
    vc = duel_lanes_of(c[0], c[1]);
    vs = duel_lanes_of(s[0], s[1]);
    /* lanes (west, east) for boundary pair 0/4, then for pair 1/3 */
    kc = _mm256_set_epi64x(duel_bcos[1], duel_bcos[1], duel_bcos[0], duel_bcos[0]);
    ks = _mm256_set_epi64x(duel_bsin[1], duel_bsin[1], duel_bsin[0], duel_bsin[0]);
    cc = _mm256_mul_epi32(vc, kc);
    ss = _mm256_mul_epi32(vs, ks);
    cs = _mm256_mul_epi32(vc, ks);
    sc = _mm256_mul_epi32(vs, kc);
    lo_x = duel_round30(_mm256_sub_epi64(cc, ss)); /* bx[0] (west, east), bx[1] (west, east) */
    lo_y = duel_round30(_mm256_add_epi64(cs, sc));
    hi_x = duel_round30(_mm256_add_epi64(cc, ss)); /* bx[4], bx[3] */
    hi_y = duel_round30(_mm256_sub_epi64(sc, cs));
    bx[0] = _mm256_permute4x64_epi64(lo_x, 0x44);
    bx[1] = _mm256_permute4x64_epi64(lo_x, 0xEE);
    bx[4] = _mm256_permute4x64_epi64(hi_x, 0x44);
    bx[3] = _mm256_permute4x64_epi64(hi_x, 0xEE);
    by[0] = _mm256_permute4x64_epi64(lo_y, 0x44);
    by[1] = _mm256_permute4x64_epi64(lo_y, 0xEE);
    by[4] = _mm256_permute4x64_epi64(hi_y, 0x44);
    by[3] = _mm256_permute4x64_epi64(hi_y, 0xEE);
    bx[2] = _mm256_sub_epi64(_mm256_setzero_si256(), vc);
    by[2] = _mm256_sub_epi64(_mm256_setzero_si256(), vs);
}

/* The sector masks of the vectors (vx, vy) in lanes: m[k] all ones where
 * the vector lies in sector k. With the boundaries 72 degrees apart in
 * angular order, "not clockwise of boundary k-1, clockwise of boundary k"
 * is duel_sector's tree for every non-zero v (a bearing on boundary k-1
 * belongs to sector k, on the ray opposite it to no neighbour of it); v = 0
 * gets no sector. */
DUEL_AVX2 DUEL_INLINE void duel_sectors4(__m256i vx, __m256i vy, const __m256i bx[5],
                                                                         const __m256i by[5], __m256i m[5])
{
    __m256i s[5];
    int k;
    /* s[k]: v clockwise of boundary k, bx * vy < by * vx (duel_sector) */
    for (k = 0; k < 5; k++)
        s[k] = _mm256_cmpgt_epi64(_mm256_mul_epi32(by[k], vx), _mm256_mul_epi32(bx[k], vy));
    for (k = 0; k < 5; k++)
        m[k] = _mm256_andnot_si256(s[(k + 4) % 5], s[k]);
}

/* the items of w->food_mask in pairs, an odd last one twice */
static void duel_lanes_make(duel_lanes *l, const duel_world *w)
{
    unsigned idx[DUEL_MAX_FOOD + 1], n = 0, p;
    uint32_t mask = w->food_mask & ((1u << w->n_food) - 1u);
    for (; mask != 0; mask &= mask - 1u)
        idx[n++] = duel_lowest_bit(mask);
    if (n & 1u) {
        idx[n] = idx[n - 1];
        n++;
    }
    for (p = 0; p < n / 2; p++) {
        l->x[p][0] = l->x[p][1] = w->food_x[idx[2 * p]];
        l->x[p][2] = l->x[p][3] = w->food_x[idx[2 * p + 1]];
        l->y[p][0] = l->y[p][1] = w->food_y[idx[2 * p]];
        l->y[p][2] = l->y[p][3] = w->food_y[idx[2 * p + 1]];
    }
    l->pairs = n / 2;
    l->mask = w->food_mask;
}

/* duel_range_reading of four squared distances given as keys (d2 - 1 with
 * the top bit flipped; INT64_MAX: none, reading 0), with the lanes'
 * divisors (duel_lanes: which = 0 four food lanes, 1 two food, two robot).
 * r = floor(sqrt(d2)) is the truncated double-precision square root of d2,
 * exactly: d2 < 2^52 on the board (offsets below 2^26 / sqrt 2) is exact in
 * a double, and for an integer k <= 2^26 every d2 < k^2 has sqrt(d2) <=
 * sqrt(k^2 - 1) < k - 1/(2k), more than half a unit in the last place (at
 * most 2^-28 there) below k, so the correctly rounded root stays below k;
 * every d2 >= k^2 has a root, and so a rounded root, of at least k. Then n
 * = floor(r / range) by a multiply (duel_divisor), the reading 32768 -
 * (n + 1) / 2 at most 32767 and at least 0 (beyond the range n >= 65536
 * makes it negative: a signed 32-bit maximum with 0 clears the whole lane,
 * its high half being -1 or 0): duel_range_reading's value
 * (floor(sqrt(floor(d2 / range^2))) = floor(floor(sqrt(d2)) / range)).
 * tests/duelsim/test_golden.c compares it with duel_sense at every
 * distance where a reading steps. */
DUEL_AVX2 DUEL_INLINE __m256i duel_readings4(__m256i key, const duel_lanes *l, int which)
{
    const __m256i none = _mm256_cmpeq_epi64(key, _mm256_set1_epi64x(INT64_MAX));
    const __m256i two52 = _mm256_set1_epi64x(0x4330000000000000LL), one = _mm256_set1_epi64x(1);
    __m256i d2 = _mm256_sub_epi64(key, _mm256_set1_epi64x(INT64_MAX));
    __m256d x = _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(d2, two52)), _mm256_castsi256_pd(two52));
    __m256i r = _mm256_cvtepi32_epi64(_mm256_cvttpd_epi32(_mm256_sqrt_pd(x)));
    __m256i n = _mm256_srlv_epi64(_mm256_mul_epu32(r, _mm256_loadu_si256((const __m256i *)(const void *)l->mul[which])),
                                  _mm256_loadu_si256((const __m256i *)(const void *)l->shift[which]));
    __m256i v = _mm256_sub_epi64(_mm256_set1_epi64x(32768), _mm256_srli_epi64(_mm256_add_epi64(n, one), 1));
    v = _mm256_add_epi64(v, _mm256_cmpgt_epi64(v, _mm256_set1_epi64x(32767)));
    v = _mm256_max_epi32(v, _mm256_setzero_si256());
    return _mm256_andnot_si256(none, v);
}

/* Pair p of the food lanes from both robots (rx, ry): the offsets into
 * *vx, *vy, and their squared lengths (below 2^52: exact) */
DUEL_AVX2 DUEL_INLINE __m256i duel_pair_offsets(const duel_lanes *l, uint32_t p,
                                                                                __m256i rx, __m256i ry, __m256i *vx,
                                                                                __m256i *vy)
{
    *vx = _mm256_sub_epi64(_mm256_loadu_si256((const __m256i *)(const void *)l->x[p]), rx);
    *vy = _mm256_sub_epi64(_mm256_loadu_si256((const __m256i *)(const void *)l->y[p]), ry);
    return _mm256_add_epi64(_mm256_mul_epi32(*vx, *vx), _mm256_mul_epi32(*vy, *vy));
}

/* The food readings of both robots and the robot reading: rd[2k + side] for
 * sector k, rd[10] (and rd[11]) for the robot rangefinder at robot_d2. */
DUEL_AVX2 DUEL_INLINE void duel_scan_pair(const duel_world *w, const duel_lanes *l, const __m256i bx[5], const __m256i by[5],
                                     int64_t robot_d2, int64_t rd[12])
{
    /* keys: d2 - 1 with the top bit flipped, so that the unsigned order of
     * d2 - 1 (duel_scan's) is the signed order AVX2 compares in; none (and an
     * item at the robot's centre) is INT64_MAX */
    const __m256i flip = _mm256_set1_epi64x(INT64_MAX);
    const __m256i rx = duel_lanes_of(w->robot[0].x, w->robot[1].x), ry = duel_lanes_of(w->robot[0].y, w->robot[1].y);
    __m256i best[5];
    uint32_t p;
    int k;

    for (k = 0; k < 5; k++)
        best[k] = flip;
    for (p = 0; p < l->pairs; p++) {
        __m256i vx, vy, key = _mm256_add_epi64(duel_pair_offsets(l, p, rx, ry, &vx, &vy), flip);
        __m256i m[5];
        duel_sectors4(vx, vy, bx, by, m);
        for (k = 0; k < 5; k++) {
            __m256i better = _mm256_and_si256(m[k], _mm256_cmpgt_epi64(best[k], key));
            best[k] = _mm256_blendv_epi8(best[k], key, better);
        }
    }
    for (k = 0; k < 5; k++) {
        /* the nearer of the two halves */
        __m256i other = _mm256_permute4x64_epi64(best[k], 0x4E);
        best[k] = _mm256_blendv_epi8(best[k], other, _mm256_cmpgt_epi64(best[k], other));
    }
    /* (west k, east k, west k+1, east k+1): sectors 0-1, 2-3, then 4 and
     * the robot rangefinder's distance */
    _mm256_storeu_si256((__m256i *)(void *)rd, duel_readings4(_mm256_blend_epi32(best[0], best[1], 0xF0), l, 0));
    _mm256_storeu_si256((__m256i *)(void *)(rd + 4), duel_readings4(_mm256_blend_epi32(best[2], best[3], 0xF0), l, 0));
    _mm256_storeu_si256((__m256i *)(void *)(rd + 8),
                        duel_readings4(_mm256_blend_epi32(best[4], _mm256_add_epi64(_mm256_set1_epi64x(robot_d2), flip), 0xF0),
                                       l, 1));
}

#define DUEL_AVX512 __attribute__((target("avx2,avx512f,avx512vl,avx512dq")))

/* duel_readings4 of four squared distances less one (unsigned; all ones:
 * none, reading 0) with AVX-512DQ's conversions between 64-bit integers and
 * doubles; the same values by the same argument */
DUEL_AVX512 DUEL_INLINE __m256i duel_readings4_vl(__m256i d2m1, const duel_lanes *l, int which)
{
    const __m256i minus1 = _mm256_set1_epi64x(-1);
    __mmask8 some = _mm256_cmpneq_epu64_mask(d2m1, minus1);
    __m256d x = _mm256_cvtepi64_pd(_mm256_sub_epi64(d2m1, minus1));
    __m256i r = _mm256_cvttpd_epi64(_mm256_sqrt_pd(x));
    __m256i n = _mm256_srlv_epi64(_mm256_mul_epu32(r, _mm256_loadu_si256((const __m256i *)(const void *)l->mul[which])),
                                  _mm256_loadu_si256((const __m256i *)(const void *)l->shift[which]));
    __m256i v = _mm256_sub_epi64(_mm256_set1_epi64x(32768), _mm256_srli_epi64(_mm256_sub_epi64(n, minus1), 1));
    return _mm256_maskz_max_epi64(some, _mm256_min_epi64(v, _mm256_set1_epi64x(32767)), _mm256_setzero_si256());
}

/* duel_scan_pair with AVX-512VL: the keys are d2 - 1 as unsigned (an item
 * at the robot's centre wraps to the largest, none), the minimum unsigned
 * (vpminuq), the sector test into masks and the and-not of two masks
 * (kandnb) choosing the lanes each sector's minimum takes */
DUEL_AVX512 DUEL_INLINE void duel_scan_pair_vl(const duel_world *w, const duel_lanes *l, const __m256i bx[5],
                                          const __m256i by[5], int64_t robot_d2, int64_t rd[12])
{
    const __m256i rx = duel_lanes_of(w->robot[0].x, w->robot[1].x), ry = duel_lanes_of(w->robot[0].y, w->robot[1].y);
    const __m256i minus1 = _mm256_set1_epi64x(-1);
    __m256i best[5];
    uint32_t p;
    int k;

    for (k = 0; k < 5; k++)
        best[k] = minus1;
    for (p = 0; p < l->pairs; p++) {
        __m256i vx, vy, d2m1 = _mm256_add_epi64(duel_pair_offsets(l, p, rx, ry, &vx, &vy), minus1);
        __mmask8 s[5];
        /* s[k]: v clockwise of boundary k (duel_sectors4) */
        for (k = 0; k < 5; k++)
            s[k] = _mm256_cmpgt_epi64_mask(_mm256_mul_epi32(by[k], vx), _mm256_mul_epi32(bx[k], vy));
        for (k = 0; k < 5; k++)
            best[k] = _mm256_mask_min_epu64(best[k], _kandn_mask8(s[(k + 4) % 5], s[k]), best[k], d2m1);
    }
    for (k = 0; k < 5; k++)
        /* the nearer of the two halves */
        best[k] = _mm256_min_epu64(best[k], _mm256_permute4x64_epi64(best[k], 0x4E));
    /* the lanes of duel_scan_pair's readings */
    _mm256_storeu_si256((__m256i *)(void *)rd, duel_readings4_vl(_mm256_blend_epi32(best[0], best[1], 0xF0), l, 0));
    _mm256_storeu_si256((__m256i *)(void *)(rd + 4), duel_readings4_vl(_mm256_blend_epi32(best[2], best[3], 0xF0), l, 0));
    _mm256_storeu_si256((__m256i *)(void *)(rd + 8),
                        duel_readings4_vl(_mm256_blend_epi32(best[4], _mm256_set1_epi64x(robot_d2 - 1), 0xF0), l, 1));
}

/* The inputs of both robots from the food readings rd (duel_scan_pair's)
 * and the frames: the robot rangefinders, energy, wall (duel_sense_finish
 * with the readings taken). d2 is the robots' squared distance. */
DUEL_AVX2 DUEL_INLINE void duel_sense_end(const duel_world *w, const int32_t c[2], const int32_t s[2],
                                          const __m256i bx[5], const __m256i by[5], const int64_t rd[12],
                                          nrt_q15 west[DUEL_N_INPUTS], nrt_q15 east[DUEL_N_INPUTS])
{
    const duel_rules *R = w->rules; /* set: duel_play made the world */
    const duel_robot *a = &w->robot[DUEL_WEST], *b = &w->robot[DUEL_EAST];
    int64_t vx = (int64_t)b->x - a->x, vy = (int64_t)b->y - a->y, d2 = vx * vx + vy * vy, sec[4];
    nrt_q15 *in[2], energy;
    __m256i m[5], rx, ry;
    int side, k;
    /* the robot rangefinders' sector: the other robot is at (vx, vy) from
     * west, at (-vx, -vy) from east; the sector's number from the masks,
     * -(m[1] + 2 m[2] + 3 m[3] + 4 m[4]) (a mask is -1), none when v = 0 */
    rx = _mm256_set_epi64x(-vx, vx, -vx, vx);
    ry = _mm256_set_epi64x(-vy, vy, -vy, vy);
    duel_sectors4(rx, ry, bx, by, m);
    m[1] = _mm256_add_epi64(m[1], m[3]);                                /* A = m1 + m3 */
    m[2] = _mm256_add_epi64(m[2], m[3]);                                /* B = m2 + m3 */
    m[4] = _mm256_add_epi64(m[2], _mm256_add_epi64(m[4], m[4]));        /* B + 2 m4 */
    /* -(A + 2 (B + 2 m4)) = -(m1 + 2 m2 + 3 m3 + 4 m4) */
    _mm256_storeu_si256((__m256i *)(void *)sec,
                        _mm256_sub_epi64(_mm256_setzero_si256(), _mm256_add_epi64(m[1], _mm256_add_epi64(m[4], m[4]))));
    in[0] = west;
    in[1] = east;
    /* the two robots read exact opposites (duel_energy_reading) */
    energy = duel_energy_reading(a->energy, b->energy, R->energy_scale);
    for (side = 0; side < 2; side++) {
        /* duel_sense_finish with the readings taken above */
        nrt_q15 *v = in[side];
        v[0] = NRT_ONE;
        for (k = 0; k < 5; k++)
            v[1 + k] = (nrt_q15)rd[2 * k + side];
        v[6] = v[7] = v[8] = v[9] = v[10] = 0;
        if (d2 != 0)
            v[6 + sec[side]] = (nrt_q15)rd[10];
        v[11] = side == 0 ? energy : (nrt_q15)-energy;
        v[12] = duel_wall_reading(&w->robot[side], c[side], s[side], R->wall_range);
    }
}

/* the robots' squared distance, for the robot rangefinders */
static int64_t duel_robots_d2(const duel_world *w)
{
    return duel_dist2(w->robot[DUEL_EAST].x, w->robot[DUEL_EAST].y, w->robot[DUEL_WEST].x, w->robot[DUEL_WEST].y);
}

DUEL_AVX2 static void duel_sense_both_avx2(const duel_world *w, duel_lanes *lanes, nrt_q15 west[DUEL_N_INPUTS],
                                           nrt_q15 east[DUEL_N_INPUTS])
{
    int64_t rd[12];
    int32_t c[2], s[2];
    __m256i bx[5], by[5];
    if (lanes->mask != w->food_mask)
        duel_lanes_make(lanes, w);
    duel_frames_of(w, c, s, bx, by);
    duel_scan_pair(w, lanes, bx, by, duel_robots_d2(w), rd);
    duel_sense_end(w, c, s, bx, by, rd, west, east);
}

/* duel_sense_both_avx2 with the AVX-512VL food scan */
DUEL_AVX512 static void duel_sense_both_vl(const duel_world *w, duel_lanes *lanes, nrt_q15 west[DUEL_N_INPUTS],
                                           nrt_q15 east[DUEL_N_INPUTS])
{
    int64_t rd[12];
    int32_t c[2], s[2];
    __m256i bx[5], by[5];
    if (lanes->mask != w->food_mask)
        duel_lanes_make(lanes, w);
    duel_frames_of(w, c, s, bx, by);
    duel_scan_pair_vl(w, lanes, bx, by, duel_robots_d2(w), rd);
    duel_sense_end(w, c, s, bx, by, rd, west, east);
}

int duel_sense_both(const duel_world *w, duel_lanes *lanes, nrt_q15 west[DUEL_N_INPUTS],
                    nrt_q15 east[DUEL_N_INPUTS])
{
    if (lanes->level == DUEL_SIMD_NONE)
        return -1;
    if (lanes->level == DUEL_SIMD_AVX512)
        duel_sense_both_vl(w, lanes, west, east);
    else
        duel_sense_both_avx2(w, lanes, west, east);
    return 0;
}

#else /* no AVX2 path on this processor or compiler */

int duel_simd_active(void)
{
    return DUEL_SIMD_NONE;
}

void duel_lanes_init(duel_lanes *lanes, const duel_rules *r)
{
    (void)r;
    lanes->mask = ~0u;
    lanes->level = DUEL_SIMD_NONE;
}

int duel_sense_both(const duel_world *w, duel_lanes *lanes, nrt_q15 west[DUEL_N_INPUTS],
                    nrt_q15 east[DUEL_N_INPUTS])
{
    (void)w;
    (void)lanes;
    (void)west;
    (void)east;
    return -1;
}

#endif
