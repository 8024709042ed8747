/* duel_config.c - the run configuration's INI sections, keys, defaults, overrides and dump. */
#include <string.h>

#include "duel_config.h"
#include "duel.h"
#include "neat_config.h"
#include "neat_ini.h"

#define RUN_KEY(name, type, lo, hi) {#name, type, offsetof(duel_config, name), lo, hi, NULL}
#define COEV_KEY(name, lo, hi) {#name, NEAT_CFG_U32, offsetof(neat_coev_params, name), lo, hi, NULL}

static const neat_cfg_key duel_run_keys[] = {
    RUN_KEY(generations, NEAT_CFG_U32, 1, 1000000),
    RUN_KEY(seed, NEAT_CFG_U32, 0, 4294967295.0),
};
static const neat_cfg_key duel_coev_keys[] = {
    COEV_KEY(species_opponents, 0, 64),
    COEV_KEY(hof_opponents, 0, 1000),
    COEV_KEY(first_opponents, 1, 1000),
    COEV_KEY(compare_configs, 1, DUEL_CONFIGS),
};
#define N_RUN (sizeof duel_run_keys / sizeof duel_run_keys[0])
#define N_COEV (sizeof duel_coev_keys / sizeof duel_coev_keys[0])

void duel_config_default(duel_config *cfg)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->generations = 500;
    cfg->seed = 1;
    cfg->coev = neat_coev_params_default();
    cfg->neat = neat_params_default();
    cfg->neat.n_inputs = DUEL_N_INPUTS - 1;
    cfg->neat.n_outputs = DUEL_N_OUTPUTS;
}

static int duel_has_key(const neat_cfg_key *keys, size_t n, const char *name)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (strcmp(keys[i].name, name) == 0)
            return 1;
    return 0;
}

/* Where name lives when it is not in the section it was given in. */
static const char *duel_key_home(const char *name)
{
    if (duel_has_key(duel_run_keys, N_RUN, name))
        return "run";
    if (duel_has_key(duel_coev_keys, N_COEV, name))
        return "coevolution";
    if (neat_config_has_key(name))
        return "neat";
    return NULL;
}

static int duel_set_in(duel_config *cfg, const char *section, const char *name, const char *value, char *err,
                       size_t err_len)
{
    int r;
    if (strcmp(section, "run") == 0)
        r = neat_config_set_in(duel_run_keys, N_RUN, cfg, name, value, err, err_len);
    else if (strcmp(section, "coevolution") == 0)
        r = neat_config_set_in(duel_coev_keys, N_COEV, &cfg->coev, name, value, err, err_len);
    else if (strcmp(section, "neat") == 0)
        r = neat_config_set(&cfg->neat, name, value, err, err_len);
    else {
        snprintf(err, err_len, "unknown section [%s] (expected [run], [coevolution] or [neat])", section);
        return -1;
    }
    if (r != 0 && strncmp(err, "unknown key", 11) == 0) {
        const char *home = duel_key_home(name);
        if (home != NULL && strcmp(home, section) != 0)
            snprintf(err, err_len, "key '%s' belongs in section [%s], not [%s]", name, home, section);
    }
    return r;
}

static int duel_ini_handler(void *user, const char *section, const char *name, const char *value, char *err,
                            size_t err_len)
{
    return duel_set_in((duel_config *)user, section, name, value, err, err_len);
}

int duel_config_check(const duel_config *cfg, char *err, size_t err_len)
{
    const char *field;
    if (cfg->neat.n_inputs != DUEL_N_INPUTS - 1 || cfg->neat.n_outputs != DUEL_N_OUTPUTS) {
        snprintf(err, err_len, "[neat] n_inputs must be %d and n_outputs %d: the duel's sensors and motors",
                 DUEL_N_INPUTS - 1, DUEL_N_OUTPUTS);
        return -1;
    }
    if (neat_params_check(&cfg->neat, &field) != NEAT_OK) {
        snprintf(err, err_len, "[neat] %s out of range", field);
        return -1;
    }
    if (neat_coev_params_check(&cfg->coev, &field) != NEAT_OK) {
        snprintf(err, err_len, "[coevolution] %s out of range", field);
        return -1;
    }
    return 0;
}

int duel_config_load(duel_config *cfg, const char *path, char *err, size_t err_len)
{
    char msg[400];
    if (neat_ini_parse_file(path, duel_ini_handler, cfg, err, err_len) != 0)
        return -1;
    if (duel_config_check(cfg, msg, sizeof msg) != 0) {
        snprintf(err, err_len, "%s: %s", path, msg);
        return -1;
    }
    return 0;
}

int duel_config_load_text(duel_config *cfg, const char *name, const char *text, size_t len, char *err,
                          size_t err_len)
{
    char msg[400];
    if (neat_ini_parse_text(name, text, len, duel_ini_handler, cfg, err, err_len) != 0)
        return -1;
    if (duel_config_check(cfg, msg, sizeof msg) != 0) {
        snprintf(err, err_len, "%s: %s", name, msg);
        return -1;
    }
    return 0;
}

int duel_config_set(duel_config *cfg, const char *assignment, char *err, size_t err_len)
{
    char buf[NEAT_INI_MAX_LINE + 1], *eq, *dot, *key, *value;
    const char *section;
    if (strlen(assignment) >= sizeof buf) {
        snprintf(err, err_len, "an override of %zu characters (at most %d)", strlen(assignment), NEAT_INI_MAX_LINE);
        return -1;
    }
    if ((eq = strchr(strcpy(buf, assignment), '=')) == NULL) {
        snprintf(err, err_len, "'%s': expected key=value or section.key=value", assignment);
        return -1;
    }
    *eq = '\0';
    key = buf;
    value = eq + 1;
    dot = strchr(key, '.');
    if (dot != NULL) {
        *dot = '\0';
        section = key;
        key = dot + 1;
    } else {
        section = duel_key_home(key);
        if (section == NULL)
            section = "neat"; /* reports the unknown key with a suggestion */
    }
    return duel_set_in(cfg, section, key, value, err, err_len);
}

void duel_config_dump(FILE *out, const duel_config *cfg)
{
    fprintf(out, "[run]\n");
    neat_config_dump_keys(out, duel_run_keys, N_RUN, cfg);
    fprintf(out, "\n[coevolution]\n");
    neat_config_dump_keys(out, duel_coev_keys, N_COEV, &cfg->coev);
    fprintf(out, "\n[neat]\n");
    neat_config_dump(out, &cfg->neat);
}
