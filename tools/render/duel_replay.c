/* duel_replay.c - a game recorded frame by frame (duel_replay.h) from a live game, through duel_play's trace callback, with each network's shape and hidden activations (for the web pages). */
#include <assert.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_replay.h"
#include "duel_trace.h"

void duel_replay_init(duel_replay *r)
{
    memset(r, 0, sizeof *r);
    r->food_config = DUEL_TRAINING;
    r->rules = *duel_rules_v1();
    r->step[0] = r->step[1] = -2; /* not recorded */
}

void duel_replay_free(duel_replay *r)
{
    int s;
    free(r->frames);
    for (s = 0; s < 2; s++) {
        free(r->net[s].mem);
        free(r->net[s].hidden);
    }
    duel_replay_init(r);
}

/* Room for one more frame. 0 or -ENOMEM. */
static int duel_replay_grow(duel_replay *r)
{
    duel_frame *f;
    size_t cap;
    int s;
    if (r->n < r->cap)
        return 0;
    cap = r->cap ? 2 * r->cap : 256;
    if (cap > (size_t)-1 / sizeof *f)
        return -ENOMEM;
    f = (duel_frame *)realloc(r->frames, cap * sizeof *f);
    if (f == NULL)
        return -ENOMEM;
    r->frames = f;
    for (s = 0; s < 2; s++) {
        size_t h = r->net[s].shape.n_hidden;
        nrt_q15 *a;
        if (h == 0)
            continue;
        if (cap > (size_t)-1 / sizeof *a / h)
            return -ENOMEM;
        a = (nrt_q15 *)realloc(r->net[s].hidden, cap * h * sizeof *a);
        if (a == NULL)
            return -ENOMEM;
        r->net[s].hidden = a;
    }
    r->cap = cap;
    return 0;
}

/* A copy of net's shape (counts, weights, sources, ends) into rn, for
 * drawing after the controller is closed. 0 or -ENOMEM. */
static int duel_replay_net_copy(duel_replay_net *rn, const nrt_net *net)
{
    size_t n_conns = net->n_conns, n_end = (size_t)net->n_outputs + net->n_hidden;
    size_t w = n_conns * sizeof(nrt_w12), sz = n_conns * sizeof(uint16_t), e = n_end * sizeof(uint16_t);
    uint8_t *m = (uint8_t *)malloc(w + sz + e + 1);
    if (m == NULL)
        return -ENOMEM;
    memset(&rn->shape, 0, sizeof rn->shape);
    rn->shape.n_inputs = net->n_inputs;
    rn->shape.n_outputs = net->n_outputs;
    rn->shape.n_hidden = net->n_hidden;
    rn->shape.n_nodes = net->n_nodes;
    rn->shape.n_conns = net->n_conns;
    rn->shape.step = net->step;
    rn->shape.weight = (nrt_w12 *)(void *)m;
    rn->shape.src = (uint16_t *)(void *)(m + w);
    rn->shape.end = (uint16_t *)(void *)(m + w + sz);
    memcpy(rn->shape.weight, net->weight, w);
    memcpy(rn->shape.src, net->src, sz);
    memcpy(rn->shape.end, net->end, e);
    rn->mem = m;
    rn->hidden = NULL;
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

/* The hidden activations of each step, by stepping side s's network again
 * through the recorded inputs: the game may have run it in another form
 * (nrt_dense's, whose state lives outside the nrt_net), and nrt_step gives
 * the same values bit for bit, which the recorded outputs confirm. 0, or
 * -EIO when an output differs (it cannot, unless the network was changed). */
static int duel_replay_hidden(duel_replay *r, nrt_net *net, int s)
{
    size_t t, h = r->net[s].shape.n_hidden;
    nrt_reset(net);
    for (t = 0; t < r->n; t++) {
        nrt_step(net, r->frames[t].in[s], NULL);
        if (memcmp(nrt_outputs(net), r->frames[t].out[s], sizeof r->frames[t].out[s]) != 0)
            return -EIO;
        if (h > 0)
            memcpy(&r->net[s].hidden[t * h], net->act[net->cur] + net->n_inputs + net->n_outputs, h * sizeof(nrt_q15));
    }
    return 0;
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
    int err, s;

    r->n = 0;
    r->food_config = food_config;
    r->rules = rules != NULL ? *rules : *duel_rules_v1();
    rec.r = r;
    rec.err = 0;
    r->step[0] = duel_trace_step_of(west);
    r->step[1] = duel_trace_step_of(east);
    for (s = 0; s < 2; s++) {
        duel_controller *c = s == 0 ? west : east;
        free(r->net[s].mem);
        free(r->net[s].hidden);
        memset(&r->net[s], 0, sizeof r->net[s]);
        if (c->net != NULL && duel_replay_net_copy(&r->net[s], c->net) != 0)
            return -ENOMEM;
    }
    r->cap = 0; /* the hidden arrays grow with the frames from here */
    err = duel_play_rules(&r->rules, west, east, food_config, &res, duel_replay_trace, &rec);
    if (!err)
        err = rec.err;
    if (!err)
        err = duel_replay_grow(r);
    for (s = 0; s < 2 && !err; s++)
        if ((s == 0 ? west : east)->net != NULL)
            err = duel_replay_hidden(r, (s == 0 ? west : east)->net, s);
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
    for (s = 0; s < 2; s++)
        if (r->net[s].shape.n_hidden > 0)
            memset(&r->net[s].hidden[r->n * r->net[s].shape.n_hidden], 0, r->net[s].shape.n_hidden * sizeof(nrt_q15));
    fin->w = last->w;
    duel_world_step(&fin->w, last->out[DUEL_WEST], last->out[DUEL_EAST], NULL);
    fin->t = fin->w.t;
    fin->ev.outcome = fin->w.outcome;
    assert(fin->t == res.steps && fin->w.outcome == res.outcome && fin->w.robot[0].energy == res.energy[0] &&
           fin->w.robot[1].energy == res.energy[1]);
    r->n++;
    return 0;
}
