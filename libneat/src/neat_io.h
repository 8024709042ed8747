/* neat_io.h - bounds-checked little-endian buffers shared by the checkpoint formats (population, coevolution). */
#ifndef NEAT_IO_H
#define NEAT_IO_H

#include "neat_internal.h"

/* A growing output buffer; the first failure sticks in err. */
typedef struct neat_wbuf {
    uint8_t *p;
    size_t n, cap;
    const neat_alloc *a;
    int err;
} neat_wbuf;

/* An input buffer: every read is bounds checked and remembers where it failed. */
typedef struct neat_rbuf {
    const uint8_t *p;
    size_t n, off;
    int err;
    size_t err_off;
} neat_rbuf;

void neat_put(neat_wbuf *w, const void *src, size_t len);
void neat_put_u8(neat_wbuf *w, uint32_t v);
void neat_put_u32(neat_wbuf *w, uint32_t v);
void neat_put_u64(neat_wbuf *w, uint64_t v);
void neat_put_f64(neat_wbuf *w, double d);
/* Seals the buffer with its CRC-32 and shrinks it to fit (freed with the
 * same allocator and its final length). */
int neat_put_finish(neat_wbuf *w, uint8_t **buf, size_t *len);

void neat_fail(neat_rbuf *r, int err);
const uint8_t *neat_get(neat_rbuf *r, size_t len);
uint32_t neat_get_u8(neat_rbuf *r);
uint32_t neat_get_u32(neat_rbuf *r);
uint64_t neat_get_u64(neat_rbuf *r);
double neat_get_f64(neat_rbuf *r);
/* The frame of a sealed buffer, before anything else is trusted: magic,
 * a version from oldest to newest (returned; 0 on failure), then the CRC-32
 * in the last 4 bytes; the body then ends before the checksum. */
uint32_t neat_get_frame(neat_rbuf *r, const uint8_t magic[8], uint32_t oldest, uint32_t newest);
/* a coevolution checkpoint's magic (neat_coev.c), for neat_checkpoint_kind */
extern const uint8_t neat_coev_magic[8];
/* a count of records of rec_size bytes that must fit in what is left */
uint32_t neat_get_count(neat_rbuf *r, size_t rec_size);

/* A game tag: its length (u32, at most NEAT_GAME_MAX) and its bytes; a
 * length read is checked against both before anything is allocated. */
void neat_put_tag(neat_wbuf *w, const neat_tag *t);
void neat_get_tag(neat_rbuf *r, const neat_alloc *a, neat_tag *t);

void neat_put_genome(neat_wbuf *w, const neat_genome *g);
/* Rebuilds through the genome API (a bad id, order or dangling connection
 * is refused as the API refuses it) and checks g against p. */
void neat_get_genome(neat_rbuf *r, neat_genome *g, const neat_params *p, const neat_alloc *a);

#endif /* NEAT_IO_H */
