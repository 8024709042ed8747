#!/usr/bin/env python3
"""run_summary.py RUN... - per run directory: dominance levels, the top dominant, and the speciation figures of
generations.csv (species counts and the compatibility threshold over the run, both populations), as a Markdown
table; with --group, the means per group of runs named NAME=GLOB-prefix (e.g. --group 0.5=power-0.5-)."""
import csv
import os
import sys


def summary(run):
    rows = list(csv.DictReader(open(os.path.join(run, "generations.csv"))))
    dom = list(csv.DictReader(open(os.path.join(run, "dominance.csv"))))
    species = [int(r["species"]) for r in rows]
    delta = [float(r["delta_t"]) for r in rows]
    gen1 = [int(r["species"]) for r in rows if r["generation"] == "1"]
    top = dom[-1]
    return {
        "run": run,
        "generations": len(rows) // 2,
        "levels": len(dom),
        "top_gen": int(top["generation"]),
        "top_hidden": int(top["hidden"]),
        "top_conns": int(top["connections"]),
        "species_gen1": sum(gen1) / max(1, len(gen1)),
        "species_mean": sum(species) / len(species),
        "delta_mean": sum(delta) / len(delta),
        "delta_max": max(delta),
        "delta_final": sum(delta[-2:]) / 2,
        "conns_mean_final": sum(float(r["mean_connections"]) for r in rows[-2:]) / 2,
        # wall time of the generations (each is on both of its rows)
        "minutes": sum(float(r["seconds"]) for r in rows if r["population"] == "A") / 60.0,
    }


COLS = [("levels", "levels", "%.1f"), ("top_gen", "top gen", "%.1f"), ("top_conns", "top conns", "%.1f"),
        ("top_hidden", "top hidden", "%.1f"), ("species_gen1", "species gen 1", "%.1f"),
        ("species_mean", "species mean", "%.1f"), ("delta_mean", "delta_t mean", "%.2f"),
        ("delta_max", "delta_t max", "%.2f"), ("delta_final", "delta_t final", "%.2f"),
        ("conns_mean_final", "pop conns final", "%.1f"), ("minutes", "minutes", "%.1f")]


def main(argv):
    groups = []
    runs = []
    i = 0
    while i < len(argv):
        if argv[i] == "--group":
            name, prefix = argv[i + 1].split("=", 1)
            groups.append((name, prefix))
            i += 2
        else:
            runs.append(argv[i])
            i += 1
    if not runs:
        sys.exit(__doc__)
    rows = [summary(r) for r in runs]
    if not groups:
        groups = [(r["run"], r["run"]) for r in rows]
    print("| runs | n | " + " | ".join(c[1] for c in COLS) + " |")
    print("|---|---|" + "---|" * len(COLS))
    for name, prefix in groups:
        mine = [r for r in rows if os.path.basename(r["run"].rstrip("/")).startswith(prefix) or r["run"] == prefix]
        if not mine:
            continue
        cells = [c[2] % (sum(r[c[0]] for r in mine) / len(mine)) for c in COLS]
        print("| %s | %d | %s |" % (name, len(mine), " | ".join(cells)))


if __name__ == "__main__":
    main(sys.argv[1:])
