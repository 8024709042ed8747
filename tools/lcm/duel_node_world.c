/* duel_node_world.c - the world as an LCM node: duelsim stepped in lockstep with two controller nodes, a silent controller losing by forfeit. */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "duel_lcm.h"

static void duel_nw_fail(duel_node_world *nw, int err, const char *fmt, ...)
{
    va_list ap;
    if (nw->err)
        return;
    nw->err = err;
    va_start(ap, fmt);
    vsnprintf(nw->r->msg, sizeof nw->r->msg, fmt, ap);
    va_end(ap);
}

/* Publishes an encoded message and records the same bytes. */
static void duel_nw_send(duel_node_world *nw, const char *channel, const uint8_t *buf, int n)
{
    if (n < 0) {
        duel_nw_fail(nw, DUEL_NODE_E_LCM, "cannot encode a message for %s", channel);
        return;
    }
    if (lcm_publish(nw->lcm, channel, buf, (unsigned)n) != 0)
        duel_nw_fail(nw, DUEL_NODE_E_LCM, "cannot publish on %s", channel);
    if (nw->o->rec != NULL && duel_lcm_rec_write(nw->o->rec, channel, buf, (size_t)n, duel_lcm_utime_now()) != 0)
        duel_nw_fail(nw, DUEL_NODE_E_LCM, "%s: write failed", nw->o->rec->path);
}

static void duel_nw_state(duel_node_world *nw, const duel_world *w, const duel_event *prev, int forfeit)
{
    uint8_t buf[DUEL_LCM_MSG_MAX];
    duel_state_t m;
    char *names[2];
    names[0] = nw->r->name[0];
    names[1] = nw->r->name[1];
    duel_lcm_state_fill(&m, w, prev, nw->o->food_config, names, forfeit);
    duel_nw_send(nw, DUEL_CH_STATE, buf, duel_state_t_encode(buf, 0, (int)sizeof buf, &m));
}

static void duel_nw_on_motor(const lcm_recv_buf_t *rbuf, const char *channel, void *ud)
{
    duel_node_world *nw = (duel_node_world *)ud;
    int side = strcmp(channel, DUEL_CH_MOTOR_WEST) == 0 ? 0 : 1;
    const char *sname = side == 0 ? "west" : "east";
    duel_motor_t m;
    char why[256];
    int err, i;

    if (nw->err)
        return;
    err = duel_msg_decode_motor(rbuf->data, rbuf->data_size, &m, why, sizeof why);
    if (err) { /* anyone can publish: a forged or broken message decides nothing */
        if (nw->r->ignored++ == 0)
            snprintf(nw->r->ignored_msg, sizeof nw->r->ignored_msg, "%s: %s", channel, why);
        return;
    }
    if (m.side != side) {
        duel_nw_fail(nw, DUEL_NODE_E_MALFORMED, "%s: a motor message for side %d", channel, m.side);
    } else if (m.step == DUEL_MOTOR_T_HELLO) {
        if (!nw->hello[side] && nw->step < 0) {
            nw->hello[side] = 1;
            snprintf(nw->r->name[side], sizeof nw->r->name[side], "%s", m.controller);
        }
    } else if (m.step == nw->step && !nw->have[side]) {
        nw->have[side] = 1;
        for (i = 0; i < DUEL_N_OUTPUTS; i++)
            nw->out[side][i] = m.output[i];
        if (nw->o->rec != NULL && duel_lcm_rec_write(nw->o->rec, channel, rbuf->data, rbuf->data_size,
                                                     rbuf->recv_utime) != 0)
            duel_nw_fail(nw, DUEL_NODE_E_LCM, "%s: write failed", nw->o->rec->path);
    } else if (m.step > nw->step) {
        duel_nw_fail(nw, DUEL_NODE_E_ORDER, "%s: the %s controller answered step %ld before it was sent (now %ld)",
                     channel, sname, (long)m.step, (long)nw->step);
    }
    /* a repeated answer or a late hello changes nothing */
    duel_motor_t_decode_cleanup(&m);
}

/* What plays a side: the first valid one of each side before the game is kept and recorded. */
static void duel_nw_on_net(const lcm_recv_buf_t *rbuf, const char *channel, void *ud)
{
    duel_node_world *nw = (duel_node_world *)ud;
    duel_net_t m;
    char why[256];

    if (nw->err)
        return;
    if (duel_msg_decode_net(rbuf->data, rbuf->data_size, &m, why, sizeof why) != DUEL_NODE_OK) {
        if (nw->r->ignored++ == 0)
            snprintf(nw->r->ignored_msg, sizeof nw->r->ignored_msg, "%s: %s", channel, why);
        return;
    }
    if (nw->step < 0 && !nw->r->have_net[m.side]) {
        nw->r->have_net[m.side] = 1;
        nw->r->net_step[m.side] = m.step;
        if (nw->o->rec != NULL && duel_lcm_rec_write(nw->o->rec, channel, rbuf->data, rbuf->data_size,
                                                     rbuf->recv_utime) != 0)
            duel_nw_fail(nw, DUEL_NODE_E_LCM, "%s: write failed", nw->o->rec->path);
    }
    duel_net_t_decode_cleanup(&m);
}

/* Handles messages until done(nw) or the deadline. */
static void duel_nw_wait(duel_node_world *nw, int64_t deadline, const int *flags)
{
    while (!nw->err && !(flags[0] && flags[1])) {
        int64_t now = duel_node_now_ms();
        if (now >= deadline)
            return;
        if (duel_node_handle(nw->lcm, (int)(deadline - now)) < 0)
            duel_nw_fail(nw, DUEL_NODE_E_LCM, "LCM failed while waiting for motor messages");
    }
}

static void duel_nw_sleep_until(int64_t when_ms)
{
    int64_t now = duel_node_now_ms();
    if (when_ms > now) {
        struct timespec ts;
        ts.tv_sec = (time_t)((when_ms - now) / 1000);
        ts.tv_nsec = (long)((when_ms - now) % 1000) * 1000000L;
        nanosleep(&ts, NULL);
    }
}

int duel_node_world_open(duel_node_world *nw, lcm_t *lcm, const duel_node_world_opts *o, duel_node_world_result *r)
{
    duel_world w;
    memset(r, 0, sizeof *r);
    memset(nw, 0, sizeof *nw);
    nw->lcm = lcm;
    nw->o = o;
    nw->r = r;
    nw->step = -1;
    if (duel_world_init_rules(&w, o->rules, o->food_config) != DUEL_OK) {
        duel_nw_fail(nw, DUEL_NODE_E_ARG, "bad food configuration %d, or rules that cannot make a game", o->food_config);
        return nw->err;
    }
    nw->sub[0] = lcm_subscribe(lcm, DUEL_CH_MOTOR_WEST, duel_nw_on_motor, nw);
    nw->sub[1] = lcm_subscribe(lcm, DUEL_CH_MOTOR_EAST, duel_nw_on_motor, nw);
    nw->sub_net = lcm_subscribe(lcm, DUEL_CH_NET, duel_nw_on_net, nw);
    if (nw->sub[0] == NULL || nw->sub[1] == NULL || nw->sub_net == NULL)
        duel_nw_fail(nw, DUEL_NODE_E_LCM, "cannot subscribe to the motor and net channels");
    return nw->err;
}

void duel_node_world_close(duel_node_world *nw)
{
    int s;
    for (s = 0; s < 2; s++)
        if (nw->sub[s] != NULL)
            lcm_unsubscribe(nw->lcm, nw->sub[s]);
    if (nw->sub_net != NULL)
        lcm_unsubscribe(nw->lcm, nw->sub_net);
    nw->sub[0] = nw->sub[1] = nw->sub_net = NULL;
}

int duel_node_world_play(duel_node_world *nw)
{
    static const char *const side_name[2] = {"west", "east"};
    const duel_node_world_opts *o = nw->o;
    duel_node_world_result *r = nw->r;
    duel_world w;
    duel_event ev;
    int s;

    if (nw->err)
        return nw->err;
    duel_world_init_rules(&w, o->rules, o->food_config);
    /* both controllers say hello before the first sensor message, so none is lost */
    duel_nw_wait(nw, duel_node_now_ms() + o->wait_ms, nw->hello);
    if (!nw->err && !(nw->hello[0] && nw->hello[1]))
        duel_nw_fail(nw, DUEL_NODE_E_TIMEOUT, "no %s controller said hello within %d ms (%s)",
                     nw->hello[0] ? "east" : nw->hello[1] ? "west" : "west or east", o->wait_ms,
                     nw->hello[0] || nw->hello[1] ? "is it running on this LCM URL?" : "are they running on this LCM URL?");
    /* a controller sends its net message just before each hello: one that came before the world listened
     * comes again with the next hello; a controller that sends none (an older one) costs this wait once */
    if (!nw->err && !(nw->r->have_net[0] && nw->r->have_net[1]))
        duel_nw_wait(nw, duel_node_now_ms() + 2 * DUEL_NODE_HELLO_MS + 50, nw->r->have_net);

    memset(&ev, 0, sizeof ev);
    if (!nw->err && o->rules != NULL && !duel_rules_equal(o->rules, duel_rules_v1())) {
        /* the world's rules before its first state: readers check the states against them */
        uint8_t buf[DUEL_LCM_MSG_MAX];
        duel_world_t m;
        duel_lcm_world_fill(&m, o->rules);
        duel_nw_send(nw, DUEL_CH_WORLD, buf, duel_world_t_encode(buf, 0, (int)sizeof buf, &m));
    }
    while (!nw->err) {
        int64_t step_start = duel_node_now_ms();
        duel_nw_state(nw, &w, w.t == 0 ? NULL : &ev, DUEL_STATE_T_FORFEIT_NONE);
        if (w.outcome != DUEL_RUNNING || nw->err)
            break;
        nw->step = (int32_t)w.t;
        nw->have[0] = nw->have[1] = 0;
        for (s = 0; s < 2; s++) {
            uint8_t buf[DUEL_LCM_MSG_MAX];
            nrt_q15 in[DUEL_N_INPUTS];
            duel_sense_t m;
            duel_sense(&w, s, in);
            duel_lcm_sense_fill(&m, s, w.t, in);
            duel_nw_send(nw, DUEL_CH_SENSE(s), buf, duel_sense_t_encode(buf, 0, (int)sizeof buf, &m));
        }
        duel_nw_wait(nw, duel_node_now_ms() + o->timeout_ms, nw->have);
        if (nw->err)
            break;
        if (!(nw->have[0] && nw->have[1])) {
            /* a silent controller loses: the state again, with the forfeit */
            int forfeit = (nw->have[0] ? 0 : DUEL_STATE_T_FORFEIT_WEST) | (nw->have[1] ? 0 : DUEL_STATE_T_FORFEIT_EAST);
            w.outcome = forfeit == DUEL_STATE_T_FORFEIT_WEST   ? DUEL_EAST_WINS
                        : forfeit == DUEL_STATE_T_FORFEIT_EAST ? DUEL_WEST_WINS
                                                               : DUEL_DRAW;
            r->forfeit = forfeit;
            duel_nw_state(nw, &w, w.t == 0 ? NULL : &ev, forfeit);
            if (forfeit == DUEL_STATE_T_FORFEIT_BOTH)
                duel_nw_fail(nw, DUEL_NODE_E_TIMEOUT, "neither controller answered step %lu within %d ms: a draw",
                             (unsigned long)w.t, o->timeout_ms);
            else
                duel_nw_fail(nw, DUEL_NODE_E_TIMEOUT, "the %s controller did not answer step %lu within %d ms: %s loses, "
                             "%s wins", side_name[nw->have[0] ? 1 : 0], (unsigned long)w.t, o->timeout_ms,
                             side_name[nw->have[0] ? 1 : 0], side_name[nw->have[0] ? 0 : 1]);
            break;
        }
        duel_world_step(&w, nw->out[0], nw->out[1], &ev);
        if (o->period_ms > 0)
            duel_nw_sleep_until(step_start + o->period_ms);
    }
    r->res.outcome = w.outcome;
    r->res.steps = w.t;
    for (s = 0; s < 2; s++) {
        r->res.energy[s] = w.robot[s].energy;
        r->res.eaten[s] = w.robot[s].eaten;
    }
    return nw->err;
}

int duel_node_world_run(lcm_t *lcm, const duel_node_world_opts *o, duel_node_world_result *r)
{
    duel_node_world nw;
    int err = duel_node_world_open(&nw, lcm, o, r);
    if (!err)
        err = duel_node_world_play(&nw);
    duel_node_world_close(&nw);
    return err;
}
