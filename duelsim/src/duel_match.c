/* duel_match.c - one game between two controllers, and the 288-game comparison of spec v1. */
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

int duel_play(duel_controller *west, duel_controller *east, int food_config, duel_result *res, duel_trace_fn trace,
              void *ud)
{
    duel_world w;
    nrt_q15 in_buf[2][DUEL_N_INPUTS], out_buf[2][DUEL_N_OUTPUTS], *in[2];
    const nrt_q15 *out[2];
    int food_near;
#if DUEL_HAVE_AVX2
    duel_lanes lanes;
    nrt_dense *dense[2] = {NULL, NULL};
    nrt_dense dense_of[2];
    int pair;
#endif
    int err, side;

    if (res == NULL || west == NULL || east == NULL)
        return DUEL_E_ARG;
    /* one network state cannot drive two robots: load the blob twice */
    if (west->net != NULL && west->net == east->net)
        return DUEL_E_ARG;
    if (!duel_controller_ok(west) || !duel_controller_ok(east))
        return DUEL_E_NET;
    err = duel_world_init(&w, food_config);
    if (err)
        return err;
    if (west->net != NULL)
        nrt_reset(west->net);
    if (east->net != NULL)
        nrt_reset(east->net);
#if DUEL_HAVE_AVX2
    /* the same steps, faster for small networks (tests/duelsim/test_golden.c) */
    duel_lanes_init(&lanes);
    if (lanes.level != DUEL_SIMD_NONE) {
        if (west->net != NULL && nrt_dense_make(&dense_of[DUEL_WEST], west->net) == NRT_OK)
            dense[DUEL_WEST] = &dense_of[DUEL_WEST];
        if (east->net != NULL && nrt_dense_make(&dense_of[DUEL_EAST], east->net) == NRT_OK)
            dense[DUEL_EAST] = &dense_of[DUEL_EAST];
    }
    /* two small networks step together (nrt_dense_step2) */
    pair = dense[DUEL_WEST] != NULL && dense[DUEL_EAST] != NULL && dense[DUEL_WEST]->rows <= NRT_DENSE_FEW &&
           dense[DUEL_EAST]->rows <= NRT_DENSE_FEW;
#endif
    while (w.outcome == DUEL_RUNNING) {
        /* 1. both sense the state at t; 2. both networks propagate once */
        /* a network's sensors go straight into its input slots */
#if DUEL_HAVE_AVX2
        /* (a dense form holds its network's state) */
        for (side = 0; side < 2; side++) {
            const duel_controller *c = side == DUEL_WEST ? west : east;
            in[side] = dense[side] != NULL ? nrt_dense_inputs(dense[side])
                                           : (c->net != NULL ? nrt_inputs(c->net) : in_buf[side]);
        }
        if (duel_sense_both(&w, &lanes, in[DUEL_WEST], in[DUEL_EAST]) != 0)
            for (side = 0; side < 2; side++)
                duel_sense(&w, side, in[side]);
        if (pair)
            nrt_dense_step2(dense[DUEL_WEST], dense[DUEL_EAST]);
        for (side = 0; side < 2; side++)
            if (dense[side] != NULL) {
                if (!pair)
                    nrt_dense_step(dense[side]);
                out[side] = nrt_dense_outputs(dense[side]);
            } else {
                out[side] = duel_act(side == DUEL_WEST ? west : east, in[side], out_buf[side]);
            }
#else
        in[DUEL_WEST] = west->net != NULL ? nrt_inputs(west->net) : in_buf[DUEL_WEST];
        in[DUEL_EAST] = east->net != NULL ? nrt_inputs(east->net) : in_buf[DUEL_EAST];
        duel_sense(&w, DUEL_WEST, in[DUEL_WEST]);
        duel_sense(&w, DUEL_EAST, in[DUEL_EAST]);
        out[DUEL_WEST] = duel_act(west, in[DUEL_WEST], out_buf[DUEL_WEST]);
        out[DUEL_EAST] = duel_act(east, in[DUEL_EAST], out_buf[DUEL_EAST]);
#endif
        food_near = duel_food_near(in[DUEL_WEST]) || duel_food_near(in[DUEL_EAST]);
        if (trace != NULL)
            duel_traced_step(&w, in, out, food_near, trace, ud);
        else
            duel_world_step_food(&w, out[DUEL_WEST], out[DUEL_EAST], NULL, food_near);
    }
#if DUEL_HAVE_AVX2
    /* the networks end as nrt_step would have left them */
    if (dense[DUEL_WEST] != NULL)
        nrt_dense_save(dense[DUEL_WEST], west->net);
    if (dense[DUEL_EAST] != NULL)
        nrt_dense_save(dense[DUEL_EAST], east->net);
#endif
    res->outcome = w.outcome;
    res->steps = w.t;
    for (side = 0; side < 2; side++) {
        res->energy[side] = w.robot[side].energy;
        res->eaten[side] = w.robot[side].eaten;
    }
    return DUEL_OK;
}

int duel_compare(duel_controller *a, duel_controller *b, duel_tally *tally)
{
    int k, side, err;
    duel_result r;
    if (tally == NULL)
        return DUEL_E_ARG;
    tally->wins_a = tally->wins_b = tally->draws = tally->timeouts = 0;
    for (k = 0; k < DUEL_CONFIGS; k++)
        for (side = 0; side < 2; side++) {
            /* side 0: a starts west; side 1: b starts west */
            err = side == 0 ? duel_play(a, b, k, &r, NULL, NULL) : duel_play(b, a, k, &r, NULL, NULL);
            if (err)
                return err;
            if (r.outcome == DUEL_DRAW)
                tally->draws++;
            else if (r.outcome == DUEL_TIMEOUT)
                tally->timeouts++;
            else if ((r.outcome == DUEL_WEST_WINS) == (side == 0))
                tally->wins_a++;
            else
                tally->wins_b++;
        }
    return DUEL_OK;
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
