/* duel_world.c - the duel world's state and its step: food layouts, motion, energy, eating, collision, timeout. */
#include <string.h>

#include "duel_internal.h"

/* Spec v1, "Food": training item i at (200 + 100 (i mod 3), 200 + 100 (i div 3));
 * candidate position j = (X[j div 4], Y[j mod 4]). */
static const int16_t duel_cand_x[3] = {60, 140, 220};
static const int16_t duel_cand_y[4] = {75, 225, 375, 525};

int duel_world_init(duel_world *w, int food_config)
{
    int i;
    if (w == NULL || food_config < DUEL_TRAINING || food_config >= DUEL_CONFIGS)
        return DUEL_E_ARG;
    memset(w, 0, sizeof *w);
    w->robot[DUEL_WEST].x = DUEL_FIX(100);
    w->robot[DUEL_WEST].y = DUEL_FIX(300);
    w->robot[DUEL_WEST].heading = DUEL_HALF_TURN; /* facing the west wall */
    w->robot[DUEL_EAST].x = DUEL_FIX(500);
    w->robot[DUEL_EAST].y = DUEL_FIX(300);
    w->robot[DUEL_EAST].heading = 0;
    for (i = 0; i < 2; i++)
        w->robot[i].energy = DUEL_FIX(DUEL_START_ENERGY);
    for (i = 0; i < DUEL_TRAIN_FOOD; i++) {
        w->food_x[i] = DUEL_FIX(200 + 100 * (i % 3));
        w->food_y[i] = DUEL_FIX(200 + 100 * (i / 3));
    }
    w->n_food = DUEL_TRAIN_FOOD;
    if (food_config >= 0) {
        int jw = food_config / 12, je = food_config % 12;
        w->food_x[9] = DUEL_FIX(duel_cand_x[jw / 4]);
        w->food_y[9] = DUEL_FIX(duel_cand_y[jw % 4]);
        w->food_x[10] = DUEL_FIX(DUEL_BOARD - duel_cand_x[je / 4]);
        w->food_y[10] = DUEL_FIX(duel_cand_y[je % 4]);
        w->n_food = DUEL_MAX_FOOD;
    }
    w->food_mask = (1u << w->n_food) - 1u;
    w->outcome = DUEL_RUNNING;
    return DUEL_OK;
}

/* Binary-angle units of half the turn for an output difference d = l - r
 * (Q15): theta / 2 = 0.12 d / 32768 rad, times 2^32 / (2 pi) units per
 * radian = 2503.2908 d; the factor in Q16 (docs/duelsim.md). */
#define DUEL_HALF_TURN_Q16 164055666LL

static int32_t duel_clamp_coord(int64_t v)
{
    if (v < DUEL_FIX(DUEL_RADIUS))
        return DUEL_FIX(DUEL_RADIUS);
    if (v > DUEL_FIX(DUEL_BOARD - DUEL_RADIUS))
        return DUEL_FIX(DUEL_BOARD - DUEL_RADIUS);
    return (int32_t)v;
}

static nrt_q15 duel_clamp_out(nrt_q15 v)
{
    return v < 0 ? 0 : v;
}

/* Appendix B: half turn, forward, half turn; energy |theta| + 1.33 f. */
static void duel_move(duel_robot *r, const nrt_q15 out[DUEL_N_OUTPUTS])
{
    int32_t l = duel_clamp_out(out[0]), rt = duel_clamp_out(out[1]), f = duel_clamp_out(out[2]);
    int32_t d = l - rt, ad = d < 0 ? -d : d;
    int32_t half = (int32_t)duel_round_shift((int64_t)d * DUEL_HALF_TURN_Q16, 16);
    /* forward 1.33 f = 133 f / 50 in Q16.16 for f in Q15 (2.66 f), rounded */
    int32_t dist = (133 * f + 25) / 50;
    /* |theta| = 0.24 |d| / 32768 rad = 0.48 |d| in Q16.16 = 12 |d| / 25, rounded */
    int32_t turn_cost = (24 * ad + 25) / 50;
    int32_t c, s;
    r->heading += (uint32_t)half;
    duel_cossin_q30(r->heading, &c, &s);
    r->x = duel_clamp_coord((int64_t)r->x + duel_round_shift((int64_t)dist * c, 30));
    r->y = duel_clamp_coord((int64_t)r->y + duel_round_shift((int64_t)dist * s, 30));
    r->heading += (uint32_t)half;
    r->energy -= turn_cost + dist;
}

/* within the eating distance on both axes (necessary, not sufficient): one
 * unsigned comparison per axis, |d| < E as (uint32_t)(d + E - 1) < 2E - 1 */
static int duel_near(const duel_robot *r, int32_t x, int32_t y)
{
    const uint32_t e = (uint32_t)DUEL_FIX(DUEL_EAT_DIST);
    return (uint32_t)r->x - (uint32_t)x + e - 1u < 2u * e - 1u && (uint32_t)r->y - (uint32_t)y + e - 1u < 2u * e - 1u;
}

int duel_world_step(duel_world *w, const nrt_q15 out_west[DUEL_N_OUTPUTS], const nrt_q15 out_east[DUEL_N_OUTPUTS],
                    duel_event *ev)
{
    return duel_world_step_food(w, out_west, out_east, ev, 1);
}

int duel_world_step_food(duel_world *w, const nrt_q15 out_west[DUEL_N_OUTPUTS],
                         const nrt_q15 out_east[DUEL_N_OUTPUTS], duel_event *ev, int food_near)
{
    static const int64_t eat2 = (int64_t)DUEL_EAT_DIST * DUEL_EAT_DIST << 32;
    static const int64_t hit2 = (int64_t)DUEL_COLLIDE_DIST * DUEL_COLLIDE_DIST << 32;
    duel_event local;
    duel_robot *a = &w->robot[DUEL_WEST], *b = &w->robot[DUEL_EAST];
    uint32_t left;
    unsigned i;

    if (ev == NULL)
        ev = &local;
    memset(ev, 0, sizeof *ev);
    if (w->outcome != DUEL_RUNNING) {
        ev->outcome = w->outcome;
        return w->outcome;
    }
    /* 3. both move (neither sees the other's move of this step) and pay */
    duel_move(a, out_west);
    duel_move(b, out_east);
    /* 4. food: below 15 eats; both: the nearer; an exact tie shares */
    for (left = food_near ? w->food_mask & ((1u << w->n_food) - 1u) : 0; left != 0; left &= left - 1u) {
        int64_t da, db;
        int ea, eb;
        i = duel_lowest_bit(left);
        /* most items are far from both robots: a box test spares the products */
        if (!duel_near(a, w->food_x[i], w->food_y[i]) && !duel_near(b, w->food_x[i], w->food_y[i]))
            continue;
        da = duel_dist2(a->x, a->y, w->food_x[i], w->food_y[i]);
        db = duel_dist2(b->x, b->y, w->food_x[i], w->food_y[i]);
        ea = da < eat2;
        eb = db < eat2;
        if (ea && eb) {
            ea = da <= db;
            eb = db <= da;
        }
        if (!ea && !eb)
            continue;
        w->food_mask &= ~(1u << i);
        if (ea && eb) {
            a->energy += DUEL_FIX(DUEL_FOOD_ENERGY / 2);
            b->energy += DUEL_FIX(DUEL_FOOD_ENERGY / 2);
        } else {
            (ea ? a : b)->energy += DUEL_FIX(DUEL_FOOD_ENERGY);
        }
        if (ea) {
            a->eaten++;
            ev->eaten_by[DUEL_WEST] |= 1u << i;
        }
        if (eb) {
            b->eaten++;
            ev->eaten_by[DUEL_EAST] |= 1u << i;
        }
    }
    w->t++;
    /* 5. collision: more energy wins, equal is a draw */
    if (duel_dist2(a->x, a->y, b->x, b->y) < hit2)
        w->outcome = a->energy > b->energy ? DUEL_WEST_WINS : (b->energy > a->energy ? DUEL_EAST_WINS : DUEL_DRAW);
    /* 6. time out */
    else if (w->t >= DUEL_MAX_STEPS)
        w->outcome = DUEL_TIMEOUT;
    ev->outcome = w->outcome;
    return w->outcome;
}
