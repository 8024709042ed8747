/* duel_plan.h - an experiment's plan: methods (a run configuration and a number of seeds each), the overrides every run shares, and the reference method whose rankings measure them all. */
/* tools/experiment/: duel_evolve experiment: the plan, the runs and comparisons it calls for, the tables, statistics and figure data it reports, and the plotting script. */
#ifndef DUEL_PLAN_H
#define DUEL_PLAN_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "duel_config.h"

#define DUEL_PLAN_MAX_METHODS 32
#define DUEL_PLAN_MAX_SETS 32     /* overrides in one section */
/* The first line of an experiment directory's configs/NAME.ini: the preset it was made from. */
#define DUEL_PLAN_PRESET_MARK "; made from preset "
#define DUEL_PLAN_MAX_NAME 48     /* a method's name: letters, digits, '-' and '_' */
#define DUEL_PLAN_MAX_RUNS 1000   /* runs of one method */
#define DUEL_PLAN_SET_LEN 1002    /* "key=value" of one INI line */
#define DUEL_PLAN_BEST_BLOB "best-topology.blob" /* start = best: the chosen champion, in the experiment directory */

typedef struct duel_plan_method {
    char name[DUEL_PLAN_MAX_NAME + 1];
    char preset[256];          /* preset = NAME: PRESETS/NAME.ini */
    uint32_t runs;
    int start_best;            /* start = best: the reference method's best champion */
    uint32_t n_sets;
    char sets[DUEL_PLAN_MAX_SETS][DUEL_PLAN_SET_LEN]; /* the other keys, "key=value", in file order */
    duel_config cfg;           /* preset, then [all runs], then these; seed = the plan's */
    char *cfg_text;            /* its configs/NAME.ini (malloc'd) */
} duel_plan_method;

typedef struct duel_plan {
    char reference[DUEL_PLAN_MAX_NAME + 1]; /* [experiment] reference (default: the first method) */
    uint32_t ref;              /* its index */
    uint32_t seed;             /* [experiment] seed: run k of a method (1, 2, ...) has seed + k - 1 */
    char presets[4096];        /* [experiment] presets: a directory, relative to the plan file */
    uint32_t n_sets;
    char sets[DUEL_PLAN_MAX_SETS][DUEL_PLAN_SET_LEN]; /* [all runs] */
    uint32_t n_methods;
    duel_plan_method m[DUEL_PLAN_MAX_METHODS];
} duel_plan;

/* Reads the plan at path, each method's preset, and extra ("key=value", applied after [all runs]: `--set`), into a
 * malloc'd *out. 0, or -1 with one line in err naming the file and line (or the preset and its line). */
int duel_plan_load(duel_plan **out, const char *path, const char *const *extra, uint32_t n_extra, char *err,
                   size_t err_len);
/* len bytes of a plan's text (named name in messages) parsed and checked, no preset read and no configuration
 * built (m[].cfg_text NULL). 0, or -1 with "NAME:LINE: problem" or "NAME: problem" in err; *out to free either way. */
int duel_plan_parse_text(duel_plan **out, const char *name, const char *text, size_t len, char *err, size_t err_len);
/* An experiment directory's plan.ini and configs/NAME.ini, as duel_plan_save wrote them. Same return. */
int duel_plan_load_dir(duel_plan **out, const char *dir, char *err, size_t err_len);
void duel_plan_free(duel_plan *p);

/* What the plan runs, a line per method (name, preset, runs, population, generations, start), and the total. */
void duel_plan_print(FILE *f, const duel_plan *p);

/* The plan's canonical text (what plan.ini holds), malloc'd, NULL when out of memory. */
char *duel_plan_text(const duel_plan *p);
/* Writes DIR/plan.ini and DIR/configs/NAME.ini. 0, or -1 after one line on stderr. */
int duel_plan_save(const duel_plan *p, const char *dir);

/* The config.ini text run k (1-based) of method i must have (its seed set), malloc'd, NULL when out of memory. */
char *duel_plan_run_config(const duel_plan *p, uint32_t i, uint32_t k);
/* The configuration file at path as this build writes it (read, then
 * dumped): a file an earlier build wrote, its reals in another form (0.3 as
 * 0.29999999999999999), compares equal to the plan's text. NULL (malloc'd
 * otherwise) if it does not read: compare its own bytes then. */
char *duel_plan_cfg_canonical(const char *path);
/* The first line where a and b differ (1-based; 0: equal), and that line of each into la and lb. */
uint32_t duel_plan_diff(const char *a, const char *b, char *la, char *lb, size_t cap);

#endif /* DUEL_PLAN_H */
