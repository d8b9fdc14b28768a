//! Every fixture program under `tests/fixtures/{ok,err}` is its own test with an insta snapshot
//! (`tests/snapshots/parse_fixtures__{ok,err}__NAME.snap`) of what the parser makes of it:
//! the diagnostics as `line:column severity: German | English`, then each block as
//! `line:column [number as written] canonical text` (the formatter's text without the number it
//! would give). `cargo insta review` accepts a change; a missing snapshot fails.
//!
//! Besides the snapshot: `ok/` programs give no diagnostics (the as-printed Musterprogramm 1
//! only its elision warnings); each `err/NAME.h` has a sidecar `NAME.expect` with
//! `LINE SEVERITY MESSAGE` lines that must all be among its diagnostics (MESSAGE a part of the
//! German text); and formatting every fixture is stable.
//!
//! Native only: the browser suite compiles this folder for wasm32 too, where there are no files.
#![cfg(not(target_arch = "wasm32"))]

use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;

use schwenkbar_core::diag::DiagCode;
use schwenkbar_core::{Block, Lang, Program, format_program, parse};
use schwenkbar_tests::fixtures_dir;

fn path(dir: &str, name: &str) -> PathBuf {
    fixtures_dir().join(dir).join(format!("{name}.h"))
}

fn source(dir: &str, name: &str) -> String {
    let path = path(dir, name);
    fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// One block's canonical text without its block number (`format_program` numbers it 0).
fn canonical(b: &Block) -> String {
    let text = format_program(&Program { blocks: vec![b.clone()] });
    let unnumbered = text.strip_prefix('/').unwrap_or(&text).strip_prefix('0');
    unnumbered.unwrap_or_else(|| panic!("format_program numbers a lone block 0: {text}")).trim().to_owned()
}

/// The readable snapshot text of a program (see the module docs).
fn render(src: &str) -> String {
    let (program, diags) = parse(src);
    let mut s = String::from("diagnostics:\n");
    if diags.is_empty() {
        s.push_str("  (none)\n");
    }
    for d in &diags {
        let _ = writeln!(
            s,
            "  {}:{} {}: {} | {}",
            d.line,
            d.column,
            d.severity.as_str(),
            d.message(Lang::De),
            d.message(Lang::En)
        );
    }
    s.push_str("blocks:\n");
    for b in &program.blocks {
        let number = b.number().map_or_else(|| "-".to_owned(), |n| n.to_string());
        let skip = if b.skip() { "/" } else { "" };
        // A cycle definition's `~` lines indented under their block.
        let text = canonical(b).replace('\n', "\n      ");
        let _ = writeln!(s, "  {}:{} [{skip}{number}] {text}", b.line(), b.column());
    }
    s
}

fn assert_snapshot(dir: &str, name: &str, src: &str) {
    insta::with_settings!({ description => format!("tests/fixtures/{dir}/{name}.h"), omit_expression => true }, {
        insta::assert_snapshot!(format!("{dir}__{name}"), render(src));
    });
}

/// Formatting twice gives the same text; for `ok/` programs the reformatted program is the
/// same program up to the renumbering.
fn assert_formatting_stable(dir: &str, name: &str, src: &str) {
    let once = format_program(&parse(src).0);
    let (again, _) = parse(&once);
    assert_eq!(format_program(&again), once, "{dir}/{name}");
    if dir == "ok" {
        let strip = |p: Program| {
            p.blocks
                .into_iter()
                .map(|b| (b.skip(), b.comment().map(str::to_owned), b.into_body()))
                .collect::<Vec<_>>()
        };
        assert!(strip(again) == strip(parse(src).0), "{name}: reformatted program differs");
    }
}

fn check_ok(name: &str) {
    let src = source("ok", name);
    let (_, diags) = parse(&src);
    let as_printed = name.contains("as_printed");
    let unexpected: Vec<String> = diags
        .iter()
        .filter(|d| !(as_printed && matches!(d.code, DiagCode::CycleParamsElided { .. })))
        .map(|d| format!("{}: {}", d.line, d.message(Lang::De)))
        .collect();
    assert!(unexpected.is_empty(), "ok/{name}.h:\n{}", unexpected.join("\n"));
    assert_formatting_stable("ok", name, &src);
    assert_snapshot("ok", name, &src);
}

fn check_err(name: &str) {
    let src = source("err", name);
    let expect_path = path("err", name).with_extension("expect");
    let expect =
        fs::read_to_string(&expect_path).unwrap_or_else(|e| panic!("{}: {e}", expect_path.display()));
    let (_, diags) = parse(&src);
    let wanted: Vec<&str> = expect.lines().filter(|l| !l.trim().is_empty()).collect();
    assert!(!wanted.is_empty(), "err/{name}.expect states no diagnostic");
    for want in wanted {
        let mut parts = want.splitn(3, ' ');
        let (line, sev, msg) = (parts.next(), parts.next(), parts.next().unwrap_or(""));
        let line: u32 = line.and_then(|l| l.parse().ok()).expect("LINE SEVERITY MESSAGE");
        let found = diags
            .iter()
            .any(|d| d.line == line && Some(d.severity.as_str()) == sev && d.message(Lang::De).contains(msg));
        assert!(found, "err/{name}.h: expected `{want}`, got {diags:#?}");
    }
    assert_formatting_stable("err", name, &src);
    assert_snapshot("err", name, &src);
}

/// One `#[test]` per fixture file, in a module per folder (`ok::paths`, `err::garbage`).
macro_rules! fixtures {
    ($dir:ident, $check:ident: $($name:ident),+ $(,)?) => {
        mod $dir {
            $(
                #[test]
                fn $name() {
                    super::$check(stringify!($name));
                }
            )+
            /// The fixtures that have a test, for the completeness check.
            pub const NAMES: &[&str] = &[$(stringify!($name)),+];
        }
    };
}

fixtures!(ok, check_ok:
    cam_hypermill,
    contour_manual,
    cam_spellings,
    cycles_continuation,
    euler_example,
    function_tcpm,
    musterprogramm1,
    musterprogramm1_as_printed,
    paths,
    plane_all,
    real_families,
);

fixtures!(err, check_err:
    cycle_param_without_value,
    duplicate_axis,
    eulnu_negative,
    function_tcpm,
    garbage,
    other_control_post,
    path_words,
    propr_90,
    seq_with_sym,
    spa_360,
    spatial_without_spc,
    word_in_wrong_block,
);

#[test]
fn every_fixture_file_has_a_test() {
    // A new fixture goes into `fixtures!` of its folder.
    schwenkbar_testkit::assert_one_test_per_program(&fixtures_dir().join("ok"), ok::NAMES);
    schwenkbar_testkit::assert_one_test_per_program(&fixtures_dir().join("err"), err::NAMES);
}

#[test]
fn as_printed_musterprogramm_warns_exactly_about_both_elided_cycles() {
    let src = source("ok", "musterprogramm1_as_printed");
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
    assert_eq!(p.blocks.last().and_then(|b| b.number()), Some(37));
}

#[test]
fn completed_musterprogramm_has_all_cycle_parameters() {
    use schwenkbar_core::BlockBody;
    let src = source("ok", "musterprogramm1");
    let (p, diags) = parse(&src);
    assert!(diags.is_empty(), "{diags:?}");
    let numbers: Vec<Option<u32>> = p.blocks.iter().map(|b| b.number()).collect();
    assert_eq!(numbers, (0..=37).map(Some).collect::<Vec<_>>());
    let params = |n: usize| match &*p.blocks[n].body() {
        BlockBody::CycleDef(c) => c.params.iter().map(|q| q.index).collect::<Vec<_>>(),
        other => panic!("block {n} is {other:?}"),
    };
    assert_eq!(params(12), [389, 225, 226, 227, 386, 218, 219, 202, 369, 370, 207, 385, 253, 200, 357, 204]);
    assert_eq!(params(27), [200, 201, 206, 202, 210, 203, 204, 211]);
    // The shipped copy is the same program.
    let shipped = fixtures_dir().join("../../static/programs/musterprogramm1.h");
    assert_eq!(fs::read_to_string(shipped).expect("static copy"), src);
}
