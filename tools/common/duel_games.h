/* duel_games.h - the duel as libneat's coevolution game: batches of games played on every core through the runtime. */
#ifndef DUEL_GAMES_H
#define DUEL_GAMES_H

#include "neat_coev.h"

typedef struct duel_games duel_games;

/* Progress of the batch in flight: called from the calling thread about
 * five times a second and once at the end (done == total). */
typedef void (*duel_progress_fn)(void *ud, uint64_t done, uint64_t total);

/* threads 0: every core. */
int duel_games_create(duel_games **out, uint32_t threads, const neat_params *p);
void duel_games_free(duel_games *dg);
uint32_t duel_games_threads(const duel_games *dg);
void duel_games_on_progress(duel_games *dg, duel_progress_fn fn, void *ud);

/* neat_play_fn: ud is the duel_games. Each game: a on the west side when
 * a_first, config -1 the training food, else comparison configuration
 * `config`. A network that cannot be encoded or loaded stops the batch with
 * its error code. The results do not depend on the number of threads. */
int duel_games_play(void *ud, neat_game *games, size_t n);

/* Totals since creation. */
uint64_t duel_games_played(const duel_games *dg);
uint64_t duel_games_steps(const duel_games *dg);

#endif /* DUEL_GAMES_H */
