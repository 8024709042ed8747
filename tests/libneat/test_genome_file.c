/* test_genome_file.c - genome files: exact round trip, stable bytes, and every truncation, corruption and header error refused with its offset. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat.h"
#include "nrt.h"

/* A genome with hidden nodes, disabled genes and evolved weights: the best
 * of a few generations of a toy task. */
static void evolved_genome(neat_genome *out)
{
    neat_params p = neat_params_default();
    neat_pop *pop = NULL;
    uint32_t gen, i, best = 0;
    p.pop_size = 40;
    p.n_inputs = 3;
    p.n_outputs = 2;
    p.add_node_prob = 0.3;
    p.add_conn_prob = 0.3;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 11, NULL), NEAT_OK);
    for (gen = 0; gen < 8; gen++) {
        for (i = 0; i < neat_pop_size(pop); i++) {
            const neat_genome *g = neat_pop_genome(pop, i);
            assert_int_equal(neat_pop_set_fitness(pop, i, 1.0 + g->n_conns + 0.5 * g->n_nodes), NEAT_OK);
        }
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    }
    for (i = 1; i < neat_pop_size(pop); i++)
        if (neat_pop_genome(pop, i)->n_nodes > neat_pop_genome(pop, best)->n_nodes)
            best = i;
    neat_genome_init(out);
    assert_int_equal(neat_genome_copy(out, neat_pop_genome(pop, best), NULL), NEAT_OK);
    neat_pop_free(pop);
    assert_true(neat_genome_hidden_count(out) > 0);
}

static void assert_same_genome(const neat_genome *a, const neat_genome *b)
{
    uint32_t i;
    assert_int_equal(a->n_nodes, b->n_nodes);
    assert_int_equal(a->n_conns, b->n_conns);
    for (i = 0; i < a->n_nodes; i++) {
        assert_int_equal(a->nodes[i].id, b->nodes[i].id);
        assert_int_equal(a->nodes[i].type, b->nodes[i].type);
    }
    for (i = 0; i < a->n_conns; i++) {
        assert_int_equal(a->conns[i].in, b->conns[i].in);
        assert_int_equal(a->conns[i].out, b->conns[i].out);
        assert_int_equal(a->conns[i].innov, b->conns[i].innov);
        assert_int_equal(a->conns[i].enabled, b->conns[i].enabled);
        assert_memory_equal(&a->conns[i].weight, &b->conns[i].weight, sizeof(double)); /* the exact bits */
    }
    assert_memory_equal(&a->fitness, &b->fitness, sizeof(double));
    assert_int_equal(a->has_fitness, b->has_fitness);
}

static void test_round_trip(void **state)
{
    neat_genome g, back;
    uint8_t *buf = NULL, *again = NULL;
    size_t len = 0, len2 = 0, off = 99;
    uint32_t ni = 0, no = 0;
    (void)state;
    evolved_genome(&g);
    assert_int_equal(neat_genome_save(&g, 3, 2, &buf, &len, NULL), NEAT_OK);
    assert_memory_equal(buf, "NEATGENM", 8);
    assert_int_equal(neat_genome_load(&back, &ni, &no, buf, len, NULL, &off), NEAT_OK);
    assert_int_equal(ni, 3);
    assert_int_equal(no, 2);
    assert_same_genome(&g, &back);
    /* saving the loaded genome gives the same bytes */
    assert_int_equal(neat_genome_save(&back, 3, 2, &again, &len2, NULL), NEAT_OK);
    assert_int_equal(len, len2);
    assert_memory_equal(buf, again, len);
    /* the blob of the loaded genome is the blob of the original */
    {
        uint8_t b1[4096], b2[4096];
        size_t l1 = 0, l2 = 0;
        assert_int_equal(neat_blob_write(&g, 3, 2, b1, sizeof b1, &l1), NEAT_OK);
        assert_int_equal(neat_blob_write(&back, 3, 2, b2, sizeof b2, &l2), NEAT_OK);
        assert_int_equal(l1, l2);
        assert_memory_equal(b1, b2, l1);
    }
    free(buf);
    free(again);
    neat_genome_free(&g, NULL);
    neat_genome_free(&back, NULL);
}

static void test_wrong_shape_refused_on_save(void **state)
{
    neat_genome g;
    uint8_t *buf = NULL;
    size_t len = 0;
    (void)state;
    neat_genome_init(&g);
    assert_int_equal(neat_genome_minimal(&g, 3, 2, NULL), NEAT_OK);
    /* a genome of 3 inputs is not one of 4 */
    assert_int_equal(neat_genome_save(&g, 4, 2, &buf, &len, NULL), NEAT_E_ARG);
    assert_null(buf);
    neat_genome_free(&g, NULL);
}

/* rewrites the CRC after a change, so that the check behind it is reached */
static void reseal(uint8_t *buf, size_t len)
{
    uint32_t c = nrt_crc32(0, buf, len - 4);
    buf[len - 4] = (uint8_t)c;
    buf[len - 3] = (uint8_t)(c >> 8);
    buf[len - 2] = (uint8_t)(c >> 16);
    buf[len - 1] = (uint8_t)(c >> 24);
}

static void test_every_truncation_and_flip_refused(void **state)
{
    neat_genome g, back;
    uint8_t *buf = NULL, *bad;
    size_t len = 0, n, off;
    int bit;
    (void)state;
    evolved_genome(&g);
    assert_int_equal(neat_genome_save(&g, 3, 2, &buf, &len, NULL), NEAT_OK);
    bad = (uint8_t *)malloc(len + 1);
    assert_non_null(bad);
    for (n = 0; n < len; n++) {
        int err;
        memcpy(bad, buf, n);
        off = (size_t)-1;
        err = neat_genome_load(&back, NULL, NULL, bad, n, NULL, &off);
        if (err != NEAT_E_TRUNCATED && err != NEAT_E_FORMAT && err != NEAT_E_CRC)
            fail_msg("%zu of %zu bytes: error %d", n, len, err);
        assert_true(off <= len);
        assert_int_equal(back.n_nodes, 0);
    }
    /* a byte more */
    memcpy(bad, buf, len);
    bad[len] = 0;
    assert_int_not_equal(neat_genome_load(&back, NULL, NULL, bad, len + 1, NULL, NULL), NEAT_OK);
    /* every bit flipped: the CRC catches it */
    for (n = 0; n < len; n++)
        for (bit = 0; bit < 8; bit++) {
            memcpy(bad, buf, len);
            bad[n] ^= (uint8_t)(1u << bit);
            assert_int_not_equal(neat_genome_load(&back, NULL, NULL, bad, len, NULL, NULL), NEAT_OK);
        }
    /* with the CRC made right again, the checks behind it: version at 8 (3: no such version) */
    memcpy(bad, buf, len);
    bad[8] = 3;
    reseal(bad, len);
    off = 0;
    assert_int_equal(neat_genome_load(&back, NULL, NULL, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 8);
    /* no outputs: n_outputs' own offset, 16 (issue 49: the loader names the field; it said 12, the shape's start) */
    memcpy(bad, buf, len);
    memset(bad + 16, 0, 4);
    reseal(bad, len);
    assert_int_equal(neat_genome_load(&back, NULL, NULL, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 16);
    /* no inputs: 12 */
    memcpy(bad, buf, len);
    memset(bad + 12, 0, 4);
    reseal(bad, len);
    assert_int_equal(neat_genome_load(&back, NULL, NULL, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 12);
    /* a shape whose sum wraps around 32 bits */
    memcpy(bad, buf, len);
    bad[12] = 0xF0, bad[13] = bad[14] = bad[15] = 0xFF;
    bad[16] = 0x10, bad[17] = bad[18] = bad[19] = 0;
    reseal(bad, len);
    assert_int_equal(neat_genome_load(&back, NULL, NULL, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 12);
    /* a node count larger than the file: refused before any allocation */
    memcpy(bad, buf, len);
    memset(bad + 20, 0xFF, 4);
    reseal(bad, len);
    assert_int_not_equal(neat_genome_load(&back, NULL, NULL, bad, len, NULL, &off), NEAT_OK);
    /* a NaN weight: the first connection's weight (after 4 + 5n node bytes, count, in, out, innov) */
    memcpy(bad, buf, len);
    {
        size_t w = 20 + 4 + 5u * g.n_nodes + 4 + 12;
        memset(bad + w, 0xFF, 8);
    }
    reseal(bad, len);
    assert_int_equal(neat_genome_load(&back, NULL, NULL, bad, len, NULL, &off), NEAT_E_FORMAT);
    free(bad);
    free(buf);
    neat_genome_free(&g, NULL);
}

/* Version 2 records the origin: the step and the run's tag travel with the
 * genome, round trip exactly, and every cut, flip and bad field is refused at
 * its offset; version 1 (no origin) is still written and read as before. */
static void test_origin(void **state)
{
    neat_genome g, back;
    neat_genome_origin o, got;
    uint8_t tag[300], *buf = NULL, *again = NULL, *v1 = NULL, *v1b = NULL, *bad;
    size_t len = 0, len2 = 0, l1 = 0, l1b = 0, n, off = 0;
    uint32_t ni = 0, no = 0, i;
    (void)state;
    for (i = 0; i < sizeof tag; i++)
        tag[i] = (uint8_t)(i * 7u + 1u);
    evolved_genome(&g);
    memset(&o, 0, sizeof o);
    o.net_step = NEAT_STEP_PROPAGATE;
    o.tag_len = sizeof tag;
    o.tag = tag;
    assert_int_equal(neat_genome_save_origin(&g, 3, 2, &o, &buf, &len, NULL), NEAT_OK);
    assert_int_equal(buf[8], 2);
    assert_int_equal(neat_genome_load_origin(&back, &ni, &no, &got, buf, len, NULL, &off), NEAT_OK);
    assert_int_equal(got.version, 2);
    assert_int_equal(got.net_step, NEAT_STEP_PROPAGATE);
    assert_int_equal(got.tag_len, sizeof tag);
    assert_memory_equal(got.tag, tag, sizeof tag);
    assert_int_equal(ni, 3);
    assert_int_equal(no, 2);
    assert_same_genome(&g, &back);
    assert_int_equal(neat_genome_save_origin(&back, 3, 2, &got, &again, &len2, NULL), NEAT_OK);
    assert_int_equal(len, len2);
    assert_memory_equal(buf, again, len);
    neat_genome_free(&back, NULL);
    /* neat_genome_load reads a version-2 file too (the origin ignored) */
    assert_int_equal(neat_genome_load(&back, NULL, NULL, buf, len, NULL, NULL), NEAT_OK);
    neat_genome_free(&back, NULL);
    /* version 1: no origin, neat_genome_save's bytes; read as sync with no tag */
    assert_int_equal(neat_genome_save(&g, 3, 2, &v1, &l1, NULL), NEAT_OK);
    assert_int_equal(neat_genome_save_origin(&g, 3, 2, NULL, &v1b, &l1b, NULL), NEAT_OK);
    assert_int_equal(l1, l1b);
    assert_memory_equal(v1, v1b, l1);
    assert_int_equal(v1[8], 1);
    assert_int_equal(len, l1 + 8 + sizeof tag);
    assert_int_equal(neat_genome_load_origin(&back, NULL, NULL, &got, v1, l1, NULL, NULL), NEAT_OK);
    assert_int_equal(got.version, 1);
    assert_int_equal(got.net_step, NEAT_STEP_SYNC);
    assert_int_equal(got.tag_len, 0);
    neat_genome_free(&back, NULL);
    /* what a save refuses: a step that is no mode, a tag too long or missing */
    o.net_step = 2;
    assert_int_equal(neat_genome_save_origin(&g, 3, 2, &o, &again, &len2, NULL), NEAT_E_ARG);
    o.net_step = NEAT_STEP_SYNC;
    o.tag_len = NEAT_GAME_MAX + 1u;
    assert_int_equal(neat_genome_save_origin(&g, 3, 2, &o, &again, &len2, NULL), NEAT_E_ARG);
    o.tag_len = 4;
    o.tag = NULL;
    assert_int_equal(neat_genome_save_origin(&g, 3, 2, &o, &again, &len2, NULL), NEAT_E_ARG);
    /* every cut of the version-2 file is refused */
    bad = (uint8_t *)malloc(len);
    assert_non_null(bad);
    for (n = 0; n < len; n++) {
        int err;
        memcpy(bad, buf, n);
        err = neat_genome_load_origin(&back, NULL, NULL, &got, bad, n, NULL, &off);
        if (err != NEAT_E_TRUNCATED && err != NEAT_E_FORMAT && err != NEAT_E_CRC)
            fail_msg("%zu of %zu bytes: error %d", n, len, err);
        assert_int_equal(back.n_nodes, 0);
    }
    /* resealed: a step that is no mode at 20, a tag length beyond the file or NEAT_GAME_MAX at 24 */
    memcpy(bad, buf, len);
    bad[20] = 2;
    reseal(bad, len);
    assert_int_equal(neat_genome_load_origin(&back, NULL, NULL, &got, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 20);
    memcpy(bad, buf, len);
    bad[24] = 0x01, bad[25] = 0x10, bad[26] = bad[27] = 0; /* 4097 */
    reseal(bad, len);
    assert_int_equal(neat_genome_load_origin(&back, NULL, NULL, &got, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 24);
    memset(bad + 24, 0xFF, 4);
    reseal(bad, len);
    assert_int_equal(neat_genome_load_origin(&back, NULL, NULL, &got, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 24);
    free(bad);
    free(buf);
    free(again);
    free(v1);
    free(v1b);
    neat_genome_free(&g, NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_wrong_shape_refused_on_save),
        cmocka_unit_test(test_every_truncation_and_flip_refused),
        cmocka_unit_test(test_origin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
