//! Programs as others write them (issue 30, first part): each lenient spelling parses to the
//! same block as the control's own spelling, `fmt` writes the control's spelling, and block
//! numbers that are missing, not ascending or written `N…` are each said once per file as a
//! warning, never as an error.

use schwenkbar_core::diag::{DiagCode, Severity};
use schwenkbar_core::format::format_program;
use schwenkbar_core::parse;

/// `lenient` and `canonical` (one block each, numbered 1) say the same.
fn same(lenient: &str, canonical: &str) {
    let (a, da) = parse(&format!("1 {lenient}\n"));
    let (b, db) = parse(&format!("1 {canonical}\n"));
    assert!(db.is_empty(), "{canonical}: {db:?}");
    assert!(da.is_empty(), "{lenient}: {da:?}");
    assert_eq!(a.blocks.len(), 1, "{lenient}");
    assert_eq!(a.blocks[0].body(), b.blocks[0].body(), "{lenient} ≠ {canonical}");
    assert_eq!(format_program(&a), format_program(&b), "fmt writes the control's spelling");
}

#[test]
fn blanks_around_a_sign_are_the_signed_word() {
    same("L Z + 13 FMAX", "L Z+13 FMAX");
    same("L Z + Q13 FMAX", "L Z+Q13 FMAX");
    same("L X - 5 Y -Q2 FMAX", "L X-5 Y-Q2 FMAX");
    same("L IX + 2.5 F100", "L IX+2.5 F100");
}

#[test]
fn numbers_without_sign_or_with_a_leading_or_trailing_point() {
    same("L X25.531 Y-79.598 FMAX", "L X+25.531 Y-79.598 FMAX");
    same("L Y-.045 F10000.", "L Y-0.045 F10000");
    same("L C270. FMAX", "L C+270 FMAX");
}

#[test]
fn fn_blocks_in_every_spacing() {
    same("FN0: Q1 = 1.995", "FN 0: Q1 = +1.995");
    same("FN 0:Q2=50", "FN 0: Q2 = +50");
    same("FN 1: Q1 =+Q1 +90", "FN 1: Q1 = +Q1 + +90");
    same("FN3: Q3 = Q1 *-2", "FN 3: Q3 = +Q1 * -2");
    same("FN 2: Q4 = +Q1 -Q2", "FN 2: Q4 = +Q1 - +Q2");
}

#[test]
fn cycle_def_without_a_blank_before_its_number() {
    let (a, da) = parse("1 CYCL DEF9.0 VERWEILZEIT\n2 CYCL DEF9.1 V.ZEIT1\n");
    let (b, _) = parse("1 CYCL DEF 9.0 VERWEILZEIT\n2 CYCL DEF 9.1 V.ZEIT1\n");
    assert!(da.is_empty(), "{da:?}");
    assert_eq!(format_program(&a), format_program(&b));
    let (a, da) = parse("1 CYCL DEF200 BOHREN ~\n  Q200=+2 ;SICHERHEITS-ABST.\n");
    let (b, _) = parse("1 CYCL DEF 200 BOHREN ~\n  Q200=+2 ;SICHERHEITS-ABST.\n");
    assert!(da.is_empty(), "{da:?}");
    assert_eq!(a.blocks[0].body(), b.blocks[0].body());
}

fn warnings(src: &str) -> Vec<(Severity, DiagCode)> {
    parse(src).1.into_iter().map(|d| (d.severity, d.code)).collect()
}

#[test]
fn block_numbers_are_said_once_per_file_and_never_an_error() {
    // Repeated, falling, restarting after 9999: one warning at the first.
    let src = "0 BEGIN PGM T MM\n9999 L X+1 FMAX\n0 L X+2 FMAX\n0 L X+3 FMAX\n5 L X+4 FMAX\n1 END PGM T MM\n";
    assert_eq!(
        warnings(src),
        [(Severity::Warning, DiagCode::BlockNumberNotAscending { previous: 9999, number: 0 })]
    );
    // Missing: once; N-prefixed: read as the number, once.
    let src = "L X+1 FMAX\nL X+2 FMAX\nN25 L Z+1 R0 FMAX\nN30 L Z+2 R0 FMAX\n";
    let (p, d) = parse(src);
    assert_eq!(p.blocks.iter().map(|b| b.number()).collect::<Vec<_>>(), [None, None, Some(25), Some(30)]);
    assert_eq!(
        d.iter().map(|d| (d.severity, d.code.clone(), d.line)).collect::<Vec<_>>(),
        [
            (Severity::Warning, DiagCode::MissingBlockNumber, 1),
            (Severity::Warning, DiagCode::BlockNumberPrefixed { number: 25 }, 3),
        ]
    );
    same("L Z+1 R0 FMAX", "L Z+1 R0 FMAX");
    let (n, _) = parse("N7 L Z+1 R0 FMAX\n");
    let (plain, _) = parse("7 L Z+1 R0 FMAX\n");
    assert_eq!(n.blocks[0].body(), plain.blocks[0].body());
    assert_eq!(format_program(&n), format_program(&plain), "fmt writes the number without N");
    // A cycle's `~` lines end at an N-numbered block as at a numbered one.
    let (p, _) = parse("N1 CYCL DEF 200 BOHREN ~\n  Q200=+2 ;SICHERHEITS-ABST.\nN2 L Z+100 R0 FMAX\n");
    assert_eq!(p.blocks.len(), 2);
}
