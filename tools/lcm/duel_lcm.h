/* duel_lcm.h - the duel over LCM, world side: messages from and to the world, event log writing and reading, the world node. */
/* tools/lcm/: the duel over LCM: messages, the controller node (runtime + LCM only, library duelnode), the world node, event logs written and read, champion games recorded (docs/lcm.md). */
#ifndef DUEL_LCM_H
#define DUEL_LCM_H

#include <stdio.h>

#include <lcm/eventlog.h>

#include "duel.h"
#include "duel_node.h"

#define DUEL_LCM_MSG_MAX 2048 /* every duel message encodes into fewer bytes (names are cut at 255) */

/* ---- messages <-> the world (duel_lcm_msg.c) ---- */

/* The state message of w: prev is the event of the step that led to it
 * (NULL at step 0), names the two controllers' names (not copied: keep them
 * alive while m is used). */
void duel_lcm_state_fill(duel_state_t *m, const duel_world *w, const duel_event *prev, int food_config,
                         char *names[2], int forfeit);
void duel_lcm_sense_fill(duel_sense_t *m, int side, uint32_t step, const nrt_q15 in[DUEL_N_INPUTS]);
void duel_lcm_motor_fill(duel_motor_t *m, int side, int32_t step, const nrt_q15 out[DUEL_N_OUTPUTS], char *name);

/* A decoded state message back into the world and the event that led to it,
 * every field checked (ranges, the food of its configuration in the world of
 * rules, NULL: v1). 0, or -1 with
 * one line in msg. */
int duel_lcm_state_read(const duel_state_t *m, const duel_rules *rules, duel_world *w, duel_event *ev, char *msg,
                        size_t msg_len);
/* A world message of the rules (a game not of world v1 publishes one first). */
void duel_lcm_world_fill(duel_world_t *m, const duel_rules *r);
/* A world message: fingerprint, version and size, then the rules' bytes
 * through duel_rules_decode and its identity against them. DUEL_NODE_OK, or
 * an error with one line in msg. */
int duel_msg_decode_world(const void *data, size_t len, duel_rules *r, char *msg, size_t msg_len);

/* "west wins (collision, more energy)" ..., with the forfeit when there is one. */
const char *duel_lcm_outcome_text(int outcome, int forfeit);

/* ---- writing an LCM event log (duel_lcm_rec.c) ---- */
typedef struct duel_lcm_rec {
    lcm_eventlog_t *log;
    char path[4096], tmp[4100]; /* written to tmp, renamed to path by duel_lcm_rec_close */
    int direct;                 /* path is no regular file (duel_out_target): written in place */
    int failed;
} duel_lcm_rec;

/* Creates path's temporary file. 0, or -1 with one line in err. */
int duel_lcm_rec_open(duel_lcm_rec *r, const char *path, char *err, size_t err_len);
/* One event; utime in microseconds. 0 or -1 (the close then fails too). */
int duel_lcm_rec_write(duel_lcm_rec *r, const char *channel, const void *data, size_t len, int64_t utime);
/* keep: flush, sync and rename to the final name (0, or -1 with err);
 * otherwise the temporary file is removed. */
int duel_lcm_rec_close(duel_lcm_rec *r, int keep, char *err, size_t err_len);

/* Microseconds since the epoch (the time stamps of live messages). */
int64_t duel_lcm_utime_now(void);

/* A game played by duel_play recorded as the world node would publish it:
 * per step the state, both sensor messages, both motor messages, and the
 * final state. Time stamps are a nominal clock, step t at t * 10 ms, so the
 * same game gives the same bytes. */
typedef struct duel_lcm_game_rec {
    duel_lcm_rec rec;
    int food_config;
    char name[2][DUEL_NODE_NAME_MAX + 1];
    duel_event prev;
    duel_trace_fn next;  /* also called with every step when not NULL (e.g. `play --trace`) */
    void *next_ud;
} duel_lcm_game_rec;

int duel_lcm_game_rec_open(duel_lcm_game_rec *g, const char *path, int food_config, const char *west,
                           const char *east, char *err, size_t err_len);
/* The world message of rules, first (nothing for world v1). */
void duel_lcm_game_rec_world(duel_lcm_game_rec *g, const duel_rules *rules);
/* What plays each side (one net message each, before the first state): a
 * builtin, or a network and its step mode. */
void duel_lcm_game_rec_nets(duel_lcm_game_rec *g, const duel_controller *west, const duel_controller *east);
/* duel_trace_fn: ud is the duel_lcm_game_rec. */
void duel_lcm_game_rec_step(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                            const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev);
int duel_lcm_game_rec_close(duel_lcm_game_rec *g, int keep, char *err, size_t err_len);

/* ---- the world node (duel_node_world.c) ---- */
typedef struct duel_node_world_opts {
    int food_config;      /* DUEL_TRAINING or 0..143 */
    const duel_rules *rules; /* the world (NULL: v1); published first on DUEL_WORLD when not v1 */
    int timeout_ms;       /* a controller answers each step within this, or loses */
    int wait_ms;          /* both controllers say hello within this */
    int period_ms;        /* at least this long per step (0: as fast as the controllers answer) */
    duel_lcm_rec *rec;    /* NULL, or every message published and accepted is also written here */
} duel_node_world_opts;

typedef struct duel_node_world_result {
    duel_result res;      /* the game (a forfeit: the other side wins) */
    int forfeit;          /* DUEL_STATE_T_FORFEIT_* */
    char name[2][DUEL_NODE_NAME_MAX + 1];
    char msg[512];        /* what went wrong, when the return is not 0 */
    uint32_t ignored;     /* motor and net messages ignored: they failed checked decoding (a forgery, or damage) */
    char ignored_msg[320]; /* the first of them, and why */
    int have_net[2];      /* a net message of the side arrived before the game (a controller of this version) */
    int net_step[2];      /* its step: DUEL_NET_T_BUILTIN, _SYNC or _PROPAGATE */
} duel_node_world_result;

typedef struct duel_node_world {
    lcm_t *lcm;
    const duel_node_world_opts *o;
    duel_node_world_result *r;
    lcm_subscription_t *sub[2], *sub_net;
    int32_t step;                   /* the step whose motor messages are awaited; -1 before the game */
    int hello[2], have[2];
    nrt_q15 out[2][DUEL_N_OUTPUTS];
    int err;
} duel_node_world;

/* Subscribes to both motor channels (hellos count from now on). 0 or a
 * DUEL_NODE_E_* code (r->msg says why). */
int duel_node_world_open(duel_node_world *nw, lcm_t *lcm, const duel_node_world_opts *o, duel_node_world_result *r);
/* Waits for both hellos, then plays one game in lockstep. 0 (a game played
 * to its end), DUEL_NODE_E_TIMEOUT (no hello, or a controller that did not
 * answer: it lost, r->res says so), or another DUEL_NODE_E_* code; r->msg
 * says why. */
int duel_node_world_play(duel_node_world *nw);
void duel_node_world_close(duel_node_world *nw);
/* open, play, close */
int duel_node_world_run(lcm_t *lcm, const duel_node_world_opts *o, duel_node_world_result *r);

/* ---- reading an LCM event log (duel_lcm_log.c) ---- */
typedef struct duel_lcm_event {
    uint64_t index;       /* its place in the file: 0 for the first event (not the event number it claims) */
    uint64_t offset;      /* of its sync word in the file */
    int64_t eventnum, utime;
    const char *channel;  /* NUL-terminated, valid until the next read */
    const uint8_t *data;
    size_t len;
} duel_lcm_event;

typedef struct duel_lcm_reader {
    FILE *f;
    char path[4096];
    uint64_t offset, size;
    uint64_t index;       /* events read so far */
    uint8_t *buf;
    size_t cap;
} duel_lcm_reader;

/* 0, or -1 with one line in err (cannot open, empty, not an LCM log). */
int duel_lcm_reader_open(duel_lcm_reader *r, const char *path, char *err, size_t err_len);
/* 1 an event, 0 the end, -1 a truncated or corrupt event (err names the offset). */
int duel_lcm_reader_next(duel_lcm_reader *r, duel_lcm_event *ev, char *err, size_t err_len);
void duel_lcm_reader_close(duel_lcm_reader *r);

/* A game gathered from a log, by step. */
#define DUEL_LCM_HAVE_STATE 1u
#define DUEL_LCM_HAVE_SENSE(side) (2u << (side))
#define DUEL_LCM_HAVE_MOTOR(side) (8u << (side))
#define DUEL_LCM_HAVE_ALL 31u

typedef struct duel_lcm_channel {
    char name[256];
    uint64_t count;
} duel_lcm_channel;

typedef struct duel_lcm_game {
    duel_world w[DUEL_MAX_STEPS + 1];    /* the state before step t */
    duel_event ev[DUEL_MAX_STEPS + 1];   /* the event of step t - 1 (from state t) */
    nrt_q15 in[DUEL_MAX_STEPS][2][DUEL_N_INPUTS];
    nrt_q15 out[DUEL_MAX_STEPS][2][DUEL_N_OUTPUTS];
    uint8_t have[DUEL_MAX_STEPS + 1];    /* DUEL_LCM_HAVE_* */
    int food_config;                     /* from the first state message */
    duel_rules rules;                    /* the world: a world message before the first state, else v1 */
    int have_world;                      /* a world message was read */
    char name[2][DUEL_NODE_NAME_MAX + 1];
    int step[2];                         /* DUEL_TRACE_STEP_*: the side's first net message, else UNKNOWN */
    int started;                         /* a state of step 0 was read */
    int over;                            /* the final state (an outcome) was read */
    uint32_t final_step;                 /* its step */
    duel_world final_w;
    int forfeit;
    uint32_t rows;                       /* steps 0..rows-1 complete (state, 2 sensors, 2 motors, next state) */
    /* the whole log */
    uint64_t events, hellos, after_end, size;
    int64_t first_utime, last_utime;
    duel_lcm_channel *channels;
    size_t n_channels;
    int truncated;                       /* the read stopped early: err says where */
} duel_lcm_game;

/* Reads the game in the log at path into *g (allocated; duel_lcm_game_free).
 * 0 a whole game; -1 nothing usable (*g NULL or still allocated for the
 * counts; err says why); -2 truncated or incomplete: g holds the events
 * before the problem (g->rows steps), err says what stopped it. */
int duel_lcm_game_read(duel_lcm_game **g, const char *path, char *err, size_t err_len);
void duel_lcm_game_free(duel_lcm_game *g);

/* ---- commands (duel_node_cmd.c, duel_log_cmd.c) and run's recording ---- */
/* Plays west against east on food_config in the world of rules (NULL: v1)
 * into the log at path (named by names), its world and net messages first.
 * 0, or -1 with one line in err. */
int duel_lcm_record_game(const char *path, const duel_rules *rules, duel_controller *west, duel_controller *east,
                         int food_config, const char *west_name, const char *east_name, duel_result *res, char *err,
                         size_t err_len);

#endif /* DUEL_LCM_H */
