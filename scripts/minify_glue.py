#!/usr/bin/env python3
"""Minifies wasm-bindgen's JS glue in a built dist/ folder (trunk 0.21's own minifier cannot parse
it) with terser, and writes the new subresource-integrity hashes of the glue and of the wasm
(changed by scripts/order_functions.py) into the pages that preload them.

Names are mangled except `__wbg_init`, one statement a line, so scripts/single_file.py still finds
the glue's parts. Usage: minify_glue.py DIST"""
import base64
import hashlib
import pathlib
import re
import subprocess
import sys


def sri(path):
    """The subresource-integrity value of a file."""
    return "sha384-" + base64.b64encode(hashlib.sha384(path.read_bytes()).digest()).decode()


dist = pathlib.Path(sys.argv[1])
hashes = {}
for glue in sorted(dist.glob("*.js")):
    if glue.name == "sw.js":
        continue
    subprocess.run(["terser", str(glue), "--module", "--mangle", "reserved=['__wbg_init']",
                    "--format", "semicolons=false", "-o", str(glue)], check=True)
    hashes[glue.name] = sri(glue)
for wasm in sorted(dist.glob("*_bg.wasm")):
    hashes[wasm.name] = sri(wasm)

# A tag naming the glue or the wasm (href="/x.js", href=/x.js) gets its new integrity.
TAG = re.compile(r"<link\b[^>]*>", re.I)
for page in sorted(dist.glob("*.html")):
    html = page.read_text(encoding="utf-8")

    def fix(m):
        tag = m.group(0)
        href = re.search(r"""href=["']?/?([^"'\s>]+)""", tag)
        if not href or href.group(1) not in hashes:
            return tag
        return re.sub(r"""integrity=(["']?)sha384-[A-Za-z0-9+/=]+\1""",
                      lambda i: f"integrity={i.group(1)}{hashes[href.group(1)]}{i.group(1)}", tag)

    page.write_text(TAG.sub(fix, html), encoding="utf-8")
print("minified glue:", ", ".join(sorted(hashes)))
