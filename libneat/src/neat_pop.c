/* neat_pop.c - the population: creation, the batch evaluation interface, and one generation (epoch). */
#include <math.h>
#include <string.h>

#include "neat_internal.h"

static void neat_genomes_free(neat_genome *gs, uint32_t n, const neat_alloc *a)
{
    uint32_t i;
    if (gs == NULL)
        return;
    for (i = 0; i < n; i++)
        neat_genome_free(&gs[i], a);
    neat_mem_free(a, gs, (size_t)n * sizeof(neat_genome));
}

static neat_genome *neat_genomes_new(uint32_t n, const neat_alloc *a)
{
    uint32_t i;
    neat_genome *gs = (neat_genome *)neat_mem_realloc(a, NULL, 0, (size_t)n * sizeof(neat_genome));
    if (gs != NULL)
        for (i = 0; i < n; i++)
            neat_genome_init(&gs[i]);
    return gs;
}

int neat_pop_alloc(neat_pop **out, const neat_params *p, const neat_alloc *alloc)
{
    neat_alloc a;
    neat_pop *pop;
    a.fn = alloc ? alloc->fn : NULL;
    a.ud = alloc ? alloc->ud : NULL;
    pop = (neat_pop *)neat_mem_realloc(&a, NULL, 0, sizeof *pop);
    if (pop == NULL)
        return NEAT_E_NOMEM;
    memset(pop, 0, sizeof *pop);
    pop->p = *p;
    pop->a = a;
    neat_genome_init(&pop->best_ever);
    neat_genome_init(&pop->last_best);
    pop->genomes = neat_genomes_new(p->pop_size, &a);
    if (pop->genomes == NULL) {
        neat_mem_free(&a, pop, sizeof *pop);
        return NEAT_E_NOMEM;
    }
    *out = pop;
    return NEAT_OK;
}

int neat_pop_create(neat_pop **out, const neat_params *p, const neat_start *start, uint64_t seed,
                    const neat_alloc *alloc)
{
    neat_pop *pop = NULL;
    neat_genome minimal;
    const neat_genome *g0;
    uint32_t i;
    int err;

    if (out == NULL || p == NULL)
        return NEAT_E_ARG;
    *out = NULL;
    if (neat_params_check(p, NULL) != NEAT_OK)
        return NEAT_E_PARAM;
    err = neat_pop_alloc(&pop, p, alloc);
    if (err)
        return err;
    neat_rng_seed(&pop->rng, seed);
    neat_genome_init(&minimal);
    if (start != NULL && start->genome != NULL) {
        g0 = start->genome;
    } else {
        err = neat_genome_minimal(&minimal, p->n_inputs, p->n_outputs, &pop->a);
        g0 = &minimal;
    }
    if (!err && (g0->n_nodes > p->max_nodes || !neat_genome_io_ok(g0, p->n_inputs, p->n_outputs)))
        err = NEAT_E_ARG;
    if (!err) {
        /* the start's markings are the population's first */
        for (i = 0; i < g0->n_nodes; i++)
            if (g0->nodes[i].id >= pop->iv.next_node)
                pop->iv.next_node = g0->nodes[i].id + 1;
        for (i = 0; i < g0->n_conns; i++)
            if (g0->conns[i].innov >= pop->iv.next_innov)
                pop->iv.next_innov = g0->conns[i].innov + 1;
    }
    for (i = 0; !err && i < p->pop_size; i++) {
        err = neat_genome_copy(&pop->genomes[i], g0, &pop->a);
        if (!err && !(start != NULL && start->keep_weights))
            neat_genome_randomize(&pop->genomes[i], &pop->rng, p->weight_init_range);
        pop->genomes[i].has_fitness = 0;
    }
    neat_genome_free(&minimal, &pop->a);
    pop->delta_t = p->delta_t;
    if (!err)
        err = neat_speciate(pop);
    if (err) {
        neat_pop_free(pop);
        return err;
    }
    *out = pop;
    return NEAT_OK;
}

void neat_pop_free(neat_pop *pop)
{
    neat_alloc a;
    uint32_t k;
    if (pop == NULL)
        return;
    a = pop->a;
    neat_genomes_free(pop->genomes, pop->p.pop_size, &a);
    neat_genomes_free(pop->spare, pop->p.pop_size, &a);
    for (k = 0; k < pop->n_species; k++)
        neat_species_free(&pop->species[k], &a);
    neat_mem_free(&a, pop->species, (size_t)pop->cap_species * sizeof(neat_species));
    neat_mem_free(&a, pop->iv.list, (size_t)pop->iv.cap * sizeof(neat_innov));
    neat_genome_free(&pop->best_ever, &a);
    neat_genome_free(&pop->last_best, &a);
    neat_tag_free(&a, &pop->game);
    neat_mem_free(&a, pop, sizeof *pop);
}

uint32_t neat_pop_size(const neat_pop *pop)
{
    return pop->p.pop_size;
}

uint32_t neat_pop_generation(const neat_pop *pop)
{
    return pop->generation;
}

const neat_params *neat_pop_params(const neat_pop *pop)
{
    return &pop->p;
}

const neat_genome *neat_pop_genome(const neat_pop *pop, uint32_t i)
{
    return i < pop->p.pop_size ? &pop->genomes[i] : NULL;
}

int neat_pop_set_fitness(neat_pop *pop, uint32_t i, double fitness)
{
    if (pop == NULL || i >= pop->p.pop_size)
        return NEAT_E_ARG;
    if (!isfinite(fitness) || fitness < 0.0) {
        pop->err_index = i;
        pop->genomes[i].has_fitness = 0;
        return NEAT_E_FITNESS;
    }
    pop->genomes[i].fitness = fitness;
    pop->genomes[i].has_fitness = 1;
    return NEAT_OK;
}

uint32_t neat_pop_error_index(const neat_pop *pop)
{
    return pop->err_index;
}

int neat_pop_epoch(neat_pop *pop)
{
    uint32_t i, k, best = 0, since_pop;
    neat_genome *next = NULL, last, ever;
    neat_spec_plan plan;
    neat_rng saved_rng;
    neat_innovs saved_iv;
    int improved, err;

    if (pop == NULL)
        return NEAT_E_ARG;
    /* an epoch creates at most 3 innovations, 1 node and 1 species per genome */
    if (pop->generation >= NEAT_COUNTER_MAX || pop->iv.next_innov > NEAT_COUNTER_MAX - 3u * pop->p.pop_size ||
        pop->iv.next_node > NEAT_COUNTER_MAX - pop->p.pop_size ||
        pop->next_species_id > NEAT_COUNTER_MAX - pop->p.pop_size)
        return NEAT_E_COUNTERS;
    for (i = 0; i < pop->p.pop_size; i++) {
        if (!pop->genomes[i].has_fitness) {
            pop->err_index = i;
            return NEAT_E_FITNESS;
        }
        if (pop->genomes[i].fitness > pop->genomes[best].fitness)
            best = i;
    }
    /* Everything that can fail comes first, on copies; the population
     * changes only in the commit below, which cannot fail. So an epoch
     * refused memory leaves the population as it was, and a retry gives
     * the same generation as if nothing had failed. */
    saved_rng = pop->rng;
    saved_iv = pop->iv;
    neat_genome_init(&last);
    neat_genome_init(&ever);
    neat_species_rank(pop); /* sorting members changes nothing the retry would not redo */
    improved = !pop->have_best || pop->genomes[best].fitness > pop->best_ever.fitness;
    since_pop = improved ? 0 : pop->since_pop_improved + 1;
    /* NEAT C++'s population record starts at 0 and must be exceeded */
    if (pop->p.pop_stagnation_rule == NEAT_POPSTAG_DELTA)
        since_pop = pop->genomes[best].fitness > (pop->have_best ? pop->best_ever.fitness : 0.0)
                        ? 0 : pop->since_pop_improved + 1;
    err = neat_genome_copy(&last, &pop->genomes[best], &pop->a);
    if (!err && improved)
        err = neat_genome_copy(&ever, &pop->genomes[best], &pop->a);
    if (!err) {
        neat_apportion(pop, &since_pop);
        /* the next generation's representatives: members of this one drawn by the PRNG
         * (a retry draws the same ones from the restored PRNG), or the champions */
        for (k = 0; k < pop->n_species && !err; k++) {
            neat_species *s = &pop->species[k];
            uint32_t m = pop->p.species_rep == NEAT_REP_CHAMPION ? 0 : neat_rng_below_inl(&pop->rng, s->n_members);
            err = neat_genome_copy(&s->rep, &pop->genomes[s->members[m]], &pop->a);
        }
    }
    if (!err) {
        /* every genome of next is written whole (copied or bred) before it is read */
        next = pop->spare != NULL ? pop->spare : neat_genomes_new(pop->p.pop_size, &pop->a);
        pop->spare = NULL;
        if (next == NULL)
            err = NEAT_E_NOMEM;
    }
    if (!err) {
        neat_innov_reset(&pop->iv);
        if (pop->p.speciate_rule == NEAT_SPECIATE_INTERLEAVED) {
            /* each child placed as it is born (NEAT C++'s Species::reproduce) */
            err = neat_speciate_plan_begin(pop, &plan);
            if (!err) {
                err = neat_reproduce(pop, next, &plan);
                err = err ? err : neat_speciate_plan_finish(pop, next, &plan);
                if (err)
                    neat_speciate_plan_free(pop, &plan);
            }
        } else {
            err = neat_reproduce(pop, next, NULL);
            if (!err)
                err = neat_speciate_plan(pop, next, &plan);
        }
    }
    if (err) {
        if (next != NULL)
            pop->spare = next; /* its storage, for the retry */
        neat_genome_free(&last, &pop->a);
        neat_genome_free(&ever, &pop->a);
        pop->rng = saved_rng;
        /* the list may have grown (moved): keep its memory, restore its length and counters */
        pop->iv.n = saved_iv.n;
        pop->iv.next_innov = saved_iv.next_innov;
        pop->iv.next_node = saved_iv.next_node;
        return err;
    }

    /* commit */
    neat_genome_free(&pop->last_best, &pop->a);
    pop->last_best = last;
    if (improved) {
        neat_genome_free(&pop->best_ever, &pop->a);
        pop->best_ever = ever;
    }
    pop->have_best = 1;
    pop->since_pop_improved = since_pop;
    for (k = 0; k < pop->n_species; k++) {
        pop->species[k].best_fitness = pop->species[k].next_best;
        pop->species[k].since_improved = pop->species[k].next_since;
        pop->species[k].culled |= pop->species[k].cull_now;
        pop->species[k].age++;
    }
    pop->spare = pop->genomes;
    pop->genomes = next;
    neat_speciate_commit(pop, &plan);
    pop->generation++;
    return NEAT_OK;
}

const neat_genome *neat_pop_last_best(const neat_pop *pop)
{
    return pop->have_best ? &pop->last_best : NULL;
}

const neat_genome *neat_pop_best_ever(const neat_pop *pop)
{
    return pop->have_best ? &pop->best_ever : NULL;
}

uint32_t neat_pop_species_count(const neat_pop *pop)
{
    return pop->n_species;
}

int neat_pop_species(const neat_pop *pop, uint32_t k, neat_species_info *info)
{
    const neat_species *s;
    if (pop == NULL || info == NULL || k >= pop->n_species)
        return NEAT_E_ARG;
    s = &pop->species[k];
    info->id = s->id;
    info->size = s->n_members;
    info->age = s->age;
    info->since_improved = s->since_improved;
    info->best_fitness = s->best_fitness;
    return NEAT_OK;
}

double neat_pop_delta_t(const neat_pop *pop)
{
    return pop->delta_t_used;
}

double neat_pop_next_delta_t(const neat_pop *pop)
{
    return pop->delta_t;
}

uint32_t neat_pop_innovations(const neat_pop *pop)
{
    return pop->iv.next_innov;
}

int neat_pop_set_params(neat_pop *pop, const neat_params *p)
{
    const char *field;
    uint32_t i;
    if (pop == NULL || p == NULL)
        return NEAT_E_ARG;
    if (neat_params_check(p, &field) != NEAT_OK)
        return NEAT_E_PARAM;
    /* the genomes and species already there must still fit */
    if (p->pop_size != pop->p.pop_size || p->n_inputs != pop->p.n_inputs || p->n_outputs != pop->p.n_outputs)
        return NEAT_E_PARAM;
    for (i = 0; i < pop->p.pop_size; i++)
        if (pop->genomes[i].n_nodes > p->max_nodes)
            return NEAT_E_PARAM;
    pop->p = *p;
    return NEAT_OK;
}

int neat_pop_replace(neat_pop *pop, const neat_genome *genomes, const uint32_t *label, uint32_t n, int evaluated,
                     double delta_t)
{
    uint32_t i, k, j, best = 0, n_sp = 0, node = 0, innov = 0, next_id;
    neat_genome *next = NULL, last, ever;
    neat_species *sp = NULL;
    int err = NEAT_OK, improved = 0;

    if (pop == NULL || genomes == NULL || label == NULL || n != pop->p.pop_size || !(delta_t <= 1e300))
        return NEAT_E_ARG;
    for (i = 0; i < n; i++) {
        const neat_genome *g = &genomes[i];
        if (!neat_genome_io_ok(g, pop->p.n_inputs, pop->p.n_outputs) || g->n_nodes > pop->p.max_nodes ||
            label[i] >= NEAT_COUNTER_MAX - n)
            return NEAT_E_ARG;
        if (g->nodes[g->n_nodes - 1].id > node)
            node = g->nodes[g->n_nodes - 1].id;
        if (g->n_conns > 0 && g->conns[g->n_conns - 1].innov > innov)
            innov = g->conns[g->n_conns - 1].innov;
        if (evaluated && !pop->genomes[i].has_fitness) {
            pop->err_index = i;
            return NEAT_E_FITNESS;
        }
        if (evaluated && pop->genomes[i].fitness > pop->genomes[best].fitness)
            best = i;
    }
    if (node >= NEAT_COUNTER_MAX - 3u * n || innov >= NEAT_COUNTER_MAX - 3u * n)
        return NEAT_E_ARG;
    neat_genome_init(&last);
    neat_genome_init(&ever);
    if (evaluated) {
        improved = !pop->have_best || pop->genomes[best].fitness > pop->best_ever.fitness;
        err = neat_genome_copy(&last, &pop->genomes[best], &pop->a);
        if (!err && improved)
            err = neat_genome_copy(&ever, &pop->genomes[best], &pop->a);
    }
    /* everything that can fail, on new storage; the commit below cannot */
    if (!err) {
        next = (neat_genome *)neat_mem_realloc(&pop->a, NULL, 0, (size_t)n * sizeof(neat_genome));
        if (next != NULL) /* initialised at once: the error path frees its entries */
            for (i = 0; i < n; i++)
                neat_genome_init(&next[i]);
        sp = (neat_species *)neat_mem_realloc(&pop->a, NULL, 0, (size_t)n * sizeof(neat_species));
        if (next == NULL || sp == NULL)
            err = NEAT_E_NOMEM;
    }
    for (i = 0; i < n && !err; i++)
        err = neat_genome_copy(&next[i], &genomes[i], &pop->a);
    for (i = 0; i < n && !err; i++) {
        for (k = 0; k < n_sp && sp[k].id != label[i]; k++)
            ;
        if (k == n_sp) {
            /* a species: its members counted first, its representative its first member */
            uint32_t count = 0;
            memset(&sp[k], 0, sizeof sp[k]);
            sp[k].id = label[i];
            for (j = i; j < n; j++)
                count += label[j] == label[i];
            sp[k].members = (uint32_t *)neat_mem_realloc(&pop->a, NULL, 0, (size_t)count * sizeof(uint32_t));
            n_sp++;
            if (sp[k].members == NULL) {
                err = NEAT_E_NOMEM;
                break;
            }
            sp[k].cap_members = count;
            neat_genome_init(&sp[k].rep);
            err = neat_genome_copy(&sp[k].rep, &genomes[i], &pop->a);
            for (j = 0; j < pop->n_species; j++)
                if (pop->species[j].id == label[i]) {
                    /* the same species as before: its history goes on */
                    sp[k].age = pop->species[j].age + (evaluated ? 1u : 0u);
                    sp[k].since_improved = pop->species[j].since_improved;
                    sp[k].best_fitness = pop->species[j].best_fitness;
                    sp[k].culled = pop->species[j].culled;
                }
        }
        sp[k].members[sp[k].n_members++] = i;
    }
    if (err) {
        for (k = 0; k < n_sp; k++)
            neat_species_free(&sp[k], &pop->a);
        neat_mem_free(&pop->a, sp, (size_t)n * sizeof(neat_species));
        if (next != NULL)
            for (i = 0; i < n; i++)
                neat_genome_free(&next[i], &pop->a);
        neat_mem_free(&pop->a, next, (size_t)n * sizeof(neat_genome));
        neat_genome_free(&last, &pop->a);
        neat_genome_free(&ever, &pop->a);
        return err;
    }
    /* commit */
    if (evaluated) {
        neat_genome_free(&pop->last_best, &pop->a);
        pop->last_best = last;
        if (improved) {
            neat_genome_free(&pop->best_ever, &pop->a);
            pop->best_ever = ever;
        }
        pop->since_pop_improved = improved ? 0 : pop->since_pop_improved + 1;
        pop->have_best = 1;
        pop->generation++;
    }
    for (i = 0; i < n; i++) {
        neat_genome_free(&pop->genomes[i], &pop->a);
        next[i].species = label[i];
        next[i].has_fitness = 0;
        next[i].fitness = 0.0;
    }
    neat_mem_free(&pop->a, pop->genomes, (size_t)n * sizeof(neat_genome));
    pop->genomes = next;
    for (k = 0; k < pop->n_species; k++)
        neat_species_free(&pop->species[k], &pop->a);
    neat_mem_free(&pop->a, pop->species, (size_t)pop->cap_species * sizeof(neat_species));
    pop->species = sp;
    pop->cap_species = n;
    pop->n_species = n_sp;
    next_id = 0;
    for (k = 0; k < n_sp; k++)
        if (sp[k].id >= next_id)
            next_id = sp[k].id + 1;
    if (next_id > pop->next_species_id)
        pop->next_species_id = next_id;
    if (node + 1 > pop->iv.next_node)
        pop->iv.next_node = node + 1;
    if (innov + 1 > pop->iv.next_innov)
        pop->iv.next_innov = innov + 1;
    neat_innov_reset(&pop->iv);
    if (delta_t > 0)
        pop->delta_t_used = delta_t;
    return NEAT_OK;
}
