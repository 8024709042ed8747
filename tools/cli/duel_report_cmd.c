/* duel_report_cmd.c - `duel_evolve report RUN --html DIR`: a run's web page (its curves and dominance ladder, each level's games as duel pages); the HTML options experiment report shares. */
#include <stdio.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_html.h"
#include "duel_text.h"

static void duel_report_wrote(void *ud, const char *path, size_t bytes)
{
    unsigned long *n = (unsigned long *)ud;
    (void)path;
    (void)bytes;
    (*n)++;
}

int duel_report_html_option(const char *cmd, int argc, char **argv, int *i, duel_html_report *o)
{
    const char *a = argv[*i];
    if (strcmp(a, "--embed") == 0) {
        o->embed = 1;
        return 1;
    }
    if (strcmp(a, "--force") == 0) {
        o->force = 1;
        return 1;
    }
    if (strcmp(a, "--games") == 0) {
        const char *v = *i + 1 < argc ? argv[*i + 1] : NULL;
        if (v == NULL) {
            fprintf(stderr, "duel_evolve: %s: --games needs a value (all, top or none)\n", cmd);
            return -1;
        }
        (*i)++;
        if (strcmp(v, "all") == 0)
            o->games = DUEL_HTML_GAMES_ALL;
        else if (strcmp(v, "top") == 0)
            o->games = DUEL_HTML_GAMES_TOP;
        else if (strcmp(v, "none") == 0)
            o->games = DUEL_HTML_GAMES_NONE;
        else {
            fprintf(stderr, "duel_evolve: %s: --games takes all, top or none, not '%s'\n", cmd, duel_esc(v));
            return -1;
        }
        return 1;
    }
    return 0;
}

/* The line both commands end with: where the pages are and how many. */
void duel_report_html_say(const char *out, unsigned long pages, const duel_html_report *o)
{
    char esc[1100];
    printf("%lu page%s in %s (%s)\n", pages, pages == 1 ? "" : "s", duel_text_escape(out, esc, sizeof esc),
           o->embed ? "games embedded" : o->games == DUEL_HTML_GAMES_NONE ? "no games" : "games in games/");
}

int duel_cmd_report(int argc, char **argv)
{
    const char *run = NULL, *out = NULL;
    duel_html_report o;
    unsigned long pages = 0;
    char msg[2048], esc[1100];
    int i, st;

    memset(&o, 0, sizeof o);
    for (i = 0; i < argc; i++) {
        int r;
        if (argv[i][0] != '-') {
            if (run != NULL) {
                fprintf(stderr, "duel_evolve: report: one run directory at a time ('%s' is another)\n", duel_esc(argv[i]));
                return 2;
            }
            run = argv[i];
            continue;
        }
        if (strcmp(argv[i], "--html") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "duel_evolve: report: --html needs a directory\n");
                return 2;
            }
            out = argv[++i];
            continue;
        }
        r = duel_report_html_option("report", argc, argv, &i, &o);
        if (r < 0)
            return 2;
        if (r == 0) {
            fprintf(stderr, "duel_evolve: report: unknown option '%s' (duel_evolve report --help)\n", duel_esc(argv[i]));
            return 2;
        }
    }
    if (run == NULL || out == NULL) {
        fprintf(stderr, "usage: duel_evolve report RUN --html DIR [--games all|top|none] [--embed] [--force]\n");
        return 2;
    }
    o.wrote = duel_report_wrote;
    o.ud = &pages;
    st = duel_html_run_report(run, out, &o, msg, sizeof msg);
    if (st != 0) {
        fprintf(stderr, "duel_evolve: report: %s\n", duel_esc_msg(msg));
        return st;
    }
    duel_report_html_say(out, pages, &o);
    printf("open %s/index.html\n", duel_text_escape(out, esc, sizeof esc));
    return 0;
}
