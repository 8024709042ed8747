/* lcm_hostile.c - the tests' hostile LCM peer: writes crafted messages as one-event logs, or publishes them on a bus. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <lcm/lcm.h>

#include "duel_motor_t.h"
#include "duel_sense_t.h"
#include "duel_state_t.h"
#include "hostile_msgs.h"

static void lh_usage(void)
{
    fprintf(stderr, "usage: lcm_hostile list\n"
                    "       lcm_hostile log NAME OUT.lcm\n"
                    "       lcm_hostile publish URL SECONDS   (every crafted message, every 5 ms, on its channel)\n"
                    "       lcm_hostile corpus DIR   (fuzz_lcm_msg seeds: a channel byte, then a message)\n");
}

static double lh_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec / 1e9;
}

/* The channel's index in fuzz_lcm_msg's table (state, sense west, sense east, motor west, motor east). */
static int lh_channel_index(const char *channel)
{
    static const char *const names[] = {"DUEL_STATE", "DUEL_SENSE_WEST", "DUEL_SENSE_EAST", "DUEL_MOTOR_WEST",
                                        "DUEL_MOTOR_EAST"};
    int i;
    for (i = 0; i < 5; i++)
        if (strcmp(names[i], channel) == 0)
            return i;
    return 0;
}

static int lh_seed(const char *dir, const char *name, int channel, const uint8_t *msg, size_t len)
{
    char path[1024];
    FILE *f;
    uint8_t c = (uint8_t)channel;
    int ok;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    if (f == NULL)
        return -1;
    ok = fwrite(&c, 1, 1, f) == 1 && fwrite(msg, 1, len, f) == len;
    return fclose(f) == 0 && ok ? 0 : -1;
}

/* Seeds: every crafted message, and one valid message of each type. */
static int hostile_corpus(const char *dir)
{
    hostile_msg m;
    uint8_t buf[1024];
    duel_sense_t s;
    duel_motor_t mo;
    duel_state_t st;
    char *names[2] = {(char *)"west", (char *)"east"};
    char name[64];
    int i, n, err = 0;
    for (i = 0; i < hostile_count(); i++) {
        if (hostile_get(i, &m) != 0)
            return -1;
        snprintf(name, sizeof name, "%s.bin", m.name);
        err |= lh_seed(dir, name, lh_channel_index(m.channel), m.data, m.len);
    }
    memset(&s, 0, sizeof s);
    s.version = DUEL_SENSE_T_VERSION;
    s.step = 3;
    for (i = 0; i < 13; i++)
        s.input[i] = (int16_t)(i * 1000);
    n = duel_sense_t_encode(buf, 0, (int)sizeof buf, &s);
    err |= n < 0 || lh_seed(dir, "sense-west.bin", 1, buf, (size_t)n);
    memset(&mo, 0, sizeof mo);
    mo.version = DUEL_MOTOR_T_VERSION;
    mo.side = 1;
    mo.step = -1;
    mo.controller = names[1];
    n = duel_motor_t_encode(buf, 0, (int)sizeof buf, &mo);
    err |= n < 0 || lh_seed(dir, "motor-east-hello.bin", 4, buf, (size_t)n);
    memset(&st, 0, sizeof st);
    st.version = DUEL_STATE_T_VERSION;
    st.food_config = -1;
    st.controller[0] = names[0];
    st.controller[1] = names[1];
    st.n_food = 9;
    st.outcome = DUEL_STATE_T_WEST_WINS;
    n = duel_state_t_encode(buf, 0, (int)sizeof buf, &st);
    err |= n < 0 || lh_seed(dir, "state-over.bin", 0, buf, (size_t)n);
    return err ? -1 : 0;
}

int main(int argc, char **argv)
{
    hostile_msg m;
    int i;
    if (argc == 2 && strcmp(argv[1], "list") == 0) {
        for (i = 0; i < hostile_count(); i++)
            if (hostile_get(i, &m) == 0)
                printf("%s %s %zu\n", m.name, m.channel, m.len);
        return 0;
    }
    if (argc == 4 && strcmp(argv[1], "log") == 0) {
        if (hostile_find(argv[2], &m) != 0) {
            fprintf(stderr, "lcm_hostile: no message '%s' (lcm_hostile list)\n", argv[2]);
            return 2;
        }
        if (hostile_write_log(&m, argv[3]) != 0) {
            fprintf(stderr, "lcm_hostile: %s: cannot write\n", argv[3]);
            return 1;
        }
        return 0;
    }
    if (argc == 3 && strcmp(argv[1], "corpus") == 0)
        return hostile_corpus(argv[2]) == 0 ? 0 : 1;
    if (argc == 4 && strcmp(argv[1], "publish") == 0) {
        double end = lh_now() + atof(argv[3]);
        unsigned long sent = 0;
        lcm_t *lcm = lcm_create(argv[2]);
        struct timespec pause = {0, 5000000};
        if (lcm == NULL) {
            fprintf(stderr, "lcm_hostile: cannot open %s\n", argv[2]);
            return 1;
        }
        while (lh_now() < end) {
            for (i = 0; i < hostile_count(); i++)
                if (hostile_get(i, &m) == 0 && lcm_publish(lcm, m.channel, m.data, (unsigned)m.len) == 0)
                    sent++;
            nanosleep(&pause, NULL);
        }
        lcm_destroy(lcm);
        printf("published %lu crafted messages\n", sent);
        return 0;
    }
    lh_usage();
    return 2;
}
