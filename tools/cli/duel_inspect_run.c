/* duel_inspect_run.c - `duel_evolve inspect DIR | CHECKPOINT`: what a run's checkpoint holds: generation, start topology, each population's species, sizes and innovations, the dominance levels. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "duel_cli.h"
#include "duel_ctrl.h"
#include "neat_coev.h"


static const char *duel_mode_name(int mode)
{
    return mode == NEAT_MODE_FIXED ? "fixed" : mode == NEAT_MODE_SIMPLIFY ? "simplify" : "complexify";
}

/* The smallest and largest innovation numbers in g (lo > hi when it has none). */
static void duel_innov_range(const neat_genome *g, uint32_t *lo, uint32_t *hi)
{
    uint32_t k;
    for (k = 0; k < g->n_conns; k++) {
        if (g->conns[k].innov < *lo)
            *lo = g->conns[k].innov;
        if (g->conns[k].innov > *hi)
            *hi = g->conns[k].innov;
    }
}

int duel_inspect_run(const char *arg)
{
    char path[4200];
    struct stat st;
    neat_coev *c;
    const neat_genome *s;
    uint32_t p, i, lo = UINT32_MAX, hi = 0;
    int e;

    if (stat(arg, &st) == 0 && S_ISDIR(st.st_mode))
        snprintf(path, sizeof path, "%s/checkpoint.bin", arg);
    else
        snprintf(path, sizeof path, "%s", arg);
    e = duel_ckpt_load("", path, &c);
    if (e > 0)
        fprintf(stderr, "duel_evolve: %s: cannot read: %s\n", path, strerror(ENOENT));
    if (e != 0)
        return 2;
    s = neat_coev_start(c);
    duel_innov_range(s, &lo, &hi);
    printf("file: %s\n", path);
    printf("coevolution checkpoint, format %u: next generation %u, seed %llu\n", NEAT_COEV_CHECKPOINT_VERSION,
           neat_coev_generation(c), (unsigned long long)neat_coev_seed(c));
    printf("mode: %s%s\n", duel_mode_name(neat_pop_params(neat_coev_pop(c, 0))->mode),
           neat_coev_get_params(c)->random_fitness ? ", random fitness" : "");
    if (lo <= hi)
        printf("start: %u nodes (%u hidden), %u connections, innovations %u..%u\n", s->n_nodes,
               neat_genome_hidden_count(s), neat_genome_enabled_count(s), lo, hi);
    else
        printf("start: %u nodes (%u hidden), no connections\n", s->n_nodes, neat_genome_hidden_count(s));
    for (p = 0; p < 2; p++) {
        const neat_pop *pop = neat_coev_pop(c, p);
        uint32_t hmin = UINT32_MAX, hmax = 0, cmin = UINT32_MAX, cmax = 0, ilo = UINT32_MAX, ihi = 0;
        for (i = 0; i < neat_pop_size(pop); i++) {
            const neat_genome *g = neat_pop_genome(pop, i);
            uint32_t h = neat_genome_hidden_count(g), n = neat_genome_enabled_count(g);
            hmin = h < hmin ? h : hmin;
            hmax = h > hmax ? h : hmax;
            cmin = n < cmin ? n : cmin;
            cmax = n > cmax ? n : cmax;
            duel_innov_range(g, &ilo, &ihi);
        }
        printf("population %c: %u genomes in %u species, delta_t %.4f; hidden %u..%u, connections %u..%u; "
               "innovations in use %u..%u, next %u\n",
               p == 0 ? 'A' : 'B', neat_pop_size(pop), neat_pop_species_count(pop), neat_pop_delta_t(pop), hmin,
               hmax, cmin, cmax, ilo <= ihi ? ilo : 0, ilo <= ihi ? ihi : 0, neat_pop_innovations(pop));
    }
    printf("dominance levels: %u\n", neat_coev_dominant_count(c));
    neat_coev_free(c);
    return 0;
}
