#!/usr/bin/env python3
"""Packs each page of a trunk build (dist/index.html, dist/kurs.html) into ONE HTML file in
dist-single/: the CSS as <style>, the JS glue and the start code as one inline
<script type="module">, the wasm as base64 handed to wasm-bindgen's init as bytes (a split page's
deferred wasm too, scripts/split_pages.py), the icon as a
data: URL. Such a file opens from a USB stick via file:// (no server; the service worker
registration in the page is guarded on http(s) and does nothing there). The pages link each
other relatively (kurs.html, index.html), so the two files work side by side.
Usage: single_file.py [DIST] [OUT]. Prints each file's size."""
import base64
import gzip
import html
import os
import re
import sys

ATTR = re.compile(r"""([^\s"'>/=]+)(?:\s*=\s*(?:"([^"]*)"|'([^']*)'|([^\s"'=<>`]+)))?""")


def attrs(tag):
    inner = re.sub(r"^<\w+|/?>$", "", tag)
    out = {}
    for m in ATTR.finditer(inner):
        value = next((g for g in m.groups()[1:] if g is not None), "")
        out[m.group(1).lower()] = html.unescape(value)
    return out


def local(dist, href):
    """The dist/ file an href names (trunk's are absolute: /name-hash.ext)."""
    path = os.path.normpath(os.path.join(dist, href.split("?")[0].lstrip("/")))
    if not path.startswith(os.path.normpath(dist) + os.sep) or not os.path.isfile(path):
        sys.exit(f"single-file: {href} is not a file in {dist}")
    return path


def read(path, mode="r"):
    with open(path, mode, **({} if "b" in mode else {"encoding": "utf-8"})) as f:
        return f.read()


def check_inline(text, what):
    """Text that goes between <script> or <style> tags must not end them early."""
    low = text.lower()
    if "</script" in low or "</style" in low or "<!--" in low:
        sys.exit(f"single-file: {what} contains </script, </style or <!-- and cannot be inlined")


def pack(dist, page):
    source = read(os.path.join(dist, page))

    def link(m):
        a = attrs(m.group(0))
        rel = a.get("rel", "").lower().split()
        href = a.get("href", "")
        if "stylesheet" in rel:
            css = read(local(dist, href))
            check_inline(css, href)
            return "<style>" + css + "</style>"
        if "icon" in rel and href.endswith(".svg"):
            data = base64.b64encode(read(local(dist, href), "rb")).decode()
            return f'<link rel="icon" type="image/svg+xml" href="data:image/svg+xml;base64,{data}">'
        # Preloads of the inlined glue and wasm; the manifest and touch icon serve installed
        # (served) apps only, and file:// pages cannot fetch them.
        if {"modulepreload", "preload", "manifest", "apple-touch-icon"} & set(rel):
            return ""
        return m.group(0)

    out = re.sub(r"<link\b[^>]*>", link, source, flags=re.I)

    starts = 0

    def script(m):
        nonlocal starts
        body = m.group(2)
        imp = re.search(r"""import\s*(\w+)\s*(?:,\s*\*\s*as\s+(\w+)\s*)?from\s*['"]([^'"]+)['"]\s*;?""", body)
        if not imp:
            return m.group(0)
        wasm = re.search(r"""module_or_path\s*:\s*['"]([^'"]+)['"]""", body)
        if not wasm:
            sys.exit(f"single-file: {page}: trunk's start script names no wasm")
        glue_name = imp.group(3)
        glue = read(local(dist, glue_name))
        check_inline(glue, glue_name)
        # The glue may be minified (scripts/env.sh build_pages): `export{j as initSync,…}` on
        # the last line after a `}`.
        if not re.search(r"^async function __wbg_init\(", glue, re.M) or not re.search(
                r"\bexport ?(?:default __wbg_init|\{[^}]*\b__wbg_init as default\b[^}]*\});?$", glue, re.M):
            sys.exit(f"single-file: {glue_name}: not wasm-bindgen's web glue (no __wbg_init as its default export)")
        if "__schwenkbarWasm" in glue:
            sys.exit(f"single-file: {glue_name} already uses the name __schwenkbarWasm")
        # Exported name → the glue's own (top-level) name for it.
        exported = [(n, n) for n in re.findall(r"^export (?:async )?(?:function\*?|class|const|let|var) (\w+)", glue, re.M)]
        for group in re.findall(r"\bexport ?\{([^}]*)\}", glue):
            for item in group.split(","):
                parts = item.split(" as ")
                if parts[0].strip():
                    exported.append((parts[-1].strip(), parts[0].strip()))
        names = [f"{name}: {local}" for name, local in exported if name != "default"]
        bindings = "{ " + ", ".join(names + ["default: __wbg_init"]) + " }"
        b64 = base64.b64encode(read(local(dist, wasm.group(1)), "rb")).decode()
        # A page split by scripts/split_pages.py: its deferred wasm goes in as bytes too.
        deferred = re.search(r"""["']([A-Za-z0-9_.-]+_deferred\.wasm)["']""", glue)
        deferred_js = ""
        if deferred:
            d64 = base64.b64encode(read(local(dist, deferred.group(1)), "rb")).decode()
            deferred_js = (f'globalThis.__schwenkbarDeferredWasm = Uint8Array.from(atob("{d64}"), '
                           "(c) => c.charCodeAt(0));\n")
        start = body[: imp.start()] + body[imp.end():]
        start = start.replace(wasm.group(0), "module_or_path: __schwenkbarWasm")
        starts += 1
        # trunk's start code in a block of its own: its names (`wasm`, the import's two) may
        # also be top-level names of the glue, which a block may shadow.
        return (
            '<script type="module">\n' + glue
            + "\n// Inlined by scripts/single_file.py: the wasm as bytes, then trunk's start code.\n"
            + f'const __schwenkbarWasm = Uint8Array.from(atob("{b64}"), (c) => c.charCodeAt(0));\n'
            + deferred_js
            + "{\n"
            + f"const {imp.group(1)} = __wbg_init;\n"
            + (f"const {imp.group(2)} = {bindings};\n" if imp.group(2) else "")
            + start + "\n}\n</script>"
        )

    out = re.sub(r"(<script\b[^>]*>)(.*?)</script>", script, out, flags=re.I | re.S)
    if starts != 1:
        sys.exit(f"single-file: {page}: expected one trunk start script, found {starts}")
    left = re.findall(r"""(?:src|href)\s*=\s*["']?/[^"'\s>]+""", out)
    if left:
        sys.exit(f"single-file: {page} still references server files: {left}")
    return out


def main():
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    dist = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "dist")
    out_dir = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "dist-single")
    os.makedirs(out_dir, exist_ok=True)
    for page in ("index.html", "kurs.html", "maschine.html"):
        text = pack(dist, page).encode("utf-8")
        path = os.path.join(out_dir, page)
        with open(path + ".tmp", "wb") as f:
            f.write(text)
        os.replace(path + ".tmp", path)
        print(f"single file: {os.path.relpath(path, root)} {len(text)} bytes "
              f"({len(text) / 1024:.0f} KB; gzip -9 {len(gzip.compress(text, 9)) / 1024:.0f} KB)")


if __name__ == "__main__":
    main()
