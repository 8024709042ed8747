#!/usr/bin/env python3
"""python_duel.py - a batch of robot-duel games from Python on 1 thread and on N: the speed-up of Duel.play_many.

The games run in C with the interpreter lock released; the figure is wall time (the threads' point), the median
of ROUNDS interleaved rounds, and the results are checked equal.

    python bench/python_duel.py [--rounds 5] [--threads 2] [--games 2000]
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import time

import neat_duel as nd


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--games", type=int, default=2000)
    a = ap.parse_args()
    pop = nd.Population(nd.Params(pop_size=32), seed=1)
    nets = [pop.genome(i).network() for i in range(32)]
    rivals: list[nd.Network | str] = [*nd.duel_builtins(), *nets[16:]]
    matches: list[tuple[nd.Network | str, nd.Network | str, int, bool]] = [
        (nets[k % 16], rivals[k % len(rivals)], k % 145 - 1, k % 2 == 0) for k in range(a.games)
    ]
    one, many = nd.Duel(threads=1), nd.Duel(threads=a.threads)
    want = one.play_many(matches)
    t1: list[float] = []
    tn: list[float] = []
    for _ in range(a.rounds):
        for duel, times in ((one, t1), (many, tn)):
            t = time.perf_counter()
            got = duel.play_many(matches)
            times.append(time.perf_counter() - t)
            assert got == want
    m1, mn = statistics.median(t1), statistics.median(tn)
    print(f"{a.games} duel games from Python: 1 thread {m1:.3f} s, {a.threads} threads {mn:.3f} s: "
          f"{m1 / mn:.2f}x (issue 41: at least 1.7 on 2 threads); the same results")
    print(f"  rounds, 1 thread: {', '.join(f'{x:.3f}' for x in t1)}; {a.threads}: {', '.join(f'{x:.3f}' for x in tn)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
