/* duel_node_msg.c - duel LCM messages decoded only after their fingerprint, format version, size and every string length are checked. */
#include <stdio.h>
#include <string.h>

#include "duel_node.h"

/* The big-endian 64-bit fingerprint or 32-bit integer at data[off]. */
static uint64_t duel_msg_be64(const uint8_t *p)
{
    uint64_t v = 0;
    int i;
    for (i = 0; i < 8; i++)
        v = (v << 8) | p[i];
    return v;
}

static int32_t duel_msg_be32(const uint8_t *p)
{
    uint32_t v = ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
    return (int32_t)v;
}

/* Fingerprint, then the version field that every duel message has first. */
int duel_msg_check(const void *data, size_t len, int64_t hash, int32_t version, const char *type, char *msg,
                          size_t msg_len)
{
    const uint8_t *p = (const uint8_t *)data;
    uint64_t got;
    int32_t v;
    if (data == NULL || len < 12) {
        snprintf(msg, msg_len, "a %zu-byte message, too short for %s", len, type);
        return DUEL_NODE_E_MALFORMED;
    }
    got = duel_msg_be64(p);
    if (got != (uint64_t)hash) {
        snprintf(msg, msg_len, "LCM fingerprint 0x%016llx is not %s's 0x%016llx (another type, or another layout of it)",
                 (unsigned long long)got, type, (unsigned long long)(uint64_t)hash);
        return DUEL_NODE_E_FINGERPRINT;
    }
    v = duel_msg_be32(p + 8);
    if (v != version) {
        snprintf(msg, msg_len, "%s format version %ld, this reader knows only version %ld", type, (long)v,
                 (long)version);
        return DUEL_NODE_E_VERSION;
    }
    return DUEL_NODE_OK;
}

/* The generated decoder allocates and copies whatever length a string
 * claims, so the layout is walked here first: `head` fixed bytes (the
 * fingerprint included), then n_strings strings (an int32 length counting
 * the NUL, 1..DUEL_NODE_NAME_MAX + 1, and that many bytes ending in a NUL),
 * then exactly `tail` fixed bytes. Only a message that passes reaches the
 * decoder, which then cannot fail or over-allocate. */
static int duel_msg_layout(const uint8_t *p, size_t len, size_t head, int n_strings, size_t tail, const char *type,
                           char *msg, size_t msg_len)
{
    size_t off = head;
    int i;
    if (len > DUEL_MSG_MAX) {
        snprintf(msg, msg_len, "a %zu-byte %s, larger than any duel message (%u bytes at most)", len, type,
                 (unsigned)DUEL_MSG_MAX);
        return DUEL_NODE_E_MALFORMED;
    }
    if (len < head) {
        snprintf(msg, msg_len, "a %zu-byte %s, shorter than its %zu fixed bytes before the strings", len, type, head);
        return DUEL_NODE_E_MALFORMED;
    }
    for (i = 0; i < n_strings; i++) {
        int32_t n;
        if (len - off < 4) {
            snprintf(msg, msg_len, "a %zu-byte %s that ends inside string %d's length", len, type, i);
            return DUEL_NODE_E_MALFORMED;
        }
        n = duel_msg_be32(p + off);
        off += 4;
        if (n < 1 || n > DUEL_NODE_NAME_MAX + 1 || (size_t)n > len - off) {
            snprintf(msg, msg_len, "%s string %d claims %ld bytes (1 to %d, and at most the %zu left)", type, i,
                     (long)n, DUEL_NODE_NAME_MAX + 1, len - off);
            return DUEL_NODE_E_MALFORMED;
        }
        if (p[off + (size_t)n - 1] != 0 || memchr(p + off, 0, (size_t)n - 1) != NULL) {
            snprintf(msg, msg_len, "%s string %d is not %ld bytes ending in its only NUL", type, i, (long)n);
            return DUEL_NODE_E_MALFORMED;
        }
        off += (size_t)n;
    }
    if (len - off != tail) {
        if (n_strings == 0)
            snprintf(msg, msg_len, "a %zu-byte %s, which has %zu bytes", len, type, tail);
        else
            snprintf(msg, msg_len, "a %zu-byte %s: %zu bytes where its layout has %zu after the strings", len, type,
                     len - off, tail);
        return DUEL_NODE_E_MALFORMED;
    }
    return DUEL_NODE_OK;
}

int duel_msg_decode_sense(const void *data, size_t len, duel_sense_t *m, char *msg, size_t msg_len)
{
    int err = duel_msg_check(data, len, __duel_sense_t_get_hash(), DUEL_SENSE_T_VERSION, "duel.sense_t", msg, msg_len);
    if (!err)
        err = duel_msg_layout((const uint8_t *)data, len, 0, 0, DUEL_MSG_SENSE_SIZE, "duel.sense_t", msg, msg_len);
    if (err)
        return err;
    if (duel_sense_t_decode(data, 0, (int)len, m) != (int)len) {
        snprintf(msg, msg_len, "a %zu-byte duel.sense_t that does not decode", len);
        return DUEL_NODE_E_MALFORMED;
    }
    if (m->side != 0 && m->side != 1) {
        snprintf(msg, msg_len, "duel.sense_t with side %d (0 west, 1 east)", m->side);
        return DUEL_NODE_E_MALFORMED;
    }
    return DUEL_NODE_OK;
}

int duel_msg_decode_motor(const void *data, size_t len, duel_motor_t *m, char *msg, size_t msg_len)
{
    int err = duel_msg_check(data, len, __duel_motor_t_get_hash(), DUEL_MOTOR_T_VERSION, "duel.motor_t", msg, msg_len);
    if (!err)
        err = duel_msg_layout((const uint8_t *)data, len, DUEL_MSG_MOTOR_HEAD, 1, 0, "duel.motor_t", msg, msg_len);
    if (err)
        return err;
    memset(m, 0, sizeof *m); /* what a failed decode allocated can be freed */
    if (duel_motor_t_decode(data, 0, (int)len, m) != (int)len) {
        snprintf(msg, msg_len, "a %zu-byte duel.motor_t that does not decode", len);
        duel_motor_t_decode_cleanup(m);
        return DUEL_NODE_E_MALFORMED;
    }
    if (m->side != 0 && m->side != 1) {
        snprintf(msg, msg_len, "duel.motor_t with side %d (0 west, 1 east)", m->side);
        duel_motor_t_decode_cleanup(m);
        return DUEL_NODE_E_MALFORMED;
    }
    return DUEL_NODE_OK;
}

int duel_msg_decode_state(const void *data, size_t len, duel_state_t *m, char *msg, size_t msg_len)
{
    int err = duel_msg_check(data, len, __duel_state_t_get_hash(), DUEL_STATE_T_VERSION, "duel.state_t", msg, msg_len);
    if (!err)
        err = duel_msg_layout((const uint8_t *)data, len, DUEL_MSG_STATE_HEAD, 2, DUEL_MSG_STATE_TAIL,
                              "duel.state_t", msg, msg_len);
    if (err)
        return err;
    memset(m, 0, sizeof *m);
    if (duel_state_t_decode(data, 0, (int)len, m) != (int)len) {
        snprintf(msg, msg_len, "a %zu-byte duel.state_t that does not decode", len);
        duel_state_t_decode_cleanup(m);
        return DUEL_NODE_E_MALFORMED;
    }
    return DUEL_NODE_OK;
}


int duel_msg_decode_net(const void *data, size_t len, duel_net_t *m, char *msg, size_t msg_len)
{
    int err = duel_msg_check(data, len, __duel_net_t_get_hash(), DUEL_NET_T_VERSION, "duel.net_t", msg, msg_len);
    if (!err)
        err = duel_msg_layout((const uint8_t *)data, len, DUEL_MSG_NET_HEAD, 1, 0, "duel.net_t", msg, msg_len);
    if (err)
        return err;
    memset(m, 0, sizeof *m);
    if (duel_net_t_decode(data, 0, (int)len, m) != (int)len) {
        snprintf(msg, msg_len, "a %zu-byte duel.net_t that does not decode", len);
        duel_net_t_decode_cleanup(m);
        return DUEL_NODE_E_MALFORMED;
    }
    if ((m->side != 0 && m->side != 1) || m->step < DUEL_NET_T_BUILTIN || m->step > DUEL_NET_T_PROPAGATE) {
        snprintf(msg, msg_len, "duel.net_t with side %d (0 west, 1 east), step %d (-1 builtin, 0 sync, 1 propagate)",
                 m->side, m->step);
        duel_net_t_decode_cleanup(m);
        return DUEL_NODE_E_MALFORMED;
    }
    return DUEL_NODE_OK;
}
