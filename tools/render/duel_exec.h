/* duel_exec.h - running the external programs the tools hand work to (ffmpeg, Graphviz dot): PATH lookup, a run with its stderr kept. */
#ifndef DUEL_EXEC_H
#define DUEL_EXEC_H

#include <stddef.h>

/* Finds the executable name on PATH (empty entries: the current directory;
 * PATH unset: /usr/local/bin:/usr/bin:/bin) and writes its path to buf.
 * 0, or -1 when there is none. */
int duel_exec_find(const char *name, char *buf, size_t len);

/* Runs the program at path with argv (argv[0] its name, NULL-terminated),
 * stdin and stdout on /dev/null, and waits for it. Returns its exit status
 * (0..255), or -1 when it could not be started or died of a signal; msg gets
 * the last non-empty line it wrote on stderr, or how it failed. */
int duel_exec_run(const char *path, char *const argv[], char *msg, size_t msg_len);

#endif /* DUEL_EXEC_H */
