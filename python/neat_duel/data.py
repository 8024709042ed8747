"""The repository's configuration files, shipped inside the package: the run configurations and experiment plans
of configs/ and neat_bench's bench/xor.ini, so that the guide's examples work after `pip install` as in a clone."""
from __future__ import annotations

import pathlib

_ROOT = pathlib.Path(__file__).resolve().parent / "data"


def data_path(name: str) -> pathlib.Path:
    """The packaged copy of the repository file name ("configs/quick.ini", "configs/plans/small.ini",
    "bench/xor.ini"). FileNotFoundError names the files there when it is not one of them."""
    p = (_ROOT / name).resolve()
    if _ROOT not in p.parents or not p.is_file():
        have = sorted(str(f.relative_to(_ROOT)) for f in _ROOT.rglob("*.ini"))
        raise FileNotFoundError(f"{name}: not a file shipped with neat_duel (shipped: {', '.join(have)})")
    return p


__all__ = ["data_path"]
