/* fuzz_crc.h - the checkpoint harnesses' CRC repair: a mutated checkpoint gets its checksums made right again, so the fuzzer reaches the parser behind them. */
#ifndef FUZZ_CRC_H
#define FUZZ_CRC_H

#include <stddef.h>
#include <stdint.h>

#include "nrt.h"

static inline uint32_t fz_le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The last 4 bytes become the CRC-32 of the bytes before them (both checkpoint formats). */
static inline void fz_fix_crc(uint8_t *p, size_t len)
{
    uint32_t crc;
    if (len < 16)
        return;
    crc = nrt_crc32(0, p, len - 4);
    p[len - 4] = (uint8_t)crc;
    p[len - 3] = (uint8_t)(crc >> 8);
    p[len - 2] = (uint8_t)(crc >> 16);
    p[len - 1] = (uint8_t)(crc >> 24);
}

/* A coevolution checkpoint: both embedded population checkpoints (at byte
 * 44, after magic, version, seed, generation and the 5 protocol words:
 * length, bytes; then the second), then the whole. */
static inline void fz_fix_coev_crc(uint8_t *p, size_t len)
{
    size_t off = 44;
    int k;
    for (k = 0; k < 2; k++) {
        uint32_t n;
        if (off + 4 > len)
            break;
        n = fz_le32(p + off);
        off += 4;
        if (n > len - off)
            break;
        fz_fix_crc(p + off, n);
        off += n;
    }
    fz_fix_crc(p, len);
}

#endif /* FUZZ_CRC_H */
