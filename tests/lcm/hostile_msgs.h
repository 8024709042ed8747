/* hostile_msgs.h - crafted duel LCM messages that lie about their string lengths or sizes, for the decoder, log and node tests. */
#ifndef HOSTILE_MSGS_H
#define HOSTILE_MSGS_H

#include <stddef.h>
#include <stdint.h>

typedef struct hostile_msg {
    const char *name;    /* what is wrong, as the tests name it */
    const char *channel; /* where a node would receive it */
    uint8_t data[1200];
    size_t len;
} hostile_msg;

/* The i-th crafted message (0 <= i < hostile_count()): 0 if there is one. */
int hostile_get(int i, hostile_msg *m);
int hostile_count(void);
/* The message named name, or -1. */
int hostile_find(const char *name, hostile_msg *m);
/* One LCM event log holding m alone (event 0, channel m->channel) at path: 0 or -1. */
int hostile_write_log(const hostile_msg *m, const char *path);

#endif /* HOSTILE_MSGS_H */
