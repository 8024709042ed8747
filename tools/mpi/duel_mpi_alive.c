/* duel_mpi_alive.c - signs of life between ranks: a thread that tells the ranks that may wait on this one that it is alive, and the check that ends the job when one waited on has been silent too long. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "duel_mpi_internal.h"
#include "neat_config.h"

/*
 * A wait with work in flight has a deadline derived from that work (rank 0
 * waiting for a chunk's results: duel_mpi_games.c). Other waits have no work
 * to measure: a rank waiting for rank 0's next chunk (rank 0 may be between
 * generations for long), rank 0 waiting for a rank that plays a whole run of
 * an experiment (hours). For those, every rank has a thread that sends a
 * sign of life (an empty DUEL_TAG_ALIVE message) once a second to the ranks
 * that may wait on it: rank 0 to every rank, the others to rank 0 and to the
 * ranks of their experiment group. A frozen process (SIGSTOP, a machine that
 * stopped) stops its thread too, so a rank silent for the deadline's base
 * (60 s, DUEL_MPI_WAIT) is taken for frozen or cut off: one line, then
 * MPI_Abort. A rank busy computing keeps sending: no deadline cuts a long
 * generation or a long run short.
 *
 * The thread needs MPI_THREAD_MULTIPLE; under a library without it there are
 * no signs of life and these waits keep no deadline (docs/cluster.md).
 */

static struct {
    int on;              /* the thread runs */
    int stop;            /* asked to end (under lock) */
    pthread_t thread;
    pthread_mutex_t lock;
    double *heard;       /* [size] CLOCK_MONOTONIC seconds a sign from each rank came last (or the start) */
    unsigned char *to;   /* [size] 1: send it signs */
} duel_alive = {0, 0, 0, PTHREAD_MUTEX_INITIALIZER, NULL, NULL};

static double duel_alive_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

int duel_mpi_wait_parse(double *out)
{
    const char *v = getenv("DUEL_MPI_WAIT");
    char *end;
    double b;
    *out = 60.0;
    if (v == NULL)
        return 0;
    /* the number syntax of every setting (neat_config_number_len): no hex, inf or nan */
    b = neat_config_number_len(v, 0) == strlen(v) && v[0] != '\0' ? strtod(v, &end) : -1.0;
    if (!(b > 0.0 && b <= 1e6))
        return -1;
    *out = b;
    return 0;
}

double duel_mpi_wait_base(void)
{
    static double base = -1.0;
    if (base < 0.0 && duel_mpi_wait_parse(&base) != 0)
        base = 60.0; /* not reached: duel_mpi_start refuses it */
    return base;
}

void duel_mpi_alive_heard(int world_rank)
{
    if (duel_alive.heard == NULL || world_rank < 0 || world_rank >= duel_mpi_g.size)
        return;
    pthread_mutex_lock(&duel_alive.lock);
    duel_alive.heard[world_rank] = duel_alive_now();
    pthread_mutex_unlock(&duel_alive.lock);
}

/* Every sign of life that has come, taken (a matched probe: the main thread may take one too, duel_mpi_recv). */
static void duel_alive_drain(void)
{
    for (;;) {
        int flag = 0;
        MPI_Message msg;
        MPI_Status st;
        if (MPI_Improbe(MPI_ANY_SOURCE, DUEL_TAG_ALIVE, MPI_COMM_WORLD, &flag, &msg, &st) != MPI_SUCCESS || !flag)
            return;
        MPI_Mrecv(NULL, 0, MPI_BYTE, &msg, MPI_STATUS_IGNORE);
        duel_mpi_alive_heard(st.MPI_SOURCE);
    }
}

static void *duel_alive_main(void *arg)
{
    double next = 0.0;
    (void)arg;
    for (;;) {
        double now = duel_alive_now();
        int stop;
        pthread_mutex_lock(&duel_alive.lock);
        stop = duel_alive.stop;
        pthread_mutex_unlock(&duel_alive.lock);
        if (stop)
            break;
        duel_alive_drain();
        if (now >= next) {
            int r;
            for (r = 0; r < duel_mpi_g.size; r++) {
                unsigned char to;
                pthread_mutex_lock(&duel_alive.lock);
                to = duel_alive.to[r];
                pthread_mutex_unlock(&duel_alive.lock);
                if (to) {
                    /* never blocks on a frozen receiver: sent and let go */
                    MPI_Request q;
                    if (MPI_Isend(NULL, 0, MPI_BYTE, r, DUEL_TAG_ALIVE, MPI_COMM_WORLD, &q) == MPI_SUCCESS)
                        MPI_Request_free(&q);
                }
            }
            next = now + 1.0;
        }
        duel_mpi_nap(50000);
    }
    return NULL;
}

int duel_mpi_alive_start(int provided)
{
    int r;
    if (provided < MPI_THREAD_MULTIPLE || duel_mpi_g.size < 2)
        return 0;
    duel_alive.heard = (double *)calloc((size_t)duel_mpi_g.size, sizeof *duel_alive.heard);
    duel_alive.to = (unsigned char *)calloc((size_t)duel_mpi_g.size, 1);
    if (duel_alive.heard == NULL || duel_alive.to == NULL)
        return -1;
    for (r = 0; r < duel_mpi_g.size; r++) {
        duel_alive.heard[r] = duel_alive_now();
        duel_alive.to[r] = r != duel_mpi_g.rank && (duel_mpi_g.rank == 0 || r == 0);
    }
    duel_alive.stop = 0;
    if (pthread_create(&duel_alive.thread, NULL, duel_alive_main, NULL) != 0)
        return -1;
    duel_alive.on = 1;
    return 0;
}

void duel_mpi_alive_link(int world_rank)
{
    if (duel_alive.to == NULL || world_rank < 0 || world_rank >= duel_mpi_g.size || world_rank == duel_mpi_g.rank)
        return;
    pthread_mutex_lock(&duel_alive.lock);
    duel_alive.to[world_rank] = 1;
    duel_alive.heard[world_rank] = duel_alive_now(); /* its signs to this rank start now too */
    pthread_mutex_unlock(&duel_alive.lock);
}

void duel_mpi_alive_check(int world_rank, const char *waiting_for)
{
    double silent, base = duel_mpi_wait_base();
    if (!duel_alive.on || world_rank < 0 || world_rank >= duel_mpi_g.size || world_rank == duel_mpi_g.rank ||
        !duel_mpi_g.peers[world_rank].beats)
        return;
    pthread_mutex_lock(&duel_alive.lock);
    silent = duel_alive_now() - duel_alive.heard[world_rank];
    pthread_mutex_unlock(&duel_alive.lock);
    if (silent <= base)
        return;
    fprintf(stderr, "duel_evolve: mpi: rank %d (on %s) has given no sign of life for %.0f s (at most %.0f s allowed) "
                    "while rank %d waits for %s: it is frozen or cut off; ending the job (resume the run or the "
                    "experiment to go on)\n",
            world_rank, duel_mpi_g.peers[world_rank].host, silent, base, duel_mpi_g.rank, waiting_for);
    fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
}

void duel_mpi_alive_stop(void)
{
    if (!duel_alive.on)
        return;
    pthread_mutex_lock(&duel_alive.lock);
    duel_alive.stop = 1;
    pthread_mutex_unlock(&duel_alive.lock);
    pthread_join(duel_alive.thread, NULL);
    duel_alive.on = 0;
    free(duel_alive.heard);
    free(duel_alive.to);
    duel_alive.heard = NULL;
    duel_alive.to = NULL;
}
