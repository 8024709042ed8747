// nd_run.cpp - duel_evolve's ladder, compare and export by the commands' own libraries (tools/common/: the same games,
// JSON and files), and a run directory's records read back by the C readers. (A run is the run engine:
// nd_engine.cpp.) Nothing here prints: a refusal comes back as the command's status and line.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include "nd.h"
extern "C" {
#include "duel_ctrl.h"
#include "duel_dominance.h"
#include "duel_export_c.h"
#include "duel_files.h"
#include "duel_ladder_games.h"
#include "duel_outputs.h"
#include "duel_perf.h"
#include "duel_generations.h"
#include "duel_html.h"
}

// duel_evolve export NAME.blob --c-array NAME -o C_FILE [--header H] [--force], by the command's own library
// (duel_export_c.c), from the blob's bytes: (status, message). The command's rules for outputs hold.
static std::tuple<int, std::string> nd_export_c(nb::bytes blob, const std::string &name, const nd_path &c_path,
                                                const nd_path &h_path, bool force)
{
    const std::string c_file = c_path.string(), header = h_path.string();
    const std::string source = name + ".blob"; // the files name their source, as `export NAME.blob` does
    char msg[4600];
    duel_export x;
    const char *in[2];
    int rc;
    std::memset(&x, 0, sizeof x);
    x.name = name.c_str();
    x.header = header.empty() ? nullptr : header.c_str();
    if (!duel_export_name_ok(x.name))
        return {2, "export: '" + name + "' is not a C identifier of at most " + std::to_string(DUEL_EXPORT_NAME_MAX) +
                       " characters (nor a keyword)"};
    {
        nb::gil_scoped_release nogil;
        // before anything is written: never over the other output or a file that is not an export
        in[0] = nullptr;
        in[1] = x.header;
        rc = duel_out_allowed_msg("export", "-o", c_file.c_str(), &duel_export_c_kind, force, in, 2, msg, sizeof msg);
        in[1] = c_file.c_str();
        if (rc == 0 && x.header != nullptr)
            rc = duel_out_allowed_msg("export", "--header", x.header, &duel_export_c_kind, force, in, 2, msg,
                                      sizeof msg);
        if (rc == 0 && duel_export_from_bytes(&x, source.c_str(), (const uint8_t *)blob.c_str(), blob.size(), msg,
                                              sizeof msg) != 0)
            rc = 2;
        if (rc == 0 && x.header != nullptr)
            rc = duel_file_write_with_msg(x.header, duel_export_write_header_cb, &x, msg, sizeof msg);
        if (rc == 0)
            rc = duel_file_write_with_msg(c_file.c_str(), duel_export_write_cb, &x, msg, sizeof msg);
        std::free(x.blob);
    }
    return {rc, rc != 0 ? std::string(msg) : std::string()};
}

// duel_evolve report RUN --html OUT / experiment report DIR --html, by the command's library: (status, message,
// pages written).
static void nd_page_count(void *ud, const char *, size_t)
{
    ++*static_cast<unsigned long *>(ud);
}

static std::tuple<int, std::string, unsigned long> nd_pages(const nd_path &dirp, const nd_path &outp, bool experiment,
                                                            const std::string &games, bool embed, bool force)
{
    duel_html_report o;
    unsigned long pages = 0;
    char msg[4600] = "";
    int st;
    std::memset(&o, 0, sizeof o);
    if (games == "all")
        o.games = DUEL_HTML_GAMES_ALL;
    else if (games == "top")
        o.games = DUEL_HTML_GAMES_TOP;
    else if (games == "none")
        o.games = DUEL_HTML_GAMES_NONE;
    else
        return {2, "games: 'all', 'top' or 'none', not '" + games + "'", 0};
    o.embed = embed;
    o.force = force;
    o.wrote = nd_page_count;
    o.ud = &pages;
    const std::string dir = dirp.string(), out = outp.string();
    {
        nb::gil_scoped_release nogil;
        st = experiment ? duel_html_experiment_report(dir.c_str(), out.c_str(), &o, msg, sizeof msg)
                        : duel_html_run_report(dir.c_str(), out.c_str(), &o, msg, sizeof msg);
    }
    return {st, st != 0 ? std::string(msg) : std::string(), pages};
}

// duel_evolve ladder DIR [--top | --levels LO-HI] [--against NAMES] --json, by the command's own library
// (duel_ladder_games.c): (status, JSON, message). A whole ladder replaces DIR/ladder.csv, as the command's does.
static std::tuple<int, std::string, std::string> nd_ladder(const nd_path &dirp, bool top, uint32_t lo, uint32_t hi,
                                                           const std::vector<std::string> &against)
{
    const std::string dir = dirp.string();
    char msg[4600], path[4200];
    int ids[DUEL_N_BUILTINS];
    uint32_t n = 0;
    int subset = lo != 0;
    if (top && lo != 0)
        return {2, "", "ladder: --top and --levels name the levels twice: give one"};
    if (lo != 0 && (lo < 1 || hi < lo || hi > 1000000))
        return {2, "", "ladder: --levels takes L or L1-L2 (levels from 1), not '" + std::to_string(lo) + "-" +
                           std::to_string(hi) + "'"};
    for (const std::string &name : against) {
        int b = duel_builtin_parse(name.c_str());
        bool again = false;
        for (uint32_t k = 0; k < n; k++)
            again = again || ids[k] == b;
        if (b < 0 || again || n == DUEL_N_BUILTINS)
            return {2, "", "ladder: --against takes built-in strategies separated by commas, each once (idle, "
                           "spinner, forager, hunter, forager-hunter), not '" + name + "'"};
        subset |= b != (int)n; // another set or order is another table
        ids[n++] = b;
    }
    if (n == 0)
        for (; n < DUEL_N_BUILTINS; n++)
            ids[n] = (int)n;
    subset |= n != DUEL_N_BUILTINS;
    duel_rules world;
    duel_ladder L;
    int e;
    char *json = nullptr, *csv = nullptr;
    size_t json_len = 0, csv_len = 0;
    {
        nb::gil_scoped_release nogil;
        e = duel_run_world_msg(dir.c_str(), &world, msg, sizeof msg) != 0 ? 2 : 0;
        snprintf(path, sizeof path, "%s/ladder.csv", dir.c_str());
        const char *in[1] = {dir.c_str()};
        if (e == 0 && !subset &&
            duel_out_own_allowed_msg("ladder", "its", path, &duel_ladder_csv_kind, 0, in, 1, msg, sizeof msg) != 0)
            e = 2;
        if (e == 0)
            e = duel_ladder_play(&L, dir.c_str(), &world, top, lo, hi, ids, n, 0, msg, sizeof msg);
        else
            std::memset(&L, 0, sizeof L);
        FILE *fj = e == 0 ? open_memstream(&json, &json_len) : nullptr;
        FILE *fc = e == 0 ? open_memstream(&csv, &csv_len) : nullptr;
        if (e == 0 && (fj == nullptr || fc == nullptr)) {
            std::snprintf(msg, sizeof msg, "ladder: out of memory");
            e = 1;
        }
        if (e == 0) {
            duel_ladder_write_json(fj, &L);
            duel_ladder_write_csv(fc, &L);
        }
        if (fj != nullptr)
            std::fclose(fj);
        if (fc != nullptr)
            std::fclose(fc);
        duel_ladder_free(&L);
        if (e == 0 && !subset && duel_file_replace(path, csv, csv_len) != 0) {
            std::snprintf(msg, sizeof msg, "%s: cannot write: %s", path, std::strerror(errno));
            e = 1;
        }
    }
    std::string out = json != nullptr ? std::string(json, json_len) : std::string();
    std::free(json);
    std::free(csv);
    if (e != 0)
        return {e, "", msg};
    return {0, out, ""};
}

// duel_evolve compare CANDIDATES --against RANKINGS [--threads T] [--cache FILE] --json, by the measure's library
// (duel_perf.c, the command's own): (status, JSON, message). The measure's lines go to one process-wide place for
// the call: one comparison at a time in a process.
static std::tuple<int, std::string, std::string> nd_compare(const std::vector<std::string> &cand,
                                                            const std::vector<std::string> &against, uint32_t threads,
                                                            const std::string &cache)
{
    static std::mutex one;
    std::unique_lock<std::mutex> held(one, std::try_to_lock);
    if (!held.owns_lock())
        throw nd_error(NEAT_E_STATE, "compare: another comparison runs in this process (one at a time)");
    std::vector<const char *> c, a, in;
    for (const std::string &x : cand)
        c.push_back(x.c_str());
    for (const std::string &x : against)
        a.push_back(x.c_str());
    in = c;
    in.insert(in.end(), a.begin(), a.end());
    char msg[8400];
    char *json = nullptr;
    size_t len = 0;
    duel_perf m;
    duel_perf_opts o;
    int rc;
    std::memset(&m, 0, sizeof m);
    std::memset(&o, 0, sizeof o);
    o.threads = threads;
    o.cache_path = cache.empty() ? nullptr : cache.c_str();
    o.mode = DUEL_PERF_PLAY;
    o.prefix = "compare: ";
    o.msg = msg;
    o.msg_cap = sizeof msg;
    {
        nb::gil_scoped_release nogil;
        // before any game: a cache file that is not a compare cache (or one of the runs) is refused
        rc = o.cache_path != nullptr ? duel_out_allowed_msg("compare", "--cache", o.cache_path, &duel_perf_cache_kind, 0,
                                                            in.data(), in.size(), msg, sizeof msg)
                                     : 0;
        if (rc == 0)
            rc = duel_perf_measure(&m, c.data(), (uint32_t)c.size(), a.data(), (uint32_t)a.size(), &o);
        FILE *f = rc == 0 ? open_memstream(&json, &len) : nullptr;
        if (rc == 0 && f == nullptr) {
            std::snprintf(msg, sizeof msg, "compare: out of memory");
            rc = 1;
        }
        if (f != nullptr) {
            duel_perf_write_json(f, &m);
            std::fclose(f);
        }
        duel_perf_free(&m);
    }
    std::string out = json != nullptr ? std::string(json, len) : std::string();
    std::free(json);
    if (rc != 0)
        return {rc, "", msg};
    return {0, out, ""};
}

static nb::list nd_dominance(const std::string &dir)
{
    duel_dominance_row *rows = nullptr;
    duel_dominance_score *scores = nullptr;
    uint32_t n = 0;
    char err[4400];
    if (duel_dominance_read_scores(dir.c_str(), &rows, &n, &scores, err, sizeof err) != 0)
        throw nd_error(NEAT_E_FORMAT, err, dir + "/dominance.csv");
    nb::list out;
    for (uint32_t i = 0; i < n; i++) {
        nb::dict d;
        d["level"] = rows[i].level;
        d["generation"] = rows[i].generation;
        d["population"] = std::string(rows[i].pop);
        d["hidden"] = rows[i].hidden;
        d["connections"] = rows[i].conns;
        std::vector<uint32_t> w, l;
        for (uint32_t k = 0; k + 1 < rows[i].level; k++) {
            w.push_back(scores[rows[i].scores + k].wins);
            l.push_back(scores[rows[i].scores + k].losses);
        }
        d["wins"] = w;
        d["losses"] = l;
        out.append(d);
    }
    std::free(rows);
    std::free(scores);
    return out;
}

static nb::list nd_generations(const std::string &dir)
{
    duel_gen_row *rows = nullptr;
    size_t n = 0;
    char err[4400];
    if (duel_generations_read(dir.c_str(), &rows, &n, err, sizeof err) != 0)
        throw nd_error(NEAT_E_FORMAT, err, dir + "/generations.csv");
    nb::list out;
    for (size_t i = 0; i < n; i++) {
        nb::dict d;
        d["generation"] = rows[i].generation;
        d["population"] = std::string(1, rows[i].pop);
        d["min_hidden"] = rows[i].min_hidden;
        d["max_hidden"] = rows[i].max_hidden;
        d["min_connections"] = rows[i].min_conns;
        d["max_connections"] = rows[i].max_conns;
        d["games"] = rows[i].games;
        d["seconds"] = rows[i].seconds;
        out.append(d);
    }
    std::free(rows);
    return out;
}

void nd_bind_run(nb::module_ &m)
{
    m.def("export_c", &nd_export_c, nb::arg("blob"), nb::arg("name"), nb::arg("c_file"), nb::arg("header") = "",
          nb::arg("force") = false,
          "duel_evolve export NAME.blob --c-array NAME -o C_FILE [--header HEADER] [--force] by the command's\n"
          "library, from the blob's bytes: (status, message).");
    duel_html_set_generator("neat-duel " NEAT_DUEL_VERSION_STRING); // the pages name their maker, as the command's do
    m.def("html_pages", &nd_pages, nb::arg("directory"), nb::arg("out"), nb::arg("experiment") = false,
          nb::arg("games") = "all", nb::arg("embed") = false, nb::arg("force") = false,
          "duel_evolve report RUN --html OUT (or experiment report DIR --html, OUT its report/html) by the command's\n"
          "library: (status, message, pages written).");
    m.def("ladder_json", &nd_ladder, nb::arg("directory"), nb::arg("top") = false, nb::arg("lo") = 0,
          nb::arg("hi") = 0, nb::arg("against") = std::vector<std::string>(),
          "duel_evolve ladder DIRECTORY --json by the command's library: (status, JSON text, message).");
    m.def("compare_json", &nd_compare, nb::arg("candidates"), nb::arg("against"), nb::arg("threads") = 0,
          nb::arg("cache") = "",
          "duel_evolve compare CANDIDATES --against RANKINGS --json by the measure's library: (status, JSON text,\n"
          "message).");
    m.def("read_dominance", &nd_dominance, nb::arg("directory"),
          nb::sig("def read_dominance(directory: str) -> list[dict[str, typing.Any]]"),
          "A run directory's dominance.csv, read and checked by duel_evolve's reader.");
    m.def("read_generations", &nd_generations, nb::arg("directory"),
          nb::sig("def read_generations(directory: str) -> list[dict[str, typing.Any]]"),
          "A run directory's generations.csv (its checked fields), read by duel_evolve's reader.");
}
