/* fuzz_blob.c - libFuzzer harness: any bytes through nrt_inspect, nrt_load, nrt_step and nrt_settle (sync and propagate blobs), and neat_genome_from_blob, must never crash; a propagate network's order is a permutation of its non-input nodes; a blob's genome writes back the same blob in the same step mode (in the writer's order: each node's connections by source). */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "neat.h"
#include "nrt.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* More than any valid blob needs (65535 connections, 256 nodes: about 198 KB). */
static uint8_t fuzz_mem[300000];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    nrt_net net;
    nrt_q15 inputs[NRT_MAX_NODES], outputs[NRT_MAX_NODES];
    size_t blob_size = 0, need = 0, off = size & 1u; /* odd buffer addresses too */
    uint32_t i;
    int err, s;

    err = nrt_inspect(data, size, &blob_size, &need);
    if (err == NRT_OK && need > sizeof fuzz_mem - 1)
        __builtin_trap(); /* nrt_inspect promised more memory than any blob can need */
    err = nrt_load(&net, data, size, fuzz_mem + off, sizeof fuzz_mem - off);
    {
        /* a start topology from a blob: refused exactly when the runtime refuses it */
        neat_genome g;
        int step = -1;
        int ge = neat_genome_from_blob_step(&g, data, size, NULL, &step);
        if ((ge == NEAT_OK) != (err == NRT_OK) || (ge != NEAT_OK && ge != NEAT_E_FORMAT))
            __builtin_trap();
        if (ge == NEAT_OK) {
            static uint8_t back[300000], again[300000];
            size_t blen = 0, alen = 0;
            uint32_t t, k, k0 = 0;
            int canonical = 1;
            /* the writer orders each node's connections by source; the runtime asks only for target order */
            for (t = 0; t < (uint32_t)net.n_outputs + net.n_hidden; k0 = net.end[t], t++)
                for (k = k0 + 1; k < net.end[t]; k++)
                    canonical &= net.src[k] >= net.src[k - 1];
            /* the same network written again, when the genome has the duel-like layout: the same blob when it
             * was in the writer's order, else a blob that reads back and writes again to itself */
            if (step != (net.step == NRT_STEP_PROPAGATE ? NEAT_STEP_PROPAGATE : NEAT_STEP_SYNC))
                __builtin_trap();
            if (neat_blob_write_step(&g, (uint32_t)net.n_inputs - 1u, net.n_outputs, step, back, sizeof back, &blen) ==
                NEAT_OK) {
                neat_genome g2;
                if (canonical && (blen != size || memcmp(back, data, size) != 0))
                    __builtin_trap();
                if (neat_genome_from_blob(&g2, back, blen, NULL) != NEAT_OK)
                    __builtin_trap();
                if (neat_blob_write_step(&g2, (uint32_t)net.n_inputs - 1u, net.n_outputs, step, again, sizeof again,
                                         &alen) != NEAT_OK || alen != blen || memcmp(again, back, blen) != 0)
                    __builtin_trap();
                neat_genome_free(&g2, NULL);
            }
            neat_genome_free(&g, NULL);
        }
    }
    if (err != NRT_OK) {
        if (err < NRT_E_WEIGHT || err > NRT_E_ARG || nrt_strerror(err)[0] == '\0')
            __builtin_trap();
        return 0;
    }
    if (blob_size != size || net.n_inputs > NRT_MAX_NODES || net.n_outputs > NRT_MAX_NODES)
        __builtin_trap();
    if ((net.order != NULL) != (net.step == NRT_STEP_PROPAGATE))
        __builtin_trap();
    if (net.order != NULL) { /* every non-input node exactly once, inside the memory nrt_inspect asked for */
        static uint8_t seen[NRT_MAX_NODES];
        memset(seen, 0, sizeof seen);
        if (net.order < fuzz_mem + off || net.order + (net.n_nodes - net.n_inputs) > fuzz_mem + off + need)
            __builtin_trap();
        for (i = 0; i < (uint32_t)net.n_nodes - net.n_inputs; i++)
            if (net.order[i] < net.n_inputs || net.order[i] >= net.n_nodes || seen[net.order[i]]++)
                __builtin_trap();
    }

    for (i = 0; i < net.n_inputs; i++)
        inputs[i] = (nrt_q15)(i == 0 ? NRT_ONE : (int32_t)(i * 7919u % 65536u) - 32768);
    nrt_reset(&net);
    for (s = 0; s < 10; s++)
        nrt_step(&net, inputs, (s & 1) ? outputs : NULL);
    for (i = 0; i < net.n_outputs; i++)
        if (outputs[i] < 0)
            __builtin_trap(); /* a sigmoid is never negative */
    (void)nrt_settle(&net, inputs, outputs, 0);
    (void)nrt_settle(&net, inputs, outputs, 1);
    (void)nrt_settle(&net, inputs, NULL, 5);
    memset(inputs, 0, sizeof inputs);
    s = nrt_settle(&net, inputs, outputs, 300);
    if (s < -1 || s == 0 || s > 300)
        __builtin_trap();
    return 0;
}
