/* duel_html_data.h - a run's and an experiment's records as the web pages' JSON: CSV tables, config.ini's entries, ladder.csv's results and a CSV column, read leniently from text (a page shows what is there; tests/fuzz/fuzz_html.c feeds them any bytes). */
#ifndef DUEL_HTML_DATA_H
#define DUEL_HTML_DATA_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "duel.h"

/* A CSV text (the project's own: no quoted field holds a comma or a line end)
 * as {"columns": [...], "rows": [[...], ...]}: the first line names the
 * columns; a field is a JSON number when the whole field is a finite decimal
 * number, else a string. only: when not NULL, only the rows whose first field
 * is exactly this. Any bytes give valid JSON. */
void duel_html_csv_table(FILE *f, const char *text, size_t len, const char *only);

/* An INI text's entries as [[section, key, value], ...] (comments, blank
 * lines and lines without '=' left out). text is NUL-terminated and is cut
 * up in place. */
void duel_html_config(FILE *f, char *text);

/* ladder.csv: for each row, its first field (the level) and the wins and
 * losses against each builtin (columns NAME_wins and NAME_losses; 0 when a
 * column is missing). */
typedef struct duel_html_ladder {
    uint32_t n;                         /* rows after the header */
    uint32_t *level;                    /* [n] */
    uint32_t (*wl)[DUEL_N_BUILTINS][2]; /* [n][builtin][0 wins, 1 losses] */
} duel_html_ladder;

/* text (len bytes, NUL-terminated, cut up in place) into l. 0, or -1 when
 * out of memory (l then empty). */
int duel_html_ladder_parse(duel_html_ladder *l, char *text, size_t len);
void duel_html_ladder_free(duel_html_ladder *l);

/* Field col (0 or 1) of every data row of a CSV text that has one, each
 * copied into a string of its own: *out[*n]. 0, or -1 when out of memory
 * (nothing then allocated). */
int duel_html_csv_column(const char *text, size_t len, int col, char ***out, size_t *n);
void duel_html_strings_free(char **v, size_t n);

#endif /* DUEL_HTML_DATA_H */
