//! Test helpers shared by the workspace's tests (a dev-dependency of core, cli and tests):
//! [`assert_close!`], the one approx-equality assertion, and [`seq_sym`], the reader of the
//! seed's SEQ/SYM table `tests/fixtures/oracles/seq_sym.tsv`, and [`collision::program`], the
//! collision scene of issue 17.
//!
//! The crate does not depend on `schwenkbar-core`: core's unit tests use it too, and a testkit
//! built on core would hand them a second copy of core's types. So it speaks plain numbers and
//! strings; each test turns them into core's types itself.

pub mod collision;
pub mod seq_sym;

use std::path::Path;

/// The configuration of every property test: `cases` cases from a fixed seed, so that a run's
/// outcome, time and memory do not depend on chance (a failure found once replays as it is; the
/// fuzz run in scripts/bench.sh is where random inputs are explored). proptest prints the
/// minimal failing input.
#[cfg(not(target_arch = "wasm32"))]
#[must_use]
pub fn proptest_cases(cases: u32) -> proptest::test_runner::Config {
    proptest::test_runner::Config {
        cases,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x5c4e_2026),
        ..proptest::test_runner::Config::default()
    }
}

/// Asserts that the NC programs in `dir` (`*.h`) are exactly `names` (file stems, any order):
/// the per-file harnesses list their fixtures by name, so a new file without a test fails here.
///
/// # Panics
/// When `dir` cannot be read or the two lists differ.
pub fn assert_one_test_per_program(dir: &Path, names: &[&str]) {
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| {
            let path = e.expect("readable entry").path();
            let stem = path.file_stem()?.to_str()?.to_owned();
            path.extension().is_some_and(|x| x == "h").then_some(stem)
        })
        .collect();
    files.sort();
    let mut names = names.to_vec();
    names.sort_unstable();
    assert_eq!(files, names, "{}: every program needs its test (and only those)", dir.display());
}

/// Asserts |actual − expected| ≤ tol element-wise for f64, arrays, vectors or glam's `DVec3` /
/// `DMat3` (anything [`Flat`]); on failure prints both values, the largest difference and the
/// context, which takes `format!` arguments.
///
/// A NaN on either side fails, whatever the tolerance.
#[macro_export]
macro_rules! assert_close {
    ($actual:expr, $expected:expr, $tol:expr $(, $($ctx:tt)+)?) => {{
        let a = $crate::flat(&$actual);
        let e = $crate::flat(&$expected);
        assert_eq!(a.len(), e.len(), "shape differs: {:?} vs {:?}", a, e);
        let diff = $crate::max_diff(&a, &e);
        assert!(
            diff <= $tol,
            "not close{}:\n  actual   {:?}\n  expected {:?}\n  max diff {:e} > tol {:e}",
            { let _s = String::new(); $( let _s = format!(" ({})", format!($($ctx)+)); )? _s },
            $actual, $expected, diff, $tol
        );
    }};
}

/// The largest |a − e| over both slices, NaN if any difference is NaN (so `diff <= tol` fails).
#[must_use]
pub fn max_diff(a: &[f64], e: &[f64]) -> f64 {
    a.iter()
        .zip(e)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0_f64, |m, d| if d.is_nan() || m.is_nan() { f64::NAN } else { m.max(d) })
}

/// Numbers flattened for [`assert_close!`].
pub trait Flat {
    fn flat_into(&self, out: &mut Vec<f64>);
}
impl Flat for f64 {
    fn flat_into(&self, out: &mut Vec<f64>) {
        out.push(*self);
    }
}
impl<T: Flat + ?Sized> Flat for &T {
    fn flat_into(&self, out: &mut Vec<f64>) {
        (**self).flat_into(out);
    }
}
impl<T: Flat, const N: usize> Flat for [T; N] {
    fn flat_into(&self, out: &mut Vec<f64>) {
        self.iter().for_each(|x| x.flat_into(out));
    }
}
impl<T: Flat> Flat for [T] {
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

/// `x` as a flat list of numbers (see [`Flat`]).
pub fn flat<T: Flat + ?Sized>(x: &T) -> Vec<f64> {
    let mut v = Vec::new();
    x.flat_into(&mut v);
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn close_values_pass_within_the_tolerance() {
        assert_close!(1.0 + 1e-10, 1.0, 1e-9);
        assert_close!([[1.0, 2.0], [3.0, 4.0]], vec![1.0, 2.0, 3.0, 4.0 + 1e-7], 1e-6, "nested {}", 1);
        assert_close!(glam::DMat3::IDENTITY, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], 0.0);
    }

    #[test]
    #[should_panic(expected = "not close (row 7)")]
    fn a_difference_beyond_the_tolerance_fails_with_the_context() {
        assert_close!([1.0, 2.0], [1.0, 2.1], 1e-3, "row {}", 7);
    }

    #[test]
    #[should_panic(expected = "shape differs")]
    fn a_different_shape_fails() {
        assert_close!([1.0, 2.0], [1.0, 2.0, 3.0], 1.0);
    }

    #[test]
    #[should_panic(expected = "not close")]
    fn nan_fails_whatever_the_tolerance() {
        assert_close!([f64::NAN, 1.0], [0.0, 1.0], f64::INFINITY);
    }

    #[test]
    fn every_program_needs_its_test() {
        let dir = std::env::temp_dir().join(format!("schwenkbar-testkit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for file in ["b.h", "a.h", "notes.txt"] {
            std::fs::write(dir.join(file), "").unwrap();
        }
        assert_one_test_per_program(&dir, &["a", "b"]);
        let missing = std::panic::catch_unwind(|| assert_one_test_per_program(&dir, &["a"]));
        let extra = std::panic::catch_unwind(|| assert_one_test_per_program(&dir, &["a", "b", "c"]));
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(missing.is_err() && extra.is_err());
    }

    #[test]
    fn matrices_flatten_row_by_row() {
        let m = glam::DMat3::from_cols_array(&[1.0, 4.0, 7.0, 2.0, 5.0, 8.0, 3.0, 6.0, 9.0]);
        assert_eq!(flat(&m), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
    }
}

/// xorshift64* (Vigna, "An experimental exploration of Marsaglia's xorshift generators,
/// scrambled", 2016): reproducible pseudo-random inputs from a fixed seed without a dependency,
/// for the fuzz run and the randomized unit tests.
#[derive(Debug, Clone)]
pub struct Rng(pub u64);

impl Rng {
    /// The next 64 random bits. A zero seed stays zero: seed with anything else.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A number in `0..n` (`0` for `n = 0`).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n.max(1)
    }

    /// An index into a slice of `n` items (`0` for `n = 0`).
    pub fn index(&mut self, n: usize) -> usize {
        self.below(n as u64) as usize
    }
}
