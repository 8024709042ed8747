/* duel_experiment.c - `duel_evolve experiment PLAN --out DIR`, `experiment resume DIR` and `experiment report DIR`: the paper's section 6 from one plan. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "duel_cli.h"
#include "duel_html.h"
#include "duel_text.h"
#include "duel_exp.h"
#include "duel_plan.h"

#define DUEL_EXP_USAGE                                                                                                \
    "usage: duel_evolve experiment PLAN --out DIR [--set key=value ...] [--jobs J] [--threads T] [--quiet]\n"        \
    "       duel_evolve experiment PLAN --dry-run [--set key=value ...]\n"                                            \
    "       duel_evolve experiment resume DIR [--jobs J] [--threads T] [--quiet]\n"                                   \
    "       duel_evolve experiment report DIR [--html [--games top|all|none] [--embed] [--force]]"

static int duel_exp_u32(const char *opt, const char *v, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long x;
    errno = 0;
    x = strtoul(v, &end, 10);
    if (*v < '0' || *v > '9' || *end != '\0' || errno || x > hi) {
        fprintf(stderr, "duel_evolve: experiment: %s takes 0 (every core) to %u, not '%s'\n", opt, hi, duel_esc(v));
        return -1;
    }
    *out = (uint32_t)x;
    return 0;
}

static void duel_exp_wrote(void *ud, const char *path, size_t bytes)
{
    (void)path;
    (void)bytes;
    (*(unsigned long *)ud)++;
}

/* The report's web pages in DIR/report/html/ (duel_html_run.c), from inside DIR, where the report left us (it
 * works in its directory, under its lock): the pages name the directory by its absolute path. */
static int duel_exp_report_html(const char *dir, duel_html_report *o)
{
    char here[4096], out[4200], shown[4200], msg[2048];
    unsigned long pages = 0;
    int st;
    if (getcwd(here, sizeof here) == NULL || (size_t)snprintf(out, sizeof out, "%s/report/html", here) >= sizeof out) {
        fprintf(stderr, "duel_evolve: experiment report: %s: name too long\n", duel_esc(dir));
        return 2;
    }
    snprintf(shown, sizeof shown, "%s/report/html", dir);
    o->wrote = duel_exp_wrote;
    o->ud = &pages;
    st = duel_html_experiment_report(here, out, o, msg, sizeof msg);
    if (st != 0) {
        fprintf(stderr, "duel_evolve: experiment report: %s\n", duel_esc_msg(msg));
        return st;
    }
    duel_report_html_say(shown, pages, o);
    return 0;
}

int duel_cmd_experiment(int argc, char **argv)
{
    duel_exp_opts o;
    duel_plan *plan = NULL;
    const char *what, *out = NULL, **sets;
    uint32_t n_sets = 0;
    char err[9000];
    int i, mode, rc, dry = 0, html = 0;
    duel_html_report ho;

    if (argc < 1 || argv[0][0] == '-') {
        /* (--help is answered before the command runs: duel_help.c) */
        fprintf(stderr, "%s\n", DUEL_EXP_USAGE);
        return 2;
    }
    /* mode 0: PLAN --out DIR; 1: resume DIR; 2: report DIR */
    mode = strcmp(argv[0], "resume") == 0 ? 1 : strcmp(argv[0], "report") == 0 ? 2 : 0;
    if (mode != 0 && (argc < 2 || argv[1][0] == '-')) {
        fprintf(stderr, "duel_evolve: experiment %s: which experiment directory? (duel_evolve experiment --help)\n",
                duel_esc(argv[0]));
        return 2;
    }
    what = mode == 0 ? argv[0] : argv[1];
    memset(&o, 0, sizeof o);
    memset(&ho, 0, sizeof ho);
    ho.games = DUEL_HTML_GAMES_TOP;
    sets = (const char **)calloc((size_t)argc + 1, sizeof *sets);
    if (sets == NULL) {
        fprintf(stderr, "duel_evolve: experiment: out of memory\n");
        return 1;
    }
    for (i = mode == 0 ? 1 : 2; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int takes = strcmp(a, "--out") == 0 || strcmp(a, "--set") == 0 || strcmp(a, "--jobs") == 0 ||
                    strcmp(a, "--threads") == 0;
        if (strcmp(a, "--quiet") == 0 && mode != 2) {
            o.quiet = 1;
            continue;
        }
        if (strcmp(a, "--dry-run") == 0 && mode == 0) {
            dry = 1;
            continue;
        }
        if (mode == 2 && strcmp(a, "--html") == 0) {
            html = 1;
            continue;
        }
        if (mode == 2) {
            int r = duel_report_html_option("experiment report", argc, argv, &i, &ho);
            if (r < 0) {
                free(sets);
                return 2;
            }
            if (r > 0)
                continue;
        }
        if (!takes || (mode == 2) || (mode == 1 && (strcmp(a, "--out") == 0 || strcmp(a, "--set") == 0))) {
            fprintf(stderr, "duel_evolve: experiment: unknown option '%s' here (duel_evolve experiment --help)\n", duel_esc(a));
            free(sets);
            return 2;
        }
        if (v == NULL) {
            fprintf(stderr, "duel_evolve: experiment: %s needs a value\n", a);
            free(sets);
            return 2;
        }
        i++;
        if (strcmp(a, "--out") == 0) {
            out = v;
        } else if (strcmp(a, "--set") == 0) {
            sets[n_sets++] = v;
        } else if (duel_exp_u32(a, v, 256, strcmp(a, "--jobs") == 0 ? &o.jobs : &o.threads) != 0) {
            free(sets);
            return 2;
        }
    }
    if (mode == 0 && out == NULL && !dry) {
        fprintf(stderr, "duel_evolve: experiment: where? (--out DIR; duel_evolve experiment --help)\n");
        free(sets);
        return 2;
    }
    if (mode == 0)
        rc = duel_plan_load(&plan, what, sets, n_sets, err, sizeof err);
    else
        rc = duel_plan_load_dir(&plan, what, err, sizeof err);
    free(sets);
    if (rc != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s\n", duel_esc_msg(err));
        duel_plan_free(plan);
        return 2;
    }
    if (dry) {
        duel_plan_print(stdout, plan);
        rc = 0;
    } else if (mode == 2) {
        rc = duel_exp_report(plan, what);
        if (rc == 0 && html)
            rc = duel_exp_report_html(what, &ho);
    }
    else
        rc = duel_exp_run(plan, mode == 0 ? out : what, &o);
    duel_plan_free(plan);
    return rc;
}
