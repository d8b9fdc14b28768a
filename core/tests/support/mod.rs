//! Shared test helpers: approx-equality that prints the difference, and block builders.
#![allow(dead_code)]

use schwenkbar_core::plane::{PlaneBlock, PlaneDef, Selection, TransformMode};

/// Asserts |actual − expected| ≤ tol element-wise for f64, arrays or nested arrays; on failure
/// prints both values, the largest difference and the context.
#[macro_export]
macro_rules! assert_close {
    ($actual:expr, $expected:expr, $tol:expr $(, $($ctx:tt)+)?) => {{
        let a = $crate::support::flat(&$actual);
        let e = $crate::support::flat(&$expected);
        assert_eq!(a.len(), e.len(), "shape differs: {:?} vs {:?}", a, e);
        let diff = a.iter().zip(&e).map(|(x, y)| (x - y).abs()).fold(0.0_f64, |m, d| if d.is_nan() { f64::NAN } else { m.max(d) });
        assert!(
            diff <= $tol,
            "not close{}:\n  actual   {:?}\n  expected {:?}\n  max diff {:e} > tol {:e}",
            { let _s = String::new(); $( let _s = format!(" ({})", format!($($ctx)+)); )? _s },
            $actual, $expected, diff, $tol
        );
    }};
}

/// Flattens numbers for [`assert_close!`].
pub trait Flat {
    fn flat_into(&self, out: &mut Vec<f64>);
}
impl Flat for f64 {
    fn flat_into(&self, out: &mut Vec<f64>) {
        out.push(*self);
    }
}
impl<T: Flat, const N: usize> Flat for [T; N] {
    fn flat_into(&self, out: &mut Vec<f64>) {
        self.iter().for_each(|x| x.flat_into(out));
    }
}
impl<T: Flat> Flat for Vec<T> {
    fn flat_into(&self, out: &mut Vec<f64>) {
        self.iter().for_each(|x| x.flat_into(out));
    }
}
impl Flat for glam::DVec3 {
    fn flat_into(&self, out: &mut Vec<f64>) {
        out.extend(self.to_array());
    }
}
impl Flat for glam::DMat3 {
    /// Row by row, as DOMAIN.md lists matrices.
    fn flat_into(&self, out: &mut Vec<f64>) {
        out.extend(self.transpose().to_cols_array());
    }
}
pub fn flat<T: Flat>(x: &T) -> Vec<f64> {
    let mut v = Vec::new();
    x.flat_into(&mut v);
    v
}

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
