//! Every fixture program under `tests/fixtures/{ok,err}` is a snapshot test (gcode-rs style):
//! the parse result (blocks, diagnostics) and the formatted text are written to `NAME.snap`
//! next to the fixture and compared on every run. `UPDATE_SNAPSHOTS=1 cargo test` rewrites them;
//! a missing snapshot fails the test.
//!
//! `ok/` programs must give no diagnostics (the as-printed Musterprogramm 1 only its elision
//! warnings); each `err/NAME.h` has a sidecar `NAME.expect` with `LINE SEVERITY MESSAGE` lines
//! that must all be among its diagnostics.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use schwenkbar_core::diag::DiagCode;
use schwenkbar_core::{Lang, format_program, parse};
use schwenkbar_tests::fixtures_dir;

fn programs(dir: &str) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = fs::read_dir(fixtures_dir().join(dir))
        .expect("fixture folder exists")
        .map(|e| e.expect("readable entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "h"))
        .collect();
    v.sort();
    assert!(!v.is_empty(), "no fixtures in {dir}");
    v
}

fn snapshot_text(src: &str) -> String {
    let (program, diags) = parse(src);
    let mut s = String::from("--- blocks\n");
    for b in &program.blocks {
        let _ = writeln!(s, "{}:{} {:?} {:?} comment={:?}", b.line, b.column, b.number, b.body, b.comment);
    }
    s.push_str("--- diagnostics\n");
    for d in &diags {
        let _ = writeln!(
            s,
            "{}:{} {}: {} | {}",
            d.line,
            d.column,
            d.severity.as_str(),
            d.message_de,
            d.message_en
        );
    }
    s.push_str("--- fmt\n");
    s.push_str(&format_program(&program));
    s
}

/// Compares with (or, with UPDATE_SNAPSHOTS=1, writes) `NAME.snap`; returns a failure text.
fn check_snapshot(path: &Path, src: &str) -> Option<String> {
    let snap = path.with_extension("snap");
    let actual = snapshot_text(src);
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some() {
        fs::write(&snap, &actual).expect("snapshot writable");
        return None;
    }
    match fs::read_to_string(&snap) {
        Err(_) => Some(format!("{}: snapshot missing (run with UPDATE_SNAPSHOTS=1)", snap.display())),
        Ok(expected) if expected != actual => Some(format!(
            "{}: snapshot differs\n--- expected\n{expected}\n--- actual\n{actual}",
            snap.display()
        )),
        Ok(_) => None,
    }
}

#[test]
fn ok_fixtures_parse_cleanly_and_match_snapshots() {
    let mut failures = Vec::new();
    for path in programs("ok") {
        let src = fs::read_to_string(&path).expect("fixture readable");
        let (_, diags) = parse(&src);
        let as_printed = path.to_string_lossy().contains("as_printed");
        for d in &diags {
            let allowed = as_printed && matches!(d.code, DiagCode::CycleParamsElided { .. });
            if !allowed {
                failures.push(format!("{}:{}: {}", path.display(), d.line, d.message(Lang::De)));
            }
        }
        failures.extend(check_snapshot(&path, &src));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn as_printed_musterprogramm_warns_exactly_about_both_elided_cycles() {
    let src = fs::read_to_string(fixtures_dir().join("ok/musterprogramm1_as_printed.h")).expect("fixture");
    let (p, diags) = parse(&src);
    let lines: Vec<(u32, &DiagCode)> = diags.iter().map(|d| (d.line, &d.code)).collect();
    assert_eq!(
        lines,
        vec![
            (13, &DiagCode::CycleParamsElided { cycle: 232 }),
            (28, &DiagCode::CycleParamsElided { cycle: 200 })
        ]
    );
    assert_eq!(p.blocks.len(), 38);
    assert_eq!(p.blocks.last().and_then(|b| b.number), Some(37));
}

#[test]
fn completed_musterprogramm_has_all_cycle_parameters() {
    use schwenkbar_core::BlockBody;
    let src = fs::read_to_string(fixtures_dir().join("ok/musterprogramm1.h")).expect("fixture");
    let (p, diags) = parse(&src);
    assert!(diags.is_empty(), "{diags:?}");
    let numbers: Vec<Option<u32>> = p.blocks.iter().map(|b| b.number).collect();
    assert_eq!(numbers, (0..=37).map(Some).collect::<Vec<_>>());
    let params = |n: usize| match &p.blocks[n].body {
        BlockBody::CycleDef(c) => c.params.iter().map(|q| q.index).collect::<Vec<_>>(),
        other => panic!("block {n} is {other:?}"),
    };
    assert_eq!(params(12), [389, 225, 226, 227, 386, 218, 219, 202, 369, 370, 207, 385, 253, 200, 357, 204]);
    assert_eq!(params(27), [200, 201, 206, 202, 210, 203, 204, 211]);
    // The shipped copy is the same program.
    let shipped = fixtures_dir().join("../../static/programs/musterprogramm1.h");
    assert_eq!(fs::read_to_string(shipped).expect("static copy"), src);
}

#[test]
fn err_fixtures_report_the_stated_diagnostics() {
    let mut failures = Vec::new();
    for path in programs("err") {
        let src = fs::read_to_string(&path).expect("fixture readable");
        let expect = fs::read_to_string(path.with_extension("expect")).expect("sidecar .expect exists");
        let (_, diags) = parse(&src);
        for want in expect.lines().filter(|l| !l.trim().is_empty()) {
            let mut parts = want.splitn(3, ' ');
            let (line, sev, msg) = (parts.next(), parts.next(), parts.next().unwrap_or(""));
            let line: u32 = line.and_then(|l| l.parse().ok()).expect("LINE SEVERITY MESSAGE");
            let found = diags
                .iter()
                .any(|d| d.line == line && Some(d.severity.as_str()) == sev && d.message_de.contains(msg));
            if !found {
                failures.push(format!("{}: expected `{want}`, got {:#?}", path.display(), diags));
            }
        }
        failures.extend(check_snapshot(&path, &src));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn formatting_is_stable_for_every_fixture() {
    for dir in ["ok", "err"] {
        for path in programs(dir) {
            let src = fs::read_to_string(&path).expect("fixture readable");
            let once = format_program(&parse(&src).0);
            let (again, _) = parse(&once);
            assert_eq!(format_program(&again), once, "{}", path.display());
            if dir == "ok" {
                // Equal up to the renumbering.
                let strip = |p: schwenkbar_core::Program| {
                    p.blocks.into_iter().map(|b| (b.skip, b.body, b.comment)).collect::<Vec<_>>()
                };
                assert!(
                    strip(again) == strip(parse(&src).0),
                    "{}: reformatted program differs",
                    path.display()
                );
            }
        }
    }
}
