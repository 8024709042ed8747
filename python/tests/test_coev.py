"""Coevolution with a game in Python and with the built-in duel; the duel's games; Python = duel_evolve."""
from __future__ import annotations

import json
import pathlib
import subprocess

import pytest

import neat_duel as nd
from conftest import ROOT, program

SMALL = str(ROOT / "tests" / "tools" / "coev-small.ini")


def toy(a: nd.Network, b: nd.Network, config: int, a_first: bool, seed: int) -> int:
    """A game of our own: the network with the larger first output on a seeded input wins."""
    x = [((seed >> k) & 7) / 8.0 for k in range(0, 36, 3)]
    oa, ob = a.step(x)[0], b.step(x)[0]
    return 1 if oa > ob else -1 if ob > oa else 0


def small_params() -> nd.Params:
    return nd.Params(pop_size=16, pop_stagnation=0)


def test_a_python_game() -> None:
    a = nd.Coevolution(small_params(), seed=3, compare_configs=6)
    recs = a.run(toy, 4)
    assert [r["generation"] for r in recs] == [0, 1, 2, 3] and a.generation == 4
    assert recs[0]["A"]["games"] > 0 and recs[-1]["dominants"] == len(a.dominants()) >= 1
    d = a.dominants()[-1]
    assert d["level"] == len(a.dominants()) and len(d["wins"]) == d["level"] - 1
    assert isinstance(d["genome"], nd.Genome) and d["population"] in ("A", "B")
    assert len(a.population("A")) == 16 and len(a.hall_of_fame("B")) == 4
    assert a.champion is not None
    b = nd.Coevolution(small_params(), seed=3, compare_configs=6)
    b.run(toy, 4)
    assert a.to_bytes() == b.to_bytes()  # a pure function of the seed


def test_a_raising_game_changes_nothing() -> None:
    c = nd.Coevolution(small_params(), seed=1, compare_configs=6)
    c.step(toy)
    before = c.to_bytes()
    n = 0

    def boom(a: nd.Network, b: nd.Network, config: int, a_first: bool, seed: int) -> int:
        nonlocal n
        n += 1
        if n == 50:
            raise KeyError("mine")
        return toy(a, b, config, a_first, seed)

    with pytest.raises(KeyError, match="mine"):
        c.step(boom)
    assert c.to_bytes() == before
    with pytest.raises(ValueError, match="the game returned 2"):
        c.step(lambda a, b, config, a_first, seed: 2)
    with pytest.raises(ValueError, match="the game returned 'x'"):
        c.step(lambda a, b, config, a_first, seed: "x")  # type: ignore[arg-type, return-value]
    assert c.to_bytes() == before
    with pytest.raises(TypeError, match="game: a function"):
        c.step(3)  # type: ignore[arg-type]
    with pytest.raises(nd.ArgumentError):
        c.run(toy, 0)
    with pytest.raises(nd.ParamError, match="pop_stagnation must be 0"):
        nd.Coevolution(nd.Params(pop_size=16))
    with pytest.raises(nd.ParamError, match="compare_configs"):
        nd.Coevolution(small_params(), compare_configs=0)


def test_checkpoints(tmp_path: pathlib.Path) -> None:
    a = nd.Coevolution(small_params(), seed=5, compare_configs=6)
    a.run(toy, 2)
    a.save(str(tmp_path / "c.ckpt"))
    b = nd.Coevolution.load(str(tmp_path / "c.ckpt"))
    a.run(toy, 2)
    b.run(toy, 2)
    assert a.to_bytes() == b.to_bytes()
    bad = bytearray((tmp_path / "c.ckpt").read_bytes())
    bad[100] ^= 0x10
    with pytest.raises(nd.FormatError, match="at byte offset"):
        nd.Coevolution.from_bytes(bytes(bad))


def test_the_duel_run_is_duel_evolves(tmp_path: pathlib.Path) -> None:
    """DuelConfig.coevolution() stepped with Duel is duel_evolve run's very run: the same checkpoint bytes, with 1
    thread or 2."""
    duel = program("DUEL_EVOLVE")
    subprocess.run([str(duel), "run", "--config", SMALL, "--out", str(tmp_path / "r"), "--generations", "3",
                    "--quiet"], check=True)
    want = (tmp_path / "r" / "checkpoint.bin").read_bytes()
    cfg = nd.DuelConfig.from_ini(SMALL)
    for threads in (1, 2):
        c = cfg.coevolution()
        c.run(nd.Duel(cfg, threads=threads), 3)
        assert c.to_bytes() == want, f"{threads} threads"
    # and the CLI's checkpoint goes on from Python
    c = nd.Coevolution.load(str(tmp_path / "r" / "checkpoint.bin"))
    c.step(nd.Duel(cfg))
    assert c.generation == 4


def test_duel_config() -> None:
    cfg = nd.DuelConfig.from_ini(SMALL)
    assert (cfg.generations, cfg.seed, cfg.params.pop_size, cfg.world) == (10, 7, 32, "v1")
    cfg.set("train_layouts=comparison")
    cfg.set("neat.add_node_prob=0.05")
    assert "train_layouts = comparison" in cfg.to_ini() and cfg.params.add_node_prob == 0.05
    with pytest.raises(nd.ParamError, match="unknown"):
        cfg.set("nope=1")
    with pytest.raises(nd.ParamError):
        nd.DuelConfig.from_ini(str(ROOT / "bench" / "xor.ini"))  # [bench] is not a run's section
    assert nd.DuelConfig().params.pop_size == 256


def test_duel_games_are_duel_evolves() -> None:
    duel = program("DUEL_EVOLVE")
    r = subprocess.run([str(duel), "play", "builtin:forager-hunter", "builtin:forager", "--games", "288", "--json"],
                       capture_output=True, text=True, check=True)
    c = json.loads(r.stdout)
    t = nd.duel_compare("forager-hunter", "builtin:forager")
    assert (t["wins"], t["losses"], t["draws"], t["timeouts"]) == (c["a_wins"], c["b_wins"], c["draws"],
                                                                    c["timeouts"])
    r = subprocess.run([str(duel), "play", "builtin:forager-hunter", "builtin:hunter", "--food", "17", "--side",
                        "east", "--json"], capture_output=True, text=True, check=True)
    g = json.loads(r.stdout)
    p = nd.duel_play("forager-hunter", "hunter", food=17, a_west=False)
    assert p["winner"] == "a" and p["outcome"] == "east" and p["steps"] == g["steps"]
    assert p["eaten"] == (g["eaten"][1], g["eaten"][0])


def test_duel_games() -> None:
    assert nd.duel_builtins() == ["idle", "spinner", "forager", "hunter", "forager-hunter"]
    net = nd.Population(nd.Params(pop_size=4), seed=1).genome(0).network()
    other = nd.Population(nd.Params(pop_size=4), seed=2).genome(0).network()
    matches = [(net, "forager", k, k % 2 == 0) for k in range(-1, 40)] + [(net, other, 3, True)]
    one = nd.Duel(threads=1).play_many(matches)
    assert one == nd.Duel(threads=2).play_many(matches) and set(one) <= {-1, 0, 1}
    for (a, b, food, west), r in list(zip(matches, one))[:6]:
        g = nd.duel_play(a, b, food=food, a_west=west)
        assert r == {"a": 1, "b": -1, "none": 0}[g["winner"]]
    with pytest.raises(nd.ArgumentError, match="not a built-in strategy"):
        nd.duel_play(net, "rambler")
    with pytest.raises(nd.ArgumentError, match="the same Network object"):
        nd.duel_compare(net, net)
    with pytest.raises(nd.ArgumentError, match="food"):
        nd.duel_play(net, "idle", food=144)
    small = nd.Population(nd.Params(pop_size=4, n_inputs=2, n_outputs=1), seed=1).genome(0).network()
    with pytest.raises(nd.ArgumentError, match="12 inputs and 3 outputs"):
        nd.duel_play(small, "idle")
    with pytest.raises(TypeError):
        nd.duel_play(3, "idle")  # type: ignore[arg-type]
