/* neat_genome_file.c - one genome with its genes as a versioned, checksummed file: a champion to seed a run with or to analyse, with where it was made. */
#include <string.h>

#include "neat_io.h"
#include "nrt.h"

int neat_genome_save_origin(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs,
                            const neat_genome_origin *origin, uint8_t **buf, size_t *len, const neat_alloc *a)
{
    neat_wbuf w;
    if (g == NULL || buf == NULL || len == NULL || !neat_genome_io_ok(g, n_inputs, n_outputs))
        return NEAT_E_ARG;
    if (origin != NULL && ((origin->net_step != NEAT_STEP_SYNC && origin->net_step != NEAT_STEP_PROPAGATE) ||
                           origin->tag_len > NEAT_GAME_MAX || (origin->tag_len > 0 && origin->tag == NULL)))
        return NEAT_E_ARG;
    memset(&w, 0, sizeof w);
    w.a = a;
    neat_put(&w, NEAT_GENOME_FILE_MAGIC, 8); /* neat.h: 8 bytes, no terminator */
    neat_put_u32(&w, origin != NULL ? 2u : 1u);
    neat_put_u32(&w, n_inputs);
    neat_put_u32(&w, n_outputs);
    if (origin != NULL) {
        neat_put_u32(&w, (uint32_t)origin->net_step);
        neat_put_u32(&w, origin->tag_len);
        if (origin->tag_len > 0)
            neat_put(&w, origin->tag, origin->tag_len);
    }
    neat_put_genome(&w, g);
    return neat_put_finish(&w, buf, len);
}

int neat_genome_save(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, uint8_t **buf, size_t *len,
                     const neat_alloc *a)
{
    return neat_genome_save_origin(g, n_inputs, n_outputs, NULL, buf, len, a);
}

int neat_genome_load_origin(neat_genome *g, uint32_t *n_inputs, uint32_t *n_outputs, neat_genome_origin *origin,
                            const uint8_t *buf, size_t len, const neat_alloc *a, size_t *err_offset)
{
    neat_rbuf r;
    neat_params p;
    neat_genome_origin o;
    uint32_t version;
    if (g == NULL || buf == NULL)
        return NEAT_E_ARG;
    neat_genome_init(g);
    memset(&r, 0, sizeof r);
    memset(&o, 0, sizeof o);
    r.p = buf;
    r.n = len;
    version = neat_get_frame(&r, (const uint8_t *)NEAT_GENOME_FILE_MAGIC, 1, NEAT_GENOME_FILE_VERSION);
    o.version = version;
    o.net_step = NEAT_STEP_SYNC;
    /* the shape first: neat_get_genome checks the genome against it (bias,
     * inputs and outputs present, at most NRT_MAX_NODES nodes) */
    p = neat_params_default();
    p.n_inputs = neat_get_u32(&r);
    p.n_outputs = neat_get_u32(&r);
    p.max_nodes = NRT_MAX_NODES;
    /* each refusal names its field's offset: n_inputs at 12, n_outputs at 16 (the one that makes the sum too large) */
    if (!r.err && (p.n_inputs < 1 || p.n_inputs >= NRT_MAX_NODES)) {
        r.off = 12;
        neat_fail(&r, NEAT_E_FORMAT);
    } else if (!r.err &&
               (p.n_outputs < 1 || p.n_outputs >= NRT_MAX_NODES || p.n_inputs + p.n_outputs + 1 > NRT_MAX_NODES)) {
        r.off = 16;
        neat_fail(&r, NEAT_E_FORMAT);
    }
    if (!r.err && version >= 2) {
        /* the origin: the step (offset 20), the tag's length (24), checked before the tag is trusted */
        uint32_t step = neat_get_u32(&r), n;
        if (!r.err && step != NEAT_STEP_SYNC && step != NEAT_STEP_PROPAGATE) {
            r.off = 20;
            neat_fail(&r, NEAT_E_FORMAT);
        }
        n = r.err ? 0 : neat_get_count(&r, 1); /* never more than the bytes left */
        if (!r.err && n > NEAT_GAME_MAX) {
            r.off = 24;
            neat_fail(&r, NEAT_E_FORMAT);
        }
        if (!r.err) {
            o.net_step = (int)step;
            o.tag_len = n;
            o.tag = n > 0 ? neat_get(&r, n) : NULL;
        }
    }
    if (!r.err)
        neat_get_genome(&r, g, &p, a);
    if (!r.err && r.off != r.n)
        neat_fail(&r, NEAT_E_FORMAT); /* bytes left over */
    if (r.err) {
        if (err_offset != NULL)
            *err_offset = r.err_off;
        neat_genome_free(g, a);
        return r.err;
    }
    if (n_inputs != NULL)
        *n_inputs = p.n_inputs;
    if (n_outputs != NULL)
        *n_outputs = p.n_outputs;
    if (origin != NULL)
        *origin = o;
    return NEAT_OK;
}

int neat_genome_load(neat_genome *g, uint32_t *n_inputs, uint32_t *n_outputs, const uint8_t *buf, size_t len,
                     const neat_alloc *a, size_t *err_offset)
{
    return neat_genome_load_origin(g, n_inputs, n_outputs, NULL, buf, len, a, err_offset);
}
