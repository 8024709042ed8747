/* duel_config.h - a coevolution run's configuration: the [run], [coevolution] and [neat] sections of an INI file. */
/* tools/common/: what the commands share: the run configuration and every libneat parameter in INI, run-directory files, controllers named on the command line, traces, genome -> blob -> runtime, the threaded game batches of coevolution. */
#ifndef DUEL_CONFIG_H
#define DUEL_CONFIG_H

#include <stddef.h>
#include <stdio.h>

#include "neat.h"
#include "neat_coev.h"

typedef struct duel_config {
    uint32_t generations; /* [run] generations to play in all */
    uint32_t seed;        /* [run] */
    neat_coev_params coev;
    neat_params neat;
} duel_config;

/* The paper's values (Appendix A, section 5): 500 generations, seed 1. */
void duel_config_default(duel_config *cfg);

/* Loads path over cfg. On error: -1 and one line in err naming the file
 * and line ("FILE:LINE: unknown key 'x' (did you mean 'y'?)"); nothing of
 * cfg is to be used then. */
int duel_config_load(duel_config *cfg, const char *path, char *err, size_t err_len);
/* The same from len bytes of text, named name in the messages. */
int duel_config_load_text(duel_config *cfg, const char *name, const char *text, size_t len, char *err,
                          size_t err_len);

/* One override, "key=value" or "section.key=value" (a bare key must name
 * one key of one section). -1 with a message in err. */
int duel_config_set(duel_config *cfg, const char *assignment, char *err, size_t err_len);

/* Every key of every section, in a form duel_config_load reads back to the
 * same configuration. */
void duel_config_dump(FILE *out, const duel_config *cfg);

/* The whole configuration is usable (ranges, the duel's 12 sensors and 3
 * outputs). -1 with a message in err. */
int duel_config_check(const duel_config *cfg, char *err, size_t err_len);

#endif /* DUEL_CONFIG_H */
