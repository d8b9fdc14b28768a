#!/usr/bin/env python3
"""Splits each built page's wasm (DIST/index.html, kurs.html, maschine.html) into what its first
screen runs and the rest (tools/wasm-split through scripts/wasm_tool.py), so that a page loads less before it shows.
Usage: split_pages.py DIST [LINKED_DIR] (cargo's wasm32 release folder: the linked binaries, for
the data, see tools/wasm-split/src/data.rs). Run by build_pages (scripts/env.sh) after trunk, before
scripts/order_functions.py.

The rule: the functions each page's first screen runs are listed in web/first_screen/PAGE.txt
(committed; a function's name as the wasm's name section gives it, without rustc's hashes; the
first line names the compiler they were recorded with), and the split keeps exactly those in the
primary. A build needs no browser and the same source gives
the same bytes. SCHWENKBAR_SPLIT says how the lists are used:
- unset: the lists split the pages (scripts/serve.sh, scripts/single-file.sh).
- check (the test command, scripts/bundle.sh): each page is also opened in headless Chromium
  (PROFILE below) and the build fails if its first screen ran functions its list does not hold
  (that code would be fetched synchronously during the start), more than PROFILE_SLACK of them;
  the split still follows the list.
  A build by another compiler than the list's only warns: its inlining makes other functions.
- record: the lists are written anew from that profile, keeping the names they held that the
  build still has (after a change to what the first screen runs: `SCHWENKBAR_SPLIT=record bash
  scripts/bundle.sh`, then commit web/first_screen/).

PROFILE: each page's wasm gets a profile byte per function; a copy of DIST with those is served
on 127.0.0.1 and opened in headless Chromium (scripts/chromium.py) until the page has started and
its set of run functions has stayed the same for PROFILE_QUIET_S seconds.
SPLIT: the listed functions stay in X_bg.wasm (the primary), the rest go to X_deferred.wasm, and
the page's glue (X.js) gets the loader (LOADER below), all three named by a hash of the two
modules (X = trunk's name with that hash): before the app starts it puts a JS function into the
table slot every deferred stub calls first; after the start it fetches and compiles
X_deferred.wasm in the background; the first deferred call before that has arrived loads it at
once (synchronous request and compile). A page packed into one file (scripts/single_file.py)
carries the deferred bytes in globalThis.__schwenkbarDeferredWasm.
If anything is missing (a page, its list, a construct the splitter does not read), the page stays
whole and a warning says why: the app works, only bigger (scripts/bundle.sh reports it).
SCHWENKBAR_NO_SPLIT=1 leaves every page whole (to compare the two)."""
import hashlib
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time

import wasm_tool
from chromium import Driver, Failure, free_port, port_open, wait_for

# Each page and the screens it is opened at ("reload": opened again, with what the visit before
# saved in the browser): the trainer on a first and a later visit; the course at each lesson (the
# trainer's Kurs link, a lesson link or the course's own next/previous, which set #kurs/N) and
# opened again; the machine editor as the trainer's EDITIEREN opens it (#machine-id).
PAGES = {
    "index.html": ["", "reload"],
    "kurs.html": [""] + [f"#kurs/{n}" for n in range(1, 12)] + ["reload"],
    "maschine.html": ["#ac-table"],
}
# The committed lists of the functions each page's first screen runs.
LISTS = pathlib.Path(__file__).resolve().parent.parent / "web" / "first_screen"
PROFILE_QUIET_S = 1.5
# Two profiles of one build can differ by a function or two (what runs before the page is quiet
# depends on timing): the check fails above this many functions the lists do not hold.
PROFILE_SLACK = 3
PROFILE_LIMIT_S = 20.0

# The helper module: imports "j" "l" ([] -> []) and exports it as "l" (a JS function made a wasm
# function, which a funcref table accepts) and a no-op "n". 44 bytes, written by hand:
# header, type [] -> [], import j.l, one function, exports l and n, the no-op's body.
HELPER = ("0,97,115,109,1,0,0,0,1,4,1,96,0,0,2,7,1,1,106,1,108,0,0,3,2,1,0,"
          "7,9,2,1,108,0,0,1,110,0,1,10,4,1,2,0,11")

LOADER = """
// Added by scripts/split_pages.py: the functions the first screen does not run are in
// __DEFERRED__; each of their stubs in this page's wasm first calls table slot __SLOT__.
const __split = { state: 0, sync: 0, ex: null, noop: null, bytes: null, ready: null };
globalThis.__schwenkbarSplit = __split;
// Resolves when the deferred code is there: the trainer simulates its start program then
// (web/src/browser.rs, deferred_code), not during the first screen. Without it (the background
// load failed) the first key loads it (the reducer simulates before any action).
globalThis.__schwenkbarSplitReady = globalThis.__schwenkbarSplitReady
    || new Promise((resolve) => { __split.ready = resolve; });
function __split_settled() {
    if (__split.ready) __split.ready();
}
function __split_attach(instance) {
    const helper = new WebAssembly.Instance(new WebAssembly.Module(new Uint8Array([__HELPER__])),
        { j: { l: __split_now } });
    __split.ex = instance.exports;
    __split.noop = helper.exports.n;
    __split.ex.__TABLE__.set(__SLOT__, helper.exports.l);
}
function __split_use(module) {
    if (__split.state === 2) return;
    new WebAssembly.Instance(module, { p: __split.ex });
    __split.ex.__TABLE__.set(__SLOT__, __split.noop);
    __split.state = 2;
    __split.bytes = null;
    __split_settled();
}
function __split_url() {
    return new URL('__DEFERRED__', import.meta.url);
}
// A deferred function is called before the background load has finished: load it now.
function __split_now() {
    __split.sync += 1;
    try {
        // The page's own copy (one-file page), else what the background load has fetched so far.
        let bytes = globalThis.__schwenkbarDeferredWasm || __split.bytes;
        if (!bytes) {
            const xhr = new XMLHttpRequest();
            xhr.open('GET', __split_url(), false);
            xhr.overrideMimeType('text/plain; charset=x-user-defined');
            xhr.send();
            if (xhr.status !== 200) throw new Error(`HTTP ${xhr.status}`);
            const text = xhr.responseText;
            bytes = new Uint8Array(text.length);
            for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i) & 0xff;
        }
        __split_use(new WebAssembly.Module(bytes));
    } catch (e) {
        // The app cannot go on without that code: say so on the page, German first.
        const note = document.createElement('div');
        note.setAttribute('role', 'alert');
        note.style.cssText = 'position:fixed;top:0;left:0;right:0;z-index:1000;padding:.6em 1em;'
            + 'background:#b00020;color:#fff;font:16px/1.4 sans-serif';
        note.textContent = 'Ein Teil von Schwenkbar ließ sich nicht laden – bitte die Seite neu laden. / '
            + `Part of Schwenkbar could not be loaded – please reload the page. (${e})`;
        document.body.prepend(note);
        throw e;
    }
}
// Served by the offline cache's service worker, the deferred bytes are on this machine: fetched
// next to the primary, so a deferred call during the start needs no synchronous request (which
// the service worker does not answer).
async function __split_early() {
    if (!globalThis.navigator || !navigator.serviceWorker || !navigator.serviceWorker.controller
        || globalThis.__schwenkbarDeferredWasm || globalThis.__schwenkbarNoPrefetch) return;
    try {
        const r = await fetch(__split_url());
        if (r.ok) __split.bytes = await r.arrayBuffer();
    } catch (e) {
        // The background load tries again; a deferred call before it, synchronously.
    }
}
function __split_prefetch() {
    if (__split.state !== 0 || globalThis.__schwenkbarNoPrefetch) return;
    __split.state = 1;
    const have = globalThis.__schwenkbarDeferredWasm || __split.bytes;
    (have ? Promise.resolve(have) : fetch(__split_url()).then((r) => {
        if (!r.ok) throw new Error(`HTTP ${r.status}`);
        return r.arrayBuffer();
    }))
        .then((bytes) => WebAssembly.compile(__split.bytes = bytes))
        .then(__split_use)
        .catch((e) => {
            if (__split.state === 1) __split.state = 0;
            console.warn('Schwenkbar: the deferred code will load when it is first needed:', e);
        });
}
"""

START = "    wasm.__wbindgen_start();\n"
LOAD = "    const { instance, module } = await __wbg_load(await module_or_path, imports);\n"


def page_files(dist, page):
    """(glue, wasm) file names a trunk page loads."""
    html = (dist / page).read_text(encoding="utf-8")
    glue = re.search(r"""import\s+init\s*,\s*\*\s*as\s+\w+\s+from\s*['"]/([^'"]+\.js)['"]""", html)
    wasm = re.search(r"""module_or_path\s*:\s*['"]/([^'"]+_bg\.wasm)['"]""", html)
    if not glue or not wasm:
        raise wasm_tool.Unsupported(f"{page}: trunk's start script not found")
    return glue.group(1), wasm.group(1)


def profiles(dist, plan, chromedriver):
    """Opens each page with its instrumented wasm; returns {page: run flags}."""
    out = {}
    work = tempfile.mkdtemp(prefix="schwenkbar-split-")
    site = os.path.join(work, "site")
    shutil.copytree(dist, site)
    # The profile is of the first screen: what waits for the deferred code (the trainer's
    # simulation of its start program) waits for ever here.
    hook = ('<script>addEventListener("TrunkApplicationStarted",'
            '(e)=>{window.__schwenkbarExports=e.detail.wasm});'
            'window.__schwenkbarSplitReady=new Promise(()=>{})</script>')
    for page, (_, wasm, data, addr, count) in plan.items():
        pathlib.Path(site, wasm).write_bytes(data)
        path = pathlib.Path(site, page)
        html = path.read_text(encoding="utf-8")
        html = re.sub(r"""\s+integrity=(["']?)sha384-[A-Za-z0-9+/=]+\1""", "", html)
        if "<script" not in html:
            raise Failure(f"{page} has no script")
        path.write_text(html.replace("<script", hook + "<script", 1), encoding="utf-8")
    port = free_port()
    server = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1",
                               "--directory", site], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    driver = None
    try:
        wait_for("the HTTP server", lambda: port_open(port), 10)
        driver = Driver(chromedriver, os.path.join(work, "profile"))
        for page, (_, wasm, data, addr, count) in plan.items():
            read = (f"const b = new Uint8Array(window.__schwenkbarExports.memory.buffer, {addr}, {count});"
                    "return Array.from(b).join('');")
            ran = [False] * count
            for n, fragment in enumerate(PAGES[page]):
                if n == 0 or fragment == "reload":
                    if n == 0:
                        driver.go(f"http://127.0.0.1:{port}/{page}{fragment}")
                    else:
                        driver.reload()
                    wait_for(f"{page} started", lambda: driver.js("return !!window.__schwenkbarExports;"), 30)
                else:
                    driver.js("location.hash = arguments[0];", fragment)
                last, since, t0 = None, time.monotonic(), time.monotonic()
                while time.monotonic() - t0 < PROFILE_LIMIT_S:
                    flags = driver.js(read)
                    if flags != last:
                        last, since = flags, time.monotonic()
                    elif time.monotonic() - since >= PROFILE_QUIET_S:
                        break
                    time.sleep(0.25)
                ran = [r or c == "1" for r, c in zip(ran, last)]
            out[page] = ran
    finally:
        if driver:
            driver.quit()
        server.terminate()
        server.wait(10)
        shutil.rmtree(work, ignore_errors=True)
    return out


def patch_glue(text, deferred, facts):
    if text.count(START) != 1 or text.count(LOAD) != 1 or "__split_" in text:
        raise wasm_tool.Unsupported("the glue's load and start calls not found once (or already split)")
    text = text.replace(START, "    __split_attach(instance);\n" + START
                        + "    setTimeout(__split_prefetch, 0);\n")
    text = text.replace(LOAD, "    const early = __split_early();\n" + LOAD + "    await early;\n")
    loader = (LOADER.replace("__DEFERRED__", deferred).replace("__SLOT__", str(facts["loader"]))
              .replace("__TABLE__", facts["table"]).replace("__HELPER__", HELPER))
    end = text.rindex("\nexport ")
    return text[:end] + "\n" + loader + text[end:]


def split_with_data(original, run, linked_dir, wasm):
    """The split with the read-only data only deferred functions read, when cargo's linked
    binary of this page (trunk's name without its hash) is there and fits; else the code alone."""
    linked = None if linked_dir is None else linked_dir / (wasm.rsplit("-", 1)[0] + ".wasm")
    if linked is not None and linked.is_file():
        try:
            return wasm_tool.split(original, run, linked.read_bytes())
        except wasm_tool.Unsupported as e:
            print(f"split: WARNING {wasm}: its data stays in the primary: {e}", file=sys.stderr)
    else:
        print(f"split: WARNING {wasm}: its data stays in the primary: no linked binary {linked}",
              file=sys.stderr)
    return wasm_tool.split(original, run)


def stable(name):
    """A function's name without the hashes rustc puts in it (the legacy mangling's `::h` and 16
    hex digits at the end, the v0 mangling's crate disambiguators `crate[16 hex digits]`): they
    depend on the build's metadata, not on the item, so the same item keeps its name. Without
    the `.N` the name section gives a name it already has (N counts through the module, so any
    change of the code renumbered them and the lists had to be recorded anew, issue 33): the
    copies of one name are first-screen functions together, which costs a few copies' bytes."""
    name = re.sub(r"\[[0-9a-f]{16}\]", "", re.sub(r"::h[0-9a-f]{16}$", "", name))
    return re.sub(r"(\.[0-9]+)+$", "", name)


def names_by_body(data):
    """The stable name of each defined function (None: the name section has none)."""
    imports, count, names = wasm_tool.names(data)
    return [None if imports + k not in names else stable(names[imports + k]) for k in range(count)]


def list_file(page):
    return LISTS / (page.removesuffix(".html") + ".txt")


def main():
    dist = pathlib.Path(sys.argv[1])
    linked_dir = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else None
    if os.environ.get("SCHWENKBAR_NO_SPLIT"):
        print("split: SCHWENKBAR_NO_SPLIT is set, every page stays whole", file=sys.stderr)
        return
    mode = os.environ.get("SCHWENKBAR_SPLIT", "")
    if mode not in ("", "check", "record"):
        sys.exit(f"split: SCHWENKBAR_SPLIT={mode}: expected check or record")
    plan, names = {}, {}
    for page in PAGES:
        try:
            glue, wasm = page_files(dist, page)
            original = (dist / wasm).read_bytes()
            names[page] = names_by_body(original)
            if mode:
                data, addr, count = wasm_tool.instrument(original)
                plan[page] = (glue, wasm, data, addr, count)
            else:
                plan[page] = (glue, wasm, None, None, None)
        except (wasm_tool.Unsupported, OSError) as e:
            print(f"split: WARNING {page} stays whole: {e}", file=sys.stderr)
    if not plan:
        return
    if mode:
        chromedriver = os.environ.get("CHROMEDRIVER", "/usr/bin/chromedriver")
        try:
            runs = profiles(dist, plan, chromedriver)
        except (Failure, OSError, subprocess.SubprocessError) as e:
            sys.exit(f"split: the profile run failed ({mode} needs Chromium): {e}")
        failed = False
        compiler = subprocess.run(["rustc", "-V"], capture_output=True, text=True).stdout.strip()
        for page, ran in runs.items():
            have = sorted({n for n, r in zip(names[page], ran) if r and n is not None})
            listed, recorded = read_list(page) or ([], None)
            if mode == "record":
                # What ran now, and what the list held before that this build still has: one
                # profile can miss a function another run takes (its timing), so lists only
                # drop names the code no longer has.
                present = {n for n in names[page] if n is not None}
                kept = set(have) | ({n for n in listed if n in present} if recorded == compiler else set())
                LISTS.mkdir(parents=True, exist_ok=True)
                lines = [f"# {compiler}"] + sorted(kept)
                list_file(page).write_text("".join(n + "\n" for n in lines), encoding="utf-8")
                print(f"split: {list_file(page)}: {len(kept)} functions recorded ({compiler})")
                continue
            held = set(listed)
            missing = [n for n in have if n not in held]
            if missing and recorded != compiler:
                # Another compiler inlines otherwise: its functions are not the ones listed.
                print(f"split: WARNING {list_file(page)} was recorded with {recorded}, this build "
                      f"uses {compiler}: {len(missing)} functions its first screen ran are not "
                      "listed (fetched after the start); record the lists for this compiler",
                      file=sys.stderr)
            elif len(missing) > PROFILE_SLACK:
                failed = True
                print(f"split: {page}'s first screen ran {len(missing)} functions {list_file(page)} does "
                      f"not hold, e.g. {missing[:3]}: record the lists anew "
                      "(SCHWENKBAR_SPLIT=record bash scripts/bundle.sh) and commit them", file=sys.stderr)
            elif missing:
                print(f"split: WARNING {page}'s first screen ran {len(missing)} functions "
                      f"{list_file(page)} does not hold ({missing}): within the profile's slack of "
                      f"{PROFILE_SLACK}; recording the lists anew adds them", file=sys.stderr)
        if failed:
            sys.exit(1)
    for page, (glue, wasm, _, _, _) in plan.items():
        found = read_list(page)
        if found is None:
            print(f"split: WARNING {page} stays whole: no list {list_file(page)}", file=sys.stderr)
            continue
        listed = set(found[0])
        # A function without a name stays in the primary: the list cannot say it is not run.
        run = [n is None or n in listed for n in names[page]]
        try:
            original = (dist / wasm).read_bytes()
            primary, deferred, facts = split_with_data(original, run, linked_dir, wasm)
        except (wasm_tool.Unsupported, KeyError) as e:
            print(f"split: WARNING {page} stays whole: {e}", file=sys.stderr)
            continue
        problem = invalid(primary, "primary") or invalid(deferred, "deferred")
        if problem:
            print(f"split: WARNING {page} stays whole: {problem}", file=sys.stderr)
            continue
        # trunk's names hash the unsplit build: the split files are named by their own bytes, so
        # that a browser's cache never pairs one build's primary with another's deferred module.
        old = wasm[: -len("_bg.wasm")]
        new = old.rsplit("-", 1)[0] + "-" + hashlib.sha256(primary + deferred).hexdigest()[:16]
        if not glue == old + ".js":
            print(f"split: WARNING {page} stays whole: {glue} and {wasm} are not named alike", file=sys.stderr)
            continue
        try:
            text = patch_glue((dist / glue).read_text(encoding="utf-8"), new + "_deferred.wasm", facts)
        except wasm_tool.Unsupported as e:
            print(f"split: WARNING {page} stays whole: {e}", file=sys.stderr)
            continue
        (dist / (new + "_bg.wasm")).write_bytes(primary)
        (dist / (new + "_deferred.wasm")).write_bytes(deferred)
        (dist / (new + ".js")).write_text(text, encoding="utf-8")
        (dist / wasm).unlink()
        (dist / glue).unlink()
        html = (dist / page).read_text(encoding="utf-8")
        (dist / page).write_text(html.replace(old, new), encoding="utf-8")
        print(f"split: {page}: {facts['functions'] - facts['deferred']} of {facts['functions']} functions "
              f"on its first screen ({list_file(page).name}); {len(original)} bytes -> {new}_bg.wasm "
              f"{len(primary)} bytes, {new}_deferred.wasm {len(deferred)} bytes, with {facts['data']} "
              "bytes of read-only data")


def read_list(page):
    """The committed names of a page's first screen and the compiler they were recorded with
    (its first line, `# rustc …`), or None without a list."""
    try:
        lines = list_file(page).read_text(encoding="utf-8").splitlines()
    except OSError:
        return None
    recorded = lines[0][2:] if lines and lines[0].startswith("# ") else None
    return [n for n in lines if n and not n.startswith("#")], recorded


def invalid(data, what):
    """Why wasm-opt does not read the module back (it validates as it reads, with the features
    of the target_features section), or None."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "m.wasm")
        with open(path, "wb") as f:
            f.write(data)
        check = subprocess.run(["wasm-opt", path, "-o", os.devnull], capture_output=True, text=True)
    return None if check.returncode == 0 else f"the {what} module does not validate:\n{check.stderr[:2000]}"


if __name__ == "__main__":
    main()
