/* duel_mpi_none.c - duel_mpi.h without MPI (a build without Open MPI): one process, rank 0 of 1; an mpirun of several copies is refused. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cores.h"
#include "duel_mpi.h"

int duel_mpi_built(void)
{
    return 0;
}

int duel_mpi_start(int argc, char **argv)
{
    const char *size = getenv("OMPI_COMM_WORLD_SIZE"), *rank = getenv("OMPI_COMM_WORLD_RANK");
    const char *off = getenv("DUEL_MPI");
    (void)argc;
    (void)argv;
    if (size == NULL)
        size = getenv("PMI_SIZE");
    if (rank == NULL)
        rank = getenv("PMI_RANK");
    if ((off == NULL || strcmp(off, "0") != 0) && size != NULL && atoi(size) > 1) {
        /* N copies would each play the whole run: refused by every one, said by the first */
        if (rank == NULL || atoi(rank) == 0)
            fprintf(stderr, "duel_evolve: started as %s MPI processes, but this duel_evolve was built without MPI "
                            "(install libopenmpi-dev and configure again: docs/cluster.md)\n", size);
        return 2;
    }
    return 0;
}

uint32_t duel_mpi_rank(void)
{
    return 0;
}

uint32_t duel_mpi_size(void)
{
    return 1;
}

uint32_t duel_mpi_default_threads(void)
{
    return duel_cores();
}

int duel_mpi_serve(int argc, char **argv, int (*command)(int argc, char **argv))
{
    (void)argc;
    (void)argv;
    (void)command;
    return 2;
}

int duel_mpi_finish(int rc)
{
    return rc;
}

void duel_mpi_attach(duel_games *dg)
{
    (void)dg;
}

uint32_t duel_mpi_games_ranks(void)
{
    return 1;
}

void duel_mpi_describe(char *out, size_t cap)
{
    if (cap > 0)
        out[0] = '\0';
}

int duel_mpi_stop_requested(void)
{
    return 0;
}

uint32_t duel_mpi_exp_open(uint32_t runs_left)
{
    (void)runs_left;
    return 0;
}

uint32_t duel_mpi_exp_slot_ranks(uint32_t slot)
{
    (void)slot;
    return 1;
}

uint32_t duel_mpi_exp_slot_threads(uint32_t slot)
{
    (void)slot;
    return duel_mpi_default_threads();
}

int duel_mpi_exp_start(uint32_t slot, int argc, char **argv)
{
    (void)slot;
    (void)argc;
    (void)argv;
    return -1;
}

int duel_mpi_exp_poll(uint32_t *slot, int *status)
{
    (void)slot;
    (void)status;
    return 0;
}

void duel_mpi_exp_interrupt(uint32_t slot)
{
    (void)slot;
}
