/* neat_phenotype.h - genome -> blob -> runtime: the one path by which tools evaluate a genome. */
#ifndef NEAT_PHENOTYPE_H
#define NEAT_PHENOTYPE_H

#include "neat.h"
#include "nrt.h"

/* Reusable buffers for one evaluating thread. */
typedef struct neat_phenotype {
    uint8_t *blob;
    size_t blob_cap, blob_len;
    void *mem;
    size_t mem_cap;
    nrt_net net;
} neat_phenotype;

void neat_phenotype_init(neat_phenotype *ph);
void neat_phenotype_free(neat_phenotype *ph);
/* Encodes g as a blob and loads it into ph->net (reset). Returns 0, a
 * negative neat_error from the encoder, or a negative nrt_error - 100. */
int neat_phenotype_load(neat_phenotype *ph, const neat_genome *g, const neat_params *p);
/* A blob (neat_phenotype_load's, sent by another process) copied and loaded:
 * the same network. 0, NEAT_E_NOMEM, or a negative nrt_error - 100 (the
 * runtime checks the blob before trusting a byte of it). */
int neat_phenotype_load_blob(neat_phenotype *ph, const uint8_t *blob, size_t len);

/* double <-> Q1.15, saturating */
nrt_q15 neat_q15(double x);
double neat_from_q15(nrt_q15 q);

#endif /* NEAT_PHENOTYPE_H */
