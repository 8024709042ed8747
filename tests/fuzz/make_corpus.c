/* make_corpus.c - writes the fuzz_blob seed corpus (valid blobs of several shapes and a few invalid ones), and with a second directory the fuzz_pop one (small population checkpoints). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "neat.h"
#include "nrt.h"

/* Enough for the largest seed (256 nodes, about 730 connections). */
#define MC_CAP 65536

static uint8_t mc_buf[MC_CAP];

/* xorshift32 (Marsaglia): fixed seeds, so the corpus is the same every time. */
static uint32_t mc_next(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *s = x;
    return x;
}

/* uniform-ish weight in [-range, range] */
static double mc_weight(uint32_t *s, double range)
{
    return ((double)(mc_next(s) % 20001u) / 10000.0 - 1.0) * range;
}

static int mc_write(const char *dir, const char *name, const uint8_t *p, size_t len)
{
    char path[1024];
    FILE *f;
    int ok;
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, name) >= sizeof path)
        return -1;
    f = fopen(path, "wb");
    if (f == NULL) {
        perror(path);
        return -1;
    }
    ok = fwrite(p, 1, len, f) == len;
    ok &= fclose(f) == 0;
    if (!ok) {
        perror(path);
        return -1;
    }
    printf("%s: %lu bytes\n", path, (unsigned long)len);
    return 0;
}

/* Nodes with the genome's ids: bias 0, inputs 1..n_in, outputs next, hidden after. */
static int mc_nodes(neat_genome *g, uint32_t n_in, uint32_t n_out, uint32_t n_hid)
{
    uint32_t i, n = n_in + 1 + n_out + n_hid;
    int err = 0;
    neat_genome_init(g);
    for (i = 0; i < n && !err; i++)
        err = neat_genome_add_node(g, i, i == 0 ? NEAT_NODE_BIAS : i <= n_in ? NEAT_NODE_INPUT
                                             : i <= n_in + n_out ? NEAT_NODE_OUTPUT : NEAT_NODE_HIDDEN, NULL);
    return err;
}

/* Encodes g and writes it, and as a propagate blob (NAME-propagate.blob, format version 2);
 * leaves the sync blob in mc_buf and its length in *len. */
static int mc_blob(const char *dir, const char *name, neat_genome *g, uint32_t n_in, uint32_t n_out, size_t *len)
{
    char pname[96];
    size_t plen = 0;
    int err = neat_blob_write_step(g, n_in, n_out, NEAT_STEP_PROPAGATE, mc_buf, sizeof mc_buf, &plen);
    if (!err) {
        snprintf(pname, sizeof pname, "%.*s-propagate.blob", (int)(strlen(name) - 5), name);
        err = mc_write(dir, pname, mc_buf, plen) ? NEAT_E_ARG : NEAT_OK;
    }
    if (!err)
        err = neat_blob_write(g, n_in, n_out, mc_buf, sizeof mc_buf, len);
    neat_genome_free(g, NULL);
    if (err) {
        fprintf(stderr, "%s: %s\n", name, neat_strerror(err));
        return -1;
    }
    return mc_write(dir, name, mc_buf, *len);
}

static void mc_fix_crc(uint8_t *b, size_t len)
{
    uint32_t crc = nrt_crc32(0, b, NRT_OFF_CRC);
    crc = nrt_crc32(crc, b + NRT_HEADER_SIZE, len - NRT_HEADER_SIZE);
    b[NRT_OFF_CRC] = (uint8_t)crc;
    b[NRT_OFF_CRC + 1] = (uint8_t)(crc >> 8);
    b[NRT_OFF_CRC + 2] = (uint8_t)(crc >> 16);
    b[NRT_OFF_CRC + 3] = (uint8_t)(crc >> 24);
}

/* Population checkpoints: 2 inputs, 1 output, 12 genomes, at generation 0
 * and after a few epochs (grown networks, several species), in each mode;
 * the simplify ones with net_step propagate and a game tag (version 3); and
 * a fourth with NEAT C++ 1.2.1's profile and a cull every 2 generations
 * (version 4: its switches and species' culled flags). */
static int mc_pops(const char *dir)
{
    static const int modes[] = {NEAT_MODE_COMPLEXIFY, NEAT_MODE_FIXED, NEAT_MODE_SIMPLIFY, NEAT_MODE_COMPLEXIFY};
    int err = 0, m;
    for (m = 0; m < 4 && !err; m++) {
        neat_params p = neat_params_default();
        neat_pop *pop;
        uint8_t *buf;
        size_t len;
        uint32_t e, i;
        char name[64];
        p.pop_size = 12;
        p.n_inputs = 2;
        p.n_outputs = 1;
        p.mode = modes[m];
        p.add_node_prob = 0.2;
        p.add_conn_prob = 0.3;
        p.net_step = m == 2 ? NEAT_STEP_PROPAGATE : NEAT_STEP_SYNC;
        if (m == 3) {
            (void)neat_params_set_profile(&p, NEAT_PROFILE_NEAT_CPP);
            p.cull_every = 2;
            p.cull_age = 1;
        }
        err = neat_pop_create(&pop, &p, NULL, 5u + (uint32_t)m, NULL);
        if (!err && m == 2)
            err = neat_pop_set_game(pop, (const uint8_t *)"duel world rules v1\0\1\2", 22);
        for (e = 0; e < 6 && !err; e++) {
            if (e == 0 || e == 5) {
                err = neat_pop_save(pop, &buf, &len);
                if (m == 3)
                    snprintf(name, sizeof name, "pop-neat-cpp-gen%u.bin", e);
                else
                    snprintf(name, sizeof name, "pop-mode%d-gen%u.bin", m, e);
                if (!err) {
                    err = mc_write(dir, name, buf, len);
                    neat_pop_buf_free(pop, buf, len);
                }
            }
            for (i = 0; i < neat_pop_size(pop) && !err; i++)
                err = neat_pop_set_fitness(pop, i, (double)(i % 5));
            if (!err)
                err = neat_pop_epoch(pop);
        }
        neat_pop_free(pop);
    }
    return err ? -1 : 0;
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    neat_genome g;
    uint32_t seed = 2024u, i, innov = 0;
    size_t len;
    uint8_t rec[NRT_CONN_SIZE];
    int err = 0;

    /* minimal: 3 sensors + bias fully connected to 1 output */
    err |= neat_genome_minimal(&g, 3, 1, NULL);
    for (i = 0; i < g.n_conns; i++)
        g.conns[i].weight = mc_weight(&seed, 4.0);
    err |= mc_blob(dir, "minimal.blob", &g, 3, 1, &len);

    /* empty: 2 sensors, 1 output, no connections at all */
    err |= mc_nodes(&g, 2, 1, 0);
    err |= mc_blob(dir, "empty.blob", &g, 2, 1, &len);

    /* xor: feed-forward, two hidden nodes, one connection disabled */
    err |= mc_nodes(&g, 2, 1, 2);
    err |= neat_genome_add_conn(&g, 1, 4, 2.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 2, 4, 2.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 0, 4, -1.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 1, 5, 2.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 2, 5, 2.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 0, 5, -3.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 4, 3, 4.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 5, 3, -4.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 0, 3, -2.0, innov++, 1, NULL);
    err |= neat_genome_add_conn(&g, 1, 3, 0.5, innov++, 0, NULL);
    err |= mc_blob(dir, "xor.blob", &g, 2, 1, &len);

    /* nodes256: the largest node count (12 sensors, 3 outputs, 240 hidden), 3 random
     * connections into every non-input node, self and backward ones included */
    err |= mc_nodes(&g, 12, 3, 240);
    innov = 0;
    for (i = 13; i < 256 && !err; i++) {
        int k;
        for (k = 0; k < 3 && !err; k++) {
            /* drawn in separate statements: argument evaluation order is unspecified */
            uint32_t src = k == 2 ? i : mc_next(&seed) % 256u;
            double w = mc_weight(&seed, 7.9);
            err |= neat_genome_add_conn(&g, src, i, w, innov++, 1, NULL);
        }
    }
    err |= mc_blob(dir, "nodes256.blob", &g, 12, 3, &len);

    /* recurrent: 3 sensors, 2 outputs, 2 fully recurrent hidden nodes; the
     * invalid seeds below are variants of it */
    err |= neat_genome_recurrent_hidden(&g, 3, 2, 2, NEAT_DIRECT_INPUTS, NULL);
    for (i = 0; i < g.n_conns; i++)
        g.conns[i].weight = mc_weight(&seed, 3.0);
    err |= mc_blob(dir, "recurrent.blob", &g, 3, 2, &len);
    if (err) {
        fprintf(stderr, "make_corpus: building the valid blobs failed\n");
        return 1;
    }

    /* bad_crc: one weight bit flipped, CRC left as it was */
    mc_buf[len - 1] ^= 0x10;
    err |= mc_write(dir, "bad_crc.blob", mc_buf, len);
    mc_buf[len - 1] ^= 0x10;

    /* bad_order: first and last connection swapped, CRC recomputed */
    memcpy(rec, mc_buf + NRT_HEADER_SIZE, NRT_CONN_SIZE);
    memcpy(mc_buf + NRT_HEADER_SIZE, mc_buf + len - NRT_CONN_SIZE, NRT_CONN_SIZE);
    memcpy(mc_buf + len - NRT_CONN_SIZE, rec, NRT_CONN_SIZE);
    mc_fix_crc(mc_buf, len);
    err |= mc_write(dir, "bad_order.blob", mc_buf, len);
    memcpy(mc_buf + len - NRT_CONN_SIZE, mc_buf + NRT_HEADER_SIZE, NRT_CONN_SIZE);
    memcpy(mc_buf + NRT_HEADER_SIZE, rec, NRT_CONN_SIZE);
    mc_fix_crc(mc_buf, len);

    /* truncated: the last connection cut in half */
    err |= mc_write(dir, "truncated.blob", mc_buf, len - 2);

    if (argc > 2 && mc_pops(argv[2]) != 0) {
        fprintf(stderr, "make_corpus: the population checkpoints failed\n");
        return 1;
    }
    return err ? 1 : 0;
}
