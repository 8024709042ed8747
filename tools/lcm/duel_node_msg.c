/* duel_node_msg.c - duel LCM messages decoded only after their fingerprint and format version are known. */
#include <stdio.h>

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
static int duel_msg_check(const void *data, size_t len, int64_t hash, int32_t version, const char *type, char *msg,
                          size_t msg_len)
{
    const uint8_t *p = (const uint8_t *)data;
    uint64_t got;
    int32_t v;
    if (data == NULL || len < 12 || len > 0x7fffffff) {
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

int duel_msg_decode_sense(const void *data, size_t len, duel_sense_t *m, char *msg, size_t msg_len)
{
    int err = duel_msg_check(data, len, __duel_sense_t_get_hash(), DUEL_SENSE_T_VERSION, "duel.sense_t", msg, msg_len);
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
    if (err)
        return err;
    if (duel_motor_t_decode(data, 0, (int)len, m) != (int)len) {
        snprintf(msg, msg_len, "a %zu-byte duel.motor_t that does not decode", len);
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
    if (err)
        return err;
    if (duel_state_t_decode(data, 0, (int)len, m) != (int)len) {
        snprintf(msg, msg_len, "a %zu-byte duel.state_t that does not decode", len);
        return DUEL_NODE_E_MALFORMED;
    }
    return DUEL_NODE_OK;
}
