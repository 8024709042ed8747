/* duel_exp.h - an experiment directory: its plan's runs played (several side by side), the best-topology champion chosen, every method measured, the report written. */
#ifndef DUEL_EXP_H
#define DUEL_EXP_H

#include <stdint.h>

#include "duel_plan.h"

typedef struct duel_exp_opts {
    uint32_t jobs;    /* runs side by side (0: one per core) */
    uint32_t threads; /* threads of each run, and of the comparisons (0: every core / jobs) */
    int quiet;        /* no progress line */
} duel_exp_opts;

/* Runs (or continues) the experiment of plan p in dir: a new directory is
 * created; an existing one must hold this very plan. 0; 2 after one line
 * (bad input: a directory of another plan, a run that is not the plan's);
 * 1 after one line (a run or a comparison failed, a file could not be
 * written); 130 when interrupted (continue with the same command). */
int duel_exp_run(const duel_plan *p, const char *dir, const duel_exp_opts *o);

/* The tables, the figures' data and the figures of a finished experiment
 * (nothing is played: every comparison comes from the caches). Same return. */
int duel_exp_report(const duel_plan *p, const char *dir);

/* duel_exp_report in the experiment directory, which is the current one (dir names it in messages). */
int duel_exp_report_here(const duel_plan *p, const char *dir);
/* dir entered (chdir) and locked, holding plan p (create: a new or empty directory becomes one, plan.ini and
 * configs/ written). 0, or the exit status after one line. */
int duel_exp_enter(const duel_plan *p, const char *dir, int create);

/* runs/NAME-K of method i, run k (1-based) */
void duel_exp_run_dir(char *out, size_t cap, const duel_plan *p, uint32_t i, uint32_t k);

#endif /* DUEL_EXP_H */
