/* duel_html.h - self-contained web pages: a duel's replay, a run's page and an experiment's, each one HTML file with its data and viewer inline (docs/render.md, "Web pages"). */
#ifndef DUEL_HTML_H
#define DUEL_HTML_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "duel_replay.h"

/* The page's data format (the "version" of its JSON; docs/render.md). */
#define DUEL_HTML_VERSION 1

/* A page is: duel_html_open (the head, the style sheet, the start of the data
 * element), one JSON object written by the caller (every string through
 * duel_html_str), duel_html_close (the viewer script). The page loads nothing:
 * its Content-Security-Policy allows only its own script and style (by hash)
 * and data: images. */
void duel_html_open(FILE *f);
void duel_html_close(FILE *f);

/* s as a JSON string safe inside a <script> element: quotes, backslash,
 * control characters, '<', '>', '&', U+2028/U+2029 escaped as \uXXXX, and
 * bytes that are not UTF-8 replaced by U+FFFD. */
void duel_html_str(FILE *f, const char *s);
/* len bytes as a base64 JSON string. */
void duel_html_b64(FILE *f, const void *data, size_t len);
/* len bytes as a JSON string "data:MIME;base64,..." (an image the page shows). */
void duel_html_data_uri(FILE *f, const char *mime, const void *data, size_t len);
/* "format", "version", "kind", "generator" and "title": the members every
 * page's object starts with (after its '{'), then a ','. */
void duel_html_common(FILE *f, const char *kind, const char *title);

/* A duel's members (kind "duel"): the world, the food, both sides and
 * their networks, the outcome and every frame. Writes the object whole,
 * braces included. -1 when out of memory (what was written is then
 * incomplete: the callers write to memory and discard it). */
int duel_html_duel_json(FILE *f, const duel_replay *r, const char *title);
/* A whole page of one duel: duel_html_open, duel_html_duel_json, duel_html_close. */
int duel_html_duel_page(FILE *f, const duel_replay *r, const char *title);

/* The version string the pages name as their generator (set by the command
 * or the package; "neat-duel" when unset). */
void duel_html_set_generator(const char *name);

#endif /* DUEL_HTML_H */

/* A duel's page written to path atomically, after the outputs' rules
 * (docs/tools.md, "Outputs": never over an input or a run's file, over an
 * existing file only when it is one of these pages or force is set). 0; 2
 * with the line in msg (refused, or cannot create); 1 (the write failed). */
int duel_html_write_duel(const char *cmd, const char *path, const duel_replay *r, const char *title, int force,
                         const char *const *inputs, size_t n_inputs, char *msg, size_t cap);
/* The same check alone, before a game is played. */
int duel_html_allowed(const char *cmd, const char *opt, const char *path, int force, const char *const *inputs,
                      size_t n_inputs, char *msg, size_t cap);

/* ---- a run's and an experiment's pages (duel_html_run.c) ---- */

/* Which levels' games a report plays and links: every level's, the top
 * level's only, or none. */
enum { DUEL_HTML_GAMES_ALL = 0, DUEL_HTML_GAMES_TOP = 1, DUEL_HTML_GAMES_NONE = 2 };

typedef struct duel_html_report {
    int games;   /* DUEL_HTML_GAMES_* */
    int embed;   /* 1: the games inside the page; 0: each in a page of its own in OUT/games/ */
    int force;   /* replace existing files that are not recognisably pages of ours */
    /* told each page written (may be NULL) */
    void (*wrote)(void *ud, const char *path, size_t bytes);
    void *ud;
} duel_html_report;

/* A run directory's page: OUT/index.html (the run's curves, its dominance
 * ladder and the ladder's results when RUN/ladder.csv holds them) and, unless
 * embedded, OUT/games/level-KK-vs-*.html: each level against the level below
 * and against every built-in strategy, on the training food, the level west,
 * in the run's world. 0; 2 with the line in msg (bad input or a refused
 * output: no page written, though OUT may have been created); 1 with the
 * line in msg (a write failed). */
int duel_html_run_report(const char *run, const char *out, const duel_html_report *o, char *msg, size_t cap);
/* An experiment's pages (after `experiment report`: DIR/report/): OUT/index.html
 * (Table 1, the figures, a page per method) and OUT/METHOD.html (the method's
 * rows and figure, its runs' curves and ladders), their games as above. */
int duel_html_experiment_report(const char *dir, const char *out, const duel_html_report *o, char *msg, size_t cap);
/* Whether the first len bytes of a file are the start of one of these pages. */
int duel_html_is_page(const uint8_t *head, size_t len);
