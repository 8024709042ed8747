/* duel_cores.c - the processors this process may run on: its affinity mask, else the online count. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include <sched.h>
#include <unistd.h>

#include "duel_cores.h"

uint32_t duel_cores(void)
{
    long n;
#ifdef CPU_COUNT
    /* a mask of more than CPU_SETSIZE (1024) processors fails here: then the online count */
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return (uint32_t)CPU_COUNT(&set);
#endif
    n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (uint32_t)n : 1u;
}
