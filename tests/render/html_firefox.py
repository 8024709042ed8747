#!/usr/bin/env python3
"""html_firefox.py - the web pages in Firefox (ESR, headless), driven over WebDriver BiDi (no geckodriver).

A duel page, a run page and an experiment page, each opened from a file:// URL: the page gets ready, steps to a frame
through its test hook, and logs nothing to the console. Exit 77 (skipped) when firefox-esr or python3-websocket is
missing (scripts/deps.sh does not install Firefox: the suite's browser is Chromium, tests/render/html_browser.py).

usage: html_firefox.py DUEL_EVOLVE DUEL_BENCH FIXTURE_EXPERIMENT
"""
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time

FIREFOX = shutil.which("firefox-esr") or shutil.which("firefox")
try:
    import websocket
except ImportError:
    websocket = None
if FIREFOX is None or websocket is None:
    print("skipped: firefox-esr and python3-websocket are needed")
    sys.exit(77)

duel, bench, fixture = sys.argv[1:4]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Bidi:
    """A WebDriver BiDi session: commands by id, the events that arrive meanwhile kept."""

    def __init__(self, url):
        self.ws = None
        for _ in range(600):  # Firefox's first start in a new profile takes a while
            try:
                self.ws = websocket.create_connection(url, suppress_origin=True, timeout=60)
                break
            except (OSError, websocket.WebSocketException):
                time.sleep(0.1)
        if self.ws is None:
            raise RuntimeError("Firefox's WebDriver BiDi server did not answer")
        self.id = 0
        self.events = []

    def cmd(self, method, params):
        self.id += 1
        self.ws.send(json.dumps({"id": self.id, "method": method, "params": params}))
        while True:
            m = json.loads(self.ws.recv())
            if m.get("id") == self.id:
                if m.get("type") == "error":
                    raise RuntimeError(f"{method}: {m}")
                return m["result"]
            self.events.append(m)

    def eval(self, ctx, expr):
        r = self.cmd("script.evaluate", {"expression": expr, "target": {"context": ctx}, "awaitPromise": False})
        if r.get("type") == "exception":
            raise RuntimeError(f"{expr}: {r}")
        return r["result"].get("value")


def main():
    tmp = tempfile.mkdtemp(prefix="html-firefox-")
    port = free_port()
    ff = subprocess.Popen([FIREFOX, "--headless", "--no-remote", "--profile", os.path.join(tmp, "profile"),
                           "--remote-debugging-port", str(port)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        os.makedirs(os.path.join(tmp, "profile"))
        subprocess.run([bench, "--write-blobs", tmp], check=True, capture_output=True)
        run = lambda *a: subprocess.run([duel, *a], check=True, capture_output=True, cwd=tmp)  # noqa: E731
        run("render", "net202a.blob", "net202b.blob", "--html", "duel.html")
        shutil.copytree(os.path.join(fixture, "runs", "complexify-3"), os.path.join(tmp, "run"))
        run("report", "run", "--html", "pages")
        shutil.copytree(fixture, os.path.join(tmp, "exp"))
        run("experiment", "report", "exp", "--html")
        b = Bidi(f"ws://127.0.0.1:{port}/session")
        b.cmd("session.new", {"capabilities": {}})
        b.cmd("session.subscribe", {"events": ["log.entryAdded"]})
        ctx = b.cmd("browsingContext.getTree", {})["contexts"][0]["context"]
        for page, kind in (("duel.html", "duel"), ("pages/index.html", "run"), ("exp/report/html/index.html",
                                                                                  "experiment")):
            b.events.clear()
            b.cmd("browsingContext.navigate", {"context": ctx, "url": "file://" + os.path.join(tmp, page),
                                               "wait": "complete"})
            for _ in range(100):
                if b.eval(ctx, "!!(window.duelPage && window.duelPage.ready)"):
                    break
                time.sleep(0.05)
            check(b.eval(ctx, "window.duelPage && window.duelPage.kind") == kind, f"{page}: not a ready {kind} page")
            if kind == "duel":
                t = b.eval(ctx, "window.duelPage.goto(100), window.duelPage.state().t")
                check(t == 100, f"{page}: goto(100) drew frame {t}")
            b.eval(ctx, "0")  # the page's log entries arrive before this answer
            logs = [e["params"] for e in b.events if e.get("method") == "log.entryAdded"]
            check(not logs, f"{page}: console: {[(x.get('level'), x.get('text')) for x in logs]}")
        b.cmd("session.end", {})
    finally:
        ff.terminate()
        try:
            ff.wait(20)
        except subprocess.TimeoutExpired:
            ff.kill()
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        return 1
    print("the pages work in", subprocess.run([FIREFOX, "--version"], capture_output=True, text=True).stdout.strip())
    return 0


if __name__ == "__main__":
    sys.exit(main())
