#!/usr/bin/env python3
"""study_cell.py CELL_DIR - docs/study.md, stage B: one cell's measures from its experiment directory, the same way for
every cell: M3 (report/table1.csv), M2 (report/ladder.csv: the top dominants against forager-hunter and forager;
report/strength.csv: the generation champions' mean wins - losses against forager-hunter), M4 (report/fig7-*.csv),
and, when CELL_DIR/lad-K.csv hold each complexifying run's ladder against forager-hunter (made by
`duel_evolve ladder CELL_DIR/runs/complexify-K --against forager-hunter --csv CELL_DIR/lad-K.csv`), criteria (a)
and (b) through scripts/study_strength.py."""
import csv
import glob
import os
import subprocess
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    cell = sys.argv[1]
    rep = os.path.join(cell, "report")
    print("cell %s" % os.path.basename(os.path.normpath(cell)))

    # M3
    t = {r["method"]: r for r in rows(os.path.join(rep, "table1.csv"))}
    for m, r in t.items():
        line = "M3 %-10s %s runs: %.1f levels (sd %.1f), performance %.1f %% highest / %.1f %% contiguous" % (
            m, r["runs"], float(r["levels_mean"]), float(r["levels_sd"]), 100 * float(r["highest_performance_mean"]),
            100 * float(r["contiguous_performance_mean"]))
        if r["levels_p"]:
            line += "; p levels %.3g, performance %.3g / %.3g" % (
                float(r["levels_p"]), float(r["highest_performance_p"]), float(r["contiguous_performance_p"]))
        print(line)

    # M2: the top dominants against the built-in strategies
    for r in rows(os.path.join(rep, "ladder.csv")):
        if r["opponent"] in ("forager-hunter", "forager"):
            print("M2 top dominants, %-10s against %-14s %s:%s of %s games" % (
                r["method"], r["opponent"], r["wins"], r["losses"], r["games"]))
    # M2: strength over the run, the generation champions' mean margin against forager-hunter
    st = rows(os.path.join(rep, "strength.csv"))
    by = {}
    for r in st:
        g = int(r["generation"])
        by.setdefault(r["method"], {}).setdefault(g, []).append(
            int(r["forager-hunter_wins"]) - int(r["forager-hunter_losses"]))
    for m, gens in by.items():
        keys = [g for g in (0, 50, 100, 150, 190) if g in gens]
        print("M2 strength %-10s mean wins - losses against forager-hunter at generation %s: %s" % (
            m, ", ".join(map(str, keys)), ", ".join("%.0f" % (sum(gens[g]) / len(gens[g])) for g in keys)))

    # M4
    fig = rows(os.path.join(rep, "fig7-complexity.csv"))
    rnd = rows(os.path.join(rep, "fig7-random.csv"))
    test = {r["measure"]: r for r in rows(os.path.join(rep, "fig7-test.csv"))}
    last = rnd[-1]
    print("M4 final dominants: %.1f connections, %.1f hidden nodes (first %.1f, %.1f; Wilcoxon p %s, %s); random "
          "fitness at generation %s: %s-%s connections, %s-%s hidden nodes" % (
              float(test["connections"]["final_mean"]), float(test["hidden"]["final_mean"]),
              float(test["connections"]["first_mean"]), float(test["hidden"]["first_mean"]),
              test["connections"]["p"], test["hidden"]["p"], last["generation"],
              "%.0f" % float(last["min_connections"]), "%.0f" % float(last["max_connections"]),
              "%.0f" % float(last["min_hidden"]), "%.0f" % float(last["max_hidden"])))
    del fig

    # criteria (a) second half and (b)
    lads = sorted(glob.glob(os.path.join(cell, "lad-*.csv")))
    if lads:
        here = os.path.dirname(os.path.abspath(__file__))
        sys.stdout.flush()
        subprocess.run([sys.executable, os.path.join(here, "study_strength.py")] + lads, check=True)
    else:
        print("(no lad-K.csv: criteria (a) and (b) need each complexifying run's ladder against forager-hunter)")


if __name__ == "__main__":
    main()
