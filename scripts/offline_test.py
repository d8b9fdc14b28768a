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
Single file (dist-single/, scripts/single-file.sh): index.html opens from file:// with the
network off and refers to no other file, and its Kurs link opens kurs.html next to it.

Prints one line per test and, per group, cargo's summary line ("test result: ok. N passed;
0 failed"), which it also appends to --log (scripts/test.sh sums those). Exits 1 on a failure.
Every wait is bounded; the server, chromedriver and Chromium are stopped at the end."""
import argparse
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
CHROME_ARGS = [
    "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--no-first-run", "--window-size=1280,800",
]


class Failure(Exception):
    pass


TIME_LIMIT_S = 300  # all tests together; each wait below is bounded as well


def out_of_time(_signum, _frame):
    raise Failure(f"the offline tests took longer than {TIME_LIMIT_S} s")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def port_open(port):
    with socket.socket() as s:
        s.settimeout(0.5)
        return s.connect_ex(("127.0.0.1", port)) == 0


def wait_for(what, check, seconds, step=0.1):
    end = time.monotonic() + seconds
    while True:
        value = check()
        if value:
            return value
        if time.monotonic() > end:
            raise Failure(f"{what}: not within {seconds} s")
        time.sleep(step)


class Driver:
    """The few W3C WebDriver commands these tests use."""

    def __init__(self, chromedriver, profile):
        self.port = free_port()
        self.proc = subprocess.Popen([chromedriver, f"--port={self.port}"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.session = None
        wait_for("chromedriver", self._ready, 20)
        options = {"args": CHROME_ARGS + [f"--user-data-dir={profile}"]}
        if os.path.exists("/usr/bin/chromium"):
            options["binary"] = "/usr/bin/chromium"
        caps = {"capabilities": {"alwaysMatch": {"browserName": "chrome", "goog:chromeOptions": options}}}
        self.session = self._call("POST", "/session", caps, timeout=60)["sessionId"]
        self.cmd("POST", "timeouts", {"script": 30000, "pageLoad": 30000})

    def _ready(self):
        try:
            return self._call("GET", "/status", timeout=2).get("ready")
        except (OSError, Failure):
            return False

    def _call(self, method, path, body=None, timeout=45):
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(f"http://127.0.0.1:{self.port}{path}", data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as r:
                return json.load(r).get("value")
        except urllib.error.HTTPError as e:
            try:
                value = json.load(e).get("value", {})
                message = f"{value.get('error')}: {value.get('message', '').splitlines()[0]}"
            except ValueError:
                message = str(e)
            raise Failure(f"webdriver {method} {path.split('/')[-1]}: {message}") from None

    def cmd(self, method, path, body=None, timeout=45):
        return self._call(method, f"/session/{self.session}/{path}", body, timeout)

    def go(self, url):
        self.cmd("POST", "url", {"url": url})

    def reload(self):
        self.cmd("POST", "refresh", {})

    def js(self, script, *args):
        return self.cmd("POST", "execute/sync", {"script": script, "args": list(args)})

    def js_async(self, script, *args):
        return self.cmd("POST", "execute/async", {"script": script, "args": list(args)})

    def cdp(self, command, params=None):
        return self.cmd("POST", "goog/cdp/execute", {"cmd": command, "params": params or {}})

    def quit(self):
        try:
            if self.session:
                self._call("DELETE", f"/session/{self.session}", timeout=20)
        except (OSError, Failure):
            pass
        self.proc.terminate()
        try:
            self.proc.wait(10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait(5)


# The rendered app: the trainer's TNC screen with its header, or the course's header.
TRAINER = """
const tnc = document.querySelector('.tnc');
const head = document.querySelector('.tnc .mode-header');
return tnc && head ? head.textContent : null;"""
COURSE = """
const head = document.querySelector('.course-head .course-title');
return head ? head.textContent : null;"""


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

            def replaced():
                # Browsers look for a new sw.js on navigation; update() makes it certain.
                driver.js_async("const done = arguments[arguments.length - 1];"
                                "navigator.serviceWorker.getRegistration().then((r) => r && r.update())"
                                ".then(() => done(), () => done());")
                keys = driver.js_async(CACHES).get("keys")
                return keys if keys and len(keys) == 1 and keys != old else None

            keys = wait_for("the new build's cache replacing the old one", replaced, 30, step=0.5)
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
        outside(driver)
        if driver.js("return !!(navigator.serviceWorker && navigator.serviceWorker.controller);"):
            raise Failure("a service worker controls the file:// page")
        return "trainer rendered from file://, refers to no other file"

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

    groups = {"offline (service worker, dist/)": 6, "single file (dist-single/)": 2}
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
