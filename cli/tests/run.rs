//! End-to-end tests of `schwenkbar run` on the completed Musterprogramm 1 and the simulator
//! fixtures.

use std::path::PathBuf;
use std::process::{Command, Output};

use schwenkbar_testkit::assert_close;

fn repo(rel: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join(rel).to_string_lossy().into_owned()
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_schwenkbar")).args(args).output().expect("binary runs")
}

fn json(o: &Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout).expect("json output")
}

/// Tolerance for numbers printed by the CLI (rounded to 1e-9 there).
const TOL: f64 = 1e-6;

/// The JSON numbers at these places (NaN where there is none, which no tolerance accepts).
fn nums<const N: usize>(vs: [&serde_json::Value; N]) -> [f64; N] {
    vs.map(|v| v.as_f64().unwrap_or(f64::NAN))
}

#[test]
fn run_musterprogramm_prints_a_row_per_block() {
    let f = repo("static/programs/musterprogramm1.h");
    let o = run(&["run", &f, "--machine", "ac-table"]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 1 + 38, "header + 38 blocks:\n{out}");
    assert!(lines[0].contains('X') && lines[0].contains('A') && lines[0].contains('C'));
    let row10 = lines.iter().find(|l| l.contains("10 PLANE SPATIAL")).expect("block 10");
    assert!(row10.contains("15.0000") && row10.contains("90.0000") && row10.contains("+15.0000"), "{row10}");
    assert!(out.contains("Zyklus 232 ausgeführt"), "{out}");
}

#[test]
fn run_json_has_the_issue_shape() {
    let f = repo("static/programs/musterprogramm1.h");
    let o = run(&["run", &f, "--machine", "ac-table", "--json", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(0));
    let v = json(&o);
    assert_eq!(v["machine"], "ac-table");
    assert!(v["error"].is_null());
    let states = v["states"].as_array().expect("states");
    assert_eq!(states.len(), 38);
    let s10 = states.iter().find(|s| s["number"] == 10).expect("block 10");
    assert_eq!(s10["block"], "10 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX ; Einschwenken");
    let axes = &s10["axes"];
    assert_close!(
        nums([&axes["A"], &axes["C"], &axes["X"], &axes["Z"]]),
        [15.0, 90.0, -600.0, 0.0],
        TOL,
        "{s10}"
    );
    assert_close!(nums([&s10["plane"]["spatial"][1]]), [15.0], TOL);
    assert_close!(nums([&s10["plane"]["tool_axis"][0]]), [15f64.to_radians().sin()], TOL);
    assert_close!(nums([&s10["q"]["120"], &s10["q"]["122"]]), [15.0, 90.0], TOL);
    assert_eq!(s10["tool_tip_wcs"].as_array().map(Vec::len), Some(3));
    let s18 = states.iter().find(|s| s["number"] == 18).expect("block 18");
    assert!(s18["plane"].is_null());
    assert_close!(nums([&s18["axes"]["A"], &s18["axes"]["C"]]), [0.0, 0.0], TOL, "{s18}");
    let s13 = states.iter().find(|s| s["number"] == 13).expect("block 13");
    assert!(s13["message"].as_str().is_some_and(|m| m.contains("Cycle 232 executed")), "{s13}");
}

#[test]
fn run_reports_the_controls_error_at_its_line() {
    let f = repo("tests/fixtures/sim/unreachable.h");
    let o = run(&["run", &f, "--machine", "ca-head", "--json"]);
    assert_eq!(o.status.code(), Some(1));
    let v = json(&o);
    assert_eq!(v["error"]["line"], 6);
    assert_eq!(v["error"]["message"], "Winkel nicht erlaubt");
    assert_eq!(v["states"].as_array().map(Vec::len), Some(5));
    let o = run(&["run", &f, "--machine", "ca-head"]);
    assert_eq!(o.status.code(), Some(1));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        out.trim_end().ends_with("Winkel nicht erlaubt: Keine der 2 Lösungen liegt im Verfahrbereich"),
        "{out}"
    );
}

/// The table is written by a second thread in batches of rows (`write_table`): a program of
/// several batches and a part gets every row once, in order, with its own values.
#[test]
fn run_table_of_many_blocks_has_every_row_in_order() {
    let n: u32 = 2500;
    let mut src = String::from("0 BEGIN PGM LONG MM\n");
    for i in 1..=n {
        src.push_str(&format!("{i} L X+{:.2} Y+0 Z+50 R0 FMAX\n", f64::from(i) * 0.01));
    }
    src.push_str(&format!("{} END PGM LONG MM\n", n + 1));
    let path = std::env::temp_dir().join(format!("schwenkbar-long-{}.h", std::process::id()));
    std::fs::write(&path, &src).expect("write program");
    let o = run(&["run", &path.to_string_lossy(), "--machine", "ac-table"]);
    let _ = std::fs::remove_file(&path);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    let rows: Vec<&str> = out.lines().skip(1).collect();
    assert_eq!(rows.len(), n as usize + 2, "BEGIN PGM, the lines, END PGM");
    // The machine X after the 5-wide line number, two blanks and the 44-wide block text.
    let x =
        |row: &str| -> f64 { row[51..].split_whitespace().next().and_then(|w| w.parse().ok()).expect("X") };
    let x1 = x(rows[1]);
    for (k, row) in rows.iter().enumerate() {
        let line: usize = row.split_whitespace().next().and_then(|w| w.parse().ok()).expect("line column");
        assert_eq!(line, k + 1, "{row}");
        if (1..=n as usize).contains(&k) {
            assert!(row.contains(&format!("{k} L X+{:.2} ", k as f64 * 0.01)), "{row}");
            assert_close!([x(row) - x1], [(k - 1) as f64 * 0.01], 1e-9, "X of block {k}: {row}");
        }
    }
}

#[test]
fn run_rejects_an_unknown_machine() {
    let f = repo("static/programs/musterprogramm1.h");
    let o = run(&["run", &f, "--machine", "no-such"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("ac-table"));
}

#[test]
fn run_json_lists_axes_in_display_order() {
    let f = repo("tests/fixtures/sim/swivel_stay.h");
    let o = run(&["run", &f, "--machine", "ac-table", "--json"]);
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    let i = |k: &str| text.find(&format!("\"{k}\":")).expect("axis key");
    assert!(i("X") < i("Y") && i("Y") < i("Z") && i("Z") < i("A") && i("A") < i("C"), "{text}");
}

/// The table (written with the exact fixed-point writer into one reused row) says, byte for
/// byte, what `format!` makes of the JSON report's numbers: `{:>5}` line, `{:<44}` block,
/// `{:>10.4}` per axis, `{:+.4}` plane angles, then the message.
#[test]
fn run_table_rows_are_the_json_states_formatted() {
    for (file, machine) in [
        ("static/programs/musterprogramm1.h", "ac-table"),
        ("tests/fixtures/sim/swivel_turn.h", "ac-table"),
        ("tests/fixtures/sim/pocket_spatial.h", "bc-head-table"),
        ("tests/fixtures/sim/relativ_chain.h", "ba-table"),
        ("tests/fixtures/sim/unreachable.h", "ca-head"),
    ] {
        let f = repo(file);
        let table = String::from_utf8(run(&["run", &f, "--machine", machine]).stdout).expect("UTF-8");
        let report = json(&run(&["run", &f, "--machine", machine, "--json"]));
        let states = report["states"].as_array().expect("states");
        // The header names the axes in the table's order (JSON objects here are sorted).
        let letters: Vec<&str> = table
            .lines()
            .next()
            .unwrap_or("")
            .split_whitespace()
            .skip(2)
            .take_while(|w| *w != "SPA/SPB/SPC")
            .collect();
        assert!(letters.len() >= 5, "{file}: {letters:?}");
        let rows: Vec<&str> = table.lines().skip(1).take(states.len()).collect();
        assert_eq!(rows.len(), states.len(), "{file}");
        for (row, s) in rows.iter().zip(states) {
            let text: String = s["block"].as_str().unwrap_or("").chars().take(44).collect();
            let mut expected = format!("{:>5}  {text:<44}", s["line"].as_u64().unwrap_or(0));
            for c in &letters {
                expected.push_str(&format!(" {:>10.4}", s["axes"][c].as_f64().unwrap_or(f64::NAN)));
            }
            let plane = match s["plane"]["spatial"].as_array() {
                Some(a) => {
                    let a: Vec<f64> = a.iter().map(|v| v.as_f64().unwrap_or(f64::NAN)).collect();
                    format!("{:+.4} {:+.4} {:+.4}", a[0], a[1], a[2])
                }
                None => "-".to_owned(),
            };
            expected.push_str(&format!("  {plane:<26}"));
            if let Some(m) = s["message"].as_str() {
                expected.push_str("  ");
                expected.push_str(m);
            }
            assert_eq!(*row, expected.trim_end(), "{file} on {machine}");
        }
    }
}

/// `--machine auto` (issue 31): the shipped machine with the program's rotary axes on which the
/// run gets furthest; which one and why on stderr, the output as for a named machine.
#[test]
fn machine_auto_takes_a_machine_with_the_programs_rotary_axes() {
    let dir = std::env::temp_dir().join(format!("schwenkbar-auto-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    for (name, words, ids) in [
        ("bc", "B+30 C+45", &["bc-head-table", "b45-nutating"][..]),
        ("ac", "A+20 C+90", &["ac-table", "ca-head"][..]),
    ] {
        let path = dir.join(format!("{name}.h"));
        let src = format!(
            "0 BEGIN PGM AUTO MM\n1 TOOL CALL 1 Z S1000\n2 L Z+50 R0 FMAX\n3 L {words} R0 FMAX\n4 END PGM AUTO MM\n"
        );
        std::fs::write(&path, src).expect("write");
        let o = run(&["run", &path.to_string_lossy(), "--machine", "auto", "--json", "--lang", "en"]);
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
        let machine = json(&o)["machine"].as_str().unwrap_or_default().to_owned();
        assert!(ids.contains(&machine.as_str()), "{name}: {machine}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("Machine chosen automatically") && err.contains(&machine), "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--tools TOOL.T`: the shop's table gives the called tools (L incl. the table's DL, R incl.
/// DR, a length under 30 mm as the difference to a zero tool); a broken table stops before the
/// run with its line.
#[test]
fn run_with_the_shops_tool_table() {
    let dir = std::env::temp_dir().join(format!("schwenkbar-tools-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let program = dir.join("t.h");
    std::fs::write(
        &program,
        "0 BEGIN PGM T MM\n1 TOOL CALL 3 Z S1000\n2 TOOL CALL \"ZENTRIERBOHRER_D6\" Z\n3 END PGM T MM\n",
    )
    .expect("write");
    let table = repo("tests/fixtures/tools/werkstatt.T");
    let p = program.to_string_lossy().into_owned();
    let o = run(&["run", &p, "--machine", "ac-table", "--tools", &table, "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let v = json(&o);
    let s1 =
        v["states"].as_array().expect("states").iter().find(|s| s["number"] == 1).expect("block 1").clone();
    assert_close!(nums([&s1["q"]["114"], &s1["q"]["108"]]), [95.6, 9.95], TOL, "{s1}");
    let s2 =
        v["states"].as_array().expect("states").iter().find(|s| s["number"] == 2).expect("block 2").clone();
    assert!(s2["message"].as_str().is_some_and(|m| m.contains("Differenz zum Nullwerkzeug")), "{s2}");

    let broken = dir.join("broken.T");
    std::fs::write(&broken, "BEGIN TOOL .T MM\nT L  R\n1 +1 x\n").expect("write");
    let o = run(&["run", &p, "--machine", "ac-table", "--tools", &broken.to_string_lossy()]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("Zeile 3: R: „x“ ist keine Zahl"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 32: the drill 5 mm deep, then `PLANE SPATIAL … TURN` without `MB MAX`: the swivel turns
/// the tool in the material. `run` says so on the PLANE block's line (stderr and the JSON state),
/// without being asked to cut the stock; with `MB MAX` it is free.
#[test]
fn run_says_a_swivel_with_the_tool_in_the_material_on_its_plane_block() {
    let program = |mb: &str| {
        format!(
            "0 BEGIN PGM SW MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n\
             3 TOOL CALL 1 Z S1000\n4 L X+50 Y+50 Z+10 R0 FMAX\n5 L Z-5 F100\n\
             6 PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN{mb} FMAX\n7 END PGM SW MM\n"
        )
    };
    let path = std::env::temp_dir().join(format!("schwenkbar-swivel-{}.h", std::process::id()));
    std::fs::write(&path, program("")).expect("temp file");
    let file = path.to_string_lossy().into_owned();
    let o = run(&["run", &file, "--machine", "ac-table", "--lang", "en"]);
    assert_eq!(
        String::from_utf8_lossy(&o.stderr),
        format!("{file}:7: Swivelling with the tool in the material: collision – retract first (MB MAX)\n")
    );
    let o = run(&["run", &file, "--machine", "ac-table", "--json"]);
    let states = json(&o)["states"].as_array().expect("states").clone();
    let said: Vec<_> =
        states.iter().filter(|s| s.get("collision").is_some()).map(|s| s["line"].clone()).collect();
    assert_eq!(said, [serde_json::json!(7)]);
    std::fs::write(&path, program(" MB MAX")).expect("temp file");
    let o = run(&["run", &file, "--machine", "ac-table"]);
    assert!(o.stderr.is_empty(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success());
    let _ = std::fs::remove_file(&path);
}

/// `--stock-stl`: the stock after the run as a binary STL (80-byte header, the triangle count,
/// 50 bytes a triangle), and on stderr what was removed and the box around what is left. Two
/// passes of the face mill (R 25) 2 mm deep over the whole 100 × 100 × 40 blank: 20,000 mm³
/// (closed form), the material left from Z−40 to Z−2.
#[test]
fn run_writes_the_stock_and_says_what_is_left() {
    let dir = std::env::temp_dir().join(format!("schwenkbar-stock-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let program = dir.join("face.h");
    std::fs::write(
        &program,
        "0 BEGIN PGM FACE MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n\
         3 TOOL CALL 16 Z S5000 F500\n4 L X-40 Y+25 Z+50 R0 FMAX\n5 L Z-2 F500\n6 L X+140\n7 L Y+75\n\
         8 L X-40\n9 L Z+50 FMAX\n10 END PGM FACE MM\n",
    )
    .expect("write");
    let stl = dir.join("face.stl");
    let (p, out) = (program.to_string_lossy().into_owned(), stl.to_string_lossy().into_owned());
    let o = run(&["run", &p, "--machine", "ac-table", "--stock-stl", &out, "--stock-resolution", "1"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("stock: 20000 mm³ of 400000 mm³ removed"), "{err}");
    assert!(err.contains("material left X+0…+100 Y+0…+100 Z-40…-2,"), "{err}");
    let bytes = std::fs::read(&stl).expect("stl written");
    let n = u32::from_le_bytes(bytes[80..84].try_into().expect("count")) as usize;
    assert!(n > 0 && bytes.len() == 84 + 50 * n, "{} bytes for {n} triangles", bytes.len());
    assert!(err.contains(&format!("{n} triangles")), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
