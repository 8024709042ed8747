/* duel_mpi_wire.c - a run's game messages between ranks checked byte by byte before a game is played from them (no MPI here: fuzzed by tests/fuzz/fuzz_mpi_wire.c). */
#include <stdlib.h>
#include <string.h>

#include "duel_mpi_wire.h"

int duel_grow(void **p, size_t *cap, size_t need, size_t elem)
{
    size_t c = *cap ? *cap : 64;
    void *np;
    if (need <= *cap)
        return 0;
    while (c < need) {
        if (c > ((size_t)-1) / 2 / (elem ? elem : 1))
            return -1;
        c *= 2;
    }
    np = realloc(*p, c * elem);
    if (np == NULL)
        return -1;
    *p = np;
    *cap = c;
    return 0;
}

/* a network not sent in this batch: no blob, and no builtin's number */
static void duel_wire_unsent(duel_net *n)
{
    n->blob = NULL;
    n->len = SIZE_MAX;
}

static int duel_wire_sent(const duel_net *n)
{
    return n->blob != NULL || n->len != SIZE_MAX;
}

static void duel_wire_clear(duel_wire_store *s)
{
    size_t i;
    for (i = 0; i < s->n_bufs; i++)
        free(s->bufs[i]);
    s->n_bufs = 0;
    for (i = 0; i < s->cap; i++)
        duel_wire_unsent(&s->nets[i]);
}

void duel_wire_store_free(duel_wire_store *s)
{
    duel_wire_clear(s);
    free(s->nets);
    free(s->bufs);
    memset(s, 0, sizeof *s);
}

static int duel_wire_work_parse(duel_wire_store *s, uint8_t *buf, size_t len, duel_work_hdr *h, duel_rules *rules,
                                 duel_match **m, size_t *m_cap)
{
    size_t pos = sizeof *h, i;
    if (len < sizeof *h)
        return -1;
    memcpy(h, buf, sizeof *h);
    if (h->magic != DUEL_MPI_WORK_MAGIC || h->count == 0 || h->count > len || h->n_new > DUEL_MPI_MAX_NETS)
        return -1;
    if (duel_rules_decode(rules, h->rules, sizeof h->rules, NULL) != DUEL_OK)
        return -1;
    if (h->batch != s->batch) {
        duel_wire_clear(s);
        s->batch = h->batch;
    }
    for (i = 0; i < h->n_new; i++) {
        uint32_t w[2];
        if (len - pos < 8)
            return -1;
        memcpy(w, buf + pos, 8);
        if (w[0] >= DUEL_MPI_MAX_NETS ||
            (w[1] < DUEL_WIRE_BUILTIN ? w[1] > len - pos - 8 : w[1] - DUEL_WIRE_BUILTIN >= DUEL_N_BUILTINS))
            return -1;
        if (w[0] >= s->cap) {
            size_t old = s->cap, k;
            if (duel_grow((void **)&s->nets, &s->cap, (size_t)w[0] + 1, sizeof *s->nets) != 0)
                return -1;
            for (k = old; k < s->cap; k++)
                duel_wire_unsent(&s->nets[k]);
        }
        if (w[1] >= DUEL_WIRE_BUILTIN) { /* a builtin strategy: its number, no bytes */
            s->nets[w[0]].blob = NULL;
            s->nets[w[0]].len = w[1] - DUEL_WIRE_BUILTIN;
            pos += 8;
            continue;
        }
        s->nets[w[0]].blob = buf + pos + 8;
        s->nets[w[0]].len = w[1];
        pos += 8 + (size_t)w[1];
    }
    if ((len - pos) % sizeof(duel_wire_match) != 0 || (len - pos) / sizeof(duel_wire_match) != h->count)
        return -1;
    if (duel_grow((void **)m, m_cap, h->count, sizeof **m) != 0)
        return -1;
    for (i = 0; i < h->count; i++) {
        duel_wire_match w;
        memcpy(&w, buf + pos + i * sizeof w, sizeof w);
        if (w.a >= s->cap || w.b >= s->cap || !duel_wire_sent(&s->nets[w.a]) || !duel_wire_sent(&s->nets[w.b]))
            return -1;
        (*m)[i].a = w.a;
        (*m)[i].b = w.b;
        (*m)[i].config = w.config;
        (*m)[i].a_first = w.a_first;
        (*m)[i].result = 0;
    }
    if (duel_grow((void **)&s->bufs, &s->bufs_cap, s->n_bufs + 1, sizeof *s->bufs) != 0)
        return -1;
    s->bufs[s->n_bufs++] = buf; /* the blobs live in it until the batch changes */
    return 0;
}

int duel_wire_work_take(duel_wire_store *s, uint8_t *buf, size_t len, duel_work_hdr *h, duel_rules *rules,
                        duel_match **m, size_t *m_cap)
{
    size_t i;
    if (duel_wire_work_parse(s, buf, len, h, rules, m, m_cap) == 0)
        return 0;
    /* refused: the caller keeps buf, so nothing may point into it (the fuzzer found the networks a bad message
     * named before its error still pointing there) */
    for (i = 0; i < s->cap; i++)
        if (s->nets[i].blob != NULL && (uintptr_t)s->nets[i].blob >= (uintptr_t)buf &&
            (uintptr_t)s->nets[i].blob < (uintptr_t)buf + len)
            duel_wire_unsent(&s->nets[i]);
    return -1;
}

int duel_wire_result_read(const uint8_t *buf, size_t len, uint64_t batch, size_t from, size_t count,
                          duel_result_hdr *h)
{
    if (len < sizeof *h || len - sizeof *h != count)
        return -1;
    memcpy(h, buf, sizeof *h);
    if (h->magic != DUEL_MPI_RESULT_MAGIC || h->batch != batch || h->from != from || h->count != count ||
        (h->err != 0 && h->err_at >= h->count) || (h->err == 0 && h->err_at != 0))
        return -1;
    return 0;
}
