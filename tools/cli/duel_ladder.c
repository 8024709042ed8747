/* duel_ladder.c - `duel_evolve ladder DIR`: every dominant strategy of a run against the built-in strategies, into ladder.csv. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "duel_cli.h"
#include "duel_ctrl.h"
#include "duel_dominance.h"
#include "duel_files.h"

typedef struct duel_rung {
    uint32_t level, generation, hidden, conns;
    char pop[8];
    duel_cli_ctrl ctrl;          /* only for loading; games use their own copies */
    duel_tally tally[DUEL_N_BUILTINS];
} duel_rung;

typedef struct duel_ladder_job {
    duel_rung *rungs;
    uint32_t n_rungs, next;
    pthread_mutex_t lock;
    int err;
} duel_ladder_job;

/* One comparison per (rung, builtin), taken in turn by each thread. */
static void *duel_ladder_worker(void *arg)
{
    duel_ladder_job *job = (duel_ladder_job *)arg;
    for (;;) {
        uint32_t k;
        duel_rung *r;
        duel_controller net, builtin;
        nrt_net mine;
        void *mem;
        size_t need;
        int err;
        pthread_mutex_lock(&job->lock);
        k = job->next++;
        pthread_mutex_unlock(&job->lock);
        if (k >= job->n_rungs * DUEL_N_BUILTINS)
            return NULL;
        r = &job->rungs[k / DUEL_N_BUILTINS];
        /* a network state per thread: load the blob again */
        nrt_mem_required(r->ctrl.blob, r->ctrl.blob_len, &need);
        mem = malloc(need);
        err = mem == NULL ? -1 : nrt_load(&mine, r->ctrl.blob, r->ctrl.blob_len, mem, need);
        memset(&net, 0, sizeof net);
        memset(&builtin, 0, sizeof builtin);
        net.net = &mine;
        builtin.builtin = (int)(k % DUEL_N_BUILTINS);
        if (err == 0)
            err = duel_compare(&net, &builtin, &r->tally[k % DUEL_N_BUILTINS]);
        free(mem);
        if (err) {
            pthread_mutex_lock(&job->lock);
            job->err = err;
            pthread_mutex_unlock(&job->lock);
        }
    }
}

/* The dominants listed in DIR/dominance.csv, with their blobs from champions/. */
static int duel_ladder_read(const char *dir, duel_rung **out, uint32_t *n_out)
{
    char err[4400], blob[4200];
    duel_dominance_row *rows;
    duel_rung *rungs;
    uint32_t n, k;
    if (duel_dominance_read(dir, &rows, &n, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", err);
        return -1;
    }
    if (n == 0) {
        fprintf(stderr, "duel_evolve: %s/dominance.csv: no dominant strategy yet\n", dir);
        free(rows);
        return -1;
    }
    rungs = (duel_rung *)calloc(n, sizeof *rungs);
    if (rungs == NULL) {
        fprintf(stderr, "duel_evolve: ladder: out of memory\n");
        free(rows);
        return -1;
    }
    for (k = 0; k < n; k++) {
        duel_rung *r = &rungs[k];
        r->level = rows[k].level;
        r->generation = rows[k].generation;
        snprintf(r->pop, sizeof r->pop, "%s", rows[k].pop);
        r->hidden = rows[k].hidden;
        r->conns = rows[k].conns;
        snprintf(blob, sizeof blob, "%s/champions/gen-%05u.blob", dir, r->generation);
        if (duel_cli_ctrl_open(&r->ctrl, blob) != 0) {
            while (k > 0)
                duel_cli_ctrl_close(&rungs[--k].ctrl);
            free(rungs);
            free(rows);
            return -1;
        }
    }
    free(rows);
    *out = rungs;
    *n_out = n;
    return 0;
}

int duel_cmd_ladder(int argc, char **argv)
{
    duel_rung *rungs;
    duel_ladder_job job;
    pthread_t th[64];
    uint32_t n, k, b, nt = 0, started = 0;
    char path[4200], *text = NULL;
    size_t len = 0;
    FILE *mem;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);

    if (argc != 1 || argv[0][0] == '-') {
        fprintf(stderr, "usage: duel_evolve ladder DIR\n");
        return 2;
    }
    if (duel_ladder_read(argv[0], &rungs, &n) != 0)
        return 2;
    memset(&job, 0, sizeof job);
    job.rungs = rungs;
    job.n_rungs = n;
    pthread_mutex_init(&job.lock, NULL);
    nt = cores > 0 ? (uint32_t)cores : 1u;
    if (nt > 64)
        nt = 64;
    for (k = 0; k < nt; k++)
        if (pthread_create(&th[started], NULL, duel_ladder_worker, &job) == 0)
            started++;
    if (started == 0)
        duel_ladder_worker(&job);
    for (k = 0; k < started; k++)
        pthread_join(th[k], NULL);
    pthread_mutex_destroy(&job.lock);

    mem = open_memstream(&text, &len);
    if (mem == NULL || job.err) {
        fprintf(stderr, "duel_evolve: ladder: %s\n", job.err ? "a comparison failed" : "out of memory");
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
    for (k = 0; k < n; k++) {
        duel_rung *r = &rungs[k];
        uint32_t tw = 0, tl = 0;
        fprintf(mem, "%u,%u,%s,%u,%u", r->level, r->generation, r->pop, r->hidden, r->conns);
        printf("%-5u %-5u %-3s %-6u %-5u", r->level, r->generation, r->pop, r->hidden, r->conns);
        for (b = 0; b < DUEL_N_BUILTINS; b++) {
            fprintf(mem, ",%u,%u", r->tally[b].wins_a, r->tally[b].wins_b);
            printf(" %7u:%-7u", r->tally[b].wins_a, r->tally[b].wins_b);
            tw += r->tally[b].wins_a;
            tl += r->tally[b].wins_b;
        }
        fprintf(mem, ",%u,%u\n", tw, tl);
        printf(" %5u:%-5u\n", tw, tl);
        duel_cli_ctrl_close(&r->ctrl);
    }
    fclose(mem);
    printf("wins:losses of %u games against each built-in strategy (draws and timeouts are neither)\n",
           2u * DUEL_CONFIGS);
    snprintf(path, sizeof path, "%s/ladder.csv", argv[0]);
    k = duel_file_replace(path, text, len) != 0;
    if (k)
        fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", path, strerror(errno));
    free(text);
    free(rungs);
    return k ? 1 : 0;
}
