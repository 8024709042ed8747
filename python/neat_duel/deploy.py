"""A champion for a microcontroller: its blob as a C array and header, written by duel_evolve export's own code.

    from neat_duel import deploy
    deploy.export_c(net, "champion", "champion.c", header="champion.h")

The C file holds the blob (docs/formats.md) as `const uint8_t NAME[]` and its length; the header declares them.
A firmware loads it with nrt_load (docs/firmware.md). The command's rules for outputs hold: an existing file that
is not a C file from export is refused unless force (docs/tools.md, "Outputs").
"""
from __future__ import annotations

import os
import tempfile
from typing import Union

from ._core import Network
from .runs import _call

PathLike = Union[str, "os.PathLike[str]"]


def export_c(net: Network, name: str, c_file: PathLike, *, header: PathLike | None = None, force: bool = False) -> None:
    """duel_evolve export BLOB --c-array NAME -o C_FILE [--header HEADER]: net's blob as C source (and a header).
    RunError with the command's message when it refuses (a bad name, a file that is not its output)."""
    with tempfile.TemporaryDirectory() as d:
        blob = os.path.join(d, f"{name}.blob")  # the files name their source: NAME.blob, as `export NAME.blob` does
        with open(blob, "wb") as f:
            f.write(net.blob)
        args = [blob, "--c-array", name, "-o", os.fspath(c_file)]
        if header is not None:
            args += ["--header", os.fspath(header)]
        if force:
            args.append("--force")
        _call("export", args, os.fspath(c_file))


__all__ = ["export_c"]
