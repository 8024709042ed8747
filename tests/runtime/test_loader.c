/* test_loader.c - the runtime's blob loader: sizes, memory, and rejection of every truncated, altered or malformed blob. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat.h"
#include "nrt.h"

/* The sample network: 3 sensors (+ bias), 2 outputs, 2 recurrent hidden
 * nodes, 24 connections of which one is disabled. */
#define LD_IN 3
#define LD_OUT 2
#define LD_HID 2
#define LD_NODES (LD_IN + 1 + LD_OUT + LD_HID)
#define LD_CONNS 24
#define LD_ENABLED (LD_CONNS - 1)
#define LD_SIZE (32 + 4 * LD_ENABLED)

typedef struct ld_blob {
    uint8_t b[512];
    size_t len;
} ld_blob;

/* Large enough for the sample at any offset; uint64_t for a known even base address. */
static uint64_t ld_mem[256];

static void ld_sample(ld_blob *s)
{
    neat_genome g;
    uint32_t i;
    assert_int_equal(neat_genome_recurrent_hidden(&g, LD_IN, LD_OUT, LD_HID, NEAT_DIRECT_INPUTS, NULL), NEAT_OK);
    assert_int_equal(g.n_conns, LD_CONNS);
    for (i = 0; i < g.n_conns; i++)
        g.conns[i].weight = ((double)((i * 7u) % 13u) - 6.0) * 0.625; /* in [-3.75, 3.75] */
    g.conns[5].enabled = 0;
    assert_int_equal(neat_blob_write(&g, LD_IN, LD_OUT, s->b, sizeof s->b, &s->len), NEAT_OK);
    neat_genome_free(&g, NULL);
}

static void ld_wr16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFF);
    p[1] = (uint8_t)(v >> 8);
}

/* Rewrites the CRC field after an edit, so the check under test is the one that fires. */
static void ld_fix_crc(ld_blob *s)
{
    uint32_t crc = nrt_crc32(0, s->b, NRT_OFF_CRC);
    crc = nrt_crc32(crc, s->b + NRT_HEADER_SIZE, s->len - NRT_HEADER_SIZE);
    ld_wr16(s->b + NRT_OFF_CRC, crc & 0xFFFF);
    ld_wr16(s->b + NRT_OFF_CRC + 2, crc >> 16);
}

static int ld_load(const ld_blob *s)
{
    nrt_net net;
    return nrt_load(&net, s->b, s->len, ld_mem, sizeof ld_mem);
}

/* The sample blob loads, with its counts in the net. */
static void test_load_ok(void **state)
{
    ld_blob s;
    nrt_net net;
    (void)state;
    ld_sample(&s);
    assert_int_equal(nrt_load(&net, s.b, s.len, ld_mem, sizeof ld_mem), NRT_OK);
    assert_int_equal(net.n_inputs, LD_IN + 1);
    assert_int_equal(net.n_outputs, LD_OUT);
    assert_int_equal(net.n_hidden, LD_HID);
    assert_int_equal(net.n_nodes, LD_NODES);
    assert_int_equal(net.n_conns, LD_ENABLED);
}

/* nrt_inspect: blob size 32 + 4 per enabled connection, and memory for the arrays of nrt_net. */
static void test_inspect_sizes(void **state)
{
    ld_blob s;
    size_t size = 0, mem = 0, mem2 = 0;
    size_t arrays = 4u * LD_ENABLED + 2u * (LD_OUT + LD_HID) + 4u * LD_NODES; /* weight+src, end, act[2] */
    (void)state;
    ld_sample(&s);
    assert_int_equal(s.len, LD_SIZE);
    assert_int_equal(nrt_inspect(s.b, s.len, &size, &mem), NRT_OK);
    assert_int_equal(size, LD_SIZE);
    assert_true(mem >= arrays && mem <= arrays + 1); /* at most one byte of alignment slack */
    assert_int_equal(nrt_mem_required(s.b, s.len, &mem2), NRT_OK);
    assert_int_equal(mem2, mem);
    /* the header alone is enough, and either output may be NULL */
    assert_int_equal(nrt_inspect(s.b, NRT_HEADER_SIZE, &size, NULL), NRT_OK);
    assert_int_equal(size, LD_SIZE);
    assert_int_equal(nrt_inspect(s.b, NRT_HEADER_SIZE, NULL, NULL), NRT_OK);
}

/* Every proper prefix of the blob (lengths 0 .. len-1) is rejected as truncated. */
static void test_every_truncation_rejected(void **state)
{
    ld_blob s;
    size_t len;
    (void)state;
    ld_sample(&s);
    for (len = 0; len < s.len; len++) {
        /* an exact-size copy, so a sanitizer build would catch any read past it */
        uint8_t *p = (uint8_t *)malloc(len + 1);
        nrt_net net;
        int err;
        assert_non_null(p);
        memcpy(p, s.b, len);
        err = nrt_load(&net, p, len, ld_mem, sizeof ld_mem);
        assert_int_equal(err, NRT_E_TRUNCATED);
        free(p);
    }
}

/* Every single-byte change anywhere (each offset, each of the 255 other values) is rejected. */
static void test_every_byte_change_rejected(void **state)
{
    ld_blob s, t;
    size_t off;
    int v;
    (void)state;
    ld_sample(&s);
    for (off = 0; off < s.len; off++) {
        for (v = 0; v < 256; v++) {
            int err;
            if (v == s.b[off])
                continue;
            t = s;
            t.b[off] = (uint8_t)v;
            err = ld_load(&t);
            if (err == NRT_OK)
                fail_msg("byte %u set to %d accepted", (unsigned)off, v);
            assert_true(err >= NRT_E_WEIGHT && err <= NRT_E_ARG);
        }
    }
}

/* Bytes after the blob's end: NRT_E_TRAILING (while nrt_inspect still reads the header). */
static void test_trailing_rejected(void **state)
{
    ld_blob s;
    size_t size = 0;
    (void)state;
    ld_sample(&s);
    s.b[s.len] = 0;
    s.len++;
    assert_int_equal(ld_load(&s), NRT_E_TRAILING);
    assert_int_equal(nrt_inspect(s.b, s.len, &size, NULL), NRT_OK);
    assert_int_equal(size, LD_SIZE);
}

/* A buffer one byte short of nrt_mem_required: NRT_E_NOMEM; exactly that size loads. */
static void test_buffer_size(void **state)
{
    ld_blob s;
    size_t need = 0;
    nrt_net net;
    uint8_t *buf = (uint8_t *)ld_mem;
    (void)state;
    ld_sample(&s);
    assert_int_equal(nrt_mem_required(s.b, s.len, &need), NRT_OK);
    assert_true(need + 1 <= sizeof ld_mem);
    assert_int_equal(nrt_load(&net, s.b, s.len, buf, need - 1), NRT_E_NOMEM);
    assert_int_equal(nrt_load(&net, s.b, s.len, buf + 1, need - 1), NRT_E_NOMEM);
    assert_int_equal(nrt_load(&net, s.b, s.len, buf, need), NRT_OK);
}

/* Exactly nrt_mem_required bytes at an odd address loads, with 16-bit arrays aligned inside the buffer. */
static void test_odd_address(void **state)
{
    ld_blob s;
    size_t need = 0;
    nrt_net net;
    uint8_t *buf = (uint8_t *)ld_mem + 1;
    nrt_q15 in[LD_IN + 1] = {NRT_ONE, 1000, -2000, 3000}, out[LD_OUT];
    (void)state;
    ld_sample(&s);
    assert_int_equal(nrt_mem_required(s.b, s.len, &need), NRT_OK);
    memset(ld_mem, 0xA5, sizeof ld_mem);
    assert_int_equal(nrt_load(&net, s.b, s.len, buf, need), NRT_OK);
    assert_int_equal((uintptr_t)net.weight & 1u, 0);
    assert_int_equal((uintptr_t)net.src & 1u, 0);
    assert_int_equal((uintptr_t)net.end & 1u, 0);
    assert_int_equal((uintptr_t)net.act[0] & 1u, 0);
    assert_int_equal((uintptr_t)net.act[1] & 1u, 0);
    /* everything lies inside [buf, buf + need) */
    assert_true((uint8_t *)net.weight >= buf);
    assert_true((uint8_t *)(net.act[1] + net.n_nodes) <= buf + need);
    nrt_step(&net, in, out);
    /* the byte after the buffer is untouched */
    assert_int_equal(buf[need], 0xA5);
}

/* Wrong magic: NRT_E_MAGIC. */
static void test_bad_magic(void **state)
{
    ld_blob s;
    int i;
    (void)state;
    for (i = 0; i < 4; i++) {
        ld_sample(&s);
        s.b[NRT_OFF_MAGIC + i] ^= 0x20;
        ld_fix_crc(&s);
        assert_int_equal(ld_load(&s), NRT_E_MAGIC);
        assert_int_equal(nrt_inspect(s.b, s.len, NULL, NULL), NRT_E_MAGIC);
    }
}

/* Format versions 0 and 3: NRT_E_VERSION; version 2 with the step byte of
 * a sync blob (0) is no blob either: NRT_E_HEADER (one encoding per network). */
static void test_bad_version(void **state)
{
    ld_blob s;
    (void)state;
    ld_sample(&s);
    ld_wr16(s.b + NRT_OFF_VERSION, 3);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_VERSION);
    ld_wr16(s.b + NRT_OFF_VERSION, 0);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_VERSION);
    ld_wr16(s.b + NRT_OFF_VERSION, 2);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_HEADER);
}

/* A nonzero reserved byte, or an unknown header size, weight format or activation: NRT_E_HEADER. */
static void test_bad_header_fields(void **state)
{
    ld_blob s;
    int off;
    (void)state;
    for (off = NRT_OFF_RESERVED; off < NRT_OFF_CRC; off++) {
        ld_sample(&s);
        s.b[off] = 1;
        ld_fix_crc(&s);
        assert_int_equal(ld_load(&s), NRT_E_HEADER);
    }
    ld_sample(&s);
    ld_wr16(s.b + NRT_OFF_HEADER_SIZE, 36);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_HEADER);
    ld_sample(&s);
    s.b[NRT_OFF_WEIGHT_BITS] = 11;
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_HEADER);
    ld_sample(&s);
    s.b[NRT_OFF_ACTIVATION] = 1;
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_HEADER);
}

/* More than 256 nodes, no input, no output, or a total size disagreeing with the connection count: NRT_E_COUNTS. */
static void test_bad_counts(void **state)
{
    ld_blob s;
    (void)state;
    ld_sample(&s);
    ld_wr16(s.b + NRT_OFF_HIDDEN, NRT_MAX_NODES - (LD_IN + 1 + LD_OUT) + 1); /* 257 nodes */
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_COUNTS);
    ld_wr16(s.b + NRT_OFF_HIDDEN, 0xFFFF);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_COUNTS);
    ld_sample(&s);
    ld_wr16(s.b + NRT_OFF_INPUTS, 0);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_COUNTS);
    ld_sample(&s);
    ld_wr16(s.b + NRT_OFF_OUTPUTS, 0);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_COUNTS);
    ld_sample(&s);
    ld_wr16(s.b + NRT_OFF_CONNS, LD_ENABLED - 1);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_COUNTS);
}

/* Exactly 256 nodes is still a valid count (extra hidden nodes without connections). */
static void test_max_nodes_accepted(void **state)
{
    ld_blob s;
    nrt_net net;
    static uint8_t big[4096];
    (void)state;
    ld_sample(&s);
    ld_wr16(s.b + NRT_OFF_HIDDEN, NRT_MAX_NODES - (LD_IN + 1 + LD_OUT));
    ld_fix_crc(&s);
    assert_int_equal(nrt_load(&net, s.b, s.len, big, sizeof big), NRT_OK);
    assert_int_equal(net.n_nodes, NRT_MAX_NODES);
}

/* A source or target node index past the last node: NRT_E_INDEX. */
static void test_index_out_of_range(void **state)
{
    ld_blob s;
    uint8_t *last;
    (void)state;
    ld_sample(&s);
    s.b[NRT_HEADER_SIZE + 0] = LD_NODES; /* source of the first connection */
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_INDEX);
    ld_sample(&s);
    s.b[NRT_HEADER_SIZE + 0] = 255;
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_INDEX);
    ld_sample(&s);
    last = s.b + s.len - NRT_CONN_SIZE;
    last[1] = LD_NODES; /* target of the last connection */
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_INDEX);
}

/* A connection into the bias or an input node: NRT_E_INDEX. */
static void test_conn_into_input(void **state)
{
    ld_blob s;
    int target;
    (void)state;
    for (target = 0; target <= LD_IN; target++) {
        ld_sample(&s);
        s.b[NRT_HEADER_SIZE + 1] = (uint8_t)target;
        ld_fix_crc(&s);
        assert_int_equal(ld_load(&s), NRT_E_INDEX);
    }
}

/* Connections not sorted by target: NRT_E_ORDER. */
static void test_conns_out_of_order(void **state)
{
    ld_blob s;
    uint8_t tmp[NRT_CONN_SIZE];
    uint8_t *first, *last;
    (void)state;
    ld_sample(&s);
    first = s.b + NRT_HEADER_SIZE;
    last = s.b + s.len - NRT_CONN_SIZE;
    assert_true(first[1] < last[1]);
    memcpy(tmp, first, NRT_CONN_SIZE);
    memcpy(first, last, NRT_CONN_SIZE);
    memcpy(last, tmp, NRT_CONN_SIZE);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_ORDER);
}

/* A weight of -32768 (outside the symmetric range the step relies on):
 * NRT_E_WEIGHT; -32767 loads. */
static void test_weight_min_rejected(void **state)
{
    ld_blob s;
    (void)state;
    ld_sample(&s);
    ld_wr16(s.b + NRT_HEADER_SIZE + 2, 0x8000u);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_E_WEIGHT);
    ld_wr16(s.b + NRT_HEADER_SIZE + 2, 0x8001u);
    ld_fix_crc(&s);
    assert_int_equal(ld_load(&s), NRT_OK);
}

/* A changed CRC field: NRT_E_CRC. */
static void test_crc_mismatch(void **state)
{
    ld_blob s;
    (void)state;
    ld_sample(&s);
    s.b[NRT_OFF_CRC + 3] ^= 0x80;
    assert_int_equal(ld_load(&s), NRT_E_CRC);
    ld_sample(&s);
    s.b[s.len - 1] ^= 0x01; /* a weight byte, CRC left stale */
    assert_int_equal(ld_load(&s), NRT_E_CRC);
}

/* NULL net, blob or buffer: NRT_E_ARG; a failed load leaves the net zeroed. */
static void test_null_args(void **state)
{
    ld_blob s;
    nrt_net net;
    size_t size;
    (void)state;
    ld_sample(&s);
    assert_int_equal(nrt_load(NULL, s.b, s.len, ld_mem, sizeof ld_mem), NRT_E_ARG);
    assert_int_equal(nrt_load(&net, NULL, s.len, ld_mem, sizeof ld_mem), NRT_E_ARG);
    assert_int_equal(nrt_load(&net, s.b, s.len, NULL, sizeof ld_mem), NRT_E_ARG);
    assert_int_equal(nrt_inspect(NULL, s.len, &size, NULL), NRT_E_ARG);
    assert_int_equal(nrt_mem_required(NULL, s.len, &size), NRT_E_ARG);
    memset(&net, 0x5A, sizeof net);
    assert_int_equal(nrt_load(&net, s.b, s.len - 1, ld_mem, sizeof ld_mem), NRT_E_TRUNCATED);
    assert_int_equal(net.n_nodes, 0);
    assert_int_equal(net.n_conns, 0);
    assert_null(net.weight);
    assert_null(net.src);
    assert_null(net.act[0]);
}

/* nrt_crc32 is the standard CRC-32 (check value of "123456789") and can be continued. */
static void test_crc32_check_value(void **state)
{
    static const char digits[] = "123456789";
    uint32_t part;
    (void)state;
    assert_int_equal(nrt_crc32(0, digits, 9), 0xCBF43926u);
    part = nrt_crc32(0, digits, 4);
    assert_int_equal(nrt_crc32(part, digits + 4, 5), 0xCBF43926u);
    assert_int_equal(nrt_crc32(0, digits, 0), 0);
}

/* nrt_crc32 (a table on hosts, bitwise at -Os) gives the bitwise CRC-32 on
 * random data of every length up to 300, continued at random points. */
static void test_crc32_matches_bitwise(void **state)
{
    static uint8_t buf[300];
    uint32_t s = 0x9E3779B9u, len;
    (void)state;
    for (len = 0; len < sizeof buf; len++) {
        uint32_t want = 0xFFFFFFFFu, i, cut;
        int b;
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        buf[len] = (uint8_t)(s >> 24);
        for (i = 0; i < len; i++) {
            want ^= buf[i];
            for (b = 0; b < 8; b++)
                want = (want >> 1) ^ (0xEDB88320u & (0u - (want & 1u)));
        }
        want = ~want;
        cut = len ? s % len : 0;
        assert_int_equal(nrt_crc32(0, buf, len), want);
        assert_int_equal(nrt_crc32(nrt_crc32(0, buf, cut), buf + cut, len - cut), want);
    }
}

/* nrt_strerror has its own non-empty text for every error code -1 .. -12. */
static void test_strerror(void **state)
{
    int e;
    const char *unknown = nrt_strerror(-13);
    (void)state;
    assert_non_null(unknown);
    for (e = NRT_E_ARG; e >= NRT_E_WEIGHT; e--) {
        const char *t = nrt_strerror(e);
        assert_non_null(t);
        assert_true(t[0] != '\0');
        assert_string_not_equal(t, unknown);
    }
    assert_non_null(nrt_strerror(NRT_OK));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_load_ok),
        cmocka_unit_test(test_inspect_sizes),
        cmocka_unit_test(test_every_truncation_rejected),
        cmocka_unit_test(test_every_byte_change_rejected),
        cmocka_unit_test(test_trailing_rejected),
        cmocka_unit_test(test_buffer_size),
        cmocka_unit_test(test_odd_address),
        cmocka_unit_test(test_bad_magic),
        cmocka_unit_test(test_weight_min_rejected),
        cmocka_unit_test(test_bad_version),
        cmocka_unit_test(test_bad_header_fields),
        cmocka_unit_test(test_bad_counts),
        cmocka_unit_test(test_max_nodes_accepted),
        cmocka_unit_test(test_index_out_of_range),
        cmocka_unit_test(test_conn_into_input),
        cmocka_unit_test(test_conns_out_of_order),
        cmocka_unit_test(test_crc_mismatch),
        cmocka_unit_test(test_null_args),
        cmocka_unit_test(test_crc32_check_value),
        cmocka_unit_test(test_crc32_matches_bitwise),
        cmocka_unit_test(test_strerror),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
