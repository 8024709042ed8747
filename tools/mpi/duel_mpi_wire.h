/* duel_mpi_wire.h - the bytes of a run's game messages between ranks (a chunk of games with the blobs it needs, and its results), written and checked without MPI so that the decoders can be fuzzed. */
#ifndef DUEL_MPI_WIRE_H
#define DUEL_MPI_WIRE_H

#include <stddef.h>
#include <stdint.h>

#include "duel_games.h"

/* Native byte order and layout: the start-up check (duel_mpi.c) makes sure
 * that every rank is the same build on the same byte order. A WORK message
 * is the header, then n_new times (uint32 id, uint32 length, the blob; a
 * builtin strategy b as the length DUEL_WIRE_BUILTIN + b and no bytes),
 * then count duel_wire_match; a RESULT message is its header and count
 * bytes (int8 results). */
#define DUEL_MPI_WORK_MAGIC 0x4b524f57u   /* "WORK" */
#define DUEL_MPI_RESULT_MAGIC 0x544c5352u /* "RSLT" */
#define DUEL_MPI_MAX_NETS (1u << 20)      /* networks a batch may name (a paper-scale batch names about 600) */
#define DUEL_WIRE_BUILTIN 0xFFFFFF00u     /* a network's length DUEL_WIRE_BUILTIN + b: builtin strategy b, no bytes */

typedef struct duel_work_hdr {
    uint32_t magic, count; /* count: games */
    uint64_t batch, from;  /* the batch's number on the wire, and its first game's index */
    uint32_t n_new, pad;   /* blobs that follow */
    uint8_t rules[DUEL_RULES_BYTES]; /* the world the games are played in (duel_rules_encode) */
    uint8_t pad2[(8 - DUEL_RULES_BYTES % 8) % 8];
} duel_work_hdr;

typedef struct duel_wire_match {
    uint32_t a, b; /* the networks' ids in this batch */
    int32_t config;
    uint8_t a_first, pad[3];
} duel_wire_match;

typedef struct duel_result_hdr {
    uint32_t magic, count;
    uint64_t batch, from;
    int32_t err, pad;      /* err: the chunk's error (0: none), at game from + err_at */
    uint64_t err_at, steps;
} duel_result_hdr;

/* A rank's networks of the batch in flight, by id; the blobs point into the messages that brought them. */
typedef struct duel_wire_store {
    uint64_t batch;
    duel_net *nets;  /* [cap]; a blob, a builtin (blob NULL, len its number), or not sent (blob NULL, len SIZE_MAX) */
    size_t cap;
    uint8_t **bufs;  /* the messages the blobs point into, freed when the batch changes */
    size_t n_bufs, bufs_cap;
} duel_wire_store;

/* A WORK message of len bytes taken: its header in *h, its world's rules in *rules, its networks kept in s (which
 * then owns buf, on success only), its games in (*m)[0..h->count) (grown as needed). 0, or -1 when any byte is
 * out of place: a wrong magic, rules duel_rules_decode refuses, a count of 0 or more games than bytes, a length
 * past the end, an id beyond DUEL_MPI_MAX_NETS, a game naming a network it was not sent, bytes left over. */
int duel_wire_work_take(duel_wire_store *s, uint8_t *buf, size_t len, duel_work_hdr *h, duel_rules *rules,
                        duel_match **m, size_t *m_cap);
void duel_wire_store_free(duel_wire_store *s);

/* A RESULT message checked against the chunk it answers (batch, from, count): 0 and *h, or -1. */
int duel_wire_result_read(const uint8_t *buf, size_t len, uint64_t batch, size_t from, size_t count,
                          duel_result_hdr *h);

/* *p grown to at least need elements of elem bytes (doubling from 64). 0, or -1 (unchanged). */
int duel_grow(void **p, size_t *cap, size_t need, size_t elem);

#endif /* DUEL_MPI_WIRE_H */
