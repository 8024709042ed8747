/* duel_font.h - the built-in bitmap font of the frames' legend, numbers and outcome (no font library, no font file). */
#ifndef DUEL_FONT_HEADER_H
#define DUEL_FONT_HEADER_H

#include <stdint.h>

/* A glyph is DUEL_FONT_W x DUEL_FONT_H dots; text advances DUEL_FONT_ADV
 * dots a character (one dot of space between glyphs). */
#define DUEL_FONT_W 5
#define DUEL_FONT_H 7
#define DUEL_FONT_ADV 6
/* g, p, q and y hang this many dots below the others (their tails): a
 * line of text takes DUEL_FONT_H + DUEL_FONT_DROP dots */
#define DUEL_FONT_DROP 2
/* The character drawn as an ellipsis (DEL, which no name shows) */
#define DUEL_FONT_ELLIPSIS '\x7f'

/* The DUEL_FONT_H rows of c's glyph, top first, bit (DUEL_FONT_W - 1 - x)
 * set where column x is drawn. */
const uint8_t *duel_font_glyph(char c);
/* How many dots lower than the others c's glyph is drawn: 0 or DUEL_FONT_DROP. */
int duel_font_drop(char c);

#endif /* DUEL_FONT_HEADER_H */
