/* neat_crossover.c - crossover: genes lined up by innovation number (the paper's Figure 4). */
#include "neat_internal.h"

/* Appends a gene to the child unless it duplicates a link the child has. */
static int neat_take(neat_genome *child, const neat_conn *c, double weight, int enabled, const neat_alloc *a)
{
    if (neat_genome_has_link(child, c->in, c->out))
        return NEAT_OK;
    return neat_genome_add_conn(child, c->in, c->out, weight, c->innov, enabled, a);
}

/* The child's nodes, from all nodes of both parents (pool, n): every
 * non-hidden node, and the hidden nodes its genes use. */
static int neat_child_nodes(neat_genome *child, const neat_node *pool, uint32_t n, const neat_alloc *a)
{
    uint32_t i, k;
    int err = NEAT_OK;
    for (i = 0; i < n && !err; i++) {
        int used = pool[i].type != NEAT_NODE_HIDDEN;
        for (k = 0; k < child->n_conns && !used; k++)
            used = child->conns[k].in == pool[i].id || child->conns[k].out == pool[i].id;
        if (used)
            err = neat_genome_add_node(child, pool[i].id, pool[i].type, a);
    }
    return err;
}

int neat_crossover(neat_genome *child, const neat_genome *mom, const neat_genome *dad, int avg, const neat_params *p,
                   neat_rng *rng, const neat_alloc *a)
{
    uint32_t i = 0, j = 0;
    int better; /* 0: mom, 1: dad, -1: equal fitness */
    int err = NEAT_OK;
    neat_genome tmp;

    child->n_nodes = 0;
    child->n_conns = 0;
    child->has_fitness = 0;
    child->fitness = 0;
    better = mom->fitness > dad->fitness ? 0 : (dad->fitness > mom->fitness ? 1 : -1);

    /* Genes first (add_conn checks endpoints, so nodes go in a scratch pass):
     * gather the genes into tmp with every node of both parents present. */
    neat_genome_init(&tmp);
    for (i = 0; i < mom->n_nodes && !err; i++)
        err = neat_genome_add_node(&tmp, mom->nodes[i].id, mom->nodes[i].type, a);
    for (i = 0; i < dad->n_nodes && !err; i++)
        if (neat_genome_find_node(&tmp, dad->nodes[i].id) == NULL)
            err = neat_genome_add_node(&tmp, dad->nodes[i].id, dad->nodes[i].type, a);

    i = 0;
    while (!err && (i < mom->n_conns || j < dad->n_conns)) {
        if (i < mom->n_conns && j < dad->n_conns && mom->conns[i].innov == dad->conns[j].innov) {
            const neat_conn *cm = &mom->conns[i], *cd = &dad->conns[j];
            const neat_conn *pick = neat_rng_uniform(rng) < 0.5 ? cm : cd;
            double w = avg ? 0.5 * (cm->weight + cd->weight) : pick->weight;
            int enabled = 1;
            if (!cm->enabled || !cd->enabled)
                enabled = !(neat_rng_uniform(rng) < p->disable_prob);
            err = neat_take(&tmp, pick, w, enabled, a);
            i++;
            j++;
        } else {
            /* disjoint or excess: only the fitter parent's, at equal fitness either's, drawn by the PRNG */
            int from_dad = j < dad->n_conns && (i >= mom->n_conns || dad->conns[j].innov < mom->conns[i].innov);
            const neat_conn *c = from_dad ? &dad->conns[j] : &mom->conns[i];
            int keep = better < 0 ? neat_rng_uniform(rng) < p->excess_equal_prob : better == from_dad;
            if (keep)
                err = neat_take(&tmp, c, c->weight, c->enabled, a);
            if (from_dad)
                j++;
            else
                i++;
        }
    }
    if (!err) {
        /* move the genes over, then the nodes they need */
        neat_genome_free(child, a);
        *child = tmp;
        neat_genome_init(&tmp);
        {
            neat_node *all = child->nodes;
            uint32_t n_all = child->n_nodes, cap_all = child->cap_nodes;
            child->nodes = NULL;
            child->n_nodes = child->cap_nodes = 0;
            err = neat_child_nodes(child, all, n_all, a);
            neat_mem_free(a, all, (size_t)cap_all * sizeof(neat_node));
        }
        /* a union too large for the blob format: the fitter parent instead */
        if (!err && child->n_nodes > p->max_nodes)
            err = neat_genome_copy(child, better == 1 ? dad : mom, a);
    }
    neat_genome_free(&tmp, a);
    child->has_fitness = 0;
    child->fitness = 0;
    return err;
}
