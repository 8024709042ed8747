// nd_duel.cpp - the robot duel from Python: duel_evolve's run configurations (DuelConfig), the duel as a
// coevolution's game played in C on every core with the interpreter lock released (Duel), single games and
// comparisons against networks or the built-in strategies.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_map>

#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include "nd.h"
extern "C" {
#include "duel.h"
#include "duel_html.h"
#include "duel_replay.h"
#include "duel_cmp_cache.h"
#include "duel_config.h"
#include "duel_games.h"
#include "duel_runtag.h"
}

// The duel as a game: its executor (threads), created for the parameters of the networks it plays.
struct nd_duel {
    // one user of the executor at a time: two coevolutions in two threads sharing a Duel take turns
    std::mutex mu;
    duel_games *dg = nullptr;
    neat_params made_for;
    uint32_t threads = 0;
    nd_duel_config config;
    nd_duel() = default;
    nd_duel(const nd_duel &) = delete;
    nd_duel &operator=(const nd_duel &) = delete;
    ~nd_duel() { duel_games_free(dg); }
};

static void nd_duel_ready(nd_duel &d, const neat_params &p)
{
    if (d.dg != nullptr && std::memcmp(&d.made_for, &p, sizeof p) == 0)
        return;
    duel_games_free(d.dg);
    d.dg = nullptr;
    int err = duel_games_create(&d.dg, d.threads, &p);
    if (err)
        nd_fail(err, "the duel's threads");
    if (duel_games_set_rules(d.dg, &d.config.cfg.world) != 0)
        throw nd_error(NEAT_E_PARAM, "the configuration's [world] rules cannot make a game");
    d.made_for = p;
}

// The duel's lock, waited for with the interpreter lock released (its holder needs that lock to finish).
static std::unique_lock<std::mutex> nd_duel_lock(nd_duel &d)
{
    std::unique_lock<std::mutex> lk(d.mu, std::defer_lock);
    if (!lk.try_lock()) {
        nb::gil_scoped_release nogil;
        lk.lock();
    }
    return lk;
}

bool nd_native_game_of(nb::handle game, neat_coev *c, nd_native_game *out)
{
    nd_duel *d = nullptr;
    if (!nb::try_cast<nd_duel *>(game, d) || d == nullptr)
        return false;
    const neat_params *p = neat_pop_params(neat_coev_pop(c, 0));
    if (p->n_inputs != DUEL_N_INPUTS - 1 || p->n_outputs != DUEL_N_OUTPUTS)
        throw nd_error(NEAT_E_PARAM, "the Coevolution's networks have n_inputs = " + std::to_string(p->n_inputs) +
                                         " and n_outputs = " + std::to_string(p->n_outputs) + ", but the duel's have " +
                                         std::to_string(DUEL_N_INPUTS - 1) + " inputs and " +
                                         std::to_string(DUEL_N_OUTPUTS) + " outputs (its sensors and motors; the " +
                                         "bias is added): Params(n_inputs=" + std::to_string(DUEL_N_INPUTS - 1) +
                                         ", n_outputs=" + std::to_string(DUEL_N_OUTPUTS) + ")");
    out->lock = nd_duel_lock(*d);
    nd_duel_ready(*d, *p);
    duel_games_set_training(d->dg, duel_train_config(&d->config.cfg, neat_coev_generation(c)));
    out->play = duel_games_play;
    out->ud = d->dg;
    return true;
}

static std::string nd_config_text(const duel_config &cfg)
{
    char *buf = nullptr;
    size_t len = 0;
    FILE *mem = open_memstream(&buf, &len);
    if (mem == nullptr)
        throw std::bad_alloc();
    duel_config_dump(mem, &cfg);
    std::fclose(mem);
    std::string s(buf, len);
    std::free(buf);
    return s;
}

// A controller of a game: a Network (its runtime network, reset by the game) or a built-in strategy's name.
struct nd_ctrl {
    duel_controller c;
    nd_network *net = nullptr;
};

static nd_ctrl nd_ctrl_of(nb::handle h, const char *which)
{
    nd_ctrl r;
    std::memset(&r.c, 0, sizeof r.c);
    if (nb::isinstance<nb::str>(h)) {
        std::string name = nb::cast<std::string>(h);
        if (name.rfind("builtin:", 0) == 0)
            name = name.substr(8);
        int b = duel_builtin_parse(name.c_str());
        if (b < 0)
            throw nd_error(NEAT_E_ARG, std::string(which) + ": '" + name +
                                           "' is not a built-in strategy (idle, spinner, forager, hunter, "
                                           "forager-hunter)");
        r.c.builtin = b;
        return r;
    }
    nd_network *n = nullptr;
    if (!nb::try_cast<nd_network *>(h, n) || n == nullptr)
        throw nb::type_error((std::string(which) + ": a Network or a built-in strategy's name").c_str());
    if (n->ph.net.n_inputs != DUEL_N_INPUTS || n->ph.net.n_outputs != DUEL_N_OUTPUTS)
        throw nd_error(NEAT_E_ARG, std::string(which) + ": a duel network has 12 inputs and 3 outputs, not " +
                                       std::to_string(n->ph.net.n_inputs - 1) + " and " +
                                       std::to_string(n->ph.net.n_outputs));
    r.net = n;
    r.c.net = &n->ph.net;
    return r;
}

// The two players of one game: two controllers, never one Network object twice (a game steps each side's own
// activations).
static void nd_ctrl_pair(nb::handle a, nb::handle b, nd_ctrl *ca, nd_ctrl *cb)
{
    *ca = nd_ctrl_of(a, "a");
    *cb = nd_ctrl_of(b, "b");
    if (ca->net != nullptr && ca->net == cb->net)
        throw nd_error(NEAT_E_ARG, "a and b are the same Network object: load it twice");
}

static const duel_rules *nd_rules(nb::handle config)
{
    if (config.is_none())
        return duel_rules_v1();
    return &nb::cast<nd_duel_config &>(config).cfg.world;
}

static const char *nd_outcome(int o)
{
    switch (o) {
    case DUEL_WEST_WINS: return "west";
    case DUEL_EAST_WINS: return "east";
    case DUEL_DRAW: return "draw";
    default: return "timeout";
    }
}

void nd_bind_duel(nb::module_ &m)
{
    nb::class_<nd_duel_config>(m, "DuelConfig",
                               "A duel_evolve run configuration: [run], [coevolution], [neat] (with start), [world]\n"
                               "and [opponents], read, checked and written by the C code duel_evolve uses\n"
                               "(docs/tools.md, docs/duel-world.md).")
        .def(nb::init<>(), "The defaults (configs/paper.ini's values, world v1).")
        .def_static("from_ini", [](const nd_path &fpath) {
                const std::string path = fpath.string();
                nd_read_file(path, 1u << 20); // a missing or unreadable file is OSError, as for every loader
                nd_duel_config *r = new nd_duel_config();
                char err[4400];
                if (duel_config_read(&r->cfg, path.c_str(), err, sizeof err) != 0) {
                    delete r;
                    throw nd_error(NEAT_E_PARAM, err, path);
                }
                return r;
            }, nb::arg("path"), nb::rv_policy::take_ownership,
            "Reads a configuration file, as duel_evolve run --config does (ParamError names file and line).")
        .def("set", [](nd_duel_config &s, const std::string &assignment) {
                char err[4400];
                duel_config tmp = s.cfg;
                if (duel_config_set(&tmp, assignment.c_str(), err, sizeof err) != 0)
                    throw nd_error(NEAT_E_PARAM, err);
                if (duel_config_check(&tmp, err, sizeof err) != 0)
                    throw nd_error(NEAT_E_PARAM, err);
                s.cfg = tmp;
            }, nb::arg("assignment"), "One KEY=VALUE or SECTION.KEY=VALUE, as duel_evolve's --set.")
        .def_prop_ro("params", [](const nd_duel_config &s) {
                nd_params p;
                p.p = s.cfg.neat;
                return p;
            }, "A copy of its [neat] parameters.")
        .def_prop_ro("generations", [](const nd_duel_config &s) { return s.cfg.generations; }, "[run] generations.")
        .def_prop_ro("seed", [](const nd_duel_config &s) { return s.cfg.seed; }, "[run] seed.")
        .def_prop_ro("world", [](const nd_duel_config &s) {
                const char *n = duel_rules_name(&s.cfg.world);
                return std::string(n != nullptr ? n : "custom");
            }, "The world's name (v1), or 'custom' for rules set key by key.")
        .def_prop_ro("world_id", [](const nd_duel_config &s) { return duel_rules_id(&s.cfg.world); },
                     "The world's identity: the 64-bit FNV-1a hash of its rules' canonical bytes (docs/formats.md).")
        .def("to_ini", [](const nd_duel_config &s) { return nd_config_text(s.cfg); },
             "Every key of every section, as duel_evolve config --dump writes them (a run's config.ini).")
        .def("coevolution", [](const nd_duel_config &s) {
                if (s.cfg.opp.n > 0)
                    throw nd_error(NEAT_E_ARG, "a configuration with [opponents] is a run against fixed opponents, "
                                               "not a coevolution");
                char err[DUEL_START_MAX_PATH + 200];
                neat_coev *c = nullptr;
                int e = duel_coev_new(&c, &s.cfg, err, sizeof err);
                if (e)
                    throw nd_error(e == 2 ? NEAT_E_PARAM : NEAT_E_NOMEM, err);
                return nd_coev_wrap(c);
            }, nb::rv_policy::take_ownership,
            "The coevolution this configuration starts, exactly as duel_evolve run starts it (the same\n"
            "start topology, seed and game tag): stepped with Duel(config), it is the same run, checkpoint\n"
            "for checkpoint.")
        .def("__repr__", [](const nd_duel_config &s) {
                return "DuelConfig(" + std::to_string(s.cfg.generations) + " generations, 2 x " +
                       std::to_string(s.cfg.neat.pop_size) + " networks, seed " + std::to_string(s.cfg.seed) + ")";
            });

    nb::class_<nd_duel>(m, "Duel",
                        "The robot duel (docs/duel-world.md) as a coevolution's game, played in C on `threads`\n"
                        "threads (0: every core) with the interpreter lock released. The results do not depend on\n"
                        "the number of threads.")
        .def("__init__", [](nd_duel *self, nb::handle config, nb::int_ threads) {
                uint32_t t = nd_u32(threads, "threads");
                new (self) nd_duel();
                self->threads = t;
                if (!config.is_none())
                    self->config.cfg = nb::cast<nd_duel_config &>(config).cfg;
            }, nb::arg("config") = nb::none(), nb::arg("threads") = 0,
            nb::sig("def __init__(self, config: DuelConfig | None = None, threads: int = 0) -> None"),
            "The duel of config's [world] and [run] train_layouts (default: world v1, the training food).")
        .def_prop_ro("threads", [](const nd_duel &d) { return d.threads; }, "Threads (0: every core).")
        .def("play_many", [](nd_duel &d, nb::handle matches_arg) {
                if (!PySequence_Check(matches_arg.ptr()) || PyUnicode_Check(matches_arg.ptr()))
                    throw nb::type_error(("matches: a list of (a, b, food, a_west) tuples, not " +
                                          std::string(Py_TYPE(matches_arg.ptr())->tp_name)).c_str());
                nb::list matches = nb::list(matches_arg);
                // every distinct network once, as a blob; builtins as duel_net without a blob
                std::vector<duel_net> nets;
                std::unordered_map<const void *, uint32_t> index;
                std::vector<duel_match> ms(nb::len(matches));
                auto id = [&](nb::handle h) -> uint32_t {
                    nd_ctrl c = nd_ctrl_of(h, "a match's player");
                    const void *key = c.net != nullptr ? (const void *)c.net : (const void *)(intptr_t)(c.c.builtin + 1);
                    auto it = index.find(key);
                    if (it != index.end())
                        return it->second;
                    duel_net n;
                    n.blob = c.net != nullptr ? c.net->ph.blob : nullptr;
                    n.len = c.net != nullptr ? c.net->ph.blob_len : (size_t)c.c.builtin;
                    nets.push_back(n);
                    index.emplace(key, (uint32_t)(nets.size() - 1));
                    return (uint32_t)(nets.size() - 1);
                };
                for (size_t i = 0; i < ms.size(); i++) {
                    std::string at = "match " + std::to_string(i);
                    nb::handle h = matches[i];
                    if (!PyTuple_Check(h.ptr()) && !PyList_Check(h.ptr()))
                        throw nb::type_error((at + ": a tuple (a, b, food, a_west), not " +
                                              std::string(Py_TYPE(h.ptr())->tp_name)).c_str());
                    nb::tuple t = nb::tuple(h);
                    if (t.size() != 4)
                        throw nd_error(NEAT_E_ARG, at + ": (a, b, food, a_west)");
                    ms[i].a = id(t[0]);
                    ms[i].b = id(t[1]);
                    long food_l = 0;
                    if (!PyLong_Check(t[2].ptr()) || PyBool_Check(t[2].ptr()) || !nb::try_cast<long>(t[2], food_l))
                        throw nb::type_error((at + ": food: an int (-1 for the training items, or 0..143), not " +
                                              std::string(Py_TYPE(t[2].ptr())->tp_name)).c_str());
                    if (food_l < DUEL_TRAINING || food_l >= DUEL_CONFIGS)
                        food_l = DUEL_CONFIGS; /* refused just below */
                    int food = (int)food_l;
                    if (food < DUEL_TRAINING || food >= DUEL_CONFIGS)
                        throw nd_error(NEAT_E_ARG, "match " + std::to_string(i) + ": food " + std::to_string(food) +
                                                       ": -1 (training) or 0..143");
                    ms[i].config = food;
                    if (!PyBool_Check(t[3].ptr()) && !nb::isinstance<nb::int_>(t[3]) &&
                        std::string(Py_TYPE(t[3].ptr())->tp_name) != "numpy.bool_" &&
                        std::string(Py_TYPE(t[3].ptr())->tp_name) != "numpy.bool")
                        throw nb::type_error((at + ": a_west: a bool, not " +
                                              std::string(Py_TYPE(t[3].ptr())->tp_name)).c_str());
                    ms[i].a_first = nd_truth(t[3]);
                    ms[i].result = 0;
                }
                neat_params p = neat_params_default();
                std::unique_lock<std::mutex> lk = nd_duel_lock(d);
                nd_duel_ready(d, p);
                int err;
                {
                    nb::gil_scoped_release nogil;
                    err = duel_games_play_nets(d.dg, nets.data(), ms.data(), ms.size());
                }
                if (err)
                    nd_fail(err, "match " + std::to_string(duel_games_error_at(d.dg)));
                std::vector<int> r(ms.size());
                for (size_t i = 0; i < ms.size(); i++)
                    r[i] = ms[i].result;
                return r;
            }, nb::arg("matches"),
            nb::sig("def play_many(self, matches: list[tuple[Network | str, Network | str, int, bool]]) -> list[int]"),
            "Plays (a, b, food, a_west) matches on the duel's threads: 1 when a won, -1 when b won, 0\n"
            "otherwise. food: -1 the training items, 0..143 a comparison layout. a and b: Networks or\n"
            "built-in strategies' names.");

    m.def("duel_builtins", []() {
            std::vector<std::string> v;
            for (int k = 0; k < DUEL_N_BUILTINS; k++)
                v.emplace_back(duel_builtin_name(k));
            return v;
        }, "The built-in strategies' names (docs/duel-world.md): idle, spinner, forager, hunter, forager-hunter.");
    m.def("duel_play", [](nb::handle a, nb::handle b, int food, bool a_west, nb::handle config) {
            nd_ctrl ca, cb;
            nd_ctrl_pair(a, b, &ca, &cb);
            if (food < DUEL_TRAINING || food >= DUEL_CONFIGS)
                throw nd_error(NEAT_E_ARG, "food: -1 (the training items) or a comparison layout 0..143");
            duel_result res;
            std::memset(&res, 0, sizeof res);
            const duel_rules *rules = nd_rules(config);
            int err;
            {
                nb::gil_scoped_release nogil;
                err = a_west ? duel_play_rules(rules, &ca.c, &cb.c, food, &res, nullptr, nullptr)
                             : duel_play_rules(rules, &cb.c, &ca.c, food, &res, nullptr, nullptr);
            }
            if (err)
                throw nd_error(NEAT_E_ARG, "duel_play: error " + std::to_string(err));
            nb::dict d;
            int w = a_west ? 0 : 1;
            d["winner"] = res.outcome == DUEL_WEST_WINS ? (a_west ? "a" : "b")
                        : res.outcome == DUEL_EAST_WINS ? (a_west ? "b" : "a") : "none";
            d["outcome"] = nd_outcome(res.outcome);
            d["text"] = duel_outcome_text(res.outcome);
            d["steps"] = res.steps;
            d["energy"] = nb::make_tuple(res.energy[w] / 65536.0, res.energy[1 - w] / 65536.0);
            d["eaten"] = nb::make_tuple(res.eaten[w], res.eaten[1 - w]);
            return d;
        }, nb::arg("a"), nb::arg("b"), nb::arg("food") = -1, nb::arg("a_west") = true, nb::arg("config") = nb::none(),
        nb::sig("def duel_play(a: Network | str, b: Network | str, food: int = -1, a_west: bool = True, "
                "config: DuelConfig | None = None) -> dict[str, typing.Any]"),
        "One game (duel_evolve play A B --food K --side west|east): winner 'a', 'b' or 'none', outcome\n"
        "('west', 'east', 'draw', 'timeout'), steps, energy and food eaten of (a, b). Networks are reset\n"
        "first.");
    m.def("duel_page", [](nb::handle a, nb::handle b, const nd_path &path, int food, bool a_west, nb::handle config,
                          const std::string &a_name, const std::string &b_name, bool force) {
            nd_ctrl ca, cb;
            nd_ctrl_pair(a, b, &ca, &cb);
            if (food < DUEL_TRAINING || food >= DUEL_CONFIGS)
                throw nd_error(NEAT_E_ARG, "food: -1 (the training items) or a comparison layout 0..143");
            const duel_rules *rules = nd_rules(config);
            const std::string out = path.string();
            char msg[4600] = "";
            int st;
            {
                nb::gil_scoped_release nogil;
                duel_replay rep;
                duel_replay_init(&rep);
                int err = a_west ? duel_replay_from_game_rules(&rep, rules, &ca.c, &cb.c, food)
                                 : duel_replay_from_game_rules(&rep, rules, &cb.c, &ca.c, food);
                if (err) {
                    std::snprintf(msg, sizeof msg, "the game failed (%d)", err);
                    st = 1;
                } else {
                    char title[600];
                    std::snprintf(rep.west, sizeof rep.west, "%s", (a_west ? a_name : b_name).c_str());
                    std::snprintf(rep.east, sizeof rep.east, "%s", (a_west ? b_name : a_name).c_str());
                    std::snprintf(title, sizeof title, "%s vs %s", rep.west, rep.east);
                    st = duel_html_write_duel("render", out.c_str(), &rep, title, force, nullptr, 0, msg, sizeof msg);
                }
                duel_replay_free(&rep);
            }
            return std::make_tuple(st, std::string(msg));
        }, nb::arg("a"), nb::arg("b"), nb::arg("path"), nb::arg("food") = -1, nb::arg("a_west") = true,
        nb::arg("config") = nb::none(), nb::arg("a_name") = "a", nb::arg("b_name") = "b", nb::arg("force") = false,
        nb::sig("def duel_page(a: Network | str, b: Network | str, path: str | os.PathLike[str], food: int = -1, "
                "a_west: bool = True, config: DuelConfig | None = None, a_name: str = 'a', b_name: str = 'b', "
                "force: bool = False) -> tuple[int, str]"),
        "duel_evolve render A B --html FILE by the command's library: the game's web page, written atomically\n"
        "(status, message).");
    m.def("duel_compare", [](nb::handle a, nb::handle b, nb::handle config) {
            nd_ctrl ca, cb;
            nd_ctrl_pair(a, b, &ca, &cb);
            duel_tally t;
            std::memset(&t, 0, sizeof t);
            const duel_rules *rules = nd_rules(config);
            int err;
            {
                nb::gil_scoped_release nogil;
                err = duel_compare_rules(rules, &ca.c, &cb.c, &t);
            }
            if (err)
                throw nd_error(NEAT_E_ARG, "duel_compare: error " + std::to_string(err));
            nb::dict d;
            d["wins"] = t.wins_a;
            d["losses"] = t.wins_b;
            d["draws"] = t.draws;
            d["timeouts"] = t.timeouts;
            return d;
        }, nb::arg("a"), nb::arg("b"), nb::arg("config") = nb::none(),
        nb::sig("def duel_compare(a: Network | str, b: Network | str, config: DuelConfig | None = None) -> "
                "dict[str, int]"),
        "The 288-game comparison (every one of the 144 layouts from both sides; duel_evolve play A B):\n"
        "a's wins, losses, draws and timeouts.");
}
