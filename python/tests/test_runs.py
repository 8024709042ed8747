"""duel_evolve's run and resume from Python: the same run directory, resumed across Python and the command."""
from __future__ import annotations

import json
import pathlib
import subprocess

import pytest

import neat_duel as nd
from neat_duel import runs
from conftest import ROOT, program

SMALL = str(ROOT / "tests" / "tools" / "coev-small.ini")


def test_python_and_the_command_resume_each_other(tmp_path: pathlib.Path) -> None:
    duel = program("DUEL_EVOLVE")
    a, b = tmp_path / "a", tmp_path / "b"
    r = runs.run(SMALL, a, generations=2)
    subprocess.run([str(duel), "resume", str(a), "--generations", "4", "--quiet"], check=True)
    r = runs.resume(a, generations=6)
    subprocess.run([str(duel), "run", "--config", SMALL, "--out", str(b), "--generations", "6", "--quiet"], check=True)
    for f in ("checkpoint.bin", "dominance.csv", "config.ini", "champions/gen-00005.blob"):
        assert (a / f).read_bytes() == (b / f).read_bytes(), f
    gens = r.generations()
    assert [g["generation"] for g in gens] == [0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5]
    doms = r.dominants()
    assert doms[0]["level"] == 1 and all(len(d["wins"]) == d["level"] - 1 for d in doms)
    top = doms[-1]
    assert r.champion(top["generation"]).network().blob == r.champion_network(top["generation"]).blob
    assert r.checkpoint().generation == 6 and r.config().seed == 7
    # a Python configuration object runs the same way
    cfg = nd.DuelConfig.from_ini(SMALL)
    c = runs.run(cfg, tmp_path / "c", generations=6, threads=2)
    assert (c.path / "checkpoint.bin").read_bytes() == (b / "checkpoint.bin").read_bytes()


def test_the_commands_refusals(tmp_path: pathlib.Path) -> None:
    runs.run(SMALL, tmp_path / "a", generations=1)
    with pytest.raises(runs.RunError, match="already holds a run") as e:
        runs.run(SMALL, tmp_path / "a")
    assert e.value.status == 2
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("mine\n")
    with pytest.raises(runs.RunError, match="not a run directory"):
        runs.run(SMALL, tmp_path / "mine", generations=1)
    assert (tmp_path / "mine" / "notes.txt").read_text() == "mine\n"
    with pytest.raises(runs.RunError):
        runs.resume(tmp_path / "nothing")
    with pytest.raises(runs.RunError, match="unknown"):
        runs.run(SMALL, tmp_path / "b", set=["nope=1"])
    # --record-champion-games needs LCM, which the package is built without: refused with one line
    status, _, text = nd._core.run_command("resume", [str(tmp_path / "a"), "--generations", "2",
                                                    "--record-champion-games", "--quiet"])
    assert status != 0 and "needs a build with LCM" in text
    with pytest.raises(FileNotFoundError):
        runs.RunDir(tmp_path / "mine")
    text = (tmp_path / "a" / "dominance.csv").read_bytes()
    (tmp_path / "a" / "dominance.csv").write_bytes(text[:-1])
    with pytest.raises(nd.FormatError, match="cut short"):
        runs.RunDir(tmp_path / "a").dominants()



def test_ladder_and_compare_are_the_commands(tmp_path: pathlib.Path) -> None:
    duel = program("DUEL_EVOLVE")
    a = runs.run(SMALL, tmp_path / "a", generations=4)
    b = runs.run(SMALL, tmp_path / "b", generations=4, seed=9)
    lad = runs.ladder(a.path)
    cli = subprocess.run([str(duel), "ladder", str(a.path), "--json"], capture_output=True, text=True, check=True)
    assert lad == json.loads(cli.stdout)
    assert [lv["level"] for lv in lad["levels"]] == [d["level"] for d in a.dominants()]
    top = runs.ladder(a.path, top=True, against=["forager-hunter"])
    assert len(top["levels"]) == 1 and top["against"] == ["forager-hunter"]
    cmp = runs.compare([a.path], [b.path], threads=2, cache=tmp_path / "cache.csv")
    subprocess.run([str(duel), "compare", str(a.path), "--against", str(b.path), "--json", str(tmp_path / "c.json"),
                    "--cache", str(tmp_path / "cache2.csv")], check=True, capture_output=True)
    want = json.loads((tmp_path / "c.json").read_text())
    assert cmp == want and cmp["candidates"] and cmp["games_per_comparison"] == 288
    with pytest.raises(runs.RunError):
        runs.ladder(tmp_path / "none")
    with pytest.raises(ValueError):
        runs.compare([], [b.path])


def test_one_command_at_a_time(tmp_path: pathlib.Path) -> None:
    import threading
    import time

    errors: list[BaseException] = []
    long = tmp_path / "long"

    def long_run() -> None:
        try:
            runs.run(SMALL, long, generations=60)
        except BaseException as e:  # noqa: BLE001 - reported below
            errors.append(e)

    t = threading.Thread(target=long_run)
    t.start()
    while t.is_alive() and not (long / "generations.csv").exists():  # the run holds the command from here on
        time.sleep(0.001)
    # a second command while the first runs is refused at once (StateError), not run over it
    with pytest.raises(nd.StateError, match="another duel_evolve command runs in this process"):
        runs.ladder(long)
    assert t.is_alive()  # (60 generations take seconds: the refusal above was made during the run)
    t.join()
    assert not errors and runs.RunDir(long).checkpoint().generation == 60
