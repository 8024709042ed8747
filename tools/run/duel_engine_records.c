/* duel_engine_records.c - what each generation writes into the run directory (champions, generations.csv, dominance.csv, strength.csv, the checkpoint), and a resume's checks and rebuilds of them. */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "duel.h"
#include "duel_cmp_cache.h"
#include "duel_ctrl.h"
#include "duel_dominance.h"
#include "duel_engine_internal.h"
#include "duel_files.h"
#include "duel_generations.h"
#include "duel_genome_file.h"
#include "duel_fixed.h"
#include "duel_pairs.h"
#include "duel_text.h"
#include "neat_phenotype.h"

/* The champion games' recorder, registered by a program that has one (duel_engine.h). */
static duel_engine_game_recorder duel_recorder;

void duel_engine_set_game_recorder(duel_engine_game_recorder fn)
{
    duel_recorder = fn;
}

static int de_record_games(const char *dir, uint32_t generation, uint32_t champion_pop, const neat_genome *champion,
                           const neat_genome *other, const neat_params *p, const duel_rules *rules, char *msg,
                           size_t cap)
{
    char esc[1100];
    if (duel_recorder != NULL)
        return duel_recorder(dir, generation, champion_pop, champion, other, p, rules, msg, cap);
    snprintf(msg, cap, "%s: --record-champion-games needs a build with LCM (duel_evolve itself)",
             duel_text_escape(dir, esc, sizeof esc));
    return -1;
}

/* checkpoint.bin, replaced atomically: the generation is saved. */
static int duel_save_checkpoint(duel_engine *R)
{
    char path[4200];
    uint8_t *buf;
    size_t len;
    int err = R->fixed != NULL ? neat_pop_save(duel_fixed_pop(R->fixed), &buf, &len) : neat_coev_save(R->coev, &buf, &len),
        r;
    if (err) {
        de_err(R, "cannot build the checkpoint: %s\n", neat_strerror(err));
        return -1;
    }
    de_path(path, sizeof path, R->dir, "checkpoint.bin");
    r = duel_file_replace(path, buf, len);
    if (r != 0)
        de_err(R, "%s: cannot write: %s\n", de_esc(R, path), strerror(errno));
    if (R->fixed != NULL)
        neat_pop_buf_free(duel_fixed_pop(R->fixed), buf, len);
    else
        neat_coev_buf_free(R->coev, buf, len);
    return r;
}

/* The champion's blob as the runtime accepted it (the one path from genome
 * to blob, neat_phenotype_load), written atomically. */
static int duel_write_blob(duel_engine *R, const char *path, const neat_genome *g, const neat_params *p)
{
    neat_phenotype ph;
    int err, r;
    neat_phenotype_init(&ph, NULL);
    err = neat_phenotype_load(&ph, g, p);
    if (err) {
        de_err(R, "%s: cannot encode: %s\n", de_esc(R, path), de_game_error(err));
        neat_phenotype_free(&ph);
        return -1;
    }
    r = duel_file_replace(path, ph.blob, ph.blob_len);
    if (r != 0)
        de_err(R, "%s: cannot write: %s\n", de_esc(R, path), strerror(errno));
    neat_phenotype_free(&ph);
    return r;
}

static int duel_strength(duel_engine *R, uint32_t g, const neat_genome *champ);

/* A champion genome file's origin: the run's step and game tag (world rules
 * first; the coevolution's, or the population's for a run against fixed
 * opponents), so that the file says where it was made once copied out. */
static const neat_genome_origin *duel_origin_of(neat_genome_origin *o, const neat_params *np, const neat_coev *c,
                                                const neat_pop *pop)
{
    size_t len = 0;
    o->version = 2;
    o->net_step = np->net_step;
    o->tag = c != NULL ? neat_coev_game(c, &len) : neat_pop_game(pop, &len);
    o->tag_len = (uint32_t)len;
    return o;
}


/* The rows the generation hook is given, emptied before each generation's record. */
static void duel_rows_clear(duel_engine *R)
{
    R->rows[0] = '\0';
    free(R->dominance_row);
    R->dominance_row = NULL;
    R->have_strength = 0;
}

int de_record(duel_engine *R, const neat_coev_report *rep, double secs)
{
    char path[4200], row[2000], err[4600];
    const neat_params *np = neat_pop_params(neat_coev_pop(R->coev, 0));
    neat_genome_origin origin;
    uint32_t p;
    struct stat st;

    duel_rows_clear(R);
    snprintf(row, sizeof row, "champions/gen-%05u.blob", rep->generation);
    de_path(path, sizeof path, R->dir, row);
    if (duel_write_blob(R, path, neat_coev_champion(R->coev), np) != 0)
        return -1;
    /* and its genes: a champion to seed a run with (start = genome:PATH) */
    snprintf(row, sizeof row, "champions/gen-%05u.genome", rep->generation);
    de_path(path, sizeof path, R->dir, row);
    if (duel_genome_write_msg(path, neat_coev_champion(R->coev), np->n_inputs, np->n_outputs,
                              duel_origin_of(&origin, np, R->coev, NULL), err, sizeof err) != 0) {
        de_err(R, "%s", de_esc_msg(R, err));
        return -1;
    }
    if (R->record_games &&
        de_record_games(R->dir, rep->generation, rep->champion_pop, neat_coev_champion(R->coev),
                                       neat_coev_hof(R->coev, rep->champion_pop ^ 1u, rep->generation), np,
                                       &R->cfg.world, err, sizeof err) != 0) {
        de_err(R, "%s", de_esc_msg(R, err));
        return -1;
    }

    de_path(path, sizeof path, R->dir, "generations.csv");
    /* missing, or left empty by a header write that failed: the header first */
    if ((stat(path, &st) != 0 || st.st_size == 0) &&
        duel_file_append(path, DUEL_GENERATIONS_HEADER) != 0)
        goto fail;
    for (p = 0; p < 2; p++) {
        const neat_coev_pop_report *pr = &rep->pop[p];
        snprintf(row, sizeof row, "%u,%s,%.0f,%.4f,%u,%.4f,%.4f,%.4f,%u,%u,%u,%u,%u,%u,%llu,%d,%.3f\n",
                 rep->generation, de_pop_name(p), pr->best_fitness, pr->mean_fitness, pr->species, pr->delta_t,
                 pr->mean_hidden, pr->mean_conns, pr->best_hidden, pr->best_conns, pr->min_hidden, pr->max_hidden,
                 pr->min_conns, pr->max_conns, (unsigned long long)pr->games, rep->champion_pop == p, secs);
        if (duel_file_append(path, row) != 0)
            goto fail;
        if (strlen(R->rows) + strlen(row) < sizeof R->rows)
            strcat(R->rows, row);
    }

    if (rep->new_dominant) {
        neat_dominant d;
        char *drow;
        int bad;
        neat_coev_dominant(R->coev, rep->dominants - 1u, &d);
        de_path(path, sizeof path, R->dir, "dominance.csv");
        if ((stat(path, &st) != 0 || st.st_size == 0) && duel_file_append(path, DUEL_DOMINANCE_HEADER) != 0)
            goto fail;
        /* "w:l" against d(n-1), d(n-2), ..., d1: the comparisons it won, in the order played */
        drow = duel_dominance_row_text(rep->dominants, d.generation, de_pop_name(d.pop)[0],
                                       neat_genome_hidden_count(d.genome), neat_genome_enabled_count(d.genome),
                                       d.n_beaten, d.wins, d.losses);
        if (drow == NULL) {
            errno = ENOMEM;
            goto fail;
        }
        bad = duel_file_append(path, drow) != 0;
        R->dominance_row = drow; /* for the generation hook; freed by the next record */
        if (bad)
            goto fail;
    }
    if (duel_strength(R, rep->generation, neat_coev_champion(R->coev)) != 0)
        return -1;
    return duel_save_checkpoint(R);
fail:
    de_err(R, "%s: cannot write: %s\n", de_esc(R, path), strerror(errno));
    return -1;
}

/* Every K generations ([run] strength_every: generations 0, K, 2K, ...; not
 * "and the last", which would depend on where a run was extended): the
 * champion of generation g against every builtin strategy, 288 games each,
 * into strength.csv (the absolute strength a run reaches, which the
 * dominance ranking, relative to the run itself, does not show). */
#define DUEL_STRENGTH_MAX_FILE (64u << 20) /* a 500-generation run measured every generation writes about 50 KB */

/* strength.csv's header; since issue 49 it ends with the champion measured (the FNV-1a hash of its blob), so that
 * a row is checked against the checkpoint: a file without the column (older) goes on without it */
static void duel_strength_header(char *row, size_t cap, int with_champion)
{
    size_t at = (size_t)snprintf(row, cap, "generation");
    int k;
    for (k = 0; k < DUEL_N_BUILTINS; k++) {
        const char *n = duel_builtin_name(k);
        at += (size_t)snprintf(row + at, cap - at, ",%s_wins,%s_losses,%s_draws,%s_timeouts", n, n, n, n);
    }
    snprintf(row + at, cap - at, "%s\n", with_champion ? ",champion" : "");
}

/* Generation g's row of strength.csv for the champion network blob: its games against every builtin. 0, or -1
 * (the games could not be played). The same blob gives the same row, so a lost row is measured again. */
static int duel_strength_row(duel_engine *R, uint32_t g, const uint8_t *blob, size_t len, char *row, size_t cap)
{
    duel_cli_ctrl a, b[DUEL_N_BUILTINS];
    duel_pair pairs[DUEL_N_BUILTINS];
    size_t at;
    int k;
    memset(&a, 0, sizeof a);
    a.blob = (uint8_t *)blob;
    a.blob_len = len;
    for (k = 0; k < DUEL_N_BUILTINS; k++) {
        memset(&b[k], 0, sizeof b[k]);
        b[k].ctrl.builtin = k;
        pairs[k].a = &a;
        pairs[k].b = &b[k];
    }
    if (duel_pairs_play(&R->cfg.world, pairs, DUEL_N_BUILTINS, R->threads, NULL, NULL) != 0)
        return -1;
    at = (size_t)snprintf(row, cap, "%u", g);
    for (k = 0; k < DUEL_N_BUILTINS; k++)
        at += (size_t)snprintf(row + at, cap - at, ",%u,%u,%u,%u", pairs[k].tally.wins_a, pairs[k].tally.wins_b,
                               pairs[k].tally.draws, pairs[k].tally.timeouts);
    if (R->strength_old)
        snprintf(row + at, cap - at, "\n");
    else
        snprintf(row + at, cap - at, ",%016llx\n", (unsigned long long)duel_blob_hash(blob, len));
    return 0;
}

static int duel_strength(duel_engine *R, uint32_t g, const neat_genome *champ)
{
    char path[4200], row[600];
    neat_phenotype ph;
    struct stat st;
    int err;
    if (R->cfg.strength_every == 0 || g % R->cfg.strength_every != 0)
        return 0;
    neat_phenotype_init(&ph, NULL);
    err = neat_phenotype_load(&ph, champ, &R->eff.neat);
    if (err == 0)
        err = duel_strength_row(R, g, ph.blob, ph.blob_len, row, sizeof row);
    neat_phenotype_free(&ph);
    if (err) {
        de_err(R, "generation %u: the champion's strength could not be measured\n", g);
        return -1;
    }
    de_path(path, sizeof path, R->dir, "strength.csv");
    if (stat(path, &st) != 0 || st.st_size == 0) {
        char head[600];
        duel_strength_header(head, sizeof head, !R->strength_old);
        if (duel_file_append(path, head) != 0)
            goto fail;
    }
    if (duel_file_append(path, row) == 0) {
        memcpy(R->strength_row, row, sizeof row);
        R->have_strength = 1;
        return 0;
    }
fail:
    de_err(R, "%s: cannot write: %s\n", de_esc(R, path), strerror(errno));
    return -1;
}

/* strength.csv must hold a row for every measured generation before g (0, K, 2K, ...): a lost row (a deleted or
 * truncated file, a partial last line) is measured again from champions/gen-G.blob, which gives the same bytes;
 * one whose champion is gone too is refused with what works. Rows after g were cut already. 0, or the exit status
 * after one line. */
/* 1 when hex (16 digits) names the blob of a champion of generation q: for a coevolution, one of the two
 * populations' bests the checkpoint's Halls of Fame hold; for a run against fixed opponents (whose checkpoint keeps
 * no earlier champion), its champions/gen-q.blob. 0 otherwise. */
static int duel_strength_champion_ok(duel_engine *R, uint32_t q, const char *hex)
{
    char want[17];
    uint32_t p;
    if (R->coev != NULL) {
        const neat_params *np = neat_pop_params(neat_coev_pop(R->coev, 0));
        for (p = 0; p < 2; p++) {
            const neat_genome *h = q < neat_coev_hof_count(R->coev, p) ? neat_coev_hof(R->coev, p, q) : NULL;
            uint8_t *b = NULL;
            size_t len = 0;
            int ok = h != NULL && duel_genome_blob(h, np->n_inputs, np->n_outputs, np->net_step, &b, &len) == 0;
            if (ok)
                snprintf(want, sizeof want, "%016llx", (unsigned long long)duel_blob_hash(b, len));
            free(b);
            if (ok && strcmp(want, hex) == 0)
                return 1;
        }
        return 0;
    }
    {
        char path[4200], name[64];
        uint8_t *b;
        size_t len;
        snprintf(name, sizeof name, "champions/gen-%05u.blob", q);
        de_path(path, sizeof path, R->dir, name);
        if (duel_file_read(path, DUEL_GENOME_MAX, &b, &len) != 0)
            return 0;
        snprintf(want, sizeof want, "%016llx", (unsigned long long)duel_blob_hash(b, len));
        free(b);
        return strcmp(want, hex) == 0;
    }
}

int de_rebuild_strength(duel_engine *R, uint32_t g)
{
    char path[4200], head[600], row[600], name[64];
    uint8_t *have = NULL, *blob;
    size_t have_len = 0, len, blen, pos;
    char *text = NULL;
    FILE *mem;
    uint32_t every = R->cfg.strength_every, q, measured = 0;
    int r;
    if (every == 0 || g == 0)
        return 0;
    de_path(path, sizeof path, R->dir, "strength.csv");
    r = duel_file_read(path, DUEL_STRENGTH_MAX_FILE, &have, &have_len);
    if (r != 0 && errno != ENOENT) {
        de_err(R, "%s: %s: refusing to replace it\n", de_esc(R, path), duel_file_strerror(errno));
        return 2;
    }
    /* the file's format: with the champion column (checked below) or, when it was written without, so on */
    duel_strength_header(head, sizeof head, 0);
    R->strength_old = have != NULL && have_len >= strlen(head) && memcmp(have, head, strlen(head)) == 0;
    duel_strength_header(head, sizeof head, !R->strength_old);
    if ((mem = open_memstream(&text, &len)) == NULL) {
        free(have);
        de_err(R, "resume: out of memory\n");
        return 1;
    }
    fputs(head, mem);
    for (q = 0; q < g; q += every) {
        /* this generation's whole line in the file as it is, else measured again */
        const char *found = NULL;
        size_t found_len = 0;
        for (pos = 0; have != NULL && pos < have_len;) {
            const uint8_t *nl = memchr(have + pos, '\n', have_len - pos);
            size_t n = nl == NULL ? have_len - pos : (size_t)(nl - (have + pos));
            int w = snprintf(name, sizeof name, "%u,", q);
            if (nl != NULL && n > (size_t)w && memcmp(have + pos, name, (size_t)w) == 0) {
                found = (const char *)have + pos;
                found_len = n + 1;
            }
            pos += n + 1;
        }
        if (found != NULL && !R->strength_old) {
            /* the row's champion must be the run's: one of generation q's bests in the checkpoint (a fixed run's
             * checkpoint keeps none: its champion blob) */
            const char *comma = found + found_len - 1;
            char got[17];
            while (comma > found && *comma != ',')
                comma--;
            if ((size_t)(found + found_len - 1 - comma) == 17) {
                memcpy(got, comma + 1, 16);
                got[16] = '\0';
            } else {
                got[0] = '\0';
            }
            if (duel_strength_champion_ok(R, q, got) != 1) {
                de_log(R, "resume: strength.csv: generation %u's row was not of the run's champion (%s): measured "
                            "again", q, got[0] != '\0' ? got : "no champion column");
                found = NULL;
            }
        }
        if (found != NULL) {
            fwrite(found, 1, found_len, mem);
            continue;
        }
        snprintf(name, sizeof name, "champions/gen-%05u.blob", q);
        {
            char bpath[4200];
            de_path(bpath, sizeof bpath, R->dir, name);
            if (duel_file_read(bpath, DUEL_GENOME_MAX, &blob, &blen) != 0) {
                de_err(R, "%s: generation %u's row is lost and cannot be measured again without "
                                "%s (%s): restore either, or resume with --set strength_every=0 to measure "
                                "nothing more\n",
                        de_esc(R, path), q, name, duel_file_strerror(errno));
                fclose(mem);
                free(text);
                free(have);
                return 2;
            }
        }
        {
            char hex[17];
            snprintf(hex, sizeof hex, "%016llx", (unsigned long long)duel_blob_hash(blob, blen));
            if (R->coev != NULL && duel_strength_champion_ok(R, q, hex) != 1) {
                de_err(R, "%s/%s is not one of generation %u's bests in the checkpoint (a file put "
                                "in its place): restore it, or resume with --set strength_every=0 to measure nothing "
                                "more\n", de_esc(R, R->dir), name, q);
                free(blob);
                fclose(mem);
                free(text);
                free(have);
                return 2;
            }
        }
        r = duel_strength_row(R, q, blob, blen, row, sizeof row);
        free(blob);
        if (r != 0) {
            de_err(R, "%s: generation %u's row could not be measured again from %s\n", de_esc(R, path), q,
                    name);
            fclose(mem);
            free(text);
            free(have);
            return 1;
        }
        fputs(row, mem);
        measured++;
    }
    if (fclose(mem) != 0) {
        free(text);
        free(have);
        de_err(R, "resume: out of memory\n");
        return 1;
    }
    if (have != NULL && have_len == len && memcmp(have, text, len) == 0) {
        free(have);
        free(text);
        return 0;
    }
    free(have);
    r = duel_file_replace(path, text, len) != 0;
    if (r)
        de_err(R, "%s: cannot rewrite: %s\n", de_esc(R, path), duel_file_strerror(errno));
    else
        de_log(R, "resume: strength.csv rebuilt (%u row%s measured again from champions/)", measured,
                 de_s(measured));
    free(text);
    return r;
}

void de_opp_label(const duel_engine *R, uint32_t k, char *buf, size_t cap)
{
    if (R->opp[k].blob == NULL)
        snprintf(buf, cap, "%s", duel_builtin_name((int)R->opp[k].len));
    else
        snprintf(buf, cap, "o%u", k + 1u);
}

/* A generation of a run against fixed opponents: its champion's blob and
 * genome, its row of generations.csv (the champion's wins, losses, draws
 * and timeouts against each opponent), the strength, the checkpoint. */
int de_record_fixed(duel_engine *R, const duel_fixed_report *rep, double secs)
{
    char path[4200], row[4000], label[32], err[4600];
    neat_genome_origin origin;
    neat_pop *pop = duel_fixed_pop(R->fixed);
    const neat_params *np = neat_pop_params(pop);
    const neat_genome *champ = neat_pop_last_best(pop);
    struct stat st;
    size_t at;
    uint32_t k;

    duel_rows_clear(R);
    snprintf(row, sizeof row, "champions/gen-%05u.blob", rep->generation);
    de_path(path, sizeof path, R->dir, row);
    if (duel_write_blob(R, path, champ, np) != 0)
        return -1;
    snprintf(row, sizeof row, "champions/gen-%05u.genome", rep->generation);
    de_path(path, sizeof path, R->dir, row);
    if (duel_genome_write_msg(path, champ, np->n_inputs, np->n_outputs, duel_origin_of(&origin, np, NULL, pop), err,
                              sizeof err) != 0) {
        de_err(R, "%s", de_esc_msg(R, err));
        return -1;
    }
    de_path(path, sizeof path, R->dir, "generations.csv");
    if (stat(path, &st) != 0 || st.st_size == 0) {
        at = (size_t)snprintf(row, sizeof row, "generation,best_fitness,mean_fitness,species,delta_t,mean_hidden,"
                                               "mean_connections,best_hidden,best_connections,host_games,games");
        for (k = 0; k < R->cfg.opp.n; k++) {
            de_opp_label(R, k, label, sizeof label);
            at += (size_t)snprintf(row + at, sizeof row - at, ",%s_wins,%s_losses,%s_draws,%s_timeouts", label, label,
                                   label, label);
        }
        snprintf(row + at, sizeof row - at, ",seconds\n");
        if (duel_file_append(path, row) != 0)
            goto fail;
    }
    at = (size_t)snprintf(row, sizeof row, "%u,%.0f,%.4f,%u,%.4f,%.4f,%.4f,%u,%u,%u,%llu", rep->generation,
                          rep->best_fitness, rep->mean_fitness, rep->species, rep->delta_t, rep->mean_hidden,
                          rep->mean_conns, rep->best_hidden, rep->best_conns, rep->host_games,
                          (unsigned long long)rep->games);
    for (k = 0; k < R->cfg.opp.n; k++)
        at += (size_t)snprintf(row + at, sizeof row - at, ",%u,%u,%u,%u", rep->best_vs[k].wins_a,
                               rep->best_vs[k].wins_b, rep->best_vs[k].draws, rep->best_vs[k].timeouts);
    snprintf(row + at, sizeof row - at, ",%.3f\n", secs);
    if (duel_file_append(path, row) != 0)
        goto fail;
    snprintf(R->rows, sizeof R->rows, "%s", row);
    if (duel_strength(R, rep->generation, champ) != 0)
        return -1;
    return duel_save_checkpoint(R);
fail:
    de_err(R, "%s: cannot write: %s\n", de_esc(R, path), strerror(errno));
    return -1;
}

/* dominance.csv as the checkpoint's dominance tournament writes it: every
 * level, rebuilt on resume whatever became of the file (cut, deleted, a
 * row torn or dropped), byte for byte what an uninterrupted run writes. 0,
 * or the exit status after one line. */
int de_rebuild_dominance(duel_engine *R)
{
    char path[4200];
    char *text = NULL;
    size_t len = 0;
    uint8_t *have = NULL;
    size_t have_len = 0;
    uint32_t k, n = neat_coev_dominant_count(R->coev);
    FILE *mem = open_memstream(&text, &len);
    int r = 0;
    if (mem == NULL) {
        de_err(R, "resume: out of memory\n");
        return 1;
    }
    if (n > 0)
        fputs(DUEL_DOMINANCE_HEADER, mem);
    for (k = 0; k < n; k++) {
        neat_dominant d;
        char *row;
        neat_coev_dominant(R->coev, k, &d);
        row = duel_dominance_row_text(k + 1u, d.generation, de_pop_name(d.pop)[0], neat_genome_hidden_count(d.genome),
                                      neat_genome_enabled_count(d.genome), d.n_beaten, d.wins, d.losses);
        if (row == NULL) {
            r = 1;
            break;
        }
        fputs(row, mem);
        free(row);
    }
    if (fclose(mem) != 0 || r) {
        de_err(R, "resume: out of memory\n");
        free(text);
        return 1;
    }
    /* each dominant's blob is its genome's encoding: one put in its place (or lost) is written again */
    for (k = 0; k < n && r == 0; k++) {
        neat_dominant d;
        const neat_params *np = neat_pop_params(neat_coev_pop(R->coev, 0));
        uint8_t *want;
        size_t wlen;
        char name[64];
        neat_coev_dominant(R->coev, k, &d);
        snprintf(name, sizeof name, "champions/gen-%05u.blob", d.generation);
        de_path(path, sizeof path, R->dir, name);
        if (duel_genome_blob(d.genome, np->n_inputs, np->n_outputs, np->net_step, &want, &wlen) != 0) {
            free(text);
            de_err(R, "resume: out of memory\n");
            return 1;
        }
        if (duel_file_read(path, DUEL_GENOME_MAX, &have, &have_len) != 0 || have_len != wlen ||
            memcmp(have, want, wlen) != 0) {
            r = duel_file_replace(path, want, wlen) != 0;
            if (r)
                de_err(R, "%s: cannot write: %s\n", de_esc(R, path), duel_file_strerror(errno));
            else
                de_log(R, "resume: %s was not the dominant of level %u: written again from the checkpoint", name,
                         k + 1u);
        }
        free(have);
        have = NULL;
        free(want);
    }
    if (r) {
        free(text);
        return 1;
    }
    de_path(path, sizeof path, R->dir, "dominance.csv");
    /* written only when it differs: an intact file is left alone; what is not a file is not ours to replace */
    r = duel_file_read(path, DUEL_DOMINANCE_MAX_FILE, &have, &have_len);
    if (r == 0 && have_len == len && (len == 0 || memcmp(have, text, len) == 0)) {
        free(have);
        free(text);
        return 0;
    }
    if (r == 0)
        free(have);
    if (r != 0 && (errno == DUEL_ENOTREG || errno == EISDIR)) {
        de_err(R, "%s: %s: refusing to replace it\n", de_esc(R, path), duel_file_strerror(errno));
        free(text);
        return 2;
    }
    if (len == 0) {
        r = unlink(path) != 0 && errno != ENOENT;
    } else {
        r = duel_file_replace(path, text, len) != 0;
        if (r == 0)
            de_log(R, "resume: dominance.csv rebuilt from the checkpoint (%u level%s)", n, de_s(n));
    }
    if (r)
        de_err(R, "%s: cannot rewrite: %s\n", de_esc(R, path), duel_file_strerror(errno));
    free(text);
    return r;
}

/* generations.csv's last row without its newline (*text, *len bytes, malloc'd: *len > 0 and the last byte not
 * '\n'): when it is a whole row of a generation the checkpoint holds (before g), the one byte is added to the file
 * (the data is whole) and to *text (*len one more), and logged; a row of a generation after the checkpoint is left
 * to be cut, as a torn one. 0 when repaired, else -1 (*len as it was). */
static int duel_repair_last_newline(duel_engine *R, const char *path, uint8_t **text, size_t *len, uint32_t g)
{
    duel_gen_row *rows;
    size_t n, at = *len;
    const uint8_t *t = *text;
    uint8_t *grown;
    char err[700];
    int r;
    /* a whole row ends in its wall time written "%.3f": a row cut inside that field is torn, not whole */
    if (at < 5 || t[at - 4] != '.' || !isdigit((unsigned char)t[at - 5]) || !isdigit((unsigned char)t[at - 3]) ||
        !isdigit((unsigned char)t[at - 2]) || !isdigit((unsigned char)t[at - 1]))
        return -1;
    if ((grown = (uint8_t *)realloc(*text, at + 1)) == NULL)
        return -1;
    *text = grown;
    grown[at] = '\n'; /* past *len until the file has it too */
    r = duel_generations_parse(path, (const char *)grown, at + 1, &rows, &n, err, sizeof err);
    if (r != 0)
        return -1;
    r = n > 0 && rows[n - 1].generation < g ? 0 : -1;
    free(rows);
    if (r != 0 || duel_file_append(path, "\n") != 0)
        return -1;
    *len = at + 1;
    de_log(R, "resume: generations.csv's last row lacked its newline (the row is whole): added");
    return 0;
}

/* generations.csv must hold every generation before g (rows after the
 * checkpoint were cut already): rows measured as they happened cannot be
 * rebuilt from the checkpoint, so a run missing some is refused with what
 * works. 0, or the exit status after one line. */
int de_check_generations(duel_engine *R, uint32_t g)
{
    duel_gen_row *rows;
    size_t n, len, keep;
    char err[700], path[4200];
    uint8_t *text;
    uint32_t done;
    int r;
    if (g == 0) /* nothing to hold yet (what is there is cut); a header cut short is written again */
        return 0;
    de_path(path, sizeof path, R->dir, "generations.csv");
    if (duel_file_read(path, DUEL_GENERATIONS_MAX_FILE, &text, &len) != 0) {
        if (errno == ENOENT)
            de_err(R, "%s: missing: " DUEL_GENERATIONS_LOST_ADVICE "\n", de_esc(R, path));
        else
            de_err(R, "%s: cannot read: %s\n", de_esc(R, path), duel_file_strerror(errno));
        return 2;
    }
    /* the complete rows: a torn last one belongs to the generation after the checkpoint, or is lost (below) */
    for (keep = len; keep > 0 && text[keep - 1] != '\n'; keep--)
        ;
    if (keep < len && duel_repair_last_newline(R, path, &text, &len, g) == 0)
        keep = len; /* the row was whole, only its newline missing: added, to the file and to text */
    r = duel_generations_parse(path, (const char *)text, keep, &rows, &n, err, sizeof err);
    free(text);
    if (r == -3) { /* a CRLF copy or a duplicated row: the rows are there, the fix is named */
        de_err(R, "%s\n", de_esc_msg(R, err));
        return 2;
    }
    if (r != 0) {
        de_err(R, "%s: " DUEL_GENERATIONS_LOST_ADVICE "\n", de_esc_msg(R, err));
        return 2;
    }
    done = n > 0 ? rows[n - 1].generation + (rows[n - 1].pop == 'B') : 0;
    free(rows);
    if (done < g) {
        de_err(R, "%s holds %u generation%s but the checkpoint %u: " DUEL_GENERATIONS_LOST_ADVICE
                        "\n", de_esc(R, path), done, de_s(done), g);
        return 2;
    }
    return 0;
}
