/* fuzz_pop.c - libFuzzer harness: any bytes (and the same with their CRC repaired) as a population checkpoint; one that loads saves back to the same bytes and survives three epochs, whose checkpoint loads again. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_crc.h"
#include "neat.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Loads buf, or traps when a checkpoint that loaded once does not load again. */
static neat_pop *fp_load(const uint8_t *buf, size_t len, int must)
{
    neat_pop *pop = NULL;
    size_t off = 0;
    int err = neat_pop_load(&pop, buf, len, NULL, &off);
    if (err != NEAT_OK) {
        if (must || off > len || neat_strerror(err)[0] == '\0')
            __builtin_trap();
        return NULL;
    }
    return pop;
}

static void fp_one(const uint8_t *data, size_t size)
{
    neat_pop *pop = fp_load(data, size, 0), *again;
    uint8_t *a, *b;
    size_t al, bl;
    uint32_t e, i;
    if (pop == NULL)
        return;
    /* save, load, save: the same bytes */
    if (neat_pop_save(pop, &a, &al) != NEAT_OK)
        __builtin_trap();
    again = fp_load(a, al, 1);
    if (neat_pop_save(again, &b, &bl) != NEAT_OK || bl != al || memcmp(a, b, al) != 0)
        __builtin_trap();
    neat_pop_buf_free(pop, a, al);
    neat_pop_buf_free(again, b, bl);
    neat_pop_free(again);
    /* three generations on a fitness that depends only on the genome's place and size */
    if (neat_pop_size(pop) <= 2000) {
        for (e = 0; e < 3; e++) {
            int err;
            for (i = 0; i < neat_pop_size(pop); i++) {
                const neat_genome *g = neat_pop_genome(pop, i);
                neat_pop_set_fitness(pop, i, (double)((i * 7919u + neat_genome_enabled_count(g)) % 101u));
            }
            err = neat_pop_epoch(pop);
            if (err == NEAT_E_NOMEM || err == NEAT_E_TOOBIG || err == NEAT_E_COUNTERS)
                break;
            if (err != NEAT_OK)
                __builtin_trap();
        }
        if (neat_pop_save(pop, &a, &al) != NEAT_OK)
            __builtin_trap();
        again = fp_load(a, al, 1); /* a checkpoint this library wrote always loads */
        neat_pop_buf_free(pop, a, al);
        neat_pop_free(again);
    }
    neat_pop_free(pop);
}

/* The input as it is, and with its checksum made right. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *fixed = (uint8_t *)malloc(size + 1);
    if (fixed == NULL)
        return 0;
    fp_one(data, size);
    memcpy(fixed, data, size);
    fz_fix_crc(fixed, size);
    fp_one(fixed, size);
    free(fixed);
    return 0;
}
