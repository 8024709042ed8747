"""ppo_ladder.py - the PPO self-play run's policies over its budget: every pool snapshot on the built-in ladder.

Each snapshot of a run of ppo_selfplay.py (OUT/pool/snap-GAMES.genome, the policy after GAMES games) and its final
policy play a 288-game comparison (neat_duel.duel_compare, what `duel_evolve play --games 288` plays) against each
built-in strategy and, with --against RUN, against that run's top dominant: the learning curve beside the
coevolution's (its ladder.csv). Needs only the neat_duel package (no PyTorch).

    python examples/rl/ppo_ladder.py OUT [--against runs/quick]

Writes OUT/ladder.csv (one row per policy: games, then wins and losses against each opponent) and prints it as a table.
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import re
import sys

import neat_duel as nd


def policies(out: str) -> list[tuple[int, str]]:
    """(games, genome file) of every snapshot in the pool's order, then the final policy when there is one."""
    with open(os.path.join(out, "state.json")) as f:
        state = json.load(f)
    found: list[tuple[int, str]] = []
    for name in state["pool"]:
        m = re.fullmatch(r"snap-(\d+)\.genome", name)
        if m is None:
            raise SystemExit(f"{out}/state.json: pool entry {name!r} is not a snapshot's name")
        if found and found[-1][0] == int(m.group(1)):
            continue  # the same file twice (a run's end could add its last snapshot again)
        found.append((int(m.group(1)), os.path.join(out, "pool", name)))
    final = os.path.join(out, "ppo-final.genome")
    if os.path.exists(final) and (not found or found[-1][0] != int(state["games"])):
        found.append((int(state["games"]), final))  # else the last snapshot is the final policy
    return found


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out", help="the run directory of ppo_selfplay.py")
    ap.add_argument("--against", default=None, help="a run directory whose top dominant each policy meets too")
    a = ap.parse_args(argv)
    opponents: list[tuple[str, nd.Network | str]] = [(b, b) for b in nd.duel_builtins()]
    if a.against:
        rd = nd.runs.RunDir(a.against)
        top = max(rd.dominants(), key=lambda d: d["level"])
        opponents.append((f"top-level-{top['level']}", rd.champion_network(top["generation"])))
    header = ["games", "policy"] + [f"{n}_{k}" for n, _ in opponents for k in ("wins", "losses")]
    rows = []
    for games, path in policies(a.out):
        net = nd.Genome.load(path).network()
        row: list[object] = [games, os.path.basename(path)]
        for _, opp in opponents:
            c = nd.duel_compare(net, opp)
            row += [c["wins"], c["losses"]]
        rows.append(row)
    tmp = os.path.join(a.out, "ladder.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)
    os.replace(tmp, os.path.join(a.out, "ladder.csv"))
    names = [n for n, _ in opponents]
    print(f"{'games':>9} " + " ".join(f"{n:>15}" for n in names))
    for row in rows:
        cells = [f"{row[2 + 2 * i]}:{row[3 + 2 * i]}" for i in range(len(names))]
        print(f"{row[0]:>9} " + " ".join(f"{c:>15}" for c in cells))
    print("wins:losses of 288 games (draws and timeouts are neither); " + os.path.join(a.out, "ladder.csv"),
          file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
