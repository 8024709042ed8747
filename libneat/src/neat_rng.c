/* neat_rng.c - libneat's own PRNG (xoshiro256**, splitmix64 seeding), its normal draws, and per-game seed derivation. */
#include <math.h>

#include "neat_internal.h"

static uint64_t neat_splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void neat_rng_seed(neat_rng *rng, uint64_t seed)
{
    int i;
    for (i = 0; i < 4; i++)
        rng->s[i] = neat_splitmix64(&seed);
}

/* xoshiro256**, its draws inline in neat_internal.h for libneat's own modules */
uint64_t neat_rng_next(neat_rng *rng)
{
    return neat_rng_next_inl(rng);
}

double neat_rng_uniform(neat_rng *rng)
{
    return neat_rng_uniform_inl(rng);
}

uint32_t neat_rng_below(neat_rng *rng, uint32_t n)
{
    return neat_rng_below_inl(rng, n);
}

uint64_t neat_seed_derive(uint64_t base, const uint64_t *keys, size_t n_keys)
{
    /* Every input passes through the splitmix64 bijection before it is
     * combined, so (base, keys) pairs cannot cancel out the way a plain
     * base ^ key would (base 1, run r and base 2, run r ^ 3 colliding). */
    uint64_t h = base, st;
    size_t i;
    st = h;
    h = neat_splitmix64(&st);
    for (i = 0; i < n_keys; i++) {
        uint64_t k = keys[i] + 0xD1B54A32D192ED03ull * (uint64_t)(i + 1);
        st = k;
        k = neat_splitmix64(&st);
        st = h ^ k;
        h = neat_splitmix64(&st);
    }
    return h;
}

double neat_rng_gauss(neat_rng *rng)
{
    /* Marsaglia's polar method; the second value of each pair is dropped so
     * that the PRNG is the only state (NEAT C++'s gaussrand keeps it in a static) */
    double u, v, s;
    do {
        u = 2.0 * neat_rng_uniform_inl(rng) - 1.0;
        v = 2.0 * neat_rng_uniform_inl(rng) - 1.0;
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    return u * sqrt(-2.0 * log(s) / s);
}
