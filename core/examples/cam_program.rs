//! Writes the generated CAM program of the benchmarks (`sample::cam_program`) to stdout:
//! `cargo run --release -p schwenkbar-core --example cam_program -- 100000 > FILE.h`, so the
//! command line and other programs can be timed on the same file (scripts/bench.sh).

use std::io::Write;

fn main() {
    let blocks = std::env::args().nth(1).and_then(|n| n.parse().ok()).unwrap_or(100_000);
    let text = schwenkbar_core::sample::cam_program(blocks);
    if let Err(e) = std::io::stdout().lock().write_all(text.as_bytes()) {
        eprintln!("error: {e}");
        std::process::exit(2);
    }
}
