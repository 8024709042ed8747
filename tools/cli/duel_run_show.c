/* duel_run_show.c - what duel_evolve run and resume show of a run engine's work: a line a generation on stderr, --json on stdout, the progress bar on a terminal, the interruption and the last line. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "duel.h"
#include "duel_fixed.h"
#include "duel_lcm_champ.h"
#include "duel_mpi.h"
#include "duel_run_show.h"
#include "duel_signal.h"
#include "duel_text.h"

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
int duel_show_play_out(duel_show *S)
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
    {
        /* the handler's flag is the engine's until it is closed: from here on a static one (the process may go
         * on: an MPI rank runs one task after another) */
        static volatile sig_atomic_t after;
        after = rc == DUEL_ENGINE_STOPPED ? 1 : *duel_engine_stop_flag(S->E);
        duel_signal_install(&after, "duel_evolve: a second signal: stopped at once; the last checkpoint stands "
                                    "(duel_evolve resume continues from it)\n");
    }
    rc_close = duel_engine_close(S->E);
    S->E = NULL;
    return rc == DUEL_ENGINE_OK ? rc_close : rc;
}

/* The MPI job's ranks play the run's games (tools/mpi/; one process without MPI). */
static const duel_engine_executor duel_mpi_exec = {duel_mpi_games_ranks, duel_mpi_default_threads, duel_mpi_attach,
                                                   duel_mpi_describe, duel_mpi_stop_requested};

void duel_show_init(duel_show *S, duel_engine_options *o)
{
    duel_engine_set_executor(&duel_mpi_exec);
    duel_engine_set_game_recorder(duel_lcm_record_champion_games);
    memset(S, 0, sizeof *S);
    memset(o, 0, sizeof *o);
    o->hooks.ud = S;
    o->hooks.say = duel_on_say;
    o->hooks.generation = duel_on_generation;
    o->hooks.progress = duel_on_progress;
}

