// nd_params.cpp - neat_duel.Params: every libneat parameter by keyword, attribute or INI file, read and checked by
// the C code the command-line tools use (one parser, one table of keys, ranges and messages).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "nd.h"

static const neat_cfg_key *nd_key(const char *name)
{
    size_t n;
    const neat_cfg_key *k = neat_config_keys(&n);
    for (size_t i = 0; i < n; i++)
        if (std::strcmp(k[i].name, name) == 0)
            return &k[i];
    return nullptr;
}

// A Python value as the INI text of key k: what a user would write in the file (bools as true/false, reals in
// their shortest exact form, names as they are).
static std::string nd_value_text(const neat_cfg_key *k, nb::handle v)
{
    if (nb::isinstance<bool>(v)) {
        if (k->type != NEAT_CFG_BOOL)
            throw nd_error(NEAT_E_PARAM, std::string(k->name) + ": a bool for a parameter that is not one");
        return nb::cast<bool>(v) ? "true" : "false";
    }
    if (nb::isinstance<nb::str>(v)) {
        if (k->type != NEAT_CFG_ENUM)
            throw nd_error(NEAT_E_PARAM, std::string(k->name) + ": a string for a number");
        return nb::cast<std::string>(v);
    }
    if (nb::isinstance<nb::int_>(v) || nb::isinstance<nb::float_>(v) || PyNumber_Check(v.ptr())) {
        if (k->type == NEAT_CFG_ENUM || k->type == NEAT_CFG_BOOL)
            throw nd_error(NEAT_E_PARAM, std::string(k->name) + ": a number for a " +
                                             (k->type == NEAT_CFG_BOOL ? "bool" : "name"));
        if (k->type == NEAT_CFG_U32) {
            if (!PyIndex_Check(v.ptr()))
                throw nd_error(NEAT_E_PARAM, std::string(k->name) + ": an integer, not " +
                                                 nb::cast<std::string>(nb::repr(v)));
            return nb::cast<std::string>(nb::str(nb::int_(v)));
        }
        double x = nb::cast<double>(nb::float_(v));
        char buf[NEAT_FMT_DOUBLE];
        if (!std::isfinite(x))
            throw nd_error(NEAT_E_PARAM, std::string(k->name) + " = " + nb::cast<std::string>(nb::repr(v)) +
                                             ": not a finite number");
        neat_fmt_double(buf, x);
        return buf;
    }
    throw nd_error(NEAT_E_PARAM, std::string(k->name) + ": a value of type " +
                                     nb::cast<std::string>(nb::str(v.type().attr("__name__"))));
}

static void nd_set(nd_params &self, const std::string &key, nb::handle v)
{
    char err[600];
    const neat_cfg_key *k = nd_key(key.c_str());
    // an unknown key goes to neat_config_set too: its message suggests the closest one
    std::string text = k != nullptr ? nd_value_text(k, v) : std::string("0");
    if (neat_config_set(&self.p, key.c_str(), text.c_str(), err, sizeof err) != 0)
        throw nd_error(NEAT_E_PARAM, err);
}

static nb::object nd_get(const nd_params &self, const neat_cfg_key *k)
{
    const char *base = (const char *)&self.p + k->offset;
    switch (k->type) {
    case NEAT_CFG_U32: return nb::cast(*(const uint32_t *)base);
    case NEAT_CFG_F64: return nb::cast(*(const double *)base);
    case NEAT_CFG_BOOL: return nb::cast(*(const int *)base != 0);
    case NEAT_CFG_ENUM: return nb::cast(std::string(k->names[*(const int *)base]));
    }
    return nb::none();
}

static void nd_check(const nd_params &self)
{
    const char *field = nullptr;
    if (neat_params_check(&self.p, &field) != NEAT_OK)
        throw nd_error(NEAT_E_PARAM, std::string("parameter ") + (field ? field : "?") +
                                         " out of range (or in conflict with another: docs/parameters.md)");
}

// The [neat] section of an INI file the command-line tools read (duel_evolve's run configurations, neat_bench's):
// the other sections are those tools' own settings, not NEAT's.
static int nd_ini_handler(void *user, const char *section, const char *key, const char *value, char *err,
                          size_t err_len)
{
    static const char *const others[] = {"run", "coevolution", "world", "opponents", "bench"};
    if (std::strcmp(section, "neat") == 0) {
        if (std::strcmp(key, "start") == 0)
            return 0; // duel_evolve's start topology: a run's setting
        return neat_config_set(&((nd_params *)user)->p, key, value, err, err_len);
    }
    for (const char *o : others)
        if (std::strcmp(section, o) == 0)
            return 0;
    std::snprintf(err, err_len, "unknown section [%s] (expected [neat], or a tool's [run], [coevolution], [world], "
                                "[opponents] or [bench])", section);
    return -1;
}

static nd_params nd_from_ini_text(const std::string &text, const std::string &name)
{
    nd_params r;
    char err[1200];
    if (neat_ini_parse_text(name.c_str(), text.data(), text.size(), nd_ini_handler, &r, err, sizeof err) != 0)
        throw nd_error(NEAT_E_PARAM, err, name);
    nd_check(r);
    return r;
}

static std::string nd_to_ini(const nd_params &self)
{
    char *buf = nullptr;
    size_t len = 0;
    FILE *mem = open_memstream(&buf, &len);
    if (mem == nullptr)
        throw std::bad_alloc();
    std::fputs("[neat]\n", mem);
    neat_config_dump(mem, &self.p);
    std::fclose(mem);
    std::string s(buf, len);
    std::free(buf);
    return s;
}

void nd_bind_params(nb::module_ &m)
{
    nb::class_<nd_params> cls(m, "Params",
                              "NEAT's parameters: the 2004 paper's Appendix A values unless set (docs/parameters.md).\n\n"
                              "Set them by keyword (Params(pop_size=150, n_inputs=2, n_outputs=1)), as attributes,\n"
                              "or from the [neat] section of an INI file the command-line tools read\n"
                              "(Params.from_ini). Every value is checked by the C library: a bad one raises\n"
                              "ParamError with its message (an unknown name suggests the closest).");
    cls.def(
        "__init__",
        [](nd_params *self, nb::kwargs kw) {
            new (self) nd_params();
            // a profile first, wherever it stands: it sets what the other keywords refine (as in an INI file)
            if (kw.contains("profile"))
                nd_set(*self, "profile", kw["profile"]);
            for (auto item : kw) {
                std::string key = nb::cast<std::string>(item.first);
                if (key != "profile")
                    nd_set(*self, key, item.second);
            }
            nd_check(*self);
        },
        nb::sig("def __init__(self, **kwargs: int | float | bool | str) -> None"),
        "Appendix A's values, with the keywords given set (ParamError if one is unknown or out of range).\n"
        "profile='neat-cpp-1.2.1' sets NEAT C++ 1.2.1's rules first, wherever it stands; the other keywords\n"
        "refine it (docs/parameters.md, \"NEAT C++ 1.2.1\").");
    size_t n;
    const neat_cfg_key *keys = neat_config_keys(&n);
    for (size_t i = 0; i < n; i++) {
        const neat_cfg_key *k = &keys[i];
        // the key's type and range, from the table the INI reader checks with
        char range[160];
        switch (k->type) {
        case NEAT_CFG_U32: std::snprintf(range, sizeof range, "an integer in [%.0f, %.0f]", k->min, k->max); break;
        case NEAT_CFG_F64: std::snprintf(range, sizeof range, "a real in [%g, %g]", k->min, k->max); break;
        case NEAT_CFG_BOOL: std::snprintf(range, sizeof range, "True or False (true or false in an INI file)"); break;
        default: {
            std::string names;
            for (int j = 0; j <= (int)k->max; j++)
                names += std::string(j ? ", " : "") + "'" + k->names[j] + "'";
            std::snprintf(range, sizeof range, "one of %s", names.c_str());
        }
        }
        std::string doc = std::string("[neat] ") + k->name + ": " + range + " (its meaning and source: docs/parameters.md)";
        switch (k->type) {
        case NEAT_CFG_U32:
            cls.def_prop_rw(k->name, [k](const nd_params &s) { return *(const uint32_t *)((const char *)&s.p + k->offset); },
                            [k](nd_params &s, nb::object v) { nd_set(s, k->name, v); },
                            doc.c_str());
            break;
        case NEAT_CFG_F64:
            cls.def_prop_rw(k->name, [k](const nd_params &s) { return *(const double *)((const char *)&s.p + k->offset); },
                            [k](nd_params &s, nb::object v) { nd_set(s, k->name, v); },
                            doc.c_str());
            break;
        case NEAT_CFG_BOOL:
            cls.def_prop_rw(k->name, [k](const nd_params &s) { return *(const int *)((const char *)&s.p + k->offset) != 0; },
                            [k](nd_params &s, nb::object v) { nd_set(s, k->name, v); },
                            doc.c_str());
            break;
        case NEAT_CFG_ENUM:
            cls.def_prop_rw(k->name,
                            [k](const nd_params &s) {
                                return std::string(k->names[*(const int *)((const char *)&s.p + k->offset)]);
                            },
                            [k](nd_params &s, nb::object v) { nd_set(s, k->name, v); },
                            doc.c_str());
            break;
        }
    }
    cls.def("set", &nd_set, nb::arg("key"), nb::arg("value"),
            "Sets one parameter by name (ParamError: unknown name, bad value).")
        .def("get", [](const nd_params &s, const std::string &key) {
                const neat_cfg_key *k = nd_key(key.c_str());
                if (k == nullptr) {
                    char err[600];
                    neat_params tmp = s.p;
                    neat_config_set(&tmp, key.c_str(), "0", err, sizeof err);
                    throw nd_error(NEAT_E_PARAM, err);
                }
                return nd_get(s, k);
            }, nb::arg("key"), "One parameter by name.")
        .def("check", &nd_check, "ParamError if the values do not hold together (neat_params_check).")
        .def_static("keys", []() {
                size_t nk;
                const neat_cfg_key *ks = neat_config_keys(&nk);
                std::vector<std::string> v;
                for (size_t i = 0; i < nk; i++)
                    v.emplace_back(ks[i].name);
                return v;
            }, "Every parameter's name, in the order to_ini writes them.")
        .def("to_dict", [](const nd_params &s) {
                size_t nk;
                const neat_cfg_key *ks = neat_config_keys(&nk);
                nb::dict d;
                for (size_t i = 0; i < nk; i++)
                    d[ks[i].name] = nd_get(s, &ks[i]);
                return d;
            }, nb::sig("def to_dict(self) -> dict[str, int | float | bool | str]"),
            "Every parameter by name: Params(**p.to_dict()) == p.")
        .def("to_ini", &nd_to_ini, "The [neat] section with every key, as duel_evolve config --dump writes it.")
        .def_static("from_ini",
                    [](const nd_path &fpath) {
                const std::string path = fpath.string();
                        std::vector<uint8_t> b = nd_read_file(path, NEAT_INI_MAX_FILE);
                        return nd_from_ini_text(std::string(b.begin(), b.end()), path);
                    },
                    nb::arg("path"),
                    "The [neat] section of an INI file (a duel_evolve configuration, bench/xor.ini); the\n"
                    "other sections are the tools' own. ParamError names the file and line of a problem.")
        .def_static("from_ini_text", &nd_from_ini_text, nb::arg("text"), nb::arg("name") = "<text>",
                    "As from_ini, from text (name in messages).")
        .def("copy", [](const nd_params &s) { return s; }, "An independent copy.")
        .def("__copy__", [](const nd_params &s) { return s; })
        .def("__deepcopy__", [](const nd_params &s, nb::handle) { return s; }, nb::arg("memo"))
        .def("__eq__", [](const nd_params &a, nb::handle b) {
                if (!nb::isinstance<nd_params>(b))
                    return false;
                return nd_to_ini(a) == nd_to_ini(nb::cast<const nd_params &>(b));
            }, nb::arg("other").none())
        .def("__repr__", [](const nd_params &s) {
                neat_params d = neat_params_default();
                size_t nk;
                const neat_cfg_key *ks = neat_config_keys(&nk);
                std::string r = "Params(";
                bool first = true;
                nd_params def;
                def.p = d;
                if (s.p.profile != d.profile) {
                    // the profile first, and the rest told apart from what the profile gives: eval(repr(p)) == p
                    r += "profile=" + nb::cast<std::string>(nb::repr(nd_get(s, &ks[0])));
                    first = false;
                    (void)neat_params_set_profile(&def.p, s.p.profile);
                }
                for (size_t i = 0; i < nk; i++) {
                    nb::object a = nd_get(s, &ks[i]), b = nd_get(def, &ks[i]);
                    if (a.equal(b) || std::strcmp(ks[i].name, "profile") == 0)
                        continue;
                    r += (first ? "" : ", ") + std::string(ks[i].name) + "=" + nb::cast<std::string>(nb::repr(a));
                    first = false;
                }
                return r + ")";
            });
    // equal by value and changeable: not a dict key or a set member
    cls.def("__hash__", [](const nd_params &) -> Py_hash_t { throw nb::type_error("unhashable type: 'Params'"); });
}
