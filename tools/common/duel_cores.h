/* duel_cores.h - the processors this process may run on: what a thread count of 0 ("every core") means. */
#ifndef DUEL_CORES_H
#define DUEL_CORES_H

#include <stdint.h>

/* The processors in this process's affinity mask (taskset, a Slurm or
 * cgroup cpuset: the cores a job was given, not the machine's), or the
 * online count where there is no mask; at least 1. */
uint32_t duel_cores(void);

#endif /* DUEL_CORES_H */
