/* fuzz_coev.c - libFuzzer harness: any bytes (and the same with their CRCs repaired) as a coevolution checkpoint; one that loads saves back to the same bytes and survives two generations of a cheap game, whose checkpoint loads again. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_crc.h"
#include "neat.h"
#include "neat_coev.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static neat_coev *fc_load(const uint8_t *buf, size_t len, int must)
{
    neat_coev *c = NULL;
    size_t off = 0;
    int err = neat_coev_load(&c, buf, len, NULL, &off);
    if (err != NEAT_OK) {
        if (must || off > len || neat_strerror(err)[0] == '\0')
            __builtin_trap();
        return NULL;
    }
    return c;
}

/* The bigger network wins; equal sizes: the game's seed decides. */
static int fc_play(void *ud, neat_game *games, size_t n)
{
    size_t i;
    (void)ud;
    for (i = 0; i < n; i++) {
        uint32_t a = neat_genome_enabled_count(games[i].a), b = neat_genome_enabled_count(games[i].b);
        games[i].result = (int8_t)(a > b ? 1 : a < b ? -1 : (games[i].seed & 1u ? 1 : -1));
    }
    return 0;
}

static void fc_one(const uint8_t *data, size_t size)
{
    neat_coev *c = fc_load(data, size, 0), *again;
    neat_coev_report rep;
    uint8_t *a, *b;
    size_t al, bl;
    uint32_t g;
    if (c == NULL)
        return;
    if (neat_coev_save(c, &a, &al) != NEAT_OK)
        __builtin_trap();
    again = fc_load(a, al, 1);
    if (neat_coev_save(again, &b, &bl) != NEAT_OK || bl != al || memcmp(a, b, al) != 0)
        __builtin_trap();
    neat_coev_buf_free(c, a, al);
    neat_coev_buf_free(again, b, bl);
    neat_coev_free(again);
    if (neat_pop_size(neat_coev_pop(c, 0)) <= 512) {
        for (g = 0; g < 2; g++) {
            int err = neat_coev_step(c, fc_play, NULL, &rep);
            if (err == NEAT_E_NOMEM || err == NEAT_E_TOOBIG || err == NEAT_E_COUNTERS)
                break;
            if (err != NEAT_OK)
                __builtin_trap();
        }
        if (neat_coev_save(c, &a, &al) != NEAT_OK)
            __builtin_trap();
        again = fc_load(a, al, 1);
        neat_coev_buf_free(c, a, al);
        neat_coev_free(again);
    }
    neat_coev_free(c);
}

/* The input as it is, and with its three checksums made right. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *fixed = (uint8_t *)malloc(size + 1);
    if (fixed == NULL)
        return 0;
    fc_one(data, size);
    memcpy(fixed, data, size);
    fz_fix_coev_crc(fixed, size);
    fc_one(fixed, size);
    free(fixed);
    return 0;
}
