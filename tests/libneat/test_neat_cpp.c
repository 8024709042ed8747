/* test_neat_cpp.c - NEAT C++ 1.2.1's rules: each switch changes what it should, and only that; the profile sets them all. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat_coev.h"
#include "neat_internal.h"

/* ---- fixtures ---- */

/* bias 0, inputs 1..2, output 3, hidden 4.. as given; genes innov = index + base */
static void build(neat_genome *g, uint32_t n_hidden, const uint32_t (*links)[2], uint32_t n_links, double w,
                  uint32_t innov_base)
{
    uint32_t i;
    neat_genome_init(g);
    assert_int_equal(neat_genome_add_node(g, 0, NEAT_NODE_BIAS, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 1, NEAT_NODE_INPUT, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 2, NEAT_NODE_INPUT, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_node(g, 3, NEAT_NODE_OUTPUT, NULL), NEAT_OK);
    for (i = 0; i < n_hidden; i++)
        assert_int_equal(neat_genome_add_node(g, 4 + i, NEAT_NODE_HIDDEN, NULL), NEAT_OK);
    for (i = 0; i < n_links; i++)
        assert_int_equal(neat_genome_add_conn(g, links[i][0], links[i][1], w, innov_base + i, 1, NULL), NEAT_OK);
}

static neat_params small_params(void)
{
    neat_params p = neat_params_default();
    p.n_inputs = 2;
    p.n_outputs = 1;
    return p;
}

/* the same genes, field by field (a struct's padding is not its value) */
static int conns_equal(const neat_conn *a, const neat_conn *b, uint32_t n)
{
    uint32_t k;
    for (k = 0; k < n; k++)
        if (a[k].in != b[k].in || a[k].out != b[k].out || a[k].weight != b[k].weight || a[k].innov != b[k].innov ||
            a[k].enabled != b[k].enabled)
            return 0;
    return 1;
}

static int has_innov(const neat_genome *g, uint32_t innov)
{
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].innov == innov)
            return 1;
    return 0;
}

/* ---- the profile ---- */

static void test_profile_sets_every_switch(void **state)
{
    neat_params d = neat_params_default(), c = neat_params_neat_cpp(), q = d;
    const char *field = NULL;
    (void)state;
    assert_int_equal(c.profile, NEAT_PROFILE_NEAT_CPP);
    assert_int_equal(c.equal_fitness_rule, NEAT_EQUAL_SMALLER);
    assert_int_equal(c.reenable_rule, NEAT_REENABLE_CPP);
    assert_int_equal(c.add_conn_rule, NEAT_ADD_CONN_CPP);
    assert_true(c.recur_only_prob == 0.2);
    assert_int_equal(c.species_rep, NEAT_REP_CHAMPION);
    assert_int_equal(c.weight_mut_rule, NEAT_WEIGHTS_CPP);
    assert_int_equal(c.elitism_rule, NEAT_ELITE_BY_OFFSPRING);
    assert_int_equal(c.interspecies_rule, NEAT_INTER_CPP);
    assert_int_equal(c.identical_rule, NEAT_IDENTICAL_EQUAL);
    assert_int_equal(c.offspring_rounding, NEAT_ROUND_SKIM);
    assert_int_equal(c.speciate_rule, NEAT_SPECIATE_INTERLEAVED);
    assert_int_equal(c.stagnation_rule, NEAT_STAGNATION_CPP);
    assert_int_equal(c.pop_stagnation_rule, NEAT_POPSTAG_DELTA);
    assert_int_equal(c.dropoff_age, 1000);
    assert_int_equal(c.pop_stagnation, 0);
    assert_int_equal(c.cull_every, 30);
    assert_int_equal(c.cull_age, 20);
    /* Appendix A's values are kept */
    assert_true(c.add_node_prob == d.add_node_prob && c.weight_mut_prob == d.weight_mut_prob);
    assert_true(c.c3 == d.c3 && c.target_species == d.target_species && c.pop_size == d.pop_size);
    assert_int_equal(neat_params_check(&c, &field), NEAT_OK);
    /* and the default profile restores the defaults' switches */
    q.pop_size = 77;
    assert_int_equal(neat_params_set_profile(&q, NEAT_PROFILE_NEAT_CPP), NEAT_OK);
    assert_int_equal(neat_params_set_profile(&q, NEAT_PROFILE_DEFAULT), NEAT_OK);
    q.pop_size = d.pop_size;
    assert_true(q.profile == d.profile && q.equal_fitness_rule == d.equal_fitness_rule &&
                q.reenable_rule == d.reenable_rule && q.add_conn_rule == d.add_conn_rule &&
                q.recur_only_prob == d.recur_only_prob && q.species_rep == d.species_rep &&
                q.weight_mut_rule == d.weight_mut_rule && q.elitism_rule == d.elitism_rule &&
                q.interspecies_rule == d.interspecies_rule && q.identical_rule == d.identical_rule &&
                q.offspring_rounding == d.offspring_rounding && q.speciate_rule == d.speciate_rule &&
                q.cull_every == d.cull_every && q.cull_age == d.cull_age &&
                q.pop_stagnation_rule == d.pop_stagnation_rule);
    assert_int_equal(q.stagnation_rule, d.stagnation_rule);
    assert_int_equal(q.dropoff_age, d.dropoff_age);
    assert_int_equal(q.pop_stagnation, d.pop_stagnation);
    assert_int_equal(neat_params_set_profile(&q, 2), NEAT_E_ARG);
    q.speciate_rule = 2;
    assert_int_equal(neat_params_check(&q, &field), NEAT_E_PARAM);
    assert_string_equal(field, "speciate_rule");
}

/* ---- row 1: unmatched genes at equal fitness ---- */

static void test_equal_fitness_smaller_parent_is_fitter(void **state)
{
    /* mom: genes 0-2 and 5 (unmatched); dad: genes 0-2 and 6, 7 (unmatched) */
    static const uint32_t base[3][2] = {{0, 3}, {1, 3}, {2, 3}};
    neat_genome mom, dad, child;
    neat_params p = small_params();
    neat_rng rng;
    int t;
    (void)state;
    build(&mom, 1, base, 3, 0.5, 0);
    assert_int_equal(neat_genome_add_conn(&mom, 1, 4, 0.1, 5, 1, NULL), NEAT_OK);
    build(&dad, 1, base, 3, -0.5, 0);
    assert_int_equal(neat_genome_add_conn(&dad, 2, 4, 0.2, 6, 1, NULL), NEAT_OK);
    assert_int_equal(neat_genome_add_conn(&dad, 4, 3, 0.3, 7, 1, NULL), NEAT_OK);
    mom.fitness = dad.fitness = 3.0;
    neat_genome_init(&child);
    neat_rng_seed(&rng, 5);
    p.equal_fitness_rule = NEAT_EQUAL_SMALLER;
    for (t = 0; t < 50; t++) {
        /* mom has fewer genes: only hers, whoever is first */
        assert_int_equal(neat_crossover(&child, &mom, &dad, t % 2, &p, &rng, NULL), NEAT_OK);
        assert_true(has_innov(&child, 5) && !has_innov(&child, 6) && !has_innov(&child, 7));
        assert_int_equal(neat_crossover(&child, &dad, &mom, t % 2, &p, &rng, NULL), NEAT_OK);
        assert_true(has_innov(&child, 5) && !has_innov(&child, 6) && !has_innov(&child, 7));
        assert_int_equal(child.n_conns, 4);
    }
    /* as many genes: the second parent's */
    assert_int_equal(neat_genome_add_conn(&mom, 2, 4, 0.2, 8, 1, NULL), NEAT_OK);
    mom.conns[mom.n_conns - 1].innov = 8;
    assert_int_equal(mom.n_conns, 5);
    for (t = 0; t < 20; t++) {
        assert_int_equal(neat_crossover(&child, &mom, &dad, 0, &p, &rng, NULL), NEAT_OK);
        assert_true(!has_innov(&child, 5) && has_innov(&child, 6) && has_innov(&child, 7) && !has_innov(&child, 8));
    }
    /* the default: unmatched genes of both parents, each with excess_equal_prob */
    {
        int saw_mom = 0, saw_dad = 0;
        p.equal_fitness_rule = NEAT_EQUAL_RANDOM;
        for (t = 0; t < 50; t++) {
            assert_int_equal(neat_crossover(&child, &mom, &dad, 0, &p, &rng, NULL), NEAT_OK);
            saw_mom |= has_innov(&child, 5);
            saw_dad |= has_innov(&child, 6);
        }
        assert_true(saw_mom && saw_dad);
    }
    /* unequal fitness: the fitter parent's alone under either rule */
    p.equal_fitness_rule = NEAT_EQUAL_SMALLER;
    dad.fitness = 4.0;
    assert_int_equal(neat_crossover(&child, &mom, &dad, 0, &p, &rng, NULL), NEAT_OK);
    assert_true(!has_innov(&child, 5) && has_innov(&child, 6) && has_innov(&child, 7));
    neat_genome_free(&mom, NULL);
    neat_genome_free(&dad, NULL);
    neat_genome_free(&child, NULL);
}

/* ---- row 4: re-enabling ---- */

/* the share of crossovers (multipoint, or averaging) whose child has the
 * matching gene 0 enabled, mom's gene 0 enabled as given, dad's disabled */
static double enabled_share(int rule, int avg, int mom_enabled)
{
    static const uint32_t base[2][2] = {{1, 3}, {2, 3}};
    neat_genome mom, dad, child;
    neat_params p = small_params();
    neat_rng rng;
    int t, on = 0, n = 20000;
    build(&mom, 0, base, 2, 0.5, 0);
    build(&dad, 0, base, 2, -0.5, 0);
    mom.conns[0].enabled = (uint8_t)mom_enabled;
    dad.conns[0].enabled = 0;
    mom.fitness = 2.0;
    dad.fitness = 1.0;
    p.reenable_rule = rule;
    neat_genome_init(&child);
    neat_rng_seed(&rng, 9);
    for (t = 0; t < n; t++) {
        assert_int_equal(neat_crossover(&child, &mom, &dad, avg, &p, &rng, NULL), NEAT_OK);
        on += child.conns[0].enabled;
        assert_int_equal(child.conns[1].enabled, 1); /* a gene enabled in both stays so */
    }
    neat_genome_free(&mom, NULL);
    neat_genome_free(&dad, NULL);
    neat_genome_free(&child, NULL);
    return (double)on / n;
}

static void test_reenable_cpp(void **state)
{
    (void)state;
    /* the release: multipoint keeps the chosen gene's flag unless 75 % disables it */
    assert_true(enabled_share(NEAT_REENABLE_CPP, 0, 0) == 0.0);
    assert_true(fabs(enabled_share(NEAT_REENABLE_CPP, 0, 1) - 0.125) < 0.01);
    /* averaging: enabled unless 75 % disables it, as the paper */
    assert_true(fabs(enabled_share(NEAT_REENABLE_CPP, 1, 0) - 0.25) < 0.01);
    assert_true(fabs(enabled_share(NEAT_REENABLE_CPP, 1, 1) - 0.25) < 0.01);
    /* the paper's rule: 25 % in every case */
    assert_true(fabs(enabled_share(NEAT_REENABLE_PAPER, 0, 0) - 0.25) < 0.01);
    assert_true(fabs(enabled_share(NEAT_REENABLE_PAPER, 0, 1) - 0.25) < 0.01);
}

/* ---- row 7: weight mutation ---- */

/* over many mutations of a genome of n genes all at 5.0, with power 0.5:
 * the share of genes at index i perturbed (near 5), replaced (within 0.5
 * of 0) and untouched */
static void weight_shares(int rule, uint32_t n, uint32_t i, double *perturbed, double *replaced, double *untouched)
{
    neat_genome g;
    neat_params p = small_params();
    neat_rng rng;
    uint32_t t, k, pe = 0, re = 0, un = 0, trials = 20000;
    uint32_t (*links)[2] = malloc(n * sizeof *links);
    assert_non_null(links);
    for (k = 0; k < n; k++) {
        links[k][0] = 4 + k;
        links[k][1] = 3;
    }
    build(&g, n, (const uint32_t(*)[2])links, n, 5.0, 0);
    free(links);
    p.weight_mut_rule = rule;
    p.weight_perturb_power = 0.5;
    p.weight_replace_range = 0.5;
    neat_rng_seed(&rng, 11);
    for (t = 0; t < trials; t++) {
        double w;
        for (k = 0; k < n; k++)
            g.conns[k].weight = 5.0;
        assert_int_equal(neat_mutate_weights(&g, &p, &rng), NEAT_OK);
        w = g.conns[i].weight;
        if (w == 5.0)
            un++;
        else if (fabs(w) <= 0.5)
            re++;
        else if (fabs(w - 5.0) <= 0.5)
            pe++;
        else
            fail_msg("weight %g", w);
    }
    *perturbed = (double)pe / trials;
    *replaced = (double)re / trials;
    *untouched = (double)un / trials;
    neat_genome_free(&g, NULL);
}

static void test_weights_cpp_head_and_tail(void **state)
{
    double pe, re, un;
    (void)state;
    /* 20 genes: gene 3 is in the head, gene 19 in the newest 20 % */
    weight_shares(NEAT_WEIGHTS_CPP, 20, 3, &pe, &re, &un);
    assert_true(fabs(pe - 0.85) < 0.015 && fabs(re - 0.10) < 0.015 && fabs(un - 0.05) < 0.01);
    weight_shares(NEAT_WEIGHTS_CPP, 20, 19, &pe, &re, &un);
    assert_true(fabs(pe - 0.60) < 0.015 && fabs(re - 0.20) < 0.015 && fabs(un - 0.20) < 0.015);
    /* fewer than 10 genes: no tail */
    weight_shares(NEAT_WEIGHTS_CPP, 5, 4, &pe, &re, &un);
    assert_true(fabs(pe - 0.85) < 0.015 && fabs(re - 0.10) < 0.015);
    /* the default: 90 % perturbed, 10 % replaced, whatever the position */
    weight_shares(NEAT_WEIGHTS_UNIFORM, 20, 19, &pe, &re, &un);
    assert_true(fabs(pe - 0.9) < 0.015 && fabs(re - 0.1) < 0.015 && un == 0.0);
}

/* ---- row 5: add connection ---- */

static void test_add_conn_cpp(void **state)
{
    /* bias, 2 inputs, output 3, hidden 4 and 5 in a chain 1 -> 4 -> 5 -> 3 */
    static const uint32_t links[3][2] = {{1, 4}, {4, 5}, {5, 3}};
    neat_params p = small_params();
    neat_rng rng;
    neat_innovs iv;
    uint32_t t, loops = 0, added = 0;
    (void)state;
    memset(&iv, 0, sizeof iv);
    iv.next_innov = 100;
    iv.next_node = 100;
    neat_rng_seed(&rng, 13);
    p.add_conn_rule = NEAT_ADD_CONN_CPP;
    for (t = 0; t < 3000; t++) {
        neat_genome g;
        uint32_t stack[16];
        uint8_t seen[16];
        const neat_conn *c;
        int loop;
        build(&g, 2, links, 3, 0.5, 0);
        p.recur_only_prob = t < 1000 ? 0.0 : (t < 2000 ? 1.0 : 0.5);
        p.allow_recurrent = t < 500 ? 0 : 1;
        iv.n = 0;
        assert_int_equal(neat_mutate_add_conn(&g, &p, &rng, &iv, NULL), NEAT_OK);
        if (g.n_conns == 4) {
            added++;
            c = &g.conns[3];
            /* never into the bias or an input */
            assert_true(c->out == 3 || c->out >= 4);
            (void)stack;
            (void)seen;
            loop = c->in == c->out;
            if (!loop) {
                /* does the new link's target reach its source along the others? */
                uint32_t a = c->out, b = c->in, steps;
                for (steps = 0; steps < 4 && a != b; steps++) {
                    uint32_t k, next = UINT32_MAX;
                    for (k = 0; k < 3; k++)
                        if (g.conns[k].in == a)
                            next = g.conns[k].out;
                    if (next == UINT32_MAX)
                        break;
                    a = next;
                }
                loop = a == b;
            }
            if (t < 1000)
                assert_false(loop); /* recur_only_prob 0 (or no recurrence): only loop-free links */
            else if (t < 2000)
                assert_true(loop); /* recur_only_prob 1: only loop-closing ones */
            else
                loops += (uint32_t)loop;
        }
        neat_genome_free(&g, NULL);
    }
    assert_true(added > 2000);
    assert_true(loops > 100 && loops < 900); /* recur_only_prob 0.5: some of each */
    neat_mem_free(NULL, iv.list, (size_t)iv.cap * sizeof(neat_innov));
}

static void test_add_conn_cpp_reuses_first_weight(void **state)
{
    /* the same new link twice in a generation: one innovation; the release's
     * rule gives it the first's weight, the default draws another */
    static const uint32_t links[2][2] = {{1, 3}, {2, 3}};
    neat_params p = small_params();
    neat_rng rng;
    int rule, same[2] = {0, 0}, pairs[2] = {0, 0};
    uint32_t t;
    (void)state;
    p.allow_recurrent = 0;
    for (rule = 0; rule < 2; rule++) {
        p.add_conn_rule = rule;
        neat_rng_seed(&rng, 17);
        for (t = 0; t < 300; t++) {
            neat_innovs iv;
            neat_genome a, b;
            memset(&iv, 0, sizeof iv);
            iv.next_innov = 10;
            /* only 0 -> 3 is open: bias to output */
            build(&a, 0, links, 2, 0.5, 0);
            build(&b, 0, links, 2, 0.5, 0);
            assert_int_equal(neat_mutate_add_conn(&a, &p, &rng, &iv, NULL), NEAT_OK);
            assert_int_equal(neat_mutate_add_conn(&b, &p, &rng, &iv, NULL), NEAT_OK);
            if (a.n_conns == 3 && b.n_conns == 3) {
                assert_int_equal(a.conns[0].innov, b.conns[0].innov); /* sorted: innovation 10 first? no: by number */
                pairs[rule]++;
                same[rule] += a.conns[2].weight == b.conns[2].weight;
            }
            neat_genome_free(&a, NULL);
            neat_genome_free(&b, NULL);
            neat_mem_free(NULL, iv.list, (size_t)iv.cap * sizeof(neat_innov));
        }
    }
    assert_true(pairs[0] > 50 && pairs[1] > 50);
    assert_int_equal(same[NEAT_ADD_CONN_CPP], pairs[NEAT_ADD_CONN_CPP]);
    assert_int_equal(same[NEAT_ADD_CONN_ANY], 0);
}

/* ---- a population's epoch under one switch ---- */

static double toy_fitness(const neat_genome *g)
{
    double s = 0.0;
    uint32_t i;
    for (i = 0; i < g->n_conns; i++)
        if (g->conns[i].enabled)
            s += g->conns[i].weight * (double)(1 + i % 3);
    return 1.0 / (1.0 + fabs(s - 1.5)) + 0.01 * neat_genome_hidden_count(g);
}

static neat_pop *run_pop(const neat_params *p, uint32_t gens, uint64_t seed)
{
    neat_pop *pop = NULL;
    uint32_t g, i;
    assert_int_equal(neat_pop_create(&pop, p, NULL, seed, NULL), NEAT_OK);
    for (g = 0; g < gens; g++) {
        for (i = 0; i < neat_pop_size(pop); i++)
            assert_int_equal(neat_pop_set_fitness(pop, i, toy_fitness(neat_pop_genome(pop, i))), NEAT_OK);
        assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    }
    return pop;
}

/* the same genomes, species count and PRNG state (the parameters differ, so the checkpoints' bytes do) */
static int same_state(const neat_pop *a, const neat_pop *b)
{
    uint32_t i, k;
    int same = a->n_species == b->n_species && memcmp(&a->rng, &b->rng, sizeof a->rng) == 0;
    for (i = 0; i < a->p.pop_size && same; i++) {
        const neat_genome *x = &a->genomes[i], *y = &b->genomes[i];
        same = x->n_nodes == y->n_nodes && x->n_conns == y->n_conns;
        for (k = 0; same && k < x->n_nodes; k++) /* field by field: a struct's padding is not its value */
            same = x->nodes[k].id == y->nodes[k].id && x->nodes[k].type == y->nodes[k].type;
        for (k = 0; same && k < x->n_conns; k++)
            same = x->conns[k].in == y->conns[k].in && x->conns[k].out == y->conns[k].out &&
                   x->conns[k].weight == y->conns[k].weight && x->conns[k].innov == y->conns[k].innov &&
                   x->conns[k].enabled == y->conns[k].enabled;
    }
    return same;
}

static neat_params pop_params(void)
{
    neat_params p = small_params();
    p.pop_size = 60;
    p.add_node_prob = 0.05;
    p.add_conn_prob = 0.2;
    return p;
}

/* A switch that can only act in a situation the run never meets leaves the
 * run as it was, byte for byte: the switch changes only what it should. */
static void test_switches_change_only_their_case(void **state)
{
    neat_params d = pop_params(), p;
    neat_pop *a, *b;
    (void)state;
    /* no structural mutation: no disabled gene, no unmatched gene, no new link */
    d.add_node_prob = 0.0;
    d.add_conn_prob = 0.0;
    a = run_pop(&d, 8, 3);
    p = d;
    p.reenable_rule = NEAT_REENABLE_CPP;
    p.equal_fitness_rule = NEAT_EQUAL_SMALLER;
    p.add_conn_rule = NEAT_ADD_CONN_CPP;
    p.recur_only_prob = 0.5;
    b = run_pop(&p, 8, 3);
    assert_true(same_state(a, b));
    neat_pop_free(b);
    /* and a switch that does act changes the run */
    p = d;
    p.species_rep = NEAT_REP_CHAMPION;
    b = run_pop(&p, 8, 3);
    assert_false(same_state(a, b));
    neat_pop_free(b);
    /* no weight mutation at all: the weight rule never runs */
    d = pop_params();
    d.weight_mut_prob = 0.0;
    neat_pop_free(a);
    a = run_pop(&d, 8, 4);
    p = d;
    p.weight_mut_rule = NEAT_WEIGHTS_CPP;
    b = run_pop(&p, 8, 4);
    assert_true(same_state(a, b));
    neat_pop_free(b);
    neat_pop_free(a);
}

static void test_species_rep_is_champion(void **state)
{
    neat_params p = pop_params();
    neat_pop *pop;
    uint32_t i, k, checked = 0;
    neat_genome champs[64];
    uint32_t ids[64], n = 0;
    (void)state;
    p.species_rep = NEAT_REP_CHAMPION;
    pop = run_pop(&p, 4, 7);
    for (i = 0; i < neat_pop_size(pop); i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, toy_fitness(neat_pop_genome(pop, i))), NEAT_OK);
    /* each species' best (lowest index on a tie), before the epoch */
    for (k = 0; k < pop->n_species && n < 64; k++) {
        const neat_species *s = &pop->species[k];
        uint32_t best = s->members[0], m;
        for (m = 1; m < s->n_members; m++)
            if (pop->genomes[s->members[m]].fitness > pop->genomes[best].fitness)
                best = s->members[m];
        neat_genome_init(&champs[n]);
        assert_int_equal(neat_genome_copy(&champs[n], &pop->genomes[best], NULL), NEAT_OK);
        ids[n++] = s->id;
    }
    assert_int_equal(neat_pop_epoch(pop), NEAT_OK);
    for (k = 0; k < pop->n_species; k++)
        for (i = 0; i < n; i++)
            if (pop->species[k].id == ids[i]) {
                const neat_genome *r = &pop->species[k].rep;
                assert_int_equal(r->n_conns, champs[i].n_conns);
                assert_true(conns_equal(r->conns, champs[i].conns, r->n_conns));
                checked++;
            }
    assert_true(checked > 0);
    for (i = 0; i < n; i++)
        neat_genome_free(&champs[i], NULL);
    neat_pop_free(pop);
}

/* ---- rows 3, 8, 12 and delta coding: apportionment on a laid-out population ---- */

static neat_pop *make_pop(uint32_t n, const neat_params *base)
{
    neat_params p = *base;
    neat_pop *pop = NULL;
    p.pop_size = n;
    p.n_inputs = 1;
    p.n_outputs = 1;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 1, NULL), NEAT_OK);
    return pop;
}

static void set_layout(neat_pop *pop, const uint32_t *sizes, uint32_t n_species)
{
    uint32_t k, i, idx = 0;
    for (k = 0; k < pop->n_species; k++)
        neat_species_free(&pop->species[k], &pop->a);
    pop->n_species = 0;
    assert_int_equal(neat_mem_reserve(&pop->a, (void **)&pop->species, &pop->cap_species, n_species,
                                      sizeof(neat_species)),
                     NEAT_OK);
    for (k = 0; k < n_species; k++) {
        neat_species *s = &pop->species[k];
        memset(s, 0, sizeof *s);
        s->id = 100 + k;
        assert_int_equal(neat_mem_reserve(&pop->a, (void **)&s->members, &s->cap_members, sizes[k], sizeof(uint32_t)),
                         NEAT_OK);
        for (i = 0; i < sizes[k]; i++) {
            pop->genomes[idx].species = s->id;
            s->members[s->n_members++] = idx++;
        }
        pop->n_species++;
    }
    assert_int_equal(idx, pop->p.pop_size);
}

static void set_fitness_all(neat_pop *pop, const double *f)
{
    uint32_t i;
    for (i = 0; i < pop->p.pop_size; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, f[i]), NEAT_OK);
}

static void test_skim_rounding(void **state)
{
    /* 10 genomes in 3 species of 3, 3, 4; shares by hand, as the release's
     * count_offspring: mean adjusted fitness 0.25; A's genomes are due 1.2
     * each: 1 + 1 + 1 with fractions 0.2 0.4 0.6 carried, none over 1; B's
     * 0.8 each: 0 0 0, fractions to 1.4 (+1, 0.4), 1.2 (+1, 0.2), 1.0 (not
     * over 1); C's 0.5 each: 0, 1.5 (+1, 0.5), 1.0, 1.5 (+1, 0.5): 3 + 2 + 2
     * = 7 < 10... */
    static const uint32_t sizes[3] = {3, 3, 4};
    static const double f[10] = {0.9, 0.9, 0.9, 0.6, 0.6, 0.6, 0.5, 0.5, 0.5, 0.5};
    neat_params p = neat_params_default();
    neat_pop *pop;
    uint32_t since = 0;
    (void)state;
    p.offspring_rounding = NEAT_ROUND_SKIM;
    pop = make_pop(10, &p);
    set_layout(pop, sizes, 3);
    set_fitness_all(pop, f);
    neat_species_rank(pop);
    neat_apportion(pop, &since);
    /* adjusted: A 0.3 each (0.9 / 3), B 0.2, C 0.125; total 2.0, mean 0.2;
     * due: A 1.5 each, B 1.0 each, C 0.625 each.
     * A: 1 (skim .5), 1 (skim 1.0, not over 1), 1 (skim 1.5: +1, .5) -> 4
     * B: 1, 1, 1 (fractions 0)                                    -> 3
     * C: 0 (.5 + .625 = 1.125: +1, .125), 0 (.75), 0 (1.375: +1, .375), 0 (1.0) -> 2
     * 9: the shortfall goes to the species due the most, A -> 5 */
    assert_int_equal(pop->species[0].offspring, 5);
    assert_int_equal(pop->species[1].offspring, 3);
    assert_int_equal(pop->species[2].offspring, 2);
    /* with the improvement rule's factor on a stagnant species, the shares still sum to the population and
     * the penalised species gets a tenth of its share (B: 3 -> 0.3 due in all; the skim carries it on) */
    pop->p.stagnation_rule = NEAT_STAGNATION_IMPROVEMENT;
    pop->p.stagnation_factor = 0.1;
    pop->p.dropoff_age = 15;
    pop->species[1].next_since = 20;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[0].offspring + pop->species[1].offspring + pop->species[2].offspring, 10);
    assert_true(pop->species[1].offspring <= 1);
    pop->p.stagnation_rule = NEAT_STAGNATION_OLDEST_WORST;
    /* largest remainder on the same shares: A 4.5, B 3, C 2.5 -> 5 (or 4), 3, 2 (or 3): the older on a tie */
    pop->p.offspring_rounding = NEAT_ROUND_REMAINDER;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[0].offspring + pop->species[1].offspring + pop->species[2].offspring, 10);
    neat_pop_free(pop);
}

static void test_elitism_by_offspring(void **state)
{
    /* species A: 8 members due 3 offspring; species B: 2 members due 7 */
    static const uint32_t sizes[2] = {8, 2};
    neat_params p = neat_params_default();
    neat_pop *pop;
    neat_genome next[10];
    uint32_t i, rule;
    (void)state;
    for (rule = 0; rule < 2; rule++) {
        p.elitism_rule = (int)rule;
        p.mutate_only_prob = 1.0;
        p.weight_mut_prob = 1.0;
        p.weight_perturb_prob = 1.0;
        p.add_node_prob = p.add_conn_prob = 0.0;
        pop = make_pop(10, &p);
        set_layout(pop, sizes, 2);
        for (i = 0; i < 10; i++)
            assert_int_equal(neat_pop_set_fitness(pop, i, 1.0 + i), NEAT_OK);
        neat_species_rank(pop);
        pop->species[0].offspring = 3;
        pop->species[1].offspring = 7;
        for (i = 0; i < 10; i++)
            neat_genome_init(&next[i]);
        neat_innov_reset(&pop->iv);
        assert_int_equal(neat_reproduce(pop, next, NULL), NEAT_OK);
        /* next[0]: A's first child; next[3]: B's */
        {
            const neat_genome *ca = &pop->genomes[pop->species[0].members[0]];
            const neat_genome *cb = &pop->genomes[pop->species[1].members[0]];
            int a_copy = next[0].n_conns == ca->n_conns &&
                         conns_equal(next[0].conns, ca->conns, ca->n_conns);
            int b_copy = next[3].n_conns == cb->n_conns &&
                         conns_equal(next[3].conns, cb->conns, cb->n_conns);
            /* by size: A (8 > 5 members) keeps its champion, B (2) does not; by offspring: B (7 > 5) */
            assert_int_equal(a_copy, rule == NEAT_ELITE_BY_SIZE);
            assert_int_equal(b_copy, rule == NEAT_ELITE_BY_OFFSPRING);
        }
        for (i = 0; i < 10; i++)
            neat_genome_free(&next[i], &pop->a);
        neat_pop_free(pop);
    }
}

static void test_cpp_stagnation_dropoff_and_cull(void **state)
{
    static const uint32_t sizes[3] = {4, 4, 4};
    neat_params p = neat_params_default();
    neat_pop *pop;
    uint32_t since = 0;
    double f[12];
    int i;
    (void)state;
    p.stagnation_rule = NEAT_STAGNATION_CPP;
    p.dropoff_age = 15;
    p.cull_every = 30;
    p.cull_age = 20;
    pop = make_pop(12, &p);
    set_layout(pop, sizes, 3);
    for (i = 0; i < 12; i++)
        f[i] = 1.0;
    set_fitness_all(pop, f);
    neat_species_rank(pop);
    /* equal species: 4 each */
    pop->generation = 5;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[0].offspring, 4);
    /* not improved for 13 generations (the release's age - last + 1 = 15): times 0.01 */
    pop->species[1].since_improved = 13;
    neat_apportion(pop, &since);
    assert_true(pop->species[1].offspring <= 1);
    pop->species[1].since_improved = 12;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[1].offspring, 4);
    /* generation 30 (the 30th epoch): the newest species aged 20 or more is culled, for good */
    pop->species[0].age = 40;
    pop->species[1].age = 19; /* 20 in the release's count */
    pop->species[2].age = 18;
    pop->generation = 29;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[1].cull_now, 1);
    assert_int_equal(pop->species[0].cull_now + pop->species[2].cull_now, 0);
    assert_int_equal(pop->species[1].culled, 0); /* for good only when the epoch commits */
    assert_true(pop->species[1].offspring <= 1);
    pop->species[1].culled |= pop->species[1].cull_now; /* as neat_pop_epoch's commit does */
    pop->generation = 30;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[1].cull_now, 0);
    assert_true(pop->species[1].offspring <= 1);
    /* none old enough: the oldest (first) species */
    pop->species[1].culled = 0;
    pop->species[0].age = 3;
    pop->species[1].age = 2;
    pop->generation = 59;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[0].cull_now, 1);
    assert_int_equal(pop->species[1].cull_now + pop->species[2].cull_now, 0);
    /* the other rules ignore the flag */
    pop->p.stagnation_rule = NEAT_STAGNATION_OLDEST_WORST;
    pop->p.dropoff_age = 30;
    pop->generation = 5;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[0].offspring, 4);
    neat_pop_free(pop);
}

static void test_delta_coding(void **state)
{
    static const uint32_t sizes[3] = {4, 4, 4};
    neat_params p = neat_params_default();
    neat_pop *pop;
    neat_genome next[12];
    uint32_t since, i;
    double f[12] = {1, 1, 1, 1, 3, 3, 3, 3, 2, 2, 2, 2};
    (void)state;
    p.pop_stagnation_rule = NEAT_POPSTAG_DELTA;
    p.pop_stagnation = 20;
    p.add_node_prob = 0.0;
    p.add_conn_prob = 0.0;
    pop = make_pop(12, &p);
    set_layout(pop, sizes, 3);
    set_fitness_all(pop, f);
    neat_species_rank(pop);
    since = 19;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[0].super + pop->species[1].super + pop->species[2].super, 0);
    since = 20;
    neat_apportion(pop, &since);
    assert_int_equal(since, 0);
    assert_int_equal(pop->species[1].offspring, 6); /* the best champion's species: half */
    assert_int_equal(pop->species[2].offspring, 6); /* the second: the rest */
    assert_int_equal(pop->species[0].offspring, 0);
    assert_true(pop->species[1].super && pop->species[2].super && !pop->species[0].super);
    for (i = 0; i < 12; i++)
        neat_genome_init(&next[i]);
    neat_innov_reset(&pop->iv);
    assert_int_equal(neat_reproduce(pop, next, NULL), NEAT_OK);
    {
        /* all copies of the champions: the last of each exact, the others with other weights */
        const neat_genome *c1 = &pop->genomes[pop->species[1].members[0]];
        const neat_genome *c2 = &pop->genomes[pop->species[2].members[0]];
        assert_true(conns_equal(next[5].conns, c1->conns, c1->n_conns));
        assert_true(conns_equal(next[11].conns, c2->conns, c2->n_conns));
        for (i = 0; i < 5; i++) {
            assert_int_equal(next[i].n_conns, c1->n_conns);
            assert_false(conns_equal(next[i].conns, c1->conns, c1->n_conns));
        }
    }
    for (i = 0; i < 12; i++)
        neat_genome_free(&next[i], &pop->a);
    /* the two-best rule instead: shares among the two, normally bred */
    pop->p.pop_stagnation_rule = NEAT_POPSTAG_TWO_BEST;
    since = 20;
    neat_apportion(pop, &since);
    assert_int_equal(pop->species[0].offspring, 0);
    assert_false(pop->species[1].super);
    neat_pop_free(pop);
}

/* ---- rows 9, 11 ---- */

static void test_identical_parents_mutated(void **state)
{
    /* two distinct genomes with the same genes: with mate_only_prob 1 the
     * default leaves their child unmutated; NEAT_IDENTICAL_EQUAL mutates it */
    static const uint32_t sizes[1] = {10};
    neat_params p = neat_params_default();
    neat_pop *pop;
    neat_genome next[10];
    uint32_t i, rule, changed[2] = {0, 0};
    (void)state;
    for (rule = 0; rule < 2; rule++) {
        p.identical_rule = (int)rule;
        p.mutate_only_prob = 0.0;
        p.mate_only_prob = 1.0;
        p.weight_mut_prob = 1.0;
        p.add_node_prob = p.add_conn_prob = 0.0;
        p.survival_fraction = 1.0;
        p.elitism_min_size = 100;
        pop = make_pop(10, &p);
        set_layout(pop, sizes, 1);
        for (i = 0; i < 10; i++) {
            assert_int_equal(neat_genome_copy(&pop->genomes[i], &pop->genomes[0], &pop->a), NEAT_OK);
            assert_int_equal(neat_pop_set_fitness(pop, i, 1.0), NEAT_OK);
        }
        neat_species_rank(pop);
        pop->species[0].offspring = 10;
        for (i = 0; i < 10; i++)
            neat_genome_init(&next[i]);
        neat_innov_reset(&pop->iv);
        assert_int_equal(neat_reproduce(pop, next, NULL), NEAT_OK);
        for (i = 0; i < 10; i++) {
            changed[rule] += !conns_equal(next[i].conns, pop->genomes[0].conns, pop->genomes[0].n_conns);
            neat_genome_free(&next[i], &pop->a);
        }
        neat_pop_free(pop);
    }
    /* the default mutates only the children of a genome with itself (1 in 10 pairs) */
    assert_true(changed[NEAT_IDENTICAL_SAME] < 6);
    assert_int_equal(changed[NEAT_IDENTICAL_EQUAL], 10);
}

static void test_interspecies_cpp_toward_best(void **state)
{
    /* 6 species of 5 genomes; species k's genomes have every weight 0.5 k
     * and fitness k + 1 (species 5 the best). Species 0 breeds all 30, every
     * child a weight-averaging crossover with an interspecies mate, never
     * mutated: the child's weights tell the mate's species. The release's
     * draw is |N(0,1)| / 4 of the way down the 5 ranks: rank 0 (species 5)
     * with P(N < 0.4) = 0.655, then fewer and fewer; species 0 itself is
     * drawn again (5 tries) */
    static const uint32_t sizes[6] = {5, 5, 5, 5, 5, 5};
    neat_params p = neat_params_default();
    neat_pop *pop;
    neat_genome next[30];
    uint32_t i, k, c, rule, hits[6];
    (void)state;
    for (rule = 0; rule < 2; rule++) {
        p.interspecies_rule = (int)rule;
        p.interspecies_prob = 1.0;
        p.mutate_only_prob = 0.0;
        p.mate_only_prob = 1.0;
        p.mate_avg_prob = 1.0;
        p.survival_fraction = 1.0;
        pop = make_pop(30, &p);
        set_layout(pop, sizes, 6);
        for (i = 0; i < 30; i++) {
            neat_genome *g = &pop->genomes[i];
            for (c = 0; c < g->n_conns; c++)
                g->conns[c].weight = 0.5 * (double)(i / 5);
            assert_int_equal(neat_pop_set_fitness(pop, i, 1.0 + (double)(i / 5)), NEAT_OK);
        }
        neat_species_rank(pop);
        for (k = 0; k < 6; k++) {
            pop->species[k].offspring = k == 0 ? 30 : 0;
            hits[k] = 0;
        }
        for (i = 0; i < 30; i++)
            neat_genome_init(&next[i]);
        for (c = 0; c < 100; c++) {
            neat_innov_reset(&pop->iv);
            assert_int_equal(neat_reproduce(pop, next, NULL), NEAT_OK);
            for (i = 0; i < 30; i++) {
                double mate = 2.0 * next[i].conns[0].weight / 0.5; /* (0 + 0.5 k) / 2 */
                k = (uint32_t)floor(mate + 0.5);
                assert_true(k < 6 && fabs(mate - k) < 1e-9);
                hits[k]++;
            }
        }
        for (i = 0; i < 30; i++)
            neat_genome_free(&next[i], &pop->a);
        if (rule == NEAT_INTER_CPP) {
            assert_true(fabs(hits[5] / 3000.0 - 0.655) < 0.03);
            assert_true(hits[5] > hits[4] && hits[4] > hits[3] && hits[3] > hits[2]);
            assert_int_equal(hits[0], 0);
        } else {
            /* the default: the other species uniformly */
            for (k = 1; k < 6; k++)
                assert_true(fabs(hits[k] / 3000.0 - 0.2) < 0.03);
            assert_int_equal(hits[0], 0);
        }
        neat_pop_free(pop);
    }
}

/* ---- row 13 (found here): interleaved speciation ---- */

static void test_interleaved_pool_holds_earlier_children(void **state)
{
    /* species 0: genome X (weights 0.5) under a far representative, species
     * 1: genome Y (weights -0.5) whose representative is X. Species 0's
     * children (X, barely mutated) are placed in species 1 as they are born,
     * and species 1 then breeds from its 3 best and from them, as NEAT
     * C++'s Species::reproduce does; bred after the whole generation,
     * species 1's children come from Y alone. */
    static const uint32_t sizes[2] = {10, 10};
    neat_params p = neat_params_default();
    neat_pop *pop;
    neat_genome next[20];
    neat_spec_plan plan;
    uint32_t i, c, rule, from_x[2] = {0, 0};
    (void)state;
    for (rule = 0; rule < 2; rule++) {
        p.speciate_rule = (int)rule;
        p.mutate_only_prob = 1.0;
        p.weight_mut_prob = 1.0;
        p.weight_perturb_prob = 1.0;
        p.weight_perturb_power = 0.01;
        p.add_node_prob = p.add_conn_prob = 0.0;
        p.elitism_min_size = 100;
        pop = make_pop(20, &p);
        set_layout(pop, sizes, 2);
        for (i = 0; i < 20; i++) {
            for (c = 0; c < pop->genomes[i].n_conns; c++)
                pop->genomes[i].conns[c].weight = i < 10 ? 0.5 : -0.5;
            assert_int_equal(neat_pop_set_fitness(pop, i, 1.0), NEAT_OK);
        }
        neat_species_rank(pop);
        assert_int_equal(neat_genome_copy(&pop->species[0].rep, &pop->genomes[0], &pop->a), NEAT_OK);
        for (c = 0; c < pop->species[0].rep.n_conns; c++)
            pop->species[0].rep.conns[c].weight = 8.0;
        assert_int_equal(neat_genome_copy(&pop->species[1].rep, &pop->genomes[0], &pop->a), NEAT_OK);
        pop->species[0].offspring = 10;
        pop->species[1].offspring = 10;
        for (i = 0; i < 20; i++)
            neat_genome_init(&next[i]);
        neat_innov_reset(&pop->iv);
        if (rule == NEAT_SPECIATE_INTERLEAVED) {
            assert_int_equal(neat_speciate_plan_begin(pop, &plan), NEAT_OK);
            assert_int_equal(neat_reproduce(pop, next, &plan), NEAT_OK);
            for (i = 0; i < 10; i++)
                assert_int_equal(plan.slot[i], 1); /* X's children: species 1 */
            neat_speciate_plan_free(pop, &plan);
        } else {
            assert_int_equal(neat_reproduce(pop, next, NULL), NEAT_OK);
        }
        for (i = 10; i < 20; i++)
            from_x[rule] += next[i].conns[0].weight > 0.0;
        for (i = 0; i < 20; i++)
            neat_genome_free(&next[i], &pop->a);
        neat_pop_free(pop);
    }
    assert_int_equal(from_x[NEAT_SPECIATE_AFTER], 0);
    assert_true(from_x[NEAT_SPECIATE_INTERLEAVED] >= 4); /* 10 of the pool's 13: 7.7 expected */
}

/* ---- another NEAT's reproduction: neat_pop_replace, neat_coev_set_reproducer ---- */

/* a stand-in for the release: each genome's copy with its weights halved, species by index modulo 3 (labels
 * 7, 8, 9) */
static int halve_all(neat_pop *pop, int evaluated)
{
    uint32_t i, c, n = neat_pop_size(pop), labels[64];
    neat_genome gs[64];
    int err;
    for (i = 0; i < n; i++) {
        neat_genome_init(&gs[i]);
        assert_int_equal(neat_genome_copy(&gs[i], neat_pop_genome(pop, i), NULL), NEAT_OK);
        for (c = 0; c < gs[i].n_conns; c++)
            gs[i].conns[c].weight *= 0.5;
        labels[i] = 7 + i % 3;
    }
    err = neat_pop_replace(pop, gs, labels, n, evaluated, 0.0);
    for (i = 0; i < n; i++)
        neat_genome_free(&gs[i], NULL);
    return err;
}

static void test_pop_replace(void **state)
{
    neat_params p = pop_params();
    neat_pop *pop = NULL, *copy;
    neat_genome bad[60];
    uint32_t i, labels[60];
    uint8_t *buf;
    size_t len;
    double w0;
    (void)state;
    p.pop_size = 30;
    assert_int_equal(neat_pop_create(&pop, &p, NULL, 3, NULL), NEAT_OK);
    w0 = neat_pop_genome(pop, 4)->conns[1].weight;
    /* unevaluated: the start replaced, no generation played */
    assert_int_equal(halve_all(pop, 0), NEAT_OK);
    assert_int_equal(neat_pop_generation(pop), 0);
    assert_true(neat_pop_genome(pop, 4)->conns[1].weight == 0.5 * w0);
    assert_int_equal(neat_pop_species_count(pop), 3);
    /* evaluated without fitness: refused, nothing changed */
    assert_int_equal(halve_all(pop, 1), NEAT_E_FITNESS);
    assert_true(neat_pop_genome(pop, 4)->conns[1].weight == 0.5 * w0);
    for (i = 0; i < 30; i++)
        assert_int_equal(neat_pop_set_fitness(pop, i, (double)(i % 7)), NEAT_OK);
    assert_int_equal(halve_all(pop, 1), NEAT_OK);
    assert_int_equal(neat_pop_generation(pop), 1);
    assert_non_null(neat_pop_best_ever(pop));
    assert_true(neat_pop_best_ever(pop)->fitness == 6.0);
    {
        neat_species_info info;
        assert_int_equal(neat_pop_species(pop, 0, &info), NEAT_OK);
        assert_int_equal(info.id, 7);
        assert_int_equal(info.age, 1); /* the same label as last generation: one older */
        assert_int_equal(info.size, 10);
    }
    /* a genome of another shape: refused, nothing changed */
    for (i = 0; i < 30; i++) {
        neat_genome_init(&bad[i]);
        assert_int_equal(neat_genome_minimal(&bad[i], 3, 1, NULL), NEAT_OK);
        labels[i] = 1;
    }
    assert_int_equal(neat_pop_replace(pop, bad, labels, 30, 0, 0.0), NEAT_E_ARG);
    assert_int_equal(neat_pop_replace(pop, bad, labels, 29, 0, 0.0), NEAT_E_ARG);
    assert_int_equal(neat_pop_species_count(pop), 3);
    for (i = 0; i < 30; i++)
        neat_genome_free(&bad[i], NULL);
    /* the result checkpoints and loads, and libneat's own epoch can go on from it */
    assert_int_equal(neat_pop_save(pop, &buf, &len), NEAT_OK);
    copy = NULL;
    assert_int_equal(neat_pop_load(&copy, buf, len, NULL, NULL), NEAT_OK);
    neat_pop_buf_free(pop, buf, len);
    for (i = 0; i < 30; i++)
        assert_int_equal(neat_pop_set_fitness(copy, i, 1.0 + i), NEAT_OK);
    assert_int_equal(neat_pop_epoch(copy), NEAT_OK);
    neat_pop_free(copy);
    neat_pop_free(pop);
}

/* an allocator that refuses its fail_at-th request (0: none) and counts the blocks alive */
typedef struct refusing {
    size_t requests, fail_at;
    long live;
} refusing;

static void *refusing_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    refusing *r = (refusing *)ud;
    (void)old_size;
    if (new_size == 0) {
        if (ptr != NULL)
            r->live--;
        free(ptr);
        return NULL;
    }
    if (++r->requests == r->fail_at)
        return NULL;
    if (ptr == NULL)
        r->live++;
    return realloc(ptr, new_size);
}

static void test_pop_replace_refused_memory(void **state)
{
    /* every allocation of neat_pop_replace refused in turn: NEAT_E_NOMEM, the population as it was, no
     * block leaked (the last try goes through) */
    neat_params p = pop_params();
    uint32_t i, c, labels[30], done = 0;
    neat_genome gs[30];
    size_t k;
    (void)state;
    p.pop_size = 30;
    for (k = 1; !done && k < 500; k++) {
        refusing r = {0, 0, 0};
        neat_alloc a = {refusing_alloc, &r};
        neat_pop *pop = NULL;
        int err;
        assert_int_equal(neat_pop_create(&pop, &p, NULL, 3, &a), NEAT_OK);
        for (i = 0; i < 30; i++) {
            neat_genome_init(&gs[i]);
            assert_int_equal(neat_genome_copy(&gs[i], neat_pop_genome(pop, i), NULL), NEAT_OK);
            for (c = 0; c < gs[i].n_conns; c++)
                gs[i].conns[c].weight = 0.25;
            labels[i] = 40 + i % 4;
            assert_int_equal(neat_pop_set_fitness(pop, i, 1.0 + i), NEAT_OK);
        }
        r.fail_at = r.requests + k;
        err = neat_pop_replace(pop, gs, labels, 30, 1, 0.0);
        if (err == NEAT_OK) {
            done = 1;
            assert_int_equal(neat_pop_generation(pop), 1);
        } else {
            assert_int_equal(err, NEAT_E_NOMEM);
            assert_int_equal(neat_pop_generation(pop), 0);
            assert_true(neat_pop_genome(pop, 0)->conns[0].weight != 0.25);
            assert_true(neat_pop_genome(pop, 0)->has_fitness);
        }
        neat_pop_free(pop);
        assert_int_equal(r.live, 0);
        for (i = 0; i < 30; i++)
            neat_genome_free(&gs[i], NULL);
    }
    assert_true(done && k > 3);
}

static int coev_halve(void *ud, uint32_t which, neat_pop *pop, int evaluated)
{
    uint32_t *calls = (uint32_t *)ud;
    calls[which * 2 + (evaluated ? 1 : 0)]++;
    return halve_all(pop, evaluated);
}

/* the game: the genome whose first weight is larger wins */
static int play_first_weight(void *ud, neat_game *games, size_t n)
{
    size_t i;
    (void)ud;
    for (i = 0; i < n; i++) {
        double a = games[i].a->conns[0].weight, b = games[i].b->conns[0].weight;
        games[i].result = (int8_t)(a > b ? 1 : (a < b ? -1 : 0));
    }
    return 0;
}

static void test_coev_reproducer(void **state)
{
    neat_params p = small_params();
    neat_coev_params cp = neat_coev_params_default();
    neat_coev *c = NULL;
    uint32_t calls[4] = {0, 0, 0, 0}, g;
    neat_coev_report rep;
    (void)state;
    p.pop_size = 30;
    p.pop_stagnation = 0;
    cp.compare_configs = 2;
    assert_int_equal(neat_coev_create(&c, &p, &cp, NULL, 5, NULL), NEAT_OK);
    assert_int_equal(neat_coev_set_reproducer(c, coev_halve, calls), NEAT_OK);
    assert_int_equal(calls[0] + calls[2], 2); /* both starts replaced */
    for (g = 0; g < 3; g++)
        assert_int_equal(neat_coev_step(c, play_first_weight, NULL, &rep), NEAT_OK);
    assert_int_equal(calls[1], 3);
    assert_int_equal(calls[3], 3);
    assert_int_equal(neat_coev_generation(c), 3);
    assert_int_equal(neat_pop_species_count(neat_coev_pop(c, 0)), 3);
    assert_int_equal(neat_pop_generation(neat_coev_pop(c, 1)), 3);
    neat_coev_free(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_profile_sets_every_switch),
        cmocka_unit_test(test_equal_fitness_smaller_parent_is_fitter),
        cmocka_unit_test(test_reenable_cpp),
        cmocka_unit_test(test_weights_cpp_head_and_tail),
        cmocka_unit_test(test_add_conn_cpp),
        cmocka_unit_test(test_add_conn_cpp_reuses_first_weight),
        cmocka_unit_test(test_switches_change_only_their_case),
        cmocka_unit_test(test_species_rep_is_champion),
        cmocka_unit_test(test_skim_rounding),
        cmocka_unit_test(test_elitism_by_offspring),
        cmocka_unit_test(test_cpp_stagnation_dropoff_and_cull),
        cmocka_unit_test(test_delta_coding),
        cmocka_unit_test(test_identical_parents_mutated),
        cmocka_unit_test(test_interspecies_cpp_toward_best),
        cmocka_unit_test(test_interleaved_pool_holds_earlier_children),
        cmocka_unit_test(test_pop_replace),
        cmocka_unit_test(test_pop_replace_refused_memory),
        cmocka_unit_test(test_coev_reproducer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
