/* duel_config_cmd.c - duel_evolve config --dump: a configuration with its files and overrides applied, written out whole. */
#include <stdio.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_config.h"
#include "duel_text.h"

int duel_cmd_config(int argc, char **argv)
{
    duel_config cfg;
    char err[600];
    const char *last = NULL; /* the last file or override: whose the final check's complaint is */
    int i, dump = 0, from_set = 0;
    duel_config_default(&cfg);
    for (i = 0; i < argc; i++) {
        if (i + 1 >= argc && (strcmp(argv[i], "--config") == 0 || strcmp(argv[i], "--set") == 0)) {
            fprintf(stderr, "duel_evolve config: %s needs a value\n", duel_esc(argv[i]));
            return 2;
        }
        if (strcmp(argv[i], "--dump") == 0) {
            dump = 1;
        } else if (strcmp(argv[i], "--config") == 0 && i + 1 < argc) {
            if (duel_config_read(&cfg, argv[++i], err, sizeof err) != 0) {
                fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
                return 2;
            }
            last = argv[i];
            from_set = 0;
        } else if (strcmp(argv[i], "--set") == 0 && i + 1 < argc) {
            /* consecutive overrides together, a profile among them first (as run and resume apply theirs) */
            const char *group[256];
            uint32_t n = 0, bad;
            while (i + 1 < argc && strcmp(argv[i], "--set") == 0 && n < 256) {
                group[n++] = argv[i + 1];
                i += 2;
            }
            i--;
            if (duel_config_set_list(&cfg, group, n, &bad, err, sizeof err) != 0) {
                char esc[1100];
                fprintf(stderr, "duel_evolve: --set %s: %s\n", duel_text_escape(group[bad], esc, sizeof esc), duel_esc_msg(err));
                return 2;
            }
            last = group[n - 1];
            from_set = 1;
        } else {
            fprintf(stderr, "duel_evolve config: unknown option '%s' (usage: duel_evolve config --dump [--config "
                            "FILE] [--set key=value ...])\n", duel_esc(argv[i]));
            return 2;
        }
    }
    if (!dump) {
        fprintf(stderr, "duel_evolve config: nothing to do (try --dump)\n");
        return 2;
    }
    if (duel_config_check(&cfg, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s%s%s%s\n", last && from_set ? "--set " : "", last ? last : "",
                last ? ": " : "", duel_esc_msg(err));
        return 2;
    }
    duel_config_dump(stdout, &cfg);
    return 0;
}
