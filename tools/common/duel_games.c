/* duel_games.c - plays batches of coevolution games on worker threads, every network through the blob and the runtime. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "duel.h"
#include "duel_games.h"
#include "neat_phenotype.h"

/* games handed out per lock: few enough to balance, many enough that the
 * lock is cold; a host's games are consecutive, so its network is reused */
#define DUEL_CHUNK 24u

struct duel_games {
    uint32_t threads;
    neat_params p;
    duel_progress_fn progress;
    void *progress_ud;
    uint64_t played, steps;
    /* the batch in flight */
    pthread_mutex_t lock;
    pthread_cond_t moved;
    neat_game *games;
    size_t n, next, done;
    size_t err_at; /* lowest failing game index, n if none */
    int err;
    uint64_t batch_steps;
};

/* One worker's two networks, reloaded only when the genome changes. */
typedef struct duel_seat {
    neat_phenotype ph;
    const neat_genome *g;
} duel_seat;

static int duel_seat_load(duel_seat *s, const neat_genome *g, const neat_params *p)
{
    int err;
    if (s->g == g)
        return 0; /* duel_play resets the network at the start of a game */
    s->g = NULL;
    err = neat_phenotype_load(&s->ph, g, p);
    if (err == 0)
        s->g = g;
    return err;
}

static int duel_play_one(duel_games *dg, duel_seat seat[2], neat_game *gm, uint32_t *steps)
{
    duel_controller west, east;
    duel_result res;
    int err = duel_seat_load(&seat[0], gm->a, &dg->p);
    if (!err)
        err = duel_seat_load(&seat[1], gm->b, &dg->p);
    if (err)
        return err;
    memset(&west, 0, sizeof west);
    memset(&east, 0, sizeof east);
    west.net = gm->a_first ? &seat[0].ph.net : &seat[1].ph.net;
    east.net = gm->a_first ? &seat[1].ph.net : &seat[0].ph.net;
    err = duel_play(&west, &east, gm->config < 0 ? DUEL_TRAINING : gm->config, &res, NULL, NULL);
    if (err)
        return err - 200;
    *steps = res.steps;
    if (res.outcome == DUEL_WEST_WINS)
        gm->result = gm->a_first ? 1 : -1;
    else if (res.outcome == DUEL_EAST_WINS)
        gm->result = gm->a_first ? -1 : 1;
    else
        gm->result = 0;
    return 0;
}

static void *duel_worker(void *arg)
{
    duel_games *dg = (duel_games *)arg;
    duel_seat seat[2];
    uint64_t steps = 0;
    int k;
    for (k = 0; k < 2; k++) {
        neat_phenotype_init(&seat[k].ph);
        seat[k].g = NULL;
    }
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
        for (i = from; i < to; i++) {
            uint32_t s = 0;
            int err = duel_play_one(dg, seat, &dg->games[i], &s);
            steps += s;
            if (err) {
                pthread_mutex_lock(&dg->lock);
                if (i < dg->err_at) {
                    dg->err_at = i;
                    dg->err = err;
                }
                dg->next = dg->n; /* stop handing out work */
                pthread_mutex_unlock(&dg->lock);
                break;
            }
        }
        pthread_mutex_lock(&dg->lock);
        dg->done += i - from;
        pthread_cond_signal(&dg->moved);
        pthread_mutex_unlock(&dg->lock);
    }
    for (k = 0; k < 2; k++)
        neat_phenotype_free(&seat[k].ph);
    return NULL;
}

int duel_games_create(duel_games **out, uint32_t threads, const neat_params *p)
{
    duel_games *dg = (duel_games *)calloc(1, sizeof *dg);
    if (dg == NULL)
        return NEAT_E_NOMEM;
    if (threads == 0) {
        long n = sysconf(_SC_NPROCESSORS_ONLN);
        threads = n > 0 ? (uint32_t)n : 1u;
    }
    dg->threads = threads;
    dg->p = *p;
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

void duel_games_on_progress(duel_games *dg, duel_progress_fn fn, void *ud)
{
    dg->progress = fn;
    dg->progress_ud = ud;
}

uint64_t duel_games_played(const duel_games *dg)
{
    return dg->played;
}

uint64_t duel_games_steps(const duel_games *dg)
{
    return dg->steps;
}

int duel_games_play(void *ud, neat_game *games, size_t n)
{
    duel_games *dg = (duel_games *)ud;
    pthread_t th[256];
    uint32_t t, nt = dg->threads < 256 ? dg->threads : 256;
    int started = 0;
    if (n == 0)
        return 0;
    if ((size_t)nt > (n + DUEL_CHUNK - 1) / DUEL_CHUNK)
        nt = (uint32_t)((n + DUEL_CHUNK - 1) / DUEL_CHUNK);
    dg->games = games;
    dg->n = n;
    dg->next = dg->done = 0;
    dg->err_at = n;
    dg->err = 0;
    dg->batch_steps = 0;
    for (t = 0; t < nt; t++)
        if (pthread_create(&th[t], NULL, duel_worker, dg) == 0)
            started++;
    if (started == 0)
        duel_worker(dg); /* no thread to be had: play here */
    /* progress while the workers play */
    pthread_mutex_lock(&dg->lock);
    while (started > 0 && dg->done < n && !dg->err) {
        struct timespec until;
        size_t done;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_nsec += 200000000L;
        if (until.tv_nsec >= 1000000000L) {
            until.tv_sec++;
            until.tv_nsec -= 1000000000L;
        }
        pthread_cond_timedwait(&dg->moved, &dg->lock, &until);
        done = dg->done;
        if (dg->progress != NULL && done < n) {
            pthread_mutex_unlock(&dg->lock);
            dg->progress(dg->progress_ud, done, n);
            pthread_mutex_lock(&dg->lock);
        }
    }
    pthread_mutex_unlock(&dg->lock);
    for (t = 0; t < (uint32_t)started; t++)
        pthread_join(th[t], NULL);
    dg->played += dg->done;
    dg->steps += dg->batch_steps;
    if (dg->progress != NULL && !dg->err)
        dg->progress(dg->progress_ud, n, n);
    return dg->err;
}
