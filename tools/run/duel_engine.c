/* duel_engine.c - the run engine's life: a new run's populations and directory, its generations one at a time (played, recorded, reported to the caller's hooks), its end. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "duel.h"
#include "duel_cores.h"
#include "duel_cmp_cache.h"
#include "duel_ctrl.h"
#include "duel_engine_internal.h"
#include "duel_files.h"
#include "duel_runtag.h"
#include "duel_text.h"
#include "duel_world_cfg.h"
#include "neat_coev.h"

double de_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec / 1e9;
}

void de_path(char *out, size_t cap, const char *dir, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
}

/* "1 hidden node", "2 hidden nodes" */
const char *de_s(uint32_t n)
{
    return n == 1 ? "" : "s";
}

const char *de_pop_name(uint32_t p)
{
    return p == 0 ? "A" : "B";
}

const char *de_esc(duel_engine *R, const char *s)
{
    char *b = R->esc[R->esc_next++ % 4];
    return duel_text_escape(s != NULL ? s : "", b, sizeof R->esc[0]);
}

const char *de_esc_msg(duel_engine *R, const char *s)
{
    char *b = R->esc_msg[R->esc_msg_next++ % 2];
    return duel_text_escape_msg(s != NULL ? s : "", b, sizeof R->esc_msg[0]);
}

/* One line for people, through the caller's hook; an error is kept as the last one too. The formats of the
 * messages moved here from the command end in "\n": it is dropped, the hook's line has none. */
void de_say(duel_engine *R, duel_say_kind kind, const char *fmt, ...)
{
    char line[sizeof R->last_error];
    va_list ap;
    va_start(ap, fmt);
    duel_text_vline(line, sizeof line, fmt, ap);
    va_end(ap);
    if (kind == DUEL_SAY_ERROR)
        memcpy(R->last_error, line, sizeof line);
    if (R->hooks.say != NULL)
        R->hooks.say(R->hooks.ud, kind, line);
}

/* One timestamped line in DIR/log.txt (and nothing else: the log is for people). */
void de_log(duel_engine *R, const char *fmt, ...)
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
    de_path(path, sizeof path, R->dir, "log.txt");
    if (!R->log_failed && duel_file_append(path, line) != 0) {
        de_err(R, "%s: cannot write: %s", de_esc(R, path), strerror(errno));
        R->log_failed = 1;
    }
}

/* The run's generation to play next. */
uint32_t de_next_gen(const duel_engine *R)
{
    return R->fixed != NULL ? neat_pop_generation(duel_fixed_pop(R->fixed)) : neat_coev_generation(R->coev);
}

void de_free_run(duel_engine *R)
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

const char *de_game_error(int err)
{
    if (err == DUEL_GAMES_E_REMOTE)
        return "another process of the MPI job failed";
    if (err <= -200)
        return "the duel refused a network";
    if (err <= -100)
        return nrt_strerror(err + 100);
    return neat_strerror(err);
}

/* The threads a run plays on, in words: "2 threads", or "all 4 cores" for 0. */
void de_threads_words(uint32_t threads, char *buf, size_t cap)
{
    if (threads == 0) {
        uint32_t cores = duel_cores();
        snprintf(buf, cap, "all %u core%s", cores, de_s(cores));
    } else {
        snprintf(buf, cap, "%u thread%s", threads, de_s(threads));
    }
}

/* The run's tag (duel_run_tag, duel_runtag.c) with its fixed opponents' identities. */
int de_run_tag_of(const duel_engine *R, uint8_t *buf, size_t *len)
{
    duel_opp_id ids[DUEL_MAX_OPPONENTS];
    uint32_t k;
    for (k = 0; k < R->cfg.opp.n; k++) {
        ids[k].is_blob = R->opp[k].blob != NULL;
        ids[k].id = R->opp[k].blob != NULL ? duel_blob_hash(R->opp[k].blob, R->opp[k].len) : (uint64_t)R->opp[k].len;
    }
    return duel_run_tag(&R->cfg, ids, buf, len);
}

int de_tag_run(duel_engine *R)
{
    uint8_t tag[DUEL_TAG_MAX];
    size_t len;
    int e = de_run_tag_of(R, tag, &len);
    if (e)
        return e;
    return R->fixed != NULL ? neat_pop_set_game(duel_fixed_pop(R->fixed), tag, len)
                            : neat_coev_set_game(R->coev, tag, len);
}

/* The opponents of a run against fixed ones: builtin:NAME as a builtin,
 * any other name a blob or genome file (a genome's network as a sync blob)
 * checked by the runtime, with the duel's 13 inputs and 3 outputs. From
 * config.ini's names (a new run), or (copies = 1) from the run's own
 * copies, opponents/NN.blob, which a new run writes so that its games never
 * depend on files outside it. 0, or 2 after one line. */
int de_load_opponents(duel_engine *R, int copies)
{
    char path[4200], err[4600];
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
        if (duel_read_blob_msg(path, &blob, &len, &origin, err, sizeof err) != 0) {
            de_err(R, "%s", de_esc_msg(R, err));
            return 2;
        }
        /* an opponent plays in the run's world: one made in another is said to be so, and logged */
        if (!copies && origin.world_from != DUEL_ORIGIN_NONE && !duel_rules_equal(&origin.world, &R->cfg.world)) {
            char a[40], b[40];
            de_say(R, DUEL_SAY_NOTE, "note: [opponents] %s was made in world %s; this run plays it in its own world, %s",
                   de_esc(R, path), duel_world_label(&origin.world, a, sizeof a),
                   duel_world_label(&R->cfg.world, b, sizeof b));
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
            de_err(R, "[opponents] %s: not a duel controller: %s", de_esc(R, path),
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
int de_copy_opponents(duel_engine *R)
{
    char path[4200];
    uint32_t k;
    if (R->cfg.opp.n == 0)
        return 0;
    snprintf(path, sizeof path, "%s/opponents", R->dir);
    if (duel_mkdir(path) != 0) {
        de_err(R, "%s: cannot create: %s", de_esc(R, path), strerror(errno));
        return -1;
    }
    for (k = 0; k < R->cfg.opp.n; k++) {
        if (R->opp[k].blob == NULL)
            continue;
        snprintf(path, sizeof path, "%s/opponents/%02u.blob", R->dir, k + 1u);
        if (duel_file_replace(path, R->opp[k].blob, R->opp[k].len) != 0) {
            de_err(R, "%s: cannot write: %s", de_esc(R, path), strerror(errno));
            return -1;
        }
    }
    return 0;
}

/* Another NEAT's reproduction, registered by a program that holds one (duel_engine.h). */
static duel_reproducer duel_other;
static int duel_have_other;

void duel_engine_set_reproducer(const duel_reproducer *r)
{
    duel_have_other = r != NULL;
    if (r != NULL)
        duel_other = *r;
}

/* A run whose [run] reproduction is another NEAT's: refused unless this program holds it. 0, or 2 after
 * one line. */
static int duel_check_reproduction(duel_engine *R)
{
    if (R->cfg.reproduction == DUEL_REPRODUCE_LIBNEAT)
        return 0;
    if (R->cfg.opp.n > 0) {
        de_err(R, "[run] reproduction = neat-cpp-1.2.1 reproduces a coevolution's populations; a run against fixed "
                  "opponents ([opponents] play) has libneat's only");
        return 2;
    }
    if (!duel_have_other || duel_other.which != R->cfg.reproduction) {
        de_err(R, "[run] reproduction = neat-cpp-1.2.1 is NEAT C++ 1.2.1's own reproduction: only neatcpp_duel, built "
                  "against a checkout of the release, runs it (tools/neatcpp/build.sh, docs/neat-cpp.md)");
        return 2;
    }
    return 0;
}

/* The populations from the configuration's start topology (and a fixed run's opponents). 0, or the status
 * after one line (2: the configuration's fault, 1: the machine's). */
int de_create(duel_engine *R)
{
    char err[DUEL_START_MAX_PATH + 200];
    neat_genome g;
    neat_start st;
    int e;
    if ((e = duel_check_reproduction(R)) != 0)
        return e;
    /* generation 0's parameters: [overrides] start later (from 1 on) */
    if (duel_config_at(&R->cfg, 0, &R->eff, err, sizeof err) != 0) {
        de_err(R, "%s", de_esc_msg(R, err));
        return 2;
    }
    if (R->cfg.n_over > 0 && R->cfg.reproduction != DUEL_REPRODUCE_LIBNEAT) {
        de_err(R, "[overrides] with [run] reproduction = neat-cpp-1.2.1: the release's reproduction takes its "
                  "parameters once; give them in [neat]");
        return 2;
    }
    if (R->cfg.opp.n == 0) {
        /* a coevolution: as the Python package starts one (duel_runtag.c) */
        e = duel_coev_new(&R->coev, &R->eff, err, sizeof err);
        if (e)
            de_err(R, "%s", de_esc_msg(R, err));
        if (e == 0 && R->cfg.n_over > 0 && (e = de_tag_run(R)) != 0)
            de_err(R, "cannot start: %s", neat_strerror(e)); /* the tag with the schedule */
        if (e == 0 && R->cfg.reproduction != DUEL_REPRODUCE_LIBNEAT) {
            /* the other NEAT's populations replace libneat's from generation 0 on */
            if (duel_other.begin(duel_other.ud, &R->eff) != 0)
                return 2;
            e = neat_coev_set_reproducer(R->coev, duel_other.reproduce, duel_other.ud);
            if (e) {
                de_err(R, "NEAT C++ 1.2.1's start: %s", neat_strerror(e));
                return 1;
            }
        }
        return e;
    }
    if (duel_start_genome(&R->cfg, &g, err, sizeof err) != 0) {
        de_err(R, "%s", de_esc_msg(R, err));
        return 2;
    }
    st.genome = &g;
    st.keep_weights = 0;
    {
        neat_pop *pop = NULL;
        if ((e = de_load_opponents(R, 0)) != 0) {
            neat_genome_free(&g, NULL);
            return e;
        }
        e = neat_pop_create(&pop, &R->eff.neat, &st, R->cfg.seed, NULL);
        if (e == 0)
            e = duel_fixed_new(&R->fixed, pop, &R->eff, R->opp, R->cfg.opp.n);
    }
    neat_genome_free(&g, NULL);
    if (e == 0)
        e = de_tag_run(R);
    if (e) {
        de_err(R, "cannot start: %s", neat_strerror(e));
        return 1;
    }
    return 0;
}

/* The start topology in words, for log.txt. */
static void duel_start_words(const duel_engine *R, char *buf, size_t cap)
{
    char st[DUEL_START_MAX_PATH + 16];
    duel_start_text(&R->cfg.start, st, sizeof st);
    if (R->fixed != NULL) {
        snprintf(buf, cap, "start %s, one population against %u fixed opponent%s", st, R->cfg.opp.n,
                 de_s(R->cfg.opp.n));
        return;
    }
    {
        const neat_genome *g = neat_coev_start(R->coev);
        uint32_t h = neat_genome_hidden_count(g), c = neat_genome_enabled_count(g);
        snprintf(buf, cap, "start %s (%u hidden node%s, %u connection%s)%s", st, h, de_s(h), c, de_s(c),
                 R->cfg.coev.random_fitness ? ", random fitness" : "");
    }
}

static void duel_on_progress(void *ud, uint64_t done, uint64_t total)
{
    duel_engine *R = (duel_engine *)ud;
    if (R->hooks.progress != NULL)
        R->hooks.progress(R->hooks.ud, R->gen_in_flight, done, total);
}

/* Another executor of the games, registered by a program that has one (duel_engine.h). */
static duel_engine_executor duel_exec;
static int duel_have_exec;

void duel_engine_set_executor(const duel_engine_executor *x)
{
    duel_have_exec = x != NULL;
    if (x != NULL)
        duel_exec = *x;
}

static uint32_t duel_exec_ranks(void)
{
    return duel_have_exec ? duel_exec.ranks() : 1u;
}

/* The games' executor for a run whose populations and directory are ready. 0, or the status after one line
 * (the run's populations freed). */
int de_go(duel_engine *R)
{
    uint32_t ranks = duel_exec_ranks(), hosts = 2u * R->cfg.neat.pop_size;
    int err;
    if (ranks > hosts) {
        /* a generation's host games go out one host's games at a time: more ranks than hosts would wait */
        de_err(R, "%u MPI ranks for a run of 2 x %u networks: at most %u ranks can play its games", ranks,
               R->cfg.neat.pop_size, hosts);
        de_free_run(R);
        return 2;
    }
    err = duel_games_create(&R->games, R->threads == 0 && ranks > 1 ? duel_exec.default_threads() : R->threads,
                            &R->eff.neat);
    if (err) {
        de_err(R, "out of memory");
        de_free_run(R);
        return 1;
    }
    if (duel_games_set_rules(R->games, &R->cfg.world) != 0) {
        de_err(R, "the run's [world] rules cannot make a game");
        duel_games_free(R->games);
        R->games = NULL;
        de_free_run(R);
        return 2;
    }
    if (duel_have_exec)
        duel_exec.attach(R->games);
    if (ranks > 1)
        de_log(R, "mpi: %u ranks, %u thread%s on rank 0", ranks, duel_games_threads(R->games),
               duel_games_threads(R->games) == 1 ? "" : "s");
    duel_games_on_progress(R->games, duel_on_progress, R);
    return 0;
}

/* An engine with the options' settings and the directory's name, nothing open. */
int de_engine_alloc(duel_engine **out, const char *dir, const duel_engine_options *o)
{
    duel_engine *R = (duel_engine *)calloc(1, sizeof *R);
    *out = NULL;
    if (R == NULL || (R->dir = (char *)malloc(strlen(dir) + 1)) == NULL) {
        free(R);
        if (o != NULL && o->hooks.say != NULL)
            o->hooks.say(o->hooks.ud, DUEL_SAY_ERROR, "out of memory");
        return DUEL_ENGINE_E_SYSTEM;
    }
    strcpy(R->dir, dir);
    R->lock.dir_fd = R->lock.file_fd = -1;
    if (o != NULL) {
        R->threads = o->threads;
        R->record_games = o->record_games;
        R->hooks = o->hooks;
    }
    *out = R;
    return 0;
}

/* An engine that failed to open: its populations, lock and memory given back. */
void de_engine_discard(duel_engine *R)
{
    if (R == NULL)
        return;
    de_free_run(R);
    duel_dir_unlock(&R->lock);
    free(R->dominance_row);
    free(R->dir);
    free(R);
}

int duel_engine_new(duel_engine **out, const duel_config *cfg, const char *dir, const duel_engine_options *o)
{
    duel_engine *R;
    char words[DUEL_START_MAX_PATH + 100];
    uint32_t k;
    int e = de_engine_alloc(&R, dir, o);
    if (e)
        return e;
    R->cfg = *cfg;
    /* the populations first: a bad start topology (an unreadable blob) is refused before anything is made */
    if ((e = de_create(R)) != 0 || (e = de_prepare_dir(R)) != 0) {
        de_engine_discard(R);
        return e;
    }
    de_threads_words(R->threads, words, sizeof words);
    de_log(R, "run: config %s, seed %u, %u generation%s, %s", o != NULL && o->config_name ? o->config_name : "(given)",
           R->cfg.seed, R->cfg.generations, de_s(R->cfg.generations), words);
    for (k = 0; o != NULL && k < o->n_sets; k++)
        de_log(R, "run: override %s", o->sets[k]);
    duel_start_words(R, words, sizeof words);
    de_log(R, "run: %s", words);
    if (R->opp_note[0] != '\0')
        de_log(R, "run: %s", R->opp_note);
    if ((e = de_go(R)) != 0) {
        de_engine_discard(R);
        return e;
    }
    *out = R;
    return 0;
}

/* The [overrides] that start at generation g, applied to the run before it plays g (as a resume at g applies them
 * to its checkpoint: the same run either way). 0, or 2 after one line. */
static int duel_apply_overrides(duel_engine *R, uint32_t g)
{
    char err[600];
    uint32_t k;
    int e;
    for (k = 0; k < R->cfg.n_over && R->cfg.over[k].from != g; k++)
        ;
    if (k == R->cfg.n_over || R->first_applied == g + 1u)
        return 0; /* none, or applied already by the resume that starts here */
    if (duel_config_at(&R->cfg, g, &R->eff, err, sizeof err) != 0) {
        de_err(R, "%s", de_esc_msg(R, err));
        return 2;
    }
    e = R->fixed != NULL ? neat_pop_set_params(duel_fixed_pop(R->fixed), &R->eff.neat)
                         : neat_coev_set_params(R->coev, &R->eff.neat, &R->eff.coev);
    if (e) {
        de_err(R, "[overrides] from %u: %s", g, neat_strerror(e));
        return 2;
    }
    duel_games_set_params(R->games, &R->eff.neat);
    de_log(R, "generation %u: overrides from here on: %s", g, R->cfg.over[k].sets);
    return 0;
}

/* The generation hook's record of generation g, the fields both kinds of run have: 0 when there is no hook. */
static int duel_hook_record(duel_engine *R, uint32_t g, double secs, duel_engine_record *rec)
{
    if (R->hooks.generation == NULL)
        return 0;
    memset(rec, 0, sizeof *rec);
    rec->generation = g;
    rec->generations = R->cfg.generations;
    rec->seconds = secs;
    rec->generations_rows = R->rows;
    rec->strength_row = R->have_strength ? R->strength_row : NULL;
    return 1;
}

/* A coevolution's generation, recorded: its line in log.txt, and the hook. */
static void duel_report(duel_engine *R, const neat_coev_report *rep, double secs)
{
    duel_engine_record rec;
    neat_dominant d;
    /* what the scores are out of: a host's games (its fitness is its wins), a comparison's games */
    uint32_t host_games = (uint32_t)(rep->pop[0].games / (R->cfg.neat.pop_size ? R->cfg.neat.pop_size : 1u));
    uint32_t cmp_games = 2u * R->eff.coev.compare_configs, cw = rep->champion_pop, dh, dc;
    neat_coev_dominant(R->coev, rep->dominants - 1u, &d);
    dh = neat_genome_hidden_count(d.genome);
    dc = neat_genome_enabled_count(d.genome);
    de_log(R, "generation %u: best A %.0f/%u B %.0f/%u wins, species A %u B %u, champion %s %u:%u of %u, "
              "dominance %u (%s%u hidden node%s, %u connection%s), %llu games in %.2f s",
           rep->generation, rep->pop[0].best_fitness, host_games, rep->pop[1].best_fitness, host_games,
           rep->pop[0].species, rep->pop[1].species, de_pop_name(cw), rep->champion_wins[cw],
           rep->champion_wins[cw ^ 1u], cmp_games, rep->dominants, rep->new_dominant ? "new: " : "", dh, de_s(dh), dc,
           de_s(dc), (unsigned long long)rep->games, secs);
    if (!duel_hook_record(R, rep->generation, secs, &rec))
        return;
    rec.coev = rep;
    rec.dominance_row = rep->new_dominant ? R->dominance_row : NULL;
    rec.dominants = rep->dominants;
    rec.dominant_generation = d.generation;
    rec.dominant_hidden = dh;
    rec.dominant_connections = dc;
    R->hooks.generation(R->hooks.ud, &rec);
}

/* A generation of a run against fixed opponents, recorded: its line in log.txt, and the hook. */
static void duel_report_fixed(duel_engine *R, const duel_fixed_report *rep, double secs)
{
    duel_engine_record rec;
    char vs[600], label[32];
    size_t at = 0;
    uint32_t k;
    vs[0] = '\0';
    for (k = 0; k < R->cfg.opp.n && at < sizeof vs; k++) {
        de_opp_label(R, k, label, sizeof label);
        at += (size_t)snprintf(vs + at, sizeof vs - at, "%s%s %u:%u", k ? ", " : "", label, rep->best_vs[k].wins_a,
                               rep->best_vs[k].wins_b);
    }
    de_log(R, "generation %u: best fitness %.0f (%u games a host), mean %.2f, species %u, champion %u hidden node%s, "
              "%u connection%s, against %s; %llu games in %.2f s",
           rep->generation, rep->best_fitness, rep->host_games, rep->mean_fitness, rep->species, rep->best_hidden,
           de_s(rep->best_hidden), rep->best_conns, de_s(rep->best_conns), vs, (unsigned long long)rep->games, secs);
    if (!duel_hook_record(R, rep->generation, secs, &rec))
        return;
    rec.fixed = rep;
    R->hooks.generation(R->hooks.ud, &rec);
}

/* The run's end in log.txt, once. */
static void duel_log_finished(duel_engine *R)
{
    uint32_t n = R->cfg.generations, dh, dc;
    if (R->finished_logged)
        return;
    R->finished_logged = 1;
    if (R->fixed != NULL) {
        const neat_genome *b = neat_pop_last_best(duel_fixed_pop(R->fixed));
        dh = neat_genome_hidden_count(b);
        dc = neat_genome_enabled_count(b);
        de_log(R, "finished %u generation%s: the last champion has %u hidden node%s, %u connection%s", n, de_s(n), dh,
               de_s(dh), dc, de_s(dc));
        return;
    }
    {
        neat_dominant d;
        uint32_t levels = neat_coev_dominant_count(R->coev);
        neat_coev_dominant(R->coev, levels - 1u, &d);
        dh = neat_genome_hidden_count(d.genome);
        dc = neat_genome_enabled_count(d.genome);
        de_log(R, "finished %u generation%s: dominance level %u, top dominant from generation %u (%u hidden node%s, "
                  "%u connection%s)",
               n, de_s(n), levels, d.generation, dh, de_s(dh), dc, de_s(dc));
    }
}

int duel_engine_step(duel_engine *R, uint32_t n)
{
    uint32_t played = 0;
    for (;;) {
        neat_coev_report rep;
        duel_fixed_report frep;
        double t0, secs;
        int err;
        if (R->log_failed)
            return DUEL_ENGINE_E_SYSTEM; /* what was done is saved; resume continues from it */
        if (de_next_gen(R) >= R->cfg.generations)
            break;
        if (R->stop || (duel_have_exec && duel_exec.stop_requested())) {
            de_log(R, "interrupted before generation %u", de_next_gen(R));
            R->stop = 0; /* the request is answered: a later step goes on */
            return DUEL_ENGINE_STOPPED;
        }
        if (n > 0 && played == n)
            return DUEL_ENGINE_OK;
        t0 = de_now();
        R->gen_in_flight = de_next_gen(R);
        if ((err = duel_apply_overrides(R, R->gen_in_flight)) != 0)
            return err;
        if (R->fixed != NULL) {
            err = duel_fixed_step(R->fixed, R->games, &frep);
        } else {
            duel_games_set_training(R->games, duel_train_config(&R->cfg, R->gen_in_flight));
            err = neat_coev_step(R->coev, duel_games_play, R->games, &rep);
        }
        if (err) {
            de_err(R, "generation %u failed: %s", R->gen_in_flight, de_game_error(err));
            de_log(R, "generation %u failed: %s", R->gen_in_flight, de_game_error(err));
            return DUEL_ENGINE_E_SYSTEM;
        }
        secs = de_now() - t0;
        R->gen_secs += secs;
        played++;
        if (R->fixed != NULL) {
            if (de_record_fixed(R, &frep, secs) != 0)
                return DUEL_ENGINE_E_SYSTEM;
            duel_report_fixed(R, &frep, secs);
        } else {
            if (de_record(R, &rep, secs) != 0)
                return DUEL_ENGINE_E_SYSTEM;
            duel_report(R, &rep, secs);
        }
    }
    if (R->stop) {
        de_log(R, "interrupted after the last generation");
        R->stop = 0;
        return DUEL_ENGINE_STOPPED;
    }
    duel_log_finished(R);
    return R->log_failed ? DUEL_ENGINE_E_SYSTEM : DUEL_ENGINE_OK;
}

void duel_engine_stop(duel_engine *R)
{
    R->stop = 1;
}

volatile sig_atomic_t *duel_engine_stop_flag(duel_engine *R)
{
    return &R->stop;
}

uint32_t duel_engine_generation(const duel_engine *R)
{
    return de_next_gen(R);
}

uint32_t duel_engine_generations(const duel_engine *R)
{
    return R->cfg.generations;
}

const char *duel_engine_dir(const duel_engine *R)
{
    return R->dir;
}

const duel_config *duel_engine_config(const duel_engine *R)
{
    return &R->cfg;
}

const duel_config *duel_engine_params(const duel_engine *R)
{
    return &R->eff;
}

const neat_coev *duel_engine_coev(const duel_engine *R)
{
    return R->coev;
}

const neat_pop *duel_engine_pop(const duel_engine *R)
{
    return R->fixed != NULL ? duel_fixed_pop(R->fixed) : NULL;
}

uint32_t duel_engine_threads(const duel_engine *R)
{
    return R->games != NULL ? duel_games_threads(R->games) : R->threads;
}

const char *duel_engine_last_error(const duel_engine *R)
{
    return R->last_error;
}

int duel_engine_close(duel_engine *R)
{
    char line[400];
    int r;
    if (R == NULL)
        return DUEL_ENGINE_OK;
    if (R->gen_secs > 0)
        de_log(R, "time: %.2f s in generations, %.2f s of it (%.1f %%) playing their %llu games", R->gen_secs,
               duel_games_seconds(R->games), 100.0 * duel_games_seconds(R->games) / R->gen_secs,
               (unsigned long long)duel_games_played(R->games));
    line[0] = '\0';
    if (duel_have_exec)
        duel_exec.describe(line, sizeof line);
    if (line[0] != '\0')
        de_log(R, "mpi: %s", line);
    /* its last lines missing from log.txt: said through the hook, and not a success */
    r = R->log_failed ? DUEL_ENGINE_E_SYSTEM : DUEL_ENGINE_OK;
    duel_games_free(R->games);
    R->games = NULL;
    de_engine_discard(R);
    return r;
}
