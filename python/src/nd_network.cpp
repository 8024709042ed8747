// nd_network.cpp - neat_duel.Network: one network in the fixed-point runtime (the microcontroller's executor),
// stepped from Python with float or Q1.15 values; its blob is exactly what a microcontroller loads.
#include <cstdlib>
#include <cstring>
#include <new>

#include <nanobind/stl/string.h>

#include "nd.h"

#define ND_BLOB_MAX (1u << 20) // a blob of 256 nodes and 65535 connections is 32 + 4 * 65535 bytes

using in_f64 = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
using in_q15 = nb::ndarray<const int16_t, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

nd_network::nd_network()
{
    neat_alloc a;
    a.fn = &nd_network::alloc;
    a.ud = this;
    neat_phenotype_init(&ph, &a);
}

nd_network::~nd_network()
{
    neat_phenotype_free(&ph);
    if (io != nullptr && !is_local(io))
        std::free(io);
}

void *nd_network::alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    nd_network *n = (nd_network *)ud;
    if (new_size == 0) {
        if (ptr != nullptr && !n->is_local(ptr))
            std::free(ptr);
        return nullptr;
    }
    if (ptr != nullptr && !n->is_local(ptr))
        return std::realloc(ptr, new_size);
    size_t need = (new_size + 15) & ~(size_t)15;
    void *r;
    if (n->local_used + need <= local_size) {
        r = n->local + n->local_used;
        n->local_used += need;
    } else {
        r = std::malloc(new_size);
        if (r == nullptr)
            return nullptr;
    }
    if (ptr != nullptr)
        std::memcpy(r, ptr, old_size < new_size ? old_size : new_size);
    return r;
}

void nd_network::sized()
{
    size_t n = (size_t)ph.net.n_inputs + ph.net.n_outputs;
    if (io != nullptr && !is_local(io))
        std::free(io);
    io = (nrt_q15 *)alloc(this, nullptr, 0, n * sizeof(nrt_q15));
    if (io == nullptr)
        throw std::bad_alloc();
    std::memset(io, 0, n * sizeof(nrt_q15));
}

static nd_network *nd_network_from_blob(const uint8_t *b, size_t len, const std::string &name)
{
    nd_network *n = new nd_network();
    int err = neat_phenotype_load_blob(&n->ph, b, len);
    if (err) {
        delete n;
        throw nd_error(err, name + ": not a network blob this runtime loads: " + nd_strerror(err), name);
    }
    n->sized();
    return n;
}

// The task's inputs (without the bias) as the runtime's: the bias first, each value in Q1.15 (neat_q15: rounded,
// saturated to [-1, 1)).
static void nd_inputs(nd_network &s, const in_f64 &x)
{
    size_t n = s.n_in() - 1;
    if (x.shape(0) != n)
        throw nd_error(NEAT_E_ARG, "inputs: " + std::to_string(x.shape(0)) + " values for a network of " +
                                       std::to_string(n) + " inputs (the bias is added here)");
    const double *v = x.data();
    s.in()[0] = NRT_ONE;
    for (size_t i = 0; i < n; i++)
        s.in()[i + 1] = neat_q15(v[i]);
}

// Inputs given as a list or tuple of numbers (the common case, read without numpy's help), or as a 1-D float64
// array (any other array is converted by numpy).
static void nd_inputs_any(nd_network &s, nb::handle x)
{
    size_t n = s.n_in() - 1;
    bool list = PyList_Check(x.ptr()), tuple = !list && PyTuple_Check(x.ptr());
    if (list || tuple) {
        Py_ssize_t len = list ? PyList_Size(x.ptr()) : PyTuple_Size(x.ptr());
        if ((size_t)len != n)
            throw nd_error(NEAT_E_ARG, "inputs: " + std::to_string(len) + " values for a network of " +
                                           std::to_string(n) + " inputs (the bias is added here)");
        s.in()[0] = NRT_ONE;
        for (size_t i = 0; i < n; i++) {
            PyObject *v = list ? PyList_GetItem(x.ptr(), (Py_ssize_t)i) : PyTuple_GetItem(x.ptr(), (Py_ssize_t)i);
            double d = PyFloat_AsDouble(v);
            if (d == -1.0 && PyErr_Occurred())
                throw nb::python_error();
            s.in()[i + 1] = neat_q15(d);
        }
        return;
    }
    {
        // a contiguous float64 buffer (a numpy array) read in place, without the array caster's cost
        Py_buffer v;
        if (PyObject_CheckBuffer(x.ptr()) && PyObject_GetBuffer(x.ptr(), &v, PyBUF_STRIDES | PyBUF_FORMAT) == 0) {
            bool f64 = v.ndim == 1 && v.itemsize == 8 && v.format != nullptr &&
                       (std::strcmp(v.format, "d") == 0 || std::strcmp(v.format, "<d") == 0 ||
                        std::strcmp(v.format, "=d") == 0) &&
                       (v.strides == nullptr || v.strides[0] == 8);
            if (f64) {
                size_t len = (size_t)v.shape[0];
                if (len != n) {
                    PyBuffer_Release(&v);
                    throw nd_error(NEAT_E_ARG, "inputs: " + std::to_string(len) + " values for a network of " +
                                                   std::to_string(n) + " inputs (the bias is added here)");
                }
                const double *d = (const double *)v.buf;
                s.in()[0] = NRT_ONE;
                for (size_t i = 0; i < n; i++)
                    s.in()[i + 1] = neat_q15(d[i]);
                PyBuffer_Release(&v);
                return;
            }
            PyBuffer_Release(&v);
        } else {
            PyErr_Clear();
        }
    }
    in_f64 arr;
    if (!nb::try_cast<in_f64>(x, arr)) {
        nb::object a = nb::module_::import_("numpy").attr("ascontiguousarray")(x, "float64");
        if (!nb::try_cast<in_f64>(a, arr))
            throw nd_error(NEAT_E_ARG, "inputs: a 1-D sequence of numbers");
        nd_inputs(s, arr);
        return;
    }
    nd_inputs(s, arr);
}

// The outputs as a list of floats (what a fitness function indexes or sums; np.asarray makes an array of it).
static nb::list nd_outputs(const nd_network &s)
{
    size_t n = s.n_out();
    PyObject *l = PyList_New((Py_ssize_t)n);
    if (l == nullptr)
        throw nb::python_error();
    for (size_t i = 0; i < n; i++)
        PyList_SetItem(l, (Py_ssize_t)i, PyFloat_FromDouble(neat_from_q15(s.out()[i])));
    return nb::steal<nb::list>(l);
}

void nd_bind_network(nb::module_ &m)
{
    nb::class_<nd_network> network = nb::class_<nd_network>(m, "Network",
                           "A network in the runtime (Q1.15 fixed point, the same code a microcontroller runs):\n"
                           "inputs in [-1, 1) without the bias (added here; a value outside saturates, NaN is 0),\n"
                           "outputs in [0, 1).")
        .def("step", [](nd_network &s, nb::handle x) {
                nd_inputs_any(s, x);
                nrt_step(&s.ph.net, s.in(), s.out());
                return nd_outputs(s);
            }, nb::arg("inputs"),
            nb::sig("def step(self, inputs: collections.abc.Sequence[float] | numpy.typing.ArrayLike) -> list[float]"),
            "One time step (a control task calls it once per step): inputs a list, tuple or 1-D array of\n"
            "n_inputs numbers; the outputs as a list of floats.")
        .def("step_into", [](nd_network &s, nb::handle x, nb::handle out) {
                // out through the buffer protocol, checked: a float32 or int64 array, or a read-only one, would
                // otherwise be converted into a copy that is written and thrown away
                Py_buffer v;
                if (!PyObject_CheckBuffer(out.ptr()) ||
                    PyObject_GetBuffer(out.ptr(), &v, PyBUF_STRIDES | PyBUF_FORMAT) != 0) {
                    PyErr_Clear();
                    throw nb::type_error(("out: a float64 array of the outputs, not " +
                                          std::string(Py_TYPE(out.ptr())->tp_name)).c_str());
                }
                bool f64 = v.ndim == 1 && v.itemsize == 8 && v.format != nullptr &&
                           (std::strcmp(v.format, "d") == 0 || std::strcmp(v.format, "<d") == 0 ||
                            std::strcmp(v.format, "=d") == 0) &&
                           (v.strides == nullptr || v.strides[0] == 8);
                std::string bad = !f64 ? "out: a float64 array of one dimension, contiguous (got format '" +
                                             std::string(v.format != nullptr ? v.format : "B") + "', " +
                                             std::to_string(v.ndim) + " dimension" + (v.ndim == 1 ? "" : "s") + ")"
                                  : v.readonly ? "out: a writable float64 array (this one is read-only)" : "";
                size_t len = v.ndim >= 1 ? (size_t)v.shape[0] : 0;
                double *o = (double *)v.buf;
                PyBuffer_Release(&v); // the array itself stays alive: out holds it
                if (!bad.empty())
                    throw nb::type_error(bad.c_str());
                if (len != s.n_out())
                    throw nd_error(NEAT_E_ARG, "out: " + std::to_string(len) + " values for " +
                                                   std::to_string(s.n_out()) + " outputs");
                nd_inputs_any(s, x);
                nrt_step(&s.ph.net, s.in(), s.out());
                for (size_t i = 0; i < s.n_out(); i++)
                    o[i] = neat_from_q15(s.out()[i]);
            }, nb::arg("inputs"), nb::arg("out"),
            nb::sig("def step_into(self, inputs: collections.abc.Sequence[float] | numpy.typing.ArrayLike, "
                    "out: numpy.typing.NDArray[numpy.float64]) -> None"),
            "step, writing the outputs into out (a writable 1-D float64 array of n_outputs values: no\n"
            "allocation; TypeError for any other array, which could only be written as a copy).")
        .def("settle", [](nd_network &s, nb::handle x, int max_steps) {
                nd_inputs_any(s, x);
                if (max_steps < 0)
                    max_steps = s.ph.net.n_nodes + 1;
                nrt_settle(&s.ph.net, s.in(), s.out(), max_steps);
                return nd_outputs(s);
            }, nb::arg("inputs"), nb::arg("max_steps") = -1,
            nb::sig("def settle(self, inputs: collections.abc.Sequence[float] | numpy.typing.ArrayLike, "
                    "max_steps: int = -1) -> list[float]"),
            "Steps with the same inputs until no activation changes (a feed-forward task), at most\n"
            "max_steps times (default: its nodes + 1): the outputs.")
        .def("step_q15", [](nd_network &s, const in_q15 &x) {
                size_t n = s.n_in();
                if (x.shape(0) != n)
                    throw nd_error(NEAT_E_ARG, "inputs: " + std::to_string(x.shape(0)) + " values for " +
                                                   std::to_string(n) + " (bias included: the first is 32767)");
                std::memcpy(s.in(), x.data(), n * sizeof(int16_t));
                nrt_step(&s.ph.net, s.in(), s.out());
                int16_t *o = new int16_t[s.n_out()];
                std::memcpy(o, s.out(), s.n_out() * sizeof(int16_t));
                nb::capsule owner(o, [](void *p) noexcept { delete[] (int16_t *)p; });
                size_t shape[1] = {s.n_out()};
                return nb::ndarray<nb::numpy, int16_t, nb::ndim<1>>(o, 1, shape, owner);
            }, nb::arg("inputs"),
            "One step in the runtime's own numbers: Q1.15 inputs with the bias first (32767), Q1.15\n"
            "outputs; bit for bit what nrt_step gives on any machine.")
        .def("reset", [](nd_network &s) { nrt_reset(&s.ph.net); },
             "All activations back to 0: call it between trials, or one trial's state leaks into the next.")
        .def_prop_ro("activations", [](nb::handle self) {
                nd_network &s = nb::cast<nd_network &>(self);
                size_t shape[1] = {s.ph.net.n_nodes};
                return nb::ndarray<nb::numpy, const int16_t, nb::ndim<1>>(s.ph.net.act[s.ph.net.cur], 1, shape, self);
            }, "The current Q1.15 activation of every node (bias, inputs, outputs, hidden): a read-only view.")
        .def_prop_ro("n_inputs", [](const nd_network &s) { return s.ph.net.n_inputs - 1; },
                     "Inputs, without the bias.")
        .def_prop_ro("n_outputs", [](const nd_network &s) { return s.ph.net.n_outputs; }, "Outputs.")
        .def_prop_ro("n_hidden", [](const nd_network &s) { return s.ph.net.n_hidden; }, "Hidden nodes.")
        .def_prop_ro("n_conns", [](const nd_network &s) { return s.ph.net.n_conns; }, "Connections.")
        .def_prop_ro("step_mode", [](const nd_network &s) {
                return std::string(s.ph.net.step == NRT_STEP_PROPAGATE ? "propagate" : "sync");
            }, "'sync' (one layer a step) or 'propagate' (feed-forward paths within the step).")
        .def_prop_ro("blob", [](const nd_network &s) { return nb::bytes((const char *)s.ph.blob, s.ph.blob_len); },
                     "The champion blob (docs/formats.md): what duel_evolve writes and a microcontroller loads.")
        .def("save", [](const nd_network &s, const nd_path &fpath) {
                const std::string path = fpath.string(); nd_write_file(path, s.ph.blob, s.ph.blob_len); },
             nb::arg("path"), "Writes the blob, through a temporary file and a rename.")
        .def("__repr__", [](const nd_network &s) {
                return "Network(" + std::to_string(s.ph.net.n_inputs - 1) + " inputs, " +
                       std::to_string(s.ph.net.n_outputs) + " outputs, " + std::to_string(s.ph.net.n_hidden) +
                       " hidden, " + std::to_string(s.ph.net.n_conns) + " connections, " +
                       (s.ph.net.step == NRT_STEP_PROPAGATE ? "propagate" : "sync") + ")";
            });
    nd_def_file_loaders(network, nd_network_from_blob, ND_BLOB_MAX, "from_blob", "blob",
                        "A network from a blob, checked by the runtime (size, magic, version, checksum, indices) before\n"
                        "a byte is trusted; FormatError otherwise.",
                        "Reads a blob file (duel_evolve's champions/gen-G.blob, a Network.save).");
}
