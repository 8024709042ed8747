/* neat_crossover.c - crossover: genes lined up by innovation number (the paper's Figure 4). */
#include "neat_internal.h"

/* Appends a gene to the child unless it duplicates a link the child has.
 * *disable (NEAT_REENABLE_CPP's pending flag; NULL otherwise): set, it
 * disables the next gene appended, and is then cleared; a skipped gene
 * leaves it for the next one, as NEAT C++'s mate_multipoint does. */
static int neat_take(neat_genome *child, const neat_conn *c, double weight, int enabled, int *disable,
                     const neat_alloc *a)
{
    if (neat_genome_has_link(child, c->in, c->out))
        return NEAT_OK;
    if (disable != NULL && *disable) {
        enabled = 0;
        *disable = 0;
    }
    return neat_genome_add_conn(child, c->in, c->out, weight, c->innov, enabled, a);
}

/* The child's nodes: the union of both parents' nodes (each list is sorted
 * by id, so a merge; on a shared id mom's entry), before any gene, because
 * add_conn checks that a gene's endpoints exist. */
static int neat_union_nodes(neat_genome *child, const neat_genome *mom, const neat_genome *dad, const neat_alloc *a)
{
    uint32_t i = 0, j = 0, n = 0;
    if (neat_mem_reserve(a, (void **)&child->nodes, &child->cap_nodes, mom->n_nodes + dad->n_nodes, sizeof(neat_node)))
        return NEAT_E_NOMEM;
    while (i < mom->n_nodes || j < dad->n_nodes) {
        if (j >= dad->n_nodes || (i < mom->n_nodes && mom->nodes[i].id <= dad->nodes[j].id)) {
            if (j < dad->n_nodes && dad->nodes[j].id == mom->nodes[i].id)
                j++;
            child->nodes[n++] = mom->nodes[i++];
        } else {
            child->nodes[n++] = dad->nodes[j++];
        }
    }
    child->n_nodes = n;
    return NEAT_OK;
}

/* Then keeps, in place and in order, every non-hidden node and the hidden
 * nodes the child's genes use. */
static void neat_drop_unused(neat_genome *child)
{
    uint32_t i, k, n = 0;
    for (i = 0; i < child->n_nodes; i++) {
        uint32_t id = child->nodes[i].id;
        int used = child->nodes[i].type != NEAT_NODE_HIDDEN;
        for (k = 0; k < child->n_conns && !used; k++)
            used = child->conns[k].in == id || child->conns[k].out == id;
        if (used)
            child->nodes[n++] = child->nodes[i];
    }
    child->n_nodes = n;
}

/* child is built in its own storage (kept from whatever it held before:
 * the population reuses a generation's genomes), so it must be neither
 * parent. */
int neat_crossover(neat_genome *child, const neat_genome *mom, const neat_genome *dad, int avg, const neat_params *p,
                   neat_rng *rng, const neat_alloc *a)
{
    uint32_t i = 0, j = 0;
    int better; /* 0: mom, 1: dad, -1: equal fitness */
    int err, pending = 0;
    /* NEAT C++'s multipoint crossover: the chosen gene's own flag, and a pending disable */
    int *disable = p->reenable_rule == NEAT_REENABLE_CPP && !avg ? &pending : NULL;

    if (child == mom || child == dad)
        return NEAT_E_ARG;
    child->n_nodes = 0;
    child->n_conns = 0;
    child->has_fitness = 0;
    child->fitness = 0;
    child->species = 0;
    better = mom->fitness > dad->fitness ? 0 : (dad->fitness > mom->fitness ? 1 : -1);
    /* NEAT C++ 1.2.1: at equal fitness the smaller genome counts as the
     * fitter (the second parent when both have as many genes) */
    if (better < 0 && p->equal_fitness_rule == NEAT_EQUAL_SMALLER)
        better = mom->n_conns < dad->n_conns ? 0 : 1;

    err = neat_union_nodes(child, mom, dad, a);
    while (!err && (i < mom->n_conns || j < dad->n_conns)) {
        if (i < mom->n_conns && j < dad->n_conns && mom->conns[i].innov == dad->conns[j].innov) {
            const neat_conn *cm = &mom->conns[i], *cd = &dad->conns[j];
            const neat_conn *pick = neat_rng_uniform_inl(rng) < 0.5 ? cm : cd;
            double w = avg ? 0.5 * (cm->weight + cd->weight) : pick->weight;
            int enabled = 1;
            if (disable != NULL) {
                enabled = pick->enabled;
                if ((!cm->enabled || !cd->enabled) && neat_rng_uniform_inl(rng) < p->disable_prob)
                    pending = 1;
            } else if (!cm->enabled || !cd->enabled) {
                enabled = !(neat_rng_uniform_inl(rng) < p->disable_prob);
            }
            err = neat_take(child, pick, w, enabled, disable, a);
            i++;
            j++;
        } else {
            /* disjoint or excess: only the fitter parent's, at equal fitness either's, drawn by the PRNG */
            int from_dad = j < dad->n_conns && (i >= mom->n_conns || dad->conns[j].innov < mom->conns[i].innov);
            const neat_conn *c = from_dad ? &dad->conns[j] : &mom->conns[i];
            int keep = better < 0 ? neat_rng_uniform_inl(rng) < p->excess_equal_prob : better == from_dad;
            if (keep)
                err = neat_take(child, c, c->weight, c->enabled, disable, a);
            if (from_dad)
                j++;
            else
                i++;
        }
    }
    if (!err) {
        neat_drop_unused(child);
        /* a union too large for the blob format: the fitter parent instead */
        if (child->n_nodes > p->max_nodes)
            err = neat_genome_copy(child, better == 1 ? dad : mom, a);
    }
    child->has_fitness = 0;
    child->fitness = 0;
    return err;
}
