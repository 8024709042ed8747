/* duel_mpi.h - duel_evolve as an MPI job (Open MPI): the start-up check, a run's games spread over ranks, an experiment's runs and comparisons handed out to ranks. */
#ifndef DUEL_MPI_H
#define DUEL_MPI_H

#include <stdint.h>

#include "duel_games.h"

/*
 * Launched by mpirun (or srun), every rank runs the same command line:
 *
 *   run, resume   rank 0 runs the coevolution and writes the run directory;
 *                 every generation's games are spread over all ranks, each
 *                 with its own threads (duel_mpi_games.c);
 *   experiment    rank 0 keeps the experiment's state and files; the runs,
 *                 comparisons and ladders are handed out to ranks as they
 *                 become free (duel_mpi_exp.c);
 *   anything else is refused: it runs in one process.
 *
 * Without MPI (a build without Open MPI, or a process not started by
 * mpirun) this is one process: rank 0 of 1. docs/cluster.md.
 */

/* 1 when this duel_evolve was built with MPI. */
int duel_mpi_built(void);

/* First thing in main. Not under mpirun: 0 (one process). Under mpirun:
 * MPI is initialised and every rank's version word and thread count are
 * exchanged; 0, or the exit status (2) after one line from rank 0 when the
 * launch is bad (another build on some rank, a build without MPI under an
 * mpirun of several processes). */
int duel_mpi_start(int argc, char **argv);
uint32_t duel_mpi_rank(void);
uint32_t duel_mpi_size(void);
/* Threads a rank uses when told 0: the cores of its machine shared by the
 * ranks on that machine. */
uint32_t duel_mpi_default_threads(void);

/* Ranks 1..N-1: whatever rank 0's command asks of them (argv is the same
 * command line, from the subcommand on), until it is done; command runs a
 * duel_evolve subcommand line in this process (an experiment's tasks). The
 * exit status. */
int duel_mpi_serve(int argc, char **argv, int (*command)(int argc, char **argv));
/* The end of the job: on rank 0, every other rank released (its exit status
 * is rc too); MPI finalised. Returns the status to exit with. */
int duel_mpi_finish(int rc);

/* Rank 0 of a run (or a group leader of an experiment): dg's batches from
 * now on spread over the run's ranks. Nothing happens with one rank. */
void duel_mpi_attach(duel_games *dg);
/* The ranks a run's games are spread over (1 without MPI). */
uint32_t duel_mpi_games_ranks(void);
/* A line for log.txt: the ranks, and the messages and bytes the games took
 * ("" with one rank). */
void duel_mpi_describe(char *out, size_t cap);
/* A run executed as an experiment's task: 1 when rank 0 asked it to stop
 * after the generation in flight. */
int duel_mpi_stop_requested(void);

/* An experiment on rank 0 of a job of several ranks: its slots (where a
 * task, a duel_evolve command line, runs). duel_mpi_exp_open forms the
 * groups of ranks (runs_left: the runs still to play) and returns the number
 * of slots (0 without MPI or with one rank). */
uint32_t duel_mpi_exp_open(uint32_t runs_left);
uint32_t duel_mpi_exp_slot_ranks(uint32_t slot);
uint32_t duel_mpi_exp_slot_threads(uint32_t slot);
/* argv from the subcommand on ("run", "--config", ...). 0, or -1. */
int duel_mpi_exp_start(uint32_t slot, int argc, char **argv);
/* 1 when a slot's task ended (*slot, its exit status), 0 when none has. Does not wait. */
int duel_mpi_exp_poll(uint32_t *slot, int *status);
/* The slot's task stops after its generation in flight (as Ctrl-C would). */
void duel_mpi_exp_interrupt(uint32_t slot);

#endif /* DUEL_MPI_H */
