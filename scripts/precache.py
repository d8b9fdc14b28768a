#!/usr/bin/env python3
"""Writes DIST/sw.js from static/sw.js for the build in DIST (default dist/): PRECACHE lists
every file in DIST (relative URLs, sorted; sw.js itself left out) and VERSION is a hash of their
names and bytes, so each different build gets its own cache and replaces the old one.
Run by build_pages (scripts/env.sh) after trunk. Prints the number of files and the version."""
import hashlib
import json
import os
import re
import sys
import urllib.parse


def main():
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    dist = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "dist")
    template_path = os.path.join(root, "static", "sw.js")
    files = []
    for base, dirs, names in os.walk(dist):
        dirs.sort()
        for name in names:
            rel = os.path.relpath(os.path.join(base, name), dist).replace(os.sep, "/")
            if rel != "sw.js":
                files.append(rel)
    files.sort()
    pages = ("index.html", "kurs.html", "maschine.html")
    if any(page not in files for page in pages):
        sys.exit(f"precache: {dist} lacks one of {', '.join(pages)}; run build_pages")
    digest = hashlib.sha256()
    with open(template_path, "rb") as f:
        template_bytes = f.read()
    digest.update(template_bytes)
    for rel in files:
        digest.update(rel.encode() + b"\0")
        with open(os.path.join(dist, rel), "rb") as f:
            digest.update(hashlib.sha256(f.read()).digest())
    version = digest.hexdigest()[:16]
    urls = [urllib.parse.quote(rel) for rel in files]
    text = template_bytes.decode("utf-8")
    text, n1 = re.subn(r'^const VERSION = "[^"]*";$', f"const VERSION = {json.dumps(version)};", text, count=1, flags=re.M)
    text, n2 = re.subn(r"^const PRECACHE = \[\];$", lambda _: "const PRECACHE = " + json.dumps(urls, indent=2) + ";",
                       text, count=1, flags=re.M)
    if n1 != 1 or n2 != 1:
        sys.exit("precache: static/sw.js lacks the VERSION or PRECACHE line")
    with open(os.path.join(dist, "sw.js"), "w", encoding="utf-8") as f:
        f.write(text)
    print(f"service worker: {dist}/sw.js precaches {len(files)} files, cache schwenkbar-{version}")


if __name__ == "__main__":
    main()
