/* duel_mpi_exp.c - an experiment over the ranks of an MPI job: groups of ranks formed, each group's leader executing the duel_evolve command lines rank 0 hands it, its other ranks playing its runs' games. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "duel_child.h"
#include "duel_mpi_internal.h"

/*
 * Rank 0 keeps the experiment (its state, plan, caches' order, report) and
 * hands out tasks: a task is a duel_evolve command line (run, resume,
 * compare, ladder) on a run directory, which every rank reaches at the same
 * path (a shared file system: docs/cluster.md). A slot is where a task runs:
 * a group of ranks whose leader executes it in its own process, the other
 * ranks of the group playing a run's games; and, when the groups are single
 * ranks, rank 0 itself, through a child process of plain duel_evolve.
 *
 * Groups are formed once, at the start: a rank given a run of its own does
 * all its work, a rank given a share of another run's games does 1/1.04 of
 * it (measured: docs/cluster.md), so every rank is a slot of its own unless
 * there are at least two ranks besides rank 0 for every run left; then the
 * ranks are shared out among the runs, (N - 1) / runs to each.
 */

typedef struct duel_setup {
    uint32_t group_size;
} duel_setup;

static int duel_exp_groups = 0;   /* remote slots */
static int duel_exp_gsize = 1;    /* ranks a group (the last one takes the ranks left over too) */
static int duel_exp_local = 0;    /* 1: slot 0 is a child process of rank 0 */
static pid_t duel_exp_child = 0;  /* slot 0's child while it runs */
static int *duel_exp_leader = NULL; /* [slots] the world rank of each remote slot's leader (index 0 unused when local) */
static unsigned char *duel_exp_busy = NULL; /* [slots] 1: the slot's leader executes a task */

/* ---- ranks 1..N-1 */

/* A task: the directory rank 0 works in, then the command line; NUL-terminated strings, one after the other. */
static int duel_exp_task(uint8_t *buf, size_t len, duel_mpi_command_fn cmd)
{
    char **argv;
    int argc = 0, rc;
    size_t i, n = 0;
    if (len == 0 || buf[len - 1] != '\0')
        return 2;
    for (i = 0; i < len; i++)
        n += buf[i] == '\0';
    if (n < 2)
        return 2;
    if (chdir((char *)buf) != 0) {
        fprintf(stderr, "duel_evolve: mpi: rank %d (on %s) cannot enter the experiment directory %s: %s (every rank "
                        "needs it at the same path: docs/cluster.md)\n",
                duel_mpi_g.rank, duel_mpi_g.peers[duel_mpi_g.rank].host, (char *)buf, strerror(errno));
        return 2;
    }
    argv = (char **)calloc(n, sizeof *argv);
    if (argv == NULL)
        return 1;
    for (i = strlen((char *)buf) + 1; i < len; i += strlen((char *)buf + i) + 1)
        argv[argc++] = (char *)buf + i;
    argv[argc] = NULL;
    rc = cmd(argc, argv);
    free(argv);
    return rc;
}

int duel_mpi_exp_serve(uint32_t threads, duel_mpi_command_fn cmd)
{
    uint8_t *buf;
    size_t len;
    MPI_Status st;
    MPI_Comm group;
    duel_setup su;
    int status = 0, n_groups, color, grank, gsize;
    /* the groups, or the end (rank 0 found nothing to do, or failed before) */
    if (duel_mpi_recv(MPI_COMM_WORLD, 0, MPI_ANY_TAG, &buf, &len, &st) != 0)
        return 1;
    if (st.MPI_TAG == DUEL_TAG_END || st.MPI_TAG != DUEL_TAG_SETUP || len != sizeof su) {
        int32_t s = 1;
        if (st.MPI_TAG == DUEL_TAG_END && len == sizeof s)
            memcpy(&s, buf, sizeof s);
        free(buf);
        return s;
    }
    memcpy(&su, buf, sizeof su);
    free(buf);
    n_groups = (duel_mpi_g.size - 1) / (int)su.group_size;
    color = (duel_mpi_g.rank - 1) / (int)su.group_size;
    if (color >= n_groups)
        color = n_groups - 1; /* the ranks left over join the last group */
    if (MPI_Comm_split(MPI_COMM_WORLD, color, duel_mpi_g.rank, &group) != MPI_SUCCESS)
        return 1;
    MPI_Comm_rank(group, &grank);
    MPI_Comm_size(group, &gsize);
    duel_mpi_g.games_comm = group;
    {
        /* a member waits on its leader, the leader on its members: signs of life between them */
        MPI_Group g, w;
        int k, wr;
        MPI_Comm_group(group, &g);
        MPI_Comm_group(MPI_COMM_WORLD, &w);
        for (k = 0; k < gsize; k++)
            if (grank == 0 || k == 0) {
                MPI_Group_translate_ranks(g, 1, &k, w, &wr);
                duel_mpi_alive_link(wr);
            }
        MPI_Group_free(&g);
        MPI_Group_free(&w);
    }
    if (grank != 0) {
        /* a member: the leader's games until its END, then rank 0's END to everybody */
        int rc = duel_mpi_games_serve(group, 0, threads, &status);
        if (rc == 0 && duel_mpi_recv(MPI_COMM_WORLD, 0, DUEL_TAG_END, &buf, &len, &st) == 0)
            free(buf);
        return rc == 0 ? status : 1;
    }
    for (;;) {
        int32_t rc;
        if (duel_mpi_recv(MPI_COMM_WORLD, 0, MPI_ANY_TAG, &buf, &len, &st) != 0)
            return 1;
        if (st.MPI_TAG == DUEL_TAG_END) {
            int32_t s = 1, r;
            if (len == sizeof s)
                memcpy(&s, buf, sizeof s);
            free(buf);
            for (r = 1; r < gsize; r++)
                duel_mpi_send(group, r, DUEL_TAG_END, &s, sizeof s);
            return s;
        }
        if (st.MPI_TAG != DUEL_TAG_TASK) { /* a stop that came after its task ended */
            free(buf);
            continue;
        }
        duel_mpi_g.in_task = 1;
        duel_mpi_g.stop_asked = 0;
        rc = duel_exp_task(buf, len, cmd);
        duel_mpi_g.in_task = 0;
        free(buf);
        fflush(stderr);
        if (duel_mpi_send(MPI_COMM_WORLD, 0, DUEL_TAG_DONE, &rc, sizeof rc) != 0)
            return 1;
    }
}

/* ---- rank 0 */

uint32_t duel_mpi_exp_open(uint32_t runs_left)
{
    duel_setup su;
    int r, n_workers = duel_mpi_g.size - 1, k;
    MPI_Comm none;
    if (!duel_mpi_g.active || duel_mpi_g.size < 2)
        return 0;
    su.group_size = runs_left > 0 && (uint32_t)duel_mpi_g.size > runs_left ? (uint32_t)n_workers / runs_left : 1u;
    if (su.group_size < 1)
        su.group_size = 1;
    duel_exp_groups = n_workers / (int)su.group_size;
    duel_exp_gsize = (int)su.group_size;
    duel_exp_local = su.group_size == 1;
    for (r = 1; r < duel_mpi_g.size; r++)
        duel_mpi_send(MPI_COMM_WORLD, r, DUEL_TAG_SETUP, &su, sizeof su);
    MPI_Comm_split(MPI_COMM_WORLD, MPI_UNDEFINED, 0, &none);
    free(duel_exp_leader);
    free(duel_exp_busy);
    duel_exp_leader = (int *)calloc((size_t)duel_exp_groups + 1u, sizeof *duel_exp_leader);
    duel_exp_busy = (unsigned char *)calloc((size_t)duel_exp_groups + 1u, 1);
    if (duel_exp_leader == NULL || duel_exp_busy == NULL)
        return 0;
    for (k = 0; k < duel_exp_groups; k++)
        duel_exp_leader[duel_exp_local + k] = 1 + k * (int)su.group_size;
    return (uint32_t)(duel_exp_local + duel_exp_groups);
}

uint32_t duel_mpi_exp_slot_threads(uint32_t slot)
{
    return duel_mpi_g.peers[duel_exp_local && slot == 0 ? 0 : duel_exp_leader[slot]].threads;
}

uint32_t duel_mpi_exp_slot_ranks(uint32_t slot)
{
    int k;
    if (duel_exp_local && slot == 0)
        return 1;
    k = (int)slot - duel_exp_local;
    return (uint32_t)(k == duel_exp_groups - 1 ? duel_mpi_g.size - 1 - k * duel_exp_gsize : duel_exp_gsize);
}

int duel_mpi_exp_start(uint32_t slot, int argc, char **argv)
{
    size_t len, pos;
    uint8_t *buf;
    char cwd[4096], self[4096];
    int i, rc;
    if (duel_exp_local && slot == 0) {
        char **full = (char **)calloc((size_t)argc + 2, sizeof *full);
        if (full == NULL)
            return -1;
        full[0] = (char *)"duel_evolve";
        for (i = 0; i < argc; i++)
            full[i + 1] = argv[i];
        duel_exp_child = duel_child_self(self, sizeof self) == 0 ? duel_child_spawn(self, full, 1) : -1;
        free(full);
        return duel_exp_child > 0 ? 0 : -1;
    }
    if (getcwd(cwd, sizeof cwd) == NULL)
        return -1;
    len = strlen(cwd) + 1;
    for (i = 0; i < argc; i++)
        len += strlen(argv[i]) + 1;
    buf = (uint8_t *)malloc(len);
    if (buf == NULL)
        return -1;
    memcpy(buf, cwd, strlen(cwd) + 1);
    pos = strlen(cwd) + 1;
    for (i = 0; i < argc; i++) {
        size_t n = strlen(argv[i]) + 1;
        memcpy(buf + pos, argv[i], n);
        pos += n;
    }
    rc = duel_mpi_send(MPI_COMM_WORLD, duel_exp_leader[slot], DUEL_TAG_TASK, buf, len);
    free(buf);
    if (rc == 0)
        duel_exp_busy[slot] = 1;
    return rc;
}

int duel_mpi_exp_poll(uint32_t *slot, int *status)
{
    int flag = 0;
    MPI_Status st;
    if (duel_exp_local && duel_exp_child > 0) {
        int ws;
        pid_t p = waitpid(duel_exp_child, &ws, WNOHANG);
        if (p == duel_exp_child) {
            duel_exp_child = 0;
            *slot = 0;
            *status = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
            return 1;
        }
    }
    if (MPI_Iprobe(MPI_ANY_SOURCE, DUEL_TAG_DONE, MPI_COMM_WORLD, &flag, &st) == MPI_SUCCESS && flag) {
        int32_t rc = 1;
        int k;
        MPI_Recv(&rc, (int)sizeof rc, MPI_BYTE, st.MPI_SOURCE, DUEL_TAG_DONE, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        for (k = duel_exp_local; k < duel_exp_local + duel_exp_groups; k++)
            if (duel_exp_leader[k] == st.MPI_SOURCE) {
                duel_exp_busy[k] = 0;
                *slot = (uint32_t)k;
                *status = rc;
                return 1;
            }
    }
    {
        /* a task has no deadline of its own (a whole run takes hours): its leader's signs of life are watched */
        int k;
        for (k = duel_exp_local; k < duel_exp_local + duel_exp_groups; k++)
            if (duel_exp_busy[k])
                duel_mpi_alive_check(duel_exp_leader[k], "the task it executes (a run, compare or ladder)");
    }
    return 0;
}

void duel_mpi_exp_interrupt(uint32_t slot)
{
    uint8_t b = 0;
    if (duel_exp_local && slot == 0) {
        if (duel_exp_child > 0)
            kill(duel_exp_child, SIGINT);
        return;
    }
    duel_mpi_send(MPI_COMM_WORLD, duel_exp_leader[slot], DUEL_TAG_INT, &b, 1);
}
