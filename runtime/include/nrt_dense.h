/* nrt_dense.h - a faster nrt_step for small networks on x86-64 hosts: the weights as a dense matrix, stepped with AVX2. */
#ifndef NRT_DENSE_H
#define NRT_DENSE_H

/*
 * One more implementation of nrt_step (nrt.h), for hosts only: the node
 * sums as a matrix-vector product, 16 connections per vpmaddwd, instead of
 * one connection list walked an entry at a time. The step is the same
 * synchronous propagation and every sum the same exact integer, so the
 * activations are identical to nrt_step's (tests/runtime/test_dense.c
 * compares them on random networks). A network qualifies when it has at most
 * NRT_DENSE_MAX_NODES nodes, no two connections with the same source and
 * target, and the dense product is estimated to cost less than the list
 * (it skips the 8 x 16 tiles of the matrix that hold no connection);
 * a processor without AVX2, or a build for anything but x86-64 (or with
 * NRT_NO_AVX2 defined), has no dense step and nrt_dense_make says so.
 */

#include "nrt.h"

/* C++ callers link against the C symbols */
#ifdef __cplusplus
extern "C" {
#endif

#define NRT_DENSE_MAX_NODES 64 /* columns: every node, in blocks of 16 */
#define NRT_DENSE_NARROW_L1 65535 /* times 32768, below 2^31 */

typedef struct nrt_dense {
    /* row j (node n_inputs + j): the weight from each node, 0 where there is
     * no connection, blocks * 16 entries a row; rows in groups of eight */
    nrt_w12 w[NRT_DENSE_MAX_NODES * NRT_DENSE_MAX_NODES];
    /* the network's state while the dense form steps it: nrt_net's two
     * activation buffers, padded to whole blocks so that a block loads
     * straight from them (and with room for a last group of eight rows) */
    nrt_q15 act[2][NRT_DENSE_MAX_NODES + 16];
    /* tiles[g]: bit b set when the tile of rows 8g..8g+7 and columns
     * 16b..16b+15 has a weight that is not 0 (the step skips the others) */
    uint8_t tiles[NRT_DENSE_MAX_NODES / 8];
    /* narrow: bit g set when every row of group g has weights of at most
     * NRT_DENSE_NARROW_L1 in absolute sum, so that its sums fit 32 bits
     * whatever the activations (the step adds them up directly) */
    uint8_t narrow;
    uint16_t rows;   /* outputs + hidden */
    uint16_t blocks; /* ceil(n_nodes / 16) */
    uint16_t n_inputs, n_nodes;
    uint8_t cur;     /* act[cur]: the current activations */
} nrt_dense;

/* The dense form of a loaded network into d, with a copy of its state (its
 * activations): NRT_OK, or NRT_E_ARG when the network does not qualify or
 * there is no dense step here (then step it with nrt_step). From then on
 * the state lives in d: write the inputs through nrt_dense_inputs, read the
 * outputs at nrt_dense_outputs, and nrt_dense_save puts the state back into
 * the network. d stays valid while net's weights do. */
NRT_API int nrt_dense_make(nrt_dense *d, const nrt_net *net);

/* The input slots of the current activations (nrt_inputs for d's state). */
static inline nrt_q15 *nrt_dense_inputs(nrt_dense *d)
{
    return d->act[d->cur];
}

/* The outputs of the last step (nrt_outputs for d's state). */
static inline const nrt_q15 *nrt_dense_outputs(const nrt_dense *d)
{
    return d->act[d->cur] + d->n_inputs;
}

/* One step of d's state, exactly nrt_step(net, nrt_inputs(net), NULL) for
 * the network d was made from in that state. */
NRT_API void nrt_dense_step(nrt_dense *d);

/* Up to this many rows (outputs + hidden) a network's sums take one
 * reduction, and two such networks share nrt_dense_step2's sigmoid pass. */
#define NRT_DENSE_FEW 4

/* Two networks' steps at once, exactly nrt_dense_step(d0) then
 * nrt_dense_step(d1) (two different forms): faster when both have at most
 * NRT_DENSE_FEW rows, their sigmoids one pass of eight; otherwise the same
 * as the two calls. */
NRT_API void nrt_dense_step2(nrt_dense *d0, nrt_dense *d1);

/* d's state into net (the network d was made from): net then holds what
 * nrt_step would have left in it. */
NRT_API void nrt_dense_save(const nrt_dense *d, nrt_net *net);

#ifdef __cplusplus
}
#endif

#endif /* NRT_DENSE_H */
