// neatcpp_native.cpp - calls the release's xor_evaluate and pole2_evaluate (compiled as C++98: experiments.h needs it).
#include "neatcpp_native.h"

#include <map>
#include <utility>
#include <vector>

#include "experiments.h"

namespace {
// Calls NNode::depth(d) makes from node n (nnode.cpp): it recurses into every
// incoming link, cycles included, until d > 100; memoised by (node, d), capped.
double depth_calls(NEAT::NNode *n, int d, std::map<std::pair<NEAT::NNode *, int>, double> &memo, double cap)
{
    if (d > 100 || n->type == NEAT::SENSOR)
        return 1.0;
    std::pair<NEAT::NNode *, int> key(n, d);
    std::map<std::pair<NEAT::NNode *, int>, double>::iterator it = memo.find(key);
    if (it != memo.end())
        return it->second;
    double calls = 1.0;
    for (std::vector<NEAT::Link *>::iterator l = n->incoming.begin(); l != n->incoming.end() && calls <= cap; ++l)
        calls += depth_calls((*l)->in_node, d + 1, memo, cap);
    memo[key] = calls;
    return calls;
}
} // namespace

int neatcpp_native_xor(NEAT::Organism *o, int *hopeless)
{
    // xor_evaluate starts with Network::max_depth, whose search is exponential
    // in a network with a cycle (the release makes some even without
    // recurrence, e.g. by crossover): beyond 10^8 calls, do what the release
    // does with a network it cannot activate (fitness 0.001, not a winner)
    // instead of running for hours, and say so
    std::map<std::pair<NEAT::NNode *, int>, double> memo;
    double calls = 0.0, cap = 1e8;
    for (std::vector<NEAT::NNode *>::iterator n = o->net->outputs.begin(); n != o->net->outputs.end(); ++n)
        calls += depth_calls(*n, 0, memo, cap);
    if (calls > cap) {
        o->fitness = 0.001;
        o->winner = false;
        *hopeless = 1;
        return 0;
    }
    *hopeless = 0;
    return xor_evaluate(o) ? 1 : 0;
}

namespace {
// CartPole is polymorphic without a virtual destructor: held by value in a
// plain struct, it is destroyed as exactly what it is
struct cart_box {
    CartPole cart;
    // pole2_test's cart for the Markov task: CartPole(true, velocity = 1)
    cart_box() : cart(true, true)
    {
        cart.nmarkov_long = false;
        cart.generalization_test = false;
    }
};
} // namespace

void *neatcpp_native_cart_new(void)
{
    return new cart_box();
}

void neatcpp_native_cart_free(void *cart)
{
    delete static_cast<cart_box *>(cart);
}

int neatcpp_native_pole_markov(NEAT::Organism *o, void *cart)
{
    return pole2_evaluate(o, true, &static_cast<cart_box *>(cart)->cart) ? 1 : 0;
}
