/* duel_sensors.h - the sensors' arithmetic that the scalar and the AVX2 sensing share: sector boundaries and tree, readings. */
#ifndef DUEL_SENSORS_H
#define DUEL_SENSORS_H

#include "duel_internal.h"

/* Boundary k (k = 0..4) between sector k and sector k+1 (counter-clockwise)
 * lies at heading + (2k + 1) * 36 degrees. Boundaries 0/4 and 1/3 are the
 * heading's unit vector rotated by +-36 and +-108 degrees: these are
 * round(2^30 cos), round(2^30 sin) of 36 and 108 degrees, applied with
 * symmetric rounding so a mirror-image heading gets mirror-image boundaries
 * exactly; boundary 2 is the heading reversed. */
static const int32_t duel_bcos[2] = {868675383, -331804471};
static const int32_t duel_bsin[2] = {631129609, 1021189159};

/* 1 - d / range in Q15 for a Q16.16 distance d below range: 32768 -
 * round(d / units_per_step), units_per_step = range * 65536 / 32768 = 2
 * range, rounded to nearest; at most 32767 */
static inline nrt_q15 duel_range_value(uint32_t d, uint32_t range)
{
    int32_t v = 32768 - (int32_t)((d + range) / (2u * range));
    if (v > 32767)
        v = 32767;
    return (nrt_q15)(v < 0 ? 0 : v);
}

/* A rangefinder reading max(0, 1 - d / range) from the exact squared
 * distance d2 (Q32): 32768 - round(d / (2 range)) with d in Q16.16.
 * round(x) = (floor(2x) + 1) / 2, and floor(d / range) =
 * floor(sqrt(floor(d2 / range^2))) exactly; below the range the quotient
 * is below 2^32 (world v1: range 850, 722500 = 850^2, and nothing on the
 * board is as far). At or beyond the range: 0, as 1 - d / range <= 0. The
 * caller gives r2 = range^2 and its limit r2 2^32 (duel_range_of), made
 * once per robot. */
typedef struct duel_range {
    uint64_t r2, limit;
} duel_range;

static inline duel_range duel_range_of(uint32_t range)
{
    duel_range r;
    r.r2 = (uint64_t)range * range;
    r.limit = r.r2 << 32;
    return r;
}

static inline nrt_q15 duel_range_reading(int64_t d2, duel_range r)
{
    uint32_t n;
    int32_t v;
    if ((uint64_t)d2 >= r.limit)
        return 0;
    n = duel_isqrt32((uint32_t)((uint64_t)d2 / r.r2));
    v = 32768 - (int32_t)((n + 1u) >> 1);
    return (nrt_q15)(v > 32767 ? 32767 : v);
}

/* The sector of the vector (vx, vy) from the robot: boundary 2 (straight
 * behind) splits the left sectors 0-2 from the right ones 3, 4, 0, then one
 * or two more cross products. A zero vector comes out as sector 0. */
static inline int duel_sector(int64_t vx, int64_t vy, const int64_t bx[5], const int64_t by[5])
{
    if (bx[2] * vy < by[2] * vx)
        return bx[0] * vy < by[0] * vx ? 0 : (bx[1] * vy < by[1] * vx ? 1 : 2);
    return bx[3] * vy < by[3] * vx ? 3 : (bx[4] * vy < by[4] * vx ? 4 : 0);
}

/* The wall input, max(0, 1 - d / range), d the distance along the heading
 * to the first board edge (world v1: range 200). */
static inline nrt_q15 duel_wall_reading(const duel_robot *r, int32_t c, int32_t s, uint32_t range)
{
    /* d = (edge - x) / cos with cos in Q30: multiply (not shift: the left
     * shift of a negative value is undefined). Only a distance below the
     * range gives a reading, and d >= edge - x (|cos| <= 1): an edge that
     * far or farther on its axis needs no division. */
    const int64_t q30 = (int64_t)1 << 30, far = (int64_t)range << 16;
    int64_t t = far, u = far, ex, ey;
    ex = c > 0 ? (int64_t)DUEL_FIX(DUEL_BOARD) - r->x : r->x;
    ey = s > 0 ? (int64_t)DUEL_FIX(DUEL_BOARD) - r->y : r->y;
    if (c != 0 && ex < far)
        t = ex * q30 / (c > 0 ? c : -c);
    if (s != 0 && ey < far)
        u = ey * q30 / (s > 0 ? s : -s);
    if (u < t)
        t = u;
    return t >= far ? 0 : duel_range_value((uint32_t)t, range);
}

/* The robot's frame for its sensors: boundary k (k = 0..4) of the
 * rangefinder sectors as Q30 vectors, and its heading's cos and sin. */
typedef struct duel_frame {
    int64_t bx[5], by[5];
    int32_t c, s;
} duel_frame;

static inline void duel_frame_of(const duel_robot *me, duel_frame *f)
{
    int k;
    duel_cossin_q30(me->heading, &f->c, &f->s);
    /* boundaries k and 4-k are the heading rotated by +-(2k+1) 36 degrees:
     * the same four products serve both; boundary 2 is -heading exactly */
    for (k = 0; k < 2; k++) {
        int64_t cc = (int64_t)f->c * duel_bcos[k], ss = (int64_t)f->s * duel_bsin[k];
        int64_t cs = (int64_t)f->c * duel_bsin[k], sc = (int64_t)f->s * duel_bcos[k];
        f->bx[k] = duel_round_shift(cc - ss, 30);
        f->by[k] = duel_round_shift(cs + sc, 30);
        f->bx[4 - k] = duel_round_shift(cc + ss, 30);
        f->by[4 - k] = duel_round_shift(sc - cs, 30);
    }
    f->bx[2] = -f->c;
    f->by[2] = -f->s;
}

/* 11: clamp((E_self - E_other) / scale, -1, 1); scale * 65536 / 32768 = 2
 * scale units per Q15 step (world v1: 400); symmetric rounding and a
 * symmetric clamp, so the two robots read exact opposites. The energies'
 * bounds (duel_rules_check) keep |diff| + scale below 2^31: a 32-bit
 * division. */
static inline nrt_q15 duel_energy_reading(int32_t self, int32_t other, uint32_t scale)
{
    int32_t diff = self - other;
    uint32_t q = ((uint32_t)(diff >= 0 ? diff : -diff) + scale) / (2u * scale);
    int32_t v = q > 32767u ? 32767 : (int32_t)q;
    return (nrt_q15)(diff >= 0 ? v : -v);
}

/* Inputs from the nearest food per sector (near: squared distance minus one,
 * UINT64_MAX for none, as duel_scan leaves it) and the rest of the state:
 * bias, food 1-5, robot 6-10, energy 11, wall 12. */
static inline void duel_sense_finish(const duel_world *w, int side, const duel_frame *f, const uint64_t near[5],
                                     nrt_q15 in[DUEL_N_INPUTS])
{
    const duel_rules *R = duel_rules_of(w);
    const duel_robot *me = &w->robot[side], *other = &w->robot[side ^ 1];
    int64_t vx = (int64_t)other->x - me->x, vy = (int64_t)other->y - me->y, d2 = vx * vx + vy * vy;
    duel_range food = duel_range_of(R->food_range);
    int k;
    in[0] = NRT_ONE;
    /* food rangefinders 1-5: max(0, 1 - d / range) */
    for (k = 0; k < 5; k++)
        in[1 + k] = near[k] == UINT64_MAX ? 0 : duel_range_reading((int64_t)(near[k] + 1u), food);
    /* robot rangefinders 6-10: one object, one sector */
    in[6] = in[7] = in[8] = in[9] = in[10] = 0;
    if (d2 != 0)
        in[6 + duel_sector(vx, vy, f->bx, f->by)] = duel_range_reading(d2, duel_range_of(R->robot_range));
    in[11] = duel_energy_reading(me->energy, other->energy, R->energy_scale);
    in[12] = duel_wall_reading(me, f->c, f->s, R->wall_range);
}

#endif /* DUEL_SENSORS_H */
