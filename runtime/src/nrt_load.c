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

#ifndef __OPTIMIZE_SIZE__
/* nrt_crc32_table[n] = the CRC register after the 8 bitwise steps from n
 * (tests/runtime/test_loader.c compares the two ways on random data). */
static const uint32_t nrt_crc32_table[256] = {
    0x00000000u, 0x77073096u, 0xEE0E612Cu, 0x990951BAu, 0x076DC419u, 0x706AF48Fu,
    0xE963A535u, 0x9E6495A3u, 0x0EDB8832u, 0x79DCB8A4u, 0xE0D5E91Eu, 0x97D2D988u,
    0x09B64C2Bu, 0x7EB17CBDu, 0xE7B82D07u, 0x90BF1D91u, 0x1DB71064u, 0x6AB020F2u,
    0xF3B97148u, 0x84BE41DEu, 0x1ADAD47Du, 0x6DDDE4EBu, 0xF4D4B551u, 0x83D385C7u,
    0x136C9856u, 0x646BA8C0u, 0xFD62F97Au, 0x8A65C9ECu, 0x14015C4Fu, 0x63066CD9u,
    0xFA0F3D63u, 0x8D080DF5u, 0x3B6E20C8u, 0x4C69105Eu, 0xD56041E4u, 0xA2677172u,
    0x3C03E4D1u, 0x4B04D447u, 0xD20D85FDu, 0xA50AB56Bu, 0x35B5A8FAu, 0x42B2986Cu,
    0xDBBBC9D6u, 0xACBCF940u, 0x32D86CE3u, 0x45DF5C75u, 0xDCD60DCFu, 0xABD13D59u,
    0x26D930ACu, 0x51DE003Au, 0xC8D75180u, 0xBFD06116u, 0x21B4F4B5u, 0x56B3C423u,
    0xCFBA9599u, 0xB8BDA50Fu, 0x2802B89Eu, 0x5F058808u, 0xC60CD9B2u, 0xB10BE924u,
    0x2F6F7C87u, 0x58684C11u, 0xC1611DABu, 0xB6662D3Du, 0x76DC4190u, 0x01DB7106u,
    0x98D220BCu, 0xEFD5102Au, 0x71B18589u, 0x06B6B51Fu, 0x9FBFE4A5u, 0xE8B8D433u,
    0x7807C9A2u, 0x0F00F934u, 0x9609A88Eu, 0xE10E9818u, 0x7F6A0DBBu, 0x086D3D2Du,
    0x91646C97u, 0xE6635C01u, 0x6B6B51F4u, 0x1C6C6162u, 0x856530D8u, 0xF262004Eu,
    0x6C0695EDu, 0x1B01A57Bu, 0x8208F4C1u, 0xF50FC457u, 0x65B0D9C6u, 0x12B7E950u,
    0x8BBEB8EAu, 0xFCB9887Cu, 0x62DD1DDFu, 0x15DA2D49u, 0x8CD37CF3u, 0xFBD44C65u,
    0x4DB26158u, 0x3AB551CEu, 0xA3BC0074u, 0xD4BB30E2u, 0x4ADFA541u, 0x3DD895D7u,
    0xA4D1C46Du, 0xD3D6F4FBu, 0x4369E96Au, 0x346ED9FCu, 0xAD678846u, 0xDA60B8D0u,
    0x44042D73u, 0x33031DE5u, 0xAA0A4C5Fu, 0xDD0D7CC9u, 0x5005713Cu, 0x270241AAu,
    0xBE0B1010u, 0xC90C2086u, 0x5768B525u, 0x206F85B3u, 0xB966D409u, 0xCE61E49Fu,
    0x5EDEF90Eu, 0x29D9C998u, 0xB0D09822u, 0xC7D7A8B4u, 0x59B33D17u, 0x2EB40D81u,
    0xB7BD5C3Bu, 0xC0BA6CADu, 0xEDB88320u, 0x9ABFB3B6u, 0x03B6E20Cu, 0x74B1D29Au,
    0xEAD54739u, 0x9DD277AFu, 0x04DB2615u, 0x73DC1683u, 0xE3630B12u, 0x94643B84u,
    0x0D6D6A3Eu, 0x7A6A5AA8u, 0xE40ECF0Bu, 0x9309FF9Du, 0x0A00AE27u, 0x7D079EB1u,
    0xF00F9344u, 0x8708A3D2u, 0x1E01F268u, 0x6906C2FEu, 0xF762575Du, 0x806567CBu,
    0x196C3671u, 0x6E6B06E7u, 0xFED41B76u, 0x89D32BE0u, 0x10DA7A5Au, 0x67DD4ACCu,
    0xF9B9DF6Fu, 0x8EBEEFF9u, 0x17B7BE43u, 0x60B08ED5u, 0xD6D6A3E8u, 0xA1D1937Eu,
    0x38D8C2C4u, 0x4FDFF252u, 0xD1BB67F1u, 0xA6BC5767u, 0x3FB506DDu, 0x48B2364Bu,
    0xD80D2BDAu, 0xAF0A1B4Cu, 0x36034AF6u, 0x41047A60u, 0xDF60EFC3u, 0xA867DF55u,
    0x316E8EEFu, 0x4669BE79u, 0xCB61B38Cu, 0xBC66831Au, 0x256FD2A0u, 0x5268E236u,
    0xCC0C7795u, 0xBB0B4703u, 0x220216B9u, 0x5505262Fu, 0xC5BA3BBEu, 0xB2BD0B28u,
    0x2BB45A92u, 0x5CB36A04u, 0xC2D7FFA7u, 0xB5D0CF31u, 0x2CD99E8Bu, 0x5BDEAE1Du,
    0x9B64C2B0u, 0xEC63F226u, 0x756AA39Cu, 0x026D930Au, 0x9C0906A9u, 0xEB0E363Fu,
    0x72076785u, 0x05005713u, 0x95BF4A82u, 0xE2B87A14u, 0x7BB12BAEu, 0x0CB61B38u,
    0x92D28E9Bu, 0xE5D5BE0Du, 0x7CDCEFB7u, 0x0BDBDF21u, 0x86D3D2D4u, 0xF1D4E242u,
    0x68DDB3F8u, 0x1FDA836Eu, 0x81BE16CDu, 0xF6B9265Bu, 0x6FB077E1u, 0x18B74777u,
    0x88085AE6u, 0xFF0F6A70u, 0x66063BCAu, 0x11010B5Cu, 0x8F659EFFu, 0xF862AE69u,
    0x616BFFD3u, 0x166CCF45u, 0xA00AE278u, 0xD70DD2EEu, 0x4E048354u, 0x3903B3C2u,
    0xA7672661u, 0xD06016F7u, 0x4969474Du, 0x3E6E77DBu, 0xAED16A4Au, 0xD9D65ADCu,
    0x40DF0B66u, 0x37D83BF0u, 0xA9BCAE53u, 0xDEBB9EC5u, 0x47B2CF7Fu, 0x30B5FFE9u,
    0xBDBDF21Cu, 0xCABAC28Au, 0x53B39330u, 0x24B4A3A6u, 0xBAD03605u, 0xCDD70693u,
    0x54DE5729u, 0x23D967BFu, 0xB3667A2Eu, 0xC4614AB8u, 0x5D681B02u, 0x2A6F2B94u,
    0xB40BBE37u, 0xC30C8EA1u, 0x5A05DF1Bu, 0x2D02EF8Du,
};
#endif

uint32_t nrt_crc32(uint32_t crc, const void *data, size_t len)
{
    const uint8_t *p = (const uint8_t *)data;
    size_t i;
    crc = ~crc;
#ifdef __OPTIMIZE_SIZE__
    /* Bitwise, no table at -Os (the firmware): it runs once per load and a
     * table would cost 1 KiB of flash. */
    for (i = 0; i < len; i++) {
        int b;
        crc ^= p[i];
        for (b = 0; b < 8; b++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
#else
    /* A byte a lookup on hosts, where checkpoints of megabytes are
     * checksummed every generation (the bitwise loop was 3-5 % of a
     * paper-scale generation) */
    for (i = 0; i < len; i++)
        crc = (crc >> 8) ^ nrt_crc32_table[(crc ^ p[i]) & 0xFFu];
#endif
    return ~crc;
}

/* Memory nrt_load lays out, all 16-bit arrays: weights and sources of the
 * connections, ends of each node's run, two activation arrays; +1 to align
 * a buffer of any address. A propagate network adds its evaluation order,
 * a byte a non-input node, after them (so a sync network's layout, and its
 * size, are what they were before the mode existed). */
static size_t nrt_mem_for(uint32_t nodes, uint32_t non_inputs, uint32_t conns, uint32_t step)
{
    return 4u * conns + 2u * non_inputs + 4u * nodes + 1u + (step == NRT_STEP_PROPAGATE ? non_inputs : 0u);
}

int nrt_inspect(const uint8_t *blob, size_t len, size_t *blob_size, size_t *mem_required)
{
    uint32_t n_in, n_out, n_hid, n_conns, nodes, total, version, step;
    if (blob == NULL)
        return NRT_E_ARG;
    if (len < NRT_HEADER_SIZE)
        return NRT_E_TRUNCATED;
    if (blob[0] != NRT_MAGIC0 || blob[1] != NRT_MAGIC1 || blob[2] != NRT_MAGIC2 || blob[3] != NRT_MAGIC3)
        return NRT_E_MAGIC;
    version = nrt_rd16(blob + NRT_OFF_VERSION);
#ifdef NRT_NO_PROPAGATE
    /* a sync-only runtime: a propagate blob is a version it does not know */
    if (version != NRT_FORMAT_VERSION)
        return NRT_E_VERSION;
#else
    if (version != NRT_FORMAT_VERSION && version != NRT_FORMAT_VERSION_PROPAGATE)
        return NRT_E_VERSION;
#endif
    if (nrt_rd16(blob + NRT_OFF_HEADER_SIZE) != NRT_HEADER_SIZE || blob[NRT_OFF_WEIGHT_BITS] != NRT_WEIGHT_FRAC_BITS ||
        blob[NRT_OFF_ACTIVATION] != NRT_ACT_SIGMOID49)
        return NRT_E_HEADER;
    /* Version 1 is sync with the step byte zero; version 2 must name
     * propagate: one encoding per network, and no version-2 blob a
     * version-1 loader could mistake for sync. */
    step = blob[NRT_OFF_STEP];
    if (step != (version == NRT_FORMAT_VERSION ? NRT_STEP_SYNC : NRT_STEP_PROPAGATE))
        return NRT_E_HEADER;
    {
        int i;
        for (i = NRT_OFF_STEP + 1; i < NRT_OFF_CRC; i++)
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
        *mem_required = nrt_mem_for(nodes, n_out + n_hid, n_conns, step);
    return NRT_OK;
}

int nrt_mem_required(const uint8_t *blob, size_t len, size_t *mem_required)
{
    return nrt_inspect(blob, len, NULL, mem_required);
}

#ifndef NRT_NO_PROPAGATE
/* A propagate network's evaluation order into net->order. Computed here
 * rather than stored in the blob: the order is a function of the
 * connections, so a blob cannot carry one that disagrees with them, a
 * version-2 blob is a version-1 blob with the step byte set, and there is
 * nothing more to check. The rule (docs/runtime.md, "Semantics"): place,
 * one at a time, the lowest-index unplaced node all of whose sources other
 * than itself are inputs or placed; when none is (only cycles remain), the
 * lowest-index unplaced node. At most N rounds of N + C checks (202
 * connections and 27 non-input nodes: under 6,200). src and end are laid
 * out (target order); act[0], which nrt_reset zeroes next, holds the
 * placed flags meanwhile. */
static void nrt_order(nrt_net *net)
{
    uint32_t n_in = net->n_inputs, non_in = (uint32_t)net->n_nodes - n_in, p, t, k;
    uint16_t *placed = (uint16_t *)(void *)net->act[0];

    for (t = 0; t < net->n_nodes; t++)
        placed[t] = (uint16_t)(t < n_in);
    for (p = 0; p < non_in; p++) {
        uint32_t pick = non_in, first = non_in;
        for (t = 0; t < non_in; t++) {
            if (placed[n_in + t])
                continue;
            if (first == non_in)
                first = t;
            for (k = t ? net->end[t - 1u] : 0u; k < net->end[t]; k++)
                if (net->src[k] != n_in + t && !placed[net->src[k]])
                    break;
            if (k == net->end[t]) {
                pick = t;
                break;
            }
        }
        if (pick == non_in)
            pick = first; /* only cycles left: its unplaced sources read the previous step */
        net->order[p] = (uint8_t)(n_in + pick);
        placed[n_in + pick] = 1;
    }
}
#endif

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
#ifndef NRT_NO_PROPAGATE
    net->step = blob[NRT_OFF_STEP];
    if (net->step == NRT_STEP_PROPAGATE) {
        net->order = (uint8_t *)(net->act[1] + nodes);
        nrt_order(net);
    }
#endif
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
