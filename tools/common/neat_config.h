/* neat_config.h - INI configuration of libneat parameters for the command-line tools (parsed by inih). */
#ifndef NEAT_CONFIG_H
#define NEAT_CONFIG_H

#include <stddef.h>
#include <stdio.h>

#include "neat.h"

/* Sets one [neat] key from its text. Returns 0, or -1 with a message in err
 * (unknown key with a "did you mean", or a bad value). */
int neat_config_set(neat_params *p, const char *key, const char *value, char *err, size_t err_len);

/* 1 if name is a [neat] key. */
int neat_config_has_key(const char *name);

/* Writes every [neat] key as "key = value" lines that load back unchanged. */
void neat_config_dump(FILE *out, const neat_params *p);

/* The known key closest to name (edit distance), for "did you mean". */
const char *neat_config_suggest(const char *name, const char *const *known, size_t n_known);

/* A tool-specific key table entry, for settings beyond libneat's. */
typedef enum { NEAT_CFG_U32, NEAT_CFG_F64, NEAT_CFG_BOOL, NEAT_CFG_ENUM } neat_cfg_type;
typedef struct neat_cfg_key {
    const char *name;
    neat_cfg_type type;
    size_t offset;
    double min, max;
    const char *const *names; /* NEAT_CFG_ENUM: the value names, index = stored int */
} neat_cfg_key;

/* The table of every [neat] key (*n entries), in the order neat_config_dump writes them. */
const neat_cfg_key *neat_config_keys(size_t *n);

/* Parses value into the field of base described by k; -1 with err on a bad value. */
/* The one number syntax every INI key takes: the length of the number at the
 * start of v, 0 when there is none. An integer is decimal digits (no sign,
 * point, exponent or 0x: "1e1" and "0x10" are not 10 and 16); a real is
 * [+-]digits[.digits][e[+-]digits] or [+-].digits[...] (never strtod's hex,
 * "inf" or "nan"). */
size_t neat_config_number_len(const char *v, int integer);

int neat_config_parse_value(const neat_cfg_key *k, void *base, const char *value, char *err, size_t err_len);
/* Sets key from a table; -1 with a "did you mean" in err if unknown. */
int neat_config_set_in(const neat_cfg_key *keys, size_t n_keys, void *base, const char *key, const char *value,
                       char *err, size_t err_len);
/* Every key as "name = value", reals in their shortest exact form. */
void neat_config_dump_keys(FILE *out, const neat_cfg_key *keys, size_t n_keys, const void *base);
/* x in the fewest significant digits (at most 17) that read back to x
 * exactly: 0.3 prints "0.3". */
#define NEAT_FMT_DOUBLE 32
void neat_fmt_double(char buf[NEAT_FMT_DOUBLE], double x);

#endif /* NEAT_CONFIG_H */
