/* duel_world_cfg.h - the [world] section: the duel's chosen rules as INI keys (a named world plus overrides), their dump, and --world. */
#ifndef DUEL_WORLD_CFG_H
#define DUEL_WORLD_CFG_H

#include <stddef.h>
#include <stdio.h>

#include "duel.h"

/*
 * [world]
 *   rules = v1                 a named world (duel_rules_named), applied first
 *   radius = 10                lengths and energies in board units (rounded to 1/65536)
 *   start_west = 100 300 180   x y heading (degrees counter-clockwise from east)
 *   start_east = 500 300 0
 *   start_energy = 1200
 *   food_energy = 200
 *   eat_dist = 15
 *   share_dist = 0
 *   train_food = 200 200, 300 200, ...   up to 9 "x y" pairs, or none
 *   candidates = 60 75, 60 225, ...      exactly 12 "x y" pairs (the west half; the east item is the mirror)
 *   food_range = 850           whole units: readings max(0, 1 - d / range)
 *   robot_range = 850
 *   energy_scale = 200
 *   wall_range = 200
 * docs/duel-world.md defines each rule; docs/tools.md the keys.
 */

/* The [world] keys, in dump order (for "did you mean" and the docs' checks). */
extern const char *const duel_world_keys[];
extern const size_t duel_world_n_keys;

/* Sets one [world] key on r from its text. "rules" replaces every field
 * with the named world's. 0, or -1 with one line in err (unknown key with a
 * suggestion, a bad value). The whole is checked later (duel_world_check). */
int duel_world_set(duel_rules *r, const char *key, const char *value, char *err, size_t err_len);

/* duel_rules_check as one line: "[world] KEY: why". 0 or -1. */
int duel_world_check(const duel_rules *r, char *err, size_t err_len);

/* Every key, "key = value" lines that load back to the same rules, after a
 * comment naming the world (or its identity when it is no named world). */
void duel_world_dump(FILE *out, const duel_rules *r);

/* A world's short name for messages: "v1", or "custom 0123456789abcdef"
 * (its identity) into buf. */
const char *duel_world_label(const duel_rules *r, char *buf, size_t cap);

/* --world SPEC for the commands that play: a named world ("v1"), or a file
 * whose [world] section gives the rules (a run's config.ini, or any INI; the
 * other sections are ignored). 0, or -1 after one line on stderr naming the
 * file and line or the key. */
int duel_world_arg(duel_rules *r, const char *spec);

/* The rules of a run directory: its config.ini's [world] section (v1 when
 * the file has none: runs made before the rules were data). 0; -1 after one
 * line on stderr. */
int duel_world_of_run(duel_rules *r, const char *run_dir);
/* The same, printing nothing: -1 with the line in msg (paths escaped; print it through duel_esc_msg). */
int duel_world_of_run_msg(duel_rules *r, const char *run_dir, char *msg, size_t cap);

#endif /* DUEL_WORLD_CFG_H */
