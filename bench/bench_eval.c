/* bench_eval.c - the per-network evaluators of XOR and double pole balancing (one network in, a fitness out). */
#include <math.h>

#include "bench_eval.h"

int bench_xor_eval(neat_phenotype *ph, double *fitness)
{
    static const int pat[4][3] = {{0, 0, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 0}};
    double err = 0.0;
    int k, correct = 1;
    for (k = 0; k < 4; k++) {
        nrt_q15 in[3], out[1];
        double o;
        in[0] = NRT_ONE;
        in[1] = pat[k][0] ? NRT_ONE : 0;
        in[2] = pat[k][1] ? NRT_ONE : 0;
        nrt_reset(&ph->net);
        /* feed-forward: propagate until nothing changes (depth <= nodes) */
        (void)nrt_settle(&ph->net, in, out, ph->net.n_nodes + 1);
        o = neat_from_q15(out[0]);
        err += fabs(o - pat[k][2]);
        if ((o >= 0.5) != (pat[k][2] == 1))
            correct = 0;
    }
    *fitness = (4.0 - err) * (4.0 - err);
    return correct;
}

/* Network inputs, scaled as in the C++ release; input 0 is the bias. */
static void bench_pole_inputs(const cartpole *c, int markov, nrt_q15 *in)
{
    in[0] = NRT_ONE;
    if (markov) {
        in[1] = neat_q15(c->s[0] / 4.8);
        in[2] = neat_q15(c->s[1] / 2.0);
        in[3] = neat_q15(c->s[2] / 0.52);
        in[4] = neat_q15(c->s[3] / 2.0);
        in[5] = neat_q15(c->s[4] / 0.52);
        in[6] = neat_q15(c->s[5] / 2.0);
    } else {
        in[1] = neat_q15(c->s[0] / 4.8);
        in[2] = neat_q15(c->s[2] / 0.52);
        in[3] = neat_q15(c->s[4] / 0.52);
    }
}

void bench_pole_step(neat_phenotype *ph, cartpole *c, int markov)
{
    nrt_q15 in[7], out[1];
    bench_pole_inputs(c, markov, in);
    nrt_step(&ph->net, in, out);
    cartpole_act(c, (neat_from_q15(out[0]) - 0.5) * 20.0);
}

uint32_t bench_pole_balance(neat_phenotype *ph, cartpole *c, int markov, uint32_t max_steps)
{
    uint32_t t;
    nrt_reset(&ph->net);
    for (t = 0; t < max_steps; t++) {
        bench_pole_step(ph, c, markov);
        if (cartpole_failed(c))
            return t;
    }
    return max_steps;
}

uint32_t bench_pole_markov(neat_phenotype *ph, uint32_t max_steps)
{
    cartpole c;
    cartpole_init(&c);
    return bench_pole_balance(ph, &c, 1, max_steps);
}
