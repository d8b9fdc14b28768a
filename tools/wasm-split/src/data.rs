//! The read-only data only deferred functions read waits for the deferred module too: it writes
//! it into the memory it imports when it is instantiated (active data segments), before any
//! deferred function can run. Which data that is comes from the linked binary (cargo's output,
//! linked with `--emit-relocs`, web/build.rs): its symbol table bounds each read-only object, its
//! relocations say which object each address in the code and in the data means (also an address
//! folded with an offset that points outside its object). An object stays in the primary when
//! the code the primary keeps holds an address inside it, at its end or meant for it, or when
//! data that stays points to it; everything wasm-bindgen and wasm-opt did after the link is seen
//! in the final code, which is what is searched.

use std::collections::{BTreeMap, HashMap, HashSet};

use wasmparser::{BinaryReader, KnownCustom, Linking, RelocationType, SymbolInfo};

use crate::Unsupported;
use crate::module::{Module, Res};

/// Sorted, disjoint [start, end) intervals: the read-only objects; which one holds an address.
struct Objects {
    spans: Vec<(u32, u32)>,
}

impl Objects {
    fn new(mut spans: Vec<(u32, u32)>) -> Objects {
        spans.sort_unstable();
        let mut out: Vec<(u32, u32)> = Vec::new();
        for (a, e) in spans {
            match out.last_mut() {
                // Overlapping symbols: one object.
                Some(last) if a < last.1 => last.1 = last.1.max(e),
                _ => out.push((a, e)),
            }
        }
        Objects { spans: out }
    }

    fn at(&self, v: u32) -> Option<usize> {
        let i = self.spans.partition_point(|&(a, _)| a <= v).checked_sub(1)?;
        (v < self.spans[i].1).then_some(i)
    }
}

/// What the linked binary says: its read-only objects, its `.rodata` segments, what each
/// address its code's relocations write means, the pointers between data (site address, target
/// object) and its memory image (segment address, bytes).
struct Linked {
    objects: Objects,
    rodata: Vec<(u32, u32)>,
    meant: HashMap<u32, HashSet<usize>>,
    edges: Vec<(u32, Option<usize>)>,
    image: Vec<(u32, Vec<u8>)>,
}

/// A relocation of an absolute wasm32 memory address: its offset, the symbol's address and the
/// value written there (symbol + addend).
struct MemoryReloc {
    ty: RelocationType,
    offset: u32,
    symbol: u32,
    value: u32,
}

fn linked(data: &[u8]) -> Res<Linked> {
    let lm = Module::read(data)?;
    let segs = &lm.segments;
    let (Some(KnownCustom::Linking(link)), Some(KnownCustom::Reloc(rcode))) =
        (lm.known("linking"), lm.known("reloc.CODE"))
    else {
        return Err(Unsupported(
            "the linked binary has no relocations (linked without --emit-relocs)".into(),
        ));
    };
    if link.version() != 2 {
        return Err(Unsupported(format!("linking section version {}", link.version())));
    }
    let mut seg_names = Vec::new();
    // The address of each symbol (None: not a defined data symbol) and its size.
    let mut symbols: Vec<Option<(u32, u32, u32)>> = Vec::new();
    for sub in link.subsections() {
        match sub? {
            Linking::SegmentInfo(map) => {
                for s in map {
                    seg_names.push(s?.name.to_owned());
                }
            }
            Linking::SymbolTable(map) => {
                for info in map {
                    symbols.push(match info? {
                        SymbolInfo::Data { symbol: Some(d), .. } => Some((d.index, d.offset, d.size)),
                        _ => None,
                    });
                }
            }
            _ => {}
        }
    }
    if seg_names.len() != segs.len() || segs.iter().any(|s| s.address.is_none()) {
        return Err(Unsupported(
            "the linked binary's data segments are not the ones its symbols name".into(),
        ));
    }
    let seg_address = |i: u32| segs.get(i as usize).and_then(|s| s.address);
    let address: Vec<Option<u32>> =
        symbols.iter().map(|s| s.and_then(|(seg, off, _)| Some(seg_address(seg)? + off))).collect();
    let rodata = segs
        .iter()
        .zip(&seg_names)
        .filter(|(_, n)| n.starts_with(".rodata"))
        .filter_map(|(s, _)| Some((s.address?, s.address? + s.bytes.len() as u32)))
        .collect();
    let objects = Objects::new(
        symbols
            .iter()
            .flatten()
            .filter(|(seg, _, size)| {
                *size > 0 && seg_names.get(*seg as usize).is_some_and(|n| n.starts_with(".rodata"))
            })
            .filter_map(|&(seg, off, size)| Some((seg_address(seg)? + off, seg_address(seg)? + off + size)))
            .collect(),
    );

    let relocs = |r: &wasmparser::RelocSectionReader<'_>| -> Res<Vec<MemoryReloc>> {
        let mut out = Vec::new();
        for e in r.entries() {
            let e = e?;
            use RelocationType::*;
            match e.ty {
                MemoryAddrLeb | MemoryAddrSleb | MemoryAddrI32 => {
                    let sym = address.get(e.index as usize).copied().flatten().ok_or_else(|| {
                        Unsupported("a memory relocation names no defined data symbol".into())
                    })?;
                    out.push(MemoryReloc {
                        ty: e.ty,
                        offset: e.offset,
                        symbol: sym,
                        value: (i64::from(sym) + e.addend) as u32,
                    });
                }
                // Function and section offsets (debug info) are no memory addresses.
                FunctionOffsetI32 | SectionOffsetI32 | FunctionOffsetI64 => {}
                ty if e.addend != 0 || !matches!(ty.addend_kind(), wasmparser::RelocAddendKind::None) => {
                    return Err(Unsupported(format!(
                        "relocation type {ty:?} (not an absolute wasm32 address)"
                    )));
                }
                _ => {}
            }
        }
        Ok(out)
    };
    // The value the linker wrote at a relocation's site (checks how it was read).
    let written = |section: &[u8], base: usize, r: &MemoryReloc| -> Option<u32> {
        let at = r.offset as usize;
        let mut reader = BinaryReader::new(section.get(at..)?, base + at);
        match r.ty {
            RelocationType::MemoryAddrI32 => {
                Some(u32::from_le_bytes(section.get(at..at + 4)?.try_into().ok()?))
            }
            RelocationType::MemoryAddrSleb => reader.read_var_i32().ok().map(|v| v as u32),
            _ => reader.read_var_u32().ok(),
        }
    };

    let code = lm.section(10).unwrap_or_default();
    let code_start = lm.section_start(10).unwrap_or(0);
    let mut meant: HashMap<u32, HashSet<usize>> = HashMap::new();
    for r in relocs(&rcode)? {
        if written(code, code_start, &r) != Some(r.value) {
            return Err(Unsupported(format!("a code relocation at {} does not hold its address", r.offset)));
        }
        if let Some(o) = objects.at(r.symbol) {
            meant.entry(r.value).or_default().insert(o);
        }
    }
    let data_section = lm.section(11).unwrap_or_default();
    let data_start = lm.section_start(11).unwrap_or(0);
    let mut edges = Vec::new();
    if let Some(KnownCustom::Reloc(rdata)) = lm.known("reloc.DATA") {
        for r in relocs(&rdata)? {
            let off = r.offset as usize;
            let seg = segs.iter().find(|s| s.in_section <= off && off < s.in_section + s.bytes.len());
            match seg {
                Some(s) if written(data_section, data_start, &r) == Some(r.value) => {
                    edges.push((s.address.unwrap_or(0) + (off - s.in_section) as u32, objects.at(r.symbol)));
                }
                _ => {
                    return Err(Unsupported(format!(
                        "a data relocation at {off} is not a pointer in the data"
                    )));
                }
            }
        }
    }
    let image = segs.iter().map(|s| (s.address.unwrap_or(0), data[s.bytes.clone()].to_vec())).collect();
    Ok(Linked { objects, rodata, meant, edges, image })
}

/// A module's initial memory from its active data segments.
pub struct MemoryImage {
    pub segs: Runs,
}

impl MemoryImage {
    pub fn of(m: &Module<'_>) -> Res<MemoryImage> {
        let mut segs = Vec::new();
        for s in &m.segments {
            let a = s.address.ok_or_else(|| Unsupported("a passive data segment".into()))?;
            segs.push((a, m.data[s.bytes.clone()].to_vec()));
        }
        Ok(MemoryImage { segs })
    }

    fn read(&self, a: u32, e: u32) -> Vec<u8> {
        let mut out = vec![0; (e - a) as usize];
        for (addr, b) in &self.segs {
            let (lo, hi) = (a.max(*addr), e.min(addr + b.len() as u32));
            if lo < hi {
                out[(lo - a) as usize..(hi - a) as usize]
                    .copy_from_slice(&b[(lo - addr) as usize..(hi - addr) as usize]);
            }
        }
        out
    }
}

/// Data as (address, bytes) runs.
pub type Runs = Vec<(u32, Vec<u8>)>;

/// The data a split moves: (the runs of (address, bytes) the deferred module writes — the
/// read-only objects only deferred code reads, checked to hold the same bytes in the linked
/// binary and in `m` —, the primary's segments without them). `kept_consts`: the addresses the
/// primary's code may form.
pub fn plan(m: &Module<'_>, linked_bytes: &[u8], kept_consts: &[u32]) -> Res<(Runs, Runs)> {
    let l = linked(linked_bytes)?;
    let by_end: HashMap<u32, usize> = l.objects.spans.iter().enumerate().map(|(i, &(_, e))| (e, i)).collect();
    let mut need = HashSet::new();
    let mut todo = Vec::new();
    let mark = |o: usize, need: &mut HashSet<usize>, todo: &mut Vec<usize>| {
        if need.insert(o) {
            todo.push(o);
        }
    };
    // The object an address is inside, the one it ends (an end pointer wasm-opt folded itself),
    // and those its relocation means.
    for &v in kept_consts.iter().chain(&m.global_consts) {
        for o in l.objects.at(v).into_iter().chain(by_end.get(&v).copied()) {
            mark(o, &mut need, &mut todo);
        }
        for &o in l.meant.get(&v).into_iter().flatten() {
            mark(o, &mut need, &mut todo);
        }
    }
    let mut out_edges: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for &(site, target) in &l.edges {
        let Some(target) = target else { continue };
        match l.objects.at(site) {
            // A pointer in mutable data (or between objects): always there.
            None => mark(target, &mut need, &mut todo),
            Some(source) => out_edges.entry(source).or_default().push(target),
        }
    }
    while let Some(o) = todo.pop() {
        for &t in out_edges.get(&o).into_iter().flatten() {
            mark(t, &mut need, &mut todo);
        }
    }
    let deferred: Vec<(u32, u32)> =
        l.objects.spans.iter().enumerate().filter(|(i, _)| !need.contains(i)).map(|(_, &s)| s).collect();
    // The same bytes after wasm-bindgen and wasm-opt (which must not have moved any data).
    let last = MemoryImage::of(m)?;
    for &(a, e) in &deferred {
        let same = l
            .image
            .iter()
            .find(|(s, b)| *s <= a && e <= s + b.len() as u32)
            .is_some_and(|(s, b)| b[(a - s) as usize..(e - s) as usize] == last.read(a, e)[..]);
        if !same {
            return Err(Unsupported(format!("the data at {a:#x} differs from the linked binary's")));
        }
    }
    // As runs: a gap of up to 8 bytes (padding) between two objects of one .rodata segment is
    // written along with them, the same read-only bytes the primary keeps there.
    let mut runs: Vec<(u32, u32)> = Vec::new();
    for &(a, e) in &deferred {
        match runs.last_mut() {
            Some(run) if a - run.1 <= 8 && l.rodata.iter().any(|&(lo, hi)| lo <= run.0 && a < hi) => {
                run.1 = e
            }
            _ => runs.push((a, e)),
        }
    }
    let moved = runs.iter().map(|&(a, e)| (a, last.read(a, e))).collect();
    Ok((moved, without(&last.segs, &deferred)))
}

/// The segments (address, bytes) with the intervals `cut` (sorted, disjoint) taken out.
fn without(segments: &[(u32, Vec<u8>)], cut: &[(u32, u32)]) -> Runs {
    let mut out = Vec::new();
    for (addr, b) in segments {
        let (mut pos, end) = (*addr, addr + b.len() as u32);
        for &(a, e) in cut {
            if e <= pos || a >= end {
                continue;
            }
            if a > pos {
                out.push((pos, b[(pos - addr) as usize..(a - addr) as usize].to_vec()));
            }
            pos = pos.max(e);
        }
        if pos < end {
            out.push((pos, b[(pos - addr) as usize..].to_vec()));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlapping_symbols_are_one_object_and_an_address_finds_its_own() {
        let o = Objects::new(vec![(20, 30), (0, 8), (4, 12), (30, 31)]);
        assert_eq!(o.spans, [(0, 12), (20, 30), (30, 31)]);
        assert_eq!(
            [o.at(0), o.at(11), o.at(12), o.at(19), o.at(29), o.at(30)],
            [Some(0), Some(0), None, None, Some(1), Some(2)]
        );
    }

    #[test]
    fn without_cuts_the_intervals_out_of_the_segments() {
        let segs = vec![(100, (0u8..20).collect::<Vec<_>>()), (200, vec![9; 4])];
        let got = without(&segs, &[(104, 108), (118, 202)]);
        assert_eq!(got, [(100, vec![0, 1, 2, 3]), (108, (8u8..18).collect()), (202, vec![9, 9])]);
    }
}
