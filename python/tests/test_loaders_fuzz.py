"""The loaders Python reaches (they are libneat's and the runtime's, which tests/fuzz fuzzes) on the fuzzers' seed
corpora and on seeded random damage: each input loads, or raises a neat_duel error; nothing else, no crash; what
loads saves back to bytes that load to the same."""
from __future__ import annotations

import pathlib
import random
from typing import Callable

import pytest

import neat_duel as nd
from conftest import ROOT

CORPUS = ROOT / "tests" / "fuzz" / "corpus"


def kinds() -> dict[str, tuple[Callable[[bytes], object], Callable[[object], bytes], bytes]]:
    pop = nd.Population(nd.Params(pop_size=12, n_inputs=3, n_outputs=2, add_node_prob=0.3), seed=2)
    pop.run(lambda g: float(g.n_enabled), 3)
    best = pop.last_best
    assert best is not None
    coev = nd.Coevolution(nd.Params(pop_size=8, n_inputs=2, n_outputs=1, pop_stagnation=0), seed=1, compare_configs=2)
    coev.run(lambda a, b, c, f, s: 1 if a.step([0.5, 0.5])[0] > b.step([0.5, 0.5])[0] else -1, 2)
    return {
        "blob": (lambda b: nd.Network.from_blob(b), lambda o: o.blob, best.network().blob),  # type: ignore[attr-defined]
        "genome": (lambda b: nd.Genome.from_bytes(b), lambda o: o.to_bytes(), best.to_bytes()),  # type: ignore[attr-defined]
        "pop": (lambda b: nd.Population.from_bytes(b), lambda o: o.to_bytes(), pop.to_bytes()),  # type: ignore[attr-defined]
        "coev": (lambda b: nd.Coevolution.from_bytes(b), lambda o: o.to_bytes(), coev.to_bytes()),  # type: ignore[attr-defined]
    }


def damage(rng: random.Random, b: bytes) -> bytes:
    x = bytearray(b)
    for _ in range(rng.randint(1, 4)):
        op = rng.randrange(4)
        if op == 0 and x:
            x[rng.randrange(len(x))] ^= 1 << rng.randrange(8)
        elif op == 1 and x:
            x = x[: rng.randrange(len(x))]
        elif op == 2:
            at = rng.randrange(len(x) + 1)
            x[at:at] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 8)))
        elif x:
            at = rng.randrange(len(x))
            x[at] = rng.choice([0, 0xFF, 0x7F, 0x80])
    return bytes(x)


@pytest.mark.parametrize("kind", ["blob", "genome", "pop", "coev"])
def test_loaders(kind: str) -> None:
    load, save, valid = kinds()[kind]
    inputs = [p.read_bytes() for p in sorted((CORPUS / kind).iterdir())] if (CORPUS / kind).is_dir() else []
    rng = random.Random(f"neat_duel {kind}")
    inputs += [damage(rng, valid) for _ in range(400)] + [b"", valid]
    loaded = 0
    for data in inputs:
        try:
            obj = load(data)
        except nd.NeatError:
            continue
        loaded += 1
        again = save(obj)
        assert save(load(again)) == again  # what loads saves to bytes that load to the same
    assert loaded >= 1  # the valid one at least
