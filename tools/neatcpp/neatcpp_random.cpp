// neatcpp_random.cpp - the NEAT C++ release's random state, made the same at the start of every run.
#include "neatcpp_random.h"

#include <stdlib.h>

// the release's neat.h (NEAT::gaussrand) through one of its headers: a bare "neat.h" is libneat's
#include "genome.h"

void neatcpp_reset_random(uint32_t seed32)
{
    // whether a call of gaussrand drew from rand() shows in rand()'s sequence
    int fresh, after;
    srand(1);
    fresh = rand();
    srand(1);
    (void)NEAT::gaussrand();
    after = rand();
    // it drew two uniforms and kept the second deviate: one more call spends it
    // (otherwise it returned the spare without drawing, and none is left)
    if (after != fresh)
        (void)NEAT::gaussrand();
    srand(seed32);
}
