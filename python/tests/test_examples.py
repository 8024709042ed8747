"""The examples that need only the package: examples/rl/ppo_ladder.py on a PPO run directory made here (its pool's
genome files written as ppo_selfplay.py writes them), its rows the comparisons neat_duel plays."""
from __future__ import annotations

import csv
import importlib.util
import json
import pathlib
from types import ModuleType

import numpy as np
import pytest

import neat_duel as nd
from neat_duel import envs
from conftest import ROOT

RUN = ROOT / "tests" / "tools" / "fixtures" / "experiment-tiny" / "runs" / "complexify-2"


def _example(name: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(name, ROOT / "examples" / "rl" / f"{name}.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _policy(rng: np.random.Generator, hidden: int = 4) -> nd.Genome:
    """A policy of ppo_selfplay.py's shape (inputs and bias -> hidden -> outputs, step propagate), random weights."""
    n_in, n_out = envs.N_OBSERVATIONS, envs.N_ACTIONS
    conns = [(src, 1 + n_in + n_out + k, float(rng.normal(0, 2))) for k in range(hidden) for src in range(n_in + 1)]
    conns += [(src, 1 + n_in + o, float(rng.normal(0, 2)))
              for o in range(n_out) for src in [0] + [1 + n_in + n_out + k for k in range(hidden)]]
    return nd.Genome.from_genes(n_in, n_out, hidden, conns, step="propagate")


def _run_dir(tmp: pathlib.Path, snaps: list[int], pool: list[str], final: bool) -> list[nd.Genome]:
    rng = np.random.default_rng(7)
    (tmp / "pool").mkdir(parents=True)
    genomes = []
    for g in snaps:
        genomes.append(_policy(rng))
        genomes[-1].save(tmp / "pool" / f"snap-{g:09d}.genome")
    if final:
        genomes[-1].save(tmp / "ppo-final.genome")
    state = {"games": snaps[-1], "budget": snaps[-1], "seed": 1, "every": 10, "next_snapshot": snaps[-1] + 10,
             "pool": pool}
    (tmp / "state.json").write_text(json.dumps(state))
    return genomes


def test_ppo_ladder_rows_are_the_comparisons(tmp_path: pathlib.Path, capsys: pytest.CaptureFixture[str]) -> None:
    ladder = _example("ppo_ladder")
    names = [f"snap-{g:09d}.genome" for g in (0, 10, 20)]
    # the run's end adding its last snapshot again, and the final policy equal to it: each listed once
    genomes = _run_dir(tmp_path, [0, 10, 20], names + names[-1:], final=True)
    assert ladder.main([str(tmp_path), "--against", str(RUN)]) == 0
    with open(tmp_path / "ladder.csv", newline="") as f:
        rows = list(csv.reader(f))
    rd = nd.runs.RunDir(RUN)
    top = max(rd.dominants(), key=lambda d: d["level"])
    opponents: list[nd.Network | str] = [*nd.duel_builtins(), rd.champion_network(top["generation"])]
    columns = [*nd.duel_builtins(), f"top-level-{top['level']}"]
    assert rows[0] == ["games", "policy"] + [f"{n}_{k}" for n in columns for k in ("wins", "losses")]
    assert [r[:2] for r in rows[1:]] == [["0", names[0]], ["10", names[1]], ["20", names[2]]]
    for row, genome in zip(rows[1:], genomes):
        want = []
        for opp in opponents:
            c = nd.duel_compare(genome.network(), opp)
            want += [str(c["wins"]), str(c["losses"])]
        assert row[2:] == want
    out = capsys.readouterr().out.splitlines()
    assert len(out) == 4 and out[3].split()[0] == "20"


def test_ppo_ladder_lists_a_final_policy_of_its_own(tmp_path: pathlib.Path) -> None:
    ladder = _example("ppo_ladder")
    _run_dir(tmp_path, [0, 10], ["snap-000000000.genome", "snap-000000010.genome"], final=False)
    state = json.loads((tmp_path / "state.json").read_text())
    state["games"] = 13  # stopped between snapshots: the final policy is a later one
    (tmp_path / "state.json").write_text(json.dumps(state))
    _policy(np.random.default_rng(3)).save(tmp_path / "ppo-final.genome")
    assert [g for g, _ in ladder.policies(str(tmp_path))] == [0, 10, 13]
    state["pool"] = ["model.zip"]
    (tmp_path / "state.json").write_text(json.dumps(state))
    with pytest.raises(SystemExit, match="not a snapshot's name"):
        ladder.policies(str(tmp_path))
