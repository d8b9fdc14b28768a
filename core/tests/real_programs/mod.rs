//! Programs as CAM systems, shops and trainees write them (issue 30): every family reads as the
//! control's own spelling (the same AST, `fmt` writes the control's form), lenient spellings are
//! said once per file, and every block runs: executed, or said on its block, never skipped.
//! Oracles: closed forms worked by hand (sin 30° = 0.5, 3–4–5, a retract of 50 mm along an
//! untilted Z axis, the cycle's set-up clearance above the surface). A file per idea: the
//! parameters and FN functions, the spellings, the M functions, the other blocks, the tools and
//! machines.

use schwenkbar_core::ast::{BlockBody, CycleValue, QL_BASE, QR_BASE};
use schwenkbar_core::diag::{DiagCode, Severity};
use schwenkbar_core::format::format_program;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::parse::Lenient;
use schwenkbar_core::plane::{MoveBack, Value};
use schwenkbar_core::sim::{SimOptions, Simulation, State, simulate};
use schwenkbar_core::{Program, parse};

/// `written` and `canonical` (one block each, numbered 1) give the same block and `fmt` text;
/// `written` with exactly the diagnostics `said`.
fn same_said(written: &str, canonical: &str, said: &[DiagCode]) {
    let (a, da) = parse(&format!("1 {written}\n"));
    let (b, db) = parse(&format!("1 {canonical}\n"));
    assert!(db.is_empty(), "{canonical}: {db:?}");
    let codes: Vec<_> = da.iter().map(|d| d.code.clone()).collect();
    assert_eq!(codes, said, "{written}");
    assert!(da.iter().all(|d| d.severity == Severity::Warning), "{written}: {da:?}");
    assert_eq!(a.blocks[0].body(), b.blocks[0].body(), "{written} ≠ {canonical}");
    assert_eq!(format_program(&a), format_program(&b), "fmt writes the control's spelling");
}

fn same(written: &str, canonical: &str) {
    same_said(written, canonical, &[]);
}

/// The body of the one block of `src`, read without a diagnostic.
fn body(src: &str) -> BlockBody {
    let (p, d) = parse(&format!("1 {src}\n"));
    assert!(d.is_empty(), "{src}: {d:?}");
    p.blocks[0].body().into_owned()
}

fn run(src: &str) -> (Program, Simulation) {
    let (program, diags) = parse(src);
    assert!(diags.iter().all(|d| !d.is_error()), "{src}\n{diags:?}");
    let m = Machine::builtin("ac-table").expect("machine");
    let sim = simulate(&program, &m, &SimOptions::default());
    assert!(sim.error.is_none(), "{src}\n{:?}", sim.error);
    (program, sim)
}

fn after(program: &Program, sim: &Simulation, number: u32) -> State {
    let idx = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
    let step = sim.first_step[idx].expect("executed") as usize;
    sim.state_at(program, step).expect("state")
}

mod blocks;
mod m_functions;
mod machines;
mod parameters;
mod spellings;
