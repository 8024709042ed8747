// neatcpp_native.h - the release's own evaluation (experiments.cpp: its network activation), a context row only.
#ifndef NEATCPP_NATIVE_H
#define NEATCPP_NATIVE_H

namespace NEAT {
class Organism;
}

// experiments.cpp's xor_evaluate: sets o->fitness and o->winner; 1 if solved.
// A network whose depth search would not end in practice (a cycle with
// branches: more than 10^8 NNode::depth calls) gets the release's fitness of
// a network it cannot activate, 0.001, and *hopeless = 1.
int neatcpp_native_xor(NEAT::Organism *o, int *hopeless);
// experiments.cpp's pole2_evaluate with velocities on a CartPole made once
// per run (neatcpp_native_cart_new / _free): fitness = its step count.
void *neatcpp_native_cart_new(void);
void neatcpp_native_cart_free(void *cart);
int neatcpp_native_pole_markov(NEAT::Organism *o, void *cart);

#endif // NEATCPP_NATIVE_H
