#!/usr/bin/env python3
"""make_mpi_corpus.py NETS_DIR OUT_DIR - seeds for fuzz_mpi_wire: WORK messages (a chunk of two games with the
blobs of duel_bench --write-blobs, one chunk split in two, a chunk without its blobs) and a RESULT, in the layout of
tools/mpi/duel_mpi_wire.h (little-endian x86-64)."""
import os
import struct
import sys

nets, out = sys.argv[1], sys.argv[2]
a = open(os.path.join(nets, "net39a.blob"), "rb").read()
b = open(os.path.join(nets, "net202a.blob"), "rb").read()
WORK, RESULT = 0x4B524F57, 0x544C5352


def work(count, batch, first, blobs, games):
    m = struct.pack("<IIQQII", WORK, count, batch, first, len(blobs), 0)
    for i, bl in blobs:
        m += struct.pack("<II", i, len(bl)) + bl
    for ga, gb, cfg, af in games:
        m += struct.pack("<IIiB3x", ga, gb, cfg, af)
    return m


def seed(name, cut, body):
    with open(os.path.join(out, name), "wb") as f:
        f.write(struct.pack("<H", cut) + body)


one = work(2, 1, 0, [(0, a), (1, b)], [(0, 1, -1, 1), (1, 0, 5, 0)])
seed("work-two-games", 0, one)
second = work(1, 1, 2, [], [(1, 0, 143, 1)])
seed("work-split", len(one), one + second)
seed("work-unsent-net", 0, work(1, 2, 0, [], [(0, 1, -1, 1)]))
seed("result", 0, struct.pack("<IIQQiiQQ", RESULT, 3, 1, 0, 0, 0, 0, 1234) + bytes([1, 0xFF, 0]))
