"""duel_evolve's runs from Python: the command's own run and resume, in this process, and a run directory read back.

A run started here is a duel_evolve run directory (config.ini, checkpoint.bin, generations.csv, dominance.csv,
champions/, log.txt): ``duel_evolve resume`` continues it, and ``resume`` here continues the command's. Every
refusal is the command's (a directory that is not a run, a hand-edited config.ini, lost records: docs/tools.md,
docs/hardening.md), raised as RunError with its message::

    from neat_duel import runs

    r = runs.run("configs/quick.ini", "runs/mine", generations=20)
    r = runs.resume("runs/mine", generations=40)
    print(r.dominants()[-1], r.champion(r.dominants()[-1]["generation"]))
"""
from __future__ import annotations

import json
import os
import pathlib
import tempfile
from typing import Any, Iterable, Union

from ._core import Coevolution, DuelConfig, Genome, Network, read_dominance, read_generations, run_command
from .errors import NeatError

PathLike = Union[str, "os.PathLike[str]"]


class RunError(NeatError):
    """duel_evolve's run or resume refused or failed: status is its exit status (2: the input's fault, 1: the
    machine's, 130: interrupted), the message its lines on stderr."""

    def __init__(self, message: str, status: int, path: str | None = None) -> None:
        super().__init__(message, 0, path)
        self.status = status


class RunDir:
    """A run directory (docs/tools.md, "The run directory"), read through duel_evolve's readers."""

    def __init__(self, path: PathLike) -> None:
        self.path = pathlib.Path(path)
        if not (self.path / "config.ini").is_file():
            raise FileNotFoundError(f"{self.path}: not a run directory (no config.ini)")

    def config(self) -> DuelConfig:
        """The run's configuration (its config.ini)."""
        return DuelConfig.from_ini(str(self.path / "config.ini"))

    def checkpoint(self) -> Coevolution:
        """The coevolution in its checkpoint.bin (a coevolution run's; Coevolution.load)."""
        return Coevolution.load(str(self.path / "checkpoint.bin"))

    def generations(self) -> list[dict[str, Any]]:
        """generations.csv's checked fields, a record per population and generation (FormatError on a damaged
        file, with what works: docs/hardening.md)."""
        return read_generations(str(self.path))

    def dominants(self) -> list[dict[str, Any]]:
        """dominance.csv: level, generation, population, hidden, connections, and its wins and losses against every
        level below (the last one first)."""
        return read_dominance(str(self.path))

    def champion(self, generation: int) -> Genome:
        """Generation's champion (champions/gen-G.genome)."""
        return Genome.load(str(self.path / "champions" / f"gen-{generation:05d}.genome"))

    def champion_network(self, generation: int) -> Network:
        """Generation's champion blob (champions/gen-G.blob): the network duel_evolve plays and exports."""
        return Network.load(str(self.path / "champions" / f"gen-{generation:05d}.blob"))

    def __repr__(self) -> str:
        return f"RunDir({str(self.path)!r})"


def _call(command: str, args: list[str], path: str, keep_stdout: bool = False) -> str:
    status, out, text = run_command(command, args, keep_stdout)
    if status == 130:
        raise KeyboardInterrupt(text.strip() or "interrupted")
    if status != 0:
        lines = [x for x in text.splitlines() if x.strip()]
        raise RunError(lines[-1] if lines else f"duel_evolve {command}: exit status {status}", status, path)
    return out


def _options(generations: int | None, threads: int | None, sets: str | Iterable[str], quiet: bool) -> list[str]:
    a: list[str] = []
    if isinstance(sets, (str, bytes)):
        sets = [os.fsdecode(sets)]  # one override, not its characters one by one
    if generations is not None:
        a += ["--generations", str(generations)]
    if threads is not None:
        a += ["--threads", str(threads)]
    for s in sets:
        a += ["--set", s]
    if quiet:
        a.append("--quiet")
    return a


def run(
    config: PathLike | DuelConfig,
    out: PathLike,
    *,
    generations: int | None = None,
    seed: int | None = None,
    threads: int | None = None,
    set: str | Iterable[str] = (),
    quiet: bool = True,
) -> RunDir:
    """duel_evolve run --config CONFIG --out OUT: a coevolution (or a run against fixed opponents) into a new run
    directory. config is a configuration file or a DuelConfig; set is one KEY=VALUE override or a list of them
    (as --set). Returns
    the run directory; RunError with the command's message when it refuses or fails."""
    args = ["--out", os.fspath(out)] + _options(generations, threads, set, quiet)
    if seed is not None:
        args += ["--seed", str(seed)]
    if isinstance(config, DuelConfig):
        with tempfile.NamedTemporaryFile("w", suffix=".ini", delete=False) as f:
            f.write(config.to_ini())
        try:
            _call("run", ["--config", f.name] + args, os.fspath(out))
        finally:
            os.unlink(f.name)
    else:
        _call("run", ["--config", os.fspath(config)] + args, os.fspath(out))
    return RunDir(out)


def resume(
    directory: PathLike,
    *,
    generations: int | None = None,
    threads: int | None = None,
    set: str | Iterable[str] = (),
    quiet: bool = True,
    shorten: bool = False,
) -> RunDir:
    """duel_evolve resume DIR: continues a run (to generations in all, when given; a finished run is only
    repaired). shorten: fewer generations in all than config.ini's, for good (--shorten). set: one KEY=VALUE
    override or a list of them. RunError with the command's message when it refuses or fails."""
    args = [os.fspath(directory)] + _options(generations, threads, set, quiet)
    if shorten:
        args.append("--shorten")
    _call("resume", args, os.fspath(directory))
    return RunDir(directory)


def ladder(
    directory: PathLike,
    *,
    top: bool = False,
    levels: tuple[int, int] | None = None,
    against: Iterable[str] = (),
) -> dict[str, Any]:
    """duel_evolve ladder DIR --json: every dominant (or the top one, or levels L1..L2) against the built-in
    strategies (or those named in against), 288 games each. The command's JSON as a dict: run, world, games,
    against, levels (each with results per strategy, total_wins, total_losses)."""
    args = [os.fspath(directory), "--json"]
    if top:
        args.append("--top")
    if levels is not None:
        args += ["--levels", f"{levels[0]}-{levels[1]}"]
    names = list(against)
    if names:
        args += ["--against", ",".join(names)]
    result: dict[str, Any] = json.loads(_call("ladder", args, os.fspath(directory), keep_stdout=True))
    return result


def compare(
    candidates: Iterable[PathLike],
    against: Iterable[PathLike],
    *,
    threads: int | None = None,
    cache: PathLike | None = None,
) -> dict[str, Any]:
    """duel_evolve compare RUN... --against RUN...: the paper's performance measure, each candidate's top dominant
    against every dominant of every ranking run (its comparisons cached as the command caches them). The
    command's JSON summary and pairs as a dict."""
    cand = [os.fspath(c) for c in candidates]
    rank = [os.fspath(a) for a in against]
    if not cand or not rank:
        raise ValueError("compare: at least one candidate and one ranking run")
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "compare.json")
        args = cand + ["--against"] + rank + ["--json", out]
        if threads is not None:
            args += ["--threads", str(threads)]
        if cache is not None:
            args += ["--cache", os.fspath(cache)]
        _call("compare", args, cand[0], keep_stdout=True)
        with open(out) as f:
            result: dict[str, Any] = json.load(f)
    return result


__all__ = ["RunDir", "RunError", "run", "resume", "ladder", "compare"]
