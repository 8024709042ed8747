#!/usr/bin/env python3
"""doc_figures.py BUILD_DIR [--write] - the deterministic figures the docs quote, measured again and checked.

A figure in README.md or docs/*.md is marked by an HTML comment right after it, invisible when
the page is rendered: `1,968<!--fig:rt_m0_total-->`. This script measures every named figure
(code sizes from the Cortex-M0+ cross build, instructions per step under QEMU -icount and stack
depths from scripts/firmware_figures.sh, neat_bench's evaluation counts for a fixed seed), then
checks that each marked number is the measured one, listing every one that is not (exit 1), or
with --write puts the measured numbers in place. Figures that depend on the machine's speed are
never marked. Exit 77 when the cross tools or QEMU are missing (CTest: skipped).
"""
import json
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MARK = re.compile(r"([0-9][0-9,]*(?:\.[0-9]+)?)<!--fig:([a-z0-9_]+)-->")


def grouped(x):
    """an integer as the docs print it: 25,250"""
    return f"{int(x + 0.5):,}"


def firmware(build):
    out = subprocess.run(["bash", os.path.join(ROOT, "scripts", "firmware_figures.sh"), build],
                         capture_output=True, text=True)
    if out.returncode == 77:
        print(out.stdout.strip())
        sys.exit(77)
    if out.returncode != 0:
        sys.exit("doc_figures.py: scripts/firmware_figures.sh failed:\n" + out.stdout + out.stderr)
    text = out.stdout
    f = {}
    # the runtime's objects and total, then duelsim's total, on the Cortex-M0+
    sizes = re.findall(r"^\s*(\d+)\s+\d+\s+\d+\s+\d+\s+[0-9a-f]+\s+(\S+)$", text, re.M)
    seen_total = 0
    for size, name in sizes:
        n = int(size)
        if name == "nrt_load.c.obj":
            f["rt_m0_load"] = grouped(n)
        elif name == "nrt_step.c.obj":
            f["rt_m0_step"] = grouped(n)
        elif name == "nrt_sigmoid.c.obj":
            f["rt_m0_sigmoid"] = grouped(n)
        elif name == "(TOTALS)":
            f["rt_m0_total" if seen_total == 0 else "duelsim_m0_total"] = grouped(n)
            seen_total += 1
    # the runtime built sync-only (NRT_NO_PROPAGATE), where the 2 KiB target applies
    for name, size in re.findall(r"^sync-only (nrt_load|nrt_step|nrt_sigmoid)\.c: (\d+) bytes$", text, re.M):
        f["rt_m0_sync_" + name[4:]] = grouped(int(size))
    m = re.search(r"^runtime code \(text \+ data\): \d+ bytes with both step modes, (\d+) sync-only", text, re.M)
    if m:
        f["rt_m0_sync_total"] = grouped(int(m.group(1)))
    images = re.findall(r"^\s*(\d+)\s+(\d+)\s+(\d+)\s+\d+\s+[0-9a-f]+\s+(duels|figures)\.elf$", text, re.M)
    for t, d, b, name in images:
        f[f"fw_m0_{name}_text"] = grouped(int(t) + int(d))
        f[f"fw_m0_{name}_bss"] = grouped(int(b))
    # per core: the two champions' step, the game step, the stack
    cores = {"microbit": "m0", "mps2-an385": "m3", "sifive_e": "rv"}
    for block in re.split(r"^figures on ", text, flags=re.M)[1:]:
        core = cores.get(block.split(":")[0])
        if core is None:
            continue
        champs = re.findall(r"^champion ([AB]): (\d+) connections.*?blob (\d+) bytes \+ state (\d+) bytes.*?"
                            r"nrt_step ([0-9.]+) instructions \(([0-9.]+) per connection\)", block, re.M)
        conns_of = {}
        for who, conns, blob, state, step, per in champs:
            conns_of[who] = conns
            f[f"{core}_step{conns}"] = grouped(float(step))
            f[f"{core}_per{conns}"] = per
            f[f"blob{conns}"] = grouped(int(blob))
            f[f"state{conns}"] = grouped(int(state))
        # the same networks stepped in propagate mode
        for who, state, step, per in re.findall(r"^champion ([AB]), propagate: state (\d+) bytes; nrt_step ([0-9.]+) "
                                                r"instructions \(([0-9.]+) per connection\)", block, re.M):
            conns = conns_of.get(who)
            if conns is None:
                continue
            f[f"{core}_pstep{conns}"] = grouped(float(step))
            f[f"{core}_pper{conns}"] = per
            f[f"pstate{conns}"] = grouped(int(state))
        m = re.search(r"([0-9.]+) instructions per game step", block)
        if m:
            f[f"{core}_game"] = grouped(float(m.group(1)))
        m = re.search(r"^stack: (\d+) bytes", block, re.M)
        if m:
            f[f"{core}_stack"] = grouped(int(m.group(1)))
        m = re.search(r"^games image: (\d+) bytes of flash, (\d+) of bss", block, re.M)
        if m:
            f[f"{core}_image"] = grouped(int(m.group(1)))
            f[f"{core}_image_bss"] = grouped(int(m.group(2)))
    return f


def bench(build):
    """neat_bench xor as the docs run it: 100 runs from seed 1, deterministic on any thread count"""
    out = subprocess.run([os.path.join(build, "bin", "neat_bench"), "xor", "--quiet"], capture_output=True,
                         text=True, check=True)
    d = json.loads(out.stdout.strip().splitlines()[-1])
    return {"xor_mean": grouped(d["mean_evaluations"]), "xor_median": grouped(d["median_evaluations"]),
            "xor_hidden": f"{d['mean_hidden_nodes']:.2f}", "xor_failures": str(d["failures"])}


def main():
    args = [a for a in sys.argv[1:] if a != "--write"]
    write = "--write" in sys.argv[1:]
    if len(args) != 1:
        sys.exit(__doc__.splitlines()[0])
    build = os.path.abspath(args[0])
    for tool in ("arm-none-eabi-gcc", "qemu-system-arm"):
        if shutil.which(tool) is None:
            print(f"doc_figures.py: {tool} not installed (scripts/deps.sh): skipped")
            sys.exit(77)
    figs = firmware(build)
    figs.update(bench(build))
    pages = [os.path.join(ROOT, "README.md")] + sorted(
        os.path.join(ROOT, "docs", p) for p in os.listdir(os.path.join(ROOT, "docs")) if p.endswith(".md"))
    stale, unknown, marked = [], [], 0
    for page in pages:
        with open(page, encoding="utf-8") as fh:
            text = fh.read()
        rel = os.path.relpath(page, ROOT)

        def fix(m):
            nonlocal marked
            marked += 1
            value, name = m.group(1), m.group(2)
            line = text.count("\n", 0, m.start()) + 1
            if name not in figs:
                unknown.append(f"{rel}:{line}: no figure named {name}")
                return m.group(0)
            if value != figs[name]:
                stale.append(f"{rel}:{line}: {name} is {value}, measured {figs[name]}")
            return figs[name] + f"<!--fig:{name}-->"

        new = MARK.sub(fix, text)
        if write and new != text:
            tmp = page + ".tmp"
            with open(tmp, "w", encoding="utf-8") as fh:
                fh.write(new)
            os.replace(tmp, page)
    for line in unknown:
        print(line)
    for line in stale:
        print(("rewritten: " if write else "stale: ") + line)
    print(f"doc_figures.py: {marked} marked figures, {len(stale)} {'rewritten' if write else 'stale'}, "
          f"{len(unknown)} unknown; measured: {len(figs)}")
    if unknown or (stale and not write):
        sys.exit(1)


if __name__ == "__main__":
    main()
