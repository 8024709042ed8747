/* test_coev.c - competitive coevolution: the protocol's games, fitness as wins, hall of fame, champions and dominance, determinism, checkpoints, errors. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat_coev.h"
#include "nrt.h"

#define MAXPOP 32
#define MAXCHAMP 64
#define MAXBATCH 64

/* ---- the synthetic game ----
 * A genome's strength is the sum of its enabled connection weights; the
 * first side is worth a little, and so is the comparison configuration.
 * Clearly stronger wins; near equal is mostly a draw, sometimes decided by
 * the game's seed (so the seeds must not depend on the order of play). */
static double coev_strength(const neat_genome *g)
{
    double s = 0.0;
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].enabled)
            s += g->conns[i].weight;
    return s;
}

static int8_t coev_result(const neat_game *gm)
{
    double d = coev_strength(gm->a) - coev_strength(gm->b);
    d += gm->a_first ? 0.1 : -0.1;
    if (gm->config >= 0)
        d += 0.05 * (double)(gm->config % 3 - 1);
    if (d > 0.3)
        return 1;
    if (d < -0.3)
        return -1;
    switch (gm->seed % 4u) {
    case 1:
        return 1;
    case 2:
        return -1;
    default:
        return 0;
    }
}

static int genome_same(const neat_genome *x, const neat_genome *y)
{
    uint32_t i;
    if (x->n_nodes != y->n_nodes || x->n_conns != y->n_conns)
        return 0;
    for (i = 0; i < x->n_nodes; i++)
        if (x->nodes[i].id != y->nodes[i].id || x->nodes[i].type != y->nodes[i].type)
            return 0;
    for (i = 0; i < x->n_conns; i++) {
        const neat_conn *a = &x->conns[i], *b = &y->conns[i];
        if (a->in != b->in || a->out != b->out || a->innov != b->innov || a->enabled != b->enabled ||
            memcmp(&a->weight, &b->weight, sizeof a->weight) != 0)
            return 0;
    }
    return 1;
}

static int in_pop(const neat_pop *pop, const neat_genome *g)
{
    uint32_t i;
    for (i = 0; i < neat_pop_size(pop); i++)
        if (neat_pop_genome(pop, i) == g)
            return 1;
    return 0;
}

static int in_hof(const neat_coev *c, uint32_t which, const neat_genome *g)
{
    uint32_t t;
    for (t = 0; t < neat_coev_hof_count(c, which); t++)
        if (neat_coev_hof(c, which, t) == g)
            return 1;
    return 0;
}

/* ---- the callback and what it saw ---- */
typedef struct coev_ctx {
    neat_coev *c;     /* the coevolution being stepped, for checks during play (NULL: no checks) */
    int check;        /* check the host games against the protocol */
    int reverse;      /* play each batch back to front */
    int fail_code;    /* returned instead of playing batch fail_batch (0: never) */
    uint32_t fail_batch;
    const uint16_t (*script)[2]; /* comparison i of a step: a wins script[i][0], b script[i][1] */
    uint32_t n_script;
    /* the step as the callback saw it */
    uint32_t batches;
    uint64_t games, batch_games[MAXBATCH];
    uint32_t size, n_opp, wins[2][MAXPOP], best[2], species[2];
    uint32_t cmp[MAXBATCH][2]; /* comparison i: a's wins, b's wins */
    neat_genome best_copy[2];
    /* species champions: met by the other population's hosts next generation */
    neat_genome champ[2][MAXCHAMP], next_champ[2][MAXCHAMP];
    uint32_t n_champ[2], n_next[2];
} coev_ctx;

static void ctx_init(coev_ctx *x, neat_coev *c)
{
    memset(x, 0, sizeof *x); /* all genomes empty (neat_genome_init is a memset) */
    x->c = c;
}

static void ctx_free(coev_ctx *x)
{
    uint32_t p, k;
    for (p = 0; p < 2; p++) {
        neat_genome_free(&x->best_copy[p], NULL);
        for (k = 0; k < MAXCHAMP; k++) {
            neat_genome_free(&x->champ[p][k], NULL);
            neat_genome_free(&x->next_champ[p][k], NULL);
        }
    }
}

/* before a step */
static void ctx_begin(coev_ctx *x)
{
    x->batches = 0;
    x->games = 0;
    memset(x->batch_games, 0, sizeof x->batch_games);
    memset(x->cmp, 0, sizeof x->cmp);
}

/* after a successful step: the champions just seen become the next generation's opponents */
static void ctx_commit(coev_ctx *x)
{
    uint32_t p, k;
    for (p = 0; p < 2; p++) {
        for (k = 0; k < MAXCHAMP; k++) {
            neat_genome t = x->champ[p][k];
            x->champ[p][k] = x->next_champ[p][k];
            x->next_champ[p][k] = t;
        }
        x->n_champ[p] = x->n_next[p];
    }
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* The host games checked against the protocol (while the population's
 * genomes still exist), and the species champions the next generation
 * must meet worked out independently. */
static void check_hosts(coev_ctx *x, const neat_game *games, size_t n)
{
    const neat_coev *c = x->c;
    const neat_coev_params *cp = neat_coev_get_params(c);
    uint32_t gen = neat_coev_generation(c), size = x->size, nopp = x->n_opp, p, h, j, s, k, i;
    uint64_t *seeds;

    assert_int_equal(nopp, gen == 0 ? cp->first_opponents : cp->species_opponents + cp->hof_opponents);
    for (p = 0; p < 2; p++) {
        const neat_pop *own = neat_coev_pop(c, p), *other = neat_coev_pop(c, p ^ 1u);
        uint32_t ns = 0, n_champ = 0, n_hof = 0;
        if (gen > 0)
            ns = x->n_champ[p ^ 1u] < cp->species_opponents ? x->n_champ[p ^ 1u] : cp->species_opponents;
        for (j = 0; j < nopp; j++) {
            const neat_genome *o = games[((size_t)p * size * nopp + j) * 2].b;
            /* the same opponent for every host, from both sides */
            for (h = 0; h < size; h++)
                for (s = 0; s < 2; s++) {
                    const neat_game *gm = &games[(((size_t)p * size + h) * nopp + j) * 2 + s];
                    assert_ptr_equal(gm->a, neat_pop_genome(own, h));
                    assert_ptr_equal(gm->b, o);
                    assert_int_equal(gm->config, -1);
                    assert_int_equal(gm->a_first, s == 0);
                }
            if (gen == 0) {
                assert_true(in_pop(other, o)); /* members of the other population */
            } else if (in_hof(c, p ^ 1u, o)) {
                n_hof++; /* the other population's hall of fame */
            } else {
                /* else a copy of one of the other population's species champions, best first */
                assert_false(in_pop(other, o));
                assert_false(in_pop(own, o));
                assert_true(n_champ < ns);
                assert_true(genome_same(o, &x->champ[p ^ 1u][n_champ]));
                n_champ++;
            }
        }
        if (gen > 0) {
            assert_int_equal(n_champ, ns);
            assert_int_equal(n_hof, nopp - ns);
        }
    }
    /* every game its own seed */
    seeds = (uint64_t *)malloc(n * sizeof *seeds);
    assert_non_null(seeds);
    for (i = 0; i < n; i++)
        seeds[i] = games[i].seed;
    qsort(seeds, n, sizeof *seeds, cmp_u64);
    for (i = 1; i < n; i++)
        assert_true(seeds[i] != seeds[i - 1]);
    free(seeds);

    /* the champions of each population's best species (by their champions'
     * wins, lower index on ties), at most species_opponents of them */
    for (p = 0; p < 2; p++) {
        const neat_pop *pop = neat_coev_pop(c, p);
        uint32_t ids[MAXPOP], n_sp = neat_pop_species_count(pop), m = 0;
        for (k = 0; k < n_sp; k++) {
            neat_species_info info;
            uint32_t best = size;
            assert_int_equal(neat_pop_species(pop, k, &info), NEAT_OK);
            for (i = 0; i < size; i++)
                if (neat_pop_genome(pop, i)->species == info.id && (best == size || x->wins[p][i] > x->wins[p][best]))
                    best = i;
            assert_true(best < size); /* no species without members */
            ids[m++] = best;
        }
        for (k = 1; k < m; k++) /* insertion sort */
            for (i = k; i > 0; i--) {
                uint32_t u = ids[i - 1], v = ids[i], t;
                if (x->wins[p][u] > x->wins[p][v] || (x->wins[p][u] == x->wins[p][v] && u < v))
                    break;
                t = ids[i - 1];
                ids[i - 1] = ids[i];
                ids[i] = t;
            }
        if (m > cp->species_opponents)
            m = cp->species_opponents;
        for (k = 0; k < m; k++)
            assert_int_equal(neat_genome_copy(&x->next_champ[p][k], neat_pop_genome(pop, ids[k]), NULL), NEAT_OK);
        x->n_next[p] = m;
    }
}

/* the host games: every host's wins and the best of each population */
static void host_batch(coev_ctx *x, const neat_game *games, size_t n)
{
    uint32_t p, h, k;
    size_t at = 0;
    x->size = neat_pop_size(neat_coev_pop(x->c, 0));
    assert_true(x->size <= MAXPOP);
    assert_int_equal(n % (4u * x->size), 0);
    x->n_opp = (uint32_t)(n / (4u * x->size));
    for (p = 0; p < 2; p++) {
        const neat_pop *pop = neat_coev_pop(x->c, p);
        x->best[p] = 0;
        for (h = 0; h < x->size; h++) {
            uint32_t w = 0;
            for (k = 0; k < 2u * x->n_opp; k++)
                w += games[at++].result > 0;
            x->wins[p][h] = w;
            if (w > x->wins[p][x->best[p]])
                x->best[p] = h;
        }
        x->species[p] = neat_pop_species_count(pop);
        assert_int_equal(neat_genome_copy(&x->best_copy[p], neat_pop_genome(pop, x->best[p]), NULL), NEAT_OK);
    }
    if (x->check)
        check_hosts(x, games, n);
}

/* comparison i of the step: 0 the two bests, then the champion against the dominants, the latest first */
static void compare_batch(coev_ctx *x, uint32_t i, neat_game *games, size_t n)
{
    const neat_coev_params *cp = neat_coev_get_params(x->c);
    size_t k;
    assert_true(i < MAXBATCH);
    assert_int_equal(n, 2u * cp->compare_configs);
    for (k = 0; k < n; k++) {
        assert_int_equal(games[k].config, (int32_t)(k / 2));
        assert_int_equal(games[k].a_first, k % 2 == 0);
        assert_ptr_equal(games[k].a, games[0].a);
        assert_ptr_equal(games[k].b, games[0].b);
    }
    if (x->script != NULL) {
        assert_true(i < x->n_script); /* no comparison beyond those scripted */
        assert_true((size_t)x->script[i][0] + x->script[i][1] <= n);
        for (k = 0; k < n; k++)
            games[k].result = (int8_t)(k < x->script[i][0] ? 1 : k < (size_t)x->script[i][0] + x->script[i][1] ? -1 : 0);
    }
    for (k = 0; k < n; k++) {
        x->cmp[i][0] += games[k].result > 0;
        x->cmp[i][1] += games[k].result < 0;
    }
    if (i == 0) {
        assert_ptr_equal(games[0].a, neat_pop_genome(neat_coev_pop(x->c, 0), x->best[0]));
        assert_ptr_equal(games[0].b, neat_pop_genome(neat_coev_pop(x->c, 1), x->best[1]));
    } else {
        uint32_t cpop = x->cmp[0][1] > x->cmp[0][0], nd = neat_coev_dominant_count(x->c);
        neat_dominant d;
        assert_ptr_equal(games[0].a, neat_pop_genome(neat_coev_pop(x->c, cpop), x->best[cpop]));
        assert_true(i <= nd);
        assert_int_equal(neat_coev_dominant(x->c, nd - i, &d), NEAT_OK);
        assert_ptr_equal(games[0].b, d.genome);
        if (i >= 2) /* it goes on only after a win */
            assert_true(x->cmp[i - 1][0] > x->cmp[i - 1][1]);
    }
}

static int coev_play(void *ud, neat_game *games, size_t n)
{
    coev_ctx *x = (coev_ctx *)ud;
    uint32_t b = x->batches++;
    size_t i;
    assert_true(n > 0);
    if (b < MAXBATCH)
        x->batch_games[b] = n;
    x->games += n;
    if (x->fail_code != 0 && b == x->fail_batch) {
        for (i = 0; i < n; i++)
            games[i].result = 1; /* scribbled on: must not matter */
        return x->fail_code;
    }
    for (i = 0; i < n; i++) {
        size_t k = x->reverse ? n - 1 - i : i;
        games[k].result = coev_result(&games[k]);
    }
    assert_int_equal(games[0].config == -1, b == 0);
    if (x->c == NULL)
        return 0;
    if (b == 0)
        host_batch(x, games, n);
    else
        compare_batch(x, b - 1, games, n);
    return 0;
}

/* ---- helpers ---- */
static neat_params coev_neat_params(uint32_t pop_size)
{
    neat_params p = neat_params_default();
    p.pop_size = pop_size;
    p.n_inputs = 3;
    p.n_outputs = 2;
    p.add_node_prob = 0.1;
    p.add_conn_prob = 0.3;
    p.target_species = 4;
    p.pop_stagnation = 0; /* refused in coevolution */
    return p;
}

static neat_coev_params small_coev_params(void)
{
    neat_coev_params cp = neat_coev_params_default();
    cp.compare_configs = 4;
    return cp;
}

static neat_coev *coev_new(uint32_t pop_size, const neat_coev_params *cp, uint64_t seed, const neat_alloc *a)
{
    neat_params p = coev_neat_params(pop_size);
    neat_coev *c = NULL;
    assert_int_equal(neat_coev_create(&c, &p, cp, NULL, seed, a), NEAT_OK);
    assert_non_null(c);
    return c;
}

static void step_ok(neat_coev *c, coev_ctx *x, neat_coev_report *r)
{
    x->c = c;
    ctx_begin(x);
    assert_int_equal(neat_coev_step(c, coev_play, x, r), NEAT_OK);
    ctx_commit(x);
}

static void steps(neat_coev *c, uint32_t n)
{
    coev_ctx x;
    uint32_t g;
    ctx_init(&x, c);
    for (g = 0; g < n; g++)
        step_ok(c, &x, NULL);
    ctx_free(&x);
}

static void save(const neat_coev *c, uint8_t **buf, size_t *len)
{
    assert_int_equal(neat_coev_save(c, buf, len), NEAT_OK);
    assert_true(*len > 16);
    assert_int_equal(neat_checkpoint_kind(*buf, *len), NEAT_CKPT_COEV); /* known by its magic */
}

static void assert_saves_equal(const neat_coev *c1, const neat_coev *c2)
{
    uint8_t *b1, *b2;
    size_t l1, l2;
    save(c1, &b1, &l1);
    save(c2, &b2, &l2);
    assert_int_equal(l1, l2);
    assert_memory_equal(b1, b2, l1);
    neat_coev_buf_free(c1, b1, l1);
    neat_coev_buf_free(c2, b2, l2);
}

static void assert_save_is(const neat_coev *c, const uint8_t *buf, size_t len)
{
    uint8_t *b;
    size_t l;
    save(c, &b, &l);
    assert_int_equal(l, len);
    assert_memory_equal(b, buf, len);
    neat_coev_buf_free(c, b, l);
}

static void reseal(uint8_t *buf, size_t len)
{
    uint32_t crc = nrt_crc32(0, buf, len - 4);
    buf[len - 4] = (uint8_t)crc;
    buf[len - 3] = (uint8_t)(crc >> 8);
    buf[len - 2] = (uint8_t)(crc >> 16);
    buf[len - 1] = (uint8_t)(crc >> 24);
}

/* ---- 1. the protocol's games and the report ---- */
static void test_protocol_counts(void **state)
{
    neat_coev_params cp = neat_coev_params_default();
    neat_coev *c = coev_new(16, &cp, 11, NULL);
    coev_ctx x;
    uint32_t g, q, h, k;
    (void)state;
    ctx_init(&x, c);
    x.check = 1;
    assert_null(neat_coev_champion(c));
    assert_int_equal(neat_coev_dominant_count(c), 0);
    for (g = 0; g < 6; g++) {
        neat_coev_report r;
        uint32_t nd = neat_coev_dominant_count(c), played, all_won = 1;
        memset(&r, 0xA5, sizeof r);
        assert_int_equal(neat_coev_generation(c), g);
        step_ok(c, &x, &r);
        assert_int_equal(neat_coev_generation(c), g + 1);
        assert_int_equal(r.generation, g);
        /* host games: pop * 12 opponents * 2 sides for each population, on the training configuration */
        assert_int_equal(x.n_opp, 12);
        assert_int_equal(x.batch_games[0], 2u * 16u * 12u * 2u);
        /* the comparison of the two bests: every configuration from both sides */
        assert_true(x.batches >= 2);
        assert_int_equal(x.batch_games[1], 2u * 144u);
        for (q = 0; q < 2; q++) {
            double sum = 0;
            uint32_t best = 0;
            for (h = 0; h < 16; h++) {
                sum += x.wins[q][h];
                if (x.wins[q][h] > best)
                    best = x.wins[q][h];
            }
            assert_int_equal(r.pop[q].games, 16u * 12u * 2u);
            assert_true(r.pop[q].best_fitness == (double)best);
            assert_int_equal(r.pop[q].best_index, x.best[q]);
            assert_true(fabs(r.pop[q].mean_fitness - sum / 16.0) < 1e-12);
            assert_int_equal(r.pop[q].species, x.species[q]);
            assert_int_equal(r.pop[q].best_conns, neat_genome_enabled_count(&x.best_copy[q]));
            assert_int_equal(r.pop[q].best_hidden, neat_genome_hidden_count(&x.best_copy[q]));
        }
        assert_int_equal(r.champion_wins[0], x.cmp[0][0]);
        assert_int_equal(r.champion_wins[1], x.cmp[0][1]);
        assert_int_equal(r.champion_pop, x.cmp[0][1] > x.cmp[0][0]);
        /* the dominance tournament: against the dominants, latest first, up to the first non-win */
        played = x.batches - 2;
        assert_true(played <= nd);
        for (k = 0; k < played; k++) {
            assert_int_equal(x.batch_games[2 + k], 2u * 144u);
            if (x.cmp[1 + k][0] <= x.cmp[1 + k][1]) {
                all_won = 0;
                assert_int_equal(k, played - 1);
            }
        }
        assert_int_equal(r.dominance_games, played * 2u * 144u);
        assert_int_equal(r.new_dominant, played == nd && all_won);
        assert_int_equal(r.dominants, nd + (uint32_t)r.new_dominant);
        assert_int_equal(neat_coev_dominant_count(c), r.dominants);
        if (g == 0)
            assert_int_equal(r.new_dominant, 1);
        /* every game counted once */
        assert_int_equal(r.games, x.games);
        assert_int_equal(r.games, r.pop[0].games + r.pop[1].games + 2u * 144u + r.dominance_games);
    }
    ctx_free(&x);
    neat_coev_free(c);
}

/* ---- 2. fitness is wins; the hall of fame keeps each generation's best ---- */
static void test_fitness_is_wins(void **state)
{
    neat_coev_params cp = small_coev_params();
    neat_coev *c = coev_new(16, &cp, 5, NULL);
    neat_genome hof[2][6];
    coev_ctx x;
    uint32_t g, q, t;
    (void)state;
    memset(hof, 0, sizeof hof);
    ctx_init(&x, c);
    for (g = 0; g < 6; g++) {
        neat_coev_report r;
        const neat_genome *champ;
        step_ok(c, &x, &r);
        for (q = 0; q < 2; q++) {
            const neat_genome *e = neat_coev_hof(c, q, g);
            assert_int_equal(neat_coev_hof_count(c, q), g + 1);
            assert_int_equal(neat_coev_hof_count(c, q), neat_coev_generation(c));
            assert_null(neat_coev_hof(c, q, g + 1));
            assert_non_null(e);
            assert_true(e->fitness == r.pop[q].best_fitness);
            assert_true(e->fitness == (double)x.wins[q][x.best[q]]);
            assert_true(genome_same(e, &x.best_copy[q]));
            assert_int_equal(neat_genome_copy(&hof[q][g], e, NULL), NEAT_OK);
            for (t = 0; t < g; t++) /* earlier entries untouched */
                assert_true(genome_same(neat_coev_hof(c, q, t), &hof[q][t]));
        }
        champ = neat_coev_champion(c);
        assert_non_null(champ);
        assert_true(genome_same(champ, &x.best_copy[r.champion_pop]));
        assert_true(champ->fitness == r.pop[r.champion_pop].best_fitness);
    }
    assert_null(neat_coev_hof(c, 2, 0));
    assert_int_equal(neat_coev_hof_count(c, 2), 0);
    for (q = 0; q < 2; q++)
        for (g = 0; g < 6; g++)
            neat_genome_free(&hof[q][g], NULL);
    ctx_free(&x);
    neat_coev_free(c);
}

/* ---- 3. generation champions and the dominance tournament, comparisons scripted ---- */
typedef struct dom_case {
    uint16_t script[4][2];
    uint32_t n_script;   /* = comparison batches expected */
    uint32_t champ_pop, dominants, new_dominant;
} dom_case;

static void test_dominance(void **state)
{
    static const dom_case cases[] = {
        {{{2, 5}}, 1, 1, 1, 1},                         /* gen 0: B's best; level 1 */
        {{{3, 3}, {5, 2}}, 2, 0, 2, 1},                 /* gen 1: tie goes to A; beats d1: level 2 */
        {{{1, 4}, {3, 3}}, 2, 1, 2, 0},                 /* gen 2: ties d2: not dominant */
        {{{4, 1}, {6, 1}, {1, 6}}, 3, 0, 2, 0},         /* gen 3: beats d2, loses to d1 */
        {{{0, 0}, {4, 3}, {5, 0}}, 3, 0, 3, 1},         /* gen 4: beats d2 and d1: level 3 */
        {{{0, 8}, {7, 1}, {2, 2}}, 3, 1, 3, 0},         /* gen 5: beats d3, ties d2: stops there */
        {{{6, 2}, {4, 4}}, 2, 0, 3, 0},                 /* gen 6: ties d3 */
    };
    neat_coev_params cp = small_coev_params();
    neat_coev *c = coev_new(12, &cp, 9, NULL);
    neat_genome champs[7];
    neat_dominant d;
    coev_ctx x;
    uint32_t g;
    (void)state;
    memset(champs, 0, sizeof champs);
    ctx_init(&x, c);
    for (g = 0; g < 7; g++) {
        const dom_case *dc = &cases[g];
        neat_coev_report r;
        x.script = dc->script;
        x.n_script = dc->n_script;
        step_ok(c, &x, &r);
        assert_int_equal(x.batches, 1 + dc->n_script);
        assert_int_equal(r.champion_pop, dc->champ_pop);
        assert_int_equal(r.champion_wins[0], dc->script[0][0]);
        assert_int_equal(r.champion_wins[1], dc->script[0][1]);
        assert_int_equal(r.dominants, dc->dominants);
        assert_int_equal(neat_coev_dominant_count(c), dc->dominants);
        assert_int_equal(r.new_dominant, dc->new_dominant);
        assert_int_equal(r.dominance_games, (dc->n_script - 1) * 2u * cp.compare_configs);
        assert_true(genome_same(neat_coev_champion(c), &x.best_copy[dc->champ_pop]));
        assert_int_equal(neat_genome_copy(&champs[g], &x.best_copy[dc->champ_pop], NULL), NEAT_OK);
    }
    assert_int_equal(neat_coev_dominant(c, 0, &d), NEAT_OK);
    assert_int_equal(d.generation, 0);
    assert_int_equal(d.pop, 1);
    assert_int_equal(d.n_beaten, 0);
    assert_true(genome_same(d.genome, &champs[0]));
    assert_int_equal(neat_coev_dominant(c, 1, &d), NEAT_OK);
    assert_int_equal(d.generation, 1);
    assert_int_equal(d.pop, 0);
    assert_int_equal(d.n_beaten, 1);
    assert_int_equal(d.wins[0], 5);
    assert_int_equal(d.losses[0], 2);
    assert_true(genome_same(d.genome, &champs[1]));
    assert_int_equal(neat_coev_dominant(c, 2, &d), NEAT_OK);
    assert_int_equal(d.generation, 4);
    assert_int_equal(d.pop, 0);
    assert_int_equal(d.n_beaten, 2);
    assert_int_equal(d.wins[0], 4); /* against d2 first */
    assert_int_equal(d.losses[0], 3);
    assert_int_equal(d.wins[1], 5);
    assert_int_equal(d.losses[1], 0);
    assert_true(genome_same(d.genome, &champs[4]));
    assert_int_equal(neat_coev_dominant(c, 3, &d), NEAT_E_ARG);

    /* the tournament survives a checkpoint */
    {
        uint8_t *buf;
        size_t len;
        neat_coev *l = NULL;
        save(c, &buf, &len);
        assert_int_equal(neat_coev_load(&l, buf, len, NULL, NULL), NEAT_OK);
        assert_int_equal(neat_coev_dominant_count(l), 3);
        assert_int_equal(neat_coev_dominant(l, 2, &d), NEAT_OK);
        assert_int_equal(d.generation, 4);
        assert_int_equal(d.n_beaten, 2);
        assert_int_equal(d.wins[1], 5);
        assert_true(genome_same(d.genome, &champs[4]));
        assert_true(genome_same(neat_coev_champion(l), &champs[6]));
        neat_coev_buf_free(c, buf, len);
        neat_coev_free(l);
    }
    for (g = 0; g < 7; g++)
        neat_genome_free(&champs[g], NULL);
    ctx_free(&x);
    neat_coev_free(c);
}

/* ---- 4. determinism: same seed, any order of play, same run ---- */
static void test_determinism(void **state)
{
    neat_coev_params cp = small_coev_params();
    neat_coev *c1 = coev_new(16, &cp, 77, NULL), *c2 = coev_new(16, &cp, 77, NULL), *c3 = coev_new(16, &cp, 78, NULL);
    coev_ctx x1, x2, x3;
    uint8_t *b1, *b3;
    size_t l1, l3;
    uint32_t g;
    (void)state;
    ctx_init(&x1, c1);
    ctx_init(&x2, c2);
    ctx_init(&x3, c3);
    x2.reverse = 1;
    for (g = 0; g < 8; g++) {
        neat_coev_report r1, r2;
        step_ok(c1, &x1, &r1);
        step_ok(c2, &x2, &r2);
        step_ok(c3, &x3, NULL);
        assert_int_equal(r1.games, r2.games);
        assert_true(r1.pop[0].best_fitness == r2.pop[0].best_fitness);
        assert_true(r1.pop[1].mean_fitness == r2.pop[1].mean_fitness);
        assert_int_equal(r1.champion_pop, r2.champion_pop);
        assert_int_equal(r1.dominants, r2.dominants);
    }
    assert_saves_equal(c1, c2);
    save(c1, &b1, &l1);
    save(c3, &b3, &l3);
    assert_int_equal(neat_coev_seed(c1), 77);
    assert_int_equal(neat_coev_seed(c3), 78);
    assert_true(l1 != l3 || memcmp(b1, b3, l1) != 0);
    neat_coev_buf_free(c1, b1, l1);
    neat_coev_buf_free(c3, b3, l3);
    ctx_free(&x1);
    ctx_free(&x2);
    ctx_free(&x3);
    neat_coev_free(c1);
    neat_coev_free(c2);
    neat_coev_free(c3);
}

/* evolution does something: after some generations the halls of fame are stronger than at the start */
static void test_evolution_meaningful(void **state)
{
    neat_coev_params cp = small_coev_params();
    neat_coev *c = coev_new(24, &cp, 3, NULL);
    uint32_t q;
    (void)state;
    steps(c, 25);
    for (q = 0; q < 2; q++)
        assert_true(coev_strength(neat_coev_hof(c, q, 24)) > coev_strength(neat_coev_hof(c, q, 0)));
    assert_true(neat_coev_dominant_count(c) >= 1);
    neat_coev_free(c);
}

/* ---- 5. checkpoints: exact resumption; every corruption and truncation refused ---- */
static void test_checkpoint_resume(void **state)
{
    neat_coev_params cp = small_coev_params();
    neat_coev *c = coev_new(16, &cp, 21, NULL), *l = NULL;
    uint8_t *buf;
    size_t len, off = 999;
    uint32_t q;
    (void)state;
    steps(c, 3);
    save(c, &buf, &len);
    assert_int_equal(neat_coev_load(&l, buf, len, NULL, &off), NEAT_OK);
    assert_non_null(l);
    assert_save_is(l, buf, len); /* the bytes again */
    assert_int_equal(neat_coev_generation(l), 3);
    assert_int_equal(neat_coev_seed(l), 21);
    assert_memory_equal(neat_coev_get_params(l), &cp, sizeof cp);
    assert_int_equal(neat_coev_dominant_count(l), neat_coev_dominant_count(c));
    assert_true(genome_same(neat_coev_champion(l), neat_coev_champion(c)));
    for (q = 0; q < 2; q++) {
        assert_int_equal(neat_coev_hof_count(l, q), 3);
        assert_true(genome_same(neat_coev_hof(l, q, 2), neat_coev_hof(c, q, 2)));
    }
    steps(c, 3);
    steps(l, 3);
    assert_saves_equal(c, l);
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(l);
    neat_coev_free(c);
}

/* A small checkpoint with every section filled: both halls of fame, species
 * champions, and a dominant that beat another (scripted comparisons). */
static neat_coev *tiny_coev(uint64_t seed, uint8_t **buf, size_t *len)
{
    static const uint16_t s0[][2] = {{1, 3}};
    static const uint16_t s1[][2] = {{3, 1}, {6, 1}};
    neat_coev_params cp = small_coev_params();
    neat_params p = coev_neat_params(5);
    neat_coev *c = NULL;
    neat_dominant d;
    coev_ctx x;
    p.n_inputs = 1;
    p.n_outputs = 1;
    p.add_node_prob = 0.1;
    p.target_species = 2;
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, seed, NULL), NEAT_OK);
    ctx_init(&x, c);
    x.script = s0;
    x.n_script = 1;
    step_ok(c, &x, NULL);
    x.script = s1;
    x.n_script = 2;
    step_ok(c, &x, NULL);
    x.script = NULL;
    step_ok(c, &x, NULL);
    ctx_free(&x);
    assert_true(neat_coev_dominant_count(c) >= 2);
    assert_int_equal(neat_coev_dominant(c, 1, &d), NEAT_OK);
    assert_int_equal(d.n_beaten, 1);
    save(c, buf, len);
    return c;
}

static int load_error_ok(int err)
{
    return err == NEAT_E_CRC || err == NEAT_E_FORMAT || err == NEAT_E_TRUNCATED;
}

static void test_checkpoint_corruption(void **state)
{
    uint8_t *buf, *bad;
    size_t len, i, off;
    neat_coev *c = tiny_coev(4, &buf, &len), *l;
    int m;
    (void)state;
    bad = (uint8_t *)malloc(len + 1);
    assert_non_null(bad);
    /* any single byte changed: refused */
    for (i = 0; i < len; i++)
        for (m = 0; m < 2; m++) {
            int err;
            memcpy(bad, buf, len);
            bad[i] ^= (uint8_t)(m ? 0xFF : 1u << (i % 8));
            l = (neat_coev *)&l;
            off = (size_t)-1;
            err = neat_coev_load(&l, bad, len, NULL, &off);
            assert_true(load_error_ok(err));
            assert_null(l);
            assert_true(off <= len);
            if (i < 12 && !(i == 8 && bad[8] == 2))
                assert_int_equal(err, NEAT_E_FORMAT); /* magic or version (3 -> 2 loads: the checksum) */
        }
    /* every truncation refused, and a byte too many */
    for (i = 0; i < len; i++) {
        int err;
        l = (neat_coev *)&l;
        off = (size_t)-1;
        err = neat_coev_load(&l, buf, i, NULL, &off);
        assert_true(load_error_ok(err));
        assert_null(l);
        assert_true(off <= i);
        if (i < 16)
            assert_int_equal(err, NEAT_E_TRUNCATED);
    }
    memcpy(bad, buf, len);
    bad[len] = 0;
    assert_true(load_error_ok(neat_coev_load(&l, bad, len + 1, NULL, NULL)));
    /* bad arguments */
    assert_int_equal(neat_coev_load(NULL, buf, len, NULL, NULL), NEAT_E_ARG);
    assert_int_equal(neat_coev_load(&l, NULL, len, NULL, NULL), NEAT_E_ARG);
    free(bad);
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(c);
}

/* Changed bytes with a valid checksum: the parser's own checks. Refused
 * with a sensible offset, or accepted; whatever is accepted saves to the
 * same bytes and can be stepped on. */
static void test_checkpoint_resealed(void **state)
{
    uint8_t *buf, *bad;
    size_t len, i, off;
    neat_coev *c = tiny_coev(6, &buf, &len), *l;
    unsigned accepted = 0, refused = 0;
    int m;
    (void)state;
    bad = (uint8_t *)malloc(len);
    assert_non_null(bad);
    for (i = 0; i + 4 < len; i++)
        for (m = 0; m < 2; m++) {
            int err;
            memcpy(bad, buf, len);
            bad[i] ^= (uint8_t)(m == 0 ? 0x01 : 0xFF);
            reseal(bad, len);
            l = NULL;
            off = (size_t)-1;
            err = neat_coev_load(&l, bad, len, NULL, &off);
            if (err != NEAT_OK) {
                /* (a population's own checksum may catch it first) */
                assert_true(load_error_ok(err));
                assert_null(l);
                assert_true(off <= len);
                refused++;
                continue;
            }
            accepted++;
            assert_save_is(l, bad, len);
            {
                coev_ctx x;
                neat_coev_report r;
                ctx_init(&x, NULL); /* no protocol checks on a state nobody made */
                err = neat_coev_step(l, coev_play, &x, &r);
                assert_true(err == NEAT_OK || err == NEAT_E_PARAM);
                ctx_free(&x);
            }
            neat_coev_free(l);
        }
    assert_true(accepted > 0);
    assert_true(refused > 0);
    free(bad);
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(c);
}

/* ---- 6. errors: the callback's and the allocator's ---- */
static void test_play_error(void **state)
{
    neat_coev_params cp = small_coev_params();
    neat_coev *c = coev_new(12, &cp, 13, NULL), *twin = coev_new(12, &cp, 13, NULL);
    coev_ctx x, xt;
    uint32_t b;
    (void)state;
    ctx_init(&x, c);
    ctx_init(&xt, twin);
    step_ok(c, &x, NULL);
    step_ok(twin, &xt, NULL);
    /* batch 0: host games; 1: the champions' comparison; 2: the first dominance comparison */
    for (b = 0; b < 3; b++) {
        neat_coev_report r, r0;
        uint8_t *pre;
        size_t len;
        uint32_t gen = neat_coev_generation(c);
        save(c, &pre, &len);
        memset(&r, 0x5A, sizeof r);
        memcpy(&r0, &r, sizeof r);
        ctx_begin(&x);
        x.fail_code = -42;
        x.fail_batch = b;
        assert_int_equal(neat_coev_step(c, coev_play, &x, &r), -42);
        assert_int_equal(x.batches, b + 1);
        assert_memory_equal(&r, &r0, sizeof r); /* no report */
        assert_int_equal(neat_coev_generation(c), gen);
        assert_int_equal(neat_coev_hof_count(c, 0), gen);
        assert_save_is(c, pre, len);
        neat_coev_buf_free(c, pre, len);
        /* then on as if nothing had happened */
        x.fail_code = 0;
        step_ok(c, &x, NULL);
        step_ok(twin, &xt, NULL);
        assert_saves_equal(c, twin);
    }
    assert_int_equal(neat_coev_step(NULL, coev_play, &x, NULL), NEAT_E_ARG);
    assert_int_equal(neat_coev_step(c, NULL, &x, NULL), NEAT_E_ARG);
    ctx_free(&x);
    ctx_free(&xt);
    neat_coev_free(c);
    neat_coev_free(twin);
}

/* a counting allocator that refuses on demand (every block carries its size) */
typedef struct counter {
    size_t live, calls, fail_at, refused, bad_size;
    int fail_after;
} counter;

#define HDR 16

static void *counting_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    counter *k = (counter *)ud;
    unsigned char *real = ptr ? (unsigned char *)ptr - HDR : NULL;
    size_t have = 0;
    if (real != NULL)
        memcpy(&have, real, sizeof have);
    if ((ptr != NULL && have != old_size) || (ptr == NULL && old_size != 0))
        k->bad_size++;
    if (new_size == 0) {
        if (real != NULL) {
            free(real);
            k->live--;
        }
        return NULL;
    }
    k->calls++;
    if (k->fail_at != 0 && (k->calls == k->fail_at || (k->fail_after && k->calls > k->fail_at))) {
        k->refused++;
        return NULL;
    }
    real = (unsigned char *)realloc(real, new_size + HDR);
    if (real == NULL)
        return NULL;
    memcpy(real, &new_size, sizeof new_size);
    if (ptr == NULL)
        k->live++;
    return real + HDR;
}

static void test_alloc_failure_in_step(void **state)
{
    neat_coev_params cp = small_coev_params();
    counter k;
    neat_alloc a;
    neat_coev *c, *l;
    uint8_t *pre, *post;
    size_t pre_len, post_len, requests, n;
    unsigned unchanged = 0, broken = 0;
    int mode;
    (void)state;
    memset(&k, 0, sizeof k);
    a.fn = counting_alloc;
    a.ud = &k;
    c = coev_new(12, &cp, 31, &a);
    steps(c, 2);
    save(c, &pre, &pre_len);
    /* the step that should happen, and how many requests it makes */
    assert_int_equal(neat_coev_load(&l, pre, pre_len, &a, NULL), NEAT_OK);
    n = k.calls;
    steps(l, 1);
    requests = k.calls - n;
    save(l, &post, &post_len);
    neat_coev_free(l);
    assert_true(requests > 10);

    for (mode = 0; mode < 2; mode++)
        for (n = 1; n <= requests + 1; n += mode ? 3 : 1) {
            coev_ctx x;
            int err;
            l = NULL;
            assert_int_equal(neat_coev_load(&l, pre, pre_len, &a, NULL), NEAT_OK);
            ctx_init(&x, l);
            k.refused = 0;
            k.fail_at = k.calls + n;
            k.fail_after = mode;
            err = neat_coev_step(l, coev_play, &x, NULL);
            k.fail_at = 0;
            if (err == NEAT_OK) {
                assert_int_equal(k.refused, 0);
                assert_save_is(l, post, post_len);
            } else {
                uint8_t *b;
                size_t bl;
                assert_int_equal(err, NEAT_E_NOMEM);
                assert_true(k.refused > 0);
                err = neat_coev_save(l, &b, &bl);
                if (err == NEAT_E_STATE) {
                    /* the documented broken case: unusable from then on */
                    broken++;
                    assert_int_equal(neat_coev_step(l, coev_play, &x, NULL), NEAT_E_STATE);
                } else {
                    /* nothing changed, and a retry gives the same generation */
                    unchanged++;
                    assert_int_equal(err, NEAT_OK);
                    assert_int_equal(bl, pre_len);
                    assert_memory_equal(b, pre, pre_len);
                    neat_coev_buf_free(l, b, bl);
                    assert_int_equal(neat_coev_generation(l), 2);
                    ctx_free(&x);
                    ctx_init(&x, l);
                    step_ok(l, &x, NULL);
                    assert_save_is(l, post, post_len);
                }
            }
            ctx_free(&x);
            neat_coev_free(l);
        }
    print_message("refused allocations: %u left the coevolution unchanged, %u broke it (of %zu requests)\n",
                  unchanged, broken, requests);
    assert_true(unchanged > requests / 2);
    neat_coev_buf_free(c, pre, pre_len);
    neat_coev_buf_free(c, post, post_len);
    neat_coev_free(c);
    assert_int_equal(k.live, 0);
    assert_int_equal(k.bad_size, 0);
}

/* creating, saving and loading refused memory: an error, nothing leaked */
static void test_alloc_failure_create_load(void **state)
{
    neat_coev_params cp = small_coev_params();
    neat_params p = coev_neat_params(8);
    counter k;
    neat_alloc a;
    neat_coev *c, *l;
    uint8_t *buf;
    size_t len, n, done = 0;
    int err;
    (void)state;
    memset(&k, 0, sizeof k);
    a.fn = counting_alloc;
    a.ud = &k;
    for (n = 1; !done; n++) {
        c = NULL;
        k.fail_at = k.calls + n;
        err = neat_coev_create(&c, &p, &cp, NULL, 2, &a);
        k.fail_at = 0;
        if (err == NEAT_OK) {
            done = 1;
            neat_coev_free(c);
        } else {
            assert_int_equal(err, NEAT_E_NOMEM);
            assert_null(c);
        }
        assert_int_equal(k.live, 0);
    }
    c = coev_new(8, &cp, 2, &a);
    steps(c, 3);
    save(c, &buf, &len);
    for (n = 1, done = 0; !done; n++) {
        l = NULL;
        k.fail_at = k.calls + n;
        err = neat_coev_load(&l, buf, len, &a, NULL);
        k.fail_at = 0;
        if (err == NEAT_OK) {
            done = 1;
            assert_save_is(l, buf, len);
            neat_coev_free(l);
        } else {
            assert_int_equal(err, NEAT_E_NOMEM);
            assert_null(l);
        }
    }
    for (n = 1, done = 0; !done; n++) {
        uint8_t *b = NULL;
        size_t bl = 0;
        k.fail_at = k.calls + n;
        err = neat_coev_save(c, &b, &bl);
        k.fail_at = 0;
        if (err == NEAT_OK) {
            done = 1;
            assert_int_equal(bl, len);
            assert_memory_equal(b, buf, len);
            neat_coev_buf_free(c, b, bl);
        } else {
            assert_int_equal(err, NEAT_E_NOMEM);
        }
    }
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(c);
    assert_int_equal(k.live, 0);
    assert_int_equal(k.bad_size, 0);
}

/* ---- 7. parameters ---- */
static void test_set_params(void **state)
{
    neat_coev_params cp = small_coev_params(), cp2;
    neat_params p = coev_neat_params(12), p2;
    neat_coev *c = coev_new(12, &cp, 17, NULL);
    coev_ctx x;
    uint8_t *pre;
    size_t len;
    uint32_t q;
    (void)state;
    ctx_init(&x, c);
    x.check = 1;
    step_ok(c, &x, NULL);
    step_ok(c, &x, NULL);

    /* a mutation rate and the number of hall-of-fame opponents: accepted, both populations */
    p2 = p;
    p2.weight_mut_prob = 0.5;
    cp2 = cp;
    cp2.hof_opponents = 3;
    assert_int_equal(neat_coev_set_params(c, &p2, &cp2), NEAT_OK);
    for (q = 0; q < 2; q++)
        assert_true(neat_pop_params(neat_coev_pop(c, q))->weight_mut_prob == 0.5);
    assert_int_equal(neat_coev_get_params(c)->hof_opponents, 3);
    save(c, &pre, &len);

    /* the population size: refused, nothing changes (not even the other fields) */
    p2.pop_size = 20;
    p2.weight_mut_prob = 0.3;
    cp2.hof_opponents = 5;
    assert_int_equal(neat_coev_set_params(c, &p2, &cp2), NEAT_E_PARAM);
    p2.pop_size = 12;
    p2.n_outputs = 3;
    assert_int_equal(neat_coev_set_params(c, &p2, &cp2), NEAT_E_PARAM);
    /* bad protocol parameters: refused */
    p2.n_outputs = 2;
    cp2.compare_configs = 0;
    assert_int_equal(neat_coev_set_params(c, &p2, &cp2), NEAT_E_PARAM);
    cp2.compare_configs = 4;
    cp2.species_opponents = 0;
    cp2.hof_opponents = 0;
    assert_int_equal(neat_coev_set_params(c, &p2, &cp2), NEAT_E_PARAM);
    assert_int_equal(neat_coev_set_params(NULL, &p2, &cp2), NEAT_E_ARG);
    for (q = 0; q < 2; q++) {
        assert_int_equal(neat_pop_size(neat_coev_pop(c, q)), 12);
        assert_true(neat_pop_params(neat_coev_pop(c, q))->weight_mut_prob == 0.5);
    }
    assert_int_equal(neat_coev_get_params(c)->hof_opponents, 3);
    assert_save_is(c, pre, len);
    neat_coev_buf_free(c, pre, len);

    /* the new protocol is played: 4 species + 3 hall-of-fame opponents */
    step_ok(c, &x, NULL);
    assert_int_equal(x.n_opp, 7);
    assert_int_equal(x.batch_games[0], 2u * 12u * 7u * 2u);
    ctx_free(&x);
    neat_coev_free(c);
}

/* fewer species opponents and comparison configurations on resumption: the checkpoint still loads */
static void test_set_params_then_checkpoint(void **state)
{
    static const uint16_t s0[][2] = {{5, 2}};
    static const uint16_t s1[][2] = {{5, 2}, {7, 1}};
    neat_coev_params cp = small_coev_params(), cp2;
    neat_params p = coev_neat_params(16);
    neat_coev *c = coev_new(16, &cp, 23, NULL), *l = NULL;
    coev_ctx x;
    uint8_t *buf;
    size_t len, off = 0;
    neat_dominant d;
    (void)state;
    ctx_init(&x, c);
    x.check = 1;
    x.script = s0;
    x.n_script = 1;
    step_ok(c, &x, NULL);
    x.script = s1;
    x.n_script = 2;
    step_ok(c, &x, NULL);
    assert_int_equal(neat_coev_dominant_count(c), 2);
    x.script = NULL;
    step_ok(c, &x, NULL);
    /* one species champion kept (there were more) */
    assert_true(x.n_champ[0] > 1 || x.n_champ[1] > 1);
    cp2 = cp;
    cp2.species_opponents = 1;
    assert_int_equal(neat_coev_set_params(c, &p, &cp2), NEAT_OK);
    save(c, &buf, &len);
    assert_int_equal(neat_coev_load(&l, buf, len, NULL, &off), NEAT_OK);
    neat_coev_free(l);
    neat_coev_buf_free(c, buf, len);
    /* 4 games a comparison (dominant 2 won 7 of 8) */
    cp2.compare_configs = 2;
    assert_int_equal(neat_coev_set_params(c, &p, &cp2), NEAT_OK);
    save(c, &buf, &len);
    l = NULL;
    assert_int_equal(neat_coev_load(&l, buf, len, NULL, &off), NEAT_OK);
    assert_int_equal(neat_coev_dominant(l, 1, &d), NEAT_OK);
    assert_int_equal(d.wins[0], 7);
    assert_int_equal(d.losses[0], 1);
    step_ok(c, &x, NULL);
    assert_int_equal(x.n_opp, 1 + cp2.hof_opponents);
    {
        coev_ctx xl;
        ctx_init(&xl, l);
        step_ok(l, &xl, NULL);
        assert_int_equal(xl.n_opp, 1 + cp2.hof_opponents);
        ctx_free(&xl);
    }
    assert_saves_equal(c, l);
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(l);
    ctx_free(&x);
    neat_coev_free(c);
}

static uint32_t max_nodes_of(const neat_genome *g, uint32_t m)
{
    return g != NULL && g->n_nodes > m ? g->n_nodes : m;
}

/* a smaller max_nodes that fits the populations but not a hall-of-fame
 * genome: refused (or the checkpoint would not load), else it loads */
static void test_set_params_max_nodes(void **state)
{
    neat_coev_params cp = small_coev_params();
    uint32_t seed, found = 0;
    (void)state;
    for (seed = 1; seed < 100 && !found; seed++) {
        neat_params p = coev_neat_params(8);
        neat_coev *c = NULL, *l = NULL;
        uint32_t g;
        p.add_node_prob = 0.1;
        p.n_inputs = 1;
        p.n_outputs = 1;
        assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, seed, NULL), NEAT_OK);
        for (g = 0; g < 12 && !found; g++) {
            uint32_t m_pop = 0, m_kept = 0, q, i;
            steps(c, 1);
            for (q = 0; q < 2; q++) {
                for (i = 0; i < 8; i++)
                    m_pop = max_nodes_of(neat_pop_genome(neat_coev_pop(c, q), i), m_pop);
                for (i = 0; i < neat_coev_hof_count(c, q); i++)
                    m_kept = max_nodes_of(neat_coev_hof(c, q, i), m_kept);
            }
            if (m_kept > m_pop) {
                neat_params p2 = p;
                uint8_t *buf;
                size_t len;
                found = 1;
                p2.max_nodes = m_pop;
                save(c, &buf, &len);
                if (neat_coev_set_params(c, &p2, &cp) == NEAT_OK) {
                    neat_coev_buf_free(c, buf, len);
                    save(c, &buf, &len);
                    assert_int_equal(neat_coev_load(&l, buf, len, NULL, NULL), NEAT_OK);
                    neat_coev_free(l);
                } else {
                    assert_save_is(c, buf, len); /* refused: nothing changed */
                    assert_int_equal(neat_pop_params(neat_coev_pop(c, 0))->max_nodes, p.max_nodes);
                    assert_int_equal(neat_pop_params(neat_coev_pop(c, 1))->max_nodes, p.max_nodes);
                }
                neat_coev_buf_free(c, buf, len);
            }
        }
        neat_coev_free(c);
    }
    assert_true(found);
}

static void test_create_and_params_check(void **state)
{
    neat_coev_params cp = neat_coev_params_default();
    neat_params p = coev_neat_params(8);
    const char *field = NULL;
    neat_coev *c = (neat_coev *)&field;
    (void)state;
    assert_int_equal(cp.species_opponents, 4);
    assert_int_equal(cp.hof_opponents, 8);
    assert_int_equal(cp.first_opponents, 12);
    assert_int_equal(cp.compare_configs, 144);
    assert_int_equal(neat_coev_params_check(&cp, &field), NEAT_OK);
    assert_null(field);
    cp.first_opponents = 0;
    assert_int_equal(neat_coev_params_check(&cp, &field), NEAT_E_PARAM);
    assert_string_equal(field, "first_opponents");
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 1, NULL), NEAT_E_PARAM);
    assert_null(c);
    cp = neat_coev_params_default();
    cp.species_opponents = 0;
    cp.hof_opponents = 0;
    assert_int_equal(neat_coev_params_check(&cp, &field), NEAT_E_PARAM);
    cp = neat_coev_params_default();
    cp.compare_configs = 30001;
    assert_int_equal(neat_coev_params_check(&cp, &field), NEAT_E_PARAM);
    assert_string_equal(field, "compare_configs");
    cp = neat_coev_params_default();
    cp.species_opponents = 65; /* more than a step can take */
    assert_int_equal(neat_coev_params_check(&cp, &field), NEAT_E_PARAM);
    assert_string_equal(field, "species_opponents");
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 1, NULL), NEAT_E_PARAM);
    cp = neat_coev_params_default();
    p.pop_size = 1;
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 1, NULL), NEAT_E_PARAM);
    assert_int_equal(neat_coev_create(NULL, &p, &cp, NULL, 1, NULL), NEAT_E_ARG);
    /* only hall-of-fame opponents, or only species champions: both work */
    p.pop_size = 8;
    cp.species_opponents = 0;
    c = coev_new(8, &cp, 1, NULL);
    steps(c, 3);
    neat_coev_free(c);
    cp.species_opponents = 3;
    cp.hof_opponents = 0;
    cp.compare_configs = 2;
    c = coev_new(8, &cp, 1, NULL);
    steps(c, 3);
    neat_coev_free(c);
}

/* ---- checkpoint version 3: the game tag; version 2 still loads ---- */

static uint32_t tc_rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

static void tc_wr32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}

static void tc_seal(uint8_t *buf, size_t len)
{
    tc_wr32(buf + len - 4, nrt_crc32(0, buf, len - 4));
}

/* A version-3 coevolution checkpoint (sync, empty tags) as version 2 wrote
 * it: no tag after the protocol's parameters (offset 44), and each
 * embedded population checkpoint without net_step and its tag (8 bytes at
 * its offset 240), at version 2. Returns the new length. */
static size_t tc_to_v2(const uint8_t *b, size_t len, uint8_t *out)
{
    size_t o = 48, n = 44;
    uint32_t i;
    memcpy(out, b, 44);
    tc_wr32(out + 8, 2);
    assert_int_equal(tc_rd32(b + 44), 0);
    for (i = 0; i < 2; i++) {
        uint32_t pl = tc_rd32(b + o);
        const uint8_t *p = b + o + 4;
        assert_int_equal(tc_rd32(p + 8), 3);
        assert_int_equal(tc_rd32(p + 240), NEAT_STEP_SYNC);
        assert_int_equal(tc_rd32(p + 244), 0);
        tc_wr32(out + n, pl - 8);
        memcpy(out + n + 4, p, 240);
        memcpy(out + n + 4 + 240, p + 248, pl - 248);
        tc_wr32(out + n + 4 + 8, 2);
        tc_seal(out + n + 4, pl - 8);
        n += 4 + pl - 8;
        o += 4 + pl;
    }
    memcpy(out + n, b + o, len - o);
    n += len - o;
    tc_seal(out, n);
    return n;
}

/* A run checkpointed before the game tag (version 2) resumes: empty tag,
 * sync networks, and saved again the version-3 bytes of the same state. */
static void test_checkpoint_version2_loads(void **state)
{
    uint8_t *buf, *v2;
    size_t len, l2, off = 0, tl = 7;
    neat_coev *c = tiny_coev(5, &buf, &len), *l = NULL;
    (void)state;
    v2 = (uint8_t *)malloc(len);
    assert_non_null(v2);
    l2 = tc_to_v2(buf, len, v2);
    assert_int_equal(l2, len - 20);
    assert_int_equal(neat_coev_load(&l, v2, l2, NULL, &off), NEAT_OK);
    assert_null(neat_coev_game(l, &tl));
    assert_int_equal(tl, 0);
    assert_save_is(l, buf, len);
    neat_coev_free(l);
    free(v2);
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(c);
}

/* The tag: copied in, NEAT_E_ARG beyond NEAT_GAME_MAX, in the checkpoint
 * byte for byte and through further generations; its length never
 * trusted: every truncation and a resealed length beyond the bytes left
 * are refused. */
static void test_checkpoint_game_tag(void **state)
{
    static uint8_t tag[NEAT_GAME_MAX + 1];
    uint8_t *buf, *b2, *bad;
    size_t len, l2, i, tl = 0, off;
    neat_coev *c = tiny_coev(6, &buf, &len), *l = NULL;
    const uint8_t *got;
    (void)state;
    neat_coev_buf_free(c, buf, len);
    for (i = 0; i < sizeof tag; i++)
        tag[i] = (uint8_t)(255u - i % 251u);
    assert_null(neat_coev_game(c, &tl));
    assert_int_equal(neat_coev_set_game(c, tag, NEAT_GAME_MAX + 1), NEAT_E_ARG);
    assert_int_equal(neat_coev_set_game(c, NULL, 1), NEAT_E_ARG);
    assert_int_equal(neat_coev_set_game(NULL, tag, 1), NEAT_E_ARG);
    assert_int_equal(neat_coev_set_game(c, tag, NEAT_GAME_MAX), NEAT_OK);
    tag[5] ^= 1;
    save(c, &buf, &len);
    assert_int_equal(tc_rd32(buf + 44), NEAT_GAME_MAX);
    assert_int_equal(neat_coev_load(&l, buf, len, NULL, &off), NEAT_OK);
    got = neat_coev_game(l, &tl);
    assert_int_equal(tl, NEAT_GAME_MAX);
    assert_int_equal(got[5], (uint8_t)(tag[5] ^ 1));
    assert_memory_equal(got, neat_coev_game(c, NULL), NEAT_GAME_MAX);
    assert_save_is(l, buf, len);
    steps(l, 1); /* a generation keeps it */
    save(l, &b2, &l2);
    assert_int_equal(tc_rd32(b2 + 44), NEAT_GAME_MAX);
    assert_memory_equal(b2 + 48, neat_coev_game(c, NULL), NEAT_GAME_MAX);
    neat_coev_buf_free(l, b2, l2);
    neat_coev_free(l);
    for (i = 0; i < len; i += 1 + (i > 60 && i < 44 + NEAT_GAME_MAX ? 97 : 0)) {
        bad = (uint8_t *)malloc(i + 1);
        assert_non_null(bad);
        memcpy(bad, buf, i);
        l = (neat_coev *)&l;
        assert_true(load_error_ok(neat_coev_load(&l, bad, i, NULL, &off)));
        assert_null(l);
        free(bad);
    }
    bad = (uint8_t *)malloc(len);
    assert_non_null(bad);
    memcpy(bad, buf, len);
    tc_wr32(bad + 44, NEAT_GAME_MAX + 1);
    tc_seal(bad, len);
    assert_int_equal(neat_coev_load(&l, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 44);
    tc_wr32(bad + 44, 0xFFFFFFF0u); /* more than the bytes left: refused before any allocation */
    tc_seal(bad, len);
    assert_int_equal(neat_coev_load(&l, bad, len, NULL, &off), NEAT_E_FORMAT);
    assert_int_equal(off, 44);
    free(bad);
    neat_coev_buf_free(c, buf, len);
    neat_coev_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_protocol_counts),
        cmocka_unit_test(test_fitness_is_wins),
        cmocka_unit_test(test_dominance),
        cmocka_unit_test(test_determinism),
        cmocka_unit_test(test_evolution_meaningful),
        cmocka_unit_test(test_checkpoint_resume),
        cmocka_unit_test(test_checkpoint_corruption),
        cmocka_unit_test(test_checkpoint_resealed),
        cmocka_unit_test(test_checkpoint_version2_loads),
        cmocka_unit_test(test_checkpoint_game_tag),
        cmocka_unit_test(test_play_error),
        cmocka_unit_test(test_alloc_failure_in_step),
        cmocka_unit_test(test_alloc_failure_create_load),
        cmocka_unit_test(test_set_params),
        cmocka_unit_test(test_set_params_then_checkpoint),
        cmocka_unit_test(test_set_params_max_nodes),
        cmocka_unit_test(test_create_and_params_check),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
