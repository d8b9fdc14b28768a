//! Parser throughput benchmark (issue 3 budgets): a generated 1,000,000-block CAM program
//! (`schwenkbar_core::sample::cam_program`), parsed once in a release build.
//!
//! Prints MB/s, blocks, peak RSS (VmHWM from /proc/self/status, Linux) relative to the file
//! size, and the time ratio of 10× the input (must stay ≤ 11 for linear scaling).
//! Run: `scripts/bench.sh` or `cargo run --release -p schwenkbar-core --example bench_parse`.

use std::time::Instant;

use schwenkbar_core::{parse, sample};

/// Peak resident set size in bytes, if the OS tells.
fn peak_rss() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// Best of `runs` timings, in seconds.
fn time_parse(src: &str, runs: usize) -> (f64, usize, usize) {
    let mut best = f64::INFINITY;
    let mut blocks = 0;
    let mut diags = 0;
    for _ in 0..runs {
        let t = Instant::now();
        let (p, d) = parse(src);
        best = best.min(t.elapsed().as_secs_f64());
        blocks = p.blocks.len();
        diags = d.len();
    }
    (best, blocks, diags)
}

/// Parse time of a `blocks`-block program in a fresh child process (best of 3 processes), so
/// both sizes start from the same allocator state (a warm heap would favour the small input).
fn child_time(blocks: usize) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let out = std::env::current_exe().ok().and_then(|exe| {
            std::process::Command::new(exe).args(["--time", &blocks.to_string()]).output().ok()
        });
        if let Some(t) =
            out.and_then(|o| String::from_utf8(o.stdout).ok()).and_then(|s| s.trim().parse::<f64>().ok())
        {
            best = best.min(t);
        }
    }
    best
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let [_, flag, n] = args.as_slice()
        && flag == "--time"
    {
        let src = sample::cam_program(n.parse().unwrap_or(1000));
        println!("{}", time_parse(&src, 1).0);
        return;
    }
    // The big run first and alone, so VmHWM measures source + AST of 1,000,000 blocks.
    let big = sample::cam_program(1_000_000);
    let mb = big.len() as f64 / 1e6;
    let base_rss = peak_rss();
    // Best of 3 (the machine is shared); each run frees its AST, so the peak is one run's.
    let (secs, blocks, diags) = time_parse(&big, 3);
    let peak = peak_rss();
    println!("input: {mb:.1} MB, {blocks} blocks, {diags} diagnostics");
    println!("throughput: {:.0} MB/s ({:.3} s)", mb / secs, secs);
    if let (Some(p), Some(b)) = (peak, base_rss) {
        println!(
            "peak RSS: {:.1} MB = {:.2}x the file (before parsing: {:.1} MB)",
            p as f64 / 1e6,
            p as f64 / big.len() as f64,
            b as f64 / 1e6
        );
    }
    drop(big);

    // Linear scaling: 100,000 vs 1,000,000 blocks, each parsed in a fresh process.
    let (t_small, t_big) = (child_time(100_000), child_time(1_000_000));
    println!("scaling: 10x input takes {:.2}x the time (budget <= 11)", t_big / t_small);
}
