/* duel_html_data.c - a run's and an experiment's records as the web pages' JSON (CSV tables, config.ini's entries, ladder.csv's results, a CSV column), read leniently: a page shows what is there, and any bytes give valid JSON. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "duel_html.h"
#include "duel_html_data.h"

/* One CSV field as JSON: a number when the whole field is one, else a string. */
static void html_data_field(FILE *f, const char *s, size_t n)
{
    char buf[256];
    char *end;
    double v;
    if (n > 0 && n < sizeof buf) {
        memcpy(buf, s, n);
        buf[n] = '\0';
        v = strtod(buf, &end);
        /* a decimal number only: not "0x1f" (hexadecimal to strtod), "inf" or "nan" */
        if (*end == '\0' && (buf[0] == '-' || (buf[0] >= '0' && buf[0] <= '9')) && strpbrk(buf, "xXpP") == NULL &&
            v == v && v - v == 0) {
            fprintf(f, "%.10g", v);
            return;
        }
    }
    {
        char *t = (char *)malloc(n + 1);
        if (t == NULL) {
            fputs("null", f);
            return;
        }
        memcpy(t, s, n);
        t[n] = '\0';
        duel_html_str(f, t);
        free(t);
    }
}

void duel_html_csv_table(FILE *f, const char *text, size_t len, const char *only)
{
    size_t i = 0;
    int line = 0;
    fputs("{\"columns\":[", f);
    while (i < len) {
        size_t e = i, fs;
        int col = 0;
        while (e < len && text[e] != '\n')
            e++;
        if (e > i && text[e - 1] == '\r')
            e--;
        if (e == i) { /* an empty line */
            i = e + 1;
            continue;
        }
        if (line > 0 && only != NULL) { /* only the rows whose first field is this */
            size_t ol = strlen(only);
            if (!(e - i >= ol && memcmp(text + i, only, ol) == 0 && (e - i == ol || text[i + ol] == ','))) {
                i = e + 1;
                continue;
            }
        }
        if (line == 1)
            fputs("],\"rows\":[[", f);
        else if (line > 1)
            fputs("],[", f);
        for (fs = i; fs <= e; col++) {
            size_t fe = fs;
            while (fe < e && text[fe] != ',')
                fe++;
            if (col)
                fputc(',', f);
            if (line == 0) {
                char *t = (char *)malloc(fe - fs + 1);
                if (t != NULL) {
                    memcpy(t, text + fs, fe - fs);
                    t[fe - fs] = '\0';
                    duel_html_str(f, t);
                    free(t);
                } else {
                    fputs("\"\"", f);
                }
            } else {
                html_data_field(f, text + fs, fe - fs);
            }
            fs = fe + 1;
        }
        line++;
        i = e + 1;
        while (i < len && (text[i] == '\n' || text[i] == '\r'))
            i++;
    }
    fputs(line <= 1 ? "],\"rows\":[]}" : "]]}", f);
}

void duel_html_config(FILE *f, char *text)
{
    char section[128] = "", *line, *save = NULL;
    int first = 1;
    fputc('[', f);
    for (line = strtok_r(text, "\n", &save); line != NULL; line = strtok_r(NULL, "\n", &save)) {
        char *eq, *k, *v, *e;
        while (*line == ' ' || *line == '\t')
            line++;
        if (*line == ';' || *line == '#' || *line == '\0' || *line == '\r')
            continue;
        if (*line == '[') {
            e = strchr(line, ']');
            if (e != NULL) {
                *e = '\0';
                snprintf(section, sizeof section, "%s", line + 1);
            }
            continue;
        }
        if ((eq = strchr(line, '=')) == NULL)
            continue;
        *eq = '\0';
        k = line;
        v = eq + 1;
        for (e = eq; e > k && (e[-1] == ' ' || e[-1] == '\t'); e--)
            e[-1] = '\0';
        while (*v == ' ' || *v == '\t')
            v++;
        for (e = v + strlen(v); e > v && (e[-1] == ' ' || e[-1] == '\r' || e[-1] == '\t'); e--)
            e[-1] = '\0';
        fputs(first ? "[" : ",[", f);
        duel_html_str(f, section);
        fputc(',', f);
        duel_html_str(f, k);
        fputc(',', f);
        duel_html_str(f, v);
        fputc(']', f);
        first = 0;
    }
    fputc(']', f);
}

void duel_html_ladder_free(duel_html_ladder *l)
{
    free(l->level);
    free(l->wl);
    memset(l, 0, sizeof *l);
}

int duel_html_ladder_parse(duel_html_ladder *l, char *text, size_t len)
{
    char *line, *save = NULL;
    int col_w[DUEL_N_BUILTINS], col_l[DUEL_N_BUILTINS], b, hdr = 1;
    size_t rows = 0, i;
    memset(l, 0, sizeof *l);
    for (b = 0; b < DUEL_N_BUILTINS; b++)
        col_w[b] = col_l[b] = -1;
    for (i = 0; i < len; i++)
        rows += text[i] == '\n';
    /* rows + 1 lines at most: the header and rows after it */
    l->level = (uint32_t *)calloc(rows + 1, sizeof *l->level);
    l->wl = (uint32_t(*)[DUEL_N_BUILTINS][2])calloc(rows + 1, sizeof *l->wl);
    if (l->level == NULL || l->wl == NULL) {
        duel_html_ladder_free(l);
        return -1;
    }
    for (line = strtok_r(text, "\n", &save); line != NULL; line = strtok_r(NULL, "\n", &save)) {
        char *fld, *s2 = NULL;
        int c = 0;
        if (hdr) {
            for (fld = strtok_r(line, ",\r", &s2); fld != NULL; fld = strtok_r(NULL, ",\r", &s2), c++)
                for (b = 0; b < DUEL_N_BUILTINS; b++) {
                    size_t bl = strlen(duel_builtin_name(b));
                    if (strncmp(fld, duel_builtin_name(b), bl) == 0 && strcmp(fld + bl, "_wins") == 0)
                        col_w[b] = c;
                    if (strncmp(fld, duel_builtin_name(b), bl) == 0 && strcmp(fld + bl, "_losses") == 0)
                        col_l[b] = c;
                }
            hdr = 0;
            continue;
        }
        for (fld = strtok_r(line, ",\r", &s2); fld != NULL; fld = strtok_r(NULL, ",\r", &s2), c++) {
            unsigned long v = strtoul(fld, NULL, 10);
            if (c == 0)
                l->level[l->n] = (uint32_t)v;
            for (b = 0; b < DUEL_N_BUILTINS; b++) {
                if (c == col_w[b])
                    l->wl[l->n][b][0] = (uint32_t)v;
                if (c == col_l[b])
                    l->wl[l->n][b][1] = (uint32_t)v;
            }
        }
        l->n++;
    }
    return 0;
}

void duel_html_strings_free(char **v, size_t n)
{
    size_t i;
    for (i = 0; v != NULL && i < n; i++)
        free(v[i]);
    free(v);
}

int duel_html_csv_column(const char *text, size_t len, int col, char ***out, size_t *n)
{
    size_t i = 0, cap = 0;
    int line = 0;
    *out = NULL;
    *n = 0;
    while (i < len) {
        size_t e = i, s, t;
        while (e < len && text[e] != '\n')
            e++;
        if (line++ > 0 && e > i) {
            s = i;
            if (col == 1) {
                while (s < e && text[s] != ',')
                    s++;
                s++;
            }
            for (t = s; t < e && text[t] != ',' && text[t] != '\r'; t++)
                ;
            if (s <= e && t > s) {
                char **grown;
                if (*n == cap) {
                    cap = cap ? 2 * cap : 16;
                    grown = (char **)realloc(*out, cap * sizeof *grown);
                    if (grown == NULL) {
                        duel_html_strings_free(*out, *n);
                        *out = NULL;
                        *n = 0;
                        return -1;
                    }
                    *out = grown;
                }
                (*out)[*n] = (char *)malloc(t - s + 1);
                if ((*out)[*n] == NULL) {
                    duel_html_strings_free(*out, *n);
                    *out = NULL;
                    *n = 0;
                    return -1;
                }
                memcpy((*out)[*n], text + s, t - s);
                (*out)[*n][t - s] = '\0';
                (*n)++;
            }
        }
        i = e + 1;
    }
    return 0;
}
