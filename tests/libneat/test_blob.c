/* test_blob.c - genome -> champion blob: size, quantisation, order, limits, and that the runtime accepts it. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "neat.h"
#include "neat_phenotype.h"
#include "nrt.h"

static int16_t blob_weight(const uint8_t *b, uint32_t k)
{
    const uint8_t *c = b + NRT_HEADER_SIZE + NRT_CONN_SIZE * k;
    return (int16_t)(uint16_t)(c[2] | (c[3] << 8));
}

/* 2 inputs, 1 output, 1 hidden; weights chosen to exercise rounding and saturation */
static void blob_genome(neat_genome *g)
{
    neat_genome_init(g);
    assert_int_equal(neat_genome_add_node(g, 0, NEAT_NODE_BIAS, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 1, NEAT_NODE_INPUT, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 2, NEAT_NODE_INPUT, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 3, NEAT_NODE_OUTPUT, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 7, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_conn(g, 7, 3, -8.0, 0, 1, NULL), NEAT_OK);  /* saturates to -32767 */
    assert_int_equal(neat_genome_add_conn(g, 1, 7, 8.0, 1, 1, NULL), NEAT_OK);   /* saturates to 32767 */
    assert_int_equal(neat_genome_add_conn(g, 2, 3, 0.5, 2, 0, NULL), NEAT_OK);   /* disabled: not written */
    assert_int_equal(neat_genome_add_conn(g, 0, 3, 1.0 / 8192.0 + 1e-12, 3, 1, NULL), NEAT_OK); /* rounds up to 1 */
    assert_int_equal(neat_genome_add_conn(g, 2, 7, -0.25, 4, 1, NULL), NEAT_OK); /* exact: -1024 */
}

static void test_size_is_32_plus_4_per_enabled(void **state)
{
    neat_genome g;
    uint8_t buf[128];
    size_t len = 0;
    (void)state;
    blob_genome(&g);
    assert_int_equal(neat_blob_size(&g), 32 + 4 * 4);
    assert_int_equal(neat_blob_write(&g, 2, 1, buf, sizeof buf, &len), NEAT_OK);
    assert_int_equal(len, 48);
    /* one byte short: refused, nothing claimed written */
    assert_int_equal(neat_blob_write(&g, 2, 1, buf, 47, &len), NEAT_E_ARG);
    neat_genome_free(&g, NULL);
}

static void test_sorted_by_target_with_symmetric_weights(void **state)
{
    neat_genome g;
    uint8_t buf[128];
    size_t len;
    uint32_t k;
    (void)state;
    blob_genome(&g);
    assert_int_equal(neat_blob_write(&g, 2, 1, buf, sizeof buf, &len), NEAT_OK);
    /* indices: bias 0, inputs 1-2, output 3, hidden (id 7) 4; order by (target, source) */
    {
        static const uint8_t want[4][2] = {{0, 3}, {4, 3}, {1, 4}, {2, 4}};
        static const int16_t w[4] = {1, -32767, 32767, -1024};
        for (k = 0; k < 4; k++) {
            assert_int_equal(buf[NRT_HEADER_SIZE + 4 * k], want[k][0]);
            assert_int_equal(buf[NRT_HEADER_SIZE + 4 * k + 1], want[k][1]);
            assert_int_equal(blob_weight(buf, k), w[k]);
        }
    }
    neat_genome_free(&g, NULL);
}

static void test_runtime_accepts_it(void **state)
{
    neat_genome g;
    uint8_t buf[128], mem[256];
    size_t len, need;
    nrt_net net;
    (void)state;
    blob_genome(&g);
    assert_int_equal(neat_blob_write(&g, 2, 1, buf, sizeof buf, &len), NEAT_OK);
    assert_int_equal(nrt_mem_required(buf, len, &need), NRT_OK);
    assert_true(need <= sizeof mem);
    assert_int_equal(nrt_load(&net, buf, len, mem, sizeof mem), NRT_OK);
    assert_int_equal(net.n_inputs, 3);
    assert_int_equal(net.n_outputs, 1);
    assert_int_equal(net.n_hidden, 1);
    assert_int_equal(net.n_conns, 4);
    neat_genome_free(&g, NULL);
}

static void test_layout_must_match(void **state)
{
    neat_genome g;
    uint8_t buf[128];
    size_t len;
    (void)state;
    blob_genome(&g);
    /* the genome has 2 inputs and 1 output, not 1 and 2 */
    assert_int_equal(neat_blob_write(&g, 1, 2, buf, sizeof buf, &len), NEAT_E_ARG);
    neat_genome_free(&g, NULL);
}

static void test_too_many_nodes(void **state)
{
    neat_genome g;
    uint8_t buf[64];
    size_t len;
    uint32_t i;
    (void)state;
    assert_int_equal(neat_genome_minimal(&g, 2, 1, NULL), NEAT_OK);
    for (i = 0; i < 253; i++) /* 4 + 253 = 257 nodes */
        assert_int_equal(neat_genome_add_node(&g, 10 + i, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    assert_int_equal(neat_blob_write(&g, 2, 1, buf, sizeof buf, &len), NEAT_E_TOOBIG);
    neat_genome_free(&g, NULL);
}

/* net_step: sync by default, checked; the phenotype encodes the run's
 * mode, so evolution evaluates what the blob records. */
static void test_net_step_param(void **state)
{
    neat_params p = neat_params_default();
    neat_phenotype ph;
    neat_genome g;
    const char *field = NULL;
    uint8_t buf[256];
    size_t len;
    (void)state;
    assert_int_equal(p.net_step, NEAT_STEP_SYNC);
    p.net_step = 2;
    assert_int_equal(neat_params_check(&p, &field), NEAT_E_PARAM);
    assert_string_equal(field, "net_step");
    p.net_step = -1;
    assert_int_equal(neat_params_check(&p, &field), NEAT_E_PARAM);
    p.net_step = NEAT_STEP_PROPAGATE;
    assert_int_equal(neat_params_check(&p, &field), NEAT_OK);
    p.n_inputs = 2;
    p.n_outputs = 1;
    assert_int_equal(neat_genome_minimal(&g, 2, 1, NULL), NEAT_OK);
    neat_phenotype_init(&ph, NULL);
    assert_int_equal(neat_phenotype_load(&ph, &g, &p), NEAT_OK);
    assert_int_equal(ph.net.step, NRT_STEP_PROPAGATE);
    assert_int_equal(ph.blob[NRT_OFF_VERSION], NRT_FORMAT_VERSION_PROPAGATE);
    p.net_step = NEAT_STEP_SYNC;
    assert_int_equal(neat_phenotype_load(&ph, &g, &p), NEAT_OK);
    assert_int_equal(ph.net.step, NRT_STEP_SYNC);
    assert_null(ph.net.order);
    assert_int_equal(neat_blob_write(&g, 2, 1, buf, sizeof buf, &len), NEAT_OK);
    assert_int_equal(len, ph.blob_len);
    assert_memory_equal(buf, ph.blob, len); /* sync: neat_blob_write's bytes */
    assert_int_equal(neat_blob_write_step(&g, 2, 1, 2, buf, sizeof buf, &len), NEAT_E_ARG);
    neat_phenotype_free(&ph);
    neat_genome_free(&g, NULL);
}

/* A blob handed over by another process (tools/mpi): no bytes, or a length without bytes, is refused before
 * anything is copied (found by fuzz_mpi_wire: a builtin's entry, blob NULL with its number as the length). */
static void test_load_blob_without_bytes(void **state)
{
    neat_phenotype ph;
    static const uint8_t none[1] = {0};
    (void)state;
    neat_phenotype_init(&ph, NULL);
    assert_int_equal(neat_phenotype_load_blob(&ph, NULL, 4), NRT_E_ARG - 100);
    assert_int_equal(neat_phenotype_load_blob(&ph, NULL, 0), NRT_E_TRUNCATED - 100);
    assert_true(neat_phenotype_load_blob(&ph, none, 0) < 0);
    neat_phenotype_free(&ph);
}

/* neat_q15 is floor(x * 32768 + 0.5) saturated to [-32768, 32767] (without
 * libm's floor since it runs for every input): the definition, checked on
 * the boundaries, the halves on both sides of zero and a sweep; NaN is 0. */
static void test_q15_is_rounded_floor(void **state)
{
    static const double xs[] = {0.0, -0.0, 1.0, -1.0, 2.0, -2.0, 0.999984741, 0.99998, -0.99998, 1e300, -1e300,
                                0.5 / 32768, -0.5 / 32768, 1.5 / 32768, -1.5 / 32768, -32767.5 / 32768,
                                -32768.5 / 32768, 32766.5 / 32768, 32767.5 / 32768, 1e-20, -1e-20};
    uint32_t i;
    int k;
    (void)state;
    for (i = 0; i < sizeof xs / sizeof xs[0]; i++) {
        double q = floor(xs[i] * 32768.0 + 0.5);
        q = q > 32767.0 ? 32767.0 : (q < -32768.0 ? -32768.0 : q);
        assert_int_equal(neat_q15(xs[i]), (int)q);
    }
    for (k = -70000; k <= 70000; k++) {
        double x = k / 65536.0 + (k % 7) * 1e-7, q = floor(x * 32768.0 + 0.5);
        q = q > 32767.0 ? 32767.0 : (q < -32768.0 ? -32768.0 : q);
        assert_int_equal(neat_q15(x), (int)q);
    }
    assert_int_equal(neat_q15(NAN), 0);
    assert_int_equal(neat_q15(INFINITY), 32767);
    assert_int_equal(neat_q15(-INFINITY), -32768);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_size_is_32_plus_4_per_enabled),
        cmocka_unit_test(test_sorted_by_target_with_symmetric_weights),
        cmocka_unit_test(test_runtime_accepts_it),
        cmocka_unit_test(test_layout_must_match),
        cmocka_unit_test(test_too_many_nodes),
        cmocka_unit_test(test_net_step_param),
        cmocka_unit_test(test_load_blob_without_bytes),
        cmocka_unit_test(test_q15_is_rounded_floor),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
