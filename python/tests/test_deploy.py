"""A champion as C source for firmware: the same files duel_evolve export writes; the command's refusals."""
from __future__ import annotations

import pathlib
import shutil
import subprocess

import pytest

import neat_duel as nd
from neat_duel import deploy
from conftest import program


def test_export_is_duel_evolves(tmp_path: pathlib.Path) -> None:
    duel = program("DUEL_EVOLVE")
    net = nd.Population(nd.Params(pop_size=4), seed=3).genome(1).network()
    py, cli = tmp_path / "py", tmp_path / "cli"
    py.mkdir()
    cli.mkdir()
    deploy.export_c(net, "champion", py / "champion.c", header=py / "champion.h")
    net.save(str(cli / "champion.blob"))
    subprocess.run([str(duel), "export", str(cli / "champion.blob"), "--c-array", "champion", "-o",
                    str(cli / "champion.c"), "--header", str(cli / "champion.h")], check=True)
    assert (py / "champion.c").read_bytes() == (cli / "champion.c").read_bytes()
    assert (py / "champion.h").read_bytes() == (cli / "champion.h").read_bytes()
    if shutil.which("cc"):  # it compiles
        subprocess.run(["cc", "-std=c99", "-Wall", "-Werror", "-c", str(py / "champion.c"), "-I", str(py), "-o",
                        str(py / "champion.o")], check=True)


def test_export_refusals(tmp_path: pathlib.Path) -> None:
    net = nd.Population(nd.Params(pop_size=4), seed=3).genome(1).network()
    mine = tmp_path / "mine.c"
    mine.write_text("my code\n")
    with pytest.raises(nd.runs.RunError, match="exists and is not a C file from duel_evolve export") as e:
        deploy.export_c(net, "champion", mine)
    assert e.value.status == 2 and mine.read_text() == "my code\n"
    deploy.export_c(net, "champion", mine, force=True)
    assert "champion" in mine.read_text()
    with pytest.raises(nd.runs.RunError):
        deploy.export_c(net, "not a name", tmp_path / "x.c")
