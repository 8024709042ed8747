/* neat_ini.h - the INI reader of every tool: sections, key = value, comments; every error names the file and line. */
#ifndef NEAT_INI_H
#define NEAT_INI_H

#include <stddef.h>

/*
 * The syntax (docs/tools.md, "Configuration"):
 *   - lines end in \n (a \r before it is dropped); at most NEAT_INI_MAX_LINE
 *     characters each, NEAT_INI_MAX_FILE bytes in all, no NUL byte;
 *   - blank lines, and lines whose first non-blank character is ';' or '#',
 *     are comments; there are no comments after a value;
 *   - [section], blanks allowed around the name;
 *   - key = value: blanks around key and value are dropped; the value is the
 *     rest of the line; every key is inside a section;
 *   - a key given twice in one section is an error (naming both lines);
 *   - at most NEAT_INI_MAX_KEYS keys; a UTF-8 byte order mark at the start is skipped.
 * Anything else is an error. The reader knows no keys: the handler does.
 */
#define NEAT_INI_MAX_LINE 1000
#define NEAT_INI_MAX_FILE (1u << 20)
#define NEAT_INI_MAX_KEYS 512 /* far more than every key of every section */

/* Called for each key in file order, except that a [neat] profile key and a
 * [world] rules key come before all the others (each sets the values the
 * other keys of its section refine: docs/parameters.md, docs/duel-world.md): 0, or -1 with one line in err (no file or line: the
 * reader adds them). */
typedef int (*neat_ini_handler)(void *user, const char *section, const char *key, const char *value, char *err,
                                size_t err_len);

/* Parses len bytes of text (not NUL-terminated) named name in messages.
 * 0, or -1 with "NAME:LINE: problem" in err. */
int neat_ini_parse_text(const char *name, const char *text, size_t len, neat_ini_handler h, void *user, char *err,
                        size_t err_len);

/* Reads path (a regular file, NEAT_INI_MAX_FILE bytes at most) and parses
 * it. 0, or -1 with one line naming the file (and the line) in err. */
int neat_ini_parse_file(const char *path, neat_ini_handler h, void *user, char *err, size_t err_len);

#endif /* NEAT_INI_H */
