"""Shared fixtures: the repository, the C programs the cross-language tests compare with (given by CTest)."""
from __future__ import annotations

import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def program(var: str) -> pathlib.Path:
    """The C program named by the environment variable var (CTest sets them), or the test is skipped."""
    p = os.environ.get(var)
    if not p:
        pytest.skip(f"{var} is not set (CTest sets it: ctest -R python/)")
    return pathlib.Path(p)


@pytest.fixture
def xor_ini() -> pathlib.Path:
    return ROOT / "bench" / "xor.ini"


XOR = ((0.0, 0.0, 0.0), (0.0, 1.0, 1.0), (1.0, 0.0, 1.0), (1.0, 1.0, 0.0))
