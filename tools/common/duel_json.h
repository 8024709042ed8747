/* duel_json.h - what the commands' JSON output shares: strings escaped as JSON wants them. */
#ifndef DUEL_JSON_H
#define DUEL_JSON_H

#include <stdio.h>

/* s as a JSON string, quotes included: '"' and '\' escaped, control characters as \u00XX
 * (other bytes as they are: file names are passed through). */
void duel_json_str(FILE *f, const char *s);

#endif /* DUEL_JSON_H */
