#!/usr/bin/env python3
"""neatcpp_compare.py RELEASE_DIR OTHER_DIR [OTHER_DIR ...] - docs/neat-cpp.md's registered comparison of
neatcpp_bench runs: each OTHER engine (libneat with the profile, libneat's default) against the release's
reproduction, on both tasks: the seven registered measures a task, two-sided tests, Holm's correction over the
14 tests of the engine's comparison, the registered margins, and the verdict per row: "match" unless the Holm p
is below 0.05 and the difference lies outside its margin. Each DIR holds xor/ and pole/, each with
neatcpp_bench's runs.csv and generations.csv."""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import neat_stats as st  # noqa: E402

GENERATION = 20  # the population measures' generation (0-based), registered


def load(d):
    with open(os.path.join(d, "runs.csv")) as f:
        runs = list(csv.DictReader(f))
    with open(os.path.join(d, "generations.csv")) as f:
        gens = list(csv.DictReader(f))
    return runs, gens


def measures(runs, gens, task):
    runs = [r for r in runs if r["task"] == task]
    solved = [r for r in runs if r["solved"] == "1"]
    at = [g for g in gens if g["task"] == task and int(g["generation"]) == GENERATION]
    return {
        "n": len(runs),
        "failures": len(runs) - len(solved),
        "evaluations": [int(r["evaluations"]) for r in solved],
        "solution_hidden": [int(r["solution_hidden"]) for r in solved],
        "solution_conns": [int(r["solution_conns"]) for r in solved],
        "pop_hidden": [float(g["mean_hidden"]) for g in at],
        "pop_conns": [float(g["mean_conns"]) for g in at],
        "species": [int(g["species"]) for g in at],
        "engine": runs[0]["engine"] if runs else "?",
    }


def within_margin(name, ref, other):
    """The registered margins: outside them a significant difference is a mismatch."""
    if name == "failures":
        return abs(other["failures"] / other["n"] - ref["failures"] / ref["n"]) <= 0.10
    a, b = ref[name], other[name]
    if not a or not b:
        return True
    if name == "evaluations":
        ratio = st.median(b) / st.median(a)
        return 0.8 <= ratio <= 1.25
    if name in ("solution_hidden", "pop_hidden"):
        return abs(st.mean(b) - st.mean(a)) <= 0.5
    if name in ("solution_conns", "pop_conns"):
        return abs(st.mean(b) - st.mean(a)) <= 0.10 * st.mean(a)
    if name == "species":
        return abs(st.median(b) - st.median(a)) <= 0.20 * st.median(a)
    raise ValueError(name)


ROWS = ["failures", "evaluations", "solution_hidden", "solution_conns", "pop_hidden", "pop_conns", "species"]


def describe(name, m):
    if name == "failures":
        return "%d of %d" % (m["failures"], m["n"])
    xs = m[name]
    if not xs:
        return "-"
    return "mean %.2f, median %.1f (n %d)" % (st.mean(xs), st.median(xs), len(xs))


TASKS = ["xor", "pole"]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    ref_dir, others = sys.argv[1], sys.argv[2:]
    ref = {t: measures(*load(os.path.join(ref_dir, t)), t) for t in TASKS}
    print("reference: %s (%s); population measures at generation %d" % (ref["xor"]["engine"], ref_dir, GENERATION))
    for od in others:
        o = {t: measures(*load(os.path.join(od, t)), t) for t in TASKS}
        rows, ps = [], []
        for t in TASKS:
            for name in ROWS:
                a, b = ref[t], o[t]
                if name == "failures":
                    p = st.fisher_exact(a["failures"], a["n"] - a["failures"], b["failures"], b["n"] - b["failures"])
                else:
                    p = st.mann_whitney(a[name], b[name])[1]
                rows.append((t, name))
                ps.append(p)
        adj = st.holm(ps)
        print("\n%s (%s) against %s, Holm over its %d tests:" % (o["xor"]["engine"], od, ref["xor"]["engine"],
                                                              len(ps)))
        print("| task | measure | %s | %s | p | Holm p | within margin | verdict |" % (ref["xor"]["engine"],
                                                                                    o["xor"]["engine"]))
        print("|---|---|---|---|---:|---:|:---:|---|")
        mismatches = 0
        for (t, name), p, a in zip(rows, ps, adj):
            ok = within_margin(name, ref[t], o[t])
            verdict = "match" if a >= 0.05 or ok else "MISMATCH"
            mismatches += verdict != "match"
            print("| %s | %s | %s | %s | %.3g | %.3g | %s | %s |" % (t, name, describe(name, ref[t]),
                                                                    describe(name, o[t]), p, a,
                                                                    "yes" if ok else "no", verdict))
        print("%d mismatch%s" % (mismatches, "" if mismatches == 1 else "es"))


if __name__ == "__main__":
    main()
