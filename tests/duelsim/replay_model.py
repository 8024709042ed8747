#!/usr/bin/env python3
"""replay_model.py WORLD.ini FOOD TRACE.csv - an independent model of the duel's rules in double precision,
written from docs/duel-world.md alone (none of the simulator's code or arithmetic), replaying a trace
(`duel_evolve play ... --world WORLD.ini --food FOOD --trace TRACE.csv`) step by step: at every step the 13
inputs of both robots computed from the traced state, and the state after the move computed from the traced
state and outputs, must agree with the trace within the fixed point's error (docs/duelsim.md). The world is
the [world] section of WORLD.ini as `duel_evolve config --dump` writes it (every key). Exit 0 and a summary
line when every step agrees; 1 and the first disagreement otherwise."""
import configparser
import csv
import math
import sys

TAU = 2.0 * math.pi


def pairs(text):
    if text.strip() == "none":
        return []
    return [tuple(float(v) for v in p.split()) for p in text.split(",")]


def world_of(path):
    cp = configparser.ConfigParser(comment_prefixes=(";", "#"), inline_comment_prefixes=None)
    cp.read(path)
    w = cp["world"]
    start = [[float(v) for v in w["start_west"].split()], [float(v) for v in w["start_east"].split()]]
    return {
        "radius": float(w["radius"]), "start": start,
        "start_energy": float(w["start_energy"]), "food_energy": float(w["food_energy"]),
        "eat": float(w["eat_dist"]), "share": float(w["share_dist"]),
        "train": pairs(w["train_food"]), "cand": pairs(w["candidates"]),
        "food_range": float(w["food_range"]), "robot_range": float(w["robot_range"]),
        "energy_scale": float(w["energy_scale"]), "wall_range": float(w["wall_range"]),
    }


def food_of(w, config):
    """docs/duel-world.md, Food: the training items, and on comparison configuration K item n at candidate
    K div 12 and item n + 1 at the mirror of candidate K mod 12."""
    items = list(w["train"])
    if config >= 0:
        items.append(w["cand"][config // 12])
        x, y = w["cand"][config % 12]
        items.append((600.0 - x, y))
    return items


def sector(bearing_deg):
    """docs/duel-world.md: sector floor((b + 36) / 72) mod 5; also how far b is from a boundary."""
    b = bearing_deg % 360.0
    s = int(math.floor((b + 36.0) / 72.0)) % 5
    edge = min(abs(((b + 36.0) % 72.0)), abs(72.0 - ((b + 36.0) % 72.0)))
    return s, edge


def reading(d, rng):
    return max(0.0, 1.0 - d / rng)


def sense(w, me, other, items, mask):
    """The 13 inputs of robot me (x, y, heading rad, energy), or None where a boundary makes the sector
    ambiguous at this precision (then the rangefinders are not compared)."""
    x, y, h, e = me
    inp = [1.0] + [0.0] * 12
    ambiguous = False
    nearest = [None] * 5
    for i, (fx, fy) in enumerate(items):
        if not (mask >> i) & 1:
            continue
        dx, dy = fx - x, fy - y
        d = math.hypot(dx, dy)
        if d == 0.0:
            continue
        s, edge = sector(math.degrees(math.atan2(dy, dx) - h))
        ambiguous |= edge < 1e-3
        if nearest[s] is None or d < nearest[s]:
            nearest[s] = d
    for s in range(5):
        if nearest[s] is not None:
            inp[1 + s] = reading(nearest[s], w["food_range"])
    ox, oy = other[0], other[1]
    d = math.hypot(ox - x, oy - y)
    if d > 0.0:
        s, edge = sector(math.degrees(math.atan2(oy - y, ox - x) - h))
        ambiguous |= edge < 1e-3
        inp[6 + s] = reading(d, w["robot_range"])
    inp[11] = max(-1.0, min(1.0, (e - other[3]) / w["energy_scale"]))
    # wall: distance along the heading to the first edge of the board
    c, sn = math.cos(h), math.sin(h)
    dist = []
    if c > 1e-12:
        dist.append((600.0 - x) / c)
    if c < -1e-12:
        dist.append(-x / c)
    if sn > 1e-12:
        dist.append((600.0 - y) / sn)
    if sn < -1e-12:
        dist.append(-y / sn)
    inp[12] = reading(min(dist), w["wall_range"])
    return inp, ambiguous


def move(w, st, out):
    """docs/duel-world.md, Motion: half turn, forward 1.33 f, half turn, clamp to [radius, 600 - radius];
    energy |theta| + 1.33 f."""
    x, y, h, e = st
    l, r, f = (max(0.0, v) for v in out)
    theta = 0.24 * (l - r)
    h += theta / 2.0
    x = min(max(x + 1.33 * f * math.cos(h), w["radius"]), 600.0 - w["radius"])
    y = min(max(y + 1.33 * f * math.sin(h), w["radius"]), 600.0 - w["radius"])
    h += theta / 2.0
    return [x, y, h, e - abs(theta) - 1.33 * f]


def angle_diff(a, b):
    return abs((a - b + math.pi) % TAU - math.pi)


def main():
    w = world_of(sys.argv[1])
    config = int(sys.argv[2])
    rows = list(csv.DictReader(open(sys.argv[3])))
    items = food_of(w, config)
    sides = ("west", "east")
    # the start is the rules' (positions, headings, energies)
    for k, side in enumerate(sides):
        sx, sy, sh = w["start"][k]
        r0 = rows[0]
        if (abs(float(r0[side + "_x"]) - sx) > 1e-5 or abs(float(r0[side + "_y"]) - sy) > 1e-5
                or angle_diff(float(r0[side + "_heading"]), math.radians(sh)) > 1e-6
                or abs(float(r0[side + "_energy"]) - w["start_energy"]) > 1e-5):
            sys.exit(f"step 0: {side} does not start where the rules say")
    compared = skipped = eats = 0
    for t, row in enumerate(rows):
        st = [[float(row[s + "_" + k]) for k in ("x", "y", "heading", "energy")] for s in sides]
        mask = int(row["food_mask"])
        for k, side in enumerate(sides):
            want, amb = sense(w, st[k], st[1 - k], items, mask)
            got = [float(row[f"{side}_in{i}"]) for i in range(13)]
            for i in range(13):
                if amb and 1 <= i <= 10:
                    continue
                # readings are Q15 (1/32768), positions 1/65536 and printed to 1e-6
                if abs(got[i] - want[i]) > 2.5e-4:
                    sys.exit(f"step {t}: {side} input {i} is {got[i]:.6f}, the rules give {want[i]:.6f}")
            compared += 1
            skipped += amb
        if t + 1 == len(rows):
            break
        nxt = rows[t + 1]
        moved = [move(w, st[k], [float(row[f"{s}_out{i}"]) for i in range(3)]) for k, s in enumerate(sides)]
        # eating: the items that left the board, each to the nearer robot within eat_dist (shared when the
        # distances are within share_dist of each other)
        gone = mask & ~int(nxt["food_mask"])
        for i, (fx, fy) in enumerate(items):
            if not (gone >> i) & 1:
                continue
            d = [math.hypot(fx - m[0], fy - m[1]) for m in moved]
            near = [dd < w["eat"] for dd in d]
            if not any(near):
                sys.exit(f"step {t}: item {i} was eaten but no robot is within {w['eat']} of it")
            eats += 1
            if all(near) and abs(d[0] - d[1]) <= w["share"] + 1e-4:
                for m in moved:
                    m[3] += w["food_energy"] / 2.0
            else:
                moved[0 if d[0] < d[1] else 1][3] += w["food_energy"]
        for i, (fx, fy) in enumerate(items):
            if (mask >> i) & 1 and not (gone >> i) & 1:
                for m in moved:
                    if math.hypot(fx - m[0], fy - m[1]) < w["eat"] - 1e-4:
                        sys.exit(f"step {t}: item {i} is within reach but was not eaten")
        for k, side in enumerate(sides):
            got = [float(nxt[side + "_" + q]) for q in ("x", "y", "heading", "energy")]
            m = moved[k]
            if abs(got[0] - m[0]) > 2e-4 or abs(got[1] - m[1]) > 2e-4 or angle_diff(got[2], m[2]) > 2e-6 \
                    or abs(got[3] - m[3]) > 1e-3:
                sys.exit(f"step {t}: {side} moved to {got}, the rules give {m}")
    print(f"{len(rows)} steps agree with the rules ({compared} sensings, {skipped} on a sector boundary "
          f"not compared; {eats} items eaten)")


if __name__ == "__main__":
    main()
