/* duel_engine_internal.h - the run engine's state and what its files share (not installed). */
#ifndef DUEL_ENGINE_INTERNAL_H
#define DUEL_ENGINE_INTERNAL_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "duel_config.h"
#include "duel_engine.h"
#include "duel_files.h"
#include "duel_fixed.h"
#include "duel_games.h"

struct duel_engine {
    char *dir;                 /* the run directory (the engine's copy) */
    duel_config cfg;           /* config.ini: generation 0's parameters and the [overrides] from later ones */
    duel_config eff;           /* the parameters of the generation in flight (cfg with its overrides up to it) */
    neat_coev *coev;           /* a coevolution run, or */
    duel_fixed *fixed;         /* a run against fixed opponents ([opponents] play) */
    duel_net opp[DUEL_MAX_OPPONENTS]; /* its opponents (blobs malloc'd) */
    duel_games *games;
    uint32_t threads;
    int record_games;          /* DIR/games/gen-NNNNN-{west,east}.lcm */
    duel_engine_hooks hooks;
    volatile sig_atomic_t stop; /* duel_engine_stop: the generation in flight finishes and is saved */
    duel_lock lock;            /* the run directory's, for the engine's life */
    uint32_t gen_in_flight;
    int log_failed;            /* log.txt could not be written: the run stops after the generation */
    int finished_logged;       /* "finished N generations" is in log.txt */
    double gen_secs;           /* this engine's generations, in seconds */
    uint32_t first_applied;    /* 1 + the generation whose overrides were applied before the loop (0: none) */
    char opp_note[4600];       /* an opponent made in another world than the run's: logged when the run starts */
    int strength_old;          /* strength.csv is of the format without its champion column: rows go on so */
    /* the rows of the generation just recorded, for the generation hook */
    char rows[4200];
    char *dominance_row;       /* malloc'd, or NULL */
    char strength_row[600];
    int have_strength;
    /* the engine's own buffers for values echoed in its messages (never a static one: engines run in threads) */
    char esc[4][1100];
    unsigned esc_next;
    char esc_msg[2][8200];
    unsigned esc_msg_next;
    char last_error[8400];
};

/* duel_engine.c */
void de_say(duel_engine *R, duel_say_kind kind, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
#define de_err(R, ...) de_say((R), DUEL_SAY_ERROR, __VA_ARGS__)
/* one timestamped line in DIR/log.txt */
void de_log(duel_engine *R, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* a path or a loader's message as it may be echoed (control bytes escaped; duel_text.h), in R's buffers */
const char *de_esc(duel_engine *R, const char *s);
const char *de_esc_msg(duel_engine *R, const char *s);
double de_now(void);
void de_path(char *out, size_t cap, const char *dir, const char *name);
const char *de_s(uint32_t n);
const char *de_pop_name(uint32_t p);
const char *de_game_error(int err);
uint32_t de_next_gen(const duel_engine *R);
void de_free_run(duel_engine *R);
int de_tag_run(duel_engine *R);
int de_run_tag_of(const duel_engine *R, uint8_t *buf, size_t *len);
int de_load_opponents(duel_engine *R, int copies);
int de_copy_opponents(duel_engine *R);
int de_create(duel_engine *R);
int de_go(duel_engine *R);
int de_engine_alloc(duel_engine **out, const char *dir, const duel_engine_options *o);
void de_engine_discard(duel_engine *R);
void de_threads_words(uint32_t threads, char *buf, size_t cap);

/* duel_engine_dir.c */
#define DUEL_SEAL "; checksum "
int de_write_config(duel_engine *R);
int de_config_sealed(const char *dir, uint32_t *gens, uint32_t *every);
int de_take_lock(duel_engine *R, const char *dir);
int de_has_history(const char *dir, char *msg, size_t cap);
int de_prepare_dir(duel_engine *R);

/* duel_engine_records.c */
int de_record(duel_engine *R, const neat_coev_report *rep, double secs);
int de_record_fixed(duel_engine *R, const duel_fixed_report *rep, double secs);
void de_opp_label(const duel_engine *R, uint32_t k, char *buf, size_t cap);
int de_rebuild_strength(duel_engine *R, uint32_t g);
int de_rebuild_dominance(duel_engine *R);
int de_check_generations(duel_engine *R, uint32_t g);

#endif /* DUEL_ENGINE_INTERNAL_H */
