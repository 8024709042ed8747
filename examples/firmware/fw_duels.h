/* fw_duels.h - the duel set the firmware example plays and prints: one source for the target and its host twin. */
#ifndef FW_DUELS_H
#define FW_DUELS_H

/*
 * Two champion blobs, A and B, play a fixed set of games (FW_DUELS_GAMES):
 * each against the built-in strategies on several food configurations and
 * from both sides, then A against B. Every line printed is built here from
 * integers only (no printf), so the target and the host print the same
 * bytes when they play the same games:
 *
 *   champion A: 188 bytes, crc 0x2bfcaf3f, 13 inputs, 3 outputs, 0 hidden, 39 connections, 227 bytes of RAM
 *   game 01 food training: west A, east builtin:forager -> east wins after 312 steps; energy 1187.125000
 *     1324.000000; eaten 2 3; outputs 0x1a2b3c4d                                 (one line)
 *   24 games: ...; all outputs 0x...
 *
 * "outputs" is a 32-bit FNV-1a hash of every motor output of the game (both
 * robots, every step, each output as two little-endian bytes), taken through
 * duel_play's trace callback; the last line hashes the outputs of all games.
 * Energies are the Q16.16 values in decimal, rounded to 6 places.
 */

#include <stddef.h>
#include <stdint.h>

#include "duel.h"

#define FW_DUELS_GAMES 26

/* Bytes for both loaded champions (nrt_mem_required each): two
 * 202-connection champions with 40 nodes need 2 x 1,023. */
#ifndef FW_ARENA
#define FW_ARENA 3072
#endif

/* Where the lines go (fw_port_write on the targets, stdout on the host). */
typedef void (*fw_write_fn)(void *ud, const char *s, size_t n);

/* Loads both champions into arena (nrt_mem_required bytes each), prints
 * their summary lines, plays the games and prints one line per game and a
 * summary. A champion the runtime refuses (its nrt_error printed), one that
 * is not a 13-input 3-output duel network, or one that does not fit in the
 * arena ends the run. The games are world v1's (world NULL), or those of
 * the world whose canonical bytes world holds (duel_evolve export --world;
 * rules that duel_rules_decode refuses end the run as a refused champion
 * does). Returns FW_EXIT_OK, FW_EXIT_REFUSED or FW_EXIT_FAILED (fw_port.h). */
int fw_duels_run(const uint8_t *const blob[2], const size_t blob_len[2], const uint8_t *world, size_t world_len,
                 void *arena, size_t arena_len, fw_write_fn write, void *ud);

/* ---- the line builder, shared with fw_figures.c ---- */
#define FW_LINE_MAX 200
typedef struct fw_line {
    char s[FW_LINE_MAX];
    size_t n;       /* characters so far (silently stops at FW_LINE_MAX - 1) */
} fw_line;

void fw_line_str(fw_line *l, const char *s);
void fw_line_udec(fw_line *l, uint32_t v);
void fw_line_dec(fw_line *l, int32_t v);
void fw_line_hex32(fw_line *l, uint32_t v); /* 0x and 8 lower-case digits */
void fw_line_q16(fw_line *l, int32_t v);    /* Q16.16 in decimal, 6 places, rounded half to even */
/* Appends '\n', writes the line, starts a new one. */
void fw_line_end(fw_line *l, fw_write_fn write, void *ud);

/* A short name of an nrt_error ("NRT_E_CRC"), "?" for unknown codes (the
 * runtime's nrt_strerror is compiled out of firmware builds). */
const char *fw_nrt_error_name(int err);

#endif /* FW_DUELS_H */
