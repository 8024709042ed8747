"""docs/python.md, docs/envs.md and the README: every ```python block runs, in order, in one namespace (as a reader types them)."""
from __future__ import annotations

import importlib.util
import os
import pathlib
import re

import pytest

from conftest import ROOT


def blocks(doc: str) -> list[str]:
    text = (ROOT / doc).read_text()
    if doc == "README.md":  # its section on the package (its other Python is LCM's: docs/lcm.md)
        text = text[text.index("\n## Python\n") :]
        text = text[: text.index("\n## ", 1)]
    return re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)


@pytest.mark.parametrize("doc, at_least", [("docs/python.md", 8), ("README.md", 1), ("docs/envs.md", 3)])
def test_the_guide_runs(doc: str, at_least: int, tmp_path: pathlib.Path, monkeypatch: pytest.MonkeyPatch) -> None:
    if doc == "docs/envs.md" and importlib.util.find_spec("pettingzoo") is None:
        pytest.skip("pettingzoo is not installed (neat_duel[envs]): docs/envs.md's python blocks were not run")
    found = blocks(doc)
    assert len(found) >= at_least
    # the guide's paths are the repository's: bench/, configs/ from the directory it runs in
    for d in ("bench", "configs"):
        os.symlink(ROOT / d, tmp_path / d)
    monkeypatch.chdir(tmp_path)
    ns: dict[str, object] = {"__name__": "__guide__"}
    # the Gymnasium blocks need the optional extra (neat_duel[gym]; the test environment has it): without it they
    # are left out, as test_gym skips, and the test says so once the others have run
    no_gym = importlib.util.find_spec("gymnasium") is None
    left_out = []
    for i, code in enumerate(found):
        if no_gym and re.search(r"\bgym\b", code):
            left_out.append(i + 1)
            continue
        try:
            exec(compile(code, f"{doc} block {i + 1}", "exec"), ns)
        except Exception as e:  # name the block
            raise AssertionError(f"{doc}, python block {i + 1} fails: {e!r}\n{code}") from e
    if left_out:
        pytest.skip(f"gymnasium is not installed: {doc}'s python blocks {left_out} were not run (the others passed)")
