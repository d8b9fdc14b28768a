//! Every simulator fixture (`tests/fixtures/sim/*.h`) through `schwenkbar run --json`: one test
//! and one insta snapshot per file (`tests/snapshots/cli__run_fixtures__NAME.snap`), so a change in
//! what the simulator computes for any block shows up as a reviewed diff. The detailed
//! assertions on the same programs are in core/tests/sim.rs; these also catch changes to the
//! numbers no assertion names.
//!
//! The snapshot is the CLI's JSON as printed (key order kept), one executed block per line, with
//! every floating-point number written with at most 6 decimals: f64 maths may differ in the last
//! bits between machines, the 6th decimal does not. `cargo insta review` accepts a change.

use std::path::PathBuf;
use std::process::Command;

/// `tests/fixtures/sim`.
fn sim_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/fixtures/sim")
}

/// Runs one fixture and compares the snapshot `cli__run_fixtures__NAME`.
fn snapshot(name: &str, machine: &str, max_blocks: Option<usize>) {
    let file = sim_dir().join(format!("{name}.h"));
    let max = max_blocks.map(|n| n.to_string());
    let mut args = vec!["run", file.to_str().expect("UTF-8 path"), "--machine", machine, "--json"];
    if let Some(max) = &max {
        args.extend(["--max-blocks", max]);
    }
    let o = Command::new(env!("CARGO_BIN_EXE_schwenkbar")).args(&args).output().expect("binary runs");
    let json = String::from_utf8(o.stdout).expect("UTF-8 output");
    let mut text = format!("exit code {}\n{}", o.status.code().unwrap_or(-1), readable(&json));
    // What stderr says (a rapid into the blank, …), without the machine's path to the file.
    let stderr = String::from_utf8_lossy(&o.stderr).replace(file.to_str().expect("UTF-8 path"), "FILE");
    if !stderr.is_empty() {
        text.push_str(&format!("\nstderr:\n{stderr}"));
    }
    let mut command = format!("schwenkbar run tests/fixtures/sim/{name}.h --machine {machine} --json");
    if let Some(max) = &max {
        command.push_str(&format!(" --max-blocks {max}"));
    }
    insta::with_settings!({ description => command, omit_expression => true }, {
        insta::assert_snapshot!(name, text);
    });
}

/// The JSON text with one state per line and rounded numbers; strings and key order untouched.
fn readable(json: &str) -> String {
    let mut out = String::with_capacity(json.len());
    let mut depth = 0;
    let mut chars = json.trim_end().chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                out.push(c);
                while let Some(s) = chars.next() {
                    out.push(s);
                    match s {
                        '\\' => out.extend(chars.next()),
                        '"' => break,
                        _ => {}
                    }
                }
            }
            '{' | '[' => {
                // Depth 2 is inside `"states":[…]`: each state on its own line.
                if depth == 2 {
                    out.push_str("\n  ");
                }
                depth += 1;
                out.push(c);
            }
            '}' | ']' => {
                depth -= 1;
                // The end of the states array.
                if depth == 1 && c == ']' {
                    out.push('\n');
                }
                out.push(c);
            }
            '-' | '0'..='9' => {
                let mut token = String::from(c);
                while let Some(&d) =
                    chars.peek().filter(|d| matches!(d, '0'..='9' | '.' | 'e' | 'E' | '+' | '-'))
                {
                    token.push(d);
                    chars.next();
                }
                out.push_str(&number(&token));
            }
            _ => out.push(c),
        }
    }
    out.push('\n');
    out
}

/// Integers as printed; floats rounded to 6 decimals, trailing zeros dropped (one kept), no `-0`.
fn number(token: &str) -> String {
    if !token.contains(['.', 'e', 'E']) {
        return token.to_owned();
    }
    let x: f64 = token.parse().unwrap_or_else(|_| panic!("not a JSON number: {token}"));
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0');
    let s = if s.ends_with('.') { format!("{s}0") } else { s.to_owned() };
    if s == "-0.0" { "0.0".to_owned() } else { s }
}

/// One `#[test]` per fixture: `name: "machine"`, with `max_blocks = N` for the endless loops
/// (cut off by the CLI's `--max-blocks` instead of a million-block snapshot).
macro_rules! fixtures {
    ($($name:ident: $machine:literal $(, max_blocks = $max:literal)?;)+) => {
        $(
            #[test]
            fn $name() {
                snapshot(stringify!($name), $machine, None $(.or(Some($max)))?);
            }
        )+
        /// The fixtures that have a test, for the completeness check.
        const NAMES: &[&str] = &[$(stringify!($name)),+];
    };
}

fixtures! {
    arcs_tilted: "ac-table";
    axial_mirror: "ac-table";
    c_without_cc: "ac-table";
    call_lbl: "ac-table";
    contour_arcs: "ac-table";
    contour_rl: "ac-table";
    cr_too_small: "ac-table";
    cycle19_stay: "ac-table";
    cycle_calls: "ac-table";
    datum_then_tilt: "ac-table";
    drill_pattern_euler: "ac-table";
    endless: "ac-table", max_blocks = 25;
    endless_fn9: "ac-table", max_blocks = 25;
    fn_jump_loop: "ac-table";
    fn_math_loop: "ac-table";
    function_tcpm: "ac-table";
    linear_limit: "ac-table";
    m99_without_cycle: "ac-table";
    mirror_then_tilt: "ac-table";
    old_cycles_7_8_10: "ac-table";
    pocket_spatial: "ac-table";
    polar_helix: "ac-table";
    relativ_chain: "ac-table";
    rotary_limit: "ca-head";
    swivel_move: "ac-table";
    swivel_stay: "ac-table";
    swivel_turn: "ac-table";
    undefined_q: "ac-table";
    unreachable: "ca-head";
    wpl_transforms: "ac-table";
}

#[test]
fn every_sim_fixture_has_a_snapshot_test() {
    // A new fixture goes into `fixtures!` with its machine.
    schwenkbar_testkit::assert_one_test_per_program(&sim_dir(), NAMES);
}

#[test]
fn readable_keeps_strings_and_rounds_floats() {
    let json = r#"{"machine":"ac-table","states":[{"line":3,"block":"L X-0.1234567 [1]","axes":{"X":-1.0000000004,"A":0.70710678118},"q":{}},{"line":4,"tip":[-0.0000001,1e-9,12.5]}],"error":{"line":6,"message":"\"}"}}"#;
    assert_eq!(
        readable(json),
        concat!(
            r#"{"machine":"ac-table","states":["#,
            "\n  ",
            r#"{"line":3,"block":"L X-0.1234567 [1]","axes":{"X":-1.0,"A":0.707107},"q":{}},"#,
            "\n  ",
            r#"{"line":4,"tip":[0.0,0.0,12.5]}"#,
            "\n",
            r#"],"error":{"line":6,"message":"\"}"}}"#,
            "\n"
        )
    );
}
