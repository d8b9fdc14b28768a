#!/usr/bin/env python3
"""Splits a page's wasm in two: the functions its first screen runs (the primary, which the page
loads) and the rest (the deferred module, fetched after the first screen, or at once when a
deferred function is called before it has arrived). Library of scripts/split_pages.py.

Why not binaryen's wasm-split: wasm-opt comes from npm (binaryen.js, no wasm-split) and Debian's
binaryen 108 reads wasm-bindgen's externref table as anyref, which browsers reject.

How, without renumbering anything in the primary:
- The primary keeps every function at its index, its imports, exports, element segments and
  names. A deferred function's body becomes a stub: call the table slot LOADER (type [] -> [])
  and then the function's own new table slot with the same arguments (call_indirect). The
  funcref table grows by one slot per deferred function plus LOADER.
- Before the app starts, the page's glue puts a JS loader into LOADER (made a wasm function by a
  tiny helper module). Once the deferred module is instantiated, its element segment fills the
  new slots with the real bodies and LOADER becomes a no-op.
- The deferred module imports the primary's memory, tables and globals in the primary's order
  (so their indices stay), the primary functions its bodies call (exported by the primary under
  short names) and defines the deferred functions; only its call/ref.func indices are renumbered.
Functions that use passive data or element segments (memory.init, table.init, …) stay in the
primary, as do SIMD bodies (the decoder does not read them).

Instrumentation (for the profile of what the first screen runs): each body first stores 1 in
its own byte of a page added above the initial memory, where dlmalloc never allocates (it grows
memory and starts at the old end)."""
import bisect

# --- LEB128 ---------------------------------------------------------------------------------


def leb(b, i, signed=False):
    """The LEB128 number at b[i] and the offset after it."""
    r = s = 0
    while True:
        x = b[i]
        i += 1
        r |= (x & 0x7F) << s
        s += 7
        if x < 0x80:
            return (r - (1 << s) if signed and x & 0x40 else r), i


def uleb(b, i):
    return leb(b, i)


def sleb(b, i):
    return leb(b, i, signed=True)


def enc_u(n):
    out = bytearray()
    while True:
        x, n = n & 0x7F, n >> 7
        out.append(x | 0x80 if n else x)
        if not n:
            return bytes(out)


def enc_s(n):
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


class Unsupported(Exception):
    """The module uses something this splitter does not handle: the page stays unsplit."""


# --- the module -------------------------------------------------------------------------------


def sections(b):
    if b[:8] != b"\0asm\x01\0\0\0":
        raise Unsupported("not a wasm module (version 1)")
    i, out = 8, []
    while i < len(b):
        sid = b[i]
        n, j = uleb(b, i + 1)
        out.append([sid, bytes(b[j:j + n])])
        i = j + n
    return out


def limits(b, i):
    flags, i = uleb(b, i)
    if flags & ~1:
        raise Unsupported(f"limits flags {flags} (shared or 64-bit)")
    lo, i = uleb(b, i)
    hi = None
    if flags & 1:
        hi, i = uleb(b, i)
    return (lo, hi), i


def enc_limits(lim):
    lo, hi = lim
    return (b"\x01" + enc_u(lo) + enc_u(hi)) if hi is not None else (b"\x00" + enc_u(lo))


def const_expr_end(b, i):
    """The end of a constant expression (global init, segment offset) starting at i."""
    while True:
        op = b[i]
        i += 1
        if op == 0x0B:
            return i
        if op in (0x41, 0x42):
            _, i = sleb(b, i)
        elif op == 0x43:
            i += 4
        elif op == 0x44:
            i += 8
        elif op in (0x23, 0xD2):
            _, i = uleb(b, i)
        elif op == 0xD0:
            _, i = sleb(b, i)
        elif op in (0x6A, 0x6B, 0x6C, 0x7C, 0x7D, 0x7E):
            pass
        else:
            raise Unsupported(f"constant expression opcode {op:#x}")


class Module:
    def __init__(self, data):
        self.secs = sections(data)
        self.types = []  # (params, results) as byte strings of valtypes
        self.imp_funcs = []  # type index of each imported function
        self.imp_globals = []  # (valtype, mut) of each imported global
        self.imp_tables = 0
        self.imp_memories = 0
        self.funcs = []  # type index of each defined function
        self.tables = []  # (reftype, limits) of each defined table
        self.memories = []  # limits of each defined memory
        self.globals = []  # (valtype, mut) of each defined global
        self.exports = []  # (name, kind, index)
        self.bodies = []
        for sid, body in self.secs:
            if sid == 1:
                self._types(body)
            elif sid == 2:
                self._imports(body)
            elif sid == 3:
                n, k = uleb(body, 0)
                for _ in range(n):
                    t, k = uleb(body, k)
                    self.funcs.append(t)
            elif sid == 4:
                n, k = uleb(body, 0)
                for _ in range(n):
                    rt = body[k]
                    if rt not in (0x70, 0x6F):
                        raise Unsupported(f"table type {rt:#x}")
                    lim, k = limits(body, k + 1)
                    self.tables.append((rt, lim))
            elif sid == 5:
                n, k = uleb(body, 0)
                for _ in range(n):
                    lim, k = limits(body, k)
                    self.memories.append(lim)
            elif sid == 6:
                n, k = uleb(body, 0)
                for _ in range(n):
                    vt, mut = body[k], body[k + 1]
                    k = const_expr_end(body, k + 2)
                    self.globals.append((vt, mut))
            elif sid == 7:
                n, k = uleb(body, 0)
                for _ in range(n):
                    ln, k = uleb(body, k)
                    name = body[k:k + ln].decode()
                    kind = body[k + ln]
                    idx, k = uleb(body, k + ln + 1)
                    self.exports.append((name, kind, idx))
            elif sid == 10:
                n, k = uleb(body, 0)
                for _ in range(n):
                    ln, k = uleb(body, k)
                    self.bodies.append(body[k:k + ln])
                    k += ln
        if len(self.bodies) != len(self.funcs):
            raise Unsupported("function and code sections differ")

    def _types(self, body):
        n, k = uleb(body, 0)
        for _ in range(n):
            if body[k] != 0x60:
                raise Unsupported(f"type form {body[k]:#x} (GC types)")
            np_, k = uleb(body, k + 1)
            params, k = body[k:k + np_], k + np_
            nr, k = uleb(body, k)
            results, k = body[k:k + nr], k + nr
            self.types.append((params, results))

    def _imports(self, body):
        n, k = uleb(body, 0)
        for _ in range(n):
            for _ in range(2):
                ln, k = uleb(body, k)
                k += ln
            kind = body[k]
            k += 1
            if kind == 0:
                t, k = uleb(body, k)
                self.imp_funcs.append(t)
            elif kind == 1:
                _, k = limits(body, k + 1)
                self.imp_tables += 1
            elif kind == 2:
                _, k = limits(body, k)
                self.imp_memories += 1
            elif kind == 3:
                self.imp_globals.append((body[k], body[k + 1]))
                k += 2
            else:
                raise Unsupported(f"import kind {kind}")

    def section(self, sid):
        return next((body for s, body in self.secs if s == sid), None)

    def write(self, replace):
        """The module with the sections in `replace` (id -> bytes) in place of its own."""
        if not set(replace) <= {sid for sid, _ in self.secs}:
            raise Unsupported("a section to replace is missing")
        out = bytearray(b"\0asm\x01\0\0\0")
        for sid, body in self.secs:
            body = replace.get(sid, body) if sid != 0 else body
            out += bytes([sid]) + enc_u(len(body)) + body
        return bytes(out)


# --- function bodies ---------------------------------------------------------------------------

# Opcodes with no immediates: numeric, parametric, end/else/return/unreachable/nop.
PLAIN = set(range(0x45, 0xC5)) | {0x00, 0x01, 0x05, 0x0B, 0x0F, 0x1A, 0x1B, 0xD1}
MEMARG = set(range(0x28, 0x3F))
VALTYPES = {0x7F, 0x7E, 0x7D, 0x7C, 0x7B, 0x70, 0x6F}


def code_start(body):
    """The offset of a body's first instruction (after its locals)."""
    n, k = uleb(body, 0)
    for _ in range(n):
        _, k = uleb(body, k)
        k += 1
    return k


def scan(body):
    """Walks a body's instructions. Returns (funcidx immediates as (start, end, index),
    whether it uses passive segments, every address it may form: its integer constants (each
    half of an i64) and memory offsets). Raises Unsupported on opcodes it does not know."""
    refs, passive, consts = [], False, []
    i = code_start(body)
    end = len(body)
    while i < end:
        op = body[i]
        i += 1
        if op in PLAIN:
            continue
        if op in (0x02, 0x03, 0x04):
            if body[i] == 0x40 or body[i] in VALTYPES:
                i += 1
            else:
                _, i = sleb(body, i)
        elif op in (0x0C, 0x0D, 0x20, 0x21, 0x22, 0x23, 0x24, 0x25, 0x26):
            _, i = uleb(body, i)
        elif op == 0x0E:
            n, i = uleb(body, i)
            for _ in range(n + 1):
                _, i = uleb(body, i)
        elif op in (0x10, 0x12, 0xD2):
            s = i
            f, i = uleb(body, i)
            refs.append((s, i, f))
        elif op in (0x11, 0x13):
            _, i = uleb(body, i)
            _, i = uleb(body, i)
        elif op == 0x1C:
            n, i = uleb(body, i)
            i += n
        elif op in MEMARG:
            align, i = uleb(body, i)
            if align & 0x40:
                _, i = uleb(body, i)
            offset, i = uleb(body, i)
            consts.append(offset)
        elif op in (0x3F, 0x40):
            _, i = uleb(body, i)
        elif op == 0x41:
            v, i = sleb(body, i)
            consts.append(v & 0xFFFFFFFF)
        elif op == 0x42:
            # Both halves: wasm-opt joins two i32 stores into one i64 store (a &str's address
            # and length in one constant).
            v, i = sleb(body, i)
            consts += [v & 0xFFFFFFFF, (v >> 32) & 0xFFFFFFFF]
        elif op == 0x43:
            i += 4
        elif op == 0x44:
            i += 8
        elif op == 0xD0:
            _, i = sleb(body, i)
        elif op == 0xFC:
            sub, i = uleb(body, i)
            if sub <= 7:
                pass
            elif sub in (8, 12, 14):
                _, i = uleb(body, i)
                _, i = uleb(body, i)
                passive = passive or sub in (8, 12)
            elif sub == 10:
                _, i = uleb(body, i)
                _, i = uleb(body, i)
            elif sub in (9, 13):
                _, i = uleb(body, i)
                passive = True
            elif sub in (11, 15, 16, 17):
                _, i = uleb(body, i)
            else:
                raise Unsupported(f"opcode 0xFC {sub}")
        else:
            raise Unsupported(f"opcode {op:#x}")
    if i != end or body[-1] != 0x0B:
        raise Unsupported("a body does not end where its size says")
    return refs, passive, consts


def renumbered(body, refs, new_index):
    out, last = bytearray(), 0
    for s, e, f in refs:
        out += body[last:s] + enc_u(new_index[f])
        last = e
    out += body[last:]
    return bytes(out)


# --- read-only data ---------------------------------------------------------------------------
# The texts and tables only deferred functions read can wait for the deferred module too: it
# writes them into the memory it imports when it is instantiated (active data segments), before
# any deferred function can run. Which those are comes from the linked binary (cargo's output,
# linked with --emit-relocs, web/build.rs): its symbol table bounds each read-only object, its
# relocations say which object each address in the code and in the data means (also an address
# folded with an offset that points outside its object). An object stays in the primary when the
# code the primary keeps holds an address inside it, at its end or meant for it, or when data
# that stays points to it; everything wasm-bindgen and wasm-opt did after the link is seen in the
# final code, which is what is searched.

# Relocation types (LLVM's WasmRelocs.def) with an addend; of those, the absolute memory
# addresses of wasm32. The others with an addend (PIC-relative, TLS, 64-bit) are refused.
RELOC_ADDEND = {3, 4, 5, 8, 9, 11, 14, 15, 16, 17, 21, 22, 23, 25}
RELOC_MEMORY = {3, 4, 5}
RELOC_OFFSETS = {8, 9, 22}  # function and section offsets (debug info): not memory
RELOC_NO_ADDEND = {0, 1, 2, 6, 7, 10, 12, 13, 18, 19, 20, 24, 26}


def data_segments(m):
    """(address or None, start of the bytes in the data section, length) of each segment."""
    body = m.section(11)
    if body is None:
        return []
    n, k = uleb(body, 0)
    out = []
    for _ in range(n):
        flags, k = uleb(body, k)
        if flags == 0 and body[k] == 0x41:
            addr, k = sleb(body, k + 1)
            if body[k] != 0x0B:
                raise Unsupported("a data segment's offset is not a constant")
            addr, k = addr & 0xFFFFFFFF, k + 1
        elif flags == 1:
            addr = None
        else:
            raise Unsupported(f"data segment flags {flags}")
        ln, k = uleb(body, k)
        out.append((addr, k, ln))
        k += ln
    return out


def custom(m, name):
    for sid, body in m.secs:
        if sid == 0:
            n, k = uleb(body, 0)
            if body[k:k + n] == name.encode():
                return body[k + n:]
    return None


class Objects:
    """Sorted, disjoint [start, end) intervals; which one holds an address."""

    def __init__(self, spans):
        self.spans = []
        for a, e in sorted(spans):
            if self.spans and a < self.spans[-1][1]:  # overlapping symbols: one object
                self.spans[-1] = (self.spans[-1][0], max(self.spans[-1][1], e))
            else:
                self.spans.append((a, e))
        self.starts = [a for a, _ in self.spans]

    def at(self, v):
        i = bisect.bisect_right(self.starts, v) - 1
        return i if i >= 0 and v < self.spans[i][1] else None


def linked_data(linked):
    """From the linked binary: (its read-only objects (Objects): the defined data symbols of
    its .rodata segments; the .rodata segments as [start, end) intervals; what each address the
    code's relocations write means, {value: {object}}; edges between data, [(site address,
    target object)]; the linked memory image as {segment address: bytes})."""
    lm = Module(linked)
    segs = data_segments(lm)
    link, rcode, rdata = custom(lm, "linking"), custom(lm, "reloc.CODE"), custom(lm, "reloc.DATA")
    if link is None or rcode is None:
        raise Unsupported("the linked binary has no relocations (linked without --emit-relocs)")
    version, k = uleb(link, 0)
    if version != 2:
        raise Unsupported(f"linking section version {version}")
    seg_names, symbols = [], []  # symbols: address of each (None: not a defined data symbol)
    while k < len(link):
        sub = link[k]
        n, k = uleb(link, k + 1)
        end = k + n
        if sub == 5:
            c, q = uleb(link, k)
            for _ in range(c):
                ln, q = uleb(link, q)
                seg_names.append(link[q:q + ln].decode())
                q += ln
                _, q = uleb(link, q)
                _, q = uleb(link, q)
        elif sub == 8:
            c, q = uleb(link, k)
            for _ in range(c):
                kind = link[q]
                flags, q = uleb(link, q + 1)
                defined = not flags & 0x10
                if kind in (0, 2, 4, 5):
                    _, q = uleb(link, q)
                    if defined or flags & 0x40:
                        ln, q = uleb(link, q)
                        q += ln
                    symbols.append(None)
                elif kind == 1:
                    ln, q = uleb(link, q)
                    q += ln
                    if defined:
                        seg, q = uleb(link, q)
                        off, q = uleb(link, q)
                        size, q = uleb(link, q)
                        symbols.append((seg, off, size))
                    else:
                        symbols.append(None)
                elif kind == 3:
                    _, q = uleb(link, q)
                    symbols.append(None)
                else:
                    raise Unsupported(f"symbol kind {kind}")
        k = end
    if len(seg_names) != len(segs) or any(a is None for a, _, _ in segs):
        raise Unsupported("the linked binary's data segments are not the ones its symbols name")
    address = [None if s is None else segs[s[0]][0] + s[1] for s in symbols]
    rodata = [(a, a + n) for (a, _, n), name in zip(segs, seg_names) if name.startswith(".rodata")]
    objects = Objects((segs[s[0]][0] + s[1], segs[s[0]][0] + s[1] + s[2]) for s in symbols
                      if s is not None and s[2] and seg_names[s[0]].startswith(".rodata"))

    def relocs(body):
        _, q = uleb(body, 0)
        c, q = uleb(body, q)
        for _ in range(c):
            t = body[q]
            off, q = uleb(body, q + 1)
            idx, q = uleb(body, q)
            addend = 0
            if t in RELOC_ADDEND:
                addend, q = sleb(body, q)
            elif t not in RELOC_NO_ADDEND:
                raise Unsupported(f"relocation type {t}")
            if t in RELOC_ADDEND - RELOC_MEMORY - RELOC_OFFSETS:
                raise Unsupported(f"relocation type {t} (not an absolute wasm32 address)")
            if t in RELOC_MEMORY:
                if idx >= len(symbols) or address[idx] is None:
                    raise Unsupported("a memory relocation names no defined data symbol")
                yield t, off, address[idx], (address[idx] + addend) & 0xFFFFFFFF

    def written(body, t, off):
        """The value the linker wrote at a relocation's site (checks how it was read)."""
        if t == 5:
            return int.from_bytes(body[off:off + 4], "little")
        return (sleb(body, off) if t == 4 else uleb(body, off))[0] & 0xFFFFFFFF

    code_body, data_body = lm.section(10), lm.section(11) or b""
    meant = {}
    for t, off, sym, value in relocs(rcode):
        if written(code_body, t, off) != value:
            raise Unsupported(f"a code relocation at {off} does not hold its address")
        o = objects.at(sym)
        if o is not None:
            meant.setdefault(value, set()).add(o)
    edges = []
    for t, off, sym, value in relocs(rdata) if rdata is not None else ():
        seg = next((s for s in segs if s[1] <= off < s[1] + s[2]), None)
        if seg is None or written(data_body, t, off) != value:
            raise Unsupported(f"a data relocation at {off} is not a pointer in the data")
        edges.append((seg[0] + off - seg[1], objects.at(sym)))
    image = {a: data_body[s:s + n] for a, s, n in segs}
    return objects, rodata, meant, edges, image


def plan_data(m, linked, kept_consts):
    """(The runs of (address, bytes) the deferred module writes: the read-only objects only
    deferred code reads, checked to hold the same bytes in the linked binary and in `m`; the
    primary's segments without those objects). `kept_consts`: the addresses the primary's code
    may form (scan)."""
    objects, rodata, meant, edges, image = linked_data(linked)
    by_end = {e: i for i, (_, e) in enumerate(objects.spans)}
    need, todo = set(), []

    def mark(v):
        # The object an address is inside, the one it ends (an end pointer wasm-opt folded
        # itself), and those its relocation means.
        for o in (objects.at(v), by_end.get(v), *meant.get(v, ())):
            if o is not None and o not in need:
                need.add(o)
                todo.append(o)

    for consts in [*kept_consts, global_consts(m)]:
        for v in consts:
            mark(v)
    out_edges = {}
    for site, target in edges:
        if target is None:
            continue
        source = objects.at(site)
        if source is None:  # a pointer in mutable data (or between objects): always there
            if target not in need:
                need.add(target)
                todo.append(target)
        else:
            out_edges.setdefault(source, []).append(target)
    while todo:
        for t in out_edges.get(todo.pop(), ()):
            if t not in need:
                need.add(t)
                todo.append(t)
    deferred = [span for i, span in enumerate(objects.spans) if i not in need]
    # The same bytes after wasm-bindgen and wasm-opt (which must not have moved any data).
    final = MemoryImage(m)
    for a, e in deferred:
        seg = next((s for s in image if s <= a and e <= s + len(image[s])), None)
        if seg is None or image[seg][a - seg:e - seg] != final.read(a, e):
            raise Unsupported(f"the data at {a:#x} differs from the linked binary's")
    # As runs: a gap of up to 8 bytes (padding) between two objects of one .rodata segment is
    # written along with them, the same read-only bytes the primary keeps there.
    runs = []
    for a, e in deferred:
        if runs and a - runs[-1][1] <= 8 and any(lo <= runs[-1][0] and a < hi for lo, hi in rodata):
            runs[-1][1] = e
        else:
            runs.append([a, e])
    return [(a, final.read(a, e)) for a, e in runs], without(final.segs, deferred)


def global_consts(m):
    """The integer constants the globals start with (wasm-opt may keep an address in one)."""
    out = []
    body = m.section(6)
    if body is not None:
        n, k = uleb(body, 0)
        for _ in range(n):
            k += 2
            if body[k] in (0x41, 0x42):
                v, _ = sleb(body, k + 1)
                out += [v & 0xFFFFFFFF, (v >> 32) & 0xFFFFFFFF]
            k = const_expr_end(body, k)
    return out


class MemoryImage:
    """A module's initial memory from its active data segments."""

    def __init__(self, m):
        self.segs = []
        body = m.section(11) or b""
        for addr, start, n in data_segments(m):
            if addr is None:
                raise Unsupported("a passive data segment")
            self.segs.append((addr, body[start:start + n]))

    def read(self, a, e):
        out = bytearray(e - a)
        for addr, b in self.segs:
            lo, hi = max(a, addr), min(e, addr + len(b))
            if lo < hi:
                out[lo - a:hi - a] = b[lo - addr:hi - addr]
        return bytes(out)


def data_section(segments):
    """An active data section of (address, bytes), leaving out the bytes that are zero anyway."""
    out, n = bytearray(), 0
    for addr, b in segments:
        if any(b):
            out += b"\x00\x41" + enc_s(addr) + b"\x0b" + enc_u(len(b)) + b
            n += 1
    return enc_u(n) + bytes(out), n


def without(segments, cut):
    """The segments (address, bytes) with the intervals `cut` (sorted, disjoint) taken out."""
    out = []
    for addr, b in segments:
        pos, end = addr, addr + len(b)
        for a, e in cut:
            if e <= pos or a >= end:
                continue
            if a > pos:
                out.append((pos, b[pos - addr:a - addr]))
            pos = max(pos, e)
        if pos < end:
            out.append((pos, b[pos - addr:]))
    return out


# --- instrumenting ----------------------------------------------------------------------------


def instrument(data):
    """The module with a profile byte per defined function. Returns (bytes, address of byte 0,
    number of functions)."""
    m = Module(data)
    if len(m.memories) != 1:
        raise Unsupported("not exactly one defined memory")
    lo, hi = m.memories[0]
    addr = lo * 65536
    mem = b"\x01" + enc_limits((lo + 1, None if hi is None else max(hi, lo + 1)))
    code = bytearray(enc_u(len(m.bodies)))
    for k, body in enumerate(m.bodies):
        c = code_start(body)
        # i32.const addr+k; i32.const 1; i32.store8 align=0 offset=0
        probe = b"\x41" + enc_s(addr + k) + b"\x41\x01\x3a\x00\x00"
        new = body[:c] + probe + body[c:]
        code += enc_u(len(new)) + new
    return m.write({5: mem, 10: bytes(code)}), addr, len(m.bodies)


# --- splitting --------------------------------------------------------------------------------

EXPORT_TABLE = "__split_table"


def short_name(prefix, n):
    digits = "0123456789abcdefghijklmnopqrstuvwxyz"
    s = ""
    while True:
        s = digits[n % 36] + s
        n //= 36
        if not n:
            return prefix + s


def split(data, run, linked=None):
    """Splits by `run` (one flag per defined function: ran on the first screen); with `linked`
    (the linked binary, see plan_data) the read-only data only deferred functions read goes too.
    Returns (primary bytes, deferred bytes, facts for the loader: loader slot, table export name,
    deferred count, deferred data bytes)."""
    m = Module(data)
    nimp = len(m.imp_funcs)
    if m.section(8) is not None:
        raise Unsupported("a start function (it would run before the loader is in its slot)")
    if len(run) != len(m.funcs):
        raise Unsupported("the profile is of another build")
    if m.imp_tables or not m.tables or m.tables[0][0] != 0x70:
        raise Unsupported("table 0 is not a defined funcref table")
    if m.imp_memories or len(m.memories) != 1:
        raise Unsupported("not exactly one defined memory")
    scans = [scan(b) for b in m.bodies]
    exported = {idx for _, kind, idx in m.exports if kind == 0}
    deferred = [k for k in range(len(m.funcs))
                if not run[k] and not scans[k][1] and nimp + k not in exported]
    if not deferred:
        raise Unsupported("nothing to defer")
    dset = {nimp + k for k in deferred}

    # Types: a [] -> [] type for LOADER.
    types = list(m.types)
    if (b"", b"") not in types:
        types.append((b"", b""))
    void = types.index((b"", b""))
    type_sec = enc_u(len(types)) + b"".join(
        b"\x60" + enc_u(len(p)) + p + enc_u(len(r)) + r for p, r in types)

    reftype, (lo, hi) = m.tables[0]
    if hi is not None and hi != lo:
        raise Unsupported("table 0 may grow at run time")
    base = lo
    slot = {nimp + k: base + n for n, k in enumerate(deferred)}
    loader = base + len(deferred)
    size = loader + 1

    # Primary: stubs, the larger table, exports for the deferred module.
    code = bytearray(enc_u(len(m.bodies)))
    for k, body in enumerate(m.bodies):
        f = nimp + k
        if f in dset:
            t = m.funcs[k]
            args = b"".join(b"\x20" + enc_u(a) for a in range(len(types[t][0])))
            body = (b"\x00" + b"\x41" + enc_s(loader) + b"\x11" + enc_u(void) + b"\x00"
                    + args + b"\x41" + enc_s(slot[f]) + b"\x11" + enc_u(t) + b"\x00" + b"\x0b")
        code += enc_u(len(body)) + body
    table_body = m.section(4)
    n, k = uleb(table_body, 0)
    _, after = limits(table_body, k + 1)
    table_sec = enc_u(n) + bytes([reftype]) + enc_limits((size, size)) + table_body[after:]

    # What the deferred bodies call in the primary.
    needed = sorted({f for k in deferred for _, _, f in scans[k][0] if f not in dset})
    have = {(kind, idx): name for name, kind, idx in m.exports}
    new_exports = []

    def export(kind, idx, name):
        if (kind, idx) not in have:
            have[(kind, idx)] = name
            new_exports.append((name, kind, idx))
        return have[(kind, idx)]

    # Function names are "~" and base-36 digits (lower case); the others upper case after "~".
    if any(name.startswith("~") for name, _, _ in m.exports):
        raise Unsupported("an export name starts with ~")
    export(1, 0, EXPORT_TABLE)
    table_names = [export(1, t, short_name("~T", t)) for t in range(len(m.tables))]
    memory_name = export(2, 0, "~M")
    all_globals = m.imp_globals + m.globals
    global_names = [export(3, g, short_name("~G", g)) for g in range(len(all_globals))]
    func_names = {f: export(0, f, short_name("~", f)) for f in needed}
    exp_sec = bytearray(enc_u(len(m.exports) + len(new_exports)))
    for name, kind, idx in m.exports + new_exports:
        exp_sec += enc_name(name) + bytes([kind]) + enc_u(idx)
    replace = {10: bytes(code), 4: table_sec, 7: bytes(exp_sec)}
    replace[1] = type_sec
    moved = []
    if linked is not None:
        moved, kept = plan_data(m, linked, [scans[k][2] for k in range(len(m.bodies)) if nimp + k not in dset])
        if moved:
            replace[11], count = data_section(kept)
            if m.section(12) is not None:
                replace[12] = enc_u(count)
    primary = m.write(replace)

    # Deferred: imports in the primary's order, then its own functions.
    mod = "p"
    imps = []
    for f in needed:
        t = m.imp_funcs[f] if f < nimp else m.funcs[f - nimp]
        imps.append(enc_name(mod) + enc_name(func_names[f]) + b"\x00" + enc_u(t))
    for t, (rt, _) in enumerate(m.tables):
        lim = (size, size) if t == 0 else m.tables[t][1]
        imps.append(enc_name(mod) + enc_name(table_names[t]) + b"\x01" + bytes([rt]) + enc_limits(lim))
    imps.append(enc_name(mod) + enc_name(memory_name) + b"\x02" + enc_limits(m.memories[0]))
    for g, (vt, mut) in enumerate(all_globals):
        imps.append(enc_name(mod) + enc_name(global_names[g]) + b"\x03" + bytes([vt, mut]))
    new_index = {f: n for n, f in enumerate(needed)}
    for n, k in enumerate(deferred):
        new_index[nimp + k] = len(needed) + n
    out = bytearray(b"\0asm\x01\0\0\0")

    def sec(sid, body):
        out.extend(bytes([sid]) + enc_u(len(body)) + body)

    sec(1, type_sec)
    sec(2, enc_u(len(imps)) + b"".join(imps))
    sec(3, enc_u(len(deferred)) + b"".join(enc_u(m.funcs[k]) for k in deferred))
    elem = (b"\x00" + b"\x41" + enc_s(base) + b"\x0b" + enc_u(len(deferred))
            + b"".join(enc_u(new_index[nimp + k]) for k in deferred))
    sec(9, b"\x01" + elem)
    dcode = bytearray(enc_u(len(deferred)))
    old_index = {n: f for f, n in new_index.items()}
    for k in deferred:
        body = renumbered(m.bodies[k], scans[k][0], new_index)
        # Read back: the same body once its calls are numbered as in the original.
        refs, _, _ = scan(body)
        if renumbered(body, refs, old_index) != m.bodies[k]:
            raise Unsupported(f"function {nimp + k} does not read back the same")
        dcode += enc_u(len(body)) + body
    sec(10, bytes(dcode))
    if moved:
        sec(11, data_section(moved)[0])
    # The features the bodies use, for tools that validate the module (wasm-opt).
    for sid, body in m.secs:
        if sid == 0 and body.startswith(enc_name("target_features")):
            sec(0, body)
    return primary, bytes(out), {"loader": loader, "table": EXPORT_TABLE, "deferred": len(deferred),
                                 "functions": len(m.funcs), "data": sum(len(b) for _, b in moved)}
