/* nrt_step.c - one synchronous fixed-point propagation per time step, and settling for feed-forward tasks. */
#include <string.h>

#include "nrt_internal.h"

void nrt_reset(nrt_net *net)
{
    memset(net->act[0], 0, 2u * net->n_nodes);
    memset(net->act[1], 0, 2u * net->n_nodes);
    net->cur = 0;
}

void nrt_step(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs)
{
    nrt_q15 *prev = net->act[net->cur];
    nrt_q15 *next = net->act[net->cur ^ 1u] + net->n_inputs;
    const nrt_w12 *w = net->weight;
    const uint16_t *src = net->src, *end = net->end;
    uint32_t j, k = 0, non_in = (uint32_t)net->n_nodes - net->n_inputs;

    /* The inputs are part of the state this step reads. */
    memcpy(prev, inputs, 2u * net->n_inputs);
    for (j = 0; j < non_in; j++) {
        /* Q3.12 x Q1.15 = Q27 products (< 2^30); 64 bits hold the sum of the
         * at most 65535 connections a blob can give one node (< 2^46). Two
         * products at a time in 32 bits: |w| <= 32767 (the loader refuses
         * -32768) and |a| <= 32768 keep each below 2^30 - 2^15, so a pair
         * cannot overflow. */
        int64_t sum = 0;
        uint32_t e = end[j];
        for (; k + 1 < e; k += 2)
            sum += (int32_t)w[k] * prev[src[k]] + (int32_t)w[k + 1] * prev[src[k + 1]];
        if (k < e) {
            sum += (int32_t)w[k] * prev[src[k]];
            k++;
        }
        next[j] = nrt_sig_eval(sum);
    }
    net->cur ^= 1u;
    if (outputs != NULL)
        memcpy(outputs, next, 2u * net->n_outputs);
}

int nrt_settle(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs, int max_steps)
{
    int s;
    uint32_t j;
    for (s = 1; s <= max_steps; s++) {
        nrt_step(net, inputs, outputs);
        /* a loop, not memcmp: the runtime needs nothing but memcpy/memset */
        for (j = net->n_inputs; j < net->n_nodes; j++)
            if (net->act[0][j] != net->act[1][j])
                break;
        if (j == net->n_nodes)
            return s;
    }
    return -1;
}
