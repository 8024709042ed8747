/* duel_lcm_champ.h - `duel_evolve run --record-champion-games`: a generation champion's games as LCM event logs. */
#ifndef DUEL_LCM_CHAMP_H
#define DUEL_LCM_CHAMP_H

#include "duel.h"
#include "neat.h"

/* Plays the generation champion against the other population's best of the
 * same generation (the two of the comparison) in the run's world (rules) on
 * the training food, the
 * champion west, then east, through the blob and the runtime, into
 * DIR/games/gen-NNNNN-west.lcm and gen-NNNNN-east.lcm (named by the
 * champion's side; DIR/games must exist). 0, or -1 with one line in msg (prints nothing). */
int duel_lcm_record_champion_games(const char *dir, uint32_t generation, uint32_t champion_pop,
                                   const neat_genome *champion, const neat_genome *other, const neat_params *p,
                                   const duel_rules *rules, char *msg, size_t cap);

#endif /* DUEL_LCM_CHAMP_H */
