/* neat_coev.c - competitive coevolution: opponents, host games, hall of fame, generation champions, dominance tournament, checkpoint. */
#include <string.h>

#include "neat_coev.h"
#include "neat_io.h"
#include "nrt.h"

/* A dominant strategy and the comparisons that made it one. */
typedef struct neat_dom {
    uint32_t generation, pop, n;
    neat_genome g;
    uint16_t *wins, *losses; /* [n] */
} neat_dom;

/* A growing array of genomes. */
typedef struct neat_glist {
    neat_genome *g;
    uint32_t n, cap;
} neat_glist;

struct neat_coev {
    neat_alloc a;
    neat_coev_params cp;
    uint64_t seed;
    uint32_t generation;
    neat_pop *pop[2];
    neat_genome start;    /* the start topology */
    neat_glist hof[2];    /* hof[i].g[t]: population i's best of generation t */
    neat_glist champs[2]; /* champions of its best species last generation, best first */
    neat_genome champion; /* the last generation champion */
    uint8_t have_champion;
    neat_dom *dom;
    uint32_t n_dom, cap_dom;
    neat_game *games; /* scratch for a generation's games */
    uint32_t cap_games;
    neat_tag game;    /* neat_coev_set_game's bytes */
    neat_coev_reproduce_fn reproduce; /* another NEAT's reproduction, or NULL */
    void *reproduce_ud;
};

/* seed-derivation tags, so the streams of different purposes never meet */
#define NEAT_TAG_POP 0x504f50u      /* population creation */
#define NEAT_TAG_OPP 0x4f5050u      /* opponent draws */
#define NEAT_TAG_HOST 0x484f5354u   /* host games */
#define NEAT_TAG_CMP 0x434d50u      /* comparisons */
#define NEAT_TAG_COIN 0x434f494eu   /* random fitness: a game's coin */

#define NEAT_COEV_MAX_CHAMPS 64        /* species_opponents at most */
#define NEAT_COEV_MAX_CONFIGS 30000u   /* compare_configs at most: a comparison's wins fit 16 bits */
#define NEAT_COEV_MAX_DRAWN 1000u      /* hof_opponents and first_opponents at most */
/* the opponents one population meets in a generation, at most */
#define NEAT_COEV_MAX_OPP (NEAT_COEV_MAX_CHAMPS + NEAT_COEV_MAX_DRAWN)

neat_coev_params neat_coev_params_default(void)
{
    neat_coev_params cp;
    cp.species_opponents = 4;
    cp.hof_opponents = 8;
    cp.first_opponents = 12;
    cp.compare_configs = 144;
    cp.random_fitness = 0;
    return cp;
}

int neat_coev_params_check(const neat_coev_params *cp, const char **field)
{
    const char *bad = NULL;
    if (cp->species_opponents > NEAT_COEV_MAX_CHAMPS)
        bad = "species_opponents";
    else if (cp->hof_opponents > NEAT_COEV_MAX_DRAWN)
        bad = "hof_opponents";
    else if (cp->species_opponents + cp->hof_opponents == 0)
        bad = "hof_opponents";
    else if (cp->first_opponents == 0 || cp->first_opponents > NEAT_COEV_MAX_DRAWN)
        bad = "first_opponents";
    else if (cp->compare_configs == 0 || cp->compare_configs > NEAT_COEV_MAX_CONFIGS)
        bad = "compare_configs";
    else if (cp->random_fitness != 0 && cp->random_fitness != 1)
        bad = "random_fitness";
    if (field != NULL)
        *field = bad;
    return bad ? NEAT_E_PARAM : NEAT_OK;
}

static void neat_glist_free(neat_glist *l, const neat_alloc *a)
{
    uint32_t i;
    for (i = 0; i < l->n; i++)
        neat_genome_free(&l->g[i], a);
    neat_mem_free(a, l->g, (size_t)l->cap * sizeof *l->g);
    memset(l, 0, sizeof *l);
}

static void neat_dom_free(neat_dom *d, const neat_alloc *a)
{
    neat_genome_free(&d->g, a);
    neat_mem_free(a, d->wins, (size_t)d->n * sizeof *d->wins);
    neat_mem_free(a, d->losses, (size_t)d->n * sizeof *d->losses);
}

void neat_coev_free(neat_coev *c)
{
    uint32_t i;
    neat_alloc a;
    if (c == NULL)
        return;
    a = c->a;
    for (i = 0; i < 2; i++) {
        neat_pop_free(c->pop[i]);
        neat_glist_free(&c->hof[i], &a);
        neat_glist_free(&c->champs[i], &a);
    }
    neat_genome_free(&c->champion, &a);
    neat_genome_free(&c->start, &a);
    for (i = 0; i < c->n_dom; i++)
        neat_dom_free(&c->dom[i], &a);
    neat_mem_free(&a, c->dom, (size_t)c->cap_dom * sizeof *c->dom);
    neat_mem_free(&a, c->games, (size_t)c->cap_games * sizeof *c->games);
    neat_tag_free(&a, &c->game);
    neat_mem_free(&a, c, sizeof *c);
}

static int neat_coev_alloc(neat_coev **out, const neat_alloc *alloc)
{
    neat_coev *c = (neat_coev *)neat_mem_realloc(alloc, NULL, 0, sizeof *c);
    if (c == NULL)
        return NEAT_E_NOMEM;
    memset(c, 0, sizeof *c);
    if (alloc != NULL)
        c->a = *alloc;
    neat_genome_init(&c->champion);
    neat_genome_init(&c->start);
    *out = c;
    return NEAT_OK;
}

int neat_coev_create(neat_coev **out, const neat_params *p, const neat_coev_params *cp, const neat_start *start,
                     uint64_t seed, const neat_alloc *alloc)
{
    neat_coev *c;
    neat_start st;
    const char *field;
    uint32_t i;
    int err;
    if (out == NULL || p == NULL || cp == NULL)
        return NEAT_E_ARG;
    *out = NULL;
    if (neat_coev_params_check(cp, &field) != NEAT_OK || neat_params_check(p, &field) != NEAT_OK ||
        p->pop_stagnation != 0)
        return NEAT_E_PARAM;
    err = neat_coev_alloc(&c, alloc);
    if (err)
        return err;
    c->cp = *cp;
    c->seed = seed;
    if (start != NULL && start->genome != NULL) {
        err = neat_genome_copy(&c->start, start->genome, &c->a);
        st = *start;
    } else {
        /* the genome neat_pop_create would build for a NULL start */
        err = neat_genome_minimal(&c->start, p->n_inputs, p->n_outputs, &c->a);
        st.genome = &c->start;
        st.keep_weights = 0;
    }
    for (i = 0; i < 2 && !err; i++) {
        uint64_t keys[2];
        keys[0] = NEAT_TAG_POP;
        keys[1] = i;
        err = neat_pop_create(&c->pop[i], p, &st, neat_seed_derive(seed, keys, 2), alloc);
    }
    if (err) {
        neat_coev_free(c);
        return err;
    }
    *out = c;
    return NEAT_OK;
}

uint32_t neat_coev_generation(const neat_coev *c)
{
    return c->generation;
}

const neat_genome *neat_coev_start(const neat_coev *c)
{
    return &c->start;
}

uint64_t neat_coev_seed(const neat_coev *c)
{
    return c->seed;
}

const neat_coev_params *neat_coev_get_params(const neat_coev *c)
{
    return &c->cp;
}

const neat_pop *neat_coev_pop(const neat_coev *c, uint32_t which)
{
    return which < 2 ? c->pop[which] : NULL;
}

uint32_t neat_coev_hof_count(const neat_coev *c, uint32_t which)
{
    return which < 2 ? c->hof[which].n : 0;
}

const neat_genome *neat_coev_hof(const neat_coev *c, uint32_t which, uint32_t generation)
{
    return which < 2 && generation < c->hof[which].n ? &c->hof[which].g[generation] : NULL;
}

const neat_genome *neat_coev_champion(const neat_coev *c)
{
    return c->have_champion ? &c->champion : NULL;
}

uint32_t neat_coev_dominant_count(const neat_coev *c)
{
    return c->n_dom;
}

int neat_coev_dominant(const neat_coev *c, uint32_t k, neat_dominant *d)
{
    if (c == NULL || d == NULL || k >= c->n_dom)
        return NEAT_E_ARG;
    d->generation = c->dom[k].generation;
    d->pop = c->dom[k].pop;
    d->genome = &c->dom[k].g;
    d->n_beaten = c->dom[k].n;
    d->wins = c->dom[k].wins;
    d->losses = c->dom[k].losses;
    return NEAT_OK;
}

/* Every genome kept (halls of fame, species champions, champion, dominants)
 * within max_nodes, as the checkpoint requires. */
static int neat_coev_kept_fit(const neat_coev *c, uint32_t max_nodes)
{
    uint32_t i, k;
    for (i = 0; i < 2; i++) {
        for (k = 0; k < c->hof[i].n; k++)
            if (c->hof[i].g[k].n_nodes > max_nodes)
                return 0;
        for (k = 0; k < c->champs[i].n; k++)
            if (c->champs[i].g[k].n_nodes > max_nodes)
                return 0;
    }
    for (k = 0; k < c->n_dom; k++)
        if (c->dom[k].g.n_nodes > max_nodes)
            return 0;
    return !c->have_champion || c->champion.n_nodes <= max_nodes;
}

int neat_coev_set_params(neat_coev *c, const neat_params *p, const neat_coev_params *cp)
{
    const char *field;
    neat_params old;
    int err;
    if (c == NULL || p == NULL || cp == NULL)
        return NEAT_E_ARG;
    old = *neat_pop_params(c->pop[0]);
    if (neat_coev_params_check(cp, &field) != NEAT_OK || !neat_coev_kept_fit(c, p->max_nodes) ||
        p->pop_stagnation != 0 || c->start.n_nodes > p->max_nodes)
        return NEAT_E_PARAM;
    err = neat_pop_set_params(c->pop[0], p);
    if (!err) {
        err = neat_pop_set_params(c->pop[1], p);
        if (err)
            (void)neat_pop_set_params(c->pop[0], &old); /* accepted before, so accepted again */
    }
    if (!err)
        c->cp = *cp;
    return err;
}

/* ---- one generation ---- */

static int neat_reserve_games(neat_coev *c, uint64_t n)
{
    void *p;
    if (n > 0x7FFFFFFFu / sizeof(neat_game))
        return NEAT_E_ARG;
    if (n <= c->cap_games)
        return NEAT_OK;
    p = neat_mem_realloc(&c->a, c->games, (size_t)c->cap_games * sizeof(neat_game), (size_t)n * sizeof(neat_game));
    if (p == NULL)
        return NEAT_E_NOMEM;
    c->games = (neat_game *)p;
    c->cap_games = (uint32_t)n;
    return NEAT_OK;
}

/* The games played, or with random_fitness their coins tossed. */
static int neat_coev_play(const neat_coev *c, neat_play_fn play, void *ud, neat_game *games, size_t n)
{
    size_t k;
    if (!c->cp.random_fitness)
        return play(ud, games, n);
    for (k = 0; k < n; k++) {
        uint64_t tag = NEAT_TAG_COIN;
        games[k].result = (int8_t)((neat_seed_derive(games[k].seed, &tag, 1) & 1u) ? 1 : -1);
    }
    return NEAT_OK;
}

/* The opponents the hosts of population which meet this generation. */
static uint32_t neat_opponents(const neat_coev *c, uint32_t which, const neat_genome **opp)
{
    uint32_t other = which ^ 1u, n = 0, i, ns, size = neat_pop_size(c->pop[other]);
    uint64_t keys[3];
    neat_rng rng;
    keys[0] = NEAT_TAG_OPP;
    keys[1] = c->generation;
    keys[2] = which;
    neat_rng_seed(&rng, neat_seed_derive(c->seed, keys, 3));
    if (c->generation == 0) {
        for (i = 0; i < c->cp.first_opponents; i++)
            opp[n++] = neat_pop_genome(c->pop[other], neat_rng_below_inl(&rng, size));
        return n;
    }
    /* fewer species than wanted: the hall of fame fills the places */
    ns = c->champs[other].n < c->cp.species_opponents ? c->champs[other].n : c->cp.species_opponents;
    for (i = 0; i < ns; i++)
        opp[n++] = &c->champs[other].g[i];
    for (i = 0; i < c->cp.hof_opponents + (c->cp.species_opponents - ns); i++)
        opp[n++] = &c->hof[other].g[neat_rng_below_inl(&rng, c->hof[other].n)];
    return n;
}

/* A comparison: x and y on every comparison configuration from both
 * sides. stage tells the comparisons of one generation apart. */
static int neat_compare(neat_coev *c, const neat_genome *x, const neat_genome *y, uint32_t stage, neat_play_fn play,
                        void *ud, uint32_t *wx, uint32_t *wy)
{
    uint32_t k, n = 2u * c->cp.compare_configs;
    int err = neat_reserve_games(c, n);
    if (err)
        return err;
    for (k = 0; k < n; k++) {
        uint64_t keys[4];
        neat_game *gm = &c->games[k];
        keys[0] = NEAT_TAG_CMP;
        keys[1] = c->generation;
        keys[2] = stage;
        keys[3] = k;
        gm->a = x;
        gm->b = y;
        gm->config = (int32_t)(k / 2u);
        gm->a_first = (uint8_t)(k % 2u == 0);
        gm->seed = neat_seed_derive(c->seed, keys, 4);
        gm->result = 0;
    }
    err = neat_coev_play(c, play, ud, c->games, n);
    if (err)
        return err;
    *wx = *wy = 0;
    for (k = 0; k < n; k++) {
        *wx += c->games[k].result > 0;
        *wy += c->games[k].result < 0;
    }
    return NEAT_OK;
}

/* Champions of the best species (by their champions' fitness, then index),
 * at most max of them, as indices into the population. */
static uint32_t neat_species_champions(const neat_pop *pop, const uint32_t *wins, uint32_t max, uint32_t *out,
                                       uint32_t *tmp)
{
    uint32_t ns = neat_pop_species_count(pop), size = neat_pop_size(pop), k, i, n = 0;
    for (k = 0; k < ns; k++) {
        neat_species_info info;
        uint32_t best = size;
        if (neat_pop_species(pop, k, &info) != NEAT_OK)
            continue;
        for (i = 0; i < size; i++)
            if (neat_pop_genome(pop, i)->species == info.id && (best == size || wins[i] > wins[best]))
                best = i;
        if (best < size)
            tmp[n++] = best;
    }
    /* insertion sort: best champion first, lower index on ties */
    for (k = 1; k < n; k++) {
        uint32_t v = tmp[k];
        for (i = k; i > 0 && (wins[tmp[i - 1]] < wins[v] || (wins[tmp[i - 1]] == wins[v] && tmp[i - 1] > v)); i--)
            tmp[i] = tmp[i - 1];
        tmp[i] = v;
    }
    if (n > max)
        n = max;
    memcpy(out, tmp, n * sizeof *out);
    return n;
}

static void neat_pop_report(const neat_pop *pop, const uint32_t *wins, uint64_t games, neat_coev_pop_report *r)
{
    uint32_t i, size = neat_pop_size(pop), best = 0;
    double sum = 0, hid = 0, con = 0;
    r->min_hidden = r->min_conns = UINT32_MAX;
    r->max_hidden = r->max_conns = 0;
    for (i = 0; i < size; i++) {
        const neat_genome *g = neat_pop_genome(pop, i);
        uint32_t gh = neat_genome_hidden_count(g), gc = neat_genome_enabled_count(g);
        sum += wins[i];
        hid += gh;
        con += gc;
        r->min_hidden = gh < r->min_hidden ? gh : r->min_hidden;
        r->max_hidden = gh > r->max_hidden ? gh : r->max_hidden;
        r->min_conns = gc < r->min_conns ? gc : r->min_conns;
        r->max_conns = gc > r->max_conns ? gc : r->max_conns;
        if (wins[i] > wins[best])
            best = i;
    }
    r->best_index = best;
    r->best_fitness = wins[best];
    r->mean_fitness = sum / size;
    r->species = neat_pop_species_count(pop);
    r->delta_t = neat_pop_delta_t(pop);
    r->mean_hidden = hid / size;
    r->mean_conns = con / size;
    r->best_hidden = neat_genome_hidden_count(neat_pop_genome(pop, best));
    r->best_conns = neat_genome_enabled_count(neat_pop_genome(pop, best));
    r->games = games;
}

/* A copy of host i carrying its wins as fitness. */
static int neat_copy_scored(neat_genome *dst, const neat_pop *pop, uint32_t i, const uint32_t *wins,
                            const neat_alloc *a)
{
    int err = neat_genome_copy(dst, neat_pop_genome(pop, i), a);
    if (!err) {
        dst->fitness = (double)wins[i];
        dst->has_fitness = 1;
    }
    return err;
}

/* Everything a generation adds, prepared before anything changes. */
typedef struct neat_gen_out {
    neat_genome hof[2], champion, dom;
    neat_genome champs[2][NEAT_COEV_MAX_CHAMPS];
    uint32_t n_champs[2];
    uint16_t *wins, *losses; /* [cap_beaten]: one place per earlier dominant */
    uint32_t n_beaten, cap_beaten;
    int new_dom;
} neat_gen_out;

static void neat_gen_out_free(neat_gen_out *o, const neat_alloc *a)
{
    uint32_t i, k;
    for (i = 0; i < 2; i++) {
        neat_genome_free(&o->hof[i], a);
        for (k = 0; k < o->n_champs[i]; k++)
            neat_genome_free(&o->champs[i][k], a);
    }
    neat_genome_free(&o->champion, a);
    neat_genome_free(&o->dom, a);
    neat_mem_free(a, o->wins, (size_t)o->cap_beaten * sizeof *o->wins);
    neat_mem_free(a, o->losses, (size_t)o->cap_beaten * sizeof *o->losses);
}

int neat_coev_step(neat_coev *c, neat_play_fn play, void *ud, neat_coev_report *rep)
{
    const neat_genome *opp[2][NEAT_COEV_MAX_OPP]; /* c->cp passed neat_coev_params_check */
    uint32_t n_opp[2], size, p, h, j, s, k, n = 0, best[2], champ_pop, cw[2];
    uint32_t *wins[2] = {NULL, NULL}, *idx = NULL, *tmp = NULL;
    neat_pop *next[2] = {NULL, NULL};
    neat_gen_out o;
    neat_coev_report r;
    const neat_genome *champ;
    int err;

    if (c == NULL || play == NULL)
        return NEAT_E_ARG;
    memset(&r, 0, sizeof r);
    memset(&o, 0, sizeof o);
    r.generation = c->generation;
    size = neat_pop_size(c->pop[0]);
    for (p = 0; p < 2; p++)
        n_opp[p] = neat_opponents(c, p, opp[p]);

    /* 1. every host plays every opponent from both sides: wins are fitness */
    err = neat_reserve_games(c, (uint64_t)2u * size * (n_opp[0] > n_opp[1] ? n_opp[0] : n_opp[1]) * 2u);
    if (err)
        return err;
    for (p = 0; p < 2; p++)
        for (h = 0; h < size; h++)
            for (j = 0; j < n_opp[p]; j++)
                for (s = 0; s < 2; s++) {
                    uint64_t keys[6];
                    neat_game *gm = &c->games[n++];
                    keys[0] = NEAT_TAG_HOST;
                    keys[1] = c->generation;
                    keys[2] = p;
                    keys[3] = h;
                    keys[4] = j;
                    keys[5] = s;
                    gm->a = neat_pop_genome(c->pop[p], h);
                    gm->b = opp[p][j];
                    gm->config = -1;
                    gm->a_first = (uint8_t)(s == 0);
                    gm->seed = neat_seed_derive(c->seed, keys, 6);
                    gm->result = 0;
                }
    err = neat_coev_play(c, play, ud, c->games, n);
    if (err)
        return err;
    r.games = n;
    for (p = 0; p < 2 && !err; p++) {
        wins[p] = (uint32_t *)neat_mem_realloc(&c->a, NULL, 0, size * sizeof(uint32_t));
        if (wins[p] == NULL)
            err = NEAT_E_NOMEM;
    }
    idx = (uint32_t *)neat_mem_realloc(&c->a, NULL, 0, 2u * size * sizeof(uint32_t));
    if (idx == NULL)
        err = NEAT_E_NOMEM;
    if (err)
        goto done;
    tmp = idx + size;
    n = 0;
    for (p = 0; p < 2; p++) {
        for (h = 0; h < size; h++) {
            uint32_t w = 0;
            for (k = 0; k < 2u * n_opp[p]; k++)
                w += c->games[n++].result > 0;
            wins[p][h] = w;
        }
        neat_pop_report(c->pop[p], wins[p], (uint64_t)size * n_opp[p] * 2u, &r.pop[p]);
        best[p] = r.pop[p].best_index;
    }

    /* 2. the generation champion: the two bests compared (ties: population 0's) */
    err = neat_compare(c, neat_pop_genome(c->pop[0], best[0]), neat_pop_genome(c->pop[1], best[1]), 0, play, ud,
                       &cw[0], &cw[1]);
    if (err)
        goto done;
    r.games += 2u * c->cp.compare_configs;
    champ_pop = cw[1] > cw[0];
    champ = neat_pop_genome(c->pop[champ_pop], best[champ_pop]);
    r.champion_pop = champ_pop;
    r.champion_wins[0] = cw[0];
    r.champion_wins[1] = cw[1];

    /* 3. dominance: superior to every dominant, the latest first */
    o.new_dom = 1;
    if (c->n_dom > 0) {
        o.wins = (uint16_t *)neat_mem_realloc(&c->a, NULL, 0, c->n_dom * sizeof(uint16_t));
        o.losses = (uint16_t *)neat_mem_realloc(&c->a, NULL, 0, c->n_dom * sizeof(uint16_t));
        if (o.wins != NULL && o.losses != NULL) {
            o.cap_beaten = c->n_dom;
        } else {
            /* free what came: nothing is sized by cap_beaten yet */
            neat_mem_free(&c->a, o.wins, c->n_dom * sizeof(uint16_t));
            neat_mem_free(&c->a, o.losses, c->n_dom * sizeof(uint16_t));
            o.wins = o.losses = NULL;
            err = NEAT_E_NOMEM;
            goto done;
        }
    }
    for (k = c->n_dom; k-- > 0;) {
        uint32_t wc, wd;
        err = neat_compare(c, champ, &c->dom[k].g, 1u + (c->n_dom - 1u - k), play, ud, &wc, &wd);
        if (err)
            goto done;
        r.dominance_games += 2u * c->cp.compare_configs;
        if (wc <= wd) {
            o.new_dom = 0;
            break;
        }
        /* within 2 x 30000 games: 16 bits hold them */
        o.wins[o.n_beaten] = (uint16_t)wc;
        o.losses[o.n_beaten] = (uint16_t)wd;
        o.n_beaten++;
    }
    r.games += r.dominance_games;

    /* 4. everything the generation adds, copied before anything changes
     * (with this generation's fitness: the population's is set in step 5) */
    for (p = 0; p < 2 && !err; p++) {
        uint32_t nc = neat_species_champions(c->pop[p], wins[p], c->cp.species_opponents, idx, tmp);
        err = neat_copy_scored(&o.hof[p], c->pop[p], best[p], wins[p], &c->a);
        for (k = 0; k < nc && !err; k++) {
            err = neat_copy_scored(&o.champs[p][k], c->pop[p], idx[k], wins[p], &c->a);
            o.n_champs[p] = k + 1;
        }
        if (!err)
            err = neat_mem_reserve(&c->a, (void **)&c->hof[p].g, &c->hof[p].cap, c->hof[p].n + 1u, sizeof(neat_genome));
        if (!err)
            err = neat_mem_reserve(&c->a, (void **)&c->champs[p].g, &c->champs[p].cap, nc, sizeof(neat_genome));
    }
    if (!err)
        err = neat_copy_scored(&o.champion, c->pop[champ_pop], best[champ_pop], wins[champ_pop], &c->a);
    if (!err && o.new_dom) {
        err = neat_copy_scored(&o.dom, c->pop[champ_pop], best[champ_pop], wins[champ_pop], &c->a);
        if (!err)
            err = neat_mem_reserve(&c->a, (void **)&c->dom, &c->cap_dom, c->n_dom + 1u, sizeof(neat_dom));
    }
    if (err)
        goto done;

    /* 5. fitness and reproduction, on copies of the populations (through
     * their checkpoints, which give the same run): a failed epoch leaves
     * both as they were, fitness, species order and representatives too */
    for (p = 0; p < 2 && !err; p++) {
        uint8_t *pb = NULL;
        size_t pl = 0;
        err = neat_pop_save(c->pop[p], &pb, &pl);
        if (!err) {
            err = neat_pop_load(&next[p], pb, pl, &c->a, NULL);
            neat_pop_buf_free(c->pop[p], pb, pl);
        }
        for (h = 0; h < size && !err; h++)
            err = neat_pop_set_fitness(next[p], h, (double)wins[p][h]);
        if (!err)
            err = c->reproduce != NULL ? c->reproduce(c->reproduce_ud, p, next[p], 1) : neat_pop_epoch(next[p]);
    }
    if (err)
        goto done;

    /* 6. commit: moves only, nothing can fail */
    for (p = 0; p < 2; p++) {
        neat_pop_free(c->pop[p]);
        c->pop[p] = next[p];
        next[p] = NULL;
        c->hof[p].g[c->hof[p].n++] = o.hof[p];
        neat_genome_init(&o.hof[p]);
        for (k = 0; k < c->champs[p].n; k++)
            neat_genome_free(&c->champs[p].g[k], &c->a);
        for (k = 0; k < o.n_champs[p]; k++) {
            c->champs[p].g[k] = o.champs[p][k];
            neat_genome_init(&o.champs[p][k]);
        }
        c->champs[p].n = o.n_champs[p];
        o.n_champs[p] = 0;
    }
    neat_genome_free(&c->champion, &c->a);
    c->champion = o.champion;
    neat_genome_init(&o.champion);
    c->have_champion = 1;
    if (o.new_dom) {
        neat_dom *d = &c->dom[c->n_dom++];
        d->generation = c->generation;
        d->pop = champ_pop;
        d->g = o.dom;
        d->n = o.n_beaten; /* = cap_beaten: it beat every earlier dominant */
        d->wins = o.wins;
        d->losses = o.losses;
        neat_genome_init(&o.dom);
        o.wins = o.losses = NULL;
        o.n_beaten = o.cap_beaten = 0;
    }
    r.dominants = c->n_dom;
    r.new_dominant = o.new_dom;
    c->generation++;
    if (rep != NULL)
        *rep = r;
done:
    neat_gen_out_free(&o, &c->a);
    for (p = 0; p < 2; p++) {
        neat_pop_free(next[p]);
        neat_mem_free(&c->a, wins[p], size * sizeof(uint32_t));
    }
    neat_mem_free(&c->a, idx, 2u * size * sizeof(uint32_t));
    return err;
}

int neat_coev_set_reproducer(neat_coev *c, neat_coev_reproduce_fn fn, void *ud)
{
    uint32_t p;
    int err = NEAT_OK;
    if (c == NULL)
        return NEAT_E_ARG;
    c->reproduce = fn;
    c->reproduce_ud = ud;
    for (p = 0; p < 2 && fn != NULL && !err; p++)
        err = fn(ud, p, c->pop[p], 0);
    return err;
}

int neat_coev_set_game(neat_coev *c, const uint8_t *bytes, size_t len)
{
    if (c == NULL)
        return NEAT_E_ARG;
    return neat_tag_set(&c->a, &c->game, bytes, len);
}

const uint8_t *neat_coev_game(const neat_coev *c, size_t *len)
{
    return neat_tag_get(&c->game, len);
}

/* ---- checkpoint ---- */

const uint8_t neat_coev_magic[8] = {'N', 'E', 'A', 'T', 'C', 'O', 'E', 'V'};

static void neat_put_glist(neat_wbuf *w, const neat_glist *l)
{
    uint32_t i;
    neat_put_u32(w, l->n);
    for (i = 0; i < l->n; i++)
        neat_put_genome(w, &l->g[i]);
}

int neat_coev_save(const neat_coev *c, uint8_t **buf, size_t *len)
{
    neat_wbuf w;
    uint32_t i, k;
    if (c == NULL || buf == NULL || len == NULL)
        return NEAT_E_ARG;
    memset(&w, 0, sizeof w);
    w.a = &c->a;
    neat_put(&w, neat_coev_magic, 8);
    neat_put_u32(&w, NEAT_COEV_CHECKPOINT_VERSION);
    neat_put_u64(&w, c->seed);
    neat_put_u32(&w, c->generation);
    neat_put_u32(&w, c->cp.species_opponents);
    neat_put_u32(&w, c->cp.hof_opponents);
    neat_put_u32(&w, c->cp.first_opponents);
    neat_put_u32(&w, c->cp.compare_configs);
    neat_put_u32(&w, (uint32_t)c->cp.random_fitness);
    neat_put_tag(&w, &c->game); /* version 3 */
    for (i = 0; i < 2; i++) {
        uint8_t *pb = NULL;
        size_t pl = 0;
        int err = neat_pop_save(c->pop[i], &pb, &pl);
        if (err) {
            neat_mem_free(&c->a, w.p, w.cap);
            return err;
        }
        neat_put_u32(&w, (uint32_t)pl);
        neat_put(&w, pb, pl);
        neat_pop_buf_free(c->pop[i], pb, pl);
    }
    neat_put_genome(&w, &c->start);
    for (i = 0; i < 2; i++) {
        neat_put_glist(&w, &c->hof[i]);
        neat_put_glist(&w, &c->champs[i]);
    }
    neat_put_u8(&w, c->have_champion);
    if (c->have_champion)
        neat_put_genome(&w, &c->champion);
    neat_put_u32(&w, c->n_dom);
    for (i = 0; i < c->n_dom; i++) {
        const neat_dom *d = &c->dom[i];
        neat_put_u32(&w, d->generation);
        neat_put_u32(&w, d->pop);
        neat_put_genome(&w, &d->g);
        neat_put_u32(&w, d->n);
        for (k = 0; k < d->n; k++) {
            neat_put_u32(&w, d->wins[k]);
            neat_put_u32(&w, d->losses[k]);
        }
    }
    return neat_put_finish(&w, buf, len);
}

void neat_coev_buf_free(const neat_coev *c, uint8_t *buf, size_t len)
{
    neat_mem_free(&c->a, buf, len);
}

static void neat_get_glist(neat_rbuf *r, neat_glist *l, uint32_t max, const neat_params *p, const neat_alloc *a)
{
    size_t at = r->off;
    uint32_t i, n = neat_get_count(r, 13);
    if (r->err)
        return;
    if (n > max) {
        r->off = at;
        neat_fail(r, NEAT_E_FORMAT);
        return;
    }
    if (neat_mem_reserve(a, (void **)&l->g, &l->cap, n, sizeof(neat_genome)) != NEAT_OK) {
        neat_fail(r, NEAT_E_NOMEM);
        return;
    }
    for (i = 0; i < n && !r->err; i++) {
        neat_genome_init(&l->g[i]);
        l->n = i + 1;
        neat_get_genome(r, &l->g[i], p, a);
    }
}

int neat_coev_load(neat_coev **out, const uint8_t *buf, size_t len, const neat_alloc *alloc, size_t *err_offset)
{
    neat_rbuf r;
    neat_coev *c = NULL;
    const uint8_t *magic;
    const neat_params *pp = NULL;
    const char *field;
    uint32_t i, k, stored, version = 0;
    int err;

    if (out == NULL || buf == NULL)
        return NEAT_E_ARG;
    *out = NULL;
    memset(&r, 0, sizeof r);
    r.p = buf;
    r.n = len;
    /* the frame first: magic, version, checksum; only then the rest */
    magic = neat_get(&r, 8);
    if (magic != NULL && memcmp(magic, neat_coev_magic, 8) != 0) {
        r.off = 0;
        neat_fail(&r, NEAT_E_FORMAT);
    }
    /* version 2 (before the game tag and net_step) still loads: its runs resume */
    if (!r.err)
        version = neat_get_u32(&r);
    if (!r.err && (version < 2 || version > NEAT_COEV_CHECKPOINT_VERSION)) {
        r.off = 8;
        neat_fail(&r, NEAT_E_FORMAT);
    }
    if (!r.err && len < 16) {
        r.off = len;
        neat_fail(&r, NEAT_E_TRUNCATED);
    }
    if (!r.err) {
        stored = (uint32_t)buf[len - 4] | ((uint32_t)buf[len - 3] << 8) | ((uint32_t)buf[len - 2] << 16) |
                 ((uint32_t)buf[len - 1] << 24);
        if (stored != nrt_crc32(0, buf, len - 4)) {
            r.off = len - 4;
            neat_fail(&r, NEAT_E_CRC);
        }
        r.n = len - 4;
    }
    if (!r.err) {
        err = neat_coev_alloc(&c, alloc);
        if (err)
            return err;
        c->seed = neat_get_u64(&r);
        c->generation = neat_get_u32(&r);
        c->cp.species_opponents = neat_get_u32(&r);
        c->cp.hof_opponents = neat_get_u32(&r);
        c->cp.first_opponents = neat_get_u32(&r);
        c->cp.compare_configs = neat_get_u32(&r);
        {
            uint32_t rf = neat_get_u32(&r);
            c->cp.random_fitness = rf <= 1u ? (int)rf : 2; /* 2: refused just below */
        }
        if (!r.err && neat_coev_params_check(&c->cp, &field) != NEAT_OK) {
            r.off = 20;
            neat_fail(&r, NEAT_E_FORMAT);
        }
        if (!r.err && version >= 3)
            neat_get_tag(&r, &c->a, &c->game);
    }
    for (i = 0; i < 2 && !r.err; i++) {
        size_t at = r.off, sub = 0;
        uint32_t pl = neat_get_count(&r, 1);
        const uint8_t *pb = neat_get(&r, pl);
        if (r.err)
            break;
        err = neat_pop_load(&c->pop[i], pb, pl, alloc, &sub);
        if (err) {
            r.off = at + 4 + sub;
            neat_fail(&r, err);
        } else if (neat_pop_generation(c->pop[i]) != c->generation ||
                   (i == 1 && (neat_pop_size(c->pop[1]) != neat_pop_size(c->pop[0]) ||
                               neat_pop_params(c->pop[1])->n_inputs != neat_pop_params(c->pop[0])->n_inputs ||
                               neat_pop_params(c->pop[1])->n_outputs != neat_pop_params(c->pop[0])->n_outputs))) {
            r.off = at;
            neat_fail(&r, NEAT_E_FORMAT);
        }
    }
    if (!r.err) {
        size_t at = r.off;
        pp = neat_pop_params(c->pop[0]);
        if (pp->pop_stagnation != 0 || neat_pop_params(c->pop[1])->pop_stagnation != 0) {
            r.off = at;
            neat_fail(&r, NEAT_E_FORMAT); /* a rule coevolution never applies */
        }
        if (!r.err)
            neat_get_genome(&r, &c->start, pp, &c->a);
    }
    for (i = 0; i < 2 && !r.err; i++) {
        size_t at = r.off;
        neat_get_glist(&r, &c->hof[i], c->generation, pp, &c->a);
        if (!r.err && c->hof[i].n != c->generation) {
            r.off = at;
            neat_fail(&r, NEAT_E_FORMAT);
        }
        /* kept under an earlier species_opponents, perhaps larger (neat_coev_set_params) */
        neat_get_glist(&r, &c->champs[i], NEAT_COEV_MAX_CHAMPS, pp, &c->a);
    }
    if (!r.err) {
        size_t at = r.off;
        c->have_champion = (uint8_t)neat_get_u8(&r);
        if (!r.err && c->have_champion != (c->generation > 0)) {
            r.off = at;
            neat_fail(&r, NEAT_E_FORMAT);
        }
        if (c->have_champion)
            neat_get_genome(&r, &c->champion, pp, &c->a);
    }
    if (!r.err) {
        size_t at = r.off;
        uint32_t nd = neat_get_count(&r, 25);
        if (!r.err && (nd > c->generation || (c->generation > 0 && nd == 0))) {
            r.off = at;
            neat_fail(&r, NEAT_E_FORMAT);
        }
        if (!r.err && neat_mem_reserve(&c->a, (void **)&c->dom, &c->cap_dom, nd, sizeof(neat_dom)) != NEAT_OK)
            neat_fail(&r, NEAT_E_NOMEM);
        for (i = 0; i < nd && !r.err; i++) {
            neat_dom *d = &c->dom[i];
            memset(d, 0, sizeof *d);
            c->n_dom = i + 1;
            at = r.off;
            d->generation = neat_get_u32(&r);
            d->pop = neat_get_u32(&r);
            if (!r.err && (d->generation >= c->generation || d->pop > 1 ||
                           (i > 0 && d->generation <= c->dom[i - 1].generation))) {
                r.off = at;
                neat_fail(&r, NEAT_E_FORMAT);
            }
            neat_get_genome(&r, &d->g, pp, &c->a);
            at = r.off;
            d->n = neat_get_count(&r, 8);
            if (!r.err && d->n != i) { /* dominant i beat the i before it */
                r.off = at;
                d->n = 0;
                neat_fail(&r, NEAT_E_FORMAT);
            }
            if (!r.err && d->n > 0) {
                d->wins = (uint16_t *)neat_mem_realloc(&c->a, NULL, 0, d->n * sizeof(uint16_t));
                d->losses = (uint16_t *)neat_mem_realloc(&c->a, NULL, 0, d->n * sizeof(uint16_t));
                if (d->wins == NULL || d->losses == NULL)
                    neat_fail(&r, NEAT_E_NOMEM);
            }
            for (k = 0; k < d->n && !r.err; k++) {
                uint32_t wv, lv;
                at = r.off;
                wv = neat_get_u32(&r);
                lv = neat_get_u32(&r);
                /* played under an earlier compare_configs, perhaps larger */
                if (!r.err && (wv <= lv || wv > 2u * NEAT_COEV_MAX_CONFIGS || wv + lv > 2u * NEAT_COEV_MAX_CONFIGS)) {
                    r.off = at;
                    neat_fail(&r, NEAT_E_FORMAT);
                }
                d->wins[k] = (uint16_t)wv;
                d->losses[k] = (uint16_t)lv;
            }
        }
    }
    if (!r.err && r.off != r.n) {
        neat_fail(&r, NEAT_E_FORMAT); /* bytes left over */
    }
    if (r.err) {
        if (err_offset != NULL)
            *err_offset = r.err_off;
        neat_coev_free(c);
        return r.err;
    }
    *out = c;
    return NEAT_OK;
}
