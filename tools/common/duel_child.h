/* duel_child.h - duel_evolve started again as a child process that dies with its parent and plays alone (an experiment's runs and ladders). */
#ifndef DUEL_CHILD_H
#define DUEL_CHILD_H

#include <sys/types.h>

/* The duel_evolve binary that is running (/proc/self/exe) into out. 0, or -1. */
int duel_child_self(char *out, size_t cap);

/* Starts the program self with args (args[0] its name) in a child that is killed when this process dies
 * (PR_SET_PDEATHSIG: kill -9 of an experiment leaves no run holding its directory's lock) and that never joins an
 * MPI job (DUEL_MPI=0), its standard output to /dev/null when quiet_out. The pid, or -1. */
pid_t duel_child_spawn(const char *self, char *const *args, int quiet_out);

#endif /* DUEL_CHILD_H */
