// neatcpp_random.h - the NEAT C++ release's random state, made the same at the start of every run.
#ifndef NEATCPP_RANDOM_H
#define NEATCPP_RANDOM_H

#include <stdint.h>

// The release's only generator is the C library's rand() (neat.h: randfloat,
// randint, randposneg), seeded nowhere in the linked code (neatmain.cpp's
// srand(time) is not linked); but NEAT::gaussrand keeps a spare deviate in a
// function static between calls, so a run could inherit one from the run
// before it in the same process. This spends any spare, then seeds rand()
// with seed32, without touching the release's sources.
void neatcpp_reset_random(uint32_t seed32);

#endif // NEATCPP_RANDOM_H
