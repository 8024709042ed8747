#!/usr/bin/env python3
"""study2_reports.py ROOT - docs/study2.md's secondary measures as each cell's own `experiment report` gives them
(ROOT/<cell>/report/table1.json): dominance levels, the contiguous reading, the report's p-values, Figure 7's test
(first against final dominants' size) and the top dominants' games against forager-hunter and forager. Reads the
reports only; the registered tests are scripts/study2_analysis.py's. Written after the runs (2026-12-07), to print
what the protocol's "Secondary measures" list names; it computes nothing the protocol decides on."""
import json
import os
import sys

CELLS = ["s0-default", "s1-profile", "s2-params256", "s3-addnode0.003", "s4-equal-smaller", "s5-cull",
         "s6-reenable", "s7-params256-values"]


def pct(x):
    return "%.1f %%" % (100 * x)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    print("Each cell's experiment report (its own runs only: s3, s4 and s6 have no fixed runs of their own)")
    print("| cell | method | runs | levels | contiguous performance | p levels | p contiguous | "
          "top dominants vs forager-hunter (w-l) | vs forager (w-l) |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    fig7 = []
    for cell in CELLS:
        path = os.path.join(root, cell, "report", "table1.json")
        if not os.path.isfile(path):
            print("| %s | no report | | | | | | | |" % cell)
            continue
        with open(path) as f:
            d = json.load(f)
        ref = d["reference"]
        p_of = {}
        tp = os.path.join(root, cell, "report", "table1.csv")
        with open(tp) as f:
            head = f.readline().strip().split(",")
            for line in f:
                row = dict(zip(head, line.strip().split(",")))
                p_of[row["method"]] = row
        for m in d["methods"]:
            lad = m["ladder"]
            row = p_of.get(m["name"], {})
            print("| %s | %s | %d | %.1f (%.1f) | %s (%s) | %s | %s | %d-%d | %d-%d |" % (
                cell, m["name"], m["runs"], m["levels"]["mean"], m["levels"]["sd"],
                pct(m["contiguous"]["performance"]["mean"]), pct(m["contiguous"]["performance"]["sd"]),
                row.get("levels_p") or ("(reference)" if m["name"] == ref else ""),
                row.get("contiguous_performance_p") or ("(reference)" if m["name"] == ref else ""),
                lad["forager-hunter"]["wins"], lad["forager-hunter"]["losses"], lad["forager"]["wins"],
                lad["forager"]["losses"]))
        c = d.get("complexification")
        if c:
            fig7.append((cell, c))
    print("\nFigure 7's test (each complexifying run's first against its final dominant: Wilcoxon signed-rank)")
    print("| cell | runs | hidden first -> final | p | connections first -> final | p |")
    print("|---|---:|---:|---:|---:|---:|")
    for cell, c in fig7:
        print("| %s | %d | %.2f -> %.2f | %.3g | %.1f -> %.1f | %.3g |" % (
            cell, c["runs"], c["hidden"]["first_mean"], c["hidden"]["final_mean"], c["hidden"]["p"],
            c["connections"]["first_mean"], c["connections"]["final_mean"], c["connections"]["p"]))


if __name__ == "__main__":
    main()
