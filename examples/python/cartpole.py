#!/usr/bin/env python3
"""CartPole (Gymnasium) balanced by a network NEAT evolves: the Gymnasium helper, seeded episodes.

    pip install .[gym]; python examples/python/cartpole.py [--generations 30] [--seed 1]
"""
from __future__ import annotations

import argparse
from typing import Any

import neat_duel as nd
from neat_duel import gym


def main() -> int:
    ap = argparse.ArgumentParser(description="CartPole by NEAT")
    ap.add_argument("--generations", type=int, default=30)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    # 4 observations (cart position and velocity, pole angle and velocity), 2 actions (push left, push right)
    params = nd.Params(pop_size=60, n_inputs=4, n_outputs=2, allow_recurrent=False)
    pop = nd.Population(params, seed=a.seed)
    train = gym.fitness("CartPole-v1", episodes=3, seed=0)

    def show(r: dict[str, Any]) -> bool:
        print(f"generation {r['generation']}: best return {r['best_fitness']:.1f}, mean {r['mean_fitness']:.1f}")
        return bool(r["best_fitness"] >= 500.0)

    pop.run(train, a.generations, until=show)
    best = pop.last_best
    assert best is not None
    test = gym.evaluate(best, "CartPole-v1", episodes=10, seed=1000)  # episodes it never saw
    print(f"the champion's mean return on 10 new episodes: {test:.1f} (500 is the most)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
