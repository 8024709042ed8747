/* neat_innov.c - historical markings: the global counters and the list of this generation's structural innovations. */
#include "neat_internal.h"

/* Linear search: a generation adds a few dozen innovations at most. */
static neat_innov *neat_innov_find(neat_innovs *iv, uint8_t kind, uint32_t in, uint32_t out, uint32_t split)
{
    uint32_t i;
    for (i = 0; i < iv->n; i++) {
        neat_innov *r = &iv->list[i];
        if (r->kind == kind && r->in == in && r->out == out && r->split == split)
            return r;
    }
    return NULL;
}

static neat_innov *neat_innov_push(neat_innovs *iv, const neat_alloc *a)
{
    if (neat_mem_reserve(a, (void **)&iv->list, &iv->cap, iv->n + 1, sizeof(neat_innov)))
        return NULL;
    return &iv->list[iv->n++];
}

int neat_innov_conn_rec(neat_innovs *iv, const neat_alloc *a, uint32_t in, uint32_t out, neat_innov **rec,
                        int *fresh)
{
    neat_innov *r = neat_innov_find(iv, NEAT_INNOV_CONN, in, out, 0);
    *fresh = r == NULL;
    if (r == NULL) {
        r = neat_innov_push(iv, a);
        if (r == NULL)
            return NEAT_E_NOMEM;
        r->kind = NEAT_INNOV_CONN;
        r->in = in;
        r->out = out;
        r->split = 0;
        r->innov = iv->next_innov++;
        r->innov2 = 0;
        r->node = 0;
        r->weight = 0.0;
    }
    *rec = r;
    return NEAT_OK;
}

int neat_innov_conn(neat_innovs *iv, const neat_alloc *a, uint32_t in, uint32_t out, uint32_t *innov)
{
    neat_innov *r;
    int fresh, err = neat_innov_conn_rec(iv, a, in, out, &r, &fresh);
    if (!err)
        *innov = r->innov;
    return err;
}

int neat_innov_node(neat_innovs *iv, const neat_alloc *a, uint32_t in, uint32_t out, uint32_t split,
                    neat_innov *out_rec)
{
    neat_innov *r = neat_innov_find(iv, NEAT_INNOV_NODE, in, out, split);
    if (r == NULL) {
        r = neat_innov_push(iv, a);
        if (r == NULL)
            return NEAT_E_NOMEM;
        r->kind = NEAT_INNOV_NODE;
        r->in = in;
        r->out = out;
        r->split = split;
        r->node = iv->next_node++;
        r->innov = iv->next_innov++;
        r->innov2 = iv->next_innov++;
        r->weight = 0.0;
    }
    *out_rec = *r;
    return NEAT_OK;
}

void neat_innov_reset(neat_innovs *iv)
{
    iv->n = 0;
}
