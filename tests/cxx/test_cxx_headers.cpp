// test_cxx_headers.cpp - every public header from C++: it compiles as C++ and links against the C libraries (extern "C").
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "duel.h"
#include "neat.h"
#include "neat_coev.h"
#include "neat_duel_version.h"
#include "neat_phenotype.h"
#include "nrt.h"
#include "nrt_dense.h"

#define CHECK(cond)                                                                                      \
    do {                                                                                                 \
        if (!(cond)) {                                                                                   \
            std::fprintf(stderr, "test_cxx_headers: %s:%d: %s failed\n", __FILE__, __LINE__, #cond);     \
            return 1;                                                                                    \
        }                                                                                                \
    } while (0)

int main()
{
    // libneat: a minimal genome of the duel's shape, its blob
    neat_params p = neat_params_default();
    const char *field = nullptr;
    CHECK(neat_params_check(&p, &field) == NEAT_OK);
    neat_rng rng;
    neat_rng_seed(&rng, 2004);
    CHECK(neat_rng_below(&rng, 10) < 10);
    neat_genome g;
    neat_genome_init(&g);
    CHECK(neat_genome_minimal(&g, DUEL_N_INPUTS - 1, DUEL_N_OUTPUTS, nullptr) == NEAT_OK);
    std::vector<uint8_t> blob(neat_blob_size(&g));
    size_t len = 0;
    CHECK(neat_blob_write(&g, DUEL_N_INPUTS - 1, DUEL_N_OUTPUTS, blob.data(), blob.size(), &len) == NEAT_OK);
    neat_genome_free(&g, nullptr);
    neat_coev_params cp = neat_coev_params_default();
    CHECK(neat_coev_params_check(&cp, &field) == NEAT_OK);

    // the runtime: the blob loaded twice (one state per robot), stepped
    size_t need = 0;
    CHECK(nrt_mem_required(blob.data(), len, &need) == NRT_OK);
    std::vector<uint64_t> mem_a(need / 8 + 1), mem_b(need / 8 + 1);
    nrt_net a, b;
    CHECK(nrt_load(&a, blob.data(), len, mem_a.data(), need) == NRT_OK);
    CHECK(nrt_load(&b, blob.data(), len, mem_b.data(), need) == NRT_OK);
    nrt_step(&a, nrt_inputs(&a), nullptr);
    CHECK(nrt_outputs(&a) != nullptr);
    nrt_reset(&a);
    static nrt_dense d; // NRT_E_ARG where there is no dense step: both are answers
    int dense = nrt_dense_make(&d, &a);
    CHECK(dense == NRT_OK || dense == NRT_E_ARG);

    // duelsim: the two networks in one game, and a builtin
    duel_controller west = {&a, 0}, east = {&b, 0};
    duel_result r;
    CHECK(duel_play(&west, &east, DUEL_TRAINING, &r, nullptr, nullptr) == DUEL_OK);
    CHECK(r.steps > 0 && duel_outcome_text(r.outcome) != nullptr);
    CHECK(duel_builtin_parse("forager") == DUEL_FORAGER);

    // neat_phenotype.h: the genome as a network, through the allocation hook's default
    neat_phenotype ph;
    neat_phenotype_init(&ph, nullptr);
    p.n_inputs = DUEL_N_INPUTS - 1;
    p.n_outputs = DUEL_N_OUTPUTS;
    neat_genome_init(&g);
    CHECK(neat_genome_minimal(&g, DUEL_N_INPUTS - 1, DUEL_N_OUTPUTS, nullptr) == NEAT_OK);
    CHECK(neat_phenotype_load(&ph, &g, &p) == 0 && ph.net.n_inputs == DUEL_N_INPUTS);
    CHECK(neat_q15(1.0) == NRT_ONE && neat_from_q15(0) == 0.0);
    neat_phenotype_free(&ph);
    neat_genome_free(&g, nullptr);
    // one version everywhere (neat_duel_version.h)
    CHECK(NEAT_VERSION_MAJOR == NRT_VERSION_MAJOR && NEAT_VERSION_MINOR == NRT_VERSION_MINOR);
    CHECK(NEAT_DUEL_VERSION_STRING[0] != '\0');
    std::printf("C++: every public header; a game of %u steps: %s\n", (unsigned)r.steps, duel_outcome_text(r.outcome));
    return 0;
}
