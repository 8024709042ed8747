/* duel_text.h - text from input made safe to print in a message: control bytes escaped, so that one message stays one line. */
#ifndef DUEL_TEXT_H
#define DUEL_TEXT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

/* s with every byte below 0x20 and 0x7f written as \xNN (and '\' as "\\"), cut to fit buf (cap >= 1). buf. */
const char *duel_text_escape(const char *s, char *buf, size_t cap);
/* The same with backslashes kept (a whole message whose values are escaped already: duel_esc_msg's way). buf. */
const char *duel_text_escape_msg(const char *s, char *buf, size_t cap);

/* duel_text_escape into one of DUEL_ESC_SLOTS buffers used in turn (of 1024 bytes): for the values echoed in one
 * message, at most that many in one call; the main thread's messages only. */
#define DUEL_ESC_SLOTS 4
const char *duel_esc(const char *s);
/* A whole message built elsewhere (an err buffer naming a file): its control bytes escaped, backslashes kept (so
 * that values escaped in it already stay as they are), in one of DUEL_ESC_SLOTS buffers of 8192 bytes; the main
 * thread's messages only. */
const char *duel_esc_msg(const char *s);

/* A message from fmt in buf (cut to fit, cap >= 1) with its trailing '\n' dropped, for a sink that ends lines
 * itself (stderr with a prefix, a caller's buffer, a hook). buf. */
const char *duel_text_vline(char *buf, size_t cap, const char *fmt, va_list ap);

/* s as one CSV field (RFC 4180): as it is, or in double quotes (each '"' doubled) when it holds a comma, a
 * quote, a CR or a LF. */
void duel_csv_field(FILE *f, const char *s);

#endif /* DUEL_TEXT_H */
