#!/usr/bin/env python3
"""Orders the functions of each built wasm in DIST so that similar code sits side by side, then
strips the names. Usage: order_functions.py DIST

Why: the size budget counts the wasm as gzip -9, whose window is 32 KB. wasm-opt -Oz leaves the
functions in link order, where a yew view and its look-alikes lie far apart. Put next to each
other, the repeats are found: the trainer's wasm compresses about 5 KB smaller (2 KB of that
is ordering by name alone). The code itself is unchanged, only its order.

How: the pages' wasm-opt runs with -g, so each wasm arrives here with its names section. Each
function's body is cut into 5-byte shingles; starting from the first function by name, the next
function is always the unplaced one sharing most shingles with the one just placed (weighted by
1/sqrt of its own shingle count, so that big functions do not win by size alone), or the next by
name when none shares enough. The functions get new names in that order and wasm-opt
--reorder-functions-by-name --strip-debug writes them so, without names. Deterministic: ties go
by name. The file names keep trunk's hash (the service worker's cache version is computed from
the files afterwards, scripts/precache.py)."""
import pathlib
import subprocess
import sys
import tempfile
from collections import defaultdict

import wasm_split
from wasm_split import enc_name, enc_u, sections, uleb

SHINGLE = 5
# A shingle found in more bodies than this is boilerplate (prologues, common calls): skipped.
COMMON = 200
# Fewer shared shingles than this is no likeness: the next function by name follows instead.
LIKE = 3


def read(b):
    """(imported function count, function bodies, names by function index)."""
    m = wasm_split.Module(b)
    names = {}
    body = wasm_split.custom(m, "name") or b""
    k = 0
    while k < len(body):
        sub = body[k]
        n, k = uleb(body, k + 1)
        part, k = body[k:k + n], k + n
        if sub == 1:  # function names
            count, q = uleb(part, 0)
            for _ in range(count):
                index, q = uleb(part, q)
                n, q = uleb(part, q)
                names[index] = part[q:q + n].decode("utf-8", "replace")
                q += n
    return len(m.imp_funcs), m.bodies, names


def order(bodies, names, imports):
    n = len(bodies)
    by_name = sorted(range(n), key=lambda k: (names.get(imports + k, ""), k))
    rank = {k: r for r, k in enumerate(by_name)}
    shingles = [{bd[i:i + SHINGLE] for i in range(max(1, len(bd) - SHINGLE + 1))} for bd in bodies]
    holders = defaultdict(list)
    for k, s in enumerate(shingles):
        for x in s:
            holders[x].append(k)
    left = set(range(n))
    next_by_name = iter(by_name)
    placed, cur = [], by_name[0]
    while True:
        left.discard(cur)
        placed.append(cur)
        if not left:
            return placed
        shared = defaultdict(int)
        for x in shingles[cur]:
            lst = holders[x]
            if len(lst) <= COMMON:
                for k in lst:
                    if k in left:
                        shared[k] += 1
        best = max(shared, key=lambda k: (shared[k] / (len(shingles[k]) ** 0.5 + 1), -rank[k]), default=None)
        if best is not None and shared[best] >= LIKE:
            cur = best
        else:
            cur = next(k for k in next_by_name if k in left)


def renamed(b, new_names):
    sub = enc_u(len(new_names)) + b"".join(enc_u(i) + enc_name(new_names[i]) for i in sorted(new_names))
    name_section = enc_name("name") + bytes([1]) + enc_u(len(sub)) + sub
    out = bytearray(b[:8])
    for sid, body in sections(b):
        if sid == 0:
            n, k = uleb(body, 0)
            # The old names, and the linker's symbols and relocations (web/build.rs keeps them
            # for scripts/split_pages.py; after wasm-bindgen they no longer fit the code).
            if body[k:k + n] in (b"name", b"linking") or body[k:k + n].startswith(b"reloc."):
                continue
        out += bytes([sid]) + enc_u(len(body)) + body
    out += bytes([0]) + enc_u(len(name_section)) + name_section
    return bytes(out)


def main():
    dist = pathlib.Path(sys.argv[1])
    for wasm in sorted(dist.glob("*_bg.wasm")):
        b = wasm.read_bytes()
        imports, bodies, names = read(b)
        if not names:
            sys.exit(f"order_functions: {wasm} has no names (the page's wasm-opt needs -g)")
        new_names = {i: f"a{i:06d}" for i in range(imports)}
        new_names.update({imports + k: f"f{r:06d}" for r, k in enumerate(order(bodies, names, imports))})
        with tempfile.TemporaryDirectory() as tmp:
            named = pathlib.Path(tmp) / "named.wasm"
            named.write_bytes(renamed(b, new_names))
            subprocess.run(["wasm-opt", str(named), "--reorder-functions-by-name", "--strip-debug",
                            "-o", str(wasm)], check=True)
        print(f"ordered functions: {wasm.name} {len(b)} -> {wasm.stat().st_size} bytes")


if __name__ == "__main__":
    main()
