"""duel_evolve's runs from Python: the run engine the command runs on, in this process, generation by generation.

A run started here is a duel_evolve run directory (config.ini, checkpoint.bin, generations.csv, dominance.csv,
champions/, log.txt): ``duel_evolve resume`` continues it, and ``resume`` here continues the command's, to the same
bytes. Every refusal is the engine's, the command's too (a directory that is not a run, a hand-edited config.ini,
lost records: docs/tools.md, docs/hardening.md), raised as RunError with its message. The games are played in C
with the interpreter lock released; two runs (each in its own directory) may go on in two threads::

    from neat_duel import runs

    with runs.Run.start("configs/quick.ini", "runs/mine", generations=20) as run:
        for g in run.generations():          # one generation at a time, each saved before it is yielded
            print(g.generation, g.dominants)
            if g.dominants >= 8:
                break                        # the run stays resumable
    r = runs.resume("runs/mine", generations=40)   # the whole rest in one call
    print(r.dominants()[-1], r.champion(r.dominants()[-1]["generation"]))

Reporters, as in neat-python: ``Run.start(..., reporters=[runs.StdOutReporter(), stats])``, each told of the run's
start, of every generation and of its end (``Reporter``; ``StatisticsReporter``, ``Checkpointer``).
"""
from __future__ import annotations

import csv
import json
import io
import os
import pathlib
import shutil
import sys
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Iterator, NoReturn, Union

from ._core import (Coevolution, DuelConfig, Genome, Network, RunEngine, compare_json, ladder_json, read_dominance,
                    read_generations)
from .errors import NeatError

PathLike = Union[str, "os.PathLike[str]"]

# the engine's kinds of line (duel_engine.h, duel_say_kind)
_SAY_ERROR, _SAY_NOTE, _SAY_INFO = 0, 1, 2


class RunError(NeatError):
    """The run engine refused or failed (as duel_evolve run or resume would): status is the command's exit status
    (2: the input's fault, 1: the machine's), the message the engine's line."""

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


def _value(text: str) -> Any:
    """A CSV field as the number it writes, or the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _rows(header: str, text: str | None) -> list[dict[str, Any]]:
    if not text:
        return []
    names = next(csv.reader([header]))
    return [dict(zip(names, (_value(v) for v in row))) for row in csv.reader(io.StringIO(text)) if row]


def _first(rows: list[dict[str, Any]]) -> dict[str, Any] | None:
    return rows[0] if rows else None


@dataclass(frozen=True)
class Generation:
    """A generation the run played and saved (its files written, the checkpoint replaced), as the engine recorded
    it. rows are its generations.csv rows (two for a coevolution: populations A and B; one against fixed
    opponents), dominance its new dominance.csv row (None unless a new dominant), strength its strength.csv row
    (None unless measured), each a dict of the file's columns."""

    generation: int
    generations: int
    seconds: float
    games: int
    champion: str | None
    champion_wins: tuple[int, int] | None
    new_dominant: bool
    dominants: int
    dominant_generation: int
    dominant_hidden: int
    dominant_connections: int
    rows: list[dict[str, Any]] = field(default_factory=list)
    dominance: dict[str, Any] | None = None
    strength: dict[str, Any] | None = None


class Reporter:
    """What a run tells its reporters (neat-python's reporters): override any of the three."""

    def start(self, run: "Run") -> None:
        """The run is open at run.generation (0 for a new run)."""

    def generation(self, run: "Run", record: Generation) -> None:
        """A generation was played and saved."""

    def end(self, run: "Run") -> None:
        """The run is closed (at its end, a stop or an error)."""


class StdOutReporter(Reporter):
    """A line a generation on stdout (or the stream given)."""

    def __init__(self, stream: Any = None) -> None:
        self.stream = stream

    def generation(self, run: "Run", record: Generation) -> None:
        out = self.stream if self.stream is not None else sys.stdout
        best = " ".join(f"{r.get('population', '')} {r['best_fitness']:.0f}".strip() for r in record.rows)
        dom = f"  dominance {record.dominants}{' new' if record.new_dominant else ''}" if record.champion else ""
        print(f"gen {record.generation} ({record.generation + 1}/{record.generations})  best {best}{dom}  "
              f"{record.games} games in {record.seconds:.2f} s", file=out, flush=True)


class StatisticsReporter(Reporter):
    """Every generation's record, kept: records, and rows() as a list of flat dicts (pandas.DataFrame(rows()))."""

    def __init__(self) -> None:
        self.records: list[Generation] = []

    def generation(self, run: "Run", record: Generation) -> None:
        self.records.append(record)

    def rows(self) -> list[dict[str, Any]]:
        """One dict a generations.csv row (a coevolution's two populations apart), with the generation's seconds,
        dominance level and, where measured, its strength columns."""
        out = []
        for r in self.records:
            for row in r.rows:
                d = dict(row)
                d["dominants"] = r.dominants
                if r.strength is not None:
                    d.update({k: v for k, v in r.strength.items() if k != "generation"})
                out.append(d)
        return out


class Checkpointer(Reporter):
    """Every `every` generations, a copy of the run's checkpoint as PREFIX + generation + ".bin" (written to a
    temporary file then renamed); the run directory checkpoints every generation by itself, and these copies are
    for going back (Coevolution.load). every >= 1."""

    def __init__(self, every: int, prefix: PathLike = "neat-checkpoint-") -> None:
        if every < 1:
            raise ValueError("Checkpointer: every must be at least 1")
        self.every = every
        self.prefix = os.fspath(prefix)

    def generation(self, run: "Run", record: Generation) -> None:
        if (record.generation + 1) % self.every != 0:
            return
        dest = f"{self.prefix}{record.generation + 1}.bin"
        tmp = dest + ".tmp"
        shutil.copyfile(run.path / "checkpoint.bin", tmp)
        os.replace(tmp, dest)


def _sets(sets: str | Iterable[str]) -> list[str]:
    if isinstance(sets, (str, bytes)):
        return [os.fsdecode(sets)]  # one override, not its characters one by one
    return [os.fsdecode(x) for x in sets]


class Run:
    """A run open in this process: Run.start makes a new one, Run.resume opens one again. The directory is locked
    while it is open (a second opener, here or duel_evolve, is refused); close() (or the with block) gives it back.
    Each generation is played in C with the interpreter lock released; Ctrl-C, an exception in a reporter or
    stop() lets the generation in flight finish and be saved, so the run stays resumable."""

    def __init__(self, engine: RunEngine, reporters: Iterable[Reporter] = (), quiet: bool = True) -> None:
        self._engine: RunEngine | None = engine
        self.path = pathlib.Path(engine.directory)
        self.quiet = quiet
        self.reporters: list[Reporter] = list(reporters)
        self._headers: dict[str, str] = {}
        self._show(engine.take_lines())
        for r in self.reporters:
            r.start(self)

    @staticmethod
    def _raise(status: int, lines: list[tuple[int, str]], path: str, what: str) -> NoReturn:
        errors = [t for k, t in lines if k == _SAY_ERROR]
        raise RunError(errors[-1] if errors else f"{what}: status {status}", status, path)

    @classmethod
    def start(
        cls,
        config: PathLike | DuelConfig,
        out: PathLike,
        *,
        generations: int | None = None,
        seed: int | None = None,
        threads: int | None = None,
        set: str | Iterable[str] = (),
        reporters: Iterable[Reporter] = (),
        quiet: bool = True,
    ) -> "Run":
        """A new run of config (a configuration file or a DuelConfig) in out, as duel_evolve run --config CONFIG
        --out OUT [--set KEY=VALUE ...] [--seed S] [--generations N] [--threads T] makes it. RunError when refused."""
        if isinstance(config, DuelConfig):
            cfg, name = config, "(DuelConfig)"
        else:
            name = os.fspath(config)
            cfg = DuelConfig.from_ini(name)
        eng, status, lines = RunEngine.new(cfg, os.fspath(out), threads or 0, _sets(set),
                                           -1 if seed is None else seed, generations or 0, name)
        _show_notes(lines, quiet)
        if eng is None:
            cls._raise(status, lines, os.fspath(out), "run")
        return cls(eng, reporters, quiet)

    @classmethod
    def resume(
        cls,
        directory: PathLike,
        *,
        generations: int | None = None,
        threads: int | None = None,
        set: str | Iterable[str] = (),
        shorten: bool = False,
        reporters: Iterable[Reporter] = (),
        quiet: bool = True,
    ) -> "Run":
        """The run in directory opened again, as duel_evolve resume DIR [--generations N [--shorten]] [--set ...]:
        checked against its checkpoint, lost records rebuilt, the overrides applied from its next generation."""
        eng, status, lines = RunEngine.resume(os.fspath(directory), threads or 0, _sets(set), generations or 0,
                                              shorten)
        _show_notes(lines, quiet)
        if eng is None:
            cls._raise(status, lines, os.fspath(directory), "resume")
        return cls(eng, reporters, quiet)

    def _show(self, lines: list[tuple[int, str]]) -> None:
        _show_notes(lines, self.quiet)

    def _open(self) -> RunEngine:
        if self._engine is None:
            raise RunError("the run is closed", 2, str(self.path))
        return self._engine

    @property
    def generation(self) -> int:
        """The generation to play next."""
        return self._open().generation

    @property
    def total(self) -> int:
        """The run's total of generations."""
        return self._open().generations

    @property
    def directory(self) -> RunDir:
        """The run directory, to read (its files are whole between generations)."""
        return RunDir(self.path)

    def add_reporter(self, reporter: Reporter) -> None:
        self.reporters.append(reporter)
        reporter.start(self)

    def _header(self, name: str) -> str:
        if name not in self._headers:
            with open(self.path / name) as f:
                self._headers[name] = f.readline()
        return self._headers[name]

    def _record(self, d: dict[str, Any]) -> Generation:
        return Generation(
            generation=d["generation"], generations=d["generations"], seconds=d["seconds"], games=d["games"],
            champion=d["champion"], champion_wins=d.get("champion_wins"), new_dominant=d["new_dominant"],
            dominants=d["dominants"], dominant_generation=d["dominant_generation"],
            dominant_hidden=d["dominant_hidden"], dominant_connections=d["dominant_connections"],
            rows=self._parse("generations.csv", d["generations_rows"]),
            dominance=_first(self._parse("dominance.csv", d["dominance_row"])),
            strength=_first(self._parse("strength.csv", d["strength_row"])))

    def _parse(self, name: str, text: str | None) -> list[dict[str, Any]]:
        return _rows(self._header(name), text) if text else []

    def generations(self, n: int | None = None) -> Iterator[Generation]:
        """Plays up to n generations (None: to the run's total), yielding each once it is saved; the reporters
        have seen it first. Leaving the loop early leaves the run whole, at the next generation."""
        eng = self._open()
        played = 0
        while (n is None or played < n) and eng.generation < eng.generations:
            got: list[dict[str, Any]] = []
            lines: list[tuple[int, str]] = []
            try:
                status = eng.step(1, got.append)
            finally:
                lines = eng.take_lines()
                self._show(lines)
                for d in got:  # a generation saved before Ctrl-C or an error is still reported
                    rec = self._record(d)
                    for r in self.reporters:
                        r.generation(self, rec)
            if status not in (0, 130):
                self._raise(status, lines, str(self.path), "step")
            for d in got:
                played += 1
                yield self._record(d)
            if status == 130 or not got:
                return

    def play(self, n: int | None = None, *, until: Callable[[Generation], object] | None = None) -> RunDir:
        """Plays up to n generations (None: to the run's total), or until until(record) is true; returns the run
        directory. The run stays open (close() or a with block)."""
        for rec in self.generations(n):
            if until is not None and until(rec):
                break
        return self.directory

    def stop(self) -> None:
        """The generation in flight is the last (from any thread); generations() then ends."""
        if self._engine is not None:
            self._engine.stop()

    def close(self) -> None:
        """Writes the run's last lines into log.txt and unlocks the directory; the reporters' end."""
        if self._engine is None:
            return
        eng, self._engine = self._engine, None
        status = eng.close()
        self._show(eng.take_lines())
        for r in self.reporters:
            r.end(self)
        if status != 0:
            raise RunError(f"{self.path}/log.txt could not be written (the run is saved)", status, str(self.path))

    def __enter__(self) -> "Run":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        state = "closed" if self._engine is None else f"at generation {self.generation} of {self.total}"
        return f"Run({str(self.path)!r}, {state})"


def _show_notes(lines: list[tuple[int, str]], quiet: bool) -> None:
    """The engine's notes on stderr as the command shows them (errors are raised instead), and its information
    unless quiet."""
    for kind, text in lines:
        if kind == _SAY_NOTE:
            print(f"duel_evolve: {text}", file=sys.stderr)
        elif kind == _SAY_INFO and not quiet:
            print(text, file=sys.stderr)


def run(
    config: PathLike | DuelConfig,
    out: PathLike,
    *,
    generations: int | None = None,
    seed: int | None = None,
    threads: int | None = None,
    set: str | Iterable[str] = (),
    quiet: bool = True,
    reporters: Iterable[Reporter] = (),
) -> RunDir:
    """duel_evolve run --config CONFIG --out OUT: a coevolution (or a run against fixed opponents) into a new run
    directory, played to its end. config is a configuration file or a DuelConfig; set is one KEY=VALUE override or
    a list of them (as --set). Returns the run directory; RunError with the engine's message when it refuses or
    fails; KeyboardInterrupt after the generation in flight is saved (resume continues)."""
    rep = list(reporters) + ([] if quiet else [StdOutReporter(sys.stderr)])
    with Run.start(config, out, generations=generations, seed=seed, threads=threads, set=set, reporters=rep,
                   quiet=quiet) as r:
        return r.play()


def resume(
    directory: PathLike,
    *,
    generations: int | None = None,
    threads: int | None = None,
    set: str | Iterable[str] = (),
    quiet: bool = True,
    shorten: bool = False,
    reporters: Iterable[Reporter] = (),
) -> RunDir:
    """duel_evolve resume DIR: continues a run to its end (to generations in all, when given; a finished run is
    only repaired). shorten: fewer generations in all than config.ini's, for good (--shorten). set: one KEY=VALUE
    override or a list of them. RunError with the engine's message when it refuses or fails."""
    rep = list(reporters) + ([] if quiet else [StdOutReporter(sys.stderr)])
    with Run.resume(directory, generations=generations, threads=threads, set=set, shorten=shorten, reporters=rep,
                    quiet=quiet) as r:
        return r.play()


def ladder(
    directory: PathLike,
    *,
    top: bool = False,
    levels: tuple[int, int] | None = None,
    against: Iterable[str] = (),
) -> dict[str, Any]:
    """duel_evolve ladder DIR --json, by the command's own library (the same games, JSON and DIR/ladder.csv): every
    dominant (or the top one, or levels L1..L2) against the built-in strategies (or those named in against), 288
    games each. The command's JSON as a dict: run, world, games, against, levels (each with results per strategy,
    total_wins, total_losses). RunError with the command's message when it refuses or fails."""
    lo, hi = levels if levels is not None else (0, 0)
    if levels is not None and (lo < 1 or hi < lo):
        raise RunError(f"ladder: --levels takes L or L1-L2 (levels from 1), not '{lo}-{hi}'", 2,
                       os.fspath(directory))
    status, text, message = ladder_json(os.fspath(directory), top, lo, hi, list(against))
    if status != 0:
        raise RunError(message, status, os.fspath(directory))
    result: dict[str, Any] = json.loads(text)
    return result


def compare(
    candidates: Iterable[PathLike],
    against: Iterable[PathLike],
    *,
    threads: int | None = None,
    cache: PathLike | None = None,
) -> dict[str, Any]:
    """duel_evolve compare RUN... --against RUN... --json, by the command's own library: the paper's performance
    measure, each candidate's top dominant against every dominant of every ranking run (its comparisons cached as
    the command caches them). The command's JSON summary and pairs as a dict; RunError with its message when it
    refuses or fails. One comparison at a time in a process (StateError for a second at once)."""
    cand = [os.fspath(c) for c in candidates]
    rank = [os.fspath(a) for a in against]
    if not cand or not rank:
        raise ValueError("compare: at least one candidate and one ranking run")
    status, text, message = compare_json(cand, rank, threads or 0, os.fspath(cache) if cache is not None else "")
    if status != 0:
        raise RunError(message, status, cand[0])
    result: dict[str, Any] = json.loads(text)
    return result


__all__ = ["Checkpointer", "Generation", "Reporter", "Run", "RunDir", "RunError", "StatisticsReporter", "StdOutReporter",
           "compare", "ladder", "resume", "run"]
