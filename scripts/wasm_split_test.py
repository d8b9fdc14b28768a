#!/usr/bin/env python3
"""Tests of scripts/wasm_split.py against an oracle it does not share: the same module run whole.
A small module (assembled by binaryen's wasm-as from the text below) is run in node unsplit and
split, with the loader wired as the pages' glue wires it (split_pages.HELPER): every export must
give the same results and make the same calls to its import, the deferred module must load once,
at the first deferred call, and never when only primary functions run. Also: the profile bytes
of an instrumented module name exactly the functions that ran, and bodies the decoder does not
know leave the module whole.

Prints one line per test and cargo's summary line, which --log appends to scripts/test.sh's log.
Usage: wasm_split_test.py [--log FILE]"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import split_pages
import wasm_split

# Functions in index order after the import: sq 1, add3 2, fact 3, twice 4, run 5, only_sq 6,
# fill 7, via_table 8, init4 9 (passive data: stays in the primary though it did not run).
WAT = r"""
(module
  (type $ii (func (param i32) (result i32)))
  (import "env" "log" (func $log (param i32)))
  (memory (export "memory") 1)
  (global $g (mut i32) (i32.const 10))
  (global $k i32 (i32.const 1000))
  (table 4 4 funcref)
  (elem (i32.const 0) $sq $add3 $fact $twice)
  (data $bytes "\01\02\03\04")
  (func $sq (param i32) (result i32) (i32.mul (local.get 0) (local.get 0)))
  (func $add3 (param i32) (result i32)
    (call $log (local.get 0))
    (i32.add (local.get 0) (i32.const 3)))
  (func $fact (param i32) (result i32)
    (if (result i32) (i32.le_s (local.get 0) (i32.const 1))
      (then (i32.const 1))
      (else (i32.mul (local.get 0) (call $fact (i32.sub (local.get 0) (i32.const 1)))))))
  (func $twice (param $x i32) (result i32) (local $t i64)
    (local.set $t (i64.extend_i32_s (local.get $x)))
    (global.set $g (i32.add (global.get $g) (call $sq (local.get $x))))
    (i32.store offset=16 (i32.const 0) (call $add3 (local.get $x)))
    (i32.add (i32.add (global.get $g) (global.get $k))
      (i32.add (i32.load offset=16 (i32.const 0)) (i32.wrap_i64 (local.get $t)))))
  (func $run (export "run") (param i32) (result i32)
    (i32.add (call $twice (local.get 0))
      (i32.add (call $fact (i32.const 5))
        (call_indirect (type $ii) (local.get 0) (i32.const 1)))))
  (func $only_sq (export "only_sq") (param i32) (result i32) (call $sq (local.get 0)))
  (func $fill (export "fill") (result i32) (call $init4) (i32.load (i32.const 32)))
  (func $via_table (export "via_table") (param i32) (result i32)
    (call_indirect (type $ii) (local.get 0) (i32.const 2)))
  (func $init4 (memory.init $bytes (i32.const 32) (i32.const 0) (i32.const 4)))
)
"""
# What ran "on the first screen": sq, run, only_sq, fill, via_table; add3, fact, twice deferred.
RUN = [True, False, False, False, True, True, True, True, False]

# The harness: the whole module, then the split pair wired like the glue does.
HARNESS = r"""
const fs = require('fs');
const [whole, primary, deferred, helper, slot, table] = process.argv.slice(2);
const calls = (name) => {
  const log = [];
  return { log, imports: { env: { log: (x) => log.push(x) } } };
};
const jobs = [['only_sq', 6], ['run', 7], ['run', 2], ['via_table', 6], ['fill']];
const out = {};
{
  const c = calls();
  const inst = new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(whole)), c.imports);
  out.whole = jobs.map(([f, ...a]) => inst.exports[f](...a));
  out.whole_log = c.log;
}
{
  const c = calls();
  const inst = new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(primary)), c.imports);
  let loads = 0;
  const loadsAt = [];
  const h = new WebAssembly.Instance(new WebAssembly.Module(new Uint8Array(JSON.parse(helper))), {
    j: { l: () => {
      loads += 1;
      new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(deferred)), { p: inst.exports });
      inst.exports[table].set(Number(slot), h.exports.n);
    } },
  });
  inst.exports[table].set(Number(slot), h.exports.l);
  out.split = jobs.map(([f, ...a]) => { const r = inst.exports[f](...a); loadsAt.push(loads); return r; });
  out.split_log = c.log;
  out.loads_after_each = loadsAt;
}
{
  // The instrumented module: which functions ran for only_sq(3).
  const inst = new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(whole + '.instr')), calls().imports);
  inst.exports.only_sq(3);
  out.profile = Array.from(new Uint8Array(inst.exports.memory.buffer, Number(process.env.ADDR), Number(process.env.COUNT)));
}
console.log(JSON.stringify(out));
"""


def assemble(tmp):
    wat = os.path.join(tmp, "m.wat")
    wasm = os.path.join(tmp, "m.wasm")
    with open(wat, "w", encoding="utf-8") as f:
        f.write(WAT)
    subprocess.run(["wasm-as", wat, "-o", wasm, "--enable-bulk-memory"], check=True)
    return wasm


def split_and_run(tmp):
    whole = assemble(tmp)
    data = open(whole, "rb").read()
    primary, deferred, facts = wasm_split.split(data, RUN)
    instr, addr, count = wasm_split.instrument(data)
    for name, b in (("p.wasm", primary), ("d.wasm", deferred), ("m.wasm.instr", instr)):
        with open(os.path.join(tmp, name), "wb") as f:
            f.write(b)
    helper = "[" + split_pages.HELPER + "]"
    js = os.path.join(tmp, "harness.js")
    with open(js, "w", encoding="utf-8") as f:
        f.write(HARNESS)
    got = json.loads(subprocess.run(
        ["node", js, whole, os.path.join(tmp, "p.wasm"), os.path.join(tmp, "d.wasm"), helper,
         str(facts["loader"]), facts["table"]],
        check=True, capture_output=True, text=True, env={**os.environ, "ADDR": str(addr), "COUNT": str(count)},
    ).stdout)
    return got, facts, addr, count, data


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--log")
    args = ap.parse_args()
    results = []

    def run(name, test):
        try:
            detail, ok = test(), True
        except (AssertionError, wasm_split.Unsupported, subprocess.CalledProcessError, ValueError) as e:
            detail, ok = f"{type(e).__name__}: {e}", False
        results.append(ok)
        print(f"test {name} ... {'ok' if ok else 'FAILED'} {detail}", flush=True)

    with tempfile.TemporaryDirectory() as tmp:
        try:
            got, facts, addr, count, data = split_and_run(tmp)
        except (wasm_split.Unsupported, subprocess.CalledProcessError, ValueError, OSError) as e:
            print(f"wasm_split tests: {type(e).__name__}: {e}", flush=True)
            got = None

        def same_results():
            assert got["split"] == got["whole"], f"split {got['split']} != whole {got['whole']}"
            assert got["split_log"] == got["whole_log"], f"calls {got['split_log']} != {got['whole_log']}"
            return f"{got['whole']}, import calls {got['whole_log']}"

        def loads_once_at_first_deferred_call():
            assert facts["deferred"] == 3, facts  # add3, fact, twice; not init4 (memory.init)
            assert got["loads_after_each"] == [0, 1, 1, 1, 1], got["loads_after_each"]
            return "not for only_sq, once at run, never again"

        def profile_names_what_ran():
            want = [1, 0, 0, 0, 0, 1, 0, 0, 0]  # only_sq and sq, which it calls
            assert got["profile"] == want, got["profile"]
            return f"{count} bytes at {addr}"

        def unknown_code_stays_whole():
            body = bytes([0, 0xFD, 0x0C]) + bytes(16) + bytes([0x1A, 0x0B])  # v128.const, drop
            try:
                wasm_split.scan(body)
            except wasm_split.Unsupported as e:
                assert "0xfd" in str(e), e
                return f"refused: {e}"
            raise AssertionError("a SIMD body was read")

        if got is None:
            results.extend([False] * 4)
        else:
            run("wasm_split::split_module_gives_the_same_results", same_results)
            run("wasm_split::deferred_loads_once_at_the_first_deferred_call", loads_once_at_first_deferred_call)
            run("wasm_split::profile_names_the_functions_that_ran", profile_names_what_ran)
            run("wasm_split::unknown_opcode_is_refused", unknown_code_stays_whole)

    passed = sum(results)
    line = f"test result: {'ok' if all(results) else 'FAILED'}. {passed} passed; {len(results) - passed} failed; wasm_split"
    print(line)
    if args.log:
        with open(args.log, "a", encoding="utf-8") as f:
            f.write(line + "\n")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
