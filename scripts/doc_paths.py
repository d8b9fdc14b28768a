#!/usr/bin/env python3
"""Every path the docs name exists (issue 33: the docs had drifted, naming files that were gone).

Reads README.md, ARCHITECTURE.md and USAGE.md; every `code span` that is a path with a slash
(`core/src/sim.rs`, `tests/tests/browser_*.rs`, `sim/cycles/{drill,face}.rs`) must name at least
one file or folder of the repository, relative to its root. Built output (`dist/`, `target/`) and
URLs are not the repository's and are skipped (`dist-single/` too: `scripts/single-file.sh` makes it). Exits 1 and lists what is missing.
"""

import glob
import os
import re
import sys

DOCS = ["README.md", "ARCHITECTURE.md", "USAGE.md"]
PATH = re.compile(r"^\.{0,2}/?[\w.*{},-]+(/[\w.*{},-]*)+$")
SKIP = ("dist/", "dist-single/", "target/", "http:", "https:", "/tmp/", "/usr/", "~/")


def expand(path):
    """`a/{b,c}.rs` -> `a/b.rs`, `a/c.rs` (one level of braces per group)."""
    m = re.search(r"\{([^{}]*)\}", path)
    if not m:
        return [path]
    return [p for alt in m.group(1).split(",") for p in expand(path[: m.start()] + alt + path[m.end() :])]


def missing(root):
    out = []
    for doc in DOCS:
        text = open(os.path.join(root, doc), encoding="utf-8").read()
        for line_no, line in enumerate(text.splitlines(), 1):
            for span in re.findall(r"`([^`\n]+)`", line):
                if not PATH.match(span) or span.startswith(SKIP) or "/" not in span:
                    continue
                if not any(glob.glob(os.path.join(root, p)) for p in expand(span)):
                    out.append(f"{doc}:{line_no}: `{span}` does not exist")
    return out


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    gone = missing(root)
    for g in gone:
        print(g)
    if gone:
        sys.exit(1)
    print(f"doc paths: every path named in {', '.join(DOCS)} exists")


if __name__ == "__main__":
    main()
