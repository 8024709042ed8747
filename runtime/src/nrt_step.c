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
    nrt_q15 *next = net->act[net->cur ^ 1u];
    const uint8_t *src = net->src;
    const nrt_w12 *w = net->weight;
    uint32_t n_in = net->n_inputs, non_in = (uint32_t)net->n_nodes - n_in;
    uint32_t j, k = 0;

    /* The inputs are part of the state this step reads. */
    memcpy(prev, inputs, 2u * n_in);
    for (j = 0; j < non_in; j++) {
        /* Q3.12 x Q1.15 = Q27 products (< 2^30); 64 bits hold the sum of the
         * at most 65535 connections a blob can give one node (< 2^46). */
        int64_t sum = 0;
        uint32_t e = net->end[j];
        for (; k < e; k++)
            sum += (int32_t)w[k] * prev[src[k]];
        next[n_in + j] = nrt_sig_eval(sum);
    }
    net->cur ^= 1u;
    if (outputs != NULL)
        memcpy(outputs, next + n_in, 2u * net->n_outputs);
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
