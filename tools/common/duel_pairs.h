/* duel_pairs.h - many 288-game comparisons between controllers named on the command line, spread over every core. */
#ifndef DUEL_PAIRS_H
#define DUEL_PAIRS_H

#include <stddef.h>
#include <stdint.h>

#include "duel_ctrl.h"

/* One comparison: a against b on every comparison food configuration from
 * both sides (duel_compare), exactly what `duel_evolve play A B --games 288`
 * plays. */
typedef struct duel_pair {
    const duel_cli_ctrl *a, *b;
    duel_tally tally; /* set by duel_pairs_play */
} duel_pair;

/* Called from the calling thread about five times a second and once at the
 * end (done == n), with the comparisons finished so far. */
typedef void (*duel_pairs_progress)(void *ud, size_t done, size_t n);

/* Plays every pair in the world of rules (NULL: v1), each on a thread's own
 * copy of its networks (threads 0: every core), so the tallies do not
 * depend on the number of threads. 0, or -1 (out of memory, or a blob that
 * no longer loads). */
int duel_pairs_play(const duel_rules *rules, duel_pair *pairs, size_t n, uint32_t threads, duel_pairs_progress fn,
                    void *ud);

#endif /* DUEL_PAIRS_H */
