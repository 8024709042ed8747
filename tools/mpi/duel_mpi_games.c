/* duel_mpi_games.c - a run's games over the ranks of an MPI job: the leader hands out chunks with the champion blobs they need, the ranks play them on their threads and send the results back. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "duel_mpi_internal.h"
#include "duel_mpi_wire.h"
#include "neat.h"

/*
 * Each batch of neat_coev_step (a generation's host games, the champion's
 * comparison, each dominance comparison) is a list of games known in
 * advance. The leader (rank 0 of a run) keeps it in duel_games: its own
 * threads take chunks of it, and so does this file for every other rank,
 * two chunks per rank in flight so that a rank never waits for the next.
 * A chunk carries the games (which two networks, which food, which side)
 * and the blob of every network the rank has not yet been sent in this
 * batch: each network crosses the network once per rank and batch. The
 * results are pure functions of the blobs, so who plays a game does not
 * matter: the run is the same with 1 rank or N.
 */

#define DUEL_MPI_CHUNK 24u /* games per chunk per thread of the rank: one host's games at the paper's protocol */

/* ---- the leader's side */

typedef struct duel_slot {
    int busy;
    size_t from, count;
    double sent_at; /* CLOCK_MONOTONIC seconds: the deadline counts from here */
    uint8_t *buf;
    size_t cap;
    MPI_Request req;
} duel_slot;

typedef struct duel_peer {
    int rank;          /* in the games communicator */
    uint32_t chunk;    /* games per chunk */
    duel_slot slot[2]; /* oldest first */
    uint8_t *sent;     /* [nets_cap] 1 when net i of this batch was sent to it */
} duel_peer;

typedef struct duel_disp {
    MPI_Comm comm;
    int n_peers;
    duel_peer *peers;
    uint64_t batch; /* duel_games' number of the batch in flight */
    uint64_t seq;   /* its number on the wire: unique in this process, whatever run or task it belongs to */
    /* the batch's networks: genome -> id (open addressing), id -> blob */
    const neat_genome **hkey;
    uint32_t *hval;
    size_t hcap;
    uint32_t n_nets;
    size_t nets_cap, *off, *len;
    uint8_t *blob;
    size_t blob_len, blob_cap;
    uint8_t *rbuf;
} duel_disp;

static duel_disp *duel_disp_g = NULL;

static void duel_disp_reset(duel_disp *d, size_t n_games)
{
    size_t want = 64;
    int k;
    while (want < 4 * (n_games + 1))
        want *= 2;
    if (want > d->hcap) {
        free(d->hkey);
        free(d->hval);
        d->hkey = (const neat_genome **)calloc(want, sizeof *d->hkey);
        d->hval = (uint32_t *)calloc(want, sizeof *d->hval);
        d->hcap = d->hkey != NULL && d->hval != NULL ? want : 0;
    } else if (d->hcap) {
        memset(d->hkey, 0, d->hcap * sizeof *d->hkey);
    }
    for (k = 0; k < d->n_peers && d->nets_cap; k++)
        memset(d->peers[k].sent, 0, d->nets_cap);
    d->n_nets = 0;
    d->blob_len = 0;
}

/* Room for n networks in the batch: their offsets and lengths, and each peer's record of what it was sent. 0 or -1. */
static int duel_disp_room(duel_disp *d, size_t n)
{
    int k;
    if (n > d->nets_cap) {
        size_t old = d->nets_cap, c1 = d->nets_cap, c2 = d->nets_cap;
        if (duel_grow((void **)&d->off, &c1, n, sizeof *d->off) != 0 ||
            duel_grow((void **)&d->len, &c2, n, sizeof *d->len) != 0)
            return -1;
        d->nets_cap = c1 < c2 ? c1 : c2;
        for (k = 0; k < d->n_peers; k++) {
            uint8_t *ns = (uint8_t *)realloc(d->peers[k].sent, d->nets_cap);
            if (ns == NULL)
                return -1;
            memset(ns + old, 0, d->nets_cap - old);
            d->peers[k].sent = ns;
        }
    }
    return 0;
}

/* The id of g's network in this batch, its blob written on first sight. -1 if it cannot be encoded (*err). */
static long duel_disp_net(duel_disp *d, const neat_genome *g, const neat_params *p, int *err)
{
    size_t h = (size_t)(((uintptr_t)g >> 4) * 11400714819323198485ull) & (d->hcap - 1), need;
    uint32_t id;
    while (d->hkey[h] != NULL) {
        if (d->hkey[h] == g)
            return (long)d->hval[h];
        h = (h + 1) & (d->hcap - 1);
    }
    need = neat_blob_size(g);
    if (d->n_nets + 1u >= DUEL_MPI_MAX_NETS) {
        *err = NEAT_E_NOMEM;
        return -1;
    }
    if (duel_disp_room(d, d->n_nets + 1u) != 0) {
        *err = NEAT_E_NOMEM;
        return -1;
    }
    if (duel_grow((void **)&d->blob, &d->blob_cap, d->blob_len + need, 1) != 0) {
        *err = NEAT_E_NOMEM;
        return -1;
    }
    id = d->n_nets;
    *err = neat_blob_write_step(g, p->n_inputs, p->n_outputs, p->net_step, d->blob + d->blob_len, need, &d->len[id]);
    if (*err)
        return -1;
    d->off[id] = d->blob_len;
    d->blob_len += d->len[id];
    d->n_nets++;
    d->hkey[h] = g;
    d->hval[h] = id;
    return (long)id;
}

/* Packs games [from, from + count) for peer k into slot s and sends it. 0; 1 when a network could not be encoded
 * (the batch's error is set); -1 when MPI failed. */
static double duel_disp_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* How long rank 0 waits for a chunk's results before it takes the rank for frozen (SIGSTOP, a machine that
 * stopped answering: a dead rank ends the job at once, a frozen one would hold it for ever): a base, 60 s
 * (DUEL_MPI_WAIT seconds in the environment instead), plus 0.25 s a game in flight to that rank, which no game
 * comes near (the slowest, two 256-node networks for 750 steps, takes well under 0.1 s). docs/cluster.md. */
static double duel_disp_deadline(const duel_peer *pe)
{
    size_t games = pe->slot[0].count + (pe->slot[1].busy ? pe->slot[1].count : 0);
    return duel_mpi_wait_base() + 0.25 * (double)games;
}

/* Ends the job when a rank has held a chunk past its deadline: one line naming it, then MPI_Abort (MPI_Finalize
 * would wait for the frozen rank). */
static void duel_disp_check_deadlines(const duel_disp *d)
{
    double now = duel_disp_now();
    int k;
    for (k = 0; k < d->n_peers; k++) {
        const duel_peer *pe = &d->peers[k];
        double limit;
        if (!pe->slot[0].busy)
            continue;
        limit = duel_disp_deadline(pe);
        if (now - pe->slot[0].sent_at > limit) {
            fprintf(stderr, "duel_evolve: mpi: rank %d has not answered for %.0f s (%zu games in flight to it, at "
                            "most %.0f s allowed): it is frozen or cut off; ending the job (resume the run to go "
                            "on)\n", pe->rank, now - pe->slot[0].sent_at,
                    pe->slot[0].count + (pe->slot[1].busy ? pe->slot[1].count : 0), limit);
            fflush(stderr);
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
    }
}

static int duel_disp_send(duel_disp *d, duel_games *dg, duel_peer *pe, duel_slot *s, size_t from, size_t count)
{
    size_t n_all, i, pos, n_new = 0, n_nets = 0;
    uint64_t batch;
    neat_game *games = duel_games_batch(dg, &n_all, &batch);
    const duel_net *nets = NULL;
    duel_match *matches = duel_games_batch_matches(dg, &nets, &n_nets);
    const neat_params *p = duel_games_params(dg);
    duel_work_hdr h;
    uint32_t *ids;
    int err = 0;
    ids = (uint32_t *)malloc(2 * count * sizeof *ids);
    if (ids == NULL) {
        duel_games_remote_done(dg, 0, 0, NEAT_E_NOMEM, from);
        return 1;
    }
    for (i = 0; i < 2 * count; i++) {
        long id;
        if (matches != NULL) {
            /* a batch of matches names its networks by index */
            id = (long)(i % 2 ? matches[from + i / 2].b : matches[from + i / 2].a);
        } else {
            const neat_game *gm = &games[from + i / 2];
            id = duel_disp_net(d, i % 2 ? gm->b : gm->a, p, &err);
        }
        if (id < 0) {
            free(ids);
            duel_games_remote_done(dg, 0, 0, err, from + i / 2);
            return 1;
        }
        ids[i] = (uint32_t)id;
    }
    /* the size: the header, the networks it lacks, the games */
    pos = sizeof h;
    for (i = 0; i < 2 * count; i++)
        if (!pe->sent[ids[i]]) {
            pe->sent[ids[i]] = 2; /* in this message */
            pos += 8 + (matches != NULL ? (nets[ids[i]].blob != NULL ? nets[ids[i]].len : 0) : d->len[ids[i]]);
            n_new++;
        }
    pos += count * sizeof(duel_wire_match);
    if (duel_grow((void **)&s->buf, &s->cap, pos, 1) != 0) {
        free(ids);
        duel_games_remote_done(dg, 0, 0, NEAT_E_NOMEM, from);
        return 1;
    }
    memset(&h, 0, sizeof h);
    h.magic = DUEL_MPI_WORK_MAGIC;
    h.count = (uint32_t)count;
    h.batch = d->seq;
    h.from = from;
    h.n_new = (uint32_t)n_new;
    if (duel_rules_encode(duel_games_rules(dg), h.rules) != DUEL_OK) {
        free(ids);
        duel_games_remote_done(dg, 0, 0, DUEL_E_RULES - 200, from);
        return 1;
    }
    memcpy(s->buf, &h, sizeof h);
    pos = sizeof h;
    for (i = 0; i < 2 * count; i++)
        if (pe->sent[ids[i]] == 2) {
            const uint8_t *blob;
            uint32_t w[2];
            w[0] = ids[i];
            if (matches != NULL) {
                blob = nets[ids[i]].blob;
                w[1] = blob != NULL ? (uint32_t)nets[ids[i]].len : DUEL_WIRE_BUILTIN + (uint32_t)nets[ids[i]].len;
            } else {
                blob = d->blob + d->off[ids[i]];
                w[1] = (uint32_t)d->len[ids[i]];
            }
            memcpy(s->buf + pos, w, sizeof w);
            if (blob != NULL)
                memcpy(s->buf + pos + 8, blob, w[1]);
            pos += 8 + (blob != NULL ? w[1] : 0u);
            pe->sent[ids[i]] = 1;
        }
    for (i = 0; i < count; i++) {
        duel_wire_match m;
        memset(&m, 0, sizeof m);
        m.a = ids[2 * i];
        m.b = ids[2 * i + 1];
        m.config = matches != NULL ? matches[from + i].config : games[from + i].config;
        m.a_first = matches != NULL ? matches[from + i].a_first : games[from + i].a_first;
        memcpy(s->buf + pos, &m, sizeof m);
        pos += sizeof m;
    }
    free(ids);
    if (MPI_Isend(s->buf, (int)pos, MPI_BYTE, pe->rank, DUEL_TAG_WORK, d->comm, &s->req) != MPI_SUCCESS)
        return -1;
    duel_mpi_g.stats.sent_msgs++;
    duel_mpi_g.stats.sent_bytes += pos;
    s->busy = 1;
    s->from = from;
    s->count = count;
    s->sent_at = duel_disp_now();
    return 0;
}

/* Fills peer k's free slots with games not yet handed out. -1 when MPI failed. */
static int duel_disp_fill(duel_disp *d, duel_games *dg, duel_peer *pe)
{
    int j;
    for (j = 0; j < 2; j++) {
        size_t from, got;
        int r;
        if (pe->slot[0].busy && pe->slot[1].busy)
            return 0;
        got = duel_games_take(dg, pe->chunk, &from);
        if (got == 0)
            return 0;
        if (pe->slot[0].busy) { /* the free one goes second: results come back in the order sent */
            r = duel_disp_send(d, dg, pe, &pe->slot[1], from, got);
        } else {
            r = duel_disp_send(d, dg, pe, &pe->slot[0], from, got);
        }
        if (r != 0)
            return r < 0 ? -1 : 0;
    }
    return 0;
}

static int duel_disp_in_flight(const duel_disp *d)
{
    int k, n = 0;
    for (k = 0; k < d->n_peers; k++)
        n += d->peers[k].slot[0].busy + d->peers[k].slot[1].busy;
    return n;
}

/* duel_remote_fn */
static int duel_disp_poll(void *ud, duel_games *dg)
{
    duel_disp *d = (duel_disp *)ud;
    size_t n;
    uint64_t batch;
    neat_game *games = duel_games_batch(dg, &n, &batch);
    const duel_net *nets = NULL;
    size_t n_nets = 0;
    duel_match *matches = duel_games_batch_matches(dg, &nets, &n_nets);
    int k, flag;
    if (batch != d->batch) {
        d->batch = batch;
        d->seq++;
        duel_mpi_g.stats.batches++;
        duel_disp_reset(d, n);
        if (d->hcap == 0 || (matches != NULL && (n_nets >= DUEL_MPI_MAX_NETS || duel_disp_room(d, n_nets) != 0)))
            return -1;
        for (k = 0; k < d->n_peers; k++)
            if (duel_disp_fill(d, dg, &d->peers[k]) != 0)
                return -1;
        return duel_disp_in_flight(d);
    }
    for (;;) {
        MPI_Status st;
        duel_result_hdr h;
        duel_peer *pe = NULL;
        duel_slot done;
        int count = 0;
        size_t i;
        if (MPI_Iprobe(MPI_ANY_SOURCE, DUEL_TAG_RESULT, d->comm, &flag, &st) != MPI_SUCCESS)
            return -1;
        if (!flag) {
            duel_disp_check_deadlines(d);
            break;
        }
        MPI_Get_count(&st, MPI_BYTE, &count);
        for (k = 0; k < d->n_peers; k++)
            if (d->peers[k].rank == st.MPI_SOURCE)
                pe = &d->peers[k];
        if (pe == NULL || !pe->slot[0].busy) {
            fprintf(stderr, "duel_evolve: mpi: a result of %d bytes from rank %d that no chunk asked for\n", count,
                    st.MPI_SOURCE);
            return -1;
        }
        d->rbuf = (uint8_t *)realloc(d->rbuf, (size_t)count);
        if (d->rbuf == NULL ||
            MPI_Recv(d->rbuf, count, MPI_BYTE, st.MPI_SOURCE, DUEL_TAG_RESULT, d->comm, MPI_STATUS_IGNORE) !=
                MPI_SUCCESS)
            return -1;
        duel_mpi_g.stats.recv_msgs++;
        duel_mpi_g.stats.recv_bytes += (uint64_t)count;
        if (duel_wire_result_read(d->rbuf, (size_t)count, d->seq, pe->slot[0].from, pe->slot[0].count, &h) != 0) {
            fprintf(stderr, "duel_evolve: mpi: rank %d answered another chunk than it was sent\n", st.MPI_SOURCE);
            return -1;
        }
        for (i = 0; i < h.count; i++) {
            if (matches != NULL)
                matches[h.from + i].result = (int8_t)d->rbuf[sizeof h + i];
            else
                games[h.from + i].result = (int8_t)d->rbuf[sizeof h + i];
        }
        MPI_Wait(&pe->slot[0].req, MPI_STATUS_IGNORE);
        done = pe->slot[0];
        pe->slot[0] = pe->slot[1];
        pe->slot[1] = done;
        pe->slot[1].busy = 0;
        duel_games_remote_done(dg, h.count, h.steps, h.err, h.from + h.err_at);
        if (duel_disp_fill(d, dg, pe) != 0)
            return -1;
    }
    return duel_disp_in_flight(d);
}

void duel_mpi_attach(duel_games *dg)
{
    duel_disp *d = duel_disp_g;
    MPI_Group gg, gw;
    int size, me, k, n = 0;
    if (!duel_mpi_g.active)
        return;
    MPI_Comm_size(duel_mpi_g.games_comm, &size);
    MPI_Comm_rank(duel_mpi_g.games_comm, &me);
    if (size < 2)
        return;
    if (d == NULL) {
        d = (duel_disp *)calloc(1, sizeof *d);
        if (d == NULL)
            return; /* played here alone: slower, the same run */
        d->peers = (duel_peer *)calloc((size_t)size, sizeof *d->peers);
        if (d->peers == NULL) {
            free(d);
            return;
        }
        d->comm = duel_mpi_g.games_comm;
        /* each peer's threads, from the start-up exchange (indexed by world rank) */
        MPI_Comm_group(d->comm, &gg);
        MPI_Comm_group(MPI_COMM_WORLD, &gw);
        for (k = 0; k < size; k++) {
            int world;
            if (k == me)
                continue;
            MPI_Group_translate_ranks(gg, 1, &k, gw, &world);
            d->peers[n].rank = k;
            d->peers[n].chunk = DUEL_MPI_CHUNK * (duel_mpi_g.peers[world].threads ? duel_mpi_g.peers[world].threads : 1);
            n++;
        }
        MPI_Group_free(&gg);
        MPI_Group_free(&gw);
        d->n_peers = n;
        duel_disp_g = d;
    }
    d->batch = 0;
    memset(&duel_mpi_g.stats, 0, sizeof duel_mpi_g.stats); /* this run's messages, from here on */
    duel_games_set_remote(dg, duel_disp_poll, d);
}

uint32_t duel_mpi_games_ranks(void)
{
    int size = 1;
    if (duel_mpi_g.active)
        MPI_Comm_size(duel_mpi_g.games_comm, &size);
    return (uint32_t)size;
}

void duel_mpi_describe(char *out, size_t cap)
{
    int size = 1;
    if (duel_mpi_g.active)
        MPI_Comm_size(duel_mpi_g.games_comm, &size);
    if (size < 2) {
        snprintf(out, cap, "%s", "");
        return;
    }
    snprintf(out, cap, "%d MPI ranks; games sent in %llu messages of %llu bytes, results in %llu of %llu bytes, "
                       "over %llu batches",
             size, (unsigned long long)duel_mpi_g.stats.sent_msgs, (unsigned long long)duel_mpi_g.stats.sent_bytes,
             (unsigned long long)duel_mpi_g.stats.recv_msgs, (unsigned long long)duel_mpi_g.stats.recv_bytes,
             (unsigned long long)duel_mpi_g.stats.batches);
}

/* ---- a rank's side */

int duel_mpi_games_serve(MPI_Comm comm, int leader, uint32_t threads, int *end_status)
{
    duel_games *dg = NULL;
    duel_wire_store store;
    duel_rules rules;
    duel_match *m = NULL;
    size_t m_cap = 0;
    uint8_t *out = NULL;
    size_t out_cap = 0;
    neat_params np = neat_params_default();
    int rc = -1;
    memset(&store, 0, sizeof store);
    if (duel_games_create(&dg, threads, &np) != 0)
        return -1;
    for (;;) {
        uint8_t *buf;
        size_t len;
        MPI_Status st;
        duel_work_hdr h;
        duel_result_hdr r;
        uint64_t steps0;
        int err;
        if (duel_mpi_recv(comm, leader, MPI_ANY_TAG, &buf, &len, &st) != 0)
            break;
        if (st.MPI_TAG == DUEL_TAG_END) {
            int32_t s = 1;
            if (len == sizeof s)
                memcpy(&s, buf, sizeof s);
            free(buf);
            *end_status = s;
            rc = 0;
            break;
        }
        if (st.MPI_TAG != DUEL_TAG_WORK || duel_wire_work_take(&store, buf, len, &h, &rules, &m, &m_cap) != 0) {
            fprintf(stderr, "duel_evolve: mpi: rank %d: a malformed message (tag %d, %zu bytes) from its leader\n",
                    duel_mpi_g.rank, st.MPI_TAG, len);
            free(buf);
            break;
        }
        steps0 = duel_games_steps(dg);
        err = duel_games_set_rules(dg, &rules);
        if (err == 0)
            err = duel_games_play_nets(dg, store.nets, m, h.count);
        memset(&r, 0, sizeof r);
        r.magic = DUEL_MPI_RESULT_MAGIC;
        r.count = h.count;
        r.batch = h.batch;
        r.from = h.from;
        r.err = err;
        r.err_at = err ? duel_games_error_at(dg) : 0;
        r.steps = duel_games_steps(dg) - steps0;
        if (duel_grow((void **)&out, &out_cap, sizeof r + h.count, 1) != 0)
            break;
        memcpy(out, &r, sizeof r);
        {
            size_t i;
            for (i = 0; i < h.count; i++)
                out[sizeof r + i] = (uint8_t)m[i].result;
        }
        if (duel_mpi_send(comm, leader, DUEL_TAG_RESULT, out, sizeof r + h.count) != 0)
            break;
    }
    duel_wire_store_free(&store);
    free(m);
    free(out);
    duel_games_free(dg);
    return rc;
}
