/* duel_dominance.c - a run directory's dominance.csv read back: one row per dominance level, every field checked. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "duel_dominance.h"
#include "duel_files.h"


/* A decimal uint32 at *p, up to a byte in stops; *p moves past it. 0 or -1. */
static int duel_dom_u32(const char **p, const char *end, uint32_t *out)
{
    uint64_t v = 0;
    const char *q = *p;
    if (q == end || *q < '0' || *q > '9')
        return -1;
    while (q < end && *q >= '0' && *q <= '9') {
        v = v * 10 + (uint64_t)(*q - '0');
        if (v > 0xffffffffu)
            return -1;
        q++;
    }
    *p = q;
    *out = (uint32_t)v;
    return 0;
}

static int duel_dom_char(const char **p, const char *end, char c)
{
    if (*p == end || **p != c)
        return -1;
    (*p)++;
    return 0;
}

int duel_dominance_parse(const char *name, const char *text, size_t len, duel_dominance_row **rows, uint32_t *n,
                         char *err, size_t err_len)
{
    return duel_dominance_parse_scores(name, text, len, rows, n, NULL, err, err_len);
}

/* s[*n] = (w, l), growing s. 0 or -1 (out of memory). */
static int duel_dom_push(duel_dominance_score **s, uint32_t *n, uint32_t *cap, uint32_t w, uint32_t l)
{
    if (*n == *cap) {
        duel_dominance_score *ns;
        uint32_t nc = *cap ? 2 * *cap : 256;
        if (nc < *cap)
            return -1;
        ns = (duel_dominance_score *)realloc(*s, (size_t)nc * sizeof *ns);
        if (ns == NULL)
            return -1;
        *s = ns;
        *cap = nc;
    }
    (*s)[*n].wins = w;
    (*s)[(*n)++].losses = l;
    return 0;
}

int duel_dominance_parse_scores(const char *name, const char *text, size_t len, duel_dominance_row **rows,
                                uint32_t *n, duel_dominance_score **scores, char *err, size_t err_len)
{
    const char *p = text, *end = text + len;
    duel_dominance_row *out = NULL;
    duel_dominance_score *sc = NULL;
    uint32_t count = 0, cap = 0, line = 1, n_sc = 0, sc_cap = 0;
    const char *nl = (const char *)memchr(p, '\n', len), *odd;
    *rows = NULL;
    *n = 0;
    if (scores != NULL)
        *scores = NULL;
    if ((line = duel_csv_odd_line(text, len, &odd)) != 0) {
        if (odd[0] == 'c')
            snprintf(err, err_len, "%s:%u: a CRLF line end (a copy converted by a tool that writes Windows line "
                                   "ends): resuming the run rebuilds the file from its checkpoint (duel_evolve resume "
                                   "RUN), or convert it back (dos2unix)", name, line);
        else
            snprintf(err, err_len, "%s:%u: the row before again (a duplicated row): resuming the run rebuilds the "
                                   "file from its checkpoint (duel_evolve resume RUN)", name, line);
        return -1;
    }
    line = 1;
    if (nl == NULL || (size_t)(nl - p) + 1 != strlen(DUEL_DOMINANCE_HEADER) ||
        memcmp(p, DUEL_DOMINANCE_HEADER, (size_t)(nl - p)) != 0) {
        snprintf(err, err_len, "%s:1: not a dominance.csv (expected the header %.*s)", name,
                 (int)strlen(DUEL_DOMINANCE_HEADER) - 1, DUEL_DOMINANCE_HEADER);
        return -1;
    }
    p = nl + 1;
    while (p < end) {
        duel_dominance_row r;
        uint32_t k, w, l;
        const char *e;
        line++;
        nl = (const char *)memchr(p, '\n', (size_t)(end - p));
        if (nl == NULL) {
            /* never dropped silently: it may be the top level (a writer that died, or a cut copy) */
            snprintf(err, err_len, "%s:%u: the last row is cut short (no newline): resuming the run rebuilds the "
                                   "file from its checkpoint (duel_evolve resume RUN)", name, line);
            goto bad;
        }
        e = nl;
        memset(&r, 0, sizeof r);
        if (duel_dom_u32(&p, e, &r.level) || duel_dom_char(&p, e, ',') || duel_dom_u32(&p, e, &r.generation) ||
            duel_dom_char(&p, e, ',') || p == e || (*p != 'A' && *p != 'B')) {
            snprintf(err, err_len, "%s:%u: not a dominance row", name, line);
            goto bad;
        }
        r.pop[0] = *p++;
        if (duel_dom_char(&p, e, ',') || duel_dom_u32(&p, e, &r.hidden) || duel_dom_char(&p, e, ',') ||
            duel_dom_u32(&p, e, &r.conns) || duel_dom_char(&p, e, ',')) {
            snprintf(err, err_len, "%s:%u: not a dominance row", name, line);
            goto bad;
        }
        /* the wins against each level below, latest first */
        r.scores = n_sc;
        for (k = 0; k + 1 < r.level; k++) {
            if ((k && duel_dom_char(&p, e, ' ')) || duel_dom_u32(&p, e, &w) || duel_dom_char(&p, e, ':') ||
                duel_dom_u32(&p, e, &l))
                break;
            if (scores != NULL && duel_dom_push(&sc, &n_sc, &sc_cap, w, l) != 0) {
                snprintf(err, err_len, "%s: out of memory", name);
                goto bad;
            }
        }
        if (k + 1 < r.level || p != e) {
            snprintf(err, err_len, "%s:%u: level %u needs %u w:l scores, one per level below", name, line, r.level,
                     r.level ? r.level - 1 : 0);
            goto bad;
        }
        if (r.level != count + 1 || (count > 0 && r.generation <= out[count - 1].generation)) {
            snprintf(err, err_len, "%s:%u: level %u of generation %u out of order (levels 1, 2, ... in increasing "
                     "generations)", name, line, r.level, r.generation);
            goto bad;
        }
        if (count == cap) {
            duel_dominance_row *nr;
            cap = cap ? 2 * cap : 64;
            nr = (duel_dominance_row *)realloc(out, cap * sizeof *nr);
            if (nr == NULL) {
                snprintf(err, err_len, "%s: out of memory", name);
                goto bad;
            }
            out = nr;
        }
        out[count++] = r;
        p = nl + 1;
    }
    *rows = out;
    *n = count;
    if (scores != NULL)
        *scores = sc;
    return 0;
bad:
    free(out);
    free(sc);
    return -1;
}

char *duel_dominance_row_text(uint32_t level, uint32_t generation, char pop, uint32_t hidden, uint32_t conns,
                              uint32_t n_beaten, const uint16_t *wins, const uint16_t *losses)
{
    /* at most 5 x 10 digits and commas, then per level "65535:65535 " */
    size_t cap = 64 + (size_t)n_beaten * 12, n;
    uint32_t k;
    char *row = (char *)malloc(cap);
    if (row == NULL)
        return NULL;
    n = (size_t)snprintf(row, cap, "%u,%u,%c,%u,%u,", level, generation, pop, hidden, conns);
    for (k = 0; k < n_beaten; k++)
        n += (size_t)snprintf(row + n, cap - n, "%s%u:%u", k ? " " : "", (unsigned)wins[k], (unsigned)losses[k]);
    snprintf(row + n, cap - n, "\n");
    return row;
}

int duel_dominance_read(const char *dir, duel_dominance_row **rows, uint32_t *n, char *err, size_t err_len)
{
    return duel_dominance_read_scores(dir, rows, n, NULL, err, err_len);
}

int duel_dominance_read_scores(const char *dir, duel_dominance_row **rows, uint32_t *n, duel_dominance_score **scores,
                               char *err, size_t err_len)
{
    char path[4200];
    uint8_t *data;
    size_t len;
    int r;
    *rows = NULL;
    if (scores != NULL)
        *scores = NULL;
    *n = 0;
    if (snprintf(path, sizeof path, "%s/dominance.csv", dir) >= (int)sizeof path) {
        snprintf(err, err_len, "%.100s...: path too long", dir);
        return -1;
    }
    r = duel_file_read(path, DUEL_DOMINANCE_MAX_FILE, &data, &len);
    if (r != 0) {
        snprintf(err, err_len, "%s: %s: %s", path, r == -1 ? "cannot open" : "cannot read", duel_file_strerror(errno));
        return -1;
    }
    r = duel_dominance_parse_scores(path, (const char *)data, len, rows, n, scores, err, err_len);
    free(data);
    return r;
}
