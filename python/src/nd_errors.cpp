// nd_errors.cpp - C error codes as Python exceptions (neat_duel.errors), with the C message, file, offset and index.
#include <nanobind/stl/string.h>

#include "nd.h"

std::string nd_strerror(int code)
{
    if (code <= -100)
        return nrt_strerror(code + 100);
    return neat_strerror(code);
}

void nd_fail(int code, const std::string &what)
{
    throw nd_error(code, what + ": " + nd_strerror(code));
}

// The class of neat_duel.errors for a code (docs/python.md, "Errors").
static const char *nd_error_class(int code)
{
    switch (code) {
    case NEAT_E_ARG: return "ArgumentError";
    case NEAT_E_NOMEM: return "OutOfMemoryError";
    case NEAT_E_PARAM: return "ParamError";
    case NEAT_E_FITNESS: return "FitnessError";
    case NEAT_E_TOOBIG: return "TooBigError";
    case NEAT_E_FORMAT:
    case NEAT_E_CRC:
    case NEAT_E_TRUNCATED: return "FormatError";
    case NEAT_E_STATE: return "StateError";
    case NEAT_E_COUNTERS: return "CountersError";
    default: return code <= -100 ? "FormatError" : "NeatError";
    }
}

void nd_bind_errors(nb::module_ &m)
{
    (void)m;
    nb::register_exception_translator([](const std::exception_ptr &p, void *) {
        try {
            std::rethrow_exception(p);
        } catch (const nd_error &e) {
            nb::object errors = nb::module_::import_("neat_duel.errors");
            nb::object cls = errors.attr(nd_error_class(e.code));
            nb::object path = e.path.empty() ? nb::none() : nb::cast(e.path);
            nb::object offset = e.offset < 0 ? nb::none() : nb::cast(e.offset);
            nb::object index = e.index < 0 ? nb::none() : nb::cast(e.index);
            nb::object exc = cls(e.msg, e.code, path, offset, index);
            PyErr_SetObject(cls.ptr(), exc.ptr());
        }
    });
}

uint64_t nd_u64(nb::int_ v, const char *name)
{
    int overflow = 0;
    long long x = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    if (x == -1 && PyErr_Occurred())
        throw nb::python_error();
    if (overflow < 0 || (overflow == 0 && x < 0))
        throw nd_error(NEAT_E_ARG, std::string(name) + ": " + nb::cast<std::string>(nb::repr(v)) +
                                       ": a count or seed is not negative");
    if (overflow == 0)
        return (uint64_t)x;
    unsigned long long u = PyLong_AsUnsignedLongLong(v.ptr());
    if (u == (unsigned long long)-1 && PyErr_Occurred()) {
        PyErr_Clear();
        throw nd_error(NEAT_E_ARG, std::string(name) + ": " + nb::cast<std::string>(nb::repr(v)) +
                                       ": more than 2^64 - 1");
    }
    return (uint64_t)u;
}

uint32_t nd_u32(nb::int_ v, const char *name, uint32_t lo)
{
    uint64_t x = nd_u64(v, name);
    if (x > 0xffffffffu)
        throw nd_error(NEAT_E_ARG, std::string(name) + ": " + std::to_string(x) + ": more than 4294967295");
    if (x < lo)
        throw nd_error(NEAT_E_ARG, std::string(name) + ": " + std::to_string(x) + ": at least " + std::to_string(lo));
    return (uint32_t)x;
}

bool nd_truth(nb::handle v)
{
    int t = PyObject_IsTrue(v.ptr());
    if (t < 0)
        throw nb::python_error();
    return t != 0;
}
