#!/usr/bin/env python3
"""build_env.py SRC SITE - links into SITE (a bare venv's site-packages) the distributions pyproject.toml's
[build-system].requires names, and what they require in turn, from this interpreter's environment: the
environment pip's build isolation would give `pip install .`, without downloading anything."""
from __future__ import annotations

import importlib.metadata as md
import pathlib
import sys
import tomllib

from packaging.requirements import Requirement


def main() -> int:
    src, site = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    todo = [Requirement(r) for r in tomllib.loads((src / "pyproject.toml").read_text())["build-system"]["requires"]]
    done: set[str] = set()
    while todo:
        req = todo.pop()
        if req.marker is not None and not req.marker.evaluate({"extra": ""}):
            continue
        dist = md.distribution(req.name)
        key = dist.metadata["Name"].lower().replace("_", "-")
        if key in done:
            continue
        done.add(key)
        if dist.version not in req.specifier:
            print(f"build_env: {req} wanted, {dist.version} here", file=sys.stderr)
            return 1
        # every top-level entry the distribution installed (its packages, modules, .libs, .dist-info)
        tops = {pathlib.PurePath(f).parts[0] for f in dist.files or [] if not str(f).startswith("..")}
        for top in sorted(tops):
            target = pathlib.Path(str(dist.locate_file(top)))
            if target.exists() and not (site / top).exists():
                (site / top).symlink_to(target)
        todo += [Requirement(r) for r in dist.requires or []]
    print("build_env:", " ".join(sorted(done)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
