/* duel_bench.c - duel speed: game-steps per second with 39- and 202-connection networks, and 288-game comparisons per second. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "duel.h"
#include "neat.h"
#include "bench_nets.h"
#include "neat_phenotype.h"

static double db_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A duel network with exactly n_conns connections: the minimal 13 x 3 = 39,
 * plus n_hidden hidden nodes and random (recurrent) connections up to n_conns. */
static int db_genome(neat_genome *g, uint32_t n_hidden, uint32_t n_conns, neat_rng *rng)
{
    return bench_random_net(g, DUEL_N_INPUTS - 1, DUEL_N_OUTPUTS, n_hidden, n_conns, 1, rng);
}

typedef struct db_pair {
    neat_phenotype ph[2];
    duel_controller c[2];
} db_pair;

static int db_pair_make(db_pair *p, uint32_t n_hidden, uint32_t n_conns, neat_rng *rng)
{
    neat_params prm = neat_params_default();
    int s, err = 0;
    prm.n_inputs = DUEL_N_INPUTS - 1;
    prm.n_outputs = DUEL_N_OUTPUTS;
    for (s = 0; s < 2 && !err; s++) {
        neat_genome g;
        neat_phenotype_init(&p->ph[s], NULL);
        err = db_genome(&g, n_hidden, n_conns, rng);
        if (!err)
            err = neat_phenotype_load(&p->ph[s], &g, &prm);
        neat_genome_free(&g, NULL);
        p->c[s].net = &p->ph[s].net;
        p->c[s].builtin = 0;
    }
    return err;
}

/* FNV-1a over a game's result */
static uint64_t db_checksum(uint64_t h, const duel_result *r)
{
    int64_t v[6];
    int k;
    v[0] = r->outcome;
    v[1] = r->steps;
    v[2] = r->energy[0];
    v[3] = r->energy[1];
    v[4] = r->eaten[0];
    v[5] = r->eaten[1];
    for (k = 0; k < 6; k++)
        h = (h ^ (uint64_t)v[k]) * 0x100000001B3ull;
    return h;
}

/* games on every configuration and side until min_seconds have passed:
 * one at a time (duel_play), or two at once (duel_play2: game k and k + 1,
 * the same two networks on swapped sides, as a host meets its opponents) */
static double db_steps_per_second(db_pair *p, double min_seconds, int two, uint64_t *steps_out)
{
    uint64_t steps = 0;
    double t0 = db_now(), t;
    int k = 0;
    do {
        if (two) {
            duel_controller *west[2], *east[2];
            duel_result r[2];
            int config[2], j;
            for (j = 0; j < 2; j++) {
                west[j] = &p->c[(k + j) & 1];
                east[j] = &p->c[(k + j + 1) & 1];
                config[j] = ((k + j) / 2) % DUEL_CONFIGS;
            }
            duel_play2(west, east, config, r);
            steps += r[0].steps + r[1].steps;
            k += 2;
        } else {
            duel_result r;
            duel_play(&p->c[k & 1], &p->c[(k + 1) & 1], (k / 2) % DUEL_CONFIGS, &r, NULL, NULL);
            steps += r.steps;
            k++;
        }
        t = db_now() - t0;
    } while (t < min_seconds);
    *steps_out = steps;
    return (double)steps / t;
}

int main(int argc, char **argv)
{
    neat_rng rng;
    db_pair p39, p202;
    uint64_t steps39, steps202;
    double sps39, sps202, two39, two202, t0, cmp_s;
    duel_tally tally;
    int callgrind_games = 0, callgrind_conns = 39, i, rc = 0;
    const char *blob_dir = NULL;

    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--callgrind") == 0 && i + 1 < argc) {
            callgrind_games = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--scalar") == 0) {
            duel_simd_allow(DUEL_SIMD_NONE); /* the scalar sensing, for comparisons */
        } else if (strcmp(argv[i], "--avx2") == 0) {
            duel_simd_allow(DUEL_SIMD_AVX2); /* the AVX2 sensing without AVX-512VL */
        } else if (strcmp(argv[i], "--conns") == 0 && i + 1 < argc) {
            callgrind_conns = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--write-blobs") == 0 && i + 1 < argc) {
            blob_dir = argv[++i];
        } else {
            fprintf(stderr, "usage: duel_bench [--scalar | --avx2] [--callgrind GAMES [--conns 39|202]] [--write-blobs DIR]\n");
            return 2;
        }
    }
    neat_rng_seed(&rng, 2004);
    if (db_pair_make(&p39, 0, 39, &rng) || db_pair_make(&p202, 20, 202, &rng)) {
        fprintf(stderr, "duel_bench: cannot build the networks\n");
        return 1;
    }
    if (blob_dir != NULL) {
        /* the four benchmark networks as blob files (net39a/b, net202a/b.blob), for tests */
        static const char *const names[4] = {"net39a", "net39b", "net202a", "net202b"};
        for (i = 0; i < 4; i++) {
            const neat_phenotype *ph = i < 2 ? &p39.ph[i] : &p202.ph[i - 2];
            char path[1024];
            FILE *f;
            snprintf(path, sizeof path, "%s/%s.blob", blob_dir, names[i]);
            f = fopen(path, "wb");
            if (f == NULL || fwrite(ph->blob, 1, ph->blob_len, f) != ph->blob_len || fclose(f) != 0) {
                fprintf(stderr, "duel_bench: %s: cannot write\n", path);
                rc = 1;
                break;
            }
        }
        goto done;
    }
    if (callgrind_games > 0) {
        /* fixed work, nothing timed: under valgrind --tool=callgrind, the
         * instructions of duel_play divided by the robot-steps printed here
         * give instructions per robot-step (sensing + network + motion) */
        uint64_t robot_steps = 0, sum = 0xCBF29CE484222325ull;
        db_pair *p = callgrind_conns == 202 ? &p202 : &p39;
        if (callgrind_conns != 39 && callgrind_conns != 202) {
            fprintf(stderr, "duel_bench: --conns is 39 or 202\n");
            rc = 2;
            goto done;
        }
        for (i = 0; i < callgrind_games; i++) {
            duel_result r;
            duel_play(&p->c[i & 1], &p->c[(i + 1) & 1], (i / 2) % DUEL_CONFIGS, &r, NULL, NULL);
            robot_steps += 2u * r.steps;
            sum = db_checksum(sum, &r);
        }
        /* the checksum of every game's result: the same for every build of the same spec */
        printf("{\"games\":%d,\"conns\":%d,\"simd\":%d,\"robot_steps\":%llu,\"checksum\":\"%016llx\"}\n",
               callgrind_games, callgrind_conns, duel_simd_active(), (unsigned long long)robot_steps,
               (unsigned long long)sum);
        goto done;
    }
    sps39 = db_steps_per_second(&p39, 1.0, 0, &steps39);
    sps202 = db_steps_per_second(&p202, 1.0, 0, &steps202);
    two39 = db_steps_per_second(&p39, 1.0, 1, &steps39);
    two202 = db_steps_per_second(&p202, 1.0, 1, &steps202);
    t0 = db_now();
    duel_compare(&p39.c[0], &p39.c[1], &tally);
    cmp_s = db_now() - t0;
    printf("39-connection networks:  %.0f game-steps/s (%.1f ns per robot-step)\n", sps39, 0.5e9 / sps39);
    printf("202-connection networks: %.0f game-steps/s (%.1f ns per robot-step)\n", sps202, 0.5e9 / sps202);
    printf("two games at once (duel_play2), 39 / 202 connections: %.0f / %.0f game-steps/s (%.2f / %.2f times one at a time)\n",
           two39, two202, two39 / sps39, two202 / sps202);
    printf("288-game comparison (39 connections): %.3f s, %.0f games/s (wins %u / %u, draws %u, timeouts %u)\n", cmp_s,
           288.0 / cmp_s, tally.wins_a, tally.wins_b, tally.draws, tally.timeouts);
    printf("sensing: %s\n", duel_simd_active() == DUEL_SIMD_AVX512 ? "AVX2 + AVX-512VL (duel_sense_avx2.c)"
                             : duel_simd_active() == DUEL_SIMD_AVX2 ? "AVX2 (duel_sense_avx2.c)" : "scalar");
    printf("{\"game_steps_per_s_39\":%.0f,\"game_steps_per_s_202\":%.0f,\"two_at_once_39\":%.0f,"
           "\"two_at_once_202\":%.0f,\"games_per_s_288\":%.1f,\"comparison_seconds\":%.4f}\n",
           sps39, sps202, two39, two202, 288.0 / cmp_s, cmp_s);
done:
    for (i = 0; i < 2; i++) {
        neat_phenotype_free(&p39.ph[i]);
        neat_phenotype_free(&p202.ph[i]);
    }
    return rc;
}
