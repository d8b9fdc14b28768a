//! Solves per second from an orientation to the chosen axis positions, explanation included
//! (its SPATIAL and EULER forms of R are made when asked for, `Explanation::spatial`/`euler`).
//! Budget (issue 4): ≥ 1,000,000 solves/s natively in release.
//!
//! Run: `cargo run --release -p schwenkbar-core --example bench_solve`

use std::hint::black_box;
use std::time::Instant;

use glam::DMat3;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::orientation;
use schwenkbar_core::solve::{self, SolveOptions};

const BUDGET: f64 = 1_000_000.0;
const N: usize = 4096;

/// Deterministic spatial angles (xorshift), so runs compare.
fn orientations() -> Vec<DMat3> {
    let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64 * 180.0 - 90.0
    };
    (0..N).map(|_| orientation::spatial(next(), next() * 0.9, next() * 2.0)).collect()
}

fn main() {
    let rs = orientations();
    let mut total_rate = f64::INFINITY;
    for id in Machine::builtin_ids() {
        let Ok(machine) = Machine::builtin(id) else {
            eprintln!("machine {id} failed to load");
            std::process::exit(2);
        };
        let opts = SolveOptions {
            start: AxisValues::default().with(machine.slave().axis, -105.0).with(machine.master().axis, 10.0),
            ..SolveOptions::default()
        };
        // Warm up, then time at least 0.5 s.
        let mut solves = 0usize;
        let mut chosen = 0usize;
        let t0 = Instant::now();
        while t0.elapsed().as_secs_f64() < 0.5 {
            for r in &rs {
                let e = solve::solve(&machine, black_box(r), &opts);
                chosen += usize::from(black_box(e).chosen.is_some());
            }
            solves += rs.len();
        }
        let secs = t0.elapsed().as_secs_f64();
        let rate = solves as f64 / secs;
        total_rate = total_rate.min(rate);
        println!(
            "bench_solve {id:<14} {rate:>12.0} solves/s  ({:.0} ns/solve, {:.0}% with a chosen solution)",
            1e9 / rate,
            100.0 * chosen as f64 / solves as f64
        );
    }
    let verdict = if total_rate >= BUDGET { "ok" } else { "BELOW BUDGET" };
    println!("bench_solve slowest machine {total_rate:.0} solves/s, budget {BUDGET:.0}: {verdict}");
    if total_rate < BUDGET {
        std::process::exit(1);
    }
}
