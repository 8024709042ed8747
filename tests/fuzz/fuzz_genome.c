/* fuzz_genome.c - libFuzzer harness: any bytes (and the same with their CRC repaired) as a genome file of either version; one that loads saves back, origin and all, to the same bytes and encodes as a blob the runtime loads. */
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
    neat_genome_origin o, o2;
    int err = neat_genome_load_origin(&g, &ni, &no, &o, data, size, NULL, &off);
    if (err != NEAT_OK) {
        if (off > size || g.n_nodes != 0 || neat_strerror(err)[0] == '\0')
            __builtin_trap();
        return;
    }
    if ((o.version != 1 && o.version != 2) || (o.net_step != NEAT_STEP_SYNC && o.net_step != NEAT_STEP_PROPAGATE) ||
        o.tag_len > NEAT_GAME_MAX || (o.version == 1 && (o.tag_len != 0 || o.net_step != NEAT_STEP_SYNC)))
        __builtin_trap();
    /* save, load, save: the same bytes, the origin (version 2) kept */
    if (neat_genome_save_origin(&g, ni, no, o.version == 2 ? &o : NULL, &a, &al, NULL) != NEAT_OK)
        __builtin_trap();
    if (neat_genome_load_origin(&again, NULL, NULL, &o2, a, al, NULL, NULL) != NEAT_OK || o2.version != o.version ||
        o2.net_step != o.net_step || o2.tag_len != o.tag_len || (o.tag_len > 0 && memcmp(o.tag, o2.tag, o.tag_len) != 0))
        __builtin_trap();
    if (neat_genome_save_origin(&again, ni, no, o.version == 2 ? &o2 : NULL, &b, &bl, NULL) != NEAT_OK || bl != al ||
        memcmp(a, b, al) != 0)
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
