//! Never panics on any input (issue 30): 10,000,000 mutated blocks of every family — the lines of
//! every fixture program (`tests/fixtures/{ok,err,sim}`, the families of real programs included)
//! changed byte by byte and word by word — are parsed, formatted, parsed and formatted again
//! (the second text must equal the first: fmt writes what reads back the same); every
//! 10,000th input is a whole mutated program, also simulated. Deterministic (a fixed seed), so
//! the figure does not depend on luck; a panic prints its input and counts.
//! Run: `scripts/bench.sh` or `cargo run --release -p schwenkbar-core --example fuzz_parse [N]`.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::Instant;

use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{SimOptions, simulate};
use schwenkbar_core::{format_program, parse};
use schwenkbar_testkit::Rng;

/// Bytes that matter to the grammar, and a few that should not be there.
const ALPHABET: &[u8] = b" \t~;:=+-.,()\"/*0123456789QLRSXYZABCIJKMNFPDTEGOUVW^\r\xc3\xa4";

/// Words of the families, spliced in whole.
const WORDS: &[&str] = &[
    "PLANE",
    "SPATIAL",
    "SPA+0",
    "SEQ-",
    "TURN",
    "MB MAX",
    "FMAX",
    "M140",
    "M128",
    "F AUTO",
    "CYCL DEF",
    "200",
    "Q200=PREDEF",
    "FAUTO",
    "TCH PROBE",
    "FN 18:",
    "SYSREAD",
    "ID270",
    "NR1",
    "IDX",
    "QR",
    "QL",
    "QS1 =",
    "TOOL DEF",
    "L+75",
    "STOP",
    "LBL",
    "GOTO",
    "CALL",
    "REP",
    "(",
    "BEGIN PGM",
    "INCH",
    "N25",
    "X 25,5",
    "Z + Q13",
    "PATTERN DEF",
    "POS1 (",
    "APPR LCT",
    "FUNCTION TCPM",
    "~",
];

fn mutate(rng: &mut Rng, text: &str) -> String {
    let mut b = text.as_bytes().to_vec();
    for _ in 0..1 + rng.index(4) {
        let at = rng.index(b.len() + 1);
        match rng.index(6) {
            0 => b.insert(at, ALPHABET[rng.index(ALPHABET.len())]),
            1 if at < b.len() => {
                b.remove(at);
            }
            2 if at < b.len() => b[at] = ALPHABET[rng.index(ALPHABET.len())],
            3 => {
                let w = WORDS[rng.index(WORDS.len())].as_bytes();
                b.splice(at..at, w.iter().copied());
            }
            4 => b.truncate(at),
            _ => {
                let end = (at + rng.index(12)).min(b.len());
                let piece = b[at..end].to_vec();
                let to = rng.index(b.len() + 1);
                b.splice(to..to, piece);
            }
        }
    }
    String::from_utf8_lossy(&b).into_owned()
}

fn fixtures() -> (Vec<String>, Vec<String>) {
    let root = format!("{}/../tests/fixtures", env!("CARGO_MANIFEST_DIR"));
    let mut programs = Vec::new();
    for dir in ["ok", "err", "sim"] {
        let Ok(entries) = std::fs::read_dir(format!("{root}/{dir}")) else { continue };
        let mut paths: Vec<_> = entries.flatten().map(|e| e.path()).collect();
        paths.sort();
        for p in paths.into_iter().filter(|p| p.extension().is_some_and(|e| e == "h")) {
            if let Ok(text) = std::fs::read_to_string(&p) {
                programs.push(text);
            }
        }
    }
    let lines = programs.iter().flat_map(|p| p.lines().map(str::to_owned)).collect();
    (programs, lines)
}

fn main() {
    let n: u64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(10_000_000);
    let (programs, lines) = fixtures();
    assert!(!lines.is_empty(), "no fixtures found");
    std::panic::set_hook(Box::new(|_| {}));
    let machine = Machine::builtin("ac-table").expect("builtin machine");
    let mut rng = Rng(0x5eed_2026_1126);
    let mut panics = 0u64;
    let mut unstable = 0u64;
    let t = Instant::now();
    for k in 0..n {
        let whole = k % 10_000 == 0;
        let input = if whole {
            let p = rng.index(programs.len());
            mutate(&mut rng, &programs[p])
        } else {
            // One block, sometimes with the next line as its continuation.
            let i = rng.index(lines.len());
            let mut s = lines[i].clone();
            if rng.index(8) == 0
                && let Some(next) = lines.get(i + 1)
            {
                s.push('\n');
                s.push_str(next);
            }
            mutate(&mut rng, &s)
        };
        let ok = catch_unwind(AssertUnwindSafe(|| {
            let (p, _) = parse(&input);
            let text = format_program(&p);
            // What fmt writes reads back as the same program: formatting it again changes nothing.
            let fixed = format_program(&parse(&text).0) == text;
            if whole {
                let _ = simulate(&p, &machine, &SimOptions::default());
            }
            fixed
        }));
        if matches!(ok, Ok(false)) {
            unstable += 1;
            if unstable <= 10 {
                eprintln!("NOT A FIXED POINT of fmt, input {k}: {input:?}");
            }
        }
        if ok.is_err() {
            panics += 1;
            if panics <= 10 {
                eprintln!("PANIC on input {k}: {input:?}");
            }
        }
    }
    let secs = t.elapsed().as_secs_f64();
    println!(
        "fuzz: {n} mutated inputs of {} fixture programs ({} lines), {panics} panics, {unstable} not formatting to a fixed point, {secs:.1} s",
        programs.len(),
        lines.len()
    );
    if panics > 0 {
        std::process::exit(1);
    }
}
