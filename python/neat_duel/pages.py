"""Web pages of duels, runs and experiments, written by duel_evolve's own library (docs/render.md, "Web pages").

    from neat_duel import pages
    pages.duel(champion, "forager-hunter", "duel.html", a_name="gen-00127")   # one game, one file
    pages.run("runs/quick", "quick-pages")                                    # quick-pages/index.html
    pages.experiment("runs/paper")                                            # runs/paper/report/html/

Each page is one self-contained HTML file (the viewer and the data inline, no network access) that opens from a
file:// URL. The command's rules for outputs hold: an existing file that is not such a page is refused unless
force, and a page never replaces a run's own file.
"""
from __future__ import annotations

import os
from typing import Literal, Union

from ._core import DuelConfig, Network, duel_page as _duel_page, html_pages as _html_pages
from .runs import RunError

PathLike = Union[str, "os.PathLike[str]"]
Games = Literal["all", "top", "none"]


def duel(a: Network | str, b: Network | str, path: PathLike, *, food: int = -1, a_west: bool = True,
         config: DuelConfig | None = None, a_name: str = "a", b_name: str = "b", force: bool = False) -> None:
    """duel_evolve render A B --html PATH: one game (food -1 the training items, 0..143 a comparison layout; a
    west unless a_west is False; in config's world, v1 by default) as a web page. a and b: Networks or built-in
    strategies' names; a_name and b_name are what the page calls them. RunError when the page is refused."""
    status, message = _duel_page(a, b, os.fspath(path), food, a_west, config, a_name, b_name, force)
    if status != 0:
        raise RunError(message, status, os.fspath(path))


def run(directory: PathLike, out: PathLike, *, games: Games = "all", embed: bool = False, force: bool = False) -> int:
    """duel_evolve report RUN --html OUT: the run's page (OUT/index.html: its curves and dominance ladder) and its
    levels' games (OUT/games/*.html, or inside the page when embed). Returns the number of pages written."""
    status, message, pages = _html_pages(os.fspath(directory), os.fspath(out), False, games, embed, force)
    if status != 0:
        raise RunError(message, status, os.fspath(directory))
    return pages


def experiment(directory: PathLike, *, games: Games = "top", embed: bool = False, force: bool = False) -> int:
    """duel_evolve experiment report DIR --html, after the report exists: DIR/report/html/index.html (Table 1, the
    figures) and a page per method. Returns the number of pages written."""
    out = os.path.join(os.fspath(directory), "report", "html")
    status, message, pages = _html_pages(os.fspath(directory), out, True, games, embed, force)
    if status != 0:
        raise RunError(message, status, os.fspath(directory))
    return pages


__all__ = ["duel", "run", "experiment"]
