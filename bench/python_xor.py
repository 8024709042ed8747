#!/usr/bin/env python3
"""python_xor.py - XOR evolved from Python: neat_duel (per genome, and batched) beside neat-python 2.0 and the C loop.

Every figure is CPU time (user + sys) per evaluation, reproduction included, measured in this one process (the C
loop: neat_bench xor as a child, its CPU time), the methods interleaved, each repeated ROUNDS times; the median is
reported, with every round. Also: Network.step with 39 connections (the duel's 12 inputs, 3 outputs, minimal).

    python bench/python_xor.py [--rounds 5] [--neat-bench build/bin/neat_bench] [--json FILE]

Needs neat_duel importable (pip install ., or PYTHONPATH=build/python) and neat-python (pip install neat-python).
"""
from __future__ import annotations

import os

# numpy's BLAS threads, started at its import, can spin, and their CPU time counts as this process's: on 2026-12-06
# a script timing Population.run after importing numpy read 3.5 us an evaluation with them, 1.75 us with one
# thread. Nothing measured here uses BLAS, so it gets one thread.
for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse
import json
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time
import timeit
from typing import Any, Callable

import numpy as np

import neat_duel as nd

ROOT = pathlib.Path(__file__).resolve().parents[1]
XOR = ((0.0, 0.0, 0.0), (0.0, 1.0, 1.0), (1.0, 0.0, 1.0), (1.0, 1.0, 0.0))
GENERATIONS = 30  # a fixed budget for every method: the same work whatever is solved when

# neat-python's XOR example configuration (its examples/xor/config-feedforward), population 150 as ours
NEAT_PYTHON_CONFIG = """
[NEAT]
fitness_criterion     = max
fitness_threshold     = 1000
pop_size              = 150
reset_on_extinction   = False
no_fitness_termination = True

[DefaultGenome]
activation_default      = sigmoid
activation_mutate_rate  = 0.0
activation_options      = sigmoid
aggregation_default     = sum
aggregation_mutate_rate = 0.0
aggregation_options     = sum
bias_init_mean          = 0.0
bias_init_stdev         = 1.0
bias_max_value          = 30.0
bias_min_value          = -30.0
bias_mutate_power       = 0.5
bias_mutate_rate        = 0.7
bias_replace_rate       = 0.1
compatibility_disjoint_coefficient = 1.0
compatibility_weight_coefficient   = 0.5
conn_add_prob           = 0.5
conn_delete_prob        = 0.5
enabled_default         = True
enabled_mutate_rate     = 0.01
feed_forward            = True
initial_connection      = full_direct
node_add_prob           = 0.2
node_delete_prob        = 0.2
num_hidden              = 0
num_inputs              = 2
num_outputs             = 1
response_init_mean      = 1.0
response_init_stdev     = 0.0
response_max_value      = 30.0
response_min_value      = -30.0
response_mutate_power   = 0.0
response_mutate_rate    = 0.0
response_replace_rate   = 0.0
weight_init_mean        = 0.0
weight_init_stdev       = 1.0
weight_max_value        = 30
weight_min_value        = -30
weight_mutate_power     = 0.5
weight_mutate_rate      = 0.8
weight_replace_rate     = 0.1

[DefaultSpeciesSet]
compatibility_threshold = 3.0

[DefaultStagnation]
species_fitness_func = max
max_stagnation       = 20
species_elitism      = 2

[DefaultReproduction]
elitism            = 2
survival_threshold = 0.2
"""


def cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def neat_python_xor(seed: int) -> tuple[float, int]:
    """neat-python 2.0, its XOR example's evaluation: (CPU seconds, evaluations)."""
    import neat  # type: ignore[import-untyped]

    with tempfile.NamedTemporaryFile("w", suffix=".ini", delete=False) as f:
        f.write(NEAT_PYTHON_CONFIG.replace("no_fitness_termination = True", f"no_fitness_termination = True\nseed = {seed}"))
    try:
        config = neat.Config(neat.DefaultGenome, neat.DefaultReproduction, neat.DefaultSpeciesSet,
                             neat.DefaultStagnation, f.name)
    finally:
        os.unlink(f.name)
    evals = 0

    def eval_genomes(genomes: Any, config: Any) -> None:
        nonlocal evals
        for _, genome in genomes:
            genome.fitness = 4.0
            net = neat.nn.FeedForwardNetwork.create(genome, config)
            for a, b, y in XOR:
                output = net.activate((a, b))
                genome.fitness -= (output[0] - y) ** 2
            evals += 1

    p = neat.Population(config)
    t = cpu()
    p.run(eval_genomes, GENERATIONS)
    return cpu() - t, evals


def xor_fitness(g: nd.Genome) -> float:
    net = g.network()
    err = 0.0
    for a, b, y in XOR:
        net.reset()
        err += abs(net.settle([a, b])[0] - y)
    return (4.0 - err) ** 2


def neat_duel_xor(seed: int) -> tuple[float, int]:
    """neat_duel with a Python fitness function per genome (Population.run)."""
    pop = nd.Population(nd.Params.from_ini(str(ROOT / "bench" / "xor.ini")), seed=seed)
    t = cpu()
    recs = pop.run(xor_fitness, GENERATIONS)
    return cpu() - t, int(recs[-1]["evaluations"])


def neat_duel_batched(seed: int) -> tuple[float, int]:
    """neat_duel's batched path: a generation's networks stepped together in C on numpy arrays."""
    pop = nd.Population(nd.Params.from_ini(str(ROOT / "bench" / "xor.ini")), seed=seed)
    inputs = [np.array([a, b]) for a, b, _ in XOR]
    t = cpu()
    for _ in range(GENERATIONS):
        nets = pop.networks()
        err = np.zeros(len(pop))
        for x, (_, _, y) in zip(inputs, XOR):
            nets.reset()
            err += np.abs(nets.settle(x)[:, 0] - y)
        pop.set_fitnesses((4.0 - err) ** 2)
        pop.epoch()
    return cpu() - t, GENERATIONS * len(pop)


def c_loop(neat_bench: str) -> tuple[float, int]:
    """neat_bench xor, one thread, 100 runs (each until solved): its CPU time and evaluations."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([neat_bench, "xor", "--runs", "100", "--threads", "1", "--quiet"], capture_output=True,
                       text=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    res = json.loads(r.stdout.strip().splitlines()[-1])
    evals = int(round(res["mean_evaluations"] * (res["runs"] - res["failures"])))
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), evals


def step_cost() -> float:
    """Network.step from Python, 12 inputs, 3 outputs, 39 connections: CPU microseconds a call."""
    net = nd.Population(nd.Params(pop_size=2), seed=1).genome(0).network()
    assert net.n_conns == 39
    x = [0.1] * 12
    n = 200000
    t = cpu()
    timeit.timeit(lambda: net.step(x), number=n)  # the lambda's own call is counted: an upper bound
    return (cpu() - t) / n * 1e6


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--neat-bench", default=str(ROOT / "build" / "bin" / "neat_bench"))
    ap.add_argument("--json", help="write the figures here too")
    a = ap.parse_args()
    methods: dict[str, Callable[[int], tuple[float, int]]] = {
        "neat-python": neat_python_xor,
        "neat_duel per genome": neat_duel_xor,
        "neat_duel batched": neat_duel_batched,
        "C loop (neat_bench)": lambda seed: c_loop(a.neat_bench),
    }
    per_eval: dict[str, list[float]] = {k: [] for k in methods}
    for r in range(a.rounds):
        for name, fn in methods.items():
            secs, evals = fn(r + 1)
            per_eval[name].append(secs / evals * 1e6)
    med = {k: statistics.median(v) for k, v in per_eval.items()}
    step = [step_cost() for _ in range(a.rounds)]
    print(f"XOR, CPU time per evaluation (reproduction included), median of {a.rounds} interleaved rounds:")
    for k, v in per_eval.items():
        print(f"  {k:22s} {med[k]:8.2f} us   rounds: {', '.join(f'{x:.2f}' for x in v)}")
    c = med["C loop (neat_bench)"]
    npy = med["neat-python"]

    def paired(num: str, den: str) -> str:
        # the ratio within each round (the methods ran back to back in it, under the same load), then the median
        r = [a / b for a, b in zip(per_eval[num], per_eval[den])]
        return f"{statistics.median(r):.1f}x, rounds {min(r):.1f}-{max(r):.1f}"

    print("  ratios of the medians, and (in brackets) the median of each round's own ratio:")
    print(f"  neat-python / per genome: {npy / med['neat_duel per genome']:.1f}x "
          f"({paired('neat-python', 'neat_duel per genome')}; issue 41: at least 20)")
    print(f"  neat-python / batched:    {npy / med['neat_duel batched']:.1f}x "
          f"({paired('neat-python', 'neat_duel batched')}; at least 30)")
    print(f"  batched / C loop:         {med['neat_duel batched'] / c:.2f}x (at most 2)")
    print(f"  neat-python / C loop:     {npy / c:.1f}x ({paired('neat-python', 'C loop (neat_bench)')})")
    print(f"Network.step, 39 connections, from Python: {statistics.median(step):.3f} us a call "
          f"(rounds: {', '.join(f'{x:.3f}' for x in step)}; at most 0.7)")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"per_evaluation_us": per_eval, "median_us": med, "step_us": step,
                       "python": sys.version.split()[0], "when": time.strftime("%Y-%m-%d %H:%M")}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
