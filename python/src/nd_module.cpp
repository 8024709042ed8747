// nd_module.cpp - the extension module neat_duel._core: the C libraries' objects, bound one file a concept.
#include <nanobind/stl/vector.h>

#include "nd.h"

NB_MODULE(_core, m)
{
    m.doc() = "neat_duel's C core (libneat, the runtime, duelsim): use it through the package neat_duel";
    m.attr("VERSION") = NEAT_DUEL_VERSION_STRING;
    m.attr("Q15_ONE") = (int)NRT_ONE;
    nd_bind_errors(m);
    nd_bind_params(m);
    nd_bind_genome(m);
    nd_bind_network(m);
    nd_bind_population(m);
    nd_bind_coev(m);
    nd_bind_duel(m);
    nd_bind_run(m);
    nd_bind_engine(m);
    nd_bind_env(m);
    m.def("seed_derive", [](uint64_t base, const std::vector<uint64_t> &keys) {
            return neat_seed_derive(base, keys.data(), keys.size());
        }, nb::arg("base"), nb::arg("keys"),
        "The seed libneat derives from a base seed and a tuple of keys (neat_bench's run r: keys [r]).");
    m.def("q15", [](double x) { return (int)neat_q15(x); }, nb::arg("x"),
          "A value as the runtime's Q1.15 (rounded to nearest, saturated to [-1, 1); NaN is 0).");
    m.def("from_q15", [](int q) {
            if (q < -32768 || q > 32767)
                throw nd_error(NEAT_E_ARG, "from_q15: " + std::to_string(q) + " is not a Q1.15 value");
            return neat_from_q15((nrt_q15)q);
        }, nb::arg("q"), "A Q1.15 value as a float (exact).");
}
