#!/usr/bin/env python3
"""Cold load of the built trainer (issue 29): dist/ served by python3's http.server on a free
127.0.0.1 port and opened RUNS times in headless Chromium (scripts/chromium.py), each time with
an empty profile, so nothing is cached and no service worker answers. Prints the first
contentful paint and the moment the program's lines are in the page (the program pane's
performance mark "schwenkbar:program-shown"), both from the start of the navigation: median
and worst. A figure, not pass/fail (scripts/bench.sh); the budget is program shown <= 800 ms."""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

from chromium import Driver, Failure, free_port, port_open, wait_for

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SHOWN = """
const m = performance.getEntriesByName('schwenkbar:program-shown')[0];
const p = performance.getEntriesByName('first-contentful-paint')[0];
return m ? [p ? p.startTime : -1, m.startTime] : null;"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dist", default=os.path.join(ROOT, "dist"))
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--chromedriver", default=os.environ.get("CHROMEDRIVER", "/usr/bin/chromedriver"))
    args = ap.parse_args()
    if not os.path.isfile(os.path.join(args.dist, "index.html")):
        sys.exit(f"{args.dist}/index.html is missing: run scripts/bundle.sh")
    port = free_port()
    server = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1",
                               "--directory", args.dist], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    work = tempfile.mkdtemp(prefix="schwenkbar-cold-")
    paints, shown = [], []
    try:
        wait_for("http.server", lambda: port_open(port), 10)
        for run in range(args.runs):
            driver = Driver(args.chromedriver, os.path.join(work, f"profile{run}"))
            try:
                driver.go(f"http://127.0.0.1:{port}/index.html")
                paint, ms = wait_for("the program shown", lambda: driver.js(SHOWN), 30, step=0.05)
                paints.append(paint)
                shown.append(ms)
            finally:
                driver.quit()
    except Failure as e:
        sys.exit(f"cold load: {e}")
    finally:
        server.terminate()
        server.wait(5)
        shutil.rmtree(work, ignore_errors=True)
    print(f"BENCH cold load of the trainer ({args.runs} runs, empty cache): first contentful paint "
          f"median {statistics.median(paints):.0f} ms; program shown median {statistics.median(shown):.0f} ms, "
          f"worst {max(shown):.0f} ms (budget 800)", flush=True)


if __name__ == "__main__":
    main()
