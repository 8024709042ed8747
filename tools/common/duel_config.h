/* duel_config.h - a run's configuration: the [run], [coevolution], [neat] and [world] sections of an INI file. */
/* tools/common/: what the commands share: the run configuration and every libneat parameter in INI, run-directory files, controllers named on the command line, traces, genome -> blob -> runtime, the threaded game batches of coevolution. */
#ifndef DUEL_CONFIG_H
#define DUEL_CONFIG_H

#include <stddef.h>
#include <stdio.h>

#include "duel.h"
#include "neat.h"
#include "neat_coev.h"

/* The run engine's library (libduelengine, docs/library.md) exports what this header and duel_engine.h declare. */
#ifndef DUEL_RUN_API
#define DUEL_RUN_API NEAT_DUEL_EXPORT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* [neat] start: the topology both populations start from. */
enum duel_start_kind {
    DUEL_START_MINIMAL = 0, /* "minimal": bias and inputs to outputs, 39 connections */
    DUEL_START_HIDDEN = 1,  /* "hidden:H:inputs" or "hidden:H:bias": H fully recurrent hidden nodes */
    DUEL_START_BLOB = 2,    /* "blob:PATH": a champion blob's network */
    DUEL_START_GENOME = 3   /* "genome:PATH": a genome file's genes (champions/gen-N.genome) */
};
#define DUEL_START_MAX_HIDDEN 240 /* 16 + 240 nodes: the blob format's 256 */
#define DUEL_START_MAX_PATH 4096
/* the largest node id or innovation number a start genome may hold: half of every counter's 2^31 - 1 stays the run's */
#define DUEL_START_MAX_COUNTER 0x3fffffffu

typedef struct duel_start {
    int kind;                 /* enum duel_start_kind */
    uint32_t hidden;          /* DUEL_START_HIDDEN: H */
    int direct;               /* DUEL_START_HIDDEN: enum neat_direct */
    char path[DUEL_START_MAX_PATH]; /* DUEL_START_BLOB, DUEL_START_GENOME: as given */
} duel_start;

/* [run] train_layouts: the food of the training games */
enum duel_train_layouts {
    DUEL_TRAIN_FIXED = 0,     /* "training": the rules' training items, every generation (the paper) */
    DUEL_TRAIN_COMPARISON = 1 /* "comparison": one of the 144 comparison layouts, drawn per generation */
};

/* [opponents]: a run of one population against fixed opponents, when play names any */
#define DUEL_MAX_OPPONENTS 16
#define DUEL_OPP_MAX_SPEC 1024
enum duel_fitness {
    DUEL_FIT_WINS = 0,  /* "wins": the games won (the paper's fitness) */
    DUEL_FIT_MARGIN = 1 /* "wins-losses": wins - losses + games played (never negative) */
};
typedef struct duel_opponents {
    uint32_t n;                                       /* 0: a coevolution run */
    char spec[DUEL_MAX_OPPONENTS][DUEL_OPP_MAX_SPEC]; /* builtin:NAME, a champion blob or a genome file */
    uint32_t layouts;   /* games: 0 the training food from both sides, N > 0 N comparison layouts from both sides */
    int fitness;        /* enum duel_fitness */
} duel_opponents;

/* [run] reproduction: libneat's, or NEAT C++ 1.2.1's own, which only a program holding the release
 * (tools/neatcpp/: neatcpp_duel, docs/neat-cpp.md) runs */
enum duel_reproduction { DUEL_REPRODUCE_LIBNEAT = 0, DUEL_REPRODUCE_NEAT_CPP = 1 };

/* [overrides]: parameter changes a run takes from a generation on (resume --set records them here, so that
 * config.ini describes the whole run and run --config RUN/config.ini plays it again); the other sections hold
 * the values of generation 0. One line per generation: "from G = key=value, key=value". */
#define DUEL_MAX_OVERRIDES 16
#define DUEL_OVERRIDE_MAX 160
typedef struct duel_override {
    uint32_t from;                 /* the first generation played with it (at least 1) */
    char sets[DUEL_OVERRIDE_MAX];  /* "key=value, ...": [neat] and [coevolution] keys only */
} duel_override;

typedef struct duel_config {
    uint32_t generations; /* [run] generations to play in all */
    uint32_t seed;        /* [run] */
    int train_layouts;    /* [run] enum duel_train_layouts */
    uint32_t strength_every; /* [run] every K generations the champion against every builtin (strength.csv); 0 never */
    int reproduction;     /* [run] enum duel_reproduction: whose reproduction the coevolution's populations use */
    neat_coev_params coev;
    neat_params neat;
    duel_start start;     /* [neat] start */
    duel_rules world;     /* [world]: the duel's chosen rules (v1 by default) */
    duel_opponents opp;   /* [opponents] */
    uint32_t n_over;      /* [overrides], in increasing generation order */
    duel_override over[DUEL_MAX_OVERRIDES];
} duel_config;

/* The paper's values (Appendix A, section 5): 500 generations, seed 1. */
DUEL_RUN_API void duel_config_default(duel_config *cfg);

/* Loads path over cfg. On error: -1 and one line in err naming the file
 * and line ("FILE:LINE: unknown key 'x' (did you mean 'y'?)"); nothing of
 * cfg is to be used then. */
DUEL_RUN_API int duel_config_load(duel_config *cfg, const char *path, char *err, size_t err_len);
/* The same without the final duel_config_check, for a file that --set
 * overrides will complete (a preset's start = blob placeholder). */
DUEL_RUN_API int duel_config_read(duel_config *cfg, const char *path, char *err, size_t err_len);
/* The same from len bytes of text, named name in the messages. */
DUEL_RUN_API int duel_config_load_text(duel_config *cfg, const char *name, const char *text, size_t len, char *err,
                          size_t err_len);

/* One override, "key=value" or "section.key=value" (a bare key must name
 * one key of one section). -1 with a message in err. */
DUEL_RUN_API int duel_config_set(duel_config *cfg, const char *assignment, char *err, size_t err_len);
/* Applies n overrides as duel_config_set does, in order, except that a [neat] profile among them
 * ("profile=NAME" or "neat.profile=NAME") comes first: a profile sets what the other keys refine, as
 * in an INI file (neat_ini.h). 0, or -1 with err and *bad (if not NULL) the index of the refused one. */
DUEL_RUN_API int duel_config_set_list(duel_config *cfg, const char *const *sets, uint32_t n, uint32_t *bad, char *err,
                         size_t err_len);

/* cfg as played at generation g: every override from g or before applied, in order (out->n_over 0: the
 * schedule is cfg's). 0, or -1 with err (an override that does not apply). */
DUEL_RUN_API int duel_config_at(const duel_config *cfg, uint32_t g, duel_config *out, char *err, size_t err_len);
/* Whether one --set assignment is a parameter a run takes from a generation on ([neat] but start, or
 * [coevolution]): those are what [overrides] records. */
DUEL_RUN_API int duel_config_set_is_param(const char *assignment);
/* Adds sets (n of them, each a parameter assignment) to cfg's overrides from generation g: a new line, or
 * the end of g's line. 0, or -1 with err (too many or too long; a comma in a value). */
DUEL_RUN_API int duel_config_add_override(duel_config *cfg, uint32_t g, const char *const *sets, uint32_t n, char *err,
                             size_t err_len);

/* Every key of every section, in a form duel_config_load reads back to the
 * same configuration. */
DUEL_RUN_API void duel_config_dump(FILE *out, const duel_config *cfg);

/* The start topology's text, as the INI takes it, into buf. */
DUEL_RUN_API void duel_start_text(const duel_start *st, char *buf, size_t cap);

/* The start topology as a genome for neat_coev_create (a blob is read and
 * checked here). 0, or -1 with a message in err naming the file. */
DUEL_RUN_API int duel_start_genome(const duel_config *cfg, neat_genome *g, char *err, size_t err_len);

/* 1 when a and b have the same nodes and the same connections (endpoints,
 * innovation, enabled), whatever their weights. */
DUEL_RUN_API int duel_same_topology(const neat_genome *a, const neat_genome *b);

/* The whole configuration is usable (ranges, the duel's 12 sensors and 3
 * outputs). -1 with a message in err. */
DUEL_RUN_API int duel_config_check(const duel_config *cfg, char *err, size_t err_len);

/* The next item of a comma-separated list ([opponents] play) at *p, blanks around it trimmed: its start and length;
 * *p moves past it and its comma. 1 when a comma followed it, else 0 (the list is done once **p is '\0'). */
DUEL_RUN_API int duel_list_next(const char **p, const char **item, size_t *len);

#ifdef __cplusplus
}
#endif

#endif /* DUEL_CONFIG_H */
