/* neat_io.c - bounds-checked little-endian writing and reading of numbers and genomes for the checkpoint formats. */
#include <string.h>

#include "nrt.h"
#include "neat_io.h"

/* ---- writing ---- */
void neat_put(neat_wbuf *w, const void *src, size_t len)
{
    if (w->err)
        return;
    if (w->n + len > w->cap) {
        size_t ncap = w->cap ? w->cap : 4096;
        uint8_t *np;
        while (ncap < w->n + len)
            ncap *= 2;
        np = (uint8_t *)neat_mem_realloc(w->a, w->p, w->cap, ncap);
        if (np == NULL) {
            w->err = NEAT_E_NOMEM;
            return;
        }
        w->p = np;
        w->cap = ncap;
    }
    memcpy(w->p + w->n, src, len);
    w->n += len;
}

void neat_put_u8(neat_wbuf *w, uint32_t v)
{
    uint8_t b = (uint8_t)v;
    neat_put(w, &b, 1);
}

void neat_put_u32(neat_wbuf *w, uint32_t v)
{
    uint8_t b[4];
    b[0] = (uint8_t)v;
    b[1] = (uint8_t)(v >> 8);
    b[2] = (uint8_t)(v >> 16);
    b[3] = (uint8_t)(v >> 24);
    neat_put(w, b, 4);
}

void neat_put_u64(neat_wbuf *w, uint64_t v)
{
    neat_put_u32(w, (uint32_t)v);
    neat_put_u32(w, (uint32_t)(v >> 32));
}

void neat_put_f64(neat_wbuf *w, double d)
{
    uint64_t v;
    memcpy(&v, &d, 8); /* the exact IEEE-754 bits */
    neat_put_u64(w, v);
}

/* ---- reading ---- */

void neat_fail(neat_rbuf *r, int err)
{
    if (!r->err) {
        r->err = err;
        r->err_off = r->off;
    }
}

const uint8_t *neat_get(neat_rbuf *r, size_t len)
{
    const uint8_t *q;
    if (r->err)
        return NULL;
    if (r->n - r->off < len) {
        neat_fail(r, NEAT_E_TRUNCATED);
        return NULL;
    }
    q = r->p + r->off;
    r->off += len;
    return q;
}

uint32_t neat_get_u8(neat_rbuf *r)
{
    const uint8_t *q = neat_get(r, 1);
    return q ? q[0] : 0;
}

uint32_t neat_get_u32(neat_rbuf *r)
{
    const uint8_t *q = neat_get(r, 4);
    return q ? (uint32_t)q[0] | ((uint32_t)q[1] << 8) | ((uint32_t)q[2] << 16) | ((uint32_t)q[3] << 24) : 0;
}

uint64_t neat_get_u64(neat_rbuf *r)
{
    uint64_t lo = neat_get_u32(r);
    return lo | ((uint64_t)neat_get_u32(r) << 32);
}

double neat_get_f64(neat_rbuf *r)
{
    uint64_t v = neat_get_u64(r);
    double d;
    memcpy(&d, &v, 8);
    return d;
}

uint32_t neat_get_count(neat_rbuf *r, size_t rec_size)
{
    size_t at = r->off;
    uint32_t n = neat_get_u32(r);
    if (!r->err && (size_t)n > (r->n - r->off) / rec_size) {
        r->off = at;
        neat_fail(r, NEAT_E_FORMAT);
        return 0;
    }
    return n;
}

int neat_put_finish(neat_wbuf *w, uint8_t **buf, size_t *len)
{
    if (!w->err)
        neat_put_u32(w, nrt_crc32(0, w->p, w->n));
    if (w->err) {
        neat_mem_free(w->a, w->p, w->cap);
        return w->err;
    }
    *buf = w->p;
    *len = w->n;
    /* the caller frees with the length, which must be the capacity: shrink to fit */
    if (w->cap != w->n) {
        uint8_t *np = (uint8_t *)neat_mem_realloc(w->a, w->p, w->cap, w->n);
        if (np == NULL) {
            neat_mem_free(w->a, w->p, w->cap);
            return NEAT_E_NOMEM;
        }
        *buf = np;
    }
    return NEAT_OK;
}

/* ---- genomes ---- */
void neat_put_genome(neat_wbuf *w, const neat_genome *g)
{
    uint32_t i;
    neat_put_u32(w, g->n_nodes);
    for (i = 0; i < g->n_nodes; i++) {
        neat_put_u32(w, g->nodes[i].id);
        neat_put_u8(w, g->nodes[i].type);
    }
    neat_put_u32(w, g->n_conns);
    for (i = 0; i < g->n_conns; i++) {
        neat_put_u32(w, g->conns[i].in);
        neat_put_u32(w, g->conns[i].out);
        neat_put_u32(w, g->conns[i].innov);
        neat_put_f64(w, g->conns[i].weight);
        neat_put_u8(w, g->conns[i].enabled);
    }
    neat_put_f64(w, g->fitness);
    neat_put_u32(w, g->species);
    neat_put_u8(w, g->has_fitness);
}

void neat_get_genome(neat_rbuf *r, neat_genome *g, const neat_params *p, const neat_alloc *a)
{
    uint32_t i, n;
    size_t start = r->off;
    n = neat_get_count(r, 5);
    for (i = 0; i < n && !r->err; i++) {
        size_t at = r->off;
        uint32_t id = neat_get_u32(r), type = neat_get_u8(r);
        int err = r->err ? 0 : neat_genome_add_node(g, id, (int)type, a);
        if (err || (g->n_nodes > 1 && g->nodes[g->n_nodes - 1].id != id)) {
            r->off = at;
            neat_fail(r, err == NEAT_E_NOMEM ? NEAT_E_NOMEM : NEAT_E_FORMAT); /* not sorted, duplicate or bad type */
        }
    }
    n = neat_get_count(r, 21);
    for (i = 0; i < n && !r->err; i++) {
        size_t at = r->off;
        uint32_t in = neat_get_u32(r), out = neat_get_u32(r), innov = neat_get_u32(r);
        double wt = neat_get_f64(r);
        uint32_t en = neat_get_u8(r);
        int err = r->err ? 0 : neat_genome_add_conn(g, in, out, wt, innov, (int)en, a);
        if (err || en > 1 || (g->n_conns > 0 && g->conns[g->n_conns - 1].innov != innov) || wt != wt) {
            r->off = at;
            neat_fail(r, err == NEAT_E_NOMEM ? NEAT_E_NOMEM : NEAT_E_FORMAT);
        }
    }
    g->fitness = neat_get_f64(r);
    g->species = neat_get_u32(r);
    g->has_fitness = (uint8_t)neat_get_u8(r);
    if (!r->err && (!neat_genome_io_ok(g, p->n_inputs, p->n_outputs) || g->n_nodes > p->max_nodes ||
                    g->has_fitness > 1 || !(g->fitness >= 0) || g->fitness > 1e308)) {
        r->off = start;
        neat_fail(r, NEAT_E_FORMAT);
    }
}


uint32_t neat_get_frame(neat_rbuf *r, const uint8_t magic[8], uint32_t oldest, uint32_t newest)
{
    const uint8_t *m = neat_get(r, 8), *buf = r->p;
    size_t len = r->n;
    uint32_t stored, version = 0;
    if (m != NULL && memcmp(m, magic, 8) != 0) {
        r->off = 0;
        neat_fail(r, NEAT_E_FORMAT);
    }
    if (!r->err)
        version = neat_get_u32(r);
    if (!r->err && (version < oldest || version > newest)) {
        r->off = 8;
        neat_fail(r, NEAT_E_FORMAT);
    }
    if (!r->err && len < 16) {
        r->off = len;
        neat_fail(r, NEAT_E_TRUNCATED);
    }
    if (r->err)
        return 0;
    stored = (uint32_t)buf[len - 4] | ((uint32_t)buf[len - 3] << 8) | ((uint32_t)buf[len - 2] << 16) |
             ((uint32_t)buf[len - 1] << 24);
    if (nrt_crc32(0, buf, len - 4) != stored) {
        r->off = len - 4;
        neat_fail(r, NEAT_E_CRC);
        return 0;
    }
    r->n = len - 4; /* the body ends at the checksum */
    return version;
}
