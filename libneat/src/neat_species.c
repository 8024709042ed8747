/* neat_species.c - speciation by compatibility distance, with a dynamic threshold moving toward a target species count. */
#include <string.h>

#include "neat_internal.h"

void neat_species_free(neat_species *s, const neat_alloc *a)
{
    neat_genome_free(&s->rep, a);
    neat_mem_free(a, s->members, (size_t)s->cap_members * sizeof(uint32_t));
    memset(s, 0, sizeof *s);
}

static int neat_species_join(neat_species *s, uint32_t idx, const neat_alloc *a)
{
    if (neat_mem_reserve(a, (void **)&s->members, &s->cap_members, s->n_members + 1, sizeof(uint32_t)))
        return NEAT_E_NOMEM;
    s->members[s->n_members++] = idx;
    return NEAT_OK;
}

int neat_speciate(neat_pop *pop)
{
    uint32_t i, k, kept;
    int err;

    for (k = 0; k < pop->n_species; k++)
        pop->species[k].n_members = 0;
    for (i = 0; i < pop->p.pop_size; i++) {
        neat_genome *g = &pop->genomes[i];
        /* the first species (oldest first) whose representative is close enough */
        for (k = 0; k < pop->n_species; k++)
            if (neat_genome_distance(g, &pop->species[k].rep, &pop->p) < pop->delta_t)
                break;
        if (k == pop->n_species) {
            neat_species *s;
            if (neat_mem_reserve(&pop->a, (void **)&pop->species, &pop->cap_species, pop->n_species + 1,
                                 sizeof(neat_species)))
                return NEAT_E_NOMEM;
            s = &pop->species[pop->n_species++];
            memset(s, 0, sizeof *s);
            s->id = pop->next_species_id++;
            err = neat_genome_copy(&s->rep, g, &pop->a);
            if (err)
                return err;
        }
        err = neat_species_join(&pop->species[k], i, &pop->a);
        if (err)
            return err;
        g->species = pop->species[k].id;
    }
    /* species no genome joined have died out */
    for (k = 0, kept = 0; k < pop->n_species; k++) {
        if (pop->species[k].n_members == 0)
            neat_species_free(&pop->species[k], &pop->a);
        else
            pop->species[kept++] = pop->species[k];
    }
    pop->n_species = kept;
    if (pop->p.target_species > 0) {
        if (pop->n_species > pop->p.target_species)
            pop->delta_t += pop->p.delta_t_step;
        else if (pop->n_species < pop->p.target_species)
            pop->delta_t -= pop->p.delta_t_step;
        if (pop->delta_t < pop->p.delta_t_min)
            pop->delta_t = pop->p.delta_t_min;
    }
    return NEAT_OK;
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
        if (s->age == 0 || pop->genomes[s->members[0]].fitness > s->best_fitness) {
            s->best_fitness = pop->genomes[s->members[0]].fitness;
            s->since_improved = 0;
        } else {
            s->since_improved++;
        }
    }
}
