/* neat_ini.c - the INI reader of every tool: sections, key = value, comments; every error names the file and line. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "neat_ini.h"


typedef struct ini_seen {
    char section[NEAT_INI_MAX_LINE + 1];
    char key[NEAT_INI_MAX_LINE + 1];
    unsigned line;
} ini_seen;

static int ini_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* [*b, *e) without blanks at either end. */
static void ini_trim(const char **b, const char **e)
{
    while (*b < *e && ini_blank(**b))
        (*b)++;
    while (*e > *b && ini_blank((*e)[-1]))
        (*e)--;
}

static void ini_copy(char *dst, const char *b, const char *e)
{
    memcpy(dst, b, (size_t)(e - b));
    dst[e - b] = '\0';
}

/* [neat] profile and [world] rules come first: each sets the values every other key of its section refines */
static int ini_first(const char *section, const char *key)
{
    return (strcmp(section, "neat") == 0 && strcmp(key, "profile") == 0) ||
           (strcmp(section, "world") == 0 && strcmp(key, "rules") == 0);
}

/* One pass over the text: pass 0 delivers only the keys ini_first names,
 * pass 1 every other key; both check the whole syntax. */
static int ini_pass(const char *name, const char *text, size_t len, neat_ini_handler h, void *user, char *err,
                    size_t err_len, int pass)
{
    /* the pairs seen so far: heap, a table of 512 * 2 KB does not belong on a stack */
    ini_seen *seen = NULL;
    size_t n_seen = 0, i;
    char section[NEAT_INI_MAX_LINE + 1], key[NEAT_INI_MAX_LINE + 1], value[NEAT_INI_MAX_LINE + 1], msg[400];
    const char *p = text, *end = text + len;
    unsigned line = 0;
    int have_section = 0, status = -1;

    if (memchr(text, '\0', len) != NULL) {
        const char *z = (const char *)memchr(text, '\0', len);
        for (p = text; p < z; p++)
            line += *p == '\n';
        snprintf(err, err_len, "%s:%u: a NUL byte: not a text file", name, line + 1);
        return -1;
    }
    if (len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0) { /* a UTF-8 byte order mark, as some editors write */
        text += 3;
        len -= 3;
        p = text;
        end = text + len;
    }
    seen = (ini_seen *)malloc(NEAT_INI_MAX_KEYS * sizeof *seen);
    if (seen == NULL) {
        snprintf(err, err_len, "%s: out of memory", name);
        return -1;
    }
    section[0] = '\0';
    while (p < end) {
        const char *nl = (const char *)memchr(p, '\n', (size_t)(end - p));
        const char *b = p, *e = nl != NULL ? nl : end, *eq;
        p = nl != NULL ? nl + 1 : end;
        line++;
        if (e > b && e[-1] == '\r')
            e--;
        if (e - b > NEAT_INI_MAX_LINE) {
            snprintf(err, err_len, "%s:%u: a line of %ld characters (at most %d)", name, line, (long)(e - b),
                     NEAT_INI_MAX_LINE);
            goto out;
        }
        {
            /* a control byte (a tab apart) is in no key or value: refused here, so that no message echoes it */
            const char *q;
            for (q = b; q < e; q++)
                if (((unsigned char)*q < 0x20 && *q != '\t') || (unsigned char)*q == 0x7f) {
                    snprintf(err, err_len, "%s:%u: a control character (byte 0x%02x) at column %ld", name, line,
                             (unsigned)(unsigned char)*q, (long)(q - b) + 1);
                    goto out;
                }
        }
        ini_trim(&b, &e);
        if (b == e || *b == ';' || *b == '#')
            continue;
        if (*b == '[') {
            const char *close = (const char *)memchr(b, ']', (size_t)(e - b));
            const char *sb = b + 1, *se = close;
            if (close == NULL || close != e - 1) {
                snprintf(err, err_len, "%s:%u: a section header is [name] alone on its line", name, line);
                goto out;
            }
            ini_trim(&sb, &se);
            if (sb == se) {
                snprintf(err, err_len, "%s:%u: an empty section name", name, line);
                goto out;
            }
            ini_copy(section, sb, se);
            have_section = 1;
            continue;
        }
        eq = (const char *)memchr(b, '=', (size_t)(e - b));
        if (eq == NULL) {
            snprintf(err, err_len, "%s:%u: expected key = value, [section] or a comment", name, line);
            goto out;
        }
        {
            const char *kb = b, *ke = eq, *vb = eq + 1, *ve = e;
            ini_trim(&kb, &ke);
            ini_trim(&vb, &ve);
            if (kb == ke) {
                snprintf(err, err_len, "%s:%u: a value without a key", name, line);
                goto out;
            }
            ini_copy(key, kb, ke);
            ini_copy(value, vb, ve);
        }
        if (!have_section) {
            snprintf(err, err_len, "%s:%u: key '%s' before any [section]", name, line, key);
            goto out;
        }
        for (i = 0; i < n_seen; i++)
            if (strcmp(seen[i].section, section) == 0 && strcmp(seen[i].key, key) == 0) {
                snprintf(err, err_len, "%s:%u: '%s' given a second time in [%s] (first on line %u)", name, line, key,
                         section, seen[i].line);
                goto out;
            }
        if (n_seen == NEAT_INI_MAX_KEYS) {
            snprintf(err, err_len, "%s:%u: more than %d keys", name, line, NEAT_INI_MAX_KEYS);
            goto out;
        }
        strcpy(seen[n_seen].section, section);
        strcpy(seen[n_seen].key, key);
        seen[n_seen].line = line;
        n_seen++;
        msg[0] = '\0';
        if (ini_first(section, key) != (pass == 0))
            continue;
        if (h(user, section, key, value, msg, sizeof msg) != 0) {
            snprintf(err, err_len, "%s:%u: %s", name, line, msg[0] ? msg : "refused");
            goto out;
        }
    }
    status = 0;
out:
    free(seen);
    return status;
}

int neat_ini_parse_text(const char *name, const char *text, size_t len, neat_ini_handler h, void *user, char *err,
                        size_t err_len)
{
    if (ini_pass(name, text, len, h, user, err, err_len, 0) != 0)
        return -1;
    return ini_pass(name, text, len, h, user, err, err_len, 1);
}

int neat_ini_parse_file(const char *path, neat_ini_handler h, void *user, char *err, size_t err_len)
{
    struct stat st;
    char *text;
    size_t got;
    int r;
    FILE *f;
    /* before opening: opening a FIFO would wait for a writer */
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        snprintf(err, err_len, "%s: not a regular file (a directory, a pipe or a device): expected an INI file", path);
        return -1;
    }
    f = fopen(path, "rb");
    if (f == NULL) {
        snprintf(err, err_len, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, err_len, "%s: not a regular file (a directory, a pipe or a device): expected an INI file", path);
        fclose(f);
        return -1;
    }
    if ((unsigned long long)st.st_size > NEAT_INI_MAX_FILE) {
        snprintf(err, err_len, "%s: %llu bytes, more than an INI file here may have (%u)", path,
                 (unsigned long long)st.st_size, NEAT_INI_MAX_FILE);
        fclose(f);
        return -1;
    }
    text = (char *)malloc((size_t)st.st_size + 1);
    if (text == NULL) {
        snprintf(err, err_len, "%s: out of memory", path);
        fclose(f);
        return -1;
    }
    got = fread(text, 1, (size_t)st.st_size + 1, f);
    if (ferror(f) || got > (size_t)st.st_size) {
        snprintf(err, err_len, "%s: cannot read%s", path, ferror(f) ? "" : ": it grew while being read");
        free(text);
        fclose(f);
        return -1;
    }
    fclose(f);
    r = neat_ini_parse_text(path, text, got, h, user, err, err_len);
    free(text);
    return r;
}
