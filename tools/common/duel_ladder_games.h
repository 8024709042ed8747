/* duel_ladder_games.h - a run's ladder: its dominants against the built-in strategies, played, and written as CSV, a table or JSON (duel_evolve ladder and the Python package's runs.ladder). */
#ifndef DUEL_LADDER_GAMES_H
#define DUEL_LADDER_GAMES_H

#include <stdint.h>
#include <stdio.h>

#include "duel.h"
#include "duel_levels.h"
#include "duel_outputs.h"
#include "duel_pairs.h"

/* A ladder played: levels first..end-1 (0-based) of the run in dir against the strategies against[0..n_against),
 * the pairs in that order (level by level). Its pairs point into it: it stays where duel_ladder_play put it. */
typedef struct duel_ladder {
    const char *dir;                       /* the caller's string */
    duel_rules world;                      /* the games' */
    int against[DUEL_N_BUILTINS];
    uint32_t n_against;
    duel_level *levels;
    uint32_t n, first, end;                /* the run's levels; the ones played */
    duel_cli_ctrl builtins[DUEL_N_BUILTINS];
    duel_pair *pairs;
} duel_ladder;

/* Plays the run in dir's dominants in world (the run's: duel_run_world): the top one alone (top), levels lo..hi
 * (1-based; 0, 0: every level), 288 games against each strategy, on threads threads (0: every core). 0; 2 (the
 * input's fault: no dominance.csv, a damaged file, a level the run does not have) or 1 (memory, a game) with the
 * line in msg; prints nothing. duel_ladder_free in either case. */
int duel_ladder_play(duel_ladder *L, const char *dir, const duel_rules *world, int top, uint32_t lo, uint32_t hi,
                     const int *against, uint32_t n_against, uint32_t threads, char *msg, size_t cap);
/* ladder.csv's text: level, generation, population, hidden, connections, NAME_wins, NAME_losses per strategy,
 * totals, the world and the dominant's network step. */
void duel_ladder_write_csv(FILE *f, const duel_ladder *L);
/* The command's table (wins:losses), and its --json (docs/tools.md, "ladder --json"). */
void duel_ladder_write_table(FILE *f, const duel_ladder *L);
void duel_ladder_write_json(FILE *f, const duel_ladder *L);
void duel_ladder_free(duel_ladder *L);
/* What a ladder CSV is (its header's start), for the output checks of RUN/ladder.csv and --csv. */
extern const duel_out_kind duel_ladder_csv_kind;

#endif /* DUEL_LADDER_GAMES_H */
