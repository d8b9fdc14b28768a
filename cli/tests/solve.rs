//! `schwenkbar solve` end to end: the seed's two SYM/SEQ tables row by row (DOMAIN.md §10,
//! oracles 13–27, from tests/fixtures/oracles/seq_sym.tsv), plus oracles 28–30, the JSON shape
//! of issue 4 and `schwenkbar machines`.

use std::process::{Command, Output};

use schwenkbar_testkit::assert_close;
use schwenkbar_testkit::seq_sym::{self, Expect};
use serde_json::Value;

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_schwenkbar")).args(args).output().expect("binary runs")
}

/// Runs `solve`, returns (exit code, JSON).
fn solve(machine: &str, start: &str, limit: Option<&str>, block: &str) -> (i32, Value) {
    let mut args = vec!["solve", "--machine", machine, "--start", start];
    if let Some(l) = limit {
        args.extend(["--limit", l]);
    }
    args.push(block);
    let o = run(&args);
    let text = String::from_utf8_lossy(&o.stdout);
    let json = serde_json::from_str(&text).unwrap_or_else(|e| {
        panic!("{args:?}: not JSON ({e}): {text} / {}", String::from_utf8_lossy(&o.stderr))
    });
    (o.status.code().unwrap_or(-1), json)
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// Runs `solve` and checks the control's answer: the chosen axes within 1e-4 (the oracles'
/// 4 decimals), or exit code 1 with the refusal's message.
fn check_row(id: &str, machine: &str, start: &str, limit: Option<&str>, block: &str, expect: &Expect) {
    let (code, j) = solve(machine, start, limit, block);
    match expect {
        Expect::Chosen(axes) => {
            assert_eq!(code, 0, "{id}: {j}");
            assert_eq!(j["error"], Value::Null, "{id}");
            let got: Vec<f64> = axes.iter().map(|(axis, _)| num(&j["chosen"][axis.to_string()])).collect();
            let want: Vec<f64> = axes.iter().map(|&(_, v)| v).collect();
            assert_close!(got, want, 1e-4, "{id}: {axes:?}: {j}");
        }
        Expect::Refused(message) => {
            assert_eq!(code, 1, "{id}: {j}");
            assert_eq!(j["chosen"], Value::Null, "{id}");
            assert_eq!(j["error"], message.as_str(), "{id}");
        }
    }
}

/// Every row of seq_sym.tsv on `machine`, each of its blocks (the "SYM=SEQ" rows both as SYM
/// and as SEQ); `count` guards against a table that lost rows.
fn check_table(machine: &str, count: usize) {
    let rows: Vec<_> = seq_sym::rows().into_iter().filter(|r| r.machine == machine).collect();
    assert_eq!(rows.len(), count, "{machine} rows in seq_sym.tsv");
    for row in rows {
        for block in row.blocks() {
            let id = format!("oracle {} ({}): {block}", row.oracle, row.source);
            check_row(&id, &row.machine, &row.start, row.limit.as_deref(), &block, &row.expect);
        }
    }
}

#[test]
fn seed_table_c_rotary_table_on_a_tilting_table() {
    // Seed S2, first example: PLANE SPATIAL SPA+0 SPB+45 SPC+0 from A0 C0 / C−105 / C−135.
    check_table("ac-table", 10);
}

#[test]
fn seed_table_b_rotary_table_on_a_tilting_table() {
    // Seed S2, second example: limits A −100…+180 are the machine's own.
    check_table("ba-table", 5);
}

#[test]
fn other_kinematics_oracles_28_to_30() {
    // 28: both candidates of SPB+45 on B head + C table.
    let (_, j) = solve("bc-head-table", "", None, "PLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY");
    let mut c: Vec<(f64, f64)> = j["candidates"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| (num(&c["axes"]["B"]), num(&c["axes"]["C"]).abs()))
        .collect();
    c.sort_by(|a, b| b.0.total_cmp(&a.0));
    assert_eq!(c, vec![(45.0, 0.0), (-45.0, 180.0)]);
    // 29: A/C, SPA+45 SPC+90 → A+45 C+90.
    let pos = Expect::Chosen(vec![('A', 45.0), ('C', 90.0)]);
    check_row("oracle 29", "ac-table", "", None, "PLANE SPATIAL SPA+45 SPB+0 SPC+90 TURN FMAX SEQ+", &pos);
    // 30: SPC only: COORD ROT leaves C where it is, TABLE ROT turns C to +45.
    for (mode, c) in [("COORD ROT", 10.0), ("TABLE ROT", 45.0)] {
        let block = format!("PLANE SPATIAL SPA+0 SPB+0 SPC+45 STAY {mode}");
        let expect = Expect::Chosen(vec![('A', 0.0), ('C', c)]);
        check_row("oracle 30", "ac-table", "A+0 C+10", None, &block, &expect);
    }
}

#[test]
fn json_has_exactly_the_fields_of_the_issue() {
    let (code, j) = solve("ac-table", "A+0 C-105", None, "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX");
    assert_eq!(code, 0);
    let keys: Vec<&str> = j.as_object().unwrap().keys().map(String::as_str).collect();
    let mut want = [
        "machine",
        "orientation",
        "tool_axis",
        "spatial",
        "euler",
        "candidates",
        "chosen",
        "error",
        "reason",
    ];
    let mut got = keys.clone();
    got.sort_unstable();
    want.sort_unstable();
    assert_eq!(got, want);
    assert_eq!(j["machine"], "ac-table");
    assert_eq!(j["orientation"].as_array().unwrap().len(), 3);
    assert_eq!(j["spatial"], serde_json::json!([0.0, 45.0, 0.0]));
    let c = &j["candidates"][0];
    let mut ck: Vec<&str> = c.as_object().unwrap().keys().map(String::as_str).collect();
    ck.sort_unstable();
    assert_eq!(ck, ["axes", "in_limits", "path"]);
    // "C travel 15 vs 195" (DOMAIN.md §10 row 16): paths 45+15 and 45+195.
    let mut paths: Vec<f64> = j["candidates"].as_array().unwrap().iter().map(|c| num(&c["path"])).collect();
    paths.sort_by(f64::total_cmp);
    assert_eq!(paths, vec![60.0, 240.0]);
    assert_eq!(j["reason"], "Kürzester Weg von der aktuellen Position der Drehachsen");
}

#[test]
fn english_and_bad_input() {
    let o = run(&[
        "solve",
        "--machine",
        "ba-table",
        "--lang",
        "en",
        "PLANE SPATIAL SPA-45 SPB+0 SPC+0 TURN FMAX SEQ+",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let j: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(j["error"], "Entered angle not permitted");
    assert_eq!(j["reason"], "SEQ+: master axis A must be positive (relative to its home position 0°)");
    for args in [
        vec!["solve", "--machine", "nope", "PLANE RESET STAY"],
        vec!["solve", "--machine", "ac-table", "--start", "X+5", "PLANE RESET STAY"],
        vec!["solve", "--machine", "ac-table", "--limit", "A=10..-10", "PLANE RESET STAY"],
        vec!["solve", "--machine", "ac-table", "L X+10 R0 FMAX"],
        vec!["solve", "--machine", "ac-table", "PLANE EULER EULPR+0 EULNU-5 EULROT0 TURN FMAX"],
        vec!["solve", "--machine", "ac-table", "PLANE AXIAL B+10 TURN FMAX"],
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(!o.stderr.is_empty(), "{args:?}");
    }
}

#[test]
fn machines_lists_the_ids() {
    let o = run(&["machines"]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        "ac-table\nba-table\nbc-head-table\nca-head\nb45-nutating\n"
    );
    let o = run(&["machines", "--json"]);
    let j: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(j.as_array().unwrap().len(), 5);
    assert_eq!(j[1]["chain"][1]["limits"], serde_json::json!({"min": -100.0, "max": 180.0}));
}
