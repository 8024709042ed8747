#!/usr/bin/env python3
"""html_browser.py - the web pages in a real browser: Debian's Chromium, headless, driven through chromedriver.

Every page duel_evolve writes (render --html, report RUN --html, experiment report --html) is opened from a file://
URL; the test fails on any console message, on any request other than the page itself and data: URLs, and when what
the page drew differs from the game: positions, headings and energies against `play --trace`, which network nodes
are lit against the trace's inputs and outputs and against the hidden activations the runtime computes (stepped
here through the Python package), and pixels read back from the board's canvas. Hostile names (</script>, quotes,
control bytes, an <img onerror>) must come out as text. Screenshots go to OUT.

usage: html_browser.py DUEL_EVOLVE DUEL_BENCH FIXTURE_EXPERIMENT PYTHON_PACKAGE_DIR OUT
Exit 77 (skipped) when chromium, chromedriver or selenium is missing.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
except ImportError:
    print("skipped: python3-selenium is not installed (scripts/deps.sh installs it)")
    sys.exit(77)
if not (os.access(CHROMIUM, os.X_OK) and os.access(CHROMEDRIVER, os.X_OK)):
    print("skipped: chromium and chromium-driver are not installed (scripts/deps.sh installs them)")
    sys.exit(77)

duel, bench, fixture, pydir, out = sys.argv[1:6]
sys.path.insert(0, pydir)
import neat_duel as nd  # noqa: E402  (the package of this build: the runtime's own hidden activations)
import numpy  # noqa: E402

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def run(*args, **kw):
    return subprocess.run([duel, *args], check=True, capture_output=True, text=True, **kw).stdout


def browser():
    o = webdriver.ChromeOptions()
    o.binary_location = CHROMIUM
    # the background-networking flags keep Chromium's own requests (updates, sync) out of the network log
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
              "--disable-background-networking", "--disable-component-update", "--disable-sync",
              "--disable-dev-shm-usage", "--window-size=1400,1000", "--force-device-scale-factor=1"):
        o.add_argument(a)
    o.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=o)


def open_page(d, path, kind):
    """Loads path, waits for the page's hook, checks the console and the requests. Returns the page's URL."""
    url = "file://" + os.path.abspath(path)
    d.get_log("performance")  # what came before is not this page's
    d.get(url)
    for _ in range(100):
        if d.execute_script("return !!(window.duelPage && window.duelPage.ready)"):
            break
        time.sleep(0.05)
    check(d.execute_script("return !!(window.duelPage && window.duelPage.ready)"), f"{path}: the page never got ready")
    check(d.execute_script("return window.duelPage.kind") == kind, f"{path}: kind is not {kind}")
    check_quiet(d, path, url)
    return url


def check_quiet(d, path, url):
    """No console message at all, and no request but the page and data: URLs."""
    logs = d.get_log("browser")
    check(not logs, f"{path}: console messages: {logs}")
    errs = d.execute_script("return (window.duelPage && window.duelPage.errors) || []")
    check(not errs, f"{path}: errors the page caught: {errs}")
    for entry in d.get_log("performance"):
        msg = json.loads(entry["message"])["message"]
        if msg.get("method") == "Network.requestWillBeSent":
            u = msg["params"]["request"]["url"]
            check(u == url or u.startswith("data:"), f"{path}: a request to {u}")


def final_energies(play_output):
    """play's line 'energy: west W, east E; food eaten: ...' -> [W, E]"""
    m = re.search(r"energy: west ([0-9.]+), east ([0-9.]+);", play_output)
    return [float(m.group(1)), float(m.group(2))]


def trace_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_duel(d, page, blobs, trace, final_energy, shot):
    """The drawn state at several frames against the trace, the runtime's hidden activations and the canvas."""
    n = d.execute_script("return window.duelPage.frames")
    check(n == len(trace) + 1, f"{page}: {n} frames for a trace of {len(trace)} steps")
    # the hidden activations as the runtime computes them, from the trace's inputs
    hidden = []
    for s, blob in enumerate(blobs):
        if blob is None:
            hidden.append(None)
            continue
        net = nd.Network.load(blob)
        net.reset()
        side = "west" if s == 0 else "east"
        acts = []
        for row in trace:
            q = [round(float(row[f"{side}_in{i}"]) * 32768) for i in range(13)]
            net.step_q15(numpy.array(q, dtype=numpy.int16))
            acts.append([a / 32768 for a in net.activations[16:]])
        hidden.append(acts)
    frames = sorted({0, 1, 2, n // 3, n // 2, n - 2, n - 1})
    for t in frames:
        st = d.execute_script(f"window.duelPage.goto({t}); return window.duelPage.state()")
        check(st["t"] == t, f"{page}: goto({t}) drew frame {st['t']}")
        for s, side in enumerate(("west", "east")):
            r = st["robots"][s]
            if t < len(trace):
                row = trace[t]
                for key in ("x", "y", "heading", "energy"):
                    check(abs(r[key] - float(row[f"{side}_{key}"])) <= 1.5e-6,
                          f"{page}: frame {t} {side} {key} {r[key]} != trace {row[side + '_' + key]}")
            else:
                check(abs(r["energy"] - final_energy[s]) <= 1.5e-6,
                      f"{page}: final {side} energy {r['energy']} != play's {final_energy[s]}")
            # the robot's centre is drawn in its colour (west blue #1f77b4, east orange #ff7f0e)
            px = d.execute_script(f"return window.duelPage.pixel({r['x']}, {r['y']})")
            want = (0x1f, 0x77, 0xb4) if s == 0 else (0xff, 0x7f, 0x0e)
            check(all(abs(px[i] - want[i]) <= 40 for i in range(3)),
                  f"{page}: frame {t} {side} centre pixel {px} is not its colour {want}")
            # lit nodes: inputs and outputs from the trace (the step of frame t; the final frame shows the last step)
            tt = min(t, len(trace) - 1)
            lit = st["lit"][s]
            if lit is None:
                check(blobs[s] is None, f"{page}: {side} has a network but no lit nodes")
                continue
            row = trace[tt]
            for i in range(13):
                check(lit[i] == (float(row[f"{side}_in{i}"]) > 0.5), f"{page}: frame {t} {side} input {i} lit wrongly")
            for k in range(3):
                check(lit[13 + k] == (float(row[f"{side}_out{k}"]) > 0.5),
                      f"{page}: frame {t} {side} output {k} lit wrongly")
            for k, a in enumerate(hidden[s][tt]):
                check(abs(st["act"][s][16 + k] - a) <= 1.5e-6,
                      f"{page}: frame {t} {side} hidden {k}: drawn {st['act'][s][16 + k]}, runtime {a}")
                check(lit[16 + k] == (a > 0.5), f"{page}: frame {t} {side} hidden {k} lit wrongly")
        # a food item still on the board is drawn green at its centre
        mask = st["food_mask"]
        if t < len(trace):
            check(mask == int(trace[t]["food_mask"]), f"{page}: frame {t} food mask {mask} != trace")
    d.execute_script(f"window.duelPage.goto({n // 2})")
    d.save_screenshot(shot)
    check_quiet(d, page, "file://" + os.path.abspath(page))


def main():
    tmp = tempfile.mkdtemp(prefix="html-browser-")
    os.makedirs(out, exist_ok=True)
    d = browser()
    try:
        subprocess.run([bench, "--write-blobs", tmp], check=True, capture_output=True)
        a, b, c = (os.path.join(tmp, n) for n in ("net202a.blob", "net202b.blob", "net39a.blob"))

        # 1. a whole 750-step game of two 202-connection networks (20 hidden nodes each): the size bound
        g1 = os.path.join(tmp, "g1.html")
        run("render", a, b, "--html", g1)
        run("play", a, b, "--trace", os.path.join(tmp, "g1.csv"))
        size = os.path.getsize(g1)
        print(f"g1.html: {size} bytes for a {len(trace_rows(os.path.join(tmp, 'g1.csv')))}-step game")
        check(size < 300_000, f"a 750-step game's page is {size} bytes (the bound is 300 kB)")
        text = run("play", a, b)
        energy = final_energies(text)
        open_page(d, g1, "duel")
        check_duel(d, g1, (a, b), trace_rows(os.path.join(tmp, "g1.csv")), energy, os.path.join(out, "duel.png"))

        # 2. a network east against a builtin, comparison food 17 (a builtin has no network drawn)
        g2 = os.path.join(tmp, "g2.html")
        run("render", c, "builtin:forager-hunter", "--food", "17", "--side", "east", "--html", g2)
        run("play", c, "builtin:forager-hunter", "--food", "17", "--side", "east", "--trace",
            os.path.join(tmp, "g2.csv"))
        text = run("play", c, "builtin:forager-hunter", "--food", "17", "--side", "east")
        energy = final_energies(text)
        open_page(d, g2, "duel")
        check_duel(d, g2, (None, c), trace_rows(os.path.join(tmp, "g2.csv")), energy,
                   os.path.join(out, "duel-builtin.png"))

        # 3. hostile names: a controller path holding </script>, an <img onerror>, quotes and control bytes
        evil_dir = os.path.join(tmp, "<")
        os.makedirs(evil_dir)
        evil = os.path.join(evil_dir, "script><img src=x onerror=window.pwned=1>\"'\x01\x1b[31m.blob")
        shutil.copy(c, evil)
        g3 = os.path.join(tmp, "g3.html")
        run("render", evil, "builtin:spinner", "--html", g3)
        raw = open(g3, "rb").read().lower()
        check(raw.count(b"</script") == 2, f"g3.html holds {raw.count(b'</script')} '</script' (2: its own)")
        check(b"<img" not in raw, "g3.html holds a raw <img")
        open_page(d, g3, "duel")
        check(d.execute_script("return window.pwned === undefined"), "a hostile name ran script")
        check(d.execute_script("return document.querySelectorAll('img').length") == 0, "a hostile name made an <img>")
        body = d.execute_script("return document.body.textContent")
        check("script><img src=x onerror=window.pwned=1>" in body, "the hostile name is not shown as text")

        # 4. a run's page and its game pages (a run of the committed tiny experiment), a hostile directory name
        run_dir = os.path.join(tmp, "run\"<img src=x onerror=window.pwned=1>")
        shutil.copytree(os.path.join(fixture, "runs", "complexify-3"), run_dir)
        pages = os.path.join(tmp, "pages")
        run("report", run_dir, "--html", pages)
        levels = trace_rows(os.path.join(run_dir, "dominance.csv"))
        open_page(d, os.path.join(pages, "index.html"), "run")
        check(d.execute_script("return window.pwned === undefined"), "a hostile run name ran script")
        hrefs = d.execute_script("return Array.from(document.querySelectorAll('a[href]')).map(a => a.getAttribute('href'))")
        games = [h for h in hrefs if h.startswith("games/")]
        check(len(games) == 6 * len(levels) - 1, f"{len(games)} game links for {len(levels)} levels")
        for h in games:
            check(os.path.isfile(os.path.join(pages, h)), f"the run page links {h}, which is not there")
        d.save_screenshot(os.path.join(out, "run.png"))
        # a link opens its game: the duel viewer of that level
        d.find_element(By.CSS_SELECTOR, f"a[href='{games[-1]}']").click()
        for _ in range(100):
            if d.execute_script("return !!(window.duelPage && window.duelPage.ready && window.duelPage.kind == 'duel')"):
                break
            time.sleep(0.05)
        check(d.execute_script("return window.duelPage.kind") == "duel", "a game link did not open a duel page")
        check_quiet(d, games[-1], d.current_url)

        # 5. the same run with its games embedded: one file, the viewer opens inside it
        pages_e = os.path.join(tmp, "pages-embed")
        run("report", run_dir, "--html", pages_e, "--embed")
        check(sorted(os.listdir(pages_e)) == ["index.html"], f"--embed wrote {os.listdir(pages_e)}")
        open_page(d, os.path.join(pages_e, "index.html"), "run")
        n_embedded = d.execute_script("return JSON.parse(document.getElementById('duel-data').textContent).embedded.length")
        check(n_embedded == 6 * len(levels) - 1, f"{n_embedded} embedded games for {len(levels)} levels")

        # 6. an experiment's pages: the index (Table 1, figures, method pages) and each method's
        exp = os.path.join(tmp, "exp")
        shutil.copytree(fixture, exp)
        run("experiment", "report", exp, "--html")
        html = os.path.join(exp, "report", "html")
        open_page(d, os.path.join(html, "index.html"), "experiment")
        imgs = d.execute_script("return Array.from(document.images).map(i => [i.complete, i.naturalWidth])")
        check(imgs and all(ok and w > 0 for ok, w in imgs), f"the index's figures did not load: {imgs}")
        d.save_screenshot(os.path.join(out, "experiment.png"))
        methods = [r["method"] for r in trace_rows(os.path.join(exp, "report", "table1.csv"))]
        for m in methods:
            open_page(d, os.path.join(html, "method-" + m + ".html"), "experiment")
            check(d.execute_script("return window.pwned === undefined"), f"method-{m}.html ran script")
        d.save_screenshot(os.path.join(out, "experiment-method.png"))
    finally:
        d.quit()
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print(f"{len(failures)} failures")
        return 1
    print("all pages checked in", CHROMIUM)
    return 0


if __name__ == "__main__":
    sys.exit(main())
