"""Python = C: neat_bench's XOR runs, the runtime's steps in a duel trace, duel_evolve's files."""
from __future__ import annotations

import csv
import pathlib
import re
import subprocess

import numpy as np

import neat_duel as nd
from conftest import ROOT, XOR, program


def xor_eval(net: nd.Network) -> tuple[float, bool]:
    """bench/bench_eval.c's bench_xor_eval, line for line."""
    err, correct = 0.0, True
    for a, b, y in XOR:
        net.reset()
        o = net.settle([a, b])[0]
        err += abs(o - y)
        if (o >= 0.5) != (y == 1):
            correct = False
    return (4.0 - err) * (4.0 - err), correct


def xor_run(params: nd.Params, seed: int, max_generations: int) -> tuple[bool, int, int]:
    """bench/task_xor.c's task_xor_run: (solved, evaluations, generations)."""
    pop = nd.Population(params, seed=seed)
    evals = 0
    for gen in range(max_generations):
        for i in range(len(pop)):
            f, solved = xor_eval(pop.genome(i).network())
            evals += 1
            pop.set_fitness(i, f)
            if solved:
                return True, evals, gen + 1
        pop.epoch()
    return False, evals, max_generations


def test_neat_bench_xor_evaluations() -> None:
    bench = program("NEAT_BENCH")
    runs = 100
    r = subprocess.run([str(bench), "xor", "--runs", str(runs), "--threads", "2"], capture_output=True, text=True,
                       check=True)
    c = {int(m[1]): (m[2] == "solved", int(m[3])) for m in
         re.finditer(r"^run (\d+): (solved|FAILED) after (\d+) evaluations", r.stderr, re.M)}
    assert len(c) == runs
    params = nd.Params.from_ini(str(ROOT / "bench" / "xor.ini"))
    for k in range(runs):
        solved, evals, _ = xor_run(params, nd.seed_derive(1, [k]), 100)
        assert (solved, evals) == c[k], f"run {k}"


def test_runtime_steps_of_a_duel_trace(tmp_path: pathlib.Path) -> None:
    """A champion blob stepped from Python gives, bit for bit, the outputs duel_evolve's C runtime gave in a game."""
    duel = program("DUEL_EVOLVE")
    bench = program("DUEL_BENCH")
    subprocess.run([str(bench), "--write-blobs", str(tmp_path)], check=True, capture_output=True)
    for name in ("net39a.blob", "net202a.blob"):
        blob = tmp_path / name
        trace = tmp_path / "trace.csv"
        subprocess.run([str(duel), "play", str(blob), "builtin:forager-hunter", "--food", "5", "--trace", str(trace),
                        "--force"], check=True, capture_output=True)
        net = nd.Network.load(str(blob))
        rows = list(csv.DictReader(trace.open()))
        assert len(rows) > 50
        for row in rows:
            x = np.array([round(float(row[f"west_in{i}"]) * 32768) for i in range(13)], dtype=np.int16)
            want = [round(float(row[f"west_out{i}"]) * 32768) for i in range(3)]
            assert list(net.step_q15(x)) == want, f"{name} step {row['t']}"


def test_files_of_duel_evolve(tmp_path: pathlib.Path) -> None:
    """A run's champion genome and blob read here are the same network; a genome saved here reads there."""
    duel = program("DUEL_EVOLVE")
    out = tmp_path / "run"
    subprocess.run([str(duel), "run", "--config", str(ROOT / "tests" / "tools" / "coev-small.ini"), "--out", str(out),
                    "--generations", "2", "--quiet"], check=True)
    g = nd.Genome.load(str(out / "champions" / "gen-00001.genome"))
    assert g.network().blob == (out / "champions" / "gen-00001.blob").read_bytes()
    g.save(str(tmp_path / "again.genome"))
    r = subprocess.run([str(duel), "inspect", str(tmp_path / "again.genome")], capture_output=True, text=True,
                       check=True)
    assert "genome" in r.stdout


def test_champion_keeps_its_origin(tmp_path: pathlib.Path) -> None:
    """Issue 49: a propagate champion of another world, copied out of its run, is still a propagate network of that
    world here, and saved again gives the same bytes (genome file format 2)."""
    duel = program("DUEL_EVOLVE")
    out = tmp_path / "run"
    subprocess.run([str(duel), "run", "--config", str(ROOT / "tests" / "tools" / "coev-small.ini"), "--out", str(out),
                    "--generations", "2", "--set", "net_step=propagate", "--set", "world.food_range=300", "--quiet"],
                   check=True)
    copy = tmp_path / "copy.genome"
    copy.write_bytes((out / "champions" / "gen-00001.genome").read_bytes())
    g = nd.Genome.load(copy)
    cfg = nd.DuelConfig.from_ini(out / "config.ini")
    assert g.step == "propagate"
    assert g.world_id == cfg.world_id != nd.DuelConfig().world_id
    assert g.network().step_mode == "propagate"
    assert g.network().blob == (out / "champions" / "gen-00001.blob").read_bytes()
    assert g.to_bytes() == copy.read_bytes()
    # a genome of a propagate population records its step, not a world
    p = nd.Params(pop_size=10, n_inputs=2, n_outputs=1, net_step="propagate")
    pop = nd.Population(p, seed=1)
    h = nd.Genome.from_bytes(pop.genome(0).to_bytes())
    assert h.step == "propagate" and h.world_id is None
    # one of a sync population is written as before origins existed (format 1)
    s = nd.Population(nd.Params(pop_size=10, n_inputs=2, n_outputs=1), seed=1).genome(0)
    assert s.to_bytes()[8] == 1 and nd.Genome.from_bytes(s.to_bytes()).step == "sync"
