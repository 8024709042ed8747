/* duel_levels.h - a run directory's dominance levels (dominance.csv) with each dominant's champion blob loaded. */
#ifndef DUEL_LEVELS_H
#define DUEL_LEVELS_H

#include <stdint.h>

#include "duel_ctrl.h"

typedef struct duel_level {
    uint32_t level, generation, hidden, conns;
    char pop[2];       /* "A" or "B" */
    duel_cli_ctrl ctrl; /* DIR/champions/gen-NNNNN.blob of that generation */
} duel_level;

/* Every level of DIR/dominance.csv, blobs loaded and checked; a run with no
 * level yet is an error. 0, or -1 after one line on stderr naming the file. */
int duel_levels_read(const char *dir, duel_level **out, uint32_t *n);
void duel_levels_free(duel_level *levels, uint32_t n);
/* The levels against the run's checkpoint (when it has one): the same dominants, generation and population, and
 * each blob the encoding of the checkpoint's dominant (an edited row, a row the checkpoint lacks, or a champion
 * blob swapped for another is refused, and resume repairs it). 0, or -1 after one line. duel_levels_read calls it. */
int duel_levels_check(const char *dir, const duel_level *levels, uint32_t n);
/* The same two, printing nothing: -1 with the line in msg (paths escaped; print it through duel_esc_msg). */
int duel_levels_read_msg(const char *dir, duel_level **out, uint32_t *n, char *msg, size_t cap);
int duel_levels_check_msg(const char *dir, const duel_level *levels, uint32_t n, char *msg, size_t cap);

#endif /* DUEL_LEVELS_H */
