/* duel_html_run.c - a run's and an experiment's web pages: their records (read by duel_html_data.c), the dominance ladder with its games (pages of their own or embedded), and the files written safely. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "duel_files.h"
#include "duel_html.h"
#include "duel_html_data.h"
#include "duel_levels.h"
#include "duel_outputs.h"
#include "duel_text.h"
#include "duel_world_cfg.h"

#define HTML_PATH 4096
#define HTML_MAX_CSV ((size_t)64 << 20) /* a 500-generation run's generations.csv is about 100 KB */

int duel_html_is_page(const uint8_t *head, size_t len)
{
    static const char start[] = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                                "<meta http-equiv=\"Content-Security-Policy\"";
    return len >= sizeof start - 1 && memcmp(head, start, sizeof start - 1) == 0;
}

static int html_is_ours(const uint8_t *head, size_t len, const char *path)
{
    (void)path;
    return duel_html_is_page(head, len);
}

static const duel_out_kind html_kind = {"a web page of duel_evolve", NULL, html_is_ours};

int duel_html_allowed(const char *cmd, const char *opt, const char *path, int force, const char *const *inputs,
                      size_t n_inputs, char *msg, size_t cap)
{
    return duel_out_allowed_msg(cmd, opt, path, &html_kind, force, inputs, n_inputs, msg, cap);
}

typedef struct html_game_page {
    const duel_replay *rep;
    const char *title;
    int err;
} html_game_page;

static void html_write_game(FILE *f, const void *ctx)
{
    html_game_page *p = (html_game_page *)(void *)(uintptr_t)ctx;
    p->err = duel_html_duel_page(f, p->rep, p->title);
}

/* The page of rep written to path atomically: 0, or 1/2 with msg. */
static int html_write_game_file(const char *path, const duel_replay *rep, const char *title, char *msg, size_t cap)
{
    html_game_page p;
    p.rep = rep;
    p.title = title;
    p.err = 0;
    return duel_file_write_checked_msg(path, html_write_game, &p, &p.err, msg, cap);
}

int duel_html_write_duel(const char *cmd, const char *path, const duel_replay *r, const char *title, int force,
                         const char *const *inputs, size_t n_inputs, char *msg, size_t cap)
{
    int st = duel_out_allowed_msg(cmd, "--html", path, &html_kind, force, inputs, n_inputs, msg, cap);
    return st != 0 ? st : html_write_game_file(path, r, title, msg, cap);
}

/* A file's text (NUL-terminated), or NULL when it does not exist. -1 with msg on another error. */
static int html_read(const char *path, char **text, size_t *len, char *msg, size_t cap)
{
    uint8_t *d = NULL;
    int r = duel_file_read(path, HTML_MAX_CSV, &d, len);
    char esc[1100];
    *text = NULL;
    if (r == -1 && errno == ENOENT)
        return 0;
    if (r != 0) {
        snprintf(msg, cap, "%s: cannot read: %s", duel_text_escape(path, esc, sizeof esc),
                 errno == EFBIG ? "larger than 64 MB" : duel_file_strerror(errno));
        return -1;
    }
    *text = (char *)realloc(d, *len + 1);
    if (*text == NULL) {
        free(d);
        snprintf(msg, cap, "%s: out of memory", duel_text_escape(path, esc, sizeof esc));
        return -1;
    }
    (*text)[*len] = '\0';
    return 0;
}

/* html_read for a file a page shows when it is there: NULL when missing or unreadable (no message). */
static char *html_read_quiet(const char *path, size_t *len)
{
    char *text = NULL, msg[1400];
    if (html_read(path, &text, len, msg, sizeof msg) != 0)
        return NULL;
    return text;
}

/* A file's CSV table, or null when the file does not exist or cannot be read. */
static void html_csv_file(FILE *f, const char *path, const char *only)
{
    char *text = NULL;
    size_t len = 0;
    if ((text = html_read_quiet(path, &len)) == NULL) {
        fputs("null", f);
        return;
    }
    duel_html_csv_table(f, text, len, only);
    free(text);
}

/* RUN/config.ini's entries as [[section, key, value], ...] ([] when it cannot be read). */
static void html_config(FILE *f, const char *run)
{
    char path[HTML_PATH], *text;
    size_t len = 0;
    snprintf(path, sizeof path, "%s/config.ini", run);
    if ((text = html_read_quiet(path, &len)) == NULL) {
        fputs("[]", f);
        return;
    }
    duel_html_config(f, text);
    free(text);
}

/* ---- a run's levels and their games ---- */

/* What the levels' games need: the run, its world, its levels, where pages go. */
typedef struct html_run {
    const char *dir;       /* the run directory */
    const char *prefix;    /* game page names start with this ("" or "RUN-") */
    duel_rules rules;
    duel_level *levels;
    uint32_t n_levels;
    duel_html_ladder ladder; /* RUN/ladder.csv's results (n = 0 when there are none) */
} html_run;

/* The writer's state: options, where the pages go, the embedded games counted, the first error. */
typedef struct html_ctx {
    const duel_html_report *o;
    const char *out;
    uint32_t n_embed;
    int err;               /* 0, 1 (a write failed) or 2 */
    char *msg;
    size_t cap;
} html_ctx;

static int html_has_games(const html_ctx *c, const html_run *r, uint32_t i)
{
    return c->o->games == DUEL_HTML_GAMES_ALL || (c->o->games == DUEL_HTML_GAMES_TOP && i + 1 == r->n_levels);
}

/* The opponents of level i: 0 the level below (when there is one), 1 + b builtin b. */
static int html_game_exists(uint32_t i, int g)
{
    return g > 0 || i > 0;
}

/* A page file name made of safe characters only (the page's links must pass the viewer's check). */
static void html_safe_name(char *dst, size_t cap, const char *src)
{
    size_t k = 0;
    for (; *src && k + 1 < cap; src++) {
        char ch = *src;
        dst[k++] = ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '-' ||
                    ch == '_' || ch == '.') ? ch : '_';
    }
    dst[k] = '\0';
}

/* A method's page: "method-NAME.html", never "index.html" whatever the method is called (a plan may name a method
   "index"; its page would have been replaced by the index, written last). */
static void html_method_page(char *dst, size_t cap, const char *method)
{
    static const char pre[] = "method-";
    if (cap < sizeof pre + 5) {
        dst[0] = '\0';
        return;
    }
    memcpy(dst, pre, sizeof pre - 1);
    html_safe_name(dst + sizeof pre - 1, cap - (sizeof pre - 1) - 5, method);
    strcat(dst, ".html");
}

static void html_game_href(char *buf, size_t cap, const html_run *r, uint32_t i, int g)
{
    if (g == 0)
        snprintf(buf, cap, "games/%slevel-%02u-vs-level-%02u.html", r->prefix, (unsigned)r->levels[i].level,
                 (unsigned)r->levels[i - 1].level);
    else
        snprintf(buf, cap, "games/%slevel-%02u-vs-%s.html", r->prefix, (unsigned)r->levels[i].level,
                 duel_builtin_name(g - 1));
}

static void html_level_name(char *buf, size_t cap, const duel_level *lv)
{
    snprintf(buf, cap, "level %u (generation %u, population %s)", (unsigned)lv->level, (unsigned)lv->generation,
             lv->pop);
}

/* Plays level i against opponent g on the training food, the level west. 0 or -1 (out of memory). */
static int html_play(duel_replay *rep, const html_run *r, uint32_t i, int g)
{
    duel_controller other;
    int err;
    if (g == 0) {
        other = r->levels[i - 1].ctrl.ctrl;
    } else {
        other.net = NULL;
        other.builtin = g - 1;
    }
    err = duel_replay_from_game_rules(rep, &r->rules, &r->levels[i].ctrl.ctrl, &other, DUEL_TRAINING);
    if (err)
        return -1;
    html_level_name(rep->west, sizeof rep->west, &r->levels[i]);
    if (g == 0)
        html_level_name(rep->east, sizeof rep->east, &r->levels[i - 1]);
    else
        snprintf(rep->east, sizeof rep->east, "builtin:%s", duel_builtin_name(g - 1));
    return 0;
}

static void html_game_title(char *buf, size_t cap, const html_run *r, uint32_t i, int g)
{
    char base[512];
    const char *slash = strrchr(r->dir, '/');
    snprintf(base, sizeof base, "%s", slash != NULL && slash[1] ? slash + 1 : r->dir);
    if (g == 0)
        snprintf(buf, cap, "%s: level %u vs level %u", base, (unsigned)r->levels[i].level,
                 (unsigned)r->levels[i - 1].level);
    else
        snprintf(buf, cap, "%s: level %u vs %s", base, (unsigned)r->levels[i].level, duel_builtin_name(g - 1));
}

static void html_wrote(const html_ctx *c, const char *path)
{
    struct stat st;
    if (c->o->wrote != NULL)
        c->o->wrote(c->o->ud, path, stat(path, &st) == 0 ? (size_t)st.st_size : 0);
}

/* The game pages of a run (not embedded), each checked (write 0: before anything is written, an existing file
 * that is not one of these pages is refused) or played and written atomically (write 1). */
static int html_game_pages(html_ctx *c, const html_run *r, int write)
{
    uint32_t i;
    int g;
    for (i = 0; i < r->n_levels; i++) {
        if (!html_has_games(c, r, i))
            continue;
        for (g = 0; g <= DUEL_N_BUILTINS; g++) {
            char rel[600], path[HTML_PATH + 600], title[700];
            duel_replay rep;
            int st;
            if (!html_game_exists(i, g))
                continue;
            html_game_href(rel, sizeof rel, r, i, g);
            snprintf(path, sizeof path, "%s/%s", c->out, rel);
            if (!write) {
                if (access(path, F_OK) == 0 && duel_out_own_allowed_msg("report", "--html", path, &html_kind,
                                                                        c->o->force, NULL, 0, c->msg, c->cap) != 0)
                    return 2;
                continue;
            }
            duel_replay_init(&rep);
            if (html_play(&rep, r, i, g) != 0) {
                duel_replay_free(&rep);
                snprintf(c->msg, c->cap, "out of memory");
                return 1;
            }
            html_game_title(title, sizeof title, r, i, g);
            st = html_write_game_file(path, &rep, title, c->msg, c->cap);
            duel_replay_free(&rep);
            if (st != 0)
                return st;
            html_wrote(c, path);
        }
    }
    return 0;
}

/* The levels as the pages' LEVEL objects; an embedded game's index counts on in c->n_embed. */
static void html_levels(FILE *f, html_ctx *c, const html_run *r)
{
    uint32_t i, k;
    int g, b;
    fputc('[', f);
    for (i = 0; i < r->n_levels; i++) {
        const duel_level *lv = &r->levels[i];
        int first = 1;
        fprintf(f, "%s{\"level\":%u,\"generation\":%u,\"population\":", i ? "," : "", (unsigned)lv->level,
                (unsigned)lv->generation);
        duel_html_str(f, lv->pop);
        fprintf(f, ",\"hidden\":%u,\"connections\":%u,\"ladder\":", (unsigned)lv->hidden, (unsigned)lv->conns);
        for (k = 0; k < r->ladder.n && r->ladder.level[k] != lv->level; k++)
            ;
        if (r->ladder.n == 0 || k == r->ladder.n) {
            fputs("null", f);
        } else {
            uint32_t tw = 0, tl = 0;
            for (int wl = 0; wl < 2; wl++) {
                fputs(wl ? ",\"losses\":{" : "{\"wins\":{", f);
                for (b = 0; b < DUEL_N_BUILTINS; b++) {
                    fprintf(f, "%s\"%s\":%u", b ? "," : "", duel_builtin_name(b), (unsigned)r->ladder.wl[k][b][wl]);
                    if (wl)
                        tl += r->ladder.wl[k][b][1];
                    else
                        tw += r->ladder.wl[k][b][0];
                }
                fputc('}', f);
            }
            fprintf(f, ",\"total_wins\":%u,\"total_losses\":%u}", (unsigned)tw, (unsigned)tl);
        }
        fputs(",\"games\":[", f);
        if (html_has_games(c, r, i))
            for (g = 0; g <= DUEL_N_BUILTINS; g++) {
                char label[64], href[600];
                if (!html_game_exists(i, g))
                    continue;
                if (g == 0)
                    snprintf(label, sizeof label, "vs level %u", (unsigned)r->levels[i - 1].level);
                else
                    snprintf(label, sizeof label, "vs %s", duel_builtin_name(g - 1));
                fputs(first ? "{\"label\":" : ",{\"label\":", f);
                duel_html_str(f, label);
                if (c->o->embed) {
                    fprintf(f, ",\"embed\":%u}", (unsigned)c->n_embed++);
                } else {
                    html_game_href(href, sizeof href, r, i, g);
                    fputs(",\"href\":", f);
                    duel_html_str(f, href);
                    fputc('}', f);
                }
                first = 0;
            }
        fputs("]}", f);
    }
    fputc(']', f);
}

/* The embedded games of a run, in the order html_levels numbered them. */
static void html_embedded(FILE *f, html_ctx *c, const html_run *r, int *first)
{
    uint32_t i;
    int g;
    if (!c->o->embed)
        return;
    for (i = 0; i < r->n_levels; i++) {
        if (!html_has_games(c, r, i))
            continue;
        for (g = 0; g <= DUEL_N_BUILTINS; g++) {
            duel_replay rep;
            char title[700];
            if (!html_game_exists(i, g))
                continue;
            if (!*first)
                fputc(',', f);
            *first = 0;
            duel_replay_init(&rep);
            html_game_title(title, sizeof title, r, i, g);
            if (html_play(&rep, r, i, g) != 0 || duel_html_duel_json(f, &rep, title) != 0) {
                fputs("null", f);
                c->err = 1;
                snprintf(c->msg, c->cap, "out of memory");
            }
            duel_replay_free(&rep);
        }
    }
}

static void html_ladder_against(FILE *f, const html_run *r)
{
    int b;
    fputc('[', f);
    for (b = 0; r->ladder.n > 0 && b < DUEL_N_BUILTINS; b++) {
        fputs(b ? "," : "", f);
        duel_html_str(f, duel_builtin_name(b));
    }
    fputc(']', f);
}

/* What a run page and an experiment's method page show of each run: ,"generations","levels","ladder_against". */
static void html_run_members(FILE *f, html_ctx *c, const html_run *r)
{
    char path[HTML_PATH + 32];
    snprintf(path, sizeof path, "%s/generations.csv", r->dir);
    fputs(",\"generations\":", f);
    html_csv_file(f, path, NULL);
    fputs(",\"levels\":", f);
    html_levels(f, c, r);
    fputs(",\"ladder_against\":", f);
    html_ladder_against(f, r);
}

/* 1 when dir holds a config.ini (plan.ini) a run (experiment) wrote. */
static int html_dir_marked(const char *dir, const char *file, const char *mark)
{
    char path[HTML_PATH], head[128];
    FILE *fp;
    size_t n, ml = strlen(mark);
    snprintf(path, sizeof path, "%s/%s", dir, file);
    if ((fp = fopen(path, "rb")) == NULL)
        return 0;
    n = fread(head, 1, sizeof head, fp);
    fclose(fp);
    return n >= ml && memcmp(head, mark, ml) == 0;
}

static int html_open_run(html_run *r, const char *dir, const char *prefix, char *msg, size_t cap)
{
    char esc[1100];
    memset(r, 0, sizeof *r);
    r->dir = dir;
    r->prefix = prefix;
    if (!html_dir_marked(dir, "config.ini", DUEL_RUN_CONFIG_MARK)) {
        snprintf(msg, cap, "%s: not a run directory (no config.ini that a run wrote)",
                 duel_text_escape(dir, esc, sizeof esc));
        return 2;
    }
    if (duel_world_of_run_msg(&r->rules, dir, msg, cap) != 0)
        return 2;
    if (duel_levels_read_msg(dir, &r->levels, &r->n_levels, msg, cap) != 0)
        return 2;
    {
        char path[HTML_PATH + 32], *text;
        size_t len = 0;
        snprintf(path, sizeof path, "%s/ladder.csv", dir);
        if ((text = html_read_quiet(path, &len)) != NULL) {
            int bad = duel_html_ladder_parse(&r->ladder, text, len);
            free(text);
            if (bad) {
                snprintf(msg, cap, "%s: out of memory", duel_text_escape(path, esc, sizeof esc));
                duel_levels_free(r->levels, r->n_levels);
                r->levels = NULL;
                return 1;
            }
        }
    }
    return 0;
}

static void html_close_run(html_run *r)
{
    if (r->levels != NULL)
        duel_levels_free(r->levels, r->n_levels);
    duel_html_ladder_free(&r->ladder);
    memset(r, 0, sizeof *r);
}

/* OUT (and OUT/games): created, never a run's or an experiment's own directory. */
static int html_prepare_out(html_ctx *c, int games)
{
    char path[HTML_PATH], esc[1100];
    if (html_dir_marked(c->out, "config.ini", DUEL_RUN_CONFIG_MARK) ||
        html_dir_marked(c->out, "plan.ini", DUEL_EXP_PLAN_MARK)) {
        snprintf(c->msg, c->cap, "%s is a run or experiment directory: choose a directory of its own for the pages",
                 duel_text_escape(c->out, esc, sizeof esc));
        return 2;
    }
    if (duel_mkdir(c->out) != 0) {
        snprintf(c->msg, c->cap, "%s: cannot create the directory: %s", duel_text_escape(c->out, esc, sizeof esc),
                 strerror(errno));
        return 2;
    }
    snprintf(path, sizeof path, "%s/games", c->out);
    if (games && duel_mkdir(path) != 0) {
        snprintf(c->msg, c->cap, "%s: cannot create the directory: %s", duel_text_escape(path, esc, sizeof esc),
                 strerror(errno));
        return 2;
    }
    return 0;
}

/* ---- the run page ---- */

typedef struct html_run_page {
    html_ctx *c;
    const html_run *r;
} html_run_page;

static void html_write_run(FILE *f, const void *ctx)
{
    const html_run_page *p = (const html_run_page *)ctx;
    html_ctx *c = p->c;
    const html_run *r = p->r;
    char path[HTML_PATH];
    const char *slash = strrchr(r->dir, '/');
    int first = 1;
    c->n_embed = 0;
    duel_html_open(f);
    fputc('{', f);
    duel_html_common(f, "run", slash != NULL && slash[1] ? slash + 1 : r->dir);
    fputs("\"run\":", f);
    duel_html_str(f, r->dir);
    fputs(",\"config\":", f);
    html_config(f, r->dir);
    snprintf(path, sizeof path, "%s/strength.csv", r->dir);
    fputs(",\"strength\":", f);
    html_csv_file(f, path, NULL);
    html_run_members(f, c, r);
    fputs(",\"embedded\":[", f);
    html_embedded(f, c, r, &first);
    fputs("]}", f);
    duel_html_close(f);
}

static int html_write_page(html_ctx *c, const char *path, duel_write_fn fn, const void *ctx)
{
    int st;
    c->err = 0;
    st = duel_file_write_checked_msg(path, fn, ctx, &c->err, c->msg, c->cap);
    if (st == 0)
        html_wrote(c, path);
    return st;
}

int duel_html_run_report(const char *run, const char *out, const duel_html_report *o, char *msg, size_t cap)
{
    html_ctx c;
    html_run r;
    html_run_page p;
    char index[HTML_PATH];
    int st;
    const char *inputs[1];

    memset(&c, 0, sizeof c);
    c.o = o;
    c.out = out;
    c.msg = msg;
    c.cap = cap;
    if ((st = html_open_run(&r, run, "", msg, cap)) != 0)
        return st;
    inputs[0] = run;
    snprintf(index, sizeof index, "%s/index.html", out);
    st = html_prepare_out(&c, !o->embed && o->games != DUEL_HTML_GAMES_NONE);
    if (st == 0 && access(index, F_OK) == 0)
        st = duel_out_allowed_msg("report", "--html", index, &html_kind, o->force, inputs, 1, msg, cap);
    if (st == 0 && !o->embed)
        st = html_game_pages(&c, &r, 0);
    if (st == 0 && !o->embed)
        st = html_game_pages(&c, &r, 1);
    if (st == 0) {
        p.c = &c;
        p.r = &r;
        st = html_write_page(&c, index, html_write_run, &p);
    }
    html_close_run(&r);
    return st;
}

/* ---- the experiment's pages ---- */

/* The experiment's methods (table1.csv's first column) and runs (runs.csv: method, run). */
typedef struct html_exp {
    const char *dir;
    char report[HTML_PATH];
    char **methods, **run_method, **run_name;
    size_t n_methods, n_runs;
    char *table1;
    size_t table1_len;
} html_exp;

static void html_exp_free(html_exp *e)
{
    duel_html_strings_free(e->methods, e->n_methods);
    duel_html_strings_free(e->run_method, e->n_runs);
    duel_html_strings_free(e->run_name, e->n_runs);
    free(e->table1);
}

static int html_open_exp(html_exp *e, const char *dir, char *msg, size_t cap)
{
    char path[HTML_PATH + 32], esc[1100], *runs = NULL;
    size_t runs_len = 0;
    char **m0 = NULL, **m1 = NULL;
    size_t n0 = 0, n1 = 0;
    memset(e, 0, sizeof *e);
    e->dir = dir;
    snprintf(e->report, sizeof e->report, "%s/report", dir);
    if (!html_dir_marked(dir, "plan.ini", DUEL_EXP_PLAN_MARK)) {
        snprintf(msg, cap, "%s: not an experiment directory (no plan.ini that an experiment wrote)",
                 duel_text_escape(dir, esc, sizeof esc));
        return 2;
    }
    snprintf(path, sizeof path, "%s/table1.csv", e->report);
    if (html_read(path, &e->table1, &e->table1_len, msg, cap) != 0)
        return 2;
    snprintf(path, sizeof path, "%s/runs.csv", e->report);
    if (e->table1 == NULL || html_read(path, &runs, &runs_len, msg, cap) != 0 || runs == NULL) {
        if (e->table1 == NULL || runs == NULL)
            snprintf(msg, cap, "%s: no report yet (report/table1.csv, report/runs.csv): the runs must be done "
                               "and reported first (duel_evolve experiment report DIR)",
                     duel_text_escape(dir, esc, sizeof esc));
        html_exp_free(e);
        return 2;
    }
    if (duel_html_csv_column(e->table1, e->table1_len, 0, &e->methods, &e->n_methods) != 0 ||
        duel_html_csv_column(runs, runs_len, 0, &m0, &n0) != 0 ||
        duel_html_csv_column(runs, runs_len, 1, &m1, &n1) != 0 || n0 != n1) {
        snprintf(msg, cap, "%s/report/runs.csv: out of memory or a row without its run",
                 duel_text_escape(dir, esc, sizeof esc));
        duel_html_strings_free(m0, n0);
        duel_html_strings_free(m1, n1);
        free(runs);
        html_exp_free(e);
        return 2;
    }
    e->run_method = m0;
    e->run_name = m1;
    e->n_runs = n0;
    free(runs);
    return 0;
}

/* A figure of the report: an SVG file as an image, when it exists. */
static void html_figure(FILE *f, const char *report, const char *name, const char *caption, int *first)
{
    char path[HTML_PATH + 300], *text = NULL;
    size_t len = 0;
    snprintf(path, sizeof path, "%s/%s", report, name);
    if ((text = html_read_quiet(path, &len)) == NULL)
        return;
    fputs(*first ? "{\"caption\":" : ",{\"caption\":", f);
    *first = 0;
    duel_html_str(f, caption);
    fputs(",\"svg\":", f);
    duel_html_data_uri(f, "image/svg+xml", text, len);
    fputc('}', f);
    free(text);
}

typedef struct html_exp_page {
    html_ctx *c;
    const html_exp *e;
    const char *method;  /* NULL: the index */
    html_run *runs;      /* the method's runs, opened */
    size_t n_runs;
} html_exp_page;

static void html_write_exp(FILE *f, const void *ctx)
{
    const html_exp_page *p = (const html_exp_page *)ctx;
    const html_exp *e = p->e;
    html_ctx *c = p->c;
    char title[600], name[300];
    size_t i;
    int first = 1;
    const char *slash = strrchr(e->dir, '/');
    c->n_embed = 0;
    snprintf(title, sizeof title, "%s%s%s", slash != NULL && slash[1] ? slash + 1 : e->dir, p->method ? ": " : "",
             p->method ? p->method : "");
    duel_html_open(f);
    fputc('{', f);
    duel_html_common(f, "experiment", title);
    fputs("\"experiment\":", f);
    duel_html_str(f, e->dir);
    fputs(",\"method\":", f);
    if (p->method)
        duel_html_str(f, p->method);
    else
        fputs("null", f);
    fputs(",\"table1\":", f);
    duel_html_csv_table(f, e->table1, e->table1_len, p->method);
    fputs(",\"figures\":[", f);
    if (p->method == NULL) {
        html_figure(f, e->report, "fig11-levels.svg", "Figure 11: what a difference in dominance level means, in games won", &first);
        html_figure(f, e->report, "fig7-complexity.svg", "Figure 7: the dominants' complexity over generations", &first);
    } else {
        char fig[400], cap2[400];
        snprintf(fig, sizeof fig, "levels-%s.svg", p->method);
        snprintf(cap2, sizeof cap2, "%s: dominance levels of each run", p->method);
        html_figure(f, e->report, fig, cap2, &first);
    }
    fputs("],\"pages\":[", f);
    for (i = 0; p->method == NULL && i < e->n_methods; i++) {
        html_method_page(name, sizeof name, e->methods[i]);
        fputs(i ? ",{\"label\":" : "{\"label\":", f);
        duel_html_str(f, e->methods[i]);
        fputs(",\"href\":", f);
        duel_html_str(f, name);
        fputc('}', f);
    }
    fputs("],\"runs\":[", f);
    for (i = 0; i < p->n_runs; i++) {
        const html_run *r = &p->runs[i];
        const char *base = strrchr(r->dir, '/');
        fputs(i ? ",{\"name\":" : "{\"name\":", f);
        duel_html_str(f, base != NULL ? base + 1 : r->dir);
        html_run_members(f, c, r);
        fputc('}', f);
    }
    fputs("],\"embedded\":[", f);
    first = 1;
    for (i = 0; i < p->n_runs; i++)
        html_embedded(f, c, &p->runs[i], &first);
    fputs("]}", f);
    duel_html_close(f);
}

int duel_html_experiment_report(const char *dir, const char *out, const duel_html_report *o, char *msg, size_t cap)
{
    html_ctx c;
    html_exp e;
    html_exp_page p;
    char path[HTML_PATH + 300], name[300];
    size_t m, i;
    int st;

    memset(&c, 0, sizeof c);
    c.o = o;
    c.out = out;
    c.msg = msg;
    c.cap = cap;
    if ((st = html_open_exp(&e, dir, msg, cap)) != 0)
        return st;
    st = html_prepare_out(&c, !o->embed && o->games != DUEL_HTML_GAMES_NONE);
    /* a page per method, then the index that links them */
    for (m = 0; st == 0 && m < e.n_methods; m++) {
        html_run *runs = (html_run *)calloc(e.n_runs + 1, sizeof *runs);
        char (*prefix)[300] = (char(*)[300])calloc(e.n_runs + 1, sizeof *prefix);
        char (*rdir)[HTML_PATH + 300] = (char(*)[HTML_PATH + 300])calloc(e.n_runs + 1, sizeof *rdir);
        size_t n = 0;
        if (runs == NULL || prefix == NULL || rdir == NULL) {
            snprintf(msg, cap, "out of memory");
            st = 1;
        }
        for (i = 0; st == 0 && i < e.n_runs; i++) {
            if (strcmp(e.run_method[i], e.methods[m]) != 0)
                continue;
            snprintf(rdir[n], sizeof rdir[n], "%s/runs/%s", dir, e.run_name[i]);
            html_safe_name(prefix[n], sizeof prefix[n] - 2, e.run_name[i]);
            strcat(prefix[n], "-");
            if ((st = html_open_run(&runs[n], rdir[n], prefix[n], msg, cap)) == 0)
                n++;
        }
        for (i = 0; st == 0 && !o->embed && i < n; i++)
            st = html_game_pages(&c, &runs[i], 0);
        for (i = 0; st == 0 && !o->embed && i < n; i++)
            st = html_game_pages(&c, &runs[i], 1);
        if (st == 0) {
            html_method_page(name, sizeof name, e.methods[m]);
            snprintf(path, sizeof path, "%s/%s", out, name);
            if (access(path, F_OK) == 0)
                st = duel_out_own_allowed_msg("experiment", "--html", path, &html_kind, o->force, NULL, 0, msg, cap);
        }
        if (st == 0) {
            p.c = &c;
            p.e = &e;
            p.method = e.methods[m];
            p.runs = runs;
            p.n_runs = n;
            st = html_write_page(&c, path, html_write_exp, &p);
        }
        for (i = 0; runs != NULL && i < n; i++)
            html_close_run(&runs[i]);
        free(runs);
        free(prefix);
        free(rdir);
    }
    if (st == 0) {
        snprintf(path, sizeof path, "%s/index.html", out);
        if (access(path, F_OK) == 0)
            st = duel_out_own_allowed_msg("experiment", "--html", path, &html_kind, o->force, NULL, 0, msg, cap);
        if (st == 0) {
            p.c = &c;
            p.e = &e;
            p.method = NULL;
            p.runs = NULL;
            p.n_runs = 0;
            st = html_write_page(&c, path, html_write_exp, &p);
        }
    }
    html_exp_free(&e);
    return st;
}
