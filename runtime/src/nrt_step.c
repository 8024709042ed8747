/* nrt_step.c - one synchronous fixed-point propagation per time step, and settling for feed-forward tasks. */
#include <string.h>

#include "nrt_internal.h"

void nrt_reset(nrt_net *net)
{
    memset(net->act[0], 0, 2u * net->n_nodes);
    memset(net->act[1], 0, 2u * net->n_nodes);
    net->cur = 0;
}

nrt_q15 *nrt_inputs(nrt_net *net)
{
    return net->act[net->cur];
}

const nrt_q15 *nrt_outputs(const nrt_net *net)
{
    return net->act[net->cur] + net->n_inputs;
}

void nrt_step(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs)
{
    nrt_q15 *prev = net->act[net->cur];
    nrt_q15 *next = net->act[net->cur ^ 1u] + net->n_inputs;
    const nrt_w12 *w = net->weight;
    const uint16_t *src = net->src, *end = net->end;
    uint32_t j, non_in = (uint32_t)net->n_nodes - net->n_inputs;

    /* The inputs are part of the state this step reads (already there when
     * the caller wrote them through nrt_inputs). */
    if (inputs != prev)
        memcpy(prev, inputs, 2u * net->n_inputs);
    for (j = 0; j < non_in; j++) {
        /* Q3.12 x Q1.15 = Q27 products (< 2^30); 64 bits hold the sum of the
         * at most 65535 connections a blob can give one node (< 2^46). Two
         * products at a time in 32 bits: |w| <= 32767 (the loader refuses
         * -32768) and |a| <= 32768 keep each below 2^30 - 2^15, so a pair
         * cannot overflow. Four connections per round keeps the loop
         * overhead off the products. */
        int64_t sum = 0;
        const nrt_w12 *we = net->weight + end[j];
        for (; we - w >= 4; w += 4, src += 4) {
            int32_t p = (int32_t)w[0] * prev[src[0]] + (int32_t)w[1] * prev[src[1]];
            int32_t q = (int32_t)w[2] * prev[src[2]] + (int32_t)w[3] * prev[src[3]];
            sum += (int64_t)p + q;
        }
        for (; w < we; w++, src++)
            sum += (int32_t)w[0] * prev[src[0]];
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
