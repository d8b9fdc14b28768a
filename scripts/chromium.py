#!/usr/bin/env python3
"""Headless Chromium through chromedriver's W3C HTTP API (python3's urllib; Chrome DevTools
Protocol commands via its goog/cdp/execute), shared by scripts/offline_test.py and
scripts/split_pages.py (the profile of a page's first screen)."""
import json
import os
import socket
import subprocess
import time
import urllib.error
import urllib.request

CHROME_ARGS = [
    "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--no-first-run", "--window-size=1280,800",
    # A German browser, as most trainees have: a first visit opens in the browser's language, and
    # the pages' first screens are profiled (split_pages.py) and tested in German.
    "--lang=de-DE",
]


class Failure(Exception):
    pass


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
        options = {"args": CHROME_ARGS + [f"--user-data-dir={profile}"],
                   "prefs": {"intl.accept_languages": "de-DE,de"}}
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
