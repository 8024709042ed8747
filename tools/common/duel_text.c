/* duel_text.c - text from input made safe to print in a message: control bytes escaped, so that one message stays one line. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "duel_text.h"

/* backslash: '\\' doubled too (a value), or kept (a message that may hold escaped values already) */
static const char *duel_text_escape_as(const char *s, char *buf, size_t cap, int backslash)
{
    size_t n = 0;
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        char esc[5];
        size_t k, len;
        if (c < 0x20 || c == 0x7f) {
            snprintf(esc, sizeof esc, "\\x%02x", (unsigned)c);
            len = 4;
        } else if (c == '\\' && backslash) {
            esc[0] = esc[1] = '\\';
            len = 2;
        } else {
            esc[0] = (char)c;
            len = 1;
        }
        if (n + len >= cap)
            break;
        for (k = 0; k < len; k++)
            buf[n++] = esc[k];
    }
    buf[n] = '\0';
    return buf;
}

const char *duel_text_escape(const char *s, char *buf, size_t cap)
{
    return duel_text_escape_as(s, buf, cap, 1);
}

void duel_csv_field(FILE *f, const char *s)
{
    if (strpbrk(s, ",\"\r\n") == NULL) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (; *s != '\0'; s++) {
        if (*s == '"')
            fputc('"', f);
        fputc(*s, f);
    }
    fputc('"', f);
}

const char *duel_text_escape_msg(const char *s, char *buf, size_t cap)
{
    return duel_text_escape_as(s, buf, cap, 0);
}

const char *duel_esc(const char *s)
{
    static char buf[DUEL_ESC_SLOTS][1024];
    static unsigned next;
    char *b = buf[next++ % DUEL_ESC_SLOTS];
    return duel_text_escape(s != NULL ? s : "", b, sizeof buf[0]);
}

const char *duel_esc_msg(const char *s)
{
    static char buf[DUEL_ESC_SLOTS][8192];
    static unsigned next;
    char *b = buf[next++ % DUEL_ESC_SLOTS];
    return duel_text_escape_as(s != NULL ? s : "", b, sizeof buf[0], 0);
}

const char *duel_text_vline(char *buf, size_t cap, const char *fmt, va_list ap)
{
    size_t n;
    vsnprintf(buf, cap, fmt, ap);
    n = strlen(buf);
    if (n > 0 && buf[n - 1] == '\n')
        buf[n - 1] = '\0';
    return buf;
}
