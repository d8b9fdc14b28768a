#!/usr/bin/env python3
"""The build's wasm tool from Python: tools/wasm-split (a Rust binary on wasmparser and
wasm-encoder, the Bytecode Alliance's reader and writer) splits a page's wasm, instruments it
for the first-screen profile, names its functions for gzip and says its layout. Used by
scripts/split_pages.py, scripts/order_functions.py and scripts/wasm_split_test.py; the binary
is built once per process in cargo's target folder, with the dev profile the native tests build
it with (so the test command builds it once; the dependencies are optimised there, Cargo.toml,
and a page's split takes well under a second). Nothing here reads wasm bytes itself."""
import os
import pathlib
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXPORT_TABLE = "__split_table"


class Unsupported(Exception):
    """The module uses something the tool does not handle: the page stays unsplit."""


_binary = None


def binary():
    global _binary
    if _binary is None:
        target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR") or ROOT / "target")
        target = target if target.is_absolute() else ROOT / target
        subprocess.run(["cargo", "build", "--quiet", "-p", "schwenkbar-wasm-split"], cwd=ROOT, check=True)
        _binary = target / "debug" / "wasm-split"
    return _binary


def run(*args):
    r = subprocess.run([str(binary()), *map(str, args)], capture_output=True, text=True)
    if r.returncode != 0:
        raise Unsupported(r.stderr.strip().removeprefix("wasm-split: ") or f"wasm-split exited {r.returncode}")
    return r.stdout


def _with_files(data, *outputs):
    """A temporary folder with `data` in in.wasm and the paths of `outputs` there."""
    tmp = tempfile.TemporaryDirectory()
    path = pathlib.Path(tmp.name)
    (path / "in.wasm").write_bytes(data)
    return tmp, path / "in.wasm", [path / o for o in outputs]


def names(data):
    """(imported function count, defined function count, {function index: name}) from the name
    section."""
    tmp, src, _ = _with_files(data)
    with tmp:
        lines = run("names", src).splitlines()
    out = {}
    for line in lines[1:]:
        index, name = line.split("\t", 1)
        out[int(index)] = name
    imports, defined = lines[0].split()
    return int(imports), int(defined), out


def instrument(data):
    """The module with a profile byte per defined function: (bytes, address of byte 0, count)."""
    tmp, src, (out,) = _with_files(data, "out.wasm")
    with tmp:
        addr, count = run("instrument", src, out).split()
        return out.read_bytes(), int(addr), int(count)


def split(data, ran, linked=None):
    """Splits by `ran` (one flag per defined function: ran on the first screen); with `linked`
    (cargo's linked binary) the read-only data only deferred functions read goes too. Returns
    (primary, deferred, facts for the loader and the figures)."""
    tmp, src, (flags, primary, deferred, link) = _with_files(data, "run", "p.wasm", "d.wasm", "linked.wasm")
    with tmp:
        flags.write_text("".join("1" if r else "0" for r in ran))
        extra = []
        if linked is not None:
            link.write_bytes(linked)
            extra = [link]
        loader, count, functions, moved = run("split", src, flags, primary, deferred, *extra).split()
        facts = {"loader": int(loader), "table": EXPORT_TABLE, "deferred": int(count),
                 "functions": int(functions), "data": int(moved)}
        return primary.read_bytes(), deferred.read_bytes(), facts


def order(data):
    """The module with its functions named in the order for gzip (scripts/order_functions.py)."""
    tmp, src, (out,) = _with_files(data, "out.wasm")
    with tmp:
        run("order", src, out)
        return out.read_bytes()


def layout(data):
    """([(section id, content start, length)], [(address or None, offset in the data section's
    content, length)])."""
    tmp, src, _ = _with_files(data)
    with tmp:
        lines = run("layout", src).splitlines()
    sections, segments = [], []
    for line in lines:
        kind, a, b, c = line.split()
        if kind == "section":
            sections.append((int(a), int(b), int(c)))
        else:
            segments.append((None if a == "passive" else int(a), int(b), int(c)))
    return sections, segments
