/* duel_replay.c - a game recorded frame by frame (duel_replay.h) from a live game, through duel_play's trace callback. */
#include <assert.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_replay.h"

void duel_replay_init(duel_replay *r)
{
    memset(r, 0, sizeof *r);
    r->food_config = DUEL_TRAINING;
    r->rules = *duel_rules_v1();
    r->step[0] = r->step[1] = -2; /* not recorded */
}

void duel_replay_free(duel_replay *r)
{
    free(r->frames);
    duel_replay_init(r);
}

/* Room for one more frame. 0 or -ENOMEM. */
static int duel_replay_grow(duel_replay *r)
{
    duel_frame *f;
    size_t cap;
    if (r->n < r->cap)
        return 0;
    cap = r->cap ? 2 * r->cap : 256;
    if (cap > (size_t)-1 / sizeof *f)
        return -ENOMEM;
    f = (duel_frame *)realloc(r->frames, cap * sizeof *f);
    if (f == NULL)
        return -ENOMEM;
    r->frames = f;
    r->cap = cap;
    return 0;
}

int duel_replay_push(duel_replay *r, const duel_frame *f)
{
    int err = duel_replay_grow(r);
    if (err)
        return err;
    r->frames[r->n++] = *f;
    return 0;
}

/* The trace callback's state: where frames go, and the first error (the
 * game cannot be stopped from the callback, so later frames are dropped). */
typedef struct duel_replay_rec {
    duel_replay *r;
    int err;
} duel_replay_rec;

static void duel_replay_trace(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                              const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    duel_replay_rec *rec = (duel_replay_rec *)ud;
    duel_frame *f;
    if (rec->err)
        return;
    rec->err = duel_replay_grow(rec->r);
    if (rec->err)
        return;
    f = &rec->r->frames[rec->r->n++];
    f->t = w->t;
    f->w = *w;
    memcpy(f->in, in, sizeof f->in);
    memcpy(f->out, out, sizeof f->out);
    f->ev = *ev;
}

int duel_replay_from_game(duel_replay *r, duel_controller *west, duel_controller *east, int food_config)
{
    return duel_replay_from_game_rules(r, NULL, west, east, food_config);
}

int duel_replay_from_game_rules(duel_replay *r, const duel_rules *rules, duel_controller *west, duel_controller *east,
                                int food_config)
{
    duel_replay_rec rec;
    duel_result res;
    duel_frame *last, *fin;
    int err;

    r->n = 0;
    r->food_config = food_config;
    r->rules = rules != NULL ? *rules : *duel_rules_v1();
    rec.r = r;
    rec.err = 0;
    err = duel_play_rules(&r->rules, west, east, food_config, &res, duel_replay_trace, &rec);
    if (!err)
        err = rec.err;
    if (!err)
        err = duel_replay_grow(r);
    if (err) {
        r->n = 0;
        return err;
    }
    /* The trace shows each state before its move; the final state is the
     * last one stepped with its outputs (duel_world_step is a pure function
     * of the state and the outputs, so this is the game's own final state). */
    assert(r->n == res.steps && r->n > 0);
    last = &r->frames[r->n - 1];
    fin = &r->frames[r->n];
    memset(fin, 0, sizeof *fin);
    fin->w = last->w;
    duel_world_step(&fin->w, last->out[DUEL_WEST], last->out[DUEL_EAST], NULL);
    fin->t = fin->w.t;
    fin->ev.outcome = fin->w.outcome;
    assert(fin->t == res.steps && fin->w.outcome == res.outcome && fin->w.robot[0].energy == res.energy[0] &&
           fin->w.robot[1].energy == res.energy[1]);
    r->n++;
    return 0;
}
