/* duel_sense.c - the 13 sensors: rangefinders by cross products (no trigonometry per object), energy, wall. */
#include "duel_sensors.h"

/* Nearest squared distance per sector, minus one, into near[5] (UINT64_MAX:
 * none) over the items whose mask bit is set. Minus one, as unsigned: an
 * object at the robot's very centre (d2 = 0) has no bearing and must give no
 * reading, and 0 - 1 wraps to the largest value, which never wins (the
 * sector tree classes it as 0, harmlessly). Sector k runs from boundary k-1
 * (inclusive: a bearing on a boundary belongs to the sector counter-clockwise
 * of it) to boundary k (exclusive); v is clockwise of boundary k when
 * cross(b_k, v) < 0. Two or three 64-bit cross products per object (Q16.16 x
 * Q30 < 2^57), no trigonometry (duel_sector). The boundaries come widened to
 * 64 bits, the robot's position is read once and only the items still on
 * the board are visited: this loop is the simulator's hot spot. */
static void duel_scan(int32_t rx, int32_t ry, const int32_t *ox, const int32_t *oy, uint32_t mask,
                      const int64_t bx[5], const int64_t by[5], uint64_t near[5])
{
    int k;
    for (k = 0; k < 5; k++)
        near[k] = UINT64_MAX;
    for (; mask != 0; mask &= mask - 1u) {
        unsigned i = duel_lowest_bit(mask);
        int64_t vx = (int64_t)ox[i] - rx, vy = (int64_t)oy[i] - ry;
        uint64_t d2m1 = (uint64_t)(vx * vx + vy * vy) - 1u;
        k = duel_sector(vx, vy, bx, by);
        if (d2m1 < near[k])
            near[k] = d2m1;
    }
}

void duel_sense(const duel_world *w, int side, nrt_q15 in[DUEL_N_INPUTS])
{
    const duel_robot *me = &w->robot[side];
    duel_frame f;
    uint64_t near[5];
    duel_frame_of(me, &f);
    duel_scan(me->x, me->y, w->food_x, w->food_y, w->food_mask & ((1u << w->n_food) - 1u), f.bx, f.by, near);
    duel_sense_finish(w, side, &f, near, in);
}
