/* fuzz_genome.c - libFuzzer harness: any bytes (and the same with their CRC repaired) as a genome file; one that loads saves back to the same bytes and encodes as a blob the runtime loads. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_crc.h"
#include "neat.h"
#include "neat_phenotype.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void fg_one(const uint8_t *data, size_t size)
{
    neat_genome g, again;
    neat_params p = neat_params_default();
    neat_phenotype ph;
    uint8_t *a, *b;
    size_t al, bl, off = 0;
    uint32_t ni, no;
    int err = neat_genome_load(&g, &ni, &no, data, size, NULL, &off);
    if (err != NEAT_OK) {
        if (off > size || g.n_nodes != 0 || neat_strerror(err)[0] == '\0')
            __builtin_trap();
        return;
    }
    /* save, load, save: the same bytes */
    if (neat_genome_save(&g, ni, no, &a, &al, NULL) != NEAT_OK)
        __builtin_trap();
    if (neat_genome_load(&again, NULL, NULL, a, al, NULL, NULL) != NEAT_OK)
        __builtin_trap();
    if (neat_genome_save(&again, ni, no, &b, &bl, NULL) != NEAT_OK || bl != al || memcmp(a, b, al) != 0)
        __builtin_trap();
    free(a);
    free(b);
    neat_genome_free(&again, NULL);
    /* a genome that loads is a network the runtime takes (or too big for a blob) */
    p.n_inputs = ni;
    p.n_outputs = no;
    neat_phenotype_init(&ph, NULL);
    err = neat_phenotype_load(&ph, &g, &p);
    if (err != NEAT_OK && err != NEAT_E_TOOBIG)
        __builtin_trap();
    neat_phenotype_free(&ph);
    neat_genome_free(&g, NULL);
}

/* The input as it is, and with its checksum made right. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *fixed = (uint8_t *)malloc(size + 1);
    if (fixed == NULL)
        return 0;
    fg_one(data, size);
    memcpy(fixed, data, size);
    fz_fix_crc(fixed, size);
    fg_one(fixed, size);
    free(fixed);
    return 0;
}
