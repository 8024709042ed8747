#!/usr/bin/env python3
"""The paper's robot duel coevolved from Python, games in C on every core; a figure of what it found.

Runs a duel_evolve configuration (its exact run: the checkpoint is duel_evolve's), then draws with matplotlib each
dominant strategy's wins against the built-in strategies (the ladder) into duel.png.

    python examples/python/robot_duel.py [--config configs/quick.ini] [--generations 30] [--out duel.png]
"""
from __future__ import annotations

import argparse
import pathlib

import neat_duel as nd

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main() -> int:
    ap = argparse.ArgumentParser(description="the robot duel, coevolved")
    ap.add_argument("--config", default=str(ROOT / "configs" / "quick.ini"))
    ap.add_argument("--generations", type=int, default=30)
    ap.add_argument("--set", action="append", default=[], help="KEY=VALUE, as duel_evolve's --set")
    ap.add_argument("--threads", type=int, default=0, help="0: every core")
    ap.add_argument("--out", default="duel.png")
    a = ap.parse_args()
    cfg = nd.DuelConfig.from_ini(a.config)
    for s in a.set:
        cfg.set(s)
    coev = cfg.coevolution()
    duel = nd.Duel(cfg, threads=a.threads)
    for rec in coev.run(duel, a.generations):
        print(f"generation {rec['generation']}: {rec['games']} games, champion {rec['champion']} "
              f"({rec[rec['champion']]['best_hidden']} hidden nodes), {rec['dominants']} dominants")
    levels = coev.dominants()
    builtins = [b for b in nd.duel_builtins() if b != "idle"]
    margin: dict[str, list[int]] = {b: [] for b in builtins}  # wins - losses of each dominant against each built-in, of 288 games
    for d in levels:
        net = d["genome"].network()
        for b in builtins:
            t = nd.duel_compare(net, b, config=cfg)
            margin[b].append(t["wins"] - t["losses"])
    import matplotlib
    import matplotlib.ticker

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 3.5))
    x = [d["level"] for d in levels]
    for b in builtins:
        ax.plot(x, margin[b], marker="o", label=b)
    ax.axhline(0, color="grey", lw=0.8)
    ax.set_xlabel("dominance level")
    ax.set_ylabel("wins - losses of 288 games")
    ax.set_title(f"{len(levels)} dominant strateg{'y' if len(levels) == 1 else 'ies'} against the built-in ones")
    ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(f"{a.out}: every dominant against {', '.join(builtins)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
