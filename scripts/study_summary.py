#!/usr/bin/env python3
"""study_summary.py M1.csv - docs/study.md's stage A table: per cell and opponent the five margins (wins - losses of
the last champion in the 288-game comparison), how many champions win more than they lose, the mean, and the exact
two-sided Mann-Whitney p-value against v1's five (the permutation distribution of U over every split of the ten
values; ties count half). A cell changes M1 when p < 0.05 for either opponent."""
import csv
import itertools
import sys


def u_stat(a, b):
    return sum(1.0 if x > y else 0.5 if x == y else 0.0 for x in a for y in b)


def mann_whitney_p(a, b):
    """Exact two-sided p: the share of splits of a + b into groups of len(a), len(b) whose U is at least as far from
    its mean as the observed one."""
    pooled = a + b
    mean = len(a) * len(b) / 2.0
    obs = abs(u_stat(a, b) - mean)
    n = total = 0
    for idx in itertools.combinations(range(len(pooled)), len(a)):
        ga = [pooled[i] for i in idx]
        gb = [pooled[i] for i in range(len(pooled)) if i not in idx]
        total += 1
        n += abs(u_stat(ga, gb) - mean) >= obs - 1e-9
    return n / total


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    cells, data = [], {}
    for r in rows:
        if r["cell"] not in cells:
            cells.append(r["cell"])
        data.setdefault((r["cell"], r["opponent"]), []).append(int(r["margin"]))
    print("| cell | opponent | margins (seeds 1-5) | wins > losses | mean | p against v1 |")
    print("|---|---|---|---:|---:|---:|")
    for c in cells:
        for opp in ("forager-hunter", "forager"):
            m = data.get((c, opp))
            if not m:
                continue
            base = data.get(("v1", opp))
            p = "" if c == "v1" or not base or len(m) < 5 or len(base) < 5 else "%.3f" % mann_whitney_p(m, base)
            print("| %s | %s | %s | %d of %d | %+.1f | %s |" % (c, opp, " ".join("%+d" % x for x in m),
                                                             sum(x > 0 for x in m), len(m), sum(m) / len(m), p))


if __name__ == "__main__":
    main()
