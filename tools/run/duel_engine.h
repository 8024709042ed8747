/* duel_engine.h - the run engine: a coevolution, or an evolution against fixed opponents, in a run directory, one generation at a time, under duel_evolve run/resume, the Python package and anyone's program. */
/* tools/run/: the run engine (docs/library.md, "The run engine"). It owns everything that makes a run directory
 * safe: the lock, the refusal of a foreign directory, the checks of a resume against the checkpoint and the seal,
 * the rebuilding of lost records, atomic writes, log.txt. It never prints and never exits: it reports through
 * the hooks its caller gives, and returns a status. */
#ifndef DUEL_ENGINE_H
#define DUEL_ENGINE_H

#include <signal.h>
#include <stdint.h>

#include "duel_config.h"
#include "neat.h"
#include "neat_coev.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The statuses every function below returns: duel_evolve's exit statuses. */
enum {
    DUEL_ENGINE_OK = 0,
    DUEL_ENGINE_E_SYSTEM = 1,  /* the machine's fault: a file that cannot be written, memory, a failed game */
    DUEL_ENGINE_E_INPUT = 2,   /* the caller's or the directory's: a refused configuration, directory or edit */
    DUEL_ENGINE_STOPPED = 130  /* stopped on request (duel_engine_stop, SIGINT under the command) */
};

/* What the engine says to people, through the say hook: a refusal or failure (the command prints it after
 * "duel_evolve: "), a note that does not stop anything (likewise), or information the command prints unless
 * --quiet ("resuming DIR at generation G of N"). */
typedef enum { DUEL_SAY_ERROR = 0, DUEL_SAY_NOTE = 1, DUEL_SAY_INFO = 2 } duel_say_kind;

struct duel_fixed_report; /* duel_fixed.h: a generation of a run against fixed opponents */

/* A generation played and recorded (every file of it written and the checkpoint saved). The rows are the bytes
 * appended to the run's files, each ending in its newline; valid during the hook only. */
typedef struct duel_engine_record {
    uint32_t generation;            /* the generation played */
    uint32_t generations;           /* the run's total */
    double seconds;                 /* its wall time, games and records */
    const neat_coev_report *coev;   /* a coevolution's report, or NULL */
    const struct duel_fixed_report *fixed; /* a run against fixed opponents': its report, or NULL */
    const char *generations_rows;   /* generations.csv: two rows (A, B) for a coevolution, one otherwise */
    const char *dominance_row;      /* dominance.csv: the new dominant's row, or NULL */
    const char *strength_row;       /* strength.csv: the champion's games against the builtins, or NULL */
    /* a coevolution's top dominant after this generation (0 for a fixed run) */
    uint32_t dominants, dominant_generation, dominant_hidden, dominant_connections;
} duel_engine_record;

typedef struct duel_engine_hooks {
    void *ud;
    /* one line, without a newline; may be NULL (the last error stays in duel_engine_last_error) */
    void (*say)(void *ud, duel_say_kind kind, const char *text);
    /* after each generation is recorded; may be NULL */
    void (*generation)(void *ud, const duel_engine_record *rec);
    /* games of the generation in flight, done of total in its current batch, from the thread that called
     * duel_engine_step, a few times a second at most; may be NULL */
    void (*progress)(void *ud, uint32_t generation, uint64_t done, uint64_t total);
} duel_engine_hooks;

typedef struct duel_engine_options {
    uint32_t threads;           /* game threads: 0 every core */
    int record_games;           /* each generation's champion games as LCM logs in DIR/games/ */
    /* a new run: where its configuration came from and the overrides it holds, for log.txt only (NULL: none);
     * a resume: the overrides to apply ("KEY=VALUE", as duel_evolve resume --set) */
    const char *config_name;
    const char *const *sets;
    uint32_t n_sets;
    uint32_t generations;       /* a resume: the run's new total (0: as config.ini says) */
    int shorten;                /* a resume: fewer generations than config.ini's are meant */
    duel_engine_hooks hooks;
} duel_engine_options;

typedef struct duel_engine duel_engine;

/* A new run of cfg (checked: duel_config_check) in dir: the directory created or taken (empty, or a run's files
 * that a run died before checkpointing), locked for the engine's life, config.ini written. */
DUEL_RUN_API int duel_engine_new(duel_engine **out, const duel_config *cfg, const char *dir, const duel_engine_options *o);
/* The run in dir, to go on from its checkpoint: config.ini, the checkpoint and the records checked against
 * each other, lost records rebuilt, o's overrides and new total applied and written into config.ini. */
DUEL_RUN_API int duel_engine_resume(duel_engine **out, const char *dir, const duel_engine_options *o);

/* Plays n generations (0: up to the run's total), or fewer at the run's end or a stop. DUEL_ENGINE_OK,
 * DUEL_ENGINE_STOPPED (what was played is saved: a resume goes on from it), or an error. */
DUEL_RUN_API int duel_engine_step(duel_engine *E, uint32_t n);
/* Asks the generation in flight to be the last: async-signal-safe, from any thread. */
DUEL_RUN_API void duel_engine_stop(duel_engine *E);
/* The flag duel_engine_stop sets, for a signal handler (duel_signal_install); cleared by duel_engine_step. */
DUEL_RUN_API volatile sig_atomic_t *duel_engine_stop_flag(duel_engine *E);

/* The generation to play next, and the run's total. */
DUEL_RUN_API uint32_t duel_engine_generation(const duel_engine *E);
DUEL_RUN_API uint32_t duel_engine_generations(const duel_engine *E);
DUEL_RUN_API const char *duel_engine_dir(const duel_engine *E);
/* The run's configuration (config.ini's, with its [overrides]) and the parameters of the generation in flight. */
DUEL_RUN_API const duel_config *duel_engine_config(const duel_engine *E);
DUEL_RUN_API const duel_config *duel_engine_params(const duel_engine *E);
/* The coevolution (NULL for a run against fixed opponents) or the fixed run's population (NULL otherwise). */
DUEL_RUN_API const neat_coev *duel_engine_coev(const duel_engine *E);
DUEL_RUN_API const neat_pop *duel_engine_pop(const duel_engine *E);
/* The game threads the run plays on. */
DUEL_RUN_API uint32_t duel_engine_threads(const duel_engine *E);
/* The last DUEL_SAY_ERROR line ("" when none). */
DUEL_RUN_API const char *duel_engine_last_error(const duel_engine *E);

/* Writes the run's last lines into log.txt (time spent, MPI), gives the directory's lock back and frees E.
 * DUEL_ENGINE_OK, or DUEL_ENGINE_E_SYSTEM when log.txt could not be written during the run. NULL is accepted. */
DUEL_RUN_API int duel_engine_close(duel_engine *E);

/* Another NEAT's reproduction for the coevolution runs this process starts whose [run] reproduction is `which`
 * (enum duel_reproduction; tools/neatcpp/neatcpp_duel.cpp: NEAT C++ 1.2.1's own): begin(ud, cfg) when such a
 * run starts (0, or -1 after one line on stderr), then reproduce as neat_coev_set_reproducer calls it. Without
 * one, such a run is refused; and such a run is never resumed, the other NEAT's populations being in no file.
 * Process-wide: set it before any engine starts. */
typedef struct duel_reproducer {
    int which;
    int (*begin)(void *ud, const duel_config *cfg);
    neat_coev_reproduce_fn reproduce;
    void *ud;
} duel_reproducer;
DUEL_RUN_API void duel_engine_set_reproducer(const duel_reproducer *r);

/* What records a generation's champion games (options' record_games) as event logs in DIR/games/: duel_evolve's
 * LCM recorder (tools/lcm/duel_lcm_champ.h), registered by a program that has it, process-wide. Without one,
 * record_games is refused. 0, or -1 with one line in msg. */
typedef int (*duel_engine_game_recorder)(const char *dir, uint32_t generation, uint32_t champion_pop,
                                         const neat_genome *champion, const neat_genome *other,
                                         const neat_params *p, const duel_rules *rules, char *msg, size_t cap);
DUEL_RUN_API void duel_engine_set_game_recorder(duel_engine_game_recorder fn);

/* Where a run's games may go besides the engine's threads (duel_evolve's MPI ranks, tools/mpi/): registered by a
 * program that has such an executor, process-wide; without one, every game is played on the engine's threads. */
struct duel_games;
typedef struct duel_engine_executor {
    uint32_t (*ranks)(void);                 /* the processes that play a run's games, this one included */
    uint32_t (*default_threads)(void);       /* the threads for threads = 0 when ranks() > 1 */
    void (*attach)(struct duel_games *games); /* the run's executor from now on spread over them */
    void (*describe)(char *out, size_t cap); /* a line for log.txt at the end ("" for none) */
    int (*stop_requested)(void);             /* 1 when the run should stop after the generation in flight */
} duel_engine_executor;
DUEL_RUN_API void duel_engine_set_executor(const duel_engine_executor *x);

#ifdef __cplusplus
}
#endif

#endif /* DUEL_ENGINE_H */
