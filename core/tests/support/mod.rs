//! Block builders shared by core's integration tests. (The approx assertion `assert_close!` and
//! the SEQ/SYM oracle table are in the workspace's dev crate, `schwenkbar-testkit`.)
#![allow(dead_code)]

use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Limits;
use schwenkbar_core::plane::{PlaneBlock, PlaneDef, RotaryAxis, Selection, TransformMode, Value};
use schwenkbar_core::{BlockBody, parse};

pub fn block(
    def: PlaneDef<f64>,
    selection: Option<Selection>,
    transform: Option<TransformMode>,
) -> PlaneBlock<f64> {
    PlaneBlock { def, positioning: None, selection, transform }
}

pub fn spatial(spa: f64, spb: f64, spc: f64) -> PlaneDef<f64> {
    PlaneDef::Spatial { spa, spb, spc }
}

/// The single PLANE block of `src` (a typed block: no block number, which only warns), which
/// must parse without errors and hold numbers only.
pub fn plane_block(src: &str) -> PlaneBlock<f64> {
    let (program, diags) = parse(src);
    assert!(!diags.iter().any(|d| d.is_error()), "{src}: {diags:?}");
    match program.blocks.as_slice() {
        [b] => match &*b.body() {
            BlockBody::Plane(p) => p
                .try_map(|v| match v {
                    Value::Number(x) => Ok(*x),
                    Value::Param { index, .. } => Err(*index),
                })
                .unwrap_or_else(|q| panic!("{src}: Q{q} has no value here")),
            other => panic!("{src}: not a PLANE block: {other:?}"),
        },
        blocks => panic!("{src}: {} blocks", blocks.len()),
    }
}

/// Axis words from the testkit's tables (`('A', 45.0)`) as axis values.
pub fn axis_values(words: &[(char, f64)]) -> AxisValues {
    words.iter().fold(AxisValues::default(), |v, &(letter, x)| v.with(rotary(letter), x))
}

/// A limit from the testkit's tables (`('A', -90.0, 10.0)`).
pub fn limits((letter, min, max): (char, f64, f64)) -> (RotaryAxis, Limits) {
    (rotary(letter), Limits { min, max })
}

pub fn rotary(letter: char) -> RotaryAxis {
    RotaryAxis::from_letter(&letter.to_string()).unwrap_or_else(|| panic!("{letter}: not a rotary axis"))
}
