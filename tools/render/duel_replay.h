/* duel_replay.h - a game as a sequence of frames (state, inputs, outputs, events): what the renderer draws, from a live game or an LCM log. */
#ifndef DUEL_REPLAY_H
#define DUEL_REPLAY_H

#include <stddef.h>

#include "duel.h"

/* Frame t: the state before step t's move (as in `play --trace`), the
 * inputs and outputs of step t and the events of step t. A finished game of
 * T steps has T frames plus a last one holding the final state (t = T, its
 * in/out zero, ev.outcome the game's outcome). */
typedef struct duel_frame {
    uint32_t t;
    duel_world w;
    nrt_q15 in[2][DUEL_N_INPUTS];
    nrt_q15 out[2][DUEL_N_OUTPUTS];
    duel_event ev;
} duel_frame;

/* A side's network as it played: its shape (a copy of the loaded net's
 * counts, weights, sources and ends; no activations) and the hidden nodes'
 * activations after each step. Recorded from a live game only (a log holds
 * no network): shape.n_nodes 0 for a builtin or a log. */
typedef struct duel_replay_net {
    nrt_net shape;    /* weight, src and end point into mem; act and order are NULL */
    void *mem;
    nrt_q15 *hidden;  /* [frame * shape.n_hidden + k]: hidden node k after frame t's step (0 at the final frame) */
} duel_replay_net;

typedef struct duel_replay {
    duel_frame *frames;
    size_t n, cap;
    int food_config;          /* DUEL_TRAINING or 0..DUEL_CONFIGS-1 */
    duel_rules rules;         /* the game's world, which every frame's world points at */
    char west[256], east[256]; /* the controllers' names, for captions */
    int step[2];              /* how each side stepped, from a log's net messages: -1 builtin, 0 sync,
                               * 1 propagate, -2 not recorded (duel_trace.h's codes; docs/lcm.md) */
    duel_replay_net net[2];   /* west, east: the networks of a live game (for the web page) */
} duel_replay;

void duel_replay_init(duel_replay *r);
void duel_replay_free(duel_replay *r);
/* Appends a copy of f. 0 or -ENOMEM. */
int duel_replay_push(duel_replay *r, const duel_frame *f);

/* Plays west against east on food_config and records every frame
 * (tools/duel_replay.c). 0, or a negative duel_error / -ENOMEM. */
int duel_replay_from_game(duel_replay *r, duel_controller *west, duel_controller *east, int food_config);
/* The same in the world of rules (NULL: v1), copied into r->rules. */
int duel_replay_from_game_rules(duel_replay *r, const duel_rules *rules, duel_controller *west, duel_controller *east,
                                int food_config);

/* Reads the frames of a game recorded as an LCM event log (`play
 * --lcm-log`, tools/duel_lcm_log.c). 0, or -1 with one line in err naming
 * the file and the problem (not an LCM log, truncated, unknown message
 * version or fingerprint, no game in it). */
int duel_replay_from_lcm_log(duel_replay *r, const char *path, char *err, size_t err_len);

#endif /* DUEL_REPLAY_H */
