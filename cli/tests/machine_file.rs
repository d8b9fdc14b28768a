//! `--machine FILE.json` (issue 17, the instructor's own machine): a copy of a shipped file runs
//! exactly as the shipped id, and a broken file is refused with its problems in German and
//! English and a non-zero exit.

use std::path::PathBuf;
use std::process::{Command, Output};

use serde_json::{Value, json};

fn repo(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..").join(rel)
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_schwenkbar")).args(args).output().expect("binary runs")
}

fn ac_table() -> Value {
    let text = std::fs::read_to_string(repo("static/machines/ac-table.json")).expect("machine file");
    serde_json::from_str(&text).expect("JSON")
}

/// Writes `v` to `name` in this test binary's scratch directory and returns the path.
fn write(name: &str, v: &Value) -> String {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, serde_json::to_string_pretty(v).expect("JSON")).expect("write machine file");
    path.to_string_lossy().into_owned()
}

#[test]
fn a_copy_of_ac_table_runs_exactly_as_the_shipped_id() {
    let copy = write("ac-table-copy.json", &ac_table());
    let mut programs = vec![repo("static/programs/musterprogramm1.h")];
    let mut fixtures: Vec<PathBuf> = std::fs::read_dir(repo("tests/fixtures/sim"))
        .expect("fixtures")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "h"))
        // The endless loops run to the block budget: seconds each in a debug build, and nothing
        // in them depends on the machine beyond what the other programs show.
        .filter(|p| !p.file_name().is_some_and(|n| n.to_string_lossy().starts_with("endless")))
        .collect();
    fixtures.sort();
    programs.extend(fixtures);
    for program in &programs {
        let program = program.to_string_lossy();
        for lang in ["de", "en"] {
            let by_id = run(&["run", &program, "--machine", "ac-table", "--json", "--lang", lang]);
            let by_file = run(&["run", &program, "--machine", &copy, "--json", "--lang", lang]);
            assert_eq!(by_file.status.code(), by_id.status.code(), "{program}");
            assert_eq!(
                String::from_utf8_lossy(&by_file.stdout),
                String::from_utf8_lossy(&by_id.stdout),
                "{program} --lang {lang}"
            );
            // The same notes too (a fixture may rapid into its blank: said on stderr).
            assert_eq!(
                String::from_utf8_lossy(&by_file.stderr),
                String::from_utf8_lossy(&by_id.stderr),
                "{program}"
            );
        }
    }
    let block = "PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX SEQ-";
    let by_id = run(&["solve", "--machine", "ac-table", block]);
    let by_file = run(&["solve", "--machine", &copy, block]);
    assert_eq!(by_file.status.code(), Some(0));
    assert_eq!(by_file.stdout, by_id.stdout);
}

/// One edit of a machine file.
type Edit = fn(&mut Value);

#[test]
fn an_invalid_file_is_refused_with_its_messages() {
    let cases: [(&str, Edit, &str, &str); 5] = [
        ("empty-id", |v| v["id"] = json!(""), "id: darf nicht leer sein", "id: must not be empty"),
        (
            "zero-direction",
            |v| v["chain"][0]["direction"] = json!([0, 0, 0]),
            "chain[0].direction: Richtung ist der Nullvektor",
            "chain[0].direction: direction is the zero vector",
        ),
        (
            "unknown-axis",
            |v| v["chain"][1]["axis"] = json!("Q"),
            "chain[1].axis: unbekannte Drehachse „Q“ (A, B oder C)",
            "chain[1].axis: unknown rotary axis \"Q\" (A, B or C)",
        ),
        (
            "head-before-table",
            |v| v["chain"][0]["carrier"] = json!("head"),
            "chain[1].carrier: Tischachse A nach einer Kopfachse",
            "chain[1].carrier: table axis A after a head axis",
        ),
        (
            "start-outside",
            |v| v["geometry"]["start"] = json!([0, 0, 10]),
            "geometry.start: Startposition Z 10 außerhalb der Grenzen -500 … 0",
            "geometry.start: start position Z 10 outside the limits -500 … 0",
        ),
    ];
    let program = repo("static/programs/musterprogramm1.h");
    for (name, edit, de, en) in cases {
        let mut v = ac_table();
        edit(&mut v);
        let file = write(&format!("{name}.json"), &v);
        for args in [
            vec!["run", &*program.to_string_lossy(), "--machine", &file, "--json"],
            vec!["solve", "--machine", &file, "PLANE RESET STAY"],
            vec!["machines", &file],
        ]
        .map(|a| a.into_iter().map(String::from).collect::<Vec<_>>())
        {
            let o = run(&args.iter().map(String::as_str).collect::<Vec<_>>());
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{name} {}: {err}", args[0]);
            assert!(o.stdout.is_empty(), "{name}: {}", String::from_utf8_lossy(&o.stdout));
            // German first, the English on the next line, each naming the file.
            let de_at = err.find(&format!("{file}: {de}")).unwrap_or_else(|| panic!("{name}: {err}"));
            let en_at = err.find(&format!("{file}: {en}")).unwrap_or_else(|| panic!("{name}: {err}"));
            assert!(de_at < en_at, "{name}: {err}");
        }
    }
}

#[test]
fn an_unreadable_or_missing_file_is_refused() {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("broken.json");
    std::fs::write(&path, "{ \"id\": ").expect("write");
    let file = path.to_string_lossy();
    let o = run(&["solve", "--machine", &file, "PLANE RESET STAY"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("Maschinendatei nicht lesbar (Zeile 1") && err.contains("Machine file unreadable"),
        "{err}"
    );
    let o = run(&["solve", "--machine", "no-such-machine.json", "PLANE RESET STAY"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no-such-machine.json"));
}

/// `schwenkbar machines FILE.json…` checks files before a class: a sound one is listed by its
/// id (or as JSON, equal to the shipped machine's for a copy), a broken one fails the command.
#[test]
fn machines_checks_the_given_files() {
    let mut v = ac_table();
    v["id"] = json!("werkstatt-1");
    let own = write("werkstatt-1.json", &v);
    let o = run(&["machines", &own]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(String::from_utf8_lossy(&o.stdout), "werkstatt-1\n");
    let copy = write("ac-table-listed.json", &ac_table());
    let listed = run(&["machines", &copy, "--json"]);
    let shipped = run(&["machines", "--json"]);
    let listed: Value = serde_json::from_slice(&listed.stdout).expect("JSON");
    let shipped: Value = serde_json::from_slice(&shipped.stdout).expect("JSON");
    assert_eq!(listed[0], shipped[0], "ac-table is the first shipped machine");
    let mut broken = ac_table();
    broken["chain"][0]["direction"] = json!([0, 0, 0]);
    let broken = write("listed-broken.json", &broken);
    let o = run(&["machines", &own, &broken]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("Richtung ist der Nullvektor"));
}
