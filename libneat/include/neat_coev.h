/* neat_coev.h - competitive coevolution of two populations (hosts against parasites and a hall of fame) and the dominance tournament, over a caller's game. */
#ifndef NEAT_COEV_H
#define NEAT_COEV_H

#include "neat.h"

/* C++ callers link against the C symbols */
#ifdef __cplusplus
extern "C" {
#endif

/*
 * The protocol of Stanley & Miikkulainen (2004), section 5, as fixed by
 * docs/duel-world.md ("Coevolution, per generation"); the game itself is the
 * caller's, played through one batch callback:
 *
 *     neat_coev *c;
 *     neat_coev_create(&c, &params, &coev_params, NULL, seed, NULL);
 *     for (;;) {
 *         neat_coev_report rep;
 *         if (neat_coev_step(c, play_batch, my_data, &rep) != NEAT_OK) break;
 *         ... rep.generation, rep.pop[0].best_fitness, rep.dominants ...
 *     }
 *
 * Every game of a generation is known before any is played, and each
 * carries a seed derived from (generation, population, host, opponent,
 * side), so the callback may play them in any order on any number of
 * threads: the run is the same.
 */

#define NEAT_COEV_CHECKPOINT_VERSION 3 /* version 2 still loads */

/* One game for the callback: a plays b. */
typedef struct neat_game {
    const neat_genome *a, *b;
    int32_t config;   /* -1: the training configuration; 0..compare_configs-1: a comparison configuration */
    uint8_t a_first;  /* 1: a takes the first starting side (the duel's west), 0: the second */
    uint64_t seed;    /* for games with chance in them; the same whatever the thread */
    int8_t result;    /* set by the callback: 1 a won, -1 b won, 0 neither (draw, timeout) */
} neat_game;

/* Plays n games, setting each result. Returns 0, or a negative code that
 * stops the generation (the coevolution is then unchanged). */
typedef int (*neat_play_fn)(void *ud, neat_game *games, size_t n);

typedef struct neat_coev_params {
    uint32_t species_opponents; /* 4: champions of the other population's best species (previous generation) */
    uint32_t hof_opponents;     /* 8: drawn with replacement from its hall of fame */
    uint32_t first_opponents;   /* 12: members drawn in generation 0, when there is no history */
    uint32_t compare_configs;   /* 144: a comparison plays each configuration from both sides */
    /* 1: the control of the paper's Figure 7: the winner of every game the
     * coevolution plays (host games, the champion's and the dominance
     * comparisons) is a fair coin drawn from the game's seed, and play is
     * never called; 0: the games decide */
    int random_fitness;
} neat_coev_params;

NEAT_API neat_coev_params neat_coev_params_default(void);
/* NEAT_E_PARAM with *field naming the first bad one. */
NEAT_API int neat_coev_params_check(const neat_coev_params *cp, const char **field);

typedef struct neat_coev neat_coev;

/* Two populations of p (both from seed, through different derived seeds),
 * from start (NULL: the minimal network; see neat_pop_create), which the
 * coevolution keeps (neat_coev_start, and its checkpoint).
 *
 * p->pop_stagnation must be 0 (else NEAT_E_PARAM): that rule (only the two
 * best species breed once the population's best fitness has not improved
 * for pop_stagnation generations) needs an absolute fitness. Here fitness
 * is a count of wins against opponents that change every generation,
 * bounded by the games played and reached early, so the best never
 * "improves" and the rule would fire on a fixed schedule. */
NEAT_API int neat_coev_create(neat_coev **out, const neat_params *p, const neat_coev_params *cp,
                              const neat_start *start, uint64_t seed, const neat_alloc *alloc);
NEAT_API void neat_coev_free(neat_coev *c);

/* What one population did in a generation. Sizes are hidden nodes and
 * enabled connections. */
typedef struct neat_coev_pop_report {
    double best_fitness, mean_fitness;
    uint32_t best_index;       /* the best host (lowest index on ties) */
    uint32_t species;
    double delta_t;            /* the threshold this generation was speciated with */
    double mean_hidden, mean_conns;
    uint32_t best_hidden, best_conns;
    uint32_t min_hidden, max_hidden; /* over the whole population */
    uint32_t min_conns, max_conns;
    uint64_t games;            /* its hosts' games */
} neat_coev_pop_report;

typedef struct neat_coev_report {
    uint32_t generation;       /* the generation just played */
    neat_coev_pop_report pop[2];
    uint32_t champion_pop;     /* 0 or 1: whose best won the comparison (ties: 0) */
    uint32_t champion_wins[2]; /* wins of population 0's and 1's best in that comparison */
    uint32_t dominants;        /* dominance level after this generation */
    int new_dominant;          /* 1 when the champion became dominant number `dominants` */
    uint32_t dominance_games;  /* games of the dominance comparisons */
    uint64_t games;            /* every game of the generation */
} neat_coev_report;

/* One generation: opponents, host games, fitness (wins), the comparison of
 * the two bests, the hall of fame, the dominance tournament, reproduction.
 * On an error from play or the allocator nothing changes (the populations
 * reproduce on copies that replace them only when everything succeeded), so
 * a retry gives the same generation. */
NEAT_API int neat_coev_step(neat_coev *c, neat_play_fn play, void *ud, neat_coev_report *rep);

NEAT_API uint32_t neat_coev_generation(const neat_coev *c); /* the next generation to play */
/* The start topology both populations were created from (its weights are
 * those it was given; every individual drew its own). */
NEAT_API const neat_genome *neat_coev_start(const neat_coev *c);
NEAT_API uint64_t neat_coev_seed(const neat_coev *c);
NEAT_API const neat_coev_params *neat_coev_get_params(const neat_coev *c);
NEAT_API const neat_pop *neat_coev_pop(const neat_coev *c, uint32_t which);
NEAT_API uint32_t neat_coev_hof_count(const neat_coev *c, uint32_t which);
NEAT_API const neat_genome *neat_coev_hof(const neat_coev *c, uint32_t which, uint32_t generation);
/* The last generation champion (NULL before the first generation). */
NEAT_API const neat_genome *neat_coev_champion(const neat_coev *c);

/* The dominance tournament: dominant k (0-based; level k + 1). */
typedef struct neat_dominant {
    uint32_t generation;
    uint32_t pop;
    const neat_genome *genome;
    uint32_t n_beaten;         /* = k: it beat every earlier dominant */
    const uint16_t *wins;      /* [n_beaten] its wins against dominant k-1, k-2, ..., 0 (the order played) */
    const uint16_t *losses;    /* [n_beaten] that dominant's wins in the same comparison */
} neat_dominant;
NEAT_API uint32_t neat_coev_dominant_count(const neat_coev *c);
NEAT_API int neat_coev_dominant(const neat_coev *c, uint32_t k, neat_dominant *d);

/* Reproduction by another NEAT (NEAT C++ 1.2.1's own, docs/neat-cpp.md):
 * fn(ud, which, pop, evaluated) makes population `which`'s next generation
 * with neat_pop_replace(pop, ..., evaluated) in place of neat_pop_epoch.
 * Called at once for both populations with evaluated 0 (the other NEAT's
 * start replaces the created one), then in every neat_coev_step with
 * evaluated 1, on a copy of the population whose genomes carry this
 * generation's fitness (wins). fn returns 0 or a negative code, which
 * fails the step. Not kept in checkpoints: a coevolution loaded from one
 * reproduces with libneat unless set again. NULL fn: libneat's own. */
typedef int (*neat_coev_reproduce_fn)(void *ud, uint32_t which, neat_pop *pop, int evaluated);
NEAT_API int neat_coev_set_reproducer(neat_coev *c, neat_coev_reproduce_fn fn, void *ud);

/* New parameters for a resumed run: both populations' (pop_size, inputs and
 * outputs cannot change; pop_stagnation must stay 0) and the protocol's. */
NEAT_API int neat_coev_set_params(neat_coev *c, const neat_params *p, const neat_coev_params *cp);

/* The game-identity tag, as neat_pop_set_game / neat_pop_game (neat.h):
 * opaque bytes (at most NEAT_GAME_MAX, NEAT_E_ARG beyond) naming the game
 * the run plays (the duel's world rules), kept in the checkpoint byte for
 * byte; empty by default and when loaded from a version-2 checkpoint. */
NEAT_API int neat_coev_set_game(neat_coev *c, const uint8_t *bytes, size_t len);
NEAT_API const uint8_t *neat_coev_game(const neat_coev *c, size_t *len);

/* The whole state (docs/formats.md, "Coevolution checkpoint"): the start
 * topology, both populations, halls of fame, the species champions the next generation
 * plays, the dominance tournament. Loading it and stepping on gives the same
 * run as never stopping. */
NEAT_API int neat_coev_save(const neat_coev *c, uint8_t **buf, size_t *len);
NEAT_API void neat_coev_buf_free(const neat_coev *c, uint8_t *buf, size_t len);
/* On NEAT_E_FORMAT/CRC/TRUNCATED, *err_offset (if not NULL) is the byte offset of the problem. */
NEAT_API int neat_coev_load(neat_coev **out, const uint8_t *buf, size_t len, const neat_alloc *alloc,
                            size_t *err_offset);

#ifdef __cplusplus
}
#endif

#endif /* NEAT_COEV_H */
