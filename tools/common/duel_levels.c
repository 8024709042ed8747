/* duel_levels.c - the dominants listed in dominance.csv, with their blobs from champions/. */
#include <stdio.h>
#include <stdlib.h>

#include "duel_ctrl.h"
#include "duel_dominance.h"
#include "duel_levels.h"

int duel_levels_read(const char *dir, duel_level **out, uint32_t *n_out)
{
    char err[4400], blob[4200];
    duel_dominance_row *rows;
    duel_level *levels;
    uint32_t n, k;
    if (duel_run_is_fixed(dir)) {
        snprintf(blob, sizeof blob, "%s/checkpoint.bin", dir);
        duel_fixed_run_refused("", blob);
        return -1;
    }
    if (duel_dominance_read(dir, &rows, &n, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", err);
        return -1;
    }
    if (n == 0) {
        fprintf(stderr, "duel_evolve: %s/dominance.csv: no dominant strategy yet\n", dir);
        free(rows);
        return -1;
    }
    levels = (duel_level *)calloc(n, sizeof *levels);
    if (levels == NULL) {
        fprintf(stderr, "duel_evolve: %s: out of memory\n", dir);
        free(rows);
        return -1;
    }
    for (k = 0; k < n; k++) {
        duel_level *l = &levels[k];
        l->level = rows[k].level;
        l->generation = rows[k].generation;
        snprintf(l->pop, sizeof l->pop, "%s", rows[k].pop);
        l->hidden = rows[k].hidden;
        l->conns = rows[k].conns;
        snprintf(blob, sizeof blob, "%s/champions/gen-%05u.blob", dir, l->generation);
        if (duel_cli_ctrl_open(&l->ctrl, blob) != 0) {
            duel_levels_free(levels, k);
            free(rows);
            return -1;
        }
    }
    free(rows);
    *out = levels;
    *n_out = n;
    return 0;
}

void duel_levels_free(duel_level *levels, uint32_t n)
{
    uint32_t k;
    if (levels == NULL)
        return;
    for (k = 0; k < n; k++)
        duel_cli_ctrl_close(&levels[k].ctrl);
    free(levels);
}
