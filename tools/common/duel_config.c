/* duel_config.c - the run configuration's INI sections, keys, defaults, overrides and dump. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_config.h"
#include "duel.h"
#include "neat_config.h"
#include "neat_ini.h"
#include "duel_files.h"
#include "duel_genome_file.h"
#include "duel_world_cfg.h"

#define RUN_KEY(name, type, lo, hi) {#name, type, offsetof(duel_config, name), lo, hi, NULL}
#define COEV_KEY(name, lo, hi) {#name, NEAT_CFG_U32, offsetof(neat_coev_params, name), lo, hi, NULL}

static const char *const duel_train_names[] = {"training", "comparison", NULL};
static const char *const duel_reproduction_names[] = {"libneat", "neat-cpp-1.2.1", NULL};
static const neat_cfg_key duel_run_keys[] = {
    RUN_KEY(generations, NEAT_CFG_U32, 1, 1000000),
    RUN_KEY(seed, NEAT_CFG_U32, 0, 4294967295.0),
    {"train_layouts", NEAT_CFG_ENUM, offsetof(duel_config, train_layouts), 0, 1, duel_train_names},
    RUN_KEY(strength_every, NEAT_CFG_U32, 0, 1000000),
    /* last: dumped only when not libneat, so that every other run's config.ini keeps its bytes */
    {"reproduction", NEAT_CFG_ENUM, offsetof(duel_config, reproduction), 0, 1, duel_reproduction_names},
};
static const neat_cfg_key duel_coev_keys[] = {
    COEV_KEY(species_opponents, 0, 64),
    COEV_KEY(hof_opponents, 0, 1000),
    COEV_KEY(first_opponents, 1, 1000),
    COEV_KEY(compare_configs, 1, DUEL_CONFIGS),
    {"random_fitness", NEAT_CFG_BOOL, offsetof(neat_coev_params, random_fitness), 0, 1, NULL},
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
    /* coevolution cannot use the whole-population stagnation rule (neat_coev.h) */
    cfg->neat.pop_stagnation = 0;
    /* the duel's weight mutation: docs/parameters.md, "Weight perturbation" (the library keeps the C++ 2.5) */
    cfg->neat.weight_perturb_power = 1.0;
    cfg->neat.weight_replace_range = 1.0;
    cfg->start.kind = DUEL_START_MINIMAL;
    cfg->train_layouts = DUEL_TRAIN_FIXED;
    cfg->world = *duel_rules_v1();
}

/* "minimal", "hidden:H:inputs", "hidden:H:bias", "blob:PATH" or "genome:PATH". */
static int duel_start_parse(duel_start *st, const char *v, char *err, size_t err_len)
{
    static const char expect[] = "expected minimal, hidden:H:inputs, hidden:H:bias, blob:PATH or genome:PATH";
    const char *c;
    /* a control character (a newline, a tab) would write a config.ini that never reads back */
    for (c = v; *c != '\0'; c++)
        if ((unsigned char)*c < 0x20 || *c == 0x7f) {
            snprintf(err, err_len, "start: a control character (byte 0x%02x) at offset %d of its value", (unsigned)(unsigned char)*c,
                     (int)(c - v));
            return -1;
        }
    if (strcmp(v, "minimal") == 0) {
        memset(st, 0, sizeof *st);
        st->kind = DUEL_START_MINIMAL;
        return 0;
    }
    if (strncmp(v, "hidden:", 7) == 0) {
        char *end;
        unsigned long h;
        errno = 0;
        h = strtoul(v + 7, &end, 10);
        if (v[7] < '0' || v[7] > '9' || errno || h < 1 || h > DUEL_START_MAX_HIDDEN || *end != ':' ||
            (strcmp(end + 1, "inputs") != 0 && strcmp(end + 1, "bias") != 0)) {
            snprintf(err, err_len, "start = '%s': hidden:H:inputs or hidden:H:bias with H in 1..%d", v,
                     DUEL_START_MAX_HIDDEN);
            return -1;
        }
        memset(st, 0, sizeof *st);
        st->kind = DUEL_START_HIDDEN;
        st->hidden = (uint32_t)h;
        st->direct = strcmp(end + 1, "bias") == 0 ? NEAT_DIRECT_BIAS : NEAT_DIRECT_INPUTS;
        return 0;
    }
    if (strncmp(v, "blob:", 5) == 0 || strcmp(v, "blob") == 0) {
        /* "blob" alone: a preset's placeholder, refused by duel_config_check unless a path replaces it */
        if (v[4] != '\0' && strlen(v + 5) >= DUEL_START_MAX_PATH) {
            snprintf(err, err_len, "start: a blob path of %zu characters (at most %d)", strlen(v + 5),
                     DUEL_START_MAX_PATH - 1);
            return -1;
        }
        memset(st, 0, sizeof *st);
        st->kind = DUEL_START_BLOB;
        if (v[4] != '\0')
            strcpy(st->path, v + 5);
        return 0;
    }
    if (strncmp(v, "genome:", 7) == 0 && v[7] != '\0') {
        if (strlen(v + 7) >= DUEL_START_MAX_PATH) {
            snprintf(err, err_len, "start: a genome path of %zu characters (at most %d)", strlen(v + 7),
                     DUEL_START_MAX_PATH - 1);
            return -1;
        }
        memset(st, 0, sizeof *st);
        st->kind = DUEL_START_GENOME;
        strcpy(st->path, v + 7);
        return 0;
    }
    snprintf(err, err_len, "start = '%s': %s", v, expect);
    return -1;
}

void duel_start_text(const duel_start *st, char *buf, size_t cap)
{
    if (st->kind == DUEL_START_HIDDEN)
        snprintf(buf, cap, "hidden:%u:%s", st->hidden, st->direct == NEAT_DIRECT_BIAS ? "bias" : "inputs");
    else if (st->kind == DUEL_START_BLOB && st->path[0] != '\0')
        snprintf(buf, cap, "blob:%s", st->path);
    else if (st->kind == DUEL_START_BLOB)
        snprintf(buf, cap, "blob");
    else if (st->kind == DUEL_START_GENOME)
        snprintf(buf, cap, "genome:%s", st->path);
    else
        snprintf(buf, cap, "minimal");
}

int duel_start_genome(const duel_config *cfg, neat_genome *g, char *err, size_t err_len)
{
    const neat_params *p = &cfg->neat;
    uint8_t *blob = NULL;
    size_t len = 0;
    int e;
    neat_genome_init(g);
    if (cfg->start.kind == DUEL_START_MINIMAL)
        e = neat_genome_minimal(g, p->n_inputs, p->n_outputs, NULL);
    else if (cfg->start.kind == DUEL_START_HIDDEN)
        e = neat_genome_recurrent_hidden(g, p->n_inputs, p->n_outputs, cfg->start.hidden, cfg->start.direct, NULL);
    else if (cfg->start.kind == DUEL_START_GENOME) {
        uint32_t ni, no;
        if (duel_file_read(cfg->start.path, DUEL_GENOME_MAX, &blob, &len) != 0) {
            snprintf(err, err_len, "%s: cannot read the start genome: %s", cfg->start.path,
                     errno == EFBIG ? "larger than 64 MB" : duel_file_strerror(errno));
            return -1;
        }
        e = duel_genome_parse(cfg->start.path, blob, len, g, &ni, &no, err, err_len);
        free(blob);
        if (e != 0)
            return -1;
        if (ni != p->n_inputs || no != p->n_outputs) {
            snprintf(err, err_len, "%s: a genome of %u inputs and %u outputs, not the duel's %u and %u",
                     cfg->start.path, ni, no, p->n_inputs, p->n_outputs);
            neat_genome_free(g, NULL);
            return -1;
        }
    } else {
        /* a blob is a few KB; a much larger file is not one */
        if (duel_file_read(cfg->start.path, 1u << 20, &blob, &len) != 0) {
            snprintf(err, err_len, "%s: cannot read the start blob: %s", cfg->start.path,
                     errno == EFBIG ? "larger than 1 MB" : duel_file_strerror(errno));
            return -1;
        }
        e = neat_genome_from_blob(g, blob, len, NULL);
        free(blob);
        if (e == NEAT_E_FORMAT) {
            snprintf(err, err_len, "%s: not a valid champion blob (duel_evolve inspect tells why)", cfg->start.path);
            return -1;
        }
        if (!e && neat_genome_hidden_count(g) + p->n_inputs + 1 + p->n_outputs != g->n_nodes) {
            snprintf(err, err_len, "%s: a network of %u nodes with %u hidden: not the duel's %u inputs and %u outputs",
                     cfg->start.path, g->n_nodes, neat_genome_hidden_count(g), p->n_inputs + 1, p->n_outputs);
            neat_genome_free(g, NULL);
            return -1;
        }
    }
    if (!e && g->n_nodes > p->max_nodes) {
        snprintf(err, err_len, "start: %u nodes, more than max_nodes = %u", g->n_nodes, p->max_nodes);
        neat_genome_free(g, NULL);
        return -1;
    }
    if (!e) {
        /* the run's own node ids and innovation numbers come after the start's, up to 2^31 - 1: a start near
         * that limit would load and then stop the run after a few generations (NEAT_E_COUNTERS) */
        uint32_t k, node = 0, innov = 0;
        for (k = 0; k < g->n_nodes; k++)
            node = g->nodes[k].id > node ? g->nodes[k].id : node;
        for (k = 0; k < g->n_conns; k++)
            innov = g->conns[k].innov > innov ? g->conns[k].innov : innov;
        if (node > DUEL_START_MAX_COUNTER || innov > DUEL_START_MAX_COUNTER) {
            snprintf(err, err_len, "%s: start genome with %s %u, more than %u: it would leave the run too few of "
                                   "its own (every counter stops at 2^31 - 1)", cfg->start.path,
                     node > DUEL_START_MAX_COUNTER ? "node id" : "innovation number",
                     node > DUEL_START_MAX_COUNTER ? node : innov, DUEL_START_MAX_COUNTER);
            neat_genome_free(g, NULL);
            return -1;
        }
    }
    if (e) {
        snprintf(err, err_len, "start: %s", neat_strerror(e));
        neat_genome_free(g, NULL);
        return -1;
    }
    return 0;
}

int duel_same_topology(const neat_genome *a, const neat_genome *b)
{
    uint32_t i;
    if (a->n_nodes != b->n_nodes || a->n_conns != b->n_conns)
        return 0;
    for (i = 0; i < a->n_nodes; i++)
        if (a->nodes[i].id != b->nodes[i].id || a->nodes[i].type != b->nodes[i].type)
            return 0;
    for (i = 0; i < a->n_conns; i++)
        if (a->conns[i].in != b->conns[i].in || a->conns[i].out != b->conns[i].out ||
            a->conns[i].innov != b->conns[i].innov || a->conns[i].enabled != b->conns[i].enabled)
            return 0;
    return 1;
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
    if (neat_config_has_key(name) || strcmp(name, "start") == 0)
        return "neat";
    {
        size_t i;
        for (i = 0; i < duel_world_n_keys; i++)
            if (strcmp(duel_world_keys[i], name) == 0)
                return "world";
    }
    if (strcmp(name, "play") == 0 || strcmp(name, "games") == 0 || strcmp(name, "fitness") == 0)
        return "opponents";
    return NULL;
}

/* [opponents] play = a, b, ...: each a builtin:NAME or a file path (no commas) */
int duel_list_next(const char **p, const char **item, size_t *len)
{
    const char *q = *p, *end, *stop;
    while (*q == ' ' || *q == '\t')
        q++;
    end = strchr(q, ',');
    stop = end != NULL ? end : q + strlen(q);
    *item = q;
    *p = end != NULL ? end + 1 : stop;
    while (stop > q && (stop[-1] == ' ' || stop[-1] == '\t'))
        stop--;
    *len = (size_t)(stop - q);
    return end != NULL;
}

static int duel_opp_play(duel_opponents *o, const char *v, char *err, size_t err_len)
{
    const char *p = v, *stop0;
    uint32_t n = 0;
    duel_opponents got = *o;
    for (stop0 = v; *stop0 != '\0'; stop0++)
        /* a newline would write a config.ini that never reads back: a run that can never be resumed */
        if ((unsigned char)*stop0 < 0x20 || *stop0 == 0x7f) {
            snprintf(err, err_len, "[opponents] play: a control character (byte 0x%02x) at offset %d of its value",
                     (unsigned)(unsigned char)*stop0, (int)(stop0 - v));
            return -1;
        }
    while (*p != '\0') {
        const char *item;
        size_t len;
        int comma = duel_list_next(&p, &item, &len);
        if (len == 0) {
            snprintf(err, err_len, "[opponents] play: an empty name (opponents are separated by commas)");
            return -1;
        }
        if (n == DUEL_MAX_OPPONENTS) {
            snprintf(err, err_len, "[opponents] play: more than %d opponents", DUEL_MAX_OPPONENTS);
            return -1;
        }
        if (len >= DUEL_OPP_MAX_SPEC) {
            snprintf(err, err_len, "[opponents] play: a name of %zu characters (at most %d)", len,
                     DUEL_OPP_MAX_SPEC - 1);
            return -1;
        }
        memcpy(got.spec[n], item, len);
        got.spec[n][len] = '\0';
        if (strncmp(got.spec[n], "builtin:", 8) == 0 && duel_builtin_parse(got.spec[n] + 8) < 0) {
            snprintf(err, err_len, "[opponents] play: '%s': no such builtin (idle, spinner, forager, hunter, "
                                   "forager-hunter)", got.spec[n]);
            return -1;
        }
        n++;
        if (comma && *p == '\0') {
            snprintf(err, err_len, "[opponents] play: an empty name after the last comma");
            return -1;
        }
    }
    got.n = n;
    *o = got;
    return 0;
}

static int duel_opp_set(duel_opponents *o, const char *name, const char *value, char *err, size_t err_len)
{
    static const char *const keys[] = {"play", "games", "fitness"};
    if (strcmp(name, "play") == 0)
        return duel_opp_play(o, value, err, err_len);
    if (strcmp(name, "games") == 0) {
        char *end;
        unsigned long n;
        if (strcmp(value, "training") == 0) {
            o->layouts = 0;
            return 0;
        }
        errno = 0;
        n = strncmp(value, "comparison:", 11) == 0 ? strtoul(value + 11, &end, 10) : 0;
        if (n < 1 || n > DUEL_CONFIGS || errno || *end != '\0' || value[11] < '0' || value[11] > '9') {
            snprintf(err, err_len, "[opponents] games = '%s': training, or comparison:N with N in 1..%d", value,
                     DUEL_CONFIGS);
            return -1;
        }
        o->layouts = (uint32_t)n;
        return 0;
    }
    if (strcmp(name, "fitness") == 0) {
        if (strcmp(value, "wins") == 0 || strcmp(value, "wins-losses") == 0) {
            o->fitness = strcmp(value, "wins") == 0 ? DUEL_FIT_WINS : DUEL_FIT_MARGIN;
            return 0;
        }
        snprintf(err, err_len, "[opponents] fitness = '%s': wins or wins-losses", value);
        return -1;
    }
    {
        const char *near = neat_config_suggest(name, keys, 3);
        snprintf(err, err_len, "unknown key '%s' in [opponents]%s%s%s", name, near ? " (did you mean '" : "",
                 near ? near : "", near ? "'?)" : "");
    }
    return -1;
}

/* [overrides] from G = key=value, ...: kept as text (checked whole by duel_config_check, when every section is
 * read), in generation order */
static int duel_over_set(duel_config *cfg, const char *name, const char *value, char *err, size_t err_len)
{
    const char *p = value, *item;
    size_t len;
    uint32_t g = 0, k;
    int more = 1;
    if (strncmp(name, "from ", 5) != 0 || name[5] == '\0' || strspn(name + 5, "0123456789") != strlen(name + 5) ||
        strlen(name + 5) > 9 || (g = (uint32_t)strtoul(name + 5, NULL, 10)) == 0) {
        snprintf(err, err_len, "[overrides] '%s': expected 'from G' with G a generation from 1 on (from G = "
                               "key=value, ...)", name);
        return -1;
    }
    if (cfg->n_over == DUEL_MAX_OVERRIDES) {
        snprintf(err, err_len, "[overrides]: more than %d lines", DUEL_MAX_OVERRIDES);
        return -1;
    }
    if (strlen(value) >= DUEL_OVERRIDE_MAX) {
        snprintf(err, err_len, "[overrides] from %u: %zu characters (at most %d)", g, strlen(value),
                 DUEL_OVERRIDE_MAX - 1);
        return -1;
    }
    while (more && *p != '\0') {
        char one[DUEL_OVERRIDE_MAX];
        more = duel_list_next(&p, &item, &len);
        memcpy(one, item, len);
        one[len] = '\0';
        if (len == 0 || strchr(one, '=') == NULL || !duel_config_set_is_param(one)) {
            snprintf(err, err_len, "[overrides] from %u: '%s': expected key=value of a [neat] or [coevolution] "
                                   "parameter", g, one);
            return -1;
        }
    }
    if (value[0] == '\0') {
        snprintf(err, err_len, "[overrides] from %u: no change", g);
        return -1;
    }
    /* in generation order, whatever the file's */
    for (k = cfg->n_over; k > 0 && cfg->over[k - 1u].from > g; k--)
        cfg->over[k] = cfg->over[k - 1u];
    cfg->over[k].from = g;
    snprintf(cfg->over[k].sets, sizeof cfg->over[k].sets, "%s", value);
    cfg->n_over++;
    return 0;
}

int duel_config_set_is_param(const char *assignment)
{
    char key[64];
    const char *eq = strchr(assignment, '='), *dot;
    size_t n = eq != NULL ? (size_t)(eq - assignment) : strlen(assignment);
    if (n >= sizeof key)
        return 0;
    memcpy(key, assignment, n);
    key[n] = '\0';
    dot = strchr(key, '.');
    if (dot != NULL)
        return (strncmp(key, "coevolution.", 12) == 0 && duel_has_key(duel_coev_keys, N_COEV, key + 12)) ||
               (strncmp(key, "neat.", 5) == 0 && strcmp(key + 5, "start") != 0 && neat_config_has_key(key + 5));
    return duel_has_key(duel_coev_keys, N_COEV, key) || (strcmp(key, "start") != 0 && neat_config_has_key(key));
}

int duel_config_at(const duel_config *cfg, uint32_t g, duel_config *out, char *err, size_t err_len)
{
    uint32_t k;
    *out = *cfg;
    out->n_over = 0;
    for (k = 0; k < cfg->n_over && cfg->over[k].from <= g; k++) {
        const char *sets[DUEL_OVERRIDE_MAX / 4], *p = cfg->over[k].sets, *item;
        char buf[DUEL_OVERRIDE_MAX], msg[400];
        size_t len, at = 0;
        uint32_t n = 0, bad = 0;
        int more = 1;
        while (more && *p != '\0' && n < DUEL_OVERRIDE_MAX / 4) {
            more = duel_list_next(&p, &item, &len);
            memcpy(buf + at, item, len);
            buf[at + len] = '\0';
            sets[n++] = buf + at;
            at += len + 1u;
        }
        if (duel_config_set_list(out, sets, n, &bad, msg, sizeof msg) != 0) {
            snprintf(err, err_len, "[overrides] from %u: %s", cfg->over[k].from, msg);
            return -1;
        }
    }
    return 0;
}

int duel_config_add_override(duel_config *cfg, uint32_t g, const char *const *sets, uint32_t n, char *err,
                             size_t err_len)
{
    char text[DUEL_OVERRIDE_MAX * 2];
    size_t at = 0;
    uint32_t k, j;
    if (n == 0)
        return 0;
    for (k = 0; k < cfg->n_over && cfg->over[k].from <= g; k++)
        ;
    if (k > 0 && cfg->over[k - 1u].from == g) {
        k--;
        at = (size_t)snprintf(text, sizeof text, "%s", cfg->over[k].sets);
    } else if (cfg->n_over == DUEL_MAX_OVERRIDES) {
        snprintf(err, err_len, "the run has overrides from %d generations already, the most config.ini keeps: "
                               "start a new run with the parameters wanted", DUEL_MAX_OVERRIDES);
        return -1;
    }
    for (j = 0; j < n; j++) {
        if (strchr(sets[j], ',') != NULL) {
            snprintf(err, err_len, "'%s': a comma in an override's value", sets[j]);
            return -1;
        }
        at += (size_t)snprintf(text + at, at < sizeof text ? sizeof text - at : 0, "%s%s", at ? ", " : "", sets[j]);
    }
    if (at >= DUEL_OVERRIDE_MAX) {
        snprintf(err, err_len, "the overrides from generation %u take %zu characters, more than config.ini keeps "
                               "(%d)", g, at, DUEL_OVERRIDE_MAX - 1);
        return -1;
    }
    if (!(k < cfg->n_over && cfg->over[k].from == g)) {
        for (j = cfg->n_over; j > k; j--)
            cfg->over[j] = cfg->over[j - 1u];
        cfg->n_over++;
        cfg->over[k].from = g;
    }
    memcpy(cfg->over[k].sets, text, at + 1u);
    return 0;
}

static int duel_set_in(duel_config *cfg, const char *section, const char *name, const char *value, char *err,
                       size_t err_len)
{
    int r;
    const char *c;
    /* a control byte in a value (--set: an INI line holding one is refused as it is read): start and play name it
     * themselves, every other key here */
    if (!(strcmp(section, "neat") == 0 && strcmp(name, "start") == 0) &&
        !(strcmp(section, "opponents") == 0 && strcmp(name, "play") == 0))
        for (c = value; *c != '\0'; c++)
            if ((unsigned char)*c < 0x20 || (unsigned char)*c == 0x7f) {
                snprintf(err, err_len, "%s: a control character (byte 0x%02x) in its value", name,
                         (unsigned)(unsigned char)*c);
                return -1;
            }
    if (strcmp(section, "overrides") == 0)
        return duel_over_set(cfg, name, value, err, err_len);
    if (strcmp(section, "run") == 0)
        r = neat_config_set_in(duel_run_keys, N_RUN, cfg, name, value, err, err_len);
    else if (strcmp(section, "coevolution") == 0)
        r = neat_config_set_in(duel_coev_keys, N_COEV, &cfg->coev, name, value, err, err_len);
    else if (strcmp(section, "neat") == 0 && strcmp(name, "start") == 0)
        return duel_start_parse(&cfg->start, value, err, err_len);
    else if (strcmp(section, "neat") == 0)
        r = neat_config_set(&cfg->neat, name, value, err, err_len);
    else if (strcmp(section, "world") == 0)
        r = duel_world_set(&cfg->world, name, value, err, err_len);
    else if (strcmp(section, "opponents") == 0)
        r = duel_opp_set(&cfg->opp, name, value, err, err_len);
    else {
        snprintf(err, err_len, "unknown section [%s] (expected [run], [coevolution], [neat], [world], [opponents] "
                               "or [overrides])", section);
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
    if (cfg->start.kind == DUEL_START_BLOB && cfg->start.path[0] == '\0') {
        snprintf(err, err_len, "[neat] start = blob needs the champion's path: blob:PATH (e.g. --set "
                               "start=blob:runs/c1/champions/gen-00123.blob)");
        return -1;
    }
    if (cfg->neat.pop_stagnation != 0 && cfg->opp.n == 0) {
        snprintf(err, err_len, "[neat] pop_stagnation must be 0 in coevolution: the rule needs an absolute fitness, "
                               "and a count of wins against changing opponents never improves (docs/parameters.md)");
        return -1;
    }
    if (cfg->start.kind == DUEL_START_HIDDEN && cfg->neat.n_inputs + 1 + cfg->neat.n_outputs + cfg->start.hidden >
                                                    cfg->neat.max_nodes) {
        snprintf(err, err_len, "[neat] start = hidden:%u: %u nodes, more than max_nodes = %u", cfg->start.hidden,
                 cfg->neat.n_inputs + 1 + cfg->neat.n_outputs + cfg->start.hidden, cfg->neat.max_nodes);
        return -1;
    }
    if (neat_coev_params_check(&cfg->coev, &field) != NEAT_OK) {
        snprintf(err, err_len, "[coevolution] %s out of range", field);
        return -1;
    }
    if (cfg->opp.n > 0 && cfg->coev.random_fitness) {
        snprintf(err, err_len, "[coevolution] random_fitness is the coevolution's control; a run against fixed "
                               "opponents ([opponents] play) has none");
        return -1;
    }
    if (cfg->n_over > 0) {
        /* each line applies, and the parameters it makes are usable */
        duel_config at;
        uint32_t k;
        char msg[400];
        for (k = 0; k < cfg->n_over; k++) {
            if (duel_config_at(cfg, cfg->over[k].from, &at, err, err_len) != 0)
                return -1;
            if (duel_config_check(&at, msg, sizeof msg) != 0) {
                snprintf(err, err_len, "[overrides] from %u: %s", cfg->over[k].from, msg);
                return -1;
            }
            if (at.neat.pop_size != cfg->neat.pop_size || at.neat.n_inputs != cfg->neat.n_inputs) {
                snprintf(err, err_len, "[overrides] from %u: pop_size cannot change during a run", cfg->over[k].from);
                return -1;
            }
            if (at.neat.net_step != cfg->neat.net_step) {
                /* a run's champions, dominants and strength rows are blobs of one step */
                snprintf(err, err_len, "[overrides] from %u: net_step cannot change during a run", cfg->over[k].from);
                return -1;
            }
        }
    }
    return duel_world_check(&cfg->world, err, err_len);
}

int duel_config_read(duel_config *cfg, const char *path, char *err, size_t err_len)
{
    return neat_ini_parse_file(path, duel_ini_handler, cfg, err, err_len) != 0 ? -1 : 0;
}

int duel_config_load(duel_config *cfg, const char *path, char *err, size_t err_len)
{
    char msg[400];
    if (duel_config_read(cfg, path, err, err_len) != 0)
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

/* "profile=...", "neat.profile=..." or "world.rules=...": a setting the others of its section refine */
static int duel_set_is_first(const char *set)
{
    if (strncmp(set, "world.", 6) == 0)
        return strncmp(set + 6, "rules", 5) == 0 && set[11] == '=';
    if (strncmp(set, "rules", 5) == 0 && set[5] == '=')
        return 1;
    if (strncmp(set, "neat.", 5) == 0)
        set += 5;
    return strncmp(set, "profile", 7) == 0 && set[7] == '=';
}

int duel_config_set_list(duel_config *cfg, const char *const *sets, uint32_t n, uint32_t *bad, char *err,
                         size_t err_len)
{
    uint32_t pass, k;
    for (pass = 0; pass < 2; pass++)
        for (k = 0; k < n; k++)
            if (duel_set_is_first(sets[k]) == (pass == 0) && duel_config_set(cfg, sets[k], err, err_len) != 0) {
                if (bad != NULL)
                    *bad = k;
                return -1;
            }
    return 0;
}

void duel_config_dump(FILE *out, const duel_config *cfg)
{
    fprintf(out, "[run]\n");
    neat_config_dump_keys(out, duel_run_keys, cfg->reproduction != DUEL_REPRODUCE_LIBNEAT ? N_RUN : N_RUN - 1, cfg);
    fprintf(out, "\n[coevolution]\n");
    neat_config_dump_keys(out, duel_coev_keys, N_COEV, &cfg->coev);
    fprintf(out, "\n[neat]\n");
    {
        char st[DUEL_START_MAX_PATH + 16];
        duel_start_text(&cfg->start, st, sizeof st);
        fprintf(out, "start = %s\n", st);
    }
    neat_config_dump(out, &cfg->neat);
    fprintf(out, "\n[world]\n");
    duel_world_dump(out, &cfg->world);
    if (cfg->opp.n > 0) {
        uint32_t k;
        fprintf(out, "\n[opponents]\nplay = ");
        for (k = 0; k < cfg->opp.n; k++)
            fprintf(out, "%s%s", k ? ", " : "", cfg->opp.spec[k]);
        if (cfg->opp.layouts == 0)
            fprintf(out, "\ngames = training\n");
        else
            fprintf(out, "\ngames = comparison:%u\n", cfg->opp.layouts);
        fprintf(out, "fitness = %s\n", cfg->opp.fitness == DUEL_FIT_WINS ? "wins" : "wins-losses");
    }
    if (cfg->n_over > 0) {
        uint32_t k;
        fprintf(out, "\n[overrides]\n; parameters changed from a generation on (resume --set): the sections above "
                     "hold generation 0's\n");
        for (k = 0; k < cfg->n_over; k++)
            fprintf(out, "from %u = %s\n", cfg->over[k].from, cfg->over[k].sets);
    }
}
