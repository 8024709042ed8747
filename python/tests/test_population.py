"""Population: run with a callback, the explicit loop, the batched path, records, checkpoints, errors."""
from __future__ import annotations

import pathlib

import numpy as np
import pytest

import neat_duel as nd
from conftest import XOR, ROOT


def xor_fitness(g: nd.Genome) -> float:
    net = g.network()
    err = 0.0
    for a, b, y in XOR:
        net.reset()
        err += abs(net.settle([a, b])[0] - y)
    return (4.0 - err) ** 2


def xor_params() -> nd.Params:
    return nd.Params.from_ini(str(ROOT / "bench" / "xor.ini"))


def test_run_solves_xor_and_records() -> None:
    pop = nd.Population(xor_params(), seed=3)
    recs = pop.run(xor_fitness, 100, until=lambda r: r["best_fitness"] > 15.5)
    assert recs[-1]["best_fitness"] > 15.5 and len(recs) < 100
    assert [r["generation"] for r in recs] == list(range(len(recs)))
    assert recs[-1]["evaluations"] == 150 * len(recs)
    assert set(recs[0]) == {"generation", "evaluations", "best_fitness", "mean_fitness", "species", "delta_t",
                            "best_hidden", "best_connections", "innovations"}
    best = pop.last_best
    assert best is not None and best.fitness == recs[-1]["best_fitness"]
    assert pop.best_ever is not None and pop.generation == len(recs)


def test_the_explicit_loop_is_the_run() -> None:
    a, b = nd.Population(xor_params(), seed=5), nd.Population(xor_params(), seed=5)
    a.run(xor_fitness, 3)
    for _ in range(3):
        for i in range(len(b)):
            b.set_fitness(i, xor_fitness(b.genome(i)))
        b.epoch()
    assert a.to_bytes() == b.to_bytes()


def test_the_batched_path_is_the_same_run() -> None:
    a, b = nd.Population(xor_params(), seed=9), nd.Population(xor_params(), seed=9)
    a.run(xor_fitness, 4)
    for _ in range(4):
        nets = b.networks()
        assert len(nets) == len(b)
        err = np.zeros(len(b))
        for x1, x2, y in XOR:
            nets.reset()
            out = nets.settle(np.array([x1, x2]))
            assert out.shape == (len(b), 1)
            err += np.abs(out[:, 0] - y)
        b.set_fitnesses((4.0 - err) ** 2)
        b.epoch()
    assert a.to_bytes() == b.to_bytes()


def test_batched_rows_and_steps() -> None:
    pop = nd.Population(nd.Params(pop_size=8, n_inputs=3, n_outputs=2), seed=1)
    nets = pop.networks()
    rows = np.random.default_rng(0).uniform(-1, 1, (8, 3))
    out = nets.step(rows)
    for i in range(8):
        net = pop.genome(i).network()
        assert net.step(list(rows[i])) == list(out[i])
    with pytest.raises(nd.ArgumentError, match=r"shape must be"):
        nets.step(np.zeros((3, 3)))


def test_a_raising_callback_stops_cleanly() -> None:
    pop = nd.Population(xor_params(), seed=2)
    ref = nd.Population(xor_params(), seed=2)
    calls = 0

    def boom(g: nd.Genome) -> float:
        nonlocal calls
        calls += 1
        if calls == 7:
            raise KeyError("mine")
        return xor_fitness(g)

    with pytest.raises(KeyError, match="mine"):
        pop.run(boom, 5)
    assert pop.generation == 0
    pop.run(xor_fitness, 2)  # the generation is evaluated again: the run goes on as if nothing happened
    ref.run(xor_fitness, 2)
    assert pop.to_bytes() == ref.to_bytes()


def test_genomes_kept_from_the_fitness_call_stay_whole() -> None:
    """run() lends each genome to the fitness call and copies it only if the call keeps it: what was kept (the
    genome, a numpy view of it, one held by a traceback) must equal what the call saw after later epochs."""
    pop = nd.Population(xor_params(), seed=4)
    kept: list[tuple[nd.Genome, bytes]] = []
    views: list[tuple[np.ndarray, bytes]] = []

    def keep(g: nd.Genome) -> float:
        if len(kept) < 40 and pop.generation % 2 == 0:
            kept.append((g, g.to_bytes()))
        if len(views) < 40 and pop.generation % 2 == 1:
            c = g.conns
            views.append((c, c.tobytes()))
        return xor_fitness(g)

    pop.run(keep, 6)
    assert len(kept) == 40 and len(views) == 40
    for g, b in kept:
        assert g.to_bytes() == b and g.fitness is None  # a copy taken before its fitness was set
    for c, b in views:
        assert c.tobytes() == b

    caught: list[BaseException] = []

    def boom(g: nd.Genome) -> float:
        raise ValueError(g.to_bytes().hex()[:16])
        return xor_fitness(g)

    try:
        pop.run(boom, 1)
    except ValueError as e:
        caught.append(e)
    tb = caught[0].__traceback__
    while tb is not None and tb.tb_frame.f_code.co_name != "boom":
        tb = tb.tb_next
    assert tb is not None
    held = tb.tb_frame.f_locals["g"]
    before = held.to_bytes()
    pop.run(xor_fitness, 3)  # three epochs free and reuse the population's genomes
    assert held.to_bytes() == before and before.hex()[:16] == str(caught[0])


def test_no_epoch_from_inside_run() -> None:
    pop = nd.Population(xor_params(), seed=6)
    ref = nd.Population(xor_params(), seed=6)

    def nested(g: nd.Genome) -> float:
        pop.epoch()
        return 1.0

    def again(g: nd.Genome) -> float:
        pop.run(xor_fitness, 1)
        return 1.0

    for f in (nested, again):
        with pytest.raises(nd.StateError, match="not from inside run"):
            pop.run(f, 2)
        assert pop.generation == 0
    pop.run(xor_fitness, 2, until=lambda r: pop.set_params(pop.params) is not None)  # set_params stays allowed
    ref.run(xor_fitness, 2)
    assert pop.to_bytes() == ref.to_bytes()


@pytest.mark.parametrize("value", [float("nan"), float("inf"), -1.0])
def test_bad_fitness(value: float) -> None:
    pop = nd.Population(xor_params(), seed=1)
    with pytest.raises(nd.FitnessError) as e:
        pop.run(lambda g: value, 1)
    assert e.value.index == 0
    with pytest.raises(TypeError, match="not a number"):
        pop.run(lambda g: "high", 1)  # type: ignore[arg-type, return-value]
    with pytest.raises(nd.FitnessError) as e:
        pop.set_fitnesses(np.array([1.0] * 149 + [value]))
    assert e.value.index == 149


def test_bad_arguments() -> None:
    pop = nd.Population(xor_params(), seed=1)
    with pytest.raises(nd.ArgumentError, match="at least 1"):
        pop.run(xor_fitness, 0)
    with pytest.raises(IndexError):
        pop.genome(150)
    with pytest.raises(IndexError):
        pop.set_fitness(150, 1.0)
    with pytest.raises(nd.ArgumentError):
        pop.set_fitnesses(np.ones(3))
    with pytest.raises(nd.FitnessError, match="genome 0 has no fitness"):
        pop.epoch()
    with pytest.raises(nd.ParamError):
        pop.set_params(nd.Params(pop_size=10))
    start = nd.Population(nd.Params(pop_size=4, n_inputs=5, n_outputs=1), seed=1).genome(0)
    with pytest.raises(nd.ArgumentError, match="a genome of 5 inputs"):
        nd.Population(xor_params(), start=start)


def test_checkpoints(tmp_path: pathlib.Path) -> None:
    a = nd.Population(xor_params(), seed=4)
    a.run(xor_fitness, 2)
    path = tmp_path / "pop.ckpt"
    a.save(str(path))
    assert [p.name for p in tmp_path.iterdir()] == ["pop.ckpt"]  # no temporary file left
    b = nd.Population.load(str(path))
    assert b.to_bytes() == a.to_bytes() and b.generation == 2 and b.params == a.params
    a.run(xor_fitness, 3)
    b.run(xor_fitness, 3)
    assert a.to_bytes() == b.to_bytes()
    data = bytearray(path.read_bytes())
    data[40] ^= 0xFF
    with pytest.raises(nd.FormatError) as e:
        nd.Population.from_bytes(bytes(data), "damaged")
    assert e.value.offset is not None and "damaged" in str(e.value)
    with pytest.raises(nd.FormatError, match="at byte offset"):
        nd.Population.from_bytes(bytes(data[:100]))


def test_start_genome_and_species() -> None:
    src = nd.Population(xor_params(), seed=1)
    src.run(xor_fitness, 5)
    start = src.last_best
    assert start is not None
    pop = nd.Population(xor_params(), seed=2, start=start, keep_weights=True)
    assert pop.genome(0).n_enabled >= 1
    sp = pop.species()
    assert sum(s["size"] for s in sp) == len(pop)
    assert pop.delta_t > 0 and pop.innovations >= 3
    assert repr(pop).startswith("Population(150 genomes, generation 0")
