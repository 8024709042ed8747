/* duel_run_show.h - what duel_evolve run and resume show of a run engine's work: a line a generation, --json, the progress bar, the interruption and the last line. */
#ifndef DUEL_RUN_SHOW_H
#define DUEL_RUN_SHOW_H

#include <stdint.h>

#include "duel_engine.h"

/* What the command shows of a run: the options that are its own, and the progress bar's state. */
typedef struct duel_show {
    duel_engine *E;
    int quiet, json, tty;
    double started;            /* monotonic seconds when this process's first generation started */
    uint32_t first_gen;        /* the generation this process started at */
    int bar_shown;
    double bar_drawn;          /* when the bar was last drawn */
} duel_show;

/* S empty and o's hooks S's (every option 0); the MPI job's ranks registered as the engine's executor. */
void duel_show_init(duel_show *S, duel_engine_options *o);
/* S->E's generations to the end or a signal (SIGINT, SIGTERM: the generation in flight finishes), shown; the engine
 * closed. Its status, the command's exit status. */
int duel_show_play_out(duel_show *S);

#endif /* DUEL_RUN_SHOW_H */
