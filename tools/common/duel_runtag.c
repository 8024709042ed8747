/* duel_runtag.c - what makes a run's games: its checkpoint's game tag, each generation's training food, and the coevolution a configuration starts; shared by duel_evolve and the Python package so that both make the same run. */
#include <stdio.h>
#include <string.h>

#include "duel_runtag.h"

/* the longest tag a run makes fits in what a checkpoint keeps */
typedef char duel_tag_fits[DUEL_TAG_MAX <= NEAT_GAME_MAX ? 1 : -1];

static size_t duel_put_u32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
    return 4;
}

int duel_run_tag(const duel_config *cfg, const duel_opp_id *opp, uint8_t buf[DUEL_TAG_MAX], size_t *len)
{
    size_t at = DUEL_RULES_BYTES;
    uint32_t k;
    if (duel_rules_encode(&cfg->world, buf) != DUEL_OK)
        return NEAT_E_ARG;
    memcpy(buf + at, "RUN1", 4);
    at += 4;
    at += duel_put_u32(buf + at, (uint32_t)cfg->train_layouts);
    at += duel_put_u32(buf + at, cfg->opp.n);
    if (cfg->opp.n > 0) {
        at += duel_put_u32(buf + at, cfg->seed);
        at += duel_put_u32(buf + at, cfg->opp.layouts);
        at += duel_put_u32(buf + at, (uint32_t)cfg->opp.fitness);
        at += duel_put_u32(buf + at, (uint32_t)cfg->neat.net_step);
        for (k = 0; k < cfg->opp.n; k++) {
            at += duel_put_u32(buf + at, (uint32_t)opp[k].is_blob);
            at += duel_put_u32(buf + at, (uint32_t)opp[k].id);
            at += duel_put_u32(buf + at, (uint32_t)(opp[k].id >> 32));
        }
    }
    /* a run with [overrides] (resume --set): each generation and its changes, so that the checkpoint records the
     * schedule it was played with; none, none written (every tag from before stays as it was) */
    if (cfg->n_over > 0) {
        memcpy(buf + at, "OVR1", 4);
        at += 4;
        at += duel_put_u32(buf + at, cfg->n_over);
        for (k = 0; k < cfg->n_over; k++) {
            size_t n = strlen(cfg->over[k].sets);
            at += duel_put_u32(buf + at, cfg->over[k].from);
            at += duel_put_u32(buf + at, (uint32_t)n);
            memcpy(buf + at, cfg->over[k].sets, n);
            at += n;
        }
    }
    *len = at;
    return 0;
}

int duel_tag_world(const uint8_t *tag, size_t len, duel_rules *r, size_t *off)
{
    duel_rules got;
    if (len == 0) {
        *r = *duel_rules_v1();
        return 1;
    }
    if (len < DUEL_RULES_BYTES) {
        if (off != NULL)
            *off = len;
        return -1;
    }
    if (duel_rules_decode(&got, tag, DUEL_RULES_BYTES, off) != DUEL_OK)
        return -1;
    *r = got;
    return 0;
}

size_t duel_run_tag_overrides(const uint8_t *tag, size_t len)
{
    /* the rules, "RUN1", train_layouts, the number of opponents n, and with n > 0 four u32 and n records of 12 */
    size_t at = DUEL_RULES_BYTES + 12, n;
    if (len < at || memcmp(tag + DUEL_RULES_BYTES, "RUN1", 4) != 0)
        return len;
    n = (size_t)tag[at - 4] | (size_t)tag[at - 3] << 8 | (size_t)tag[at - 2] << 16 | (size_t)tag[at - 1] << 24;
    if (n > DUEL_MAX_OPPONENTS)
        return len;
    if (n > 0)
        at += 16 + 12 * n;
    return at + 4 <= len && memcmp(tag + at, "OVR1", 4) == 0 ? at : len;
}
int32_t duel_train_config(const duel_config *cfg, uint32_t g)
{
    uint64_t keys[2];
    if (cfg->train_layouts != DUEL_TRAIN_COMPARISON)
        return DUEL_TRAINING;
    keys[0] = 0x7472616eu; /* "tran": apart from every other use of the seed */
    keys[1] = g;
    return (int32_t)(neat_seed_derive(cfg->seed, keys, 2) % DUEL_CONFIGS);
}

int duel_coev_new(neat_coev **out, const duel_config *cfg, char *err, size_t err_len)
{
    neat_genome g;
    neat_start st;
    uint8_t tag[DUEL_TAG_MAX];
    size_t len;
    int e;
    *out = NULL;
    if (cfg->n_over > 0) {
        snprintf(err, err_len, "[overrides] (parameters changed from a generation on): a schedule duel_evolve run "
                               "and resume play; give the parameters of generation 0 here");
        return 2;
    }
    if (duel_start_genome(cfg, &g, err, err_len) != 0)
        return 2;
    st.genome = &g;
    st.keep_weights = 0;
    e = neat_coev_create(out, &cfg->neat, &cfg->coev, &st, cfg->seed, NULL);
    neat_genome_free(&g, NULL);
    if (e == 0)
        e = duel_run_tag(cfg, NULL, tag, &len);
    if (e == 0)
        e = neat_coev_set_game(*out, tag, len);
    if (e) {
        snprintf(err, err_len, "cannot start: %s", neat_strerror(e));
        neat_coev_free(*out);
        *out = NULL;
        return 1;
    }
    return 0;
}
