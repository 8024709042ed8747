/* duel_run.c - duel_evolve run, resume and config: a coevolution run, or a run against fixed opponents, in a run directory, checkpointed every generation. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <ctype.h>
#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "duel.h"
#include "duel_cli.h"
#include "duel_cmp_cache.h"
#include "duel_config.h"
#include "duel_cores.h"
#include "duel_ctrl.h"
#include "duel_dominance.h"
#include "duel_files.h"
#include "duel_fixed.h"
#include "duel_pairs.h"
#include "duel_generations.h"
#include "duel_outputs.h"
#include "duel_plan.h"
#include "duel_runtag.h"
#include "duel_games.h"
#include "duel_lcm_champ.h"
#include "duel_mpi.h"
#include "duel_signal.h"
#include "duel_text.h"
#include "duel_world_cfg.h"
#include "neat_coev.h"
#include "neat_phenotype.h"

/* Set by SIGINT/SIGTERM: the generation in progress finishes and is saved. */
static volatile sig_atomic_t duel_stop = 0;

typedef struct duel_run {
    const char *dir;
    duel_config cfg;           /* config.ini: generation 0's parameters and the [overrides] from later ones */
    duel_config eff;           /* the parameters of the generation in flight (cfg with its overrides up to it) */
    neat_coev *coev;           /* a coevolution run, or */
    duel_fixed *fixed;         /* a run against fixed opponents ([opponents] play) */
    duel_net opp[DUEL_MAX_OPPONENTS]; /* its opponents (blobs malloc'd) */
    duel_games *games;
    uint32_t threads;
    int quiet, json, tty;
    int record_games;          /* --record-champion-games: DIR/games/gen-NNNNN-{west,east}.lcm */
    double started;            /* monotonic seconds at this process's first generation */
    uint32_t first_gen;        /* the generation this process started at */
    uint32_t gen_in_flight;
    int bar_shown;
    double bar_drawn;          /* when the bar was last drawn */
    int log_failed;            /* log.txt could not be written: the run stops after the generation */
    double gen_secs;           /* this process's generations, in seconds */
    uint32_t first_applied;    /* 1 + the generation whose overrides were applied before the loop (0: none) */
    char opp_note[4600];       /* an opponent made in another world than the run's: logged when the run starts */
    int strength_old;          /* strength.csv is of the format without its champion column: rows go on so */
} duel_run;

static double duel_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec / 1e9;
}

static void duel_path(char *out, size_t cap, const char *dir, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
}

/* One timestamped line in DIR/log.txt (and nothing else: the log is for people). */
static void duel_log(duel_run *R, const char *fmt, ...)
{
    char path[4200], line[1200], stamp[64];
    time_t now = time(NULL);
    struct tm tmv;
    va_list ap;
    size_t n;
    gmtime_r(&now, &tmv);
    strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", &tmv);
    n = (size_t)snprintf(line, sizeof line, "%s ", stamp);
    va_start(ap, fmt);
    vsnprintf(line + n, sizeof line - n - 1, fmt, ap);
    va_end(ap);
    strcat(line, "\n");
    duel_path(path, sizeof path, R->dir, "log.txt");
    if (!R->log_failed && duel_file_append(path, line) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
        R->log_failed = 1;
    }
}

/* config.ini's seal: its second line holds the FNV-1a hash of every line after it, so that resume tells the
 * run's own writing from a hand edit of any key ([run]'s generations and strength_every, which the checkpoint does
 * not hold, included). */
#define DUEL_SEAL "; checksum "
#define DUEL_SEAL_TAIL ": written by the run (a hand edit is refused by resume; give a change as resume --set KEY=VALUE)\n"
/* what the seal records: the [run] keys the checkpoint does not hold, so that an edit of one is named */
#define DUEL_SEAL_KEYS "; generations = %u, strength_every = %u\n"

static int duel_write_config(const duel_run *R)
{
    char path[4200], *text = NULL, *body = NULL;
    size_t len = 0, blen = 0;
    FILE *mem = open_memstream(&body, &blen);
    int r;
    if (mem == NULL)
        return -1;
    duel_config_dump(mem, &R->cfg);
    if (fclose(mem) != 0) {
        free(body);
        return -1;
    }
    mem = open_memstream(&text, &len);
    if (mem == NULL) {
        free(body);
        return -1;
    }
    fprintf(mem, DUEL_RUN_CONFIG_MARK " (duel_evolve config --dump format)\n");
    fprintf(mem, DUEL_SEAL "%016llx" DUEL_SEAL_TAIL, (unsigned long long)duel_blob_hash((const uint8_t *)body, blen));
    fprintf(mem, DUEL_SEAL_KEYS, R->cfg.generations, R->cfg.strength_every);
    fwrite(body, 1, blen, mem);
    free(body);
    if (fclose(mem) != 0) {
        free(text);
        return -1;
    }
    duel_path(path, sizeof path, R->dir, "config.ini");
    r = duel_file_replace(path, text, len);
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    free(text);
    return r;
}

static int duel_save_checkpoint(const duel_run *R)
{
    char path[4200];
    uint8_t *buf;
    size_t len;
    int err = R->fixed != NULL ? neat_pop_save(duel_fixed_pop(R->fixed), &buf, &len) : neat_coev_save(R->coev, &buf, &len),
        r;
    if (err) {
        fprintf(stderr, "duel_evolve: cannot build the checkpoint: %s\n", neat_strerror(err));
        return -1;
    }
    duel_path(path, sizeof path, R->dir, "checkpoint.bin");
    r = duel_file_replace(path, buf, len);
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    if (R->fixed != NULL)
        neat_pop_buf_free(duel_fixed_pop(R->fixed), buf, len);
    else
        neat_coev_buf_free(R->coev, buf, len);
    return r;
}

/* The run's generation to play next, and its end. */
static uint32_t duel_next_gen(const duel_run *R)
{
    return R->fixed != NULL ? neat_pop_generation(duel_fixed_pop(R->fixed)) : neat_coev_generation(R->coev);
}

static void duel_run_free(duel_run *R)
{
    uint32_t k;
    neat_coev_free(R->coev);
    duel_fixed_free(R->fixed);
    R->coev = NULL;
    R->fixed = NULL;
    for (k = 0; k < DUEL_MAX_OPPONENTS; k++) {
        free((void *)R->opp[k].blob);
        R->opp[k].blob = NULL;
    }
}


static const char *duel_game_error(int err)
{
    if (err == DUEL_GAMES_E_REMOTE)
        return "another process of the MPI job failed";
    if (err <= -200)
        return "the duel refused a network";
    if (err <= -100)
        return nrt_strerror(err + 100);
    return neat_strerror(err);
}

/* The champion's blob as the runtime accepted it (the one path from genome
 * to blob, neat_phenotype_load), written atomically. */
static int duel_write_blob(const char *path, const neat_genome *g, const neat_params *p)
{
    neat_phenotype ph;
    int err, r;
    neat_phenotype_init(&ph, NULL);
    err = neat_phenotype_load(&ph, g, p);
    if (err) {
        fprintf(stderr, "duel_evolve: %s: cannot encode: %s\n", duel_esc(path), duel_game_error(err));
        neat_phenotype_free(&ph);
        return -1;
    }
    r = duel_file_replace(path, ph.blob, ph.blob_len);
    if (r != 0)
        fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    neat_phenotype_free(&ph);
    return r;
}

static int duel_strength(duel_run *R, uint32_t g, const neat_genome *champ);

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

static const char *duel_pop_name(uint32_t p)
{
    return p == 0 ? "A" : "B";
}

static int duel_record(duel_run *R, const neat_coev_report *rep, double secs)
{
    char path[4200], row[2000];
    const neat_params *np = neat_pop_params(neat_coev_pop(R->coev, 0));
    neat_genome_origin origin;
    uint32_t p;
    struct stat st;

    snprintf(row, sizeof row, "champions/gen-%05u.blob", rep->generation);
    duel_path(path, sizeof path, R->dir, row);
    if (duel_write_blob(path, neat_coev_champion(R->coev), np) != 0)
        return -1;
    /* and its genes: a champion to seed a run with (start = genome:PATH) */
    snprintf(row, sizeof row, "champions/gen-%05u.genome", rep->generation);
    duel_path(path, sizeof path, R->dir, row);
    if (duel_genome_write(path, neat_coev_champion(R->coev), np->n_inputs, np->n_outputs,
                          duel_origin_of(&origin, np, R->coev, NULL)) != 0)
        return -1;
    if (R->record_games &&
        duel_lcm_record_champion_games(R->dir, rep->generation, rep->champion_pop, neat_coev_champion(R->coev),
                                       neat_coev_hof(R->coev, rep->champion_pop ^ 1u, rep->generation), np,
                                       &R->cfg.world) != 0)
        return -1;

    duel_path(path, sizeof path, R->dir, "generations.csv");
    /* missing, or left empty by a header write that failed: the header first */
    if ((stat(path, &st) != 0 || st.st_size == 0) &&
        duel_file_append(path, DUEL_GENERATIONS_HEADER) != 0)
        goto fail;
    for (p = 0; p < 2; p++) {
        const neat_coev_pop_report *pr = &rep->pop[p];
        snprintf(row, sizeof row, "%u,%s,%.0f,%.4f,%u,%.4f,%.4f,%.4f,%u,%u,%u,%u,%u,%u,%llu,%d,%.3f\n",
                 rep->generation, duel_pop_name(p), pr->best_fitness, pr->mean_fitness, pr->species, pr->delta_t,
                 pr->mean_hidden, pr->mean_conns, pr->best_hidden, pr->best_conns, pr->min_hidden, pr->max_hidden,
                 pr->min_conns, pr->max_conns, (unsigned long long)pr->games, rep->champion_pop == p, secs);
        if (duel_file_append(path, row) != 0)
            goto fail;
    }

    if (rep->new_dominant) {
        neat_dominant d;
        char *drow;
        int bad;
        neat_coev_dominant(R->coev, rep->dominants - 1u, &d);
        duel_path(path, sizeof path, R->dir, "dominance.csv");
        if ((stat(path, &st) != 0 || st.st_size == 0) && duel_file_append(path, DUEL_DOMINANCE_HEADER) != 0)
            goto fail;
        /* "w:l" against d(n-1), d(n-2), ..., d1: the comparisons it won, in the order played */
        drow = duel_dominance_row_text(rep->dominants, d.generation, duel_pop_name(d.pop)[0],
                                       neat_genome_hidden_count(d.genome), neat_genome_enabled_count(d.genome),
                                       d.n_beaten, d.wins, d.losses);
        if (drow == NULL) {
            errno = ENOMEM;
            goto fail;
        }
        bad = duel_file_append(path, drow) != 0;
        free(drow);
        if (bad)
            goto fail;
    }
    if (duel_strength(R, rep->generation, neat_coev_champion(R->coev)) != 0)
        return -1;
    return duel_save_checkpoint(R);
fail:
    fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    return -1;
}

/* Every K generations ([run] strength_every: generations 0, K, 2K, ...; not
 * "and the last", which would depend on where a run was extended): the
 * champion of generation g against every builtin strategy, 288 games each,
 * into strength.csv (the absolute strength a run reaches, which the
 * dominance ranking, relative to the run itself, does not show). */
static const char *duel_s(uint32_t n);
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
static int duel_strength_row(duel_run *R, uint32_t g, const uint8_t *blob, size_t len, char *row, size_t cap)
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

static int duel_strength(duel_run *R, uint32_t g, const neat_genome *champ)
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
        fprintf(stderr, "duel_evolve: generation %u: the champion's strength could not be measured\n", g);
        return -1;
    }
    duel_path(path, sizeof path, R->dir, "strength.csv");
    if (stat(path, &st) != 0 || st.st_size == 0) {
        char head[600];
        duel_strength_header(head, sizeof head, !R->strength_old);
        if (duel_file_append(path, head) != 0)
            goto fail;
    }
    if (duel_file_append(path, row) == 0)
        return 0;
fail:
    fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    return -1;
}

/* strength.csv must hold a row for every measured generation before g (0, K, 2K, ...): a lost row (a deleted or
 * truncated file, a partial last line) is measured again from champions/gen-G.blob, which gives the same bytes;
 * one whose champion is gone too is refused with what works. Rows after g were cut already. 0, or the exit status
 * after one line. */
/* 1 when hex (16 digits) names the blob of a champion of generation q: for a coevolution, one of the two
 * populations' bests the checkpoint's Halls of Fame hold; for a run against fixed opponents (whose checkpoint keeps
 * no earlier champion), its champions/gen-q.blob. 0 otherwise. */
static int duel_strength_champion_ok(duel_run *R, uint32_t q, const char *hex)
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
        duel_path(path, sizeof path, R->dir, name);
        if (duel_file_read(path, DUEL_GENOME_MAX, &b, &len) != 0)
            return 0;
        snprintf(want, sizeof want, "%016llx", (unsigned long long)duel_blob_hash(b, len));
        free(b);
        return strcmp(want, hex) == 0;
    }
}

static int duel_rebuild_strength(duel_run *R, uint32_t g)
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
    duel_path(path, sizeof path, R->dir, "strength.csv");
    r = duel_file_read(path, DUEL_STRENGTH_MAX_FILE, &have, &have_len);
    if (r != 0 && errno != ENOENT) {
        fprintf(stderr, "duel_evolve: %s: %s: refusing to replace it\n", duel_esc(path), duel_file_strerror(errno));
        return 2;
    }
    /* the file's format: with the champion column (checked below) or, when it was written without, so on */
    duel_strength_header(head, sizeof head, 0);
    R->strength_old = have != NULL && have_len >= strlen(head) && memcmp(have, head, strlen(head)) == 0;
    duel_strength_header(head, sizeof head, !R->strength_old);
    if ((mem = open_memstream(&text, &len)) == NULL) {
        free(have);
        fprintf(stderr, "duel_evolve: resume: out of memory\n");
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
                duel_log(R, "resume: strength.csv: generation %u's row was not of the run's champion (%s): measured "
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
            duel_path(bpath, sizeof bpath, R->dir, name);
            if (duel_file_read(bpath, DUEL_GENOME_MAX, &blob, &blen) != 0) {
                fprintf(stderr, "duel_evolve: %s: generation %u's row is lost and cannot be measured again without "
                                "%s (%s): restore either, or resume with --set strength_every=0 to measure "
                                "nothing more\n",
                        duel_esc(path), q, name, duel_file_strerror(errno));
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
                fprintf(stderr, "duel_evolve: %s/%s is not one of generation %u's bests in the checkpoint (a file put "
                                "in its place): restore it, or resume with --set strength_every=0 to measure nothing "
                                "more\n", duel_esc(R->dir), name, q);
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
            fprintf(stderr, "duel_evolve: %s: generation %u's row could not be measured again from %s\n", duel_esc(path), q,
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
        fprintf(stderr, "duel_evolve: resume: out of memory\n");
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
        fprintf(stderr, "duel_evolve: %s: cannot rewrite: %s\n", duel_esc(path), duel_file_strerror(errno));
    else
        duel_log(R, "resume: strength.csv rebuilt (%u row%s measured again from champions/)", measured,
                 duel_s(measured));
    free(text);
    return r;
}

/* Opponent k's name in generations.csv's columns: its builtin's, or o1, o2, ... */
static void duel_opp_label(const duel_run *R, uint32_t k, char *buf, size_t cap)
{
    if (R->opp[k].blob == NULL)
        snprintf(buf, cap, "%s", duel_builtin_name((int)R->opp[k].len));
    else
        snprintf(buf, cap, "o%u", k + 1u);
}

/* A generation of a run against fixed opponents: its champion's blob and
 * genome, its row of generations.csv (the champion's wins, losses, draws
 * and timeouts against each opponent), the strength, the checkpoint. */
static int duel_record_fixed(duel_run *R, const duel_fixed_report *rep, double secs)
{
    char path[4200], row[4000], label[32];
    neat_genome_origin origin;
    neat_pop *pop = duel_fixed_pop(R->fixed);
    const neat_params *np = neat_pop_params(pop);
    const neat_genome *champ = neat_pop_last_best(pop);
    struct stat st;
    size_t at;
    uint32_t k;

    snprintf(row, sizeof row, "champions/gen-%05u.blob", rep->generation);
    duel_path(path, sizeof path, R->dir, row);
    if (duel_write_blob(path, champ, np) != 0)
        return -1;
    snprintf(row, sizeof row, "champions/gen-%05u.genome", rep->generation);
    duel_path(path, sizeof path, R->dir, row);
    if (duel_genome_write(path, champ, np->n_inputs, np->n_outputs,
                          duel_origin_of(&origin, np, NULL, pop)) != 0)
        return -1;
    duel_path(path, sizeof path, R->dir, "generations.csv");
    if (stat(path, &st) != 0 || st.st_size == 0) {
        at = (size_t)snprintf(row, sizeof row, "generation,best_fitness,mean_fitness,species,delta_t,mean_hidden,"
                                               "mean_connections,best_hidden,best_connections,host_games,games");
        for (k = 0; k < R->cfg.opp.n; k++) {
            duel_opp_label(R, k, label, sizeof label);
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
    if (duel_strength(R, rep->generation, champ) != 0)
        return -1;
    return duel_save_checkpoint(R);
fail:
    fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
    return -1;
}

static void duel_clear_bar(duel_run *R)
{
    if (R->bar_shown) {
        fprintf(stderr, "\r%-79s\r", "");
        R->bar_shown = 0;
    }
}

static void duel_on_progress(void *ud, uint64_t done, uint64_t total)
{
    duel_run *R = (duel_run *)ud;
    char bar[31];
    int i, fill = total ? (int)(30 * done / total) : 30;
    double now;
    if (R->quiet || !R->tty)
        return;
    /* about five redraws a second, whatever the batches */
    now = duel_now();
    if (now - R->bar_drawn < 0.2)
        return;
    R->bar_drawn = now;
    for (i = 0; i < 30; i++)
        bar[i] = i < fill ? '=' : (i == fill ? '>' : ' ');
    bar[30] = '\0';
    fprintf(stderr, "\rgeneration %u [%s] %llu/%llu games of this batch", R->gen_in_flight, bar,
            (unsigned long long)done, (unsigned long long)total);
    fflush(stderr);
    R->bar_shown = 1;
}

static void duel_eta(char *out, size_t cap, double secs)
{
    long s = (long)(secs + 0.5);
    if (s >= 3600)
        snprintf(out, cap, "%ldh%02ldm", s / 3600, s / 60 % 60);
    else if (s >= 60)
        snprintf(out, cap, "%ldm%02lds", s / 60, s % 60);
    else
        snprintf(out, cap, "%lds", s);
}

/* "1 hidden node", "2 hidden nodes" */
static const char *duel_s(uint32_t n)
{
    return n == 1 ? "" : "s";
}

/* The threads a run plays on, in words: "2 threads", or "all 4 cores" for 0. */
static void duel_threads_words(uint32_t threads, char *buf, size_t cap)
{
    if (threads == 0) {
        uint32_t cores = duel_cores();
        snprintf(buf, cap, "all %u core%s", cores, duel_s(cores));
    } else {
        snprintf(buf, cap, "%u thread%s", threads, duel_s(threads));
    }
}

static void duel_report(duel_run *R, const neat_coev_report *rep, double secs)
{
    neat_dominant d;
    /* what the scores are out of: a host's games (its fitness is its wins), a comparison's games */
    uint32_t host_games = (uint32_t)(rep->pop[0].games / (R->cfg.neat.pop_size ? R->cfg.neat.pop_size : 1u));
    uint32_t cmp_games = 2u * R->eff.coev.compare_configs, cw = rep->champion_pop;
    uint32_t dh, dc;
    uint32_t gens_done = rep->generation + 1u - R->first_gen, left = R->cfg.generations - rep->generation - 1u;
    double elapsed = duel_now() - R->started, gps = secs > 0 ? rep->games / secs : 0;
    char eta[32];
    neat_coev_dominant(R->coev, rep->dominants - 1u, &d);
    dh = neat_genome_hidden_count(d.genome);
    dc = neat_genome_enabled_count(d.genome);
    duel_eta(eta, sizeof eta, elapsed / gens_done * left);
    duel_clear_bar(R);
    if (!R->quiet)
        fprintf(stderr,
                "gen %u (%u/%u)  best A %.0f/%u B %.0f/%u wins  species A %u B %u  champion %s %u:%u of %u  "
                "dominance %u%s (%u hidden, %u conns)  %.0f games/s  ETA %s\n",
                rep->generation, rep->generation + 1u, R->cfg.generations, rep->pop[0].best_fitness, host_games,
                rep->pop[1].best_fitness, host_games, rep->pop[0].species, rep->pop[1].species, duel_pop_name(cw),
                rep->champion_wins[cw], rep->champion_wins[cw ^ 1u], cmp_games, rep->dominants,
                rep->new_dominant ? " new" : "", dh, dc, gps, eta);
    if (R->json) {
        uint32_t p;
        printf("{\"generation\":%u,\"pop\":[", rep->generation);
        for (p = 0; p < 2; p++) {
            const neat_coev_pop_report *pr = &rep->pop[p];
            printf("%s{\"best\":%.0f,\"mean\":%.4f,\"species\":%u,\"delta_t\":%.4f,\"mean_hidden\":%.4f,"
                   "\"mean_connections\":%.4f,\"best_hidden\":%u,\"best_connections\":%u}",
                   p ? "," : "", pr->best_fitness, pr->mean_fitness, pr->species, pr->delta_t, pr->mean_hidden,
                   pr->mean_conns, pr->best_hidden, pr->best_conns);
        }
        printf("],\"champion\":\"%s\",\"champion_wins\":[%u,%u],\"dominance\":%u,\"new_dominant\":%s,"
               "\"dominant_hidden\":%u,\"dominant_connections\":%u,\"games\":%llu,\"seconds\":%.3f,"
               "\"games_per_s\":%.0f,\"eta_s\":%.0f}\n",
               duel_pop_name(rep->champion_pop), rep->champion_wins[0], rep->champion_wins[1], rep->dominants,
               rep->new_dominant ? "true" : "false", dh, dc, (unsigned long long)rep->games, secs, gps,
               elapsed / gens_done * left);
        fflush(stdout);
    }
    duel_log(R, "generation %u: best A %.0f/%u B %.0f/%u wins, species A %u B %u, champion %s %u:%u of %u, "
                "dominance %u (%s%u hidden node%s, %u connection%s), %llu games in %.2f s",
             rep->generation, rep->pop[0].best_fitness, host_games, rep->pop[1].best_fitness, host_games,
             rep->pop[0].species, rep->pop[1].species, duel_pop_name(cw), rep->champion_wins[cw],
             rep->champion_wins[cw ^ 1u], cmp_games, rep->dominants, rep->new_dominant ? "new: " : "", dh,
             duel_s(dh), dc, duel_s(dc), (unsigned long long)rep->games, secs);
}


/* A generation of a run against fixed opponents on stderr (and --json, log.txt) */
static void duel_report_fixed(duel_run *R, const duel_fixed_report *rep, double secs)
{
    uint32_t gens_done = rep->generation + 1u - R->first_gen, left = R->cfg.generations - rep->generation - 1u, k;
    double elapsed = duel_now() - R->started, gps = secs > 0 ? rep->games / secs : 0;
    char eta[32], vs[600], label[32];
    size_t at = 0;
    vs[0] = '\0';
    for (k = 0; k < R->cfg.opp.n && at < sizeof vs; k++) {
        duel_opp_label(R, k, label, sizeof label);
        at += (size_t)snprintf(vs + at, sizeof vs - at, "%s%s %u:%u", k ? ", " : "", label, rep->best_vs[k].wins_a,
                               rep->best_vs[k].wins_b);
    }
    duel_eta(eta, sizeof eta, elapsed / gens_done * left);
    duel_clear_bar(R);
    if (!R->quiet)
        fprintf(stderr, "gen %u (%u/%u)  best %.0f  mean %.2f  species %u  champion (%u hidden, %u conns) vs %s  "
                        "%.0f games/s  ETA %s\n",
                rep->generation, rep->generation + 1u, R->cfg.generations, rep->best_fitness, rep->mean_fitness,
                rep->species, rep->best_hidden, rep->best_conns, vs, gps, eta);
    if (R->json) {
        printf("{\"generation\":%u,\"best\":%.0f,\"mean\":%.4f,\"species\":%u,\"delta_t\":%.4f,"
               "\"mean_hidden\":%.4f,\"mean_connections\":%.4f,\"best_hidden\":%u,\"best_connections\":%u,"
               "\"against\":[",
               rep->generation, rep->best_fitness, rep->mean_fitness, rep->species, rep->delta_t, rep->mean_hidden,
               rep->mean_conns, rep->best_hidden, rep->best_conns);
        for (k = 0; k < R->cfg.opp.n; k++) {
            duel_opp_label(R, k, label, sizeof label);
            printf("%s{\"opponent\":\"%s\",\"wins\":%u,\"losses\":%u,\"draws\":%u,\"timeouts\":%u}", k ? "," : "",
                   label, rep->best_vs[k].wins_a, rep->best_vs[k].wins_b, rep->best_vs[k].draws,
                   rep->best_vs[k].timeouts);
        }
        printf("],\"games\":%llu,\"seconds\":%.3f,\"games_per_s\":%.0f,\"eta_s\":%.0f}\n",
               (unsigned long long)rep->games, secs, gps, elapsed / gens_done * left);
        fflush(stdout);
    }
    duel_log(R, "generation %u: best fitness %.0f (%u games a host), mean %.2f, species %u, champion %u hidden node%s, "
                "%u connection%s, against %s; %llu games in %.2f s",
             rep->generation, rep->best_fitness, rep->host_games, rep->mean_fitness, rep->species, rep->best_hidden,
             duel_s(rep->best_hidden), rep->best_conns, duel_s(rep->best_conns), vs, (unsigned long long)rep->games,
             secs);
}

/* Generations until the configured count, a signal or an error. */
/* The [overrides] that start at generation g, applied to the run before it plays g (as a resume at g applies them
 * to its checkpoint: the same run either way). 0, or 2 after one line. */
static int duel_apply_overrides(duel_run *R, uint32_t g)
{
    char err[600];
    uint32_t k;
    int e;
    for (k = 0; k < R->cfg.n_over && R->cfg.over[k].from != g; k++)
        ;
    if (k == R->cfg.n_over || R->first_applied == g + 1u)
        return 0; /* none, or applied already by the resume that starts here */
    if (duel_config_at(&R->cfg, g, &R->eff, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    e = R->fixed != NULL ? neat_pop_set_params(duel_fixed_pop(R->fixed), &R->eff.neat)
                         : neat_coev_set_params(R->coev, &R->eff.neat, &R->eff.coev);
    if (e) {
        fprintf(stderr, "duel_evolve: [overrides] from %u: %s\n", g, neat_strerror(e));
        return 2;
    }
    duel_games_set_params(R->games, &R->eff.neat);
    duel_log(R, "generation %u: overrides from here on: %s", g, R->cfg.over[k].sets);
    return 0;
}

static int duel_loop(duel_run *R)
{
    duel_stop = 0; /* a process that plays several runs (the Python package) starts each without a stop */
    duel_signal_install(&duel_stop, "duel_evolve: a second signal: stopped at once; the last checkpoint stands "
                                    "(duel_evolve resume continues from it)\n");
    R->tty = isatty(2);
    R->started = duel_now();
    R->first_gen = duel_next_gen(R);
    duel_games_on_progress(R->games, duel_on_progress, R);
    while (duel_next_gen(R) < R->cfg.generations) {
        neat_coev_report rep;
        duel_fixed_report frep;
        double t0 = duel_now(), secs;
        int err;
        if (R->log_failed)
            return 1; /* what was done is saved; resume continues from it */
        if (duel_stop || duel_mpi_stop_requested()) {
            uint32_t n = duel_next_gen(R);
            duel_clear_bar(R);
            duel_log(R, "interrupted before generation %u", n);
            fprintf(stderr, "duel_evolve: interrupted; %u generation%s saved. Resume with: duel_evolve resume %s\n",
                    n, n == 1 ? " is" : "s are", duel_esc(R->dir));
            return 130;
        }
        R->gen_in_flight = duel_next_gen(R);
        if ((err = duel_apply_overrides(R, R->gen_in_flight)) != 0)
            return err;
        if (R->fixed != NULL) {
            err = duel_fixed_step(R->fixed, R->games, &frep);
        } else {
            duel_games_set_training(R->games, duel_train_config(&R->cfg, R->gen_in_flight));
            err = neat_coev_step(R->coev, duel_games_play, R->games, &rep);
        }
        if (err) {
            duel_clear_bar(R);
            fprintf(stderr, "duel_evolve: generation %u failed: %s\n", R->gen_in_flight, duel_game_error(err));
            duel_log(R, "generation %u failed: %s", R->gen_in_flight, duel_game_error(err));
            return 1;
        }
        secs = duel_now() - t0;
        R->gen_secs += secs;
        if (R->fixed != NULL) {
            if (duel_record_fixed(R, &frep, secs) != 0)
                return 1;
            duel_report_fixed(R, &frep, secs);
            continue;
        }
        if (duel_record(R, &rep, secs) != 0)
            return 1;
        duel_report(R, &rep, secs);
    }
    if (duel_stop) {
        duel_log(R, "interrupted after the last generation");
        fprintf(stderr, "duel_evolve: interrupted; the run is complete (%u generations)\n", R->cfg.generations);
        return 130;
    }
    if (R->fixed != NULL) {
        const neat_genome *b = neat_pop_last_best(duel_fixed_pop(R->fixed));
        uint32_t dh = neat_genome_hidden_count(b), dc = neat_genome_enabled_count(b);
        duel_log(R, "finished %u generation%s: the last champion has %u hidden node%s, %u connection%s",
                 R->cfg.generations, duel_s(R->cfg.generations), dh, duel_s(dh), dc, duel_s(dc));
        if (R->log_failed)
            return 1;
        if (!R->quiet)
            fprintf(stderr, "done: %u generation%s in %s; the last champion: %u hidden node%s, %u connection%s "
                            "(champions/gen-%05u.blob)\n", R->cfg.generations, duel_s(R->cfg.generations), duel_esc(R->dir),
                    dh, duel_s(dh), dc, duel_s(dc), R->cfg.generations - 1u);
        return 0;
    }
    {
        neat_dominant d;
        uint32_t n = neat_coev_dominant_count(R->coev), dh, dc;
        neat_coev_dominant(R->coev, n - 1u, &d);
        dh = neat_genome_hidden_count(d.genome);
        dc = neat_genome_enabled_count(d.genome);
        duel_log(R, "finished %u generation%s: dominance level %u, top dominant from generation %u (%u hidden node%s, "
                    "%u connection%s)",
                 R->cfg.generations, duel_s(R->cfg.generations), n, d.generation, dh, duel_s(dh), dc, duel_s(dc));
        if (R->log_failed)
            return 1;
        if (!R->quiet)
            fprintf(stderr, "done: %u generation%s in %s; dominance level %u; top dominant: generation %u, %u "
                            "hidden node%s, %u connection%s (champions/gen-%05u.blob)\n",
                    R->cfg.generations, duel_s(R->cfg.generations), duel_esc(R->dir), n, d.generation, dh, duel_s(dh), dc,
                    duel_s(dc), d.generation);
    }
    return 0;
}

static int duel_parse_u32(const char *opt, const char *v, uint32_t lo, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long long x;
    errno = 0;
    x = v != NULL ? strtoull(v, &end, 10) : 0;
    if (v == NULL || end == v || *end != '\0' || errno != 0 || x < lo || x > hi || v[0] == '-') {
        fprintf(stderr, "duel_evolve: %s takes an integer in [%u, %u], not '%s'\n", opt, lo, hi, duel_esc(v));
        return -1;
    }
    *out = (uint32_t)x;
    return 0;
}

/* The lock of this process's run directory (-1: none), given back when the command ends: an MPI rank executes
 * one experiment task after another in one process. */
static duel_lock duel_run_lock = {-1, -1};

/* One process per run directory: a second run or resume there is refused. */
static int duel_take_lock(const char *dir)
{
    if (duel_dir_lock(dir, &duel_run_lock) == 0)
        return 0;
    if (errno == EWOULDBLOCK)
        fprintf(stderr, "duel_evolve: %s is in use by another duel_evolve run or resume\n", duel_esc(dir));
    else if (errno == ELOOP)
        fprintf(stderr, "duel_evolve: %s/.lock is a symbolic link: refusing to follow it (remove it)\n", duel_esc(dir));
    else
        fprintf(stderr, "duel_evolve: %s/.lock: cannot open: %s\n", duel_esc(dir), strerror(errno));
    return -1;
}

/* The options run and resume share: --generations, --threads, --quiet,
 * --json, --record-champion-games. 1 when argv[*i] was one (and *i is past
 * its value), 0 when it is not, -1 after a message on a bad value. */
static int duel_common_option(duel_run *R, int argc, char **argv, int *i, uint32_t *gens, int *have_gens)
{
    const char *a = argv[*i], *v = *i + 1 < argc ? argv[*i + 1] : NULL;
    if (strcmp(a, "--generations") == 0) {
        if (duel_parse_u32(a, v, 1, 1000000, gens))
            return -1;
        *have_gens = 1;
        ++*i;
    } else if (strcmp(a, "--threads") == 0) {
        if (duel_parse_u32(a, v, 0, 256, &R->threads))
            return -1;
        ++*i;
    } else if (strcmp(a, "--quiet") == 0) {
        R->quiet = 1;
    } else if (strcmp(a, "--json") == 0) {
        R->json = 1;
    } else if (strcmp(a, "--record-champion-games") == 0) {
        R->record_games = 1;
    } else {
        return 0;
    }
    return 1;
}

/* A run directory without a checkpoint: a run that died during generation
 * 0 may have recorded that generation's rows and blob (they are redone), but
 * anything of a later generation means a checkpoint existed and is gone:
 * starting over (run) or from generation 0 (resume) would discard or mix
 * what was recorded, so such a directory is refused. 1 (what in msg), or 0. */
static int duel_has_history(const char *dir, char *msg, size_t cap)
{
    char path[4200];
    uint8_t *data;
    size_t len, i;
    unsigned long rows = 0, blobs = 0;
    DIR *d;
    struct dirent *e;
    duel_path(path, sizeof path, dir, "generations.csv");
    if (duel_file_read(path, DUEL_GENERATIONS_MAX_FILE, &data, &len) == 0) {
        /* rows whose generation (the first field) is not 0 */
        for (i = 0; i < len; i++)
            if ((i == 0 || data[i - 1] == '\n') && data[i] >= '0' && data[i] <= '9' &&
                !(data[i] == '0' && i + 1 < len && data[i + 1] == ','))
                rows++;
        free(data);
    }
    duel_path(path, sizeof path, dir, "champions");
    d = opendir(path);
    if (d != NULL) {
        while ((e = readdir(d)) != NULL) {
            size_t n = strlen(e->d_name);
            blobs += n > 5 && strcmp(e->d_name + n - 5, ".blob") == 0 && strcmp(e->d_name, "gen-00000.blob") != 0;
        }
        closedir(d);
    }
    if (rows == 0 && blobs == 0)
        return 0;
    snprintf(msg, cap, "%lu rows of generations.csv and %lu champion blobs of generations after 0", rows, blobs);
    return 1;
}

static int duel_go(duel_run *R)
{
    uint32_t ranks = duel_mpi_games_ranks(), hosts = 2u * R->cfg.neat.pop_size;
    char line[400];
    int err;
    if (ranks > hosts) {
        /* a generation's host games go out one host's games at a time: more ranks than hosts would wait */
        fprintf(stderr, "duel_evolve: %u MPI ranks for a run of 2 x %u networks: at most %u ranks can play its "
                        "games\n", ranks, R->cfg.neat.pop_size, hosts);
        duel_run_free(R);
        return 2;
    }
    err = duel_games_create(&R->games, R->threads == 0 && ranks > 1 ? duel_mpi_default_threads() : R->threads,
                            &R->eff.neat);
    if (err) {
        fprintf(stderr, "duel_evolve: out of memory\n");
        return 1;
    }
    if (duel_games_set_rules(R->games, &R->cfg.world) != 0) {
        fprintf(stderr, "duel_evolve: the run's [world] rules cannot make a game\n");
        duel_games_free(R->games);
        duel_run_free(R);
        return 2;
    }
    duel_mpi_attach(R->games);
    if (ranks > 1)
        duel_log(R, "mpi: %u ranks, %u thread%s on rank 0", ranks, duel_games_threads(R->games),
                 duel_games_threads(R->games) == 1 ? "" : "s");
    err = duel_loop(R);
    if (R->gen_secs > 0)
        duel_log(R, "time: %.2f s in generations, %.2f s of it (%.1f %%) playing their %llu games",
                 R->gen_secs, duel_games_seconds(R->games), 100.0 * duel_games_seconds(R->games) / R->gen_secs,
                 (unsigned long long)duel_games_played(R->games));
    duel_mpi_describe(line, sizeof line);
    if (line[0] != '\0')
        duel_log(R, "mpi: %s", line);
    if (R->log_failed && err == 0)
        err = 1; /* its last lines are missing from log.txt: said on stderr, and not a success */
    duel_games_free(R->games);
    duel_run_free(R);
    return err;
}

/* The run's tag (duel_run_tag, duel_runtag.c) with its fixed opponents' identities. */
static int duel_run_tag_of(const duel_run *R, uint8_t buf[DUEL_TAG_MAX], size_t *len)
{
    duel_opp_id ids[DUEL_MAX_OPPONENTS];
    uint32_t k;
    for (k = 0; k < R->cfg.opp.n; k++) {
        ids[k].is_blob = R->opp[k].blob != NULL;
        ids[k].id = R->opp[k].blob != NULL ? duel_blob_hash(R->opp[k].blob, R->opp[k].len) : (uint64_t)R->opp[k].len;
    }
    return duel_run_tag(&R->cfg, ids, buf, len);
}

static int duel_tag_run(duel_run *R)
{
    uint8_t tag[DUEL_TAG_MAX];
    size_t len;
    int e = duel_run_tag_of(R, tag, &len);
    if (e)
        return e;
    return R->fixed != NULL ? neat_pop_set_game(duel_fixed_pop(R->fixed), tag, len)
                            : neat_coev_set_game(R->coev, tag, len);
}

/* A resumed run's tag against config.ini's: 0, or -1 after one line naming
 * what changed. An empty tag (a run from before the rules were data) is
 * world v1's with the training food. */
/* The overrides a tag records from before generation g against config.ini's: the same lines, in the same order
 * (a change to one the run has played is a hand edit; those from g on are still to come). 1 when they agree. */
static int duel_tag_overrides_agree(const duel_config *cfg, const uint8_t *tag, size_t len, uint32_t g)
{
    size_t at = duel_run_tag_overrides(tag, len);
    uint32_t n = 0, k, j = 0;
    if (at < len) {
        at += 4;
        if (at + 4 > len)
            return 0;
        n = (uint32_t)tag[at] | (uint32_t)tag[at + 1] << 8 | (uint32_t)tag[at + 2] << 16 | (uint32_t)tag[at + 3] << 24;
        at += 4;
    }
    for (k = 0; k < n; k++) {
        uint32_t from, tl;
        if (at + 8 > len)
            return 0;
        from = (uint32_t)tag[at] | (uint32_t)tag[at + 1] << 8 | (uint32_t)tag[at + 2] << 16 |
               (uint32_t)tag[at + 3] << 24;
        tl = (uint32_t)tag[at + 4] | (uint32_t)tag[at + 5] << 8 | (uint32_t)tag[at + 6] << 16 |
             (uint32_t)tag[at + 7] << 24;
        at += 8;
        if (tl > len - at)
            return 0;
        if (from < g) {
            if (j >= cfg->n_over || cfg->over[j].from != from || strlen(cfg->over[j].sets) != tl ||
                memcmp(cfg->over[j].sets, tag + at, tl) != 0)
                return 0;
            j++;
        }
        at += tl;
    }
    /* config.ini has no line before g that the checkpoint lacks */
    return j == cfg->n_over || cfg->over[j].from >= g;
}

static int duel_check_tag(const duel_run *R, const uint8_t *tag, size_t len, const char *path, uint32_t g)
{
    uint8_t want[DUEL_TAG_MAX];
    size_t wlen;
    duel_rules made;
    char a[40], b[40];
    if (duel_run_tag_of(R, want, &wlen) != 0)
        return -1;
    made = *duel_rules_v1();
    if (len > 0 && duel_rules_decode(&made, tag, len < DUEL_RULES_BYTES ? len : DUEL_RULES_BYTES, NULL) != DUEL_OK) {
        fprintf(stderr, "duel_evolve: %s: its world's rules (the game tag) are damaged\n", duel_esc(path));
        return -1;
    }
    if (!duel_rules_equal(&made, &R->cfg.world)) {
        fprintf(stderr, "duel_evolve: %s: the run was made in world %s, but config.ini's [world] says %s: a run's "
                        "rules cannot change (restore config.ini, or start a new run)\n", duel_esc(path),
                duel_world_label(&made, a, sizeof a), duel_world_label(&R->cfg.world, b, sizeof b));
        return -1;
    }
    if (len > 0 && !duel_tag_overrides_agree(&R->cfg, tag, len, g)) {
        fprintf(stderr, "duel_evolve: %s: the run was played with other [overrides] before generation %u than "
                        "config.ini says (a hand edit): restore config.ini\n", duel_esc(path), g);
        return -1;
    }
    /* what makes the games, the overrides apart (compared above) */
    len = duel_run_tag_overrides(tag, len);
    wlen = duel_run_tag_overrides(want, wlen);
    if (len == 0 ? R->cfg.train_layouts != DUEL_TRAIN_FIXED || R->cfg.opp.n != 0
                 : len != wlen || memcmp(tag, want, len) != 0) {
        fprintf(stderr, "duel_evolve: %s: the run was made with other games than config.ini now makes ([run] "
                        "train_layouts, [opponents], their files in opponents/, or net_step changed): restore them, "
                        "or start a new run\n", duel_esc(path));
        return -1;
    }
    return 0;
}

/* The opponents of a run against fixed ones: builtin:NAME as a builtin,
 * any other name a blob or genome file (a genome's network as a sync blob)
 * checked by the runtime, with the duel's 13 inputs and 3 outputs. From
 * config.ini's names (a new run), or (copies = 1) from the run's own
 * copies, opponents/NN.blob, which a new run writes so that its games never
 * depend on files outside it. 0, or 2 after one line on stderr. */
static int duel_load_opponents(duel_run *R, int copies)
{
    char path[4200];
    uint32_t k;
    for (k = 0; k < R->cfg.opp.n; k++) {
        const char *spec = R->cfg.opp.spec[k];
        uint8_t *blob;
        size_t len, need;
        void *mem;
        nrt_net net;
        duel_origin origin;
        int e;
        if (strncmp(spec, "builtin:", 8) == 0) {
            R->opp[k].blob = NULL;
            R->opp[k].len = (size_t)duel_builtin_parse(spec + 8);
            continue;
        }
        if (copies)
            snprintf(path, sizeof path, "%s/opponents/%02u.blob", R->dir, k + 1u);
        else
            snprintf(path, sizeof path, "%s", spec);
        if (duel_cli_read_blob_origin(path, &blob, &len, &origin) != 0)
            return 2;
        /* an opponent plays in the run's world: one made in another is said to be so, on stderr and in the log */
        if (!copies && origin.world_from != DUEL_ORIGIN_NONE && !duel_rules_equal(&origin.world, &R->cfg.world)) {
            char a[40], b[40];
            fprintf(stderr, "duel_evolve: note: [opponents] %s was made in world %s; this run plays it in its own "
                            "world, %s\n",
                    duel_esc(path), duel_world_label(&origin.world, a, sizeof a), duel_world_label(&R->cfg.world, b, sizeof b));
            snprintf(R->opp_note, sizeof R->opp_note, "[opponents] %s was made in world %s; played in the run's "
                     "world, %s", path, a, b);
        }
        e = nrt_mem_required(blob, len, &need);
        mem = e == 0 ? malloc(need) : NULL;
        if (e == 0 && mem == NULL)
            e = NRT_E_NOMEM;
        if (e == 0)
            e = nrt_load(&net, blob, len, mem, need);
        if (e == 0 && (net.n_inputs != DUEL_N_INPUTS || net.n_outputs != DUEL_N_OUTPUTS))
            e = NRT_E_COUNTS;
        free(mem);
        if (e != 0) {
            fprintf(stderr, "duel_evolve: [opponents] %s: not a duel controller: %s\n", duel_esc(path),
                    e == NRT_E_COUNTS ? "it does not have the duel's 13 inputs and 3 outputs" : nrt_strerror(e));
            free(blob);
            return 2;
        }
        R->opp[k].blob = blob;
        R->opp[k].len = len;
    }
    return 0;
}

/* A new run's copies of its opponents' blobs: opponents/NN.blob */
static int duel_copy_opponents(const duel_run *R)
{
    char path[4200];
    uint32_t k;
    if (R->cfg.opp.n == 0)
        return 0;
    snprintf(path, sizeof path, "%s/opponents", R->dir);
    if (duel_mkdir(path) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot create: %s\n", duel_esc(path), strerror(errno));
        return -1;
    }
    for (k = 0; k < R->cfg.opp.n; k++) {
        if (R->opp[k].blob == NULL)
            continue;
        snprintf(path, sizeof path, "%s/opponents/%02u.blob", R->dir, k + 1u);
        if (duel_file_replace(path, R->opp[k].blob, R->opp[k].len) != 0) {
            fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
            return -1;
        }
    }
    return 0;
}

/* Another NEAT's reproduction, registered by a program that holds one (duel_cli.h). */
static duel_reproducer duel_other;
static int duel_have_other;

void duel_run_set_reproducer(const duel_reproducer *r)
{
    duel_have_other = r != NULL;
    if (r != NULL)
        duel_other = *r;
}

/* A run whose [run] reproduction is another NEAT's: refused unless this program holds it. 0, or 2 after
 * one line on stderr. */
static int duel_check_reproduction(const duel_run *R)
{
    if (R->cfg.reproduction == DUEL_REPRODUCE_LIBNEAT)
        return 0;
    if (R->cfg.opp.n > 0) {
        fprintf(stderr, "duel_evolve: [run] reproduction = neat-cpp-1.2.1 reproduces a coevolution's populations; a run "
                        "against fixed opponents ([opponents] play) has libneat's only\n");
        return 2;
    }
    if (!duel_have_other || duel_other.which != R->cfg.reproduction) {
        fprintf(stderr, "duel_evolve: [run] reproduction = neat-cpp-1.2.1 is NEAT C++ 1.2.1's own reproduction: only "
                        "neatcpp_duel, built against a checkout of the release, runs it (tools/neatcpp/build.sh, "
                        "docs/neat-cpp.md)\n");
        return 2;
    }
    return 0;
}

/* The two populations from the configuration's start topology. 0, or -1
 * after one line on stderr (2: the configuration's fault, 1: the machine's). */
static int duel_create(duel_run *R)
{
    char err[DUEL_START_MAX_PATH + 200];
    neat_genome g;
    neat_start st;
    int e;
    if ((e = duel_check_reproduction(R)) != 0)
        return e;
    /* generation 0's parameters: [overrides] start later (from 1 on) */
    if (duel_config_at(&R->cfg, 0, &R->eff, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (R->cfg.n_over > 0 && R->cfg.reproduction != DUEL_REPRODUCE_LIBNEAT) {
        fprintf(stderr, "duel_evolve: [overrides] with [run] reproduction = neat-cpp-1.2.1: the release's "
                        "reproduction takes its parameters once; give them in [neat]\n");
        return 2;
    }
    if (R->cfg.opp.n == 0) {
        /* a coevolution: as the Python package starts one (duel_runtag.c) */
        e = duel_coev_new(&R->coev, &R->eff, err, sizeof err);
        if (e)
            fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        if (e == 0 && R->cfg.n_over > 0 && (e = duel_tag_run(R)) != 0)
            fprintf(stderr, "duel_evolve: cannot start: %s\n", neat_strerror(e)); /* the tag with the schedule */
        if (e == 0 && R->cfg.reproduction != DUEL_REPRODUCE_LIBNEAT) {
            /* the other NEAT's populations replace libneat's from generation 0 on */
            if (duel_other.begin(duel_other.ud, &R->eff) != 0)
                return 2;
            e = neat_coev_set_reproducer(R->coev, duel_other.reproduce, duel_other.ud);
            if (e) {
                fprintf(stderr, "duel_evolve: NEAT C++ 1.2.1's start: %s\n", neat_strerror(e));
                return 1;
            }
        }
        return e;
    }
    if (duel_start_genome(&R->cfg, &g, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    st.genome = &g;
    st.keep_weights = 0;
    {
        neat_pop *pop = NULL;
        if ((e = duel_load_opponents(R, 0)) != 0) {
            neat_genome_free(&g, NULL);
            return e;
        }
        e = neat_pop_create(&pop, &R->eff.neat, &st, R->cfg.seed, NULL);
        if (e == 0)
            e = duel_fixed_new(&R->fixed, pop, &R->eff, R->opp, R->cfg.opp.n);
    }
    neat_genome_free(&g, NULL);
    if (e == 0)
        e = duel_tag_run(R);
    if (e) {
        fprintf(stderr, "duel_evolve: cannot start: %s\n", neat_strerror(e));
        return 1;
    }
    return 0;
}

/* The start topology in words, for log.txt. */
static void duel_start_words(const duel_run *R, char *buf, size_t cap)
{
    char st[DUEL_START_MAX_PATH + 16];
    duel_start_text(&R->cfg.start, st, sizeof st);
    if (R->fixed != NULL) {
        snprintf(buf, cap, "start %s, one population against %u fixed opponent%s", st, R->cfg.opp.n,
                 duel_s(R->cfg.opp.n));
        return;
    }
    {
        const neat_genome *g = neat_coev_start(R->coev);
        uint32_t h = neat_genome_hidden_count(g), c = neat_genome_enabled_count(g);
        snprintf(buf, cap, "start %s (%u hidden node%s, %u connection%s)%s", st, h, duel_s(h), c, duel_s(c),
                 R->cfg.coev.random_fitness ? ", random fitness" : "");
    }
}

/* 1 when dir/name is an empty directory. */
static int duel_empty_dir(const char *dir, const char *name)
{
    char path[4200];
    DIR *d;
    struct dirent *e;
    int empty = 1;
    duel_path(path, sizeof path, dir, name);
    if ((d = opendir(path)) == NULL)
        return 0;
    while (empty && (e = readdir(d)) != NULL)
        empty = strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0;
    closedir(d);
    return empty;
}

/* Whether an existing directory may become a new run: empty, or a run's own
 * files only, with a config.ini (if any) that a run wrote. 1, or 0 with the
 * first foreign entry in what. */
static int duel_dir_is_runs(const char *dir, char *what, size_t cap)
{
    char path[4200], first[300] = "";
    DIR *d = opendir(dir);
    struct dirent *e;
    uint8_t *text;
    size_t len;
    int ok = 1;
    if (d == NULL) {
        snprintf(what, cap, "cannot be listed: %s", strerror(errno));
        return 0;
    }
    while (ok && (e = readdir(d)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        if (!duel_is_run_file(e->d_name)) {
            char esc[1100];
            snprintf(what, cap, "holds '%s', which is not a run's", duel_text_escape(e->d_name, esc, sizeof esc));
            ok = 0;
        } else if (first[0] == '\0' && strcmp(e->d_name, ".lock") != 0 && strcmp(e->d_name, "config.ini.tmp") != 0 &&
                   !duel_empty_dir(dir, e->d_name)) {
            snprintf(first, sizeof first, "%s", e->d_name);
        }
    }
    closedir(d);
    duel_path(path, sizeof path, dir, "config.ini");
    /* a run writes config.ini before anything else it keeps: files of a run's names without it are someone
     * else's (a user's generations.csv) */
    if (ok && first[0] != '\0' && access(path, F_OK) != 0) {
        char esc[1100];
        snprintf(what, cap, "holds '%s' but no config.ini of a run", duel_text_escape(first, esc, sizeof esc));
        ok = 0;
    }
    if (ok && duel_file_read(path, 1u << 20, &text, &len) == 0) {
        static const char mark[] = DUEL_RUN_CONFIG_MARK;
        ok = len >= sizeof mark - 1 && memcmp(text, mark, sizeof mark - 1) == 0;
        if (!ok)
            snprintf(what, cap, "holds a config.ini that a run did not write");
        free(text);
    } else if (ok && errno != ENOENT) {
        snprintf(what, cap, "config.ini: %s", duel_file_strerror(errno));
        ok = 0;
    }
    return ok;
}

/* A new run's directory: created and locked, refused when it holds a run,
 * the records of one or anything not a run's, cleared of a run that died
 * before its first checkpoint, with config.ini written. 0, or the exit
 * status after one line. */
static int duel_prepare_dir(duel_run *R)
{
    static const char *const files[] = {"generations.csv", "dominance.csv", "strength.csv"};
    char err[600], path[4200];
    struct stat st;
    int i;
    /* looked at before anything is created in it, and again under the lock */
    if (stat(R->dir, &st) == 0 && S_ISDIR(st.st_mode) && !duel_dir_is_runs(R->dir, err, sizeof err)) {
        fprintf(stderr, "duel_evolve: %s is not empty and not a run directory (it %s): choose another --out\n",
                duel_esc(R->dir), duel_esc_msg(err));
        return 2;
    }
    if (duel_mkdir(R->dir) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot create: %s\n", duel_esc(R->dir), strerror(errno));
        return 2;
    }
    if (duel_take_lock(R->dir) != 0)
        return 2;
    if (!duel_dir_is_runs(R->dir, err, sizeof err)) {
        fprintf(stderr, "duel_evolve: %s is not empty and not a run directory (it %s): choose another --out\n",
                duel_esc(R->dir), duel_esc_msg(err));
        return 2;
    }
    duel_path(path, sizeof path, R->dir, "champions");
    if (duel_mkdir(path) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot create: %s\n", duel_esc(path), strerror(errno));
        return 2;
    }
    duel_path(path, sizeof path, R->dir, "checkpoint.bin");
    if (stat(path, &st) == 0) { /* checked under the lock: two runs cannot both pass */
        fprintf(stderr, "duel_evolve: %s already holds a run: resume it with duel_evolve resume %s, or choose "
                        "another --out\n", duel_esc(R->dir), duel_esc(R->dir));
        return 2;
    }
    duel_path(path, sizeof path, R->dir, "games");
    if (R->record_games && duel_mkdir(path) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot create: %s\n", duel_esc(path), strerror(errno));
        return 2;
    }
    /* a directory left by a run that died before its first checkpoint starts over; one whose checkpoint
     * is gone but whose generations are recorded is not overwritten */
    if (duel_has_history(R->dir, err, sizeof err)) {
        fprintf(stderr, "duel_evolve: %s has no checkpoint.bin but holds %s: refusing to overwrite them (restore "
                        "the checkpoint and resume, or choose another --out)\n", duel_esc(R->dir), duel_esc_msg(err));
        return 2;
    }
    for (i = 0; i < 3; i++) {
        duel_path(path, sizeof path, R->dir, files[i]);
        unlink(path);
    }
    /* config.ini first: it is what marks the directory as a run's if this is killed before the rest */
    if (duel_write_config(R) != 0)
        return 1;
    return duel_copy_opponents(R) != 0 ? 1 : 0;
}

static void duel_unlock(void)
{
    duel_dir_unlock(&duel_run_lock);
}

static int duel_run_main(int argc, char **argv);
static int duel_resume_main(int argc, char **argv);

int duel_cmd_run(int argc, char **argv)
{
    int rc = duel_run_main(argc, argv);
    duel_unlock();
    return rc;
}

int duel_cmd_resume(int argc, char **argv)
{
    int rc = duel_resume_main(argc, argv);
    duel_unlock();
    return rc;
}

static int duel_run_main(int argc, char **argv)
{
    duel_run R;
    const char *config = NULL;
    char err[600], words[DUEL_START_MAX_PATH + 100], *sets[64];
    uint32_t seed = 0, gens = 0, n_sets = 0, k;
    int i, c, have_seed = 0, have_gens = 0, e;

    memset(&R, 0, sizeof R);
    duel_config_default(&R.cfg);
    for (i = 0; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (v == NULL && (strcmp(a, "--config") == 0 || strcmp(a, "--out") == 0 || strcmp(a, "--set") == 0)) {
            fprintf(stderr, "duel_evolve run: %s needs a value\n", a);
            return 2;
        }
        if (strcmp(a, "--config") == 0 && v) {
            config = v;
            i++;
        } else if (strcmp(a, "--out") == 0 && v) {
            R.dir = v;
            i++;
        } else if (strcmp(a, "--seed") == 0) {
            if (duel_parse_u32(a, v, 0, 4294967295u, &seed))
                return 2;
            have_seed = 1;
            i++;
        } else if (strcmp(a, "--set") == 0 && v && n_sets < 64) {
            sets[n_sets++] = argv[++i];
        } else if ((c = duel_common_option(&R, argc, argv, &i, &gens, &have_gens)) != 0) {
            if (c < 0)
                return 2;
        } else {
            fprintf(stderr, "duel_evolve run: unknown option '%s' (usage: duel_evolve run --config FILE --out DIR "
                            "[--set key=value ...] [--seed S] [--generations N] [--threads T] [--quiet] [--json] "
                            "[--record-champion-games])\n", duel_esc(a));
            return 2;
        }
    }
    if (config == NULL || R.dir == NULL) {
        fprintf(stderr, "duel_evolve run: --config FILE and --out DIR are required\n");
        return 2;
    }
    if (duel_config_read(&R.cfg, config, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (duel_config_set_list(&R.cfg, (const char *const *)sets, n_sets, &k, err, sizeof err) != 0) {
        char esc[1100];
        fprintf(stderr, "duel_evolve: --set %s: %s\n", duel_text_escape(sets[k], esc, sizeof esc), duel_esc_msg(err));
        return 2;
    }
    if (have_seed)
        R.cfg.seed = seed;
    if (have_gens)
        R.cfg.generations = gens;
    if (duel_config_check(&R.cfg, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s: %s\n", n_sets > 0 ? "the configuration with its --set overrides" : config,
                duel_esc_msg(err));
        return 2;
    }
    /* the populations first: a bad start topology (an unreadable blob) is refused before anything is made */
    if ((e = duel_create(&R)) != 0)
        return e;
    if ((e = duel_prepare_dir(&R)) != 0) {
        duel_run_free(&R);
        return e;
    }
    duel_threads_words(R.threads, words, sizeof words);
    duel_log(&R, "run: config %s, seed %u, %u generation%s, %s", config, R.cfg.seed, R.cfg.generations,
             duel_s(R.cfg.generations), words);
    for (k = 0; k < n_sets; k++)
        duel_log(&R, "run: override %s", sets[k]);
    duel_start_words(&R, words, sizeof words);
    duel_log(&R, "run: %s", words);
    if (R.opp_note[0] != '\0')
        duel_log(&R, "run: %s", R.opp_note);
    return duel_go(&R);
}

/* config.ini's start topology is the one the checkpoint carries. A blob or
 * genome file that is no longer there is not needed: the checkpoint has its network. */
static int duel_check_start(duel_run *R, const char *ckpt)
{
    char err[DUEL_START_MAX_PATH + 200], st[DUEL_START_MAX_PATH + 16];
    const neat_genome *have = neat_coev_start(R->coev);
    neat_genome want;
    int same;
    if ((R->cfg.start.kind == DUEL_START_BLOB || R->cfg.start.kind == DUEL_START_GENOME) &&
        access(R->cfg.start.path, F_OK) != 0)
        return 0;
    if (duel_start_genome(&R->cfg, &want, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return -1;
    }
    same = duel_same_topology(have, &want);
    neat_genome_free(&want, NULL);
    if (!same) {
        duel_start_text(&R->cfg.start, st, sizeof st);
        fprintf(stderr, "duel_evolve: %s: started from %u hidden nodes and %u connections, but config.ini says "
                        "start = %s\n", ckpt, neat_genome_hidden_count(have), neat_genome_enabled_count(have), st);
        return -1;
    }
    return 0;
}

/* The population checkpoint of a run against fixed opponents: 0; 1 when it
 * does not exist; -1 after one line naming the file and the offset. */
static int duel_pop_ckpt_load(const char *path, neat_pop **out)
{
    uint8_t *buf;
    size_t len, off = 0;
    int err;
    *out = NULL;
    if (duel_file_read(path, DUEL_CKPT_MAX, &buf, &len) != 0) {
        if (errno == ENOENT)
            return 1;
        fprintf(stderr, "duel_evolve: %s: cannot read: %s\n", duel_esc(path), errno == EFBIG ? "larger than 1 GB" : duel_file_strerror(errno));
        return -1;
    }
    if (neat_checkpoint_kind(buf, len) == NEAT_CKPT_COEV) {
        fprintf(stderr, "duel_evolve: %s: a coevolution's checkpoint, but config.ini names [opponents]: restore the "
                        "run's config.ini\n", duel_esc(path));
        free(buf);
        return -1;
    }
    err = neat_pop_load(out, buf, len, NULL, &off);
    if (err)
        fprintf(stderr, "duel_evolve: %s: offset %zu: %s\n", duel_esc(path), off, neat_strerror(err));
    free(buf);
    return err ? -1 : 0;
}

/* dominance.csv as the checkpoint's dominance tournament writes it: every
 * level, rebuilt on resume whatever became of the file (cut, deleted, a
 * row torn or dropped), byte for byte what an uninterrupted run writes. 0,
 * or the exit status after one line. */
static int duel_rebuild_dominance(duel_run *R)
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
        fprintf(stderr, "duel_evolve: resume: out of memory\n");
        return 1;
    }
    if (n > 0)
        fputs(DUEL_DOMINANCE_HEADER, mem);
    for (k = 0; k < n; k++) {
        neat_dominant d;
        char *row;
        neat_coev_dominant(R->coev, k, &d);
        row = duel_dominance_row_text(k + 1u, d.generation, duel_pop_name(d.pop)[0], neat_genome_hidden_count(d.genome),
                                      neat_genome_enabled_count(d.genome), d.n_beaten, d.wins, d.losses);
        if (row == NULL) {
            r = 1;
            break;
        }
        fputs(row, mem);
        free(row);
    }
    if (fclose(mem) != 0 || r) {
        fprintf(stderr, "duel_evolve: resume: out of memory\n");
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
        duel_path(path, sizeof path, R->dir, name);
        if (duel_genome_blob(d.genome, np->n_inputs, np->n_outputs, np->net_step, &want, &wlen) != 0) {
            free(text);
            fprintf(stderr, "duel_evolve: resume: out of memory\n");
            return 1;
        }
        if (duel_file_read(path, DUEL_GENOME_MAX, &have, &have_len) != 0 || have_len != wlen ||
            memcmp(have, want, wlen) != 0) {
            r = duel_file_replace(path, want, wlen) != 0;
            if (r)
                fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(path), duel_file_strerror(errno));
            else
                duel_log(R, "resume: %s was not the dominant of level %u: written again from the checkpoint", name,
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
    duel_path(path, sizeof path, R->dir, "dominance.csv");
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
        fprintf(stderr, "duel_evolve: %s: %s: refusing to replace it\n", duel_esc(path), duel_file_strerror(errno));
        free(text);
        return 2;
    }
    if (len == 0) {
        r = unlink(path) != 0 && errno != ENOENT;
    } else {
        r = duel_file_replace(path, text, len) != 0;
        if (r == 0)
            duel_log(R, "resume: dominance.csv rebuilt from the checkpoint (%u level%s)", n, duel_s(n));
    }
    if (r)
        fprintf(stderr, "duel_evolve: %s: cannot rewrite: %s\n", duel_esc(path), duel_file_strerror(errno));
    free(text);
    return r;
}

/* generations.csv must hold every generation before g (rows after the
 * checkpoint were cut already): rows measured as they happened cannot be
 * rebuilt from the checkpoint, so a run missing some is refused with what
 * works. 0, or the exit status after one line. */
/* Whether dir/config.ini is as the run wrote it: 1 (its seal holds), 0 (no seal: a run from before it, whose
 * [run] keys cannot be checked), -1 (edited since: the seal does not hold, or the file cannot be read). With a
 * seal, *gens and *every are the values the run wrote. */
static int duel_config_sealed(const char *dir, uint32_t *gens, uint32_t *every)
{
    char path[4200];
    uint8_t *text;
    size_t len, a, b, c;
    unsigned long long want;
    unsigned g, e;
    int r;
    duel_path(path, sizeof path, dir, "config.ini");
    if (duel_file_read(path, 1u << 20, &text, &len) != 0)
        return -1;
    for (a = 0; a < len && text[a] != '\n'; a++)
        ;
    a++; /* the second line: the checksum; the third: the keys */
    if (a + strlen(DUEL_SEAL) + 16 > len || memcmp(text + a, DUEL_SEAL, strlen(DUEL_SEAL)) != 0) {
        free(text);
        return 0;
    }
    for (b = a; b < len && text[b] != '\n'; b++)
        ;
    for (c = b + 1; c < len && text[c] != '\n'; c++)
        ;
    r = -1;
    if (c < len && sscanf((const char *)text + a + strlen(DUEL_SEAL), "%16llx", &want) == 1 &&
        sscanf((const char *)text + b + 1, "; generations = %u, strength_every = %u", &g, &e) == 2) {
        *gens = g;
        *every = e;
        r = duel_blob_hash(text + c + 1, len - c - 1) == (uint64_t)want ? 1 : -1;
    }
    free(text);
    return r;
}

/* 1 when one of the overrides sets [run] key (KEY=... or run.KEY=...). */
static int duel_sets_key(char **sets, uint32_t n, const char *key)
{
    uint32_t k;
    size_t n_key = strlen(key);
    for (k = 0; k < n; k++) {
        const char *v = strncmp(sets[k], "run.", 4) == 0 ? sets[k] + 4 : sets[k];
        if (strncmp(v, key, n_key) == 0 && v[n_key] == '=')
            return 1;
    }
    return 0;
}

/* generations.csv's last row without its newline (*text, *len bytes, malloc'd: *len > 0 and the last byte not
 * '\n'): when it is a whole row of a generation the checkpoint holds (before g), the one byte is added to the file
 * (the data is whole) and to *text (*len one more), and logged; a row of a generation after the checkpoint is left
 * to be cut, as a torn one. 0 when repaired, else -1 (*len as it was). */
static int duel_repair_last_newline(duel_run *R, const char *path, uint8_t **text, size_t *len, uint32_t g)
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
    duel_log(R, "resume: generations.csv's last row lacked its newline (the row is whole): added");
    return 0;
}

static int duel_check_generations(duel_run *R, uint32_t g)
{
    duel_gen_row *rows;
    size_t n, len, keep;
    char err[700], path[4200];
    uint8_t *text;
    uint32_t done;
    int r;
    if (g == 0) /* nothing to hold yet (what is there is cut); a header cut short is written again */
        return 0;
    duel_path(path, sizeof path, R->dir, "generations.csv");
    if (duel_file_read(path, DUEL_GENERATIONS_MAX_FILE, &text, &len) != 0) {
        if (errno == ENOENT)
            fprintf(stderr, "duel_evolve: %s: missing: " DUEL_GENERATIONS_LOST_ADVICE "\n", duel_esc(path));
        else
            fprintf(stderr, "duel_evolve: %s: cannot read: %s\n", duel_esc(path), duel_file_strerror(errno));
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
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (r != 0) {
        fprintf(stderr, "duel_evolve: %s: " DUEL_GENERATIONS_LOST_ADVICE "\n", duel_esc_msg(err));
        return 2;
    }
    done = n > 0 ? rows[n - 1].generation + (rows[n - 1].pop == 'B') : 0;
    free(rows);
    if (done < g) {
        fprintf(stderr, "duel_evolve: %s holds %u generation%s but the checkpoint %u: " DUEL_GENERATIONS_LOST_ADVICE
                        "\n", duel_esc(path), done, duel_s(done), g);
        return 2;
    }
    return 0;
}

/* config.ini against what the checkpoint's run was made with: the NEAT
 * and coevolution parameters it holds (cp NULL for a run against fixed
 * opponents). A hand edit is never taken silently: a change is made with
 * --set, which is applied and logged. 0, or 2 after one line naming the
 * first key that differs. */
static int duel_check_edits(const duel_config *config_ini, const neat_params *np, const neat_coev_params *cp,
                            const char *dir, char **sets, uint32_t n_sets, char *differs, size_t differs_cap)
{
    duel_config file = *config_ini, ck = *config_ini;
    char *a = NULL, *b = NULL, err[600], la[300], lb[300];
    size_t alen = 0, blen = 0;
    FILE *fa, *fb;
    int r = 0;
    ck.neat = *np;
    if (cp != NULL)
        ck.coev = *cp;
    /* a key this resume sets is a change made the right way, on both sides */
    if (duel_config_set_list(&file, (const char *const *)sets, n_sets, NULL, err, sizeof err) != 0 ||
        duel_config_set_list(&ck, (const char *const *)sets, n_sets, NULL, err, sizeof err) != 0)
        return 2; /* not reached: the same overrides were applied before */
    fa = open_memstream(&a, &alen);
    fb = open_memstream(&b, &blen);
    if (fa == NULL || fb == NULL) {
        if (fa != NULL)
            fclose(fa);
        if (fb != NULL)
            fclose(fb);
        free(a);
        free(b);
        fprintf(stderr, "duel_evolve: resume: out of memory\n");
        return 1;
    }
    duel_config_dump(fa, &file);
    duel_config_dump(fb, &ck);
    if (fclose(fa) != 0 || fclose(fb) != 0) {
        fprintf(stderr, "duel_evolve: resume: out of memory\n");
        r = 1;
    } else if (duel_plan_diff(a, b, la, lb, sizeof la) != 0) {
        if (differs != NULL) {
            /* config.ini as a run wrote it: an override of a resume that played no generation (or whose
             * checkpoint was not saved); the caller takes the checkpoint's */
            snprintf(differs, differs_cap, "config.ini said '%s', the checkpoint '%s'", la, lb);
            r = 3;
        } else {
            fprintf(stderr, "duel_evolve: %s/config.ini says '%s' but the run in its checkpoint has '%s': a hand edit "
                            "of config.ini is not taken (give a change as --set KEY=VALUE, which is applied and "
                            "logged, or restore config.ini)\n", duel_esc(dir), la, lb);
            r = 2;
        }
    }
    free(a);
    free(b);
    return r;
}

/* config.ini as a run wrote it, but with parameters the checkpoint's run never played (a resume's --set whose
 * generation was never saved): the checkpoint is the run; config.ini follows it (written again once this resume's
 * own overrides are applied), and the log says so. 0, or 2 after one line. */
static int duel_take_checkpoint(duel_run *R, duel_config *before, const neat_params *np, const neat_coev_params *cp,
                                char **sets, uint32_t n_sets, const char *differs)
{
    char err[600];
    before->neat = *np;
    if (cp != NULL)
        before->coev = *cp;
    R->cfg.neat = *np;
    if (cp != NULL)
        R->cfg.coev = *cp;
    if (duel_config_set_list(&R->cfg, (const char *const *)sets, n_sets, NULL, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: --set: %s\n", duel_esc_msg(err)); /* not reached: the same overrides were applied before */
        return 2;
    }
    duel_log(R, "resume: %s, an override of a resume that played no generation: the run is the checkpoint's, and "
                "config.ini is written again", differs);
    return 0;
}

/* A resume's parameters against its checkpoint at generation g: config.ini as played up to g - 1 (generation
 * 0's with the [overrides] before g) must be what the checkpoint holds; a sealed config.ini that is not (an
 * override of a resume from before [overrides], baked into [neat], whose generation was never saved) gives way
 * to the checkpoint. 0, or the exit status after one line. */
static int duel_resume_params(duel_run *R, duel_config *before, const neat_params *np, const neat_coev_params *cp,
                              uint32_t g, int sealed, char **psets, uint32_t n_psets, char *differs,
                              size_t differs_cap)
{
    duel_config played;
    char err[600];
    int e;
    if (duel_config_at(before, g > 0 ? g - 1u : 0, &played, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s/config.ini: %s\n", duel_esc(R->dir), duel_esc_msg(err));
        return 2;
    }
    /* a key this resume sets is a change made the right way, edited by hand to the same value or not */
    e = duel_check_edits(&played, np, cp, R->dir, psets, n_psets,
                         sealed == 1 && before->n_over == 0 ? differs : NULL, differs_cap);
    if (e == 3)
        return duel_take_checkpoint(R, before, np, cp, NULL, 0, differs);
    if (e != 0 || n_psets == 0)
        return e;
    {
        char quiet[700]; /* the probe says nothing: 3 when config.ini was edited to what --set gives */
        if (duel_check_edits(&played, np, cp, R->dir, NULL, 0, quiet, sizeof quiet) == 0)
            return 0;
    }
    /* config.ini edited by hand to what --set gives: the change applies from g (it goes into [overrides]), and
     * generation 0's values are the checkpoint's, the run having no overrides before */
    if (before->n_over > 0)
        return duel_check_edits(&played, np, cp, R->dir, NULL, 0, NULL, 0); /* says which key; with a schedule,
                                                                                * the hand edit stays refused */
    R->cfg.neat = *np;
    if (cp != NULL)
        R->cfg.coev = *cp;
    return 0;
}

/* This resume's parameter overrides go into [overrides] from generation g, and the run plays g with every
 * override up to it. 0, or 2 after one line. */
static int duel_resume_schedule(duel_run *R, uint32_t g, char **psets, uint32_t n_psets)
{
    char err[600];
    if (n_psets > 0 && g < R->cfg.generations &&
        duel_config_add_override(&R->cfg, g, (const char *const *)psets, n_psets, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: resume: --set: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (duel_config_at(&R->cfg, g, &R->eff, err, sizeof err) != 0 || duel_config_check(&R->eff, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    R->first_applied = g + 1u;
    return 0;
}

static int duel_resume_main(int argc, char **argv)
{
    duel_run R;
    neat_pop *pop = NULL;
    char err[600], path[4200], *sets[64], *psets[64], differs[700] = "";
    uint32_t gens = 0, n_sets = 0, n_psets = 0, k, g;
    int i, c, have_gens = 0, shorten = 0, e, sealed;
    uint32_t seal_gens = 0, seal_every = 0;
    duel_config before;

    memset(&R, 0, sizeof R);
    for (i = 0; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--set") == 0 && v == NULL) {
            fprintf(stderr, "duel_evolve resume: --set needs a value\n");
            return 2;
        }
        if ((c = duel_common_option(&R, argc, argv, &i, &gens, &have_gens)) != 0) {
            if (c < 0)
                return 2;
        } else if (strcmp(a, "--shorten") == 0) {
            shorten = 1;
        } else if (strcmp(a, "--set") == 0 && v && n_sets < 64) {
            sets[n_sets++] = argv[++i];
        } else if (a[0] != '-' && R.dir == NULL) {
            R.dir = a;
        } else {
            fprintf(stderr, "duel_evolve resume: unknown option '%s' (usage: duel_evolve resume DIR [--generations "
                            "N [--shorten]] [--set key=value ...] [--threads T] [--quiet] [--json] "
                            "[--record-champion-games])\n", duel_esc(a));
            return 2;
        }
    }
    if (R.dir == NULL) {
        fprintf(stderr, "duel_evolve resume: which run directory?\n");
        return 2;
    }
    duel_path(path, sizeof path, R.dir, "games");
    if (R.record_games && duel_mkdir(path) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot create: %s\n", duel_esc(path), strerror(errno));
        return 2;
    }
    duel_config_default(&R.cfg);
    duel_path(path, sizeof path, R.dir, "config.ini");
    if (duel_config_load(&R.cfg, path, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    before = R.cfg;
    if (R.cfg.reproduction != DUEL_REPRODUCE_LIBNEAT) {
        /* libneat would go on where NEAT C++ 1.2.1 reproduced, whose populations no file holds */
        fprintf(stderr, "duel_evolve: %s: [run] reproduction = neat-cpp-1.2.1: a run reproduced by NEAT C++ 1.2.1's own "
                        "code cannot be resumed (the release's populations are in no file); start it again (it is "
                        "deterministic: the same seed gives the same run)\n", duel_esc(path));
        return 2;
    }
    if (duel_take_lock(R.dir) != 0)
        return 2;
    /* the parameters (a [neat] or [coevolution] key) apply from the next generation on and go into [overrides];
     * the other keys ([run]'s) change config.ini itself. Both are checked here, on a copy, first. */
    {
        duel_config scratch = R.cfg;
        if (duel_config_set_list(&scratch, (const char *const *)sets, n_sets, &k, err, sizeof err) != 0) {
            char esc[1100];
            fprintf(stderr, "duel_evolve: --set %s: %s\n", duel_text_escape(sets[k], esc, sizeof esc), duel_esc_msg(err));
            return 2;
        }
        for (k = 0; k < n_sets; k++) {
            if (duel_config_set_is_param(sets[k]))
                psets[n_psets++] = sets[k];
            else if (duel_config_set(&R.cfg, sets[k], err, sizeof err) != 0)
                return 2; /* not reached: applied above */
        }
    }
    if (have_gens)
        R.cfg.generations = gens;
    /* the run's total changes only when asked: fewer generations than config.ini's needs --shorten */
    if (R.cfg.generations < before.generations && !shorten) {
        fprintf(stderr, "duel_evolve: resume: the run has %u generations in all (config.ini); %u would shorten it "
                        "for good: add --shorten to mean that\n", before.generations, R.cfg.generations);
        return 2;
    }
    if (shorten && R.cfg.generations >= before.generations) {
        fprintf(stderr, "duel_evolve: resume: --shorten with %u generations, not fewer than the run's %u\n",
                R.cfg.generations, before.generations);
        return 2;
    }
    if (R.cfg.seed != before.seed) {
        fprintf(stderr, "duel_evolve: --set seed: a run's seed cannot change; start a new run instead\n");
        return 2;
    }
    if (memcmp(&R.cfg.start, &before.start, sizeof before.start) != 0) {
        fprintf(stderr, "duel_evolve: --set start: a run's start topology cannot change; start a new run instead\n");
        return 2;
    }
    if (!duel_rules_equal(&R.cfg.world, &before.world)) {
        fprintf(stderr, "duel_evolve: --set: a run's [world] rules cannot change; start a new run instead\n");
        return 2;
    }
    if (memcmp(&R.cfg.opp, &before.opp, sizeof before.opp) != 0) {
        fprintf(stderr, "duel_evolve: --set: a run's [opponents] cannot change; start a new run instead\n");
        return 2;
    }
    if (R.cfg.train_layouts != before.train_layouts) {
        fprintf(stderr, "duel_evolve: --set train_layouts: a run's training food cannot change; start a new run "
                        "instead\n");
        return 2;
    }
    {
        /* what the run would play with the overrides (wherever they are scheduled) */
        duel_config scratch;
        if (duel_config_check(&R.cfg, err, sizeof err) != 0 ||
            duel_config_at(&R.cfg, UINT32_MAX, &scratch, err, sizeof err) != 0 ||
            duel_config_set_list(&scratch, (const char *const *)psets, n_psets, NULL, err, sizeof err) != 0 ||
            duel_config_check(&scratch, err, sizeof err) != 0) {
            fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
            return 2;
        }
        if (scratch.neat.pop_size != R.cfg.neat.pop_size) {
            fprintf(stderr, "duel_evolve: the overrides do not fit this run (pop_size cannot change)\n");
            return 2;
        }
        if (scratch.neat.net_step != R.cfg.neat.net_step) {
            /* its champions, dominants and strength rows are blobs of that step, checked against the checkpoint
             * in it */
            fprintf(stderr, "duel_evolve: --set net_step: a run's network step cannot change; start a new run "
                            "instead\n");
            return 2;
        }
    }

    /* a hand edit of any key is refused: the NEAT and coevolution keys are named below (against the checkpoint),
     * the others ([run]'s generations, strength_every, ...) by the seal the run wrote */
    sealed = duel_config_sealed(R.dir, &seal_gens, &seal_every);
    duel_path(path, sizeof path, R.dir, "checkpoint.bin");
    c = R.cfg.opp.n > 0 ? duel_pop_ckpt_load(path, &pop) : duel_ckpt_load("", path, &R.coev);
    if (c < 0)
        return 2;
    if (R.cfg.opp.n > 0 && (e = duel_load_opponents(&R, 1)) != 0) {
        neat_pop_free(pop);
        duel_run_free(&R);
        return e;
    }
    if (c > 0) {
        /* died before its first checkpoint: start from generation 0; but a run that recorded
         * generations and lost its checkpoint cannot go on */
        if (duel_has_history(R.dir, err, sizeof err)) {
            fprintf(stderr, "duel_evolve: %s: missing, but the run directory holds %s: cannot resume without it "
                            "(restore it from a backup, or start a new run)\n", duel_esc(path), duel_esc_msg(err));
            duel_run_free(&R);
            return 2;
        }
        duel_run_free(&R);
        /* no generation was played: the parameters are generation 0's */
        if (duel_config_set_list(&R.cfg, (const char *const *)psets, n_psets, NULL, err, sizeof err) != 0)
            return 2; /* not reached: checked above */
        if ((e = duel_create(&R)) != 0)
            return e;
    } else if (R.cfg.opp.n > 0) {
        size_t tlen = 0;
        const uint8_t *tag = neat_pop_game(pop, &tlen);
        g = neat_pop_generation(pop);
        e = duel_resume_params(&R, &before, neat_pop_params(pop), NULL, g, sealed, psets, n_psets, differs,
                               sizeof differs);
        if (e == 0 && duel_check_tag(&R, tag, tlen, path, g) != 0)
            e = 2;
        if (e == 0)
            e = duel_resume_schedule(&R, g, psets, n_psets);
        if (e != 0) {
            neat_pop_free(pop);
            duel_run_free(&R);
            return e;
        }
        e = neat_pop_set_params(pop, &R.eff.neat);
        if (e == 0)
            e = duel_fixed_new(&R.fixed, pop, &R.eff, R.opp, R.cfg.opp.n);
        else
            neat_pop_free(pop);
        if (e) {
            fprintf(stderr, "duel_evolve: the overrides do not fit this run (pop_size cannot change): %s\n",
                    neat_strerror(e));
            duel_run_free(&R);
            return 2;
        }
    } else {
        size_t tlen = 0;
        const uint8_t *tag = neat_coev_game(R.coev, &tlen);
        if (neat_coev_seed(R.coev) != R.cfg.seed) {
            fprintf(stderr, "duel_evolve: %s: seed %llu, but config.ini says %u\n", duel_esc(path),
                    (unsigned long long)neat_coev_seed(R.coev), R.cfg.seed);
            duel_run_free(&R);
            return 2;
        }
        g = neat_coev_generation(R.coev);
        e = duel_resume_params(&R, &before, neat_pop_params(neat_coev_pop(R.coev, 0)), neat_coev_get_params(R.coev),
                               g, sealed, psets, n_psets, differs, sizeof differs);
        if (e == 0 && (duel_check_start(&R, path) != 0 || duel_check_tag(&R, tag, tlen, path, g) != 0))
            e = 2;
        if (e == 0)
            e = duel_resume_schedule(&R, g, psets, n_psets);
        if (e != 0) {
            duel_run_free(&R);
            return e;
        }
        e = neat_coev_set_params(R.coev, &R.eff.neat, &R.eff.coev);
        if (e) {
            fprintf(stderr, "duel_evolve: the overrides do not fit this run (pop_size cannot change): %s\n",
                    neat_strerror(e));
            duel_run_free(&R);
            return 2;
        }
    }
    /* the [run] keys the checkpoint does not hold, against what the run wrote: an edit is refused, naming the key,
     * unless this resume gives the same change the right way (as the parameters above) */
    {
        /* an edit is one the seal does not explain and this resume does not give again as an override */
        int g_edit = sealed < 0 && c == 0 && before.generations != seal_gens &&
                     !((have_gens || duel_sets_key(sets, n_sets, "generations")) &&
                       R.cfg.generations == before.generations);
        int e_edit = sealed < 0 && c == 0 && before.strength_every != seal_every &&
                     !(duel_sets_key(sets, n_sets, "strength_every") && R.cfg.strength_every == before.strength_every);
        if (g_edit || e_edit) {
            fprintf(stderr, "duel_evolve: %s/config.ini says '%s = %u' but the run wrote '%s = %u': a hand edit of "
                            "config.ini is not taken (give a change as %s, which is applied and logged, or restore "
                            "config.ini)\n", duel_esc(R.dir), g_edit ? "generations" : "strength_every",
                    g_edit ? before.generations : before.strength_every, g_edit ? "generations" : "strength_every",
                    g_edit ? seal_gens : seal_every, g_edit ? "resume --generations N" : "--set strength_every=K");
            duel_run_free(&R);
            return 2;
        }
    }
    /* a run from before the rules were data carries them from now on */
    if (duel_tag_run(&R) != 0) {
        fprintf(stderr, "duel_evolve: cannot resume: out of memory\n");
        duel_run_free(&R);
        return 1;
    }
    g = duel_next_gen(&R);
    /* rows written after the checkpoint belong to a generation that runs
     * again: generations.csv keeps the generations before it, dominance.csv
     * (whose first field is the level) the levels it holds */
    /* nothing is cut before the records are known to be whole */
    if (R.coev != NULL && (k = duel_check_generations(&R, g)) != 0) {
        duel_run_free(&R);
        return k;
    }
    duel_path(path, sizeof path, R.dir, "generations.csv");
    if (duel_csv_keep_before(path, g) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot rewrite: %s\n", duel_esc(path), duel_file_strerror(errno));
        duel_run_free(&R);
        return 1;
    }
    duel_path(path, sizeof path, R.dir, "strength.csv");
    if (duel_csv_keep_before(path, g) != 0) {
        fprintf(stderr, "duel_evolve: %s: cannot rewrite: %s\n", duel_esc(path), duel_file_strerror(errno));
        duel_run_free(&R);
        return 1;
    }
    if (R.coev != NULL && (k = duel_rebuild_dominance(&R)) != 0) {
        duel_run_free(&R);
        return k;
    }
    if ((k = duel_rebuild_strength(&R, g)) != 0) {
        duel_run_free(&R);
        return k;
    }
    if (n_sets > 0 && g >= R.cfg.generations) {
        /* it would reach config.ini and never the checkpoint: the next resume would find them disagreeing */
        fprintf(stderr, "duel_evolve: resume: the run has played its %u generations: an override (--set) applies to "
                        "generations to come; give --generations N with it to extend the run\n", g);
        duel_run_free(&R);
        return 2;
    }
    for (k = 0; k < n_sets; k++)
        duel_log(&R, "resume: override %s", sets[k]);
    if (g > R.cfg.generations) {
        fprintf(stderr, "duel_evolve: resume: the run has played %u generations already, more than %u\n", g,
                R.cfg.generations);
        duel_run_free(&R);
        return 2;
    }
    if (R.cfg.generations != before.generations) {
        const char *how = R.cfg.generations > before.generations ? "extended" : "shortened";
        duel_log(&R, "resume: generations %u -> %u (%s; config.ini now says %u)", before.generations,
                 R.cfg.generations, how, R.cfg.generations);
        if (!R.quiet)
            fprintf(stderr, "%s %s from %u to %u generations (stored in config.ini)\n", duel_esc(R.dir), how,
                    before.generations, R.cfg.generations);
    }
    if (duel_write_config(&R) != 0) {
        duel_run_free(&R);
        return 1;
    }
    {
        char th[64];
        duel_threads_words(R.threads, th, sizeof th);
        duel_log(&R, "resume at generation %u of %u, %s", g, R.cfg.generations, th);
    }
    if (!R.quiet)
        fprintf(stderr, "resuming %s at generation %u of %u\n", duel_esc(R.dir), g, R.cfg.generations);
    return duel_go(&R);
}

int duel_cmd_config(int argc, char **argv)
{
    duel_config cfg;
    char err[600];
    const char *last = NULL; /* the last file or override: whose the final check's complaint is */
    int i, dump = 0, from_set = 0;
    duel_config_default(&cfg);
    for (i = 0; i < argc; i++) {
        if (i + 1 >= argc && (strcmp(argv[i], "--config") == 0 || strcmp(argv[i], "--set") == 0)) {
            fprintf(stderr, "duel_evolve config: %s needs a value\n", duel_esc(argv[i]));
            return 2;
        }
        if (strcmp(argv[i], "--dump") == 0) {
            dump = 1;
        } else if (strcmp(argv[i], "--config") == 0 && i + 1 < argc) {
            if (duel_config_read(&cfg, argv[++i], err, sizeof err) != 0) {
                fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
                return 2;
            }
            last = argv[i];
            from_set = 0;
        } else if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
            /* consecutive overrides together, a profile among them first (as run and resume apply theirs) */
            const char *group[256];
            uint32_t n = 0, bad;
            while (i + 1 < argc && strcmp(argv[i], "--set") == 0 && n < 256) {
                group[n++] = argv[i + 1];
                i += 2;
            }
            i--;
            if (duel_config_set_list(&cfg, group, n, &bad, err, sizeof err) != 0) {
                char esc[1100];
                fprintf(stderr, "duel_evolve: --set %s: %s\n", duel_text_escape(group[bad], esc, sizeof esc), duel_esc_msg(err));
                return 2;
            }
            last = group[n - 1];
            from_set = 1;
        } else {
            fprintf(stderr, "duel_evolve config: unknown option '%s' (usage: duel_evolve config --dump [--config "
                            "FILE] [--set key=value ...])\n", duel_esc(argv[i]));
            return 2;
        }
    }
    if (!dump) {
        fprintf(stderr, "duel_evolve config: nothing to do (try --dump)\n");
        return 2;
    }
    if (duel_config_check(&cfg, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s%s%s%s\n", last && from_set ? "--set " : "", last ? last : "",
                last ? ": " : "", duel_esc_msg(err));
        return 2;
    }
    duel_config_dump(stdout, &cfg);
    return 0;
}
