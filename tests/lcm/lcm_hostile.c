/* lcm_hostile.c - the tests' hostile LCM peer: writes crafted messages as one-event logs, or publishes them on a bus. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <lcm/lcm.h>

#include "hostile_msgs.h"

static void lh_usage(void)
{
    fprintf(stderr, "usage: lcm_hostile list\n"
                    "       lcm_hostile log NAME OUT.lcm\n"
                    "       lcm_hostile publish URL SECONDS   (every crafted message, every 5 ms, on its channel)\n");
}

static double lh_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec / 1e9;
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
