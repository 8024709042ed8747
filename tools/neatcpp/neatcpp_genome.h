// neatcpp_genome.h - a NEAT C++ release genome (NEAT::Genome) as a libneat genome, for our runtime to evaluate.
#ifndef NEATCPP_GENOME_H
#define NEATCPP_GENOME_H

#include <stdint.h>

#include "neat.h"

namespace NEAT {
class Genome;
}

// The shape of g: sensors labelled INPUT (*n_inputs) and nodes labelled
// OUTPUT (*n_outputs). NEAT_OK, or NEAT_E_ARG unless g has exactly one BIAS
// node and at least one output (our networks always have the bias).
int neatcpp_genome_shape(const NEAT::Genome *g, uint32_t *n_inputs, uint32_t *n_outputs);

// Rebuilds g in out (initialised here; neat_genome_free it) through the
// public genome API: the bias is node 0, the inputs 1..n and the outputs
// n+1..n+m in the release's node order, hidden nodes the following ids in
// that order; one connection per gene, in the release's gene order (sorted
// by innovation number) with innovation = its index, enabled flag and
// weight kept. A weight beyond the blob's [-8, 8] is clamped there and
// counted in *clamped (the release caps its own at +-8, so this stays 0
// unless something else wrote the weight). NEAT_OK or a neat_error
// (NEAT_E_ARG: a gene names a node the genome has not).
int neatcpp_genome_convert(const NEAT::Genome *g, neat_genome *out, uint32_t *clamped);

// The same, keeping the historical markings, for a genome descended from a
// start made by neatcpp_genome_from_libneat: node id = the release's node_id
// - 1, innovation = the release's innovation number - 1 (whole numbers: the
// release counts them up by 1.0). A gene whose innovation number repeats
// one of the genome's, which libneat's genome cannot hold, is left out and
// counted in *dropped, and so is a node whose id repeats one's (the genes
// name nodes by id: they keep the one); every other gene is kept, a second link between two
// nodes too (the release's, its recurrent flag telling them apart), so our
// runtime adds up what the release's network does. NEAT_OK or a neat_error.
int neatcpp_genome_convert_ids(const NEAT::Genome *g, neat_genome *out, uint32_t *dropped);

// A release genome of g's structure (node_id = id + 1, innovation = innov +
// 1, weights and enabled flags kept; one trait), as a start for
// NEAT::Population(start, size). A gene is flagged recurrent when it is a
// self-loop or runs from a hidden or output node to one of lower id, the
// order libneat's hidden layers are laid out in. NULL if the allocator fails.
NEAT::Genome *neatcpp_genome_from_libneat(const neat_genome *g);

#endif // NEATCPP_GENOME_H
