#!/usr/bin/env python3
"""decode_log.py - a duel recorded by `duel_evolve play --lcm-log` read with the PyPI lcm package and the
types `lcm-gen -p` generates from lcmtypes/ (the README's example); checks the step count and the final event
against what `play` printed.

usage: PYTHONPATH=build/lcmgen/python decode_log.py GAME.lcm PLAY_OUTPUT.txt
"""
import re
import sys

import lcm
from duel import motor_t, net_t, sense_t, state_t

STEPS = {net_t.BUILTIN: "builtin", net_t.SYNC: "sync", net_t.PROPAGATE: "propagate"}
OUTCOMES = {state_t.WEST_WINS: "west wins", state_t.EAST_WINS: "east wins", state_t.DRAW: "draw",
            state_t.TIMEOUT: "timeout"}


def read_game(path):
    """The state messages, the sensor and motor message counts and the net messages by side of the game in the
    log at path."""
    states, senses, motors, nets = [], 0, 0, {}
    for event in lcm.EventLog(path, "r"):
        if event.channel == "DUEL_STATE":
            msg = state_t.decode(event.data)  # raises ValueError on another fingerprint
            version = msg.version
        elif event.channel in ("DUEL_SENSE_WEST", "DUEL_SENSE_EAST"):
            msg = sense_t.decode(event.data)
            version, senses = msg.version, senses + 1
        elif event.channel in ("DUEL_MOTOR_WEST", "DUEL_MOTOR_EAST"):
            msg = motor_t.decode(event.data)
            version, motors = msg.version, motors + (msg.step >= 0)  # step -1: a controller's hello
        elif event.channel == "DUEL_NET":
            msg = net_t.decode(event.data)
            version = msg.version
            nets.setdefault(msg.side, []).append(msg)
        else:
            continue
        if version != type(msg).VERSION:
            sys.exit(f"{path}: {event.channel}: format version {version}, this reader knows {type(msg).VERSION}")
        if event.channel == "DUEL_STATE":
            states.append(msg)
    return states, senses, motors, nets


def main():
    log_path, play_path = sys.argv[1], sys.argv[2]
    states, senses, motors, nets = read_game(log_path)
    final = states[-1]
    with open(play_path) as f:
        play = f.read().splitlines()
    m = re.match(r"(.*) \(.*\) after (\d+) steps$", play[1])
    outcome, steps = m.group(1), int(m.group(2))
    steps_ab = re.match(r"world .*; network step: A (\S+), B (\S+)$", play[3]).groups()
    energy = re.match(r"energy: west (\S+), east (\S+); food eaten: west (\d+), east (\d+)$", play[2]).groups()

    checks = [
        ("state messages", len(states), steps + 1),
        ("sensor messages", senses, 2 * steps),
        ("motor messages", motors, 2 * steps),
        ("steps", final.step, steps),
        ("final event", OUTCOMES.get(final.outcome), outcome),
        ("steps before it ran", [s.outcome for s in states[:-1]], [state_t.RUNNING] * steps),
        ("west energy", f"{final.energy[0] / 65536:.6f}", energy[0]),
        ("east energy", f"{final.energy[1] / 65536:.6f}", energy[1]),
        ("food eaten", [final.eaten[0], final.eaten[1]], [int(energy[2]), int(energy[3])]),
        ("controllers", f"west {final.controller[0]}, east {final.controller[1]}", play[0].split(", ", 1)[1]),
        ("net messages per side", [len(nets.get(0, [])), len(nets.get(1, []))], [1, 1]),
        ("net names", [n[0].controller for _, n in sorted(nets.items())], list(final.controller)),
        ("net steps", sorted(STEPS.get(n[0].step) for n in nets.values()), sorted(steps_ab)),
    ]
    bad = [f"{what}: log {got!r}, play {want!r}" for what, got, want in checks if got != want]
    if bad:
        sys.exit(f"{log_path}: " + "; ".join(bad))
    print(f"{log_path}: {steps} steps, {OUTCOMES[final.outcome]}, final energies {energy[0]} / {energy[1]}: as play said")


if __name__ == "__main__":
    main()
