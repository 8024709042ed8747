#!/usr/bin/env python3
"""page_screenshot.py - a screenshot of one of duel_evolve's web pages in headless Chromium (docs/render.md's pictures).

usage: page_screenshot.py PAGE.html OUT.png [--frame T] [--size WxH]
--frame T: a duel page drawn at frame T (its test hook: window.duelPage.goto). Needs chromium, chromium-driver and
python3-selenium (scripts/deps.sh installs them). Run it with /usr/bin/python3.
"""
import argparse
import os
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

ap = argparse.ArgumentParser()
ap.add_argument("page")
ap.add_argument("out")
ap.add_argument("--frame", type=int)
ap.add_argument("--size", default="1400x1000")
a = ap.parse_args()
o = webdriver.ChromeOptions()
o.binary_location = "/usr/bin/chromium"
for arg in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
            "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--disable-dev-shm-usage", "--force-device-scale-factor=1", "--window-size=" + a.size.replace("x", ",")):
    o.add_argument(arg)
d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=o)
try:
    d.get("file://" + os.path.abspath(a.page))
    for _ in range(200):
        if d.execute_script("return !!(window.duelPage && window.duelPage.ready)"):
            break
        time.sleep(0.05)
    if a.frame is not None:
        d.execute_script(f"window.duelPage.goto({a.frame})")
    d.save_screenshot(a.out)
finally:
    d.quit()
print(a.out)
