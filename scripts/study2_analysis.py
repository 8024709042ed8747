#!/usr/bin/env python3
"""study2_analysis.py ROOT [--duel DUEL_EVOLVE] [--skip-compare] - docs/study2.md's registered analysis of the
experiment directories ROOT/<cell> (made by `duel_evolve experiment configs/plans/study2/<cell>.ini --out
ROOT/<cell>`): the primary measure (Table 1's performance, the "highest" reading) of every run against its cell's
complexifying rankings (`duel_evolve compare`, CSVs in ROOT/analysis/), the registered tests (two-sided), Holm's
correction over the primary family and, apart, over the secondary one, and the secondary measures. Prints the
tables docs/study2.md quotes; a cell not yet run is reported as missing and its tests left out (the families are
then incomplete, and the script says so: the decision waits for every cell)."""
import csv
import glob
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import neat_stats as st  # noqa: E402

# cell -> where each method's runs are: (cell directory, method name in it). The fixed topologies of a cell whose
# setting cannot touch them (add-node rate, equal-fitness inheritance, re-enabling: a fixed topology has no
# unmatched and no disabled gene and never adds a node) are s0-default's own runs, measured against this cell's
# complexifying rankings.
CELLS = {
    "s0-default": {"complexify": ("s0-default", "complexify"), "fixed-10": ("s0-default", "fixed-10"),
                   "fixed-5": ("s0-default", "fixed-5")},
    "s1-profile": {"complexify": ("s1-profile", "complexify"), "fixed-10": ("s1-profile", "fixed-10"),
                   "fixed-5": ("s1-profile", "fixed-5")},
    "s2-params256": {"complexify": ("s2-params256", "complexify"), "fixed-10": ("s2-params256", "fixed-10"),
                     "fixed-5": ("s2-params256", "fixed-5")},
    "s3-addnode0.003": {"complexify": ("s3-addnode0.003", "complexify"), "fixed-10": ("s0-default", "fixed-10"),
                        "fixed-5": ("s0-default", "fixed-5")},
    "s4-equal-smaller": {"complexify": ("s4-equal-smaller", "complexify"), "fixed-10": ("s0-default", "fixed-10"),
                         "fixed-5": ("s0-default", "fixed-5")},
    "s5-cull": {"complexify": ("s5-cull", "complexify"), "fixed-10": ("s5-cull", "fixed-10"),
                "fixed-5": ("s5-cull", "fixed-5")},
    "s6-reenable": {"complexify": ("s6-reenable", "complexify"), "fixed-10": ("s0-default", "fixed-10"),
                    "fixed-5": ("s0-default", "fixed-5")},
    "s7-params256-values": {"complexify": ("s7-params256-values", "complexify"),
                            "fixed-10": ("s7-params256-values", "fixed-10"),
                            "fixed-5": ("s7-params256-values", "fixed-5")},
}
PRIMARY = ["s0-default", "s1-profile", "s2-params256", "s3-addnode0.003"]
SECONDARY = ["s4-equal-smaller", "s5-cull", "s6-reenable", "s7-params256-values"]
INTERACTION_BASE = "s0-default"
ROUNDS = 20000


def runs_of(root, cell_dir, method):
    """The finished runs of a method (an experiment's runs/METHOD-K directories holding dominance.csv)."""
    found = glob.glob(os.path.join(root, cell_dir, "runs", method + "-*"))
    runs = [d for d in found if os.path.isfile(os.path.join(d, "dominance.csv"))]
    return sorted(runs, key=lambda d: int(d.rsplit("-", 1)[1]))


def performance(root, duel, cell, method, cands, rankings, skip):
    """Each candidate run's mean 'highest' performance over the cell's complexifying rankings (itself excluded,
    as compare does), from duel_evolve compare's per-pair CSV."""
    out = os.path.join(root, "analysis", "%s-%s.csv" % (cell, method))
    if not skip or not os.path.isfile(out):
        os.makedirs(os.path.dirname(out), exist_ok=True)
        cmd = [duel, "compare"] + cands + ["--against"] + rankings + ["--csv", out, "--force"]
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    per = {}
    with open(out) as f:
        for r in csv.DictReader(f):
            per.setdefault(r["candidate"], []).append(float(r["highest_performance"]))
    return [st.mean(per[c]) for c in sorted(per)]


def gap(c, f):
    return st.mean(c) - st.mean(f)


def interaction_p(cell_c, cell_f, base_c, base_f, seed=1):
    """Two-sided permutation test of (complexify - fixed) in a cell minus the same in the base cell: method labels
    shuffled within each cell, ROUNDS relabellings of a seeded generator."""
    import random
    rng = random.Random(seed)
    obs = gap(cell_c, cell_f) - gap(base_c, base_f)
    a, b = list(cell_c) + list(cell_f), list(base_c) + list(base_f)
    hits = 0
    for _ in range(ROUNDS):
        rng.shuffle(a)
        rng.shuffle(b)
        s = gap(a[:len(cell_c)], a[len(cell_c):]) - gap(b[:len(base_c)], b[len(base_c):])
        hits += abs(s) >= abs(obs) - 1e-12
    return obs, (hits + 1) / (ROUNDS + 1)


def sizes_at(run, generations):
    """Population A and B's mean hidden nodes and connections at each generation asked (generations.csv)."""
    got = {}
    with open(os.path.join(run, "generations.csv")) as f:
        for r in csv.DictReader(f):
            g = int(r["generation"])
            if g in generations:
                got.setdefault(g, []).append((float(r["mean_hidden"]), float(r["mean_connections"])))
    return {g: (st.mean([x[0] for x in v]), st.mean([x[1] for x in v])) for g, v in got.items()}


def strength_within_runs(root, duel, runs, cell, skip, seed=1):
    """Absolute strength within runs: each run's dominants against forager-hunter (duel_evolve ladder, cached in
    ROOT/analysis/), the Spearman correlation of level and wins - losses within each run, their mean, and the
    two-sided p of a permutation test that shuffles the margins within each run (never across runs)."""
    import random
    from study_strength import spearman
    per = []
    for r in runs:
        out = os.path.join(root, "analysis", "ladder-%s-%s.csv" % (cell, os.path.basename(r)))
        if not skip or not os.path.isfile(out):
            subprocess.run([duel, "ladder", r, "--against", "forager-hunter", "--csv", out, "--force"], check=True,
                           stdout=subprocess.DEVNULL)
        with open(out) as f:
            rows = list(csv.DictReader(f))
        if len(rows) < 3:
            continue  # too few dominants for a correlation
        lv = [int(x["level"]) for x in rows]
        mg = [int(x["forager-hunter_wins"]) - int(x["forager-hunter_losses"]) for x in rows]
        per.append((lv, mg))
    if not per:
        return float("nan"), 1.0, 0
    obs = st.mean([spearman(lv, mg) for lv, mg in per])
    rng = random.Random(seed)
    hits = 0
    for _ in range(ROUNDS // 4):
        vals = []
        for lv, mg in per:
            m = list(mg)
            rng.shuffle(m)
            vals.append(spearman(lv, m))
        hits += abs(st.mean(vals)) >= abs(obs) - 1e-12
    return obs, (hits + 1) / (ROUNDS // 4 + 1), len(per)


def main():
    args = sys.argv[1:]
    duel, skip = "build/bin/duel_evolve", False
    if "--duel" in args:
        i = args.index("--duel")
        duel = args[i + 1]
        del args[i:i + 2]
    if "--skip-compare" in args:
        skip = True
        args.remove("--skip-compare")
    if len(args) != 1:
        sys.exit(__doc__)
    root = args[0]
    perf, missing = {}, []
    for cell, where in CELLS.items():
        runs = {m: runs_of(root, d, meth) for m, (d, meth) in where.items()}
        if any(not r for r in runs.values()):
            missing.append(cell)
            continue
        perf[cell] = {m: performance(root, duel, cell, m, runs[m], runs["complexify"], skip) for m in runs}
    print("Performance (highest reading) against each cell's complexifying rankings: mean (sd), runs")
    print("| cell | complexify | fixed-10 | fixed-5 |")
    print("|---|---|---|---|")
    for cell in CELLS:
        if cell in perf:
            print("| %s | %s |" % (cell, " | ".join(
                "%.1f %% (%.1f), %d" % (100 * st.mean(v), 100 * (st.mean([(x - st.mean(v)) ** 2 for x in v]) *
                                                                  len(v) / max(1, len(v) - 1)) ** 0.5, len(v))
                for v in (perf[cell]["complexify"], perf[cell]["fixed-10"], perf[cell]["fixed-5"]))))
        else:
            print("| %s | not run yet | | |" % cell)
    for family, cells in (("primary", PRIMARY), ("secondary", SECONDARY)):
        rows, ps = [], []
        for cell in cells:
            if cell not in perf:
                continue
            for f in ("fixed-10", "fixed-5"):
                p = st.mann_whitney(perf[cell]["complexify"], perf[cell][f])[1]
                rows.append(("%s: complexify vs %s" % (cell, f), gap(perf[cell]["complexify"], perf[cell][f]), p))
                ps.append(p)
        inter = ["s3-addnode0.003"] if family == "primary" else SECONDARY
        for cell in inter:
            if cell not in perf or INTERACTION_BASE not in perf:
                continue
            fixed = perf[cell]["fixed-10"] + perf[cell]["fixed-5"]
            base_fixed = perf[INTERACTION_BASE]["fixed-10"] + perf[INTERACTION_BASE]["fixed-5"]
            d, p = interaction_p(perf[cell]["complexify"], fixed, perf[INTERACTION_BASE]["complexify"], base_fixed)
            rows.append(("%s vs %s: (complexify - fixed) difference" % (cell, INTERACTION_BASE), d, p))
            ps.append(p)
        adj = st.holm(ps) if ps else []
        want = 9 if family == "primary" else 12
        print("\n%s family (%d of its %d tests%s):" % (family.capitalize(), len(ps), want,
                                                       "" if len(ps) == want else "; incomplete: Holm over these"))
        print("| test | difference (points) | p | Holm p |")
        print("|---|---:|---:|---:|")
        for (name, d, p), a in zip(rows, adj):
            print("| %s | %+.1f | %.3g | %.3g |" % (name, 100 * d, p, a))
    print("\nSecondary: population sizes (mean hidden nodes, connections of A and B) at generations 50, 100, 199, "
          "complexifying runs, mean over runs")
    for cell in CELLS:
        if cell not in perf:
            continue
        d, meth = CELLS[cell]["complexify"]
        at = [sizes_at(r, {50, 100, 199}) for r in runs_of(root, d, meth)]
        cols = []
        for g in (50, 100, 199):
            h = [a[g][0] for a in at if g in a]
            c = [a[g][1] for a in at if g in a]
            cols.append("%.2f / %.1f" % (st.mean(h), st.mean(c)) if h else "-")
        print("| %s | %s |" % (cell, " | ".join(cols)))
    print("\nSecondary: absolute strength within runs (complexifying runs' dominants against forager-hunter)")
    print("| cell | runs | mean within-run Spearman rho (level, wins - losses) | permutation p (within runs) |")
    print("|---|---:|---:|---:|")
    for cell in PRIMARY:
        if cell not in perf:
            continue
        d, meth = CELLS[cell]["complexify"]
        rho, p, n = strength_within_runs(root, duel, runs_of(root, d, meth), cell, skip)
        print("| %s | %d | %+.3f | %.4f |" % (cell, n, rho, p))
    if missing:
        print("\nnot run yet: %s" % ", ".join(missing))


if __name__ == "__main__":
    main()
