/* coev_game.c - competitive coevolution (neat_coev.h) on a game of our own, not the robot duel: race to ten. */
#include <stdio.h>

#include "neat.h"
#include "neat_coev.h"
#include "neat_phenotype.h"
#include "nrt.h"

/*
 * Race to ten: a counter starts at 0..3; the players take turns adding 1 or
 * 2, and whoever brings it to 10 wins. The position with r still to go is
 * won by the player to move unless r is a multiple of 3 (take r mod 3, then
 * answer 1 with 2 and 2 with 1), so there is a best play to discover, and
 * the start and who moves first decide the game between two perfect players.
 * A network sees r in binary (4 inputs) and takes 2 when its output is at
 * least 0.5. libneat knows nothing of this: it hands out pairs of genomes,
 * the callback below says who won.
 */
#define GOAL 10
#define STARTS 4        /* comparison configurations: starts 0..3, each from both sides */
#define GENERATIONS 40

/* 1 or 2: the network's move with r to go. */
static int move(neat_phenotype *ph, int r)
{
    nrt_q15 *in, out;
    int b;
    nrt_reset(&ph->net);
    in = nrt_inputs(&ph->net);
    in[0] = NRT_ONE; /* the bias */
    for (b = 0; b < 4; b++)
        in[1 + b] = r >> b & 1 ? NRT_ONE : 0;
    nrt_settle(&ph->net, in, &out, 20);
    return out >= NRT_ONE / 2 ? 2 : 1;
}

typedef struct game_ctx {
    neat_phenotype ph[2]; /* one network per player (one thread plays every game) */
    const neat_params *p;
} game_ctx;

/* The batch callback: every game of the batch, a against b, the result 1 (a won) or -1 (b won). */
static int play(void *ud, neat_game *games, size_t n)
{
    game_ctx *x = ud;
    size_t k;
    for (k = 0; k < n; k++) {
        neat_game *gm = &games[k];
        /* training games start where the game's seed says, comparisons where the configuration says */
        int count = gm->config < 0 ? (int)(gm->seed % STARTS) : gm->config;
        int turn = gm->a_first ? 0 : 1; /* 0: a to move */
        if (neat_phenotype_load(&x->ph[0], gm->a, x->p) || neat_phenotype_load(&x->ph[1], gm->b, x->p))
            return NEAT_E_NOMEM; /* stops the generation; neat_coev_step returns it */
        for (;;) {
            count += move(&x->ph[turn], GOAL - count);
            if (count >= GOAL)
                break;
            turn ^= 1;
        }
        gm->result = (int8_t)(turn == 0 ? 1 : -1);
    }
    return 0;
}

int main(void)
{
    neat_params p = neat_params_default();
    neat_coev_params cp = neat_coev_params_default();
    neat_coev_report rep;
    neat_coev *c;
    game_ctx x;
    int r, best = 0, err = NEAT_OK;
    uint32_t gen;
    p.n_inputs = 4, p.n_outputs = 1, p.pop_size = 60, p.allow_recurrent = 0; /* a move from the position alone */
    p.pop_stagnation = 0; /* neat_coev_create requires it: fitness here is wins, relative to the opponents */
    cp.compare_configs = STARTS;
    if (neat_coev_create(&c, &p, &cp, NULL, 7, NULL) != NEAT_OK)
        return 2;
    x.p = &p;
    neat_phenotype_init(&x.ph[0], NULL);
    neat_phenotype_init(&x.ph[1], NULL);
    for (gen = 0; gen < GENERATIONS && err == NEAT_OK; gen++) {
        err = neat_coev_step(c, play, &x, &rep);
        if (err == NEAT_OK && (rep.new_dominant || gen + 1 == GENERATIONS))
            printf("generation %2u: dominance level %u, best wins %.0f / %.0f\n", (unsigned)rep.generation,
                   (unsigned)rep.dominants, rep.pop[0].best_fitness, rep.pop[1].best_fitness);
    }
    /* the last champion against the known best play, over the 7 positions a player to move can win */
    if (err == NEAT_OK && neat_phenotype_load(&x.ph[0], neat_coev_champion(c), &p) == 0) {
        for (r = 1; r <= GOAL; r++)
            best += r % 3 != 0 && move(&x.ph[0], r) == r % 3;
        printf("champion: the winning move in %d of 7 winnable positions\n", best);
    }
    neat_phenotype_free(&x.ph[0]);
    neat_phenotype_free(&x.ph[1]);
    neat_coev_free(c);
    if (err != NEAT_OK)
        fprintf(stderr, "coev_game: %s\n", neat_strerror(err));
    return err == NEAT_OK && rep.dominants >= 1 ? 0 : 1; /* the tournament found at least one dominant */
}
