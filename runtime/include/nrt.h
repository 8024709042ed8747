/* nrt.h - the controller runtime: loads a champion blob into caller memory and steps it in fixed point. */
#ifndef NRT_H
#define NRT_H

/*
 * The runtime never allocates, never uses floating point and needs nothing
 * from libc but memcpy and memset, so it links into bare-metal firmware.
 * Every function returns 0 or a negative nrt_error; bad bytes are a code,
 * never a crash or an out-of-bounds read.
 *
 * Usage:
 *     size_t need;
 *     nrt_mem_required(blob, blob_len, &need);      // reads the header only
 *     nrt_load(&net, blob, blob_len, buf, buf_len); // validates everything
 *     nrt_reset(&net);                              // all activations 0
 *     nrt_step(&net, inputs, outputs);              // once per time step
 *
 * The blob format is byte-by-byte in docs/formats.md; the fixed-point
 * formats and the sigmoid's error bound are in docs/runtime.md.
 */

#include <stddef.h>
#include <stdint.h>

#include "neat_duel_version.h"

/* C++ callers link against the C symbols */
#ifdef __cplusplus
extern "C" {
#endif

/* ---- versions ---------------------------------------------------------- */
/* the library's version: the project's (neat_duel_version.h) */
#define NRT_VERSION_MAJOR NEAT_DUEL_VERSION_MAJOR
#define NRT_VERSION_MINOR NEAT_DUEL_VERSION_MINOR
#define NRT_FORMAT_VERSION 1 /* blob format version: the bytes (of a sync network) */
/* a propagate network's blob: version 1's bytes with the step byte set
 * (a version-1 loader refuses it rather than run it synchronously) */
#define NRT_FORMAT_VERSION_PROPAGATE 2

/* the export attribute of the shared libraries (empty in static and firmware builds) */
#ifndef NRT_API
#define NRT_API NEAT_DUEL_EXPORT
#endif

/* ---- fixed-point types ------------------------------------------------- */
/* Activations, inputs and outputs: Q1.15, 32767 = 1.0 - 2^-15. */
typedef int16_t nrt_q15;
/* Weights: Q3.12 (range [-8, 8), step 2^-12). */
typedef int16_t nrt_w12;
#define NRT_ONE ((nrt_q15)32767)   /* the closest Q1.15 value to 1.0 */
#define NRT_WEIGHT_FRAC_BITS 12
#define NRT_WEIGHT_MAX 32767
#define NRT_WEIGHT_MIN (-32767) /* symmetric: -32768 is refused, so two products fit 32 bits */

/* ---- blob layout (little endian, read byte by byte) -------------------- */
#define NRT_MAGIC0 'N'
#define NRT_MAGIC1 'R'
#define NRT_MAGIC2 'T'
#define NRT_MAGIC3 'B'
#define NRT_HEADER_SIZE 32u
#define NRT_CONN_SIZE 4u
#define NRT_MAX_NODES 256u /* node indices are one byte */
#define NRT_ACT_SIGMOID49 0 /* 1 / (1 + exp(-4.9 x)) */

/* Offsets of the header fields (see docs/formats.md). */
#define NRT_OFF_MAGIC 0
#define NRT_OFF_VERSION 4
#define NRT_OFF_HEADER_SIZE 6
#define NRT_OFF_INPUTS 8
#define NRT_OFF_OUTPUTS 10
#define NRT_OFF_HIDDEN 12
#define NRT_OFF_CONNS 14
#define NRT_OFF_TOTAL_SIZE 16
#define NRT_OFF_WEIGHT_BITS 20
#define NRT_OFF_ACTIVATION 21
#define NRT_OFF_RESERVED 22 /* 6 bytes, zero in version 1 */
#define NRT_OFF_STEP 22     /* version 2: the step mode (NRT_STEP_PROPAGATE); 23..27 zero */

/* How nrt_step evaluates a network (docs/runtime.md, "Semantics"). */
enum nrt_step_mode {
    NRT_STEP_SYNC = 0,     /* every node from the previous step's activations (version 1 blobs) */
    NRT_STEP_PROPAGATE = 1 /* nodes in place in evaluation order: sources already evaluated give this step's value */
};
#define NRT_OFF_CRC 28

/* ---- errors ------------------------------------------------------------- */
enum nrt_error {
    NRT_OK = 0,
    NRT_E_ARG = -1,      /* NULL pointer or impossible argument */
    NRT_E_TRUNCATED = -2, /* fewer bytes than the header says */
    NRT_E_MAGIC = -3,    /* not a blob */
    NRT_E_VERSION = -4,  /* a format version this runtime does not know */
    NRT_E_HEADER = -5,   /* header size, weight format, activation or step mode unknown, reserved not zero */
    NRT_E_COUNTS = -6,   /* node or connection counts impossible */
    NRT_E_CRC = -7,      /* checksum mismatch */
    NRT_E_INDEX = -8,    /* a connection names a node out of range, or into an input */
    NRT_E_ORDER = -9,    /* connections not sorted by target */
    NRT_E_NOMEM = -10,   /* the caller's buffer is too small */
    NRT_E_TRAILING = -11, /* more bytes than the header says */
    NRT_E_WEIGHT = -12    /* a weight of -32768 (outside the symmetric Q3.12 range) */
};

/* ---- state --------------------------------------------------------------
 * Fully defined so a caller can place it statically. All pointers point
 * into the caller's buffer given to nrt_load; the blob itself is not kept.
 */
typedef struct nrt_net {
    uint16_t n_inputs;  /* input 0 is the bias: callers supply NRT_ONE */
    uint16_t n_outputs;
    uint16_t n_hidden;
    uint16_t n_nodes;   /* inputs + outputs + hidden */
    uint16_t n_conns;
    uint16_t cur;       /* which of act[0], act[1] holds the current step (sync; propagate keeps it) */
    nrt_w12 *weight;    /* [n_conns] */
    uint16_t *src;      /* [n_conns] source node of each connection */
    uint16_t *end;      /* [n_outputs + n_hidden] one past the last connection into each node */
    nrt_q15 *act[2];    /* [n_nodes] activations of the previous and next step */
    /* NRT_STEP_PROPAGATE only (NULL in sync): order[p] is the node index
     * evaluated p-th (docs/runtime.md, "Semantics"); a propagate step works
     * in place on act[cur], which it does not swap. */
    uint8_t *order;     /* [n_outputs + n_hidden] */
    uint16_t step;      /* enum nrt_step_mode, from the blob */
} nrt_net;

/* ---- functions ---------------------------------------------------------- */

/* CRC-32 (IEEE 802.3, reflected, as zlib) of len bytes, continuing from crc
 * (start with 0). */
NRT_API uint32_t nrt_crc32(uint32_t crc, const void *data, size_t len);

/* From the first NRT_HEADER_SIZE bytes: the blob's total size and the bytes of
 * memory nrt_load will need. Checks magic, version and counts, not the CRC.
 * Either output pointer may be NULL. Returns 0 or a negative nrt_error. */
NRT_API int nrt_inspect(const uint8_t *blob, size_t len, size_t *blob_size, size_t *mem_required);

/* Same as nrt_inspect, memory only. */
NRT_API int nrt_mem_required(const uint8_t *blob, size_t len, size_t *mem_required);

/* Validates the whole blob (size, magic, version, header, counts, CRC,
 * indices, order) and, only then, lays the network out in mem (any
 * alignment; mem_len >= nrt_mem_required); a propagate network's
 * evaluation order is computed here (docs/runtime.md). The network starts reset.
 * Returns 0 or a negative nrt_error; on error net is zeroed. */
NRT_API int nrt_load(nrt_net *net, const uint8_t *blob, size_t len, void *mem, size_t mem_len);

/* All hidden and output activations back to 0 (start of a game). */
NRT_API void nrt_reset(nrt_net *net);

/* One step in the blob's mode. NRT_STEP_SYNC: one synchronous propagation,
 * every non-input node's new activation from the previous step's activations
 * (the inputs being those given now). NRT_STEP_PROPAGATE: the nodes in
 * evaluation order, each from this step's value of a source evaluated
 * before it (or an input) and the previous step's of any other (itself, a
 * later node): a feed-forward path reaches the outputs within the step.
 * inputs has n_inputs values, outputs receives n_outputs values (may be NULL). */
NRT_API void nrt_step(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs);

/* The n_inputs slots the next nrt_step reads its inputs from: a caller may
 * write the sensor values here and pass this pointer to nrt_step as inputs,
 * sparing the copy (valid until that step). */
NRT_API nrt_q15 *nrt_inputs(nrt_net *net);

/* The n_outputs values the last nrt_step produced, in place (valid until
 * the next step): the alternative to copying them out. */
NRT_API const nrt_q15 *nrt_outputs(const nrt_net *net);

/* For feed-forward tasks: steps with the same inputs until no activation
 * changes, at most max_steps times. Returns the number of steps taken, or
 * -1 if the network was still changing after max_steps (outputs then hold
 * the last step's values). */
NRT_API int nrt_settle(nrt_net *net, const nrt_q15 *inputs, nrt_q15 *outputs, int max_steps);

/* The fixed-point sigmoid: Q1.15 of 1/(1+exp(-4.9 x)) for x = sum / 2^27. */
NRT_API nrt_q15 nrt_sigmoid(int64_t sum);

#ifndef NRT_NO_STRERROR
/* A short English description of an nrt_error (host builds only). */
NRT_API const char *nrt_strerror(int err);
#endif

#ifdef __cplusplus
}
#endif

#endif /* NRT_H */
