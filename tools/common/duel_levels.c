/* duel_levels.c - the dominants listed in dominance.csv, with their blobs from champions/. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel_ctrl.h"
#include "neat_coev.h"
#include "duel_dominance.h"
#include "duel_levels.h"
#include "duel_text.h"

int duel_levels_read_msg(const char *dir, duel_level **out, uint32_t *n_out, char *msg, size_t cap)
{
    char err[4400], blob[4200], esc[1100];
    duel_dominance_row *rows;
    duel_level *levels;
    uint32_t n, k;
    duel_text_escape(dir, esc, sizeof esc);
    if (duel_run_is_fixed(dir)) {
        snprintf(blob, sizeof blob, "%s/checkpoint.bin", dir);
        duel_fixed_run_refused_msg("", blob, msg, cap);
        return -1;
    }
    if (duel_dominance_read(dir, &rows, &n, err, sizeof err) != 0) {
        snprintf(msg, cap, "%s", err);
        return -1;
    }
    if (n == 0) {
        snprintf(msg, cap, "%s/dominance.csv: no dominant strategy yet", esc);
        free(rows);
        return -1;
    }
    levels = (duel_level *)calloc(n, sizeof *levels);
    if (levels == NULL) {
        snprintf(msg, cap, "%s: out of memory", esc);
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
        if (duel_ctrl_open_msg(&l->ctrl, blob, 0, msg, cap) != 0) {
            duel_levels_free(levels, k);
            free(rows);
            return -1;
        }
    }
    free(rows);
    if (duel_levels_check_msg(dir, levels, n, msg, cap) != 0) {
        duel_levels_free(levels, n);
        return -1;
    }
    *out = levels;
    *n_out = n;
    return 0;
}

int duel_levels_read(const char *dir, duel_level **out, uint32_t *n)
{
    char msg[4600];
    if (duel_levels_read_msg(dir, out, n, msg, sizeof msg) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return -1;
}

int duel_levels_check_msg(const char *dir, const duel_level *levels, uint32_t n, char *msg, size_t cap)
{
    char path[4200], esc[1100];
    neat_coev *c = NULL;
    const neat_params *np;
    uint32_t doms, k;
    int e;
    snprintf(path, sizeof path, "%s/checkpoint.bin", dir);
    duel_text_escape(dir, esc, sizeof esc);
    e = duel_ckpt_load_msg("", path, &c, msg, cap);
    if (e != 0)
        return e < 0 ? -1 : 0; /* no checkpoint (a run copied without it): dominance.csv is all there is */
    np = neat_pop_params(neat_coev_pop(c, 0));
    doms = neat_coev_dominant_count(c);
    for (k = 0; k < n || k < doms; k++) {
        neat_dominant d;
        uint8_t *want;
        size_t len;
        if (k >= doms || k >= n) {
            snprintf(msg, cap, "%s/dominance.csv: %u levels, but the checkpoint has %u: resume the run to repair it",
                     esc, n, doms);
            neat_coev_free(c);
            return -1;
        }
        neat_coev_dominant(c, k, &d);
        if (d.generation != levels[k].generation || d.pop != (uint32_t)(levels[k].pop[0] == 'B')) {
            snprintf(msg, cap, "%s/dominance.csv: level %u says generation %u (%s), but the checkpoint's is "
                               "generation %u (%s): an edited or transplanted row; resume the run to rebuild it",
                     esc, k + 1u, levels[k].generation, levels[k].pop, d.generation, d.pop ? "B" : "A");
            neat_coev_free(c);
            return -1;
        }
        e = duel_genome_blob(d.genome, np->n_inputs, np->n_outputs, np->net_step, &want, &len);
        if (e == 0 && (len != levels[k].ctrl.blob_len || memcmp(want, levels[k].ctrl.blob, len) != 0)) {
            snprintf(msg, cap, "%s/champions/gen-%05u.blob is not the checkpoint's dominant of level %u (a file put "
                               "in its place): resume the run to write it again", esc, levels[k].generation, k + 1u);
            e = -1;
        } else if (e != 0) {
            snprintf(msg, cap, "%s: level %u: %s", esc, k + 1u, neat_strerror(e));
            e = -1;
        }
        free(want);
        if (e != 0) {
            neat_coev_free(c);
            return -1;
        }
    }
    neat_coev_free(c);
    return 0;
}

int duel_levels_check(const char *dir, const duel_level *levels, uint32_t n)
{
    char msg[4600];
    if (duel_levels_check_msg(dir, levels, n, msg, sizeof msg) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return -1;
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
