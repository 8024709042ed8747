/* fw_main.c - the firmware example's main: the champions linked into the image (duel_evolve export) play the duel set on the target. */
#include "fw_duels.h"
#include "fw_port.h"

/* Generated at build time by `duel_evolve export BLOB --c-array NAME`. */
extern const uint8_t fw_champion_a[];
extern const size_t fw_champion_a_len;
extern const uint8_t fw_champion_b[];
extern const size_t fw_champion_b_len;
#ifdef FW_WORLD
/* the world's rules, by `duel_evolve export --world SPEC --c-array fw_world` (CMake's FW_WORLD) */
extern const uint8_t fw_world[];
extern const size_t fw_world_len;
#endif

int main(void);

static void fw_write(void *ud, const char *s, size_t n)
{
    (void)ud;
    fw_port_write(s, n);
}

int main(void)
{
    /* The networks live here; the blobs stay in flash and are not copied. */
    static uint8_t arena[FW_ARENA];
    const uint8_t *const blob[2] = {fw_champion_a, fw_champion_b};
    const size_t len[2] = {fw_champion_a_len, fw_champion_b_len};

#ifdef FW_WORLD
    return fw_duels_run(blob, len, fw_world, fw_world_len, arena, sizeof arena, fw_write, NULL);
#else
    return fw_duels_run(blob, len, NULL, 0, arena, sizeof arena, fw_write, NULL);
#endif
}
