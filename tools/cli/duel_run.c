/* duel_run.c - duel_evolve run and resume: their options, and the run engine's reports on stderr and stdout (the engine, tools/run/, does the run). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "duel.h"
#include "duel_cli.h"
#include "duel_config.h"
#include "duel_engine.h"
#include "duel_mpi.h"
#include "duel_signal.h"
#include "duel_text.h"

/* What the command shows of a run: the options that are its own, and the progress bar's state. */
typedef struct duel_show {
    duel_engine *E;
    int quiet, json, tty;
    double started;            /* monotonic seconds when this process's first generation started */
    uint32_t first_gen;        /* the generation this process started at */
    int bar_shown;
    double bar_drawn;          /* when the bar was last drawn */
} duel_show;

static double duel_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec / 1e9;
}

/* "1 hidden node", "2 hidden nodes" */
static const char *duel_s(uint32_t n)
{
    return n == 1 ? "" : "s";
}

static void duel_clear_bar(duel_show *S)
{
    if (S->bar_shown) {
        fprintf(stderr, "\r%-79s\r", "");
        S->bar_shown = 0;
    }
}

static void duel_on_say(void *ud, duel_say_kind kind, const char *text)
{
    duel_show *S = (duel_show *)ud;
    duel_clear_bar(S);
    if (kind == DUEL_SAY_INFO) {
        if (!S->quiet)
            fprintf(stderr, "%s\n", text);
        return;
    }
    fprintf(stderr, "duel_evolve: %s\n", text);
}

static void duel_on_progress(void *ud, uint32_t gen, uint64_t done, uint64_t total)
{
    duel_show *S = (duel_show *)ud;
    char bar[31];
    int i, fill = total ? (int)(30 * done / total) : 30;
    double now;
    if (S->quiet || !S->tty)
        return;
    /* about five redraws a second, whatever the batches */
    now = duel_now();
    if (now - S->bar_drawn < 0.2)
        return;
    S->bar_drawn = now;
    for (i = 0; i < 30; i++)
        bar[i] = i < fill ? '=' : (i == fill ? '>' : ' ');
    bar[30] = '\0';
    fprintf(stderr, "\rgeneration %u [%s] %llu/%llu games of this batch", gen, bar, (unsigned long long)done,
            (unsigned long long)total);
    fflush(stderr);
    S->bar_shown = 1;
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

/* Opponent k's name in generations.csv's columns: its builtin's, or o1, o2, ... */
static void duel_opp_label(const duel_config *cfg, uint32_t k, char *buf, size_t cap)
{
    if (strncmp(cfg->opp.spec[k], "builtin:", 8) == 0)
        snprintf(buf, cap, "%s", duel_builtin_name(duel_builtin_parse(cfg->opp.spec[k] + 8)));
    else
        snprintf(buf, cap, "o%u", k + 1u);
}

/* A coevolution's generation on stderr (and --json on stdout). */
static void duel_show_coev(duel_show *S, const duel_engine_record *r)
{
    const neat_coev_report *rep = r->coev;
    const duel_config *cfg = duel_engine_config(S->E);
    /* what the scores are out of: a host's games (its fitness is its wins), a comparison's games */
    uint32_t host_games = (uint32_t)(rep->pop[0].games / (cfg->neat.pop_size ? cfg->neat.pop_size : 1u));
    uint32_t cmp_games = 2u * duel_engine_params(S->E)->coev.compare_configs, cw = rep->champion_pop;
    uint32_t gens_done = rep->generation + 1u - S->first_gen, left = r->generations - rep->generation - 1u;
    double elapsed = duel_now() - S->started, gps = r->seconds > 0 ? rep->games / r->seconds : 0;
    char eta[32];
    duel_eta(eta, sizeof eta, elapsed / gens_done * left);
    if (!S->quiet)
        fprintf(stderr,
                "gen %u (%u/%u)  best A %.0f/%u B %.0f/%u wins  species A %u B %u  champion %s %u:%u of %u  "
                "dominance %u%s (%u hidden, %u conns)  %.0f games/s  ETA %s\n",
                rep->generation, rep->generation + 1u, r->generations, rep->pop[0].best_fitness, host_games,
                rep->pop[1].best_fitness, host_games, rep->pop[0].species, rep->pop[1].species, cw ? "B" : "A",
                rep->champion_wins[cw], rep->champion_wins[cw ^ 1u], cmp_games, rep->dominants,
                rep->new_dominant ? " new" : "", r->dominant_hidden, r->dominant_connections, gps, eta);
    if (S->json) {
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
               cw ? "B" : "A", rep->champion_wins[0], rep->champion_wins[1], rep->dominants,
               rep->new_dominant ? "true" : "false", r->dominant_hidden, r->dominant_connections,
               (unsigned long long)rep->games, r->seconds, gps, elapsed / gens_done * left);
        fflush(stdout);
    }
}

/* A generation of a run against fixed opponents on stderr (and --json on stdout). */
static void duel_show_fixed(duel_show *S, const duel_engine_record *r)
{
    const duel_fixed_report *rep = r->fixed;
    const duel_config *cfg = duel_engine_config(S->E);
    uint32_t gens_done = rep->generation + 1u - S->first_gen, left = r->generations - rep->generation - 1u, k;
    double elapsed = duel_now() - S->started, gps = r->seconds > 0 ? rep->games / r->seconds : 0;
    char eta[32], vs[600], label[32];
    size_t at = 0;
    vs[0] = '\0';
    for (k = 0; k < cfg->opp.n && at < sizeof vs; k++) {
        duel_opp_label(cfg, k, label, sizeof label);
        at += (size_t)snprintf(vs + at, sizeof vs - at, "%s%s %u:%u", k ? ", " : "", label, rep->best_vs[k].wins_a,
                               rep->best_vs[k].wins_b);
    }
    duel_eta(eta, sizeof eta, elapsed / gens_done * left);
    if (!S->quiet)
        fprintf(stderr, "gen %u (%u/%u)  best %.0f  mean %.2f  species %u  champion (%u hidden, %u conns) vs %s  "
                        "%.0f games/s  ETA %s\n",
                rep->generation, rep->generation + 1u, r->generations, rep->best_fitness, rep->mean_fitness,
                rep->species, rep->best_hidden, rep->best_conns, vs, gps, eta);
    if (S->json) {
        printf("{\"generation\":%u,\"best\":%.0f,\"mean\":%.4f,\"species\":%u,\"delta_t\":%.4f,"
               "\"mean_hidden\":%.4f,\"mean_connections\":%.4f,\"best_hidden\":%u,\"best_connections\":%u,"
               "\"against\":[",
               rep->generation, rep->best_fitness, rep->mean_fitness, rep->species, rep->delta_t, rep->mean_hidden,
               rep->mean_conns, rep->best_hidden, rep->best_conns);
        for (k = 0; k < cfg->opp.n; k++) {
            duel_opp_label(cfg, k, label, sizeof label);
            printf("%s{\"opponent\":\"%s\",\"wins\":%u,\"losses\":%u,\"draws\":%u,\"timeouts\":%u}", k ? "," : "",
                   label, rep->best_vs[k].wins_a, rep->best_vs[k].wins_b, rep->best_vs[k].draws,
                   rep->best_vs[k].timeouts);
        }
        printf("],\"games\":%llu,\"seconds\":%.3f,\"games_per_s\":%.0f,\"eta_s\":%.0f}\n",
               (unsigned long long)rep->games, r->seconds, gps, elapsed / gens_done * left);
        fflush(stdout);
    }
}

static void duel_on_generation(void *ud, const duel_engine_record *r)
{
    duel_show *S = (duel_show *)ud;
    duel_clear_bar(S);
    if (r->coev != NULL)
        duel_show_coev(S, r);
    else
        duel_show_fixed(S, r);
}

/* The run's last line: where it ended, and its best. */
static void duel_show_done(duel_show *S)
{
    uint32_t n = duel_engine_generations(S->E), dh, dc;
    const char *dir = duel_engine_dir(S->E);
    char esc[1100];
    if (S->quiet)
        return;
    duel_text_escape(dir, esc, sizeof esc);
    if (duel_engine_coev(S->E) == NULL) {
        const neat_genome *b = neat_pop_last_best(duel_engine_pop(S->E));
        dh = neat_genome_hidden_count(b);
        dc = neat_genome_enabled_count(b);
        fprintf(stderr, "done: %u generation%s in %s; the last champion: %u hidden node%s, %u connection%s "
                        "(champions/gen-%05u.blob)\n", n, duel_s(n), esc, dh, duel_s(dh), dc, duel_s(dc), n - 1u);
        return;
    }
    {
        const neat_coev *c = duel_engine_coev(S->E);
        neat_dominant d;
        uint32_t levels = neat_coev_dominant_count(c);
        neat_coev_dominant(c, levels - 1u, &d);
        dh = neat_genome_hidden_count(d.genome);
        dc = neat_genome_enabled_count(d.genome);
        fprintf(stderr, "done: %u generation%s in %s; dominance level %u; top dominant: generation %u, %u hidden "
                        "node%s, %u connection%s (champions/gen-%05u.blob)\n",
                n, duel_s(n), esc, levels, d.generation, dh, duel_s(dh), dc, duel_s(dc), d.generation);
    }
}

/* The engine's generations to the end (or a signal), shown; its status as the exit status. */
static int duel_play_out(duel_show *S)
{
    uint32_t g;
    int rc, rc_close;
    char esc[1100];
    duel_signal_install(duel_engine_stop_flag(S->E), "duel_evolve: a second signal: stopped at once; the last "
                                                     "checkpoint stands (duel_evolve resume continues from it)\n");
    S->tty = isatty(2);
    S->started = duel_now();
    S->first_gen = duel_engine_generation(S->E);
    rc = duel_engine_step(S->E, 0);
    duel_clear_bar(S);
    g = duel_engine_generation(S->E);
    if (rc == DUEL_ENGINE_STOPPED) {
        if (g < duel_engine_generations(S->E))
            fprintf(stderr, "duel_evolve: interrupted; %u generation%s saved. Resume with: duel_evolve resume %s\n",
                    g, g == 1 ? " is" : "s are", duel_text_escape(duel_engine_dir(S->E), esc, sizeof esc));
        else
            fprintf(stderr, "duel_evolve: interrupted; the run is complete (%u generations)\n",
                    duel_engine_generations(S->E));
    } else if (rc == DUEL_ENGINE_OK) {
        duel_show_done(S);
    }
    rc_close = duel_engine_close(S->E);
    S->E = NULL;
    return rc == DUEL_ENGINE_OK ? rc_close : rc;
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

/* The options run and resume share: --generations, --threads, --quiet,
 * --json, --record-champion-games. 1 when argv[*i] was one (and *i is past
 * its value), 0 when it is not, -1 after a message on a bad value. */
static int duel_common_option(duel_show *S, duel_engine_options *o, int argc, char **argv, int *i)
{
    const char *a = argv[*i], *v = *i + 1 < argc ? argv[*i + 1] : NULL;
    if (strcmp(a, "--generations") == 0) {
        if (duel_parse_u32(a, v, 1, 1000000, &o->generations))
            return -1;
        ++*i;
    } else if (strcmp(a, "--threads") == 0) {
        if (duel_parse_u32(a, v, 0, 256, &o->threads))
            return -1;
        ++*i;
    } else if (strcmp(a, "--quiet") == 0) {
        S->quiet = 1;
    } else if (strcmp(a, "--json") == 0) {
        S->json = 1;
    } else if (strcmp(a, "--record-champion-games") == 0) {
        o->record_games = 1;
    } else {
        return 0;
    }
    return 1;
}

/* The MPI job's ranks play the run's games (tools/mpi/; one process without MPI). */
static const duel_engine_executor duel_mpi_exec = {duel_mpi_games_ranks, duel_mpi_default_threads, duel_mpi_attach,
                                                   duel_mpi_describe, duel_mpi_stop_requested};

static void duel_hooks(duel_show *S, duel_engine_options *o)
{
    duel_engine_set_executor(&duel_mpi_exec);
    memset(S, 0, sizeof *S);
    memset(o, 0, sizeof *o);
    o->hooks.ud = S;
    o->hooks.say = duel_on_say;
    o->hooks.generation = duel_on_generation;
    o->hooks.progress = duel_on_progress;
}

int duel_cmd_run(int argc, char **argv)
{
    duel_show S;
    duel_engine_options o;
    duel_config cfg;
    const char *config = NULL, *dir = NULL;
    char err[600], *sets[64];
    uint32_t seed = 0, n_sets = 0, k;
    int i, c, have_seed = 0, e;

    duel_hooks(&S, &o);
    duel_config_default(&cfg);
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
            dir = v;
            i++;
        } else if (strcmp(a, "--seed") == 0) {
            if (duel_parse_u32(a, v, 0, 4294967295u, &seed))
                return 2;
            have_seed = 1;
            i++;
        } else if (strcmp(a, "--set") == 0 && v && n_sets < 64) {
            sets[n_sets++] = argv[++i];
        } else if ((c = duel_common_option(&S, &o, argc, argv, &i)) != 0) {
            if (c < 0)
                return 2;
        } else {
            fprintf(stderr, "duel_evolve run: unknown option '%s' (usage: duel_evolve run --config FILE --out DIR "
                            "[--set key=value ...] [--seed S] [--generations N] [--threads T] [--quiet] [--json] "
                            "[--record-champion-games])\n", duel_esc(a));
            return 2;
        }
    }
    if (config == NULL || dir == NULL) {
        fprintf(stderr, "duel_evolve run: --config FILE and --out DIR are required\n");
        return 2;
    }
    if (duel_config_read(&cfg, config, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (duel_config_set_list(&cfg, (const char *const *)sets, n_sets, &k, err, sizeof err) != 0) {
        char esc[1100];
        fprintf(stderr, "duel_evolve: --set %s: %s\n", duel_text_escape(sets[k], esc, sizeof esc), duel_esc_msg(err));
        return 2;
    }
    if (have_seed)
        cfg.seed = seed;
    if (o.generations > 0)
        cfg.generations = o.generations;
    if (duel_config_check(&cfg, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s: %s\n", n_sets > 0 ? "the configuration with its --set overrides" : config,
                duel_esc_msg(err));
        return 2;
    }
    o.config_name = config;
    o.sets = (const char *const *)sets;
    o.n_sets = n_sets;
    o.generations = 0;
    if ((e = duel_engine_new(&S.E, &cfg, dir, &o)) != 0)
        return e;
    return duel_play_out(&S);
}

int duel_cmd_resume(int argc, char **argv)
{
    duel_show S;
    duel_engine_options o;
    const char *dir = NULL;
    char *sets[64];
    uint32_t n_sets = 0;
    int i, c, e;

    duel_hooks(&S, &o);
    for (i = 0; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--set") == 0 && v == NULL) {
            fprintf(stderr, "duel_evolve resume: --set needs a value\n");
            return 2;
        }
        if ((c = duel_common_option(&S, &o, argc, argv, &i)) != 0) {
            if (c < 0)
                return 2;
        } else if (strcmp(a, "--shorten") == 0) {
            o.shorten = 1;
        } else if (strcmp(a, "--set") == 0 && v && n_sets < 64) {
            sets[n_sets++] = argv[++i];
        } else if (a[0] != '-' && dir == NULL) {
            dir = a;
        } else {
            fprintf(stderr, "duel_evolve resume: unknown option '%s' (usage: duel_evolve resume DIR [--generations "
                            "N [--shorten]] [--set key=value ...] [--threads T] [--quiet] [--json] "
                            "[--record-champion-games])\n", duel_esc(a));
            return 2;
        }
    }
    if (dir == NULL) {
        fprintf(stderr, "duel_evolve resume: which run directory?\n");
        return 2;
    }
    o.sets = (const char *const *)sets;
    o.n_sets = n_sets;
    if ((e = duel_engine_resume(&S.E, dir, &o)) != 0)
        return e;
    return duel_play_out(&S);
}
