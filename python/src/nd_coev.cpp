// nd_coev.cpp - neat_duel.Coevolution: two populations coevolved by the 2004 paper's protocol (libneat's
// neat_coev: hosts against parasites and a hall of fame, the dominance tournament) over a game written in Python,
// or over the built-in robot duel played in C on every core (nd_duel.cpp).
#include <cstring>
#include <exception>
#include <unordered_map>

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "nd.h"
#include "neat_coev.h"

#define ND_CKPT_MAX ((size_t)1 << 30)


static neat_coev *nd_c(const nd_coev &s)
{
    if (s.c == nullptr)
        throw nd_error(NEAT_E_STATE, "the coevolution is not there (a failed load)");
    return s.c;
}

static const char nd_busy_msg[] = ": this Coevolution is already playing a generation (called from its game function, "
                                  "or from another thread while it plays): one call at a time";

// nd_c for every call that reads or changes the populations: refused while a generation is played.
static neat_coev *nd_c_idle(const nd_coev &s, const char *what)
{
    if (s.busy.load() != 0)
        throw nd_error(NEAT_E_STATE, std::string(what) + nd_busy_msg);
    return nd_c(s);
}

// Marks a generation in play for its lifetime (refusing a second one).
struct nd_busy {
    nd_coev &s;
    nd_busy(nd_coev &s_, const char *what) : s(s_)
    {
        nd_c(s);
        if (s.busy.exchange(1) != 0)
            throw nd_error(NEAT_E_STATE, std::string(what) + nd_busy_msg);
    }
    ~nd_busy() { s.busy.store(0); }
    nd_busy(const nd_busy &) = delete;
    nd_busy &operator=(const nd_busy &) = delete;
};

// A batch of games played by a Python function play(a, b, config, a_first, seed) -> 1, -1 or 0. The networks of a
// batch are built once per genome; each game starts from reset networks. A Python exception must not cross
// libneat's C frames: it is kept here, the batch fails, and it is raised again once neat_coev_step has returned
// (the coevolution then unchanged).
struct nd_pyplay {
    nb::callable play;
    const neat_params *params;
    std::exception_ptr error;
};

static int nd_pyplay_batch(void *ud, neat_game *games, size_t n)
{
    nd_pyplay *P = (nd_pyplay *)ud;
    try {
        std::unordered_map<const neat_genome *, nb::object> nets;
        auto net = [&](const neat_genome *g) -> nb::object {
            auto it = nets.find(g);
            if (it != nets.end())
                return it->second;
            nd_network *n = new nd_network();
            int err = neat_phenotype_load(&n->ph, g, P->params);
            if (err) {
                delete n;
                nd_fail(err, "a genome's network");
            }
            n->sized();
            nb::object o = nb::cast(n, nb::rv_policy::take_ownership);
            nets.emplace(g, o);
            return o;
        };
        for (size_t i = 0; i < n; i++) {
            nb::object a = net(games[i].a), b = net(games[i].b);
            nrt_reset(&nb::cast<nd_network &>(a).ph.net);
            nrt_reset(&nb::cast<nd_network &>(b).ph.net);
            nb::object r = P->play(a, b, games[i].config, (bool)games[i].a_first, games[i].seed);
            long v = 2;
            if (!nb::try_cast<long>(r, v) || v < -1 || v > 1)
                throw nb::value_error(("the game returned " + nb::cast<std::string>(nb::repr(r)) +
                                       ": 1 (a won), -1 (b won) or 0 (neither)").c_str());
            games[i].result = (int8_t)v;
        }
        return 0;
    } catch (...) {
        P->error = std::current_exception();
        return NEAT_E_STATE;
    }
}

static nb::dict nd_pop_report(const neat_coev_pop_report &p)
{
    nb::dict d;
    d["best_fitness"] = p.best_fitness;
    d["mean_fitness"] = p.mean_fitness;
    d["best_index"] = p.best_index;
    d["species"] = p.species;
    d["delta_t"] = p.delta_t;
    d["mean_hidden"] = p.mean_hidden;
    d["mean_connections"] = p.mean_conns;
    d["best_hidden"] = p.best_hidden;
    d["best_connections"] = p.best_conns;
    d["games"] = p.games;
    return d;
}

static nb::dict nd_report(const neat_coev_report &r)
{
    nb::dict d;
    d["generation"] = r.generation;
    d["A"] = nd_pop_report(r.pop[0]);
    d["B"] = nd_pop_report(r.pop[1]);
    d["champion"] = r.champion_pop == 0 ? "A" : "B";
    d["champion_wins"] = nb::make_tuple(r.champion_wins[0], r.champion_wins[1]);
    d["dominants"] = r.dominants;
    d["new_dominant"] = r.new_dominant != 0;
    d["dominance_games"] = r.dominance_games;
    d["games"] = r.games;
    return d;
}

// One generation with game: a Python function, or a built-in game object that plays in C (nd_duel.cpp).
static nb::dict nd_step(nd_coev &s, nb::handle game)
{
    nd_busy busy(s, "step");
    neat_coev *c = s.c;
    neat_coev_report rep;
    std::memset(&rep, 0, sizeof rep);
    nd_native_game native;
    if (nd_native_game_of(game, c, &native)) {
        int err;
        {
            nb::gil_scoped_release nogil;
            err = neat_coev_step(c, native.play, native.ud, &rep);
        }
        if (err)
            nd_fail(err, "generation " + std::to_string(neat_coev_generation(c)));
        return nd_report(rep);
    }
    if (!PyCallable_Check(game.ptr()))
        throw nb::type_error("game: a function play(a, b, config, a_first, seed) -> 1, -1 or 0, or neat_duel.Duel");
    nd_pyplay P{nb::borrow<nb::callable>(game), neat_pop_params(neat_coev_pop(c, 0)), nullptr};
    int err = neat_coev_step(c, nd_pyplay_batch, &P, &rep);
    if (P.error)
        std::rethrow_exception(P.error);
    if (err)
        nd_fail(err, "generation " + std::to_string(neat_coev_generation(c)));
    return nd_report(rep);
}

static nb::bytes nd_coev_bytes(const nd_coev &s)
{
    uint8_t *buf = nullptr;
    size_t len = 0;
    int err = neat_coev_save(nd_c_idle(s, "saving"), &buf, &len);
    if (err)
        nd_fail(err, "saving the coevolution");
    nb::bytes b((const char *)buf, len);
    neat_coev_buf_free(s.c, buf, len);
    return b;
}

static nd_coev *nd_coev_from_bytes(const uint8_t *b, size_t len, const std::string &name)
{
    nd_coev *r = new nd_coev();
    size_t off = 0;
    int err = neat_coev_load(&r->c, b, len, nullptr, &off);
    if (err) {
        delete r;
        throw nd_error(err, name + ": " + nd_strerror(err) + " at byte offset " + std::to_string(off), name,
                       (long long)off);
    }
    return r;
}

nd_coev *nd_coev_wrap(neat_coev *c)
{
    nd_coev *r = new nd_coev();
    r->c = c;
    return r;
}

void nd_bind_coev(nb::module_ &m)
{
    nb::class_<nd_coev> coev = nb::class_<nd_coev>(m, "Coevolution",
                        "Competitive coevolution (Stanley & Miikkulainen 2004, section 5): two populations, A and B,\n"
                        "each host playing the other population's best species' champions and its hall of fame;\n"
                        "the dominance tournament records every new dominant strategy. The game is yours (a Python\n"
                        "function) or the built-in robot duel (neat_duel.Duel), played in C on every core.")
        .def("__init__", [](nd_coev *self, const nd_params &params, nb::int_ seed_arg, const nd_genome *start,
                            uint32_t species_opponents, uint32_t hof_opponents, uint32_t first_opponents,
                            uint32_t compare_configs, bool random_fitness) {
                uint64_t seed = nd_u64(seed_arg, "seed");
                new (self) nd_coev();
                neat_coev_params cp = neat_coev_params_default();
                cp.species_opponents = species_opponents;
                cp.hof_opponents = hof_opponents;
                cp.first_opponents = first_opponents;
                cp.compare_configs = compare_configs;
                cp.random_fitness = random_fitness;
                const char *field = nullptr;
                if (neat_coev_params_check(&cp, &field) != NEAT_OK)
                    throw nd_error(NEAT_E_PARAM, std::string(field ? field : "?") + " out of range");
                if (neat_params_check(&params.p, &field) != NEAT_OK)
                    throw nd_error(NEAT_E_PARAM, std::string("parameter ") + (field ? field : "?") + " out of range");
                if (params.p.pop_stagnation != 0)
                    throw nd_error(NEAT_E_PARAM, "pop_stagnation must be 0 in a coevolution (Params(pop_stagnation=0):"
                                                 " a count of wins against changing opponents is not an absolute "
                                                 "fitness, neat_coev.h)");
                neat_start st;
                st.genome = start != nullptr ? &start->gen() : nullptr;
                st.keep_weights = 0;
                int err = neat_coev_create(&self->c, &params.p, &cp, start != nullptr ? &st : nullptr, seed, nullptr);
                if (err)
                    nd_fail(err, "creating the coevolution");
            }, nb::arg("params"), nb::arg("seed") = 0, nb::arg("start") = nb::none(), nb::kw_only(),
            nb::arg("species_opponents") = 4, nb::arg("hof_opponents") = 8, nb::arg("first_opponents") = 12,
            nb::arg("compare_configs") = 144, nb::arg("random_fitness") = false,
            "Two populations of params from seed (the protocol's defaults are the paper's: 4 species\n"
            "champions and 8 hall-of-fame members a host, 12 opponents in generation 0, 144 comparison\n"
            "configurations, each played from both sides). random_fitness: the paper's Figure 7 control.")
        .def("step", &nd_step, nb::arg("game"),
             nb::sig("def step(self, game: collections.abc.Callable[[Network, Network, int, bool, int], int] | Duel) "
                     "-> dict[str, typing.Any]"),
             "One generation. game(a, b, config, a_first, seed) plays network a against b and returns 1 (a\n"
             "won), -1 (b won) or 0; config is -1 for a training game, else the comparison configuration;\n"
             "a_first says whether a takes the first side; seed is the game's own (the same on every\n"
             "machine). Returns the generation's record. A game that raises stops the generation: the\n"
             "exception goes through and the coevolution is unchanged.")
        .def("run", [](nd_coev &s, nb::handle game, nb::int_ gens, nb::object until) {
                uint32_t generations = nd_u32(gens, "generations", 1);
                nb::list out;
                for (uint32_t g = 0; g < generations; g++) {
                    nb::dict r = nd_step(s, game);
                    out.append(r);
                    if (!until.is_none() && nd_truth(until(r)))
                        break;
                    // Ctrl-C between generations (a generation played in C is whole, and the state consistent)
                    if (PyErr_CheckSignals() != 0)
                        throw nb::python_error();
                }
                return out;
            }, nb::arg("game"), nb::arg("generations"), nb::arg("until") = nb::none(),
            nb::sig("def run(self, game: collections.abc.Callable[[Network, Network, int, bool, int], int] | Duel, "
                    "generations: int, until: collections.abc.Callable[[dict[str, typing.Any]], bool] | None = None)"
                    " -> list[dict[str, typing.Any]]"),
            "step for generations (fewer if until(record) says so): the records.")
        .def_prop_ro("generation", [](const nd_coev &s) { return neat_coev_generation(nd_c(s)); },
                     "The next generation to play.")
        .def_prop_ro("seed", [](const nd_coev &s) { return neat_coev_seed(nd_c(s)); }, "Its seed.")
        .def("population", [](const nd_coev &s, const std::string &which) {
                if (which != "A" && which != "B")
                    throw nd_error(NEAT_E_ARG, "population: 'A' or 'B'");
                const neat_pop *p = neat_coev_pop(nd_c_idle(s, "population"), which == "A" ? 0 : 1);
                std::vector<nb::object> v;
                for (uint32_t i = 0; i < neat_pop_size(p); i++)
                    v.push_back(nb::cast(nd_genome_copy(neat_pop_genome(p, i), *neat_pop_params(p))));
                return v;
            }, nb::arg("which"), nb::sig("def population(self, which: str) -> list[Genome]"),
            "Copies of population 'A' or 'B''s genomes.")
        .def_prop_ro("champion", [](const nd_coev &s) -> nb::object {
                const neat_genome *g = neat_coev_champion(nd_c_idle(s, "champion"));
                if (g == nullptr)
                    return nb::none();
                return nb::cast(nd_genome_copy(g, *neat_pop_params(neat_coev_pop(s.c, 0))));
            }, nb::sig("def champion(self) -> Genome | None"), "The last generation's champion (None before one).")
        .def("hall_of_fame", [](const nd_coev &s, const std::string &which) {
                if (which != "A" && which != "B")
                    throw nd_error(NEAT_E_ARG, "hall_of_fame: 'A' or 'B'");
                neat_coev *c = nd_c_idle(s, "hall_of_fame");
                uint32_t w = which == "A" ? 0 : 1;
                std::vector<nb::object> v;
                for (uint32_t g = 0; g < neat_coev_hof_count(c, w); g++)
                    v.push_back(nb::cast(nd_genome_copy(neat_coev_hof(c, w, g), *neat_pop_params(neat_coev_pop(c, 0)))));
                return v;
            }, nb::arg("which"), nb::sig("def hall_of_fame(self, which: str) -> list[Genome]"),
            "The hall of fame of 'A' or 'B': its best of every generation, oldest first.")
        .def("dominants", [](const nd_coev &s) {
                neat_coev *c = nd_c_idle(s, "dominants");
                nb::list out;
                for (uint32_t k = 0; k < neat_coev_dominant_count(c); k++) {
                    neat_dominant d;
                    if (neat_coev_dominant(c, k, &d) != NEAT_OK)
                        continue;
                    nb::dict r;
                    r["level"] = k + 1;
                    r["generation"] = d.generation;
                    r["population"] = d.pop == 0 ? "A" : "B";
                    r["genome"] = nb::cast(nd_genome_copy(d.genome, *neat_pop_params(neat_coev_pop(c, 0))));
                    std::vector<uint32_t> w(d.wins, d.wins + d.n_beaten), l(d.losses, d.losses + d.n_beaten);
                    r["wins"] = w;
                    r["losses"] = l;
                    out.append(r);
                }
                return out;
            }, nb::sig("def dominants(self) -> list[dict[str, typing.Any]]"),
            "The dominance tournament: level, generation, population, genome, and its wins and losses\n"
            "against every earlier dominant (the last one first, as played).")
        .def("to_bytes", &nd_coev_bytes, "The whole state as a coevolution checkpoint (docs/formats.md).")
        .def("save", [](const nd_coev &s, const nd_path &fpath) {
                const std::string path = fpath.string();
                nb::bytes b = nd_coev_bytes(s);
                nd_write_file(path, (const uint8_t *)b.c_str(), b.size());
            }, nb::arg("path"), "Writes the checkpoint through a temporary file and a rename.")
        .def("__repr__", [](const nd_coev &s) {
                neat_coev *c = nd_c(s);
                return "Coevolution(2 x " + std::to_string(neat_pop_size(neat_coev_pop(c, 0))) + " genomes, generation " +
                       std::to_string(neat_coev_generation(c)) + ", " + std::to_string(neat_coev_dominant_count(c)) +
                       " dominants)";
            });
    nd_def_file_loaders(coev, nd_coev_from_bytes, ND_CKPT_MAX, "from_bytes", "data",
                        "A checkpoint's bytes, checked before any is trusted (FormatError names the byte offset).",
                        "Reads a coevolution checkpoint: Coevolution.save's, or a duel_evolve run's checkpoint.bin.");
}
