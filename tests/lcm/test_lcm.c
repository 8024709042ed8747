/* test_lcm.c - the duel over LCM in one process: checked decoding, state messages back into worlds, nodes over memq:// against duel_play, forfeits, event logs (truncated, corrupt, unknown versions) and replay frames. */
#define _POSIX_C_SOURCE 200809L
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "bench_nets.h"
#include "duel_lcm.h"
#include "duel_replay.h"
#include "hostile_msgs.h"

/* ---- fixtures: random networks with hidden nodes and recurrent connections ---- */

typedef struct tl_net {
    uint8_t blob[4096];
    size_t len;
    uint64_t mem[1024];
    nrt_net net;
} tl_net;

static void tl_net_make(tl_net *t, uint64_t seed, uint32_t hidden, uint32_t conns)
{
    neat_genome g;
    neat_rng rng;
    size_t need = 0;
    neat_rng_seed(&rng, seed);
    assert_int_equal(bench_random_net(&g, DUEL_N_INPUTS - 1, DUEL_N_OUTPUTS, hidden, conns, 1, &rng), NEAT_OK);
    assert_int_equal(neat_blob_write(&g, DUEL_N_INPUTS - 1, DUEL_N_OUTPUTS, t->blob, sizeof t->blob, &t->len), NEAT_OK);
    neat_genome_free(&g, NULL);
    assert_int_equal(nrt_mem_required(t->blob, t->len, &need), NRT_OK);
    assert_true(need <= sizeof t->mem);
    assert_int_equal(nrt_load(&t->net, t->blob, t->len, t->mem, sizeof t->mem), NRT_OK);
}

/* A second copy of the same network (a game may not share one nrt_net). */
static void tl_net_copy(tl_net *dst, const tl_net *src)
{
    memcpy(dst->blob, src->blob, src->len);
    dst->len = src->len;
    assert_int_equal(nrt_load(&dst->net, dst->blob, dst->len, dst->mem, sizeof dst->mem), NRT_OK);
}

static void tl_path(char *out, size_t cap, const char *what)
{
    snprintf(out, cap, "test_lcm_%ld_%s.lcm", (long)getpid(), what);
}

static void tl_world_equal(const duel_world *a, const duel_world *b)
{
    int s, i;
    assert_int_equal(a->t, b->t);
    assert_int_equal(a->outcome, b->outcome);
    assert_int_equal(a->n_food, b->n_food);
    assert_int_equal(a->food_mask, b->food_mask);
    for (i = 0; i < DUEL_MAX_FOOD; i++) {
        assert_int_equal(a->food_x[i], b->food_x[i]);
        assert_int_equal(a->food_y[i], b->food_y[i]);
    }
    for (s = 0; s < 2; s++) {
        assert_int_equal(a->robot[s].x, b->robot[s].x);
        assert_int_equal(a->robot[s].y, b->robot[s].y);
        assert_int_equal(a->robot[s].heading, b->robot[s].heading);
        assert_int_equal(a->robot[s].energy, b->robot[s].energy);
        assert_int_equal(a->robot[s].eaten, b->robot[s].eaten);
    }
}

/* What duel_play's trace callback saw: the reference every LCM path must reproduce. */
typedef struct tl_trace {
    uint32_t n;
    duel_world w[DUEL_MAX_STEPS];
    nrt_q15 in[DUEL_MAX_STEPS][2][DUEL_N_INPUTS];
    nrt_q15 out[DUEL_MAX_STEPS][2][DUEL_N_OUTPUTS];
    duel_event ev[DUEL_MAX_STEPS];
} tl_trace;

static void tl_trace_fn(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                        const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    tl_trace *t = (tl_trace *)ud;
    t->w[t->n] = *w;
    memcpy(t->in[t->n], in, sizeof t->in[0]);
    memcpy(t->out[t->n], out, sizeof t->out[0]);
    t->ev[t->n] = *ev;
    t->n++;
}

/* The game in g equals the trace, step by step, and ends as res says. */
static void tl_game_equals_trace(const duel_lcm_game *g, const tl_trace *tr, const duel_result *res)
{
    uint32_t t;
    assert_true(g->started && g->over);
    assert_int_equal(g->rows, tr->n);
    assert_int_equal(g->final_step, res->steps);
    assert_int_equal(g->final_w.outcome, res->outcome);
    assert_int_equal(g->final_w.robot[0].energy, res->energy[0]);
    assert_int_equal(g->final_w.robot[1].energy, res->energy[1]);
    for (t = 0; t < tr->n; t++) {
        tl_world_equal(&g->w[t], &tr->w[t]);
        assert_memory_equal(g->in[t], tr->in[t], sizeof g->in[t]);
        assert_memory_equal(g->out[t], tr->out[t], sizeof g->out[t]);
        assert_int_equal(g->ev[t + 1].eaten_by[0], tr->ev[t].eaten_by[0]);
        assert_int_equal(g->ev[t + 1].eaten_by[1], tr->ev[t].eaten_by[1]);
        assert_int_equal(g->ev[t + 1].outcome, tr->ev[t].outcome);
    }
}

/* ---- checked decoding ---- */

static void test_decode_checks(void **state)
{
    uint8_t buf[DUEL_LCM_MSG_MAX];
    nrt_q15 in[DUEL_N_INPUTS];
    duel_sense_t m, back;
    duel_state_t st;
    char msg[256];
    int n, i;
    (void)state;

    for (i = 0; i < DUEL_N_INPUTS; i++)
        in[i] = (nrt_q15)(i * 2000 - 12000);
    duel_lcm_sense_fill(&m, DUEL_EAST, 17, in);
    n = duel_sense_t_encode(buf, 0, (int)sizeof buf, &m);
    assert_true(n > 0);
    assert_int_equal(duel_msg_decode_sense(buf, (size_t)n, &back, msg, sizeof msg), DUEL_NODE_OK);
    assert_int_equal(back.side, DUEL_EAST);
    assert_int_equal(back.step, 17);
    assert_memory_equal(back.input, in, sizeof in);

    /* another type on the channel: the fingerprint says so */
    assert_int_equal(duel_msg_decode_state(buf, (size_t)n, &st, msg, sizeof msg), DUEL_NODE_E_FINGERPRINT);
    assert_non_null(strstr(msg, "fingerprint"));
    buf[3] ^= 0x40;
    assert_int_equal(duel_msg_decode_sense(buf, (size_t)n, &back, msg, sizeof msg), DUEL_NODE_E_FINGERPRINT);
    buf[3] ^= 0x40;
    /* cut short, or with a byte too many */
    assert_int_equal(duel_msg_decode_sense(buf, (size_t)n - 1, &back, msg, sizeof msg), DUEL_NODE_E_MALFORMED);
    assert_int_equal(duel_msg_decode_sense(buf, 8, &back, msg, sizeof msg), DUEL_NODE_E_MALFORMED);
    assert_int_equal(duel_msg_decode_sense(buf, (size_t)n + 1, &back, msg, sizeof msg), DUEL_NODE_E_MALFORMED);
    /* a version from the future, same layout: refused, never guessed at */
    m.version = 99;
    n = duel_sense_t_encode(buf, 0, (int)sizeof buf, &m);
    assert_int_equal(duel_msg_decode_sense(buf, (size_t)n, &back, msg, sizeof msg), DUEL_NODE_E_VERSION);
    assert_non_null(strstr(msg, "version 99"));
    /* a side that is neither */
    m.version = DUEL_SENSE_T_VERSION;
    m.side = 2;
    n = duel_sense_t_encode(buf, 0, (int)sizeof buf, &m);
    assert_int_equal(duel_msg_decode_sense(buf, (size_t)n, &back, msg, sizeof msg), DUEL_NODE_E_MALFORMED);
}

/* Messages that lie about a string's length or their size (hostile_msgs.c):
 * every decoder refuses each of them before the generated code allocates
 * (a negative length crashed it, 2 GB were allocated and leaked), and a log
 * holding one stops at event 0 with the reason. */
static void test_decode_hostile(void **state)
{
    hostile_msg h;
    duel_sense_t se;
    duel_motor_t mo;
    duel_state_t st;
    duel_lcm_game *g;
    char msg[400], path[256];
    int i, n = 0;
    (void)state;
    tl_path(path, sizeof path, "hostile");
    for (i = 0; i < hostile_count(); i++) {
        assert_int_equal(hostile_get(i, &h), 0);
        assert_true(duel_msg_decode_sense(h.data, h.len, &se, msg, sizeof msg) != DUEL_NODE_OK);
        assert_true(duel_msg_decode_motor(h.data, h.len, &mo, msg, sizeof msg) != DUEL_NODE_OK);
        assert_true(duel_msg_decode_state(h.data, h.len, &st, msg, sizeof msg) != DUEL_NODE_OK);
        assert_int_equal(hostile_write_log(&h, path), 0);
        assert_true(duel_lcm_game_read(&g, path, msg, sizeof msg) != 0);
        assert_non_null(strstr(msg, "event 0 at offset 0: "));
        assert_non_null(strstr(msg, h.channel));
        assert_int_equal(g->events, 1);
        assert_int_equal(g->started, 0);
        duel_lcm_game_free(g);
        n++;
    }
    assert_true(n >= 10);
    /* the bound: a state message with two names of the longest length decodes, one byte more does not */
    {
        uint8_t buf[DUEL_MSG_MAX + 8];
        char name[DUEL_NODE_NAME_MAX + 1];
        char *names[2];
        duel_world w;
        duel_event ev;
        int len;
        memset(name, 'n', DUEL_NODE_NAME_MAX);
        name[DUEL_NODE_NAME_MAX] = '\0';
        names[0] = names[1] = name;
        duel_world_init(&w, DUEL_TRAINING);
        memset(&ev, 0, sizeof ev);
        duel_lcm_state_fill(&st, &w, &ev, DUEL_TRAINING, names, 0);
        len = duel_state_t_encode(buf, 0, (int)sizeof buf, &st);
        assert_int_equal(len, (int)DUEL_MSG_MAX);
        assert_int_equal(duel_msg_decode_state(buf, (size_t)len, &st, msg, sizeof msg), DUEL_NODE_OK);
        assert_string_equal(st.controller[1], name);
        duel_state_t_decode_cleanup(&st);
        assert_int_equal(duel_msg_decode_state(buf, (size_t)len + 1, &st, msg, sizeof msg), DUEL_NODE_E_MALFORMED);
    }
    unlink(path);
}

/* ---- state messages: every state of a game, encoded, decoded and read back ---- */

typedef struct tl_roundtrip {
    duel_event prev;
    int steps;
} tl_roundtrip;

static void tl_roundtrip_fn(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                            const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    tl_roundtrip *rt = (tl_roundtrip *)ud;
    uint8_t buf[DUEL_LCM_MSG_MAX];
    char *names[2] = {"west, with a comma", "east \"quoted\""};
    duel_state_t m, back;
    duel_world w2;
    duel_event e2;
    char msg[256];
    int n;
    (void)in;
    (void)out;
    duel_lcm_state_fill(&m, w, w->t ? &rt->prev : NULL, 7, names, DUEL_STATE_T_FORFEIT_NONE);
    n = duel_state_t_encode(buf, 0, (int)sizeof buf, &m);
    assert_true(n > 0 && n <= DUEL_LCM_MSG_MAX);
    assert_int_equal(duel_msg_decode_state(buf, (size_t)n, &back, msg, sizeof msg), DUEL_NODE_OK);
    assert_int_equal(duel_lcm_state_read(&back, NULL, &w2, &e2, msg, sizeof msg), 0);
    tl_world_equal(&w2, w);
    assert_string_equal(back.controller[0], names[0]);
    if (w->t) {
        assert_int_equal(e2.eaten_by[0], rt->prev.eaten_by[0]);
        assert_int_equal(e2.eaten_by[1], rt->prev.eaten_by[1]);
    }
    duel_state_t_decode_cleanup(&back);
    rt->prev = *ev;
    rt->steps++;
}

static void test_state_roundtrip(void **state)
{
    tl_net a, b;
    duel_controller w, e;
    duel_result res;
    tl_roundtrip rt;
    (void)state;
    tl_net_make(&a, 1, 3, 60);
    tl_net_make(&b, 2, 0, 39);
    w.net = &a.net;
    e.net = &b.net;
    memset(&rt, 0, sizeof rt);
    assert_int_equal(duel_play(&w, &e, 7, &res, tl_roundtrip_fn, &rt), DUEL_OK);
    assert_int_equal(rt.steps, (int)res.steps);
    /* headings cover the whole circle, including pi (the start of west) */
    {
        duel_world x;
        duel_state_t m;
        duel_event ev;
        char msg[256], *names[2] = {"a", "b"};
        uint32_t k;
        duel_world_init(&x, DUEL_TRAINING);
        for (k = 0; k < 64; k++) {
            duel_world y;
            x.robot[1].heading = k * 0x04000000u + (k & 1u);
            duel_lcm_state_fill(&m, &x, NULL, DUEL_TRAINING, names, 0);
            assert_int_equal(duel_lcm_state_read(&m, NULL, &y, &ev, msg, sizeof msg), 0);
            assert_int_equal(y.robot[1].heading, x.robot[1].heading);
            assert_true(m.heading_deg[1] > -180.0 && m.heading_deg[1] <= 180.0);
        }
    }
}

static void test_state_read_rejects(void **state)
{
    duel_world w, back;
    duel_state_t m;
    duel_event ev;
    char msg[256], *names[2] = {"a", "b"};
    (void)state;
    duel_world_init(&w, 42);
    duel_lcm_state_fill(&m, &w, NULL, 42, names, 0);
    assert_int_equal(duel_lcm_state_read(&m, NULL, &back, &ev, msg, sizeof msg), 0);
    m.food_x[10] += 1; /* not where configuration 42 puts it */
    assert_int_equal(duel_lcm_state_read(&m, NULL, &back, &ev, msg, sizeof msg), -1);
    assert_non_null(strstr(msg, "food item 10"));
    duel_lcm_state_fill(&m, &w, NULL, DUEL_TRAINING, names, 0); /* 11 items on the training food */
    assert_int_equal(duel_lcm_state_read(&m, NULL, &back, &ev, msg, sizeof msg), -1);
    duel_lcm_state_fill(&m, &w, NULL, 42, names, 0);
    m.step = DUEL_MAX_STEPS + 1;
    assert_int_equal(duel_lcm_state_read(&m, NULL, &back, &ev, msg, sizeof msg), -1);
    duel_lcm_state_fill(&m, &w, NULL, 42, names, 0);
    m.x[1] = DUEL_FIX(DUEL_BOARD);
    assert_int_equal(duel_lcm_state_read(&m, NULL, &back, &ev, msg, sizeof msg), -1);
    duel_lcm_state_fill(&m, &w, NULL, 42, names, 0);
    m.food_mask = 1 << 11;
    assert_int_equal(duel_lcm_state_read(&m, NULL, &back, &ev, msg, sizeof msg), -1);
    duel_lcm_state_fill(&m, &w, NULL, 42, names, 0);
    m.outcome = 5;
    assert_int_equal(duel_lcm_state_read(&m, NULL, &back, &ev, msg, sizeof msg), -1);
}

/* ---- the nodes in one process over memq:// ---- */

/* A world node and two controller nodes on one memq:// instance play the
 * game duel_play plays, message for message. */
static void test_memq_nodes_equal_play(void **state)
{
    static tl_trace tr;
    tl_net a, b, a2, b2;
    duel_controller w, e;
    duel_result res;
    duel_node_ctrl cw, ce;
    duel_node_world nw;
    duel_node_world_opts o;
    duel_node_world_result r;
    duel_lcm_rec rec;
    duel_lcm_game *g;
    lcm_t *lcm;
    char path[256], err[512];
    int food;
    (void)state;

    tl_net_make(&a, 11, 4, 90);
    tl_net_make(&b, 12, 2, 60);
    tl_net_copy(&a2, &a);
    tl_net_copy(&b2, &b);
    tl_path(path, sizeof path, "memq");
    for (food = -1; food < 144; food += 29) {
        memset(&tr, 0, sizeof tr);
        w.net = &a.net;
        e.net = &b.net;
        assert_int_equal(duel_play(&w, &e, food, &res, tl_trace_fn, &tr), DUEL_OK);

        lcm = lcm_create("memq://");
        assert_non_null(lcm);
        memset(&o, 0, sizeof o);
        o.food_config = food;
        o.timeout_ms = 1000;
        o.wait_ms = 1000;
        assert_int_equal(duel_lcm_rec_open(&rec, path, err, sizeof err), 0);
        o.rec = &rec;
        assert_int_equal(duel_node_world_open(&nw, lcm, &o, &r), DUEL_NODE_OK);
        assert_int_equal(duel_node_ctrl_start(&cw, lcm, &a2.net, DUEL_WEST, "west.blob"), DUEL_NODE_OK);
        assert_int_equal(duel_node_ctrl_start(&ce, lcm, &b2.net, DUEL_EAST, "east.blob"), DUEL_NODE_OK);
        assert_int_equal(duel_node_ctrl_hello(&cw), DUEL_NODE_OK);
        assert_int_equal(duel_node_ctrl_hello(&ce), DUEL_NODE_OK);
        assert_int_equal(duel_node_world_play(&nw), DUEL_NODE_OK);
        /* the final state reaches the controllers too */
        while (!(cw.game_over && ce.game_over) && lcm_handle_timeout(lcm, 100) > 0) {
        }
        assert_true(cw.game_over && ce.game_over);
        assert_int_equal(cw.outcome, res.outcome);
        assert_int_equal(cw.steps, res.steps);
        assert_int_equal(cw.err, 0);
        duel_node_world_close(&nw);
        duel_node_ctrl_stop(&cw);
        duel_node_ctrl_stop(&ce);
        lcm_destroy(lcm);
        assert_int_equal(duel_lcm_rec_close(&rec, 1, err, sizeof err), 0);

        assert_int_equal(r.res.outcome, res.outcome);
        assert_int_equal(r.res.steps, res.steps);
        assert_int_equal(r.res.energy[0], res.energy[0]);
        assert_int_equal(r.res.energy[1], res.energy[1]);
        assert_string_equal(r.name[0], "west.blob");
        assert_int_equal(duel_lcm_game_read(&g, path, err, sizeof err), 0);
        tl_game_equals_trace(g, &tr, &res);
        assert_string_equal(g->name[1], "east.blob");
        assert_int_equal(g->food_config, food);
        assert_int_equal(g->hellos, 0); /* the world records what it accepts */
        duel_lcm_game_free(g);
    }
    unlink(path);
}

/* An east "controller" that answers the first steps, then falls silent. */
typedef struct tl_quitter {
    lcm_t *lcm;
    int32_t answer_until;
} tl_quitter;

static void tl_quitter_on_sense(const lcm_recv_buf_t *rbuf, const char *channel, void *ud)
{
    tl_quitter *q = (tl_quitter *)ud;
    duel_sense_t s;
    duel_motor_t m;
    nrt_q15 out[DUEL_N_OUTPUTS] = {0, 0, 20000};
    char msg[256];
    (void)channel;
    assert_int_equal(duel_msg_decode_sense(rbuf->data, rbuf->data_size, &s, msg, sizeof msg), 0);
    if (s.step < q->answer_until) {
        duel_lcm_motor_fill(&m, DUEL_EAST, s.step, out, "quitter");
        assert_int_equal(duel_motor_t_publish(q->lcm, DUEL_CH_MOTOR_EAST, &m), 0);
    }
}

static void test_memq_forfeit(void **state)
{
    tl_net a;
    duel_node_ctrl cw;
    duel_node_world_opts o;
    duel_node_world_result r;
    duel_node_world nw;
    tl_quitter q;
    duel_motor_t hello;
    duel_net_t net;
    char quitter[] = "quitter";
    nrt_q15 zero[DUEL_N_OUTPUTS] = {0, 0, 0};
    lcm_subscription_t *sub;
    lcm_t *lcm;
    int64_t t0, ms;
    (void)state;

    tl_net_make(&a, 21, 1, 45);
    lcm = lcm_create("memq://");
    assert_non_null(lcm);
    memset(&o, 0, sizeof o);
    o.food_config = DUEL_TRAINING;
    o.timeout_ms = 150;
    o.wait_ms = 1000;
    q.lcm = lcm;
    q.answer_until = 10;
    assert_int_equal(duel_node_world_open(&nw, lcm, &o, &r), 0);
    assert_int_equal(duel_node_ctrl_start(&cw, lcm, &a.net, DUEL_WEST, "w"), 0);
    sub = lcm_subscribe(lcm, DUEL_CH_SENSE_EAST, tl_quitter_on_sense, &q);
    assert_int_equal(duel_node_ctrl_hello(&cw), 0);
    /* the quitter says what it is, then hello, as a controller node does */
    memset(&net, 0, sizeof net);
    net.version = DUEL_NET_T_VERSION;
    net.side = DUEL_EAST;
    net.step = DUEL_NET_T_SYNC;
    net.controller = quitter;
    assert_int_equal(duel_net_t_publish(lcm, DUEL_CH_NET, &net), 0);
    duel_lcm_motor_fill(&hello, DUEL_EAST, DUEL_MOTOR_T_HELLO, zero, quitter);
    assert_int_equal(duel_motor_t_publish(lcm, DUEL_CH_MOTOR_EAST, &hello), 0);
    t0 = duel_node_now_ms();
    assert_int_equal(duel_node_world_play(&nw), DUEL_NODE_E_TIMEOUT);
    ms = duel_node_now_ms() - t0;
    assert_true(ms >= 150 && ms < 150 + 500);
    assert_int_equal(r.forfeit, DUEL_STATE_T_FORFEIT_EAST);
    assert_int_equal(r.res.outcome, DUEL_WEST_WINS);
    assert_int_equal(r.res.steps, 10);
    assert_non_null(strstr(r.msg, "east controller did not answer step 10 within 150 ms"));
    /* what plays each side, from the net messages sent with the hellos */
    assert_true(r.have_net[0] && r.have_net[1]);
    assert_int_equal(r.net_step[0], a.net.step == NRT_STEP_PROPAGATE ? DUEL_NET_T_PROPAGATE : DUEL_NET_T_SYNC);
    assert_int_equal(r.net_step[1], DUEL_NET_T_SYNC);
    while (!cw.game_over && lcm_handle_timeout(lcm, 100) > 0) {
    }
    assert_true(cw.game_over);
    assert_int_equal(cw.forfeit, DUEL_STATE_T_FORFEIT_EAST);
    duel_node_world_close(&nw);
    duel_node_ctrl_stop(&cw);
    lcm_unsubscribe(lcm, sub);

    /* nobody there at all: no hello, no game */
    assert_int_equal(duel_node_world_open(&nw, lcm, &o, &r), 0);
    o.wait_ms = 50;
    assert_int_equal(duel_node_world_play(&nw), DUEL_NODE_E_TIMEOUT);
    assert_non_null(strstr(r.msg, "said hello"));
    duel_node_world_close(&nw);
    lcm_destroy(lcm);
}

/* ---- event logs ---- */

static long tl_file_size(const char *path)
{
    FILE *f = fopen(path, "rb");
    long n;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fclose(f);
    return n;
}

static void tl_copy_prefix(const char *from, const char *to, long n)
{
    FILE *a = fopen(from, "rb"), *b = fopen(to, "wb");
    int c;
    assert_non_null(a);
    assert_non_null(b);
    while (n-- > 0 && (c = getc(a)) != EOF)
        putc(c, b);
    fclose(a);
    fclose(b);
}

static void test_log_truncated(void **state)
{
    static tl_trace tr;
    tl_net a, b;
    duel_controller w, e;
    duel_result res;
    duel_lcm_game *g;
    char path[256], cut[256], err[512];
    long size, at;
    (void)state;

    tl_net_make(&a, 31, 2, 50);
    tl_net_make(&b, 32, 0, 39);
    w.net = &a.net;
    e.net = &b.net;
    tl_path(path, sizeof path, "full");
    tl_path(cut, sizeof cut, "cut");
    assert_int_equal(duel_lcm_record_game(path, NULL, &w, &e, 100, "a", "b", &res, err, sizeof err), 0);
    memset(&tr, 0, sizeof tr);
    assert_int_equal(duel_play(&w, &e, 100, &res, tl_trace_fn, &tr), DUEL_OK);
    assert_int_equal(duel_lcm_game_read(&g, path, err, sizeof err), 0);
    tl_game_equals_trace(g, &tr, &res);
    duel_lcm_game_free(g);

    /* cut anywhere: inside a header, inside a channel, inside a payload,
     * at an event boundary: what came before still reads, in order */
    size = tl_file_size(path);
    for (at = 600; at < size; at += size / 37 + 1) { /* past the first state message */
        uint32_t t;
        tl_copy_prefix(path, cut, at);
        assert_int_equal(duel_lcm_game_read(&g, cut, err, sizeof err), -2);
        assert_non_null(g);
        assert_true(g->rows < tr.n);
        assert_true(strstr(err, "truncated") != NULL || strstr(err, "unfinished") != NULL);
        for (t = 0; t < g->rows; t++) {
            tl_world_equal(&g->w[t], &tr.w[t]);
            assert_memory_equal(g->out[t], tr.out[t], sizeof g->out[t]);
        }
        duel_lcm_game_free(g);
    }
    /* not a log at all, and an empty file */
    {
        FILE *f = fopen(cut, "wb");
        fputs("t,west_x,west_y\n0,100,300\n", f);
        fclose(f);
        assert_int_equal(duel_lcm_game_read(&g, cut, err, sizeof err), -1);
        assert_non_null(strstr(err, "offset 0: not an LCM event log"));
        f = fopen(cut, "wb");
        fclose(f);
        assert_int_equal(duel_lcm_game_read(&g, cut, err, sizeof err), -1);
        assert_non_null(strstr(err, "empty"));
        assert_int_equal(duel_lcm_game_read(&g, "no/such/file.lcm", err, sizeof err), -1);
        assert_non_null(strstr(err, "cannot open"));
    }
    unlink(path);
    unlink(cut);
}

/* A version-99 state message in the middle of a log stops the reader there. */
static void test_log_unknown_version(void **state)
{
    tl_net a, b;
    duel_controller w, e;
    duel_result res;
    duel_lcm_reader rd;
    duel_lcm_event ev;
    duel_lcm_game *g;
    char path[256], bad[256], err[512];
    uint64_t patch = 0;
    FILE *f;
    int n = 0;
    (void)state;

    tl_net_make(&a, 41, 0, 39);
    tl_net_make(&b, 42, 1, 40);
    w.net = &a.net;
    e.net = &b.net;
    tl_path(path, sizeof path, "v");
    tl_path(bad, sizeof bad, "v99");
    assert_int_equal(duel_lcm_record_game(path, NULL, &w, &e, DUEL_TRAINING, "a", "b", &res, err, sizeof err), 0);
    assert_true(res.steps > 20);
    /* the 21st state message (step 20): its version field follows the 8-byte fingerprint */
    assert_int_equal(duel_lcm_reader_open(&rd, path, err, sizeof err), 0);
    while (duel_lcm_reader_next(&rd, &ev, err, sizeof err) == 1)
        if (strcmp(ev.channel, DUEL_CH_STATE) == 0 && n++ == 20) {
            patch = ev.offset + 28 + strlen(ev.channel) + 8 + 3;
            break;
        }
    duel_lcm_reader_close(&rd);
    assert_true(patch != 0);
    tl_copy_prefix(path, bad, tl_file_size(path));
    f = fopen(bad, "r+b");
    fseek(f, (long)patch, SEEK_SET);
    putc(99, f);
    fclose(f);
    assert_int_equal(duel_lcm_game_read(&g, bad, err, sizeof err), -2);
    assert_non_null(strstr(err, "DUEL_STATE: duel.state_t format version 99, this reader knows only version 1"));
    assert_int_equal(g->rows, 19); /* step 19 needs the state of step 20 for its event */
    duel_lcm_game_free(g);
    unlink(path);
    unlink(bad);
}

/* Replay frames from a log: the frames of duel_replay.h, the last one the
 * final state (the same as duel_replay_from_game's when it is linked). */
static void test_replay_frames(void **state)
{
    static tl_trace tr;
    tl_net a, b;
    duel_controller w, e;
    duel_result res;
    duel_replay r;
    char path[256], err[512];
    const duel_frame *last;
    uint32_t t;
    (void)state;

    tl_net_make(&a, 51, 2, 70);
    tl_net_make(&b, 52, 2, 70);
    w.net = &a.net;
    e.net = &b.net;
    tl_path(path, sizeof path, "replay");
    assert_int_equal(duel_lcm_record_game(path, NULL, &w, &e, 3, "net-a", "net-b", &res, err, sizeof err), 0);
    memset(&tr, 0, sizeof tr);
    assert_int_equal(duel_play(&w, &e, 3, &res, tl_trace_fn, &tr), DUEL_OK);
    memset(&r, 0, sizeof r);
    assert_int_equal(duel_replay_from_lcm_log(&r, path, err, sizeof err), 0);
    assert_int_equal(r.n, res.steps + 1);
    assert_int_equal(r.food_config, 3);
    assert_string_equal(r.west, "net-a");
    assert_string_equal(r.east, "net-b");
    for (t = 0; t < res.steps; t++) {
        assert_int_equal(r.frames[t].t, t);
        tl_world_equal(&r.frames[t].w, &tr.w[t]);
        assert_memory_equal(r.frames[t].in, tr.in[t], sizeof tr.in[t]);
        assert_memory_equal(r.frames[t].out, tr.out[t], sizeof tr.out[t]);
        assert_memory_equal(&r.frames[t].ev, &tr.ev[t], sizeof tr.ev[t]);
    }
    last = &r.frames[res.steps];
    assert_int_equal(last->t, res.steps);
    assert_int_equal(last->ev.outcome, res.outcome);
    assert_int_equal(last->w.robot[0].energy, res.energy[0]);
#ifdef TL_HAVE_REPLAY_GAME
    {
        duel_replay r2;
        duel_replay_init(&r2);
        assert_int_equal(duel_replay_from_game(&r2, &w, &e, 3), 0);
        assert_int_equal(r2.n, r.n);
        for (t = 0; t < r.n; t++) {
            assert_int_equal(r2.frames[t].t, r.frames[t].t);
            tl_world_equal(&r2.frames[t].w, &r.frames[t].w);
            assert_memory_equal(r2.frames[t].in, r.frames[t].in, sizeof r.frames[t].in);
            assert_memory_equal(r2.frames[t].out, r.frames[t].out, sizeof r.frames[t].out);
            assert_memory_equal(&r2.frames[t].ev, &r.frames[t].ev, sizeof r.frames[t].ev);
        }
        duel_replay_free(&r2);
    }
#endif
    free(r.frames);
    /* a truncated log: -1 and one line naming the file and the offset */
    tl_copy_prefix(path, "test_lcm_cut_replay.lcm", tl_file_size(path) - 10);
    memset(&r, 0, sizeof r);
    assert_int_equal(duel_replay_from_lcm_log(&r, "test_lcm_cut_replay.lcm", err, sizeof err), -1);
    assert_non_null(strstr(err, "test_lcm_cut_replay.lcm: offset "));
    assert_non_null(strstr(err, "truncated"));
    assert_null(strchr(err, '\n'));
    free(r.frames);
    unlink("test_lcm_cut_replay.lcm");
    unlink(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_decode_checks),
        cmocka_unit_test(test_decode_hostile),
        cmocka_unit_test(test_state_roundtrip),
        cmocka_unit_test(test_state_read_rejects),
        cmocka_unit_test(test_memq_nodes_equal_play),
        cmocka_unit_test(test_memq_forfeit),
        cmocka_unit_test(test_log_truncated),
        cmocka_unit_test(test_log_unknown_version),
        cmocka_unit_test(test_replay_frames),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
