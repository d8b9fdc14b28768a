#!/usr/bin/env python3
"""Offline tests of the built app (issue 12), in headless Chromium through chromedriver's W3C
HTTP API (python3's urllib; Chrome DevTools Protocol commands via its goog/cdp/execute).

Service worker (dist/, served by python3's http.server on a free 127.0.0.1 port): one online
visit of the trainer; once the service worker controls the page, a second build (one file
changed, sw.js written anew) must replace the cache at the next visit; then the HTTP cache is cleared and
the browser goes offline (Network.emulateNetworkConditions): the trainer reloads and the course,
never visited, opens. Then, back "online" but with the server stopped, both open again. The
manifest must parse without errors and the page be installable (Page.getInstallabilityErrors).
The emulation takes the page offline, not the service worker's own fetches (Chromium 156): those
steps show that the worker answers every request of the page; the stopped server shows that the
answers come from its cache (a worker that does not cache kurs.html fails only there).
Split wasm (dist/): the trainer's first screen needs none of the deferred wasm, which loads
after it or at a deferred call; and a run link at block 30 of Musterprogramm 1 shows the cut
part (issue 32), saved as target/screenshots/musterprogramm1-block30.png. That screenshot is
taken in real time once the figures line is there: scripts/screenshot.sh's virtual time gives the
page almost no animation frames in headless Chromium, and the view cuts in frames.
Single file (dist-single/, scripts/single-file.sh): index.html opens from file:// with the
network off and refers to no other file, and its Kurs link opens kurs.html next to it.

Prints one line per test and, per group, cargo's summary line ("test result: ok. N passed;
0 failed"), which it also appends to --log (scripts/test.sh sums those). Exits 1 on a failure.
Every wait is bounded; the server, chromedriver and Chromium are stopped at the end."""
import argparse
import base64
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.parse

from chromium import Driver, Failure, free_port, port_open, wait_for

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
TIME_LIMIT_S = 300  # all tests together; each wait below is bounded as well


def out_of_time(_signum, _frame):
    raise Failure(f"the offline tests took longer than {TIME_LIMIT_S} s")


# The rendered app: the trainer's TNC screen with its header, or the course's header.
TRAINER = """
const tnc = document.querySelector('.tnc');
const head = document.querySelector('.tnc .mode-header');
return tnc && head ? head.textContent : null;"""
COURSE = """
const head = document.querySelector('.course-head .course-title');
return head ? head.textContent : null;"""
# The machine editor showing a machine (its id in an input).
EDITOR = """
const inputs = [...document.querySelectorAll('input')].map((i) => i.value);
return document.querySelector('.ed-inputs') ? inputs.join(' ') : null;"""


def rendered(driver, probe, words, seconds=30):
    def check():
        try:
            text = driver.js(probe)
        except Failure:
            return None  # the page is still navigating
        return text if text and all(w in text for w in words) else None

    return wait_for(f"the page showing {' / '.join(words)}", check, seconds, step=0.2)


def controlled(driver):
    return driver.js("return !!(navigator.serviceWorker && navigator.serviceWorker.controller);")


CACHES = """
const done = arguments[arguments.length - 1];
caches.keys().then(async (keys) => {
  const own = keys.filter((k) => k.startsWith('schwenkbar-'));
  const entries = own.length ? (await (await caches.open(own[0])).keys()).map((r) => new URL(r.url).pathname) : [];
  done({ keys: own, entries });
}).catch((e) => done({ error: String(e) }));"""


def service_worker_tests(driver, dist, work, run):
    # A copy of dist/ is served, so that a second build can be made of it (new_build).
    site = os.path.join(work, "site")
    shutil.copytree(dist, site)
    port = free_port()
    server = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1",
                               "--directory", site], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    base = f"http://127.0.0.1:{port}/"
    try:
        wait_for("the HTTP server", lambda: port_open(port), 10)
        state = {}

        def first_visit():
            driver.go(base)
            rendered(driver, TRAINER, ["Schwenkbar", "Bearbeitungsebene schwenken"])
            wait_for("the service worker controlling the page", lambda: controlled(driver), 30, step=0.2)
            cached = driver.js_async(CACHES)
            entries = cached.get("entries", [])
            need = ["/index.html", "/kurs.html", "/maschine.html", "/manifest.webmanifest"]
            kinds = [".wasm", ".js", ".css", ".png", ".svg"]
            if len(cached.get("keys", [])) != 1 or not all(n in entries for n in need) \
                    or not all(any(e.endswith(k) for e in entries) for k in kinds):
                raise Failure(f"cache storage: {cached}")
            state["files"] = len(entries)
            return f"controlled, cache {cached['keys'][0]} with {len(entries)} files"

        def installable():
            manifest = driver.cdp("Page.getAppManifest")
            if manifest.get("errors"):
                raise Failure(f"manifest errors: {manifest['errors']}")
            data = json.loads(manifest.get("data") or "{}")
            if not data.get("name", "").startswith("Schwenkbar – Bearbeitungsebene schwenken"):
                raise Failure(f"manifest name: {data.get('name')!r}")
            errors = driver.cdp("Page.getInstallabilityErrors").get("installabilityErrors", [])
            if errors:
                raise Failure(f"installability errors: {errors}")
            return "no manifest or installability errors"

        def new_build():
            # Another build: one file changes, build_pages' precache.py writes a new sw.js.
            old = driver.js_async(CACHES).get("keys")
            with open(os.path.join(site, "manifest.webmanifest"), "a", encoding="utf-8") as f:
                f.write("\n")
            subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "precache.py"), site],
                           check=True, stdout=subprocess.DEVNULL, timeout=30)
            driver.go(base)
            rendered(driver, TRAINER, ["Schwenkbar"])

            asked = [0.0]

            def replaced():
                # Browsers look for a new sw.js on navigation; update() makes it certain. Asked
                # again only every 10 s: an update() while the new worker installs starts its
                # check anew (once, on a loaded machine, the cache was not replaced in 30 s).
                if time.monotonic() - asked[0] > 10:
                    asked[0] = time.monotonic()
                    driver.js_async("const done = arguments[arguments.length - 1];"
                                    "navigator.serviceWorker.getRegistration().then((r) => r && r.update())"
                                    ".then(() => done(), () => done());")
                keys = driver.js_async(CACHES).get("keys")
                return keys if keys and len(keys) == 1 and keys != old else None

            try:
                keys = wait_for("the new build's cache replacing the old one", replaced, 60, step=0.5)
            except Failure as e:
                # What the browser had: the workers' states and the caches, to tell why.
                state = driver.js_async(
                    "const done = arguments[arguments.length - 1];"
                    "navigator.serviceWorker.getRegistration().then(async (r) => done({"
                    "installing: r && r.installing && r.installing.state,"
                    "waiting: r && r.waiting && r.waiting.state,"
                    "active: r && r.active && r.active.state,"
                    "caches: await caches.keys()}), (x) => done(String(x)));")
                raise Failure(f"{e}; service worker and caches then: {state}") from e
            wait_for("the new service worker controlling the page", lambda: controlled(driver), 10)
            return f"{old[0]} replaced by {keys[0]}, the old cache deleted"

        def offline_emulated():
            driver.cdp("Network.enable")
            driver.cdp("Network.clearBrowserCache")
            driver.cdp("Network.emulateNetworkConditions",
                       {"offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})
            driver.reload()
            text = rendered(driver, TRAINER, ["Schwenkbar", "Bearbeitungsebene schwenken"])
            if not controlled(driver):
                raise Failure("the reloaded page is not controlled by the service worker")
            return f"trainer rendered offline: {text.strip()[:60]!r}"

        def course_offline_emulated():
            driver.go(base + "kurs.html")
            text = rendered(driver, COURSE, ["Kurs"])
            return f"course (never visited online) rendered offline: {text.strip()!r}"

        def server_stopped():
            driver.cdp("Network.emulateNetworkConditions",
                       {"offline": False, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})
            server.terminate()
            server.wait(10)
            if port_open(port):
                raise Failure("the HTTP server still answers")
            driver.cdp("Network.clearBrowserCache")
            driver.go(base)
            rendered(driver, TRAINER, ["Schwenkbar", "Bearbeitungsebene schwenken"])
            driver.go(base + "kurs.html#kurs/1")
            rendered(driver, COURSE, ["Kurs"])
            return "trainer and course rendered with the server stopped"

        run("offline::first_visit_installs_service_worker", first_visit)
        run("offline::manifest_installable", installable)
        run("offline::new_build_replaces_the_cache", new_build)
        run("offline::trainer_reloads_offline", offline_emulated)
        run("offline::course_opens_offline", course_offline_emulated)
        run("offline::both_pages_with_server_stopped", server_stopped)
    finally:
        if server.poll() is None:
            server.terminate()
            try:
                server.wait(10)
            except subprocess.TimeoutExpired:
                server.kill()


# A page split by scripts/split_pages.py: the loader's state (0 not loaded, 1 loading, 2 loaded)
# and how many times a deferred function had to load it at once.
SPLIT = """
const s = globalThis.__schwenkbarSplit;
return s ? { state: s.state, sync: s.sync, errors: window.__schwenkbarErrors || [] } : null;"""
ERRORS = ("window.__schwenkbarErrors = [];"
          "addEventListener('error', (e) => window.__schwenkbarErrors.push(String(e.message)));"
          "addEventListener('unhandledrejection', (e) => window.__schwenkbarErrors.push(String(e.reason)));")


# The page as the DOM has it: texts, classes and attributes (read-only data the primary would
# lack shows as an empty or wrong string somewhere in there).
PAGE_HTML = "return document.body.outerHTML;"


def split_state(driver):
    state = driver.js(SPLIT)
    if state is None:
        raise Failure("the trainer's wasm is not split (no loader in its glue)")
    if state["errors"]:
        raise Failure(f"errors in the page: {state['errors']}")
    return state


def split_tests(driver, dist, run):
    """The trainer's split wasm (dist/, its own origin, so no service worker)."""
    port = free_port()
    server = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1",
                               "--directory", dist], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    base = f"http://127.0.0.1:{port}/"
    hooks = []
    try:
        wait_for("the HTTP server", lambda: port_open(port), 10)
        hooks.append(driver.cdp("Page.addScriptToEvaluateOnNewDocument", {"source": ERRORS})["identifier"])
        driver.cdp("Network.enable")

        def first_screen_alone():
            driver.cdp("Network.setBlockedURLs", {"urls": ["*_deferred.wasm"]})
            try:
                driver.go(base)
                text = rendered(driver, TRAINER, ["Schwenkbar", "Bearbeitungsebene schwenken"])
                program = wait_for("the program list", lambda: driver.js(
                    "const p = document.querySelector('.blocks'); return p && p.innerText.includes('BEGIN PGM') ? p.innerText : null;"), 20)
                time.sleep(1)
                state = split_state(driver)
                if state["state"] == 2 or state["sync"]:
                    raise Failure(f"the first screen needed the deferred wasm: {state}")
            finally:
                driver.cdp("Network.setBlockedURLs", {"urls": []})
            return f"trainer and program ({len(program.splitlines())} lines) shown with the deferred wasm blocked: {text.strip()[:40]!r}"

        def loads_after_first_screen():
            driver.go(base + "?after")
            rendered(driver, TRAINER, ["Schwenkbar"])
            state = wait_for("the deferred wasm loaded in the background",
                             lambda: (lambda s: s if s["state"] == 2 else None)(split_state(driver)), 20)
            if state["sync"]:
                raise Failure(f"a deferred function ran before the background load: {state}")
            return "loaded in the background, no deferred call before it"

        def first_screen_same_without_deferred_data():
            # The deferred wasm also carries the read-only data (texts, tables) only its functions
            # read: a first screen must read none of it (tools/wasm-split/src/data.rs). Each
            # page, with the state the loads before saved, once whole (the deferred part loaded)
            # and once with it blocked: the same HTML. What waits for the deferred code (the
            # trainer's simulation of its start program, AppState::sim_pending) waits in both.
            sizes = []
            waits = driver.cdp("Page.addScriptToEvaluateOnNewDocument", {
                "source": "globalThis.__schwenkbarSplitReady = new Promise(() => {});"})["identifier"]
            try:
                return same_html(sizes)
            finally:
                driver.cdp("Page.removeScriptToEvaluateOnNewDocument", {"identifier": waits})

        def same_html(sizes):
            for page, probe, words in (("", TRAINER, ["Schwenkbar"]), ("kurs.html", COURSE, ["Schwenkbar"]),
                                       ("maschine.html#ac-table", EDITOR, ["ac-table"])):
                path, _, fragment = page.partition("#")
                driver.go(f"{base}{path}?whole#{fragment}")
                rendered(driver, probe, words)
                wait_for("the deferred wasm loaded", lambda: split_state(driver)["state"] == 2, 20)
                time.sleep(1)
                whole = driver.js(PAGE_HTML)
                driver.cdp("Network.setBlockedURLs", {"urls": ["*_deferred.wasm"]})
                try:
                    driver.go(f"{base}{path}?primary#{fragment}")
                    rendered(driver, probe, words)
                    time.sleep(1)
                    state = split_state(driver)
                    alone = driver.js(PAGE_HTML)
                finally:
                    driver.cdp("Network.setBlockedURLs", {"urls": []})
                if state["state"] == 2 or state["sync"]:
                    raise Failure(f"{page or 'index.html'}: the first screen needed the deferred wasm: {state}")
                if alone != whole:
                    at = next(i for i, (x, y) in enumerate(zip(alone + "\0", whole + "\0")) if x != y)
                    raise Failure(f"{page or 'index.html'}: the first screen differs without the deferred wasm: "
                                  f"{alone[max(0, at - 80):at + 40]!r} instead of {whole[max(0, at - 80):at + 40]!r}")
                sizes.append(f"{page or 'index.html'} {len(whole)}")
            return f"the same HTML with and without the deferred wasm ({', '.join(sizes)} characters)"

        def loads_on_first_use():
            hooks.append(driver.cdp("Page.addScriptToEvaluateOnNewDocument",
                                    {"source": "globalThis.__schwenkbarNoPrefetch = true;"})["identifier"])
            driver.go(base + "?first-use")
            rendered(driver, TRAINER, ["Schwenkbar"])
            time.sleep(1)
            before = split_state(driver)
            if before["state"] != 0 or before["sync"]:
                raise Failure(f"loaded without a deferred call: {before}")
            # SPEC FCT (F1): the dialog's first softkey row is code the first screen never ran.
            driver.js("document.dispatchEvent(new KeyboardEvent('keydown', { key: 'F1', bubbles: true }));")
            row = wait_for("the SPEC FCT softkeys", lambda: driver.js(
                "const r = document.querySelector('.softkeys'); return r && r.innerText.includes('SCHWENKEN') ? r.innerText : null;"), 10)
            after = split_state(driver)
            if after["state"] != 2 or after["sync"] != 1:
                raise Failure(f"SPEC FCT did not load the deferred wasm once: {after}")
            return f"F1 loaded it at once (1 synchronous load), softkeys {' '.join(row.split())!r}"

        def missing_says_so():
            driver.cdp("Network.setBlockedURLs", {"urls": ["*_deferred.wasm"]})
            try:
                driver.go(base + "?missing")
                rendered(driver, TRAINER, ["Schwenkbar"])
                driver.js("document.dispatchEvent(new KeyboardEvent('keydown', { key: 'F1', bubbles: true }));")
                alert = wait_for("the message that a part could not be loaded", lambda: driver.js(
                    "const a = document.querySelector('[role=alert]'); return a ? a.textContent : null;"), 10)
            finally:
                driver.cdp("Network.setBlockedURLs", {"urls": []})
            if not alert.startswith("Ein Teil von Schwenkbar ließ sich nicht laden") or "Part of Schwenkbar" not in alert:
                raise Failure(f"the message: {alert!r}")
            return f"{alert[:70]!r}…"

        def run_link_shows_the_part():
            with open(os.path.join(ROOT, "static", "programs", "musterprogramm1.h"), encoding="utf-8") as f:
                text = f.read()
            driver.cmd("POST", "window/rect", {"width": 1920, "height": 1080})
            driver.go(f"{base}?block30#pgm={urllib.parse.quote(text, safe='-_.~')}&block=30&machine=ac-table&run=1")
            figures = wait_for("the stock's figures at block 30", lambda: driver.js(
                "const f = document.querySelector('[data-testid=stock-figures]');"
                " return f && f.textContent.startsWith('Abgetragen') ? f.textContent : null;"), 60, step=0.2)
            time.sleep(0.5)
            shot = os.path.join(ROOT, "target", "screenshots", "musterprogramm1-block30.png")
            os.makedirs(os.path.dirname(shot), exist_ok=True)
            png = base64.b64decode(driver.cmd("GET", "screenshot"))
            with open(shot, "wb") as f:
                f.write(png)
            driver.cmd("POST", "window/rect", {"width": 1280, "height": 800})
            return f"{figures!r}, {len(png)} bytes in {os.path.relpath(shot, ROOT)}"

        run("split::trainer_first_screen_without_the_deferred_wasm", first_screen_alone)
        run("split::deferred_wasm_loads_after_the_first_screen", loads_after_first_screen)
        run("split::first_screen_the_same_without_the_deferred_data", first_screen_same_without_deferred_data)
        run("split::deferred_call_before_the_load_loads_it_at_once", loads_on_first_use)
        run("split::deferred_wasm_missing_says_so", missing_says_so)
        run("stock::run_link_at_block_30_shows_the_part", run_link_shows_the_part)
    finally:
        for hook in hooks:
            try:
                driver.cdp("Page.removeScriptToEvaluateOnNewDocument", {"identifier": hook})
            except Failure:
                pass
        server.terminate()
        server.wait(10)


# What a page refers to besides itself: elements naming files, and what it fetched (file://
# loads do not show in Resource Timing, hence the elements as well).
OUTSIDE = """
const named = [...document.querySelectorAll('script[src], link[href], img[src], iframe[src], source[src], object[data]')]
  .map((e) => e.src || e.href || e.data).filter((u) => !u.startsWith('data:'));
return named.concat(performance.getEntriesByType('resource').map((e) => e.name));"""


def outside(driver):
    refs = driver.js(OUTSIDE)
    if refs:
        raise Failure(f"the single file refers to other files: {refs}")


def single_file_tests(driver, single, run):
    index = "file://" + os.path.abspath(os.path.join(single, "index.html"))

    def trainer():
        driver.cdp("Network.emulateNetworkConditions",
                   {"offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1})
        driver.go(index)
        rendered(driver, TRAINER, ["Schwenkbar", "Bearbeitungsebene schwenken"])
        wait_for("the deferred wasm loaded from the page's own bytes",
                 lambda: (driver.js(SPLIT) or {}).get("state") == 2, 20)
        outside(driver)
        if driver.js("return !!(navigator.serviceWorker && navigator.serviceWorker.controller);"):
            raise Failure("a service worker controls the file:// page")
        return "trainer rendered from file:// with its deferred wasm inside, refers to no other file"

    def course_link():
        driver.js("document.querySelector('[data-testid=course-link]').click();")
        wait_for("kurs.html opened by the Kurs link",
                 lambda: (driver.js("return location.href;") or "").endswith("/kurs.html"), 20)
        rendered(driver, COURSE, ["Kurs"])
        outside(driver)
        return "the Kurs link opened dist-single/kurs.html, course rendered"

    run("single_file::trainer_from_file_url", trainer)
    run("single_file::course_link_between_files", course_link)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dist", default=os.path.join(ROOT, "dist"))
    ap.add_argument("--single", default=os.path.join(ROOT, "dist-single"))
    ap.add_argument("--log", help="append the summary lines to this file (scripts/test.sh's log)")
    ap.add_argument("--chromedriver", default=os.environ.get("CHROMEDRIVER", "/usr/bin/chromedriver"))
    args = ap.parse_args()

    results = {}

    def runner(group):
        def run(name, test):
            t0 = time.monotonic()
            try:
                detail = test()
                ok = True
            except (Failure, OSError, ValueError, KeyError, TypeError, AttributeError,
                    subprocess.SubprocessError) as e:
                detail, ok = f"{type(e).__name__}: {e}" if not isinstance(e, Failure) else str(e), False
            results.setdefault(group, []).append(ok)
            print(f"test {name} ... {'ok' if ok else 'FAILED'} ({time.monotonic() - t0:.1f} s) {detail}", flush=True)
            return ok
        return run

    groups = {"split wasm (dist/)": 6, "offline (service worker, dist/)": 6, "single file (dist-single/)": 2}
    signal.signal(signal.SIGALRM, out_of_time)
    signal.alarm(TIME_LIMIT_S)
    work = tempfile.mkdtemp(prefix="schwenkbar-offline-")
    profile = os.path.join(work, "profile")
    driver = None
    t0 = time.monotonic()
    try:
        for path in (os.path.join(args.dist, "sw.js"), os.path.join(args.single, "index.html")):
            if not os.path.isfile(path):
                raise Failure(f"{path} is missing: run scripts/bundle.sh and scripts/single-file.sh --from-dist")
        driver = Driver(args.chromedriver, profile)
        split_tests(driver, args.dist, runner("split wasm (dist/)"))
        service_worker_tests(driver, args.dist, work, runner("offline (service worker, dist/)"))
        single_file_tests(driver, args.single, runner("single file (dist-single/)"))
    except (Failure, OSError) as e:
        print(f"offline tests: {e}", flush=True)
    finally:
        signal.alarm(0)
        if driver:
            driver.quit()
        shutil.rmtree(work, ignore_errors=True)

    lines = []
    for group, planned in groups.items():
        got = results.get(group, [])
        passed = sum(got)
        failed = planned - passed  # tests that did not run count as failed
        verdict = "ok" if failed == 0 else "FAILED"
        lines.append(f"test result: {verdict}. {passed} passed; {failed} failed; {group}")
    print("\n".join(lines) + f"\noffline tests took {time.monotonic() - t0:.1f} s", flush=True)
    if args.log:
        with open(args.log, "a", encoding="utf-8") as f:
            f.write("\n".join(lines) + "\n")
    return 0 if all("FAILED" not in line for line in lines) else 1


if __name__ == "__main__":
    sys.exit(main())
