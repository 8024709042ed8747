/* mpi_skew.c - a rank of another build (compiled with another DUEL_MPI_SALT): started beside duel_evolve, it must get the job refused at start-up with one line. */
#include <stdio.h>

#include "duel_mpi.h"

static int mpi_skew_command(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return 2;
}

int main(int argc, char **argv)
{
    int rc = duel_mpi_start(argc - 1, argv + 1);
    if (rc == 0) /* the check let it in: behave as a rank would, so that the test sees the job go through */
        rc = duel_mpi_rank() == 0 ? 0 : duel_mpi_serve(argc - 1, argv + 1, mpi_skew_command);
    return duel_mpi_finish(rc);
}
