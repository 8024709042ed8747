/* bench_activation.c - ns per connection per step of the fixed-point runtime vs a plain double-precision network. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "bench.h"
#include "bench_nets.h"
#include "neat_phenotype.h"

#define ACT_INPUTS 12 /* the duel's sensors (plus the bias) */
#define ACT_OUTPUTS 3
#define ACT_TRIALS 5  /* timed trials per network and implementation */

static double act_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A recurrent genome with exactly n_conns connections between random node
 * pairs (self and backward connections included). */
static int act_genome(neat_genome *g, uint32_t n_hidden, uint32_t n_conns, neat_rng *rng)
{
    return bench_random_net(g, ACT_INPUTS, ACT_OUTPUTS, n_hidden, n_conns, 0, rng);
}

/* The straightforward double-precision network the ratio is measured against. */
typedef struct act_ref {
    uint32_t n_nodes, n_conns;
    uint32_t *src, *dst;
    double *w, *act, *sum;
    int propagate; /* connections grouped by target in the runtime's evaluation order, evaluated in place */
} act_ref;

static void act_ref_build(act_ref *r, const neat_genome *g, const nrt_net *net)
{
    uint32_t k;
    r->propagate = net->order != NULL;
    r->n_nodes = g->n_nodes;
    r->n_conns = g->n_conns;
    r->src = (uint32_t *)malloc(g->n_conns * sizeof(uint32_t));
    r->dst = (uint32_t *)malloc(g->n_conns * sizeof(uint32_t));
    r->w = (double *)malloc(g->n_conns * sizeof(double));
    r->act = (double *)calloc(g->n_nodes, sizeof(double));
    r->sum = (double *)calloc(g->n_nodes, sizeof(double));
    for (k = 0; k < g->n_conns; k++) {
        r->src[k] = g->conns[k].in; /* ids are indices here */
        r->dst[k] = g->conns[k].out;
        r->w[k] = g->conns[k].weight;
    }
    if (r->propagate) { /* the same connections, each node's together, nodes in evaluation order */
        uint32_t p, n = 0;
        for (p = 0; p < (uint32_t)net->n_nodes - net->n_inputs; p++)
            for (k = 0; k < g->n_conns; k++)
                if (g->conns[k].out == net->order[p]) {
                    r->src[n] = g->conns[k].in;
                    r->dst[n] = g->conns[k].out;
                    r->w[n++] = g->conns[k].weight;
                }
        /* order[] for the nodes without connections: a zero sum */
        r->sum = (double *)realloc(r->sum, (size_t)(net->n_nodes - net->n_inputs) * sizeof(double));
        for (p = 0; p < (uint32_t)net->n_nodes - net->n_inputs; p++)
            r->sum[p] = net->order[p];
    }
}

static void act_ref_step(act_ref *r, const double *in)
{
    uint32_t k, j;
    for (j = 0; j <= ACT_INPUTS; j++)
        r->act[j] = in[j];
    if (r->propagate) { /* in place: sum[p] holds the p-th node's index */
        uint32_t p;
        for (p = 0, k = 0; p < r->n_nodes - ACT_INPUTS - 1; p++) {
            double s = 0.0;
            j = (uint32_t)r->sum[p];
            for (; k < r->n_conns && r->dst[k] == j; k++)
                s += r->w[k] * r->act[r->src[k]];
            r->act[j] = 1.0 / (1.0 + exp(-4.9 * s));
        }
        return;
    }
    for (j = ACT_INPUTS + 1; j < r->n_nodes; j++)
        r->sum[j] = 0.0;
    for (k = 0; k < r->n_conns; k++)
        r->sum[r->dst[k]] += r->w[k] * r->act[r->src[k]];
    for (j = ACT_INPUTS + 1; j < r->n_nodes; j++)
        r->act[j] = 1.0 / (1.0 + exp(-4.9 * r->sum[j]));
}

static void act_ref_free(act_ref *r)
{
    free(r->src);
    free(r->dst);
    free(r->w);
    free(r->act);
    free(r->sum);
}

static int act_one(uint32_t n_hidden, uint32_t n_conns, int net_step, neat_rng *rng, double min_seconds,
                   double *ns_fixed, double *ns_double, double *max_diff)
{
    neat_genome g;
    neat_params p = neat_params_default();
    neat_phenotype ph;
    act_ref ref;
    nrt_q15 in[ACT_INPUTS + 1], out[ACT_OUTPUTS];
    double din[ACT_INPUTS + 1], t0, t, sink = 0.0;
    uint64_t steps, s;
    uint32_t j;
    int err, trial;

    p.n_inputs = ACT_INPUTS;
    p.n_outputs = ACT_OUTPUTS;
    p.net_step = net_step;
    err = act_genome(&g, n_hidden, n_conns, rng);
    neat_phenotype_init(&ph, NULL);
    if (!err)
        err = neat_phenotype_load(&ph, &g, &p);
    if (err) {
        neat_genome_free(&g, NULL);
        return err;
    }
    act_ref_build(&ref, &g, &ph.net);
    for (j = 0; j <= ACT_INPUTS; j++) {
        din[j] = j == 0 ? 1.0 : neat_from_q15(neat_q15(neat_rng_uniform(rng)));
        in[j] = j == 0 ? NRT_ONE : neat_q15(din[j]);
    }
    din[0] = neat_from_q15(NRT_ONE);
    /* accuracy: the same 1000 steps in both */
    *max_diff = 0.0;
    nrt_reset(&ph.net);
    for (s = 0; s < 1000; s++) {
        nrt_step(&ph.net, in, out);
        act_ref_step(&ref, din);
        for (j = 0; j < ACT_OUTPUTS; j++) {
            double d = fabs(neat_from_q15(out[j]) - ref.act[ACT_INPUTS + 1 + j]);
            if (d > *max_diff)
                *max_diff = d;
        }
    }
    /* speed: ACT_TRIALS alternating trials of each, every trial 10000 steps
     * at a time until min_seconds / ACT_TRIALS have passed; the fastest
     * trial of each is reported (the machine is shared: slower trials
     * measure the neighbours) */
    *ns_fixed = *ns_double = 1e30;
    for (trial = 0; trial < ACT_TRIALS; trial++) {
        steps = 0;
        t0 = act_now();
        do {
            for (s = 0; s < 10000; s++) {
                in[1] = (nrt_q15)(in[1] ^ (nrt_q15)(s & 1));
                nrt_step(&ph.net, in, out);
            }
            steps += 10000;
            t = act_now() - t0;
        } while (t < min_seconds / ACT_TRIALS);
        sink += out[0];
        if (t * 1e9 / ((double)steps * n_conns) < *ns_fixed)
            *ns_fixed = t * 1e9 / ((double)steps * n_conns);
        steps = 0;
        t0 = act_now();
        do {
            for (s = 0; s < 10000; s++) {
                din[1] += (s & 1) ? 1e-9 : -1e-9;
                act_ref_step(&ref, din);
            }
            steps += 10000;
            t = act_now() - t0;
        } while (t < min_seconds / ACT_TRIALS);
        sink += ref.act[ACT_INPUTS + 1];
        if (t * 1e9 / ((double)steps * n_conns) < *ns_double)
            *ns_double = t * 1e9 / ((double)steps * n_conns);
    }
    if (sink == 12345.6789)
        printf("#\n"); /* keeps the loops' results alive */
    act_ref_free(&ref);
    neat_phenotype_free(&ph);
    neat_genome_free(&g, NULL);
    return 0;
}

int bench_activation_count(uint64_t seed, uint32_t conns, uint64_t steps, int net_step)
{
    /* exactly `steps` runtime steps of one network, nothing timed: under
     * valgrind --tool=callgrind, nrt_step's instructions / steps / conns is
     * a figure that does not depend on the machine's load */
    neat_rng rng;
    neat_genome g;
    neat_params p = neat_params_default();
    neat_phenotype ph;
    nrt_q15 in[ACT_INPUTS + 1], out[ACT_OUTPUTS];
    uint64_t s;
    uint32_t j;
    int err, sink = 0;
    neat_rng_seed(&rng, seed);
    p.n_inputs = ACT_INPUTS;
    p.n_outputs = ACT_OUTPUTS;
    p.net_step = net_step;
    if (conns == 40) {
        err = act_genome(&g, 2, 40, &rng);
    } else {
        neat_genome scratch;
        err = act_genome(&scratch, 2, 40, &rng); /* the same draws as bench_activation */
        neat_genome_free(&scratch, NULL);
        if (!err)
            err = act_genome(&g, 20, 200, &rng);
    }
    neat_phenotype_init(&ph, NULL);
    if (!err)
        err = neat_phenotype_load(&ph, &g, &p);
    if (err) {
        fprintf(stderr, "neat_bench: activation: cannot build the test network (%s)\n", neat_strerror(err));
        neat_genome_free(&g, NULL);
        return 1;
    }
    for (j = 0; j <= ACT_INPUTS; j++)
        in[j] = j == 0 ? NRT_ONE : neat_q15(neat_rng_uniform(&rng));
    nrt_reset(&ph.net);
    for (s = 0; s < steps; s++) {
        in[1] = (nrt_q15)(in[1] ^ (nrt_q15)(s & 1));
        nrt_step(&ph.net, in, out);
        sink += out[0];
    }
    printf("%u connections: %llu steps done (output sum %d)\n", conns, (unsigned long long)steps, sink);
    neat_phenotype_free(&ph);
    neat_genome_free(&g, NULL);
    return 0;
}

/* net_step: NEAT_STEP_SYNC, NEAT_STEP_PROPAGATE, or BENCH_STEP_BOTH (sync's
 * lines, unchanged, then propagate's). The same two networks either way:
 * each mode's draws start from the seed. */
int bench_activation(uint64_t seed, double min_seconds, int net_step)
{
    neat_rng rng;
    double f[2][2], d[2][2], e[2][2];
    int err = 0, m;
    static const char *const name[2] = {"", " (propagate)"};
    for (m = 0; m < 2 && !err; m++) {
        if (net_step != BENCH_STEP_BOTH && net_step != m)
            continue;
        neat_rng_seed(&rng, seed);
        err = act_one(2, 40, m, &rng, min_seconds, &f[m][0], &d[m][0], &e[m][0]);
        if (!err)
            err = act_one(20, 200, m, &rng, min_seconds, &f[m][1], &d[m][1], &e[m][1]);
    }
    if (err) {
        fprintf(stderr, "neat_bench: activation: cannot build the test networks (%s)\n", neat_strerror(err));
        return 1;
    }
    for (m = 0; m < 2; m++) {
        if (net_step != BENCH_STEP_BOTH && net_step != m)
            continue;
        printf("40 connections%s:  fixed point %.3f ns/conn/step, double %.3f ns/conn/step (ratio %.2f), max output diff %.2e\n",
               name[m], f[m][0], d[m][0], d[m][0] / f[m][0], e[m][0]);
        printf("200 connections%s: fixed point %.3f ns/conn/step, double %.3f ns/conn/step (ratio %.2f), max output diff %.2e\n",
               name[m], f[m][1], d[m][1], d[m][1] / f[m][1], e[m][1]);
    }
    m = net_step == NEAT_STEP_PROPAGATE ? 1 : 0;
    printf("{\"task\":\"activation\",\"ns_per_conn_step_40\":%.4f,\"ns_per_conn_step_200\":%.4f,"
           "\"double_ns_per_conn_step_40\":%.4f,\"double_ns_per_conn_step_200\":%.4f,"
           "\"max_output_diff_40\":%.3e,\"max_output_diff_200\":%.3e,\"seconds_per_measure\":%.2f,"
           "\"trials\":%d",
           f[m][0], f[m][1], d[m][0], d[m][1], e[m][0], e[m][1], min_seconds, ACT_TRIALS);
    if (net_step == NEAT_STEP_PROPAGATE)
        printf(",\"net_step\":\"propagate\"");
    if (net_step == BENCH_STEP_BOTH)
        printf(",\"propagate_ns_per_conn_step_40\":%.4f,\"propagate_ns_per_conn_step_200\":%.4f,"
               "\"propagate_double_ns_per_conn_step_40\":%.4f,\"propagate_double_ns_per_conn_step_200\":%.4f,"
               "\"propagate_max_output_diff_40\":%.3e,\"propagate_max_output_diff_200\":%.3e",
               f[1][0], f[1][1], d[1][0], d[1][1], e[1][0], e[1][1]);
    printf("}\n");
    return 0;
}
