/* duel_node_controller.c - a champion as an LCM node: each sensor message steps the runtime once and is answered by a motor message. */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "duel_node.h"

#define DUEL_NODE_INPUTS ((int)(sizeof(((duel_sense_t *)0)->input) / sizeof(int16_t)))
#define DUEL_NODE_OUTPUTS ((int)(sizeof(((duel_motor_t *)0)->output) / sizeof(int16_t)))

int64_t duel_node_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

/* Records the first error only: it is the one that explains the others. */
static void duel_node_fail(duel_node_ctrl *c, int err, const char *fmt, ...)
{
    va_list ap;
    if (c->err)
        return;
    c->err = err;
    va_start(ap, fmt);
    vsnprintf(c->msg, sizeof c->msg, fmt, ap);
    va_end(ap);
}

/* A message that fails checked decoding is counted and its first reason kept. */
static void duel_node_ignore(duel_node_ctrl *c, const char *channel, const char *why)
{
    if (c->ignored++ == 0)
        snprintf(c->ignored_msg, sizeof c->ignored_msg, "%s: %s", channel, why);
}

static int duel_node_publish(duel_node_ctrl *c, int32_t step, const nrt_q15 *out)
{
    duel_motor_t m;
    int i;
    memset(&m, 0, sizeof m);
    m.version = DUEL_MOTOR_T_VERSION;
    m.side = (int8_t)c->side;
    m.step = step;
    for (i = 0; i < DUEL_NODE_OUTPUTS; i++) {
        m.output[i] = out != NULL ? out[i] : 0;
        m.value[i] = m.output[i] / 32768.0;
    }
    m.controller = c->name;
    if (duel_motor_t_publish(c->lcm, DUEL_CH_MOTOR(c->side), &m) != 0) {
        duel_node_fail(c, DUEL_NODE_E_LCM, "cannot publish on %s", DUEL_CH_MOTOR(c->side));
        return DUEL_NODE_E_LCM;
    }
    return DUEL_NODE_OK;
}

/* A sensor message: one network step, one motor message. */
static void duel_node_on_sense(const lcm_recv_buf_t *rbuf, const char *channel, void *ud)
{
    duel_node_ctrl *c = (duel_node_ctrl *)ud;
    duel_sense_t s;
    nrt_q15 out[DUEL_NODE_OUTPUTS];
    char why[256];
    int err;

    if (c->err)
        return;
    err = duel_msg_decode_sense(rbuf->data, rbuf->data_size, &s, why, sizeof why);
    if (err) { /* anyone can publish: a forged or broken message decides nothing */
        duel_node_ignore(c, channel, why);
        return;
    }
    if (s.side != c->side) {
        duel_node_fail(c, DUEL_NODE_E_MALFORMED, "%s: a sensor message for side %d", channel, s.side);
        return;
    }
    if (s.step == 0) { /* a game starts: the network forgets the last one */
        nrt_reset(c->net);
        c->game_over = 0;
    } else if (s.step != c->next_step) {
        duel_node_fail(c, DUEL_NODE_E_ORDER, "%s: sensor message of step %ld, expected step %ld (a message was lost)",
                       channel, (long)s.step, (long)(c->next_step < 0 ? 0 : c->next_step));
        return;
    }
    nrt_step(c->net, s.input, out);
    c->next_step = s.step + 1;
    c->steps++;
    duel_node_publish(c, s.step, out);
}

/* A state message: only its outcome matters here (the game is over). */
static void duel_node_on_state(const lcm_recv_buf_t *rbuf, const char *channel, void *ud)
{
    duel_node_ctrl *c = (duel_node_ctrl *)ud;
    duel_state_t st;
    char why[256];
    int err;

    if (c->err)
        return;
    err = duel_msg_decode_state(rbuf->data, rbuf->data_size, &st, why, sizeof why);
    if (err) { /* anyone can publish: a forged or broken message decides nothing */
        duel_node_ignore(c, channel, why);
        return;
    }
    if (st.outcome != DUEL_STATE_T_RUNNING && c->next_step >= 0) {
        c->game_over = 1;
        c->outcome = st.outcome;
        c->forfeit = st.forfeit;
    }
    duel_state_t_decode_cleanup(&st);
}

int duel_node_ctrl_start(duel_node_ctrl *c, lcm_t *lcm, nrt_net *net, int side, const char *name)
{
    if (c == NULL || lcm == NULL || net == NULL || (side != 0 && side != 1) || net->n_inputs != DUEL_NODE_INPUTS ||
        net->n_outputs != DUEL_NODE_OUTPUTS)
        return DUEL_NODE_E_ARG;
    memset(c, 0, sizeof *c);
    c->lcm = lcm;
    c->net = net;
    c->side = side;
    c->next_step = -1;
    snprintf(c->name, sizeof c->name, "%s", name != NULL ? name : "");
    c->sub_sense = lcm_subscribe(lcm, DUEL_CH_SENSE(side), duel_node_on_sense, c);
    c->sub_state = lcm_subscribe(lcm, DUEL_CH_STATE, duel_node_on_state, c);
    if (c->sub_sense == NULL || c->sub_state == NULL) {
        duel_node_ctrl_stop(c);
        return DUEL_NODE_E_LCM;
    }
    return DUEL_NODE_OK;
}

int duel_node_ctrl_hello(duel_node_ctrl *c)
{
    /* what this side is, just before the hello, so the world has it when the game starts */
    duel_net_t n;
    memset(&n, 0, sizeof n);
    n.version = DUEL_NET_T_VERSION;
    n.side = (int8_t)c->side;
    n.step = c->net->step == NRT_STEP_PROPAGATE ? DUEL_NET_T_PROPAGATE : DUEL_NET_T_SYNC;
    n.controller = c->name;
    if (duel_net_t_publish(c->lcm, DUEL_CH_NET, &n) != 0) {
        duel_node_fail(c, DUEL_NODE_E_LCM, "cannot publish on %s", DUEL_CH_NET);
        return DUEL_NODE_E_LCM;
    }
    return duel_node_publish(c, DUEL_MOTOR_T_HELLO, NULL);
}

void duel_node_ctrl_stop(duel_node_ctrl *c)
{
    if (c->sub_sense != NULL)
        lcm_unsubscribe(c->lcm, c->sub_sense);
    if (c->sub_state != NULL)
        lcm_unsubscribe(c->lcm, c->sub_state);
    c->sub_sense = c->sub_state = NULL;
}

int duel_node_ctrl_run(duel_node_ctrl *c, int wait_ms, int timeout_ms)
{
    int64_t start = duel_node_now_ms(), heard = start, next_hello = start;
    while (!c->err && !c->game_over) {
        int64_t now = duel_node_now_ms(), until;
        int rc;
        if (c->next_step < 0) { /* the world has not started: say hello now and then */
            if (now - start >= wait_ms) {
                duel_node_fail(c, DUEL_NODE_E_TIMEOUT, "no sensor message on %s in %d ms: no world node on this LCM URL?",
                               DUEL_CH_SENSE(c->side), wait_ms);
                break;
            }
            if (now >= next_hello) {
                if (duel_node_ctrl_hello(c) != 0)
                    break;
                next_hello = now + DUEL_NODE_HELLO_MS;
            }
            until = next_hello < start + wait_ms ? next_hello : start + wait_ms;
        } else {
            if (now - heard >= timeout_ms) {
                duel_node_fail(c, DUEL_NODE_E_TIMEOUT, "no message from the world node for %d ms after step %ld",
                               timeout_ms, (long)(c->next_step - 1));
                break;
            }
            until = heard + timeout_ms;
        }
        rc = duel_node_handle(c->lcm, (int)(until > now ? until - now : 0));
        if (rc < 0) {
            duel_node_fail(c, DUEL_NODE_E_LCM, "LCM failed while waiting for messages");
            break;
        }
        if (rc > 0)
            heard = duel_node_now_ms();
    }
    return c->err;
}
