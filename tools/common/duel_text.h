/* duel_text.h - text from input made safe to print in a message: control bytes escaped, so that one message stays one line. */
#ifndef DUEL_TEXT_H
#define DUEL_TEXT_H

#include <stddef.h>

/* s with every byte below 0x20 and 0x7f written as \xNN (and '\' as "\\"), cut to fit buf (cap >= 1). buf. */
const char *duel_text_escape(const char *s, char *buf, size_t cap);

#endif /* DUEL_TEXT_H */
