/* neat_mutate.c - mutation: weights, add connection, add node (complexifying), remove connection (simplifying). */
#include <string.h>

#include "neat_internal.h"
#include "nrt.h"

static double neat_clamp(double w, double max)
{
    return w > max ? max : (w < -max ? -max : w);
}

/* NEAT C++ 1.2.1's Genome::mutate_link_weights at rate 1.0 (what its
 * reproduction uses): one "severe" coin for the genome; then for each gene
 * a value uniform in [-power, power] that is added (perturbed), replaces
 * the weight, or is dropped, with the chances
 *     severe:                          0.7 / 0.2 / 0.1
 *     not severe, the newest 20 % of
 *     the genes of a genome of >= 10:  0.5 / 0.2 / 0.3
 *     not severe, the others:          1   / 0   / 0
 * (net 0.85 / 0.1 / 0.05 and 0.6 / 0.2 / 0.2), the result capped at
 * weight_max. "Newest" is by position: the genes are in innovation order. */
static void neat_mutate_weights_cpp(neat_genome *g, const neat_params *p, neat_rng *rng)
{
    uint32_t i;
    int severe = neat_rng_uniform_inl(rng) > 0.5;
    double tail_from = 0.8 * (double)g->n_conns;
    for (i = 0; i < g->n_conns; i++) {
        double perturb_above, replace_above, r, choice, *w = &g->conns[i].weight;
        if (severe) {
            perturb_above = 0.3;
            replace_above = 0.1;
        } else if (g->n_conns >= 10 && (double)i > tail_from) {
            perturb_above = 0.5;
            replace_above = 0.3;
        } else {
            perturb_above = 0.0; /* the release's 1 - rate, with rate 1 */
            replace_above = 0.0;
        }
        r = (2.0 * neat_rng_uniform_inl(rng) - 1.0) * p->weight_perturb_power;
        choice = neat_rng_uniform_inl(rng);
        if (choice > perturb_above)
            *w = neat_clamp(*w + r, p->weight_max);
        else if (choice > replace_above)
            *w = neat_clamp(r, p->weight_max);
    }
}

int neat_mutate_weights(neat_genome *g, const neat_params *p, neat_rng *rng)
{
    uint32_t i;
    if (p->weight_mut_rule == NEAT_WEIGHTS_CPP) {
        neat_mutate_weights_cpp(g, p, rng);
        return NEAT_OK;
    }
    for (i = 0; i < g->n_conns; i++) {
        double u = neat_rng_uniform_inl(rng), r = 2.0 * neat_rng_uniform_inl(rng) - 1.0;
        double *w = &g->conns[i].weight;
        if (u < p->weight_perturb_prob)
            *w = neat_clamp(*w + r * p->weight_perturb_power, p->weight_max);
        else
            *w = r * p->weight_replace_range;
    }
    return NEAT_OK;
}

/* Is there a path from 'from' to 'to' along the genome's connections (only
 * its enabled ones if enabled_only)? Used to keep networks feed-forward when
 * recurrence is off, and by NEAT_ADD_CONN_CPP to tell loop-closing links. */
static int neat_reaches_on(const neat_genome *g, uint32_t from, uint32_t to, uint32_t *stack, uint8_t *seen,
                           int enabled_only)
{
    uint32_t sp = 0, i, k;
    memset(seen, 0, g->n_nodes);
    stack[sp++] = from;
    while (sp > 0) {
        uint32_t n = stack[--sp];
        if (n == to)
            return 1;
        for (i = 0; i < g->n_conns; i++) {
            if (g->conns[i].in != n || (enabled_only && !g->conns[i].enabled))
                continue;
            k = (uint32_t)(neat_genome_find_node(g, g->conns[i].out) - g->nodes);
            if (!seen[k]) {
                seen[k] = 1;
                stack[sp++] = g->conns[i].out;
            }
        }
    }
    return 0;
}

static int neat_reaches(const neat_genome *g, uint32_t from, uint32_t to, uint32_t *stack, uint8_t *seen)
{
    return neat_reaches_on(g, from, to, stack, seen, 0);
}

/* NEAT C++ 1.2.1's Genome::mutate_add_link: with recur_only_prob (when
 * recurrence is allowed) only a link that closes a loop is sought, half the
 * tries a self-loop, otherwise only one that closes none; the source is any
 * node, the target an output or hidden node; a loop is a path back along
 * the enabled genes (the release keeps a recurrent flag per gene and
 * follows only the genes not flagged: the structure stands in for it
 * here); a link found again in the same generation gets its innovation and
 * its first weight. */
static int neat_mutate_add_conn_cpp(neat_genome *g, const neat_params *p, neat_rng *rng, neat_innovs *iv,
                                    const neat_alloc *a, uint32_t *stack, uint8_t *seen)
{
    uint32_t t, first = 1 + p->n_inputs, n1, n2, targets;
    int want_loop;
    if (g->n_nodes <= first)
        return NEAT_OK;
    targets = g->n_nodes - first;
    want_loop = p->allow_recurrent && neat_rng_uniform_inl(rng) < p->recur_only_prob;
    for (t = 0; t < p->add_conn_tries; t++) {
        const neat_node *src, *dst;
        int loop;
        if (want_loop && neat_rng_uniform_inl(rng) > 0.5) {
            n1 = n2 = first + neat_rng_below_inl(rng, targets);
        } else {
            n1 = neat_rng_below_inl(rng, g->n_nodes);
            n2 = first + neat_rng_below_inl(rng, targets);
        }
        src = &g->nodes[n1];
        dst = &g->nodes[n2];
        if (neat_genome_has_link(g, src->id, dst->id))
            continue;
        loop = src->id == dst->id || neat_reaches_on(g, dst->id, src->id, stack, seen, 1);
        if (loop == want_loop) {
            neat_innov *rec;
            int fresh, err = neat_innov_conn_rec(iv, a, src->id, dst->id, &rec, &fresh);
            if (err)
                return err;
            if (fresh)
                rec->weight = (2.0 * neat_rng_uniform_inl(rng) - 1.0) * p->weight_init_range;
            return neat_genome_add_conn(g, src->id, dst->id, rec->weight, rec->innov, 1, a);
        }
    }
    return NEAT_OK;
}

int neat_mutate_add_conn(neat_genome *g, const neat_params *p, neat_rng *rng, neat_innovs *iv, const neat_alloc *a)
{
    /* the cycle check's scratch: on the stack for any genome a blob can
     * hold (256 nodes), allocated only for a larger one */
    uint32_t t, innov, *stack = NULL, stack_here[NRT_MAX_NODES];
    uint8_t *seen = NULL, seen_here[NRT_MAX_NODES];
    size_t stack_bytes = (size_t)g->n_nodes * sizeof(uint32_t);
    int err = NEAT_OK, here = g->n_nodes <= NRT_MAX_NODES, cpp = p->add_conn_rule == NEAT_ADD_CONN_CPP;

    if ((!p->allow_recurrent || cpp) && here) {
        stack = stack_here;
        seen = seen_here;
    } else if (!p->allow_recurrent || cpp) {
        stack = (uint32_t *)neat_mem_realloc(a, NULL, 0, stack_bytes);
        seen = (uint8_t *)neat_mem_realloc(a, NULL, 0, g->n_nodes);
        if (stack == NULL || seen == NULL) {
            err = NEAT_E_NOMEM;
            goto cleanup;
        }
    }
    if (cpp) {
        err = neat_mutate_add_conn_cpp(g, p, rng, iv, a, stack, seen);
        goto cleanup;
    }
    for (t = 0; t < p->add_conn_tries; t++) {
        const neat_node *src = &g->nodes[neat_rng_below_inl(rng, g->n_nodes)];
        const neat_node *dst = &g->nodes[neat_rng_below_inl(rng, g->n_nodes)];
        if (dst->type == NEAT_NODE_BIAS || dst->type == NEAT_NODE_INPUT)
            continue;
        if (neat_genome_has_link(g, src->id, dst->id))
            continue;
        if (!p->allow_recurrent && (src->id == dst->id || neat_reaches(g, dst->id, src->id, stack, seen)))
            continue;
        err = neat_innov_conn(iv, a, src->id, dst->id, &innov);
        if (!err)
            err = neat_genome_add_conn(g, src->id, dst->id, (2.0 * neat_rng_uniform_inl(rng) - 1.0) * p->weight_init_range,
                                       innov, 1, a);
        break;
    }
cleanup:
    if (!here) {
        neat_mem_free(a, stack, stack_bytes);
        neat_mem_free(a, seen, g->n_nodes);
    }
    return err;
}

int neat_mutate_add_node(neat_genome *g, const neat_params *p, neat_rng *rng, neat_innovs *iv, const neat_alloc *a)
{
    uint32_t t, k, in, out, node;
    double w;
    neat_innov rec;
    int err;

    if (g->n_nodes >= p->max_nodes || g->n_conns == 0)
        return NEAT_OK;
    /* as the C++ release: 20 tries for an enabled gene not leaving the bias */
    for (t = 0; t < 20; t++) {
        k = neat_rng_below_inl(rng, g->n_conns);
        if (g->conns[k].enabled && neat_genome_find_node(g, g->conns[k].in)->type != NEAT_NODE_BIAS)
            break;
    }
    if (t == 20)
        return NEAT_OK;
    in = g->conns[k].in;
    out = g->conns[k].out;
    w = g->conns[k].weight;
    err = neat_innov_node(iv, a, in, out, g->conns[k].innov, &rec);
    if (err)
        return err;
    node = rec.node;
    if (neat_genome_find_node(g, node) != NULL) {
        /* this genome already has that split's node (from a crossover of the
         * same generation): a fresh node and genes keep the genome valid */
        rec.node = node = iv->next_node++;
        rec.innov = iv->next_innov++;
        rec.innov2 = iv->next_innov++;
    }
    g->conns[k].enabled = 0;
    err = neat_genome_add_node(g, node, NEAT_NODE_HIDDEN, a);
    if (!err)
        err = neat_genome_add_conn(g, in, node, 1.0, rec.innov, 1, a);
    if (!err)
        err = neat_genome_add_conn(g, node, out, w, rec.innov2, 1, a);
    return err;
}

int neat_mutate_remove_conn(neat_genome *g, neat_rng *rng)
{
    uint32_t k, i, id, used;
    if (g->n_conns == 0)
        return NEAT_OK;
    k = neat_rng_below_inl(rng, g->n_conns);
    memmove(g->conns + k, g->conns + k + 1, (g->n_conns - k - 1) * sizeof(neat_conn));
    g->n_conns--;
    /* hidden nodes left without any connection gene go too */
    for (i = 0; i < g->n_nodes;) {
        if (g->nodes[i].type == NEAT_NODE_HIDDEN) {
            id = g->nodes[i].id;
            used = 0;
            for (k = 0; k < g->n_conns && !used; k++)
                used = g->conns[k].in == id || g->conns[k].out == id;
            if (!used) {
                memmove(g->nodes + i, g->nodes + i + 1, (g->n_nodes - i - 1) * sizeof(neat_node));
                g->n_nodes--;
                continue;
            }
        }
        i++;
    }
    return NEAT_OK;
}

int neat_mutate(neat_genome *g, const neat_params *p, neat_rng *rng, neat_innovs *iv, const neat_alloc *a)
{
    /* As the C++ release: a structural mutation takes the place of the
     * weight mutation for that offspring (docs/parameters.md). */
    switch (p->mode) {
    case NEAT_MODE_COMPLEXIFY:
        if (neat_rng_uniform_inl(rng) < p->add_node_prob)
            return neat_mutate_add_node(g, p, rng, iv, a);
        if (neat_rng_uniform_inl(rng) < p->add_conn_prob)
            return neat_mutate_add_conn(g, p, rng, iv, a);
        break;
    case NEAT_MODE_SIMPLIFY:
        if (neat_rng_uniform_inl(rng) < p->add_node_prob + p->add_conn_prob)
            return neat_mutate_remove_conn(g, rng);
        break;
    default:
        break;
    }
    if (neat_rng_uniform_inl(rng) < p->weight_mut_prob)
        return neat_mutate_weights(g, p, rng);
    return NEAT_OK;
}
