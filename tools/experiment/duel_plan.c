/* duel_plan.c - an experiment's plan read from its INI file (or from an experiment directory), each method's run configuration built from its preset and the overrides. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "duel_files.h"
#include "duel_outputs.h"
#include "duel_plan.h"
#include "duel_runtag.h"
#include "duel_world_cfg.h"
#include "duel_text.h"
#include "neat_ini.h"

#define DUEL_PLAN_HEADER DUEL_EXP_PLAN_MARK " (duel_evolve experiment): its methods' run configurations are configs/NAME.ini\n"
#define DUEL_PLAN_CFG_HEADER DUEL_RUN_CONFIG_MARK " (duel_evolve config --dump format)\n"

typedef struct duel_plan_reader {
    duel_plan *p;
    int in_all, in_experiment, method; /* the section: method index, or -1 */
    int have_runs[DUEL_PLAN_MAX_METHODS], have_preset[DUEL_PLAN_MAX_METHODS];
    int from_dir; /* plan.ini of an experiment directory: presets are not read */
    char dir[4200]; /* the plan's directory: what a relative start path is relative to */
} duel_plan_reader;

static int duel_plan_name_ok(const char *s)
{
    size_t n = strlen(s), k;
    if (n == 0 || n > DUEL_PLAN_MAX_NAME)
        return 0;
    for (k = 0; k < n; k++)
        if (!((s[k] >= 'a' && s[k] <= 'z') || (s[k] >= 'A' && s[k] <= 'Z') || (s[k] >= '0' && s[k] <= '9') ||
              s[k] == '-' || s[k] == '_'))
            return 0;
    return 1;
}

static int duel_plan_u32(const char *v, uint32_t lo, uint32_t hi, uint32_t *out)
{
    char *end;
    unsigned long x;
    if (*v < '0' || *v > '9')
        return -1;
    errno = 0;
    x = strtoul(v, &end, 10);
    if (*end != '\0' || errno || x < lo || x > hi)
        return -1;
    *out = (uint32_t)x;
    return 0;
}

static int duel_plan_add_set(char (*sets)[DUEL_PLAN_SET_LEN], uint32_t *n, const char *key, const char *value,
                             char *err, size_t err_len)
{
    if (strcmp(key, "seed") == 0 || strcmp(key, "run.seed") == 0) {
        /* every run would be given it, and it would be replaced by the experiment's: refused, not ignored */
        snprintf(err, err_len, "%s = %s: the runs of an experiment take their seeds from [experiment] seed (run k of "
                               "a method plays with seed + k - 1): set it there, or give --set seed=N on the command "
                               "line", key, value);
        return -1;
    }
    if (*n == DUEL_PLAN_MAX_SETS) {
        snprintf(err, err_len, "more than %d overrides in one section", DUEL_PLAN_MAX_SETS);
        return -1;
    }
    if (strlen(key) + strlen(value) + 2 > DUEL_PLAN_SET_LEN) {
        snprintf(err, err_len, "'%s': too long", key);
        return -1;
    }
    snprintf(sets[(*n)++], DUEL_PLAN_SET_LEN, "%s=%s", key, value);
    return 0;
}

/* An override "start=blob:PATH" or "start=genome:PATH" (or "neat.start=...") whose PATH is relative: made
 * absolute against base, once, when the plan is read; each run then opens that file whatever its working
 * directory (the experiment's), and plan.ini stores it so. The file must exist now. 0, or -1 with err. */
static int duel_plan_resolve_start(char *set, const char *base, char *err, size_t err_len)
{
    const char *eq = strchr(set, '='), *path;
    char joined[8600], real[4200];
    size_t klen = eq != NULL ? (size_t)(eq - set) : 0, plen;
    if (eq == NULL || !((klen == 5 && strncmp(set, "start", 5) == 0) || (klen == 10 && strncmp(set, "neat.start", 10) == 0)))
        return 0;
    path = strncmp(eq + 1, "blob:", 5) == 0 ? eq + 6 : strncmp(eq + 1, "genome:", 7) == 0 ? eq + 8 : NULL;
    if (path == NULL || path[0] == '/' || path[0] == '\0')
        return 0;
    if ((size_t)snprintf(joined, sizeof joined, "%s/%s", base, path) >= sizeof joined ||
        realpath(joined, real) == NULL) {
        snprintf(err, err_len, "%s (relative to %s): %s", set, base,
                 strlen(joined) >= sizeof joined - 1 ? "path too long" : strerror(errno));
        return -1;
    }
    plen = (size_t)(path - set);
    if (plen + strlen(real) + 1 > DUEL_PLAN_SET_LEN) {
        snprintf(err, err_len, "%.*s: %s: too long once made absolute (%s)", (int)plen, set, path, real);
        return -1;
    }
    strcpy(set + plen, real);
    return 0;
}

/* An override "play=..." (or "opponents.play=...") whose opponents include relative paths: each made absolute
 * against base, as start paths are (a same-named file where the runs work is never the one used); builtins stay.
 * Each file must exist now. 0, or -1 with err. */
static int duel_plan_resolve_play(char *set, const char *base, char *err, size_t err_len)
{
    const char *eq = strchr(set, '='), *p;
    char out[DUEL_PLAN_SET_LEN], joined[8600], real[4200];
    size_t klen = eq != NULL ? (size_t)(eq - set) : 0, n;
    if (eq == NULL || !((klen == 4 && strncmp(set, "play", 4) == 0) ||
                        (klen == 14 && strncmp(set, "opponents.play", 14) == 0)))
        return 0;
    for (p = eq + 1; *p != '\0'; p++)
        if ((unsigned char)*p < 0x20 || *p == 0x7f)
            return 0; /* refused, naming the byte, by the [opponents] reader (duel_plan_try_set) */
    n = (size_t)snprintf(out, sizeof out, "%.*s", (int)(klen + 1), set);
    for (p = eq + 1; *p != '\0';) {
        const char *at;
        char item[4200];
        size_t len;
        int comma = duel_list_next(&p, &at, &len), first = n == klen + 1;
        if (len >= sizeof item)
            len = sizeof item - 1; /* refused by the [opponents] reader as too long */
        snprintf(item, sizeof item, "%.*s", (int)len, at);
        if (item[0] != '\0' && item[0] != '/' && strncmp(item, "builtin:", 8) != 0) {
            if ((size_t)snprintf(joined, sizeof joined, "%s/%s", base, item) >= sizeof joined ||
                realpath(joined, real) == NULL) {
                snprintf(err, err_len, "play: %s (relative to %s): %s", item, base,
                         strlen(joined) >= sizeof joined - 1 ? "path too long" : strerror(errno));
                return -1;
            }
            snprintf(item, sizeof item, "%s", real);
        }
        n += (size_t)snprintf(out + n, n < sizeof out ? sizeof out - n : 0, "%s%s", first ? "" : ", ", item);
        if (n >= sizeof out) {
            snprintf(err, err_len, "play: too long once its paths are made absolute");
            return -1;
        }
        if (!comma)
            break;
    }
    memcpy(set, out, n + 1);
    return 0;
}

/* Each override is tried on a default configuration at once, so that an unknown key names its line. */
static int duel_plan_try_set(const char *set, char *err, size_t err_len)
{
    duel_config c;
    duel_config_default(&c);
    return duel_config_set(&c, set, err, err_len);
}

static int duel_plan_handler(void *user, const char *section, const char *key, const char *value, char *err,
                             size_t err_len)
{
    duel_plan_reader *r = (duel_plan_reader *)user;
    duel_plan *p = r->p;
    duel_plan_method *m;
    if (strcmp(section, "experiment") == 0) {
        if (strcmp(key, "reference") == 0) {
            if (!duel_plan_name_ok(value)) {
                snprintf(err, err_len, "reference = '%s': not a method name", value);
                return -1;
            }
            strcpy(p->reference, value);
        } else if (strcmp(key, "seed") == 0) {
            if (duel_plan_u32(value, 0, 0xffffffffu, &p->seed) != 0) {
                snprintf(err, err_len, "seed = '%s': expected 0 to 4294967295", value);
                return -1;
            }
        } else if (strcmp(key, "presets") == 0 && !r->from_dir) {
            if (strlen(value) >= sizeof p->presets) {
                snprintf(err, err_len, "presets: a path too long");
                return -1;
            }
            strcpy(p->presets, value);
        } else {
            snprintf(err, err_len, "unknown key '%s' in [experiment] (reference, seed, presets)", key);
            return -1;
        }
        return 0;
    }
    if (strcmp(section, "all runs") == 0) {
        if (duel_plan_add_set(p->sets, &p->n_sets, key, value, err, err_len) != 0 ||
            (!r->from_dir && (duel_plan_resolve_start(p->sets[p->n_sets - 1], r->dir, err, err_len) != 0 ||
                              duel_plan_resolve_play(p->sets[p->n_sets - 1], r->dir, err, err_len) != 0)))
            return -1;
        return duel_plan_try_set(p->sets[p->n_sets - 1], err, err_len);
    }
    if (strncmp(section, "method ", 7) != 0) {
        snprintf(err, err_len, "unknown section [%s] ([experiment], [all runs], [method NAME])", section);
        return -1;
    }
    section += 7;
    while (*section == ' ')
        section++;
    if (!duel_plan_name_ok(section)) {
        snprintf(err, err_len, "[method %s]: a method's name is 1 to %d letters, digits, '-' or '_'", section,
                 DUEL_PLAN_MAX_NAME);
        return -1;
    }
    if (p->n_methods == 0 || strcmp(p->m[p->n_methods - 1].name, section) != 0) {
        uint32_t k;
        for (k = 0; k < p->n_methods; k++)
            if (strcmp(p->m[k].name, section) == 0) {
                snprintf(err, err_len, "[method %s] a second time", section);
                return -1;
            }
        if (p->n_methods == DUEL_PLAN_MAX_METHODS) {
            snprintf(err, err_len, "more than %d methods", DUEL_PLAN_MAX_METHODS);
            return -1;
        }
        strcpy(p->m[p->n_methods++].name, section);
    }
    m = &p->m[p->n_methods - 1];
    if (strcmp(key, "preset") == 0) {
        if (!duel_plan_name_ok(value)) {
            snprintf(err, err_len, "preset = '%s': a preset's name (configs/NAME.ini without .ini)", value);
            return -1;
        }
        strcpy(m->preset, value);
        r->have_preset[p->n_methods - 1] = 1;
    } else if (strcmp(key, "runs") == 0) {
        if (duel_plan_u32(value, 1, DUEL_PLAN_MAX_RUNS, &m->runs) != 0) {
            snprintf(err, err_len, "runs = '%s': expected 1 to %d", value, DUEL_PLAN_MAX_RUNS);
            return -1;
        }
        r->have_runs[p->n_methods - 1] = 1;
    } else if (strcmp(key, "start") == 0 && strcmp(value, "best") == 0) {
        m->start_best = 1;
    } else {
        if (duel_plan_add_set(m->sets, &m->n_sets, key, value, err, err_len) != 0 ||
            (!r->from_dir && (duel_plan_resolve_start(m->sets[m->n_sets - 1], r->dir, err, err_len) != 0 ||
                              duel_plan_resolve_play(m->sets[m->n_sets - 1], r->dir, err, err_len) != 0)))
            return -1;
        return duel_plan_try_set(m->sets[m->n_sets - 1], err, err_len);
    }
    return 0;
}

/* Directory part of path ("." when none). */
static void duel_plan_dirname(const char *path, char *out, size_t cap)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL)
        snprintf(out, cap, ".");
    else if (slash == path)
        snprintf(out, cap, "/");
    else
        snprintf(out, cap, "%.*s", (int)(slash - path), path);
}

static char *duel_plan_cfg_text(const duel_config *cfg)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (mem == NULL)
        return NULL;
    fputs(DUEL_PLAN_CFG_HEADER, mem);
    duel_config_dump(mem, cfg);
    if (fclose(mem) != 0) {
        free(text);
        return NULL;
    }
    return text;
}

/* The plan's [all runs] overrides, then the method's, on cfg: one list, so that a profile among
 * them comes first (duel_config_set_list). 0, or -1 with err. */
static int duel_plan_apply_sets(const duel_plan *p, const duel_plan_method *m, duel_config *cfg, char *err,
                                size_t err_len)
{
    const char *all[2 * DUEL_PLAN_MAX_SETS];
    uint32_t k, n = 0;
    for (k = 0; k < p->n_sets && n < 2 * DUEL_PLAN_MAX_SETS; k++)
        all[n++] = p->sets[k];
    for (k = 0; k < m->n_sets && n < 2 * DUEL_PLAN_MAX_SETS; k++)
        all[n++] = m->sets[k];
    return duel_config_set_list(cfg, all, n, NULL, err, err_len);
}

/* An experiment directory's plan.ini and its configs/NAME.ini must say the same: the configuration with plan.ini's
 * overrides applied again is the configuration. An edit of either after the experiment started would be ignored
 * (plan.ini) or taken by the runs not yet begun only (configs/): refused instead. 0, or -1 with err. */
static int duel_plan_agrees(const duel_plan *p, const duel_plan_method *m, const char *path, char *err,
                            size_t err_len)
{
    duel_config c = m->cfg;
    char msg[1200], la[300], lb[300], *text;
    uint32_t line;
    if (duel_plan_apply_sets(p, m, &c, msg, sizeof msg) != 0) {
        snprintf(err, err_len, "[method %s]: plan.ini: %s", m->name, msg);
        return -1;
    }
    c.seed = p->seed;
    if (m->start_best) {
        c.start.kind = DUEL_START_BLOB;
        strcpy(c.start.path, DUEL_PLAN_BEST_BLOB);
    }
    text = duel_plan_cfg_text(&c);
    if (text == NULL) {
        snprintf(err, err_len, "out of memory");
        return -1;
    }
    line = duel_plan_diff(m->cfg_text, text, la, lb, sizeof la);
    free(text);
    if (line != 0) {
        snprintf(err, err_len, "%s says '%s' but plan.ini makes '%s' (line %u): the plan of an experiment cannot "
                               "change once it started (restore them; a changed plan is a new experiment directory)",
                 path, la, lb, line);
        return -1;
    }
    return 0;
}

/* configs/NAME.ini's first line names the preset it was made from (a directory made before the mark has none:
 * nothing to check); plan.ini's preset = must name the same. 0, or -1 with err. */
static int duel_plan_same_preset(const duel_plan_method *m, const char *path, char *err, size_t err_len)
{
    uint8_t *text;
    size_t len, mark = strlen(DUEL_PLAN_PRESET_MARK), n;
    if (duel_file_read(path, 1u << 20, &text, &len) != 0)
        return 0; /* duel_config_read has read it already: a file gone since is found by the runs */
    if (len < mark || memcmp(text, DUEL_PLAN_PRESET_MARK, mark) != 0) {
        free(text);
        return 0;
    }
    for (n = mark; n < len && text[n] != '\n'; n++)
        ;
    if (n - mark != strlen(m->preset) || memcmp(text + mark, m->preset, n - mark) != 0) {
        snprintf(err, err_len, "plan.ini says preset = %s but %s was made from preset %.*s: the plan of an "
                               "experiment cannot change once it started (restore plan.ini; a changed plan is a new "
                               "experiment directory)",
                 m->preset, path, (int)(n - mark > 64 ? 64 : n - mark), (const char *)text + mark);
        free(text);
        return -1;
    }
    free(text);
    return 0;
}

/* Every method's configuration: its preset (or, from_dir, DIR/configs/NAME.ini), [all runs], its keys. */
static int duel_plan_build(duel_plan *p, const char *base, int from_dir, char *err, size_t err_len)
{
    uint32_t i;
    char path[8400], msg[1200];
    for (i = 0; i < p->n_methods; i++) {
        duel_plan_method *m = &p->m[i];
        int n;
        duel_config_default(&m->cfg);
        if (from_dir)
            n = snprintf(path, sizeof path, "%s/configs/%s.ini", base, m->name);
        else
            n = snprintf(path, sizeof path, "%s/%s.ini", base, m->preset);
        if (n < 0 || (size_t)n >= sizeof path) {
            snprintf(err, err_len, "[method %s]: the path of its configuration is longer than %zu bytes", m->name,
                     sizeof path - 1);
            return -1;
        }
        if (duel_config_read(&m->cfg, path, msg, sizeof msg) != 0) {
            snprintf(err, err_len, "[method %s]: %s", m->name, msg);
            return -1;
        }
        if (!from_dir && duel_plan_apply_sets(p, m, &m->cfg, msg, sizeof msg) != 0) {
            snprintf(err, err_len, "[method %s]: %s", m->name, msg);
            return -1;
        }
        if (!from_dir) {
            m->cfg.seed = p->seed;
            if (m->start_best) {
                m->cfg.start.kind = DUEL_START_BLOB;
                strcpy(m->cfg.start.path, DUEL_PLAN_BEST_BLOB);
            }
        }
        if (duel_config_check(&m->cfg, msg, sizeof msg) != 0) {
            snprintf(err, err_len, "[method %s] (%s): %s", m->name, path, msg);
            return -1;
        }
        /* the start topology opened and checked now, as each run will (start = best is made by the reference) */
        if (!m->start_best && m->cfg.opp.n == 0) {
            neat_coev *c = NULL;
            duel_config first; /* generation 0's parameters: [overrides] come later in each run */
            int e = duel_config_at(&m->cfg, 0, &first, msg, sizeof msg) != 0 ? 2 : duel_coev_new(&c, &first, msg, sizeof msg);
            neat_coev_free(c);
            if (e != 0) {
                snprintf(err, err_len, "[method %s]: %s", m->name, msg);
                return -1;
            }
        }
        m->cfg_text = duel_plan_cfg_text(&m->cfg);
        if (m->cfg_text == NULL) {
            snprintf(err, err_len, "out of memory");
            return -1;
        }
        if (from_dir && (duel_plan_same_preset(m, path, err, err_len) != 0 ||
                         duel_plan_agrees(p, m, path, err, err_len) != 0))
            return -1;
        /* every method can be measured: the report compares each method's dominants with the reference's
         * rankings in one world, so a method without a dominance tournament, or of another world, is refused
         * now, not after its runs */
        if (m->cfg.opp.n > 0) {
            snprintf(err, err_len, "[method %s]: a run against fixed opponents ([opponents] play) has no dominance "
                                   "tournament, and an experiment measures every method by its dominants against "
                                   "the %s rankings: run it with duel_evolve run instead", m->name,
                     p->reference[0] != '\0' ? p->reference : p->m[0].name);
            return -1;
        }
        if (i > 0 && !duel_rules_equal(&m->cfg.world, &p->m[0].cfg.world)) {
            char a[40], b[40];
            snprintf(err, err_len, "[method %s] plays in world %s but [method %s] in world %s: an experiment "
                                   "compares its methods in one world", m->name,
                     duel_world_label(&m->cfg.world, a, sizeof a), p->m[0].name,
                     duel_world_label(&p->m[0].cfg.world, b, sizeof b));
            return -1;
        }
    }
    return 0;
}

/* The plan at path (from_dir: an experiment directory's plan.ini, configurations from base/configs), the extra
 * overrides after [all runs], every method's configuration built. */
/* The plan's text (a file at path, or len bytes of text named path), parsed, the extra overrides added and the
 * whole checked; no configuration is built. */
static int duel_plan_parse(duel_plan **out, const char *path, const char *text, size_t text_len, int from_dir,
                           const char *const *extra, uint32_t n_extra, char *err, size_t err_len)
{
    duel_plan_reader r;
    duel_plan *p = (duel_plan *)calloc(1, sizeof *p);
    char msg[1200];
    uint32_t i, k;
    *out = p;
    if (p == NULL) {
        snprintf(err, err_len, "out of memory");
        return -1;
    }
    p->seed = 1;
    memset(&r, 0, sizeof r);
    r.p = p;
    r.from_dir = from_dir;
    duel_plan_dirname(path, r.dir, sizeof r.dir);
    if ((text != NULL ? neat_ini_parse_text(path, text, text_len, duel_plan_handler, &r, err, err_len)
                      : neat_ini_parse_file(path, duel_plan_handler, &r, err, err_len)) != 0)
        return -1;
    for (i = 0; i < n_extra; i++) {
        const char *eq = strchr(extra[i], '=');
        char key[DUEL_PLAN_SET_LEN];
        if (eq == NULL || eq == extra[i] || (size_t)(eq - extra[i]) >= sizeof key) {
            snprintf(err, err_len, "--set '%s': expected key=value or section.key=value", extra[i]);
            return -1;
        }
        snprintf(key, sizeof key, "%.*s", (int)(eq - extra[i]), extra[i]);
        if (strcmp(key, "seed") == 0 || strcmp(key, "run.seed") == 0 || strcmp(key, "experiment.seed") == 0) {
            /* the experiment's seed: run k of each method plays with seed + k - 1 */
            if (duel_plan_u32(eq + 1, 0, 0xffffffffu, &p->seed) != 0) {
                char e[1100];
                snprintf(err, err_len, "--set %s: expected 0 to 4294967295", duel_text_escape(extra[i], e, sizeof e));
                return -1;
            }
            continue;
        }
        if (duel_plan_try_set(extra[i], msg, sizeof msg) != 0) {
            {
                char e[1100];
                snprintf(err, err_len, "--set %s: %s", duel_text_escape(extra[i], e, sizeof e), msg);
            }
            return -1;
        }
        /* a key [all runs] has already gets the new value in its place: plan.ini holds each key once */
        for (k = 0; k < p->n_sets; k++)
            if (strncmp(p->sets[k], key, strlen(key)) == 0 && p->sets[k][strlen(key)] == '=')
                break;
        if (k < p->n_sets) {
            if (strlen(extra[i]) >= DUEL_PLAN_SET_LEN) {
                snprintf(err, err_len, "--set %s: too long", key);
                return -1;
            }
            snprintf(p->sets[k], DUEL_PLAN_SET_LEN, "%s", extra[i]);
        } else if (duel_plan_add_set(p->sets, &p->n_sets, key, eq + 1, msg, sizeof msg) != 0) {
            {
                char e[1100];
                snprintf(err, err_len, "--set %s: %s", duel_text_escape(extra[i], e, sizeof e), msg);
            }
            return -1;
        } else {
            k = p->n_sets - 1;
        }
        /* a path on the command line is the working directory's */
        if (duel_plan_resolve_start(p->sets[k], ".", msg, sizeof msg) != 0 ||
            duel_plan_resolve_play(p->sets[k], ".", msg, sizeof msg) != 0) {
            {
                char e[1100];
                snprintf(err, err_len, "--set %s: %s", duel_text_escape(extra[i], e, sizeof e), msg);
            }
            return -1;
        }
    }
    if (p->n_methods == 0) {
        snprintf(err, err_len, "%s: no [method NAME] section: a plan needs at least one method", path);
        return -1;
    }
    for (i = 0; i < p->n_methods; i++)
        if (!r.have_runs[i] || !r.have_preset[i]) {
            snprintf(err, err_len, "%s: [method %s] needs %s", path, p->m[i].name,
                     r.have_preset[i] ? "runs = N" : "preset = NAME");
            return -1;
        }
    if (p->reference[0] == '\0')
        strcpy(p->reference, p->m[0].name);
    for (p->ref = 0; p->ref < p->n_methods && strcmp(p->m[p->ref].name, p->reference) != 0; p->ref++)
        ;
    if (p->ref == p->n_methods) {
        snprintf(err, err_len, "%s: reference = %s names no [method %s]", path, p->reference, p->reference);
        return -1;
    }
    if (p->m[p->ref].start_best) {
        snprintf(err, err_len, "%s: the reference method %s cannot start from its own best champion (start = best)",
                 path, p->reference);
        return -1;
    }
    if (p->m[p->ref].runs < 2) {
        snprintf(err, err_len, "%s: the reference method %s needs at least 2 runs (each run is measured against the "
                 "others' rankings)", path, p->reference);
        return -1;
    }
    return 0;
}

int duel_plan_parse_text(duel_plan **out, const char *name, const char *text, size_t len, char *err, size_t err_len)
{
    return duel_plan_parse(out, name, text, len, 0, NULL, 0, err, err_len);
}

static int duel_plan_read(duel_plan **out, const char *path, int from_dir, const char *base,
                          const char *const *extra, uint32_t n_extra, char *err, size_t err_len)
{
    duel_plan *p;
    if (duel_plan_parse(out, path, NULL, 0, from_dir, extra, n_extra, err, err_len) != 0)
        return -1;
    p = *out;
    if (!from_dir) {
        char dir[4200], presets[8400];
        duel_plan_dirname(path, dir, sizeof dir);
        if (p->presets[0] == '/')
            snprintf(presets, sizeof presets, "%s", p->presets);
        else
            snprintf(presets, sizeof presets, "%s/%s", dir, p->presets[0] ? p->presets : ".");
        return duel_plan_build(p, presets, 0, err, err_len);
    }
    return duel_plan_build(p, base, 1, err, err_len);
}

int duel_plan_load(duel_plan **out, const char *path, const char *const *extra, uint32_t n_extra, char *err,
                   size_t err_len)
{
    return duel_plan_read(out, path, 0, NULL, extra, n_extra, err, err_len);
}

int duel_plan_load_dir(duel_plan **out, const char *dir, char *err, size_t err_len)
{
    char path[4200];
    struct stat st;
    int n = snprintf(path, sizeof path, "%s/plan.ini", dir);
    *out = NULL;
    if (n < 0 || (size_t)n >= sizeof path) {
        snprintf(err, err_len, "%.64s...: the experiment directory's path is longer than %zu bytes", dir,
                 sizeof path - sizeof "/plan.ini");
        return -1;
    }
    if (stat(path, &st) != 0 && errno == ENOENT) {
        snprintf(err, err_len, "%s: not an experiment directory (no plan.ini)", dir);
        return -1;
    }
    return duel_plan_read(out, path, 1, dir, NULL, 0, err, err_len);
}

void duel_plan_free(duel_plan *p)
{
    uint32_t i;
    if (p == NULL)
        return;
    for (i = 0; i < p->n_methods; i++)
        free(p->m[i].cfg_text);
    free(p);
}

char *duel_plan_text(const duel_plan *p)
{
    char *text = NULL;
    size_t len = 0;
    uint32_t i, k;
    FILE *mem = open_memstream(&text, &len);
    if (mem == NULL)
        return NULL;
    fprintf(mem, "%s[experiment]\nreference = %s\nseed = %u\n", DUEL_PLAN_HEADER, p->reference, p->seed);
    if (p->n_sets > 0)
        fprintf(mem, "\n[all runs]\n");
    for (k = 0; k < p->n_sets; k++) {
        const char *eq = strchr(p->sets[k], '=');
        fprintf(mem, "%.*s = %s\n", (int)(eq - p->sets[k]), p->sets[k], eq + 1);
    }
    for (i = 0; i < p->n_methods; i++) {
        const duel_plan_method *m = &p->m[i];
        fprintf(mem, "\n[method %s]\npreset = %s\nruns = %u\n", m->name, m->preset, m->runs);
        if (m->start_best)
            fprintf(mem, "start = best\n");
        for (k = 0; k < m->n_sets; k++) {
            const char *eq = strchr(m->sets[k], '=');
            fprintf(mem, "%.*s = %s\n", (int)(eq - m->sets[k]), m->sets[k], eq + 1);
        }
    }
    if (fclose(mem) != 0) {
        free(text);
        return NULL;
    }
    return text;
}

int duel_plan_save(const duel_plan *p, const char *dir)
{
    char path[4200], *text;
    uint32_t i;
    /* Room for the longest file name below, so no snprintf here can truncate (a truncated path would
       write the wrong file); duel_exp passes ".", so this guards other callers. */
    if (strlen(dir) + sizeof "/configs/" + DUEL_PLAN_MAX_NAME + sizeof ".ini" > sizeof path) {
        fprintf(stderr, "duel_evolve: experiment: %.64s...: a directory path longer than %zu bytes\n", duel_esc(dir),
                sizeof path - sizeof "/configs/" - DUEL_PLAN_MAX_NAME - sizeof ".ini");
        return -1;
    }
    text = duel_plan_text(p);
    snprintf(path, sizeof path, "%s/configs", dir);
    if (text == NULL || duel_mkdir(path) != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s: %s\n", duel_esc(path), text == NULL ? "out of memory" : strerror(errno));
        free(text);
        return -1;
    }
    for (i = 0; i < p->n_methods; i++) {
        char *cfg = NULL;
        size_t cfg_len = 0;
        FILE *mem = open_memstream(&cfg, &cfg_len);
        int w;
        if (mem != NULL) {
            /* the preset it was made from, so that an edit of plan.ini's preset = is seen (duel_plan_same_preset) */
            fprintf(mem, "%s%s\n%s", DUEL_PLAN_PRESET_MARK, p->m[i].preset, p->m[i].cfg_text);
            if (fclose(mem) != 0) {
                free(cfg);
                cfg = NULL;
            }
        }
        snprintf(path, sizeof path, "%s/configs/%s.ini", dir, p->m[i].name);
        w = cfg == NULL ? -1 : duel_file_replace(path, cfg, cfg_len);
        free(cfg);
        if (w != 0) {
            fprintf(stderr, "duel_evolve: experiment: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
            free(text);
            return -1;
        }
    }
    snprintf(path, sizeof path, "%s/plan.ini", dir);
    if (duel_file_replace(path, text, strlen(text)) != 0) {
        fprintf(stderr, "duel_evolve: experiment: %s: cannot write: %s\n", duel_esc(path), strerror(errno));
        free(text);
        return -1;
    }
    free(text);
    return 0;
}

char *duel_plan_cfg_canonical(const char *path)
{
    duel_config c;
    char err[600];
    duel_config_default(&c);
    if (duel_config_read(&c, path, err, sizeof err) != 0)
        return NULL;
    return duel_plan_cfg_text(&c);
}

char *duel_plan_run_config(const duel_plan *p, uint32_t i, uint32_t k)
{
    duel_config c = p->m[i].cfg;
    c.seed = p->seed + (k - 1);
    return duel_plan_cfg_text(&c);
}

uint32_t duel_plan_diff(const char *a, const char *b, char *la, char *lb, size_t cap)
{
    uint32_t line = 1;
    for (;;) {
        size_t na = strcspn(a, "\n"), nb = strcspn(b, "\n");
        if (na != nb || memcmp(a, b, na) != 0 || (a[na] == '\0') != (b[nb] == '\0')) {
            snprintf(la, cap, "%.*s", (int)na, a);
            snprintf(lb, cap, "%.*s", (int)nb, b);
            return line;
        }
        if (a[na] == '\0')
            return 0;
        a += na + 1;
        b += nb + 1;
        line++;
    }
}

void duel_plan_print(FILE *f, const duel_plan *p)
{
    uint32_t i, runs = 0;
    uint64_t gens = 0;
    for (i = 0; i < p->n_methods; i++) {
        const duel_plan_method *m = &p->m[i];
        char st[DUEL_START_MAX_PATH + 16];
        duel_start_text(&m->cfg.start, st, sizeof st);
        fprintf(f, "%-20s %-16s %4u run%s of 2 x %u networks, %u generations, start %s%s%s\n", m->name, m->preset,
                m->runs, m->runs == 1 ? " " : "s", m->cfg.neat.pop_size, m->cfg.generations,
                m->start_best ? "= the best champion of " : st, m->start_best ? p->reference : "",
                m->cfg.coev.random_fitness ? ", random fitness" : "");
        runs += m->runs;
        gens += (uint64_t)m->runs * m->cfg.generations;
    }
    fprintf(f, "%u runs, %llu generations in all; every method against the %s rankings (seeds %u, %u, ...)\n", runs,
            (unsigned long long)gens, p->reference, p->seed, p->seed + 1);
}
