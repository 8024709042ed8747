"""duel_evolve's run and resume from Python: the same run directory, resumed across Python and the command."""
from __future__ import annotations

import json
import pathlib
import subprocess
import time

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
    # no command line is run in the package: every run, ladder, comparison and export is a library's
    assert not hasattr(nd._core, "run_command")
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
    from_python = (a.path / "ladder.csv").read_bytes()
    cli = subprocess.run([str(duel), "ladder", str(a.path), "--json"], capture_output=True, text=True, check=True)
    assert lad == json.loads(cli.stdout)
    assert from_python == (a.path / "ladder.csv").read_bytes()  # the same RUN/ladder.csv, the command's
    with pytest.raises(runs.RunError, match="--top and --levels name the levels twice"):
        runs.ladder(a.path, top=True, levels=(1, 1))
    with pytest.raises(runs.RunError, match="each once"):
        runs.ladder(a.path, against=["idle", "idle"])
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
    with pytest.raises(runs.RunError, match="^compare: .*none") as e:  # the measure's own line, nothing printed
        runs.compare([tmp_path / "none"], [b.path])
    assert e.value.status == 2


def test_two_runs_in_two_threads(tmp_path: pathlib.Path) -> None:
    """Two runs at once in one process (each its own directory, the interpreter lock released while they play),
    each the same as alone; a second opener of a directory in use is refused by the engine's lock."""
    import threading

    errors: list[BaseException] = []

    def one(name: str, seed: int) -> None:
        try:
            runs.run(SMALL, tmp_path / name, generations=8, seed=seed, threads=1)
        except BaseException as e:  # noqa: BLE001 - reported below
            errors.append(e)

    threads = [threading.Thread(target=one, args=(n, s)) for n, s in (("x", 3), ("y", 4))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    runs.run(SMALL, tmp_path / "x1", generations=8, seed=3, threads=1)
    for f in ("checkpoint.bin", "dominance.csv"):
        assert (tmp_path / "x" / f).read_bytes() == (tmp_path / "x1" / f).read_bytes()
    with runs.Run.start(SMALL, tmp_path / "z", generations=4) as held:
        with pytest.raises(runs.RunError, match="in use by another") as e:
            runs.Run.resume(tmp_path / "z")
        assert e.value.status == 2
        assert held.generation == 0
    with runs.Run.resume(tmp_path / "z") as again:  # given back by close
        assert again.total == 4


def test_generation_by_generation_with_reporters(tmp_path: pathlib.Path) -> None:
    """A Run iterated a generation at a time, with a custom reporter, the statistics and the checkpointer, and
    left early: the directory is a whole run at that generation, which resume (here or duel_evolve) continues."""

    class Count(runs.Reporter):
        def __init__(self) -> None:
            self.started = self.ended = 0
            self.seen: list[int] = []

        def start(self, run: runs.Run) -> None:
            self.started += 1

        def generation(self, run: runs.Run, record: runs.Generation) -> None:
            self.seen.append(record.generation)

        def end(self, run: runs.Run) -> None:
            self.ended += 1

    count, stats = Count(), runs.StatisticsReporter()
    ck = runs.Checkpointer(2, tmp_path / "ck-")
    with runs.Run.start(SMALL, tmp_path / "a", generations=10, reporters=[count, stats, ck]) as run:
        for g in run.generations():
            assert g.rows[0]["generation"] == g.generation and [r["population"] for r in g.rows] == ["A", "B"]
            if g.dominants >= 3 or g.generation == 6:
                break
        stopped_at = run.generation
    assert count.started == 1 and count.ended == 1 and count.seen == list(range(stopped_at))
    assert len(stats.rows()) == 2 * stopped_at and stats.rows()[0]["population"] == "A"
    assert (tmp_path / "ck-2.bin").read_bytes()[:8] == (tmp_path / "a" / "checkpoint.bin").read_bytes()[:8]
    assert runs.RunDir(tmp_path / "a").checkpoint().generation == stopped_at
    # the rest from Python equals the whole run made at once
    runs.resume(tmp_path / "a")
    runs.run(SMALL, tmp_path / "b", generations=10)
    for f in ("checkpoint.bin", "dominance.csv"):
        assert (tmp_path / "a" / f).read_bytes() == (tmp_path / "b" / f).read_bytes()
    # an exception in a reporter stops the run after the generation in flight, which is saved
    class Boom(runs.Reporter):
        def generation(self, run: runs.Run, record: runs.Generation) -> None:
            if record.generation == 2:
                raise RuntimeError("boom")

    with pytest.raises(RuntimeError, match="boom"):
        runs.run(SMALL, tmp_path / "c", generations=10, reporters=[Boom()])
    assert runs.RunDir(tmp_path / "c").checkpoint().generation == 3
    # play() with an early stop condition
    with runs.Run.resume(tmp_path / "c") as run:
        run.play(until=lambda g: g.generation >= 5)
        assert run.generation == 6


def test_ctrl_c_saves_the_generation_in_flight(tmp_path: pathlib.Path) -> None:
    """Ctrl-C during a run's games: the generation in flight finishes and is saved, KeyboardInterrupt is raised,
    and the run resumes to the bytes of one that never stopped."""
    import _thread
    import threading

    t0 = time.perf_counter()
    runs.run(SMALL, tmp_path / "ref", generations=12, threads=1)
    per_gen = (time.perf_counter() - t0) / 12
    timer = threading.Timer(max(0.05, 3 * per_gen), _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            runs.run(SMALL, tmp_path / "cut", generations=12, threads=1)
    finally:
        timer.cancel()
    done = runs.RunDir(tmp_path / "cut").checkpoint().generation
    assert 0 < done < 12
    runs.resume(tmp_path / "cut")
    for f in ("checkpoint.bin", "dominance.csv"):
        assert (tmp_path / "cut" / f).read_bytes() == (tmp_path / "ref" / f).read_bytes()

