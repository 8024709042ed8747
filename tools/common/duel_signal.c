/* duel_signal.c - Ctrl-C and SIGTERM: a clean stop on the first, duplicates of it ignored, an immediate stop on a later second. */
#define _POSIX_C_SOURCE 200809L
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "duel_signal.h"

static volatile sig_atomic_t *duel_sig_stop;
static const char *duel_sig_second;
static struct timespec duel_sig_first;

/* Only async-signal-safe calls here: clock_gettime, write, signal, raise. */
static void duel_sig_handler(int sig)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (!*duel_sig_stop) {
        *duel_sig_stop = 1;
        duel_sig_first = now;
        return;
    }
    if (now.tv_sec - duel_sig_first.tv_sec < 1 ||
        (now.tv_sec - duel_sig_first.tv_sec == 1 && now.tv_nsec < duel_sig_first.tv_nsec))
        return; /* the first signal again, delivered twice */
    if (write(2, duel_sig_second, strlen(duel_sig_second)) < 0) {
        /* nothing to be done about it here */
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

void duel_signal_install(volatile sig_atomic_t *stop, const char *second)
{
    struct sigaction sa;
    duel_sig_stop = stop;
    duel_sig_second = second;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = duel_sig_handler;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}
