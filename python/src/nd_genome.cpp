// nd_genome.cpp - neat_duel.Genome: one genome's genes as numpy arrays (views, not copies), its network, its file
// (the genome file format of docs/formats.md) and its Graphviz picture.
#include <cstdlib>
#include <cstring>
#include <new>

#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include "duel.h"
#include "nd.h"
extern "C" {
#include "duel_runtag.h"
}

// numpy's structured dtypes of the C structs (neat_node, neat_conn), built once by neat_duel._dtypes from these
static_assert(sizeof(neat_node) == 8 && offsetof(neat_node, type) == 4, "neat_node layout");
static_assert(sizeof(neat_conn) == 24 && offsetof(neat_conn, weight) == 8 && offsetof(neat_conn, innov) == 16 &&
                  offsetof(neat_conn, enabled) == 20,
              "neat_conn layout");

#define ND_GENOME_MAX (64u << 20) // a genome file of 256 nodes and every connection is far smaller

bool nd_genome::own() noexcept
{
    if (borrowed == nullptr)
        return true;
    const neat_genome *b = borrowed;
    borrowed = nullptr;
    if (neat_genome_copy(&g, b, nullptr) == NEAT_OK)
        return true;
    neat_genome_free(&g, nullptr);
    return false;
}

nd_genome nd_genome_copy(const neat_genome *g, const neat_params &p)
{
    nd_genome r;
    int err = neat_genome_copy(&r.g, g, nullptr);
    if (err)
        nd_fail(err, "copying a genome");
    r.n_inputs = p.n_inputs;
    r.n_outputs = p.n_outputs;
    r.net_step = p.net_step;
    return r;
}

// The raw bytes of n records of size sz at p, read-only, kept alive by owner; viewed as a structured dtype.
static nb::object nd_view(const void *p, size_t n, size_t sz, nb::handle owner, const char *dtype)
{
    static const uint8_t empty[1] = {0};
    size_t shape[1] = {n * sz};
    nb::ndarray<nb::numpy, const uint8_t, nb::ndim<1>> raw(p != nullptr ? p : empty, 1, shape, owner);
    nb::object dt = nb::module_::import_("neat_duel._dtypes").attr(dtype);
    return nb::cast(raw).attr("view")(dt);
}

static nd_genome *nd_genome_from_bytes(const uint8_t *b, size_t len, const std::string &name)
{
    nd_genome *r = new nd_genome();
    size_t off = 0;
    uint32_t ni = 0, no = 0;
    neat_genome_origin o;
    int err = neat_genome_load_origin(&r->g, &ni, &no, &o, b, len, nullptr, &off);
    if (err) {
        delete r;
        throw nd_error(err, name + ": " + nd_strerror(err) + " at byte offset " + std::to_string(off), name,
                       (long long)off);
    }
    r->n_inputs = ni;
    r->n_outputs = no;
    // a file that records its step is played in it (a propagate champion is never run as sync)
    r->net_step = o.net_step;
    r->has_origin = o.version >= 2;
    if (o.tag_len > 0)
        r->origin_tag.assign((const char *)o.tag, o.tag_len);
    return r;
}

// The genome file's bytes: version 2 with the origin when there is one to record (a loaded origin, or a step
// other than sync), else version 1, byte for byte as before origins existed.
static nb::bytes nd_genome_bytes(const nd_genome &s)
{
    uint8_t *buf = nullptr;
    size_t len = 0;
    neat_genome_origin o;
    std::memset(&o, 0, sizeof o);
    o.version = 2;
    o.net_step = s.net_step;
    o.tag_len = (uint32_t)s.origin_tag.size();
    o.tag = s.origin_tag.empty() ? nullptr : (const uint8_t *)s.origin_tag.data();
    bool with = s.has_origin || s.net_step != NEAT_STEP_SYNC;
    int err = neat_genome_save_origin(&s.gen(), s.n_inputs, s.n_outputs, with ? &o : nullptr, &buf, &len, nullptr);
    if (err)
        nd_fail(err, "saving a genome");
    nb::bytes b((const char *)buf, len);
    std::free(buf);
    return b;
}

nb::object nd_network_of(const nd_genome &g)
{
    static const neat_params base = neat_params_default();
    neat_params p = base;
    p.n_inputs = g.n_inputs;
    p.n_outputs = g.n_outputs;
    p.net_step = g.net_step;
    // constructed where it stays (its buffers may be inside it), marked ready for Python only when loaded
    nb::object o = nb::inst_alloc(nb::type<nd_network>());
    nd_network *n = new (nb::inst_ptr<nd_network>(o)) nd_network();
    int err = neat_phenotype_load(&n->ph, &g.gen(), &p);
    try {
        if (err)
            nd_fail(err, "the genome's network");
        n->sized();
    } catch (...) {
        n->~nd_network(); // a not-ready instance is freed without its destructor
        throw;
    }
    nb::inst_mark_ready(o);
    return o;
}

static std::string nd_dot(const nd_genome &s)
{
    // inputs at the bottom, outputs at the top; disabled genes dashed and grey; weights as labels and widths
    std::string d = "digraph genome {\n  rankdir=BT;\n  node [shape=circle, fontsize=10];\n";
    std::string ins = "  { rank=same;", outs = "  { rank=same;";
    for (uint32_t i = 0; i < s.gen().n_nodes; i++) {
        const neat_node &n = s.gen().nodes[i];
        std::string id = std::to_string(n.id);
        const char *shape = n.type == NEAT_NODE_BIAS ? "box" : n.type == NEAT_NODE_INPUT ? "invtriangle"
                          : n.type == NEAT_NODE_OUTPUT ? "doublecircle" : "circle";
        const char *label = n.type == NEAT_NODE_BIAS ? "bias" : nullptr;
        d += "  n" + id + " [shape=" + shape + ", label=\"" + (label ? label : id) + "\"];\n";
        if (n.type == NEAT_NODE_BIAS || n.type == NEAT_NODE_INPUT)
            ins += " n" + id + ";";
        else if (n.type == NEAT_NODE_OUTPUT)
            outs += " n" + id + ";";
    }
    d += ins + " }\n" + outs + " }\n";
    for (uint32_t i = 0; i < s.gen().n_conns; i++) {
        const neat_conn &c = s.gen().conns[i];
        char w[64];
        std::snprintf(w, sizeof w, "%.3f", c.weight);
        double pen = 0.5 + (c.weight < 0 ? -c.weight : c.weight) / 2;
        char pw[32];
        std::snprintf(pw, sizeof pw, "%.2f", pen > 4 ? 4.0 : pen);
        d += "  n" + std::to_string(c.in) + " -> n" + std::to_string(c.out) + " [label=\"" + w + "\", penwidth=" +
             pw + ", color=\"" + (c.enabled ? (c.weight < 0 ? "#c0392b" : "#2c3e50") : "#bbbbbb") + "\"" +
             (c.enabled ? "" : ", style=dashed") + "];\n";
    }
    return d + "}\n";
}

void nd_bind_genome(nb::module_ &m)
{
    nb::class_<nd_genome> genome = nb::class_<nd_genome>(m, "Genome",
                          "One genome: its nodes and connection genes (numpy views of the C arrays), fitness and\n"
                          "species, the network it encodes, its file. A genome taken from a Population is a copy:\n"
                          "the population's next generation does not change it.")
        .def_prop_ro("nodes", [](nb::handle self) {
                nd_genome &s = nb::cast<nd_genome &>(self);
                if (!s.own()) // a view outlives the fitness call that borrowed the genes
                    throw std::bad_alloc();
                return nd_view(s.gen().nodes, s.gen().n_nodes, sizeof(neat_node), self, "NODE");
            }, nb::sig("def nodes(self) -> numpy.typing.NDArray[numpy.void]"),
            "The nodes, sorted by id: a read-only structured array (id uint32, type uint8: 0 bias, 1 input,\n"
            "2 output, 3 hidden), a view of the genome's memory.")
        .def_prop_ro("conns", [](nb::handle self) {
                nd_genome &s = nb::cast<nd_genome &>(self);
                if (!s.own())
                    throw std::bad_alloc();
                return nd_view(s.gen().conns, s.gen().n_conns, sizeof(neat_conn), self, "CONN");
            }, nb::sig("def conns(self) -> numpy.typing.NDArray[numpy.void]"),
            "The connection genes, sorted by innovation number: a read-only structured array (in, out\n"
            "uint32 node ids; weight float64; innov uint32; enabled uint8), a view of the genome's memory.")
        .def_prop_ro("n_inputs", [](const nd_genome &s) { return s.n_inputs; }, "Inputs of its task, without the bias.")
        .def_prop_ro("step", [](const nd_genome &s) { return s.net_step == NEAT_STEP_PROPAGATE ? "propagate" : "sync"; },
                     nb::sig("def step(self) -> str"),
                     "The network step it is evaluated with, 'sync' or 'propagate': its population's, or what\n"
                     "its genome file records (a file of format 1 records none: 'sync').")
        .def_prop_ro("world_id", [](const nd_genome &s) -> nb::object {
                duel_rules r; // a file without a tag, or with another program's, names no world
                if (duel_tag_world((const uint8_t *)s.origin_tag.data(), s.origin_tag.size(), &r, nullptr) != 0)
                    return nb::none();
                return nb::int_(duel_rules_id(&r));
            }, nb::sig("def world_id(self) -> int | None"),
            "The identity of the duel world its genome file says it was evolved in (DuelConfig.world_id's\n"
            "number), None when the file records none.")
        .def_prop_ro("n_outputs", [](const nd_genome &s) { return s.n_outputs; }, "Outputs of its task.")
        .def_prop_ro("n_hidden", [](const nd_genome &s) { return neat_genome_hidden_count(&s.gen()); }, "Hidden nodes.")
        .def_prop_ro("n_enabled", [](const nd_genome &s) { return neat_genome_enabled_count(&s.gen()); },
                     "Enabled connections (those its network has).")
        .def_prop_ro("fitness", [](const nd_genome &s) -> nb::object {
                return s.gen().has_fitness ? nb::cast(s.gen().fitness) : nb::none();
            }, nb::sig("def fitness(self) -> float | None"), "Its fitness, None before it was given one.")
        .def_prop_ro("species", [](const nd_genome &s) { return s.gen().species; }, "The id of its species.")
        .def_static("from_genes", [](uint32_t n_inputs, uint32_t n_outputs, uint32_t n_hidden,
                                     const std::vector<std::tuple<uint32_t, uint32_t, double>> &conns,
                                     const std::string &step) {
                // node ids as libneat numbers them: 0 the bias, 1..n_inputs the inputs, then the outputs, then hidden
                if (n_inputs == 0 || n_outputs == 0 || (uint64_t)n_inputs + n_outputs + n_hidden + 1 > NRT_MAX_NODES)
                    throw nd_error(NEAT_E_ARG, "from_genes: 1.. inputs and outputs, and at most " +
                                                   std::to_string(NRT_MAX_NODES) + " nodes with the bias");
                if (step != "sync" && step != "propagate")
                    throw nd_error(NEAT_E_ARG, "from_genes: step is 'sync' or 'propagate', not '" + step + "'");
                const uint32_t n_nodes = 1 + n_inputs + n_outputs + n_hidden;
                nd_genome r;
                r.n_inputs = n_inputs;
                r.n_outputs = n_outputs;
                r.net_step = step == "propagate" ? NEAT_STEP_PROPAGATE : NEAT_STEP_SYNC;
                int err = 0;
                for (uint32_t id = 0; id < n_nodes && !err; id++) {
                    int type = id == 0 ? NEAT_NODE_BIAS : id <= n_inputs ? NEAT_NODE_INPUT
                             : id <= n_inputs + n_outputs ? NEAT_NODE_OUTPUT : NEAT_NODE_HIDDEN;
                    err = neat_genome_add_node(&r.g, id, type, nullptr);
                }
                uint32_t innov = 0;
                for (const auto &c : conns) {
                    uint32_t in = std::get<0>(c), out = std::get<1>(c);
                    if (in >= n_nodes || out >= n_nodes || (out >= 1 && out <= n_inputs) || out == 0)
                        throw nd_error(NEAT_E_ARG, "from_genes: connection " + std::to_string(innov) + " (" +
                                                       std::to_string(in) + " -> " + std::to_string(out) +
                                                       ") leaves the nodes or ends at the bias or an input");
                    if (!err)
                        err = neat_genome_add_conn(&r.g, in, out, std::get<2>(c), innov, 1, nullptr);
                    innov++;
                }
                if (err)
                    nd_fail(err, "building a genome");
                return r;
            }, nb::arg("n_inputs"), nb::arg("n_outputs"), nb::arg("n_hidden"), nb::arg("conns"),
            nb::arg("step") = "sync",
            "A genome from its genes (another learner's network in this format: a policy trained by\n"
            "gradient descent, say): node 0 the bias, 1..n_inputs the inputs, then the outputs, then\n"
            "n_hidden hidden nodes; conns (in, out, weight) every one enabled, innovation numbers in\n"
            "order; step 'sync' or 'propagate' (a feed-forward net in one step). Every node computes\n"
            "the runtime's sigmoid 1/(1+exp(-4.9 x)) of its weighted sum; weights are stored in Q3.12\n"
            "(|w| < 8) in its network.")
        .def("network", &nd_network_of, nb::sig("def network(self) -> Network"),
             "Its network in the runtime, encoded exactly as evolution evaluates it (and as a\n"
             "microcontroller runs it): step, settle, reset.")
        .def("distance", [](const nd_genome &a, const nd_genome &b, const nd_params &p) {
                return neat_genome_distance(&a.gen(), &b.gen(), &p.p);
            }, nb::arg("other"), nb::arg("params"), "The compatibility distance delta under params' c1, c2, c3.")
        .def("to_bytes", &nd_genome_bytes,
             "The genome file's bytes (docs/formats.md): every gene, exact weights, a checksum, and\n"
             "where it was made (its step, and the run's tag a loaded file recorded).")
        .def("save", [](const nd_genome &s, const nd_path &fpath) {
                const std::string path = fpath.string();
                nb::bytes b = nd_genome_bytes(s);
                nd_write_file(path, (const uint8_t *)b.c_str(), b.size());
            }, nb::arg("path"),
            "Writes the genome file (what duel_evolve writes as champions/gen-G.genome; a run can start\n"
            "from it), through a temporary file and a rename.")
        .def("to_dot", &nd_dot,
             "The network as Graphviz text (dot -Tsvg): inputs at the bottom, disabled genes dashed.")
        .def("__repr__", [](const nd_genome &s) {
                std::string f = s.gen().has_fitness ? std::to_string(s.gen().fitness) : "None";
                return "Genome(" + std::to_string(s.gen().n_nodes) + " nodes, " + std::to_string(s.gen().n_conns) +
                       " connections (" + std::to_string(neat_genome_enabled_count(&s.gen())) + " enabled), fitness " +
                       f + ")";
            });
    nd_def_file_loaders(genome, nd_genome_from_bytes, ND_GENOME_MAX, "from_bytes", "data",
                        "A genome file's bytes, checked (magic, version, checksum) before anything is trusted;\n"
                        "FormatError names the byte offset of a problem.",
                        "Reads a genome file (FormatError names the file and the byte offset of a problem).");
}
