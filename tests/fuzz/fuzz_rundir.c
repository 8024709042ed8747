/* fuzz_rundir.c - libFuzzer harness: any bytes as a run directory's dominance.csv (the ladder and compare read it), as its generations.csv (the experiment reads it), as its compare-cache.csv, and as a generations.csv cut back on resume, which must stay a prefix that ends at a row. */
#define _POSIX_C_SOURCE 200809L
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "duel_cmp_cache.h"
#include "duel_dominance.h"
#include "duel_generations.h"
#include "duel_files.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char fr_path[64];

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    snprintf(fr_path, sizeof fr_path, "/tmp/fuzz_rundir.%ld.csv", (long)getpid());
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    duel_dominance_row *rows;
    duel_dominance_score *scores;
    uint32_t n, k;
    char err[400];
    uint8_t *back;
    size_t len;
    FILE *f;
    if (duel_dominance_parse_scores("d.csv", (const char *)data, size, &rows, &n, &scores, err, sizeof err) == 0) {
        uint32_t at = 0;
        if (size > 0 && data[size - 1] != '\n')
            __builtin_trap(); /* a cut last row is never dropped silently (issue 40) */
        for (k = 0; k < n; k++) {
            if (rows[k].level != k + 1 || (rows[k].pop[0] != 'A' && rows[k].pop[0] != 'B') || rows[k].scores != at)
                __builtin_trap();
            at += k; /* level k + 1 has k scores */
        }
        if (at > 0 && scores == NULL)
            __builtin_trap();
        if (at > 0) { /* the last score is there (ASan checks the read) */
            volatile uint32_t last = scores[at - 1].wins + scores[at - 1].losses;
            (void)last;
        }
        free(rows);
        free(scores);
    } else if (strncmp(err, "d.csv", 5) != 0 || rows != NULL || n != 0 || scores != NULL) {
        __builtin_trap();
    }
    {
        duel_gen_row *g;
        size_t ng, k2;
        if (duel_generations_parse("g.csv", (const char *)data, size, &g, &ng, err, sizeof err) == 0) {
            uint32_t done = duel_generations_done(g, ng);
            if (size > 0 && data[size - 1] != '\n')
                __builtin_trap(); /* a cut last row is never dropped silently */
            for (k2 = 0; k2 < ng; k2++) /* no row missing: 0 A, 0 B, 1 A, ... */
                if (g[k2].generation != k2 / 2 || g[k2].pop != (k2 % 2 ? 'B' : 'A'))
                    __builtin_trap();
            for (k2 = 0; k2 < ng; k2++)
                if ((g[k2].pop != 'A' && g[k2].pop != 'B') || (g[k2].pop == 'B' && g[k2].generation >= done))
                    __builtin_trap();
            free(g);
        } else if (strncmp(err, "g.csv", 5) != 0 || g != NULL || ng != 0) {
            __builtin_trap();
        }
    }
    {
        duel_cmp_cache c;
        if (duel_cmp_cache_parse(&c, "c.csv", (const char *)data, size, err, sizeof err) == 0) {
            size_t i;
            if (size > 0 && data[size - 1] != '\n') {
                /* a last line without its newline is taken only as a whole entry (issue 49): the same cache as with
                 * the newline, and written back whole at the next save */
                duel_cmp_cache whole;
                char *t = (char *)malloc(size + 1);
                if (t == NULL)
                    abort();
                memcpy(t, data, size);
                t[size] = '\n';
                if (duel_cmp_cache_parse(&whole, "c.csv", t, size + 1, err, sizeof err) != 0 || whole.n != c.n ||
                    !c.dirty)
                    __builtin_trap();
                duel_cmp_cache_free(&whole);
                free(t);
            }
            for (i = 0; i < c.n; i++)
                if (c.e[i].tally.wins_a + c.e[i].tally.wins_b + c.e[i].tally.draws + c.e[i].tally.timeouts != 288u ||
                    (i > 0 && !(c.e[i - 1].a < c.e[i].a || (c.e[i - 1].a == c.e[i].a && c.e[i - 1].b < c.e[i].b))) ||
                    duel_cmp_cache_find(&c, c.e[i].world, c.e[i].a, c.e[i].b) != &c.e[i].tally)
                    __builtin_trap();
            duel_cmp_cache_free(&c);
        } else if (strncmp(err, "c.csv", 5) != 0) {
            __builtin_trap();
        }
    }
    f = fopen(fr_path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0)
        abort();
    if (duel_csv_keep_before(fr_path, size ? data[0] % 8u : 0u) == 0) {
        if (duel_file_read(fr_path, size + 1, &back, &len) != 0)
            __builtin_trap();
        if (len > size || memcmp(back, data, len) != 0 || (len > 0 && back[len - 1] != '\n'))
            __builtin_trap();
        free(back);
    }
    unlink(fr_path);
    return 0;
}
