// nd_env.cpp - the robot duel as a reinforcement-learning environment's core (neat_duel.envs): K games held in C and
// stepped together on numpy arrays by duelsim's own world (duel_world_init_rules, duel_sense, duel_world_step), the
// interpreter lock released while they step; and the built-in strategies' actions (duel_builtin_act).
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <memory>
#include <thread>

#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>

#include "nd.h"
extern "C" {
#include "duel.h"
}

// The observation: the 12 sensor values a network reads after its bias (inputs 1..12 of docs/duelsim.md).
static constexpr size_t ND_OBS = DUEL_N_INPUTS - 1;

using act_in = nb::ndarray<const float, nb::shape<-1, 2, DUEL_N_OUTPUTS>, nb::c_contig, nb::device::cpu>;
using idx_in = nb::ndarray<const int64_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using obs_in = nb::ndarray<const float, nb::shape<-1, ND_OBS>, nb::c_contig, nb::device::cpu>;
using f32_3 = nb::ndarray<nb::numpy, float, nb::ndim<3>>;
using f32_2 = nb::ndarray<nb::numpy, float, nb::ndim<2>>;
using b_1 = nb::ndarray<nb::numpy, bool, nb::ndim<1>>;

// A new numpy array of n values of T, owned by Python (its memory freed with the array).
template <class T, size_t D>
static nb::ndarray<nb::numpy, T, nb::ndim<D>> nd_owned(std::unique_ptr<T[]> p, const size_t (&shape)[D])
{
    T *raw = p.release();
    nb::capsule owner(raw, [](void *q) noexcept { delete[] (T *)q; });
    return nb::ndarray<nb::numpy, T, nb::ndim<D>>(raw, D, shape, owner);
}

// An action value as the runtime's Q1.15, exactly as a network's output is one: neat_q15 (floor(a * 32768 + 0.5),
// saturated to [-32768, 32767], NaN 0), so an action q / 32768 is q again; the world reads a negative output as 0.
static inline nrt_q15 nd_action_q15(float a)
{
    return neat_q15((double)a);
}

// One robot's observation: its 13 inputs without the bias, each q / 32768 (exact in float32).
static inline void nd_observe(const duel_world *w, int side, float *obs)
{
    nrt_q15 in[DUEL_N_INPUTS];
    duel_sense(w, side, in);
    for (size_t i = 0; i < ND_OBS; i++)
        obs[i] = (float)in[i + 1] * (1.0f / 32768.0f);
}

// K games and what their last step did.
struct nd_envs {
    duel_rules rules;                  // the games' world (each duel_world points at it: this object never moves)
    std::vector<duel_world> w;
    std::vector<int16_t> layout;       // each game's food: -1 the training items, 0..143 a comparison layout
    std::vector<duel_event> ev;        // each game's last step's events
    double shaping = 0.0;              // the shaped reward's weight (0: off)
    uint32_t threads = 1;
    std::mutex mu;                     // one call at a time (the interpreter lock is released while stepping)
    // the helper threads: in every step each thread, the caller's too, claims chunks of games until none is left
    // (a helper the system has not run yet finds none, and the caller never waits for it)
    std::vector<std::thread> workers;
    std::mutex pool_mu;
    std::condition_variable go, done;
    uint64_t job = 0;                  // step number: the helpers wake when it grows
    size_t chunk = 0, n_chunks = 0;    // games a chunk, chunks of the step
    size_t next = 0, finished = 0;     // the next chunk to claim, the chunks stepped
    bool quit = false;
    const float *job_act = nullptr;
    float *job_obs = nullptr, *job_rew = nullptr;
    bool *job_term = nullptr, *job_trunc = nullptr;

    nd_envs() = default;
    nd_envs(const nd_envs &) = delete;
    nd_envs &operator=(const nd_envs &) = delete;
    ~nd_envs()
    {
        {
            std::lock_guard<std::mutex> lk(pool_mu);
            quit = true;
        }
        go.notify_all();
        for (auto &t : workers)
            t.join();
    }
    size_t size() const { return w.size(); }
    void step_range(size_t lo, size_t hi);
    void step_all();
    void claim_and_step(uint64_t id);
    void worker();
};

// Steps games [lo, hi): the job's actions in, its observations, rewards and flags out. A game already over is not
// stepped: its observation is its last, its reward 0 and its flags what they were.
void nd_envs::step_range(size_t lo, size_t hi)
{
    const double scale = 1.0 / (double)rules.energy_scale;
    for (size_t k = lo; k < hi; k++) {
        duel_world *g = &w[k];
        const float *a = job_act + k * 2 * DUEL_N_OUTPUTS;
        float *r = job_rew + k * 2;
        if (g->outcome == DUEL_RUNNING) {
            nrt_q15 out[2][DUEL_N_OUTPUTS];
            for (int s = 0; s < 2; s++)
                for (int i = 0; i < DUEL_N_OUTPUTS; i++)
                    out[s][i] = nd_action_q15(a[s * DUEL_N_OUTPUTS + i]);
            int32_t before = g->robot[DUEL_WEST].energy - g->robot[DUEL_EAST].energy;
            int o = duel_world_step(g, out[DUEL_WEST], out[DUEL_EAST], &ev[k]);
            double rw = o == DUEL_WEST_WINS ? 1.0 : o == DUEL_EAST_WINS ? -1.0 : 0.0;
            if (shaping != 0.0) {
                int32_t after = g->robot[DUEL_WEST].energy - g->robot[DUEL_EAST].energy;
                rw += shaping * ((double)after - (double)before) / 65536.0 * scale;
            }
            r[0] = (float)rw;
            r[1] = (float)(0.0 - rw); // +0.0, not -0.0, when rw is 0
        } else {
            std::memset(&ev[k], 0, sizeof ev[k]);
            ev[k].outcome = g->outcome;
            r[0] = r[1] = 0.0f;
        }
        nd_observe(g, DUEL_WEST, job_obs + k * 2 * ND_OBS);
        nd_observe(g, DUEL_EAST, job_obs + k * 2 * ND_OBS + ND_OBS);
        job_term[k] = g->outcome == DUEL_WEST_WINS || g->outcome == DUEL_EAST_WINS || g->outcome == DUEL_DRAW;
        job_trunc[k] = g->outcome == DUEL_TIMEOUT;
    }
}

// Claims and steps chunks of step id until none is left (or the step is another's).
void nd_envs::claim_and_step(uint64_t id)
{
    for (;;) {
        size_t c;
        {
            std::lock_guard<std::mutex> lk(pool_mu);
            if (job != id || next >= n_chunks)
                return;
            c = next++;
        }
        size_t lo = c * chunk, hi = lo + chunk < size() ? lo + chunk : size();
        step_range(lo, hi);
        bool last;
        {
            std::lock_guard<std::mutex> lk(pool_mu);
            last = ++finished == n_chunks;
        }
        if (last)
            done.notify_all();
    }
}

void nd_envs::worker()
{
    uint64_t seen = 0;
    for (;;) {
        {
            std::unique_lock<std::mutex> lk(pool_mu);
            go.wait(lk, [&] { return quit || job != seen; });
            if (quit)
                return;
            seen = job;
        }
        claim_and_step(seen);
    }
}

// Every game of the job on the batch's threads (the job's arrays set). Each game is stepped alone, whichever thread
// steps it: the results do not depend on the threads.
void nd_envs::step_all()
{
    if (threads <= 1) {
        step_range(0, size());
        return;
    }
    uint64_t id;
    {
        std::lock_guard<std::mutex> lk(pool_mu);
        chunk = (size() + 4 * threads - 1) / (4 * threads); // four chunks a thread: an uneven start evens out
        n_chunks = (size() + chunk - 1) / chunk;
        next = finished = 0;
        id = ++job;
    }
    go.notify_all();
    claim_and_step(id);
    std::unique_lock<std::mutex> lk(pool_mu);
    done.wait(lk, [&] { return finished == n_chunks; });
}

// The batch's lock, waited for with the interpreter lock released (its holder needs that lock to finish).
static std::unique_lock<std::mutex> nd_envs_lock(nd_envs &e)
{
    std::unique_lock<std::mutex> lk(e.mu, std::defer_lock);
    if (!lk.try_lock()) {
        nb::gil_scoped_release nogil;
        lk.lock();
    }
    return lk;
}

// Every game's observations, (K, 2, 12).
static f32_3 nd_envs_observe(const nd_envs &e)
{
    std::unique_ptr<float[]> obs(new float[e.size() * 2 * ND_OBS]);
    for (size_t k = 0; k < e.size(); k++) {
        nd_observe(&e.w[k], DUEL_WEST, &obs[k * 2 * ND_OBS]);
        nd_observe(&e.w[k], DUEL_EAST, &obs[k * 2 * ND_OBS + ND_OBS]);
    }
    size_t shape[3] = {e.size(), 2, ND_OBS};
    return nd_owned(std::move(obs), shape);
}

static const char *nd_outcome_name(int o)
{
    switch (o) {
    case DUEL_RUNNING: return "running";
    case DUEL_WEST_WINS: return "west";
    case DUEL_EAST_WINS: return "east";
    case DUEL_DRAW: return "draw";
    default: return "timeout";
    }
}

// The builtin strategy named (with or without "builtin:"), or ArgumentError.
static int nd_builtin_of(const std::string &name_arg)
{
    std::string name = name_arg.rfind("builtin:", 0) == 0 ? name_arg.substr(8) : name_arg;
    int b = duel_builtin_parse(name.c_str());
    if (b < 0) {
        std::string all;
        for (int k = 0; k < DUEL_N_BUILTINS; k++)
            all += std::string(k ? ", " : "") + duel_builtin_name(k);
        throw nd_error(NEAT_E_ARG, "'" + name + "' is not a built-in strategy (" + all + ")");
    }
    return b;
}

void nd_bind_env(nb::module_ &m)
{
    nb::class_<nd_envs>(m, "DuelBatch",
                        "K robot duels held in C and stepped together (neat_duel.envs, docs/envs.md): duelsim's own\n"
                        "world, numpy arrays in and out, the interpreter lock released while the games step. A game's\n"
                        "observation is each robot's 12 sensor values (a network's inputs 1..12, Q1.15 / 32768); its\n"
                        "action each robot's 3 motor outputs (turn left, turn right, forward) in [0, 1], converted\n"
                        "to Q1.15 as a network's outputs are.")
        .def("__init__", [](nd_envs *self, nb::int_ num_games, nb::handle config, double shaping, nb::int_ threads) {
                uint32_t k = nd_u32(num_games, "num_games", 1);
                uint32_t t = nd_u32(threads, "threads", 1);
                if (!std::isfinite(shaping))
                    throw nd_error(NEAT_E_ARG, "shaping: a finite number");
                nd_duel_config *cfg = nullptr;
                if (!config.is_none() && (!nb::try_cast<nd_duel_config *>(config, cfg) || cfg == nullptr))
                    throw nb::type_error(("config: a DuelConfig or None, not " +
                                          std::string(Py_TYPE(config.ptr())->tp_name)).c_str());
                const duel_rules *r = cfg == nullptr ? duel_rules_v1() : &cfg->cfg.world;
                const char *field = nullptr, *why = nullptr;
                if (duel_rules_check(r, &field, &why) != DUEL_OK)
                    throw nd_error(NEAT_E_PARAM, std::string("the configuration's [world] rules cannot make a game: ") +
                                                     (field ? field : "?") + ": " + (why ? why : "?"));
                new (self) nd_envs();
                self->rules = *r;
                self->shaping = shaping;
                self->threads = t > k ? k : t;
                self->w.resize(k);
                self->layout.assign(k, (int16_t)DUEL_TRAINING);
                self->ev.resize(k);
                std::memset(self->ev.data(), 0, k * sizeof(duel_event));
                for (uint32_t i = 0; i < k; i++)
                    duel_world_init_rules(&self->w[i], &self->rules, DUEL_TRAINING);
                for (uint32_t i = 1; i < self->threads; i++)
                    self->workers.emplace_back([self] { self->worker(); });
            }, nb::arg("num_games"), nb::arg("config") = nb::none(), nb::arg("shaping") = 0.0,
            nb::arg("threads") = 1,
            nb::sig("def __init__(self, num_games: int, config: DuelConfig | None = None, shaping: float = 0.0, "
                    "threads: int = 1) -> None"),
            "num_games games of config's [world] (default world v1), each at its start on the training food.\n"
            "shaping: the weight of the shaped reward (0, the default: off; docs/envs.md). threads: how many\n"
            "threads step the games (each game alone, so the results do not depend on it).")
        .def("__len__", [](const nd_envs &e) { return e.size(); })
        .def_prop_ro("num_games", [](const nd_envs &e) { return e.size(); }, "K, the games held.")
        .def_prop_ro("threads", [](const nd_envs &e) { return e.threads; }, "Threads stepping the games.")
        .def_prop_ro("shaping", [](const nd_envs &e) { return e.shaping; }, "The shaped reward's weight.")
        .def_prop_ro("world_id", [](const nd_envs &e) { return duel_rules_id(&e.rules); },
                     "The world's identity (duel_rules_id; v1 0xb43972def416b019).")
        .def("reset", [](nd_envs &e, const idx_in &indices, const idx_in &layouts) {
                size_t n = indices.shape(0);
                if (layouts.shape(0) != n)
                    throw nd_error(NEAT_E_ARG, "reset: " + std::to_string(n) + " indices but " +
                                                   std::to_string(layouts.shape(0)) + " layouts");
                for (size_t i = 0; i < n; i++) { // all checked before any game changes
                    int64_t k = indices.data()[i], f = layouts.data()[i];
                    if (k < 0 || (uint64_t)k >= e.size())
                        throw nd_error(NEAT_E_ARG, "reset: index " + std::to_string(k) + " of " +
                                                       std::to_string(e.size()) + " games");
                    if (f < DUEL_TRAINING || f >= DUEL_CONFIGS)
                        throw nd_error(NEAT_E_ARG, "reset: layout " + std::to_string(f) +
                                                       ": -1 (the training items) or a comparison layout 0..143");
                }
                std::unique_lock<std::mutex> lk = nd_envs_lock(e);
                std::unique_ptr<float[]> obs(new float[n * 2 * ND_OBS]);
                for (size_t i = 0; i < n; i++) {
                    size_t k = (size_t)indices.data()[i];
                    int f = (int)layouts.data()[i];
                    duel_world_init_rules(&e.w[k], &e.rules, f);
                    e.layout[k] = (int16_t)f;
                    std::memset(&e.ev[k], 0, sizeof e.ev[k]);
                    nd_observe(&e.w[k], DUEL_WEST, &obs[i * 2 * ND_OBS]);
                    nd_observe(&e.w[k], DUEL_EAST, &obs[i * 2 * ND_OBS + ND_OBS]);
                }
                size_t shape[3] = {n, 2, ND_OBS};
                return nd_owned(std::move(obs), shape);
            }, nb::arg("indices"), nb::arg("layouts"),
            "Starts game indices[i] again on food layout layouts[i] (-1: the training items; 0..143: a\n"
            "comparison layout), both int64 arrays; returns those games' first observations, (n, 2, 12)\n"
            "float32, west then east.")
        .def("step", [](nd_envs &e, const act_in &actions) {
                size_t k = e.size();
                if (actions.shape(0) != k)
                    throw nd_error(NEAT_E_ARG, "step: actions of " + std::to_string(actions.shape(0)) + " games for " +
                                                   std::to_string(k) + " (shape (K, 2, 3): game, west/east, l r f)");
                std::unique_ptr<float[]> obs(new float[k * 2 * ND_OBS]), rew(new float[k * 2]);
                std::unique_ptr<bool[]> term(new bool[k]), trunc(new bool[k]);
                {
                    std::unique_lock<std::mutex> lk = nd_envs_lock(e);
                    nb::gil_scoped_release nogil;
                    e.job_act = actions.data();
                    e.job_obs = obs.get();
                    e.job_rew = rew.get();
                    e.job_term = term.get();
                    e.job_trunc = trunc.get();
                    e.step_all();
                }
                size_t s3[3] = {k, 2, ND_OBS}, s2[2] = {k, 2}, s1[1] = {k};
                return std::make_tuple(nd_owned(std::move(obs), s3), nd_owned(std::move(rew), s2),
                                       nd_owned(std::move(term), s1), nd_owned(std::move(trunc), s1));
            }, nb::arg("actions"),
            "One step of every game: actions (K, 2, 3) float32, [game, west/east, (turn left, turn right,\n"
            "forward)], each converted to Q1.15 as neat_duel.q15 does (floor(a * 32768 + 0.5), saturated;\n"
            "NaN is 0). Returns (obs (K, 2, 12) float32, rewards (K, 2) float32, terminated (K,) bool,\n"
            "truncated (K,) bool): terminated after a collision, truncated at the step limit (750). A game\n"
            "already over is not stepped (reward 0, its flags as they were) until reset.")
        .def("observe", [](nd_envs &e) {
                std::unique_lock<std::mutex> lk = nd_envs_lock(e);
                return nd_envs_observe(e);
            }, "Every game's current observations, (K, 2, 12) float32.")
        .def("state", [](nd_envs &e, nb::int_ index) {
                uint32_t k = nd_u32(index, "index");
                if (k >= e.size())
                    throw nb::index_error(("game " + std::to_string(k) + " of " + std::to_string(e.size())).c_str());
                std::unique_lock<std::mutex> lk = nd_envs_lock(e);
                const duel_world &g = e.w[k];
                nb::dict d;
                d["t"] = g.t;
                d["layout"] = (int)e.layout[k];
                d["food_mask"] = g.food_mask;
                d["outcome"] = nd_outcome_name(g.outcome);
                static const char *const side_names[2] = {"west", "east"};
                for (int s = 0; s < 2; s++) {
                    nb::dict r;
                    r["x"] = g.robot[s].x;
                    r["y"] = g.robot[s].y;
                    r["heading"] = g.robot[s].heading;
                    r["energy"] = g.robot[s].energy;
                    r["eaten"] = (int)g.robot[s].eaten;
                    r["ate"] = e.ev[k].eaten_by[s];
                    d[side_names[s]] = r;
                }
                return d;
            }, nb::arg("index"), nb::sig("def state(self, index: int) -> dict[str, typing.Any]"),
            "Game index's state in the world's own numbers: t (steps played), layout, food_mask (bit i:\n"
            "item i on the board), outcome ('running', 'west', 'east', 'draw', 'timeout') and per side\n"
            "('west', 'east') x, y and energy (Q16.16), heading (binary angle, 2^32 a turn), eaten (items\n"
            "so far) and ate (bit i: it ate item i in the last step).")
        .def("food", [](nd_envs &e, nb::int_ index) {
                uint32_t k = nd_u32(index, "index");
                if (k >= e.size())
                    throw nb::index_error(("game " + std::to_string(k) + " of " + std::to_string(e.size())).c_str());
                std::unique_lock<std::mutex> lk = nd_envs_lock(e);
                nb::list items;
                for (unsigned i = 0; i < e.w[k].n_food; i++)
                    items.append(nb::make_tuple(e.w[k].food_x[i], e.w[k].food_y[i]));
                return items;
            }, nb::arg("index"), nb::sig("def food(self, index: int) -> list[tuple[int, int]]"),
            "Game index's food items (eaten or not: food_mask says), (x, y) in Q16.16.");

    m.def("duel_builtin_act", [](const std::string &name, const obs_in &obs) {
            int b = nd_builtin_of(name);
            size_t n = obs.shape(0);
            std::unique_ptr<float[]> out(new float[n * DUEL_N_OUTPUTS]);
            for (size_t j = 0; j < n; j++) {
                nrt_q15 in[DUEL_N_INPUTS], o[DUEL_N_OUTPUTS];
                in[0] = NRT_ONE;
                for (size_t i = 0; i < ND_OBS; i++)
                    in[i + 1] = neat_q15((double)obs.data()[j * ND_OBS + i]);
                duel_builtin_act(b, in, o);
                for (size_t i = 0; i < DUEL_N_OUTPUTS; i++)
                    out[j * DUEL_N_OUTPUTS + i] = (float)o[i] * (1.0f / 32768.0f);
            }
            size_t shape[2] = {n, DUEL_N_OUTPUTS};
            return nd_owned(std::move(out), shape);
        }, nb::arg("name"), nb::arg("obs"),
        "The built-in strategy's actions (duel_builtin_act) for observations (n, 12) float32: (n, 3)\n"
        "float32, each output q / 32768. The observations become Q1.15 by neat_duel.q15, the bias is\n"
        "prepended.");
}
