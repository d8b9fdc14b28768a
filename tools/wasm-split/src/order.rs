//! The functions of a built wasm ordered so that similar code sits side by side.
//!
//! Why: the size budget counts the wasm as gzip -9, whose window is 32 KB. wasm-opt -Oz leaves
//! the functions in link order, where a yew view and its look-alikes lie far apart. Put next to
//! each other, the repeats are found: the trainer's wasm compresses about 5 KB smaller (2 KB of
//! that is ordering by name alone). The code itself is unchanged, only its order.
//!
//! How: the pages' wasm-opt runs with -g, so each wasm arrives with its names section. Each
//! function's body is cut into 5-byte shingles; starting from the first function by name, the
//! next function is always the unplaced one sharing most shingles with the one just placed
//! (weighted by 1/sqrt of its own shingle count, so that big functions do not win by size
//! alone), or the next by name when none shares enough. The functions get new names in that
//! order (written here), and `wasm-opt --reorder-functions-by-name --strip-debug` writes them
//! so, without names (scripts/env.sh). Deterministic: ties go by name.

use std::collections::{BTreeSet, HashMap};

use wasm_encoder::{NameMap, NameSection, RawSection};

use crate::Unsupported;
use crate::module::{Module, Res};

const SHINGLE: usize = 5;
/// A shingle found in more bodies than this is boilerplate (prologues, common calls): skipped.
const COMMON: usize = 200;
/// Fewer shared shingles than this is no likeness: the next function by name follows instead.
const LIKE: u32 = 3;

/// The defined functions (by their index among the defined ones) in the order to write them.
fn order<'a>(bodies: &[&'a [u8]], names: &HashMap<u32, String>, imports: u32) -> Vec<usize> {
    let n = bodies.len();
    let mut by_name: Vec<usize> = (0..n).collect();
    let name = |k: usize| names.get(&(imports + k as u32)).map_or("", String::as_str);
    by_name.sort_by(|&a, &b| name(a).cmp(name(b)).then(a.cmp(&b)));
    let mut rank = vec![0; n];
    for (r, &k) in by_name.iter().enumerate() {
        rank[k] = r;
    }
    let shingles: Vec<BTreeSet<&'a [u8]>> = bodies
        .iter()
        .map(|b| {
            (0..b.len().saturating_sub(SHINGLE - 1).max(1))
                .map(|i| &b[i..(i + SHINGLE).min(b.len())])
                .collect()
        })
        .collect();
    let mut holders: HashMap<&[u8], Vec<usize>> = HashMap::new();
    for (k, s) in shingles.iter().enumerate() {
        for x in s {
            holders.entry(x).or_default().push(k);
        }
    }
    let mut left = vec![true; n];
    let mut remaining = n;
    let mut next_by_name = by_name.iter().copied();
    let mut placed = Vec::with_capacity(n);
    let Some(mut cur) = by_name.first().copied() else { return placed };
    loop {
        if left[cur] {
            left[cur] = false;
            remaining -= 1;
        }
        placed.push(cur);
        if remaining == 0 {
            return placed;
        }
        let mut shared: HashMap<usize, u32> = HashMap::new();
        for x in &shingles[cur] {
            let lst = &holders[x];
            if lst.len() <= COMMON {
                for &k in lst.iter().filter(|&&k| left[k]) {
                    *shared.entry(k).or_default() += 1;
                }
            }
        }
        let score = |k: usize| f64::from(shared[&k]) / ((shingles[k].len() as f64).sqrt() + 1.0);
        let best =
            shared.keys().copied().max_by(|&a, &b| score(a).total_cmp(&score(b)).then(rank[b].cmp(&rank[a])));
        cur = match best {
            Some(b) if shared[&b] >= LIKE => b,
            _ => match next_by_name.find(|&k| left[k]) {
                Some(k) => k,
                None => return placed,
            },
        };
    }
}

/// The module with its functions named in the order to write them (`a000000…` the imports,
/// `f000000…` the defined functions), without its old names and the linker's symbols and
/// relocations (web/build.rs keeps them for the split; after wasm-bindgen they no longer fit
/// the code).
pub fn renamed(data: &[u8]) -> Res<Vec<u8>> {
    let m = Module::read(data)?;
    let names: HashMap<u32, String> = m.function_names()?.into_iter().collect();
    if names.is_empty() {
        return Err(Unsupported("no names (the page's wasm-opt needs -g)".into()));
    }
    let imports = m.imp_funcs.len() as u32;
    let bodies: Vec<&[u8]> = m.bodies.iter().map(|b| &data[b.range()]).collect();
    let mut map = NameMap::new();
    for i in 0..imports {
        map.append(i, &format!("a{i:06}"));
    }
    let mut new_names: Vec<(u32, String)> = order(&bodies, &names, imports)
        .into_iter()
        .enumerate()
        .map(|(r, k)| (imports + k as u32, format!("f{r:06}")))
        .collect();
    new_names.sort();
    for (i, name) in &new_names {
        map.append(*i, name);
    }
    let mut section = NameSection::new();
    section.functions(&map);
    let mut out = wasm_encoder::Module::new();
    for (id, range) in &m.sections {
        if *id == 0 {
            let reader = wasmparser::BinaryReader::new(&data[range.clone()], range.start);
            let name = wasmparser::CustomSectionReader::new(reader)?.name();
            if name == "name" || name == "linking" || name.starts_with("reloc.") {
                continue;
            }
        }
        out.section(&RawSection { id: *id, data: &data[range.clone()] });
    }
    out.section(&section);
    Ok(out.finish())
}
