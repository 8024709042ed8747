/* neat_game.c - the game-identity tag: opaque bytes a run records in its checkpoint (which world rules it was made with). */
#include <string.h>

#include "neat_io.h"

int neat_tag_set(const neat_alloc *a, neat_tag *t, const uint8_t *bytes, size_t len)
{
    uint8_t *copy = NULL;
    if (len > NEAT_GAME_MAX || (bytes == NULL && len > 0))
        return NEAT_E_ARG;
    /* the new copy first: on NEAT_E_NOMEM the old tag stays */
    if (len > 0) {
        copy = (uint8_t *)neat_mem_realloc(a, NULL, 0, len);
        if (copy == NULL)
            return NEAT_E_NOMEM;
        memcpy(copy, bytes, len);
    }
    neat_tag_free(a, t);
    t->bytes = copy;
    t->len = len;
    return NEAT_OK;
}

void neat_tag_free(const neat_alloc *a, neat_tag *t)
{
    neat_mem_free(a, t->bytes, t->len);
    t->bytes = NULL;
    t->len = 0;
}

const uint8_t *neat_tag_get(const neat_tag *t, size_t *len)
{
    if (len != NULL)
        *len = t->len;
    return t->bytes;
}

void neat_put_tag(neat_wbuf *w, const neat_tag *t)
{
    neat_put_u32(w, (uint32_t)t->len);
    if (t->len > 0)
        neat_put(w, t->bytes, t->len);
}

void neat_get_tag(neat_rbuf *r, const neat_alloc *a, neat_tag *t)
{
    size_t at = r->off;
    uint32_t n = neat_get_count(r, 1); /* never more than the bytes left */
    const uint8_t *b;
    int err;
    if (r->err)
        return;
    if (n > NEAT_GAME_MAX) {
        r->off = at;
        neat_fail(r, NEAT_E_FORMAT);
        return;
    }
    b = neat_get(r, n);
    if (r->err)
        return;
    err = neat_tag_set(a, t, b, n);
    if (err)
        neat_fail(r, err);
}

int neat_pop_set_game(neat_pop *pop, const uint8_t *bytes, size_t len)
{
    if (pop == NULL)
        return NEAT_E_ARG;
    return neat_tag_set(&pop->a, &pop->game, bytes, len);
}

const uint8_t *neat_pop_game(const neat_pop *pop, size_t *len)
{
    return neat_tag_get(&pop->game, len);
}
