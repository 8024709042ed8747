/* duel_fixed.c - a generation of evolution against fixed opponents: the layouts drawn, the hosts' games on every core, fitness, the champion's record, the epoch. */
#include <stdlib.h>
#include <string.h>

#include "duel_fixed.h"
#include "neat_phenotype.h"

struct duel_fixed {
    neat_pop *pop;
    uint64_t seed;
    uint32_t layouts;   /* 0: the training food */
    int fitness;        /* enum duel_fitness */
    int net_step;
    uint32_t n_opp;
    duel_net *opp;      /* [n_opp]: blobs point into opp_buf */
    uint8_t *opp_buf;
    /* a generation's hosts and games, grown as needed */
    uint8_t *blobs;
    size_t blobs_cap;
    size_t *off;        /* [pop] each host's blob in blobs */
    duel_net *nets;     /* [pop + n_opp] */
    duel_match *m;
    size_t m_cap;
};

void duel_fixed_layouts(uint64_t seed, uint32_t n, uint32_t g, int32_t out[DUEL_CONFIGS])
{
    uint64_t keys[2];
    neat_rng rng;
    uint32_t k;
    int32_t all[DUEL_CONFIGS];
    keys[0] = 0x6c617973u; /* "lays": apart from every other use of the seed */
    keys[1] = g;
    neat_rng_seed(&rng, neat_seed_derive(seed, keys, 2));
    for (k = 0; k < DUEL_CONFIGS; k++)
        all[k] = (int32_t)k;
    /* the first n of a Fisher-Yates shuffle: n distinct layouts */
    for (k = 0; k < n; k++) {
        uint32_t j = k + neat_rng_below(&rng, DUEL_CONFIGS - k);
        int32_t t = all[k];
        all[k] = all[j];
        all[j] = t;
        out[k] = all[k];
    }
}

int duel_fixed_new(duel_fixed **out, neat_pop *pop, const duel_config *cfg, const duel_net *opps, uint32_t n)
{
    duel_fixed *f = (duel_fixed *)calloc(1, sizeof *f);
    size_t total = 0, at = 0;
    uint32_t k, size = neat_pop_size(pop);
    *out = NULL;
    if (f == NULL || n == 0 || n > DUEL_MAX_OPPONENTS) {
        free(f);
        neat_pop_free(pop);
        return n == 0 || n > DUEL_MAX_OPPONENTS ? NEAT_E_ARG : NEAT_E_NOMEM;
    }
    f->pop = pop;
    f->seed = cfg->seed;
    f->layouts = cfg->opp.layouts;
    f->fitness = cfg->opp.fitness;
    f->net_step = cfg->neat.net_step;
    f->n_opp = n;
    for (k = 0; k < n; k++)
        total += opps[k].blob != NULL ? opps[k].len : 0;
    f->opp = (duel_net *)calloc(n, sizeof *f->opp);
    f->opp_buf = (uint8_t *)malloc(total + 1);
    f->off = (size_t *)calloc(size, sizeof *f->off);
    f->nets = (duel_net *)calloc((size_t)size + n, sizeof *f->nets);
    if (f->opp == NULL || f->opp_buf == NULL || f->off == NULL || f->nets == NULL) {
        duel_fixed_free(f);
        return NEAT_E_NOMEM;
    }
    for (k = 0; k < n; k++) {
        f->opp[k] = opps[k];
        if (opps[k].blob != NULL) {
            memcpy(f->opp_buf + at, opps[k].blob, opps[k].len);
            f->opp[k].blob = f->opp_buf + at;
            at += opps[k].len;
        }
    }
    *out = f;
    return 0;
}

void duel_fixed_free(duel_fixed *f)
{
    if (f == NULL)
        return;
    neat_pop_free(f->pop);
    free(f->opp);
    free(f->opp_buf);
    free(f->blobs);
    free(f->off);
    free(f->nets);
    free(f->m);
    free(f);
}

neat_pop *duel_fixed_pop(const duel_fixed *f)
{
    return f->pop;
}

/* Every host's blob (the run's step mode) into f->blobs, and the nets:
 * hosts first, then the opponents. */
static int duel_fixed_encode(duel_fixed *f)
{
    const neat_params *p = neat_pop_params(f->pop);
    uint32_t i, size = neat_pop_size(f->pop);
    size_t total = 0, at = 0;
    for (i = 0; i < size; i++)
        total += neat_blob_size(neat_pop_genome(f->pop, i));
    if (total > f->blobs_cap) {
        uint8_t *b = (uint8_t *)realloc(f->blobs, total);
        if (b == NULL)
            return NEAT_E_NOMEM;
        f->blobs = b;
        f->blobs_cap = total;
    }
    for (i = 0; i < size; i++) {
        size_t len = 0;
        int err = neat_blob_write_step(neat_pop_genome(f->pop, i), p->n_inputs, p->n_outputs, f->net_step,
                                       f->blobs + at, total - at, &len);
        if (err)
            return err;
        f->off[i] = at;
        at += len;
    }
    for (i = 0; i < size; i++) {
        f->nets[i].blob = f->blobs + f->off[i];
        f->nets[i].len = (i + 1 < size ? f->off[i + 1] : at) - f->off[i];
    }
    for (i = 0; i < f->n_opp; i++)
        f->nets[size + i] = f->opp[i];
    return 0;
}

/* A net as a controller of its own (net and mem the caller's): a blob loaded, or a builtin */
static int duel_fixed_ctrl(const duel_net *n, duel_controller *c, nrt_net *net, void **mem)
{
    size_t need;
    memset(c, 0, sizeof *c);
    *mem = NULL;
    if (n->blob == NULL) {
        c->builtin = (int)n->len;
        return 0;
    }
    if (nrt_mem_required(n->blob, n->len, &need) != 0 || (*mem = malloc(need)) == NULL ||
        nrt_load(net, n->blob, n->len, *mem, need) != 0)
        return NEAT_E_NOMEM;
    c->net = net;
    return 0;
}

/* The champion's games again, one by one, for what a match result does not
 * tell: draws apart from timeouts. */
static int duel_fixed_tally(duel_fixed *f, const duel_rules *rules, uint32_t host, const duel_match *m, size_t n,
                            duel_tally *vs)
{
    duel_controller hc, oc;
    nrt_net hn, on;
    void *hm = NULL, *om = NULL;
    size_t i;
    int err = duel_fixed_ctrl(&f->nets[host], &hc, &hn, &hm);
    memset(vs, 0, f->n_opp * sizeof *vs);
    for (i = 0; i < n && err == 0; i++) {
        duel_result r;
        duel_tally *t = &vs[m[i].b - neat_pop_size(f->pop)];
        err = duel_fixed_ctrl(&f->nets[m[i].b], &oc, &on, &om);
        if (err == 0)
            err = m[i].a_first ? duel_play_rules(rules, &hc, &oc, m[i].config, &r, NULL, NULL)
                               : duel_play_rules(rules, &oc, &hc, m[i].config, &r, NULL, NULL);
        free(om);
        om = NULL;
        if (err) {
            err = err <= -100 ? err : err - 200;
            break;
        }
        if (r.outcome == DUEL_DRAW)
            t->draws++;
        else if (r.outcome == DUEL_TIMEOUT)
            t->timeouts++;
        else if ((r.outcome == DUEL_WEST_WINS) == (m[i].a_first != 0))
            t->wins_a++;
        else
            t->wins_b++;
    }
    free(hm);
    return err;
}

int duel_fixed_step(duel_fixed *f, duel_games *dg, duel_fixed_report *rep)
{
    uint32_t size = neat_pop_size(f->pop), i, k, l, s, best = 0;
    int32_t lay[DUEL_CONFIGS];
    uint32_t n_lay, per_host, gen = neat_pop_generation(f->pop);
    size_t n, at = 0;
    double sum = 0, *fit;
    int err;

    memset(rep, 0, sizeof *rep);
    n_lay = f->layouts;
    if (n_lay > 0) {
        duel_fixed_layouts(f->seed, n_lay, gen, lay);
    } else {
        lay[0] = DUEL_TRAINING;
        n_lay = 1;
    }
    per_host = 2u * f->n_opp * n_lay;
    n = (size_t)size * per_host;
    err = duel_fixed_encode(f);
    if (err)
        return err;
    if (n > f->m_cap) {
        duel_match *m = (duel_match *)realloc(f->m, n * sizeof *m);
        if (m == NULL)
            return NEAT_E_NOMEM;
        f->m = m;
        f->m_cap = n;
    }
    /* a host's games consecutive (its network stays loaded): every opponent, layout, side */
    for (i = 0; i < size; i++)
        for (k = 0; k < f->n_opp; k++)
            for (l = 0; l < n_lay; l++)
                for (s = 0; s < 2; s++, at++) {
                    f->m[at].a = i;
                    f->m[at].b = size + k;
                    f->m[at].config = lay[l];
                    f->m[at].a_first = (uint8_t)(s == 0);
                    f->m[at].result = 0;
                }
    duel_games_set_training(dg, DUEL_TRAINING);
    err = duel_games_play_matches(dg, f->nets, (size_t)size + f->n_opp, f->m, n);
    if (err)
        return err;
    fit = (double *)malloc(size * sizeof *fit);
    if (fit == NULL)
        return NEAT_E_NOMEM;
    for (i = 0; i < size; i++) {
        int wins = 0, losses = 0;
        const duel_match *m = f->m + (size_t)i * per_host;
        for (k = 0; k < per_host; k++) {
            wins += m[k].result > 0;
            losses += m[k].result < 0;
        }
        fit[i] = f->fitness == DUEL_FIT_WINS ? (double)wins : (double)(wins - losses + (int)per_host);
        sum += fit[i];
        if (fit[i] > fit[best])
            best = i;
    }
    err = duel_fixed_tally(f, duel_games_rules(dg), best, f->m + (size_t)best * per_host, per_host, rep->best_vs);
    for (i = 0; i < size && err == 0; i++)
        err = neat_pop_set_fitness(f->pop, i, fit[i]);
    if (err == 0) {
        rep->generation = gen;
        rep->best_fitness = fit[best];
        rep->mean_fitness = sum / size;
        rep->best_index = best;
        rep->species = neat_pop_species_count(f->pop);
        rep->delta_t = neat_pop_delta_t(f->pop);
        for (i = 0; i < size; i++) {
            const neat_genome *g = neat_pop_genome(f->pop, i);
            rep->mean_hidden += neat_genome_hidden_count(g);
            rep->mean_conns += neat_genome_enabled_count(g);
        }
        rep->mean_hidden /= size;
        rep->mean_conns /= size;
        rep->best_hidden = neat_genome_hidden_count(neat_pop_genome(f->pop, best));
        rep->best_conns = neat_genome_enabled_count(neat_pop_genome(f->pop, best));
        rep->host_games = per_host;
        rep->games = n + per_host;
        err = neat_pop_epoch(f->pop);
    }
    free(fit);
    return err;
}
