/* duel_lcm_rec.c - LCM event logs written through a temporary file and renamed, and a duel_play game recorded as the world node publishes it. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "duel_files.h"
#include "duel_lcm.h"
#include "duel_trace.h"

/* a net message's step is the trace's step code */
typedef char duel_lcm_step_codes_agree[(DUEL_NET_T_BUILTIN == DUEL_TRACE_STEP_BUILTIN && DUEL_NET_T_SYNC ==
                                        DUEL_TRACE_STEP_SYNC && DUEL_NET_T_PROPAGATE == DUEL_TRACE_STEP_PROPAGATE)
                                           ? 1
                                           : -1];

#define DUEL_LCM_NOMINAL_STEP_US 10000 /* the nominal clock of recorded games: 100 steps a second */

int64_t duel_lcm_utime_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    return (int64_t)ts.tv_sec * 1000000 + ts.tv_nsec / 1000;
}

int duel_lcm_rec_open(duel_lcm_rec *r, const char *path, char *err, size_t err_len)
{
    memset(r, 0, sizeof *r);
    if (strlen(path) >= sizeof r->path) {
        snprintf(err, err_len, "%.200s...: path too long", path);
        return -1;
    }
    if (duel_out_target(path, r->path, sizeof r->path, &r->direct) != 0) {
        snprintf(err, err_len, "%s: cannot write: %s", path, strerror(errno));
        return -1;
    }
    snprintf(r->tmp, sizeof r->tmp, "%s.tmp", r->path);
    /* a stale temporary, or a link planted there, is removed: lcm_eventlog_create would follow it */
    if (!r->direct && unlink(r->tmp) != 0 && errno != ENOENT) {
        snprintf(err, err_len, "%s: cannot write: %s", path, strerror(errno));
        return -1;
    }
    errno = 0;
    r->log = lcm_eventlog_create(r->direct ? r->path : r->tmp, "w");
    if (r->log == NULL) {
        snprintf(err, err_len, "%s: cannot write: %s", path, errno ? strerror(errno) : "lcm_eventlog_create failed");
        return -1;
    }
    return 0;
}

int duel_lcm_rec_write(duel_lcm_rec *r, const char *channel, const void *data, size_t len, int64_t utime)
{
    lcm_eventlog_event_t e;
    if (r->failed)
        return -1;
    memset(&e, 0, sizeof e);
    e.timestamp = utime;
    e.channellen = (int32_t)strlen(channel);
    e.datalen = (int32_t)len;
    e.channel = (char *)channel; /* lcm_eventlog_write_event only reads it */
    e.data = (void *)data;
    if (lcm_eventlog_write_event(r->log, &e) != 0)
        r->failed = 1;
    return r->failed ? -1 : 0;
}

int duel_lcm_rec_close(duel_lcm_rec *r, int keep, char *err, size_t err_len)
{
    int bad;
    if (r->log == NULL)
        return -1;
    bad = r->failed || fflush(r->log->f) != 0 || ferror(r->log->f) ||
          (keep && !r->direct && fsync(fileno(r->log->f)) != 0);
    lcm_eventlog_destroy(r->log);
    r->log = NULL;
    if (r->direct && !bad)
        return 0;
    if (keep && !bad && !r->direct && duel_file_commit(r->tmp, r->path) == 0)
        return 0;
    if (!r->direct)
        unlink(r->tmp);
    if (keep) {
        snprintf(err, err_len, "%s: write failed: %s", r->path, errno ? strerror(errno) : "I/O error");
        return -1;
    }
    return 0;
}

/* Encodes one message of the duel with its generated encoder. */
#define DUEL_LCM_PUT(g, type, channel, msg, utime)                                                                   \
    do {                                                                                                               \
        uint8_t buf_[DUEL_LCM_MSG_MAX];                                                                                \
        int n_ = type##_encode(buf_, 0, (int)sizeof buf_, (msg));                                                      \
        if (n_ < 0)                                                                                                    \
            (g)->rec.failed = 1;                                                                                       \
        else                                                                                                           \
            duel_lcm_rec_write(&(g)->rec, (channel), buf_, (size_t)n_, (utime));                                       \
    } while (0)

int duel_lcm_game_rec_open(duel_lcm_game_rec *g, const char *path, int food_config, const char *west,
                           const char *east, char *err, size_t err_len)
{
    memset(g, 0, sizeof *g);
    g->food_config = food_config;
    snprintf(g->name[0], sizeof g->name[0], "%s", west);
    snprintf(g->name[1], sizeof g->name[1], "%s", east);
    return duel_lcm_rec_open(&g->rec, path, err, err_len);
}

void duel_lcm_game_rec_world(duel_lcm_game_rec *g, const duel_rules *rules)
{
    duel_world_t m;
    if (rules == NULL || duel_rules_equal(rules, duel_rules_v1()))
        return; /* a log without a world message is world v1's: v1's logs are as they were */
    duel_lcm_world_fill(&m, rules);
    DUEL_LCM_PUT(g, duel_world_t, DUEL_CH_WORLD, &m, 0);
}

void duel_lcm_game_rec_nets(duel_lcm_game_rec *g, const duel_controller *west, const duel_controller *east)
{
    const duel_controller *c[2];
    int s;
    c[0] = west;
    c[1] = east;
    for (s = 0; s < 2; s++) {
        duel_net_t m;
        memset(&m, 0, sizeof m);
        m.version = DUEL_NET_T_VERSION;
        m.side = (int8_t)s;
        m.step = (int8_t)duel_trace_step_of(c[s]); /* the values of duel_net_t's step */
        m.controller = g->name[s];
        DUEL_LCM_PUT(g, duel_net_t, DUEL_CH_NET, &m, 0);
    }
}

static void duel_lcm_game_rec_state(duel_lcm_game_rec *g, const duel_world *w, const duel_event *prev)
{
    duel_state_t m;
    char *names[2];
    names[0] = g->name[0];
    names[1] = g->name[1];
    duel_lcm_state_fill(&m, w, prev, g->food_config, names, DUEL_STATE_T_FORFEIT_NONE);
    DUEL_LCM_PUT(g, duel_state_t, DUEL_CH_STATE, &m, (int64_t)w->t * DUEL_LCM_NOMINAL_STEP_US);
}

void duel_lcm_game_rec_step(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                            const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    duel_lcm_game_rec *g = (duel_lcm_game_rec *)ud;
    int64_t t0 = (int64_t)w->t * DUEL_LCM_NOMINAL_STEP_US;
    int s;

    if (g->next != NULL)
        g->next(g->next_ud, w, in, out, ev);
    /* the order of the world node: state, sensors, motors (microseconds apart) */
    duel_lcm_game_rec_state(g, w, w->t == 0 ? NULL : &g->prev);
    for (s = 0; s < 2; s++) {
        duel_sense_t m;
        duel_lcm_sense_fill(&m, s, w->t, in[s]);
        DUEL_LCM_PUT(g, duel_sense_t, DUEL_CH_SENSE(s), &m, t0 + 1 + s);
    }
    for (s = 0; s < 2; s++) {
        duel_motor_t m;
        duel_lcm_motor_fill(&m, s, (int32_t)w->t, out[s], g->name[s]);
        DUEL_LCM_PUT(g, duel_motor_t, DUEL_CH_MOTOR(s), &m, t0 + 3 + s);
    }
    g->prev = *ev;
    if (ev->outcome != DUEL_RUNNING) {
        /* the last step: its result is the final state (the step is a pure function of these) */
        duel_world after = *w;
        duel_event again;
        duel_world_step(&after, out[0], out[1], &again);
        duel_lcm_game_rec_state(g, &after, &again);
    }
}

int duel_lcm_game_rec_close(duel_lcm_game_rec *g, int keep, char *err, size_t err_len)
{
    return duel_lcm_rec_close(&g->rec, keep, err, err_len);
}

int duel_lcm_record_game(const char *path, const duel_rules *rules, duel_controller *west, duel_controller *east,
                         int food_config, const char *west_name, const char *east_name, duel_result *res, char *err,
                         size_t err_len)
{
    duel_lcm_game_rec g;
    int e;
    if (duel_lcm_game_rec_open(&g, path, food_config, west_name, east_name, err, err_len) != 0)
        return -1;
    duel_lcm_game_rec_world(&g, rules);
    duel_lcm_game_rec_nets(&g, west, east);
    e = duel_play_rules(rules != NULL ? rules : duel_rules_v1(), west, east, food_config, res, duel_lcm_game_rec_step,
                        &g);
    if (e != DUEL_OK) {
        duel_lcm_game_rec_close(&g, 0, err, err_len);
        snprintf(err, err_len, "%s: the game failed (%d)", path, e);
        return -1;
    }
    return duel_lcm_game_rec_close(&g, 1, err, err_len);
}
