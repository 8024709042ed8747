/* duel.h - the robot duel world (docs/duel-world.md) in fixed point: its chosen rules as data, world, sensors, games, comparisons. */
#ifndef DUEL_H
#define DUEL_H

/*
 * Everything on the game path is integer arithmetic, so a game is the same
 * bit for bit on every machine, compiler and thread count. The formats are
 * written once, in docs/duelsim.md:
 *   positions, distances, energies  int32 Q16.16 (DUEL_ONE = 1.0)
 *   headings                        uint32 binary angle (2^32 = one turn, counter-clockwise from +x)
 *   sensor values, motor outputs    nrt_q15 (Q1.15), as the runtime uses them
 * Nothing here allocates; a world is a plain struct the caller owns.
 */

#include <stddef.h>
#include <stdint.h>

#include "nrt.h"

/* C++ callers link against the C symbols */
#ifdef __cplusplus
extern "C" {
#endif

#define DUEL_SPEC_VERSION 1

/* the export attribute of the shared libraries (empty in static and firmware builds) */
#ifndef DUEL_API
#define DUEL_API NEAT_DUEL_EXPORT
#endif

/* ---- fixed point ---- */
#define DUEL_ONE 65536                 /* Q16.16 */
#define DUEL_FIX(v) ((int32_t)((v) * DUEL_ONE))
typedef uint32_t duel_angle;           /* binary angle */
#define DUEL_HALF_TURN 0x80000000u     /* pi */

/* ---- the world's fixed rules ([paper] in docs/duel-world.md) ---- */
#define DUEL_BOARD 600
#define DUEL_MAX_STEPS 750
#define DUEL_COLLIDE_DIST 20
#define DUEL_MAX_FOOD 11
#define DUEL_MAX_TRAIN_FOOD 9          /* a comparison layout adds 2 items to the training ones */
#define DUEL_CANDIDATES 12             /* candidate positions of a comparison item on each half */
#define DUEL_CONFIGS 144               /* comparison food configurations: 12 x 12 */
#define DUEL_TRAINING (-1)             /* food configuration: the training items */
#define DUEL_N_INPUTS 13               /* bias, 5 food, 5 robot, energy difference, wall */
#define DUEL_N_OUTPUTS 3               /* turn left, turn right, forward */

/* World v1's chosen values (duel_rules_v1 holds them all; the code reads
 * the rules of its world, never these) */
#define DUEL_RADIUS 10
#define DUEL_START_ENERGY 1200
#define DUEL_FOOD_ENERGY 200
#define DUEL_EAT_DIST 15
#define DUEL_TRAIN_FOOD 9

/* ---- the world's chosen rules, as data (docs/duel-world.md) ----
 * Every rule marked [chosen] is a field here; a caller may make any world
 * that duel_rules_check accepts. Lengths and energies are Q16.16, headings
 * binary angles; the readings' ranges and scale are whole units, because
 * their arithmetic divides by them exactly. The struct is plain data the
 * caller owns: nothing here allocates or keeps a pointer to it past a
 * call, except the world (below), which points at its rules for the game. */
typedef struct duel_rules {
    int32_t radius;                    /* a robot's radius: its centre stays in [radius, 600 - radius]; v1 10 */
    int32_t start_x[2], start_y[2];    /* [side] start position; v1 west (100, 300), east (500, 300) */
    uint32_t start_heading[2];         /* [side] binary angle; v1 west pi, east 0 (facing away) */
    int32_t start_energy;              /* v1 1200 */
    int32_t food_energy;               /* an item's worth; v1 200 */
    int32_t eat_dist;                  /* an item is eaten below this distance from a centre; v1 15 */
    int32_t share_dist;                /* both within eat_dist and their distances this close: shared, half
                                        * each; v1 0 (only an exact tie) */
    uint32_t n_train;                  /* training items, 0..DUEL_MAX_TRAIN_FOOD; v1 9 */
    int32_t train_x[DUEL_MAX_TRAIN_FOOD], train_y[DUEL_MAX_TRAIN_FOOD]; /* v1 the 3 x 3 grid */
    int32_t cand_x[DUEL_CANDIDATES], cand_y[DUEL_CANDIDATES]; /* comparison item 9 at cand[K / 12], item 10 at
                                        * the mirror (x -> 600 - x) of cand[K % 12]; v1 the 3 x 4 grid of the west half */
    uint16_t food_range;               /* food rangefinders read max(0, 1 - d / food_range); v1 850 */
    uint16_t robot_range;              /* the robot rangefinders likewise; v1 850 */
    uint16_t energy_scale;             /* energy input clamp((E_self - E_other) / scale, -1, 1); v1 200 */
    uint16_t wall_range;               /* wall input max(0, 1 - d / wall_range); v1 200 */
} duel_rules;

/* World v1, the project's rules since its start (docs/duel-world.md): a
 * pointer to constant rules (a function, not an exported object: shared
 * libraries export functions only). */
DUEL_API const duel_rules *duel_rules_v1(void);

/* The rules of a named world ("v1"), or NULL. */
DUEL_API const duel_rules *duel_rules_named(const char *name);
/* The name of rules equal to a named world's, or NULL. */
DUEL_API const char *duel_rules_name(const duel_rules *r);

/* Whether the rules can make a game: DUEL_OK, or DUEL_E_RULES with *field
 * (the INI key: "radius", "start_west", "train_food", ...) and *why (a
 * phrase) set; either pointer may be NULL. Every function below that takes
 * rules checks them first. */
DUEL_API int duel_rules_check(const duel_rules *r, const char **field, const char **why);

/* The rules' canonical bytes (docs/formats.md, "World rules"): what a run's
 * checkpoint keeps. DUEL_RULES_BYTES exactly; unused training slots are
 * written as zeros whatever they hold. */
#define DUEL_RULES_BYTES 236
DUEL_API int duel_rules_encode(const duel_rules *r, uint8_t out[DUEL_RULES_BYTES]);
/* Rules from their bytes: magic, version, length and CRC-32 first, then
 * duel_rules_check. DUEL_OK, or DUEL_E_RULES with *offset (may be NULL) the
 * byte where the problem is (its field's, for rules that cannot make a
 * game). */
DUEL_API int duel_rules_decode(duel_rules *r, const uint8_t *bytes, size_t len, size_t *offset);
/* The rules' identity: a 64-bit FNV-1a hash of their canonical bytes. Equal
 * rules, equal identity; the comparison cache, MPI jobs and logs key on it. */
DUEL_API uint64_t duel_rules_id(const duel_rules *r);
/* Equal as games (the canonical bytes are equal). */
DUEL_API int duel_rules_equal(const duel_rules *a, const duel_rules *b);

enum duel_side { DUEL_WEST = 0, DUEL_EAST = 1 };

/* How a game ended (duel_result.outcome) and what happened in a step (duel_event.kind). */
enum duel_outcome {
    DUEL_RUNNING = 0,
    DUEL_WEST_WINS = 1,  /* collision, west had more energy */
    DUEL_EAST_WINS = 2,
    DUEL_DRAW = 3,       /* collision at equal energy */
    DUEL_TIMEOUT = 4     /* 750 steps without a collision */
};

enum duel_error {
    DUEL_OK = 0,
    DUEL_E_ARG = -1,     /* NULL, bad side, bad food configuration, bad builtin name */
    DUEL_E_NET = -2,     /* a network controller without the 13 inputs / 3 outputs */
    DUEL_E_RULES = -3    /* rules that cannot make a game (duel_rules_check) */
};

typedef struct duel_robot {
    int32_t x, y;        /* Q16.16, kept in [radius, 600 - radius] */
    duel_angle heading;
    int32_t energy;      /* Q16.16 */
    uint8_t eaten;       /* food items eaten (a shared item counts for both) */
} duel_robot;

typedef struct duel_world {
    duel_robot robot[2];
    int32_t food_x[DUEL_MAX_FOOD], food_y[DUEL_MAX_FOOD]; /* Q16.16 */
    uint8_t n_food;
    uint32_t food_mask;  /* bit i set while item i is on the board */
    uint32_t t;          /* steps played */
    int outcome;         /* enum duel_outcome */
    const duel_rules *rules; /* the game's rules (NULL is read as world v1); the caller keeps them alive */
} duel_world;

/* One step's events, for traces. */
typedef struct duel_event {
    uint32_t eaten_by[2]; /* bit i: the robot ate item i this step */
    int outcome;          /* DUEL_RUNNING or how the game ended in this step */
} duel_event;

/* ---- world ---- */
/* Start of a game of world v1 on food configuration DUEL_TRAINING or 0..143. */
DUEL_API int duel_world_init(duel_world *w, int food_config);
/* The same under rules (checked: DUEL_E_RULES), which the world then points
 * at until the game ends. */
DUEL_API int duel_world_init_rules(duel_world *w, const duel_rules *rules, int food_config);
/* The 13 inputs of robot `side` from the current state (spec order). */
DUEL_API void duel_sense(const duel_world *w, int side, nrt_q15 in[DUEL_N_INPUTS]);
/* One step with both robots' outputs (l, r, f): move, pay, eat, collide,
 * time out. ev may be NULL. Returns the outcome (DUEL_RUNNING while on). */
DUEL_API int duel_world_step(duel_world *w, const nrt_q15 out_west[DUEL_N_OUTPUTS],
                             const nrt_q15 out_east[DUEL_N_OUTPUTS], duel_event *ev);

/* ---- fixed-point geometry (duel_trig.c) ---- */
/* cos and sin of a binary angle, Q2.30; exactly symmetric (cos(-a) = cos(a),
 * cos(pi - a) = -cos(a), ...). Error against double: docs/duelsim.md. */
DUEL_API void duel_cossin(duel_angle a, int32_t *c, int32_t *s);
/* floor(sqrt(x)) */
DUEL_API uint32_t duel_isqrt64(uint64_t x);

/* ---- the vector path ---- */
/* The sensing paths of an x86-64 build (docs/duelsim.md, "Speed"); every
 * result is the same on each. */
enum duel_simd {
    DUEL_SIMD_NONE = 0,  /* scalar: duel_sense for each robot */
    DUEL_SIMD_AVX2 = 1,  /* both robots at once with AVX2 */
    DUEL_SIMD_AVX512 = 2 /* the same, the food scan with AVX-512VL's masks */
};
/* The path duel_play takes (enum duel_simd): the best this processor has,
 * up to the cap of duel_simd_allow. Non-zero whenever any vector path is. */
DUEL_API int duel_simd_active(void);
/* Caps the path at level (enum duel_simd; the default, DUEL_SIMD_AVX512,
 * allows every one; 0 the scalar path only), for comparisons and tests.
 * Not synchronised: call it before any game starts. */
DUEL_API void duel_simd_allow(int level);

/* ---- controllers ---- */
enum duel_builtin { DUEL_IDLE = 0, DUEL_SPINNER, DUEL_FORAGER, DUEL_HUNTER, DUEL_FORAGER_HUNTER, DUEL_N_BUILTINS };

typedef struct duel_controller {
    nrt_net *net;        /* a loaded champion, or NULL for a builtin */
    int builtin;         /* enum duel_builtin when net is NULL */
} duel_controller;

/* "idle", "spinner", ... -> enum duel_builtin, or DUEL_E_ARG. */
DUEL_API int duel_builtin_parse(const char *name);
DUEL_API const char *duel_builtin_name(int builtin);
/* The builtin's outputs for these inputs (pure functions of the inputs). */
DUEL_API void duel_builtin_act(int builtin, const nrt_q15 in[DUEL_N_INPUTS], nrt_q15 out[DUEL_N_OUTPUTS]);

/* ---- games ---- */
typedef struct duel_result {
    int outcome;         /* enum duel_outcome */
    uint32_t steps;
    int32_t energy[2];   /* final, Q16.16 */
    uint8_t eaten[2];
} duel_result;

/* Called before each step's move: t, the state, both robots' inputs and outputs. */
typedef void (*duel_trace_fn)(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                              const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev);

/* One game. Networks are reset first; the two controllers may not share one
 * nrt_net (DUEL_E_ARG: load the blob twice). trace may be NULL; it is called
 * once per step with the state before the move and that step's events. */
DUEL_API int duel_play(duel_controller *west, duel_controller *east, int food_config, duel_result *res,
                       duel_trace_fn trace, void *ud);
/* The same under rules (NULL: v1). */
DUEL_API int duel_play_rules(const duel_rules *rules, duel_controller *west, duel_controller *east, int food_config,
                             duel_result *res, duel_trace_fn trace, void *ud);

/* Two games at once, game k between west[k] and east[k] on food_config[k]:
 * exactly what duel_play(west[0], ...) then duel_play(west[1], ...) give
 * (results, and the networks' states after). Faster on x86-64 hosts, where
 * the two games' steps interleave (docs/duelsim.md); the two games may
 * share controllers (a host meeting two opponents), one game's two
 * controllers may not share a network (DUEL_E_ARG). No trace. On an error
 * neither result is set: duel_play each game to learn which one fails. */
DUEL_API int duel_play2(duel_controller *const west[2], duel_controller *const east[2], const int food_config[2],
                        duel_result res[2]);
/* The same under rules (NULL: v1), both games. */
DUEL_API int duel_play2_rules(const duel_rules *rules, duel_controller *const west[2], duel_controller *const east[2],
                              const int food_config[2], duel_result res[2]);

/* The 288-game comparison: every configuration, a starting west then east. */
typedef struct duel_tally {
    uint32_t wins_a, wins_b, draws, timeouts;
} duel_tally;
DUEL_API int duel_compare(duel_controller *a, duel_controller *b, duel_tally *tally);
/* The same under rules (NULL: v1). */
DUEL_API int duel_compare_rules(const duel_rules *rules, duel_controller *a, duel_controller *b, duel_tally *tally);

/* How a game ended, for people: "west wins (collision, more energy)", ... */
DUEL_API const char *duel_outcome_text(int outcome);

#ifdef __cplusplus
}
#endif

#endif /* DUEL_H */
