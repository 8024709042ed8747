/* duel_lcm_log.c - LCM event logs read event by event (truncation and corruption found by offset), a game gathered from one, and its replay frames. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_files.h"
#include "duel_lcm.h"
#include "duel_replay.h"
#include "duel_trace.h"

/* LCM's log format: per event, big-endian: sync word, event number,
 * microseconds, channel length, data length, channel, data. */
#define DUEL_LCM_SYNC 0xEDA1DA01u
#define DUEL_LCM_HEADER 28u
#define DUEL_LCM_MAX_CHANNEL 255u
#define DUEL_LCM_MAX_DATA (64u << 20) /* far more than any message here; a larger length is corruption */

static uint32_t duel_lcm_be32(const uint8_t *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
}

static uint64_t duel_lcm_be64(const uint8_t *p)
{
    return ((uint64_t)duel_lcm_be32(p) << 32) | duel_lcm_be32(p + 4);
}

int duel_lcm_reader_open(duel_lcm_reader *r, const char *path, char *err, size_t err_len)
{
    uint8_t head[4];
    long size;
    memset(r, 0, sizeof *r);
    snprintf(r->path, sizeof r->path, "%s", path);
    r->f = duel_fopen_regular(path); /* a FIFO would block, a device may be endless */
    if (r->f == NULL) {
        snprintf(err, err_len, "%s: cannot open: %s", path, duel_file_strerror(errno));
        return -1;
    }
    if (fseek(r->f, 0, SEEK_END) != 0 || (size = ftell(r->f)) < 0 || fseek(r->f, 0, SEEK_SET) != 0) {
        snprintf(err, err_len, "%s: cannot read: not a regular file", path);
        duel_lcm_reader_close(r);
        return -1;
    }
    r->size = (uint64_t)size;
    if (size == 0) {
        snprintf(err, err_len, "%s: empty file, not an LCM event log", path);
        duel_lcm_reader_close(r);
        return -1;
    }
    if (fread(head, 1, sizeof head, r->f) != sizeof head || duel_lcm_be32(head) != DUEL_LCM_SYNC) {
        snprintf(err, err_len, "%s: offset 0: not an LCM event log (no sync word 0x%08X)", path, DUEL_LCM_SYNC);
        duel_lcm_reader_close(r);
        return -1;
    }
    fseek(r->f, 0, SEEK_SET);
    return 0;
}

int duel_lcm_reader_next(duel_lcm_reader *r, duel_lcm_event *ev, char *err, size_t err_len)
{
    uint8_t h[DUEL_LCM_HEADER];
    size_t got = fread(h, 1, sizeof h, r->f);
    uint32_t clen, dlen;
    size_t need;

    if (got == 0 && feof(r->f))
        return 0;
    if (got < sizeof h) {
        snprintf(err, err_len, "%s: offset %llu: truncated event header (%zu of %u bytes)", r->path,
                 (unsigned long long)r->offset, got, DUEL_LCM_HEADER);
        return -1;
    }
    if (duel_lcm_be32(h) != DUEL_LCM_SYNC) {
        snprintf(err, err_len, "%s: offset %llu: no LCM sync word: corrupt event log", r->path,
                 (unsigned long long)r->offset);
        return -1;
    }
    clen = duel_lcm_be32(h + 20);
    dlen = duel_lcm_be32(h + 24);
    if (clen == 0 || clen > DUEL_LCM_MAX_CHANNEL || dlen > DUEL_LCM_MAX_DATA) {
        snprintf(err, err_len, "%s: offset %llu: impossible event (channel %lu bytes, data %lu bytes): corrupt", r->path,
                 (unsigned long long)r->offset, (unsigned long)clen, (unsigned long)dlen);
        return -1;
    }
    if (r->offset + DUEL_LCM_HEADER + clen + dlen > r->size) { /* no overflow: clen, dlen are bounded above */
        /* the lengths claim more than the file holds: nothing is allocated for them */
        uint64_t left = r->size > r->offset + DUEL_LCM_HEADER ? r->size - r->offset - DUEL_LCM_HEADER : 0;
        snprintf(err, err_len, "%s: offset %llu: truncated event (%llu of %lu bytes after its header)", r->path,
                 (unsigned long long)r->offset, (unsigned long long)left, (unsigned long)clen + dlen);
        return -1;
    }
    need = (size_t)clen + 1 + dlen;
    if (need > r->cap) {
        uint8_t *nb = (uint8_t *)realloc(r->buf, need);
        if (nb == NULL) {
            snprintf(err, err_len, "%s: out of memory", r->path);
            return -1;
        }
        r->buf = nb;
        r->cap = need;
    }
    got = fread(r->buf, 1, clen, r->f);
    if (got == clen)
        got += fread(r->buf + clen + 1, 1, dlen, r->f);
    if (got < (size_t)clen + dlen) {
        snprintf(err, err_len, "%s: offset %llu: truncated event (%zu of %lu bytes after its header)", r->path,
                 (unsigned long long)r->offset, got, (unsigned long)clen + dlen);
        return -1;
    }
    r->buf[clen] = '\0';
    ev->index = r->index;
    ev->offset = r->offset;
    ev->eventnum = (int64_t)duel_lcm_be64(h + 4);
    ev->utime = (int64_t)duel_lcm_be64(h + 12);
    ev->channel = (const char *)r->buf;
    ev->data = r->buf + clen + 1;
    ev->len = dlen;
    if (strlen(ev->channel) != clen) {
        snprintf(err, err_len, "%s: offset %llu: a channel name with a NUL byte: corrupt", r->path,
                 (unsigned long long)r->offset);
        return -1;
    }
    r->offset += DUEL_LCM_HEADER + clen + dlen;
    r->index++;
    return 1;
}

void duel_lcm_reader_close(duel_lcm_reader *r)
{
    if (r->f != NULL)
        fclose(r->f);
    free(r->buf);
    r->f = NULL;
    r->buf = NULL;
    r->cap = 0;
}

/* ---- a game from the events ---- */

static int duel_lcm_count_channel(duel_lcm_game *g, const char *channel)
{
    size_t i;
    duel_lcm_channel *nc;
    for (i = 0; i < g->n_channels; i++)
        if (strcmp(g->channels[i].name, channel) == 0) {
            g->channels[i].count++;
            return 0;
        }
    nc = (duel_lcm_channel *)realloc(g->channels, (g->n_channels + 1) * sizeof *nc);
    if (nc == NULL)
        return -1;
    g->channels = nc;
    snprintf(nc[g->n_channels].name, sizeof nc[g->n_channels].name, "%s", channel);
    nc[g->n_channels].count = 1;
    g->n_channels++;
    return 0;
}

/* One state message: step t's state, or the final one. -1 with msg on a
 * message that contradicts the game so far. */
static int duel_lcm_take_state(duel_lcm_game *g, const duel_state_t *m, char *msg, size_t msg_len)
{
    duel_world w;
    duel_event ev;
    uint32_t t;
    int s;
    if (duel_lcm_state_read(m, &g->rules, &w, &ev, msg, msg_len) != 0)
        return -1;
    t = w.t;
    if (!g->started) {
        if (t != 0) {
            snprintf(msg, msg_len, "the first state message is of step %lu, not 0: not the start of a game",
                     (unsigned long)t);
            return -1;
        }
        g->started = 1;
        g->food_config = m->food_config;
        for (s = 0; s < 2; s++)
            snprintf(g->name[s], sizeof g->name[s], "%s", m->controller[s]);
    } else if (m->food_config != g->food_config) {
        snprintf(msg, msg_len, "food configuration %ld in the middle of a game of configuration %d",
                 (long)m->food_config, g->food_config);
        return -1;
    }
    if (m->forfeit == DUEL_STATE_T_FORFEIT_NONE) {
        if (g->have[t] & DUEL_LCM_HAVE_STATE) {
            snprintf(msg, msg_len, "a second state message of step %lu", (unsigned long)t);
            return -1;
        }
        g->have[t] |= DUEL_LCM_HAVE_STATE;
        g->w[t] = w;
        g->ev[t] = ev;
    }
    if (w.outcome != DUEL_RUNNING) {
        g->over = 1;
        g->final_step = t;
        g->final_w = w;
        g->forfeit = m->forfeit;
    }
    return 0;
}

static int duel_lcm_take(duel_lcm_game *g, const duel_lcm_event *e, char *msg, size_t msg_len)
{
    int err = 0, s;
    if (strcmp(e->channel, DUEL_CH_WORLD) == 0) {
        /* the world's rules, once, before the game's first state */
        duel_rules r;
        if (duel_msg_decode_world(e->data, e->len, &r, msg, msg_len) != DUEL_NODE_OK)
            return -1;
        if (g->started || g->have_world) {
            snprintf(msg, msg_len, "a world message %s", g->started ? "after the game's first state" : "twice");
            return -1;
        }
        g->rules = r;
        g->have_world = 1;
        return 0;
    }
    if (strcmp(e->channel, DUEL_CH_NET) == 0) {
        /* what plays a side: the first of each side counts; a controller repeats it with its hellos */
        duel_net_t m;
        if (duel_msg_decode_net(e->data, e->len, &m, msg, msg_len) != DUEL_NODE_OK)
            return -1;
        if (g->step[m.side] == DUEL_TRACE_STEP_UNKNOWN) {
            g->step[m.side] = m.step;
        } else if (g->step[m.side] != m.step) {
            snprintf(msg, msg_len, "the %s side's net message says %s, an earlier one %s", m.side ? "east" : "west",
                     duel_trace_step_name(m.step), duel_trace_step_name(g->step[m.side]));
            err = -1;
        }
        duel_net_t_decode_cleanup(&m);
        return err;
    }
    if (strcmp(e->channel, DUEL_CH_STATE) == 0) {
        duel_state_t m;
        err = duel_msg_decode_state(e->data, e->len, &m, msg, msg_len);
        if (!err) {
            err = duel_lcm_take_state(g, &m, msg, msg_len);
            duel_state_t_decode_cleanup(&m);
        }
        return err;
    }
    for (s = 0; s < 2; s++) {
        if (strcmp(e->channel, DUEL_CH_SENSE(s)) == 0) {
            duel_sense_t m;
            err = duel_msg_decode_sense(e->data, e->len, &m, msg, msg_len);
            if (err)
                return -1;
            if (m.side != s || m.step < 0 || m.step >= DUEL_MAX_STEPS) {
                snprintf(msg, msg_len, "a sensor message of side %d, step %ld", m.side, (long)m.step);
                return -1;
            }
            if (g->have[m.step] & DUEL_LCM_HAVE_SENSE(s)) {
                snprintf(msg, msg_len, "a second sensor message of step %ld", (long)m.step);
                return -1;
            }
            g->have[m.step] |= DUEL_LCM_HAVE_SENSE(s);
            memcpy(g->in[m.step][s], m.input, sizeof g->in[m.step][s]);
            return 0;
        }
        if (strcmp(e->channel, DUEL_CH_MOTOR(s)) == 0) {
            duel_motor_t m;
            err = duel_msg_decode_motor(e->data, e->len, &m, msg, msg_len);
            if (err)
                return -1;
            if (m.side != s || m.step < DUEL_MOTOR_T_HELLO || m.step >= DUEL_MAX_STEPS) {
                snprintf(msg, msg_len, "a motor message of side %d, step %ld", m.side, (long)m.step);
                err = -1;
            } else if (m.step == DUEL_MOTOR_T_HELLO) {
                g->hellos++;
            } else if (g->have[m.step] & DUEL_LCM_HAVE_MOTOR(s)) {
                /* a controller may answer a repeated sensor message again: the same outputs */
                if (memcmp(g->out[m.step][s], m.output, sizeof g->out[m.step][s]) != 0) {
                    snprintf(msg, msg_len, "two different motor messages of step %ld", (long)m.step);
                    err = -1;
                }
            } else {
                g->have[m.step] |= DUEL_LCM_HAVE_MOTOR(s);
                memcpy(g->out[m.step][s], m.output, sizeof g->out[m.step][s]);
            }
            duel_motor_t_decode_cleanup(&m);
            return err;
        }
    }
    return 0; /* another channel: counted, not read */
}

int duel_lcm_game_read(duel_lcm_game **out, const char *path, char *err, size_t err_len)
{
    duel_lcm_reader rd;
    duel_lcm_event e;
    duel_lcm_game *g;
    char msg[400];
    int rc, status = 0;
    uint32_t t;

    *out = NULL;
    if (duel_lcm_reader_open(&rd, path, err, err_len) != 0)
        return -1;
    g = (duel_lcm_game *)calloc(1, sizeof *g);
    if (g != NULL) {
        g->rules = *duel_rules_v1(); /* a log without a world message is world v1's */
        g->step[0] = g->step[1] = DUEL_TRACE_STEP_UNKNOWN; /* and one without net messages does not say */
    }
    if (g == NULL) {
        snprintf(err, err_len, "%s: out of memory", path);
        duel_lcm_reader_close(&rd);
        return -1;
    }
    g->size = rd.size;
    g->food_config = DUEL_TRAINING;
    *out = g;
    while ((rc = duel_lcm_reader_next(&rd, &e, err, err_len)) == 1) {
        if (g->events == 0)
            g->first_utime = e.utime;
        g->last_utime = e.utime;
        g->events++;
        if (duel_lcm_count_channel(g, e.channel) != 0) {
            snprintf(err, err_len, "%s: out of memory", path);
            rc = -1;
            break;
        }
        if (g->over) { /* another game, or traffic after the end: counted only */
            g->after_end++;
            continue;
        }
        if (duel_lcm_take(g, &e, msg, sizeof msg) != 0) {
            snprintf(err, err_len, "%s: event %llu at offset %llu: %s: %s", path, (unsigned long long)e.index,
                     (unsigned long long)e.offset, e.channel, msg);
            rc = -2; /* a message this reader must not guess at: stop, keep what came before */
            break;
        }
    }
    duel_lcm_reader_close(&rd);
    if (rc == -1)
        g->truncated = 1;

    /* the complete steps, from 0 */
    for (t = 0; t < DUEL_MAX_STEPS; t++) {
        if ((g->have[t] & DUEL_LCM_HAVE_ALL) != DUEL_LCM_HAVE_ALL || !(g->have[t + 1] & DUEL_LCM_HAVE_STATE))
            break;
        if (g->w[t].outcome != DUEL_RUNNING)
            break;
    }
    g->rows = t;
    if (rc != 0) {
        status = g->started ? -2 : -1;
    } else if (!g->started) {
        snprintf(err, err_len, "%s: no duel game in this LCM log (no %s message of step 0)", path, DUEL_CH_STATE);
        status = -1;
    } else if (!g->over) {
        snprintf(err, err_len, "%s: the game stops after %lu complete steps without an outcome (an unfinished "
                 "recording)", path, (unsigned long)g->rows);
        status = -2;
    } else if (g->rows != g->final_step) {
        snprintf(err, err_len, "%s: step %lu lacks a message (state, both sensors, both motors, next state): an "
                 "incomplete recording", path, (unsigned long)g->rows);
        status = -2;
    }
    return status;
}

void duel_lcm_game_free(duel_lcm_game *g)
{
    if (g != NULL)
        free(g->channels);
    free(g);
}

/* ---- replay frames (duel_replay.h) ---- */

int duel_replay_from_lcm_log(duel_replay *r, const char *path, char *err, size_t err_len)
{
    duel_lcm_game *g;
    duel_frame f;
    uint32_t t;
    int status = duel_lcm_game_read(&g, path, err, err_len);

    r->n = 0;
    if (g != NULL && g->started) {
        r->food_config = g->food_config;
        r->rules = g->rules; /* the frames' worlds point here, not into g, which is freed below */
        snprintf(r->west, sizeof r->west, "%s", g->name[0]);
        snprintf(r->east, sizeof r->east, "%s", g->name[1]);
        r->step[0] = g->step[0];
        r->step[1] = g->step[1];
        /* what came before a truncation stays readable */
        for (t = 0; t < g->rows; t++) {
            memset(&f, 0, sizeof f);
            f.t = t;
            f.w = g->w[t];
            f.w.rules = &r->rules;
            memcpy(f.in, g->in[t], sizeof f.in);
            memcpy(f.out, g->out[t], sizeof f.out);
            f.ev = g->ev[t + 1];
            if (duel_replay_push(r, &f) != 0) {
                snprintf(err, err_len, "%s: out of memory", path);
                status = -1;
                break;
            }
        }
        if (status == 0) {
            memset(&f, 0, sizeof f);
            f.t = g->final_step;
            f.w = g->final_w;
            f.w.rules = &r->rules;
            f.ev.outcome = g->final_w.outcome;
            if (duel_replay_push(r, &f) != 0) {
                snprintf(err, err_len, "%s: out of memory", path);
                status = -1;
            }
        }
    }
    duel_lcm_game_free(g);
    return status == 0 ? 0 : -1;
}
