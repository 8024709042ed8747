/* nrt_step.c - one fixed-point step of a network (sync or propagate, docs/runtime.md), and settling for feed-forward tasks. */
#include <string.h>

#include "nrt_internal.h"

/* Connections k and k + 1 of a node: their products w * a as one 64-bit
 * term. On a 64-bit processor each product is widened (a 64-bit multiply
 * costs what a 32-bit one does); elsewhere the pair is summed in 32 bits
 * first, which cannot overflow: |w| <= 32767 (the loader refuses -32768)
 * and |a| <= 32768 keep each product at most 2^30 - 2^15, so one widening
 * (on Armv6-M a sign extension and a 64-bit add) serves two connections.
 * Either way the sum of the node is the same exact integer. */
#if UINTPTR_MAX > 0xFFFFFFFFu
#define NRT_PAIR(w, src, a, k) \
    ((int64_t)(w)[k] * (a)[(src)[k]] + (int64_t)(w)[(k) + 1u] * (a)[(src)[(k) + 1u]])
#else
#define NRT_PAIR(w, src, a, k) \
    ((int64_t)((int32_t)(w)[k] * (a)[(src)[k]] + (int32_t)(w)[(k) + 1u] * (a)[(src)[(k) + 1u]]))
#endif

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

#ifndef NRT_NO_PROPAGATE
/* The propagate step: in place on the current activations, the nodes in
 * the loader's evaluation order, so a source evaluated earlier in this step
 * (or an input) gives its new value and any other (the node itself, a later
 * one) its previous one: the definition of docs/runtime.md, word for word.
 * Kept apart from the sync loop so that one stays what it was, and small
 * rather than fast (one connection a round, the sigmoid called, not
 * inlined): Cortex-M0+ flash is the scarce thing (docs/runtime.md, "Size
 * on Cortex-M0+"). */
#if defined(__GNUC__) || defined(__clang__)
/* apart, not inlined: inlined, it changed the sync step's registers and
 * stack frame, and cost it 70 instructions on Cortex-M0+ */
__attribute__((noinline))
#endif
static void nrt_step_propagate(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs)
{
    nrt_q15 *a = net->act[net->cur];
    const uint8_t *o = net->order, *oe = o + (net->n_nodes - net->n_inputs);
    const uint16_t *end = net->end;
    uint32_t n_in = net->n_inputs;

    if (inputs != a)
        memcpy(a, inputs, 2u * n_in);
    for (; o != oe; o++) {
        uint32_t t = *o - n_in; /* the node's run: end[t - 1] .. end[t] */
        uint32_t k = t ? end[t - 1u] : 0u, e = end[t];
        int64_t sum = 0;
        for (; k < e; k++)
            sum += (int32_t)net->weight[k] * a[net->src[k]];
        a[*o] = nrt_sigmoid(sum);
    }
    if (outputs != NULL)
        memcpy(outputs, a + n_in, 2u * net->n_outputs);
}
#endif

/* The sync step: one synchronous propagation. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline)) /* its own frame, the one it had before the modes */
#endif
static void nrt_step_sync(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs)
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
    for (j = 0; j < non_in; j++) {
        /* Q3.12 x Q1.15 = Q27 products (< 2^30); 64 bits hold the sum of the
         * at most 65535 connections a blob can give one node (< 2^46). The
         * sum is exact, so the order and grouping of its terms are free:
         * NRT_PAIR chooses them for the processor. One index k runs
         * through both connection arrays, four connections a round. (Of
         * the eleven tails tried, this one made every instruction count on
         * Cortex-M0+, M3 and RISC-V lower than before; docs/firmware.md.) */
        size_t e = end[j];
        int64_t sum = 0;
        for (; k + 4u <= e; k += 4u)
            sum += NRT_PAIR(w, src, prev, k) + NRT_PAIR(w, src, prev, k + 2u);
        if (k != e) { /* the last 1-3: a pair, a single, or both */
            size_t r = e - k;
            if (r & 2u) {
                sum += NRT_PAIR(w, src, prev, k);
                k += 2u;
            }
            if (r & 1u) {
                sum += (int32_t)w[k] * prev[src[k]];
                k += 1u;
            }
        }
        next[j] = nrt_sig_eval(sum);
    }
    net->cur ^= 1u;
    if (outputs != NULL)
        memcpy(outputs, next, 2u * net->n_outputs);
}

void nrt_step(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs)
{
#ifndef NRT_NO_PROPAGATE
    if (net->order != NULL) {
        nrt_step_propagate(net, inputs, outputs);
        return;
    }
#endif
    nrt_step_sync(net, inputs, outputs);
}

int nrt_settle(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs, int max_steps)
{
    int s;
    uint32_t j;
    for (s = 1; s <= max_steps; s++) {
#ifndef NRT_NO_PROPAGATE
        /* a propagate step works in place: the previous state, to compare
         * with, is copied aside first */
        if (net->order != NULL)
            memcpy(net->act[net->cur ^ 1u], net->act[net->cur], 2u * net->n_nodes);
#endif
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
