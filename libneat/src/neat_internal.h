/* neat_internal.h - libneat's internal state and the functions its modules share. */
#ifndef NEAT_INTERNAL_H
#define NEAT_INTERNAL_H

#include "neat.h"

/* ---- memory (neat_alloc.c) ---- */
void *neat_mem_realloc(const neat_alloc *a, void *ptr, size_t old_size, size_t new_size);
void neat_mem_free(const neat_alloc *a, void *ptr, size_t size);
/* grows *arr (elem bytes each) to hold at least need elements; 0 or NEAT_E_NOMEM */
int neat_mem_reserve(const neat_alloc *a, void **arr, uint32_t *cap, uint32_t need, size_t elem);

/* The largest value of every counter a run keeps (node ids, innovation
 * numbers, species ids, generations): a checkpoint holding more is refused,
 * and an epoch that could pass it is refused (NEAT_E_TOOBIG) before it
 * changes anything. 2^31 - 1 leaves room for an epoch's worth of ids above
 * it (at most 3 innovations, one node and one species per genome), so no
 * counter ever wraps; a run needs millions of generations to get there. */
#define NEAT_COUNTER_MAX 0x7fffffffu

/* ---- innovation list of the current generation (neat_innov.c) ---- */
enum { NEAT_INNOV_CONN = 0, NEAT_INNOV_NODE = 1 };
typedef struct neat_innov {
    uint8_t kind;
    uint32_t in, out, split; /* split: innovation of the connection an added node split */
    uint32_t innov;          /* the new connection; for a node: in -> node */
    uint32_t innov2;         /* node -> out */
    uint32_t node;           /* the new node's id */
    double weight;           /* a connection's first weight (NEAT_ADD_CONN_CPP reuses it within the generation;
                              * not in checkpoints: the list is emptied before it is read again) */
} neat_innov;

typedef struct neat_innovs {
    neat_innov *list;
    uint32_t n, cap;
    uint32_t next_innov; /* global counters */
    uint32_t next_node;
} neat_innovs;

int neat_innov_conn(neat_innovs *iv, const neat_alloc *a, uint32_t in, uint32_t out, uint32_t *innov);
/* The same, and *rec the list's entry (its weight 0 and *fresh 1 when the innovation is new). */
int neat_innov_conn_rec(neat_innovs *iv, const neat_alloc *a, uint32_t in, uint32_t out, neat_innov **rec,
                        int *fresh);
int neat_innov_node(neat_innovs *iv, const neat_alloc *a, uint32_t in, uint32_t out, uint32_t split,
                    neat_innov *out_rec);
void neat_innov_reset(neat_innovs *iv); /* start of every generation's reproduction */

/* ---- genome helpers (neat_genome.c) ---- */
const neat_node *neat_genome_find_node(const neat_genome *g, uint32_t id);
/* bias id 0, inputs 1..n_in, outputs next, all other nodes hidden */
int neat_genome_io_ok(const neat_genome *g, uint32_t n_in, uint32_t n_out);
int neat_genome_has_link(const neat_genome *g, uint32_t in, uint32_t out);
/* neat_genome_distance(a, b, p) < delta_t, often without counting every
 * gene (speciation asks it of each genome against every species) */
int neat_genome_compatible(const neat_genome *a, const neat_genome *b, const neat_params *p, double delta_t);
/* weights uniform in [-range, range] */
void neat_genome_randomize(neat_genome *g, neat_rng *rng, double range);

/* ---- mutation and crossover (neat_mutate.c, neat_crossover.c) ---- */
int neat_mutate(neat_genome *g, const neat_params *p, neat_rng *rng, neat_innovs *iv, const neat_alloc *a);
int neat_mutate_weights(neat_genome *g, const neat_params *p, neat_rng *rng);
int neat_mutate_add_conn(neat_genome *g, const neat_params *p, neat_rng *rng, neat_innovs *iv, const neat_alloc *a);
int neat_mutate_add_node(neat_genome *g, const neat_params *p, neat_rng *rng, neat_innovs *iv, const neat_alloc *a);
int neat_mutate_remove_conn(neat_genome *g, neat_rng *rng);
/* child from mom and dad (fitness decides disjoint/excess); avg: average matching weights */
int neat_crossover(neat_genome *child, const neat_genome *mom, const neat_genome *dad, int avg, const neat_params *p,
                   neat_rng *rng, const neat_alloc *a);

/* ---- species (neat_species.c) ---- */
typedef struct neat_species {
    uint32_t id;
    uint32_t age;
    uint32_t since_improved;
    double best_fitness;
    neat_genome rep;   /* representative, a member of the previous generation */
    uint32_t *members; /* indices into pop->genomes, best first after neat_species_rank */
    uint32_t n_members, cap_members;
    /* per-epoch scratch: statistics after this generation (neat_species_rank),
     * committed only when the epoch succeeds */
    double next_best;
    uint32_t next_since;
    /* per-epoch scratch (neat_apportion) */
    double adj_sum;    /* sum of the members' shared fitness */
    double remainder;  /* fractional part of its quota */
    uint32_t offspring;
    uint8_t eligible;  /* may breed this generation */
    uint8_t super;     /* NEAT_POPSTAG_DELTA this generation: the offspring are copies of the champion */
    uint8_t culled;    /* NEAT_STAGNATION_CPP: culled for good (its fitness times 0.01 from then on) */
    uint8_t cull_now;  /* per-epoch scratch: culled this generation (committed into culled with the epoch) */
    double factor;     /* per-epoch scratch: its share over its members' shared sum (stagnation penalties) */
} neat_species;

/* ---- the population ---- */
/* The game-identity tag (neat_game.c): at most NEAT_GAME_MAX bytes, owned. */
typedef struct neat_tag {
    uint8_t *bytes; /* NULL when empty */
    size_t len;
} neat_tag;
/* Copies bytes in (the old tag is kept on failure): NEAT_E_ARG beyond NEAT_GAME_MAX. */
int neat_tag_set(const neat_alloc *a, neat_tag *t, const uint8_t *bytes, size_t len);
void neat_tag_free(const neat_alloc *a, neat_tag *t);
const uint8_t *neat_tag_get(const neat_tag *t, size_t *len);

struct neat_pop {
    neat_params p;
    neat_alloc a;
    neat_rng rng;
    uint32_t generation;
    neat_innovs iv;
    double delta_t;       /* the next speciation's threshold */
    double delta_t_used;  /* the threshold the current generation was speciated with */
    neat_genome *genomes; /* [p.pop_size] */
    neat_genome *spare;   /* [p.pop_size] or NULL: the generation before, its
                           * storage kept for the next (an epoch then
                           * allocates only when a genome outgrows it) */
    neat_species *species;
    uint32_t n_species, cap_species;
    uint32_t next_species_id;
    neat_genome best_ever, last_best;
    uint8_t have_best;
    uint32_t since_pop_improved;
    uint32_t err_index;
    neat_tag game;        /* neat_pop_set_game's bytes */
};

/* An empty population holding p and the allocator (neat_pop.c; used by
 * neat_pop_create and neat_pop_load). */
int neat_pop_alloc(neat_pop **out, const neat_params *p, const neat_alloc *alloc);

/* Speciation in two phases so that an epoch refused memory leaves the
 * population as it was: the plan decides each genome's species and
 * allocates everything; the commit cannot fail. */
typedef struct neat_spec_plan {
    uint32_t *slot;       /* [pop_size] species index; >= n_species: a new species */
    uint32_t *founder;    /* [n_new] genome founding each new species */
    uint32_t *count;      /* [n_species + n_new] members per slot */
    uint32_t **members;   /* [n_new] member arrays of the new species */
    neat_genome *reps;    /* [n_new] their representatives */
    uint32_t ns;          /* species before the plan */
    uint32_t n_new, n_slots, cap;
} neat_spec_plan;
/* Plans the speciation of gs[pop_size] against pop->species' representatives. */
int neat_speciate_plan(neat_pop *pop, const neat_genome *gs, neat_spec_plan *plan);
/* Applies it to gs (which must be pop->genomes by then): fills the species,
 * founds the new ones, drops empty ones, moves delta_t. Frees the plan. */
void neat_speciate_commit(neat_pop *pop, neat_spec_plan *plan);
void neat_speciate_plan_free(neat_pop *pop, neat_spec_plan *plan);
/* The plan in three steps (neat_speciate_plan is all three): begin
 * allocates it; place puts gs[i] in the first species whose representative
 * is close enough, or a new one (gs[i] may be placed as soon as it exists:
 * NEAT_SPECIATE_INTERLEAVED); finish allocates what the commit needs. */
int neat_speciate_plan_begin(neat_pop *pop, neat_spec_plan *plan);
void neat_speciate_place(neat_pop *pop, const neat_genome *gs, neat_spec_plan *plan, uint32_t i);
int neat_speciate_plan_finish(neat_pop *pop, const neat_genome *gs, neat_spec_plan *plan);
/* Both at once, on pop->genomes (population creation). */
int neat_speciate(neat_pop *pop);
/* Members of each species best first (ties: lower index), and the species'
 * statistics after this generation into next_best / next_since. */
void neat_species_rank(neat_pop *pop);
void neat_species_free(neat_species *s, const neat_alloc *a);

/* ---- reproduction (neat_reproduce.c) ---- */
/* offspring per species: sum == pop_size, whatever the fitness values.
 * *since_pop: generations without a new population best (may be reset). */
void neat_apportion(neat_pop *pop, uint32_t *since_pop);
/* the next generation into next[pop_size] (initialised genomes); plan: NULL,
 * or (NEAT_SPECIATE_INTERLEAVED) a begun plan each child is placed in as it
 * is born */
int neat_reproduce(neat_pop *pop, neat_genome *next, neat_spec_plan *plan);
/* a standard normal draw (Marsaglia's polar method) */
double neat_rng_gauss(neat_rng *rng);


/* ---- the PRNG's draws, inline for libneat's modules: an epoch makes
 * thousands, and the calls were 4 % of neat_bench xor's CPU. The public
 * neat_rng_next, _uniform and _below (neat_rng.c) are these. ---- */
static inline uint64_t neat_rng_next_inl(neat_rng *rng)
{
    uint64_t *s = rng->s;
    uint64_t r = s[1] * 5;
    uint64_t t = s[1] << 17;
    r = (r << 7 | r >> 57) * 9; /* xoshiro256**: rotl(s[1] * 5, 7) * 9 */
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = s[3] << 45 | s[3] >> 19;
    return r;
}

/* uniform in [0, 1), 53 bits */
static inline double neat_rng_uniform_inl(neat_rng *rng)
{
    return (double)(neat_rng_next_inl(rng) >> 11) * (1.0 / 9007199254740992.0);
}

/* uniform in [0, n), n > 0: the top partial block rejected so every value is equally likely */
static inline uint32_t neat_rng_below_inl(neat_rng *rng, uint32_t n)
{
    uint64_t limit = UINT64_MAX - (UINT64_MAX % n), x;
    do
        x = neat_rng_next_inl(rng);
    while (x >= limit);
    return (uint32_t)(x % n);
}

#endif /* NEAT_INTERNAL_H */
