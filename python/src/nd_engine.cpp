// nd_engine.cpp - the run engine (tools/run/duel_engine.h) from Python: a run directory opened new or again, its
// generations played with the interpreter lock released, each one handed to a Python callable; what the engine
// says kept for the package (neat_duel.runs) to raise or show. Every rule of a run directory is the engine's, the
// same as duel_evolve run and resume's.
#include <chrono>
#include <cstring>

#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include "nd.h"
extern "C" {
#include "duel_engine.h"
#include "duel_fixed.h"
}

namespace {

struct nd_engine {
    duel_engine *E = nullptr;
    std::mutex busy;                            // one step at a time; close waits for it
    std::mutex said_mu;                         // the engine's thread adds, Python's takes
    std::vector<std::pair<int, std::string>> said; // the engine's lines since the last take
    nb::object on_generation;                    // during a step: the callable, or None
    bool failed = false;                         // the callable raised, or Ctrl-C (kept in error)
    bool callable_failed = false;                // the callable raised: not called again in this step
    nb::object error_type, error_value, error_tb;
    std::chrono::steady_clock::time_point checked; // Ctrl-C last looked for
    nd_engine() = default;
    nd_engine(const nd_engine &) = delete;
    nd_engine &operator=(const nd_engine &) = delete;
    ~nd_engine()
    {
        if (E != nullptr) {
            nb::gil_scoped_release nogil;
            duel_engine_close(E);
        }
    }
};

// The error raised in a hook, kept to be raised again when the step returns; the engine asked to stop after the
// generation in flight (so that the run directory is whole).
static void nd_keep_error(nd_engine *s)
{
    PyObject *t, *v, *tb;
    PyErr_Fetch(&t, &v, &tb);
    PyErr_NormalizeException(&t, &v, &tb);
    if (!s->failed) {
        s->failed = true;
        s->error_type = nb::steal(t);
        s->error_value = nb::steal(v);
        s->error_tb = nb::steal(tb);
    } else {
        Py_XDECREF(t);
        Py_XDECREF(v);
        Py_XDECREF(tb);
    }
    duel_engine_stop(s->E);
}

static void nd_on_say(void *ud, duel_say_kind kind, const char *text)
{
    nd_engine *s = static_cast<nd_engine *>(ud);
    std::lock_guard<std::mutex> lk(s->said_mu); // the engine's own thread: no Python here
    s->said.emplace_back((int)kind, std::string(text));
}

static nb::dict nd_record_dict(const duel_engine_record *r)
{
    nb::dict d;
    d["generation"] = r->generation;
    d["generations"] = r->generations;
    d["seconds"] = r->seconds;
    d["generations_rows"] = std::string(r->generations_rows != nullptr ? r->generations_rows : "");
    d["dominance_row"] = r->dominance_row != nullptr ? nb::object(nb::str(r->dominance_row)) : nb::none();
    d["strength_row"] = r->strength_row != nullptr ? nb::object(nb::str(r->strength_row)) : nb::none();
    if (r->coev != nullptr) {
        d["champion"] = std::string(r->coev->champion_pop ? "B" : "A");
        d["champion_wins"] = nb::make_tuple(r->coev->champion_wins[0], r->coev->champion_wins[1]);
        d["new_dominant"] = r->coev->new_dominant != 0;
        d["games"] = (unsigned long long)r->coev->games;
    } else {
        d["champion"] = nb::none();
        d["new_dominant"] = false;
        d["games"] = (unsigned long long)r->fixed->games;
    }
    d["dominants"] = r->dominants;
    d["dominant_generation"] = r->dominant_generation;
    d["dominant_hidden"] = r->dominant_hidden;
    d["dominant_connections"] = r->dominant_connections;
    return d;
}

static void nd_on_generation(void *ud, const duel_engine_record *r)
{
    nd_engine *s = static_cast<nd_engine *>(ud);
    nb::gil_scoped_acquire gil;
    if (!s->failed && PyErr_CheckSignals() != 0)
        nd_keep_error(s); // Ctrl-C: this generation is saved and still reported, and it is the last
    if (s->callable_failed || s->on_generation.is_none())
        return;
    try {
        s->on_generation(nd_record_dict(r));
    } catch (nb::python_error &e) {
        e.restore();
        s->callable_failed = true;
        nd_keep_error(s);
    }
}

// Ctrl-C during a generation's games: Python's handler only sets a flag, looked at here (a few times a second),
// and the generation in flight is the last.
static void nd_on_progress(void *ud, uint32_t, uint64_t, uint64_t)
{
    nd_engine *s = static_cast<nd_engine *>(ud);
    auto now = std::chrono::steady_clock::now();
    if (now - s->checked < std::chrono::milliseconds(100))
        return;
    s->checked = now;
    nb::gil_scoped_acquire gil;
    if (!s->failed && PyErr_CheckSignals() != 0)
        nd_keep_error(s);
}

static duel_engine_options nd_options(nd_engine *s, uint32_t threads, const std::vector<const char *> &sets)
{
    duel_engine_options o;
    std::memset(&o, 0, sizeof o);
    o.threads = threads;
    o.sets = sets.empty() ? nullptr : sets.data();
    o.n_sets = (uint32_t)sets.size();
    o.hooks.ud = s;
    o.hooks.say = nd_on_say;
    o.hooks.generation = nd_on_generation;
    o.hooks.progress = nd_on_progress;
    return o;
}

static nb::list nd_take_said(nd_engine &s)
{
    std::vector<std::pair<int, std::string>> taken;
    {
        std::lock_guard<std::mutex> lk(s.said_mu);
        taken.swap(s.said);
    }
    nb::list out;
    for (auto &p : taken)
        out.append(nb::make_tuple(p.first, p.second));
    return out;
}

static std::vector<const char *> nd_c_strings(const std::vector<std::string> &v)
{
    std::vector<const char *> out;
    for (const std::string &x : v)
        out.push_back(x.c_str());
    return out;
}

static nd_engine &nd_open(nd_engine &s)
{
    if (s.E == nullptr)
        throw nd_error(NEAT_E_STATE, "the run is closed");
    return s;
}

} // namespace

void nd_bind_engine(nb::module_ &m)
{
    nb::class_<nd_engine>(m, "RunEngine",
                          "The run engine (duel_engine.h) under neat_duel.runs.Run: use that. new() and resume()\n"
                          "return (engine or None, status, lines); status is duel_evolve's exit status.")
        .def_static("new", [](const nd_duel_config &config, const nd_path &dir, uint32_t threads,
                              const std::vector<std::string> &sets, int64_t seed, uint32_t generations,
                              const std::string &config_name) {
                // the configuration as duel_evolve run makes it: the overrides together (a profile first), then
                // --seed and --generations, then checked
                duel_config cfg = config.cfg;
                std::vector<const char *> cs = nd_c_strings(sets);
                char err[4400];
                uint32_t bad = 0;
                nb::list refused;
                if (duel_config_set_list(&cfg, cs.empty() ? nullptr : cs.data(), (uint32_t)cs.size(), &bad, err,
                                         sizeof err) != 0) {
                    refused.append(nb::make_tuple(0, "--set " + sets[bad] + ": " + err));
                    return nb::make_tuple(nb::none(), 2, refused);
                }
                if (seed >= 0)
                    cfg.seed = (uint32_t)seed;
                if (generations > 0)
                    cfg.generations = generations;
                if (duel_config_check(&cfg, err, sizeof err) != 0) {
                    refused.append(nb::make_tuple(0, std::string(sets.empty() ? config_name
                                                                             : "the configuration with its --set "
                                                                               "overrides") + ": " + err));
                    return nb::make_tuple(nb::none(), 2, refused);
                }
                auto *s = new nd_engine();
                duel_engine_options o = nd_options(s, threads, cs);
                o.config_name = config_name.c_str();
                std::string d = dir.string();
                int rc;
                {
                    nb::gil_scoped_release nogil;
                    rc = duel_engine_new(&s->E, &cfg, d.c_str(), &o);
                }
                nb::list said = nd_take_said(*s);
                if (rc != 0) {
                    delete s;
                    return nb::make_tuple(nb::none(), rc, said);
                }
                return nb::make_tuple(nb::cast(s, nb::rv_policy::take_ownership), rc, said);
            }, nb::arg("config"), nb::arg("directory"), nb::arg("threads") = 0,
            nb::arg("sets") = std::vector<std::string>(), nb::arg("seed") = -1, nb::arg("generations") = 0,
            nb::arg("config_name") = "(DuelConfig)",
            nb::sig("def new(config: DuelConfig, directory: str | os.PathLike[str], threads: int = 0, "
                    "sets: list[str] = [], seed: int = -1, generations: int = 0, config_name: str = '(DuelConfig)') "
                    "-> tuple[RunEngine | None, int, list[tuple[int, str]]]"),
            "A new run of config with the overrides sets (KEY=VALUE), seed (-1: the configuration's) and\n"
            "generations (0: the configuration's) in directory, as duel_evolve run makes it: (engine, 0, lines),\n"
            "or (None, status, lines) when refused.")
        .def_static("resume", [](const nd_path &dir, uint32_t threads, const std::vector<std::string> &sets,
                                 uint32_t generations, bool shorten) {
                auto *s = new nd_engine();
                std::vector<const char *> cs = nd_c_strings(sets);
                duel_engine_options o = nd_options(s, threads, cs);
                o.generations = generations;
                o.shorten = shorten;
                std::string d = dir.string();
                int rc;
                {
                    nb::gil_scoped_release nogil;
                    rc = duel_engine_resume(&s->E, d.c_str(), &o);
                }
                nb::list said = nd_take_said(*s);
                if (rc != 0) {
                    delete s;
                    return nb::make_tuple(nb::none(), rc, said);
                }
                return nb::make_tuple(nb::cast(s, nb::rv_policy::take_ownership), rc, said);
            }, nb::arg("directory"), nb::arg("threads") = 0, nb::arg("sets") = std::vector<std::string>(),
            nb::arg("generations") = 0, nb::arg("shorten") = false,
            nb::sig("def resume(directory: str | os.PathLike[str], threads: int = 0, sets: list[str] = "
                    "[], generations: int = 0, shorten: bool = False) -> tuple[RunEngine | None, int, "
                    "list[tuple[int, str]]]"),
            "The run in directory opened again: (engine, 0, lines), or (None, status, lines) when refused.")
        .def("step", [](nd_engine &s, uint32_t n, nb::object on_generation) {
                nd_open(s);
                std::unique_lock<std::mutex> held(s.busy, std::try_to_lock);
                if (!held.owns_lock())
                    throw nd_error(NEAT_E_STATE, "this run is already playing generations (another thread)");
                s.on_generation = on_generation;
                s.failed = false;
                s.callable_failed = false;
                s.checked = std::chrono::steady_clock::now();
                int rc;
                {
                    nb::gil_scoped_release nogil;
                    rc = duel_engine_step(s.E, n);
                }
                s.on_generation = nb::none();
                if (s.failed) {
                    s.failed = false;
                    PyErr_Restore(s.error_type.release().ptr(), s.error_value.release().ptr(),
                                  s.error_tb.release().ptr());
                    throw nb::python_error();
                }
                return rc;
            }, nb::arg("n"), nb::arg("on_generation") = nb::none(),
            nb::sig("def step(self, n: int, on_generation: typing.Callable[[dict[str, typing.Any]], object] | None "
                    "= None) -> int"),
            "Plays n generations (0: to the end), or fewer at the end or a stop; calls on_generation with each\n"
            "one's record. The engine's status; an exception raised by on_generation (or Ctrl-C) comes back\n"
            "once the generation in flight is saved.")
        .def("stop", [](nd_engine &s) { if (s.E != nullptr) duel_engine_stop(s.E); },
             "The generation in flight is the last of the step (from any thread).")
        .def("take_lines", [](nd_engine &s) { return nd_take_said(s); },
             nb::sig("def take_lines(self) -> list[tuple[int, str]]"),
             "What the engine said since the last call: (kind, text), kind 0 error, 1 note, 2 information.")
        .def_prop_ro("generation", [](nd_engine &s) { return duel_engine_generation(nd_open(s).E); },
                     "The generation to play next.")
        .def_prop_ro("generations", [](nd_engine &s) { return duel_engine_generations(nd_open(s).E); },
                     "The run's total.")
        .def_prop_ro("directory", [](nd_engine &s) { return std::string(duel_engine_dir(nd_open(s).E)); },
                     "The run directory.")
        .def_prop_ro("is_coevolution", [](nd_engine &s) { return duel_engine_coev(nd_open(s).E) != nullptr; },
                     "False for a run against fixed opponents.")
        .def_prop_ro("closed", [](nd_engine &s) { return s.E == nullptr; }, "Whether close() was called.")
        .def("close", [](nd_engine &s) {
                if (s.E == nullptr)
                    return 0;
                std::unique_lock<std::mutex> held(s.busy, std::try_to_lock);
                if (!held.owns_lock())
                    throw nd_error(NEAT_E_STATE, "this run is playing generations (another thread): stop it first");
                int rc;
                {
                    nb::gil_scoped_release nogil;
                    rc = duel_engine_close(s.E);
                }
                s.E = nullptr;
                return rc;
            }, "Writes the run's last lines into log.txt and gives the directory back. Its status (1: log.txt\n"
               "could not be written).");
}
