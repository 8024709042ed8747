/* duel_generations.h - a run directory's generations.csv read back: one row per population and generation, the fields the experiment's progress and report use, every one checked. */
#ifndef DUEL_GENERATIONS_H
#define DUEL_GENERATIONS_H

#include <stddef.h>
#include <stdint.h>

#define DUEL_GENERATIONS_HEADER                                                                                       \
    "generation,population,best_fitness,mean_fitness,species,delta_t,mean_hidden,mean_connections,best_hidden,"       \
    "best_connections,min_hidden,max_hidden,min_connections,max_connections,games,champion,seconds\n"
#define DUEL_GENERATIONS_FIELDS 17
#define DUEL_GENERATIONS_MAX_FILE (256u << 20) /* a 500-generation run writes about 100 KB */

/* What to do about rows that are lost: measured as they happened, they cannot be rebuilt from the checkpoint;
 * a run plays again to the same rows (the same seed and configuration: config.ini). */
#define DUEL_GENERATIONS_LOST_ADVICE                                                                                  \
    "rows lost cannot be rebuilt from the checkpoint: restore the file, or play the run again (duel_evolve run "     \
    "--config RUN/config.ini --out NEW_DIR gives the same rows; in an experiment, delete the run's directory and "    \
    "duel_evolve experiment resume plays it again)"

typedef struct duel_gen_row {
    uint32_t generation;
    char pop;                      /* 'A' or 'B' */
    uint32_t min_hidden, max_hidden, min_conns, max_conns;
    double games, seconds;
} duel_gen_row;

/* Parses the text of a generations.csv (name for messages): the header, then rows of 17 fields with a generation
 * and a population A or B; a torn last row (no newline) is not a row. *rows (malloc'd, the caller frees it; NULL
 * when there is none) and *n. 0, or -1 with "NAME:LINE: problem" in err; -3 for a CRLF copy or a duplicated row
 * (duel_csv_odd_line: the rows are there, the message names the fix). */
int duel_generations_parse(const char *name, const char *text, size_t len, duel_gen_row **rows, size_t *n, char *err,
                           size_t err_len);

/* DIR/generations.csv read and parsed. 0; -1 when it cannot be read (errno set, err names the file); -2 when it
 * is not a generations.csv (err names the file and line). */
int duel_generations_read(const char *dir, duel_gen_row **rows, size_t *n, char *err, size_t err_len);

/* The generations recorded in full (the last one whose population B row is there; 0 for none). */
uint32_t duel_generations_done(const duel_gen_row *rows, size_t n);

#endif /* DUEL_GENERATIONS_H */
