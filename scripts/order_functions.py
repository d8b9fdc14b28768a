#!/usr/bin/env python3
"""Orders the functions of each built wasm in DIST so that similar code sits side by side, then
strips the names. Usage: order_functions.py DIST

Why and how: tools/wasm-split/src/order.rs (`wasm-split order`) names the functions in the order
that puts look-alikes next to each other (gzip's 32 KB window then finds the repeats: the
trainer's wasm compresses about 5 KB smaller); wasm-opt --reorder-functions-by-name
--strip-debug writes them so, without names. The code itself is unchanged, only its order. The
file names keep trunk's hash (the service worker's cache version is computed from the files
afterwards, scripts/precache.py)."""
import pathlib
import subprocess
import sys
import tempfile

import wasm_tool


def main():
    dist = pathlib.Path(sys.argv[1])
    for wasm in sorted(dist.glob("*_bg.wasm")):
        b = wasm.read_bytes()
        try:
            named_bytes = wasm_tool.order(b)
        except wasm_tool.Unsupported as e:
            sys.exit(f"order_functions: {wasm}: {e}")
        with tempfile.TemporaryDirectory() as tmp:
            named = pathlib.Path(tmp) / "named.wasm"
            named.write_bytes(named_bytes)
            subprocess.run(["wasm-opt", str(named), "--reorder-functions-by-name", "--strip-debug",
                            "-o", str(wasm)], check=True)
        print(f"ordered functions: {wasm.name} {len(b)} -> {wasm.stat().st_size} bytes")


if __name__ == "__main__":
    main()
