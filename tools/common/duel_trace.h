/* duel_trace.h - the per-step CSV trace of a game (columns in docs/duelsim.md), as play --trace and log dump print it. */
#ifndef DUEL_TRACE_H
#define DUEL_TRACE_H

#include <stdio.h>

#include "duel.h"

/* The CSV trace of docs/duelsim.md: header, then one row per step (a
 * duel_trace_fn: file is the FILE *). */
void duel_trace_header(FILE *f);
void duel_trace_row(void *file, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                    const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev);

#endif /* DUEL_TRACE_H */
