#!/usr/bin/env python3
"""Competitive coevolution of a game written in Python: race to ten (examples/coev_game/coev_game.c in C).

A counter starts at 0..3; the players take turns adding 1 or 2, and whoever brings it to 10 wins. The position
with r still to go is lost for the player to move when r is a multiple of 3, so there is a best play to discover.
A network sees r in binary (4 inputs) and takes 2 when its output is at least 0.5.

    python examples/python/race_to_ten.py [--generations 40]
"""
from __future__ import annotations

import argparse

import neat_duel as nd

GOAL = 10


def move(net: nd.Network, r: int) -> int:
    net.reset()
    return 2 if net.step([float(r >> k & 1) for k in range(4)])[0] >= 0.5 else 1


def play(a: nd.Network, b: nd.Network, config: int, a_first: bool, seed: int) -> int:
    """The coevolution's game: 1 when a wins, -1 when b does. config -1 (training) starts from seed's draw."""
    start = (seed % 4) if config < 0 else config % 4
    counter, a_turn = start, a_first
    while True:
        counter += move(a if a_turn else b, GOAL - counter)
        if counter >= GOAL:
            return 1 if a_turn else -1
        a_turn = not a_turn


def perfect_score(net: nd.Network) -> int:
    """Positions r = 1..10 where the network plays the winning move (the other move is a loss)."""
    return sum(1 for r in range(1, GOAL + 1) if r % 3 != 0 and move(net, r) == r % 3)


def main() -> int:
    ap = argparse.ArgumentParser(description="race to ten, coevolved")
    ap.add_argument("--generations", type=int, default=40)
    a = ap.parse_args()
    params = nd.Params(pop_size=40, n_inputs=4, n_outputs=1, pop_stagnation=0)
    coev = nd.Coevolution(params, seed=1, compare_configs=4)
    for _ in range(a.generations):
        rec = coev.step(play)  # one generation at a time: the champion below is this generation's
        if rec["new_dominant"]:
            champ = coev.champion
            assert champ is not None
            print(f"generation {rec['generation']}: dominant {rec['dominants']} (population {rec['champion']}), "
                  f"the winning move in {perfect_score(champ.network())} of 7 winnable positions")
    top = coev.dominants()[-1]
    print(f"{len(coev.dominants())} dominant strategies; the top one, from generation {top['generation']}, plays the "
          f"winning move in {perfect_score(top['genome'].network())} of 7 winnable positions")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
