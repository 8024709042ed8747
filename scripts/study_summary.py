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


FIELDS = ["cell", "opponent", "seed", "wins", "losses", "draws", "timeouts", "margin", "champion_hidden",
          "champion_connections", "run_seconds"]


def read_rows(path):
    """The rows of M1.csv, each whole and once; SystemExit(2) with a message naming the line otherwise (a cut
    row, a row written twice, a header of another file): a row is never counted, or dropped, silently."""
    with open(path, newline="") as f:
        text = f.read()
    if not text.endswith("\n"):
        raise SystemExit("%s: the last line is cut short (no newline): a run killed while its row was written; "
                         "delete that line and run scripts/study_m1.sh again (it plays that run again)" % path)
    lines = text.split("\n")[:-1]
    if not lines or lines[0].rstrip("\r").split(",") != FIELDS:
        raise SystemExit("%s:1: not an M1 table (expected the header %s)" % (path, ",".join(FIELDS)))
    rows, seen = [], {}
    for n, line in enumerate(lines[1:], start=2):
        line = line.rstrip("\r")
        vals = next(csv.reader([line])) if line else []
        if len(vals) != len(FIELDS):
            raise SystemExit("%s:%d: %d fields, expected %d: a cut or edited row (delete it and run "
                             "scripts/study_m1.sh again)" % (path, n, len(vals), len(FIELDS)))
        r = dict(zip(FIELDS, vals))
        try:
            for k in ("seed", "wins", "losses", "draws", "timeouts", "margin"):
                int(r[k])
        except ValueError:
            raise SystemExit("%s:%d: '%s' is not a whole number: a cut or edited row" % (path, n, r[k])) from None
        key = (r["cell"], r["opponent"], r["seed"])
        if key in seen:
            raise SystemExit("%s:%d: cell %s, opponent %s, seed %s a second time (first on line %d): a run counted "
                             "twice (two scripts writing one file?); keep one row" % ((path, n) + key + (seen[key],)))
        seen[key] = n
        rows.append(r)
    return rows


def main():
    rows = read_rows(sys.argv[1])
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
