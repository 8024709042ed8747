/* duel_netgraph.h - a champion network's graph as people look at it: targets, recurrent connections, layers by depth, dead nodes and node names (inspect, dot and the web pages). */
#ifndef DUEL_NETGRAPH_H
#define DUEL_NETGRAPH_H

#include <stdint.h>

#include "nrt.h"

#define DUEL_NETGRAPH_NAME 24 /* longest node name, with its terminator */

/* What inspect, dot and the web pages derive from a loaded network. Node v:
 * 0..n_inputs-1 inputs (0 the bias), then the outputs, then the hidden nodes. */
typedef struct duel_netgraph {
    const nrt_net *net;  /* the caller keeps it alive */
    uint16_t *dst;       /* [n_conns] target node of each connection */
    uint8_t *recurrent;  /* [n_conns] 1 if the connection lies on a directed cycle */
    unsigned n_recurrent;
    /* the drawing's layers: depth[v] of a hidden node is the longest path of
     * feed-forward (not recurrent) connections from an input, at least 1;
     * inputs 0; max_depth the largest hidden depth */
    int depth[NRT_MAX_NODES], max_depth;
    /* dead[v]: a hidden node no input reaches or that reaches no output
     * (what it computes never gets from the sensors to the motors) */
    uint8_t dead[NRT_MAX_NODES];
    unsigned n_dead;
    int duel_names;      /* 13 inputs and 3 outputs: the duel's sensor and motor names */
    uint32_t n_in[NRT_MAX_NODES], n_out[NRT_MAX_NODES]; /* connections into and out of each node */
} duel_netgraph;

/* The graph of a loaded network. 0, or -1 when out of memory (g is then
 * empty and duel_netgraph_free may still be called). */
int duel_netgraph_build(duel_netgraph *g, const nrt_net *net);
void duel_netgraph_free(duel_netgraph *g);

/* "bias", "input", "output" or "hidden" */
const char *duel_netgraph_kind(const duel_netgraph *g, unsigned v);
/* Node v's name: the duel's sensor or motor name (food_ahead, turn_left,
 * ...), else bias, inK, outK; hK for hidden node index K. */
const char *duel_netgraph_name(const duel_netgraph *g, unsigned v, char buf[DUEL_NETGRAPH_NAME]);
/* Whether node v is an output. */
int duel_netgraph_is_output(const duel_netgraph *g, unsigned v);
/* Whether connection k sets the drawing's layers: a feed-forward one (not
 * on a cycle) that does not leave an output (the outputs are the top layer
 * whatever they feed back into). These form a DAG. */
int duel_netgraph_layering(const duel_netgraph *g, uint32_t k);

#endif /* DUEL_NETGRAPH_H */
