//! `schwenkbar solve` end to end: the seed's two SYM/SEQ tables row by row (DOMAIN.md §10,
//! oracles 13–27), plus oracles 28–30, the JSON shape of issue 4 and `schwenkbar machines`.

use std::process::{Command, Output};

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

/// Expected `chosen` as (axis, value) pairs, or `None` for "Winkel nicht erlaubt".
type Expect = Option<&'static [(&'static str, f64)]>;

fn check_row(id: u8, machine: &str, start: &str, limit: Option<&str>, block: &str, expect: Expect) {
    let (code, j) = solve(machine, start, limit, block);
    match expect {
        Some(axes) => {
            assert_eq!(code, 0, "row {id}: {j}");
            assert_eq!(j["error"], Value::Null, "row {id}");
            for (axis, value) in axes {
                let got = num(&j["chosen"][axis]);
                assert!(
                    (got - value).abs() < 1e-4,
                    "row {id}: {axis} = {got}, expected {value} (diff {:e}): {j}",
                    got - value
                );
            }
        }
        None => {
            assert_eq!(code, 1, "row {id}: {j}");
            assert_eq!(j["chosen"], Value::Null, "row {id}");
            assert_eq!(j["error"], "Winkel nicht erlaubt", "row {id}");
        }
    }
}

const POS: Expect = Some(&[("A", 45.0), ("C", 90.0)]);
const NEG: Expect = Some(&[("A", -45.0), ("C", -90.0)]);

#[test]
fn seed_table_c_rotary_table_on_a_tilting_table() {
    // Seed S2, first example: PLANE SPATIAL SPA+0 SPB+45 SPC+0; the "SYM = SEQ" column is run
    // both as SEQ and as SYM (symmetry point A0 on this machine).
    let base = "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX";
    let lim = Some("A=-90..10");
    let rows: [(u8, &str, Option<&str>, &str, Expect); 10] = [
        (13, "A+0 C+0", None, "", POS),
        (14, "A+0 C+0", None, "+", POS),
        (15, "A+0 C+0", None, "-", NEG),
        (16, "A+0 C-105", None, "", NEG),
        (17, "A+0 C-105", None, "+", POS),
        (18, "A+0 C-105", None, "-", NEG),
        (19, "A+0 C+0", lim, "", NEG),
        (20, "A+0 C+0", lim, "+", None),
        (21, "A+0 C+0", lim, "-", NEG),
        (22, "A+0 C-135", None, "+", POS),
    ];
    for (id, start, limit, sign, expect) in rows {
        if sign.is_empty() {
            check_row(id, "ac-table", start, limit, base, expect);
        } else {
            for word in ["SEQ", "SYM"] {
                check_row(id, "ac-table", start, limit, &format!("{base} {word}{sign}"), expect);
            }
        }
    }
}

#[test]
fn seed_table_b_rotary_table_on_a_tilting_table() {
    // Seed S2, second example: limits A −100…+180 are the machine's own.
    let base = "PLANE SPATIAL SPA-45 SPB+0 SPC+0 TURN FMAX";
    let good: Expect = Some(&[("A", -45.0), ("B", 0.0)]);
    let rows: [(u8, &str, Expect); 5] =
        [(23, " SYM+", good), (24, " SYM-", None), (25, " SEQ+", None), (26, " SEQ-", good), (27, "", good)];
    for (id, opt, expect) in rows {
        check_row(id, "ba-table", "", None, &format!("{base}{opt}"), expect);
    }
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
    check_row(29, "ac-table", "", None, "PLANE SPATIAL SPA+45 SPB+0 SPC+90 TURN FMAX SEQ+", POS);
    // 30: SPC only: COORD ROT leaves C where it is, TABLE ROT turns C to +45.
    check_row(
        30,
        "ac-table",
        "A+0 C+10",
        None,
        "PLANE SPATIAL SPA+0 SPB+0 SPC+45 STAY COORD ROT",
        Some(&[("A", 0.0), ("C", 10.0)]),
    );
    check_row(
        30,
        "ac-table",
        "A+0 C+10",
        None,
        "PLANE SPATIAL SPA+0 SPB+0 SPC+45 STAY TABLE ROT",
        Some(&[("A", 0.0), ("C", 45.0)]),
    );
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
