/* duel_cli.h - the duel_evolve subcommands, one entry point each (dispatched by duel_evolve.c), and the dot writer render-net shares. */
/* tools/cli/: the duel_evolve command: the dispatcher and one file per subcommand (their entry points in duel_cli.h). */
#ifndef DUEL_CLI_H
#define DUEL_CLI_H

#include <stdio.h>

#include "duel_config.h"
#include "neat_coev.h"

/* The whole duel_evolve command (duel_evolve.c): argv[1] the subcommand; the process's exit status.
 * duel_main.c is duel_evolve's main; a program that is duel_evolve with a hook of its own calls it too
 * (tools/neatcpp/neatcpp_duel.cpp). */
int duel_evolve_main(int argc, char **argv);

/* Another NEAT's reproduction for its runs: duel_engine_set_reproducer (tools/run/duel_engine.h). */

/* What the `dot` picture leaves out: connections whose |weight| is below
 * min_weight (0: none left out). */
typedef struct duel_dot_opts {
    double min_weight;
} duel_dot_opts;
/* "--min-weight W" (0 <= W <= 8, the largest Q3.12 magnitude) into o. 0, or
 * -1 after one line on stderr naming cmd. */
int duel_dot_parse_min_weight(const char *cmd, const char *v, duel_dot_opts *o);
/* The `dot` command's Graphviz picture of the champion blob at path, written
 * to f (tools/cli/duel_inspect.c). 0, or -1 after one line on stderr naming the
 * file and the problem (unreadable or invalid blob, out of memory). */
int duel_dot_blob(FILE *f, const char *path, const duel_dot_opts *o);
/* `duel_evolve COMMAND --help` (duel_help.c): whether argv holds --help or
 * -h; COMMAND's synopsis and options on f (0, or -1: no such command). */
int duel_help_wanted(int argc, char **argv);
int duel_help(const char *command, FILE *f);
/* An option given last, without its value: "needs a value" if it is one of
 * takes_value (NULL-terminated), "unknown option" otherwise. Returns 2. */
int duel_cli_missing_value(const char *command, const char *opt, const char *const *takes_value);

/* `inspect` on a run directory or its checkpoint (tools/cli/duel_inspect_run.c): 0, or 2 after one line. */
int duel_inspect_run(const char *path);

int duel_cmd_play(int argc, char **argv);
int duel_cmd_run(int argc, char **argv);
int duel_cmd_resume(int argc, char **argv);
int duel_cmd_config(int argc, char **argv);
int duel_cmd_ladder(int argc, char **argv);
int duel_cmd_compare(int argc, char **argv);
int duel_cmd_experiment(int argc, char **argv);
int duel_cmd_inspect(int argc, char **argv);
int duel_cmd_dot(int argc, char **argv);
int duel_cmd_node(int argc, char **argv);
int duel_cmd_log(int argc, char **argv);
int duel_cmd_render(int argc, char **argv);
int duel_cmd_render_net(int argc, char **argv);
int duel_cmd_export(int argc, char **argv);
int duel_cmd_report(int argc, char **argv);

struct duel_html_report;
/* The web pages' options (--games all|top|none, --embed, --force) at argv[*i]: 1 taken (and *i past its value),
 * 0 not one of them, -1 after one line (a bad value). report and experiment report share them. */
int duel_report_html_option(const char *cmd, int argc, char **argv, int *i, struct duel_html_report *o);
/* "N pages in DIR (...)" */
void duel_report_html_say(const char *out, unsigned long pages, const struct duel_html_report *o);

#endif /* DUEL_CLI_H */
