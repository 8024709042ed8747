"""The exceptions of neat_duel: one class a C error code, each with the C library's message."""
from __future__ import annotations


class NeatError(Exception):
    """An error the C libraries reported.

    Attributes:
        code: the C error code (neat.h's neat_error; an nrt_error - 100 for a blob the runtime refused).
        path: the file concerned, or None.
        offset: the byte offset of the problem in that file (or bytes), or None.
        index: the genome concerned (a refused fitness), or None.
    """

    def __init__(
        self,
        message: str,
        code: int = 0,
        path: str | None = None,
        offset: int | None = None,
        index: int | None = None,
    ) -> None:
        super().__init__(message)
        self.code = code
        self.path = path
        self.offset = offset
        self.index = index


class ArgumentError(NeatError, ValueError):
    """A bad argument: a wrong shape, a count out of range (NEAT_E_ARG)."""


class OutOfMemoryError(NeatError, MemoryError):
    """The allocator refused (NEAT_E_NOMEM)."""


class ParamError(NeatError, ValueError):
    """A parameter unknown or out of its range, or an INI file that does not read (NEAT_E_PARAM)."""


class FitnessError(NeatError, ValueError):
    """A fitness that is negative, NaN or infinite, or missing at epoch (NEAT_E_FITNESS); index names the genome."""


class TooBigError(NeatError, ValueError):
    """A network too large for the blob format: more than 256 nodes or 65535 connections (NEAT_E_TOOBIG)."""


class FormatError(NeatError, ValueError):
    """Bytes that are not a valid checkpoint, genome file or blob: magic, version, size, checksum or value."""


class StateError(NeatError, RuntimeError):
    """A call out of order (NEAT_E_STATE)."""


class CountersError(NeatError, OverflowError):
    """Node ids, innovation numbers, species ids or generations at their limit, 2^31 - 1 (NEAT_E_COUNTERS)."""


__all__ = [
    "NeatError",
    "ArgumentError",
    "OutOfMemoryError",
    "ParamError",
    "FitnessError",
    "TooBigError",
    "FormatError",
    "StateError",
    "CountersError",
]
