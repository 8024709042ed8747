/* neat_species.c - speciation by compatibility distance, with a dynamic threshold moving toward a target species count. */
#include <string.h>

#include "neat_internal.h"

void neat_species_free(neat_species *s, const neat_alloc *a)
{
    neat_genome_free(&s->rep, a);
    neat_mem_free(a, s->members, (size_t)s->cap_members * sizeof(uint32_t));
    memset(s, 0, sizeof *s);
}

void neat_speciate_plan_free(neat_pop *pop, neat_spec_plan *plan)
{
    uint32_t j;
    const neat_alloc *a = &pop->a;
    for (j = 0; j < plan->n_new; j++) {
        if (plan->reps != NULL)
            neat_genome_free(&plan->reps[j], a);
        if (plan->members != NULL && plan->count != NULL)
            neat_mem_free(a, plan->members[j], (size_t)plan->count[plan->ns + j] * sizeof(uint32_t));
    }
    neat_mem_free(a, plan->slot, (size_t)pop->p.pop_size * sizeof(uint32_t));
    neat_mem_free(a, plan->founder, (size_t)plan->cap * sizeof(uint32_t));
    neat_mem_free(a, plan->count, (size_t)(plan->ns + plan->cap) * sizeof(uint32_t));
    neat_mem_free(a, plan->members, (size_t)plan->cap * sizeof(uint32_t *));
    neat_mem_free(a, plan->reps, (size_t)plan->cap * sizeof(neat_genome));
    memset(plan, 0, sizeof *plan);
}

int neat_speciate_plan_begin(neat_pop *pop, neat_spec_plan *plan)
{
    const neat_alloc *a = &pop->a;
    uint32_t n = pop->p.pop_size, ns = pop->n_species;

    memset(plan, 0, sizeof *plan);
    /* at most one new species per genome */
    plan->cap = n;
    plan->ns = ns;
    plan->slot = (uint32_t *)neat_mem_realloc(a, NULL, 0, (size_t)n * sizeof(uint32_t));
    plan->founder = (uint32_t *)neat_mem_realloc(a, NULL, 0, (size_t)n * sizeof(uint32_t));
    plan->count = (uint32_t *)neat_mem_realloc(a, NULL, 0, (size_t)(ns + n) * sizeof(uint32_t));
    if (plan->slot == NULL || plan->founder == NULL || plan->count == NULL) {
        neat_speciate_plan_free(pop, plan);
        return NEAT_E_NOMEM;
    }
    memset(plan->count, 0, (size_t)(ns + n) * sizeof(uint32_t));
    return NEAT_OK;
}

void neat_speciate_place(neat_pop *pop, const neat_genome *gs, neat_spec_plan *plan, uint32_t i)
{
    uint32_t k, j, ns = plan->ns;
    /* the first species (oldest first) whose representative is close
     * enough; the founders of this generation's new species come last */
    for (k = 0; k < ns; k++)
        if (neat_genome_compatible(&gs[i], &pop->species[k].rep, &pop->p, pop->delta_t))
            break;
    if (k == ns) {
        for (j = 0; j < plan->n_new; j++)
            if (neat_genome_compatible(&gs[i], &gs[plan->founder[j]], &pop->p, pop->delta_t))
                break;
        if (j == plan->n_new)
            plan->founder[plan->n_new++] = i;
        k = ns + j;
    }
    plan->slot[i] = k;
    plan->count[k]++;
}

int neat_speciate_plan_finish(neat_pop *pop, const neat_genome *gs, neat_spec_plan *plan)
{
    const neat_alloc *a = &pop->a;
    uint32_t k, j, ns = plan->ns;

    plan->n_slots = ns + plan->n_new;
    /* every allocation the commit will need, now */
    if (neat_mem_reserve(a, (void **)&pop->species, &pop->cap_species, plan->n_slots, sizeof(neat_species)))
        goto nomem;
    for (k = 0; k < ns; k++) {
        neat_species *s = &pop->species[k];
        if (neat_mem_reserve(a, (void **)&s->members, &s->cap_members, plan->count[k], sizeof(uint32_t)))
            goto nomem;
    }
    if (plan->n_new > 0) {
        /* each array initialised as soon as it exists: the error path frees its entries */
        plan->members = (uint32_t **)neat_mem_realloc(a, NULL, 0, (size_t)plan->cap * sizeof(uint32_t *));
        if (plan->members == NULL)
            goto nomem;
        for (j = 0; j < plan->n_new; j++)
            plan->members[j] = NULL;
        plan->reps = (neat_genome *)neat_mem_realloc(a, NULL, 0, (size_t)plan->cap * sizeof(neat_genome));
        if (plan->reps == NULL)
            goto nomem;
        for (j = 0; j < plan->n_new; j++)
            neat_genome_init(&plan->reps[j]);
        for (j = 0; j < plan->n_new; j++) {
            plan->members[j] = (uint32_t *)neat_mem_realloc(a, NULL, 0, (size_t)plan->count[ns + j] * sizeof(uint32_t));
            if (plan->members[j] == NULL || neat_genome_copy(&plan->reps[j], &gs[plan->founder[j]], a))
                goto nomem;
        }
    }
    return NEAT_OK;
nomem:
    neat_speciate_plan_free(pop, plan);
    return NEAT_E_NOMEM;
}

int neat_speciate_plan(neat_pop *pop, const neat_genome *gs, neat_spec_plan *plan)
{
    uint32_t i;
    int err = neat_speciate_plan_begin(pop, plan);
    if (err)
        return err;
    for (i = 0; i < pop->p.pop_size; i++)
        neat_speciate_place(pop, gs, plan, i);
    return neat_speciate_plan_finish(pop, gs, plan);
}

void neat_speciate_commit(neat_pop *pop, neat_spec_plan *plan)
{
    uint32_t i, k, j, kept, ns = pop->n_species;

    for (k = 0; k < ns; k++)
        pop->species[k].n_members = 0;
    for (j = 0; j < plan->n_new; j++) {
        neat_species *s = &pop->species[ns + j];
        memset(s, 0, sizeof *s);
        s->id = pop->next_species_id++;
        s->rep = plan->reps[j]; /* moved */
        neat_genome_init(&plan->reps[j]);
        s->members = plan->members[j];
        s->cap_members = plan->count[ns + j];
        plan->members[j] = NULL;
        plan->count[ns + j] = 0;
    }
    pop->n_species = plan->n_slots;
    for (i = 0; i < pop->p.pop_size; i++) {
        neat_species *s = &pop->species[plan->slot[i]];
        s->members[s->n_members++] = i;
        pop->genomes[i].species = s->id;
    }
    /* species no genome joined have died out */
    for (k = 0, kept = 0; k < pop->n_species; k++) {
        if (pop->species[k].n_members == 0)
            neat_species_free(&pop->species[k], &pop->a);
        else
            pop->species[kept++] = pop->species[k];
    }
    pop->n_species = kept;
    pop->delta_t_used = pop->delta_t;
    if (pop->p.target_species > 0) {
        if (pop->n_species > pop->p.target_species)
            pop->delta_t += pop->p.delta_t_step;
        else if (pop->n_species < pop->p.target_species)
            pop->delta_t -= pop->p.delta_t_step;
        if (pop->delta_t < pop->p.delta_t_min)
            pop->delta_t = pop->p.delta_t_min;
    }
    neat_speciate_plan_free(pop, plan);
}

int neat_speciate(neat_pop *pop)
{
    neat_spec_plan plan;
    int err = neat_speciate_plan(pop, pop->genomes, &plan);
    if (!err)
        neat_speciate_commit(pop, &plan);
    return err;
}

/* better-first order: higher fitness, then lower index */
static int neat_better(const neat_pop *pop, uint32_t x, uint32_t y)
{
    double fx = pop->genomes[x].fitness, fy = pop->genomes[y].fitness;
    return fx > fy || (fx == fy && x < y);
}

void neat_species_rank(neat_pop *pop)
{
    uint32_t k, i, j;
    for (k = 0; k < pop->n_species; k++) {
        neat_species *s = &pop->species[k];
        /* insertion sort: species are small and the order must be total */
        for (i = 1; i < s->n_members; i++) {
            uint32_t m = s->members[i];
            for (j = i; j > 0 && neat_better(pop, m, s->members[j - 1]); j--)
                s->members[j] = s->members[j - 1];
            s->members[j] = m;
        }
        if (pop->p.stagnation_rule == NEAT_STAGNATION_CPP) {
            /* NEAT C++'s max_fitness_ever starts at 0 and must be exceeded */
            double before = s->age == 0 ? 0.0 : s->best_fitness;
            int up = pop->genomes[s->members[0]].fitness > before;
            s->next_best = up ? pop->genomes[s->members[0]].fitness : before;
            s->next_since = up ? 0 : s->since_improved + 1;
        } else if (s->age == 0 || pop->genomes[s->members[0]].fitness > s->best_fitness) {
            s->next_best = pop->genomes[s->members[0]].fitness;
            s->next_since = 0;
        } else {
            s->next_best = s->best_fitness;
            s->next_since = s->since_improved + 1;
        }
    }
}
