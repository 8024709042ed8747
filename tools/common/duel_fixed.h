/* duel_fixed.h - evolution against fixed opponents: one population whose fitness is its games against builtin strategies and champions, played on every core. */
#ifndef DUEL_FIXED_H
#define DUEL_FIXED_H

#include <stddef.h>
#include <stdint.h>

#include "duel.h"
#include "duel_config.h"
#include "duel_games.h"
#include "neat.h"

/*
 * Each generation every host plays every opponent on each of the
 * generation's layouts from both sides: the rules' training food ([opponents]
 * games = training), or N comparison layouts drawn from the run's seed and
 * the generation (games = comparison:N; the same for any number of threads,
 * ranks or resumes). Its fitness is its wins, or wins - losses + games
 * (fitness = wins-losses). The games are played through duel_games (every
 * thread; hosts encoded as the run's blobs), so a host's network is the one
 * its champion blob holds.
 */

typedef struct duel_fixed duel_fixed;

/* What a generation did. best_vs[k]: the generation's best host (highest
 * fitness, lowest index on ties: the champion) against opponent k in that
 * generation's games, wins_a its wins, wins_b the opponent's. */
typedef struct duel_fixed_report {
    uint32_t generation;
    double best_fitness, mean_fitness;
    uint32_t best_index;
    uint32_t species;
    double delta_t;
    double mean_hidden, mean_conns;
    uint32_t best_hidden, best_conns;
    uint32_t host_games;             /* games per host */
    uint64_t games;                  /* every game of the generation */
    duel_tally best_vs[DUEL_MAX_OPPONENTS];
} duel_fixed_report;

/* The engine over pop (which it then owns and frees), for the run's
 * configuration (seed, [opponents], net_step) and opponents: n nets, a blob
 * each or a builtin (duel_net with a NULL blob), copied. 0 or NEAT_E_NOMEM
 * (pop freed). */
int duel_fixed_new(duel_fixed **out, neat_pop *pop, const duel_config *cfg, const duel_net *opps, uint32_t n);
void duel_fixed_free(duel_fixed *f);
neat_pop *duel_fixed_pop(const duel_fixed *f);

/* The n comparison layouts of generation g of a run with this seed (games =
 * comparison:n): n distinct configurations in out, drawn from (seed, g). */
void duel_fixed_layouts(uint64_t seed, uint32_t n, uint32_t g, int32_t out[DUEL_CONFIGS]);

/* One generation: the games on dg (its rules are the run's), fitness,
 * the champion's tallies, the epoch. On an error nothing changes (the
 * population stays in its generation): 0, a negative neat_error, a runtime
 * error - 100, a duel error - 200, or DUEL_GAMES_E_REMOTE. */
int duel_fixed_step(duel_fixed *f, duel_games *dg, duel_fixed_report *rep);

#endif /* DUEL_FIXED_H */
