//! How each block family's parser stops (issue 30, the grammar as nom combinators): a hard stop
//! is the block's one error, on the word it names (the span's text below, worked out by hand
//! from the block); a recoverable stop of a family ("not one of my blocks") keeps the block as
//! an unknown one with a warning; a finding that does not stop the block (a value out of
//! range) comes with the block read.

use schwenkbar_core::ast::BlockBody;
use schwenkbar_core::diag::{DiagCode, Expected, Severity};
use schwenkbar_core::parse;

/// A finding on `block`: its code, severity, the text its span marks, where that starts in
/// `block`, and what was expected there.
struct Finding {
    code: DiagCode,
    severity: Severity,
    marked: String,
    start: usize,
    expected: Option<Expected>,
}

/// `block` read as block 1 of a program: its body and its findings.
fn read(block: &str) -> (BlockBody, Vec<Finding>) {
    let text = format!("1 {block}");
    let (program, diags) = parse(&text);
    let findings = diags
        .iter()
        .map(|d| Finding {
            code: d.code.clone(),
            severity: d.severity,
            marked: text[d.span.start..d.span.end].to_owned(),
            start: d.span.start - 2,
            expected: d.expected,
        })
        .collect();
    (program.blocks[0].body().into_owned(), findings)
}

/// The one finding of `block` and its body.
fn one(block: &str) -> (Finding, BlockBody) {
    let (body, mut findings) = read(block);
    assert_eq!(findings.len(), 1, "{block}");
    (findings.remove(0), body)
}

fn dup(word: &str) -> DiagCode {
    DiagCode::Duplicate { word: word.to_owned() }
}

#[test]
fn a_hard_stop_names_its_word() {
    let missing = |word| DiagCode::MissingWord { word };
    let not_allowed = |word: &str| DiagCode::NotAllowed { word: word.to_owned() };
    let cases: [(&str, DiagCode, &str); 15] = [
        ("PLANE SPATIAL SPA+0 SPB+0", missing("SPC"), ""),
        ("PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN SEQ+ SYM-", DiagCode::SeqWithSym, "SYM-"),
        ("PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN STAY", dup("STAY"), "STAY"),
        ("PLANE SPATIAL SPA+0 SPB+0 SPC+0 STAY COORD ROT TABLE ROT", dup("TABLE ROT"), "TABLE ROT"),
        ("PLANE AXIAL B+10 IB+5", dup("B"), "IB+5"),
        ("PLANE RELATIV SPX+5", missing("SPA|SPB|SPC"), "SPX+5"),
        ("L X+1 Y+2 X+3", dup("X"), "X+3"),
        ("L X+1 DR+ F100", not_allowed("DR+"), "DR+"),
        ("CR X+1 Y+1 DR+", missing("R"), ""),
        ("TOOL CALL 5 Z S100 S200", dup("S"), "S200"),
        ("TRANS DATUM AXIS", missing("X|Y|Z"), ""),
        ("APPR LT X+1 Y+1 RL F100", missing("LEN"), ""),
        ("PATTERN DEF POS1 (Y+1)", missing("X"), "POS"),
        ("CYCL CALL POS X+1 Y+1 FMAX", missing("Z"), ""),
        // Named by its number, however the line wrote it.
        ("CYCL DEF 200 BOHREN ~\n  Q200=+2 ~\n  Q0200=+3", dup("Q200"), "Q0200=+3"),
    ];
    for (block, code, text) in cases {
        let (f, body) = one(block);
        assert_eq!((f.code, f.severity, f.marked.as_str()), (code, Severity::Error, text), "{block}");
        assert!(matches!(body, BlockBody::Invalid { .. }), "{block}: {body:?}");
        // The end of the block when the word is missing there.
        if text.is_empty() {
            assert_eq!(f.start, block.len(), "{block}");
        }
    }
}

#[test]
fn a_stop_inside_a_word_names_what_was_expected_there() {
    let cases = [
        ("PLANE SPATAL SPA+0", "SPATAL", "SPATIAL|PROJECTED|EULER|VECTOR|POINTS|RELATIV|AXIAL|RESET"),
        ("PLANE RESET STAY COORD", "", "ROT"),
        ("FN 9: IF +Q1 NE +0 GOTO LBL 1", "NE", "EQU"),
        ("FN 1: Q1 = +1 - +2", "-", "+"),
        ("L X+1 Y+2 PQ", "PQ", "X|Y|Z|A|B|C|R0|RL|RR|F|M"),
        ("TOOL CALL 5 Z S100 T7", "T7", "S|F|DL|DR|DR2"),
        ("CYCL CALL PAT F100 X", "X", "F|M"),
    ];
    for (block, marked, expected) in cases {
        let (f, body) = one(block);
        assert_eq!(f.code, DiagCode::InvalidInput, "{block}");
        assert_eq!(f.marked, marked, "{block}");
        assert_eq!(f.expected, Some(Expected::Nc(expected)), "{block}");
        assert!(matches!(body, BlockBody::Invalid { .. }), "{block}");
    }
}

#[test]
fn a_program_call_needs_its_name() {
    let (f, body) = one("CALL PGM");
    assert_eq!((f.code, f.marked.as_str(), f.expected), (DiagCode::InvalidInput, "", Some(Expected::Name)));
    assert!(matches!(body, BlockBody::Invalid { .. }));
    // A number run on is the name (`CALL PGM100`, as `LBL1`); letters run on are no call.
    assert!(matches!(read("CALL PGM100").0, BlockBody::CallPgm { path } if path == "100"));
    assert!(matches!(read("CALL PGMX").0, BlockBody::Unknown { .. }));
}

#[test]
fn a_family_that_does_not_know_the_block_keeps_it_unknown() {
    for block in [
        "TRANS SCALE 2",
        "FUNCTION PROG PATH IS CONTOUR",
        "BLK FORM CYLINDER Z R50 L100",
        "CYCL END",
        "CALL XYZ",
        "PATTERN 2",
    ] {
        let (f, body) = one(block);
        assert_eq!((f.code, f.severity), (DiagCode::UnknownBlock, Severity::Warning), "{block}");
        assert!(matches!(&body, BlockBody::Unknown { text } if text == block), "{block}: {body:?}");
    }
}

#[test]
fn a_finding_that_does_not_stop_the_block_comes_with_the_block_read() {
    let (f, body) = one("PLANE SPATIAL SPA+400 SPB+0 SPC+0 TURN");
    assert!(matches!(f.code, DiagCode::AngleNotPermitted { word: "SPA", .. }), "{:?}", f.code);
    assert_eq!((f.severity, f.marked.as_str()), (Severity::Error, "SPA+400"));
    assert!(matches!(body, BlockBody::Plane(_)));
    // A range error and then a hard stop: both said, in the order of the words.
    let (_, findings) = read("PLANE SPATIAL SPA+400 SPB+0 SPC+0 TURN XYZ");
    let codes: Vec<_> = findings.into_iter().map(|f| f.code).collect();
    assert!(
        matches!(codes.as_slice(), [DiagCode::AngleNotPermitted { .. }, DiagCode::InvalidInput]),
        "{codes:?}"
    );
    let (f, body) = one("PLANE VECTOR BX+0 BY+0 BZ+0 NX+0 NY+0 NZ+1 STAY");
    assert_eq!(
        (f.code, f.severity, f.marked.as_str()),
        (DiagCode::ZeroVector { word: "B" }, Severity::Error, "BX")
    );
    assert!(matches!(body, BlockBody::Plane(_)));
    let (f, body) = one("PLANE SPATIAL SPA+0 SPB+0 SPC+0");
    assert_eq!((f.code, f.severity), (DiagCode::MissingPositioning, Severity::Warning));
    assert!(matches!(body, BlockBody::Plane(_)));
}
