/* test_alloc.c - the allocation hook: every refused allocation is NEAT_E_NOMEM, never a crash or a leak. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "neat.h"
#include "neat_phenotype.h"

/* ---- a counting allocator ----
 * Every block carries its size in a 16-byte header, so the old_size the
 * library passes on realloc and free is checked too. */
typedef struct counter {
    size_t live;      /* blocks allocated and not freed */
    size_t calls;     /* allocation requests (new_size > 0) so far */
    size_t fail_at;   /* refuse request number fail_at (1-based; 0 never) */
    int fail_after;   /* and every request after it */
    size_t refused;
    size_t bad_size;  /* old_size not matching the block */
} counter;

#define HDR 16

static void *counting_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    counter *c = (counter *)ud;
    unsigned char *real = ptr ? (unsigned char *)ptr - HDR : NULL;
    size_t have = 0;
    if (real != NULL)
        memcpy(&have, real, sizeof have);
    if (ptr != NULL && have != old_size)
        c->bad_size++;
    if (ptr == NULL && old_size != 0)
        c->bad_size++;
    if (new_size == 0) {
        if (real != NULL) {
            free(real);
            c->live--;
        }
        return NULL;
    }
    c->calls++;
    if (c->fail_at != 0 && (c->calls == c->fail_at || (c->fail_after && c->calls > c->fail_at))) {
        c->refused++;
        return NULL;
    }
    real = (unsigned char *)realloc(real, new_size + HDR);
    if (real == NULL)
        return NULL;
    memcpy(real, &new_size, sizeof new_size);
    if (ptr == NULL)
        c->live++;
    return real + HDR;
}

static void counter_init(counter *c, size_t fail_at, int fail_after)
{
    memset(c, 0, sizeof *c);
    c->fail_at = fail_at;
    c->fail_after = fail_after;
}

/* the profile of the scenario's population: the _cpp variants run NEAT
 * C++ 1.2.1's rules, whose interleaved speciation and mate choice allocate
 * elsewhere */
static int alloc_profile = NEAT_PROFILE_DEFAULT;

static neat_params alloc_params(void)
{
    neat_params p = neat_params_default();
    if (alloc_profile == NEAT_PROFILE_NEAT_CPP) {
        (void)neat_params_set_profile(&p, alloc_profile);
        p.cull_every = 2; /* a cull in the scenario's few epochs */
        p.cull_age = 1;
    }
    p.pop_size = 16;
    p.n_inputs = 2;
    p.n_outputs = 1;
    p.add_node_prob = 0.2; /* plenty of structure, so every allocation site is reached */
    p.add_conn_prob = 0.4;
    p.target_species = 3;
    p.allow_recurrent = 0; /* add_conn's scratch buffers for the cycle check */
    return p;
}

static int set_all_fitness(neat_pop *pop)
{
    uint32_t i, k;
    int err = NEAT_OK;
    for (i = 0; i < neat_pop_size(pop) && !err; i++) {
        const neat_genome *g = neat_pop_genome(pop, i);
        double s = 0.0;
        for (k = 0; k < g->n_conns; k++)
            s += g->conns[k].weight;
        err = neat_pop_set_fitness(pop, i, 1.0 / (1.0 + fabs(s - 1.0)));
    }
    return err;
}

/* create, 3 epochs, save, load, one epoch of the loaded copy, free all.
 * retry: after a refused epoch, try the epoch again (the allocator then
 * works again when only one request was refused). */
static int scenario(const neat_alloc *a, int retry, int *retried_ok)
{
    neat_params p = alloc_params();
    neat_pop *pop = NULL, *copy = NULL;
    uint8_t *buf = NULL;
    size_t len = 0, off = 0;
    int err, g;

    err = neat_pop_create(&pop, &p, NULL, 7, a);
    if (err) {
        assert_null(pop);
        return err;
    }
    for (g = 0; g < 3 && !err; g++) {
        err = set_all_fitness(pop);
        if (!err)
            err = neat_pop_epoch(pop);
        if (err == NEAT_E_NOMEM && retry) {
            /* the epoch again, or, if it got as far as the next
             * generation, that generation's epoch */
            if (neat_pop_generation(pop) != (uint32_t)g)
                err = set_all_fitness(pop);
            else
                err = NEAT_OK;
            if (!err)
                err = neat_pop_epoch(pop);
            if (err == NEAT_OK)
                ++*retried_ok;
        }
    }
    if (!err)
        err = neat_pop_save(pop, &buf, &len);
    if (!err) {
        err = neat_pop_load(&copy, buf, len, a, &off);
        neat_pop_buf_free(pop, buf, len);
        if (err)
            assert_null(copy);
    }
    if (!err) {
        err = set_all_fitness(copy);
        if (!err)
            err = neat_pop_epoch(copy);
    }
    neat_pop_free(copy);
    neat_pop_free(pop);
    return err;
}

static size_t requests_of_full_run(void)
{
    counter c;
    neat_alloc a;
    counter_init(&c, 0, 0);
    a.fn = counting_alloc;
    a.ud = &c;
    assert_int_equal(scenario(&a, 0, NULL), NEAT_OK);
    return c.calls;
}

static void test_default_allocator(void **state)
{
    neat_alloc a;
    (void)state;
    assert_int_equal(scenario(NULL, 0, NULL), NEAT_OK);
    /* a hook struct with a NULL function is the default too */
    a.fn = NULL;
    a.ud = NULL;
    assert_int_equal(scenario(&a, 0, NULL), NEAT_OK);
}

static void test_counting_allocator_balanced(void **state)
{
    counter c;
    neat_alloc a;
    (void)state;
    counter_init(&c, 0, 0);
    a.fn = counting_alloc;
    a.ud = &c;
    assert_int_equal(scenario(&a, 0, NULL), NEAT_OK);
    assert_true(c.calls > 100);
    assert_int_equal(c.live, 0);
    assert_int_equal(c.bad_size, 0);
}

static void test_every_allocation_refused_once(void **state)
{
    size_t m = requests_of_full_run(), n;
    (void)state;
    for (n = 1; n <= m; n++) {
        counter c;
        neat_alloc a;
        int err;
        counter_init(&c, n, 0);
        a.fn = counting_alloc;
        a.ud = &c;
        err = scenario(&a, 0, NULL);
        if (err != NEAT_OK && err != NEAT_E_NOMEM)
            fail_msg("request %zu of %zu refused: error %d", n, m, err);
        /* a refusal is never swallowed */
        if (c.refused > 0 && err != NEAT_E_NOMEM)
            fail_msg("request %zu of %zu refused but the run succeeded", n, m);
        if (c.live != 0)
            fail_msg("request %zu of %zu refused: %zu blocks leaked", n, m, c.live);
        if (c.bad_size != 0)
            fail_msg("request %zu of %zu refused: %zu frees with a wrong size", n, m, c.bad_size);
    }
}

static void test_every_allocation_from_n_refused(void **state)
{
    size_t m = requests_of_full_run(), n;
    (void)state;
    for (n = 1; n <= m; n++) {
        counter c;
        neat_alloc a;
        int err;
        counter_init(&c, n, 1);
        a.fn = counting_alloc;
        a.ud = &c;
        err = scenario(&a, 0, NULL);
        if (err != NEAT_E_NOMEM)
            fail_msg("requests from %zu of %zu refused: error %d", n, m, err);
        if (c.live != 0)
            fail_msg("requests from %zu of %zu refused: %zu blocks leaked", n, m, c.live);
        if (c.bad_size != 0)
            fail_msg("requests from %zu of %zu refused: %zu frees with a wrong size", n, m, c.bad_size);
    }
}

static void test_epoch_retry_after_nomem(void **state)
{
    /* an epoch refused one allocation: the population must still be
     * valid, so the same epoch tried again with memory available works */
    size_t m = requests_of_full_run(), n;
    int retried_ok = 0;
    (void)state;
    for (n = 1; n <= m; n++) {
        counter c;
        neat_alloc a;
        int err;
        counter_init(&c, n, 0);
        a.fn = counting_alloc;
        a.ud = &c;
        err = scenario(&a, 1, &retried_ok);
        if (err != NEAT_OK && err != NEAT_E_NOMEM)
            fail_msg("request %zu refused, epoch retried: error %d", n, err);
        if (c.live != 0)
            fail_msg("request %zu refused, epoch retried: %zu blocks leaked", n, c.live);
    }
    assert_true(retried_ok > 0);
}

/* The phenotype's buffers come from the same hook: balanced, old sizes
 * right, and a refusal of either buffer is NEAT_E_NOMEM, never a crash. */
static void test_phenotype_through_hook(void **state)
{
    neat_params p = alloc_params();
    neat_genome g;
    size_t n;
    (void)state;
    memset(&g, 0, sizeof g);
    assert_int_equal(neat_genome_minimal(&g, p.n_inputs, p.n_outputs, NULL), NEAT_OK);
    for (n = 0; n <= 3; n++) {
        counter c;
        neat_alloc a;
        neat_phenotype ph;
        nrt_q15 in[3] = {NRT_ONE, 0, 0}, out[1];
        int err;
        counter_init(&c, n, 0);
        a.fn = counting_alloc;
        a.ud = &c;
        neat_phenotype_init(&ph, &a);
        err = neat_phenotype_load(&ph, &g, &p);
        if (n == 1 || n == 2) {
            assert_int_equal(err, NEAT_E_NOMEM);
        } else {
            assert_int_equal(err, NEAT_OK);
            assert_true(nrt_settle(&ph.net, in, out, 10) >= 0);
            /* loading again reuses the buffers */
            assert_int_equal(neat_phenotype_load(&ph, &g, &p), NEAT_OK);
            assert_int_equal(c.calls, 2);
        }
        neat_phenotype_free(&ph);
        assert_int_equal(c.live, 0);
        assert_int_equal(c.bad_size, 0);
    }
    neat_genome_free(&g, NULL);
}

#define ALLOC_CPP(name)                                                                                             \
    static void name##_cpp(void **state)                                                                            \
    {                                                                                                               \
        alloc_profile = NEAT_PROFILE_NEAT_CPP;                                                                      \
        name(state);                                                                                                \
        alloc_profile = NEAT_PROFILE_DEFAULT;                                                                       \
    }
ALLOC_CPP(test_counting_allocator_balanced)
ALLOC_CPP(test_every_allocation_refused_once)
ALLOC_CPP(test_every_allocation_from_n_refused)
ALLOC_CPP(test_epoch_retry_after_nomem)

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_allocator),
        cmocka_unit_test(test_counting_allocator_balanced),
        cmocka_unit_test(test_every_allocation_refused_once),
        cmocka_unit_test(test_every_allocation_from_n_refused),
        cmocka_unit_test(test_epoch_retry_after_nomem),
        cmocka_unit_test(test_phenotype_through_hook),
        cmocka_unit_test(test_counting_allocator_balanced_cpp),
        cmocka_unit_test(test_every_allocation_refused_once_cpp),
        cmocka_unit_test(test_every_allocation_from_n_refused_cpp),
        cmocka_unit_test(test_epoch_retry_after_nomem_cpp),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
