/* fuzz_ini.c - libFuzzer harness: any text as duel_evolve's run configuration (its first line also as a --set override), as an experiment's plan, and as neat_bench's configuration; errors name the line, a loaded configuration dumps to text that loads back to the same dump. */
#define _POSIX_C_SOURCE 200809L
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "duel_config.h"
#include "duel_plan.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char *fi_dump(const duel_config *cfg, size_t *len)
{
    char *text = NULL;
    FILE *f = open_memstream(&text, len);
    if (f == NULL)
        __builtin_trap();
    duel_config_dump(f, cfg);
    fclose(f);
    return text;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    duel_config cfg, back;
    bench_cfg bc;
    char err[600], line[1100];
    const char *text = (const char *)data;
    const char *nl = (const char *)memchr(data, '\n', size);
    size_t n = nl != NULL ? (size_t)(nl - text) : size;

    duel_config_default(&cfg);
    err[0] = '\0';
    if (duel_config_load_text(&cfg, "f.ini", text, size, err, sizeof err) == 0) {
        size_t l1, l2;
        char *d1 = fi_dump(&cfg, &l1), *d2;
        duel_config_default(&back);
        if (duel_config_load_text(&back, "dump", d1, l1, err, sizeof err) != 0)
            __builtin_trap(); /* a dump always loads */
        d2 = fi_dump(&back, &l2);
        if (l1 != l2 || memcmp(d1, d2, l1) != 0)
            __builtin_trap();
        free(d1);
        free(d2);
    } else if (strncmp(err, "f.ini", 5) != 0) {
        __builtin_trap(); /* every error names the file */
    }
    /* the first line as an override */
    if (n < sizeof line && memchr(text, '\0', n) == NULL) {
        memcpy(line, text, n);
        line[n] = '\0';
        duel_config_default(&cfg);
        if (duel_config_set(&cfg, line, err, sizeof err) == 0)
            (void)duel_config_check(&cfg, err, sizeof err);
    }
    /* the text as an experiment's plan: a parsed plan is consistent, an error names the file */
    {
        duel_plan *plan = NULL;
        if (duel_plan_parse_text(&plan, "p.ini", text, size, err, sizeof err) == 0) {
            uint32_t i;
            if (plan->n_methods == 0 || plan->n_methods > DUEL_PLAN_MAX_METHODS || plan->ref >= plan->n_methods ||
                plan->m[plan->ref].runs < 2 || plan->m[plan->ref].start_best)
                __builtin_trap();
            for (i = 0; i < plan->n_methods; i++)
                if (plan->m[i].runs < 1 || plan->m[i].runs > DUEL_PLAN_MAX_RUNS || plan->m[i].name[0] == '\0' ||
                    plan->m[i].preset[0] == '\0' || plan->m[i].n_sets > DUEL_PLAN_MAX_SETS)
                    __builtin_trap();
            {
                char *t = duel_plan_text(plan); /* the canonical text parses back to the same text */
                duel_plan *again = NULL;
                char *t2;
                if (t == NULL || duel_plan_parse_text(&again, "back", t, strlen(t), err, sizeof err) != 0)
                    __builtin_trap();
                t2 = duel_plan_text(again);
                if (t2 == NULL || strcmp(t, t2) != 0)
                    __builtin_trap();
                free(t);
                free(t2);
                duel_plan_free(again);
            }
        } else if (strncmp(err, "p.ini", 5) != 0 && strcmp(err, "out of memory") != 0) {
            __builtin_trap();
        }
        duel_plan_free(plan);
    }
    memset(&bc, 0, sizeof bc);
    bc.neat = neat_params_default();
    if (bench_config_load_text(&bc, "b.ini", text, size, err, sizeof err) != 0 && strncmp(err, "b.ini", 5) != 0)
        __builtin_trap();
    return 0;
}
