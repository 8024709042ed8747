#!/usr/bin/env python3
"""experiment_check.py DIR - an experiment's report recomputed from its run directories, independently of the C code.

Checks runs.csv against each run's dominance.csv; table1.csv's means and standard deviations against runs.csv and
its Mann-Whitney p-values against an exact permutation test enumerated here (every split of the runs); the data of
Figures 7, 11 and 12-15 against dominance.csv and generations.csv. Exits 1 with the first difference.
"""
import csv
import itertools
import json
import math
import os
import sys
from fractions import Fraction


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def fail(msg):
    print("FAIL: %s" % msg)
    sys.exit(1)


def close(a, b, what, tol=1e-4):
    if abs(float(a) - float(b)) > tol * max(1.0, abs(float(b))):
        fail("%s: report %s, recomputed %s" % (what, a, b))


def ranks(v):
    s = sorted(v)
    r = {}
    for x in set(v):
        idx = [i + 1 for i, y in enumerate(s) if y == x]
        r[x] = Fraction(sum(idx), len(idx))
    return [r[x] for x in v]


def mwu_exact(x, y):
    v = x + y
    r = ranks(v)
    n, nx = len(v), len(x)
    obs = sum(r[:nx])
    mean = Fraction(nx * (n + 1), 2)
    hit = total = 0
    for comb in itertools.combinations(range(n), nx):
        s = sum(r[i] for i in comb)
        total += 1
        hit += abs(s - mean) >= abs(obs - mean)
    return float(Fraction(hit, total))


def wilcoxon_exact(d):
    d = [x for x in d if x != 0]
    if not d:
        return 1.0
    r = ranks([abs(x) for x in d])
    obs = sum(r[i] for i in range(len(d)) if d[i] > 0)
    mean = sum(r) / 2
    hit = 0
    for signs in itertools.product((0, 1), repeat=len(d)):
        s = sum(r[i] for i in range(len(d)) if signs[i])
        hit += abs(s - mean) >= abs(obs - mean)
    return float(Fraction(hit, 2 ** len(d)))


def sd(v):
    if len(v) < 2:
        return 0.0
    m = sum(v) / len(v)
    return math.sqrt(sum((x - m) ** 2 for x in v) / (len(v) - 1))


def dominance(run_dir):
    out = []
    for r in rows(os.path.join(run_dir, "dominance.csv")):
        wl = [tuple(int(t) for t in s.split(":")) for s in r["wins"].split()] if r["wins"] else []
        out.append({"level": int(r["level"]), "generation": int(r["generation"]), "hidden": int(r["hidden"]),
                    "connections": int(r["connections"]), "scores": wl})
    return out


def main():
    d = sys.argv[1]
    rep = os.path.join(d, "report")
    table = json.load(open(os.path.join(rep, "table1.json")))
    ref = table["reference"]
    runs = rows(os.path.join(rep, "runs.csv"))
    dom = {}
    for r in runs:
        lv = dominance(os.path.join(d, "runs", r["run"]))
        dom[r["run"]] = lv
        if int(r["levels"]) != len(lv) or int(r["top_generation"]) != lv[-1]["generation"] or \
                int(r["top_connections"]) != lv[-1]["connections"] or int(r["top_hidden"]) != lv[-1]["hidden"]:
            fail("runs.csv %s: levels/top dominant differ from its dominance.csv" % r["run"])
        ladder = rows(os.path.join(d, "runs", r["run"], "ladder.csv"))[-1]
        if int(ladder["level"]) != len(lv) or ladder["total_wins"] != r["ladder_wins"]:
            fail("runs.csv %s: the ladder is not its top dominant's" % r["run"])
    cols = ["levels", "top_generation", "highest_performance", "highest_equivalent_generation",
            "contiguous_performance", "contiguous_equivalent_generation"]
    by = {}
    for r in runs:
        by.setdefault(r["method"], []).append(r)
    for t in rows(os.path.join(rep, "table1.csv")):
        mine = by[t["method"]]
        if int(t["runs"]) != len(mine):
            fail("table1.csv %s: %s runs, runs.csv has %d" % (t["method"], t["runs"], len(mine)))
        for c in cols:
            v = [float(r[c]) for r in mine]
            close(t[c + "_mean"], sum(v) / len(v), "table1.csv %s %s mean" % (t["method"], c))
            close(t[c + "_sd"], sd(v), "table1.csv %s %s sd" % (t["method"], c))
            if t["method"] == ref:
                if t[c + "_p"] != "":
                    fail("table1.csv: a p-value for the reference itself")
                continue
            w = [float(r[c]) for r in by[ref]]
            close(t[c + "_p"], mwu_exact(w, v), "table1.csv %s %s p" % (t["method"], c))
    # Figure 7: the current dominant at every generation where a reference run gains a level
    refruns = [dom[r["run"]] for r in by[ref]]
    gens = sorted({lv["generation"] for run in refruns for lv in run})
    fig7 = rows(os.path.join(rep, "fig7-complexity.csv"))
    if [int(r["generation"]) for r in fig7] != gens:
        fail("fig7-complexity.csv: generations %s, expected %s" % ([r["generation"] for r in fig7], gens))
    for r in fig7:
        g = int(r["generation"])
        cur = [[lv for lv in run if lv["generation"] <= g][-1] for run in refruns
               if any(lv["generation"] <= g for lv in run)]
        close(r["mean_connections"], sum(c["connections"] for c in cur) / len(cur), "fig7 connections at %d" % g)
        close(r["mean_hidden"], sum(c["hidden"] for c in cur) / len(cur), "fig7 hidden at %d" % g)
    test = {r["measure"]: r for r in rows(os.path.join(rep, "fig7-test.csv"))}
    for key, measure in (("connections", "connections"), ("hidden", "hidden")):
        diff = [run[-1][key] - run[0][key] for run in refruns]
        close(test[measure]["p"], wilcoxon_exact(diff), "fig7-test %s p" % measure)
    # Figure 7's random-fitness bounds
    randm = [m["name"] for m in table["methods"] if m["random_fitness"]]
    per_gen = {}
    for m in randm:
        for r in by[m]:
            bounds = {}
            for g in rows(os.path.join(d, "runs", r["run"], "generations.csv")):
                b = bounds.setdefault(int(g["generation"]), [1e9, -1, 1e9, -1])
                b[0] = min(b[0], int(g["min_connections"]))
                b[1] = max(b[1], int(g["max_connections"]))
                b[2] = min(b[2], int(g["min_hidden"]))
                b[3] = max(b[3], int(g["max_hidden"]))
            for g, b in bounds.items():
                per_gen.setdefault(g, []).append(b)
    fig7r = rows(os.path.join(rep, "fig7-random.csv"))
    if len(fig7r) != len(per_gen):
        fail("fig7-random.csv: %d generations, expected %d" % (len(fig7r), len(per_gen)))
    for r in fig7r:
        bs = per_gen[int(r["generation"])]
        for i, k in enumerate(("min_connections", "max_connections", "min_hidden", "max_hidden")):
            close(r[k], sum(b[i] for b in bs) / len(bs), "fig7-random %s at %s" % (k, r["generation"]))
    # Figure 11: wins - losses against each level below, by the difference in level
    extra = {}
    for run in refruns:
        for lv in run:
            for j, (w, l) in enumerate(lv["scores"]):
                extra.setdefault(j + 1, []).append(w - l)
    fig11 = rows(os.path.join(rep, "fig11-levels.csv"))
    if [int(r["level_difference"]) for r in fig11] != sorted(extra):
        fail("fig11-levels.csv: differences %s, expected %s" % ([r["level_difference"] for r in fig11], sorted(extra)))
    for r in fig11:
        v = extra[int(r["level_difference"])]
        if int(r["comparisons"]) != len(v):
            fail("fig11 %s: %s comparisons, expected %d" % (r["level_difference"], r["comparisons"], len(v)))
        close(r["mean_extra_wins"], sum(v) / len(v), "fig11 mean at %s" % r["level_difference"])
        close(r["sd_extra_wins"], sd(v), "fig11 sd at %s" % r["level_difference"])
    # Figures 12-15: each method's typical run (median performance) beside the reference's
    for m in table["methods"]:
        if m["name"] == ref:
            continue
        lv = rows(os.path.join(rep, "levels-%s.csv" % m["name"]))
        for series, name in (("reference", table["methods"][[x["name"] for x in table["methods"]].index(ref)]
                              ["typical_run"]), ("method", m["typical_run"])):
            got = [(int(r["level"]), int(r["generation"]), int(r["connections"])) for r in lv if r["series"] == series]
            want = [(x["level"], x["generation"], x["connections"]) for x in dom[name]]
            if got != want:
                fail("levels-%s.csv %s: %s, expected %s's %s" % (m["name"], series, got, name, want))
        perf = sorted(float(r["highest_performance"]) for r in by[m["name"]])
        typical = [r for r in by[m["name"]] if r["run"] == m["typical_run"]][0]
        if float(typical["highest_performance"]) != perf[(len(perf) - 1) // 2]:
            fail("%s: the typical run %s is not the median" % (m["name"], m["typical_run"]))
    print("report of %s: %d runs, %d methods recomputed" % (d, len(runs), len(table["methods"])))


if __name__ == "__main__":
    main()
