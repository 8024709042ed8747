/* nrt_load.c - validates a champion blob byte by byte and lays the network out in the caller's memory. */
#include <string.h>

#include "nrt.h"

static uint16_t nrt_rd16(const uint8_t *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static uint32_t nrt_rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

uint32_t nrt_crc32(uint32_t crc, const void *data, size_t len)
{
    /* Bitwise, no table: it runs once per load and a table would cost 1 KiB of flash. */
    const uint8_t *p = (const uint8_t *)data;
    size_t i;
    int b;
    crc = ~crc;
    for (i = 0; i < len; i++) {
        crc ^= p[i];
        for (b = 0; b < 8; b++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

/* Memory nrt_load lays out, all 16-bit arrays: weights and sources of the
 * connections, ends of each node's run, two activation arrays; +1 to align
 * a buffer of any address. */
static size_t nrt_mem_for(uint32_t nodes, uint32_t non_inputs, uint32_t conns)
{
    return 4u * conns + 2u * non_inputs + 4u * nodes + 1u;
}

int nrt_inspect(const uint8_t *blob, size_t len, size_t *blob_size, size_t *mem_required)
{
    uint32_t n_in, n_out, n_hid, n_conns, nodes, total;
    if (blob == NULL)
        return NRT_E_ARG;
    if (len < NRT_HEADER_SIZE)
        return NRT_E_TRUNCATED;
    if (blob[0] != NRT_MAGIC0 || blob[1] != NRT_MAGIC1 || blob[2] != NRT_MAGIC2 || blob[3] != NRT_MAGIC3)
        return NRT_E_MAGIC;
    if (nrt_rd16(blob + NRT_OFF_VERSION) != NRT_FORMAT_VERSION)
        return NRT_E_VERSION;
    if (nrt_rd16(blob + NRT_OFF_HEADER_SIZE) != NRT_HEADER_SIZE || blob[NRT_OFF_WEIGHT_BITS] != NRT_WEIGHT_FRAC_BITS ||
        blob[NRT_OFF_ACTIVATION] != NRT_ACT_SIGMOID49)
        return NRT_E_HEADER;
    {
        int i;
        for (i = NRT_OFF_RESERVED; i < NRT_OFF_CRC; i++)
            if (blob[i] != 0)
                return NRT_E_HEADER;
    }
    n_in = nrt_rd16(blob + NRT_OFF_INPUTS);
    n_out = nrt_rd16(blob + NRT_OFF_OUTPUTS);
    n_hid = nrt_rd16(blob + NRT_OFF_HIDDEN);
    n_conns = nrt_rd16(blob + NRT_OFF_CONNS);
    nodes = n_in + n_out + n_hid;
    if (n_in < 1 || n_out < 1 || nodes > NRT_MAX_NODES)
        return NRT_E_COUNTS;
    total = nrt_rd32(blob + NRT_OFF_TOTAL_SIZE);
    if (total != NRT_HEADER_SIZE + NRT_CONN_SIZE * n_conns)
        return NRT_E_COUNTS;
    if (blob_size != NULL)
        *blob_size = total;
    if (mem_required != NULL)
        *mem_required = nrt_mem_for(nodes, n_out + n_hid, n_conns);
    return NRT_OK;
}

int nrt_mem_required(const uint8_t *blob, size_t len, size_t *mem_required)
{
    return nrt_inspect(blob, len, NULL, mem_required);
}

int nrt_load(nrt_net *net, const uint8_t *blob, size_t len, void *mem, size_t mem_len)
{
    size_t total, need;
    uint32_t crc, k, n_conns, n_in, nodes, prev_dst = 0;
    uint16_t j;
    uint8_t *m;
    int err;

    if (net == NULL)
        return NRT_E_ARG;
    memset(net, 0, sizeof *net);
    if (mem == NULL)
        return NRT_E_ARG;
    err = nrt_inspect(blob, len, &total, &need);
    if (err != NRT_OK)
        return err;
    if (len < total)
        return NRT_E_TRUNCATED;
    if (len > total)
        return NRT_E_TRAILING;
    crc = nrt_crc32(0, blob, NRT_OFF_CRC);
    crc = nrt_crc32(crc, blob + NRT_HEADER_SIZE, total - NRT_HEADER_SIZE);
    if (crc != nrt_rd32(blob + NRT_OFF_CRC))
        return NRT_E_CRC;

    n_in = nrt_rd16(blob + NRT_OFF_INPUTS);
    n_conns = nrt_rd16(blob + NRT_OFF_CONNS);
    nodes = n_in + nrt_rd16(blob + NRT_OFF_OUTPUTS) + nrt_rd16(blob + NRT_OFF_HIDDEN);
    for (k = 0; k < n_conns; k++) {
        const uint8_t *c = blob + NRT_HEADER_SIZE + NRT_CONN_SIZE * k;
        if (c[0] >= nodes || c[1] < n_in || c[1] >= nodes)
            return NRT_E_INDEX;
        if (c[1] < prev_dst)
            return NRT_E_ORDER;
        if (nrt_rd16(c + 2) == 0x8000u)
            return NRT_E_WEIGHT;
        prev_dst = c[1];
    }
    if (mem_len < need)
        return NRT_E_NOMEM;

    /* Everything checked: lay out the buffer (16-bit arrays, 2-aligned). */
    net->n_inputs = (uint16_t)n_in;
    net->n_outputs = nrt_rd16(blob + NRT_OFF_OUTPUTS);
    net->n_hidden = nrt_rd16(blob + NRT_OFF_HIDDEN);
    net->n_nodes = (uint16_t)nodes;
    net->n_conns = (uint16_t)n_conns;
    m = (uint8_t *)mem;
    m += (uintptr_t)m & 1u;
    net->weight = (nrt_w12 *)(void *)m;
    m += 2u * n_conns;
    net->src = (uint16_t *)(void *)m;
    m += 2u * n_conns;
    net->end = (uint16_t *)(void *)m;
    m += 2u * (nodes - n_in);
    net->act[0] = (nrt_q15 *)(void *)m;
    m += 2u * nodes;
    net->act[1] = (nrt_q15 *)(void *)m;

    for (j = 0; j < nodes - n_in; j++)
        net->end[j] = 0;
    for (k = 0; k < n_conns; k++) {
        const uint8_t *c = blob + NRT_HEADER_SIZE + NRT_CONN_SIZE * k;
        net->weight[k] = (nrt_w12)nrt_rd16(c + 2);
        net->src[k] = c[0];
        net->end[c[1] - n_in] = (uint16_t)(k + 1);
    }
    /* a node with no incoming connection ends where the previous one did */
    for (j = 1; j < nodes - n_in; j++)
        if (net->end[j] < net->end[j - 1])
            net->end[j] = net->end[j - 1];
    nrt_reset(net);
    return NRT_OK;
}

#ifndef NRT_NO_STRERROR
const char *nrt_strerror(int err)
{
    switch (err) {
    case NRT_OK: return "ok";
    case NRT_E_ARG: return "invalid argument";
    case NRT_E_TRUNCATED: return "blob truncated";
    case NRT_E_MAGIC: return "not a champion blob (bad magic)";
    case NRT_E_VERSION: return "unknown blob format version";
    case NRT_E_HEADER: return "bad blob header (size, weight format, activation or reserved bytes)";
    case NRT_E_COUNTS: return "impossible node or connection counts";
    case NRT_E_CRC: return "checksum mismatch";
    case NRT_E_INDEX: return "connection refers to a node out of range or into an input";
    case NRT_E_ORDER: return "connections not sorted by target node";
    case NRT_E_NOMEM: return "buffer too small for this network";
    case NRT_E_TRAILING: return "bytes after the end of the blob";
    case NRT_E_WEIGHT: return "weight -32768 outside the symmetric Q3.12 range";
    default: return "unknown error";
    }
}
#endif
