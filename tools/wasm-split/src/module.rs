//! A module as the splitter sees it, read with wasmparser: its sections in order (to write back
//! the ones it does not change as they were), its types, imports, functions, tables, memories,
//! globals, exports, function bodies and data segments.

use std::ops::Range;

use wasmparser::{
    BinaryReader, CompositeInnerType, DataKind, ExternalKind, FuncType, FunctionBody, GlobalType,
    KnownCustom, MemoryType, Operator, Parser, Payload, TableInit, TableType, TypeRef, WasmFeatures,
};

use crate::Unsupported;

pub type Res<T> = Result<T, Unsupported>;

impl From<wasmparser::BinaryReaderError> for Unsupported {
    fn from(e: wasmparser::BinaryReaderError) -> Self {
        Unsupported(format!("unreadable: {e}"))
    }
}

/// One active or passive data segment: its address (`None`: passive) and where its bytes are
/// in the module, absolute and relative to the data section's content.
pub struct Segment {
    pub address: Option<u32>,
    pub bytes: Range<usize>,
    pub in_section: usize,
}

pub struct Module<'a> {
    pub data: &'a [u8],
    /// Every section as (id, range of its content), in the file's order.
    pub sections: Vec<(u8, Range<usize>)>,
    pub types: Vec<FuncType>,
    pub imp_funcs: Vec<u32>,
    pub imp_globals: Vec<GlobalType>,
    pub imp_tables: usize,
    pub imp_memories: usize,
    pub funcs: Vec<u32>,
    pub tables: Vec<TableType>,
    pub memories: Vec<MemoryType>,
    pub globals: Vec<GlobalType>,
    /// The integer constants the globals start with (each half of an i64).
    pub global_consts: Vec<u32>,
    pub exports: Vec<(String, ExternalKind, u32)>,
    pub bodies: Vec<FunctionBody<'a>>,
    pub start: bool,
    pub segments: Vec<Segment>,
}

/// What the splitter reads: the features rustc and wasm-bindgen use, without SIMD and threads,
/// whose memory instructions it does not follow.
fn features() -> WasmFeatures {
    WasmFeatures::default() - WasmFeatures::SIMD - WasmFeatures::RELAXED_SIMD - WasmFeatures::THREADS
}

impl<'a> Module<'a> {
    pub fn read(data: &'a [u8]) -> Res<Module<'a>> {
        let mut validator = wasmparser::Validator::new_with_features(features());
        validator
            .validate_all(data)
            .map_err(|e| Unsupported(format!("not a module the splitter reads: {e}")))?;
        let mut m = Module {
            data,
            sections: Vec::new(),
            types: Vec::new(),
            imp_funcs: Vec::new(),
            imp_globals: Vec::new(),
            imp_tables: 0,
            imp_memories: 0,
            funcs: Vec::new(),
            tables: Vec::new(),
            memories: Vec::new(),
            globals: Vec::new(),
            global_consts: Vec::new(),
            exports: Vec::new(),
            bodies: Vec::new(),
            start: false,
            segments: Vec::new(),
        };
        for payload in Parser::new(0).parse_all(data) {
            let payload = payload?;
            if let Some(section) = payload.as_section() {
                m.sections.push(section);
            }
            match payload {
                Payload::TypeSection(r) => {
                    for group in r {
                        let group = group?;
                        if group.is_explicit_rec_group() {
                            return Err(Unsupported("a recursion group (GC types)".into()));
                        }
                        for sub in group.into_types() {
                            match sub.composite_type.inner {
                                CompositeInnerType::Func(f) => m.types.push(f),
                                _ => {
                                    return Err(Unsupported(
                                        "a type that is not a function's (GC types)".into(),
                                    ));
                                }
                            }
                        }
                    }
                }
                Payload::ImportSection(r) => {
                    for import in r.into_imports() {
                        match import?.ty {
                            TypeRef::Func(t) => m.imp_funcs.push(t),
                            TypeRef::Table(_) => m.imp_tables += 1,
                            TypeRef::Memory(_) => m.imp_memories += 1,
                            TypeRef::Global(g) => m.imp_globals.push(g),
                            _ => {
                                return Err(Unsupported(
                                    "an import kind other than function, table, memory, global".into(),
                                ));
                            }
                        }
                    }
                }
                Payload::FunctionSection(r) => {
                    for t in r {
                        m.funcs.push(t?);
                    }
                }
                Payload::TableSection(r) => {
                    for t in r {
                        let t = t?;
                        if !matches!(t.init, TableInit::RefNull) {
                            return Err(Unsupported("a table with an initial expression".into()));
                        }
                        m.tables.push(t.ty);
                    }
                }
                Payload::MemorySection(r) => {
                    for mem in r {
                        let mem = mem?;
                        if mem.memory64 || mem.shared {
                            return Err(Unsupported("a shared or 64-bit memory".into()));
                        }
                        m.memories.push(mem);
                    }
                }
                Payload::GlobalSection(r) => {
                    for g in r {
                        let g = g?;
                        for op in g.init_expr.get_operators_reader() {
                            m.global_consts.extend(int_halves(&op?));
                        }
                        m.globals.push(g.ty);
                    }
                }
                Payload::ExportSection(r) => {
                    for e in r {
                        let e = e?;
                        m.exports.push((e.name.to_owned(), e.kind, e.index));
                    }
                }
                Payload::StartSection { .. } => m.start = true,
                Payload::DataSection(r) => {
                    let base = r.range().start;
                    for d in r {
                        let d = d?;
                        let start = d.data.as_ptr() as usize - data.as_ptr() as usize;
                        let address = match d.kind {
                            DataKind::Passive => None,
                            DataKind::Active { memory_index: 0, offset_expr } => {
                                let mut ops = offset_expr.get_operators_reader();
                                match (ops.read()?, ops.read()?) {
                                    (Operator::I32Const { value }, Operator::End) => Some(value as u32),
                                    _ => {
                                        return Err(Unsupported(
                                            "a data segment's offset is not a constant".into(),
                                        ));
                                    }
                                }
                            }
                            DataKind::Active { .. } => {
                                return Err(Unsupported("data for a second memory".into()));
                            }
                        };
                        m.segments.push(Segment {
                            address,
                            bytes: start..start + d.data.len(),
                            in_section: start - base,
                        });
                    }
                }
                Payload::CodeSectionEntry(body) => m.bodies.push(body),
                _ => {}
            }
        }
        if m.bodies.len() != m.funcs.len() {
            return Err(Unsupported("function and code sections differ".into()));
        }
        Ok(m)
    }

    /// The content of the first section with id `id`.
    pub fn section(&self, id: u8) -> Option<&'a [u8]> {
        self.sections.iter().find(|(s, _)| *s == id).map(|(_, r)| &self.data[r.clone()])
    }

    /// Where the code section's content starts (relocation offsets count from there).
    pub fn section_start(&self, id: u8) -> Option<usize> {
        self.sections.iter().find(|(s, _)| *s == id).map(|(_, r)| r.start)
    }

    /// A custom section's reader by name.
    pub fn custom(&self, name: &str) -> Option<wasmparser::CustomSectionReader<'a>> {
        self.sections.iter().filter(|(id, _)| *id == 0).find_map(|(_, r)| {
            let reader = BinaryReader::new(&self.data[r.clone()], r.start);
            wasmparser::CustomSectionReader::new(reader).ok().filter(|c| c.name() == name)
        })
    }

    /// Whether the custom section `name` is known to wasmparser as linking or relocations.
    pub fn known(&self, name: &str) -> Option<KnownCustom<'a>> {
        self.custom(name).map(|c| c.as_known())
    }

    /// A function's type (imported or defined), by its index in the function space.
    pub fn func_type(&self, f: u32) -> u32 {
        let n = self.imp_funcs.len() as u32;
        if f < n { self.imp_funcs[f as usize] } else { self.funcs[(f - n) as usize] }
    }

    /// The names the name section gives the functions, by function index.
    pub fn function_names(&self) -> Res<Vec<(u32, String)>> {
        let Some(c) = self.custom("name") else { return Ok(Vec::new()) };
        let mut out = Vec::new();
        let reader = wasmparser::NameSectionReader::new(BinaryReader::new(c.data(), c.data_offset()));
        for name in reader {
            if let wasmparser::Name::Function(map) = name? {
                for n in map {
                    let n = n?;
                    out.push((n.index, n.name.to_owned()));
                }
            }
        }
        Ok(out)
    }
}

/// An integer constant's value as the addresses it may form: an i32's, both halves of an i64's
/// (wasm-opt joins two i32 stores into one i64 store: a `&str`'s address and length in one).
pub fn int_halves(op: &Operator<'_>) -> Vec<u32> {
    match *op {
        Operator::I32Const { value } => vec![value as u32],
        Operator::I64Const { value } => vec![value as u32, (value >> 32) as u32],
        _ => Vec::new(),
    }
}

/// What a body's instructions say: the function indices it names (calls, `ref.func`), whether
/// it uses a passive segment (`memory.init`, `table.init`, `data.drop`, `elem.drop`), and every
/// address it may form (its integer constants and memory offsets).
pub struct Scan {
    pub refs: Vec<u32>,
    pub passive: bool,
    pub consts: Vec<u32>,
}

pub fn scan(body: &FunctionBody<'_>) -> Res<Scan> {
    let mut s = Scan { refs: Vec::new(), passive: false, consts: Vec::new() };
    for op in body.get_operators_reader()? {
        let op = op?;
        s.consts.extend(int_halves(&op));
        match op {
            Operator::Call { function_index }
            | Operator::ReturnCall { function_index }
            | Operator::RefFunc { function_index } => s.refs.push(function_index),
            Operator::MemoryInit { .. }
            | Operator::DataDrop { .. }
            | Operator::TableInit { .. }
            | Operator::ElemDrop { .. } => {
                s.passive = true;
            }
            Operator::I32Load { memarg }
            | Operator::I64Load { memarg }
            | Operator::F32Load { memarg }
            | Operator::F64Load { memarg }
            | Operator::I32Load8S { memarg }
            | Operator::I32Load8U { memarg }
            | Operator::I32Load16S { memarg }
            | Operator::I32Load16U { memarg }
            | Operator::I64Load8S { memarg }
            | Operator::I64Load8U { memarg }
            | Operator::I64Load16S { memarg }
            | Operator::I64Load16U { memarg }
            | Operator::I64Load32S { memarg }
            | Operator::I64Load32U { memarg }
            | Operator::I32Store { memarg }
            | Operator::I64Store { memarg }
            | Operator::F32Store { memarg }
            | Operator::F64Store { memarg }
            | Operator::I32Store8 { memarg }
            | Operator::I32Store16 { memarg }
            | Operator::I64Store8 { memarg }
            | Operator::I64Store16 { memarg }
            | Operator::I64Store32 { memarg } => s.consts.push(memarg.offset as u32),
            _ => {}
        }
    }
    Ok(s)
}
