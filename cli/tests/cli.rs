//! End-to-end tests of the `schwenkbar` binary on the fixture programs.

use std::path::PathBuf;
use std::process::{Command, Output};

fn fixture(rel: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../tests/fixtures").join(rel)
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_schwenkbar")).args(args).output().expect("binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn check_completed_musterprogramm_is_clean() {
    let f = fixture("ok/musterprogramm1.h");
    let o = run(&["check", f.to_str().expect("utf-8 path")]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(stdout(&o), "");
}

#[test]
fn check_as_printed_reports_only_elision_warnings() {
    let f = fixture("ok/musterprogramm1_as_printed.h");
    let name = f.to_str().expect("utf-8 path");
    let o = run(&["check", name]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        stdout(&o),
        format!(
            "{name}:13:29: warning: Zyklusparameter ausgelassen: CYCL DEF 232\n\
             {name}:28:24: warning: Zyklusparameter ausgelassen: CYCL DEF 200\n"
        )
    );
}

#[test]
fn check_err_fixtures_print_expected_line_and_message() {
    let dir = fixture("err");
    let mut seen = 0;
    for entry in std::fs::read_dir(&dir).expect("err fixtures") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "h") {
            continue;
        }
        let name = path.to_str().expect("utf-8 path");
        let expect = std::fs::read_to_string(path.with_extension("expect")).expect("sidecar");
        let o = run(&["check", name]);
        assert_eq!(o.status.code(), Some(1), "{name}");
        let out = stdout(&o);
        for want in expect.lines().filter(|l| !l.is_empty()) {
            let mut p = want.splitn(3, ' ');
            let (line, sev, msg) = (p.next().unwrap_or(""), p.next().unwrap_or(""), p.next().unwrap_or(""));
            let hit = out.lines().any(|l| {
                l.starts_with(&format!("{name}:{line}:"))
                    && l.contains(&format!(": {sev}: "))
                    && l.contains(msg)
            });
            assert!(hit, "{name}: `{want}` not in\n{out}");
        }
        seen += 1;
    }
    assert!(seen >= 10, "only {seen} err fixtures");
}

#[test]
fn check_json_lists_blocks_and_diagnostics() {
    let f = fixture("err/spa_360.h");
    let o = run(&["check", "--json", "--lang", "en", f.to_str().expect("utf-8 path")]);
    assert_eq!(o.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    assert_eq!(v["blocks"], 4);
    let d = &v["diagnostics"][0];
    assert_eq!(d["line"], 3);
    assert_eq!(d["column"], 17);
    assert_eq!(d["severity"], "error");
    assert_eq!(d["message"], "Entered angle not permitted: SPA 360 (-359.9999…359.9999)");
}

#[test]
fn check_reads_latin1_files() {
    let dir = std::env::temp_dir().join(format!("schwenkbar-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let f = dir.join("latin1.h");
    std::fs::write(
        &f,
        b"0 BEGIN PGM L1 MM\n1 PLANE RESET TURN FMAX ; Schwenken r\xfccksetzen\n2 END PGM L1 MM\n",
    )
    .expect("write");
    let o = run(&["check", f.to_str().expect("utf-8 path")]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let o = run(&["fmt", f.to_str().expect("utf-8 path")]);
    assert!(stdout(&o).contains("; Schwenken rücksetzen"), "{}", stdout(&o));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn fmt_prints_canonical_form_and_check_detects_differences() {
    let f = fixture("ok/euler_example.h");
    let o = run(&["fmt", f.to_str().expect("utf-8 path")]);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    assert!(
        out.contains("7 PLANE EULER EULPR+90 EULNU+45 EULROT+0 TURN MB MAX FMAX SYM- TABLE ROT\n"),
        "{out}"
    );
    // The fixture writes `EULNU45` without sign: not canonical.
    let o = run(&["fmt", "--check", f.to_str().expect("utf-8 path")]);
    assert_eq!(o.status.code(), Some(1));

    let dir = std::env::temp_dir().join(format!("schwenkbar-fmt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let canonical = dir.join("canonical.h");
    std::fs::write(&canonical, &out).expect("write");
    let o = run(&["fmt", "--check", canonical.to_str().expect("utf-8 path")]);
    assert_eq!(o.status.code(), Some(0));
    let _ = std::fs::remove_dir_all(&dir);
}
