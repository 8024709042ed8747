"""Web pages from Python: the same bytes as duel_evolve render --html and report --html, the command's refusals."""
from __future__ import annotations

import pathlib
import shutil
import subprocess

import pytest

import neat_duel as nd
from neat_duel import pages
from conftest import ROOT, program

FIXTURE = ROOT / "tests" / "tools" / "fixtures" / "experiment-tiny"


def test_duel_page_is_the_commands(tmp_path: pathlib.Path) -> None:
    duel = program("DUEL_EVOLVE")
    net = nd.Population(nd.Params(pop_size=4, n_inputs=12, n_outputs=3), seed=3).genome(1).network()
    net.save(str(tmp_path / "champ.blob"))
    pages.duel(net, "forager-hunter", tmp_path / "py.html", food=17, a_west=False, a_name="champ.blob",
               b_name="builtin:forager-hunter")
    subprocess.run([str(duel), "render", "champ.blob", "builtin:forager-hunter", "--food", "17", "--side", "east",
                    "--html", "cli.html"], check=True, cwd=tmp_path, capture_output=True)
    assert (tmp_path / "py.html").read_bytes() == (tmp_path / "cli.html").read_bytes()
    text = (tmp_path / "py.html").read_text()
    assert text.startswith("<!DOCTYPE html>") and '"food_config":17' in text


def test_run_pages_are_the_commands(tmp_path: pathlib.Path) -> None:
    duel = program("DUEL_EVOLVE")
    run = tmp_path / "run"
    shutil.copytree(FIXTURE / "runs" / "complexify-3", run)
    n = pages.run(run, tmp_path / "py", games="top")
    subprocess.run([str(duel), "report", str(run), "--html", str(tmp_path / "cli"), "--games", "top"], check=True,
                   capture_output=True)
    files = sorted(p.relative_to(tmp_path / "py") for p in (tmp_path / "py").rglob("*.html"))
    assert n == len(files) == 7  # the index and the top level's six games
    for f in files:
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f


def test_experiment_pages(tmp_path: pathlib.Path) -> None:
    exp = tmp_path / "exp"
    shutil.copytree(FIXTURE, exp)
    n = pages.experiment(exp, games="none", embed=False)
    methods = [line.split(",")[0] for line in (exp / "report" / "table1.csv").read_text().splitlines()[1:]]
    assert n == len(methods) + 1
    for m in methods:
        assert (exp / "report" / "html" / f"method-{m}.html").is_file()


def test_refusals(tmp_path: pathlib.Path) -> None:
    mine = tmp_path / "mine.html"
    mine.write_text("my page\n")
    with pytest.raises(nd.runs.RunError, match="is not a web page of duel_evolve") as e:
        pages.duel("forager", "hunter", mine)
    assert e.value.status == 2 and mine.read_text() == "my page\n"
    pages.duel("forager", "hunter", mine, force=True)
    assert mine.read_text().startswith("<!DOCTYPE html>")
    with pytest.raises(nd.runs.RunError, match="not a run directory"):
        pages.run(tmp_path, tmp_path / "out")
    with pytest.raises(nd.runs.RunError, match="'all', 'top' or 'none'"):
        pages.run(tmp_path, tmp_path / "out", games="some")  # type: ignore[arg-type]
    with pytest.raises(nd.ArgumentError):
        pages.duel("forager", "no-such-builtin", tmp_path / "x.html")
