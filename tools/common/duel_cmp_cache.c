/* duel_cmp_cache.c - the comparison cache: a CSV of (world, blob hash, blob hash, tally), the world the rules' identity. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <unistd.h>

#include "duel_cmp_cache.h"
#include "duel_files.h"

#define DUEL_CMP_HEADER "# duel_evolve compare cache 2: world,a_hash,b_hash,wins_a,wins_b,draws,timeouts\n"
/* format 1 (before the rules were data) named the world version in its
 * header; its entries are world v1's */
#define DUEL_CMP_HEADER_1 "# duel_evolve compare cache 1, duel world 1: a_hash,b_hash,wins_a,wins_b,draws,timeouts\n"
#define DUEL_CMP_MAX_FILE ((size_t)1 << 30)

uint64_t duel_blob_hash(const uint8_t *blob, size_t len)
{
    uint64_t h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < len; i++) {
        h ^= blob[i];
        h *= 1099511628211ull;
    }
    return h;
}

static int duel_cmp_less(const duel_cmp_entry *e, uint64_t w, uint64_t a, uint64_t b)
{
    return e->world < w || (e->world == w && (e->a < a || (e->a == a && e->b < b)));
}

static int duel_cmp_is(const duel_cmp_entry *e, uint64_t w, uint64_t a, uint64_t b)
{
    return e->world == w && e->a == a && e->b == b;
}

/* The first entry not less than (w, a, b). */
static size_t duel_cmp_lower(const duel_cmp_cache *c, uint64_t w, uint64_t a, uint64_t b)
{
    size_t lo = 0, hi = c->n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (duel_cmp_less(&c->e[mid], w, a, b))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

const duel_tally *duel_cmp_cache_find(const duel_cmp_cache *c, uint64_t world, uint64_t a, uint64_t b)
{
    size_t k = duel_cmp_lower(c, world, a, b);
    return k < c->n && duel_cmp_is(&c->e[k], world, a, b) ? &c->e[k].tally : NULL;
}

int duel_cmp_cache_add(duel_cmp_cache *c, uint64_t world, uint64_t a, uint64_t b, const duel_tally *t)
{
    size_t k = duel_cmp_lower(c, world, a, b);
    if (k < c->n && duel_cmp_is(&c->e[k], world, a, b)) {
        c->e[k].tally = *t;
        c->dirty = 1;
        return 0;
    }
    if (c->n == c->cap) {
        size_t cap = c->cap ? 2 * c->cap : 256;
        duel_cmp_entry *e = (duel_cmp_entry *)realloc(c->e, cap * sizeof *e);
        if (e == NULL)
            return -1;
        c->e = e;
        c->cap = cap;
    }
    memmove(c->e + k + 1, c->e + k, (c->n - k) * sizeof *c->e);
    c->e[k].world = world;
    c->e[k].a = a;
    c->e[k].b = b;
    c->e[k].tally = *t;
    c->n++;
    c->dirty = 1;
    return 0;
}

/* "hhhh...h" of exactly 16 hex digits */
static int duel_cmp_hex(const char *s, uint64_t *v)
{
    int i;
    *v = 0;
    for (i = 0; i < 16; i++) {
        char ch = s[i];
        int d = ch >= '0' && ch <= '9' ? ch - '0' : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : -1;
        if (d < 0)
            return -1;
        *v = *v << 4 | (uint64_t)d;
    }
    return 0;
}

static int duel_cmp_u32(const char **s, char end, uint32_t *v)
{
    const char *p = *s;
    uint64_t x = 0;
    if (*p < '0' || *p > '9')
        return -1;
    while (*p >= '0' && *p <= '9' && x <= 0xFFFFFFFFu)
        x = x * 10 + (uint64_t)(*p++ - '0');
    if (x > 0xFFFFFFFFu || *p != end)
        return -1;
    *v = (uint32_t)x;
    *s = p + 1;
    return 0;
}

int duel_cmp_cache_open(duel_cmp_cache *c, const char *path, char *err, size_t err_len)
{
    uint8_t *text;
    size_t len;
    int r = duel_file_read(path, DUEL_CMP_MAX_FILE, &text, &len);
    memset(c, 0, sizeof *c);
    if (r != 0) {
        snprintf(c->path, sizeof c->path, "%s", path);
        if (r == -1 && errno == ENOENT)
            return 0;
        snprintf(err, err_len, "%s: cannot read: %s", path, errno == EFBIG ? "larger than 1 GB" : duel_file_strerror(errno));
        return -1;
    }
    r = duel_cmp_cache_parse(c, path, (const char *)text, len, err, err_len);
    free(text);
    return r;
}

/* 1 when text starts with header, its newline written "\n" or "\r\n"; *hlen is how long it is there. */
static int duel_cmp_starts(const char *text, size_t len, const char *header, size_t *hlen)
{
    size_t n = strlen(header) - 1; /* without its newline */
    if (len < n + 1 || memcmp(text, header, n) != 0)
        return 0;
    if (text[n] == '\n') {
        *hlen = n + 1;
        return 1;
    }
    if (len >= n + 2 && text[n] == '\r' && text[n + 1] == '\n') {
        *hlen = n + 2;
        return 1;
    }
    return 0;
}

int duel_cmp_cache_is(const uint8_t *head, size_t len, const char *path)
{
    size_t hlen;
    (void)path;
    return duel_cmp_starts((const char *)head, len, DUEL_CMP_HEADER, &hlen) ||
           duel_cmp_starts((const char *)head, len, DUEL_CMP_HEADER_1, &hlen);
}

int duel_cmp_cache_parse(duel_cmp_cache *c, const char *path, const char *text, size_t len, char *err,
                         size_t err_len)
{
    size_t at, line = 1, hlen = 0;
    int v1, unterminated = 0;

    memset(c, 0, sizeof *c);
    snprintf(c->path, sizeof c->path, "%s", path);
    if (len == 0)
        return 0; /* an empty file: an empty cache */
    v1 = duel_cmp_starts(text, len, DUEL_CMP_HEADER_1, &hlen);
    if (!v1 && !duel_cmp_starts(text, len, DUEL_CMP_HEADER, &hlen)) {
        /* not ours, or a version this build does not know: never replaced silently */
        snprintf(err, err_len, "%s: not a compare cache this version reads (its first line is not '%.*s'): "
                               "refusing to replace it (move it away, or --force replaces it)", path,
                 (int)strlen(DUEL_CMP_HEADER) - 1, DUEL_CMP_HEADER);
        return -2;
    }
    for (at = hlen; at < len; line++) {
        char row[160];
        const char *p = row;
        size_t end = at, stop, key = v1 ? 34 : 51;
        uint64_t w, a, b;
        duel_tally t;
        const duel_tally *have;
        while (end < len && text[end] != '\n')
            end++;
        /* the cache is replaced whole, never appended: a last line without its newline is a whole entry that lost
         * one byte (taken, and written back whole at the next save) or damage (refused below) */
        unterminated = end == len;
        stop = end > at && text[end - 1] == '\r' ? end - 1 : end; /* a CRLF copy reads the same */
        if (stop - at >= sizeof row || stop - at < key)
            goto bad;
        memcpy(row, text + at, stop - at);
        row[stop - at] = '\0';
        if (strlen(row) != stop - at)
            goto bad;
        if (v1) {
            w = duel_rules_id(duel_rules_v1());
        } else {
            if (duel_cmp_hex(p, &w) || p[16] != ',')
                goto bad;
            p += 17;
        }
        if (duel_cmp_hex(p, &a) || p[16] != ',' || duel_cmp_hex(p + 17, &b) || p[33] != ',')
            goto bad;
        p += 34;
        if (duel_cmp_u32(&p, ',', &t.wins_a) || duel_cmp_u32(&p, ',', &t.wins_b) || duel_cmp_u32(&p, ',', &t.draws) ||
            duel_cmp_u32(&p, '\0', &t.timeouts) || (uint64_t)t.wins_a + t.wins_b + t.draws + t.timeouts !=
                                                         2u * DUEL_CONFIGS)
            goto bad;
        have = duel_cmp_cache_find(c, w, a, b);
        if (have != NULL && memcmp(have, &t, sizeof t) != 0) {
            /* two results for one comparison: which is right cannot be known */
            snprintf(err, err_len, "%s:%zu: a second, different result for the comparison of %016" PRIx64
                                   " against %016" PRIx64 " (an edited or merged file): delete the file to rebuild "
                                   "it (its games are played again)", path, line + 1, a, b);
            duel_cmp_cache_free(c);
            return -1;
        }
        if (have == NULL && duel_cmp_cache_add(c, w, a, b, &t) != 0) {
            snprintf(err, err_len, "%s: out of memory", path);
            duel_cmp_cache_free(c);
            return -1;
        }
        at = end + 1;
    }
    /* a format-1 file is written back in format 2 when it next saves, and one missing its last newline whole */
    c->dirty = v1 || unterminated;
    return 0;
bad:
    if (unterminated) {
        snprintf(err, err_len, "%s:%zu: the last line is cut short (no newline, and not a whole entry): delete the "
                               "file to rebuild it (its games are played again)", path, line + 1);
        duel_cmp_cache_free(c);
        return -1;
    }
    snprintf(err, err_len, "%s:%zu: not a cache entry (%sa_hash,b_hash,wins_a,wins_b,draws,timeouts summing to %d): "
                           "delete the file to rebuild it", path, line + 1, v1 ? "" : "world,", 2 * DUEL_CONFIGS);
    duel_cmp_cache_free(c);
    return -1;
}

/* Another compare may have saved entries since this one opened the file: they are taken in (a comparison's
 * result is the same whoever played it), under PATH.lock, so that two compares of one candidate lose nothing. */
static void duel_cmp_cache_merge(duel_cmp_cache *c)
{
    duel_cmp_cache disk;
    char err[600];
    size_t k;
    if (duel_cmp_cache_open(&disk, c->path, err, sizeof err) != 0)
        return; /* missing, or damaged since: ours replaces it */
    for (k = 0; k < disk.n; k++)
        if (duel_cmp_cache_find(c, disk.e[k].world, disk.e[k].a, disk.e[k].b) == NULL &&
            duel_cmp_cache_add(c, disk.e[k].world, disk.e[k].a, disk.e[k].b, &disk.e[k].tally) != 0)
            break;
    duel_cmp_cache_free(&disk);
}

int duel_cmp_cache_save(duel_cmp_cache *c)
{
    char *text = NULL, lock[4210];
    size_t len = 0, k;
    FILE *mem;
    int r, fd = -1;
    if (!c->dirty)
        return 0;
    /* PATH.lock: held while the file is read back and replaced (a lock that cannot be made: no merge) */
    if ((size_t)snprintf(lock, sizeof lock, "%s.lock", c->path) < sizeof lock) {
        fd = open(lock, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (fd >= 0 && flock(fd, LOCK_EX) != 0) {
            close(fd);
            fd = -1;
        }
    }
    if (fd >= 0)
        duel_cmp_cache_merge(c);
    mem = open_memstream(&text, &len);
    if (mem == NULL)
        return -1;
    fputs(DUEL_CMP_HEADER, mem);
    for (k = 0; k < c->n; k++)
        fprintf(mem, "%016" PRIx64 ",%016" PRIx64 ",%016" PRIx64 ",%u,%u,%u,%u\n", c->e[k].world, c->e[k].a, c->e[k].b,
                c->e[k].tally.wins_a,
                c->e[k].tally.wins_b, c->e[k].tally.draws, c->e[k].tally.timeouts);
    if (fclose(mem) != 0) {
        free(text);
        if (fd >= 0)
            close(fd);
        return -1;
    }
    r = duel_file_replace(c->path, text, len);
    free(text);
    if (fd >= 0)
        close(fd); /* the lock goes with it */
    if (r == 0)
        c->dirty = 0;
    return r;
}

void duel_cmp_cache_free(duel_cmp_cache *c)
{
    free(c->e);
    c->e = NULL;
    c->n = c->cap = 0;
}
