/* duel_games.h - the duel as libneat's coevolution game: batches of games played on every core through the runtime. */
#ifndef DUEL_GAMES_H
#define DUEL_GAMES_H

#include "duel.h"
#include "neat_coev.h"

typedef struct duel_games duel_games;

/* Progress of the batch in flight: called from the calling thread about
 * five times a second and once at the end (done == total). */
typedef void (*duel_progress_fn)(void *ud, uint64_t done, uint64_t total);

/* threads 0: every core. The games are world v1's until duel_games_set_rules. */
int duel_games_create(duel_games **out, uint32_t threads, const neat_params *p);
/* The world of every later game (copied; checked: DUEL_E_RULES). */
int duel_games_set_rules(duel_games *dg, const duel_rules *r);
const duel_rules *duel_games_rules(const duel_games *dg);
/* The food of the training games (config -1) from now on: DUEL_TRAINING
 * (the rules' training items, the default) or a comparison layout 0..143
 * ([run] train_layouts = comparison draws one per generation). */
void duel_games_set_training(duel_games *dg, int32_t config);
void duel_games_free(duel_games *dg);
uint32_t duel_games_threads(const duel_games *dg);
void duel_games_on_progress(duel_games *dg, duel_progress_fn fn, void *ud);

/* neat_play_fn: ud is the duel_games. Each game: a on the west side when
 * a_first, config -1 the training food, else comparison configuration
 * `config`. A network that cannot be encoded or loaded stops the batch with
 * its error code. The results do not depend on the number of threads. */
int duel_games_play(void *ud, neat_game *games, size_t n);

/* Games between networks given as blobs (another process's share of a
 * batch, tools/mpi): match i plays nets[a] against nets[b], a on the west
 * side when a_first, config as in neat_game; result as in neat_game. The
 * same results as the genomes the blobs were written from. A duel_net
 * without a blob (NULL) is the builtin strategy number len. */
typedef struct duel_net {
    const uint8_t *blob;
    size_t len;
} duel_net;
typedef struct duel_match {
    uint32_t a, b;
    int32_t config;
    uint8_t a_first;
    int8_t result;
} duel_match;
int duel_games_play_nets(duel_games *dg, const duel_net *nets, duel_match *m, size_t n);
/* The same as a batch of this process's own (a run against fixed opponents):
 * played on its threads and, with a remote executor, on other ranks too.
 * nets has n_nets entries. */
int duel_games_play_matches(duel_games *dg, const duel_net *nets, size_t n_nets, duel_match *m, size_t n);
/* After a batch that failed: the index of the lowest failing game. */
size_t duel_games_error_at(const duel_games *dg);

/* A remote executor (tools/mpi/duel_mpi_games.c): while a batch of
 * duel_games_play is in flight, fn is called on the calling thread, once
 * as the batch starts and then about every millisecond (two chunks in
 * flight per rank hide the wait). It takes games with duel_games_take, has
 * them played elsewhere, writes their results into the batch's games and
 * reports them with duel_games_remote_done. It returns how many of its
 * requests are still out (the batch ends when every game is done and none
 * is out), or a negative value when it cannot go on (the batch then fails
 * with DUEL_GAMES_E_REMOTE). */
#define DUEL_GAMES_E_REMOTE (-300)
typedef int (*duel_remote_fn)(void *ud, duel_games *dg);
void duel_games_set_remote(duel_games *dg, duel_remote_fn fn, void *ud);
/* The batch in flight, its size, and its number (1 for the first batch):
 * its games, or NULL for a batch of matches (duel_games_play_matches), whose
 * matches and networks duel_games_batch_matches gives (NULL otherwise). */
neat_game *duel_games_batch(duel_games *dg, size_t *n, uint64_t *batch_no);
duel_match *duel_games_batch_matches(duel_games *dg, const duel_net **nets, size_t *n_nets);
/* Up to max games not yet handed out, from *from on: how many (0: none left). */
size_t duel_games_take(duel_games *dg, size_t max, size_t *from);
/* count games played elsewhere, with their steps; err (0 if none) at game err_at of the batch. */
void duel_games_remote_done(duel_games *dg, size_t count, uint64_t steps, int err, size_t err_at);
const neat_params *duel_games_params(const duel_games *dg);
/* The parameters networks are built with from the next batch on (a run's [overrides] between generations). */
void duel_games_set_params(duel_games *dg, const neat_params *p);

/* Totals since creation. */
uint64_t duel_games_played(const duel_games *dg);
uint64_t duel_games_steps(const duel_games *dg);
double duel_games_seconds(const duel_games *dg); /* wall seconds from each batch's start to its end */

#endif /* DUEL_GAMES_H */
