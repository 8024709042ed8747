"""docs/python.md: every ```python block runs, in order, in one namespace (as a reader would type them)."""
from __future__ import annotations

import os
import pathlib
import re

import pytest

from conftest import ROOT


def blocks() -> list[str]:
    text = (ROOT / "docs" / "python.md").read_text()
    return re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)


def test_the_guide_runs(tmp_path: pathlib.Path, monkeypatch: pytest.MonkeyPatch) -> None:
    found = blocks()
    assert len(found) >= 8
    # the guide's paths are the repository's: bench/, configs/ from the directory it runs in
    for d in ("bench", "configs"):
        os.symlink(ROOT / d, tmp_path / d)
    monkeypatch.chdir(tmp_path)
    ns: dict[str, object] = {"__name__": "__guide__"}
    for i, code in enumerate(found):
        try:
            exec(compile(code, f"docs/python.md block {i + 1}", "exec"), ns)
        except Exception as e:  # name the block
            raise AssertionError(f"docs/python.md, python block {i + 1} fails: {e!r}\n{code}") from e
