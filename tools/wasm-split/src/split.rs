//! The split and the profile's instrumentation.
//!
//! How, without renumbering anything in the primary:
//! - The primary keeps every function at its index, its imports, exports, element segments and
//!   names. A deferred function's body becomes a stub: call the table slot LOADER (type [] -> [])
//!   and then the function's own new table slot with the same arguments (`call_indirect`). The
//!   funcref table grows by one slot per deferred function plus LOADER.
//! - Before the app starts, the page's glue puts a JS loader into LOADER (made a wasm function by
//!   a tiny helper module, scripts/split_pages.py). Once the deferred module is instantiated, its
//!   element segment fills the new slots with the real bodies and LOADER becomes a no-op.
//! - The deferred module imports the primary's memory, tables and globals in the primary's order
//!   (so their indices stay), the primary functions its bodies call (exported by the primary
//!   under short names) and defines the deferred functions; only its function indices are
//!   renumbered (wasm-encoder's reencoder).
//!
//! Functions that use passive data or element segments (`memory.init`, `table.init`, …) stay in
//! the primary.

use std::borrow::Cow;
use std::collections::{BTreeSet, HashMap};

use wasm_encoder::reencode::{Reencode, RoundtripReencoder};
use wasm_encoder::{
    CodeSection, ConstExpr, DataCountSection, DataSection, ElementSection, Elements, EntityType,
    ExportSection, Function, FunctionSection, ImportSection, Instruction, MemArg, MemorySection, MemoryType,
    RawSection, TableSection, TableType, TypeSection,
};
use wasmparser::{ExternalKind, FuncType};

use crate::Unsupported;
use crate::data;
use crate::module::{Module, Res, scan};

/// The export of the funcref table the loader fills.
pub const EXPORT_TABLE: &str = "__split_table";

/// What the page's loader needs to know, and the figures split_pages.py prints.
pub struct Facts {
    pub loader: u32,
    pub deferred: usize,
    pub functions: usize,
    pub data: usize,
}

fn val(v: wasmparser::ValType) -> Res<wasm_encoder::ValType> {
    RoundtripReencoder.val_type(v).map_err(|e| Unsupported(format!("a value type: {e:?}")))
}

fn types_section(types: &[FuncType]) -> Res<TypeSection> {
    let mut s = TypeSection::new();
    for t in types {
        let params = t.params().iter().map(|&v| val(v)).collect::<Res<Vec<_>>>()?;
        let results = t.results().iter().map(|&v| val(v)).collect::<Res<Vec<_>>>()?;
        s.ty().function(params, results);
    }
    Ok(s)
}

fn memory_type(m: wasmparser::MemoryType) -> Res<MemoryType> {
    RoundtripReencoder.memory_type(m).map_err(|e| Unsupported(format!("a memory type: {e:?}")))
}

fn table_type(t: &wasmparser::TableType) -> Res<TableType> {
    RoundtripReencoder.table_type(*t).map_err(|e| Unsupported(format!("a table type: {e:?}")))
}

/// `prefix` and `n` in base 36 (lower case digits and letters).
fn short_name(prefix: &str, mut n: usize) -> String {
    const DIGITS: &[u8] = b"0123456789abcdefghijklmnopqrstuvwxyz";
    let mut s = Vec::new();
    loop {
        s.push(DIGITS[n % 36]);
        n /= 36;
        if n == 0 {
            break;
        }
    }
    s.reverse();
    format!("{prefix}{}", String::from_utf8_lossy(&s))
}

/// An active data section of (address, bytes) for memory 0, leaving out the segments that are
/// all zero (the memory is zero anyway); with the number of segments.
fn data_section(segments: &[(u32, Vec<u8>)]) -> (DataSection, u32) {
    let mut s = DataSection::new();
    for (addr, b) in segments.iter().filter(|(_, b)| b.iter().any(|&x| x != 0)) {
        s.active(0, &ConstExpr::i32_const(*addr as i32), b.iter().copied());
    }
    let n = s.len();
    (s, n)
}

/// The module `m` written with `replace` (section id → new section bytes) in place of its own
/// sections of those ids; the others as they were.
fn write(m: &Module<'_>, replace: &HashMap<u8, Vec<u8>>) -> Res<Vec<u8>> {
    for id in replace.keys() {
        if !m.sections.iter().any(|(s, _)| s == id) {
            return Err(Unsupported(format!("section {id} to replace is missing")));
        }
    }
    let mut out = wasm_encoder::Module::new();
    for (id, range) in &m.sections {
        let data = match replace.get(id) {
            Some(new) if *id != 0 => &new[..],
            _ => &m.data[range.clone()],
        };
        out.section(&RawSection { id: *id, data });
    }
    Ok(out.finish())
}

/// The bytes of an instruction.
fn instruction(i: &Instruction<'_>) -> Vec<u8> {
    let mut v = Vec::new();
    wasm_encoder::Encode::encode(i, &mut v);
    v
}

/// A section's content: what its `Encode` writes after the content's size.
fn content(s: &impl wasm_encoder::Encode) -> Res<Vec<u8>> {
    let mut v = Vec::new();
    s.encode(&mut v);
    let mut reader = wasmparser::BinaryReader::new(&v, 0);
    let size = reader.read_var_u32()? as usize;
    let start = reader.original_position();
    Ok(v[start..start + size].to_vec())
}

/// Splits `data` by `run` (one flag per defined function: ran on the first screen); with
/// `linked` (the linked binary, see [`data::plan`]) the read-only data only deferred functions
/// read goes too. Returns (primary, deferred, facts).
pub fn split(data: &[u8], run: &[bool], linked: Option<&[u8]>) -> Res<(Vec<u8>, Vec<u8>, Facts)> {
    let m = Module::read(data)?;
    let nimp = m.imp_funcs.len() as u32;
    if m.start {
        return Err(Unsupported("a start function (it would run before the loader is in its slot)".into()));
    }
    if run.len() != m.funcs.len() {
        return Err(Unsupported("the profile is of another build".into()));
    }
    if m.imp_tables > 0 || m.tables.first().is_none_or(|t| t.element_type != wasmparser::RefType::FUNCREF) {
        return Err(Unsupported("table 0 is not a defined funcref table".into()));
    }
    if m.imp_memories > 0 || m.memories.len() != 1 {
        return Err(Unsupported("not exactly one defined memory".into()));
    }
    let scans = m.bodies.iter().map(scan).collect::<Res<Vec<_>>>()?;
    let exported: BTreeSet<u32> =
        m.exports.iter().filter(|(_, k, _)| *k == ExternalKind::Func).map(|(_, _, i)| *i).collect();
    let deferred: Vec<usize> = (0..m.funcs.len())
        .filter(|&k| !run[k] && !scans[k].passive && !exported.contains(&(nimp + k as u32)))
        .collect();
    if deferred.is_empty() {
        return Err(Unsupported("nothing to defer".into()));
    }
    let dset: BTreeSet<u32> = deferred.iter().map(|&k| nimp + k as u32).collect();

    // Types: a [] -> [] type for LOADER.
    let mut types = m.types.clone();
    let void = match types.iter().position(|t| t.params().is_empty() && t.results().is_empty()) {
        Some(i) => i as u32,
        None => {
            types.push(FuncType::new([], []));
            types.len() as u32 - 1
        }
    };
    let type_sec = types_section(&types)?;

    let t0 = m.tables[0];
    if t0.maximum.is_some_and(|max| max != t0.initial) || t0.maximum.is_none() {
        return Err(Unsupported("table 0 may grow at run time".into()));
    }
    let base = u32::try_from(t0.initial).map_err(|_| Unsupported("a 64-bit table".into()))?;
    let slot: HashMap<u32, u32> =
        deferred.iter().enumerate().map(|(n, &k)| (nimp + k as u32, base + n as u32)).collect();
    let loader = base + deferred.len() as u32;
    let size = loader + 1;
    let grown = TableType { minimum: u64::from(size), maximum: Some(u64::from(size)), ..table_type(&t0)? };

    // Primary: stubs, the larger table, exports for the deferred module.
    let mut code = CodeSection::new();
    for (k, body) in m.bodies.iter().enumerate() {
        let f = nimp + k as u32;
        match slot.get(&f) {
            Some(&own) => {
                let t = m.funcs[k];
                let mut stub = Function::new([]);
                stub.instruction(&Instruction::I32Const(loader as i32));
                stub.instruction(&Instruction::CallIndirect { type_index: void, table_index: 0 });
                for a in 0..types[t as usize].params().len() as u32 {
                    stub.instruction(&Instruction::LocalGet(a));
                }
                stub.instruction(&Instruction::I32Const(own as i32));
                stub.instruction(&Instruction::CallIndirect { type_index: t, table_index: 0 });
                stub.instruction(&Instruction::End);
                code.function(&stub);
            }
            None => {
                code.raw(&m.data[body.range()]);
            }
        }
    }
    let mut tables = TableSection::new();
    tables.table(grown);
    for t in &m.tables[1..] {
        tables.table(table_type(t)?);
    }

    // What the deferred bodies call in the primary.
    let needed: Vec<u32> = deferred
        .iter()
        .flat_map(|&k| scans[k].refs.iter().copied())
        .filter(|f| !dset.contains(f))
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    if m.exports.iter().any(|(n, _, _)| n.starts_with('~')) {
        return Err(Unsupported("an export name starts with ~".into()));
    }
    // By (kind, index); a kind as its discriminant (wasmparser's kinds are not `Hash`).
    let mut have: HashMap<(u8, u32), String> =
        m.exports.iter().map(|(n, k, i)| ((*k as u8, *i), n.clone())).collect();
    let mut new_exports: Vec<(String, ExternalKind, u32)> = Vec::new();
    let mut export = |kind: ExternalKind, idx: u32, name: String| -> String {
        have.entry((kind as u8, idx))
            .or_insert_with(|| {
                new_exports.push((name.clone(), kind, idx));
                name
            })
            .clone()
    };
    // Function names are "~" and base-36 digits (lower case); the others upper case after "~".
    export(ExternalKind::Table, 0, EXPORT_TABLE.to_owned());
    let table_names: Vec<String> =
        (0..m.tables.len()).map(|t| export(ExternalKind::Table, t as u32, short_name("~T", t))).collect();
    let memory_name = export(ExternalKind::Memory, 0, "~M".to_owned());
    let all_globals: Vec<wasmparser::GlobalType> = m.imp_globals.iter().chain(&m.globals).copied().collect();
    let global_names: Vec<String> =
        (0..all_globals.len()).map(|g| export(ExternalKind::Global, g as u32, short_name("~G", g))).collect();
    let func_names: HashMap<u32, String> =
        needed.iter().map(|&f| (f, export(ExternalKind::Func, f, short_name("~", f as usize)))).collect();
    let mut exports = ExportSection::new();
    for (name, kind, idx) in m.exports.iter().chain(&new_exports) {
        exports.export(
            name,
            RoundtripReencoder.export_kind(*kind).map_err(|e| Unsupported(format!("{e:?}")))?,
            *idx,
        );
    }

    let mut replace: HashMap<u8, Vec<u8>> = HashMap::new();
    replace.insert(1, content(&type_sec)?);
    replace.insert(4, content(&tables)?);
    replace.insert(7, content(&exports)?);
    replace.insert(10, content(&code)?);
    let mut moved = Vec::new();
    if let Some(linked) = linked {
        let kept: Vec<u32> = (0..m.bodies.len())
            .filter(|k| !dset.contains(&(nimp + *k as u32)))
            .flat_map(|k| scans[k].consts.iter().copied())
            .collect();
        let (m_moved, kept_segments) = data::plan(&m, linked, &kept)?;
        if !m_moved.is_empty() {
            let (sec, count) = data_section(&kept_segments);
            replace.insert(11, content(&sec)?);
            if m.section(12).is_some() {
                replace.insert(12, content(&DataCountSection { count })?);
            }
        }
        moved = m_moved;
    }
    let primary = write(&m, &replace)?;

    // Deferred: imports in the primary's order, then its own functions.
    let mut imports = ImportSection::new();
    for &f in &needed {
        imports.import("p", &func_names[&f], EntityType::Function(m.func_type(f)));
    }
    for (t, table) in m.tables.iter().enumerate() {
        let ty = if t == 0 { grown } else { table_type(table)? };
        imports.import("p", &table_names[t], EntityType::Table(ty));
    }
    imports.import("p", &memory_name, EntityType::Memory(memory_type(m.memories[0])?));
    for (g, ty) in all_globals.iter().enumerate() {
        let ty =
            RoundtripReencoder.global_type(*ty).map_err(|e| Unsupported(format!("a global type: {e:?}")))?;
        imports.import("p", &global_names[g], EntityType::Global(ty));
    }
    let mut new_index: HashMap<u32, u32> = needed.iter().enumerate().map(|(n, &f)| (f, n as u32)).collect();
    for (n, &k) in deferred.iter().enumerate() {
        new_index.insert(nimp + k as u32, (needed.len() + n) as u32);
    }
    let mut funcs = FunctionSection::new();
    for &k in &deferred {
        funcs.function(m.funcs[k]);
    }
    let mut elements = ElementSection::new();
    let slots: Vec<u32> = deferred.iter().map(|&k| new_index[&(nimp + k as u32)]).collect();
    elements.active(None, &ConstExpr::i32_const(base as i32), Elements::Functions(Cow::Borrowed(&slots)));
    let mut dcode = CodeSection::new();
    let mut remap = Renumber(&new_index);
    for &k in &deferred {
        remap
            .parse_function_body(&mut dcode, m.bodies[k].clone())
            .map_err(|e| Unsupported(format!("function {}: {e:?}", nimp + k as u32)))?;
    }
    let mut out = wasm_encoder::Module::new();
    out.section(&type_sec);
    out.section(&imports);
    out.section(&funcs);
    out.section(&elements);
    out.section(&dcode);
    if !moved.is_empty() {
        out.section(&data_section(&moved).0);
    }
    // The features the bodies use, for tools that validate the module (wasm-opt).
    if let Some(c) = m.custom("target_features") {
        out.section(&RawSection { id: 0, data: &m.data[c.range()] });
    }
    let facts = Facts {
        loader,
        deferred: deferred.len(),
        functions: m.funcs.len(),
        data: moved.iter().map(|(_, b)| b.len()).sum(),
    };
    Ok((primary, out.finish(), facts))
}

/// Function indices renumbered for the deferred module.
struct Renumber<'a>(&'a HashMap<u32, u32>);

impl Reencode for Renumber<'_> {
    type Error = String;

    fn function_index(&mut self, func: u32) -> Result<u32, wasm_encoder::reencode::Error<String>> {
        self.0.get(&func).copied().ok_or_else(|| {
            wasm_encoder::reencode::Error::UserError(format!(
                "function {func} is neither imported nor deferred"
            ))
        })
    }
}

/// The module with a profile byte per defined function: each body first stores 1 in its own byte
/// of a page added above the initial memory, where dlmalloc never allocates (it grows memory and
/// starts at the old end). Returns (bytes, address of byte 0, number of functions).
pub fn instrument(data: &[u8]) -> Res<(Vec<u8>, u32, usize)> {
    let m = Module::read(data)?;
    if m.memories.len() != 1 {
        return Err(Unsupported("not exactly one defined memory".into()));
    }
    let mem = m.memories[0];
    let addr = u32::try_from(mem.initial * 65536).map_err(|_| Unsupported("a memory above 4 GB".into()))?;
    let mut memories = MemorySection::new();
    memories.memory(MemoryType {
        minimum: mem.initial + 1,
        maximum: mem.maximum.map(|hi| hi.max(mem.initial + 1)),
        ..memory_type(mem)?
    });
    let mut code = CodeSection::new();
    for (k, body) in m.bodies.iter().enumerate() {
        let ops = body.get_operators_reader()?.original_position();
        let range = body.range();
        let mut new = m.data[range.start..ops].to_vec();
        // i32.const addr+k; i32.const 1; i32.store8 align=0 offset=0
        for i in [
            Instruction::I32Const((addr + k as u32) as i32),
            Instruction::I32Const(1),
            Instruction::I32Store8(MemArg { offset: 0, align: 0, memory_index: 0 }),
        ] {
            new.extend(instruction(&i));
        }
        new.extend_from_slice(&m.data[ops..range.end]);
        code.raw(&new);
    }
    let replace = HashMap::from([(5, content(&memories)?), (10, content(&code)?)]);
    Ok((write(&m, &replace)?, addr, m.bodies.len()))
}

#[cfg(test)]
mod tests {
    use wasm_encoder::{ExportKind, Function, Instruction, Module as Out, RefType, ValType};

    use super::*;

    /// A module of four functions (i32) -> i32: `main` (exported) calls `a`, `a` calls `b`,
    /// `c` only adds; a table of one slot, one memory.
    fn module() -> Vec<u8> {
        let mut types = TypeSection::new();
        types.ty().function([ValType::I32], [ValType::I32]);
        let mut funcs = FunctionSection::new();
        (0..4).for_each(|_| {
            funcs.function(0);
        });
        let mut tables = TableSection::new();
        tables.table(TableType {
            element_type: RefType::FUNCREF,
            table64: false,
            minimum: 1,
            maximum: Some(1),
            shared: false,
        });
        let mut memories = MemorySection::new();
        memories.memory(MemoryType {
            minimum: 1,
            maximum: None,
            memory64: false,
            shared: false,
            page_size_log2: None,
        });
        let mut exports = ExportSection::new();
        exports.export("main", ExportKind::Func, 0);
        let mut code = CodeSection::new();
        for body in [
            vec![Instruction::LocalGet(0), Instruction::Call(1), Instruction::End],
            vec![Instruction::LocalGet(0), Instruction::Call(2), Instruction::End],
            vec![Instruction::LocalGet(0), Instruction::I32Const(2), Instruction::I32Mul, Instruction::End],
            vec![Instruction::LocalGet(0), Instruction::I32Const(1), Instruction::I32Add, Instruction::End],
        ] {
            let mut f = Function::new([]);
            body.iter().for_each(|i| {
                f.instruction(i);
            });
            code.function(&f);
        }
        let mut m = Out::new();
        m.section(&types)
            .section(&funcs)
            .section(&tables)
            .section(&memories)
            .section(&exports)
            .section(&code);
        m.finish()
    }

    fn valid(bytes: &[u8]) {
        wasmparser::Validator::new().validate_all(bytes).expect("a valid module");
    }

    #[test]
    fn the_functions_not_run_move_to_a_valid_deferred_module_and_the_primary_keeps_its_indices() {
        let data = module();
        let (primary, deferred, facts) = split(&data, &[true, true, false, false], None).expect("split");
        valid(&primary);
        valid(&deferred);
        // b and c deferred; slots 1 and 2 after the one slot there was, the loader in 3.
        assert_eq!((facts.deferred, facts.functions, facts.loader), (2, 4, 3));
        let p = Module::read(&primary).expect("primary");
        assert_eq!(p.funcs.len(), 4, "every function keeps its index");
        assert_eq!((p.tables[0].initial, p.tables[0].maximum), (4, Some(4)));
        let names: Vec<&str> = p.exports.iter().map(|(n, _, _)| n.as_str()).collect();
        assert_eq!(
            names,
            ["main", EXPORT_TABLE, "~M"],
            "no primary function is called from the deferred ones"
        );
        let d = Module::read(&deferred).expect("deferred");
        assert_eq!((d.imp_funcs.len(), d.funcs.len(), d.imp_tables, d.imp_memories), (0, 2, 1, 1));
        // The exported function and the ones that ran stay, whatever the flags say of them.
        let (_, _, facts) = split(&data, &[false, true, true, false], None).expect("split");
        assert_eq!(facts.deferred, 1);
        // `a` deferred calls `b` in the primary: exported to the deferred module by a short name.
        let (primary, deferred, _) = split(&data, &[true, false, true, true], None).expect("split");
        valid(&deferred);
        let p = Module::read(&primary).expect("primary");
        assert!(
            p.exports.iter().any(|(n, k, i)| n == "~2" && *k == ExternalKind::Func && *i == 2),
            "{:?}",
            p.exports
        );
        assert!(split(&data, &[true; 4], None).is_err(), "nothing to defer");
        assert!(split(&data, &[true; 3], None).is_err(), "a profile of another build");
    }

    #[test]
    fn instrumenting_adds_a_page_and_a_store_per_function() {
        let (bytes, addr, count) = instrument(&module()).expect("instrument");
        valid(&bytes);
        assert_eq!((addr, count), (65536, 4));
        assert_eq!(Module::read(&bytes).expect("read").memories[0].initial, 2);
    }

    #[test]
    fn short_names_count_in_base_36() {
        assert_eq!([short_name("~", 0), short_name("~", 35), short_name("~T", 36)], ["~0", "~z", "~T10"]);
    }
}
