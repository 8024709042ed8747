/* duel_generations.c - a run directory's generations.csv read back: per population and generation, its sizes, games and seconds, every field checked. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel_files.h"
#include "duel_generations.h"

/* A field of a row: [b, e) as a uint32 (0) or a double (1). 0 or -1. */
static int duel_gen_num(const char *b, const char *e, int real, double *out)
{
    char buf[64], *end;
    size_t n = (size_t)(e - b);
    if (n == 0 || n >= sizeof buf)
        return -1;
    memcpy(buf, b, n);
    buf[n] = '\0';
    if (real) {
        if (!((buf[0] >= '0' && buf[0] <= '9') || buf[0] == '-'))
            return -1;
        *out = strtod(buf, &end);
    } else {
        unsigned long long v;
        if (buf[0] < '0' || buf[0] > '9')
            return -1;
        errno = 0;
        v = strtoull(buf, &end, 10);
        if (errno || v > 0xffffffffull)
            return -1;
        *out = (double)v;
    }
    return *end == '\0' ? 0 : -1;
}

int duel_generations_parse(const char *name, const char *text, size_t len, duel_gen_row **rows, size_t *n, char *err,
                           size_t err_len)
{
    const char *p = text, *end = text + len, *nl;
    size_t hl = strlen(DUEL_GENERATIONS_HEADER), count = 0, cap = 0;
    duel_gen_row *out = NULL;
    uint32_t line = 1;
    const char *odd;
    *rows = NULL;
    *n = 0;
    if ((line = duel_csv_odd_line(text, len, &odd)) != 0) {
        if (odd[0] == 'c')
            snprintf(err, err_len, "%s:%u: a CRLF line end (a copy converted by a tool that writes Windows line "
                                   "ends): convert it back (dos2unix), the data is the same", name, line);
        else
            snprintf(err, err_len, "%s:%u: the row before again (a duplicated row): delete one of the two", name,
                     line);
        return -3;
    }
    line = 1;
    if (len < hl || memcmp(text, DUEL_GENERATIONS_HEADER, hl) != 0) {
        snprintf(err, err_len, "%s:1: not a generations.csv (expected its header)", name);
        return -1;
    }
    p += hl;
    while (p < end && (nl = (const char *)memchr(p, '\n', (size_t)(end - p))) != NULL) {
        const char *f[DUEL_GENERATIONS_FIELDS + 1], *q = p;
        duel_gen_row r;
        double v[DUEL_GENERATIONS_FIELDS];
        int k, nf = 0;
        line++;
        f[nf++] = q;
        while (q < nl && nf <= DUEL_GENERATIONS_FIELDS) {
            if (*q == ',')
                f[nf++] = q + 1;
            q++;
        }
        if (nf != DUEL_GENERATIONS_FIELDS || f[2] - f[1] != 2 || (f[1][0] != 'A' && f[1][0] != 'B')) {
            snprintf(err, err_len, "%s:%u: not a row of %d fields with population A or B", name, line,
                     DUEL_GENERATIONS_FIELDS);
            free(out);
            return -1;
        }
        for (k = 0; k < DUEL_GENERATIONS_FIELDS; k++) {
            const char *fe = k + 1 < DUEL_GENERATIONS_FIELDS ? f[k + 1] - 1 : nl;
            int real = k == 2 || k == 3 || k == 5 || k == 6 || k == 7 || k == 16;
            if (k == 1)
                continue;
            if (duel_gen_num(f[k], fe, real, &v[k]) != 0) {
                snprintf(err, err_len, "%s:%u: field %d is not a number", name, line, k + 1);
                free(out);
                return -1;
            }
        }
        r.generation = (uint32_t)v[0];
        r.pop = f[1][0];
        r.min_hidden = (uint32_t)v[10];
        r.max_hidden = (uint32_t)v[11];
        r.min_conns = (uint32_t)v[12];
        r.max_conns = (uint32_t)v[13];
        r.games = v[14];
        r.seconds = v[16];
        if (count == cap) {
            duel_gen_row *nr;
            cap = cap ? 2 * cap : 256;
            nr = (duel_gen_row *)realloc(out, cap * sizeof *nr);
            if (nr == NULL) {
                snprintf(err, err_len, "%s: out of memory", name);
                free(out);
                return -1;
            }
            out = nr;
        }
        /* a row lost in the middle (a cut or edited copy) is found here, not later as a wrong figure */
        if (count == 0 ? r.generation != 0 || r.pop != 'A'
                       : r.pop == out[count - 1].pop ||
                             r.generation != out[count - 1].generation + (out[count - 1].pop == 'B')) {
            snprintf(err, err_len, "%s:%u: generation %u %c follows generation %u %c: rows are missing", name, line,
                     r.generation, r.pop, count ? out[count - 1].generation : 0, count ? out[count - 1].pop : '-');
            free(out);
            return -1;
        }
        out[count++] = r;
        p = nl + 1;
    }
    if (p < end) {
        /* never dropped silently: a writer that died mid-row, or a cut copy */
        snprintf(err, err_len, "%s:%u: the last row is cut short (no newline): resuming the run cuts it", name,
                 line + 1);
        free(out);
        return -1;
    }
    *rows = out;
    *n = count;
    return 0;
}

int duel_generations_read(const char *dir, duel_gen_row **rows, size_t *n, char *err, size_t err_len)
{
    char path[4200];
    uint8_t *data;
    size_t len;
    int r;
    *rows = NULL;
    *n = 0;
    snprintf(path, sizeof path, "%s/generations.csv", dir);
    r = duel_file_read(path, DUEL_GENERATIONS_MAX_FILE, &data, &len);
    if (r != 0) {
        snprintf(err, err_len, "%s: %s", path, duel_file_strerror(errno));
        return -1;
    }
    r = duel_generations_parse(path, (const char *)data, len, rows, n, err, err_len);
    free(data);
    return r == 0 ? 0 : -2;
}

uint32_t duel_generations_done(const duel_gen_row *rows, size_t n)
{
    uint32_t done = 0;
    size_t k;
    for (k = 0; k < n; k++)
        if (rows[k].pop == 'B' && rows[k].generation + 1 > done)
            done = rows[k].generation + 1;
    return done;
}
