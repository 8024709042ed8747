/* neat_phenotype.h - genome -> blob -> runtime network in one call: what evolution evaluates is what would be flashed. */
#ifndef NEAT_PHENOTYPE_H
#define NEAT_PHENOTYPE_H

/*
 * Evaluating a genome for your own task:
 *
 *     neat_phenotype ph;
 *     neat_phenotype_init(&ph, NULL);               // NULL: libc's realloc/free
 *     neat_phenotype_load(&ph, genome, &params);    // encode + validate + lay out
 *     nrt_reset(&ph.net);                           // before every trial
 *     nrt_q15 *in = nrt_inputs(&ph.net);            // n_inputs + 1 slots
 *     in[0] = NRT_ONE;                              // the bias, always NRT_ONE
 *     in[1] = neat_q15(x1); in[2] = neat_q15(x2);   // the task's inputs
 *     nrt_settle(&ph.net, in, out, 20);             // feed-forward tasks
 *     // or nrt_step(&ph.net, in, out) once per time step (control tasks)
 *     y = neat_from_q15(out[0]);
 *     neat_phenotype_free(&ph);
 *
 * What a caller must know:
 * - Inputs: the network has params.n_inputs + 1 inputs. Input 0 is the bias
 *   and must be NRT_ONE on every step; the task's inputs are 1 ..
 *   n_inputs. (ph.net.n_inputs counts the bias; params.n_inputs does not.)
 * - Values are Q1.15 fixed point (nrt_q15: 32767 = 1.0 - 2^-15, -32768 =
 *   -1.0). neat_q15 converts a double, rounding to nearest and saturating
 *   to [-1, 1); neat_from_q15 converts back. Scale a task's inputs into
 *   [-1, 1) yourself.
 * - Outputs are the sigmoid 1 / (1 + exp(-4.9 x)) of each output node's
 *   weighted sum, in [0, 1) (Q1.15 0 .. 32767); outputs n_outputs values.
 * - Weights: the genome's double weights are rounded to the nearest Q3.12
 *   (step 2^-12) and saturate to [-8 + 2^-12, 8 - 2^-12]; neat_params_check
 *   refuses weight_max above 8 for that reason. The network is the
 *   genome's enabled connections only.
 * - Time: with p->net_step NEAT_STEP_SYNC (the default) nrt_step is one
 *   synchronous step (every node reads the previous step's activations), so
 *   a signal needs one step per layer to reach an output; with
 *   NEAT_STEP_PROPAGATE the nodes are evaluated in order within the step,
 *   so it reaches the outputs at once and only cycles read the previous
 *   step (docs/runtime.md). The blob records the mode. A feed-forward task
 *   calls nrt_settle (steps until nothing changes); a recurrent or control
 *   task calls nrt_step once per time step.
 *   nrt_reset zeroes all activations: call it between trials, or the last
 *   trial's state leaks into the next. It zeroes the input slots too, so
 *   write the inputs through nrt_inputs after it, not before.
 * - ph.blob / ph.blob_len hold the network's champion blob (docs/formats.md)
 *   after a load: write them to a file and the runtime loads exactly this
 *   network on a microcontroller.
 * - One neat_phenotype per evaluating thread; loading reuses its buffers.
 */

#include "neat.h"
#include "nrt.h"

/* C++ callers link against the C symbols */
#ifdef __cplusplus
extern "C" {
#endif

/* Reusable buffers for one evaluating thread. */
typedef struct neat_phenotype {
    uint8_t *blob;      /* the last loaded network's blob */
    size_t blob_cap, blob_len;
    void *mem;          /* the runtime's memory for net */
    size_t mem_cap;
    nrt_net net;        /* the network: nrt_step / nrt_settle / nrt_reset it */
    neat_alloc alloc;   /* the allocator given to neat_phenotype_init */
} neat_phenotype;

/* Empty buffers; every allocation goes through a (NULL: libc). */
NEAT_API void neat_phenotype_init(neat_phenotype *ph, const neat_alloc *a);
/* Releases the buffers; ph may be initialised again. */
NEAT_API void neat_phenotype_free(neat_phenotype *ph);
/* Encodes g as a blob for a task of p->n_inputs inputs and p->n_outputs
 * outputs, stepping in p->net_step, and loads it into ph->net (reset). Returns 0, a negative
 * neat_error from the encoder (NEAT_E_TOOBIG, NEAT_E_NOMEM), or a negative
 * nrt_error - 100. */
NEAT_API int neat_phenotype_load(neat_phenotype *ph, const neat_genome *g, const neat_params *p);
/* A blob (neat_phenotype_load's, read from a file or sent by another
 * process) copied and loaded: the same network. 0, NEAT_E_NOMEM, or a
 * negative nrt_error - 100 (the runtime checks the blob before trusting a
 * byte of it; a NULL blob with len > 0 is NRT_E_ARG - 100). */
NEAT_API int neat_phenotype_load_blob(neat_phenotype *ph, const uint8_t *blob, size_t len);

/* double -> Q1.15, rounded to nearest (halves up), saturating to [-1, 1 - 2^-15]; NaN -> 0 */
NEAT_API nrt_q15 neat_q15(double x);
/* Q1.15 -> double (exact) */
NEAT_API double neat_from_q15(nrt_q15 q);

#ifdef __cplusplus
}
#endif

#endif /* NEAT_PHENOTYPE_H */
