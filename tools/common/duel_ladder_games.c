/* duel_ladder_games.c - a run's ladder: its dominants against the built-in strategies, played, and written as CSV, a table or JSON. */
#include <stdlib.h>
#include <string.h>

#include "duel_json.h"
#include "duel_ladder_games.h"
#include "duel_text.h"
#include "duel_world_cfg.h"

const duel_out_kind duel_ladder_csv_kind = {"a ladder CSV", "level,generation,population,hidden,connections,", NULL};

int duel_ladder_play(duel_ladder *L, const char *dir, const duel_rules *world, int top, uint32_t lo, uint32_t hi,
                     const int *against, uint32_t n_against, uint32_t threads, char *msg, size_t cap)
{
    uint32_t k, b;
    char esc[1100];
    memset(L, 0, sizeof *L);
    L->dir = dir;
    L->world = *world;
    for (b = 0; b < n_against && b < DUEL_N_BUILTINS; b++)
        L->against[b] = against[b];
    L->n_against = b;
    if (duel_levels_read_msg(dir, &L->levels, &L->n, msg, cap) != 0)
        return 2;
    /* top: the highest dominant alone (what an experiment's report needs); lo..hi: a range */
    L->first = top ? L->n - 1 : (lo ? lo - 1 : 0);
    L->end = lo ? hi : L->n;
    if (lo && hi > L->n) {
        snprintf(msg, cap, "ladder: %s has %u dominance level%s, not %u", duel_text_escape(dir, esc, sizeof esc),
                 L->n, L->n == 1 ? "" : "s", hi);
        return 2;
    }
    /* one comparison per (level, strategy) */
    for (b = 0; b < L->n_against; b++)
        L->builtins[b].ctrl.builtin = L->against[b];
    L->pairs = (duel_pair *)calloc((size_t)(L->end - L->first) * L->n_against + 1, sizeof *L->pairs);
    if (L->pairs == NULL) {
        snprintf(msg, cap, "ladder: out of memory");
        return 1;
    }
    for (k = 0; k < (L->end - L->first) * L->n_against; k++) {
        L->pairs[k].a = &L->levels[L->first + k / L->n_against].ctrl;
        L->pairs[k].b = &L->builtins[k % L->n_against];
    }
    if (duel_pairs_play(&L->world, L->pairs, (size_t)(L->end - L->first) * L->n_against, threads, NULL, NULL) != 0) {
        snprintf(msg, cap, "ladder: a comparison failed");
        return 1;
    }
    return 0;
}

static const duel_tally *duel_ladder_tally(const duel_ladder *L, uint32_t k, uint32_t b)
{
    return &L->pairs[(k - L->first) * L->n_against + b].tally;
}

void duel_ladder_write_csv(FILE *f, const duel_ladder *L)
{
    uint32_t k, b;
    char w[40];
    duel_world_label(&L->world, w, sizeof w);
    fprintf(f, "level,generation,population,hidden,connections");
    for (b = 0; b < L->n_against; b++)
        fprintf(f, ",%s_wins,%s_losses", duel_builtin_name(L->against[b]), duel_builtin_name(L->against[b]));
    fprintf(f, ",total_wins,total_losses,world,step\n");
    for (k = L->first; k < L->end; k++) {
        const duel_level *lv = &L->levels[k];
        uint32_t tw = 0, tl = 0;
        fprintf(f, "%u,%u,%s,%u,%u", lv->level, lv->generation, lv->pop, lv->hidden, lv->conns);
        for (b = 0; b < L->n_against; b++) {
            const duel_tally *t = duel_ladder_tally(L, k, b);
            fprintf(f, ",%u,%u", t->wins_a, t->wins_b);
            tw += t->wins_a;
            tl += t->wins_b;
        }
        fprintf(f, ",%u,%u,%s,%s\n", tw, tl, w, duel_origin_step_text(&lv->ctrl.origin));
    }
}

void duel_ladder_write_table(FILE *f, const duel_ladder *L)
{
    uint32_t k, b;
    char w[40];
    fprintf(f, "%-5s %-5s %-3s %-6s %-5s", "level", "gen", "pop", "hidden", "conns");
    for (b = 0; b < L->n_against; b++)
        fprintf(f, " %15s", duel_builtin_name(L->against[b]));
    fprintf(f, " %11s\n", "total");
    for (k = L->first; k < L->end; k++) {
        const duel_level *lv = &L->levels[k];
        uint32_t tw = 0, tl = 0;
        fprintf(f, "%-5u %-5u %-3s %-6u %-5u", lv->level, lv->generation, lv->pop, lv->hidden, lv->conns);
        for (b = 0; b < L->n_against; b++) {
            const duel_tally *t = duel_ladder_tally(L, k, b);
            fprintf(f, " %7u:%-7u", t->wins_a, t->wins_b);
            tw += t->wins_a;
            tl += t->wins_b;
        }
        fprintf(f, " %5u:%-5u\n", tw, tl);
    }
    fprintf(f, "wins:losses of %u games against each built-in strategy (draws and timeouts are neither), world %s, "
               "network step %s\n", 2u * DUEL_CONFIGS, duel_world_label(&L->world, w, sizeof w),
            L->end > L->first ? duel_origin_step_text(&L->levels[L->first].ctrl.origin) : "none");
}

/* docs/tools.md, "ladder --json" */
void duel_ladder_write_json(FILE *f, const duel_ladder *L)
{
    uint32_t k, b;
    char w[40];
    fprintf(f, "{\"run\":");
    duel_json_str(f, L->dir);
    fprintf(f, ",\"world\":\"%s\",\"world_id\":\"%016llx\",\"step\":\"%s\",\"games\":%u,\"against\":[",
            duel_world_label(&L->world, w, sizeof w), (unsigned long long)duel_rules_id(&L->world),
            L->end > L->first ? duel_origin_step_text(&L->levels[L->first].ctrl.origin) : "none", 2u * DUEL_CONFIGS);
    for (b = 0; b < L->n_against; b++)
        fprintf(f, "%s\"%s\"", b ? "," : "", duel_builtin_name(L->against[b]));
    fprintf(f, "],\"levels\":[");
    for (k = L->first; k < L->end; k++) {
        const duel_level *lv = &L->levels[k];
        uint32_t tw = 0, tl = 0;
        fprintf(f, "%s{\"level\":%u,\"generation\":%u,\"population\":\"%s\",\"hidden\":%u,\"connections\":%u,"
                   "\"results\":{", k > L->first ? "," : "", lv->level, lv->generation, lv->pop, lv->hidden,
                lv->conns);
        for (b = 0; b < L->n_against; b++) {
            const duel_tally *t = duel_ladder_tally(L, k, b);
            fprintf(f, "%s\"%s\":{\"wins\":%u,\"losses\":%u,\"draws\":%u,\"timeouts\":%u}", b ? "," : "",
                    duel_builtin_name(L->against[b]), t->wins_a, t->wins_b, t->draws, t->timeouts);
            tw += t->wins_a;
            tl += t->wins_b;
        }
        fprintf(f, "},\"total_wins\":%u,\"total_losses\":%u}", tw, tl);
    }
    fprintf(f, "]}\n");
}

void duel_ladder_free(duel_ladder *L)
{
    free(L->pairs);
    L->pairs = NULL;
    duel_levels_free(L->levels, L->n);
    L->levels = NULL;
    L->n = 0;
}
