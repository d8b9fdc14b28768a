//! Simulator benchmark (issue 5 budget): the generated 1,000,000-block CAM program
//! (`schwenkbar_core::sample::cam_program`) simulated on `ac-table` in a release build.
//!
//! Prints blocks per second of `simulate` (best of 3 runs; must be ≥ 1,000,000), the time of
//! `state_at` for a late block (re-simulation from the nearest checkpoint, must be instant for the
//! UI) and of the first `state_at` on each of 100 spread steps, and the memory of the records.
//! Then the whole run of Musterprogramm 1 (`static/programs/musterprogramm1.h`) on every shipped
//! machine, best of 20 (issue 17 budget with collision checking: ≤ 50 ms).
//! Run: `scripts/bench.sh` or `cargo run --release -p schwenkbar-core --example bench_sim`.

use std::time::Instant;

use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{Record, SimOptions, simulate};
use schwenkbar_core::{parse, sample};

fn main() {
    let blocks = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(1_000_000usize);
    let src = sample::cam_program(blocks);
    let (program, _) = parse(&src);
    let Ok(machine) = Machine::builtin("ac-table") else {
        eprintln!("no machine ac-table");
        return;
    };
    let opts = SimOptions::default();
    let mut best = f64::INFINITY;
    let mut sim = simulate(&program, &machine, &opts);
    for _ in 0..3 {
        let t = Instant::now();
        sim = simulate(&program, &machine, &opts);
        best = best.min(t.elapsed().as_secs_f64());
    }
    if let Some(e) = &sim.error {
        eprintln!("run stopped at line {}: {}", e.line, e.message.en);
    }
    let steps = sim.len();
    let rate = steps as f64 / best;
    println!(
        "simulate: {steps} blocks in {:.1} ms = {:.2} M blocks/s (budget ≥ 1.00)",
        best * 1e3,
        rate / 1e6
    );

    let late = steps.saturating_sub(2);
    let t = Instant::now();
    let state = sim.state_at(&program, late);
    let dt = t.elapsed().as_secs_f64();
    println!(
        "state_at({late}): {:.3} ms (checkpoint every {} blocks){}",
        dt * 1e3,
        sim.options.checkpoint_interval,
        if state.is_some() { "" } else { " — no state!" }
    );
    let mut worst = 0.0_f64;
    for k in 0..100 {
        let step = (steps / 100) * k + (k * 37) % sim.options.checkpoint_interval;
        let t = Instant::now();
        let _ = sim.state_at(&program, step.min(steps.saturating_sub(1)));
        worst = worst.max(t.elapsed().as_secs_f64());
    }
    println!("state_at worst of 100 spread steps: {:.3} ms", worst * 1e3);
    println!(
        "records: {} bytes each, {:.1} MB in all",
        std::mem::size_of::<Record>(),
        (steps * std::mem::size_of::<Record>()) as f64 / 1e6
    );
    musterprogramm1();
}

/// The whole run of Musterprogramm 1 on every shipped machine, best of 20.
fn musterprogramm1() {
    let src = include_str!("../../static/programs/musterprogramm1.h");
    let (program, _) = parse(src);
    for id in Machine::builtin_ids() {
        let Ok(machine) = Machine::builtin(id) else { continue };
        let mut best = f64::INFINITY;
        let mut sim = simulate(&program, &machine, &SimOptions::default());
        for _ in 0..20 {
            let t = Instant::now();
            sim = simulate(&program, &machine, &SimOptions::default());
            best = best.min(t.elapsed().as_secs_f64());
        }
        let stop = sim
            .error
            .map_or_else(String::new, |e| format!(" (stopped at line {}: {})", e.line, e.message.en));
        println!(
            "musterprogramm1 on {id}: {} steps in {:.3} ms (budget ≤ 50){stop}",
            sim.records.len(),
            best * 1e3
        );
    }
}
