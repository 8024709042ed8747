"""A champion for a microcontroller: its blob as a C array and header, written by duel_evolve export's own library.

    from neat_duel import deploy
    deploy.export_c(net, "champion", "champion.c", header="champion.h")

The C file holds the blob (docs/formats.md) as `const uint8_t NAME[]` and its length; the header declares them.
A firmware loads it with nrt_load (docs/firmware.md). The command's rules for outputs hold: an existing file that
is not a C file from export is refused unless force (docs/tools.md, "Outputs").
"""
from __future__ import annotations

import os
from typing import Union

from ._core import Network, export_c as _export_c
from .runs import RunError

PathLike = Union[str, "os.PathLike[str]"]


def export_c(net: Network, name: str, c_file: PathLike, *, header: PathLike | None = None, force: bool = False) -> None:
    """duel_evolve export BLOB --c-array NAME -o C_FILE [--header HEADER]: net's blob as C source (and a header).
    RunError with the command's message when it refuses (a bad name, a file that is not its output)."""
    status, message = _export_c(net.blob, name, os.fspath(c_file), os.fspath(header) if header is not None else "",
                                force)
    if status != 0:
        raise RunError(message, status, os.fspath(c_file))

__all__ = ["export_c"]
