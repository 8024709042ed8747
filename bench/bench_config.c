/* bench_config.c - neat_bench's INI configuration: the [bench] keys beside libneat's [neat] section. */
#include <stdio.h>
#include <string.h>

#include "bench.h"
#include "neat_config.h"
#include "neat_ini.h"

#define BENCH_KEY(name, type, lo, hi) {#name, type, offsetof(bench_cfg, name), lo, hi, NULL}
static const neat_cfg_key bench_keys[] = {
    BENCH_KEY(runs, NEAT_CFG_U32, 1, 100000),
    BENCH_KEY(max_generations, NEAT_CFG_U32, 1, 100000000),
    BENCH_KEY(max_evaluations, NEAT_CFG_U32, 0, 4000000000.0),
    BENCH_KEY(threads, NEAT_CFG_U32, 0, 1024),
    BENCH_KEY(balance_steps, NEAT_CFG_U32, 1, 100000000),
    BENCH_KEY(damping_steps, NEAT_CFG_U32, 101, 100000000),
    BENCH_KEY(generalization_min, NEAT_CFG_U32, 0, 625),
};
#define BENCH_N_KEYS (sizeof bench_keys / sizeof bench_keys[0])

static int bench_ini_handler(void *user, const char *section, const char *name, const char *value, char *err,
                             size_t err_len)
{
    bench_cfg *cfg = (bench_cfg *)user;
    if (strcmp(section, "neat") == 0)
        return neat_config_set(&cfg->neat, name, value, err, err_len);
    if (strcmp(section, "bench") == 0)
        return neat_config_set_in(bench_keys, BENCH_N_KEYS, cfg, name, value, err, err_len);
    snprintf(err, err_len, "unknown section [%s] (expected [bench] or [neat])", section);
    return -1;
}

int bench_config_load(bench_cfg *cfg, const char *path)
{
    const char *field;
    char err[600];
    if (neat_ini_parse_file(path, bench_ini_handler, cfg, err, sizeof err) != 0) {
        fprintf(stderr, "neat_bench: %s\n", err);
        return -1;
    }
    if (neat_params_check(&cfg->neat, &field) != NEAT_OK) {
        fprintf(stderr, "neat_bench: %s: parameter %s out of range\n", path, field);
        return -1;
    }
    return 0;
}

int bench_config_load_text(bench_cfg *cfg, const char *name, const char *text, size_t len, char *err, size_t err_len)
{
    const char *field;
    if (neat_ini_parse_text(name, text, len, bench_ini_handler, cfg, err, err_len) != 0)
        return -1;
    if (neat_params_check(&cfg->neat, &field) != NEAT_OK) {
        snprintf(err, err_len, "%s: parameter %s out of range", name, field);
        return -1;
    }
    return 0;
}

void bench_config_dump(FILE *out, const bench_cfg *cfg)
{
    neat_config_dump_keys(out, bench_keys, BENCH_N_KEYS, cfg);
}
