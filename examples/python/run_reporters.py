#!/usr/bin/env python3
"""A duel_evolve run directory from Python, a generation at a time: a reporter of one's own, the statistics as
rows for pandas, and a stop on a condition of one's own; the run stays resumable (duel_evolve resume, runs.resume).

    python examples/python/run_reporters.py [--config configs/quick.ini] [--out runs/reporters] [--levels 6]
"""
from __future__ import annotations

import argparse
import pathlib
import sys

from neat_duel import runs

ROOT = pathlib.Path(__file__).resolve().parents[2]


class NewDominants(runs.Reporter):
    """Says each new dominant as it is found, with its size."""

    def generation(self, run: runs.Run, record: runs.Generation) -> None:
        if record.new_dominant:
            print(f"generation {record.generation}: dominant {record.dominants} (population {record.champion}, "
                  f"{record.dominant_hidden} hidden nodes, {record.dominant_connections} connections)")


def main() -> int:
    ap = argparse.ArgumentParser(description="a run with reporters and an early stop")
    ap.add_argument("--config", default=str(ROOT / "configs" / "quick.ini"))
    ap.add_argument("--out", default="runs/reporters")
    ap.add_argument("--levels", type=int, default=6, help="stop once the dominance tournament has this many levels")
    ap.add_argument("--set", action="append", default=[], help="KEY=VALUE, as duel_evolve's --set")
    ap.add_argument("--threads", type=int, default=0, help="0: every core")
    a = ap.parse_args()
    stats = runs.StatisticsReporter()
    with runs.Run.start(a.config, a.out, set=a.set, threads=a.threads,
                        reporters=[NewDominants(), stats, runs.Checkpointer(10, f"{a.out}-gen-")]) as run:
        for g in run.generations():
            if g.dominants >= a.levels:
                print(f"{a.levels} levels at generation {g.generation}: stopped, {run.total - run.generation} "
                      f"generations left (resume with: duel_evolve resume {a.out})")
                break
    rows = stats.rows()  # pandas.DataFrame(rows) if pandas is there
    best = max(rows, key=lambda r: (r["best_fitness"], -r["generation"]))
    print(f"{len(rows)} rows; the best host: {best['best_fitness']} wins, population {best['population']}, "
          f"generation {best['generation']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
