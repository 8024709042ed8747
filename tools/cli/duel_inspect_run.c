/* duel_inspect_run.c - `duel_evolve inspect DIR | CHECKPOINT`: what a run's checkpoint holds: generation, start topology, each population's species, sizes and innovations, the dominance levels. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "duel_cli.h"
#include "duel_ctrl.h"
#include "duel_files.h"
#include "duel_world_cfg.h"
#include "neat_coev.h"
#include "duel_runtag.h"
#include "duel_text.h"


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

/* One population's line: its genomes, species, threshold, sizes and innovations. */
static void duel_inspect_pop(const neat_pop *pop, const char *name)
{
    uint32_t i, hmin = UINT32_MAX, hmax = 0, cmin = UINT32_MAX, cmax = 0, ilo = UINT32_MAX, ihi = 0;
    for (i = 0; i < neat_pop_size(pop); i++) {
        const neat_genome *g = neat_pop_genome(pop, i);
        uint32_t h = neat_genome_hidden_count(g), n = neat_genome_enabled_count(g);
        hmin = h < hmin ? h : hmin;
        hmax = h > hmax ? h : hmax;
        cmin = n < cmin ? n : cmin;
        cmax = n > cmax ? n : cmax;
        duel_innov_range(g, &ilo, &ihi);
    }
    printf("%s: %u genomes in %u species, delta_t %.4f; hidden %u..%u, connections %u..%u; "
           "innovations in use %u..%u, next %u\n",
           name, neat_pop_size(pop), neat_pop_species_count(pop), neat_pop_delta_t(pop), hmin, hmax, cmin, cmax,
           ilo <= ihi ? ilo : 0, ilo <= ihi ? ihi : 0, neat_pop_innovations(pop));
}

/* The world of a checkpoint's game tag (its first DUEL_RULES_BYTES; none: v1) */
static void duel_inspect_world(const uint8_t *tag, size_t len)
{
    duel_rules r;
    char label[40];
    if (duel_tag_world(tag, len, &r, NULL) < 0) {
        printf("world: damaged rules in the checkpoint's tag\n");
        return;
    }
    printf("world: %s%s\n", duel_world_label(&r, label, sizeof label), len == 0 ? " (no tag: a run from before the "
                                                                                   "rules were data)" : "");
}

/* A run against fixed opponents: its population checkpoint. */
static void duel_inspect_pop_ckpt(const char *path, neat_pop *pop, uint32_t format)
{
    size_t tlen = 0;
    const uint8_t *tag;
    printf("file: %s\n", path);
    /* the file's own format: 3, or 4 with NEAT C++ 1.2.1's switches (the loader checked bytes 8-11) */
    printf("population checkpoint (a run against fixed opponents), format %u: next generation %u\n", format,
           neat_pop_generation(pop));
    printf("mode: %s, net_step %s\n", duel_mode_name(neat_pop_params(pop)->mode),
           neat_pop_params(pop)->net_step == NEAT_STEP_PROPAGATE ? "propagate" : "sync");
    duel_inspect_pop(pop, "population");
    tag = neat_pop_game(pop, &tlen);
    duel_inspect_world(tag, tlen);
}

int duel_inspect_run(const char *arg)
{
    char path[4200];
    struct stat st;
    neat_coev *c;
    const neat_genome *s;
    uint32_t p, lo = UINT32_MAX, hi = 0;
    int e;

    if (stat(arg, &st) == 0 && S_ISDIR(st.st_mode))
        snprintf(path, sizeof path, "%s/checkpoint.bin", arg);
    else
        snprintf(path, sizeof path, "%s", arg);
    {
        /* either kind of checkpoint: a population's is a run against fixed opponents' */
        char msg[4600];
        neat_pop *pop;
        uint32_t format = 0;
        e = duel_any_ckpt_load_msg("", path, &c, &pop, &format, msg, sizeof msg);
        if (e > 0)
            fprintf(stderr, "duel_evolve: %s: cannot read: %s\n", duel_esc(path), strerror(ENOENT));
        else if (e < 0)
            fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(msg));
        if (e != 0)
            return 2;
        if (pop != NULL) {
            duel_inspect_pop_ckpt(path, pop, format);
            neat_pop_free(pop);
            return 0;
        }
    }
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
    for (p = 0; p < 2; p++)
        duel_inspect_pop(neat_coev_pop(c, p), p == 0 ? "population A" : "population B");
    printf("dominance levels: %u\n", neat_coev_dominant_count(c));
    {
        size_t tlen = 0;
        const uint8_t *tag = neat_coev_game(c, &tlen);
        duel_inspect_world(tag, tlen);
    }
    neat_coev_free(c);
    return 0;
}
