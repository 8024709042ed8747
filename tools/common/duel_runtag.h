/* duel_runtag.h - what makes a run's games: its checkpoint's game tag, each generation's training food, and the coevolution a configuration starts; shared by duel_evolve and the Python package so that both make the same run. */
#ifndef DUEL_RUNTAG_H
#define DUEL_RUNTAG_H

#include <stddef.h>
#include <stdint.h>

#include "duel_config.h"
#include "neat_coev.h"

/* A fixed opponent in the tag: a builtin (is_blob 0, id its number) or a blob (is_blob 1, id its duel_blob_hash). */
typedef struct duel_opp_id {
    int is_blob;
    uint64_t id;
} duel_opp_id;

/* The run's tag (the game tag its checkpoint keeps): the world's rules first (their canonical bytes:
 * duel_ckpt_world reads them), then "RUN1", the training food ([run] train_layouts), the number of fixed
 * opponents and, for a run against them (opp: cfg->opp.n entries), its seed, [opponents] games and fitness, the
 * step mode, and each opponent. Resume compares it with what config.ini makes: a run's games cannot change under
 * it. 0, or NEAT_E_ARG (rules that do not encode). */
#define DUEL_TAG_MAX (DUEL_RULES_BYTES + 32 + 12 * DUEL_MAX_OPPONENTS + 8 + (8 + DUEL_OVERRIDE_MAX) * DUEL_MAX_OVERRIDES)
int duel_run_tag(const duel_config *cfg, const duel_opp_id *opp, uint8_t buf[DUEL_TAG_MAX], size_t *len);
/* The world a game tag names (a run's checkpoint, a genome file's origin): its first DUEL_RULES_BYTES are the
 * rules. 0 with them in *r; 1 for an empty tag (a run from before the rules were data: *r is world v1, which a
 * caller may take or not); -1 for a tag too short or whose rules do not decode (*off, when not NULL, the byte).
 * The one decoder of a tag's world: each caller says what an empty or damaged one means to it. */
int duel_tag_world(const uint8_t *tag, size_t len, duel_rules *r, size_t *off);
/* Where a run tag's overrides ("OVR1", then their count and each generation, length and text) start: the
 * offset of "OVR1" after the rules, or len when it has none. */
size_t duel_run_tag_overrides(const uint8_t *tag, size_t len);

/* The food of generation g's training games: the rules' training items (DUEL_TRAINING), or ([run] train_layouts
 * = comparison) one of the 144 comparison layouts drawn from the run's seed and the generation (the same for any
 * number of threads, ranks or resumes). */
int32_t duel_train_config(const duel_config *cfg, uint32_t g);

/* The coevolution of a configuration without fixed opponents, as duel_evolve run starts it: both populations
 * from its start topology and seed, tagged with duel_run_tag. 0; 2 with err (the configuration's fault: its start
 * genome); 1 with err (the machine's). */
int duel_coev_new(neat_coev **out, const duel_config *cfg, char *err, size_t err_len);

#endif /* DUEL_RUNTAG_H */
