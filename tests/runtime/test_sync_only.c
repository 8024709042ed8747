/* test_sync_only.c - the runtime built with NRT_NO_PROPAGATE (a sync-only firmware's): sync blobs load and step as ever, a propagate blob is refused as a version it does not know. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "nrt.h"

#ifndef NRT_NO_PROPAGATE
#error "this test is built with NRT_NO_PROPAGATE (tests/CMakeLists.txt)"
#endif

/* A blob written byte by byte (no libneat here: it links the full
 * runtime): bias and one input into one output and a hidden node, the
 * hidden node into the output, the output into itself. */
static size_t so_blob(uint8_t *b, int version)
{
    static const uint8_t conns[][4] = {{0, 2, 0x00, 0xF8}, {1, 2, 0x00, 0x10}, {2, 2, 0x00, 0x08}, {3, 2, 0x00, 0x20},
                                       {1, 3, 0x00, 0x18}};
    size_t len = NRT_HEADER_SIZE + sizeof conns;
    uint32_t crc;
    memset(b, 0, NRT_HEADER_SIZE);
    b[0] = NRT_MAGIC0, b[1] = NRT_MAGIC1, b[2] = NRT_MAGIC2, b[3] = NRT_MAGIC3;
    b[NRT_OFF_VERSION] = (uint8_t)version;
    b[NRT_OFF_HEADER_SIZE] = NRT_HEADER_SIZE;
    b[NRT_OFF_INPUTS] = 2;
    b[NRT_OFF_OUTPUTS] = 1;
    b[NRT_OFF_HIDDEN] = 1;
    b[NRT_OFF_CONNS] = 5;
    b[NRT_OFF_TOTAL_SIZE] = (uint8_t)len;
    b[NRT_OFF_WEIGHT_BITS] = NRT_WEIGHT_FRAC_BITS;
    b[NRT_OFF_STEP] = (uint8_t)(version == NRT_FORMAT_VERSION_PROPAGATE ? NRT_STEP_PROPAGATE : NRT_STEP_SYNC);
    memcpy(b + NRT_HEADER_SIZE, conns, sizeof conns);
    crc = nrt_crc32(0, b, NRT_OFF_CRC);
    crc = nrt_crc32(crc, b + NRT_HEADER_SIZE, len - NRT_HEADER_SIZE);
    b[NRT_OFF_CRC] = (uint8_t)crc, b[NRT_OFF_CRC + 1] = (uint8_t)(crc >> 8);
    b[NRT_OFF_CRC + 2] = (uint8_t)(crc >> 16), b[NRT_OFF_CRC + 3] = (uint8_t)(crc >> 24);
    return len;
}

static void test_sync_loads_propagate_refused(void **state)
{
    uint8_t b[64];
    uint64_t mem[64];
    size_t len, need = 0;
    nrt_net net;
    nrt_q15 in[2] = {NRT_ONE, 12000}, out[1];
    (void)state;
    len = so_blob(b, NRT_FORMAT_VERSION);
    assert_int_equal(nrt_mem_required(b, len, &need), NRT_OK);
    assert_int_equal(need, 4u * 5u + 2u * 2u + 4u * 4u + 1u); /* the sync layout: no order */
    assert_int_equal(nrt_load(&net, b, len, mem, sizeof mem), NRT_OK);
    assert_null(net.order);
    nrt_step(&net, in, out);
    nrt_step(&net, in, out);
    assert_true(out[0] > 0);
    len = so_blob(b, NRT_FORMAT_VERSION_PROPAGATE);
    assert_int_equal(nrt_mem_required(b, len, &need), NRT_E_VERSION);
    assert_int_equal(nrt_load(&net, b, len, mem, sizeof mem), NRT_E_VERSION); /* never run as sync */
    assert_null(net.weight);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sync_loads_propagate_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
