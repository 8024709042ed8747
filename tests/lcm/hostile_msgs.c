/* hostile_msgs.c - crafted duel LCM messages that lie about their string lengths or sizes, for the decoder, log and node tests. */
#include <stdio.h>
#include <string.h>

#include "duel_motor_t.h"
#include "duel_net_t.h"
#include "duel_sense_t.h"
#include "duel_state_t.h"
#include "hostile_msgs.h"

typedef struct hm_buf {
    uint8_t *p;
    size_t n, cap;
} hm_buf;

static void hm_u8(hm_buf *b, uint32_t v)
{
    if (b->n < b->cap)
        b->p[b->n] = (uint8_t)v;
    b->n++;
}

static void hm_be32(hm_buf *b, uint32_t v)
{
    hm_u8(b, v >> 24);
    hm_u8(b, (v >> 16) & 0xff);
    hm_u8(b, (v >> 8) & 0xff);
    hm_u8(b, v & 0xff);
}

static void hm_be64(hm_buf *b, uint64_t v)
{
    hm_be32(b, (uint32_t)(v >> 32));
    hm_be32(b, (uint32_t)v);
}

static void hm_zeros(hm_buf *b, size_t n)
{
    while (n--)
        hm_u8(b, 0);
}

/* A string field: the claimed length, then the bytes given (which need not agree). */
static void hm_string(hm_buf *b, int32_t claimed, const char *bytes, size_t n)
{
    size_t i;
    hm_be32(b, (uint32_t)claimed);
    for (i = 0; i < n; i++)
        hm_u8(b, (uint8_t)bytes[i]);
}

/* motor_t up to its string: fingerprint, version 1, side, step, output[3], value[3] */
static void hm_motor_head(hm_buf *b, int side, int32_t step)
{
    hm_be64(b, (uint64_t)__duel_motor_t_get_hash());
    hm_be32(b, DUEL_MOTOR_T_VERSION);
    hm_u8(b, (uint32_t)side);
    hm_be32(b, (uint32_t)step);
    hm_zeros(b, 6 + 24);
}

/* state_t up to its strings: fingerprint, version 1, step 0, food_config -1 */
static void hm_state_head(hm_buf *b)
{
    hm_be64(b, (uint64_t)__duel_state_t_get_hash());
    hm_be32(b, DUEL_STATE_T_VERSION);
    hm_be32(b, 0);
    hm_be32(b, 0xffffffffu);
}

/* net_t up to its string: fingerprint, version 1, side, step */
static void hm_net_head(hm_buf *b, int side, int step)
{
    hm_be64(b, (uint64_t)__duel_net_t_get_hash());
    hm_be32(b, DUEL_NET_T_VERSION);
    hm_u8(b, (uint32_t)side);
    hm_u8(b, (uint32_t)(uint8_t)step);
}

int hostile_count(void)
{
    return 15;
}

int hostile_get(int i, hostile_msg *m)
{
    hm_buf b;
    size_t k;
    memset(m, 0, sizeof *m);
    b.p = m->data;
    b.n = 0;
    b.cap = sizeof m->data;
    switch (i) {
    case 0: /* a hello whose name claims -5 bytes: 51 bytes, 94 as a log */
        m->name = "motor-negative";
        m->channel = "DUEL_MOTOR_EAST";
        hm_motor_head(&b, 1, -1);
        hm_string(&b, -5, NULL, 0);
        break;
    case 1: /* the state's first name claims -1 bytes: 24 bytes, 62 as a log */
        m->name = "state-negative";
        m->channel = "DUEL_STATE";
        hm_state_head(&b);
        hm_string(&b, -1, NULL, 0);
        break;
    case 2: /* a name of 3 bytes without its NUL, then nothing */
        m->name = "motor-no-nul";
        m->channel = "DUEL_MOTOR_WEST";
        hm_motor_head(&b, 0, -1);
        hm_string(&b, 3, "abc", 3);
        break;
    case 3: /* a name that claims 2 GB */
        m->name = "motor-huge";
        m->channel = "DUEL_MOTOR_EAST";
        hm_motor_head(&b, 1, -1);
        hm_string(&b, 0x7ffffff0, "abc", 3);
        break;
    case 4: /* a state whose second name claims 100 MB */
        m->name = "state-huge";
        m->channel = "DUEL_STATE";
        hm_state_head(&b);
        hm_string(&b, 2, "w", 2);
        hm_string(&b, 100000000, "e", 2);
        break;
    case 5: /* a name of 300 bytes: longer than any node sends */
        m->name = "motor-long-name";
        m->channel = "DUEL_MOTOR_WEST";
        hm_motor_head(&b, 0, -1);
        hm_be32(&b, 301);
        for (k = 0; k < 300; k++)
            hm_u8(&b, 'x');
        hm_u8(&b, 0);
        break;
    case 6: /* a zero-length name (not even its NUL) */
        m->name = "motor-zero";
        m->channel = "DUEL_MOTOR_WEST";
        hm_motor_head(&b, 0, -1);
        hm_string(&b, 0, NULL, 0);
        break;
    case 7: /* a state with both names fine and its tail cut */
        m->name = "state-short-tail";
        m->channel = "DUEL_STATE";
        hm_state_head(&b);
        hm_string(&b, 2, "w", 2);
        hm_string(&b, 2, "e", 2);
        hm_zeros(&b, 100);
        break;
    case 8: /* a sensor message with bytes to spare */
        m->name = "sense-long";
        m->channel = "DUEL_SENSE_WEST";
        hm_be64(&b, (uint64_t)__duel_sense_t_get_hash());
        hm_be32(&b, DUEL_SENSE_T_VERSION);
        hm_zeros(&b, 1 + 4 + 26 + 104 + 500);
        break;
    case 9: /* a name with a NUL inside */
        m->name = "motor-inner-nul";
        m->channel = "DUEL_MOTOR_EAST";
        hm_motor_head(&b, 1, -1);
        hm_string(&b, 4, "a\0b", 4);
        break;
    case 10: /* a message far larger than any duel message */
        m->name = "state-oversize";
        m->channel = "DUEL_STATE";
        hm_state_head(&b);
        hm_string(&b, 2, "w", 2);
        hm_string(&b, 2, "e", 2);
        hm_zeros(&b, 1000);
        break;
    case 11: /* a state message that ends before its names begin (found by fuzz_lcm_log) */
        m->name = "state-cut-head";
        m->channel = "DUEL_STATE";
        hm_state_head(&b);
        b.n -= 5;
        break;
    case 12: /* a motor message that ends inside its outputs */
        m->name = "motor-cut-head";
        m->channel = "DUEL_MOTOR_WEST";
        hm_motor_head(&b, 0, 4);
        b.n -= 20;
        break;
    case 13: /* what plays a side, its name claiming -5 bytes */
        m->name = "net-negative";
        m->channel = "DUEL_NET";
        hm_net_head(&b, 0, 0);
        hm_string(&b, -5, NULL, 0);
        break;
    case 14: /* a step mode that does not exist (a recorded game would say it) */
        m->name = "net-bad-step";
        m->channel = "DUEL_NET";
        hm_net_head(&b, 1, 7);
        hm_string(&b, 2, "x", 2);
        break;
    default:
        return -1;
    }
    if (b.n > b.cap)
        return -1;
    m->len = b.n;
    return 0;
}

int hostile_find(const char *name, hostile_msg *m)
{
    int i;
    for (i = 0; i < hostile_count(); i++)
        if (hostile_get(i, m) == 0 && strcmp(m->name, name) == 0)
            return 0;
    return -1;
}

int hostile_write_log(const hostile_msg *m, const char *path)
{
    uint8_t h[28];
    hm_buf b;
    size_t clen = strlen(m->channel);
    FILE *f = fopen(path, "wb");
    int ok;
    if (f == NULL)
        return -1;
    b.p = h;
    b.n = 0;
    b.cap = sizeof h;
    hm_be32(&b, 0xEDA1DA01u); /* sync word */
    hm_be64(&b, 0);           /* event number */
    hm_be64(&b, 1000000);     /* microseconds */
    hm_be32(&b, (uint32_t)clen);
    hm_be32(&b, (uint32_t)m->len);
    ok = fwrite(h, 1, sizeof h, f) == sizeof h && fwrite(m->channel, 1, clen, f) == clen &&
         fwrite(m->data, 1, m->len, f) == m->len;
    return fclose(f) == 0 && ok ? 0 : -1;
}
