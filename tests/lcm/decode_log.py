#!/usr/bin/env python3
"""decode_log.py - a duel recorded by `duel_evolve play --lcm-log` read with the PyPI lcm package and the
types `lcm-gen -p` generates from lcmtypes/ (the README's example); checks the step count and the final event
against what `play` printed.

usage: PYTHONPATH=build/lcmgen/python decode_log.py GAME.lcm PLAY_OUTPUT.txt
"""
import re
import sys

import lcm
from duel import motor_t, sense_t, state_t

OUTCOMES = {state_t.WEST_WINS: "west wins", state_t.EAST_WINS: "east wins", state_t.DRAW: "draw",
            state_t.TIMEOUT: "timeout"}


def read_game(path):
    """The state messages and the sensor and motor message counts of the game in the log at path."""
    states, senses, motors = [], 0, 0
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
        else:
            continue
        if version != type(msg).VERSION:
            sys.exit(f"{path}: {event.channel}: format version {version}, this reader knows {type(msg).VERSION}")
        if event.channel == "DUEL_STATE":
            states.append(msg)
    return states, senses, motors


def main():
    log_path, play_path = sys.argv[1], sys.argv[2]
    states, senses, motors = read_game(log_path)
    final = states[-1]
    with open(play_path) as f:
        play = f.read().splitlines()
    m = re.match(r"(.*) \(.*\) after (\d+) steps$", play[1])
    outcome, steps = m.group(1), int(m.group(2))
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
    ]
    bad = [f"{what}: log {got!r}, play {want!r}" for what, got, want in checks if got != want]
    if bad:
        sys.exit(f"{log_path}: " + "; ".join(bad))
    print(f"{log_path}: {steps} steps, {OUTCOMES[final.outcome]}, final energies {energy[0]} / {energy[1]}: as play said")


if __name__ == "__main__":
    main()
