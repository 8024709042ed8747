/* duel_cli.h - what the duel_evolve subcommands share: controllers from blob files or builtin names, traces. */
#ifndef DUEL_CLI_H
#define DUEL_CLI_H

#include <stdio.h>

#include "duel.h"

/* A controller named on the command line: a blob file or builtin:NAME. */
typedef struct duel_cli_ctrl {
    duel_controller ctrl;
    nrt_net net;
    void *mem;
    uint8_t *blob;
    size_t blob_len;
    char name[256];
} duel_cli_ctrl;

/* Reads the whole file at path into a malloc'd *blob (the caller frees it)
 * of *len bytes, not validated; on error prints one line naming the file and
 * the problem to stderr and returns -1 (*blob NULL). */
int duel_cli_read_blob(const char *path, uint8_t **blob, size_t *len);

/* Loads spec into c; on error prints one line naming the problem to stderr
 * and returns -1. */
int duel_cli_ctrl_open(duel_cli_ctrl *c, const char *spec);
void duel_cli_ctrl_close(duel_cli_ctrl *c);

/* The CSV trace of docs/duelsim.md: header, then one row per step. */
void duel_trace_header(FILE *f);
void duel_trace_row(void *file, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                    const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev);

/* The `dot` command's Graphviz picture of the champion blob at path, written
 * to f (tools/duel_inspect.c). 0, or -1 after one line on stderr naming the
 * file and the problem (unreadable or invalid blob, out of memory). */
int duel_dot_blob(FILE *f, const char *path);

int duel_cmd_play(int argc, char **argv);
int duel_cmd_run(int argc, char **argv);
int duel_cmd_resume(int argc, char **argv);
int duel_cmd_config(int argc, char **argv);
int duel_cmd_ladder(int argc, char **argv);
int duel_cmd_inspect(int argc, char **argv);
int duel_cmd_dot(int argc, char **argv);
int duel_cmd_node(int argc, char **argv);
int duel_cmd_log(int argc, char **argv);
int duel_cmd_render(int argc, char **argv);
int duel_cmd_render_net(int argc, char **argv);
int duel_cmd_export(int argc, char **argv);

#endif /* DUEL_CLI_H */
