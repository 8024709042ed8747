/* duel_outputs.h - whether a command may write an output where it was told to: never over one of its inputs, and over an existing file only when that file is recognisably this command's output of this kind (or the user says --force). */
#ifndef DUEL_OUTPUTS_H
#define DUEL_OUTPUTS_H

#include <stddef.h>
#include <stdint.h>

/* The first line of a run's config.ini and of an experiment's plan.ini (their writers start each file with it;
 * a directory is recognised as a run's or an experiment's by it). */
#define DUEL_RUN_CONFIG_MARK "; the effective configuration of this run"
#define DUEL_EXP_PLAN_MARK "; the plan of this experiment"

/* How much of an existing file is looked at to recognise it. */
#define DUEL_OUT_HEAD 4096

/* A kind of output: what the message calls it, and how one is recognised
 * (the first bytes every such file starts with, or a test of the first
 * DUEL_OUT_HEAD bytes, or both: either one suffices). */
typedef struct duel_out_kind {
    const char *name;   /* "a compare CSV" */
    const char *prefix; /* NULL: no prefix */
    int (*ours)(const uint8_t *head, size_t len, const char *path);
} duel_out_kind;

/* Whether command cmd may write its output opt (an option's name, "-o")
 * at path:
 * - never a directory, and never in a directory that does not exist (both
 *   refused before any work);
 * - never a file of any run or experiment directory (a run's checkpoint,
 *   configuration, records, log, champions, opponents, games, ladder; an
 *   experiment's plan, configurations, report), even with force;
 * - never over one of its inputs (the same file however named, a run
 *   directory's own records when an input is a run directory, or another
 *   output of the same command): refused even with force;
 * - over an existing regular file only when it is empty, recognisably of
 *   this kind, or force is set;
 * - anything else that exists (a pipe, /dev/stdout, a device) is written in
 *   place as before, and a missing file is created.
 * 0, or 2 after one line on stderr. inputs may hold NULLs (skipped). */
int duel_out_allowed(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                     const char *const *inputs, size_t n_inputs);

/* duel_out_allowed for the file a command keeps in the run it reads (ladder's
 * RUN/ladder.csv): the run-file rule above is not applied. */
int duel_out_own_allowed(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                         const char *const *inputs, size_t n_inputs);
/* The same two, printing nothing: 2 with the line in msg (names escaped; print it through duel_esc_msg). */
int duel_out_allowed_msg(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind, int force,
                         const char *const *inputs, size_t n_inputs, char *msg, size_t cap);
int duel_out_own_allowed_msg(const char *cmd, const char *opt, const char *path, const duel_out_kind *kind,
                             int force, const char *const *inputs, size_t n_inputs, char *msg, size_t cap);

/* 1 when a and b name the same file (both existing: the same inode; else
 * the same resolved directory and name). */
int duel_same_path(const char *a, const char *b);

/* 1 when name is one of the files a run directory holds (docs/tools.md, "The
 * run directory"), or NAME.tmp of one. */
int duel_is_run_file(const char *name);

/* 1 when the first bytes are an LCM event log's whose first event is on one
 * of this project's channels (DUEL_...). */
int duel_out_is_duel_lcm(const uint8_t *head, size_t len, const char *path);

#endif /* DUEL_OUTPUTS_H */
