/* duel_mpi_internal.h - what the files of tools/mpi share: the job's ranks, the message tags, waiting without spinning, counted sends. */
#ifndef DUEL_MPI_INTERNAL_H
#define DUEL_MPI_INTERNAL_H

#include <mpi.h>
#include <stddef.h>
#include <stdint.h>

#include "duel_mpi.h"

/* Every message of the job, by tag. Payloads are native-endian structs and
 * byte strings: the start-up check makes sure every rank is the same build
 * on the same byte order. */
enum {
    DUEL_TAG_END = 1,    /* 0 -> rank: the job is over; int32 exit status */
    DUEL_TAG_WORK = 2,   /* leader -> rank: games to play (duel_mpi_games.c) */
    DUEL_TAG_RESULT = 3, /* rank -> leader: their results */
    DUEL_TAG_SETUP = 4,  /* 0 -> rank: the experiment's groups (duel_mpi_exp.c) */
    DUEL_TAG_TASK = 5,   /* 0 -> group leader: a duel_evolve command line to execute */
    DUEL_TAG_DONE = 6,   /* group leader -> 0: its exit status */
    DUEL_TAG_INT = 7,    /* 0 -> group leader: stop the task after the generation in flight */
    DUEL_TAG_ALIVE = 8   /* any -> the ranks that may wait on it: a sign of life, empty (duel_mpi_alive.c) */
};

/* The messages and bytes of a run's games this process sent and received (log.txt's mpi: line). */
typedef struct duel_mpi_stats {
    uint64_t sent_msgs, sent_bytes, recv_msgs, recv_bytes, batches;
} duel_mpi_stats;

/* What each rank told the others at start-up. */
typedef struct duel_mpi_peer {
    uint64_t version;   /* duel_mpi_version_word() */
    uint32_t threads;   /* the threads it plays with */
    uint32_t local;     /* ranks on its machine */
    uint32_t beats;     /* 1: it sends signs of life (its MPI gives MPI_THREAD_MULTIPLE) */
    uint32_t pad;
    char host[64];
} duel_mpi_peer;

/* The job (valid after duel_mpi_start under mpirun). */
typedef struct duel_mpi_job {
    int active;              /* MPI initialised */
    int rank, size;
    duel_mpi_peer *peers;    /* [size] */
    MPI_Comm games_comm;     /* whom a run's games go to (rank 0 of it hands them out): the world, or an
                              * experiment's group */
    int in_task;             /* a group leader executing rank 0's task */
    int stop_asked;          /* rank 0 sent DUEL_TAG_INT */
    int quiet_end;           /* the start-up check failed: every rank knows, nobody waits for an END */
    duel_mpi_stats stats;
} duel_mpi_job;
extern duel_mpi_job duel_mpi_g;

/* Receives a message of tag (MPI_ANY_TAG: any) from src on comm into a new
 * buffer (*buf, *len; free it), sleeping between looks instead of spinning:
 * the cores belong to the games. 0, or -1 if MPI failed. */
int duel_mpi_recv(MPI_Comm comm, int src, int tag, uint8_t **buf, size_t *len, MPI_Status *st);
/* Sends and counts. 0, or -1. */
int duel_mpi_send(MPI_Comm comm, int dst, int tag, const void *buf, size_t len);
/* A short sleep (between looks at the network, in loops that poll). */
void duel_mpi_nap(long usec);

/* Ranks 1..N-1 of a run: its games, from the leader of comm, until END; the exit status rank 0 sent. */
int duel_mpi_games_serve(MPI_Comm comm, int leader, uint32_t threads, int *end_status);

/* Signs of life (duel_mpi_alive.c). The deadline's base: 60 s, or DUEL_MPI_WAIT seconds from the environment. */
double duel_mpi_wait_base(void);
/* DUEL_MPI_WAIT read: 0 with *out its seconds (60 when unset), or -1 when it is set but not seconds in (0, 1e6]. */
int duel_mpi_wait_parse(double *out);
/* Starts the thread that sends signs of life (when provided is MPI_THREAD_MULTIPLE). 0, or -1. */
int duel_mpi_alive_start(int provided);
/* Sends signs of life to world_rank too (a rank of this one's experiment group). */
void duel_mpi_alive_link(int world_rank);
/* A sign of life from world_rank taken by another receiver. */
void duel_mpi_alive_heard(int world_rank);
/* Ends the job (one line, MPI_Abort) when world_rank, which this rank waits on for waiting_for, has been silent
 * longer than the deadline's base. */
void duel_mpi_alive_check(int world_rank, const char *waiting_for);
/* Stops the thread (before the job's END and MPI_Finalize). */
void duel_mpi_alive_stop(void);

/* The experiment's side of duel_mpi_serve (ranks 1..N-1). */
typedef int (*duel_mpi_command_fn)(int argc, char **argv);
int duel_mpi_exp_serve(uint32_t threads, duel_mpi_command_fn cmd);

#endif /* DUEL_MPI_INTERNAL_H */
