#!/usr/bin/env python3
"""Tests of the wasm splitter (tools/wasm-split, through scripts/wasm_tool.py) against an oracle
it does not share: the same module run whole.
A small module (assembled by binaryen's wasm-as from the text below) is run in node unsplit and
split, with the loader wired as the pages' glue wires it (split_pages.HELPER): every export must
give the same results and make the same calls to its import, the deferred module must load once,
at the first deferred call, and never when only primary functions run. Also: the profile bytes
of an instrumented module name exactly the functions that ran, and bodies the decoder does not
know (SIMD) leave the module whole. Read-only data: what only deferred code reads moves to the deferred
module, what the primary reads (through an address outside the object, through a pointer in
data, inside it with no relocation, in half an i64) stays, and memory after the load is the whole module's.

Prints one line per test and cargo's summary line, which --log appends to scripts/test.sh's log.
Usage: wasm_split_test.py [--log FILE]"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import split_pages
import wasm_tool

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

# The split pair wired like the pages' glue wires it: `wired(imports)` gives the primary's
# instance and how often the deferred module was loaded so far.
WIRE = r"""
const fs = require('fs');
function wired(primary, deferred, helper, slot, table, imports) {
  const inst = new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(primary)), imports);
  let loads = 0;
  const h = new WebAssembly.Instance(new WebAssembly.Module(new Uint8Array(JSON.parse(helper))), {
    j: { l: () => {
      loads += 1;
      new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(deferred)), { p: inst.exports });
      inst.exports[table].set(Number(slot), h.exports.n);
    } },
  });
  inst.exports[table].set(Number(slot), h.exports.l);
  return { inst, loads: () => loads };
}
"""

# The harness: the whole module, then the split pair.
HARNESS = WIRE + r"""
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
  const { inst, loads } = wired(primary, deferred, helper, slot, table, c.imports);
  const loadsAt = [];
  out.split = jobs.map(([f, ...a]) => { const r = inst.exports[f](...a); loadsAt.push(loads()); return r; });
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


# Read-only data: a module laid out as a linker lays out Rust's statics, with the linker's symbol
# table and relocations written beside it as `wasm-ld --emit-relocs` writes them (linked()).
# .rodata (256..336) holds the objects below, .data (340) the pointer F. p_* functions run on the
# first screen (primary), d_* not (deferred; called through the exported call_*).
# - A: read by d_a only: moves.          - B: read by p_b at 252 + 12: the constant is B - 12,
# - C: read through P, which p_c reads:    which lies outside B (the relocation says it means B).
#   stays.                               - D: read by d_e only, points to E: both move.
# - G: pointed to by F (mutable .data,    - H: p_h reads H + 4 (316), an address with no
#   always in the primary): stays.          relocation (as wasm-opt folds one): stays.
# - I: read by d_i only: moves.
# - J: p_j stores its address and length as one i64 (as wasm-opt joins two i32 stores): stays.
DATA = {"A": (256, 4), "B": (264, 4), "C": (272, 4), "P": (280, 4), "D": (288, 4), "E": (296, 4),
        "G": (304, 4), "H": (312, 8), "J": (320, 4), "I": (328, 8)}
DATA_WAT = r"""
(module
  (memory (export "memory") 1)
  (table 1 1 funcref)
  (data (i32.const 256) "\65\00\00\00\00\00\00\00\ca\00\00\00\00\00\00\00\2f\01\00\00\00\00\00\00"
    "\10\01\00\00\00\00\00\00\28\01\00\00\00\00\00\00\f9\01\00\00\00\00\00\00\c3\02\00\00\00\00\00\00"
    "\28\03\00\00\29\03\00\00\e8\03\00\00\00\00\00\00\8d\03\00\00\8e\03\00\00")
  (data (i32.const 340) "\30\01\00\00")
  (func $p_b (export "p_b") (param i32) (result i32) (i32.load (i32.add (i32.const 252) (local.get 0))))
  (func $p_c (export "p_c") (result i32) (i32.load (i32.load (i32.const 280))))
  (func $p_g (export "p_g") (result i32) (i32.load (i32.load (i32.const 340))))
  (func $p_h (export "p_h") (result i32) (i32.load (i32.const 316)))
  (func $p_j (export "p_j") (result i32)
    (i64.store (i32.const 0) (i64.const 17179869504))
    (i32.load (i32.load (i32.const 0))))
  (func $d_a (result i32) (i32.load (i32.const 256)))
  (func $d_e (result i32) (i32.load (i32.load (i32.const 288))))
  (func $d_i (result i32) (i32.add (i32.load (i32.const 328)) (i32.load (i32.const 332))))
  (func $call_a (export "call_a") (result i32) (call $d_a))
  (func $call_e (export "call_e") (result i32) (call $d_e))
  (func $call_i (export "call_i") (result i32) (call $d_i))
)
"""
DATA_RUN = [True, True, True, True, True, False, False, False, True, True, True]
# The code's addresses and what they mean (symbol, addend); 316 has none (see H).
CODE_RELOCS = {252: ("B", -12), 280: ("P", 0), 340: ("F", 0), 256: ("A", 0), 288: ("D", 0),
               328: ("I", 0), 332: ("I", 4)}
DATA_RELOCS = {280: "C", 288: "E", 340: "G"}  # pointer site -> object
DATA_JOBS = [["p_b", 12], ["p_c"], ["p_g"], ["p_h"], ["p_j"], ["call_a"], ["call_e"], ["call_i"]]

DATA_HARNESS = WIRE + r"""
const [whole, primary, deferred, helper, slot, table, jobs] = process.argv.slice(2);
const out = { whole: [], split: [], loads: [] };
const w = new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(whole)), {});
for (const [f, ...a] of JSON.parse(jobs)) out.whole.push(w.exports[f](...a));
const { inst, loads } = wired(primary, deferred, helper, slot, table, {});
const mem = () => new Int32Array(inst.exports.memory.buffer);
out.before = Array.from(mem().slice(64, 88));  // bytes 256..352 before the deferred module
for (const [f, ...a] of JSON.parse(jobs)) { out.split.push(inst.exports[f](...a)); out.loads.push(loads()); }
out.after = Array.from(mem().slice(64, 88));
out.whole_mem = Array.from(new Int32Array(w.exports.memory.buffer).slice(64, 88));
console.log(JSON.stringify(out));
"""


def enc_u(n):
    """LEB128 of an unsigned number: this test writes what wasm-ld --emit-relocs would."""
    out = bytearray()
    while True:
        x, n = n & 0x7F, n >> 7
        out.append(x | 0x80 if n else x)
        if not n:
            return bytes(out)


def enc_s(n):
    """LEB128 of a signed number."""
    out = bytearray()
    while True:
        x, n = n & 0x7F, n >> 7
        done = (n == 0 and not x & 0x40) or (n == -1 and x & 0x40)
        out.append(x if done else x | 0x80)
        if done:
            return bytes(out)


def enc_name(s):
    s = s.encode()
    return enc_u(len(s)) + s


def linked(module):
    """`module` with the custom sections wasm-ld --emit-relocs writes: linking (segment info,
    symbol table: the data symbols of DATA and F) and reloc.CODE / reloc.DATA. Where the code
    section and the data segments lie comes from the tool's layout."""
    sections, segs = wasm_tool.layout(module)
    names = list(DATA) + ["F"]
    symtab = enc_u(len(names))
    for n in names:
        seg, (addr, size) = (1, (340, 4)) if n == "F" else (0, DATA[n])
        symtab += b"\x01\x00" + enc_name(n) + enc_u(seg) + enc_u(addr - segs[seg][0]) + enc_u(size)
    info = enc_u(2) + b"".join(enc_name(n) + b"\x02\x00" for n in (".rodata", ".data"))
    link = (enc_name("linking") + enc_u(2) + b"\x05" + enc_u(len(info)) + info
            + b"\x08" + enc_u(len(symtab)) + symtab)
    start, length = next((s, n) for sid, s, n in sections if sid == 10)
    code = module[start:start + length]
    rc = b""
    for value, (sym, addend) in CODE_RELOCS.items():
        at = code.index(b"\x41" + enc_s(value)) + 1
        rc += b"\x04" + enc_u(at) + enc_u(names.index(sym)) + enc_s(addend)
    rd = b""
    for site, target in DATA_RELOCS.items():
        seg = segs[0] if site < 336 else segs[1]
        at = seg[1] + site - seg[0]
        rd += b"\x05" + enc_u(at) + enc_u(names.index(target)) + enc_s(0)
    out = bytearray(module)
    for body in (link,
                 enc_name("reloc.CODE") + b"\x0a" + enc_u(len(CODE_RELOCS)) + rc,
                 enc_name("reloc.DATA") + b"\x0b" + enc_u(len(DATA_RELOCS)) + rd):
        out += b"\x00" + enc_u(len(body)) + body
    return bytes(out)


def split_data_and_run(tmp):
    whole = assemble(tmp, DATA_WAT, "d")
    data = open(whole, "rb").read()
    primary, deferred, facts = wasm_tool.split(data, DATA_RUN, linked(data))
    for name, b in (("dp.wasm", primary), ("dd.wasm", deferred)):
        with open(os.path.join(tmp, name), "wb") as f:
            f.write(b)
    js = os.path.join(tmp, "data_harness.js")
    with open(js, "w", encoding="utf-8") as f:
        f.write(DATA_HARNESS)
    got = json.loads(subprocess.run(
        ["node", js, whole, os.path.join(tmp, "dp.wasm"), os.path.join(tmp, "dd.wasm"),
         "[" + split_pages.HELPER + "]", str(facts["loader"]), facts["table"], json.dumps(DATA_JOBS)],
        check=True, capture_output=True, text=True).stdout)
    return got, facts


def assemble(tmp, text=WAT, name="m", *features):
    wat = os.path.join(tmp, name + ".wat")
    wasm = os.path.join(tmp, name + ".wasm")
    with open(wat, "w", encoding="utf-8") as f:
        f.write(text)
    subprocess.run(["wasm-as", wat, "-o", wasm, "--enable-bulk-memory", *features], check=True)
    return wasm


def split_and_run(tmp):
    whole = assemble(tmp)
    data = open(whole, "rb").read()
    primary, deferred, facts = wasm_tool.split(data, RUN)
    instr, addr, count = wasm_tool.instrument(data)
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
        except (AssertionError, wasm_tool.Unsupported, subprocess.CalledProcessError, ValueError) as e:
            detail, ok = f"{type(e).__name__}: {e}", False
        results.append(ok)
        print(f"test {name} ... {'ok' if ok else 'FAILED'} {detail}", flush=True)

    with tempfile.TemporaryDirectory() as tmp:
        try:
            got, facts, addr, count, data = split_and_run(tmp)
        except (wasm_tool.Unsupported, subprocess.CalledProcessError, ValueError, OSError) as e:
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
            simd = WAT.replace("(func $sq (param i32) (result i32)",
                               "(func $sq (param i32) (result i32) (drop (v128.const i64x2 0 0))")
            module = open(assemble(tmp, simd, "simd", "--enable-simd"), "rb").read()
            try:
                wasm_tool.split(module, RUN)
            except wasm_tool.Unsupported as e:
                assert "SIMD" in str(e) or "simd" in str(e), e
                return f"refused: {e}"
            raise AssertionError("a SIMD body was read")

        try:
            dgot, dfacts = split_data_and_run(tmp)
        except (wasm_tool.Unsupported, subprocess.CalledProcessError, ValueError, OSError) as e:
            print(f"wasm_split data tests: {type(e).__name__}: {e}", flush=True)
            dgot = None

        def word(name):
            return (DATA[name][0] - 256) // 4

        def data_moves_with_the_deferred_code():
            moved = [n for n in DATA if dgot["before"][word(n)] == 0 and dgot["whole_mem"][word(n)] != 0]
            assert moved == ["A", "D", "E", "I"], f"moved before the deferred module: {moved}"
            assert dgot["after"] == dgot["whole_mem"], f"memory after {dgot['after']} != {dgot['whole_mem']}"
            assert dfacts["data"] >= 4 * 4 + 8, dfacts
            return f"A, D, E, I moved ({dfacts['data']} bytes with padding); B, C, P, G, H, J stay"

        def data_read_first_screen_then_deferred():
            assert dgot["split"] == dgot["whole"], f"split {dgot['split']} != whole {dgot['whole']}"
            assert dgot["loads"] == [0, 0, 0, 0, 0, 1, 1, 1], dgot["loads"]
            return f"{dgot['whole']}: the five primary reads before any load, the deferred ones after"

        if got is None:
            results.extend([False] * 4)
        else:
            run("wasm_split::split_module_gives_the_same_results", same_results)
            run("wasm_split::deferred_loads_once_at_the_first_deferred_call", loads_once_at_first_deferred_call)
            run("wasm_split::profile_names_the_functions_that_ran", profile_names_what_ran)
            run("wasm_split::unknown_opcode_is_refused", unknown_code_stays_whole)
        if dgot is None:
            results.extend([False] * 2)
        else:
            run("wasm_split::read_only_data_only_deferred_code_reads_moves", data_moves_with_the_deferred_code)
            run("wasm_split::primary_reads_its_data_before_the_load", data_read_first_screen_then_deferred)

    passed = sum(results)
    line = f"test result: {'ok' if all(results) else 'FAILED'}. {passed} passed; {len(results) - passed} failed; wasm_split"
    print(line)
    if args.log:
        with open(args.log, "a", encoding="utf-8") as f:
            f.write(line + "\n")
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
