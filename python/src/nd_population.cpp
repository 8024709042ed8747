// nd_population.cpp - neat_duel.Population: a NEAT population (libneat's neat_pop) evolved from Python, genome by
// genome through a fitness callback or a whole generation at once through numpy (Networks), saved and loaded as
// libneat checkpoints.
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "nd.h"

#define ND_CKPT_MAX ((size_t)1 << 30) // duel_evolve's limit for checkpoints (DUEL_CKPT_MAX)

struct nd_population {
    neat_pop *pop = nullptr;
    bool running = false; // inside run(): its fitness calls borrow the genomes an epoch would free
    nd_population() = default;
    nd_population(const nd_population &) = delete;
    nd_population &operator=(const nd_population &) = delete;
    ~nd_population() { neat_pop_free(pop); }
};

// One generation's network buffers, bump-allocated from a few large blocks and released together: a generation's
// phenotypes cost a few allocations instead of two each (libneat's allocation hook, neat_alloc).
struct nd_arena {
    std::vector<uint8_t *> blocks;
    size_t used = 0, cap = 0;
    nd_arena() = default;
    nd_arena(const nd_arena &) = delete;
    nd_arena &operator=(const nd_arena &) = delete;
    ~nd_arena()
    {
        for (uint8_t *b : blocks)
            std::free(b);
    }
    static void *fn(void *ud, void *ptr, size_t old_size, size_t new_size)
    {
        nd_arena *a = (nd_arena *)ud;
        if (new_size == 0)
            return nullptr; // released with the arena
        size_t need = (new_size + 15) & ~(size_t)15;
        if (a->used + need > a->cap) {
            size_t sz = need > ((size_t)64 << 10) ? need : ((size_t)64 << 10);
            uint8_t *b = (uint8_t *)std::malloc(sz);
            if (b == nullptr)
                return nullptr;
            a->blocks.push_back(b);
            a->used = 0;
            a->cap = sz;
        }
        uint8_t *r = a->blocks.back() + a->used;
        a->used += need;
        if (ptr != nullptr)
            std::memcpy(r, ptr, old_size < new_size ? old_size : new_size);
        return r;
    }
};

// Every network of a generation, stepped together in C.
struct nd_networks {
    nd_arena arena; // declared first: destroyed after the phenotypes
    std::vector<neat_phenotype> ph;
    uint32_t n_in = 0, n_out = 0; // without the bias
    nd_networks() = default;
    nd_networks(const nd_networks &) = delete;
    nd_networks &operator=(const nd_networks &) = delete;
    ~nd_networks()
    {
        for (auto &p : ph)
            neat_phenotype_free(&p);
    }
};

using in_any = nb::ndarray<const double, nb::c_contig, nb::device::cpu>;
using batch_out = nb::ndarray<nb::numpy, double, nb::ndim<2>>;
using fit_in = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

static neat_pop *nd_pop(const nd_population &s)
{
    if (s.pop == nullptr)
        throw nd_error(NEAT_E_STATE, "the population is not there (a failed load)");
    return s.pop;
}

// For the calls that change the generation: refused while run() evaluates it.
static neat_pop *nd_pop_idle(const nd_population &s, const char *what)
{
    if (s.running)
        throw nd_error(NEAT_E_STATE, std::string(what) + ": not from inside run()'s fitness function (run() is " +
                                         "evaluating this generation)");
    return nd_pop(s);
}

static void nd_fitness_fail(int err, uint32_t i, double f)
{
    throw nd_error(err, "genome " + std::to_string(i) + ": fitness " + std::to_string(f) +
                            ": a fitness must be finite and not negative (" + nd_strerror(err) + ")",
                   "", -1, i);
}

static nd_networks *nd_networks_of(const nd_population &s)
{
    neat_pop *pop = nd_pop(s);
    const neat_params *p = neat_pop_params(pop);
    uint32_t n = neat_pop_size(pop);
    nd_networks *b = new nd_networks();
    b->n_in = p->n_inputs;
    b->n_out = p->n_outputs;
    b->ph.resize(n);
    neat_alloc a;
    a.fn = &nd_arena::fn;
    a.ud = &b->arena;
    for (auto &ph : b->ph)
        neat_phenotype_init(&ph, &a);
    for (uint32_t i = 0; i < n; i++) {
        int err = neat_phenotype_load(&b->ph[i], neat_pop_genome(pop, i), p);
        if (err) {
            delete b;
            nd_fail(err, "genome " + std::to_string(i) + "'s network");
        }
    }
    return b;
}

// Steps (settle: max_steps >= 0, or -1 for each network's nodes + 1; step: max_steps == -2) every network with
// its row of x (or all with the one row), into a new (networks, outputs) array.
static batch_out nd_batch(nd_networks &b, const in_any &x, int max_steps)
{
    size_t n = b.ph.size(), rows;
    if (x.ndim() == 1 && x.shape(0) == b.n_in)
        rows = 1;
    else if (x.ndim() == 2 && x.shape(1) == b.n_in && (x.shape(0) == n || x.shape(0) == 1))
        rows = x.shape(0);
    else
        throw nd_error(NEAT_E_ARG, "inputs: shape must be (" + std::to_string(b.n_in) + ",), (1, " +
                                       std::to_string(b.n_in) + ") or (" + std::to_string(n) + ", " +
                                       std::to_string(b.n_in) + ")");
    double *o = new double[n * b.n_out > 0 ? n * b.n_out : 1];
    const double *v = x.data();
    {
        nb::gil_scoped_release nogil;
        std::vector<nrt_q15> in(b.n_in + 1), out(b.n_out);
        for (size_t k = 0; k < n; k++) {
            const double *row = v + (rows == 1 ? 0 : k * b.n_in);
            in[0] = NRT_ONE;
            for (uint32_t i = 0; i < b.n_in; i++)
                in[i + 1] = neat_q15(row[i]);
            nrt_net *net = &b.ph[k].net;
            if (max_steps == -2)
                nrt_step(net, in.data(), out.data());
            else
                nrt_settle(net, in.data(), out.data(), max_steps >= 0 ? max_steps : net->n_nodes + 1);
            for (uint32_t j = 0; j < b.n_out; j++)
                o[k * b.n_out + j] = neat_from_q15(out[j]);
        }
    }
    nb::capsule owner(o, [](void *p) noexcept { delete[] (double *)p; });
    size_t shape[2] = {n, b.n_out};
    return batch_out(o, 2, shape, owner);
}

static nb::dict nd_record(neat_pop *pop, const std::vector<double> &fit, uint64_t evaluations)
{
    nb::dict r;
    double best = 0, sum = 0;
    for (double f : fit) {
        best = f > best ? f : best;
        sum += f;
    }
    r["generation"] = neat_pop_generation(pop);
    r["evaluations"] = evaluations;
    r["best_fitness"] = best;
    r["mean_fitness"] = fit.empty() ? 0.0 : sum / (double)fit.size();
    r["species"] = neat_pop_species_count(pop);
    r["delta_t"] = neat_pop_delta_t(pop);
    return r;
}

static void nd_record_best(nb::dict &r, neat_pop *pop)
{
    const neat_genome *b = neat_pop_last_best(pop);
    r["best_hidden"] = b ? neat_genome_hidden_count(b) : 0u;
    r["best_connections"] = b ? neat_genome_enabled_count(b) : 0u;
    r["innovations"] = neat_pop_innovations(pop);
}

static nd_population *nd_pop_from_bytes(const uint8_t *b, size_t len, const std::string &name)
{
    nd_population *r = new nd_population();
    size_t off = 0;
    int err = neat_pop_load(&r->pop, b, len, nullptr, &off);
    if (err) {
        delete r;
        throw nd_error(err, name + ": " + nd_strerror(err) + " at byte offset " + std::to_string(off), name,
                       (long long)off);
    }
    return r;
}

static nb::bytes nd_pop_bytes(const nd_population &s)
{
    uint8_t *buf = nullptr;
    size_t len = 0;
    int err = neat_pop_save(nd_pop(s), &buf, &len);
    if (err)
        nd_fail(err, "saving the population");
    nb::bytes b((const char *)buf, len);
    neat_pop_buf_free(s.pop, buf, len);
    return b;
}

void nd_bind_population(nb::module_ &m)
{
    nb::class_<nd_networks>(m, "Networks",
                            "Every network of one generation in C: stepped together on numpy arrays (the batched\n"
                            "evaluation path), the interpreter lock released meanwhile.")
        .def("__len__", [](const nd_networks &b) { return b.ph.size(); })
        .def("reset", [](nd_networks &b) {
                for (auto &p : b.ph)
                    nrt_reset(&p.net);
            }, "All activations of every network back to 0.")
        .def("step", [](nd_networks &b, const in_any &x) { return nd_batch(b, x, -2); }, nb::arg("inputs"),
             "One step of every network: inputs (n_inputs,) for all or (networks, n_inputs), one row\n"
             "each; the outputs as a (networks, n_outputs) array.")
        .def("settle", [](nd_networks &b, const in_any &x, int max_steps) { return nd_batch(b, x, max_steps); },
             nb::arg("inputs"), nb::arg("max_steps") = -1,
             "Network.settle for every network (max_steps -1: each network's nodes + 1).");

    nb::class_<nd_population> population = nb::class_<nd_population>(m, "Population",
                              "A NEAT population (libneat). Evolve it with run(fitness, generations), or step by\n"
                              "step: give every genome a fitness (set_fitness, set_fitnesses), then epoch(). The run\n"
                              "is a pure function of (params, seed, fitness values): the same on every machine.")
        .def("__init__", [](nd_population *self, const nd_params &params, nb::int_ seed_arg, const nd_genome *start,
                            bool keep_weights) {
                uint64_t seed = nd_u64(seed_arg, "seed");
                new (self) nd_population();
                neat_start st;
                st.genome = start != nullptr ? &start->gen() : nullptr;
                st.keep_weights = keep_weights;
                const char *field = nullptr;
                if (neat_params_check(&params.p, &field) != NEAT_OK)
                    throw nd_error(NEAT_E_PARAM, std::string("parameter ") + (field ? field : "?") + " out of range");
                if (start != nullptr && (start->n_inputs != params.p.n_inputs || start->n_outputs != params.p.n_outputs))
                    throw nd_error(NEAT_E_ARG, "start: a genome of " + std::to_string(start->n_inputs) + " inputs and " +
                                                   std::to_string(start->n_outputs) + " outputs for parameters of " +
                                                   std::to_string(params.p.n_inputs) + " and " +
                                                   std::to_string(params.p.n_outputs));
                int err = neat_pop_create(&self->pop, &params.p, start != nullptr ? &st : nullptr, seed, nullptr);
                if (err)
                    nd_fail(err, "creating the population");
            }, nb::arg("params"), nb::arg("seed") = 0, nb::arg("start") = nb::none(), nb::arg("keep_weights") = false,
            "A first generation: the minimal topology (bias and inputs to outputs), or start's, weights\n"
            "drawn from seed (kept from start with keep_weights).")
        .def("__len__", [](const nd_population &s) { return neat_pop_size(nd_pop(s)); })
        .def_prop_ro("generation", [](const nd_population &s) { return neat_pop_generation(nd_pop(s)); },
                     "The generation being evaluated (0 first).")
        .def_prop_ro("params", [](const nd_population &s) {
                nd_params p;
                p.p = *neat_pop_params(nd_pop(s));
                return p;
            }, "A copy of its parameters.")
        .def("set_params", [](nd_population &s, const nd_params &p) {
                int err = neat_pop_set_params(nd_pop(s), &p.p);
                if (err)
                    throw nd_error(err, "set_params: " + nd_strerror(err) +
                                            " (pop_size, n_inputs and n_outputs cannot change)");
            }, nb::arg("params"), "Changes the parameters from the next epoch on (not the population's shape).")
        .def("genome", [](const nd_population &s, uint32_t i) {
                neat_pop *pop = nd_pop(s);
                if (i >= neat_pop_size(pop))
                    throw nb::index_error(("genome " + std::to_string(i) + " of " +
                                           std::to_string(neat_pop_size(pop))).c_str());
                return nd_genome_copy(neat_pop_genome(pop, i), *neat_pop_params(pop));
            }, nb::arg("index"), "A copy of genome index of this generation.")
        .def("set_fitness", [](nd_population &s, uint32_t i, double f) {
                neat_pop *pop = nd_pop(s);
                if (i >= neat_pop_size(pop))
                    throw nb::index_error(("genome " + std::to_string(i) + " of " +
                                           std::to_string(neat_pop_size(pop))).c_str());
                int err = neat_pop_set_fitness(pop, i, f);
                if (err)
                    nd_fitness_fail(err, i, f);
            }, nb::arg("index"), nb::arg("fitness"),
            "Genome index's fitness: finite and not negative (FitnessError otherwise).")
        .def("set_fitnesses", [](nd_population &s, const fit_in &f) {
                neat_pop *pop = nd_pop(s);
                uint32_t n = neat_pop_size(pop);
                if (f.shape(0) != n)
                    throw nd_error(NEAT_E_ARG, "fitnesses: " + std::to_string(f.shape(0)) + " values for " +
                                                   std::to_string(n) + " genomes");
                for (uint32_t i = 0; i < n; i++) // all checked before any is set: nothing half-done
                    if (!std::isfinite(f.data()[i]) || f.data()[i] < 0)
                        nd_fitness_fail(NEAT_E_FITNESS, i, f.data()[i]);
                for (uint32_t i = 0; i < n; i++)
                    neat_pop_set_fitness(pop, i, f.data()[i]);
            }, nb::arg("fitnesses"), "Every genome's fitness at once, from a float64 array.")
        .def("epoch", [](nd_population &s) {
                neat_pop *pop = nd_pop_idle(s, "epoch");
                int err = neat_pop_epoch(pop);
                if (err == NEAT_E_FITNESS)
                    throw nd_error(err, "epoch: genome " + std::to_string(neat_pop_error_index(pop)) +
                                            " has no fitness yet", "", -1, neat_pop_error_index(pop));
                if (err)
                    nd_fail(err, "epoch");
            }, "The next generation (every genome needs its fitness: FitnessError names the first without).")
        .def("networks", &nd_networks_of, nb::rv_policy::take_ownership,
             "Every genome's network of this generation, for batched evaluation in C.")
        .def("run", [](nd_population &s, nb::callable fitness, nb::int_ gens, nb::object until) {
                neat_pop *pop = nd_pop_idle(s, "run");
                uint32_t generations = nd_u32(gens, "generations", 1);
                // while a generation is evaluated its genomes are borrowed: an epoch (or a nested run) would free them
                struct running_flag {
                    bool &f;
                    explicit running_flag(bool &x) : f(x) { f = true; }
                    ~running_flag() { f = false; }
                };
                nb::list records;
                // counted from the population's generation 0 (each generation evaluates every genome once), so a
                // second run, or a run after a checkpoint load, goes on counting
                uint64_t evaluations = (uint64_t)neat_pop_generation(pop) * neat_pop_size(pop);
                for (uint32_t gen = 0; gen < generations; gen++) {
                    uint32_t n = neat_pop_size(pop);
                    const neat_params *p = neat_pop_params(pop);
                    std::vector<double> fit(n);
                    {
                        running_flag flag(s.running);
                        for (uint32_t i = 0; i < n; i++) {
                            nb::object r;
                            {
                                nd_genome view;
                                view.borrowed = neat_pop_genome(pop, i);
                                view.n_inputs = p->n_inputs;
                                view.n_outputs = p->n_outputs;
                                view.net_step = p->net_step;
                                nb::object g = nb::cast(std::move(view));
                                // After the call (returned or raised), a genome still referenced gets its own copy,
                                // made before its fitness is set: the object a copy would have been.
                                struct unborrow {
                                    nb::handle h;
                                    ~unborrow()
                                    {
                                        nd_genome *ng = nb::inst_ptr<nd_genome>(h);
                                        if (ng->borrowed != nullptr && Py_REFCNT(h.ptr()) > 1)
                                            (void)ng->own(); // out of memory: left empty, never dangling
                                        ng->borrowed = nullptr;
                                    }
                                } release{g};
                                r = fitness(g); // a raise goes through: the generation stays to be evaluated again
                            }
                            double f = 0.0;
                            if (!nb::try_cast<double>(r, f))
                                throw nb::type_error(("the fitness of genome " + std::to_string(i) + " is " +
                                                      nb::cast<std::string>(nb::repr(r)) + ", not a number").c_str());
                            int err = neat_pop_set_fitness(pop, i, f);
                            if (err)
                                nd_fitness_fail(err, i, f);
                            fit[i] = f;
                            evaluations++;
                        }
                    }
                    nb::dict rec = nd_record(pop, fit, evaluations);
                    int err = neat_pop_epoch(pop);
                    if (err)
                        nd_fail(err, "epoch");
                    nd_record_best(rec, pop);
                    records.append(rec);
                    if (!until.is_none() && nd_truth(until(rec)))
                        break;
                    if (PyErr_CheckSignals() != 0) // Ctrl-C between generations: the population is whole
                        throw nb::python_error();
                }
                return records;
            }, nb::arg("fitness"), nb::arg("generations"), nb::arg("until") = nb::none(),
            nb::sig("def run(self, fitness: collections.abc.Callable[[Genome], float], generations: int, "
                    "until: collections.abc.Callable[[dict[str, typing.Any]], bool] | None = None) -> "
                    "list[dict[str, typing.Any]]"),
            "Evolves for generations (fewer if until(record) says so): fitness(genome) gives each genome's\n"
            "fitness. Returns one record per generation (generation, evaluations, best_fitness,\n"
            "mean_fitness, species, delta_t, best_hidden, best_connections, innovations): plain dicts,\n"
            "pandas.DataFrame(records) makes a table. A fitness that raises stops the run: the exception\n"
            "goes through and the population stays in the generation it was evaluating. The genome given\n"
            "to fitness is the population's own, lent (copied only if fitness keeps it); epoch() or run()\n"
            "from inside fitness is a StateError.")
        .def_prop_ro("last_best", [](const nd_population &s) -> nb::object {
                const neat_genome *g = neat_pop_last_best(nd_pop(s));
                if (g == nullptr)
                    return nb::none();
                return nb::cast(nd_genome_copy(g, *neat_pop_params(s.pop)));
            }, nb::sig("def last_best(self) -> Genome | None"),
            "The best genome of the last generation evaluated (None before the first epoch).")
        .def_prop_ro("best_ever", [](const nd_population &s) -> nb::object {
                const neat_genome *g = neat_pop_best_ever(nd_pop(s));
                if (g == nullptr)
                    return nb::none();
                return nb::cast(nd_genome_copy(g, *neat_pop_params(s.pop)));
            }, nb::sig("def best_ever(self) -> Genome | None"),
            "The one genome with the highest fitness of all generations evaluated so far (a copy; None\n"
            "before the first epoch).")
        .def("species", [](const nd_population &s) {
                neat_pop *pop = nd_pop(s);
                nb::list out;
                for (uint32_t k = 0; k < neat_pop_species_count(pop); k++) {
                    neat_species_info si;
                    if (neat_pop_species(pop, k, &si) != NEAT_OK)
                        continue;
                    nb::dict d;
                    d["id"] = si.id;
                    d["size"] = si.size;
                    d["age"] = si.age;
                    d["since_improved"] = si.since_improved;
                    d["best_fitness"] = si.best_fitness;
                    out.append(d);
                }
                return out;
            }, nb::sig("def species(self) -> list[dict[str, typing.Any]]"),
            "This generation's species: id, size, age, since_improved, best_fitness.")
        .def_prop_ro("delta_t", [](const nd_population &s) { return neat_pop_delta_t(nd_pop(s)); },
                     "The compatibility threshold this generation was speciated with.")
        .def_prop_ro("innovations", [](const nd_population &s) { return neat_pop_innovations(nd_pop(s)); },
                     "Innovation numbers used so far.")
        .def("to_bytes", &nd_pop_bytes, "The whole state as a libneat checkpoint (docs/formats.md).")
        .def("save", [](const nd_population &s, const nd_path &fpath) {
                const std::string path = fpath.string();
                nb::bytes b = nd_pop_bytes(s);
                nd_write_file(path, (const uint8_t *)b.c_str(), b.size());
            }, nb::arg("path"),
            "Writes the checkpoint through a temporary file and a rename: loading it and going on gives\n"
            "the run that never stopped.")
        .def("__repr__", [](const nd_population &s) {
                neat_pop *pop = nd_pop(s);
                return "Population(" + std::to_string(neat_pop_size(pop)) + " genomes, generation " +
                       std::to_string(neat_pop_generation(pop)) + ", " + std::to_string(neat_pop_species_count(pop)) +
                       " species)";
            });
    nd_def_file_loaders(population, nd_pop_from_bytes, ND_CKPT_MAX, "from_bytes", "data",
                        "A checkpoint's bytes, checked (magic, version, sizes, checksum) before any is trusted.",
                        "Reads a checkpoint (FormatError names the file and the byte offset of a problem).");
}
