/* duel_node.h - the duel over LCM, controller side: channel names, checked decoding, and the controller node (the runtime and LCM only). */
#ifndef DUEL_NODE_H
#define DUEL_NODE_H

/*
 * The messages (the .lcm files in lcmtypes/, docs/lcm.md) and the lockstep protocol:
 *
 *   controller  --motor step -1 (hello)-->  world     until the first sensor message
 *   world       --state t----------------->  all
 *   world       --sense t (each side)----->  controller of that side
 *   controller  --motor t----------------->  world     nrt_step once per sensor message
 *   ...                                                 the world steps when both motors of t are in
 *   world       --state T (outcome set)--->  all       the game is over
 *
 * Nothing here needs the duel simulator: this header, duel_node_controller.c
 * and duel_node_msg.c are what a firmware with a radio would carry along with
 * the runtime (nrt.h) and LCM.
 */

#include <stddef.h>
#include <stdint.h>

#include <lcm/lcm.h>

#include "duel_motor_t.h"
#include "duel_net_t.h"
#include "duel_sense_t.h"
#include "duel_state_t.h"
#include "duel_world_t.h"
#include "nrt.h"

/* ---- channels ---- */
#define DUEL_CH_STATE "DUEL_STATE"
#define DUEL_CH_WORLD "DUEL_WORLD" /* the rules, when the world is not v1 (duel_world_t) */
#define DUEL_CH_NET "DUEL_NET"     /* what plays a side and its step mode (duel_net_t) */
#define DUEL_CH_SENSE_WEST "DUEL_SENSE_WEST"
#define DUEL_CH_SENSE_EAST "DUEL_SENSE_EAST"
#define DUEL_CH_MOTOR_WEST "DUEL_MOTOR_WEST"
#define DUEL_CH_MOTOR_EAST "DUEL_MOTOR_EAST"
#define DUEL_CH_SENSE(side) ((side) == 0 ? DUEL_CH_SENSE_WEST : DUEL_CH_SENSE_EAST)
#define DUEL_CH_MOTOR(side) ((side) == 0 ? DUEL_CH_MOTOR_WEST : DUEL_CH_MOTOR_EAST)

#define DUEL_NODE_NAME_MAX 255 /* controller names are cut to this many bytes */
#define DUEL_NODE_HELLO_MS 100 /* a controller repeats its hello this often until the game starts */

/* Encoded sizes (the 8-byte fingerprint included) of the fixed parts of the
 * messages; each string adds 4 bytes of length and its bytes with the NUL. */
#define DUEL_MSG_SENSE_SIZE 147u /* fingerprint, version, side, step, input[13], value[13] */
#define DUEL_MSG_MOTOR_HEAD 47u  /* fingerprint, version, side, step, output[3], value[3]; then controller */
#define DUEL_MSG_STATE_HEAD 20u  /* fingerprint, version, step, food_config; then controller[2] */
#define DUEL_MSG_STATE_TAIL 201u /* x[2] .. energy_units[2] */
#define DUEL_MSG_NET_HEAD 14u    /* fingerprint, version, side, step; then controller */
/* No duel message is larger (a state message with two 255-byte names). */
#define DUEL_MSG_MAX (DUEL_MSG_STATE_HEAD + 2u * (4u + DUEL_NODE_NAME_MAX + 1u) + DUEL_MSG_STATE_TAIL)

/* ---- errors ---- */
enum duel_node_error {
    DUEL_NODE_OK = 0,
    DUEL_NODE_E_ARG = -1,         /* NULL, bad side */
    DUEL_NODE_E_FINGERPRINT = -2, /* a message whose LCM fingerprint is not its channel's type */
    DUEL_NODE_E_VERSION = -3,     /* a message format version this code does not know */
    DUEL_NODE_E_MALFORMED = -4,   /* the right fingerprint, but too short or bad fields */
    DUEL_NODE_E_ORDER = -5,       /* a step out of sequence (a lost message) */
    DUEL_NODE_E_TIMEOUT = -6,     /* nothing heard in time */
    DUEL_NODE_E_LCM = -7          /* LCM failed (publish, handle) */
};

/* ---- checked decoding (duel_node_msg.c) ----
 * Each checks the fingerprint, then the format version (the first field),
 * then the size and every string (length 1..DUEL_NODE_NAME_MAX + 1, within
 * the message, ending in its only NUL), then decodes. 0, or a DUEL_NODE_E_* code with one line in msg saying what
 * is wrong (no file or channel: the caller adds those). Free a decoded motor
 * or state message with duel_motor_t_decode_cleanup / duel_state_t_decode_cleanup. */
int duel_msg_decode_sense(const void *data, size_t len, duel_sense_t *m, char *msg, size_t msg_len);
int duel_msg_decode_motor(const void *data, size_t len, duel_motor_t *m, char *msg, size_t msg_len);
int duel_msg_decode_state(const void *data, size_t len, duel_state_t *m, char *msg, size_t msg_len);
/* also checks side (0, 1) and step (BUILTIN, SYNC, PROPAGATE); free with duel_net_t_decode_cleanup */
int duel_msg_decode_net(const void *data, size_t len, duel_net_t *m, char *msg, size_t msg_len);
/* The fingerprint and format version every duel message starts with
 * (duel_lcm_msg.c checks the world message with it). DUEL_NODE_OK, or an
 * error with one line in msg. */
int duel_msg_check(const void *data, size_t len, int64_t hash, int32_t version, const char *type, char *msg,
                   size_t msg_len);

/* ---- the controller node (duel_node_controller.c) ---- */
typedef struct duel_node_ctrl {
    lcm_t *lcm;
    nrt_net *net;
    int side;                 /* 0 west, 1 east */
    char name[DUEL_NODE_NAME_MAX + 1];
    int32_t next_step;        /* the sensor step expected next; -1 before the first */
    uint32_t steps;           /* sensor messages answered */
    int game_over;            /* 1 once a state message with an outcome arrived */
    int8_t outcome, forfeit;  /* from that message */
    int err;                  /* the first error (a DUEL_NODE_E_*), 0 while fine */
    char msg[320];            /* its description */
    uint32_t ignored;         /* messages ignored: they failed checked decoding (a forgery, or damage) */
    char ignored_msg[320];    /* the first of them, and why */
    lcm_subscription_t *sub_sense, *sub_state;
} duel_node_ctrl;

/* Subscribes to the side's sensor channel and the state channel; net is
 * loaded and reset on every step 0. 0 or DUEL_NODE_E_ARG / _LCM. */
int duel_node_ctrl_start(duel_node_ctrl *c, lcm_t *lcm, nrt_net *net, int side, const char *name);
/* Publishes one hello: what plays this side (DUEL_NET), then a motor message
 * of step -1. 0 or DUEL_NODE_E_LCM. */
int duel_node_ctrl_hello(duel_node_ctrl *c);
void duel_node_ctrl_stop(duel_node_ctrl *c);

/* A controller process's loop: a hello every DUEL_NODE_HELLO_MS until the
 * first sensor message (at most wait_ms), then handles messages until the
 * game is over, failing when no message arrives for timeout_ms. 0 once the
 * game is over, or a DUEL_NODE_E_* code (c->msg says why). */
int duel_node_ctrl_run(duel_node_ctrl *c, int wait_ms, int timeout_ms);

/* Milliseconds of a monotonic clock (deadlines for lcm_handle_timeout). */
int64_t duel_node_now_ms(void);

/* lcm_create(url) without the library's chatter on stderr; NULL when the
 * URL is bad or, for tcpq://, no hub answers. */
lcm_t *duel_node_lcm_create(const char *url);
/* lcm_handle_timeout for lockstep traffic over tcpq://: LCM's Java hub
 * writes each message in five small writes with Nagle's algorithm on, so a
 * receiver that delays its ACKs (Linux: up to 40 ms) stalls every message;
 * this ACKs at once (TCP_QUICKACK) and sends at once (TCP_NODELAY) when the
 * LCM file descriptor is a TCP socket, and is lcm_handle_timeout otherwise. */
int duel_node_handle(lcm_t *lcm, int timeout_ms);

#endif /* DUEL_NODE_H */
