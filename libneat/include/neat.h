/* neat.h - NEAT (Stanley & Miikkulainen): genomes, historical markings, speciation, reproduction, blobs, checkpoints. */
#ifndef NEAT_H
#define NEAT_H

/*
 * libneat is plain C99 with no dependency beyond libc and the runtime's
 * format header (nrt.h). It never prints, never exits, and allocates only
 * through the neat_alloc hook given at creation. A run is a pure function of
 * (parameters, seed, fitness values): the library hands out genomes, the
 * caller evaluates them in any order on any number of threads, and gives the
 * fitness back (neat_pop_set_fitness), then calls neat_pop_epoch.
 *
 *     neat_pop *pop;
 *     neat_pop_create(&pop, &params, NULL, seed, NULL);
 *     for (;;) {
 *         for (i = 0; i < neat_pop_size(pop); i++)
 *             neat_pop_set_fitness(pop, i, evaluate(neat_pop_genome(pop, i)));
 *         neat_pop_epoch(pop);
 *     }
 */

#include <stddef.h>
#include <stdint.h>

#include "neat_duel_version.h"

/* C++ callers link against the C symbols */
#ifdef __cplusplus
extern "C" {
#endif

/* ---- versions ---------------------------------------------------------- */
/* the library's version: the project's (neat_duel_version.h) */
#define NEAT_VERSION_MAJOR NEAT_DUEL_VERSION_MAJOR
#define NEAT_VERSION_MINOR NEAT_DUEL_VERSION_MINOR
#define NEAT_CHECKPOINT_VERSION 4 /* checkpoint format, apart from the code (versions 2 and 3 still load; a
                                   * population using none of NEAT C++'s switches is written as version 3) */
#define NEAT_GENOME_FILE_VERSION 2 /* genome file format: 2 records the genome's origin (neat_genome_save_origin); 1
                                    * (neat_genome_save) records none and still loads */
#define NEAT_GENOME_FILE_MAGIC "NEATGENM" /* its first 8 bytes */

/* the export attribute of the shared libraries (empty in static and firmware builds) */
#ifndef NEAT_API
#define NEAT_API NEAT_DUEL_EXPORT
#endif

/* ---- errors ------------------------------------------------------------- */
enum neat_error {
    NEAT_OK = 0,
    NEAT_E_ARG = -1,       /* bad argument (NULL, out of range) */
    NEAT_E_NOMEM = -2,     /* the allocator refused */
    NEAT_E_PARAM = -3,     /* a parameter out of its documented range */
    NEAT_E_FITNESS = -4,   /* a fitness negative, NaN or infinite, or missing: see neat_pop_error_index */
    NEAT_E_TOOBIG = -5,    /* a network too large for the blob format */
    NEAT_E_FORMAT = -6,    /* checkpoint or genome file bytes: bad magic, version, size or value */
    NEAT_E_CRC = -7,       /* checkpoint or genome file checksum mismatch */
    NEAT_E_TRUNCATED = -8, /* checkpoint or genome file shorter than it says */
    NEAT_E_STATE = -9,     /* call out of order (e.g. fitness after epoch) */
    NEAT_E_COUNTERS = -10  /* node ids, innovation numbers, species ids or generations at their limit (2^31 - 1) */
};

/* ---- allocation: one realloc-style hook ---------------------------------
 * fn(ud, ptr, old_size, new_size): new_size 0 frees ptr and returns NULL;
 * otherwise it returns a block of new_size bytes holding the first
 * min(old, new) bytes of ptr, or NULL when it refuses (ptr is then kept).
 * A NULL neat_alloc pointer means the C library's realloc/free. */
typedef void *(*neat_alloc_fn)(void *ud, void *ptr, size_t old_size, size_t new_size);
typedef struct neat_alloc {
    neat_alloc_fn fn;
    void *ud;
} neat_alloc;

/* ---- the PRNG (xoshiro256**, seeded through splitmix64) ----------------- */
typedef struct neat_rng {
    uint64_t s[4];
} neat_rng;

NEAT_API void neat_rng_seed(neat_rng *rng, uint64_t seed);
NEAT_API uint64_t neat_rng_next(neat_rng *rng);
/* uniform in [0, 1), 53 bits */
NEAT_API double neat_rng_uniform(neat_rng *rng);
/* uniform integer in [0, n), n > 0, without modulo bias */
NEAT_API uint32_t neat_rng_below(neat_rng *rng, uint32_t n);
/* A seed derived from a base seed and a tuple of keys (e.g. generation,
 * host, opponent, side): the same tuple gives the same seed on every
 * machine, independently of evaluation order. */
NEAT_API uint64_t neat_seed_derive(uint64_t base, const uint64_t *keys, size_t n_keys);

/* ---- parameters ---------------------------------------------------------
 * neat_params_default() gives the paper's Appendix A values; every other
 * value and its source is in docs/parameters.md.
 *
 * The task's own shape is not a NEAT parameter, and the defaults are the
 * robot duel's (12 inputs, 3 outputs, 256 networks, recurrent connections
 * allowed). For any other task set at least:
 *
 *     neat_params p = neat_params_default();
 *     p.n_inputs = 3;          // the task's inputs, without the bias
 *     p.n_outputs = 1;         // the task's outputs
 *     p.pop_size = 150;        // the 2002 paper's size for small tasks
 *     p.allow_recurrent = 0;   // feed-forward tasks (nrt_settle then settles)
 *
 * and check with neat_params_check (neat_pop_create does too). */
enum neat_mode {
    NEAT_MODE_COMPLEXIFY = 0, /* structural mutation adds nodes and connections */
    NEAT_MODE_FIXED = 1,      /* no structural mutation */
    NEAT_MODE_SIMPLIFY = 2    /* structural mutation removes connections */
};

enum neat_stagnation {
    /* 2004 paper, Appendix A: the lowest performing species older than
     * dropoff_age generations gets no offspring */
    NEAT_STAGNATION_OLDEST_WORST = 0,
    /* 2002 paper: a species whose best fitness has not improved for
     * dropoff_age generations breeds no more (stagnation_factor 0), or
     * breeds at stagnation_factor times its share */
    NEAT_STAGNATION_IMPROVEMENT = 1,
    /* NEAT C++ 1.2.1 (Species::adjust_fitness, Population::epoch): every
     * cull_every-th generation one species at least cull_age old is culled
     * for good, and a culled species, or one whose best has not risen for
     * dropoff_age - 1 generations, has its fitness times 0.01 */
    NEAT_STAGNATION_CPP = 2
};

/* ---- NEAT C++ 1.2.1's own rules (docs/parameters.md, "NEAT C++ 1.2.1") --
 * Where Kenneth Stanley's release differs from the paper's text, libneat
 * follows the text by default (each switch 0) and offers the release's rule
 * (each switch 1). neat_params_neat_cpp() sets them all. */
enum neat_profile {
    NEAT_PROFILE_DEFAULT = 0, /* the paper's text (Appendix A) where it speaks */
    NEAT_PROFILE_NEAT_CPP = 1 /* NEAT C++ 1.2.1, the authors' release */
};
/* equal_fitness_rule: a crossover of parents of equal fitness */
enum { NEAT_EQUAL_RANDOM = 0,  /* each unmatched gene of either parent kept with excess_equal_prob */
       NEAT_EQUAL_SMALLER = 1  /* the parent with fewer genes counts as the fitter (the second on a tie) */ };
/* reenable_rule: a matching gene disabled in either parent */
enum { NEAT_REENABLE_PAPER = 0, /* enabled unless disable_prob says disabled */
       NEAT_REENABLE_CPP = 1    /* multipoint crossover keeps the chosen gene's flag unless disable_prob disables it */ };
/* add_conn_rule: how a new connection is sought */
enum { NEAT_ADD_CONN_ANY = 0,  /* any pair (any target but the bias and inputs) */
       NEAT_ADD_CONN_CPP = 1   /* a loop-closing link with recur_only_prob, else a loop-free one; targets drawn from
                                * outputs and hidden nodes; an innovation repeated in a generation reuses its weight */ };
/* species_rep: what a genome of the next generation is compared with */
enum { NEAT_REP_RANDOM = 0, NEAT_REP_CHAMPION = 1 };
/* weight_mut_rule */
enum { NEAT_WEIGHTS_UNIFORM = 0, /* each weight perturbed with weight_perturb_prob, else replaced */
       NEAT_WEIGHTS_CPP = 1      /* a "severe" coin per genome, the newest 20 % of the genes apart (see docs) */ };
/* elitism_rule: the champion is copied when the species has more than elitism_min_size ... */
enum { NEAT_ELITE_BY_SIZE = 0, /* ... members */
       NEAT_ELITE_BY_OFFSPRING = 1 /* ... offspring due */ };
/* interspecies_rule: the other parent of an interspecies crossover */
enum { NEAT_INTER_UNIFORM = 0, /* another species' champion, uniformly */
       NEAT_INTER_CPP = 1      /* a species drawn from a normal toward the best (5 tries), else its own champion */ };
/* identical_rule: a crossover child is always mutated when its parents are ... */
enum { NEAT_IDENTICAL_SAME = 0, /* ... the same genome */
       NEAT_IDENTICAL_EQUAL = 1 /* ... the same genome or at distance 0 */ };
/* offspring_rounding */
enum { NEAT_ROUND_REMAINDER = 0, /* largest remainder over the species */
       NEAT_ROUND_SKIM = 1       /* per genome, the fractions carried from genome to genome, the shortfall to the
                                  * species due the most */ };
/* speciate_rule */
enum { NEAT_SPECIATE_AFTER = 0,      /* the next generation speciated once it is whole */
       NEAT_SPECIATE_INTERLEAVED = 1 /* each child placed as it is born, and a later species' parents include the
                                      * children of earlier species that joined it */ };
/* pop_stagnation_rule: when the population's best has not risen for pop_stagnation generations */
enum { NEAT_POPSTAG_TWO_BEST = 0, /* only the two best species breed, as usual */
       NEAT_POPSTAG_DELTA = 1     /* "delta coding": the two best species' champions fill half the population
                                   * each with mutated copies of themselves */ };

/* How a network steps (the runtime's modes, docs/runtime.md "Semantics"):
 * what evolution evaluates and what the champion blob records. */
enum neat_net_step {
    NEAT_STEP_SYNC = 0,     /* one synchronous propagation a step: a signal takes a step per layer (the paper-era NEAT's) */
    NEAT_STEP_PROPAGATE = 1 /* feed-forward paths evaluated in order within the step; cycles read the previous step */
};

typedef struct neat_params {
    uint32_t pop_size;          /* 256 (Appendix A) */
    uint32_t n_inputs;          /* the task's inputs, not counting the bias (default 12: the duel's sensors) */
    uint32_t n_outputs;         /* the task's outputs (default 3: the duel's motors) */
    int mode;                   /* enum neat_mode */
    /* compatibility: delta = c1 E / N + c2 D / N + c3 W */
    double c1, c2, c3;          /* 1, 1, 2 */
    int normalize_by_size;      /* 0: N = 1 (Appendix A); 1: N = genes of the larger genome */
    double delta_t;             /* initial threshold, 3.0 */
    double delta_t_step;        /* 0.3 per generation */
    double delta_t_min;         /* floor of the dynamic threshold */
    uint32_t target_species;    /* 10; 0 keeps delta_t fixed */
    /* reproduction */
    double survival_fraction;   /* fraction of each species (best first) allowed to mate */
    uint32_t elitism_min_size;  /* champion copied when the species has more than this: 5 */
    int stagnation_rule;        /* enum neat_stagnation: which species stop breeding */
    uint32_t dropoff_age;       /* 30: the age (or generations without improvement) that counts as stagnant */
    double stagnation_factor;   /* NEAT_STAGNATION_IMPROVEMENT: stagnant species' share times this (0 = none) */
    uint32_t pop_stagnation;    /* generations without a new population best before only the 2 best species breed; 0 = never */
    double mutate_only_prob;    /* 0.25 */
    double mate_only_prob;      /* offspring of crossover left unmutated */
    double interspecies_prob;   /* 0.05 */
    double mate_avg_prob;       /* 0.4: matching weights averaged */
    double disable_prob;        /* 0.75: inherited gene disabled if disabled in either parent */
    double excess_equal_prob;   /* at equal fitness, each disjoint/excess gene of either parent is kept with this */
    /* mutation */
    double weight_mut_prob;     /* 0.8 */
    double weight_perturb_prob; /* 0.9 (else a new random value) */
    double weight_perturb_power;/* perturbation uniform in [-power, power] */
    double weight_init_range;   /* initial weights and new connections uniform in [-range, range] */
    double weight_replace_range;/* a replaced weight is uniform in [-range, range] */
    double weight_max;          /* |w| clamp; must fit the blob's Q3.12 range */
    double add_conn_prob;       /* 0.1 */
    double add_node_prob;       /* 0.01 */
    uint32_t add_conn_tries;    /* attempts to find an unconnected pair */
    int allow_recurrent;        /* 1 (default): recurrent and self connections may be added; 0: feed-forward only */
    uint32_t max_nodes;         /* never more nodes than the blob format allows (256) */
    int net_step;               /* enum neat_net_step: NEAT_STEP_SYNC (default) or NEAT_STEP_PROPAGATE */
    /* NEAT C++ 1.2.1's rules (the enums above; all 0 by default) */
    int profile;                /* enum neat_profile: which profile set the switches (a record: the switches decide) */
    int equal_fitness_rule;
    int reenable_rule;
    int add_conn_rule;
    double recur_only_prob;     /* NEAT_ADD_CONN_CPP: the chance a new link must close a loop (params256.ne: 0.2) */
    int species_rep;
    int weight_mut_rule;
    int elitism_rule;
    int interspecies_rule;
    int identical_rule;
    int offspring_rounding;
    int speciate_rule;
    uint32_t cull_every;        /* NEAT_STAGNATION_CPP: a species culled every this many generations (30; 0 never) */
    uint32_t cull_age;          /* NEAT_STAGNATION_CPP: ... among the species at least this many generations old (20) */
    int pop_stagnation_rule;
} neat_params;

NEAT_API neat_params neat_params_default(void);
/* Appendix A's values with NEAT C++ 1.2.1's rules (every switch above at
 * its release value), and where Appendix A is silent the release's
 * params256.ne: recur_only_prob 0.2, dropoff_age 1000, the cull every 30
 * generations among species aged 20; pop_stagnation 0 (the release's
 * dropoff_age + 5 = 1005 generations, beyond any run here). */
NEAT_API neat_params neat_params_neat_cpp(void);
/* Sets the switches of profile (enum neat_profile) and the values they
 * bring (as neat_params_neat_cpp, or neat_params_default's for
 * NEAT_PROFILE_DEFAULT), leaving every other value of *p as it is.
 * NEAT_E_ARG for an unknown profile. */
NEAT_API int neat_params_set_profile(neat_params *p, int profile);
/* 1 if p uses any of NEAT C++ 1.2.1's rules (a switch, the profile, or
 * recur_only_prob, cull_every, cull_age away from neat_params_default's),
 * else 0: then its checkpoints and configuration dumps are written as
 * before the switches existed, byte for byte. */
NEAT_API int neat_params_uses_neat_cpp(const neat_params *p);
/* NEAT_OK, or NEAT_E_PARAM with *field set to the offending field's name. */
NEAT_API int neat_params_check(const neat_params *p, const char **field);

/* ---- genomes ------------------------------------------------------------ */
enum neat_node_type { NEAT_NODE_BIAS = 0, NEAT_NODE_INPUT = 1, NEAT_NODE_OUTPUT = 2, NEAT_NODE_HIDDEN = 3 };

typedef struct neat_node {
    uint32_t id;   /* bias 0, inputs 1..n, outputs next, hidden from the population's counter */
    uint8_t type;  /* enum neat_node_type */
} neat_node;

typedef struct neat_conn {
    uint32_t in, out; /* node ids */
    double weight;
    uint32_t innov;   /* historical marking */
    uint8_t enabled;
} neat_conn;

/* Nodes sorted by id, connections by innovation number. */
typedef struct neat_genome {
    neat_node *nodes;
    neat_conn *conns;
    uint32_t n_nodes, n_conns;
    uint32_t cap_nodes, cap_conns;
    double fitness;
    uint32_t species;   /* id of its species */
    uint8_t has_fitness;
} neat_genome;

/* A start topology handed to neat_pop_create (weights are re-drawn for every
 * individual unless keep_weights): either built with the constructors below,
 * or by hand with neat_genome_add_node / neat_genome_add_conn. */
NEAT_API void neat_genome_init(neat_genome *g);
NEAT_API void neat_genome_free(neat_genome *g, const neat_alloc *a);
NEAT_API int neat_genome_copy(neat_genome *dst, const neat_genome *src, const neat_alloc *a);
NEAT_API int neat_genome_add_node(neat_genome *g, uint32_t id, int type, const neat_alloc *a);
NEAT_API int neat_genome_add_conn(neat_genome *g, uint32_t in, uint32_t out, double weight, uint32_t innov, int enabled,
                                  const neat_alloc *a);
/* bias and every input connected to every output (the paper's minimal start) */
NEAT_API int neat_genome_minimal(neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, const neat_alloc *a);
/* H hidden nodes: bias+inputs -> hidden, hidden -> hidden (all pairs, self
 * included), hidden -> outputs, plus direct connections to the outputs:
 * NEAT_DIRECT_INPUTS from the bias and every input ((I+1)O: H^2 + 16H + 39
 * connections for the duel's 12 inputs and 3 outputs), NEAT_DIRECT_BIAS
 * from the bias only (O: H^2 + 16H + 3). Innovations 0, 1, ... in that
 * order; weights 0. */
enum neat_direct { NEAT_DIRECT_INPUTS = 0, NEAT_DIRECT_BIAS = 1 };
NEAT_API int neat_genome_recurrent_hidden(neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, uint32_t n_hidden,
                                          int direct, const neat_alloc *a);
/* The network of a champion blob (validated as nrt_load does) as a genome:
 * nodes and connections kept, node ids as the blob's node indices (bias 0,
 * inputs, outputs, hidden), innovations 0, 1, ... in the blob's connection
 * order, weights the blob's. NEAT_E_FORMAT if the blob is not valid. A
 * genome has no step mode: the blob's (sync or propagate) is dropped, and a
 * run evaluates the genome in its own params.net_step; a caller that must
 * not change a champion's behaviour compares the two with
 * neat_genome_from_blob_step. */
NEAT_API int neat_genome_from_blob(neat_genome *g, const uint8_t *blob, size_t len, const neat_alloc *a);
/* Also the blob's step mode in *net_step (enum neat_net_step; may be NULL). */
NEAT_API int neat_genome_from_blob_step(neat_genome *g, const uint8_t *blob, size_t len, const neat_alloc *a,
                                        int *net_step);
NEAT_API uint32_t neat_genome_hidden_count(const neat_genome *g);
NEAT_API uint32_t neat_genome_enabled_count(const neat_genome *g);
/* Compatibility distance delta under p (c1, c2, c3, normalize_by_size). */
NEAT_API double neat_genome_distance(const neat_genome *a, const neat_genome *b, const neat_params *p);

/* ---- phenotype: genome -> champion blob (docs/formats.md) ---------------- */
/* Bytes the blob of g takes: 32 + 4 per enabled connection. */
NEAT_API size_t neat_blob_size(const neat_genome *g);
/* Writes the blob of a sync network into buf (cap bytes): format version 1.
 * NEAT_E_TOOBIG if the network has more than 256 nodes or 65535 enabled
 * connections; NEAT_E_ARG if cap is short. */
NEAT_API int neat_blob_write(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, uint8_t *buf, size_t cap,
                             size_t *len);
/* The same for net_step (enum neat_net_step): NEAT_STEP_SYNC gives
 * neat_blob_write's bytes, NEAT_STEP_PROPAGATE a format-version-2 blob of
 * the same size (docs/formats.md); NEAT_E_ARG for another value. */
NEAT_API int neat_blob_write_step(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, int net_step,
                                  uint8_t *buf, size_t cap, size_t *len);

/* ---- genome file: one genome with all its genes (docs/formats.md) -------
 * Unlike a blob, it keeps what evolution needs: node ids, innovation
 * numbers, disabled genes and the exact double weights, so a champion can
 * seed a new run (neat_start) or be analysed. Versioned and checksummed. */
/* Writes g, a genome for n_inputs inputs and n_outputs outputs (without the
 * bias), into a new buffer *buf of *len bytes from allocator a (NULL: libc;
 * free it with the same allocator and *len). NEAT_E_ARG if g lacks the bias,
 * an input or an output of that shape. */
NEAT_API int neat_genome_save(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs, uint8_t **buf,
                              size_t *len, const neat_alloc *a);
/* Reads a genome file into g (initialised here; free it with
 * neat_genome_free) and its shape into *n_inputs, *n_outputs (either may be
 * NULL). Checks magic, version and CRC before anything else, then rebuilds
 * the genome through the genome API. NEAT_E_FORMAT, NEAT_E_CRC or
 * NEAT_E_TRUNCATED with *err_offset (if not NULL) the byte offset of the
 * problem; g is then empty. */
NEAT_API int neat_genome_load(neat_genome *g, uint32_t *n_inputs, uint32_t *n_outputs, const uint8_t *buf,
                              size_t len, const neat_alloc *a, size_t *err_offset);

/* Where a genome was made, as a genome file of version 2 records it: the
 * network step its fitness was measured with and the game tag of its run
 * (opaque bytes, at most NEAT_GAME_MAX: the duel's tools put the run's tag
 * there, world rules first), so that a genome copied out of its run is still
 * played as it was evolved. */
typedef struct neat_genome_origin {
    uint32_t version;   /* load: the file's format version; 1 records no origin (sync, no tag) */
    int net_step;       /* NEAT_STEP_SYNC or NEAT_STEP_PROPAGATE */
    uint32_t tag_len;   /* the tag's length */
    const uint8_t *tag; /* save: tag_len bytes (NULL when 0); load: points into the loaded buffer */
} neat_genome_origin;
/* neat_genome_save with the origin (version 2); origin NULL writes version 1,
 * byte for byte neat_genome_save's. NEAT_E_ARG also for a step that is not
 * a mode or a tag longer than NEAT_GAME_MAX. */
NEAT_API int neat_genome_save_origin(const neat_genome *g, uint32_t n_inputs, uint32_t n_outputs,
                                     const neat_genome_origin *origin, uint8_t **buf, size_t *len,
                                     const neat_alloc *a);
/* neat_genome_load that also reads the origin into *origin (NULL: ignored):
 * a version-1 file gives version 1, sync and an empty tag. The tag's step
 * and length are checked (at offsets 20 and 24) before the genome is read. */
NEAT_API int neat_genome_load_origin(neat_genome *g, uint32_t *n_inputs, uint32_t *n_outputs,
                                     neat_genome_origin *origin, const uint8_t *buf, size_t len,
                                     const neat_alloc *a, size_t *err_offset);

/* ---- population ---------------------------------------------------------- */
typedef struct neat_pop neat_pop;

/* start: NULL for the minimal start, or a start topology (its nodes and
 * innovations are the population's first; weights re-drawn unless
 * keep_weights). In simplify mode all innovations come from the start. */
typedef struct neat_start {
    const neat_genome *genome;
    int keep_weights;
} neat_start;

NEAT_API int neat_pop_create(neat_pop **out, const neat_params *p, const neat_start *start, uint64_t seed,
                             const neat_alloc *alloc);
NEAT_API void neat_pop_free(neat_pop *pop);

NEAT_API uint32_t neat_pop_size(const neat_pop *pop);
NEAT_API uint32_t neat_pop_generation(const neat_pop *pop);
NEAT_API const neat_params *neat_pop_params(const neat_pop *pop);
NEAT_API const neat_genome *neat_pop_genome(const neat_pop *pop, uint32_t i);
/* Thread-safe for distinct i. Rejects NaN, infinity and negatives (NEAT_E_FITNESS). */
NEAT_API int neat_pop_set_fitness(neat_pop *pop, uint32_t i, double fitness);
/* Fitness set for every genome: the next generation. On any error the
 * population stays in this generation (NEAT_E_FITNESS: neat_pop_error_index
 * names the first bad genome; NEAT_E_NOMEM: a retry gives the same
 * generation). After NEAT_E_NOMEM its genomes, fitness, counters and PRNG
 * are untouched, but the species' member order and representatives may
 * already be those the retry recomputes anyway, so a checkpoint saved then
 * can differ in those bytes while continuing to the same run. */
NEAT_API int neat_pop_epoch(neat_pop *pop);
NEAT_API uint32_t neat_pop_error_index(const neat_pop *pop);

/* After an epoch: the best genome of the generation just evaluated (highest
 * fitness, lowest index on ties), and the best ever. NULL before any epoch. */
NEAT_API const neat_genome *neat_pop_last_best(const neat_pop *pop);
NEAT_API const neat_genome *neat_pop_best_ever(const neat_pop *pop);

/* Species of the current generation. */
typedef struct neat_species_info {
    uint32_t id;
    uint32_t size;
    uint32_t age;            /* generations since creation */
    uint32_t since_improved; /* generations since its best fitness rose */
    double best_fitness;     /* best fitness ever of the species */
} neat_species_info;
NEAT_API uint32_t neat_pop_species_count(const neat_pop *pop);
NEAT_API int neat_pop_species(const neat_pop *pop, uint32_t k, neat_species_info *info);
/* The compatibility threshold the current generation was speciated with,
 * and the one the next speciation will use (moved by delta_t_step toward
 * target_species after each speciation). */
NEAT_API double neat_pop_delta_t(const neat_pop *pop);
NEAT_API double neat_pop_next_delta_t(const neat_pop *pop);
NEAT_API uint32_t neat_pop_innovations(const neat_pop *pop); /* innovation numbers used so far */
/* Changes the parameters of a running population (a resumed run's
 * overrides). NEAT_E_PARAM if p is out of range or changes pop_size,
 * n_inputs or n_outputs, or max_nodes is below a genome's size. */
NEAT_API int neat_pop_set_params(neat_pop *pop, const neat_params *p);

/* A generation made by another NEAT's reproduction (NEAT C++ 1.2.1's own,
 * in docs/neat-cpp.md): genomes[0..n-1] (n = pop_size) become the
 * population's, copied, and label[i] names genome i's species (the same
 * label, the same species; a label that was a species of the population's
 * last generation keeps its age and record; the labels become the species'
 * ids). evaluated 1: after every genome of the current generation has its
 * fitness, in place of neat_pop_epoch (the best of the generation and the
 * best ever are kept as an epoch keeps them; the generation counter
 * advances); evaluated 0: replaces the current, unevaluated generation (a
 * start made elsewhere). The counters move past every node id and
 * innovation number the genomes use. NEAT_E_ARG for a genome not of the
 * population's shape or larger than max_nodes, or a label at the counters'
 * limit; NEAT_E_FITNESS; NEAT_E_NOMEM: on every error the population is
 * unchanged. delta_t > 0: the threshold the other NEAT speciated them with
 * (neat_pop_delta_t reports it); otherwise libneat's is kept. A species'
 * record (its best fitness, generations since it rose) is carried over, not
 * updated: the other NEAT keeps its own. */
NEAT_API int neat_pop_replace(neat_pop *pop, const neat_genome *genomes, const uint32_t *label, uint32_t n,
                              int evaluated, double delta_t);

/* ---- checkpoints (docs/formats.md) --------------------------------------
 * The whole state: parameters, genomes, species, delta_t, innovation list,
 * counters, PRNG, generation, fitness. Loading it and running on gives the
 * same run as never stopping. */
NEAT_API int neat_pop_save(const neat_pop *pop, uint8_t **buf, size_t *len); /* *buf from the pop's allocator */
NEAT_API void neat_pop_buf_free(const neat_pop *pop, uint8_t *buf, size_t len);
/* On NEAT_E_FORMAT/CRC/TRUNCATED, *err_offset (if not NULL) is the byte offset of the problem. */
NEAT_API int neat_pop_load(neat_pop **out, const uint8_t *buf, size_t len, const neat_alloc *alloc, size_t *err_offset);
/* What a checkpoint's first 8 bytes say it is, and nothing more (a load checks the rest): a population's
 * (neat_pop_save), a coevolution's (neat_coev_save, neat_coev.h), or neither. Callers that accept one kind name
 * the other for what it is instead of "malformed". */
enum neat_checkpoint_kind { NEAT_CKPT_NONE = 0, NEAT_CKPT_POP = 1, NEAT_CKPT_COEV = 2 };
NEAT_API int neat_checkpoint_kind(const uint8_t *buf, size_t len);

/* The game-identity tag: opaque bytes naming what the run was made with
 * (e.g. the world rules of a game, which libneat does not know), kept in
 * the checkpoint byte for byte. Copied in (through the pop's allocator);
 * empty by default and in checkpoints of version 2. NEAT_E_ARG beyond
 * NEAT_GAME_MAX bytes or for NULL bytes with len > 0; NEAT_E_NOMEM (the old
 * tag kept). len 0 empties it. */
#define NEAT_GAME_MAX 4096u
NEAT_API int neat_pop_set_game(neat_pop *pop, const uint8_t *bytes, size_t len);
/* The tag's bytes (NULL when empty) and *len (if not NULL), valid until the next set or free. */
NEAT_API const uint8_t *neat_pop_game(const neat_pop *pop, size_t *len);

NEAT_API const char *neat_strerror(int err);

#ifdef __cplusplus
}
#endif

#endif /* NEAT_H */
