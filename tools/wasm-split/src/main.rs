//! The build's wasm tool (scripts/split_pages.py, scripts/env.sh): splits a page's wasm in two —
//! the functions its first screen runs (the primary, which the page loads) and the rest (the
//! deferred module, fetched after the first screen, or at once when a deferred function is
//! called before it has arrived) — and orders a wasm's functions for gzip. Modules are read and
//! written with wasmparser and wasm-encoder; nothing here parses wasm bytes itself.
//!
//! Usage (exit 3 with the reason on stderr when a module uses something the tool does not
//! handle: the page then stays whole):
//!   wasm-split names IN                 the imported and defined function counts, then
//!                                       `index<TAB>name` per named function
//!   wasm-split instrument IN OUT        the profile build; prints `address count`
//!   wasm-split split IN RUN PRIMARY DEFERRED \[LINKED\]
//!                                       RUN: one `1`/`0` per defined function (ran on the first
//!                                       screen); prints `loader deferred functions data`
//!   wasm-split order IN OUT             the functions named in the order for gzip
//!   wasm-split layout IN                `section ID START LENGTH` per section (its content),
//!                                       `segment ADDRESS OFFSET LENGTH` per data segment (offset
//!                                       in the data section's content): what a test needs to
//!                                       write a linked binary's relocations

mod data;
mod module;
mod order;
mod split;

use std::process::ExitCode;

/// A module the tool does not handle, and why.
#[derive(Debug)]
pub struct Unsupported(pub String);

fn read(path: &str) -> Result<Vec<u8>, Unsupported> {
    std::fs::read(path).map_err(|e| Unsupported(format!("{path}: {e}")))
}

fn write(path: &str, bytes: &[u8]) -> Result<(), Unsupported> {
    std::fs::write(path, bytes).map_err(|e| Unsupported(format!("{path}: {e}")))
}

fn run(args: &[String]) -> Result<String, Unsupported> {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    match args.as_slice() {
        ["names", input] => {
            let data = read(input)?;
            let m = module::Module::read(&data)?;
            let mut out = format!("{} {}\n", m.imp_funcs.len(), m.funcs.len());
            for (index, name) in m.function_names()? {
                out.push_str(&format!("{index}\t{name}\n"));
            }
            Ok(out)
        }
        ["instrument", input, output] => {
            let (bytes, address, count) = split::instrument(&read(input)?)?;
            write(output, &bytes)?;
            Ok(format!("{address} {count}\n"))
        }
        ["split", input, run, primary, deferred, linked @ ..] if linked.len() <= 1 => {
            let flags = read(run)?;
            let flags: Vec<bool> = flags.iter().filter(|b| !b.is_ascii_whitespace()).map(|&b| b == b'1').collect();
            let linked = linked.first().map(|p| read(p)).transpose()?;
            let (p, d, facts) = split::split(&read(input)?, &flags, linked.as_deref())?;
            write(primary, &p)?;
            write(deferred, &d)?;
            Ok(format!("{} {} {} {}\n", facts.loader, facts.deferred, facts.functions, facts.data))
        }
        ["layout", input] => {
            let data = read(input)?;
            let m = module::Module::read(&data)?;
            let mut out = String::new();
            for (id, r) in &m.sections {
                out.push_str(&format!("section {id} {} {}\n", r.start, r.len()));
            }
            for s in &m.segments {
                let address = s.address.map_or_else(|| "passive".to_owned(), |a| a.to_string());
                out.push_str(&format!("segment {address} {} {}\n", s.in_section, s.bytes.len()));
            }
            Ok(out)
        }
        ["order", input, output] => {
            let bytes = order::renamed(&read(input)?)?;
            write(output, &bytes)?;
            Ok(String::new())
        }
        _ => Err(Unsupported(
            "usage: wasm-split names IN | instrument IN OUT | split IN RUN PRIMARY DEFERRED [LINKED] | order IN OUT | layout IN"
                .into(),
        )),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(out) => {
            print!("{out}");
            ExitCode::SUCCESS
        }
        Err(Unsupported(why)) => {
            eprintln!("wasm-split: {why}");
            ExitCode::from(3)
        }
    }
}
