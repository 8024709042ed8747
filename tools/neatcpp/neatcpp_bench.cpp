// neatcpp_bench.cpp - NEAT C++ 1.2.1's reproduction, or libneat's, on our XOR and double-pole evaluation, run by run.
//
// The release keeps its state in globals (parameters, rand(), a spare
// Gaussian deviate): one process runs its runs one after another, and every
// run starts from the same state (neatcpp_release_reset), so a run's result
// does not depend on the runs before it (docs/neat-cpp.md).
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <streambuf>
#include <string>
#include <vector>

#include "bench_eval.h"
#include "neat.h"
// the tools' header has no C++ guards of its own
extern "C" {
#include "neat_config.h"
}
#include "neat_phenotype.h"
#include "neatcpp_genome.h"
#include "neatcpp_native.h"
#include "neatcpp_params.h"
#include "neatcpp_random.h"

// the release's headers
#include "genome.h"
#include "organism.h"
#include "population.h"
#include "species.h"

#ifndef NEATCPP_DIR
#define NEATCPP_DIR "."
#endif

namespace {

// The Markov task is solved by balancing this many steps (bench/pole.ini's balance_steps).
const uint32_t POLE_STEPS = 100000;

struct options {
    std::string engine, task, ne, start, out, profile, eval;
    uint32_t runs, first_run, max_generations;
    uint64_t seed, max_evaluations;
    int have_max_gen, have_max_evals;
    std::vector<std::string> sets;
};

struct run_result {
    int solved;
    uint64_t evaluations;
    uint32_t generations, hidden, conns, clamped;
    uint32_t hopeless; // --eval native: networks xor_evaluate could not have finished (neatcpp_native.h)
};

// Statistics of one evaluated generation (generations.csv).
struct gen_stats {
    uint32_t n, species, max_hidden;
    double sum_hidden, sum_conns, best, sum_fitness;
};

// std::cout of the release (it narrates every epoch) goes nowhere; ours is printf.
class null_buf : public std::streambuf {
protected:
    int overflow(int c) { return c == EOF ? 0 : c; }
    std::streamsize xsputn(const char *, std::streamsize n) { return n; }
};

void usage(FILE *f)
{
    fprintf(f,
            "usage: neatcpp_bench --engine release|libneat --task xor|pole --ne PARAMS.ne [--start STARTGENES]\n"
            "                     --runs N [--first-run K] --seed S --out DIR [--max-generations G]\n"
            "                     [--max-evaluations E] [--set key=value ...] [--profile NAME]\n"
            "                     [--eval ours|native]\n"
            "Runs NEAT C++ 1.2.1's reproduction (release) or libneat's on our evaluation (bench/bench_eval.c).\n"
            "  --ne PARAMS.ne        the release's parameter file; libneat gets the mapped neat_params\n"
            "  --start STARTGENES    start genome (default: the release's xorstartgenes / pole2startgenes1);\n"
            "                        libneat starts from its minimal genome of the same shape\n"
            "  --runs N, --first-run K  runs K .. K+N-1; run r's seed is neat_seed_derive(S, r)\n"
            "  --max-generations G   default 100 (xor), 1000 (pole)\n"
            "  --max-evaluations E   default none (xor), 100000 (pole), checked after each generation\n"
            "  --set key=value       libneat: a [neat] key over the mapped parameters; release: net_step only\n"
            "  --profile NAME        libneat: the profile's rules (neat-cpp-1.2.1) with the file's values, before --set\n"
            "  --eval native         release: its own evaluation (experiments.cpp) as a context row\n"
            "Writes DIR/runs.csv and DIR/generations.csv; one summary line on stdout.\n"
            "Built against the release at " NEATCPP_DIR "\n");
}

int parse_u64(const char *opt, const char *s, uint64_t max, uint64_t *out)
{
    char *end;
    unsigned long long v;
    errno = 0;
    v = strtoull(s, &end, 10);
    if (s[0] == '\0' || s[0] == '-' || *end != '\0' || errno || v > max) {
        fprintf(stderr, "neatcpp_bench: bad value '%s' for %s\n", s, opt);
        return -1;
    }
    *out = v;
    return 0;
}

int parse_args(int argc, char **argv, options *o)
{
    int have_seed = 0, have_runs = 0;
    o->runs = 0;
    o->first_run = 0;
    o->seed = 0;
    o->max_generations = 0;
    o->max_evaluations = 0;
    o->have_max_gen = o->have_max_evals = 0;
    o->eval = "ours";
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        uint64_t v;
        if (a == "--help" || a == "-h") {
            usage(stdout);
            exit(0);
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "neatcpp_bench: %s needs a value (or is unknown)\n", a.c_str());
            return -1;
        }
        const char *val = argv[++i];
        if (a == "--engine")
            o->engine = val;
        else if (a == "--task")
            o->task = val;
        else if (a == "--ne")
            o->ne = val;
        else if (a == "--start")
            o->start = val;
        else if (a == "--out")
            o->out = val;
        else if (a == "--profile")
            o->profile = val;
        else if (a == "--eval")
            o->eval = val;
        else if (a == "--set")
            o->sets.push_back(val);
        else if (a == "--runs") {
            if (parse_u64(a.c_str(), val, 1000000, &v) || v == 0)
                return -1;
            o->runs = (uint32_t)v;
            have_runs = 1;
        } else if (a == "--first-run") {
            if (parse_u64(a.c_str(), val, 1000000, &v))
                return -1;
            o->first_run = (uint32_t)v;
        } else if (a == "--seed") {
            if (parse_u64(a.c_str(), val, UINT64_MAX, &o->seed))
                return -1;
            have_seed = 1;
        } else if (a == "--max-generations") {
            if (parse_u64(a.c_str(), val, 1000000, &v) || v == 0)
                return -1;
            o->max_generations = (uint32_t)v;
            o->have_max_gen = 1;
        } else if (a == "--max-evaluations") {
            if (parse_u64(a.c_str(), val, UINT64_MAX, &o->max_evaluations))
                return -1;
            o->have_max_evals = 1;
        } else {
            fprintf(stderr, "neatcpp_bench: unknown option '%s'\n", a.c_str());
            return -1;
        }
    }
    if (o->engine != "release" && o->engine != "libneat") {
        fprintf(stderr, "neatcpp_bench: --engine release or libneat\n");
        return -1;
    }
    if (o->task != "xor" && o->task != "pole") {
        fprintf(stderr, "neatcpp_bench: --task xor or pole (the Markov double pole)\n");
        return -1;
    }
    if (o->ne.empty() || o->out.empty() || !have_seed || !have_runs) {
        fprintf(stderr, "neatcpp_bench: --ne, --runs, --seed and --out are required (--help)\n");
        return -1;
    }
    if (o->eval != "ours" && o->eval != "native") {
        fprintf(stderr, "neatcpp_bench: --eval ours or native\n");
        return -1;
    }
    if (o->eval == "native" && o->engine != "release") {
        fprintf(stderr, "neatcpp_bench: --eval native is the release's own evaluation: --engine release\n");
        return -1;
    }
    if (!o->profile.empty() && o->engine != "libneat") {
        fprintf(stderr, "neatcpp_bench: --profile sets libneat parameters: --engine libneat\n");
        return -1;
    }
    if (o->start.empty())
        o->start = std::string(NEATCPP_DIR) + (o->task == "xor" ? "/xorstartgenes" : "/pole2startgenes1");
    if (!o->have_max_gen)
        o->max_generations = o->task == "xor" ? 100 : 1000;
    if (!o->have_max_evals)
        o->max_evaluations = o->task == "xor" ? 0 : 100000;
    return 0;
}

// The start genome as experiments.cpp reads it: "genomestart ID" then the genome.
NEAT::Genome *read_start(const std::string &path)
{
    std::ifstream f(path.c_str());
    char word[128] = "";
    int id = 0;
    if (!f) {
        fprintf(stderr, "neatcpp_bench: cannot read the start genome %s\n", path.c_str());
        return NULL;
    }
    f.width(sizeof word);
    f >> word >> id;
    if (!f || strcmp(word, "genomestart") != 0) {
        fprintf(stderr, "neatcpp_bench: %s: not a start genome (no 'genomestart ID')\n", path.c_str());
        return NULL;
    }
    return new NEAT::Genome(id, f);
}

// libneat's minimal start is every sensor (bias included) to every output,
// no hidden node: the release's start files are that, which this checks.
int start_is_minimal(const NEAT::Genome *g, uint32_t n_in, uint32_t n_out)
{
    if (g->nodes.size() != n_in + n_out + 1 || g->genes.size() != (n_in + 1) * n_out)
        return 0;
    for (size_t i = 0; i < g->genes.size(); i++)
        if (!g->genes[i]->enable || g->genes[i]->lnk->out_node->gen_node_label != NEAT::OUTPUT ||
            g->genes[i]->lnk->in_node->type != NEAT::SENSOR)
            return 0;
    return 1;
}


void stats_add(gen_stats *s, const neat_genome *g, double f)
{
    uint32_t h = neat_genome_hidden_count(g);
    s->n++;
    s->sum_hidden += h;
    s->sum_conns += neat_genome_enabled_count(g);
    if (h > s->max_hidden)
        s->max_hidden = h;
    if (s->n == 1 || f > s->best)
        s->best = f;
    s->sum_fitness += f;
}

// Our evaluation of one network: fitness as bench/task_xor.c and task_pole.c set it.
int evaluate(const options &o, neat_phenotype *ph, double *f)
{
    if (o.task == "xor")
        return bench_xor_eval(ph, f);
    uint32_t steps = bench_pole_markov(ph, POLE_STEPS);
    *f = steps;
    return steps >= POLE_STEPS;
}

void solved_by(run_result *r, const neat_genome *g, uint64_t evals, uint32_t gen)
{
    r->solved = 1;
    r->evaluations = evals;
    r->generations = gen + 1;
    r->hidden = neat_genome_hidden_count(g);
    r->conns = neat_genome_enabled_count(g);
}

struct out_files {
    FILE *runs, *gens;
};

void write_gen(out_files *of, const options &o, const char *engine, uint32_t run, uint32_t gen, const gen_stats &s)
{
    fprintf(of->gens, "%s,%s,%u,%u,%u,%.6f,%.6f,%u,%.17g,%.17g\n", engine, o.task.c_str(), run, gen, s.species,
            s.sum_hidden / s.n, s.sum_conns / s.n, s.max_hidden, s.best, s.sum_fitness / s.n);
}

// One run of the release's reproduction (experiments.cpp's xor_test / pole2_test
// loop, with our evaluation unless --eval native).
int run_release(const options &o, NEAT::Genome *start, const neat_params &p, uint32_t run, uint64_t seed,
                out_files *of, run_result *res)
{
    const int native = o.eval == "native";
    const char *engine = native ? "release-native" : "release";
    neat_phenotype ph;
    uint64_t evals = 0;
    uint32_t gen;
    int err = 0;
    void *cart = native && o.task == "pole" ? neatcpp_native_cart_new() : NULL;

    neatcpp_reset_random((uint32_t)(seed & 0xffffffffu));
    NEAT::Population *pop = new NEAT::Population(start, NEAT::pop_size);
    neat_phenotype_init(&ph, NULL);
    for (gen = 0; !err && gen < o.max_generations; gen++) {
        gen_stats s;
        memset(&s, 0, sizeof s);
        s.species = (uint32_t)pop->species.size();
        // every organism, in the population's order (as xor_epoch / pole2_epoch);
        // the evaluations counted are those up to the first solution
        for (size_t i = 0; i < pop->organisms.size() && !err; i++) {
            NEAT::Organism *org = pop->organisms[i];
            neat_genome g;
            double f = 0.0;
            int solved;
            err = neatcpp_genome_convert(org->gnome, &g, &res->clamped);
            if (err)
                break;
            if (native) {
                int hopeless = 0;
                solved = o.task == "xor" ? neatcpp_native_xor(org, &hopeless) : neatcpp_native_pole_markov(org, cart);
                res->hopeless += (uint32_t)hopeless;
                f = org->fitness;
            } else {
                err = neat_phenotype_load(&ph, &g, &p);
                if (err) {
                    neat_genome_free(&g, NULL);
                    break;
                }
                solved = evaluate(o, &ph, &f);
                org->fitness = f;
                org->winner = solved != 0;
            }
            if (!res->solved)
                evals++;
            if (solved && !res->solved)
                solved_by(res, &g, evals, gen);
            stats_add(&s, &g, f);
            neat_genome_free(&g, NULL);
        }
        if (err)
            break;
        write_gen(of, o, engine, run, gen, s);
        if (res->solved || (o.max_evaluations && evals >= o.max_evaluations))
            break;
        // experiments.cpp's bookkeeping before the epoch (only printed by the release, kept for fidelity)
        for (size_t k = 0; k < pop->species.size(); k++) {
            pop->species[k]->compute_average_fitness();
            pop->species[k]->compute_max_fitness();
        }
        pop->epoch((int)gen + 1); // experiments.cpp counts generations from 1 (epoch's "generation % 30")
    }
    if (!res->solved) {
        res->evaluations = evals;
        res->generations = gen < o.max_generations ? gen + 1 : gen;
    }
    neat_phenotype_free(&ph);
    if (cart)
        neatcpp_native_cart_free(cart);
    delete pop;
    return err;
}

// One run of libneat's reproduction on the same evaluation (bench/task_xor.c's loop).
int run_libneat(const options &o, const neat_params &p, uint32_t run, uint64_t seed, out_files *of, run_result *res)
{
    neat_pop *pop = NULL;
    neat_phenotype ph;
    uint64_t evals = 0;
    uint32_t gen;
    int err = neat_pop_create(&pop, &p, NULL, seed, NULL);
    neat_phenotype_init(&ph, NULL);
    for (gen = 0; !err && gen < o.max_generations; gen++) {
        gen_stats s;
        memset(&s, 0, sizeof s);
        s.species = neat_pop_species_count(pop);
        for (uint32_t i = 0; i < neat_pop_size(pop) && !err; i++) {
            const neat_genome *g = neat_pop_genome(pop, i);
            double f;
            int solved;
            err = neat_phenotype_load(&ph, g, &p);
            if (err)
                break;
            solved = evaluate(o, &ph, &f);
            if (!res->solved)
                evals++;
            if (solved && !res->solved)
                solved_by(res, g, evals, gen);
            stats_add(&s, g, f);
            err = neat_pop_set_fitness(pop, i, f);
        }
        if (err)
            break;
        write_gen(of, o, "libneat", run, gen, s);
        if (res->solved || (o.max_evaluations && evals >= o.max_evaluations))
            break;
        err = neat_pop_epoch(pop);
    }
    if (!res->solved) {
        res->evaluations = evals;
        res->generations = gen < o.max_generations ? gen + 1 : gen;
    }
    neat_phenotype_free(&ph);
    neat_pop_free(pop);
    return err;
}

// The libneat parameters of this invocation: the .ne mapping, the profile, the --set keys.
int libneat_params(const options &o, const neatcpp_ne &ne, uint32_t n_in, uint32_t n_out, neat_params *p)
{
    char err[512];
    const char *field = NULL;
    *p = neatcpp_params_from_ne(&ne, n_in, n_out);
    if (!o.profile.empty()) {
        // The profile's rules, with the file's values: it brings its own dropoff_age, pop_stagnation and
        // recur_only_prob (params256.ne's and the coevolution's), which the file sets here
        neat_params file = *p;
        if (neat_config_set(p, "profile", o.profile.c_str(), err, sizeof err) != 0) {
            fprintf(stderr, "neatcpp_bench: --profile %s: %s\n", o.profile.c_str(), err);
            return -1;
        }
        p->dropoff_age = file.dropoff_age;
        p->pop_stagnation = file.pop_stagnation; // the release's dropoff_age + 5
        p->recur_only_prob = file.recur_only_prob;
    }
    for (size_t i = 0; i < o.sets.size(); i++) {
        std::string kv = o.sets[i];
        size_t eq = kv.find('=');
        if (eq == std::string::npos) {
            fprintf(stderr, "neatcpp_bench: --set %s: key=value\n", kv.c_str());
            return -1;
        }
        std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
        if (o.engine == "release" && key != "net_step") {
            fprintf(stderr, "neatcpp_bench: --set %s: the release's parameters come from the .ne file; only "
                            "net_step (how our runtime steps its networks) applies to it\n", key.c_str());
            return -1;
        }
        if (neat_config_set(p, key.c_str(), value.c_str(), err, sizeof err) != 0) {
            fprintf(stderr, "neatcpp_bench: --set %s: %s\n", kv.c_str(), err);
            return -1;
        }
    }
    if (neat_params_check(p, &field) != NEAT_OK) {
        fprintf(stderr, "neatcpp_bench: parameter %s out of range\n", field);
        return -1;
    }
    return 0;
}

// The release's parameters as it loads them must be the values we mapped from.
int check_release_globals(const neatcpp_ne &ne)
{
    const double got[NE_COUNT] = {
        NEAT::trait_param_mut_prob, NEAT::trait_mutation_power, NEAT::linktrait_mut_sig, NEAT::nodetrait_mut_sig,
        NEAT::weight_mut_power, NEAT::recur_prob, NEAT::disjoint_coeff, NEAT::excess_coeff, NEAT::mutdiff_coeff,
        NEAT::compat_threshold, NEAT::age_significance, NEAT::survival_thresh, NEAT::mutate_only_prob,
        NEAT::mutate_random_trait_prob, NEAT::mutate_link_trait_prob, NEAT::mutate_node_trait_prob,
        NEAT::mutate_link_weights_prob, NEAT::mutate_toggle_enable_prob, NEAT::mutate_gene_reenable_prob,
        NEAT::mutate_add_node_prob, NEAT::mutate_add_link_prob, NEAT::interspecies_mate_rate,
        NEAT::mate_multipoint_prob, NEAT::mate_multipoint_avg_prob, NEAT::mate_singlepoint_prob,
        NEAT::mate_only_prob, NEAT::recur_only_prob, (double)NEAT::pop_size, (double)NEAT::dropoff_age,
        (double)NEAT::newlink_tries, (double)NEAT::print_every, (double)NEAT::babies_stolen,
        (double)NEAT::num_runs};
    for (int k = 0; k < NE_COUNT; k++)
        if (got[k] != ne.v[k]) {
            fprintf(stderr, "neatcpp_bench: the release read %s = %.17g, our reader %.17g\n", neatcpp_ne_name(k),
                    got[k], ne.v[k]);
            return -1;
        }
    return 0;
}

FILE *open_tmp(const std::string &path)
{
    FILE *f = fopen((path + ".tmp").c_str(), "w");
    if (f == NULL)
        fprintf(stderr, "neatcpp_bench: cannot write %s.tmp: %s\n", path.c_str(), strerror(errno));
    return f;
}

int close_rename(FILE *f, const std::string &path)
{
    int bad = ferror(f) | fclose(f);
    if (bad || rename((path + ".tmp").c_str(), path.c_str()) != 0) {
        fprintf(stderr, "neatcpp_bench: cannot write %s\n", path.c_str());
        return -1;
    }
    return 0;
}

int bench_main(int argc, char **argv)
{
    options o;
    neatcpp_ne ne;
    neat_params p;
    char err[512];
    uint32_t n_in = 0, n_out = 0, solved = 0, errors = 0, hopeless = 0;
    std::vector<uint64_t> ev;
    double sum_ev = 0;

    if (parse_args(argc, argv, &o))
        return 2;
    if (neatcpp_ne_read(o.ne.c_str(), &ne, err, sizeof err)) {
        fprintf(stderr, "neatcpp_bench: %s\n", err);
        return 2;
    }
    NEAT::Genome *start = read_start(o.start);
    if (start == NULL)
        return 2;
    if (neatcpp_genome_shape(start, &n_in, &n_out) != NEAT_OK || n_out != 1 ||
        n_in != (o.task == "xor" ? 2u : 6u)) {
        fprintf(stderr, "neatcpp_bench: %s: %u inputs and %u outputs besides one bias; the %s task has %u and 1\n",
                o.start.c_str(), n_in, n_out, o.task.c_str(), o.task == "xor" ? 2u : 6u);
        return 2;
    }
    if (o.engine == "libneat" && !start_is_minimal(start, n_in, n_out)) {
        fprintf(stderr, "neatcpp_bench: %s is not the minimal start (every sensor to every output), which is "
                        "the one libneat starts from\n", o.start.c_str());
        return 2;
    }
    // the release engine evaluates with these too: n_inputs, n_outputs, net_step
    if (libneat_params(o, ne, n_in, n_out, &p))
        return 2;
    if (o.engine == "release") {
        if (!NEAT::load_neat_params(o.ne.c_str(), false) || check_release_globals(ne))
            return 2;
    }

    std::string runs_path = o.out + "/runs.csv", gens_path = o.out + "/generations.csv";
    out_files of;
    // the directory itself, and its parents (mkdir -p), so that a fresh DIR needs no step of its own
    for (size_t at = 1; at <= o.out.size(); at++)
        if (at == o.out.size() || o.out[at] == '/') {
            std::string part = o.out.substr(0, at);
            if (mkdir(part.c_str(), 0777) != 0 && errno != EEXIST) {
                fprintf(stderr, "neatcpp_bench: cannot make %s: %s\n", part.c_str(), strerror(errno));
                return 1;
            }
        }
    of.runs = open_tmp(runs_path);
    of.gens = of.runs ? open_tmp(gens_path) : NULL;
    if (of.gens == NULL)
        return 1;
    fprintf(of.runs, "engine,task,run,seed,solved,evaluations,generations,solution_hidden,solution_conns,"
                     "clamped_weights\n");
    fprintf(of.gens, "engine,task,run,generation,species,mean_hidden,mean_conns,max_hidden,best_fitness,"
                     "mean_fitness\n");

    clock_t c0 = clock();
    for (uint32_t k = 0; k < o.runs; k++) {
        uint64_t r = (uint64_t)o.first_run + k, seed = neat_seed_derive(o.seed, &r, 1);
        run_result res;
        memset(&res, 0, sizeof res);
        int rc = o.engine == "release" ? run_release(o, start, p, (uint32_t)r, seed, &of, &res)
                                       : run_libneat(o, p, (uint32_t)r, seed, &of, &res);
        if (rc) {
            fprintf(stderr, "neatcpp_bench: run %" PRIu64 ": %s\n", r,
                    rc < -90 ? nrt_strerror(rc + 100) : neat_strerror(rc));
            errors++;
        }
        fprintf(of.runs, "%s,%s,%" PRIu64 ",%" PRIu64 ",%d,%" PRIu64 ",%u,%u,%u,%u\n",
                o.engine == "release" && o.eval == "native" ? "release-native" : o.engine.c_str(), o.task.c_str(), r,
                seed, res.solved, res.evaluations, res.generations, res.hidden, res.conns, res.clamped);
        if (res.hopeless)
            fprintf(stderr, "neatcpp_bench: run %" PRIu64 ": %u networks given fitness 0.001 unevaluated: the "
                            "release's max_depth would not have ended on them\n", r, res.hopeless);
        hopeless += res.hopeless;
        fflush(of.runs);
        fflush(of.gens);
        if (res.solved) {
            solved++;
            ev.push_back(res.evaluations);
            sum_ev += (double)res.evaluations;
        }
    }
    double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    if (close_rename(of.runs, runs_path) | close_rename(of.gens, gens_path))
        return 1;

    double median = 0;
    std::sort(ev.begin(), ev.end());
    if (!ev.empty())
        median = ev.size() % 2 ? (double)ev[ev.size() / 2]
                               : 0.5 * (double)(ev[ev.size() / 2 - 1] + ev[ev.size() / 2]);
    printf("engine %s%s task %s: %u runs (%u..%u), %u solved, mean %.1f evaluations, median %.1f, %u failures, "
           "%u errors, %.2f s CPU%s\n",
           o.engine.c_str(), o.eval == "native" ? " (native evaluation)" : "", o.task.c_str(), o.runs, o.first_run,
           o.first_run + o.runs - 1, solved, solved ? sum_ev / solved : 0.0, median, o.runs - solved, errors, cpu,
           hopeless ? " (some networks unevaluated: stderr)" : "");
    delete start;
    return errors ? 1 : 0;
}

} // namespace

int main(int argc, char **argv)
{
    null_buf sink;
    std::streambuf *was = std::cout.rdbuf(&sink);
    // the release's pole2_evaluate may wait on std::cin (its "ORGANISM DAMAGED" alert): never block
    std::cin.setstate(std::ios::failbit);
    int rc = bench_main(argc, argv);
    std::cout.rdbuf(was);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "neatcpp_bench: cannot write standard output: %s\n", strerror(errno));
        return rc ? rc : 1;
    }
    return rc;
}
