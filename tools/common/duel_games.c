/* duel_games.c - plays batches of coevolution games on worker threads, two at a time, every network through the blob and the runtime (and, with a remote executor from tools/mpi, on other processes too). */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "duel.h"
#include "duel_cores.h"
#include "duel_games.h"
#include "neat_phenotype.h"

/* games handed out per lock: few enough to balance, many enough that the
 * lock is cold; a host's games are consecutive, so its network is reused */
#define DUEL_CHUNK 24u

struct duel_games {
    uint32_t threads;
    neat_params p;
    duel_rules rules;       /* the world the games are played in */
    int32_t train_config;   /* the training games' food: DUEL_TRAINING or a comparison layout */
    duel_progress_fn progress;
    void *progress_ud;
    duel_remote_fn remote;
    void *remote_ud;
    uint64_t played, steps, batches;
    double secs; /* wall seconds in batches */
    /* the batch in flight: coevolution games (games) or games between blobs (matches, nets) */
    pthread_mutex_t lock;
    pthread_cond_t moved;
    neat_game *games;
    duel_match *matches;
    const duel_net *nets;
    size_t n_nets;      /* of a batch of matches */
    size_t n, next, done;
    size_t err_at; /* lowest failing game index, n if none */
    int err;
    uint64_t batch_steps;
};

/* A network a worker has loaded, and what it was loaded from. */
typedef struct duel_seat {
    neat_phenotype ph;
    const void *key; /* the genome, or the duel_net */
    int builtin;     /* a duel_net without a blob: that builtin strategy (enum duel_builtin), else -1 */
} duel_seat;

/* Opponents a worker keeps loaded: a generation's hosts all meet the same
 * few (4 species champions and 8 of the Hall of Fame in configs/paper.ini),
 * so each is loaded about once per worker and batch rather than once per
 * host (perf: the loads' checksums were 2 % of a paper-scale generation). */
#define DUEL_KEPT 16u

/* One worker's networks: the hosts (a) of the two games it plays at once,
 * and the opponents (b) it has met, reloaded only when a player is not
 * among them. Per batch: a key is a pointer, which a later batch may reuse
 * for another network. */
typedef struct duel_seats {
    duel_seat host[2], kept[DUEL_KEPT];
    uint32_t next; /* the kept seat to load into next, round robin */
} duel_seats;

static int duel_seat_load(duel_seat *s, const duel_games *dg, const void *key)
{
    int err;
    if (s->key == key)
        return 0; /* duel_play resets the network at the start of a game */
    s->key = NULL;
    s->builtin = -1;
    if (dg->games != NULL) {
        err = neat_phenotype_load(&s->ph, (const neat_genome *)key, &dg->p);
    } else {
        const duel_net *net = (const duel_net *)key;
        if (net->blob == NULL) {
            if (net->len >= DUEL_N_BUILTINS)
                return DUEL_E_ARG - 200;
            s->builtin = (int)net->len;
            err = 0;
        } else {
            err = neat_phenotype_load_blob(&s->ph, net->blob, net->len);
        }
    }
    if (err == 0)
        s->key = key;
    return err;
}

/* The host seat holding key, else key loaded into the one that is not
 * busy (the other game's of a pair; NULL: none is). */
static duel_seat *duel_seat_host(duel_seats *ss, const duel_games *dg, const void *key, const duel_seat *busy,
                                 int *err)
{
    duel_seat *s = busy == &ss->host[0] ? &ss->host[1] : &ss->host[0];
    if (ss->host[0].key == key)
        return &ss->host[0];
    if (ss->host[1].key == key)
        return &ss->host[1];
    *err = duel_seat_load(s, dg, key);
    return s;
}

/* The kept seat holding key, loaded into the next one that is not busy if
 * none does. */
static duel_seat *duel_seat_kept(duel_seats *ss, const duel_games *dg, const void *key, const duel_seat *busy,
                                 int *err)
{
    duel_seat *s;
    uint32_t k;
    for (k = 0; k < DUEL_KEPT; k++)
        if (ss->kept[k].key == key)
            return &ss->kept[k];
    if (&ss->kept[ss->next] == busy)
        ss->next = (ss->next + 1u) % DUEL_KEPT;
    s = &ss->kept[ss->next];
    ss->next = (ss->next + 1u) % DUEL_KEPT;
    *err = duel_seat_load(s, dg, key);
    return s;
}

/* Game i of the batch set up: its players loaded (into seats other than
 * the busy ones, those of a game being played with it), its sides and
 * food. */
typedef struct duel_setup {
    duel_seat *host, *opp;
    duel_controller west, east;
    int config, a_first;
} duel_setup;

/* the controller of what a seat holds: its network, or its builtin */
static void duel_seat_controller(duel_seat *s, duel_controller *c)
{
    memset(c, 0, sizeof *c);
    if (s->builtin >= 0)
        c->builtin = s->builtin;
    else
        c->net = &s->ph.net;
}

static int duel_setup_game(duel_games *dg, duel_seats *ss, size_t i, const duel_setup *busy, duel_setup *g)
{
    const void *a, *b;
    int err = 0;
    if (dg->games != NULL) {
        a = dg->games[i].a;
        b = dg->games[i].b;
        g->config = dg->games[i].config;
        g->a_first = dg->games[i].a_first;
    } else {
        a = &dg->nets[dg->matches[i].a];
        b = &dg->nets[dg->matches[i].b];
        g->config = dg->matches[i].config;
        g->a_first = dg->matches[i].a_first;
    }
    if (g->config < 0)
        g->config = DUEL_TRAINING;
    g->host = duel_seat_host(ss, dg, a, busy != NULL ? busy->host : NULL, &err);
    if (err)
        return err;
    g->opp = duel_seat_kept(ss, dg, b, busy != NULL ? busy->opp : NULL, &err);
    if (err)
        return err;
    duel_seat_controller(g->a_first ? g->host : g->opp, &g->west);
    duel_seat_controller(g->a_first ? g->opp : g->host, &g->east);
    return 0;
}

/* Game i's result, for a (1 won, -1 lost, 0 neither) */
static void duel_record_game(duel_games *dg, size_t i, const duel_setup *g, const duel_result *res)
{
    int8_t result;
    if (res->outcome == DUEL_WEST_WINS)
        result = g->a_first ? 1 : -1;
    else if (res->outcome == DUEL_EAST_WINS)
        result = g->a_first ? -1 : 1;
    else
        result = 0;
    if (dg->games != NULL)
        dg->games[i].result = result;
    else
        dg->matches[i].result = result;
}

/* Game i of the batch: played, its result set. */
static int duel_play_one(duel_games *dg, duel_seats *ss, size_t i, uint32_t *steps)
{
    duel_setup g;
    duel_result res;
    int err = duel_setup_game(dg, ss, i, NULL, &g);
    if (err)
        return err;
    err = duel_play_rules(&dg->rules, &g.west, &g.east, g.config, &res, NULL, NULL);
    if (err)
        return err - 200;
    *steps = res.steps;
    duel_record_game(dg, i, &g, &res);
    return 0;
}

/* Games i and i + 1 at once (duel_play2: the same results, faster), or on
 * a failure one by one, so that the error and *at (the failing game) are
 * those of duel_play_one. */
static int duel_play_two(duel_games *dg, duel_seats *ss, size_t i, uint32_t *steps, size_t *at)
{
    duel_setup g[2];
    duel_result res[2];
    duel_controller *west[2], *east[2];
    int config[2], err, k;
    err = duel_setup_game(dg, ss, i, NULL, &g[0]);
    if (err == 0)
        err = duel_setup_game(dg, ss, i + 1, &g[0], &g[1]);
    if (err == 0) {
        for (k = 0; k < 2; k++) {
            west[k] = &g[k].west;
            east[k] = &g[k].east;
            config[k] = g[k].config;
        }
        err = duel_play2_rules(&dg->rules, west, east, config, res);
    }
    if (err == 0) {
        for (k = 0; k < 2; k++)
            duel_record_game(dg, i + (size_t)k, &g[k], &res[k]);
        *steps = res[0].steps + res[1].steps;
        return 0;
    }
    *steps = 0;
    for (k = 0; k < 2; k++) {
        uint32_t s = 0;
        *at = i + (size_t)k;
        err = duel_play_one(dg, ss, *at, &s);
        if (err)
            return err;
        *steps += s;
    }
    return 0;
}

/* The lowest failing game wins, whoever played it: the error is the same whatever the threads or ranks. */
static void duel_fail_locked(duel_games *dg, size_t at, int err)
{
    if (at < dg->err_at) {
        dg->err_at = at;
        dg->err = err;
    }
    dg->next = dg->n; /* stop handing out work */
}

static void *duel_worker(void *arg)
{
    duel_games *dg = (duel_games *)arg;
    duel_seats *ss = (duel_seats *)malloc(sizeof *ss);
    uint64_t steps = 0;
    uint32_t k;
    if (ss == NULL) {
        pthread_mutex_lock(&dg->lock);
        duel_fail_locked(dg, dg->next, NEAT_E_NOMEM);
        pthread_mutex_unlock(&dg->lock);
        return NULL;
    }
    for (k = 0; k < 2; k++) {
        neat_phenotype_init(&ss->host[k].ph, NULL);
        ss->host[k].key = NULL;
        ss->host[k].builtin = -1;
    }
    for (k = 0; k < DUEL_KEPT; k++) {
        neat_phenotype_init(&ss->kept[k].ph, NULL);
        ss->kept[k].key = NULL;
        ss->kept[k].builtin = -1;
    }
    ss->next = 0;
    for (;;) {
        size_t i, from, to;
        pthread_mutex_lock(&dg->lock);
        dg->batch_steps += steps;
        steps = 0;
        from = dg->next;
        to = from + DUEL_CHUNK < dg->n ? from + DUEL_CHUNK : dg->n;
        dg->next = to;
        pthread_mutex_unlock(&dg->lock);
        if (from >= to)
            break;
        for (i = from; i < to;) {
            /* two games at a time (a chunk's games are one host's, mostly) */
            uint32_t s = 0;
            size_t at = i, n = i + 1 < to ? 2 : 1;
            int err = n == 2 ? duel_play_two(dg, ss, i, &s, &at) : duel_play_one(dg, ss, i, &s);
            steps += s;
            if (err) {
                pthread_mutex_lock(&dg->lock);
                duel_fail_locked(dg, at, err);
                pthread_mutex_unlock(&dg->lock);
                i = at;
                break;
            }
            i += n;
        }
        pthread_mutex_lock(&dg->lock);
        dg->done += i - from;
        pthread_cond_signal(&dg->moved);
        pthread_mutex_unlock(&dg->lock);
    }
    for (k = 0; k < 2; k++)
        neat_phenotype_free(&ss->host[k].ph);
    for (k = 0; k < DUEL_KEPT; k++)
        neat_phenotype_free(&ss->kept[k].ph);
    free(ss);
    return NULL;
}

int duel_games_create(duel_games **out, uint32_t threads, const neat_params *p)
{
    duel_games *dg = (duel_games *)calloc(1, sizeof *dg);
    if (dg == NULL)
        return NEAT_E_NOMEM;
    if (threads == 0)
        threads = duel_cores();
    dg->threads = threads;
    dg->p = *p;
    dg->rules = *duel_rules_v1();
    dg->train_config = DUEL_TRAINING;
    pthread_mutex_init(&dg->lock, NULL);
    pthread_cond_init(&dg->moved, NULL);
    *out = dg;
    return 0;
}

void duel_games_free(duel_games *dg)
{
    if (dg == NULL)
        return;
    pthread_mutex_destroy(&dg->lock);
    pthread_cond_destroy(&dg->moved);
    free(dg);
}

uint32_t duel_games_threads(const duel_games *dg)
{
    return dg->threads;
}

const neat_params *duel_games_params(const duel_games *dg)
{
    return &dg->p;
}

void duel_games_set_params(duel_games *dg, const neat_params *p)
{
    dg->p = *p;
}

int duel_games_set_rules(duel_games *dg, const duel_rules *r)
{
    if (duel_rules_check(r, NULL, NULL) != DUEL_OK)
        return DUEL_E_RULES;
    dg->rules = *r;
    return 0;
}

const duel_rules *duel_games_rules(const duel_games *dg)
{
    return &dg->rules;
}

void duel_games_set_training(duel_games *dg, int32_t config)
{
    dg->train_config = config;
}

void duel_games_on_progress(duel_games *dg, duel_progress_fn fn, void *ud)
{
    dg->progress = fn;
    dg->progress_ud = ud;
}

void duel_games_set_remote(duel_games *dg, duel_remote_fn fn, void *ud)
{
    dg->remote = fn;
    dg->remote_ud = ud;
}

uint64_t duel_games_played(const duel_games *dg)
{
    return dg->played;
}

uint64_t duel_games_steps(const duel_games *dg)
{
    return dg->steps;
}

double duel_games_seconds(const duel_games *dg)
{
    return dg->secs;
}

neat_game *duel_games_batch(duel_games *dg, size_t *n, uint64_t *batch_no)
{
    *n = dg->n;
    *batch_no = dg->batches;
    return dg->games;
}

duel_match *duel_games_batch_matches(duel_games *dg, const duel_net **nets, size_t *n_nets)
{
    *nets = dg->nets;
    *n_nets = dg->n_nets;
    return dg->games == NULL ? dg->matches : NULL;
}

size_t duel_games_error_at(const duel_games *dg)
{
    return dg->err_at;
}

size_t duel_games_take(duel_games *dg, size_t max, size_t *from)
{
    size_t got;
    pthread_mutex_lock(&dg->lock);
    *from = dg->next;
    got = dg->n - dg->next < max ? dg->n - dg->next : max;
    dg->next += got;
    pthread_mutex_unlock(&dg->lock);
    return got;
}

void duel_games_remote_done(duel_games *dg, size_t count, uint64_t steps, int err, size_t err_at)
{
    pthread_mutex_lock(&dg->lock);
    dg->done += count;
    dg->batch_steps += steps;
    if (err)
        duel_fail_locked(dg, err_at, err);
    pthread_mutex_unlock(&dg->lock);
}

static double duel_games_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec / 1e9;
}

/* The batch set up in dg (games or matches, n): played by the threads here and, with a remote executor, by
 * other processes too, whose share the remote function hands out and collects on this thread. */
static int duel_games_run(duel_games *dg, size_t n)
{
    double t0 = duel_games_now();
    pthread_t th[256];
    uint32_t t, nt = dg->threads < 256 ? dg->threads : 256;
    int started = 0, remote_err = 0;
    dg->n = n;
    dg->next = dg->done = 0;
    dg->err_at = n;
    dg->err = 0;
    dg->batch_steps = 0;
    dg->batches++;
    if ((size_t)nt > (n + DUEL_CHUNK - 1) / DUEL_CHUNK)
        nt = (uint32_t)((n + DUEL_CHUNK - 1) / DUEL_CHUNK);
    /* a remote executor first: its processes start on their share while the threads here start */
    if (dg->remote != NULL && dg->remote(dg->remote_ud, dg) < 0)
        remote_err = 1;
    for (t = 0; t < nt && !remote_err; t++)
        if (pthread_create(&th[t], NULL, duel_worker, dg) == 0)
            started++;
    if (started == 0 && dg->remote == NULL)
        duel_worker(dg); /* no thread to be had: play here */
    /* progress while the workers play (and, with a remote executor, its messages served every millisecond) */
    for (;;) {
        struct timespec until;
        size_t done;
        int in_flight = 0, finished;
        if (dg->remote != NULL && !remote_err) {
            in_flight = dg->remote(dg->remote_ud, dg);
            if (in_flight < 0) {
                remote_err = 1;
                in_flight = 0;
            }
        }
        pthread_mutex_lock(&dg->lock);
        if (started == 0 && dg->remote != NULL && in_flight == 0 && dg->next < n && !remote_err) {
            /* nobody here to play what is left, and no other process asking: play it on this thread */
            pthread_mutex_unlock(&dg->lock);
            duel_worker(dg);
            pthread_mutex_lock(&dg->lock);
        }
        finished = remote_err || ((dg->done >= n || dg->err) && in_flight == 0);
        if (!finished) {
            clock_gettime(CLOCK_REALTIME, &until);
            until.tv_nsec += dg->remote != NULL ? 1000000L : 200000000L;
            if (until.tv_nsec >= 1000000000L) {
                until.tv_sec++;
                until.tv_nsec -= 1000000000L;
            }
            pthread_cond_timedwait(&dg->moved, &dg->lock, &until);
        }
        done = dg->done;
        pthread_mutex_unlock(&dg->lock);
        if (finished)
            break;
        if (dg->progress != NULL && done < n)
            dg->progress(dg->progress_ud, done, n);
    }
    for (t = 0; t < (uint32_t)started; t++)
        pthread_join(th[t], NULL);
    if (remote_err && !dg->err)
        dg->err = DUEL_GAMES_E_REMOTE;
    dg->played += dg->done;
    dg->steps += dg->batch_steps;
    dg->secs += duel_games_now() - t0;
    if (dg->progress != NULL && !dg->err)
        dg->progress(dg->progress_ud, n, n);
    return dg->err;
}

int duel_games_play(void *ud, neat_game *games, size_t n)
{
    duel_games *dg = (duel_games *)ud;
    size_t i;
    if (n == 0)
        return 0;
    /* the generation's training food, written into the games before any is
     * handed out (to this process's workers or to other ranks): libneat
     * only writes a game's configuration */
    if (dg->train_config != DUEL_TRAINING)
        for (i = 0; i < n; i++)
            if (games[i].config < 0)
                games[i].config = dg->train_config;
    dg->games = games;
    dg->matches = NULL;
    dg->nets = NULL;
    return duel_games_run(dg, n);
}

int duel_games_play_nets(duel_games *dg, const duel_net *nets, duel_match *m, size_t n)
{
    duel_remote_fn remote = dg->remote;
    int err;
    if (n == 0)
        return 0;
    dg->games = NULL;
    dg->matches = m;
    dg->nets = nets;
    dg->n_nets = 0;
    dg->remote = NULL; /* games between blobs are another process's share: played here */
    err = duel_games_run(dg, n);
    dg->remote = remote;
    return err;
}

int duel_games_play_matches(duel_games *dg, const duel_net *nets, size_t n_nets, duel_match *m, size_t n)
{
    if (n == 0)
        return 0;
    dg->games = NULL;
    dg->matches = m;
    dg->nets = nets;
    dg->n_nets = n_nets;
    return duel_games_run(dg, n);
}
