/* neat_blob.c - genome <-> champion blob: the phenotype the runtime executes (format in docs/formats.md), and a blob's network as a start genome. */
#include <math.h>
#include <string.h>

#include "nrt.h"
#include "neat_internal.h"

size_t neat_blob_size(const neat_genome *g)
{
    return NRT_HEADER_SIZE + NRT_CONN_SIZE * (size_t)neat_genome_enabled_count(g);
}

static void neat_wr16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFF);
    p[1] = (uint8_t)((v >> 8) & 0xFF);
}

static void neat_wr32(uint8_t *p, uint32_t v)
{
    neat_wr16(p, v & 0xFFFF);
    neat_wr16(p + 2, v >> 16);
}

/* Runtime index of a node = its position in the genome: bias 0, inputs
 * 1..n_in, outputs next (ids equal to their positions: neat_blob_write
 * checks these), then hidden nodes in id order. */
static uint32_t neat_blob_index(const neat_genome *g, uint32_t n_io, uint32_t id)
{
    return id < n_io ? id : (uint32_t)(neat_genome_find_node(g, id) - g->nodes);
}

static int32_t neat_quantize(double w)
{
    double q = floor(w * (double)(1 << NRT_WEIGHT_FRAC_BITS) + 0.5);
    if (q > NRT_WEIGHT_MAX)
        q = NRT_WEIGHT_MAX;
    if (q < NRT_WEIGHT_MIN)
        q = NRT_WEIGHT_MIN;
    return (int32_t)q;
}

int neat_blob_write(const neat_genome *g, uint32_t n_in, uint32_t n_out, uint8_t *buf, size_t cap, size_t *len)
{
    return neat_blob_write_step(g, n_in, n_out, NEAT_STEP_SYNC, buf, cap, len);
}

int neat_blob_write_step(const neat_genome *g, uint32_t n_in, uint32_t n_out, int net_step, uint8_t *buf, size_t cap,
                         size_t *len)
{
    uint32_t i, k, n = 0, n_hid, n_io = n_in + 1 + n_out, n_en;
    size_t size;
    uint32_t crc;

    if (g == NULL || buf == NULL || (net_step != NEAT_STEP_SYNC && net_step != NEAT_STEP_PROPAGATE))
        return NEAT_E_ARG;
    /* bias, inputs and outputs first with ids 0..n_io-1, every other node hidden */
    if (!neat_genome_io_ok(g, n_in, n_out))
        return NEAT_E_ARG; /* n_in / n_out do not match the genome */
    n_hid = g->n_nodes - n_io;
    n_en = neat_genome_enabled_count(g);
    if (g->n_nodes > NRT_MAX_NODES || n_en > 0xFFFF)
        return NEAT_E_TOOBIG;
    size = NRT_HEADER_SIZE + NRT_CONN_SIZE * (size_t)n_en;
    if (cap < size)
        return NEAT_E_ARG;

    memset(buf, 0, NRT_HEADER_SIZE);
    buf[0] = NRT_MAGIC0;
    buf[1] = NRT_MAGIC1;
    buf[2] = NRT_MAGIC2;
    buf[3] = NRT_MAGIC3;
    /* a sync blob is version 1, byte for byte as before the modes; a
     * propagate one version 2 with the step byte set (the runtime computes
     * its evaluation order from the connections) */
    neat_wr16(buf + NRT_OFF_VERSION, net_step == NEAT_STEP_SYNC ? NRT_FORMAT_VERSION : NRT_FORMAT_VERSION_PROPAGATE);
    buf[NRT_OFF_STEP] = (uint8_t)(net_step == NEAT_STEP_SYNC ? NRT_STEP_SYNC : NRT_STEP_PROPAGATE);
    neat_wr16(buf + NRT_OFF_HEADER_SIZE, NRT_HEADER_SIZE);
    neat_wr16(buf + NRT_OFF_INPUTS, n_in + 1);
    neat_wr16(buf + NRT_OFF_OUTPUTS, n_out);
    neat_wr16(buf + NRT_OFF_HIDDEN, n_hid);
    neat_wr16(buf + NRT_OFF_CONNS, n_en);
    neat_wr32(buf + NRT_OFF_TOTAL_SIZE, (uint32_t)size);
    buf[NRT_OFF_WEIGHT_BITS] = NRT_WEIGHT_FRAC_BITS;
    buf[NRT_OFF_ACTIVATION] = NRT_ACT_SIGMOID49;

    for (i = 0; i < g->n_conns; i++) {
        const neat_conn *c = &g->conns[i];
        uint8_t rec[4];
        if (!c->enabled)
            continue;
        rec[0] = (uint8_t)neat_blob_index(g, n_io, c->in);
        rec[1] = (uint8_t)neat_blob_index(g, n_io, c->out);
        neat_wr16(rec + 2, (uint32_t)neat_quantize(c->weight) & 0xFFFF);
        /* insertion into (target, source) order, which the runtime requires */
        for (k = n; k > 0; k--) {
            uint8_t *prev = buf + NRT_HEADER_SIZE + 4 * (k - 1);
            if (prev[1] < rec[1] || (prev[1] == rec[1] && prev[0] <= rec[0]))
                break;
            memcpy(prev + 4, prev, 4);
        }
        memcpy(buf + NRT_HEADER_SIZE + 4 * k, rec, 4);
        n++;
    }
    crc = nrt_crc32(0, buf, NRT_OFF_CRC);
    crc = nrt_crc32(crc, buf + NRT_HEADER_SIZE, size - NRT_HEADER_SIZE);
    neat_wr32(buf + NRT_OFF_CRC, crc);
    if (len != NULL)
        *len = size;
    return NEAT_OK;
}

int neat_genome_from_blob(neat_genome *g, const uint8_t *blob, size_t len, const neat_alloc *a)
{
    return neat_genome_from_blob_step(g, blob, len, a, NULL);
}

int neat_genome_from_blob_step(neat_genome *g, const uint8_t *blob, size_t len, const neat_alloc *a, int *net_step)
{
    nrt_net net;
    size_t need = 0;
    void *mem;
    uint32_t i, k;
    int err;

    if (g == NULL || blob == NULL)
        return NEAT_E_ARG;
    neat_genome_init(g);
    if (nrt_mem_required(blob, len, &need) != NRT_OK)
        return NEAT_E_FORMAT;
    mem = neat_mem_realloc(a, NULL, 0, need);
    if (mem == NULL)
        return NEAT_E_NOMEM;
    if (nrt_load(&net, blob, len, mem, need) != NRT_OK) {
        neat_mem_free(a, mem, need);
        return NEAT_E_FORMAT;
    }
    neat_mem_free(a, mem, need);
    /* the runtime's node order is the genome's: bias, inputs, outputs, hidden */
    err = NEAT_OK;
    for (i = 0; i < net.n_nodes && !err; i++)
        err = neat_genome_add_node(g, i,
                                   i == 0 ? NEAT_NODE_BIAS
                                   : i < net.n_inputs ? NEAT_NODE_INPUT
                                   : i < (uint32_t)net.n_inputs + net.n_outputs ? NEAT_NODE_OUTPUT
                                                                                 : NEAT_NODE_HIDDEN,
                                   a);
    /* the connections as the blob lists them (nrt_load vouched for every
     * byte): the genome of a blob is the same whatever its step mode */
    for (k = 0; k < net.n_conns && !err; k++) {
        const uint8_t *c = blob + NRT_HEADER_SIZE + NRT_CONN_SIZE * k;
        int16_t w = (int16_t)(uint16_t)(c[2] | (c[3] << 8));
        err = neat_genome_add_conn(g, c[0], c[1], (double)w / (double)(1 << NRT_WEIGHT_FRAC_BITS), k, 1, a);
    }
    if (err)
        neat_genome_free(g, a);
    else if (net_step != NULL)
        *net_step = net.step == NRT_STEP_PROPAGATE ? NEAT_STEP_PROPAGATE : NEAT_STEP_SYNC;
    /* only the allocator can fail here */
    return err;
}
