/* duel_match.c - one game between two controllers under a world's rules, and the 288-game comparison. */
#include <string.h>

#include "duel_internal.h"
#include "nrt_dense.h"

/* The controller's outputs for in: a network's in place (no copy), a
 * builtin's in buf. */
static const nrt_q15 *duel_act(duel_controller *c, const nrt_q15 in[DUEL_N_INPUTS], nrt_q15 buf[DUEL_N_OUTPUTS])
{
    if (c->net != NULL) {
        nrt_step(c->net, in, NULL);
        return nrt_outputs(c->net);
    }
    duel_builtin_act(c->builtin, in, buf);
    return buf;
}

static int duel_controller_ok(const duel_controller *c)
{
    if (c == NULL)
        return 0;
    if (c->net != NULL)
        return c->net->n_inputs == DUEL_N_INPUTS && c->net->n_outputs == DUEL_N_OUTPUTS;
    return c->builtin >= 0 && c->builtin < DUEL_N_BUILTINS;
}

/* One step of a traced game: the callback gets the state before the move
 * and plain copies of the inputs and outputs (a network's are still in its
 * activation buffers). Apart from duel_play, so that the untraced games,
 * and the firmware, do not carry the copies on their stack (and kept out
 * of line for that: inlined, its locals would join duel_play's frame). */
DUEL_NOINLINE static void duel_traced_step(duel_world *w, nrt_q15 *const in[2], const nrt_q15 *const out[2],
                                           int food_near, duel_trace_fn trace, void *ud)
{
    duel_world before = *w;
    nrt_q15 in_copy[2][DUEL_N_INPUTS], out_copy[2][DUEL_N_OUTPUTS];
    duel_event ev;
    int side;
    for (side = 0; side < 2; side++) {
        memcpy(in_copy[side], in[side], sizeof in_copy[side]);
        memcpy(out_copy[side], out[side], sizeof out_copy[side]);
    }
    duel_world_step_food(w, out[DUEL_WEST], out[DUEL_EAST], &ev, food_near);
    trace(ud, &before, (const nrt_q15(*)[DUEL_N_INPUTS])in_copy, (const nrt_q15(*)[DUEL_N_OUTPUTS])out_copy, &ev);
}

#if DUEL_HAVE_AVX2
/* One game in play on an x86-64 host: its world, its controllers' inputs
 * and outputs, and the dense forms of its networks, which then hold their
 * state. duel_play steps one; duel_play2 two, phase by phase. */
typedef struct duel_game {
    duel_world w;
    duel_controller *c[2];
    nrt_q15 in_buf[2][DUEL_N_INPUTS], out_buf[2][DUEL_N_OUTPUTS], *in[2];
    const nrt_q15 *out[2];
    int food_near;
    nrt_q15 near_limit; /* duel_food_near_limit of the game's rules */
    duel_lanes lanes;
    nrt_dense *dense[2];
    int pair; /* both networks small: stepped together (nrt_dense_step2) */
    nrt_dense dense_of[2];
} duel_game;

/* The game's start: world, networks reset, their dense forms made */
static int duel_game_begin(duel_game *g, const duel_rules *rules, duel_controller *west, duel_controller *east,
                           int food_config)
{
    int err, side;
    if (west == NULL || east == NULL)
        return DUEL_E_ARG;
    /* one network state cannot drive two robots: load the blob twice */
    if (west->net != NULL && west->net == east->net)
        return DUEL_E_ARG;
    if (!duel_controller_ok(west) || !duel_controller_ok(east))
        return DUEL_E_NET;
    err = duel_world_start(&g->w, rules, food_config);
    if (err)
        return err;
    g->near_limit = duel_food_near_limit(rules);
    g->c[DUEL_WEST] = west;
    g->c[DUEL_EAST] = east;
    for (side = 0; side < 2; side++)
        if (g->c[side]->net != NULL)
            nrt_reset(g->c[side]->net);
    /* the same steps, faster for small networks (tests/duelsim/test_golden.c) */
    duel_lanes_init(&g->lanes, rules);
    for (side = 0; side < 2; side++) {
        g->dense[side] = NULL;
        if (g->lanes.level != DUEL_SIMD_NONE && g->c[side]->net != NULL &&
            nrt_dense_make(&g->dense_of[side], g->c[side]->net) == NRT_OK)
            g->dense[side] = &g->dense_of[side];
    }
    g->pair = g->dense[DUEL_WEST] != NULL && g->dense[DUEL_EAST] != NULL &&
              g->dense[DUEL_WEST]->rows <= NRT_DENSE_FEW && g->dense[DUEL_EAST]->rows <= NRT_DENSE_FEW;
    return DUEL_OK;
}

/* 1. both robots sense the state at t; a network's sensors go straight
 * into its input slots (a dense form's, when it has one) */
static void duel_game_sense(duel_game *g)
{
    int side;
    for (side = 0; side < 2; side++) {
        const duel_controller *c = g->c[side];
        if (g->dense[side] != NULL) {
            g->in[side] = nrt_dense_inputs(g->dense[side]);
            continue;
        }
        g->in[side] = c->net != NULL ? nrt_inputs(c->net) : g->in_buf[side];
    }
    if (duel_sense_both(&g->w, &g->lanes, g->in[DUEL_WEST], g->in[DUEL_EAST]) == 0)
        return;
    for (side = 0; side < 2; side++)
        duel_sense(&g->w, side, g->in[side]);
}

/* 2. both networks propagate once (or the builtins act) */
static void duel_game_think(duel_game *g)
{
    int side;
    if (g->pair)
        nrt_dense_step2(g->dense[DUEL_WEST], g->dense[DUEL_EAST]);
    for (side = 0; side < 2; side++) {
        if (g->dense[side] != NULL) {
            if (!g->pair)
                nrt_dense_step(g->dense[side]);
            g->out[side] = nrt_dense_outputs(g->dense[side]);
            continue;
        }
        g->out[side] = duel_act(g->c[side], g->in[side], g->out_buf[side]);
    }
    g->food_near = duel_food_near(g->in[DUEL_WEST], g->near_limit) || duel_food_near(g->in[DUEL_EAST], g->near_limit);
}

/* 3-6. the move and the rules (duel_world_step) */
static void duel_game_move(duel_game *g, duel_trace_fn trace, void *ud)
{
    if (trace != NULL)
        duel_traced_step(&g->w, g->in, g->out, g->food_near, trace, ud);
    else
        duel_world_step_food(&g->w, g->out[DUEL_WEST], g->out[DUEL_EAST], NULL, g->food_near);
}

/* The game's result; the networks end as nrt_step would have left them */
static void duel_game_end(duel_game *g, duel_result *res)
{
    int side;
    for (side = 0; side < 2; side++)
        if (g->dense[side] != NULL)
            nrt_dense_save(g->dense[side], g->c[side]->net);
    res->outcome = g->w.outcome;
    res->steps = g->w.t;
    for (side = 0; side < 2; side++) {
        res->energy[side] = g->w.robot[side].energy;
        res->eaten[side] = g->w.robot[side].eaten;
    }
}

static int duel_play_in(const duel_rules *rules, duel_controller *west, duel_controller *east, int food_config,
                        duel_result *res, duel_trace_fn trace, void *ud)
{
    duel_game g;
    int err;
    if (res == NULL)
        return DUEL_E_ARG;
    err = duel_game_begin(&g, rules, west, east, food_config);
    if (err)
        return err;
    while (g.w.outcome == DUEL_RUNNING) {
        duel_game_sense(&g);
        duel_game_think(&g);
        duel_game_move(&g, trace, ud);
    }
    duel_game_end(&g, res);
    return DUEL_OK;
}

static void duel_game_run(duel_game *g)
{
    while (g->w.outcome == DUEL_RUNNING) {
        duel_game_sense(g);
        duel_game_think(g);
        duel_game_move(g, NULL, NULL);
    }
}

/* Whether g steps network n (one the other game has too) in a dense form
 * of its own, with its own copy of the state */
static int duel_game_own_state(const duel_game *g, const nrt_net *n)
{
    int side;
    for (side = 0; side < 2; side++)
        if (g->c[side]->net == n)
            return g->dense[side] != NULL;
    return 1; /* not in this game */
}

/* Whether the two games can be played at the same time: each network they
 * share is stepped through a state of its own in each (a dense form made
 * from the reset network) */
static int duel_games_apart(const duel_game g[2])
{
    int side;
    for (side = 0; side < 2; side++) {
        const nrt_net *n = g[1].c[side]->net;
        if (n != NULL && (n == g[0].c[DUEL_WEST]->net || n == g[0].c[DUEL_EAST]->net) &&
            (!duel_game_own_state(&g[0], n) || !duel_game_own_state(&g[1], n)))
            return 0;
    }
    return 1;
}

static int duel_play2_in(const duel_rules *rules, duel_controller *const west[2], duel_controller *const east[2],
                         const int food_config[2], duel_result res[2])
{
    duel_game g[2];
    int err, k;
    if (west == NULL || east == NULL || food_config == NULL || res == NULL)
        return DUEL_E_ARG;
    err = duel_game_begin(&g[0], rules, west[0], east[0], food_config[0]);
    if (err == DUEL_OK)
        err = duel_game_begin(&g[1], rules, west[1], east[1], food_config[1]);
    if (err)
        return err;
    if (!duel_games_apart(g)) {
        /* one after the other, as two calls of duel_play: game 1 starts
         * again from the networks as game 0 leaves them */
        duel_game_run(&g[0]);
        duel_game_end(&g[0], &res[0]);
        err = duel_game_begin(&g[1], rules, west[1], east[1], food_config[1]);
        if (err)
            return err;
        duel_game_run(&g[1]);
        duel_game_end(&g[1], &res[1]);
        return DUEL_OK;
    }
    /* Phase by phase: each game's step is one chain of dependent
     * instructions (sense, propagate, move), and the processor overlaps
     * the two games' chains. Either game's results are its own: nothing
     * passes between them. */
    while (g[0].w.outcome == DUEL_RUNNING && g[1].w.outcome == DUEL_RUNNING) {
        duel_game_sense(&g[0]);
        duel_game_sense(&g[1]);
        duel_game_think(&g[0]);
        duel_game_think(&g[1]);
        duel_game_move(&g[0], NULL, NULL);
        duel_game_move(&g[1], NULL, NULL);
    }
    /* the longer game alone; the networks' states saved in the order of
     * two duel_play calls */
    for (k = 0; k < 2; k++) {
        duel_game_run(&g[k]);
        duel_game_end(&g[k], &res[k]);
    }
    return DUEL_OK;
}

#else /* no dense forms (the firmware, any host but x86-64): the loop as it was */

static int duel_play_in(const duel_rules *rules, duel_controller *west, duel_controller *east, int food_config,
                        duel_result *res, duel_trace_fn trace, void *ud)
{
    duel_world w;
    nrt_q15 in_buf[2][DUEL_N_INPUTS], out_buf[2][DUEL_N_OUTPUTS], *in[2];
    const nrt_q15 *out[2];
    int food_near;
    nrt_q15 near_limit = duel_food_near_limit(rules);
    int err, side;

    if (res == NULL || west == NULL || east == NULL)
        return DUEL_E_ARG;
    /* one network state cannot drive two robots: load the blob twice */
    if (west->net != NULL && west->net == east->net)
        return DUEL_E_ARG;
    if (!duel_controller_ok(west) || !duel_controller_ok(east))
        return DUEL_E_NET;
    err = duel_world_start(&w, rules, food_config);
    if (err)
        return err;
    if (west->net != NULL)
        nrt_reset(west->net);
    if (east->net != NULL)
        nrt_reset(east->net);
    while (w.outcome == DUEL_RUNNING) {
        /* 1. both sense the state at t; 2. both networks propagate once;
         * a network's sensors go straight into its input slots */
        in[DUEL_WEST] = west->net != NULL ? nrt_inputs(west->net) : in_buf[DUEL_WEST];
        in[DUEL_EAST] = east->net != NULL ? nrt_inputs(east->net) : in_buf[DUEL_EAST];
        duel_sense(&w, DUEL_WEST, in[DUEL_WEST]);
        duel_sense(&w, DUEL_EAST, in[DUEL_EAST]);
        out[DUEL_WEST] = duel_act(west, in[DUEL_WEST], out_buf[DUEL_WEST]);
        out[DUEL_EAST] = duel_act(east, in[DUEL_EAST], out_buf[DUEL_EAST]);
        food_near = duel_food_near(in[DUEL_WEST], near_limit) || duel_food_near(in[DUEL_EAST], near_limit);
        if (trace != NULL)
            duel_traced_step(&w, in, out, food_near, trace, ud);
        else
            duel_world_step_food(&w, out[DUEL_WEST], out[DUEL_EAST], NULL, food_near);
    }
    res->outcome = w.outcome;
    res->steps = w.t;
    for (side = 0; side < 2; side++) {
        res->energy[side] = w.robot[side].energy;
        res->eaten[side] = w.robot[side].eaten;
    }
    return DUEL_OK;
}

/* the networks the two games share have one state: one game after the other */
static int duel_play2_in(const duel_rules *rules, duel_controller *const west[2], duel_controller *const east[2],
                         const int food_config[2], duel_result res[2])
{
    int err, k;
    if (west == NULL || east == NULL || food_config == NULL || res == NULL)
        return DUEL_E_ARG;
    for (k = 0; k < 2; k++) {
        err = duel_play_in(rules, west[k], east[k], food_config[k], &res[k], NULL, NULL);
        if (err)
            return err;
    }
    return DUEL_OK;
}

#endif

/* The public games: v1 as it always was (no check: its rules are known
 * good), other rules checked once per call */
int duel_play(duel_controller *west, duel_controller *east, int food_config, duel_result *res, duel_trace_fn trace,
              void *ud)
{
    return duel_play_in(&duel_v1_rules, west, east, food_config, res, trace, ud);
}

int duel_play_rules(const duel_rules *rules, duel_controller *west, duel_controller *east, int food_config,
                    duel_result *res, duel_trace_fn trace, void *ud)
{
    if (rules == NULL)
        rules = &duel_v1_rules;
    else if (duel_rules_check(rules, NULL, NULL) != DUEL_OK)
        return DUEL_E_RULES;
    return duel_play_in(rules, west, east, food_config, res, trace, ud);
}

int duel_play2(duel_controller *const west[2], duel_controller *const east[2], const int food_config[2],
               duel_result res[2])
{
    return duel_play2_in(&duel_v1_rules, west, east, food_config, res);
}

int duel_play2_rules(const duel_rules *rules, duel_controller *const west[2], duel_controller *const east[2],
                     const int food_config[2], duel_result res[2])
{
    if (rules == NULL)
        rules = &duel_v1_rules;
    else if (duel_rules_check(rules, NULL, NULL) != DUEL_OK)
        return DUEL_E_RULES;
    return duel_play2_in(rules, west, east, food_config, res);
}

/* A game of the comparison in the tally: side 0, a started west */
static void duel_tally_add(duel_tally *tally, int outcome, int side)
{
    if (outcome == DUEL_DRAW)
        tally->draws++;
    else if (outcome == DUEL_TIMEOUT)
        tally->timeouts++;
    else if ((outcome == DUEL_WEST_WINS) == (side == 0))
        tally->wins_a++;
    else
        tally->wins_b++;
}

static int duel_compare_in(const duel_rules *rules, duel_controller *a, duel_controller *b, duel_tally *tally)
{
    int k, side, err;
#if DUEL_HAVE_AVX2
    duel_controller *west[2], *east[2];
    duel_result r[2];
    int config[2];
    /* side 0: a starts west; side 1: b starts west; both sides of a
     * configuration at once (elsewhere, where duel_play2 would be two
     * calls of duel_play anyway, the loop as it was: the firmware's code
     * stays as small) */
    west[0] = east[1] = a;
    east[0] = west[1] = b;
#else
    duel_result r;
#endif
    if (tally == NULL)
        return DUEL_E_ARG;
    tally->wins_a = tally->wins_b = tally->draws = tally->timeouts = 0;
    for (k = 0; k < DUEL_CONFIGS; k++) {
#if DUEL_HAVE_AVX2
        config[0] = config[1] = k;
        err = duel_play2_in(rules, west, east, config, r);
        if (err)
            return err;
        for (side = 0; side < 2; side++)
            duel_tally_add(tally, r[side].outcome, side);
#else
        for (side = 0; side < 2; side++) {
            /* side 0: a starts west; side 1: b starts west */
            err = side == 0 ? duel_play_in(rules, a, b, k, &r, NULL, NULL) : duel_play_in(rules, b, a, k, &r, NULL, NULL);
            if (err)
                return err;
            duel_tally_add(tally, r.outcome, side);
        }
#endif
    }
    return DUEL_OK;
}

int duel_compare(duel_controller *a, duel_controller *b, duel_tally *tally)
{
    return duel_compare_in(&duel_v1_rules, a, b, tally);
}

int duel_compare_rules(const duel_rules *rules, duel_controller *a, duel_controller *b, duel_tally *tally)
{
    if (rules == NULL)
        rules = &duel_v1_rules;
    else if (duel_rules_check(rules, NULL, NULL) != DUEL_OK)
        return DUEL_E_RULES;
    return duel_compare_in(rules, a, b, tally);
}

const char *duel_outcome_text(int outcome)
{
    switch (outcome) {
    case DUEL_WEST_WINS: return "west wins (collision, more energy)";
    case DUEL_EAST_WINS: return "east wins (collision, more energy)";
    case DUEL_DRAW: return "draw (collision at equal energy)";
    case DUEL_TIMEOUT: return "timeout (no collision)";
    default: return "unfinished";
    }
}
