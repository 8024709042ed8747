/* fuzz_rules.c - libFuzzer harness for a world's rules from their bytes (duel_rules_decode): any input is refused or is canonical rules, under which a game plays to its end without any undefined behaviour. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "duel.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    duel_rules r;
    uint8_t back[DUEL_RULES_BYTES];
    size_t off = 0;
    duel_controller a, b;
    duel_result res;
    int k;
    if (duel_rules_decode(&r, data, size, &off) != DUEL_OK) {
        if (off > size && off > DUEL_RULES_BYTES)
            __builtin_trap(); /* an offset past anything given */
        return 0;
    }
    /* accepted: the bytes are the canonical ones, and the rules make games */
    if (duel_rules_encode(&r, back) != DUEL_OK || size != DUEL_RULES_BYTES || memcmp(back, data, size) != 0)
        __builtin_trap();
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    /* the builtins that eat, chase and flee, on the training food and one comparison layout */
    for (k = 0; k < 2; k++) {
        a.builtin = k == 0 ? DUEL_FORAGER_HUNTER : DUEL_HUNTER;
        b.builtin = k == 0 ? DUEL_FORAGER : DUEL_FORAGER_HUNTER;
        if (duel_play_rules(&r, &a, &b, k == 0 ? DUEL_TRAINING : (int)(data[8] % DUEL_CONFIGS), &res, NULL, NULL) !=
                DUEL_OK ||
            res.outcome == DUEL_RUNNING || res.steps > DUEL_MAX_STEPS)
            __builtin_trap();
    }
    return 0;
}
