/* duel_pairs.c - a pool of threads taking comparisons in turn, each on its own copies of the networks. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "duel_cores.h"
#include "duel_pairs.h"

typedef struct duel_pairs_job {
    const duel_rules *rules;
    duel_pair *pairs;
    size_t n, next, done;
    pthread_mutex_t lock;
    pthread_cond_t changed;
    int err;
} duel_pairs_job;

/* A controller for this thread: a builtin as it is, a network loaded again
 * into mem (a network has state; threads cannot share one). */
static int duel_pairs_own(const duel_cli_ctrl *c, duel_controller *out, nrt_net *net, void **mem)
{
    size_t need;
    memset(out, 0, sizeof *out);
    *mem = NULL;
    if (c->blob == NULL) {
        out->builtin = c->ctrl.builtin;
        return 0;
    }
    if (nrt_mem_required(c->blob, c->blob_len, &need) != 0 || (*mem = malloc(need)) == NULL ||
        nrt_load(net, c->blob, c->blob_len, *mem, need) != 0)
        return -1;
    out->net = net;
    return 0;
}

static void *duel_pairs_worker(void *arg)
{
    duel_pairs_job *job = (duel_pairs_job *)arg;
    for (;;) {
        duel_controller a, b;
        nrt_net na, nb;
        void *ma = NULL, *mb = NULL;
        size_t k;
        int err;
        pthread_mutex_lock(&job->lock);
        k = job->err ? job->n : job->next++;
        pthread_mutex_unlock(&job->lock);
        if (k >= job->n)
            return NULL;
        err = duel_pairs_own(job->pairs[k].a, &a, &na, &ma) != 0 || duel_pairs_own(job->pairs[k].b, &b, &nb, &mb) != 0;
        if (!err)
            err = duel_compare_rules(job->rules, &a, &b, &job->pairs[k].tally) != 0;
        free(ma);
        free(mb);
        pthread_mutex_lock(&job->lock);
        if (err)
            job->err = -1;
        job->done++;
        pthread_cond_signal(&job->changed);
        pthread_mutex_unlock(&job->lock);
    }
}

int duel_pairs_play(const duel_rules *rules, duel_pair *pairs, size_t n, uint32_t threads, duel_pairs_progress fn,
                    void *ud)
{
    duel_pairs_job job;
    pthread_t th[256];
    uint32_t k, started = 0;

    if (threads == 0)
        threads = duel_cores();
    if (threads > 256)
        threads = 256;
    if ((size_t)threads > n)
        threads = n > 0 ? (uint32_t)n : 1u;
    memset(&job, 0, sizeof job);
    job.rules = rules;
    job.pairs = pairs;
    job.n = n;
    pthread_mutex_init(&job.lock, NULL);
    pthread_cond_init(&job.changed, NULL);
    for (k = 0; k < threads; k++)
        if (pthread_create(&th[started], NULL, duel_pairs_worker, &job) == 0)
            started++;
    if (started == 0) {
        duel_pairs_worker(&job);
    } else {
        /* the calling thread reports progress while the workers play */
        pthread_mutex_lock(&job.lock);
        while (job.done < job.n && !(job.err && job.done == job.next)) {
            struct timespec until;
            clock_gettime(CLOCK_REALTIME, &until);
            until.tv_nsec += 200000000L;
            if (until.tv_nsec >= 1000000000L) {
                until.tv_sec++;
                until.tv_nsec -= 1000000000L;
            }
            pthread_cond_timedwait(&job.changed, &job.lock, &until);
            if (fn != NULL && job.done < job.n) {
                size_t d = job.done;
                pthread_mutex_unlock(&job.lock);
                fn(ud, d, n);
                pthread_mutex_lock(&job.lock);
            }
        }
        pthread_mutex_unlock(&job.lock);
    }
    for (k = 0; k < started; k++)
        pthread_join(th[k], NULL);
    pthread_cond_destroy(&job.changed);
    pthread_mutex_destroy(&job.lock);
    if (fn != NULL && !job.err)
        fn(ud, n, n);
    return job.err;
}
