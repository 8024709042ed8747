/* duel_trace.h - the per-step CSV trace of a game (columns in docs/duelsim.md), as play --trace and log dump print it. */
#ifndef DUEL_TRACE_H
#define DUEL_TRACE_H

#include <stdint.h>
#include <stdio.h>

#include "duel.h"

/* How a side stepped (the values of duel_net_t's step, and one more). */
enum {
    DUEL_TRACE_STEP_UNKNOWN = -2, /* a log that does not say (written before the net messages existed) */
    DUEL_TRACE_STEP_BUILTIN = -1, /* a built-in strategy: no network */
    DUEL_TRACE_STEP_SYNC = 0,     /* NRT_STEP_SYNC */
    DUEL_TRACE_STEP_PROPAGATE = 1 /* NRT_STEP_PROPAGATE */
};

/* A trace being written: every row ends with the world's identity and both
 * sides' step modes, so a trace copied anywhere still says what made it. */
typedef struct duel_trace {
    FILE *f;
    uint64_t world_id; /* duel_rules_id of the rules played */
    int step[2];       /* DUEL_TRACE_STEP_*, west and east */
} duel_trace;

/* The step of a controller: builtin, or its network's mode. */
int duel_trace_step_of(const duel_controller *c);
/* "sync", "propagate", "builtin", "unknown" */
const char *duel_trace_step_name(int step);
/* The CSV trace of docs/duelsim.md: header, then one row per step (a
 * duel_trace_fn: ud is the duel_trace). */
void duel_trace_header(FILE *f);
void duel_trace_row(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                    const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev);

#endif /* DUEL_TRACE_H */
