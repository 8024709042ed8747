/* test_checkpoint.c - checkpoints: exact resumption, stable bytes, truncation, corruption and header errors. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat_internal.h"
#include "nrt.h"

/* the profile the populations of a test use (the _cpp variants below set
 * NEAT_PROFILE_NEAT_CPP, whose checkpoints are version 4) */
static int ckpt_profile = NEAT_PROFILE_DEFAULT;

static neat_params ckpt_params(uint32_t pop_size)
{
    neat_params p = neat_params_default();
    assert_int_equal(neat_params_set_profile(&p, ckpt_profile), NEAT_OK);
    if (ckpt_profile == NEAT_PROFILE_NEAT_CPP) {
        p.cull_every = 3; /* a cull within the tests' few generations */
        p.cull_age = 1;
    }
    p.pop_size = pop_size;
    p.n_inputs = 2;
    p.n_outputs = 1;
    p.add_node_prob = 0.05;
    p.add_conn_prob = 0.2;
    return p;
}

static double toy_fitness(const neat_genome *g)
{
    double s = 0.0;
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].enabled)
            s += g->conns[i].weight * (double)(1 + i % 3);
    return 1.0 / (1.0 + fabs(s - 1.5)) + 0.01 * neat_genome_hidden_count(g);
}

static void evaluate(neat_pop *pop, uint32_t from, uint32_t to)
{
    uint32_t i;
    for (i = from; i < to; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, toy_fitness(neat_pop_genome(pop, i))), NEAT_OK);
}

static void run_generations(neat_pop *pop, uint32_t n)
{
    uint32_t g;
    for (g = 0; g < n; g++) {
        evaluate(pop, 0, neat_pop_size(pop));
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    }
}

static neat_pop *evolved_pop(uint32_t pop_size, uint32_t generations, uint64_t seed)
{
    neat_params p = ckpt_params(pop_size);
    neat_pop *pop = NULL;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, seed, NULL), NEAT_OK);
    run_generations(pop, generations);
    return pop;
}

static void save(const neat_pop *pop, uint8_t **buf, size_t *len)
{
    assert_int_equal(neat_pop_save(pop, buf, len), NEAT_OK);
    assert_true(*len > 16);
}

static neat_pop *load_ok(const uint8_t *buf, size_t len)
{
    neat_pop *pop = NULL;
    size_t off = 12345;
    assert_int_equal(neat_pop_load(&pop, buf, len, NULL, &off), NEAT_OK);
    assert_non_null(pop);
    return pop;
}

static void reseal(uint8_t *buf, size_t len)
{
    uint32_t crc = nrt_crc32(0, buf, len - 4);
    buf[len - 4] = (uint8_t)crc;
    buf[len - 3] = (uint8_t)(crc >> 8);
    buf[len - 2] = (uint8_t)(crc >> 16);
    buf[len - 1] = (uint8_t)(crc >> 24);
}

static void assert_same_bytes(const neat_pop *a, const neat_pop *b)
{
    uint8_t *ba, *bb;
    size_t la, lb;
    save(a, &ba, &la);
    save(b, &bb, &lb);
    assert_int_equal(la, lb);
    assert_memory_equal(ba, bb, la);
    neat_pop_buf_free(a, ba, la);
    neat_pop_buf_free(b, bb, lb);
}

static void assert_same_best_blob(const neat_pop *a, const neat_pop *b)
{
    uint8_t ba[4096], bb[4096];
    size_t la, lb;
    assert_non_null(neat_pop_best_ever(a));
    assert_non_null(neat_pop_best_ever(b));
    assert_int_equal(neat_blob_write(neat_pop_best_ever(a), 2, 1, ba, sizeof ba, &la), NEAT_OK);
    assert_int_equal(neat_blob_write(neat_pop_best_ever(b), 2, 1, bb, sizeof bb, &lb), NEAT_OK);
    assert_int_equal(la, lb);
    assert_memory_equal(ba, bb, la);
}

/* ---- round trips ---- */

static void test_resume_gives_same_run(void **state)
{
    neat_pop *orig = evolved_pop(40, 5, 21), *copy;
    uint8_t *buf;
    size_t len;
    (void)state;
    save(orig, &buf, &len);
    copy = load_ok(buf, len);
    neat_pop_buf_free(orig, buf, len);
    assert_int_equal(neat_pop_generation(copy), 5);
    run_generations(orig, 10);
    run_generations(copy, 10);
    assert_int_equal(neat_pop_generation(copy), 15);
    assert_same_bytes(orig, copy);
    assert_same_best_blob(orig, copy);
    /* the run did change over those generations */
    assert_true(neat_pop_best_ever(orig)->fitness > 0.0);
    neat_pop_free(orig);
    neat_pop_free(copy);
}

static void test_resume_mid_generation(void **state)
{
    /* saved with half the fitness values given: the rest given after the
     * load, then the same epoch */
    neat_pop *orig = evolved_pop(40, 3, 22), *copy;
    uint8_t *buf;
    size_t len;
    (void)state;
    evaluate(orig, 0, 20);
    save(orig, &buf, &len);
    copy = load_ok(buf, len);
    neat_pop_buf_free(orig, buf, len);
    /* the missing ones are still missing after the load */
    assert_int_equal(neat_pop_epoch(copy), NEAT_E_FITNESS);
    assert_int_equal(neat_pop_error_index(copy), 20);
    evaluate(orig, 20, 40);
    evaluate(copy, 20, 40);
    assert_int_equal(neat_pop_epoch(orig), NEAT_OK);
    assert_int_equal(neat_pop_epoch(copy), NEAT_OK);
    run_generations(orig, 3);
    run_generations(copy, 3);
    assert_same_bytes(orig, copy);
    neat_pop_free(orig);
    neat_pop_free(copy);
}

static void test_save_load_save_is_identity(void **state)
{
    static const uint32_t gens[] = {0, 1, 6};
    size_t k;
    (void)state;
    for (k = 0; k < 3; k++) {
        neat_pop *pop = evolved_pop(30, gens[k], 23 + k), *copy;
        uint8_t *b1, *b2;
        size_t l1, l2;
        save(pop, &b1, &l1);
        copy = load_ok(b1, l1);
        save(copy, &b2, &l2);
        assert_int_equal(l1, l2);
        assert_memory_equal(b1, b2, l1);
        /* loaded state answers as the original */
        assert_int_equal(neat_pop_generation(copy), gens[k]);
        assert_int_equal(neat_pop_species_count(copy), neat_pop_species_count(pop));
        assert_int_equal(neat_pop_innovations(copy), neat_pop_innovations(pop));
        assert_true(neat_pop_delta_t(copy) == neat_pop_delta_t(pop));
        assert_true((neat_pop_best_ever(copy) == NULL) == (gens[k] == 0));
        neat_pop_buf_free(pop, b1, l1);
        neat_pop_buf_free(copy, b2, l2);
        neat_pop_free(pop);
        neat_pop_free(copy);
    }
}

static void test_save_is_deterministic(void **state)
{
    neat_pop *a = evolved_pop(30, 4, 30), *b = evolved_pop(30, 4, 30);
    (void)state;
    assert_same_bytes(a, a);
    assert_same_bytes(a, b);
    neat_pop_free(a);
    neat_pop_free(b);
}

static void test_header_layout(void **state)
{
    neat_pop *pop = evolved_pop(10, 1, 31);
    uint8_t *buf;
    size_t len;
    uint32_t crc;
    (void)state;
    save(pop, &buf, &len);
    assert_memory_equal(buf, "NEATCKPT", 8);
    /* known by its magic, and only by a whole one */
    assert_int_equal(neat_checkpoint_kind(buf, len), NEAT_CKPT_POP);
    assert_int_equal(neat_checkpoint_kind(buf, 7), NEAT_CKPT_NONE);
    assert_int_equal(neat_checkpoint_kind(NULL, 8), NEAT_CKPT_NONE);
    assert_int_equal(neat_checkpoint_kind(buf + 1, len - 1), NEAT_CKPT_NONE);
    /* the default rules' checkpoints keep version 3's bytes; NEAT C++'s switches need version 4 */
    assert_int_equal(buf[8] | buf[9] << 8 | buf[10] << 16 | (uint32_t)buf[11] << 24,
                     ckpt_profile == NEAT_PROFILE_DEFAULT ? 3 : NEAT_CHECKPOINT_VERSION);
    crc = (uint32_t)buf[len - 4] | (uint32_t)buf[len - 3] << 8 | (uint32_t)buf[len - 2] << 16 |
          (uint32_t)buf[len - 1] << 24;
    assert_int_equal(crc, nrt_crc32(0, buf, len - 4));
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

/* ---- damaged checkpoints ---- */

static void test_every_truncation_rejected(void **state)
{
    neat_pop *pop = evolved_pop(40, 5, 32), *out;
    uint8_t *buf, *copy;
    size_t len, n, off;
    uint32_t tried = 0;
    int err;
    (void)state;
    save(pop, &buf, &len);
    assert_true(len > 2000);
    for (n = 0; n < len; n += n < 2000 ? 1 : 7) {
        /* a copy of exactly n bytes, so reading past it is caught by ASan */
        copy = (uint8_t *)malloc(n ? n : 1);
        assert_non_null(copy);
        memcpy(copy, buf, n);
        out = (neat_pop *)copy; /* must be cleared */
        off = (size_t)-1;
        err = neat_pop_load(&out, copy, n, NULL, &off);
        if (err == NEAT_OK)
            fail_msg("truncated to %zu of %zu bytes: accepted", n, len);
        assert_null(out);
        assert_true(err == NEAT_E_TRUNCATED || err == NEAT_E_CRC || err == NEAT_E_FORMAT);
        assert_true(off <= n);
        if (n < 16)
            assert_int_equal(err, NEAT_E_TRUNCATED);
        free(copy);
        tried++;
    }
    assert_true(tried > 2000);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

static void test_single_byte_corruption_rejected(void **state)
{
    static const uint8_t flips[] = {0x01, 0x80, 0xFF};
    neat_pop *pop = evolved_pop(30, 5, 33), *out;
    uint8_t *buf;
    size_t len, i, f, off;
    int err;
    (void)state;
    save(pop, &buf, &len);
    for (i = 0; i < len; i++)
        for (f = 0; f < 3; f++) {
            if (f > 0 && i % 5 != 0)
                continue;
            buf[i] ^= flips[f];
            off = (size_t)-1;
            out = NULL;
            err = neat_pop_load(&out, buf, len, NULL, &off);
            buf[i] ^= flips[f];
            assert_null(out);
            if (i < 8) { /* magic */
                assert_int_equal(err, NEAT_E_FORMAT);
                assert_int_equal(off, 0);
            } else if (i < 12 && !(i == 8 && (buf[8] ^ flips[f]) == 2)) { /* version */
                assert_int_equal(err, NEAT_E_FORMAT);
                assert_int_equal(off, 8);
            } else if (i == 8) { /* 3 -> 2, a version that loads: the checksum catches it */
                assert_int_equal(err, NEAT_E_CRC);
            } else { /* body or checksum: the checksum is where it shows */
                if (err != NEAT_E_CRC)
                    fail_msg("byte %zu ^ 0x%02x: error %d", i, flips[f], err);
                assert_int_equal(off, len - 4);
            }
        }
    /* and the untouched buffer still loads */
    out = load_ok(buf, len);
    neat_pop_free(out);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

static void test_bad_magic(void **state)
{
    neat_pop *pop = evolved_pop(10, 1, 34), *out = NULL;
    uint8_t *buf;
    size_t len, off = 999;
    (void)state;
    save(pop, &buf, &len);
    buf[3] = 'X';
    reseal(buf, len); /* the magic, not the checksum, is what fails */
    assert_int_equal(neat_pop_load(&out, buf, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 0);
    assert_null(out);
    /* not a checkpoint at all */
    off = 999;
    assert_int_equal(neat_pop_load(&out, (const uint8_t *)"NRTB0000000000000000", 20, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 0);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

static void test_bad_version(void **state)
{
    /* 2, 3 and 4 load (tests of version 2: test_version2_loads; of 4: the _cpp tests) */
    static const uint8_t versions[][4] = {{0, 0, 0, 0}, {1, 0, 0, 0}, {5, 0, 0, 0}, {3, 0, 0, 1}};
    neat_pop *pop = evolved_pop(10, 1, 35), *out = NULL;
    uint8_t *buf;
    size_t len, off, k;
    (void)state;
    save(pop, &buf, &len);
    for (k = 0; k < 4; k++) {
        memcpy(buf + 8, versions[k], 4);
        reseal(buf, len);
        off = 999;
        assert_int_equal(neat_pop_load(&out, buf, len, NULL, &off), NEAT_E_FORMAT);
        assert_int_equal(off, 8);
        assert_null(out);
    }
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

static void test_trailing_bytes_rejected(void **state)
{
    neat_pop *pop = evolved_pop(10, 1, 36), *out = NULL;
    uint8_t *buf, *big;
    size_t len, off = 999;
    (void)state;
    save(pop, &buf, &len);
    big = (uint8_t *)malloc(len + 4);
    assert_non_null(big);
    memcpy(big, buf, len - 4);
    memset(big + len - 4, 0, 4);
    reseal(big, len + 4);
    assert_int_equal(neat_pop_load(&out, big, len + 4, NULL, &off), NEAT_E_FORMAT);
    assert_null(out);
    assert_true(off <= len);
    free(big);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

static void test_resealed_corruption_never_crashes(void **state)
{
    /* each byte of the body changed and the checksum recomputed: the load
     * either refuses with an offset inside the buffer, or gives a
     * population that can still be stepped (errors allowed, no crash, no
     * leak: run under ASan) */
    static const uint8_t vals[] = {0x00, 0xFF};
    neat_pop *pop = evolved_pop(8, 2, 37), *out;
    uint8_t *buf;
    size_t len, i, v, off;
    uint32_t accepted = 0, refused = 0;
    int err;
    (void)state;
    save(pop, &buf, &len);
    for (i = 12; i < len - 4; i++)
        for (v = 0; v < 4; v++) {
            uint8_t old = buf[i];
            buf[i] = v < 2 ? vals[v] : (uint8_t)(old ^ (v == 2 ? 0x01 : 0x40));
            if (buf[i] == old) {
                continue;
            }
            reseal(buf, len);
            out = NULL;
            off = (size_t)-1;
            err = neat_pop_load(&out, buf, len, NULL, &off);
            if (err == NEAT_OK) {
                uint32_t k;
                accepted++;
                assert_non_null(out);
                /* (a huge add_conn_tries is legal but slow: not stepped) */
                if (neat_pop_params(out)->add_conn_tries <= 1000) {
                    for (k = 0; k < neat_pop_size(out); k++)
                        (void)neat_pop_set_fitness(out, k, 1.0 + k);
                    (void)neat_pop_epoch(out);
                }
                neat_pop_free(out);
            } else {
                refused++;
                assert_null(out);
                assert_true(err == NEAT_E_FORMAT || err == NEAT_E_TRUNCATED);
                assert_true(off < len);
            }
            buf[i] = old;
        }
    reseal(buf, len);
    assert_true(refused > 0);
    assert_true(accepted > 0); /* weights, fitness values... are free */
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

/* ---- values the checksum cannot vouch for ----
 * A checkpoint whose CRC is right can still hold state no run can reach.
 * The counters and delta_t sit right after the PRNG state (docs/formats.md):
 * found here through the PRNG bytes, so a layout change fails loudly. */
static size_t state_offset(const neat_pop *pop, const uint8_t *buf, size_t len)
{
    uint8_t want[32];
    size_t i, at = 0, hits = 0;
    for (i = 0; i < 32; i++)
        want[i] = (uint8_t)(pop->rng.s[i / 8] >> (8 * (i % 8)));
    for (i = 12; i + 32 <= len; i++)
        if (memcmp(buf + i, want, 32) == 0) {
            at = i;
            hits++;
        }
    assert_int_equal(hits, 1);
    return at;
}

static void put_u32_at(uint8_t *buf, size_t at, uint32_t v)
{
    buf[at] = (uint8_t)v;
    buf[at + 1] = (uint8_t)(v >> 8);
    buf[at + 2] = (uint8_t)(v >> 16);
    buf[at + 3] = (uint8_t)(v >> 24);
}

/* loads buf with bytes [at, at + n) replaced by val and the CRC recomputed;
 * returns the load's result (the population, if any, is freed) */
static int load_patched(const uint8_t *buf, size_t len, size_t at, const void *val, size_t n)
{
    uint8_t *copy = (uint8_t *)malloc(len);
    neat_pop *out = NULL;
    int err;
    assert_non_null(copy);
    memcpy(copy, buf, len);
    memcpy(copy + at, val, n);
    reseal(copy, len);
    err = neat_pop_load(&out, copy, len, NULL, NULL);
    neat_pop_free(out);
    free(copy);
    return err;
}

static void test_load_rejects_stale_counters(void **state)
{
    /* next innovation / node id / species id at or below ones in use: the
     * loaded population hands out numbers that already mean something else
     * (next_innov 0 or next_node 0 makes the very next neat_pop_epoch fail
     * with NEAT_E_ARG; a stale species id duplicates a species).
     * neat_pop_load checks them against every genome and species loaded. */
    neat_pop *pop = evolved_pop(30, 5, 38);
    uint8_t *buf, v[4];
    size_t len, at;
    int e_innov, e_node, e_species;
    (void)state;
    save(pop, &buf, &len);
    at = state_offset(pop, buf, len) + 32;
    /* sanity: the offsets found hold the counters */
    put_u32_at(v, 0, neat_pop_innovations(pop));
    assert_memory_equal(buf + at + 4, v, 4);
    put_u32_at(v, 0, 0);
    e_innov = load_patched(buf, len, at + 4, v, 4);
    e_node = load_patched(buf, len, at + 8, v, 4);
    e_species = load_patched(buf, len, at + 12, v, 4);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
    assert_int_equal(e_innov, NEAT_E_FORMAT);
    assert_int_equal(e_node, NEAT_E_FORMAT);
    assert_int_equal(e_species, NEAT_E_FORMAT);
}

static void test_load_rejects_bad_delta_t(void **state)
{
    /* a NaN threshold puts every genome in a species of its own for ever
     * (NaN compares false, so neither speciation nor the delta_t_min floor
     * ever act); a negative or infinite one is no threshold either.
     * neat_pop_load range-checks the population's current delta_t (not
     * only the parameter, which neat_params_check covers). */
    static const double bad[] = {NAN, -1.0, 0.0, INFINITY};
    neat_pop *pop = evolved_pop(30, 5, 39);
    uint8_t *buf, v[8];
    size_t len, at, k, b;
    int errs[4];
    (void)state;
    save(pop, &buf, &len);
    at = state_offset(pop, buf, len) + 32 + 20;
    for (k = 0; k < 4; k++) {
        uint64_t bits;
        memcpy(&bits, &bad[k], 8);
        for (b = 0; b < 8; b++)
            v[b] = (uint8_t)(bits >> (8 * b));
        errs[k] = load_patched(buf, len, at, v, 8);
    }
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
    for (k = 0; k < 4; k++)
        if (errs[k] != NEAT_E_FORMAT)
            fail_msg("delta_t %g: load returned %d", bad[k], errs[k]);
}

static void test_load_rejects_zero_rng_state(void **state)
{
    /* xoshiro256** never leaves the all-zero state: every draw is 0, and
     * the run is silently frozen (no structural mutation ever again).
     * neat_pop_load refuses that state. */
    static const uint8_t zeros[32] = {0};
    neat_pop *pop = evolved_pop(30, 5, 40);
    uint8_t *buf;
    size_t len, at;
    int err;
    (void)state;
    save(pop, &buf, &len);
    at = state_offset(pop, buf, len);
    err = load_patched(buf, len, at, zeros, 32);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
    assert_int_equal(err, NEAT_E_FORMAT);
}

static void test_load_rejects_null_arguments(void **state)
{
    neat_pop *out = NULL;
    (void)state;
    assert_int_equal(neat_pop_load(NULL, (const uint8_t *)"x", 1, NULL, NULL), NEAT_E_ARG);
    assert_int_equal(neat_pop_load(&out, NULL, 10, NULL, NULL), NEAT_E_ARG);
    assert_int_equal(neat_pop_save(NULL, NULL, NULL), NEAT_E_ARG);
}

/* ---- version 3: net_step and the game tag ---- */

/* Where version 3 puts net_step: after the 228 bytes of version 2's
 * parameters (13 u32, 22 f64) behind magic and version; the tag's length next. */
#define CK_NET_STEP_OFF 240u

/* A version-3 checkpoint with net_step sync and an empty tag, rewritten as
 * version 2 wrote it: without those 8 bytes. */
static size_t ck_to_v2(const uint8_t *v3, size_t len, uint8_t *out)
{
    static const uint8_t zero[8] = {0};
    assert_memory_equal(v3 + CK_NET_STEP_OFF, zero, 8);
    memcpy(out, v3, CK_NET_STEP_OFF);
    memcpy(out + CK_NET_STEP_OFF, v3 + CK_NET_STEP_OFF + 8, len - CK_NET_STEP_OFF - 8);
    out[8] = 2;
    reseal(out, len - 8);
    return len - 8;
}

/* A run saved before this version (checkpoint version 2) still loads, as a
 * sync run with an empty tag, and goes on as it would have: saved again it
 * is the version-3 checkpoint of the same state. */
static void test_version2_loads(void **state)
{
    neat_pop *pop = evolved_pop(12, 3, 71), *out;
    uint8_t *buf, *v2, *again;
    size_t len, l2, la, tl = 99;
    (void)state;
    save(pop, &buf, &len);
    assert_int_equal(buf[CK_NET_STEP_OFF - 4], 0); /* max_nodes' high byte: the layout is what we think */
    v2 = (uint8_t *)malloc(len);
    assert_non_null(v2);
    l2 = ck_to_v2(buf, len, v2);
    out = load_ok(v2, l2);
    assert_int_equal(neat_pop_params(out)->net_step, NEAT_STEP_SYNC);
    assert_null(neat_pop_game(out, &tl));
    assert_int_equal(tl, 0);
    save(out, &again, &la);
    assert_int_equal(la, len);
    assert_memory_equal(again, buf, len);
    /* and both go on to the same generation */
    run_generations(pop, 2);
    run_generations(out, 2);
    assert_same_bytes(pop, out);
    neat_pop_buf_free(out, again, la);
    neat_pop_free(out);
    free(v2);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

/* The tag and net_step survive save and load byte for byte; at most
 * NEAT_GAME_MAX bytes; copied in (the caller's buffer may change after). */
static void test_game_tag_round_trip(void **state)
{
    static uint8_t tag[NEAT_GAME_MAX + 1];
    neat_params p = ckpt_params(10);
    neat_pop *pop = NULL, *out;
    uint8_t *buf, *again;
    const uint8_t *got;
    size_t len, la, i, tl = 0;
    (void)state;
    p.net_step = NEAT_STEP_PROPAGATE;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 5, NULL), NEAT_OK);
    assert_null(neat_pop_game(pop, &tl)); /* empty by default */
    assert_int_equal(tl, 0);
    for (i = 0; i < sizeof tag; i++)
        tag[i] = (uint8_t)(i * 37u + (i >> 8));
    assert_int_equal(neat_pop_set_game(pop, tag, NEAT_GAME_MAX + 1), NEAT_E_ARG);
    assert_int_equal(neat_pop_set_game(pop, NULL, 3), NEAT_E_ARG);
    assert_int_equal(neat_pop_set_game(NULL, tag, 3), NEAT_E_ARG);
    assert_int_equal(neat_pop_set_game(pop, tag, NEAT_GAME_MAX), NEAT_OK);
    assert_int_equal(neat_pop_set_game(pop, tag, 301), NEAT_OK); /* replaces it */
    tag[0] ^= 0xFF; /* copied in: the caller's bytes are its own */
    got = neat_pop_game(pop, &tl);
    assert_int_equal(tl, 301);
    assert_int_equal(got[0], (uint8_t)(tag[0] ^ 0xFF));
    assert_memory_equal(got + 1, tag + 1, 300);
    run_generations(pop, 2);
    save(pop, &buf, &len);
    out = load_ok(buf, len);
    assert_int_equal(neat_pop_params(out)->net_step, NEAT_STEP_PROPAGATE);
    got = neat_pop_game(out, &tl);
    assert_int_equal(tl, 301);
    assert_memory_equal(got, neat_pop_game(pop, NULL), 301);
    save(out, &again, &la);
    assert_int_equal(la, len);
    assert_memory_equal(again, buf, len);
    neat_pop_buf_free(out, again, la);
    assert_int_equal(neat_pop_set_game(out, NULL, 0), NEAT_OK); /* emptied */
    assert_null(neat_pop_game(out, &tl));
    assert_int_equal(tl, 0);
    neat_pop_free(out);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

/* The tag's length is never trusted: every truncation of a tagged
 * checkpoint, and resealed lengths beyond NEAT_GAME_MAX or the bytes left,
 * are refused without reading past the buffer. */
static void test_game_tag_hostile(void **state)
{
    static const uint32_t lens[] = {NEAT_GAME_MAX + 1u, 0xFFFFFFFFu, 0x80000000u, 4000u};
    neat_pop *pop = evolved_pop(8, 1, 72), *out;
    uint8_t *buf, *bad;
    size_t len, n, off, k;
    (void)state;
    assert_int_equal(neat_pop_set_game(pop, (const uint8_t *)"world-rules v1", 14), NEAT_OK);
    save(pop, &buf, &len);
    for (n = 0; n < len; n++) {
        bad = (uint8_t *)malloc(n + 1);
        assert_non_null(bad);
        memcpy(bad, buf, n);
        out = NULL;
        assert_true(neat_pop_load(&out, bad, n, NULL, &off) != NEAT_OK);
        assert_null(out);
        free(bad);
    }
    bad = (uint8_t *)malloc(len);
    assert_non_null(bad);
    for (k = 0; k < sizeof lens / sizeof lens[0]; k++) {
        int err;
        memcpy(bad, buf, len);
        bad[CK_NET_STEP_OFF + 4] = (uint8_t)lens[k];
        bad[CK_NET_STEP_OFF + 5] = (uint8_t)(lens[k] >> 8);
        bad[CK_NET_STEP_OFF + 6] = (uint8_t)(lens[k] >> 16);
        bad[CK_NET_STEP_OFF + 7] = (uint8_t)(lens[k] >> 24);
        reseal(bad, len);
        out = NULL;
        off = 0;
        err = neat_pop_load(&out, bad, len, NULL, &off);
        assert_true(err == NEAT_E_FORMAT || err == NEAT_E_TRUNCATED);
        assert_int_equal(off, CK_NET_STEP_OFF + 4); /* at the length */
        assert_null(out);
    }
    /* a shorter length: the tag is then other bytes and the rest misparses, refused somewhere */
    memcpy(bad, buf, len);
    bad[CK_NET_STEP_OFF + 4] = 3;
    reseal(bad, len);
    out = NULL;
    assert_true(neat_pop_load(&out, bad, len, NULL, NULL) != NEAT_OK);
    assert_null(out);
    /* an unknown net_step */
    memcpy(bad, buf, len);
    bad[CK_NET_STEP_OFF] = 2;
    reseal(bad, len);
    assert_int_equal(neat_pop_load(&out, bad, len, NULL, &off), NEAT_E_FORMAT);
    free(bad);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
}

/* ---- NEAT C++ 1.2.1's switches: version 4 ---- */

#define CKPT_CPP(name)                                                                                              \
    static void name##_cpp(void **state)                                                                            \
    {                                                                                                               \
        ckpt_profile = NEAT_PROFILE_NEAT_CPP;                                                                       \
        name(state);                                                                                                \
        ckpt_profile = NEAT_PROFILE_DEFAULT;                                                                        \
    }
CKPT_CPP(test_resume_gives_same_run)
CKPT_CPP(test_resume_mid_generation)
CKPT_CPP(test_save_load_save_is_identity)
CKPT_CPP(test_header_layout)
CKPT_CPP(test_every_truncation_rejected)
CKPT_CPP(test_single_byte_corruption_rejected)

static void test_cpp_switches_and_culls_round_trip(void **state)
{
    neat_pop *pop, *copy;
    uint8_t *buf;
    size_t len;
    neat_params p;
    uint32_t k, culled = 0;
    (void)state;
    ckpt_profile = NEAT_PROFILE_NEAT_CPP;
    pop = evolved_pop(40, 6, 41);
    ckpt_profile = NEAT_PROFILE_DEFAULT;
    p = *neat_pop_params(pop);
    assert_true(pop->n_species > 1);
    for (k = 0; k < pop->n_species; k++) {
        pop->species[k].culled = (uint8_t)(k % 2); /* whatever the run culled, both values */
        culled += pop->species[k].culled;
    }
    assert_true(culled > 0);
    save(pop, &buf, &len);
    copy = load_ok(buf, len);
    {
        const neat_params *q = neat_pop_params(copy);
        assert_int_equal(q->profile, NEAT_PROFILE_NEAT_CPP);
        assert_int_equal(q->equal_fitness_rule, p.equal_fitness_rule);
        assert_int_equal(q->reenable_rule, p.reenable_rule);
        assert_int_equal(q->add_conn_rule, p.add_conn_rule);
        assert_true(q->recur_only_prob == p.recur_only_prob);
        assert_int_equal(q->species_rep, p.species_rep);
        assert_int_equal(q->weight_mut_rule, p.weight_mut_rule);
        assert_int_equal(q->elitism_rule, p.elitism_rule);
        assert_int_equal(q->interspecies_rule, p.interspecies_rule);
        assert_int_equal(q->identical_rule, p.identical_rule);
        assert_int_equal(q->offspring_rounding, p.offspring_rounding);
        assert_int_equal(q->speciate_rule, p.speciate_rule);
        assert_int_equal(q->cull_every, 3);
        assert_int_equal(q->cull_age, 1);
        assert_int_equal(q->pop_stagnation_rule, p.pop_stagnation_rule);
        assert_int_equal(q->stagnation_rule, NEAT_STAGNATION_CPP);
    }
    for (k = 0; k < pop->n_species; k++)
        assert_int_equal(copy->species[k].culled, pop->species[k].culled);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
    neat_pop_free(copy);
}

static void test_version3_loads_with_default_switches(void **state)
{
    neat_pop *pop = evolved_pop(30, 2, 42), *copy;
    neat_params d = neat_params_default();
    uint8_t *buf;
    size_t len;
    (void)state;
    save(pop, &buf, &len);
    assert_int_equal(buf[8], 3);
    copy = load_ok(buf, len);
    assert_int_equal(neat_pop_params(copy)->profile, NEAT_PROFILE_DEFAULT);
    assert_int_equal(neat_pop_params(copy)->speciate_rule, d.speciate_rule);
    assert_int_equal(neat_pop_params(copy)->cull_every, d.cull_every);
    assert_int_equal(neat_pop_params(copy)->stagnation_rule, NEAT_STAGNATION_OLDEST_WORST);
    neat_pop_buf_free(pop, buf, len);
    neat_pop_free(pop);
    neat_pop_free(copy);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_resume_gives_same_run),
        cmocka_unit_test(test_resume_mid_generation),
        cmocka_unit_test(test_save_load_save_is_identity),
        cmocka_unit_test(test_save_is_deterministic),
        cmocka_unit_test(test_header_layout),
        cmocka_unit_test(test_every_truncation_rejected),
        cmocka_unit_test(test_single_byte_corruption_rejected),
        cmocka_unit_test(test_bad_magic),
        cmocka_unit_test(test_bad_version),
        cmocka_unit_test(test_trailing_bytes_rejected),
        cmocka_unit_test(test_resealed_corruption_never_crashes),
        cmocka_unit_test(test_load_rejects_stale_counters),
        cmocka_unit_test(test_load_rejects_bad_delta_t),
        cmocka_unit_test(test_load_rejects_zero_rng_state),
        cmocka_unit_test(test_load_rejects_null_arguments),
        cmocka_unit_test(test_version2_loads),
        cmocka_unit_test(test_game_tag_round_trip),
        cmocka_unit_test(test_game_tag_hostile),
        cmocka_unit_test(test_resume_gives_same_run_cpp),
        cmocka_unit_test(test_resume_mid_generation_cpp),
        cmocka_unit_test(test_save_load_save_is_identity_cpp),
        cmocka_unit_test(test_header_layout_cpp),
        cmocka_unit_test(test_every_truncation_rejected_cpp),
        cmocka_unit_test(test_single_byte_corruption_rejected_cpp),
        cmocka_unit_test(test_cpp_switches_and_culls_round_trip),
        cmocka_unit_test(test_version3_loads_with_default_switches),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
