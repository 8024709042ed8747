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
    size_t k = 0; /* size_t: k + 1 can fold into an address */

    /* The inputs are part of the state this step reads (already there when
     * the caller wrote them through nrt_inputs). */
    if (inputs != prev)
        memcpy(prev, inputs, 2u * net->n_inputs);
#if NRT_HAVE_AVX2
    /* the same sums eight connections a round, where the processor can */
    if (nrt_nodes_avx2(net, prev, next) == 0)
        non_in = 0;
#endif
    for (j = 0; j < non_in; j++) {
        /* Q3.12 x Q1.15 = Q27 products (< 2^30); 64 bits hold the sum of the
         * at most 65535 connections a blob can give one node (< 2^46). The
         * sum is exact, so the order and grouping of its terms are free:
         * NRT_PAIR chooses them for the processor. One index k runs
         * through both connection arrays, four connections a round. (Of
         * the tails tried, this one made every Cortex-M figure better;
         * docs/firmware.md.) */
        size_t e = end[j];
        int64_t sum = 0;
        for (; k + 4u <= e; k += 4u)
            sum += NRT_PAIR(w, src, prev, k) + NRT_PAIR(w, src, prev, k + 2u);
        sum = nrt_tail(sum, w, src, prev, k, e);
        k = e;
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
