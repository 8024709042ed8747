/* duel_dominance.h - a run directory's dominance.csv read back: one row per dominance level, every field checked. */
#ifndef DUEL_DOMINANCE_H
#define DUEL_DOMINANCE_H

#include <stddef.h>
#include <stdint.h>

typedef struct duel_dominance_row {
    uint32_t level;      /* 1, 2, ...: the row's place */
    uint32_t generation; /* whose champion (champions/gen-NNNNN.blob) it is */
    char pop[2];         /* "A" or "B" */
    uint32_t hidden, conns;
    uint32_t scores;     /* duel_dominance_parse_scores: where this row's scores start */
} duel_dominance_row;

/* A row's result against one level below it: wins and losses of its 288 games. */
typedef struct duel_dominance_score {
    uint32_t wins, losses;
} duel_dominance_score;

#define DUEL_DOMINANCE_HEADER "level,generation,population,hidden,connections,wins\n"
#define DUEL_DOMINANCE_MAX_FILE (256u << 20) /* a 500-generation run writes about 30 KB */

/* Parses the text of a dominance.csv (name for messages): the header, then
 * rows "level,generation,population,hidden,connections,wins" with levels
 * 1, 2, ... in order, generations increasing, population A or B and wins a
 * list of "w:l" separated by single spaces, one per level below. A torn last
 * row (no newline: the writer died) is not a row. *rows (malloc'd, the
 * caller frees it; NULL when there is none) and *n. 0, or -1 with
 * "NAME:LINE: problem" in err. */
int duel_dominance_parse(const char *name, const char *text, size_t len, duel_dominance_row **rows, uint32_t *n,
                         char *err, size_t err_len);

/* The same, and the scores: *scores (malloc'd, the caller frees it; NULL
 * when there is none) holds, for each row, level - 1 scores from
 * (*scores)[row.scores] on: against level - 1 first, level 1 last. */
int duel_dominance_parse_scores(const char *name, const char *text, size_t len, duel_dominance_row **rows,
                                uint32_t *n, duel_dominance_score **scores, char *err, size_t err_len);

/* One row of dominance.csv, newline included, in a malloc'd string (NULL when
 * out of memory): the wins field lists "w:l" for each of the n_beaten levels
 * below, latest first, however many there are. */
char *duel_dominance_row_text(uint32_t level, uint32_t generation, char pop, uint32_t hidden, uint32_t conns,
                              uint32_t n_beaten, const uint16_t *wins, const uint16_t *losses);

/* DIR/dominance.csv read and parsed; err names the file. 0 or -1. */
int duel_dominance_read(const char *dir, duel_dominance_row **rows, uint32_t *n, char *err, size_t err_len);
/* The same with the scores (duel_dominance_parse_scores). */
int duel_dominance_read_scores(const char *dir, duel_dominance_row **rows, uint32_t *n, duel_dominance_score **scores,
                               char *err, size_t err_len);

#endif /* DUEL_DOMINANCE_H */
