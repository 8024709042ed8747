/* neat_config.c - INI keys of the [neat] section: one table naming every libneat parameter, its type and range. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "neat_config.h"

#define NEAT_KEY(name, type, lo, hi) {#name, type, offsetof(neat_params, name), lo, hi, NULL}
#define NEAT_ENUM(name, names, n) {#name, NEAT_CFG_ENUM, offsetof(neat_params, name), 0, (n) - 1, names}

static const char *const neat_mode_names[] = {"complexify", "fixed", "simplify"};
static const char *const neat_stagnation_names[] = {"oldest-worst", "improvement", "neat-cpp"};
static const char *const neat_net_step_names[] = {"sync", "propagate"}; /* enum neat_net_step */
/* NEAT C++ 1.2.1's switches: this library's rule first (0), the release's second (1) */
static const char *const neat_profile_names[] = {"default", "neat-cpp-1.2.1"};
static const char *const neat_equal_names[] = {"random", "smaller"};
static const char *const neat_reenable_names[] = {"paper", "neat-cpp"};
static const char *const neat_add_conn_names[] = {"any", "neat-cpp"};
static const char *const neat_rep_names[] = {"random", "champion"};
static const char *const neat_weights_names[] = {"uniform", "neat-cpp"};
static const char *const neat_elite_names[] = {"size", "offspring"};
static const char *const neat_inter_names[] = {"uniform", "neat-cpp"};
static const char *const neat_identical_names[] = {"same", "equal"};
static const char *const neat_rounding_names[] = {"remainder", "skim"};
static const char *const neat_speciate_names[] = {"after", "interleaved"};
static const char *const neat_popstag_names[] = {"two-best", "delta-coding"};

static const neat_cfg_key neat_keys[] = {
    /* first: setting it sets the switches below (neat_params_set_profile), and an INI file delivers it before
     * every other key (neat_ini.h), so a dump loads back unchanged */
    NEAT_ENUM(profile, neat_profile_names, 2),
    NEAT_KEY(pop_size, NEAT_CFG_U32, 2, 1000000),
    NEAT_KEY(n_inputs, NEAT_CFG_U32, 0, 254),
    NEAT_KEY(n_outputs, NEAT_CFG_U32, 1, 255),
    NEAT_ENUM(mode, neat_mode_names, 3),
    NEAT_KEY(c1, NEAT_CFG_F64, 0, 1e9),
    NEAT_KEY(c2, NEAT_CFG_F64, 0, 1e9),
    NEAT_KEY(c3, NEAT_CFG_F64, 0, 1e9),
    NEAT_KEY(normalize_by_size, NEAT_CFG_BOOL, 0, 1),
    NEAT_KEY(delta_t, NEAT_CFG_F64, 1e-9, 1e9),
    NEAT_KEY(delta_t_step, NEAT_CFG_F64, 0, 1e9),
    NEAT_KEY(delta_t_min, NEAT_CFG_F64, 1e-9, 1e9),
    NEAT_KEY(target_species, NEAT_CFG_U32, 0, 1000000),
    NEAT_KEY(survival_fraction, NEAT_CFG_F64, 1e-9, 1),
    NEAT_KEY(elitism_min_size, NEAT_CFG_U32, 0, 1000000),
    NEAT_ENUM(stagnation_rule, neat_stagnation_names, 3),
    NEAT_KEY(dropoff_age, NEAT_CFG_U32, 0, 1000000000),
    NEAT_KEY(stagnation_factor, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(pop_stagnation, NEAT_CFG_U32, 0, 1000000000),
    NEAT_KEY(mutate_only_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(mate_only_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(interspecies_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(mate_avg_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(disable_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(excess_equal_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(weight_mut_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(weight_perturb_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(weight_perturb_power, NEAT_CFG_F64, 0, 1e3),
    NEAT_KEY(weight_init_range, NEAT_CFG_F64, 0, 8),
    NEAT_KEY(weight_replace_range, NEAT_CFG_F64, 0, 8),
    NEAT_KEY(weight_max, NEAT_CFG_F64, 1e-9, 8),
    NEAT_KEY(add_conn_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(add_node_prob, NEAT_CFG_F64, 0, 1),
    NEAT_KEY(add_conn_tries, NEAT_CFG_U32, 0, 1000),
    NEAT_KEY(allow_recurrent, NEAT_CFG_BOOL, 0, 1),
    NEAT_KEY(max_nodes, NEAT_CFG_U32, 2, 256),
    NEAT_ENUM(net_step, neat_net_step_names, 2),
    NEAT_ENUM(equal_fitness_rule, neat_equal_names, 2),
    NEAT_ENUM(reenable_rule, neat_reenable_names, 2),
    NEAT_ENUM(add_conn_rule, neat_add_conn_names, 2),
    NEAT_KEY(recur_only_prob, NEAT_CFG_F64, 0, 1),
    NEAT_ENUM(species_rep, neat_rep_names, 2),
    NEAT_ENUM(weight_mut_rule, neat_weights_names, 2),
    NEAT_ENUM(elitism_rule, neat_elite_names, 2),
    NEAT_ENUM(interspecies_rule, neat_inter_names, 2),
    NEAT_ENUM(identical_rule, neat_identical_names, 2),
    NEAT_ENUM(offspring_rounding, neat_rounding_names, 2),
    NEAT_ENUM(speciate_rule, neat_speciate_names, 2),
    NEAT_KEY(cull_every, NEAT_CFG_U32, 0, 1000000000),
    NEAT_KEY(cull_age, NEAT_CFG_U32, 0, 1000000000),
    NEAT_ENUM(pop_stagnation_rule, neat_popstag_names, 2),
};
#define NEAT_N_KEYS (sizeof neat_keys / sizeof neat_keys[0])

const neat_cfg_key *neat_config_keys(size_t *n)
{
    *n = NEAT_N_KEYS;
    return neat_keys;
}

static size_t neat_edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), i, j, row[64], prev, tmp;
    if (lb >= 64)
        return (size_t)-1;
    for (j = 0; j <= lb; j++)
        row[j] = j;
    for (i = 1; i <= la; i++) {
        prev = row[0];
        row[0] = i;
        for (j = 1; j <= lb; j++) {
            size_t best = prev + (a[i - 1] != b[j - 1]);
            if (row[j] + 1 < best)
                best = row[j] + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            tmp = row[j];
            row[j] = best;
            prev = tmp;
        }
    }
    return row[lb];
}

const char *neat_config_suggest(const char *name, const char *const *known, size_t n_known)
{
    size_t i, best_d = (size_t)-1;
    const char *best = NULL;
    for (i = 0; i < n_known; i++) {
        size_t d = neat_edit_distance(name, known[i]);
        if (d < best_d) {
            best_d = d;
            best = known[i];
        }
    }
    /* only a plausible typo is worth suggesting */
    return best_d <= 1 + strlen(name) / 3 ? best : NULL;
}

size_t neat_config_number_len(const char *v, int integer)
{
    const char *p = v;
    int digits = 0;
    if (!integer && (*p == '+' || *p == '-'))
        p++;
    while (*p >= '0' && *p <= '9') {
        p++;
        digits++;
    }
    if (integer)
        return digits > 0 ? (size_t)(p - v) : 0;
    if (*p == '.') {
        p++;
        while (*p >= '0' && *p <= '9') {
            p++;
            digits++;
        }
    }
    if (digits == 0)
        return 0;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        if (*q == '+' || *q == '-')
            q++;
        if (*q >= '0' && *q <= '9') {
            while (*q >= '0' && *q <= '9')
                q++;
            p = q;
        }
    }
    return (size_t)(p - v);
}

/* The whole of v is a number in the one syntax (neat_config_number_len). */
static int neat_config_decimal(const char *v, int integer)
{
    size_t n = neat_config_number_len(v, integer);
    return n > 0 && v[n] == '\0';
}

int neat_config_parse_value(const neat_cfg_key *k, void *base, const char *value, char *err, size_t err_len)
{
    char *end = NULL;
    double d;
    void *field = (char *)base + k->offset;
    if (k->type == NEAT_CFG_ENUM) {
        int m, n = (int)k->max + 1;
        char expect[200] = "";
        for (m = 0; m < n; m++)
            if (strcmp(value, k->names[m]) == 0) {
                *(int *)field = m;
                return 0;
            }
        for (m = 0; m < n; m++) {
            strncat(expect, m ? ", " : "", sizeof expect - strlen(expect) - 1);
            strncat(expect, k->names[m], sizeof expect - strlen(expect) - 1);
        }
        snprintf(err, err_len, "bad value '%s' for %s: expected one of %s", value, k->name, expect);
        return -1;
    }
    if (k->type == NEAT_CFG_BOOL) {
        if (strcmp(value, "1") == 0 || strcmp(value, "true") == 0 || strcmp(value, "yes") == 0) {
            *(int *)field = 1;
            return 0;
        }
        if (strcmp(value, "0") == 0 || strcmp(value, "false") == 0 || strcmp(value, "no") == 0) {
            *(int *)field = 0;
            return 0;
        }
        snprintf(err, err_len, "bad value '%s' for %s: expected true or false", value, k->name);
        return -1;
    }
    errno = 0;
    d = strtod(value, &end);
    if (!neat_config_decimal(value, k->type == NEAT_CFG_U32) || end == value || *end != '\0' || errno != 0 ||
        !isfinite(d) || d < k->min || d > k->max || (k->type == NEAT_CFG_U32 && d != floor(d))) {
        snprintf(err, err_len, "bad value '%s' for %s: expected %s in [%g, %g]", value, k->name,
                 k->type == NEAT_CFG_U32 ? "an integer" : "a number", k->min, k->max);
        return -1;
    }
    if (k->type == NEAT_CFG_U32)
        *(uint32_t *)field = (uint32_t)d;
    else
        *(double *)field = d;
    return 0;
}

int neat_config_set_in(const neat_cfg_key *keys, size_t n_keys, void *base, const char *key, const char *value,
                       char *err, size_t err_len)
{
    size_t i;
    const char *names[128], *hint;
    for (i = 0; i < n_keys; i++)
        if (strcmp(keys[i].name, key) == 0)
            return neat_config_parse_value(&keys[i], base, value, err, err_len);
    for (i = 0; i < n_keys && i < 128; i++)
        names[i] = keys[i].name;
    hint = neat_config_suggest(key, names, i);
    if (hint != NULL)
        snprintf(err, err_len, "unknown key '%s' (did you mean '%s'?)", key, hint);
    else
        snprintf(err, err_len, "unknown key '%s'", key);
    return -1;
}

int neat_config_has_key(const char *name)
{
    size_t i;
    for (i = 0; i < NEAT_N_KEYS; i++)
        if (strcmp(neat_keys[i].name, name) == 0)
            return 1;
    return 0;
}

int neat_config_set(neat_params *p, const char *key, const char *value, char *err, size_t err_len)
{
    if (strcmp(key, "profile") == 0) {
        /* a profile is a set of switches and values, not one field */
        neat_params tmp = *p;
        if (neat_config_parse_value(&neat_keys[0], &tmp, value, err, err_len) != 0)
            return -1;
        return neat_params_set_profile(p, tmp.profile) == NEAT_OK ? 0 : -1;
    }
    return neat_config_set_in(neat_keys, NEAT_N_KEYS, p, key, value, err, err_len);
}

void neat_fmt_double(char buf[NEAT_FMT_DOUBLE], double x)
{
    int prec;
    /* the fewest significant digits that read back to the same double:
     * 0.3, not 0.29999999999999999 (17 digits always do) */
    for (prec = 1; prec < 17; prec++) {
        snprintf(buf, NEAT_FMT_DOUBLE, "%.*g", prec, x);
        if (strtod(buf, NULL) == x)
            return;
    }
    snprintf(buf, NEAT_FMT_DOUBLE, "%.17g", x);
}

void neat_config_dump_keys(FILE *out, const neat_cfg_key *keys, size_t n_keys, const void *base)
{
    size_t i;
    for (i = 0; i < n_keys; i++) {
        const void *field = (const char *)base + keys[i].offset;
        switch (keys[i].type) {
        case NEAT_CFG_U32:
            fprintf(out, "%s = %u\n", keys[i].name, (unsigned)*(const uint32_t *)field);
            break;
        case NEAT_CFG_F64: {
            char num[NEAT_FMT_DOUBLE];
            neat_fmt_double(num, *(const double *)field);
            fprintf(out, "%s = %s\n", keys[i].name, num);
            break;
        }
        case NEAT_CFG_BOOL:
            fprintf(out, "%s = %s\n", keys[i].name, *(const int *)field ? "true" : "false");
            break;
        case NEAT_CFG_ENUM:
            fprintf(out, "%s = %s\n", keys[i].name, keys[i].names[*(const int *)field]);
            break;
        }
    }
}

void neat_config_dump(FILE *out, const neat_params *p)
{
    /* The keys of NEAT C++ 1.2.1's rules are the table's first (profile) and those from
     * equal_fitness_rule on. A configuration that uses none of them is written as before they existed,
     * byte for byte (run directories' config.ini, experiments' configs/NAME.ini, which resume compares). */
    size_t tail = 1;
    while (tail < NEAT_N_KEYS && strcmp(neat_keys[tail].name, "equal_fitness_rule") != 0)
        tail++;
    if (neat_params_uses_neat_cpp(p))
        neat_config_dump_keys(out, neat_keys, NEAT_N_KEYS, p);
    else
        neat_config_dump_keys(out, neat_keys + 1, tail - 1, p);
}
