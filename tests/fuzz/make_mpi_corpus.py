#!/usr/bin/env python3
"""make_mpi_corpus.py NETS_DIR OUT_DIR - seeds for fuzz_mpi_wire: WORK messages (a chunk of two games with the
blobs of duel_bench --write-blobs, one chunk split in two, a chunk without its blobs) and a RESULT, in the layout of
tools/mpi/duel_mpi_wire.h (little-endian x86-64)."""
import os
import struct
import sys
import zlib

nets, out = sys.argv[1], sys.argv[2]
a = open(os.path.join(nets, "net39a.blob"), "rb").read()
b = open(os.path.join(nets, "net202a.blob"), "rb").read()
WORK, RESULT = 0x4B524F57, 0x544C5352


def q(v):
    return v * 65536


def rules_v1():
    """World v1's canonical bytes (docs/formats.md, "World rules"), padded to the header's 8-byte alignment."""
    r = b"DRUL" + struct.pack("<HH", 1, 236)
    r += struct.pack("<i", q(10))
    r += struct.pack("<iiIiiI", q(100), q(300), 0x80000000, q(500), q(300), 0)
    r += struct.pack("<iiiiI", q(1200), q(200), q(15), 0, 9)
    for i in range(9):
        r += struct.pack("<ii", q(200 + 100 * (i % 3)), q(200 + 100 * (i // 3)))
    for j in range(12):
        r += struct.pack("<ii", q((60, 140, 220)[j // 4]), q((75, 225, 375, 525)[j % 4]))
    r += struct.pack("<HHHH", 850, 850, 200, 200)
    r += struct.pack("<I", zlib.crc32(r))
    assert len(r) == 236
    return r + bytes(4)


def work(count, batch, first, blobs, games):
    m = struct.pack("<IIQQII", WORK, count, batch, first, len(blobs), 0) + rules_v1()
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
