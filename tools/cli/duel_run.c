/* duel_run.c - duel_evolve run and resume: their options, given to the run engine (tools/run/), which does the run; duel_run_show.c shows it. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_config.h"
#include "duel_run_show.h"
#include "duel_text.h"

static int duel_parse_u32(const char *opt, const char *v, uint32_t lo, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long long x;
    errno = 0;
    x = v != NULL ? strtoull(v, &end, 10) : 0;
    if (v == NULL || end == v || *end != '\0' || errno != 0 || x < lo || x > hi || v[0] == '-') {
        fprintf(stderr, "duel_evolve: %s takes an integer in [%u, %u], not '%s'\n", opt, lo, hi, duel_esc(v));
        return -1;
    }
    *out = (uint32_t)x;
    return 0;
}

/* The options run and resume share: --generations, --threads, --quiet,
 * --json, --record-champion-games. 1 when argv[*i] was one (and *i is past
 * its value), 0 when it is not, -1 after a message on a bad value. */
static int duel_common_option(duel_show *S, duel_engine_options *o, int argc, char **argv, int *i)
{
    const char *a = argv[*i], *v = *i + 1 < argc ? argv[*i + 1] : NULL;
    if (strcmp(a, "--generations") == 0) {
        if (duel_parse_u32(a, v, 1, 1000000, &o->generations))
            return -1;
        ++*i;
    } else if (strcmp(a, "--threads") == 0) {
        if (duel_parse_u32(a, v, 0, 256, &o->threads))
            return -1;
        ++*i;
    } else if (strcmp(a, "--quiet") == 0) {
        S->quiet = 1;
    } else if (strcmp(a, "--json") == 0) {
        S->json = 1;
    } else if (strcmp(a, "--record-champion-games") == 0) {
        o->record_games = 1;
    } else {
        return 0;
    }
    return 1;
}

int duel_cmd_run(int argc, char **argv)
{
    duel_show S;
    duel_engine_options o;
    duel_config cfg;
    const char *config = NULL, *dir = NULL;
    char err[600], *sets[64];
    uint32_t seed = 0, n_sets = 0, k;
    int i, c, have_seed = 0, e;

    duel_show_init(&S, &o);
    duel_config_default(&cfg);
    for (i = 0; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (v == NULL && (strcmp(a, "--config") == 0 || strcmp(a, "--out") == 0 || strcmp(a, "--set") == 0)) {
            fprintf(stderr, "duel_evolve run: %s needs a value\n", a);
            return 2;
        }
        if (strcmp(a, "--config") == 0 && v) {
            config = v;
            i++;
        } else if (strcmp(a, "--out") == 0 && v) {
            dir = v;
            i++;
        } else if (strcmp(a, "--seed") == 0) {
            if (duel_parse_u32(a, v, 0, 4294967295u, &seed))
                return 2;
            have_seed = 1;
            i++;
        } else if (strcmp(a, "--set") == 0 && v && n_sets < 64) {
            sets[n_sets++] = argv[++i];
        } else if ((c = duel_common_option(&S, &o, argc, argv, &i)) != 0) {
            if (c < 0)
                return 2;
        } else {
            fprintf(stderr, "duel_evolve run: unknown option '%s' (usage: duel_evolve run --config FILE --out DIR "
                            "[--set key=value ...] [--seed S] [--generations N] [--threads T] [--quiet] [--json] "
                            "[--record-champion-games])\n", duel_esc(a));
            return 2;
        }
    }
    if (config == NULL || dir == NULL) {
        fprintf(stderr, "duel_evolve run: --config FILE and --out DIR are required\n");
        return 2;
    }
    if (duel_config_read(&cfg, config, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (duel_config_set_list(&cfg, (const char *const *)sets, n_sets, &k, err, sizeof err) != 0) {
        char esc[1100];
        fprintf(stderr, "duel_evolve: --set %s: %s\n", duel_text_escape(sets[k], esc, sizeof esc), duel_esc_msg(err));
        return 2;
    }
    if (have_seed)
        cfg.seed = seed;
    if (o.generations > 0)
        cfg.generations = o.generations;
    if (duel_config_check(&cfg, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s: %s\n", n_sets > 0 ? "the configuration with its --set overrides" : config,
                duel_esc_msg(err));
        return 2;
    }
    o.config_name = config;
    o.sets = (const char *const *)sets;
    o.n_sets = n_sets;
    o.generations = 0;
    if ((e = duel_engine_new(&S.E, &cfg, dir, &o)) != 0)
        return e;
    return duel_show_play_out(&S);
}

int duel_cmd_resume(int argc, char **argv)
{
    duel_show S;
    duel_engine_options o;
    const char *dir = NULL;
    char *sets[64];
    uint32_t n_sets = 0;
    int i, c, e;

    duel_show_init(&S, &o);
    for (i = 0; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--set") == 0 && v == NULL) {
            fprintf(stderr, "duel_evolve resume: --set needs a value\n");
            return 2;
        }
        if ((c = duel_common_option(&S, &o, argc, argv, &i)) != 0) {
            if (c < 0)
                return 2;
        } else if (strcmp(a, "--shorten") == 0) {
            o.shorten = 1;
        } else if (strcmp(a, "--set") == 0 && v && n_sets < 64) {
            sets[n_sets++] = argv[++i];
        } else if (a[0] != '-' && dir == NULL) {
            dir = a;
        } else {
            fprintf(stderr, "duel_evolve resume: unknown option '%s' (usage: duel_evolve resume DIR [--generations "
                            "N [--shorten]] [--set key=value ...] [--threads T] [--quiet] [--json] "
                            "[--record-champion-games])\n", duel_esc(a));
            return 2;
        }
    }
    if (dir == NULL) {
        fprintf(stderr, "duel_evolve resume: which run directory?\n");
        return 2;
    }
    o.sets = (const char *const *)sets;
    o.n_sets = n_sets;
    if ((e = duel_engine_resume(&S.E, dir, &o)) != 0)
        return e;
    return duel_show_play_out(&S);
}
