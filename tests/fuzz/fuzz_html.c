/* fuzz_html.c - libFuzzer harness: any bytes as the records a run's and an experiment's web pages show (a CSV table such as generations.csv or table1.csv, config.ini, ladder.csv, runs.csv's columns); what the pages embed must be strict JSON, valid UTF-8 and without a '<' (it sits in a script element). */
#define _POSIX_C_SOURCE 200809L
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel_html_data.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* ---- a strict JSON checker (RFC 8259), for what the pages' viewer gives JSON.parse ---- */

typedef struct fj {
    const unsigned char *s, *end;
} fj;

static void fj_ws(fj *j)
{
    while (j->s < j->end && (*j->s == ' ' || *j->s == '\t' || *j->s == '\n' || *j->s == '\r'))
        j->s++;
}

static int fj_lit(fj *j, const char *w)
{
    size_t n = strlen(w);
    if ((size_t)(j->end - j->s) < n || memcmp(j->s, w, n) != 0)
        return 0;
    j->s += n;
    return 1;
}

static int fj_digits(fj *j)
{
    const unsigned char *a = j->s;
    while (j->s < j->end && *j->s >= '0' && *j->s <= '9')
        j->s++;
    return j->s > a;
}

static int fj_number(fj *j)
{
    if (j->s < j->end && *j->s == '-')
        j->s++;
    if (j->s < j->end && *j->s == '0')
        j->s++;
    else if (!fj_digits(j))
        return 0;
    if (j->s < j->end && *j->s == '.') {
        j->s++;
        if (!fj_digits(j))
            return 0;
    }
    if (j->s < j->end && (*j->s == 'e' || *j->s == 'E')) {
        j->s++;
        if (j->s < j->end && (*j->s == '+' || *j->s == '-'))
            j->s++;
        if (!fj_digits(j))
            return 0;
    }
    return 1;
}

/* one UTF-8 sequence (no overlong form, no surrogate, at most U+10FFFF) */
static int fj_utf8(fj *j)
{
    unsigned c = *j->s, n, k;
    uint32_t cp;
    if (c < 0x80) {
        j->s++;
        return 1;
    }
    n = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    if (n == 0 || c > 0xF4 || (size_t)(j->end - j->s) <= n)
        return 0;
    cp = c & (0x3Fu >> n);
    for (k = 1; k <= n; k++) {
        if ((j->s[k] & 0xC0) != 0x80)
            return 0;
        cp = cp << 6 | (j->s[k] & 0x3Fu);
    }
    if ((n == 1 && cp < 0x80) || (n == 2 && cp < 0x800) || (n == 3 && cp < 0x10000) || cp > 0x10FFFF ||
        (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    j->s += n + 1;
    return 1;
}

static int fj_string(fj *j)
{
    if (j->s >= j->end || *j->s != '"')
        return 0;
    j->s++;
    while (j->s < j->end && *j->s != '"') {
        if (*j->s < 0x20)
            return 0;
        if (*j->s == '\\') {
            j->s++;
            if (j->s >= j->end)
                return 0;
            if (*j->s == 'u') {
                int k;
                for (k = 1; k <= 4; k++)
                    if (j->s + k >= j->end || !strchr("0123456789abcdefABCDEF", j->s[k]) || j->s[k] == 0)
                        return 0;
                j->s += 5;
            } else if (strchr("\"\\/bfnrt", *j->s) != NULL && *j->s != 0) {
                j->s++;
            } else {
                return 0;
            }
        } else if (!fj_utf8(j)) {
            return 0;
        }
    }
    if (j->s >= j->end)
        return 0;
    j->s++;
    return 1;
}

static int fj_value(fj *j, int depth)
{
    if (depth > 16)
        return 0;
    fj_ws(j);
    if (j->s >= j->end)
        return 0;
    if (*j->s == '{' || *j->s == '[') {
        unsigned char close = *j->s == '{' ? '}' : ']';
        int obj = close == '}';
        j->s++;
        fj_ws(j);
        if (j->s < j->end && *j->s == close) {
            j->s++;
            return 1;
        }
        for (;;) {
            if (obj) {
                fj_ws(j);
                if (!fj_string(j))
                    return 0;
                fj_ws(j);
                if (j->s >= j->end || *j->s != ':')
                    return 0;
                j->s++;
            }
            if (!fj_value(j, depth + 1))
                return 0;
            fj_ws(j);
            if (j->s < j->end && *j->s == ',') {
                j->s++;
                continue;
            }
            if (j->s < j->end && *j->s == close) {
                j->s++;
                return 1;
            }
            return 0;
        }
    }
    if (*j->s == '"')
        return fj_string(j);
    if (*j->s == '-' || (*j->s >= '0' && *j->s <= '9'))
        return fj_number(j);
    return fj_lit(j, "true") || fj_lit(j, "false") || fj_lit(j, "null");
}

/* The text written by fn is one JSON value, valid UTF-8, without '<' (else the harness traps). */
static void fh_check(const char *text, size_t len)
{
    fj j;
    j.s = (const unsigned char *)text;
    j.end = j.s + len;
    if (!fj_value(&j, 0))
        __builtin_trap();
    fj_ws(&j);
    if (j.s != j.end || memchr(text, '<', len) != NULL)
        __builtin_trap();
}

static FILE *fh_open(char **buf, size_t *len)
{
    FILE *f = open_memstream(buf, len);
    if (f == NULL)
        abort();
    return f;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *buf = NULL, *text;
    size_t len = 0, nl = 0, i;
    FILE *f;
    static const char *const only[] = {NULL, "complexify", ""};

    for (i = 0; i < sizeof only / sizeof *only; i++) { /* generations.csv, table1.csv (all rows, a method's) */
        f = fh_open(&buf, &len);
        duel_html_csv_table(f, (const char *)data, size, only[i]);
        fclose(f);
        fh_check(buf, len);
        free(buf);
        buf = NULL;
    }

    text = (char *)malloc(size + 1); /* the readers' texts are NUL-terminated copies of the file */
    if (text == NULL)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    f = fh_open(&buf, &len);
    duel_html_config(f, text);
    fclose(f);
    fh_check(buf, len);
    free(buf);
    buf = NULL;

    memcpy(text, data, size);
    text[size] = '\0';
    {
        duel_html_ladder l;
        for (i = 0; i < size; i++)
            nl += data[i] == '\n';
        if (duel_html_ladder_parse(&l, text, size) == 0) {
            if (l.n > nl) /* the header and the rows are lines */
                __builtin_trap();
            for (i = 0; i < l.n; i++) { /* every row's results are there (ASan checks the reads) */
                volatile uint32_t s = l.level[i] + l.wl[i][DUEL_N_BUILTINS - 1][1];
                (void)s;
            }
            duel_html_ladder_free(&l);
        }
    }
    free(text);

    for (i = 0; i < 2; i++) { /* runs.csv's methods and runs */
        char **v;
        size_t n, k;
        if (duel_html_csv_column((const char *)data, size, (int)i, &v, &n) != 0)
            continue;
        if (n > nl + 1)
            __builtin_trap();
        for (k = 0; k < n; k++) /* a field: not empty, never more than one */
            if (v[k][0] == '\0' && memchr(data, '\0', size) == NULL)
                __builtin_trap();
            else if (strpbrk(v[k], ",\n\r") != NULL)
                __builtin_trap();
        duel_html_strings_free(v, n);
    }
    return 0;
}
