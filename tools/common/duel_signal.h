/* duel_signal.h - Ctrl-C and SIGTERM for the long commands: the first asks for a clean stop, a later second one stops at once. */
#ifndef DUEL_SIGNAL_H
#define DUEL_SIGNAL_H

#include <signal.h>

/* Installs the handler for SIGINT and SIGTERM. The first signal sets *stop
 * (the command finishes what it must and exits cleanly). The same signal
 * delivered twice at once (`timeout` sends it to the process and to its
 * group; a terminal's Ctrl-C reaches every process of the job) counts once:
 * a second signal within a second of the first is ignored. One later than
 * that prints `second` on stderr and ends the process at once by the
 * signal (exit status 128 + the signal's number). */
void duel_signal_install(volatile sig_atomic_t *stop, const char *second);

#endif /* DUEL_SIGNAL_H */
