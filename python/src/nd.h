// nd.h - what the binding's files share: the C headers, the C error codes raised as neat_duel.errors exceptions, the
// genome and network objects.
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <cstdint>
#include <atomic>
#include <mutex>
#include <string>
#include <vector>

#include "neat.h"
#include "neat_phenotype.h"
#include "nrt.h"
#include "neat_coev.h"
extern "C" {
#include "duel_config.h"
#include "neat_config.h"
#include "neat_ini.h"
}

namespace nb = nanobind;

// A duel_evolve run configuration ([run], [coevolution], [neat], [world], [opponents]), read and written by the
// C code duel_evolve uses (DuelConfig, nd_duel.cpp).
struct nd_duel_config {
    duel_config cfg;
    nd_duel_config() { duel_config_default(&cfg); }
};

// A C error on its way to Python: neat_duel.errors picks the class from the code (nd_errors.cpp).
struct nd_error : std::exception {
    int code;          // a neat_error, or an nrt_error - 100
    std::string msg;   // the whole message, file and offset included
    std::string path;  // the file, if any
    long long offset;  // the byte offset of the problem in it, or -1
    long long index;   // the genome whose fitness was refused, or -1
    nd_error(int c, std::string m, std::string p = "", long long off = -1, long long idx = -1)
        : code(c), msg(std::move(m)), path(std::move(p)), offset(off), index(idx)
    {
    }
    const char *what() const noexcept override { return msg.c_str(); }
};

// The text of a libneat code (or an nrt code - 100).
std::string nd_strerror(int code);
// Raises code with "what: the C library's text".
[[noreturn]] void nd_fail(int code, const std::string &what);
// A Python int argument as an unsigned count or seed: a negative or too large one is ArgumentError (a ValueError)
// naming it, not nanobind's generic TypeError. lo: the least allowed.
uint64_t nd_u64(nb::int_ v, const char *name);
uint32_t nd_u32(nb::int_ v, const char *name, uint32_t lo = 0);
// The truth value of a Python object, as Python's if reads it (a numpy bool, None, 1, a list).
bool nd_truth(nb::handle v);

// A genome of its own (a copy: what the population does next never changes it), with the shape and step mode its
// network is built with. Inside Population.run's fitness call it borrows the population's genome instead of copying
// it, and copies it only if the call keeps a reference when it returns (or asks for a numpy view): the copy most
// evaluations never need.
struct nd_genome {
    neat_genome g;
    const neat_genome *borrowed = nullptr; // the population's genome, during one fitness call only
    uint32_t n_inputs = 0, n_outputs = 0;
    int net_step = NEAT_STEP_SYNC;
    // where a genome file says it was made (docs/formats.md, genome file version 2): kept to be written again
    bool has_origin = false;
    std::string origin_tag; // its run's game tag (the duel's world rules first)
    nd_genome() { neat_genome_init(&g); }
    nd_genome(nd_genome &&o) noexcept
        : g(o.g), borrowed(o.borrowed), n_inputs(o.n_inputs), n_outputs(o.n_outputs), net_step(o.net_step),
          has_origin(o.has_origin), origin_tag(std::move(o.origin_tag))
    {
        neat_genome_init(&o.g);
        o.borrowed = nullptr;
    }
    nd_genome(const nd_genome &) = delete;
    nd_genome &operator=(const nd_genome &) = delete;
    ~nd_genome() { neat_genome_free(&g, nullptr); }
    // Its genes, its own or borrowed.
    const neat_genome &gen() const { return borrowed != nullptr ? *borrowed : g; }
    // Makes borrowed genes its own (a copy); false if memory ran out (then it is left empty, never dangling).
    bool own() noexcept;
};

// A network in the runtime (what a microcontroller runs), with its input and output buffers. A small network's
// buffers (its blob, the runtime's memory, the inputs and outputs) are carved from `local` (a genome's network
// built in every evaluation then costs no allocation of its own); so the network never moves once loaded.
struct nd_network {
    static constexpr size_t local_size = 320; // an XOR or pole network, with room; larger ones use the heap
    neat_phenotype ph;
    nrt_q15 *io = nullptr; // the inputs (the bias first), then the outputs
    size_t local_used = 0;
    alignas(16) uint8_t local[local_size];
    nd_network();
    nd_network(const nd_network &) = delete;
    nd_network &operator=(const nd_network &) = delete;
    ~nd_network();
    void sized(); // io sized to the loaded network
    size_t n_in() const { return ph.net.n_inputs; } // the bias included
    size_t n_out() const { return ph.net.n_outputs; }
    nrt_q15 *in() { return io; }
    nrt_q15 *out() { return io + ph.net.n_inputs; }
    const nrt_q15 *out() const { return io + ph.net.n_inputs; }
    // libneat's allocation hook for ph: local while it lasts, then the heap
    static void *alloc(void *ud, void *ptr, size_t old_size, size_t new_size);
    bool is_local(const void *p) const { return (const uint8_t *)p >= local && (const uint8_t *)p < local + local_size; }
};

// A copy of g (shape and step mode from p), returned by value: nb::cast moves it into its Python object.
nd_genome nd_genome_copy(const neat_genome *g, const neat_params &p);
// g's network, loaded (encoded exactly as evolution evaluates it), built in place in its Python object.
nb::object nd_network_of(const nd_genome &g);
// Writes bytes to path through a temporary file and a rename (never a half-written file); raises OSError.
void nd_write_file(const std::string &path, const uint8_t *bytes, size_t len);
// The whole regular file at path, at most cap bytes; raises OSError (or a format error for a larger file).
std::vector<uint8_t> nd_read_file(const std::string &path, size_t cap);


void nd_bind_errors(nb::module_ &m);
void nd_bind_params(nb::module_ &m);
void nd_bind_genome(nb::module_ &m);
void nd_bind_network(nb::module_ &m);
void nd_bind_population(nb::module_ &m);

// A path argument: a str or any os.PathLike (pathlib.Path), as Python's own open takes (the caster below).
struct nd_path {
    std::string s;
    std::string string() const { return s; }
};

namespace nanobind::detail {
template <> struct type_caster<nd_path> {
    NB_TYPE_CASTER(nd_path, const_name("str | os.PathLike[str]"))
    bool from_python(handle src, uint8_t, cleanup_list *) noexcept
    {
        PyObject *fs = PyOS_FSPath(src.ptr());
        if (fs == nullptr) {
            PyErr_Clear();
            return false;
        }
        bool ok = PyUnicode_Check(fs);
        if (ok) {
            Py_ssize_t n = 0;
            const char *c = PyUnicode_AsUTF8AndSize(fs, &n);
            ok = c != nullptr;
            if (ok)
                value.s.assign(c, (size_t)n);
            else
                PyErr_Clear();
        }
        Py_DECREF(fs);
        return ok;
    }
    static handle from_cpp(const nd_path &p, rv_policy, cleanup_list *) noexcept
    {
        return PyUnicode_FromStringAndSize(p.s.data(), (Py_ssize_t)p.s.size());
    }
};
} // namespace nanobind::detail

// A class whose objects come from a file's bytes: its static from_bytes (or from_blob: bytes_fn) and load, the one
// way a binding reads a file (at most cap bytes, nd_read_file) and hands the bytes to its decoder, which names the
// file (or the name given, "<bytes>") in its errors.
template <class T>
void nd_def_file_loaders(nb::class_<T> &cls, T *(*decode)(const uint8_t *, size_t, const std::string &), size_t cap,
                         const char *bytes_fn, const char *bytes_arg, const char *bytes_doc, const char *load_doc)
{
    cls.def_static(bytes_fn, [decode](nb::bytes data, const std::string &name) {
            return decode((const uint8_t *)data.c_str(), data.size(), name);
        }, nb::arg(bytes_arg), nb::arg("name") = "<bytes>", nb::rv_policy::take_ownership, bytes_doc);
    cls.def_static("load", [decode, cap](const nd_path &fpath) {
            const std::string path = fpath.string();
            std::vector<uint8_t> b = nd_read_file(path, cap);
            return decode(b.data(), b.size(), path);
        }, nb::arg("path"), nb::rv_policy::take_ownership, load_doc);
}

// The parameters object bound as neat_duel.Params.
struct nd_params {
    neat_params p = neat_params_default();
};

// A game played in C (neat_duel.Duel): its batch function and data for coevolution c's next generation.
struct nd_native_game {
    neat_play_fn play = nullptr;
    void *ud = nullptr;
    std::unique_lock<std::mutex> lock; // the game object's, held until the generation is played
};
// 1 with out filled when game is a built-in game object (locked for this caller, waited for without the
// interpreter lock, and prepared for c's parameters and next generation), else 0. Raises ParamError when c's
// networks do not fit the game.
bool nd_native_game_of(nb::handle game, neat_coev *c, nd_native_game *out);
// A coevolution (neat_duel.Coevolution).
struct nd_coev {
    neat_coev *c = nullptr;
    // 1 while a generation is played (step or run): a second step, or a read of the state, from the game function
    // or another thread is refused instead of reaching memory the step is changing
    std::atomic<int> busy{0};
    nd_coev() = default;
    nd_coev(const nd_coev &) = delete;
    nd_coev &operator=(const nd_coev &) = delete;
    ~nd_coev() { neat_coev_free(c); }
};
// Takes ownership of c as a neat_duel.Coevolution.
nd_coev *nd_coev_wrap(neat_coev *c);
void nd_bind_coev(nb::module_ &m);
void nd_bind_duel(nb::module_ &m);
void nd_bind_run(nb::module_ &m);
void nd_bind_engine(nb::module_ &m);
void nd_bind_env(nb::module_ &m);
