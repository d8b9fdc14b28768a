#!/usr/bin/env python3
"""Core's modules form layers, not a circle (issue 33): no top-level module of core/src reaches
itself through `crate::` paths (`use crate::plane::…`, `crate::unconfirmed::X` in code). A
circle makes every module of it depend on every other, so none can be read, tested or moved
alone. Comments (doc links among them) do not count: they are no dependency. A module's own
files (`sim.rs` with `sim/*.rs`) count as one. Exits 1 and prints each circle with its edges.
"""

import collections
import os
import re
import sys


def modules(src):
    """Top-level module name -> its files (lib.rs is the root, not a module)."""
    out = collections.defaultdict(list)
    for dirpath, _, files in os.walk(src):
        for f in files:
            if f.endswith(".rs"):
                path = os.path.join(dirpath, f)
                top = os.path.relpath(path, src).split(os.sep)[0].removesuffix(".rs")
                if top not in ("lib", "main"):
                    out[top].append(path)
    return out


def code(text):
    """The text without its unit tests and comments."""
    text = re.sub(r"#\[cfg\(test\)\]\s*mod tests\s*\{.*", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def graph(src):
    mods = modules(src)
    edges = collections.defaultdict(set)
    for top, files in mods.items():
        for path in files:
            text = code(open(path, encoding="utf-8").read())
            names = re.findall(r"crate::(\w+)", text)
            for group in re.findall(r"crate::\{([^;]*)\}", text, flags=re.S):
                names += re.findall(r"(?:^|[,{\s])(\w+)", group)
            edges[top] |= {n for n in names if n in mods and n != top}
    return mods, edges


def circles(nodes, edges):
    """Strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, found, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return found


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    mods, edges = graph(os.path.join(root, "core", "src"))
    found = circles(mods, edges)
    for comp in found:
        print("core import circle: " + ", ".join(comp))
        for v in comp:
            print(f"  {v} -> {', '.join(sorted(edges[v] & set(comp)))}")
    if found:
        sys.exit(1)
    print(f"core layers: {len(mods)} top-level modules, no import circle")


if __name__ == "__main__":
    main()
