#!/usr/bin/env python3
"""python_envs.py - agent-steps a second of the duel environments (neat_duel.envs): the C batch and Python's loop.

An agent-step is one robot's step (a game step is two). Measured, each the median of ROUNDS rounds, with wall time
and CPU time (user + sys of the whole process, every thread):

- ``DuelBatch.step``: K games in one C call, actions (K, 2, 3) drawn in numpy before the clock starts; the games are
  reset every 750 steps and only the games still running are counted;
- ``DuelVecEnv.step``: the same through the vectorised environment (a game that ends starts again at once, so every
  game steps every call);
- ``DuelEnv.step``: the PettingZoo loop, one game, actions as dicts of pre-drawn arrays;
- ``DuelVsEnv.step``: one learner against a built-in strategy (its action computed in C each step).

    python bench/python_envs.py [--games 256] [--threads 1] [--rounds 5] [--steps 3000]
"""
from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time
from typing import Callable

import numpy as np

from neat_duel.envs import MAX_STEPS, DuelBatch, DuelEnv, DuelVecEnv, DuelVsEnv


def timed(fn: Callable[[], int]) -> tuple[int, float, float]:
    """(agent-steps, wall seconds, CPU seconds) of one call of fn, which returns the agent-steps it played."""
    c0, t0 = time.process_time(), time.perf_counter()
    n = fn()
    return n, time.perf_counter() - t0, time.process_time() - c0


def main() -> int:
    doc = __doc__ or ""
    ap = argparse.ArgumentParser(description=doc.split("\n")[0])
    ap.add_argument("--games", type=int, default=256, help="K, the games of the C batch (default 256)")
    ap.add_argument("--threads", type=int, default=1, help="threads of the C batch (default 1)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--steps", type=int, default=3000, help="calls of step a round for the C batch")
    ap.add_argument("--python-steps", type=int, default=20000, help="steps a round for the one-game loops")
    a = ap.parse_args()
    k: int = a.games
    steps: int = a.steps
    py_steps: int = a.python_steps
    threads: int = a.threads
    rng = np.random.default_rng(1)
    acts = [rng.random((k, 2, 3), dtype=np.float32) for _ in range(64)]
    one = [rng.random((2, 3), dtype=np.float32) for _ in range(256)]
    dicts = [{"west": x[0], "east": x[1]} for x in one]

    batch = DuelBatch(k, threads=threads)
    everyone = np.arange(k, dtype=np.int64)
    training = np.full(k, -1, dtype=np.int64)

    def run_batch() -> int:
        n = 0
        running = k
        for i in range(steps):
            if i % MAX_STEPS == 0:
                batch.reset(everyone, training)
                running = k
            n += 2 * running
            _, _, term, trunc = batch.step(acts[i % 64])
            running = k - int(np.count_nonzero(term | trunc))  # the games that go on
        return n

    vec = DuelVecEnv(k, layouts="comparison", threads=threads)
    vec.reset(seed=1)

    def run_vec() -> int:
        for i in range(steps):
            vec.step(acts[i % 64])
        return 2 * k * steps

    env = DuelEnv(layouts="comparison")
    env.reset(seed=1)

    def run_env() -> int:
        n = 0
        for i in range(py_steps):
            if not env.agents:
                env.reset()
            env.step(dicts[i % 256])
            n += 2
        return n

    vs = DuelVsEnv("forager-hunter", layouts="comparison")
    vs.reset(seed=1)

    def run_vs() -> int:
        over = False
        for i in range(py_steps):
            if over:
                vs.reset()
            _, _, term, trunc, _ = vs.step(one[i % 256][0])
            over = term or trunc
        return 2 * py_steps

    methods: list[tuple[str, Callable[[], int]]] = [
        (f"DuelBatch.step, K = {k}, {threads} thread(s)", run_batch),
        (f"DuelVecEnv.step, K = {k}, {threads} thread(s), autoreset", run_vec),
        ("DuelEnv.step (PettingZoo, dicts), 1 game", run_env),
        ("DuelVsEnv.step (Gymnasium) against forager-hunter, 1 game", run_vs),
    ]
    load0 = os.getloadavg()
    results: dict[str, list[tuple[int, float, float]]] = {name: [] for name, _ in methods}
    for _ in range(a.rounds):
        for name, fn in methods:
            results[name].append(timed(fn))
    load1 = os.getloadavg()
    print(f"load average {load0[0]:.2f} {load0[1]:.2f} {load0[2]:.2f} before, "
          f"{load1[0]:.2f} {load1[1]:.2f} {load1[2]:.2f} after; {os.cpu_count()} cores; "
          f"median of {a.rounds} rounds, methods interleaved")
    summary = {}
    for name, rs in results.items():
        wall = statistics.median(n / w for n, w, _ in rs)
        cpu = statistics.median(n / c for n, _, c in rs if c > 0)
        print(f"{name}: {wall / 1e6:.3f} M agent-steps/s wall, {cpu / 1e6:.3f} M per CPU second "
              f"(rounds, wall: {', '.join(f'{n / w / 1e6:.2f}' for n, w, _ in rs)} M)")
        summary[name] = {"wall": round(wall), "cpu": round(cpu)}
    print(json.dumps({"load": [round(x, 2) for x in load0 + load1], "agent_steps_per_s": summary}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
