/* neat_checkpoint.c - the population checkpoint: every bit of state, little endian, CRC-32 sealed (docs/formats.md). */
#include <string.h>

#include "nrt.h"
#include "neat_io.h"

static const uint8_t neat_ckpt_magic[8] = {'N', 'E', 'A', 'T', 'C', 'K', 'P', 'T'};

/* Version 4 holds NEAT C++ 1.2.1's switches (and each species' culled
 * flag); a population that uses none of them is written as version 3, so
 * that every checkpoint of the default rules keeps its bytes. */
static int neat_ckpt_needs_v4(const neat_pop *pop)
{
    uint32_t k;
    for (k = 0; k < pop->n_species; k++)
        if (pop->species[k].culled)
            return 1;
    return neat_params_uses_neat_cpp(&pop->p);
}

/* ---- parameters: one fixed order, the struct's ---- */
static void neat_put_params(neat_wbuf *w, const neat_params *p, uint32_t version)
{
    neat_put_u32(w, p->pop_size);
    neat_put_u32(w, p->n_inputs);
    neat_put_u32(w, p->n_outputs);
    neat_put_u32(w, (uint32_t)p->mode);
    neat_put_f64(w, p->c1);
    neat_put_f64(w, p->c2);
    neat_put_f64(w, p->c3);
    neat_put_u32(w, (uint32_t)p->normalize_by_size);
    neat_put_f64(w, p->delta_t);
    neat_put_f64(w, p->delta_t_step);
    neat_put_f64(w, p->delta_t_min);
    neat_put_u32(w, p->target_species);
    neat_put_f64(w, p->survival_fraction);
    neat_put_u32(w, p->elitism_min_size);
    neat_put_u32(w, (uint32_t)p->stagnation_rule);
    neat_put_u32(w, p->dropoff_age);
    neat_put_f64(w, p->stagnation_factor);
    neat_put_u32(w, p->pop_stagnation);
    neat_put_f64(w, p->mutate_only_prob);
    neat_put_f64(w, p->mate_only_prob);
    neat_put_f64(w, p->interspecies_prob);
    neat_put_f64(w, p->mate_avg_prob);
    neat_put_f64(w, p->disable_prob);
    neat_put_f64(w, p->excess_equal_prob);
    neat_put_f64(w, p->weight_mut_prob);
    neat_put_f64(w, p->weight_perturb_prob);
    neat_put_f64(w, p->weight_perturb_power);
    neat_put_f64(w, p->weight_init_range);
    neat_put_f64(w, p->weight_replace_range);
    neat_put_f64(w, p->weight_max);
    neat_put_f64(w, p->add_conn_prob);
    neat_put_f64(w, p->add_node_prob);
    neat_put_u32(w, p->add_conn_tries);
    neat_put_u32(w, (uint32_t)p->allow_recurrent);
    neat_put_u32(w, p->max_nodes);
    neat_put_u32(w, (uint32_t)p->net_step); /* version 3 */
    if (version < 4)
        return;
    neat_put_u32(w, (uint32_t)p->profile);
    neat_put_u32(w, (uint32_t)p->equal_fitness_rule);
    neat_put_u32(w, (uint32_t)p->reenable_rule);
    neat_put_u32(w, (uint32_t)p->add_conn_rule);
    neat_put_f64(w, p->recur_only_prob);
    neat_put_u32(w, (uint32_t)p->species_rep);
    neat_put_u32(w, (uint32_t)p->weight_mut_rule);
    neat_put_u32(w, (uint32_t)p->elitism_rule);
    neat_put_u32(w, (uint32_t)p->interspecies_rule);
    neat_put_u32(w, (uint32_t)p->identical_rule);
    neat_put_u32(w, (uint32_t)p->offspring_rounding);
    neat_put_u32(w, (uint32_t)p->speciate_rule);
    neat_put_u32(w, p->cull_every);
    neat_put_u32(w, p->cull_age);
    neat_put_u32(w, (uint32_t)p->pop_stagnation_rule);
}

/* version: the checkpoint's; before 3 the networks stepped sync, the only mode. *p starts as
 * neat_params_default(): what an older version does not hold keeps its default. */
static void neat_get_params(neat_rbuf *r, neat_params *p, uint32_t version)
{
    p->pop_size = neat_get_u32(r);
    p->n_inputs = neat_get_u32(r);
    p->n_outputs = neat_get_u32(r);
    p->mode = (int)neat_get_u32(r);
    p->c1 = neat_get_f64(r);
    p->c2 = neat_get_f64(r);
    p->c3 = neat_get_f64(r);
    p->normalize_by_size = (int)neat_get_u32(r);
    p->delta_t = neat_get_f64(r);
    p->delta_t_step = neat_get_f64(r);
    p->delta_t_min = neat_get_f64(r);
    p->target_species = neat_get_u32(r);
    p->survival_fraction = neat_get_f64(r);
    p->elitism_min_size = neat_get_u32(r);
    p->stagnation_rule = (int)neat_get_u32(r);
    p->dropoff_age = neat_get_u32(r);
    p->stagnation_factor = neat_get_f64(r);
    p->pop_stagnation = neat_get_u32(r);
    p->mutate_only_prob = neat_get_f64(r);
    p->mate_only_prob = neat_get_f64(r);
    p->interspecies_prob = neat_get_f64(r);
    p->mate_avg_prob = neat_get_f64(r);
    p->disable_prob = neat_get_f64(r);
    p->excess_equal_prob = neat_get_f64(r);
    p->weight_mut_prob = neat_get_f64(r);
    p->weight_perturb_prob = neat_get_f64(r);
    p->weight_perturb_power = neat_get_f64(r);
    p->weight_init_range = neat_get_f64(r);
    p->weight_replace_range = neat_get_f64(r);
    p->weight_max = neat_get_f64(r);
    p->add_conn_prob = neat_get_f64(r);
    p->add_node_prob = neat_get_f64(r);
    p->add_conn_tries = neat_get_u32(r);
    p->allow_recurrent = (int)neat_get_u32(r);
    p->max_nodes = neat_get_u32(r);
    p->net_step = version >= 3 ? (int)neat_get_u32(r) : NEAT_STEP_SYNC;
    if (version < 4)
        return; /* before NEAT C++'s switches: *p came in as neat_params_default(), every one at libneat's rule */
    p->profile = (int)neat_get_u32(r);
    p->equal_fitness_rule = (int)neat_get_u32(r);
    p->reenable_rule = (int)neat_get_u32(r);
    p->add_conn_rule = (int)neat_get_u32(r);
    p->recur_only_prob = neat_get_f64(r);
    p->species_rep = (int)neat_get_u32(r);
    p->weight_mut_rule = (int)neat_get_u32(r);
    p->elitism_rule = (int)neat_get_u32(r);
    p->interspecies_rule = (int)neat_get_u32(r);
    p->identical_rule = (int)neat_get_u32(r);
    p->offspring_rounding = (int)neat_get_u32(r);
    p->speciate_rule = (int)neat_get_u32(r);
    p->cull_every = neat_get_u32(r);
    p->cull_age = neat_get_u32(r);
    p->pop_stagnation_rule = (int)neat_get_u32(r);
}

/* Largest node id and innovation number a genome uses. */
static void neat_genome_max_ids(const neat_genome *g, uint32_t *node, uint32_t *innov)
{
    if (g->n_nodes > 0 && g->nodes[g->n_nodes - 1].id > *node)
        *node = g->nodes[g->n_nodes - 1].id;
    if (g->n_conns > 0 && g->conns[g->n_conns - 1].innov > *innov)
        *innov = g->conns[g->n_conns - 1].innov;
}

/* The counters and state a correct CRC alone cannot vouch for: counters
 * above every number in use, unique species ids, a usable threshold and a
 * PRNG state that is not the all-zero fixed point. */
static int neat_pop_state_ok(const neat_pop *pop)
{
    uint32_t i, k, j, node = 0, innov = 0;
    if (!(pop->delta_t > 0) || pop->delta_t > 1e300 || !(pop->delta_t_used > 0) || pop->delta_t_used > 1e300)
        return 0;
    if ((pop->rng.s[0] | pop->rng.s[1] | pop->rng.s[2] | pop->rng.s[3]) == 0)
        return 0;
    for (i = 0; i < pop->p.pop_size; i++)
        neat_genome_max_ids(&pop->genomes[i], &node, &innov);
    if (pop->have_best) {
        neat_genome_max_ids(&pop->best_ever, &node, &innov);
        neat_genome_max_ids(&pop->last_best, &node, &innov);
    }
    for (k = 0; k < pop->n_species; k++) {
        neat_genome_max_ids(&pop->species[k].rep, &node, &innov);
        if (pop->species[k].id >= pop->next_species_id)
            return 0;
        for (j = 0; j < k; j++)
            if (pop->species[j].id == pop->species[k].id)
                return 0;
    }
    for (i = 0; i < pop->iv.n; i++) {
        const neat_innov *v = &pop->iv.list[i];
        if (v->kind > NEAT_INNOV_NODE || v->innov >= pop->iv.next_innov ||
            (v->kind == NEAT_INNOV_NODE && (v->innov2 >= pop->iv.next_innov || v->node >= pop->iv.next_node)))
            return 0;
    }
    return node < pop->iv.next_node && innov < pop->iv.next_innov;
}

int neat_pop_save(const neat_pop *pop, uint8_t **buf, size_t *len)
{
    neat_wbuf w;
    uint32_t i, k, version;
    if (pop == NULL || buf == NULL || len == NULL)
        return NEAT_E_ARG;
    memset(&w, 0, sizeof w);
    w.a = &pop->a;
    version = neat_ckpt_needs_v4(pop) ? 4 : 3;
    neat_put(&w, neat_ckpt_magic, 8);
    neat_put_u32(&w, version);
    neat_put_params(&w, &pop->p, version);
    neat_put_tag(&w, &pop->game);
    for (i = 0; i < 4; i++)
        neat_put_u64(&w, pop->rng.s[i]);
    neat_put_u32(&w, pop->generation);
    neat_put_u32(&w, pop->iv.next_innov);
    neat_put_u32(&w, pop->iv.next_node);
    neat_put_u32(&w, pop->next_species_id);
    neat_put_u32(&w, pop->since_pop_improved);
    neat_put_f64(&w, pop->delta_t);
    neat_put_f64(&w, pop->delta_t_used);
    neat_put_u32(&w, pop->iv.n);
    for (i = 0; i < pop->iv.n; i++) {
        const neat_innov *v = &pop->iv.list[i];
        neat_put_u8(&w, v->kind);
        neat_put_u32(&w, v->in);
        neat_put_u32(&w, v->out);
        neat_put_u32(&w, v->split);
        neat_put_u32(&w, v->innov);
        neat_put_u32(&w, v->innov2);
        neat_put_u32(&w, v->node);
    }
    neat_put_u8(&w, pop->have_best);
    if (pop->have_best) {
        neat_put_genome(&w, &pop->best_ever);
        neat_put_genome(&w, &pop->last_best);
    }
    for (i = 0; i < pop->p.pop_size; i++)
        neat_put_genome(&w, &pop->genomes[i]);
    neat_put_u32(&w, pop->n_species);
    for (k = 0; k < pop->n_species; k++) {
        const neat_species *s = &pop->species[k];
        neat_put_u32(&w, s->id);
        neat_put_u32(&w, s->age);
        neat_put_u32(&w, s->since_improved);
        neat_put_f64(&w, s->best_fitness);
        neat_put_genome(&w, &s->rep);
        neat_put_u32(&w, s->n_members);
        for (i = 0; i < s->n_members; i++)
            neat_put_u32(&w, s->members[i]);
        if (version >= 4)
            neat_put_u8(&w, s->culled);
    }
    return neat_put_finish(&w, buf, len);
}

void neat_pop_buf_free(const neat_pop *pop, uint8_t *buf, size_t len)
{
    neat_mem_free(&pop->a, buf, len);
}

int neat_pop_load(neat_pop **out, const uint8_t *buf, size_t len, const neat_alloc *alloc, size_t *err_offset)
{
    neat_rbuf r;
    neat_params p = neat_params_default();
    neat_pop *pop = NULL;
    uint32_t i, k, n;
    uint8_t *seen = NULL;
    size_t state_off;
    uint32_t version;
    int err;

    if (out == NULL || buf == NULL)
        return NEAT_E_ARG;
    *out = NULL;
    memset(&r, 0, sizeof r);
    r.p = buf;
    r.n = len;
    /* version 2 (before net_step and the game tag) still loads: sync, no tag */
    version = neat_get_frame(&r, neat_ckpt_magic, 2, NEAT_CHECKPOINT_VERSION);
    if (!r.err) {
        size_t at = r.off;
        neat_get_params(&r, &p, version);
        if (!r.err && neat_params_check(&p, NULL) != NEAT_OK) {
            r.off = at;
            neat_fail(&r, NEAT_E_FORMAT);
        }
    }
    if (!r.err) {
        err = neat_pop_alloc(&pop, &p, alloc);
        if (err)
            neat_fail(&r, err);
    }
    if (!r.err && version >= 3)
        neat_get_tag(&r, &pop->a, &pop->game);
    state_off = r.off;
    if (!r.err) {
        for (i = 0; i < 4; i++)
            pop->rng.s[i] = neat_get_u64(&r);
        pop->generation = neat_get_u32(&r);
        pop->iv.next_innov = neat_get_u32(&r);
        pop->iv.next_node = neat_get_u32(&r);
        pop->next_species_id = neat_get_u32(&r);
        pop->since_pop_improved = neat_get_u32(&r);
        if (!r.err && (pop->generation > NEAT_COUNTER_MAX || pop->iv.next_innov > NEAT_COUNTER_MAX ||
                       pop->iv.next_node > NEAT_COUNTER_MAX || pop->next_species_id > NEAT_COUNTER_MAX ||
                       pop->since_pop_improved > pop->generation))
            neat_fail(&r, NEAT_E_FORMAT); /* counters past their limit: the run could not go on */
        pop->delta_t = neat_get_f64(&r);
        pop->delta_t_used = neat_get_f64(&r);
        n = neat_get_count(&r, 25);
        if (!r.err && neat_mem_reserve(&pop->a, (void **)&pop->iv.list, &pop->iv.cap, n, sizeof(neat_innov)))
            neat_fail(&r, NEAT_E_NOMEM);
        for (i = 0; i < n && !r.err; i++) {
            neat_innov *v = &pop->iv.list[i];
            v->kind = (uint8_t)neat_get_u8(&r);
            v->in = neat_get_u32(&r);
            v->out = neat_get_u32(&r);
            v->split = neat_get_u32(&r);
            v->innov = neat_get_u32(&r);
            v->innov2 = neat_get_u32(&r);
            v->node = neat_get_u32(&r);
            v->weight = 0.0;
            pop->iv.n = i + 1;
        }
        pop->have_best = (uint8_t)neat_get_u8(&r);
        if (pop->have_best > 1)
            neat_fail(&r, NEAT_E_FORMAT);
        if (pop->have_best) {
            neat_get_genome(&r, &pop->best_ever, &p, &pop->a);
            neat_get_genome(&r, &pop->last_best, &p, &pop->a);
        }
        for (i = 0; i < p.pop_size && !r.err; i++)
            neat_get_genome(&r, &pop->genomes[i], &p, &pop->a);
        n = neat_get_count(&r, 33);
        seen = (uint8_t *)neat_mem_realloc(&pop->a, NULL, 0, p.pop_size);
        if (seen == NULL)
            neat_fail(&r, NEAT_E_NOMEM);
        else
            memset(seen, 0, p.pop_size);
        if (!r.err && neat_mem_reserve(&pop->a, (void **)&pop->species, &pop->cap_species, n, sizeof(neat_species)))
            neat_fail(&r, NEAT_E_NOMEM);
        for (k = 0; k < n && !r.err; k++) {
            neat_species *s = &pop->species[k];
            memset(s, 0, sizeof *s);
            pop->n_species = k + 1;
            s->id = neat_get_u32(&r);
            s->age = neat_get_u32(&r);
            s->since_improved = neat_get_u32(&r);
            s->best_fitness = neat_get_f64(&r);
            neat_get_genome(&r, &s->rep, &p, &pop->a);
            s->n_members = 0;
            {
                uint32_t m = neat_get_count(&r, 4);
                if (!r.err && neat_mem_reserve(&pop->a, (void **)&s->members, &s->cap_members, m, sizeof(uint32_t)))
                    neat_fail(&r, NEAT_E_NOMEM);
                if (!r.err && m == 0)
                    neat_fail(&r, NEAT_E_FORMAT); /* a species without members cannot exist */
                for (i = 0; i < m && !r.err; i++) {
                    size_t at = r.off;
                    uint32_t idx = neat_get_u32(&r);
                    if (!r.err && (idx >= p.pop_size || seen[idx]++)) {
                        r.off = at;
                        neat_fail(&r, NEAT_E_FORMAT);
                    }
                    s->members[s->n_members++] = idx;
                }
            }
            if (version >= 4) {
                s->culled = (uint8_t)neat_get_u8(&r);
                if (s->culled > 1)
                    neat_fail(&r, NEAT_E_FORMAT);
            }
        }
        /* every genome in exactly one species */
        for (i = 0; i < p.pop_size && !r.err; i++)
            if (!seen[i])
                neat_fail(&r, NEAT_E_FORMAT);
        if (!r.err && r.off != r.n)
            neat_fail(&r, NEAT_E_FORMAT); /* bytes left over */
        if (!r.err && !neat_pop_state_ok(pop)) {
            r.off = state_off; /* the population state, after the parameters */
            neat_fail(&r, NEAT_E_FORMAT);
        }
        neat_mem_free(&pop->a, seen, p.pop_size);
    }
    if (r.err) {
        if (err_offset != NULL)
            *err_offset = r.err_off;
        neat_pop_free(pop);
        return r.err;
    }
    *out = pop;
    return NEAT_OK;
}

int neat_checkpoint_kind(const uint8_t *buf, size_t len)
{
    if (buf == NULL || len < 8)
        return NEAT_CKPT_NONE;
    if (memcmp(buf, neat_ckpt_magic, 8) == 0)
        return NEAT_CKPT_POP;
    return memcmp(buf, neat_coev_magic, 8) == 0 ? NEAT_CKPT_COEV : NEAT_CKPT_NONE;
}
