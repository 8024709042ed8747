/* duel_ladder.c - `duel_evolve ladder DIR [--top]`: every dominant strategy of a run (or its highest) against the built-in strategies, into ladder.csv. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_files.h"
#include "duel_levels.h"
#include "duel_pairs.h"

int duel_cmd_ladder(int argc, char **argv)
{
    duel_level *levels;
    duel_cli_ctrl builtins[DUEL_N_BUILTINS];
    duel_pair *pairs;
    uint32_t n, k, b;
    char path[4200], *text = NULL;
    size_t len = 0;
    FILE *mem;
    int err;

    int top = argc == 2 && strcmp(argv[1], "--top") == 0;
    uint32_t first = 0;

    if ((argc != 1 && !top) || argv[0][0] == '-') {
        fprintf(stderr, "usage: duel_evolve ladder DIR [--top]\n");
        return 2;
    }
    if (duel_levels_read(argv[0], &levels, &n) != 0)
        return 2;
    /* --top: the highest dominant alone (what an experiment's report needs) */
    first = top ? n - 1 : 0;
    /* one comparison per (level, builtin) */
    memset(builtins, 0, sizeof builtins);
    for (b = 0; b < DUEL_N_BUILTINS; b++)
        builtins[b].ctrl.builtin = (int)b;
    pairs = (duel_pair *)calloc((size_t)(n - first) * DUEL_N_BUILTINS, sizeof *pairs);
    if (pairs == NULL) {
        fprintf(stderr, "duel_evolve: ladder: out of memory\n");
        duel_levels_free(levels, n);
        return 1;
    }
    for (k = 0; k < (n - first) * DUEL_N_BUILTINS; k++) {
        pairs[k].a = &levels[first + k / DUEL_N_BUILTINS].ctrl;
        pairs[k].b = &builtins[k % DUEL_N_BUILTINS];
    }
    err = duel_pairs_play(pairs, (size_t)(n - first) * DUEL_N_BUILTINS, 0, NULL, NULL);
    mem = open_memstream(&text, &len);
    if (mem == NULL || err) {
        fprintf(stderr, "duel_evolve: ladder: %s\n", err ? "a comparison failed" : "out of memory");
        free(pairs);
        duel_levels_free(levels, n);
        return 1;
    }
    fprintf(mem, "level,generation,population,hidden,connections");
    for (b = 0; b < DUEL_N_BUILTINS; b++)
        fprintf(mem, ",%s_wins,%s_losses", duel_builtin_name((int)b), duel_builtin_name((int)b));
    fprintf(mem, ",total_wins,total_losses\n");
    printf("%-5s %-5s %-3s %-6s %-5s", "level", "gen", "pop", "hidden", "conns");
    for (b = 0; b < DUEL_N_BUILTINS; b++)
        printf(" %15s", duel_builtin_name((int)b));
    printf(" %11s\n", "total");
    for (k = first; k < n; k++) {
        const duel_level *r = &levels[k];
        uint32_t tw = 0, tl = 0;
        fprintf(mem, "%u,%u,%s,%u,%u", r->level, r->generation, r->pop, r->hidden, r->conns);
        printf("%-5u %-5u %-3s %-6u %-5u", r->level, r->generation, r->pop, r->hidden, r->conns);
        for (b = 0; b < DUEL_N_BUILTINS; b++) {
            const duel_tally *t = &pairs[(k - first) * DUEL_N_BUILTINS + b].tally;
            fprintf(mem, ",%u,%u", t->wins_a, t->wins_b);
            printf(" %7u:%-7u", t->wins_a, t->wins_b);
            tw += t->wins_a;
            tl += t->wins_b;
        }
        fprintf(mem, ",%u,%u\n", tw, tl);
        printf(" %5u:%-5u\n", tw, tl);
    }
    fclose(mem);
    free(pairs);
    duel_levels_free(levels, n);
    printf("wins:losses of %u games against each built-in strategy (draws and timeouts are neither)\n",
           2u * DUEL_CONFIGS);
    snprintf(path, sizeof path, "%s/ladder.csv", argv[0]);
    k = duel_file_replace(path, text, len) != 0;
    if (k)
        fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", path, strerror(errno));
    free(text);
    return k ? 1 : 0;
}
