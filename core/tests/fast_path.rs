//! Differential tests of the parser's fast path (issue 16): `parse` (straight lines through the
//! fast path into compact blocks) and `parse_general` (every block through the general parser)
//! must give the same program and the same diagnostics, compared through their full `Debug`
//! form, which includes spans, lines, columns and every number's bits as written by `{:?}`.

use std::fmt::Write as _;
use std::path::Path;

use proptest::prelude::*;
use schwenkbar_core::{parse, parse_general, sample};

/// Both parses of `src`: (fast, general), each as its `Debug` text, and how many blocks the fast
/// path read.
fn both(src: &str) -> (String, String, usize) {
    let fast = parse(src);
    let compact = fast.0.blocks.iter().filter(|b| b.is_compact()).count();
    (format!("{fast:#?}"), format!("{:#?}", parse_general(src)), compact)
}

fn assert_same(src: &str, what: &str) -> usize {
    let (fast, general, compact) = both(src);
    if fast != general {
        let line = fast.lines().zip(general.lines()).position(|(a, b)| a != b).unwrap_or(0);
        let around = |t: &str| t.lines().skip(line.saturating_sub(8)).take(12).collect::<Vec<_>>().join("\n");
        panic!("{what}: fast path differs\n--- fast:\n{}\n--- general:\n{}", around(&fast), around(&general));
    }
    compact
}

fn fixtures(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("fixture dir").flatten() {
        let path = entry.path();
        if path.is_dir() {
            fixtures(&path, out);
        } else if path.extension().is_some_and(|e| e == "h") {
            out.push(path);
        }
    }
}

#[test]
fn fixtures_read_the_same_through_both_paths() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/fixtures");
    let mut files = Vec::new();
    fixtures(&root, &mut files);
    assert!(files.len() > 20, "fixtures not found under {}", root.display());
    let mut compact = 0;
    for file in files {
        let bytes = std::fs::read(&file).expect("fixture");
        let src = schwenkbar_core::text::decode(bytes);
        compact += assert_same(&src, &file.display().to_string());
        // The same program with the other line ending.
        compact += assert_same(&src.replace('\n', "\r\n"), &format!("{} (CRLF)", file.display()));
    }
    assert!(compact > 50, "the fast path read only {compact} fixture blocks");
}

#[test]
fn the_cam_program_reads_the_same_and_almost_all_fast() {
    let src = sample::cam_program(20_000);
    let compact = assert_same(&src, "cam_program");
    assert!(compact > 19_900, "only {compact} compact blocks");
}

/// Pieces of straight lines, plausible and broken.
fn header() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "",
        "1 ",
        "12 ",
        "/5 ",
        "/ 5 ",
        "5 /",
        "5 / ",
        "  7 ",
        "\t8\t",
        "0012 ",
        "999999999 ",
        "1234567890 ",
        "4294967296 ",
        "3",
        "3X ",
        " /",
        "5 \u{a0}",
        "\u{a0}5 ",
    ])
    .prop_map(str::to_owned)
}

fn number() -> impl Strategy<Value = String> {
    let digits = prop::sample::select(vec![
        "",
        "0",
        "1",
        "25",
        "2500",
        "12.5",
        "12.5000",
        ".5",
        "5.",
        ".",
        "1.2.3",
        "0.000000000000001",
        "0.0000000000000001",
        "134217727",
        "134217728",
        "99999999",
        "999999999",
        "1234567890",
        "00000000001",
        "-",
        "+",
        "Q1",
        "Q",
        "x",
        "1e5",
        "50,5",
    ]);
    (prop::sample::select(vec!["", "+", "-", "++"]), digits).prop_map(|(s, d)| format!("{s}{d}"))
}

fn word() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (prop::sample::select(vec!["X", "Y", "Z", "A", "C", "IX", "W"]), number()).prop_map(|(a, n)| format!("{a}{n}")),
        2 => number().prop_map(|n| format!("F{n}")),
        2 => prop::sample::select(vec![
            "FMAX", "F MAX", "F AUTO", "FMAXX", "F", "R0", "RL", "RR", "R5", "R0X", "M3", "M91", "DR+", ";", "; note",
            ";x~", "~", "X", "LX", "\u{e4}", "\r", "\u{b}",
        ])
        .prop_map(str::to_owned),
    ]
}

fn line() -> impl Strategy<Value = String> {
    (
        header(),
        prop::sample::select(vec!["L", "L", "L", "LP", "l", "L5", ""]),
        prop::collection::vec((prop::sample::select(vec![" ", " ", "  ", "\t", ""]), word()), 0..7),
        prop::sample::select(vec!["", " ", "\t", " ~"]),
    )
        .prop_map(|(h, kw, words, tail)| {
            let mut s = format!("{h}{kw}");
            for (sep, w) in words {
                let _ = write!(s, "{sep}{w}");
            }
            s + tail
        })
}

proptest! {
    #![proptest_config(schwenkbar_testkit::proptest_cases(2000))]

    #[test]
    fn generated_lines_read_the_same_through_both_paths(
        lines in prop::collection::vec(line(), 1..8),
        breaks in prop::collection::vec(prop::sample::select(vec!["\n", "\r\n", "\r\n", "\n\n", "\r"]), 8),
    ) {
        let mut src = String::from("0 BEGIN PGM T MM\n");
        for (l, br) in lines.iter().zip(&breaks) {
            src.push_str(l);
            src.push_str(br);
        }
        let (fast, general, _) = both(&src);
        prop_assert_eq!(fast, general, "{:?}", src);
    }
}

/// The generator reaches the fast path: most plain lines are read by it.
#[test]
fn plain_generated_lines_take_the_fast_path() {
    let src = "1 L X+1 Y-2.5 Z+.5 F2500\n2 /L X-0 R0 FMAX\n\t3 L Z+134217727\n/4 L\n";
    assert_eq!(assert_same(src, "plain"), 4);
}
