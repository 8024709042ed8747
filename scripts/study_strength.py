#!/usr/bin/env python3
"""study_strength.py LADDER.csv... - docs/study.md criterion (b): over the dominants of a cell's complexifying runs
(each run's `duel_evolve ladder RUN --against forager-hunter --csv FILE`), the Spearman correlation between a
dominant's level divided by its run's levels and its wins - losses against forager-hunter: pooled, with the two-sided
p-value of a permutation test (20,000 shuffles, seeded), and within each run. Also criterion (a)'s second half: the
top dominant of each run wins more than it loses."""
import csv
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from neat_stats import ranks  # noqa: E402


def spearman(x, y):
    rx, ry = ranks(x), ranks(y)
    n = len(x)
    mx, my = sum(rx) / n, sum(ry) / n
    sxy = sum((a - mx) * (b - my) for a, b in zip(rx, ry))
    sxx = sum((a - mx) ** 2 for a in rx)
    syy = sum((b - my) ** 2 for b in ry)
    return sxy / (sxx * syy) ** 0.5 if sxx > 0 and syy > 0 else 0.0


def main():
    xs, ys, per_run, tops = [], [], [], []
    for path in sys.argv[1:]:
        rows = list(csv.DictReader(open(path)))
        n = len(rows)
        x = [int(r["level"]) / n for r in rows]
        y = [int(r["forager-hunter_wins"]) - int(r["forager-hunter_losses"]) for r in rows]
        xs += x
        ys += y
        per_run.append(spearman(x, y))
        tops.append((int(rows[-1]["forager-hunter_wins"]), int(rows[-1]["forager-hunter_losses"])))
    rho = spearman(xs, ys)
    rng = random.Random(39)
    extreme = 0
    shuffled = list(ys)
    for _ in range(20000):
        rng.shuffle(shuffled)
        extreme += abs(spearman(xs, shuffled)) >= abs(rho) - 1e-12
    print("dominants: %d in %d runs" % (len(xs), len(per_run)))
    print("pooled Spearman rho (level / levels, wins - losses against forager-hunter): %+.3f, permutation p = %.4f"
          % (rho, (extreme + 1) / 20001.0))
    print("within each run: " + " ".join("%+.2f" % r for r in per_run) + " (%d of %d positive)"
          % (sum(r > 0 for r in per_run), len(per_run)))
    print("top dominants against forager-hunter: " + " ".join("%d:%d" % t for t in tops) +
          " (%d of %d win more than they lose)" % (sum(w > l for w, l in tops), len(tops)))


if __name__ == "__main__":
    main()
