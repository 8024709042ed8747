/* neat_genome.c - genomes: node and connection genes, start topologies, compatibility distance. */
#include <math.h>
#include <string.h>

#include "neat_internal.h"

void neat_genome_init(neat_genome *g)
{
    memset(g, 0, sizeof *g);
}

void neat_genome_free(neat_genome *g, const neat_alloc *a)
{
    neat_mem_free(a, g->nodes, (size_t)g->cap_nodes * sizeof(neat_node));
    neat_mem_free(a, g->conns, (size_t)g->cap_conns * sizeof(neat_conn));
    neat_genome_init(g);
}

int neat_genome_copy(neat_genome *dst, const neat_genome *src, const neat_alloc *a)
{
    if (dst == src)
        return NEAT_OK;
    if (neat_mem_reserve(a, (void **)&dst->nodes, &dst->cap_nodes, src->n_nodes, sizeof(neat_node)) ||
        neat_mem_reserve(a, (void **)&dst->conns, &dst->cap_conns, src->n_conns, sizeof(neat_conn)))
        return NEAT_E_NOMEM;
    if (src->n_nodes)
        memcpy(dst->nodes, src->nodes, src->n_nodes * sizeof(neat_node));
    if (src->n_conns)
        memcpy(dst->conns, src->conns, src->n_conns * sizeof(neat_conn));
    dst->n_nodes = src->n_nodes;
    dst->n_conns = src->n_conns;
    dst->fitness = src->fitness;
    dst->has_fitness = src->has_fitness;
    dst->species = src->species;
    return NEAT_OK;
}

/* index of the first node with id >= id (nodes are sorted by id) */
static uint32_t neat_node_lower(const neat_genome *g, uint32_t id)
{
    uint32_t lo = 0, hi = g->n_nodes;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (g->nodes[mid].id < id)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

const neat_node *neat_genome_find_node(const neat_genome *g, uint32_t id)
{
    uint32_t i = neat_node_lower(g, id);
    return (i < g->n_nodes && g->nodes[i].id == id) ? &g->nodes[i] : NULL;
}

int neat_genome_add_node(neat_genome *g, uint32_t id, int type, const neat_alloc *a)
{
    uint32_t i;
    if (type < NEAT_NODE_BIAS || type > NEAT_NODE_HIDDEN)
        return NEAT_E_ARG;
    i = neat_node_lower(g, id);
    if (i < g->n_nodes && g->nodes[i].id == id)
        return NEAT_E_ARG;
    if (neat_mem_reserve(a, (void **)&g->nodes, &g->cap_nodes, g->n_nodes + 1, sizeof(neat_node)))
        return NEAT_E_NOMEM;
    memmove(g->nodes + i + 1, g->nodes + i, (g->n_nodes - i) * sizeof(neat_node));
    g->nodes[i].id = id;
    g->nodes[i].type = (uint8_t)type;
    g->n_nodes++;
    return NEAT_OK;
}

int neat_genome_add_conn(neat_genome *g, uint32_t in, uint32_t out, double weight, uint32_t innov, int enabled,
                         const neat_alloc *a)
{
    uint32_t i = g->n_conns;
    const neat_node *dst = neat_genome_find_node(g, out);
    if (neat_genome_find_node(g, in) == NULL || dst == NULL || dst->type == NEAT_NODE_BIAS ||
        dst->type == NEAT_NODE_INPUT)
        return NEAT_E_ARG;
    if (neat_mem_reserve(a, (void **)&g->conns, &g->cap_conns, g->n_conns + 1, sizeof(neat_conn)))
        return NEAT_E_NOMEM;
    /* keep innovation order: new genes are usually the newest, so scan back */
    while (i > 0 && g->conns[i - 1].innov > innov)
        i--;
    if (i > 0 && g->conns[i - 1].innov == innov)
        return NEAT_E_ARG;
    memmove(g->conns + i + 1, g->conns + i, (g->n_conns - i) * sizeof(neat_conn));
    g->conns[i].in = in;
    g->conns[i].out = out;
    g->conns[i].weight = weight;
    g->conns[i].innov = innov;
    g->conns[i].enabled = (uint8_t)(enabled != 0);
    g->n_conns++;
    return NEAT_OK;
}

int neat_genome_has_link(const neat_genome *g, uint32_t in, uint32_t out)
{
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].in == in && g->conns[i].out == out)
            return 1;
    return 0;
}

/* bias (id 0), inputs 1..n_in, outputs n_in+1..n_in+n_out */
static int neat_genome_io(neat_genome *g, uint32_t n_in, uint32_t n_out, const neat_alloc *a)
{
    uint32_t i;
    int err = neat_genome_add_node(g, 0, NEAT_NODE_BIAS, a);
    for (i = 1; !err && i <= n_in; i++)
        err = neat_genome_add_node(g, i, NEAT_NODE_INPUT, a);
    for (i = 0; !err && i < n_out; i++)
        err = neat_genome_add_node(g, n_in + 1 + i, NEAT_NODE_OUTPUT, a);
    return err;
}

int neat_genome_io_ok(const neat_genome *g, uint32_t n_in, uint32_t n_out)
{
    uint32_t i;
    if (g->n_nodes < n_in + 1 + n_out)
        return 0;
    for (i = 0; i < n_in + 1 + n_out; i++) {
        int want = i == 0 ? NEAT_NODE_BIAS : (i <= n_in ? NEAT_NODE_INPUT : NEAT_NODE_OUTPUT);
        if (g->nodes[i].id != i || g->nodes[i].type != want)
            return 0;
    }
    for (; i < g->n_nodes; i++)
        if (g->nodes[i].type != NEAT_NODE_HIDDEN)
            return 0;
    return 1;
}

int neat_genome_minimal(neat_genome *g, uint32_t n_in, uint32_t n_out, const neat_alloc *a)
{
    uint32_t o, s, innov = 0;
    int err;
    neat_genome_init(g);
    err = neat_genome_io(g, n_in, n_out, a);
    for (o = 0; !err && o < n_out; o++)
        for (s = 0; !err && s <= n_in; s++)
            err = neat_genome_add_conn(g, s, n_in + 1 + o, 0.0, innov++, 1, a);
    if (err)
        neat_genome_free(g, a);
    return err;
}

int neat_genome_recurrent_hidden(neat_genome *g, uint32_t n_in, uint32_t n_out, uint32_t n_hid, int direct,
                                 const neat_alloc *a)
{
    uint32_t h, k, s, o, innov = 0, first_hid = n_in + n_out + 1;
    int err;
    neat_genome_init(g);
    if (direct != NEAT_DIRECT_INPUTS && direct != NEAT_DIRECT_BIAS)
        return NEAT_E_ARG;
    err = neat_genome_io(g, n_in, n_out, a);
    for (h = 0; !err && h < n_hid; h++)
        err = neat_genome_add_node(g, first_hid + h, NEAT_NODE_HIDDEN, a);
    for (h = 0; !err && h < n_hid; h++)
        for (s = 0; !err && s <= n_in; s++)
            err = neat_genome_add_conn(g, s, first_hid + h, 0.0, innov++, 1, a);
    for (h = 0; !err && h < n_hid; h++)
        for (k = 0; !err && k < n_hid; k++)
            err = neat_genome_add_conn(g, first_hid + k, first_hid + h, 0.0, innov++, 1, a);
    for (o = 0; !err && o < n_out; o++)
        for (h = 0; !err && h < n_hid; h++)
            err = neat_genome_add_conn(g, first_hid + h, n_in + 1 + o, 0.0, innov++, 1, a);
    for (o = 0; !err && o < n_out; o++)
        for (s = 0; !err && s <= (direct == NEAT_DIRECT_BIAS ? 0u : n_in); s++)
            err = neat_genome_add_conn(g, s, n_in + 1 + o, 0.0, innov++, 1, a);
    if (err)
        neat_genome_free(g, a);
    return err;
}

uint32_t neat_genome_hidden_count(const neat_genome *g)
{
    uint32_t i, n = 0;
    for (i = 0; i < g->n_nodes; i++)
        n += g->nodes[i].type == NEAT_NODE_HIDDEN;
    return n;
}

uint32_t neat_genome_enabled_count(const neat_genome *g)
{
    uint32_t i, n = 0;
    for (i = 0; i < g->n_conns; i++)
        n += g->conns[i].enabled;
    return n;
}

void neat_genome_randomize(neat_genome *g, neat_rng *rng, double range)
{
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        g->conns[i].weight = (2.0 * neat_rng_uniform_inl(rng) - 1.0) * range;
}

/* The compatibility distance, or stop as soon as the disjoint genes alone
 * reach it. That early answer is exact for a caller asking "distance <
 * stop?": every term of the sum is >= 0 (c1..c3 are, params_check says so)
 * and rounding is monotone, so the term c2 * disjoint / n can only grow as
 * more genes are counted, and the rounded sum of it with non-negative terms
 * is at least it; once it is >= stop, the whole distance is too. */
static double neat_distance(const neat_genome *a, const neat_genome *b, const neat_params *p, double stop)
{
    const neat_conn *ca = a->conns, *cb = b->conns;
    uint32_t i = 0, j = 0, na = a->n_conns, nb = b->n_conns, matching = 0, disjoint = 0, excess;
    double wdiff = 0.0, n = 1.0, w;
    if (p->normalize_by_size) {
        n = (double)(na > nb ? na : nb);
        if (n < 1.0)
            n = 1.0;
    }
    /* While both genomes have genes left, an unmatched gene lies below the
     * other genome's next (so its last) innovation: disjoint. What is left
     * after one genome runs out lies beyond its last innovation: excess. */
    while (i < na && j < nb) {
        uint32_t ia = ca[i].innov, ib = cb[j].innov;
        if (ia == ib) {
            wdiff += fabs(ca[i].weight - cb[j].weight);
            matching++;
            i++;
            j++;
        } else {
            disjoint++;
            if (ia < ib)
                i++;
            else
                j++;
            if (p->c2 * disjoint / n >= stop)
                return stop;
        }
    }
    excess = (na - i) + (nb - j);
    w = matching ? wdiff / matching : 0.0;
    return p->c1 * excess / n + p->c2 * disjoint / n + p->c3 * w;
}

double neat_genome_distance(const neat_genome *a, const neat_genome *b, const neat_params *p)
{
    return neat_distance(a, b, p, HUGE_VAL); /* never reached: the terms are finite */
}

int neat_genome_compatible(const neat_genome *a, const neat_genome *b, const neat_params *p, double delta_t)
{
    return neat_distance(a, b, p, delta_t) < delta_t;
}
