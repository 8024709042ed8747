/* duel_world_cfg.c - the [world] section: parsing each rule's key, the whole checked, dumped back, and --world. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "duel_world_cfg.h"
#include "neat_config.h"
#include "neat_ini.h"
#include "duel_text.h"

const char *const duel_world_keys[] = {"rules",        "radius",     "start_west", "start_east",  "start_energy",
                                       "food_energy",  "eat_dist",   "share_dist", "train_food",  "candidates",
                                       "food_range",   "robot_range", "energy_scale", "wall_range"};
const size_t duel_world_n_keys = sizeof duel_world_keys / sizeof duel_world_keys[0];

/* A finite number at s in the syntax of every INI key (neat_config_number_len: no hex, inf or nan), the blanks
 * after it skipped; NULL when there is none. */
static const char *duel_num_of(const char *s, double *v, int integer)
{
    char *end;
    size_t n = neat_config_number_len(s, integer);
    if (n == 0)
        return NULL;
    errno = 0;
    *v = strtod(s, &end);
    if (end != s + n || errno == ERANGE || !isfinite(*v))
        return NULL;
    while (*end == ' ' || *end == '\t')
        end++;
    return end;
}

static const char *duel_num(const char *s, double *v)
{
    return duel_num_of(s, v, 0);
}

/* A length or energy in units, to Q16.16 rounded to nearest; lo..hi units. */
static int duel_q16(const char *s, const char **rest, double lo, double hi, int32_t *out)
{
    double v;
    const char *e = duel_num(s, &v);
    if (e == NULL || v < lo || v > hi)
        return -1;
    *out = (int32_t)floor(v * DUEL_ONE + 0.5);
    *rest = e;
    return 0;
}

static int duel_q16_key(const char *key, const char *value, double lo, double hi, int32_t *out, char *err,
                        size_t err_len)
{
    const char *rest;
    if (duel_q16(value, &rest, lo, hi, out) != 0 || *rest != '\0') {
        snprintf(err, err_len, "[world] %s = '%s': expected a number from %g to %g", key, value, lo, hi);
        return -1;
    }
    return 0;
}

static int duel_u16_key(const char *key, const char *value, uint16_t *out, char *err, size_t err_len)
{
    double v;
    const char *rest = duel_num_of(value, &v, 1);
    if (rest == NULL || *rest != '\0' || v < 1 || v > 65535 || v != floor(v)) {
        snprintf(err, err_len, "[world] %s = '%s': expected a whole number of units from 1 to 65535", key, value);
        return -1;
    }
    *out = (uint16_t)v;
    return 0;
}

/* "x y heading": a start */
static int duel_start_key(duel_rules *r, int side, const char *key, const char *value, char *err, size_t err_len)
{
    const char *p = value;
    int32_t x, y;
    double deg;
    if (duel_q16(p, &p, -32000, 32000, &x) != 0 || duel_q16(p, &p, -32000, 32000, &y) != 0 ||
        (p = duel_num(p, &deg)) == NULL || *p != '\0' || fabs(deg) > 1e6) {
        snprintf(err, err_len, "[world] %s = '%s': expected x y heading (units, units, degrees)", key, value);
        return -1;
    }
    r->start_x[side] = x;
    r->start_y[side] = y;
    /* degrees to a binary angle, rounded to nearest, modulo a turn: the
     * dump's exact decimal of a binary angle reads back to the same angle */
    deg = fmod(deg, 360.0);
    if (deg < 0)
        deg += 360.0;
    r->start_heading[side] = (uint32_t)(uint64_t)floor(deg * 4294967296.0 / 360.0 + 0.5);
    return 0;
}

/* "x y, x y, ...": at most max positions (exactly max when exact), or "none" */
static int duel_list_key(const char *key, const char *value, int32_t *xs, int32_t *ys, uint32_t max, int exact,
                         uint32_t *n, char *err, size_t err_len)
{
    const char *p = value;
    uint32_t k = 0;
    if (!exact && strcmp(value, "none") == 0) {
        *n = 0;
        return 0;
    }
    for (;;) {
        int32_t x, y;
        if (k == max) {
            snprintf(err, err_len, "[world] %s: more than %u positions", key, max);
            return -1;
        }
        if (duel_q16(p, &p, -32000, 32000, &x) != 0 || duel_q16(p, &p, -32000, 32000, &y) != 0 ||
            (*p != ',' && *p != '\0')) {
            snprintf(err, err_len, "[world] %s: position %u: expected \"x y\" pairs separated by commas%s", key,
                     k + 1, exact ? "" : " (or none)");
            return -1;
        }
        xs[k] = x;
        ys[k] = y;
        k++;
        if (*p == '\0')
            break;
        p++;
        while (*p == ' ' || *p == '\t')
            p++;
    }
    if (exact && k != max) {
        snprintf(err, err_len, "[world] %s: %u positions, expected exactly %u", key, k, max);
        return -1;
    }
    *n = k;
    return 0;
}

int duel_world_set(duel_rules *r, const char *key, const char *value, char *err, size_t err_len)
{
    uint32_t n;
    if (strcmp(key, "rules") == 0) {
        const duel_rules *named = duel_rules_named(value);
        if (named == NULL) {
            snprintf(err, err_len, "[world] rules = '%s': unknown world (known: v1)", value);
            return -1;
        }
        *r = *named;
        return 0;
    }
    if (strcmp(key, "radius") == 0)
        return duel_q16_key(key, value, 0, 32000, &r->radius, err, err_len);
    if (strcmp(key, "start_west") == 0)
        return duel_start_key(r, DUEL_WEST, key, value, err, err_len);
    if (strcmp(key, "start_east") == 0)
        return duel_start_key(r, DUEL_EAST, key, value, err, err_len);
    if (strcmp(key, "start_energy") == 0)
        return duel_q16_key(key, value, 0, 32000, &r->start_energy, err, err_len);
    if (strcmp(key, "food_energy") == 0)
        return duel_q16_key(key, value, 0, 32000, &r->food_energy, err, err_len);
    if (strcmp(key, "eat_dist") == 0)
        return duel_q16_key(key, value, 0, 32000, &r->eat_dist, err, err_len);
    if (strcmp(key, "share_dist") == 0)
        return duel_q16_key(key, value, 0, 32000, &r->share_dist, err, err_len);
    if (strcmp(key, "train_food") == 0) {
        int32_t xs[DUEL_MAX_TRAIN_FOOD], ys[DUEL_MAX_TRAIN_FOOD];
        if (duel_list_key(key, value, xs, ys, DUEL_MAX_TRAIN_FOOD, 0, &n, err, err_len) != 0)
            return -1;
        memset(r->train_x, 0, sizeof r->train_x);
        memset(r->train_y, 0, sizeof r->train_y);
        memcpy(r->train_x, xs, n * sizeof xs[0]);
        memcpy(r->train_y, ys, n * sizeof ys[0]);
        r->n_train = n;
        return 0;
    }
    if (strcmp(key, "candidates") == 0)
        return duel_list_key(key, value, r->cand_x, r->cand_y, DUEL_CANDIDATES, 1, &n, err, err_len);
    if (strcmp(key, "food_range") == 0)
        return duel_u16_key(key, value, &r->food_range, err, err_len);
    if (strcmp(key, "robot_range") == 0)
        return duel_u16_key(key, value, &r->robot_range, err, err_len);
    if (strcmp(key, "energy_scale") == 0)
        return duel_u16_key(key, value, &r->energy_scale, err, err_len);
    if (strcmp(key, "wall_range") == 0)
        return duel_u16_key(key, value, &r->wall_range, err, err_len);
    {
        const char *near = neat_config_suggest(key, duel_world_keys, duel_world_n_keys);
        if (near != NULL)
            snprintf(err, err_len, "unknown key '%s' in [world] (did you mean '%s'?)", key, near);
        else
            snprintf(err, err_len, "unknown key '%s' in [world]", key);
    }
    return -1;
}

int duel_world_check(const duel_rules *r, char *err, size_t err_len)
{
    const char *field = NULL, *why = NULL;
    if (duel_rules_check(r, &field, &why) == DUEL_OK)
        return 0;
    snprintf(err, err_len, "[world] %s: %s", field, why);
    return -1;
}

/* x (a binary fraction: a Q16.16 value, a binary angle in degrees) in
 * plain decimals, the fewest that read back to x exactly: 10, 0.5, 33.3 */
static void duel_put_exact(FILE *out, double x)
{
    char b[80];
    int prec;
    for (prec = 0; prec < 40; prec++) {
        snprintf(b, sizeof b, "%.*f", prec, x);
        if (strtod(b, NULL) == x)
            break;
    }
    fputs(b, out);
}

static void duel_put_q16(FILE *out, int32_t v)
{
    duel_put_exact(out, (double)v / DUEL_ONE);
}

static void duel_put_start(FILE *out, const duel_rules *r, int side)
{
    fprintf(out, "start_%s = ", side == DUEL_WEST ? "west" : "east");
    duel_put_q16(out, r->start_x[side]);
    fputc(' ', out);
    duel_put_q16(out, r->start_y[side]);
    fputc(' ', out);
    duel_put_exact(out, (double)r->start_heading[side] * 360.0 / 4294967296.0);
    fputc('\n', out);
}

static void duel_put_list(FILE *out, const char *key, const int32_t *xs, const int32_t *ys, uint32_t n)
{
    uint32_t i;
    fprintf(out, "%s = ", key);
    if (n == 0)
        fputs("none", out);
    for (i = 0; i < n; i++) {
        if (i > 0)
            fputs(", ", out);
        duel_put_q16(out, xs[i]);
        fputc(' ', out);
        duel_put_q16(out, ys[i]);
    }
    fputc('\n', out);
}

const char *duel_world_label(const duel_rules *r, char *buf, size_t cap)
{
    const char *name = duel_rules_name(r);
    if (name != NULL)
        snprintf(buf, cap, "%s", name);
    else
        snprintf(buf, cap, "custom %016llx", (unsigned long long)duel_rules_id(r));
    return buf;
}

void duel_world_dump(FILE *out, const duel_rules *r)
{
    const char *name = duel_rules_name(r);
    if (name != NULL)
        fprintf(out, "; world %s (identity %016llx): every rule below, docs/duel-world.md\n", name,
                (unsigned long long)duel_rules_id(r));
    else
        fprintf(out, "; a world of its own (identity %016llx), world v1 with the changes below (docs/duel-world.md)\n",
                (unsigned long long)duel_rules_id(r));
    fprintf(out, "rules = %s\n", name != NULL ? name : "v1");
    fputs("radius = ", out);
    duel_put_q16(out, r->radius);
    fputc('\n', out);
    duel_put_start(out, r, DUEL_WEST);
    duel_put_start(out, r, DUEL_EAST);
    fputs("start_energy = ", out);
    duel_put_q16(out, r->start_energy);
    fputs("\nfood_energy = ", out);
    duel_put_q16(out, r->food_energy);
    fputs("\neat_dist = ", out);
    duel_put_q16(out, r->eat_dist);
    fputs("\nshare_dist = ", out);
    duel_put_q16(out, r->share_dist);
    fputc('\n', out);
    duel_put_list(out, "train_food", r->train_x, r->train_y, r->n_train);
    duel_put_list(out, "candidates", r->cand_x, r->cand_y, DUEL_CANDIDATES);
    fprintf(out, "food_range = %u\nrobot_range = %u\nenergy_scale = %u\nwall_range = %u\n", r->food_range,
            r->robot_range, r->energy_scale, r->wall_range);
}

/* ---- --world ---- */

typedef struct duel_world_file {
    duel_rules *r;
    int seen;
} duel_world_file;

static int duel_world_ini(void *user, const char *section, const char *key, const char *value, char *err,
                          size_t err_len)
{
    duel_world_file *f = (duel_world_file *)user;
    if (strcmp(section, "world") != 0)
        return 0;
    f->seen = 1;
    return duel_world_set(f->r, key, value, err, err_len);
}

/* the [world] of path over v1; *seen whether it had one. 0, or -1 with the line in msg (printed through
 * duel_esc_msg) */
static int duel_world_read_msg(duel_rules *r, const char *path, int *seen, char *out, size_t cap)
{
    char err[600], msg[400], esc[1100];
    duel_world_file f;
    *r = *duel_rules_v1();
    f.r = r;
    f.seen = 0;
    if (neat_ini_parse_file(path, duel_world_ini, &f, err, sizeof err) != 0) {
        snprintf(out, cap, "%s", err);
        return -1;
    }
    if (duel_world_check(r, msg, sizeof msg) != 0) {
        snprintf(out, cap, "%s: %s", duel_text_escape(path, esc, sizeof esc), msg);
        return -1;
    }
    *seen = f.seen;
    return 0;
}

static int duel_world_read(duel_rules *r, const char *path, int *seen)
{
    char msg[1700];
    if (duel_world_read_msg(r, path, seen, msg, sizeof msg) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return -1;
}

int duel_world_arg(duel_rules *r, const char *spec)
{
    const duel_rules *named = duel_rules_named(spec);
    int seen;
    if (named != NULL) {
        *r = *named;
        return 0;
    }
    if (strchr(spec, '/') == NULL && strchr(spec, '.') == NULL) {
        fprintf(stderr, "duel_evolve: --world %s: no such world (known: v1) and not a file path\n", duel_esc(spec));
        return -1;
    }
    if (duel_world_read(r, spec, &seen) != 0)
        return -1;
    if (!seen) {
        fprintf(stderr, "duel_evolve: --world %s: the file has no [world] section\n", duel_esc(spec));
        return -1;
    }
    return 0;
}

int duel_world_of_run_msg(duel_rules *r, const char *run_dir, char *msg, size_t cap)
{
    char path[4200], esc[1100];
    int seen;
    if ((size_t)snprintf(path, sizeof path, "%s/config.ini", run_dir) >= sizeof path) {
        snprintf(msg, cap, "%s: the path is too long", duel_text_escape(run_dir, esc, sizeof esc));
        return -1;
    }
    return duel_world_read_msg(r, path, &seen, msg, cap);
}

int duel_world_of_run(duel_rules *r, const char *run_dir)
{
    char msg[1700];
    if (duel_world_of_run_msg(r, run_dir, msg, sizeof msg) == 0)
        return 0;
    fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
    return -1;
}
