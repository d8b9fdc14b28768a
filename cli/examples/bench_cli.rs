//! Whole-process figures of the release `schwenkbar` (issue 16 budgets): `check` on the
//! 1,000,000-block program (≥ 200 MB/s: read, parse, report) and `run` on the 100,000-block
//! program (table and `--json`, output to /dev/null), and `run` on 100,000 moves inside a blank
//! (issue 32, [`sample::moves_in_blank`]). Writes the generated programs next to the
//! binary (`target/release/`) and prints figures, best of 3; it does not pass or fail.
//! Run: `scripts/bench.sh`, or `cargo build --release -p schwenkbar` and then
//! `cargo run --release -p schwenkbar --example bench_cli`.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use schwenkbar_core::sample;

/// Best wall time of 3 runs of `schwenkbar args…`, in seconds, and whether the last one
/// succeeded.
fn best_of_3(exe: &Path, args: &[&str]) -> (f64, bool) {
    let mut best = f64::INFINITY;
    let mut ok = false;
    for _ in 0..3 {
        let t = Instant::now();
        let status = Command::new(exe).args(args).stdout(Stdio::null()).stderr(Stdio::null()).status();
        best = best.min(t.elapsed().as_secs_f64());
        ok = status.is_ok_and(|s| s.success());
    }
    (best, ok)
}

fn write_program(dir: &Path, blocks: usize) -> PathBuf {
    write(dir.join(format!("bench_cam_{blocks}.h")), &sample::cam_program(blocks))
}

fn write(path: PathBuf, text: &str) -> PathBuf {
    if let Err(e) = std::fs::write(&path, text) {
        eprintln!("cannot write {}: {e}", path.display());
        std::process::exit(2);
    }
    path
}

fn main() {
    let Some(dir) = std::env::current_exe().ok().and_then(|e| Some(e.parent()?.parent()?.to_path_buf()))
    else {
        eprintln!("cannot locate the target directory");
        std::process::exit(2);
    };
    let exe = dir.join("schwenkbar");
    if !exe.exists() {
        eprintln!("{} missing: cargo build --release -p schwenkbar first", exe.display());
        std::process::exit(2);
    }
    let big = write_program(&dir, 1_000_000);
    let mb = std::fs::metadata(&big).map_or(0.0, |m| m.len() as f64 / 1e6);
    let file = big.to_string_lossy();
    let (secs, ok) = best_of_3(&exe, &["check", &file]);
    println!(
        "check 1,000,000 blocks ({mb:.1} MB): {secs:.3} s = {:.0} MB/s end to end (budget >= 200){}",
        mb / secs,
        if ok { "" } else { " FAILED" }
    );

    let small = write_program(&dir, 100_000);
    let file = small.to_string_lossy();
    for (what, json) in [("table", false), ("--json", true)] {
        let mut args = vec!["run", &*file, "--machine", "ac-table"];
        if json {
            args.push("--json");
        }
        let (secs, ok) = best_of_3(&exe, &args);
        println!("run 100,000 blocks ({what}): {:.1} ms{}", secs * 1e3, if ok { "" } else { " FAILED" });
    }

    // Issue 32: every move inside the blank, near the table (the collision check's worst case).
    let blank = write(dir.join("bench_blank_100000.h"), &sample::moves_in_blank(100_000));
    let file = blank.to_string_lossy();
    let (secs, ok) = best_of_3(&exe, &["run", &file, "--machine", "bc-head-table"]);
    println!(
        "run 100,000 moves inside a 200x200x50 blank (bc-head-table): {:.1} ms{}",
        secs * 1e3,
        if ok { "" } else { " FAILED" }
    );
}
