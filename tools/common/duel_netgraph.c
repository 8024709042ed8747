/* duel_netgraph.c - a loaded network's graph: connection targets, recurrent connections (Tarjan's components), layers by depth, dead nodes and node names. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel.h"
#include "duel_netgraph.h"

/* Names of the duel's inputs (docs/duelsim.md, sensors in the spec's order;
 * rangefinder sector k is centred on heading + k * 72 degrees counter-clockwise)
 * and outputs. Networks of other sizes get generic names. */
static const char *const duel_ng_inputs[DUEL_N_INPUTS] = {
    "bias",           "food_ahead",  "food_left",       "food_back_left",   "food_back_right",
    "food_right",     "robot_ahead", "robot_left",      "robot_back_left",  "robot_back_right",
    "robot_right",    "energy_diff", "wall"};
static const char *const duel_ng_outputs[DUEL_N_OUTPUTS] = {"turn_left", "turn_right", "forward"};

/* Tarjan's strongly connected components over the network's nodes (a DFS;
 * depth at most NRT_MAX_NODES). */
typedef struct duel_ng_scc {
    duel_netgraph *g;
    const uint32_t *first; /* [n_nodes + 1] outgoing connections of node v: by_src[first[v] .. first[v+1]) */
    const uint32_t *by_src;
    int index[NRT_MAX_NODES], low[NRT_MAX_NODES], comp[NRT_MAX_NODES];
    uint8_t on_stack[NRT_MAX_NODES];
    uint16_t stack[NRT_MAX_NODES];
    int sp, next_index, n_comp;
} duel_ng_scc;

static void duel_ng_scc_visit(duel_ng_scc *s, unsigned v)
{
    uint32_t e;
    s->index[v] = s->low[v] = s->next_index++;
    s->stack[s->sp++] = (uint16_t)v;
    s->on_stack[v] = 1;
    for (e = s->first[v]; e < s->first[v + 1]; e++) {
        unsigned w = s->g->dst[s->by_src[e]];
        if (s->index[w] < 0) {
            duel_ng_scc_visit(s, w);
            if (s->low[w] < s->low[v])
                s->low[v] = s->low[w];
        } else if (s->on_stack[w] && s->index[w] < s->low[v]) {
            s->low[v] = s->index[w];
        }
    }
    if (s->low[v] == s->index[v]) {
        unsigned w;
        do {
            w = s->stack[--s->sp];
            s->on_stack[w] = 0;
            s->comp[w] = s->n_comp;
        } while (w != v);
        s->n_comp++;
    }
}

/* Marks the recurrent connections: source and target in one strongly
 * connected component, i.e. the target reaches the source again (a self
 * loop included). Independent of node or connection order. Returns 0 or -1
 * (out of memory). */
static int duel_ng_recurrence(duel_netgraph *g)
{
    const nrt_net *n = g->net;
    duel_ng_scc *s = (duel_ng_scc *)calloc(1, sizeof *s);
    uint32_t *first = (uint32_t *)calloc(n->n_nodes + 1u, sizeof *first);
    uint32_t *by_src = (uint32_t *)malloc((n->n_conns + 1u) * sizeof *by_src);
    uint32_t k, fill[NRT_MAX_NODES];
    unsigned v;

    if (s == NULL || first == NULL || by_src == NULL) {
        free(s);
        free(first);
        free(by_src);
        return -1;
    }
    for (k = 0; k < n->n_conns; k++)
        first[n->src[k] + 1]++;
    for (v = 0; v < n->n_nodes; v++) {
        first[v + 1] += first[v];
        fill[v] = first[v];
    }
    for (k = 0; k < n->n_conns; k++)
        by_src[fill[n->src[k]]++] = k;
    s->g = g;
    s->first = first;
    s->by_src = by_src;
    for (v = 0; v < n->n_nodes; v++)
        s->index[v] = -1;
    for (v = 0; v < n->n_nodes; v++)
        if (s->index[v] < 0)
            duel_ng_scc_visit(s, v);
    g->n_recurrent = 0;
    for (k = 0; k < n->n_conns; k++) {
        g->recurrent[k] = s->comp[n->src[k]] == s->comp[g->dst[k]];
        g->n_recurrent += g->recurrent[k];
    }
    free(s);
    free(first);
    free(by_src);
    return 0;
}

int duel_netgraph_is_output(const duel_netgraph *g, unsigned v)
{
    return v >= g->net->n_inputs && v < (unsigned)(g->net->n_inputs + g->net->n_outputs);
}

/* Whether connection k sets the drawing's layers: a feed-forward one (not
 * on a cycle) that does not leave an output (the outputs are the top layer
 * whatever they feed back into). These form a DAG. */
int duel_netgraph_layering(const duel_netgraph *g, uint32_t k)
{
    return !g->recurrent[k] && !duel_netgraph_is_output(g, g->net->src[k]);
}

/* Depths and dead nodes (after duel_ng_recurrence). Relaxation over the
 * connections rather than a topological sort: at most n_nodes rounds of a
 * few hundred connections, and the same answer for any connection order. */
static void duel_ng_layers(duel_netgraph *g)
{
    const nrt_net *n = g->net;
    uint8_t from_in[NRT_MAX_NODES], to_out[NRT_MAX_NODES];
    unsigned v, round, n_io = (unsigned)(n->n_inputs + n->n_outputs);
    uint32_t k;
    int changed = 1;

    for (v = 0; v < n->n_nodes; v++) {
        g->depth[v] = v < n->n_inputs ? 0 : 1;
        from_in[v] = v < n->n_inputs;
        to_out[v] = duel_netgraph_is_output(g, v);
    }
    for (round = 0; changed && round <= n->n_nodes; round++) {
        changed = 0;
        for (k = 0; k < n->n_conns; k++) {
            unsigned a = n->src[k], b = g->dst[k];
            if (duel_netgraph_layering(g, k) && b >= n_io && g->depth[a] + 1 > g->depth[b]) {
                g->depth[b] = g->depth[a] + 1;
                changed = 1;
            }
            if (from_in[a] && !from_in[b])
                from_in[b] = changed = 1;
            if (to_out[b] && !to_out[a])
                to_out[a] = changed = 1;
        }
    }
    g->max_depth = 0;
    g->n_dead = 0;
    for (v = n_io; v < n->n_nodes; v++) {
        if (g->depth[v] > g->max_depth)
            g->max_depth = g->depth[v];
        g->dead[v] = !from_in[v] || !to_out[v];
        g->n_dead += g->dead[v];
    }
}

int duel_netgraph_build(duel_netgraph *g, const nrt_net *n)
{
    uint32_t k;
    unsigned j;

    memset(g, 0, sizeof *g);
    g->net = n;
    g->dst = (uint16_t *)malloc((n->n_conns + 1u) * sizeof *g->dst);
    g->recurrent = (uint8_t *)malloc(n->n_conns + 1u);
    if (g->dst == NULL || g->recurrent == NULL) {
        duel_netgraph_free(g);
        return -1;
    }
    /* the connections into non-input node j end at end[j], start where j-1's end */
    for (j = 0, k = 0; j < (unsigned)(n->n_nodes - n->n_inputs); j++)
        for (; k < n->end[j]; k++)
            g->dst[k] = (uint16_t)(n->n_inputs + j);
    for (k = 0; k < n->n_conns; k++) {
        g->n_out[n->src[k]]++;
        g->n_in[g->dst[k]]++;
    }
    if (duel_ng_recurrence(g) != 0) {
        duel_netgraph_free(g);
        return -1;
    }
    duel_ng_layers(g);
    g->duel_names = n->n_inputs == DUEL_N_INPUTS && n->n_outputs == DUEL_N_OUTPUTS;
    return 0;
}

void duel_netgraph_free(duel_netgraph *g)
{
    free(g->dst);
    free(g->recurrent);
    memset(g, 0, sizeof *g);
}

const char *duel_netgraph_kind(const duel_netgraph *g, unsigned v)
{
    if (v == 0)
        return "bias";
    if (v < g->net->n_inputs)
        return "input";
    return v < (unsigned)(g->net->n_inputs + g->net->n_outputs) ? "output" : "hidden";
}

const char *duel_netgraph_name(const duel_netgraph *g, unsigned v, char buf[DUEL_NETGRAPH_NAME])
{
    unsigned n_in = g->net->n_inputs, n_out = g->net->n_outputs;
    if (v == 0)
        return "bias";
    if (v < n_in) {
        if (g->duel_names)
            return duel_ng_inputs[v];
        snprintf(buf, DUEL_NETGRAPH_NAME, "in%u", v);
    } else if (v < n_in + n_out) {
        if (g->duel_names)
            return duel_ng_outputs[v - n_in];
        snprintf(buf, DUEL_NETGRAPH_NAME, "out%u", v - n_in);
    } else {
        snprintf(buf, DUEL_NETGRAPH_NAME, "h%u", v);
    }
    return buf;
}
