/* duel_cmp_cache.h - finished 288-game comparisons kept in a file, keyed by the world's identity and the hashes of the two blobs, so a repeated or extended compare plays nothing twice. */
#ifndef DUEL_CMP_CACHE_H
#define DUEL_CMP_CACHE_H

#include <stddef.h>
#include <stdint.h>

#include "duel.h"

typedef struct duel_cmp_entry {
    uint64_t world; /* duel_rules_id of the world the games were played in */
    uint64_t a, b;  /* duel_blob_hash of the two blobs, a played first-named */
    duel_tally tally;
} duel_cmp_entry;

typedef struct duel_cmp_cache {
    char path[4200];
    duel_cmp_entry *e; /* sorted by (world, a, b) */
    size_t n, cap;
    int dirty;
} duel_cmp_cache;

/* 64-bit FNV-1a of the blob's bytes: the key of its comparisons. */
uint64_t duel_blob_hash(const uint8_t *blob, size_t len);

/* Reads path (missing or empty: an empty cache). A file in format 1
 * (before the rules were data) is world v1's and is written back in format
 * 2; CRLF line ends read as LF. 0; -1 with "PATH:LINE: problem" in err for a
 * damaged line, a cut last line or two different results for one
 * comparison; -2 when the file is not a cache (another header): it is never
 * replaced unless the caller (--force) starts afresh. */
int duel_cmp_cache_open(duel_cmp_cache *c, const char *path, char *err, size_t err_len);
/* The same from len bytes of text (path names it and is where it saves). */
int duel_cmp_cache_parse(duel_cmp_cache *c, const char *path, const char *text, size_t len, char *err,
                         size_t err_len);
/* 1 when the first bytes are a compare cache's (duel_out_kind's test). */
int duel_cmp_cache_is(const uint8_t *head, size_t len, const char *path);
/* The comparison of a against b in world (duel_rules_id), or NULL. */
const duel_tally *duel_cmp_cache_find(const duel_cmp_cache *c, uint64_t world, uint64_t a, uint64_t b);
/* 0, or -1 when out of memory. */
int duel_cmp_cache_add(duel_cmp_cache *c, uint64_t world, uint64_t a, uint64_t b, const duel_tally *t);
/* Writes the file (temporary, then rename) when something was added, first
 * taking in what another process saved there meanwhile, under PATH.lock
 * (flock): two compares of one candidate lose no entry. 0 or -1 (errno
 * set). */
int duel_cmp_cache_save(duel_cmp_cache *c);
void duel_cmp_cache_free(duel_cmp_cache *c);

#endif /* DUEL_CMP_CACHE_H */
