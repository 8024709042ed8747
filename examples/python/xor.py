#!/usr/bin/env python3
"""XOR evolved by NEAT from Python (the 2002 paper's first test): a fitness function per genome.

    python examples/python/xor.py [--seed 1] [--out DIR]

Prints a line per generation and writes the champion's genome file, blob and Graphviz picture into DIR.
"""
from __future__ import annotations

import argparse
import pathlib
from typing import Any

import neat_duel as nd

CASES = [((0.0, 0.0), 0.0), ((0.0, 1.0), 1.0), ((1.0, 0.0), 1.0), ((1.0, 1.0), 0.0)]


def fitness(genome: nd.Genome) -> float:
    """(4 - total error)^2, as the paper: 16 for a perfect network."""
    net = genome.network()
    error = 0.0
    for inputs, target in CASES:
        net.reset()
        error += abs(net.settle(list(inputs))[0] - target)
    return (4.0 - error) ** 2


def solved(genome: nd.Genome) -> bool:
    net = genome.network()
    right = 0
    for inputs, target in CASES:
        net.reset()
        right += (net.settle(list(inputs))[0] >= 0.5) == (target == 1.0)
    return right == 4


def main() -> int:
    ap = argparse.ArgumentParser(description="XOR by NEAT")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default="xor-out")
    a = ap.parse_args()
    params = nd.Params(pop_size=150, n_inputs=2, n_outputs=1, allow_recurrent=False, c3=0.4,
                       target_species=20, add_conn_prob=0.2)
    pop = nd.Population(params, seed=a.seed)

    def show(record: dict[str, Any]) -> bool:
        print("generation {generation}: best {best_fitness:.3f}, mean {mean_fitness:.3f}, {species} species, "
              "best network {best_hidden} hidden / {best_connections} connections".format(**record))
        best = pop.last_best
        return best is not None and solved(best)

    records = pop.run(fitness, generations=200, until=show)
    best = pop.last_best
    assert best is not None
    out = pathlib.Path(a.out)
    out.mkdir(exist_ok=True)
    best.save(str(out / "champion.genome"))
    best.network().save(str(out / "champion.blob"))
    (out / "champion.dot").write_text(best.to_dot())
    print(f"{'solved' if solved(best) else 'not solved'} after {records[-1]['evaluations']} evaluations; "
          f"champion in {out}/ (champion.genome, .blob, .dot)")
    return 0 if solved(best) else 1


if __name__ == "__main__":
    raise SystemExit(main())
