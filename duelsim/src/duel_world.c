/* duel_world.c - the duel world's state and its step: food layouts, motion, energy, eating, collision, timeout. */
#include <string.h>

#include "duel_internal.h"

/* The start of a game under rules already checked (duel_rules_check): the
 * robots at their starts, the training items, and on a comparison
 * configuration K two more: item 9 at candidate K div 12, item 10 at the
 * mirror of candidate K mod 12 (docs/duel-world.md, "Food"). */
int duel_world_start(duel_world *w, const duel_rules *r, int food_config)
{
    uint32_t i;
    int side;
    if (w == NULL || food_config < DUEL_TRAINING || food_config >= DUEL_CONFIGS)
        return DUEL_E_ARG;
    memset(w, 0, sizeof *w);
    for (side = 0; side < 2; side++) {
        w->robot[side].x = r->start_x[side];
        w->robot[side].y = r->start_y[side];
        w->robot[side].heading = r->start_heading[side];
        w->robot[side].energy = r->start_energy;
    }
    for (i = 0; i < r->n_train; i++) {
        w->food_x[i] = r->train_x[i];
        w->food_y[i] = r->train_y[i];
    }
    w->n_food = (uint8_t)r->n_train;
    if (food_config >= 0) {
        int jw = food_config / DUEL_CANDIDATES, je = food_config % DUEL_CANDIDATES;
        w->food_x[w->n_food] = r->cand_x[jw];
        w->food_y[w->n_food] = r->cand_y[jw];
        w->food_x[w->n_food + 1] = DUEL_FIX(DUEL_BOARD) - r->cand_x[je];
        w->food_y[w->n_food + 1] = r->cand_y[je];
        w->n_food += 2;
    }
    w->food_mask = (1u << w->n_food) - 1u;
    w->outcome = DUEL_RUNNING;
    w->rules = r;
    return DUEL_OK;
}

int duel_world_init(duel_world *w, int food_config)
{
    return duel_world_start(w, &duel_v1_rules, food_config);
}

int duel_world_init_rules(duel_world *w, const duel_rules *rules, int food_config)
{
    if (rules == NULL)
        return duel_world_init(w, food_config);
    if (duel_rules_check(rules, NULL, NULL) != DUEL_OK)
        return DUEL_E_RULES;
    return duel_world_start(w, rules, food_config);
}

/* Binary-angle units of half the turn for an output difference d = l - r
 * (Q15): theta / 2 = 0.12 d / 32768 rad, times 2^32 / (2 pi) units per
 * radian = 2503.2908 d; the factor in Q16 (docs/duelsim.md). */
#define DUEL_HALF_TURN_Q16 164055666LL

/* a coordinate kept in [lo, hi] = [radius, 600 - radius]: the robot slides
 * along a wall (the bounds 64-bit, computed once a step) */
static int32_t duel_clamp_coord(int64_t v, int64_t lo, int64_t hi)
{
    return (int32_t)(v < lo ? lo : (v > hi ? hi : v));
}

static nrt_q15 duel_clamp_out(nrt_q15 v)
{
    return v < 0 ? 0 : v;
}

/* Appendix B: half turn, forward, half turn; energy |theta| + 1.33 f. */
static void duel_move(duel_robot *r, const nrt_q15 out[DUEL_N_OUTPUTS], int64_t lo, int64_t hi)
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
    r->x = duel_clamp_coord((int64_t)r->x + duel_round_shift((int64_t)dist * c, 30), lo, hi);
    r->y = duel_clamp_coord((int64_t)r->y + duel_round_shift((int64_t)dist * s, 30), lo, hi);
    r->heading += (uint32_t)half;
    r->energy -= turn_cost + dist;
}

/* within the eating distance on both axes (necessary, not sufficient): one
 * unsigned comparison per axis, |d| < E as (uint32_t)(d + E - 1) < 2E - 1 */
static int duel_near(const duel_robot *r, int32_t x, int32_t y, uint32_t e)
{
    return (uint32_t)r->x - (uint32_t)x + e - 1u < 2u * e - 1u && (uint32_t)r->y - (uint32_t)y + e - 1u < 2u * e - 1u;
}

/* Both robots within the eating distance of one item, at squared distances
 * da and db (Q32): whether they share it. An exact tie always does; with
 * share_dist m > 0 (Q16.16), also when the farther distance is at most the
 * nearer plus m: db <= da + 2 m sqrt(da) + m^2 for da <= db, the root
 * rounded down (docs/duel-world.md). Eating is rare: the root costs nothing
 * that matters. */
static int duel_shared(int64_t da, int64_t db, int32_t m)
{
    int64_t lo = da < db ? da : db, hi = da < db ? db : da;
    if (lo == hi)
        return 1;
    if (m == 0)
        return 0;
    return hi <= lo + 2 * (int64_t)m * duel_isqrt64((uint64_t)lo) + (int64_t)m * m;
}

int duel_world_step(duel_world *w, const nrt_q15 out_west[DUEL_N_OUTPUTS], const nrt_q15 out_east[DUEL_N_OUTPUTS],
                    duel_event *ev)
{
    if (w != NULL && w->rules == NULL)
        w->rules = &duel_v1_rules; /* a world made by hand: what NULL means */
    return duel_world_step_food(w, out_west, out_east, ev, 1);
}

int duel_world_step_food(duel_world *w, const nrt_q15 out_west[DUEL_N_OUTPUTS],
                         const nrt_q15 out_east[DUEL_N_OUTPUTS], duel_event *ev, int food_near)
{
    static const int64_t hit2 = (int64_t)DUEL_COLLIDE_DIST * DUEL_COLLIDE_DIST << 32;
    const duel_rules *R = w->rules;
    duel_event local;
    duel_robot *a = &w->robot[DUEL_WEST], *b = &w->robot[DUEL_EAST];
    int64_t lo, hi;
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
    lo = R->radius;
    hi = (int64_t)DUEL_FIX(DUEL_BOARD) - R->radius;
    duel_move(a, out_west, lo, hi);
    duel_move(b, out_east, lo, hi);
    /* 4. food: below 15 eats; both: the nearer; an exact tie shares */
    for (left = food_near ? w->food_mask & ((1u << w->n_food) - 1u) : 0; left != 0; left &= left - 1u) {
        int64_t da, db;
        int ea, eb;
        i = duel_lowest_bit(left);
        /* most items are far from both robots: a box test spares the products */
        if (!duel_near(a, w->food_x[i], w->food_y[i], (uint32_t)R->eat_dist) &&
            !duel_near(b, w->food_x[i], w->food_y[i], (uint32_t)R->eat_dist))
            continue;
        da = duel_dist2(a->x, a->y, w->food_x[i], w->food_y[i]);
        db = duel_dist2(b->x, b->y, w->food_x[i], w->food_y[i]);
        ea = da < (int64_t)R->eat_dist * R->eat_dist;
        eb = db < (int64_t)R->eat_dist * R->eat_dist;
        if (ea && eb && !duel_shared(da, db, R->share_dist)) {
            ea = da < db;
            eb = db < da;
        }
        if (!ea && !eb)
            continue;
        w->food_mask &= ~(1u << i);
        if (ea && eb) {
            a->energy += R->food_energy / 2;
            b->energy += R->food_energy / 2;
        } else {
            (ea ? a : b)->energy += R->food_energy;
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
