/* duel_exp.c - an experiment's runs played side by side as child processes (or as tasks on the slots of an MPI job), continued after any interruption, the best-topology champion chosen, every method compared and laddered. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "duel_child.h"
#include "duel_cores.h"
#include "duel_ctrl.h"
#include "duel_exp.h"
#include "duel_files.h"
#include "duel_generations.h"
#include "duel_mpi.h"
#include "duel_perf.h"
#include "duel_signal.h"
#include "neat_coev.h"
#include "duel_text.h"

/* Set by SIGINT/SIGTERM: the runs finish their generation and stop (they get the signal too). */
static volatile sig_atomic_t duel_exp_stop = 0;


void duel_exp_run_dir(char *out, size_t cap, const duel_plan *p, uint32_t i, uint32_t k)
{
    snprintf(out, cap, "runs/%s-%u", p->m[i].name, k);
}

static double duel_exp_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* ---- the directory: a new one, or one of this very plan */

/* Every entry of runs/ is a run of the plan, and each run's config.ini is the one the plan gives it. 0, or 2
 * after one line. */
static int duel_exp_check_runs(const duel_plan *p, const char *dir)
{
    DIR *d = opendir("runs");
    struct dirent *e;
    int rc = 0;
    if (d == NULL)
        return 0; /* no run yet */
    while (rc == 0 && (e = readdir(d)) != NULL) {
        uint32_t i, k = 0;
        char name[600], path[700], want_line[300], have_line[300];
        uint8_t *have;
        size_t len;
        char *want;
        if (e->d_name[0] == '.')
            continue;
        for (i = 0; i < p->n_methods; i++) {
            size_t n = strlen(p->m[i].name);
            char *end;
            unsigned long v;
            if (strncmp(e->d_name, p->m[i].name, n) != 0 || e->d_name[n] != '-' || e->d_name[n + 1] < '1' ||
                e->d_name[n + 1] > '9')
                continue;
            v = strtoul(e->d_name + n + 1, &end, 10);
            snprintf(name, sizeof name, "%s-%lu", p->m[i].name, v);
            if (*end == '\0' && v >= 1 && v <= p->m[i].runs && strcmp(name, e->d_name) == 0) {
                k = (uint32_t)v;
                break;
            }
        }
        if (k == 0) {
            fprintf(stderr, "duel_evolve: experiment: %s/runs/%s is no run of this plan (its runs are NAME-1 to "
                            "NAME-RUNS of each [method NAME]): move it away, or use another directory\n", duel_esc(dir),
                    e->d_name);
            rc = 2;
            break;
        }
        snprintf(name, sizeof name, "runs/%s", e->d_name);
        snprintf(path, sizeof path, "%s/config.ini", name);
        if (duel_file_read(path, 1u << 20, &have, &len) != 0)
            continue; /* died before writing it: the run starts over */
        want = duel_plan_run_config(p, i, k);
        if (want == NULL) {
            free(have);
            fprintf(stderr, "duel_evolve: experiment: out of memory\n");
            rc = 1;
            break;
        }
        have = (uint8_t *)realloc(have, len + 1);
        if (have != NULL) {
            uint32_t line;
            char *canon = duel_plan_cfg_canonical(path);
            have[len] = '\0';
            line = duel_plan_diff(canon != NULL ? canon : (const char *)have, want, have_line, want_line,
                                  sizeof have_line);
            free(canon);
            if (line != 0) {
                fprintf(stderr, "duel_evolve: experiment: %s/%s belongs to another plan: line %u is '%s', the plan "
                                "gives '%s'\n", duel_esc(dir), duel_esc(path), line, have_line, want_line);
                rc = 2;
            }
        } else {
            fprintf(stderr, "duel_evolve: experiment: out of memory\n");
            rc = 1;
        }
        free(have);
        free(want);
    }
    closedir(d);
    return rc;
}

/* dir created (or found), entered and locked, and holding this plan. 0, or the exit status after one line. */
int duel_exp_enter(const duel_plan *p, const char *dir, int create)
{
    struct stat st;
    char *text = duel_plan_text(p);
    uint8_t *have;
    size_t len;
    static duel_lock lock = {-1, -1}; /* held until the process ends */
    int rc;
    if (text == NULL) {
        fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        return 1;
    }
    if (stat(dir, &st) != 0) {
        if (!create) {
            fprintf(stderr, "duel_evolve: experiment: %s: %s\n", duel_esc(dir), strerror(errno));
            free(text);
            return 2;
        }
        if (duel_mkdir(dir) != 0) {
            fprintf(stderr, "duel_evolve: experiment: %s: cannot create: %s\n", duel_esc(dir), strerror(errno));
            free(text);
            return 2;
        }
    } else if (!S_ISDIR(st.st_mode)) {
        fprintf(stderr, "duel_evolve: experiment: %s: not a directory\n", duel_esc(dir));
        free(text);
        return 2;
    }
    if (chdir(dir) != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s: %s\n", duel_esc(dir), strerror(errno));
        free(text);
        return 2;
    }
    if (lock.dir_fd < 0 && lock.file_fd < 0 && duel_dir_lock(".", &lock) != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s: %s\n", duel_esc(dir),
                errno == EWOULDBLOCK ? "another duel_evolve experiment is working in it"
                : errno == ELOOP     ? ".lock is a symbolic link: refusing to follow it (remove it)"
                                     : strerror(errno));
        free(text);
        return 2;
    }
    rc = duel_file_read("plan.ini", 1u << 20, &have, &len);
    if (rc == 0) {
        char la[300], lb[300];
        uint32_t line;
        uint8_t *h = (uint8_t *)realloc(have, len + 1);
        if (h == NULL) {
            free(have);
            free(text);
            fprintf(stderr, "duel_evolve: experiment: out of memory\n");
            return 1;
        }
        h[len] = '\0';
        line = duel_plan_diff((const char *)h, text, la, lb, sizeof la);
        free(h);
        if (line != 0) {
            fprintf(stderr, "duel_evolve: experiment: %s/plan.ini holds another plan: line %u is '%s', this plan "
                            "gives '%s' (a changed plan needs a new directory)\n", duel_esc(dir), line, la, lb);
            free(text);
            return 2;
        }
    } else if (errno != ENOENT) {
        fprintf(stderr, "duel_evolve: experiment: %s/plan.ini: %s\n", duel_esc(dir), strerror(errno));
        free(text);
        return 2;
    } else {
        /* no plan.ini: only an empty directory becomes an experiment (the lock file aside) */
        DIR *d = opendir(".");
        struct dirent *e;
        int other = 0;
        while (d != NULL && (e = readdir(d)) != NULL)
            other |= strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0 && strcmp(e->d_name, ".lock") != 0;
        if (d != NULL)
            closedir(d);
        if (other || !create) {
            fprintf(stderr, "duel_evolve: experiment: %s: %s\n", duel_esc(dir),
                    create ? "not empty and not an experiment directory (no plan.ini): choose another --out"
                           : "not an experiment directory (no plan.ini)");
            free(text);
            return 2;
        }
    }
    free(text);
    /* the stored method configurations are the plan's (a changed preset is a changed plan) */
    {
        uint32_t i;
        for (i = 0; i < p->n_methods; i++) {
            char path[200], la[300], lb[300];
            uint8_t *c;
            size_t n;
            snprintf(path, sizeof path, "configs/%s.ini", p->m[i].name);
            if (duel_file_read(path, 1u << 20, &c, &n) != 0)
                continue;
            if ((have = (uint8_t *)realloc(c, n + 1)) == NULL) {
                free(c);
                fprintf(stderr, "duel_evolve: experiment: out of memory\n");
                return 1;
            }
            have[n] = '\0';
            {
                /* compared as this build writes it: an earlier build's form of the same values is the same */
                char *canon = duel_plan_cfg_canonical(path);
                if (canon != NULL) {
                    free(have);
                    have = (uint8_t *)canon;
                }
            }
            if (duel_plan_diff((const char *)have, p->m[i].cfg_text, la, lb, sizeof la) != 0) {
                fprintf(stderr, "duel_evolve: experiment: %s/%s differs from what the plan's preset gives now "
                                "('%s' there, '%s' now): a changed plan needs a new directory\n", duel_esc(dir), duel_esc(path), la, lb);
                free(have);
                return 2;
            }
            free(have);
        }
    }
    rc = duel_exp_check_runs(p, dir);
    if (rc != 0)
        return rc;
    /* written again each time (the same bytes): a deleted configs/NAME.ini comes back for the runs to read */
    if (create && duel_plan_save(p, ".") != 0)
        return 1;
    return 0;
}

/* ---- one run: its state, the child process that plays it, its progress */

enum { DUEL_RUN_NEW = 0, DUEL_RUN_PARTIAL = 1, DUEL_RUN_DONE = 2 };

typedef struct duel_exp_run_state {
    uint32_t method, k, generations;
    char dir[300];
    int state;
    pid_t pid;                 /* running: its child (one process), 0 otherwise */
    int running;               /* played now (as a child, or by a slot of an MPI job) */
    uint32_t gen_done;         /* from generations.csv, for the progress line */
    double seconds;            /* the seconds of the generations recorded */
    double games;              /* the games they played */
} duel_exp_run_state;

/* generations.csv of a run: the generations recorded, their seconds and games (population A's rows hold them). */
static void duel_exp_progress_of(duel_exp_run_state *r)
{
    duel_gen_row *rows;
    size_t n, k;
    char err[600];
    double secs = 0.0, games = 0.0;
    if (duel_generations_read(r->dir, &rows, &n, err, sizeof err) != 0)
        return; /* not yet there, or being written: the next look */
    for (k = 0; k < n; k++)
        if (rows[k].pop == 'A') {
            secs += rows[k].seconds;
            games += rows[k].games;
        }
    r->gen_done = duel_generations_done(rows, n);
    r->seconds = secs;
    r->games = games;
    free(rows);
}

/* The dominance levels of a run so far (the rows of its dominance.csv). */
static uint32_t duel_exp_levels(const duel_exp_run_state *r)
{
    char path[400];
    uint8_t *data;
    size_t len, i;
    uint32_t n = 0;
    snprintf(path, sizeof path, "%s/dominance.csv", r->dir);
    if (duel_file_read(path, 64u << 20, &data, &len) != 0)
        return 0;
    for (i = 0; i < len; i++)
        n += data[i] == '\n';
    free(data);
    return n > 0 ? n - 1 : 0;
}

static int duel_exp_state(duel_exp_run_state *r)
{
    char path[400];
    neat_coev *c;
    int e;
    snprintf(path, sizeof path, "%s/checkpoint.bin", r->dir);
    e = duel_ckpt_load("experiment: ", path, &c);
    if (e < 0)
        return -1;
    if (e > 0) {
        r->state = DUEL_RUN_NEW;
        return 0;
    }
    r->state = neat_coev_generation(c) >= r->generations ? DUEL_RUN_DONE : DUEL_RUN_PARTIAL;
    neat_coev_free(c);
    return 0;
}

/* The command line that plays run r from where it is: argv[0] the subcommand (run or resume), in a's buffers. */
typedef struct duel_exp_args {
    char cfg[200], seed[16], thr[16];
    char *argv[16];
    int argc;
} duel_exp_args;

static void duel_exp_run_args(duel_exp_args *a, const duel_plan *p, duel_exp_run_state *r, uint32_t threads)
{
    int n = 0;
    snprintf(a->thr, sizeof a->thr, "%u", threads);
    if (r->state == DUEL_RUN_NEW) {
        snprintf(a->cfg, sizeof a->cfg, "configs/%s.ini", p->m[r->method].name);
        snprintf(a->seed, sizeof a->seed, "%u", p->seed + (r->k - 1));
        a->argv[n++] = (char *)"run";
        a->argv[n++] = (char *)"--config";
        a->argv[n++] = a->cfg;
        a->argv[n++] = (char *)"--seed";
        a->argv[n++] = a->seed;
        a->argv[n++] = (char *)"--out";
        a->argv[n++] = r->dir;
    } else {
        a->argv[n++] = (char *)"resume";
        a->argv[n++] = r->dir;
    }
    a->argv[n++] = (char *)"--threads";
    a->argv[n++] = a->thr;
    a->argv[n++] = (char *)"--quiet";
    a->argv[n] = NULL;
    a->argc = n;
}

static pid_t duel_exp_start_run(const char *self, const duel_plan *p, duel_exp_run_state *r, uint32_t threads)
{
    duel_exp_args a;
    char *argv[17];
    int i;
    duel_exp_run_args(&a, p, r, threads);
    argv[0] = (char *)"duel_evolve";
    for (i = 0; i <= a.argc; i++)
        argv[i + 1] = a.argv[i];
    return duel_child_spawn(self, argv, 1);
}

static void duel_exp_hms(char *out, size_t cap, double s)
{
    unsigned long t = s > 0 ? (unsigned long)(s + 0.5) : 0;
    snprintf(out, cap, "%lu:%02lu:%02lu", t / 3600, t / 60 % 60, t % 60);
}

typedef struct duel_exp_sched {
    const duel_plan *p;
    duel_exp_run_state *runs;
    uint32_t n_runs, done;
    int tty, quiet;
    double started, last_line;
} duel_exp_sched;

/* Seconds a generation of method i takes: measured on its runs so far, else the mean of all runs. */
static double duel_exp_rate(const duel_exp_sched *s, uint32_t method)
{
    double secs = 0.0, all_secs = 0.0;
    uint32_t gens = 0, all_gens = 0, k;
    for (k = 0; k < s->n_runs; k++) {
        const duel_exp_run_state *r = &s->runs[k];
        all_secs += r->seconds;
        all_gens += r->gen_done;
        if (r->method == method) {
            secs += r->seconds;
            gens += r->gen_done;
        }
    }
    if (gens > 0)
        return secs / gens;
    return all_gens > 0 ? all_secs / all_gens : 0.0;
}

static void duel_exp_show(duel_exp_sched *s, uint32_t jobs, int final)
{
    char line[1024], eta[32];
    size_t n = 0;
    double left = 0.0;
    uint32_t k, running = 0;
    double now = duel_exp_now();
    if (s->quiet || (!final && now - s->last_line < (s->tty ? 1.0 : 60.0)))
        return;
    s->last_line = now;
    for (k = 0; k < s->n_runs; k++) {
        duel_exp_run_state *r = &s->runs[k];
        if (r->running)
            duel_exp_progress_of(r);
        if (r->state != DUEL_RUN_DONE)
            left += duel_exp_rate(s, r->method) * (double)(r->generations - (r->gen_done < r->generations ? r->gen_done : r->generations));
    }
    {
        /* then the comparisons and ladders, 288 games each, at the games per second the runs played: every
         * run's top dominant against each level of each reference ranking (as many levels as the finished
         * reference runs have, 10 before there is one) and against the built-in strategies */
        double secs = 0.0, games = 0.0, levels = 0.0, cmp;
        uint32_t n_ref = 0, done_ref = 0;
        for (k = 0; k < s->n_runs; k++) {
            secs += s->runs[k].seconds;
            games += s->runs[k].games;
            if (s->runs[k].method == s->p->ref) {
                n_ref++;
                if (s->runs[k].state == DUEL_RUN_DONE) {
                    levels += duel_exp_levels(&s->runs[k]);
                    done_ref++;
                }
            }
        }
        levels = done_ref ? levels / done_ref : 10.0;
        cmp = ((double)s->n_runs * n_ref * levels + (double)s->n_runs * DUEL_N_BUILTINS) * 2.0 * DUEL_CONFIGS;
        if (games > 0.0)
            left += cmp * secs / games;
    }
    if (left > 0.0)
        duel_exp_hms(eta, sizeof eta, left / (jobs ? jobs : 1));
    else
        snprintf(eta, sizeof eta, "%s", s->done == s->n_runs ? "0:00:00" : "(measuring)");
    n += (size_t)snprintf(line + n, sizeof line - n, "experiment: %u/%u runs done", s->done, s->n_runs);
    for (k = 0; k < s->n_runs && n < sizeof line - 80; k++)
        if (s->runs[k].running)
            n += (size_t)snprintf(line + n, sizeof line - n, "%s %s %u/%u", running++ ? "," : ";",
                                  s->runs[k].dir + 5, s->runs[k].gen_done, s->runs[k].generations);
    snprintf(line + n, sizeof line - n, "; about %s to the end", eta);
    if (s->tty)
        fprintf(stderr, "\r%s\033[K", line);
    else
        fprintf(stderr, "%s\n", line);
}

/* ---- the best-topology champion */

/* The reference method's champion with the highest performance against the other reference runs' rankings
 * ("highest" reading, then "contiguous", then the first run), copied to best-topology.blob and described in
 * best-topology.txt. 0, or the exit status after one line. */
static int duel_exp_choose_best(const duel_plan *p, uint32_t threads)
{
    const duel_plan_method *m = &p->m[p->ref];
    const char **dirs = (const char **)calloc(m->runs, sizeof *dirs);
    char (*names)[300] = (char (*)[300])calloc(m->runs, sizeof *names);
    duel_perf perf;
    duel_perf_opts o;
    uint32_t k, best = 0;
    int rc, chosen_now;
    if (dirs == NULL || names == NULL) {
        free(dirs);
        free(names);
        fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        return 1;
    }
    for (k = 0; k < m->runs; k++) {
        duel_exp_run_dir(names[k], sizeof names[k], p, p->ref, k + 1);
        dirs[k] = names[k];
    }
    memset(&o, 0, sizeof o);
    o.threads = threads;
    o.prefix = "experiment: ";
    o.progress = isatty(STDERR_FILENO);
    rc = duel_perf_measure(&perf, dirs, m->runs, dirs, m->runs, &o);
    if (rc == 0) {
        const duel_level *top;
        char path[400], text[1200];
        uint8_t *have;
        size_t len;
        for (k = 1; k < m->runs; k++)
            if (perf.perf_hi[k] > perf.perf_hi[best] ||
                (perf.perf_hi[k] == perf.perf_hi[best] && perf.perf_co[k] > perf.perf_co[best]))
                best = k;
        top = &perf.runs[best].levels[perf.runs[best].n_levels - 1];
        snprintf(path, sizeof path, "%s/champions/gen-%05u.blob", names[best], top->generation);
        snprintf(text, sizeof text,
                 "; start = best of this experiment: the %s champion with the highest performance against the other "
                 "%s runs' dominance rankings\nrun = %s\nchampion = %s\nlevel = %u\ngeneration = %u\nhidden = %u\n"
                 "connections = %u\nperformance_highest = %.6f\nperformance_contiguous = %.6f\n",
                 m->name, m->name, names[best] + 5, path, perf.runs[best].n_levels, top->generation, top->hidden,
                 top->conns, perf.perf_hi[best], perf.perf_co[best]);
        chosen_now = 0;
        if (duel_file_read(DUEL_PLAN_BEST_BLOB, DUEL_CKPT_MAX, &have, &len) == 0) {
            int same = len == top->ctrl.blob_len && memcmp(have, top->ctrl.blob, len) == 0;
            free(have);
            if (!same) {
                fprintf(stderr, "duel_evolve: experiment: %s is not %s, the champion this plan chooses: it was "
                                "changed by hand\n", DUEL_PLAN_BEST_BLOB, duel_esc(path));
                rc = 2;
            }
        } else if (duel_file_replace(DUEL_PLAN_BEST_BLOB, top->ctrl.blob, top->ctrl.blob_len) != 0) {
            fprintf(stderr, "duel_evolve: experiment: %s: cannot write: %s\n", DUEL_PLAN_BEST_BLOB, strerror(errno));
            rc = 1;
        } else {
            chosen_now = 1;
        }
        if (rc == 0 && duel_file_replace("best-topology.txt", text, strlen(text)) != 0) {
            fprintf(stderr, "duel_evolve: experiment: best-topology.txt: cannot write: %s\n", strerror(errno));
            rc = 1;
        }
        if (rc == 0 && chosen_now)
            fprintf(stderr, "experiment: the best %s champion: %s (level %u, %u hidden, %u connections, performance "
                            "%.1f %%)\n", m->name, duel_esc(path), perf.runs[best].n_levels, top->hidden, top->conns,
                    100.0 * perf.perf_hi[best]);
    }
    duel_perf_free(&perf);
    free(dirs);
    free(names);
    return rc;
}

/* ---- the whole experiment */

static int duel_exp_any_best(const duel_plan *p)
{
    uint32_t i;
    for (i = 0; i < p->n_methods; i++)
        if (p->m[i].start_best)
            return 1;
    return 0;
}

/* Every run of the plan to the end, jobs at a time: the reference method's first, the start = best methods' once
 * the champion is chosen. 0, or the exit status after one line. */
/* "; its log: DIR/log.txt" when the failed run wrote one, else where its error is (never a log that is not there). */
static const char *duel_exp_log_hint(const char *dir, char *buf, size_t cap)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/log.txt", dir);
    if (access(path, F_OK) == 0)
        snprintf(buf, cap, "; its log: %s", path);
    else
        snprintf(buf, cap, "; it wrote no log: its error is the line above");
    return buf;
}

static int duel_exp_play_runs(duel_exp_sched *s, const char *self, uint32_t jobs, uint32_t threads,
                              uint32_t cmp_threads)
{
    const duel_plan *p = s->p;
    uint32_t k, running = 0, ref_left = 0;
    int best_ready = !duel_exp_any_best(p), failed = 0;
    int forwarded = 0;
    char hint[4300];
    for (k = 0; k < s->n_runs; k++)
        ref_left += s->runs[k].method == p->ref && s->runs[k].state != DUEL_RUN_DONE;
    for (;;) {
        int status;
        pid_t pid;
        if (!best_ready && ref_left == 0 && !duel_exp_stop && !failed) {
            /* at once, beside the runs still going (they share the cores; nothing depends on who is first) */
            int rc;
            if (s->tty && !s->quiet)
                fprintf(stderr, "\r\033[K");
            rc = duel_exp_choose_best(p, cmp_threads);
            if (rc != 0)
                return rc;
            best_ready = 1;
        }
        /* start what may start */
        for (k = 0; k < s->n_runs && running < jobs && !duel_exp_stop && !failed; k++) {
            duel_exp_run_state *r = &s->runs[k];
            if (r->state == DUEL_RUN_DONE || r->pid != 0 || (p->m[r->method].start_best && !best_ready))
                continue;
            r->pid = duel_exp_start_run(self, p, r, threads);
            if (r->pid < 0) {
                fprintf(stderr, "duel_evolve: experiment: cannot start a run: %s\n", strerror(errno));
                r->pid = 0;
                failed = 1;
                break;
            }
            r->running = 1;
            running++;
        }
        if (running == 0)
            break;
        if (duel_exp_stop && !forwarded) {
            /* a signal to this process alone (kill -INT): the runs finish their generation and save it */
            for (k = 0; k < s->n_runs; k++)
                if (s->runs[k].pid > 0)
                    kill(s->runs[k].pid, SIGINT);
            forwarded = 1;
        }
        duel_exp_show(s, jobs, 0);
        pid = waitpid(-1, &status, WNOHANG);
        if (pid == 0 || (pid < 0 && errno == EINTR)) {
            struct timespec ts = {0, 200000000L};
            nanosleep(&ts, NULL);
            continue;
        }
        if (pid < 0)
            break;
        for (k = 0; k < s->n_runs && s->runs[k].pid != pid; k++)
            ;
        if (k == s->n_runs)
            continue;
        running--;
        s->runs[k].pid = 0;
        s->runs[k].running = 0;
        duel_exp_progress_of(&s->runs[k]);
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
            s->runs[k].state = DUEL_RUN_DONE;
            s->done++;
            ref_left -= s->runs[k].method == p->ref;
        } else {
            s->runs[k].state = DUEL_RUN_PARTIAL;
            if (!duel_exp_stop) {
                if (s->tty && !s->quiet)
                    fprintf(stderr, "\r\033[K");
                fprintf(stderr, "duel_evolve: experiment: %s failed (%s %d)%s\n", duel_esc(s->runs[k].dir),
                        WIFEXITED(status) ? "exit status" : "signal",
                        WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status),
                        duel_exp_log_hint(s->runs[k].dir, hint, sizeof hint));
                failed = 1;
            }
        }
    }
    if (!s->quiet) {
        duel_exp_show(s, jobs, 1);
        if (s->tty)
            fprintf(stderr, "\n");
    }
    if (duel_exp_stop)
        return 130;
    return failed ? 1 : 0;
}

/* ---- the runs, comparisons and ladders over the slots of an MPI job (tools/mpi/duel_mpi.h) */

enum { DUEL_TASK_NONE = 0, DUEL_TASK_RUN, DUEL_TASK_COMPARE, DUEL_TASK_LADDER };

typedef struct duel_exp_slot {
    int kind;   /* DUEL_TASK_* (NONE: free) */
    uint32_t run;
} duel_exp_slot;

/* `compare RUN --against REF... --threads T`: run k's comparisons against the reference rankings, cached in
 * RUN/compare-cache.csv (the report reads them from there, as if they had been played there). */
static int duel_exp_start_compare(const duel_exp_sched *s, uint32_t slot, uint32_t k)
{
    const duel_plan *p = s->p;
    uint32_t n = p->m[p->ref].runs, j;
    char **argv = (char **)calloc(n + 6, sizeof *argv), thr[16];
    char (*refs)[300] = (char (*)[300])calloc(n, sizeof *refs);
    int argc = 0, rc = -1;
    if (argv != NULL && refs != NULL) {
        snprintf(thr, sizeof thr, "%u", duel_mpi_exp_slot_threads(slot));
        argv[argc++] = (char *)"compare";
        argv[argc++] = (char *)s->runs[k].dir;
        argv[argc++] = (char *)"--against";
        for (j = 0; j < n; j++) {
            duel_exp_run_dir(refs[j], sizeof refs[j], p, p->ref, j + 1);
            argv[argc++] = refs[j];
        }
        argv[argc++] = (char *)"--threads";
        argv[argc++] = thr;
        rc = duel_mpi_exp_start(slot, argc, argv);
    }
    free(argv);
    free(refs);
    return rc;
}

static int duel_exp_has_ladder(const duel_exp_run_state *r)
{
    char path[400];
    struct stat st;
    snprintf(path, sizeof path, "%s/ladder.csv", r->dir);
    return stat(path, &st) == 0;
}

/* Every run to its end, every run compared against the reference rankings, every run laddered, tasks handed to
 * the slots as they become free: first the reference runs' comparisons (the best-topology champion waits for
 * them), then the runs, then the other comparisons, then the ladders. The comparisons and ladders that
 * duel_exp_run does next then find everything in the caches. 0, or the exit status after one line. */
static int duel_exp_play_mpi(duel_exp_sched *s)
{
    const duel_plan *p = s->p;
    uint32_t n_slots, k, j, left = 0, ref_runs_left = 0, ref_cmp_left = 0, busy = 0;
    duel_exp_slot *slot;
    uint8_t *cmp_done, *lad_done;
    int best_ready = !duel_exp_any_best(p), failed = 0, forwarded = 0;
    char hint[4300];
    for (k = 0; k < s->n_runs; k++)
        left += s->runs[k].state != DUEL_RUN_DONE;
    n_slots = duel_mpi_exp_open(left);
    slot = (duel_exp_slot *)calloc(n_slots + 1u, sizeof *slot);
    cmp_done = (uint8_t *)calloc(s->n_runs, 1);
    lad_done = (uint8_t *)calloc(s->n_runs, 1);
    if (n_slots == 0 || slot == NULL || cmp_done == NULL || lad_done == NULL) {
        free(slot);
        free(cmp_done);
        free(lad_done);
        fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        return 1;
    }
    for (j = 0; j < n_slots; j++)
        for (k = 0; k < p->n_methods; k++)
            if (duel_mpi_exp_slot_ranks(j) > 2u * p->m[k].cfg.neat.pop_size) {
                /* the run would refuse it (duel_run.c): say so before anything starts */
                fprintf(stderr, "duel_evolve: experiment: %u MPI ranks make groups of %u ranks, more than the 2 x %u "
                                "networks of a %s run can use: at most %u ranks a run (docs/cluster.md)\n",
                        duel_mpi_size(), duel_mpi_exp_slot_ranks(j), p->m[k].cfg.neat.pop_size, p->m[k].name,
                        2u * p->m[k].cfg.neat.pop_size);
                free(slot);
                free(cmp_done);
                free(lad_done);
                return 2;
            }
    if (!s->quiet) {
        fprintf(stderr, "experiment: %u MPI ranks as %u slot%s (", duel_mpi_size(), n_slots, n_slots == 1 ? "" : "s");
        for (j = 0; j < n_slots; j++)
            fprintf(stderr, "%s%u rank%s x %u threads", j ? ", " : "", duel_mpi_exp_slot_ranks(j),
                    duel_mpi_exp_slot_ranks(j) == 1 ? "" : "s", duel_mpi_exp_slot_threads(j));
        fprintf(stderr, ")\n");
    }
    for (k = 0; k < s->n_runs; k++) {
        lad_done[k] = (uint8_t)duel_exp_has_ladder(&s->runs[k]);
        if (s->runs[k].method == p->ref) {
            ref_runs_left += s->runs[k].state != DUEL_RUN_DONE;
            ref_cmp_left++;
        }
    }
    for (;;) {
        uint32_t which;
        int status;
        if (duel_exp_stop && !forwarded) {
            for (j = 0; j < n_slots; j++)
                if (slot[j].kind != DUEL_TASK_NONE)
                    duel_mpi_exp_interrupt(j);
            forwarded = 1;
        }
        if (!best_ready && ref_runs_left == 0 && ref_cmp_left == 0 && !duel_exp_stop && !failed) {
            /* every comparison it needs is cached: nothing is played here */
            int rc;
            if (s->tty && !s->quiet)
                fprintf(stderr, "\r\033[K");
            rc = duel_exp_choose_best(p, duel_mpi_default_threads());
            if (rc != 0) {
                failed = rc;
                continue;
            }
            best_ready = 1;
        }
        for (j = 0; j < n_slots && !duel_exp_stop && !failed; j++) {
            int kind = DUEL_TASK_NONE, rc;
            uint32_t pick = 0, pass;
            if (slot[j].kind != DUEL_TASK_NONE)
                continue;
            for (pass = 0; pass < 4 && kind == DUEL_TASK_NONE; pass++)
                for (k = 0; k < s->n_runs && kind == DUEL_TASK_NONE; k++) {
                    duel_exp_run_state *r = &s->runs[k];
                    int is_ref = r->method == p->ref, can_cmp = r->state == DUEL_RUN_DONE && !cmp_done[k] &&
                                                                !r->running && ref_runs_left == 0;
                    if (pass == 0 && is_ref && can_cmp)
                        kind = DUEL_TASK_COMPARE;
                    else if (pass == 1 && r->state != DUEL_RUN_DONE && !r->running &&
                             (!p->m[r->method].start_best || best_ready))
                        kind = DUEL_TASK_RUN;
                    else if (pass == 2 && can_cmp)
                        kind = DUEL_TASK_COMPARE;
                    else if (pass == 3 && r->state == DUEL_RUN_DONE && !lad_done[k] && !r->running)
                        kind = DUEL_TASK_LADDER;
                    pick = k;
                }
            if (kind == DUEL_TASK_NONE)
                break;
            if (kind == DUEL_TASK_RUN) {
                duel_exp_args a;
                duel_exp_run_args(&a, p, &s->runs[pick], duel_mpi_exp_slot_threads(j));
                rc = duel_mpi_exp_start(j, a.argc, a.argv);
            } else if (kind == DUEL_TASK_COMPARE) {
                rc = duel_exp_start_compare(s, j, pick);
            } else {
                char *argv[4];
                argv[0] = (char *)"ladder";
                argv[1] = s->runs[pick].dir;
                argv[2] = (char *)"--top";
                argv[3] = NULL;
                rc = duel_mpi_exp_start(j, 3, argv);
            }
            if (rc != 0) {
                fprintf(stderr, "duel_evolve: experiment: cannot hand %s a task\n", s->runs[pick].dir);
                failed = 1;
                break;
            }
            slot[j].kind = kind;
            slot[j].run = pick;
            s->runs[pick].running = 1;
            busy++;
        }
        if (busy == 0)
            break;
        duel_exp_show(s, n_slots, 0);
        if (!duel_mpi_exp_poll(&which, &status)) {
            struct timespec ts = {0, 20000000L};
            nanosleep(&ts, NULL);
            continue;
        }
        k = slot[which].run;
        busy--;
        s->runs[k].running = 0;
        if (slot[which].kind == DUEL_TASK_RUN) {
            duel_exp_progress_of(&s->runs[k]);
            if (status == 0) {
                s->runs[k].state = DUEL_RUN_DONE;
                s->done++;
                ref_runs_left -= s->runs[k].method == p->ref;
            } else {
                s->runs[k].state = DUEL_RUN_PARTIAL;
            }
        } else if (status == 0 && slot[which].kind == DUEL_TASK_COMPARE) {
            cmp_done[k] = 1;
            ref_cmp_left -= s->runs[k].method == p->ref;
        } else if (status == 0) {
            lad_done[k] = 1;
        }
        if (status != 0 && !duel_exp_stop && !failed) {
            if (s->tty && !s->quiet)
                fprintf(stderr, "\r\033[K");
            fprintf(stderr, "duel_evolve: experiment: %s of %s failed (exit status %d)%s\n",
                    slot[which].kind == DUEL_TASK_RUN ? "the run" : slot[which].kind == DUEL_TASK_COMPARE ?
                                                                     "the comparison" : "the ladder",
                    duel_esc(s->runs[k].dir), status,
                    slot[which].kind == DUEL_TASK_RUN ? duel_exp_log_hint(s->runs[k].dir, hint, sizeof hint) : "");
            failed = status == 2 ? 2 : 1;
        }
        slot[which].kind = DUEL_TASK_NONE;
    }
    if (!s->quiet) {
        duel_exp_show(s, n_slots, 1);
        if (s->tty)
            fprintf(stderr, "\n");
    }
    free(slot);
    free(cmp_done);
    free(lad_done);
    if (duel_exp_stop)
        return 130;
    return failed;
}

/* Every method's runs against the reference rankings (played once, then cached in each run). */
static int duel_exp_compare_all(const duel_plan *p, uint32_t threads)
{
    uint32_t i, k;
    const duel_plan_method *ref = &p->m[p->ref];
    for (i = 0; i < p->n_methods && !duel_exp_stop; i++) {
        const duel_plan_method *m = &p->m[i];
        const char **cand = (const char **)calloc(m->runs, sizeof *cand);
        const char **against = (const char **)calloc(ref->runs, sizeof *against);
        char (*cn)[300] = (char (*)[300])calloc(m->runs, sizeof *cn);
        char (*an)[300] = (char (*)[300])calloc(ref->runs, sizeof *an);
        duel_perf perf;
        duel_perf_opts o;
        char prefix[100];
        int rc = 1;
        if (cand != NULL && against != NULL && cn != NULL && an != NULL) {
            for (k = 0; k < m->runs; k++) {
                duel_exp_run_dir(cn[k], sizeof cn[k], p, i, k + 1);
                cand[k] = cn[k];
            }
            for (k = 0; k < ref->runs; k++) {
                duel_exp_run_dir(an[k], sizeof an[k], p, p->ref, k + 1);
                against[k] = an[k];
            }
            snprintf(prefix, sizeof prefix, "experiment: %s: ", m->name);
            memset(&o, 0, sizeof o);
            o.threads = threads;
            o.prefix = prefix;
            o.progress = isatty(STDERR_FILENO);
            rc = duel_perf_measure(&perf, cand, m->runs, against, ref->runs, &o);
            duel_perf_free(&perf);
        } else {
            fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        }
        free(cand);
        free(against);
        free(cn);
        free(an);
        if (rc != 0)
            return rc;
    }
    return duel_exp_stop ? 130 : 0;
}

/* `duel_evolve ladder RUN --top` for each run without its ladder.csv, jobs at a time. */
static int duel_exp_ladders(const duel_exp_sched *s, const char *self, uint32_t jobs)
{
    uint32_t k = 0, running = 0;
    int failed = 0;
    pid_t *pids = (pid_t *)calloc(s->n_runs, sizeof *pids);
    if (pids == NULL) {
        fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        return 1;
    }
    for (;;) {
        int status;
        pid_t pid;
        uint32_t j;
        for (; k < s->n_runs && running < jobs && !duel_exp_stop && !failed; k++) {
            char *argv[5];
            if (duel_exp_has_ladder(&s->runs[k]))
                continue;
            argv[0] = (char *)"duel_evolve";
            argv[1] = (char *)"ladder";
            argv[2] = (char *)s->runs[k].dir;
            argv[3] = (char *)"--top";
            argv[4] = NULL;
            pids[k] = duel_child_spawn(self, argv, 1);
            if (pids[k] < 0) {
                pids[k] = 0;
                failed = 1;
                break;
            }
            running++;
        }
        if (running == 0)
            break;
        pid = waitpid(-1, &status, 0);
        if (pid < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        for (j = 0; j < s->n_runs && pids[j] != pid; j++)
            ;
        if (j == s->n_runs)
            continue;
        running--;
        pids[j] = 0;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            if (!duel_exp_stop)
                fprintf(stderr, "duel_evolve: experiment: duel_evolve ladder %s failed\n", s->runs[j].dir);
            failed = 1;
        }
    }
    free(pids);
    if (duel_exp_stop)
        return 130;
    return failed ? 1 : 0;
}

int duel_exp_run(const duel_plan *p, const char *dir, const duel_exp_opts *o)
{
    duel_exp_sched s;
    char self[4096];
    uint32_t i, k, jobs, threads, cores;
    int rc;

    cores = duel_cores();
    jobs = o->jobs ? o->jobs : cores;
    threads = o->threads ? o->threads : (cores / jobs ? cores / jobs : 1);
    if (duel_child_self(self, sizeof self) != 0) {
        fprintf(stderr, "duel_evolve: experiment: cannot find this program (/proc/self/exe): %s\n", strerror(errno));
        return 1;
    }
    rc = duel_exp_enter(p, dir, 1);
    if (rc != 0)
        return rc;
    memset(&s, 0, sizeof s);
    s.p = p;
    s.tty = isatty(STDERR_FILENO);
    s.quiet = o->quiet;
    s.started = duel_exp_now();
    for (i = 0; i < p->n_methods; i++)
        s.n_runs += p->m[i].runs;
    s.runs = (duel_exp_run_state *)calloc(s.n_runs, sizeof *s.runs);
    if (s.runs == NULL) {
        fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        return 1;
    }
    /* the reference method's runs first: the best-topology champion needs them */
    for (i = 0, s.n_runs = 0; i < p->n_methods; i++) {
        uint32_t m = i == 0 ? p->ref : (i <= p->ref ? i - 1 : i);
        for (k = 1; k <= p->m[m].runs; k++) {
            duel_exp_run_state *r = &s.runs[s.n_runs++];
            r->method = m;
            r->k = k;
            r->generations = p->m[m].cfg.generations;
            duel_exp_run_dir(r->dir, sizeof r->dir, p, m, k);
            if (duel_exp_state(r) != 0) {
                free(s.runs);
                return 2;
            }
            duel_exp_progress_of(r);
            s.done += r->state == DUEL_RUN_DONE;
        }
    }
    if (duel_mkdir("runs") != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s/runs: cannot create: %s\n", duel_esc(dir), strerror(errno));
        free(s.runs);
        return 1;
    }
    if (!o->quiet && duel_mpi_size() > 1)
        fprintf(stderr, "experiment %s: %u methods, %u runs (%u done)\n", duel_esc(dir), p->n_methods, s.n_runs, s.done);
    else if (!o->quiet)
        fprintf(stderr, "experiment %s: %u methods, %u runs (%u done), %u side by side with %u thread%s each\n", duel_esc(dir),
                p->n_methods, s.n_runs, s.done, jobs, threads, threads == 1 ? "" : "s");
    duel_signal_install(&duel_exp_stop, "duel_evolve: experiment: a second signal: stopped at once; the runs keep "
                                        "their last generation (duel_evolve experiment resume continues)\n");
    if (duel_mpi_size() > 1)
        rc = duel_exp_play_mpi(&s);
    else
        rc = duel_exp_play_runs(&s, self, jobs, threads, o->threads ? o->threads : 0);
    if (rc == 0 && !o->quiet)
        fprintf(stderr, "experiment: every method against the %s rankings\n", p->reference);
    if (rc == 0)
        rc = duel_exp_compare_all(p, o->threads ? o->threads : 0);
    if (rc == 0)
        rc = duel_exp_ladders(&s, self, jobs);
    free(s.runs);
    if (rc == 130) {
        fprintf(stderr, "duel_evolve: experiment: interrupted; what is done is kept. Continue with: duel_evolve "
                        "experiment resume %s\n", duel_esc(dir));
        return rc;
    }
    if (rc != 0)
        return rc;
    return duel_exp_report_here(p, dir);
}
